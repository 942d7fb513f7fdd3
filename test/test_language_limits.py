"""Issue 21: counts in instructions are bounded whole numbers; oversized translations are refused."""
import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.errors import ErrorCode, LimitExceededError, LtlInstructError, TranslationError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.task import MAX_COUNT, at_least, at_most, exactly, near_atom
from ltl_instruct.core.spec import Descriptor, atoms_of


@pytest.fixture(scope='module')
def translator():
    return make_translator('offline')


@pytest.mark.parametrize('text, count', [
    ('visit the kitchen 50 times', 50),          # RecursionError on main
    ('visit the kitchen 1000000 times', 1000000),  # grew past 3 GiB on main
    ('visit the kitchen 21 times', 21),
    ('go to the hall 1,000 times', 1000),
])
def test_counts_above_the_maximum_are_limit_exceeded(translator, text, count):
    with pytest.raises(LimitExceededError) as e:
        translator.translate(text)
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED
    assert str(count) in e.value.message and str(MAX_COUNT) in e.value.message


@pytest.mark.parametrize('text, shown', [
    ('visit the kitchen -3 times', '-3'),        # became 3 visits on main
    ('visit the kitchen 2.5 times', '2.5'),      # became 5 visits of kitchen_2 on main
    ('visit the kitchen 0.5 times', '0.5'),
])
def test_negative_and_fractional_counts_are_refused(translator, text, shown):
    with pytest.raises(TranslationError) as e:
        translator.translate(text)
    assert e.value.code == ErrorCode.TRANSLATION_ERROR
    assert shown in e.value.message


def test_the_maximum_count_translates(translator):
    f = translator.translate(f'visit the kitchen {MAX_COUNT} times').formula
    assert str(f).count('!near[kitchen]') == MAX_COUNT - 1


def test_small_counts_are_unchanged(translator):
    assert str(translator.translate('visit the kitchen 3 times').formula) == \
        'F (near[kitchen] & F (!near[kitchen] & F (near[kitchen] & F (!near[kitchen] & F near[kitchen]))))'


@pytest.mark.parametrize('builder', [at_least, at_most, exactly])
def test_count_builders_check_their_count(builder):
    x = near_atom(Descriptor('kitchen'))
    with pytest.raises(LimitExceededError):
        builder(x, MAX_COUNT + 1)
    with pytest.raises(TranslationError):
        builder(x, -1)
    with pytest.raises(TranslationError):
        builder(x, 2.5)


def test_translation_with_more_than_64_atoms_is_refused(translator):
    words = ('apple banana cherry dog egg fig grape house igloo jam kite lemon mango nut olive pear '
             'quilt rose sun tree umbrella vase wall yarn zebra').split()
    names = [f'the {a} {b}' for a in ('red', 'blue', 'green') for b in words][:66]
    assert len(atoms_of(translator.translate('go to ' + ', then '.join(names[:60])).formula)) == 60
    with pytest.raises(LimitExceededError) as e:
        translator.translate('go to ' + ', then '.join(names))
    assert 'the limit is 64' in e.value.message


@pytest.mark.parametrize('text', ['visit the kitchen 50 times', 'visit the kitchen -3 times'])
def test_cli_exits_2_with_the_typed_error(text, capsys):
    assert main(['translate', text]) == 2
    err = capsys.readouterr().err
    assert err.startswith('error [') and 'Traceback' not in err


def test_typed_errors_are_ltl_instruct_errors():
    assert issubclass(TranslationError, LtlInstructError)

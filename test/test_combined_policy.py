"""The combined translator's policy, decided on readings made up here (no model is loaded)."""
import math

import pytest

from ltl_instruct.core.errors import TranslationError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.language.combined import CombinedTranslator, Policy
from ltl_instruct.core.language.neural.decode import Hypothesis
from ltl_instruct.core.language.neural.translator import LEAVE_OUT_ODDS, _readings
from ltl_instruct.core.spec import parse_formula

TEXT = 'go to the kitchen, then the hall'


@pytest.fixture(scope='module')
def combined():
    t = CombinedTranslator(model_path='/nonexistent/bundle')   # the model part is replaced by readings
    assert t.model is None
    return t


def _rules(formula: str, unread=('guessed "then the hall" as a place to go',)) -> Translation:
    """The rules' reading; by default one that guessed a part (the model may override only those)."""
    extra = {'unread': list(unread)} if unread else {}
    return Translation(TEXT, parse_formula(formula), 'offline', (), extra)


def _model(formula: str, confidence: float, complete: bool = True,
           mentions=('kitchen', 'hall')) -> Translation:
    said = [{'text': f'the {m}', 'descriptor': m, 'slot': f's{i}'} for i, m in enumerate(mentions, 1)]
    return Translation(TEXT, parse_formula(formula), 'neural', (), {
        'confidence': confidence, 'complete': complete, 'flagged': confidence < 0.6, 'alternatives': [],
        'mentions': said})


RULES = 'F near[kitchen] & F near[hall]'
MODEL = 'F (near[kitchen] & F near[hall])'


def test_agreement_goes_on_unflagged(combined):
    t = combined.decide((_rules(MODEL, unread=()), None, _model(MODEL, 0.7)), Policy())
    assert t.extra['agreement'] is True and not t.extra['flagged']


def test_disagreement_below_override_keeps_the_rules_flagged(combined):
    t = combined.decide((_rules(RULES), None, _model(MODEL, 0.8)), Policy(override=0.9))
    assert str(t.formula) == RULES
    assert t.extra['flagged'] and t.extra['alternatives'] == [MODEL]


def test_sure_model_overrides_flagged_with_the_rules_as_alternative(combined):
    t = combined.decide((_rules(RULES), None, _model(MODEL, 0.95)), Policy(override=0.9))
    assert str(t.formula) == MODEL and t.backend == 'combined'
    assert t.extra['flagged'] and t.extra['alternatives'][0] == RULES
    assert any('rules read this differently' in n for n in t.extra['unread'])


def test_a_rules_reading_that_placed_every_word_is_never_overridden(combined):
    """Construction tests: 56 sure model readings had replaced right ones ("Never mind, go to the porch.")."""
    t = combined.decide((_rules(RULES, unread=()), None, _model(MODEL, 0.999)), Policy())
    assert str(t.formula) == RULES and t.extra['flagged'] and t.extra['alternatives'][0] == MODEL
    t = combined.decide((_rules(RULES, unread=()), None, _model(MODEL, 0.999)), Policy(read_all_stands=False))
    assert str(t.formula) == MODEL


def test_incomplete_or_misspelt_model_never_overrides(combined):
    incomplete = _model(MODEL, 0.99, complete=False)
    assert str(combined.decide((_rules(RULES), None, incomplete), Policy(override=0.5)).formula) == RULES
    gibberish = _model('F (near[qzxv] & F near[hall])', 0.99, mentions=('qzxv', 'hall'))
    assert str(combined.decide((_rules(RULES), None, gibberish), Policy(override=0.5)).formula) == RULES


def test_refusal_taken_over_only_when_sure(combined):
    refusal = TranslationError('could not place "zorp"', details={'part': 'zorp'})
    t = combined.decide((None, refusal, _model(MODEL, 0.6)), Policy(takeover=0.5))
    assert str(t.formula) == MODEL and t.extra['flagged'] and t.extra['rules_error']
    with pytest.raises(TranslationError):
        combined.decide((None, refusal, _model(MODEL, 0.4)), Policy(takeover=0.5))
    count = TranslationError('too many visits', details={'part': 'x', 'count': 50})
    with pytest.raises(TranslationError):
        combined.decide((None, count, _model(MODEL, 0.99)), Policy(takeover=0.5))


@pytest.mark.parametrize('part,refused', [
    ('since the hall is off limits', True), ('but never the hall', True),
    ('head straight away to the hall', False), ('zorp the hall', False),
    ('the hall , order does not matter', False)])
def test_a_refusal_over_a_rule_is_taken_over_only_by_a_reading_that_avoids(combined, part, refused):
    """"Go to the kitchen, since the hall is off limits": the model's F (kitchen & F hall) had gone on."""
    refusal = TranslationError(f'could not place "{part}"', details={'part': part})
    if refused:
        with pytest.raises(TranslationError):
            combined.decide((None, refusal, _model(MODEL, 0.99)), Policy())
        assert combined.decide((None, refusal, _model(MODEL, 0.99)), Policy(rules_kept=False))
    else:
        assert str(combined.decide((None, refusal, _model(MODEL, 0.99)), Policy()).formula) == MODEL
    avoiding = 'F near[kitchen] & G !near[hall]'
    assert str(combined.decide((None, refusal, _model(avoiding, 0.99)), Policy()).formula) == avoiding


def test_reading_that_leaves_a_mention_out_must_be_much_likelier():
    descriptors = {'s1': 'fridge', 's2': 'freezer'}
    left_out = Hypothesis(('F', 'near', 's2'), math.log(0.6))
    complete = Hypothesis(('F', '&', 'near', 's1', 'F', 'near', 's2'), math.log(0.3))
    best, whole = _readings([left_out, complete], descriptors)[0]
    assert str(best[0]) == 'F (near[fridge] & F near[freezer])' and whole   # only 2x likelier
    much = Hypothesis(('F', 'near', 's2'), math.log(0.3 * LEAVE_OUT_ODDS * 1.1))
    best, whole = _readings([much, complete], descriptors)[0]
    assert str(best[0]) == 'F near[freezer]' and not whole


def test_model_never_overrides_a_count(combined):
    """The model miscounts nested visits: a reading naming one place three times stays the rules'."""
    thrice = 'F (near[kitchen] & F (!near[kitchen] & F near[kitchen]))'
    t = combined.decide((_rules(thrice), None, _model('F near[kitchen]', 0.99, mentions=('kitchen',))),
                        Policy(override=0.5))
    assert str(t.formula) == thrice and t.extra['flagged']
    t = combined.decide((_rules('F near[kitchen]'), None, _model(thrice, 0.99, mentions=('kitchen',))),
                        Policy(override=0.5))
    assert str(t.formula) == 'F near[kitchen]' and t.extra['flagged']
    # unless the policy lets it (a model that writes counts as macros may count well enough)
    t = combined.decide((_rules('F near[kitchen]'), None, _model(thrice, 0.99, mentions=('kitchen',))),
                        Policy(override=0.5, counts=True))
    assert str(t.formula) == thrice and t.extra['flagged']


def test_a_clause_read_as_one_name_is_not_sure(combined):
    """A name longer than any object's, which the phrase reader could not split, keeps the rules'."""
    blob = 'dock_next_to_tv_or_one_next_to_shelf'
    t = combined.decide((_rules(RULES), None, _model(f'F near[{blob}]', 0.99, mentions=(blob,))),
                        Policy(override=0.5))
    assert str(t.formula) == RULES and t.extra['flagged']
    related = 'F near[dock::isnextto(tv)]'
    t = combined.decide((_rules(RULES), None, _model(related, 0.99, mentions=('dock::isnextto(tv)',))),
                        Policy(override=0.5))
    assert str(t.formula) == related   # a thing with its relations is a parsed name


def test_a_reading_naming_what_the_map_lacks_gives_way_at_takeover_confidence():
    """With landmarks given, the rules' "green" is no place of the map; the model's green_room is."""
    mapped = CombinedTranslator(model_path='/nonexistent/bundle',
                                landmarks=('green_room', 'red_room', 'blue_room'))
    said = 'F (near[green] & F (near[red_room] & F near[blue_room]))'    # "through the green or red room"
    meant = 'F ((near[green_room] | near[red_room]) & F near[blue_room])'
    rules = _rules(said)
    model = _model(meant, 0.6, mentions=('green_room', 'red_room', 'blue_room'))
    t = mapped.decide((rules, None, model), Policy(takeover=0.5, override=0.95))
    assert str(t.formula) == meant and t.extra['flagged']
    assert said in t.extra['alternatives']
    # not without the policy, and not below the takeover confidence
    t = mapped.decide((rules, None, model), Policy(takeover=0.5, override=0.95, off_map=False))
    assert str(t.formula) == said and t.extra['flagged']
    weak = _model(meant, 0.4, mentions=('green_room', 'red_room', 'blue_room'))
    t = mapped.decide((rules, None, weak), Policy(takeover=0.5, override=0.95))
    assert str(t.formula) == said and t.extra['flagged']


def test_a_reading_naming_what_the_map_lacks_is_flagged_even_when_both_agree():
    """Drone: "without going to any other floors" read by both as !near[other_floors], not flagged before."""
    mapped = CombinedTranslator(model_path='/nonexistent/bundle', landmarks=('kitchen', 'hall'))
    said = 'F near[kitchen] & G !near[other_floors]'
    t = mapped.decide((_rules(said, unread=()), None, _model(said, 0.99)), Policy())
    assert t.extra['agreement'] is True and t.extra['flagged']
    assert any('other_floors: none of the landmarks given' in n for n in t.extra['unread'])
    t = mapped.decide((_rules(RULES, unread=()), None, _model(RULES, 0.99)), Policy())
    assert not t.extra['flagged']

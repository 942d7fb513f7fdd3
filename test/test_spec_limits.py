"""Issue 21: formulas inside the parser's limits never recurse past Python's limit.

The parser accepts nesting up to 200; every stage after it (printer, normal form,
automaton, English) must then finish or raise a typed error, never ``RecursionError``.
"""
import pytest

from ltl_instruct.cli import main
from ltl_instruct.commands.formula import report
from ltl_instruct.core.automaton import to_nnf
from ltl_instruct.core.errors import ErrorCode, LimitExceededError, LtlInstructError
from ltl_instruct.core.spec import Not, near, parse_formula

ATOMS = [f'a{i}' for i in range(60)]

INSIDE_LIMITS = {
    'not199': '!' * 199 + 'a',
    'F199': 'F' * 199 + ' a',
    'X199': 'X' * 199 + ' a',
    'G199': 'G' * 199 + ' a',
    'implies_chain': ' -> '.join(ATOMS[i % 60] for i in range(199)),
    'F_of_implies_chain': 'F' * 199 + '(' + ' -> '.join(ATOMS[i % 60] for i in range(195)) + ')',
    'not_parens': '!(' * 60 + 'a' + ')' * 60,
    'unary_runs_in_parens': ('!!!(') * 60 + 'a' + ')' * 60,
    'next_runs_in_parens': ('XXX(') * 60 + 'a' + ')' * 60,
    'descriptor32': 'near[' + 'a::isabove(' * 32 + 'b' + ')' * 32 + ']',
}


@pytest.mark.parametrize('name', sorted(INSIDE_LIMITS))
def test_deep_formulas_inside_the_limits_finish(name):
    try:
        r = report(INSIDE_LIMITS[name])
    except LtlInstructError:   # a typed refusal is fine; a RecursionError is not
        return
    assert r['formula']


def test_199_nots_print_and_round_trip():
    f = parse_formula('!' * 199 + 'a')
    text = str(f)
    assert text == '!' * 199 + 'near[a]'
    assert parse_formula(text) == f


def test_printer_handles_formulas_deeper_than_python_recursion():
    f = near('a')
    for _ in range(5000):    # built in code, not parsed: no parser limit applies
        f = Not(f)
    assert str(f) == '!' * 5000 + 'near[a]'
    assert to_nnf(f) == near('a')


def test_cli_199_nots_exits_0(capsys):
    assert main(['formula', '!' * 199 + 'a']) in (0, 1)


def test_iff_chain_compiles_without_expansion():
    # guards and states are BDDs (issue 22): no normal form, so 199 <-> over 60 atoms is small
    text = ' <-> '.join(ATOMS[i % 60] for i in range(199))
    r = report(text)
    assert r['satisfiable'] and len(r['automaton']['states']) == 3
    with pytest.raises(LimitExceededError) as e:   # the written-out normal form is still refused
        to_nnf(parse_formula(text))
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED and 'expands to more than' in e.value.message


def test_cli_long_iff_chain_exits_0(capsys):
    assert main(['formula', ' <-> '.join(ATOMS[i % 60] for i in range(199))]) == 0
    assert 'automaton:   3 states' in capsys.readouterr().out


def test_unary_operators_count_towards_nesting():
    # runs of 150 unary operators in four nested parentheses: 600 operators on one path
    text = ('!' * 150 + '(') * 4 + 'a' + ')' * 4
    with pytest.raises(LimitExceededError) as e:
        parse_formula(text)
    assert 'unary operators' in e.value.message


def test_descriptors_nest_at_most_32_levels():
    with pytest.raises(LimitExceededError) as e:
        parse_formula('near[' + 'a::isabove(' * 33 + 'b' + ')' * 33 + ']')
    assert 'descriptors nest deeper than 32' in e.value.message

"""Parser and printer of task formulas: the syntax of spec/formula.md, exactly."""
import json
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.errors import ErrorCode, FormulaSyntaxError, LimitExceededError
from ltl_instruct.core.spec import (
    COMPARATORS, FALSE, TRUE, Always, And, Atom, Descriptor, Eventually, Iff, Implies, Next, Not,
    Or, ParseLimits, Relation, Release, Until, WeakUntil, avoided_referents_of, near,
    parse_descriptor, parse_formula, referents_of,
)

SPEC_EXAMPLES = [
    'F near[coffee_shop] & F near[parking_sign]',
    'F (near[chair::isbetween(green_laptop, yellow_box::isbelow(play_toy))])',
    'F (near[table::isbehind(fridge)] & F (pick[beer] & F (near[couch] & F release[beer, couch])))',
    'F near[blue_couch] & G !near[steel_door]',
    '!near[brown_desk] U near[bookshelf]',
    'F (near[green_plush_toy] & F (pick[green_plush_toy] & F (near[whiteboard::isinfrontof('
    'green_plush_toy)] & !near[robot::isinfrontof(green_plush_toy)] & F release[green_plush_toy, '
    'whiteboard::isinfrontof(green_plush_toy)])))',
]

a, b, c = near('a'), near('b'), near('c')


@pytest.mark.parametrize('text', SPEC_EXAMPLES)
def test_spec_examples_parse_and_round_trip(text):
    f = parse_formula(text)
    assert parse_formula(str(f)) == f


@pytest.mark.parametrize('text, expected', [
    ('a U b U c', Until(a, Until(b, c))),                    # U is right-assoc
    ('a -> b -> c', Implies(a, Implies(b, c))),              # -> is right-assoc
    ('!a U b', Until(Not(a), b)),                            # unary binds tighter than U
    ('F a U b', Until(Eventually(a), b)),
    ('a U b & c', And((Until(a, b), c))),                    # U tighter than &
    ('a & b | c', Or((And((a, b)), c))),                     # & tighter than |
    ('a | b -> c', Implies(Or((a, b)), c)),                  # | tighter than ->
    ('a <-> b', Iff(a, b)),
    ('~a', Not(a)),                                          # both negations
    ('a R b', Release(a, b)),
    ('a W b', WeakUntil(a, b)),
    ('X a', Next(a)),
    ('GF a', Always(Eventually(a))),                         # Spot-style glued unary operators
    ('true & false', And((TRUE, FALSE))),
    ('a', Atom('near', (Descriptor('a'),))),                 # a plain prop means near[prop]
    ('pick[x]', Atom('pick', (Descriptor('x'),))),
    ('release[x, y]', Atom('release', (Descriptor('x'), Descriptor('y')))),
])
def test_precedence_and_associativity(text, expected):
    assert parse_formula(text) == expected


def test_every_comparator_and_arity():
    for comp, arity in COMPARATORS.items():
        args = ', '.join(f'o{i}' for i in range(arity))
        d = parse_descriptor(f'x::{comp}({args})')
        assert d.relations[0].comparator == comp and len(d.relations[0].args) == arity
        wrong = ', '.join(f'o{i}' for i in range(arity + 1))
        with pytest.raises(FormulaSyntaxError):
            parse_descriptor(f'x::{comp}({wrong})')


def test_nested_descriptor_structure():
    d = parse_descriptor('chair::isbetween(laptop, box::isbelow(toy))::isleftof(door)')
    assert d == Descriptor('chair', (
        Relation('isbetween', (Descriptor('laptop'),
                               Descriptor('box', (Relation('isbelow', (Descriptor('toy'),)),)))),
        Relation('isleftof', (Descriptor('door'),))))
    assert d.depth == 2


@pytest.mark.parametrize('text, column, expected', [
    ('F near[a', 9, "','"),
    ('near[a, b]', 1, '1 argument'),
    ('F & a', 3, 'a formula'),
    ('a U', 4, 'a formula'),
    ('near[Sofa]', 6, 'snake_case'),
    ('G !near[door] )', 15, 'end of input'),
    ('pick[x] & foo[y]', 11, "'near'"),
    ('F near[a::isfoo(b)]', 11, 'isbehind'),
    ('near[true]', 6, 'a name'),
    ('(a & b', 7, "')'"),
    ('a $ b', 3, 'operator'),
    ('', 1, 'a formula'),
])
def test_errors_name_column_caret_and_expectation(text, column, expected):
    with pytest.raises(FormulaSyntaxError) as ei:
        parse_formula(text)
    e = ei.value
    assert e.code == ErrorCode.PARSE_ERROR
    assert e.details['column'] == column
    assert expected in e.details['expected']
    lines = e.message.splitlines()
    assert lines[0].startswith(f'line 1, column {column}:')
    assert lines[2].index('^') == 2 + column - 1  # caret under the column


def test_error_on_second_line_names_the_line():
    with pytest.raises(FormulaSyntaxError) as ei:
        parse_formula('F near[a] &\n  G !')
    assert ei.value.details['line'] == 2


@pytest.mark.parametrize('text', [
    'a' * 30_000,
    '(' * 5000 + 'a' + ')' * 5000,
    '!' * 5000 + 'a',
    ' & '.join(f'near[o{i}]' for i in range(100)),
    'F ' * 3000 + 'a',
    'near[' + 'x::isabove(' * 400 + 'y' + ')' * 400 + ']',
])
def test_limits_give_clear_errors_not_crashes(text):
    with pytest.raises(LimitExceededError) as ei:
        parse_formula(text)
    assert ei.value.code == ErrorCode.LIMIT_EXCEEDED


def test_limits_are_configurable():
    parse_formula(' & '.join(f'near[o{i}]' for i in range(100)), ParseLimits(max_atoms=100))


def test_non_text_input_is_a_typed_error():
    with pytest.raises(FormulaSyntaxError):
        parse_formula(None)  # type: ignore[arg-type]


def test_ast_is_immutable_and_hashable():
    f = parse_formula('F near[a] & G !near[b]')
    with pytest.raises(Exception):
        f.operands = ()  # type: ignore[misc]
    assert {f: 1}[parse_formula('F near[a] & G !near[b]')] == 1


def test_referents_and_avoid_lists():
    f = parse_formula(SPEC_EXAMPLES[-1])
    assert [str(d) for d in referents_of(f)] == [
        'green_plush_toy', 'whiteboard::isinfrontof(green_plush_toy)',
        'robot::isinfrontof(green_plush_toy)']
    assert [str(d) for d in avoided_referents_of(f)] == ['robot::isinfrontof(green_plush_toy)']


DEV = Path(__file__).resolve().parents[2] / 'shared' / 'datasets' / 'spatial-temporal-dev' / 'dev.jsonl'


@pytest.mark.skipif(not DEV.exists(), reason='shared datasets not present')
def test_dev_set_formulas_parse_with_their_referents():
    for line in DEV.read_text().splitlines():
        item = json.loads(line)
        f = parse_formula(item['formula'])
        assert parse_formula(str(f)) == f
        assert [str(d).replace(' ', '') for d in referents_of(f)] == item['referents'], item['id']
        assert [str(d).replace(' ', '') for d in avoided_referents_of(f)] == item['avoid'], item['id']


# ---------------------------------------------------------------- round trip (property)

names = st.sampled_from(['a', 'b', 'sofa', 'red_chair', 'p1'])


def descriptors(depth=2):
    base = names.map(Descriptor)
    if depth == 0:
        return base
    sub = descriptors(depth - 1)
    rel = st.sampled_from(sorted(COMPARATORS)).flatmap(
        lambda c: st.tuples(*[sub] * COMPARATORS[c]).map(lambda args: Relation(c, args)))
    return st.one_of(base, st.tuples(names, st.lists(rel, min_size=1, max_size=2)).map(
        lambda t: Descriptor(t[0], tuple(t[1]))))


atoms = st.one_of(
    descriptors().map(lambda d: Atom('near', (d,))),
    descriptors(1).map(lambda d: Atom('pick', (d,))),
    st.tuples(descriptors(1), descriptors(1)).map(lambda t: Atom('release', t)))

formulas = st.recursive(
    st.one_of(atoms, st.sampled_from([TRUE, FALSE])),
    lambda sub: st.one_of(
        st.builds(Not, sub), st.builds(Eventually, sub), st.builds(Always, sub), st.builds(Next, sub),
        st.builds(Until, sub, sub), st.builds(Release, sub, sub), st.builds(WeakUntil, sub, sub),
        st.builds(Implies, sub, sub), st.builds(Iff, sub, sub),
        st.lists(sub, min_size=2, max_size=3).map(lambda xs: And(tuple(xs))),
        st.lists(sub, min_size=2, max_size=3).map(lambda xs: Or(tuple(xs)))),
    max_leaves=12)


def _flat(f):
    """The parser flattens nested & and |: compare modulo that."""
    from ltl_instruct.core.spec.ast import _NAry
    if isinstance(f, _NAry):
        out = []
        for o in f.operands:
            o = _flat(o)
            out.extend(o.operands if type(o) is type(f) else (o,))
        return type(f)(tuple(out))
    kids = f.children()
    if not kids:
        return f
    return type(f)(*[_flat(k) for k in kids])


@settings(max_examples=300, derandomize=True, deadline=None)
@given(formulas)
def test_print_then_parse_gives_the_same_ast(f):
    assert parse_formula(str(f)) == _flat(f)

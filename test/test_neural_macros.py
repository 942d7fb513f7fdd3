"""Task macros of the learned translator's output language (``neural/macros.py``, ``grammar.py``).

Each rewrite must be proved on automata: the tokens read back (``from_prefix``) accept exactly
the traces of the formula written, whichever data set's way of writing the task it was.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.automaton.dfa import equivalent
from ltl_instruct.core.language.neural.generator import generate
from ltl_instruct.core.language.neural.grammar import (
    TOKEN_ID, GrammarState, check_prefix, from_prefix, to_prefix,
)
from ltl_instruct.core.language.neural.macros import lifted_tokens
from ltl_instruct.core.language.task import at_most, exactly
from ltl_instruct.core.spec import parse_formula

A, B, C = 'near[s1]', 'near[s2]', 'near[s3]'


def _exactly_lang2ltl(x: str, n: int) -> str:
    """Lang2LTL's way of writing "exactly n times" (not ours: the macro must be found by meaning)."""
    stay = f'G !{x}'
    for k in range(2 * n):
        stay = f'({x} | G {stay})' if k % 2 == 0 else f'(!{x} | G {stay})'
    visits = x
    for _ in range(n - 1):
        visits = f'{x} & F (!{x} & F ({visits}))'
    return f'({stay}) U ({visits} & ({stay}))'


@pytest.mark.parametrize('text, macro, at_most_tokens', [
    (_exactly_lang2ltl(A, 5), ['exactly', '5'], 4),
    (str(exactly(parse_formula(A), 3)), ['exactly', '3'], 4),
    (f'!F ({A} & ({A} U (!{A} & (!{A} U F ({A} & ({A} U (!{A} & (!{A} U F {A}))))))))', ['atmost', '2'], 4),
    (f'F ({A} & ({A} U (!{A} & (!{A} U F {A}))))', ['atleast', '2'], 4),
    (f'F ({A} & F (!{A} & F ({A} & F (!{A} & F {A}))))', ['atleast', '3'], 4),
    (f'(!{B} U {A}) & (!{C} U {B}) & F {C}', ['ordered'], 8),
    # the rules' way: the sequence written out and every ordering, the chain implied
    (f'F ({A} & F ({B} & F {C})) & (!{B} U {A}) & (!{C} U {B}) & (!{C} U {A})', ['ordered'], 8),
    (f'(!{B} U {A}) & (!{C} U {B}) & F {C} & (!{A} U {A} U !{A} U {B}) & (!{B} U {B} U !{B} U {C})',
     ['strict'], 8),
])
def test_a_task_is_written_as_its_macro(text, macro, at_most_tokens):
    f = parse_formula(text)
    tokens = lifted_tokens(f)
    assert tokens[:len(macro)] == macro
    assert len(tokens) <= at_most_tokens
    assert check_prefix(tokens)
    assert equivalent(from_prefix(tokens), f)


def test_a_chain_is_kept_apart_from_the_rest_of_a_conjunction():
    f = parse_formula(f'G !near[s4] & (!{B} U {A}) & F {B}')
    tokens = lifted_tokens(f)
    assert tokens == ['&', 'ordered', 'near', 's1', 'near', 's2', 'G', '!', 'near', 's4']
    assert equivalent(from_prefix(tokens), f)


@pytest.mark.parametrize('text', [
    f'(!{B} U {A}) & (!{C} U {B})',                     # nothing required: not a chain of visits
    f'(!{B} U {A}) & (!{C} U {A}) & F {B} & F {C}',     # a before b and c, b and c in any order
    f'F ({A} & F (!{A} & F {A})) & G !{B}',             # a count of a, beside something else
    f'{A} U (!{A} U (F {A}))',                         # names a three times, not a count
])
def test_what_is_no_macro_is_written_as_it_is(text):
    f = parse_formula(text)
    tokens = lifted_tokens(f)
    assert equivalent(from_prefix(tokens), f)
    assert not {'ordered', 'strict'} & set(tokens)
    if text.startswith('F ('):
        assert tokens[:3] == ['&', 'atleast', '2']
    elif 'atleast' not in tokens:
        assert tokens == to_prefix(f)


def test_macros_read_back_as_the_task_builders_write_them():
    assert from_prefix(['atmost', '2', 'near', 's1']) == at_most(parse_formula(A), 2)
    assert from_prefix(['exactly', '1', 'near', 's1']) == exactly(parse_formula(A), 1)
    # a chain inside another operator is expanded before the operator takes it
    chain_in_g = parse_formula(f'G ((!{B} U {A}) & F {B})')
    assert from_prefix(['G', 'ordered', 'near', 's1', 'near', 's2']) == chain_in_g


def test_a_count_position_takes_only_a_count():
    state = GrammarState.start().push(TOKEN_ID['atleast'])
    assert sorted(state.allowed(2)) == sorted(TOKEN_ID[str(n)] for n in range(1, 10))
    assert not check_prefix(['atleast', 'near', 's1', '2'])
    assert not check_prefix(['atleast', '2'])


def test_generated_training_formulas_keep_their_meaning():
    checked = 0
    for ex in generate(150, seed=5):
        f = parse_formula(ex.lifted)
        try:
            tokens = lifted_tokens(f)
        except Exception:     # more slots than the decoder has: left out of training, as before
            continue
        assert equivalent(from_prefix(tokens), f), ex.lifted
        checked += 1
    assert checked > 100

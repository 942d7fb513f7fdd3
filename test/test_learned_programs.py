"""Postfix programs: masks give only valid programs; the LTLf checker agrees with the automaton."""
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.semantics import holds
from ltl_instruct.core.language.learned.programs import (
    OutputVocabulary, accepts, allowed_mask, first_acceptance, is_valid_program, program_to_formula,
    stack_effect,
)
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.spec.ast import near

VOCAB = OutputVocabulary(('a', 'b', 'c'))
MAX_LEN = 9


def random_program(rng: np.random.Generator, max_len: int = MAX_LEN) -> tuple[int, ...]:
    """Draw tokens uniformly among those the mask allows until END."""
    effect = stack_effect(VOCAB)
    tokens: list[int] = []
    stack = 0
    while True:
        mask = allowed_mask(VOCAB, np.array([stack]), np.array([len(tokens)]),
                            np.array([tokens[-1] if tokens else -1]), max_len)[0]
        assert mask.any(), 'the mask must never strand a program'
        tok = int(rng.choice(np.flatnonzero(mask)))
        if tok == VOCAB.end_id:
            return tuple(tokens)
        tokens.append(tok)
        stack += int(effect[tok])


@settings(max_examples=300, derandomize=True, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_masked_decoding_only_yields_valid_programs(seed):
    prog = random_program(np.random.default_rng(seed))
    assert 1 <= len(prog) <= MAX_LEN
    assert is_valid_program(VOCAB, prog)
    assert is_valid_program(VOCAB, prog + (VOCAB.end_id,))
    f = program_to_formula(VOCAB, prog)
    assert parse_formula(str(f)) == f or str(parse_formula(str(f))) == str(f)


def test_mask_rules():
    ids = {t: i for i, t in enumerate(VOCAB.tokens)}
    m = allowed_mask(VOCAB, np.array([0, 1, 2, 1, 1]), np.array([0, 1, 2, 2, MAX_LEN]),
                     np.array([-1, ids['a'], ids['b'], ids['F'], ids['G']]), MAX_LEN)
    assert m[0, ids['a']] and not m[0, ids['F']] and not m[0, ids['&']] and not m[0, VOCAB.end_id]
    assert m[1, ids['F']] and m[1, VOCAB.end_id] and not m[1, ids['U']]
    assert m[2, ids['U']] and not m[2, VOCAB.end_id]
    assert not m[3, ids['F']] and not m[3, ids['G']] and m[3, ids['!']] and m[3, ids['X']]  # no F F, F G
    assert m[4].tolist() == [t == VOCAB.end_id for t in range(VOCAB.size)]   # out of room: END only


def test_invalid_programs_are_refused():
    ids = {t: i for i, t in enumerate(VOCAB.tokens)}
    for bad in [(), (ids['F'],), (ids['a'], ids['b']), (ids['a'], ids['&']), (99,)]:
        assert not is_valid_program(VOCAB, bad)


def test_program_to_formula_reads_postfix_in_order():
    ids = {t: i for i, t in enumerate(VOCAB.tokens)}
    prog = (ids['b'], ids['!'], ids['a'], ids['U'], ids['c'], ids['F'], ids['&'])
    assert program_to_formula(VOCAB, prog) == parse_formula('(!b U a) & F c')
    assert VOCAB.text(prog) == 'b ! a U c F &'


def _letters(trace):
    return [frozenset({near(VOCAB.props[v])}) for v in trace]


@settings(max_examples=300, derandomize=True, deadline=None)
@given(st.integers(0, 2**32 - 1), st.lists(st.integers(0, 2), min_size=1, max_size=6))
def test_checker_agrees_with_automaton_and_reference(seed, trace):
    prog = random_program(np.random.default_rng(seed))
    f = program_to_formula(VOCAB, prog)
    aut = compile_automaton(f)
    states = aut.run(_letters(trace))
    first_by_automaton = next((i for i, s in enumerate(states[1:], 1) if s in aut.accepting), None)
    assert first_acceptance(VOCAB, prog, trace) == first_by_automaton
    assert accepts(VOCAB, prog, trace) == holds(f, _letters(trace)) == (states[-1] in aut.accepting)


def test_checker_known_cases():
    ids = {t: i for i, t in enumerate(VOCAB.tokens)}
    a, b, c = 0, 1, 2
    seq = (a, b, c, ids['F'], ids['&'], ids['F'], ids['&'])          # a & F(b & F c)
    assert first_acceptance(VOCAB, seq, (a, c, b, c)) == 4
    assert first_acceptance(VOCAB, seq, (a, c, b)) is None
    nxt = (b, ids['X'])                                              # X b: strong next
    assert not accepts(VOCAB, nxt, (a,)) and accepts(VOCAB, nxt, (a, b))
    always = (c, ids['!'], ids['G'])                                 # G !c
    assert first_acceptance(VOCAB, always, (a, b)) == 1 and not accepts(VOCAB, always, (a, c))

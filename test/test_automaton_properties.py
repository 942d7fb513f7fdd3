"""The automaton earns trust the way LTL tools do.

1. It agrees with a direct recursive evaluator of the semantics on traces.
2. A formula's DFA and its negation's accept no common trace and together accept all.
3. (test_automaton_oracle.py) Its language equals ltlf2dfa+mona's.
Failures are shrunk by hypothesis; shrunk cases live in regressions/automaton_formulas.txt.
"""
import itertools
import random
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

sys.path.insert(0, str(Path(__file__).parent))
from ltl_oracles import all_traces, languages_differ, minimal_states, valid_letters  # noqa: E402

from ltl_instruct.core.automaton import (  # noqa: E402
    compile_automaton, distinguishing_pair, equivalent, holds, on_the_fly_automaton,
)
from ltl_instruct.core.automaton.random_formulas import default_atoms, random_formula  # noqa: E402
from ltl_instruct.core.errors import LimitExceededError  # noqa: E402
from ltl_instruct.core.spec import (  # noqa: E402
    FALSE, TRUE, Always, And, Eventually, Iff, Implies, Next, Not, Or, Release, Until, WeakUntil,
    atoms_of, parse_formula,
)

REGRESSIONS = [line for line in
               (Path(__file__).parent / 'regressions' / 'automaton_formulas.txt').read_text().splitlines()
               if line.strip() and not line.startswith('#')]


def check_against_evaluator(f, max_len_by_atoms=None, random_traces=300, seed=0):
    atoms = atoms_of(f)
    aut = compile_automaton(f)
    letters = valid_letters(atoms) if atoms else [frozenset()]
    n = len(atoms)
    max_len = {0: 6, 1: 6, 2: 6, 3: 4}.get(n, 3) if max_len_by_atoms is None else max_len_by_atoms
    for trace in all_traces(letters, max_len):
        assert aut.accepts(trace) == holds(f, trace), (str(f), [sorted(x.key for x in t) for t in trace])
    rng = random.Random(seed)
    for _ in range(random_traces):  # longer traces over many atoms: sampled
        trace = [rng.choice(letters) for _ in range(rng.randint(1, 6))]
        assert aut.accepts(trace) == holds(f, trace), (str(f), [sorted(x.key for x in t) for t in trace])


def check_negation(f):
    a, b = compile_automaton(f), compile_automaton(Not(f))
    # product search: after >= 1 letter, exactly one of the two must accept
    from collections import deque
    from ltl_instruct.core.automaton.dfa import _cubes_meet
    start = [(x.dst, y.dst) for x in a.edges_from(a.initial) for y in b.edges_from(b.initial)
             if _cubes_meet(x.guard, y.guard)]
    seen, q = set(start), deque(start)
    while q:
        s, t = q.popleft()
        assert (s in a.accepting) != (t in b.accepting), f'{f}: states {s},{t}'
        for x in a.edges_from(s):
            for y in b.edges_from(t):
                p = (x.dst, y.dst)
                if p not in seen and _cubes_meet(x.guard, y.guard):
                    seen.add(p)
                    q.append(p)


@pytest.mark.parametrize('text', REGRESSIONS)
def test_regression_formulas(text):
    f = parse_formula(text)
    check_against_evaluator(f)
    check_negation(f)


def test_seeded_random_formulas_agree_with_evaluator_and_negation():
    rng = random.Random(20261124)
    for _ in range(150):
        atoms = default_atoms(rng.randint(1, 5), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 7))
        check_against_evaluator(f, random_traces=150, seed=rng.randint(0, 10**6))
        check_negation(f)


# hypothesis: small formulas over two atoms (one an event), shrunk on failure
ATOMS = default_atoms(2) + default_atoms(3, events=True)[2:]
leaf = st.sampled_from(list(ATOMS) + [TRUE, FALSE])
formulas = st.recursive(leaf, lambda sub: st.one_of(
    st.builds(Not, sub), st.builds(Eventually, sub), st.builds(Always, sub), st.builds(Next, sub),
    st.builds(Until, sub, sub), st.builds(Release, sub, sub), st.builds(WeakUntil, sub, sub),
    st.builds(Implies, sub, sub), st.builds(Iff, sub, sub),
    st.builds(lambda x, y: And((x, y)), sub, sub), st.builds(lambda x, y: Or((x, y)), sub, sub)),
    max_leaves=6)


@settings(max_examples=200, derandomize=True, deadline=None)
@given(formulas)
def test_hypothesis_formulas_agree_with_evaluator_on_every_trace_up_to_6(f):
    check_against_evaluator(f, max_len_by_atoms=6 if len(atoms_of(f)) <= 2 else 4, random_traces=0)
    check_negation(f)


# ---------------------------------------------------------------- structure

def test_g_is_kept_across_steps():
    aut = compile_automaton('F near[a] & G !near[b]')
    a, b = atoms_of(aut.formula)
    assert not aut.accepts([set(), {a}, {b}])       # b after reaching a still violates
    assert aut.accepts([set(), set(), {a}])
    assert not aut.accepts([{b}, {a}])


def test_events_are_mutually_exclusive():
    aut = compile_automaton('F (pick[x] & release[x, y])')
    assert not aut.is_satisfiable
    with pytest.raises(ValueError):
        aut.step(aut.initial, set(aut.atoms))


def test_guards_are_symbolic_not_enumerated():
    # 12 independent avoidances: 2^12 letters, but the initial state needs only a few cubes
    text = 'F near[goal] & ' + ' & '.join(f'G !near[o{i}]' for i in range(12))
    aut = compile_automaton(text)
    assert aut.num_states == 3
    assert sum(len(e.guard.cubes) for e in aut.edges_from(aut.initial)) <= 16


def test_edges_are_disjoint_and_complete():
    rng = random.Random(7)
    for _ in range(40):
        atoms = default_atoms(3, events=rng.random() < 0.5)
        aut = compile_automaton(random_formula(rng, atoms, 5))
        for s in range(aut.num_states):
            for letter in valid_letters(atoms):
                hits = [e for e in aut.edges_from(s) if e.guard.evaluate(letter)]
                assert len(hits) == 1


def test_accepting_states_sink_and_paths():
    aut = compile_automaton('F (near[a] & F near[b]) & G !near[c]')
    assert aut.is_satisfiable and aut.sink is not None
    paths = aut.accepting_paths()
    assert paths and all(p[-1].dst in aut.accepting for p in paths)
    assert all(e.dst != aut.sink for p in paths for e in p)
    assert len(paths[0]) <= len(paths[-1])
    for e in aut.edges():
        assert e.atoms <= set(aut.atoms)


@pytest.mark.parametrize('text', ['F near[a] & G !near[a]', 'G false', 'false', 'near[a] & !near[a]',
                                  'F (pick[x] & release[x, y])', 'X false'])
def test_unsatisfiable_is_detected(text):
    aut = compile_automaton(text)
    assert not aut.is_satisfiable
    assert aut.accepting_paths() == []


def test_state_limit_is_a_typed_error():
    text = ' & '.join(f'F near[o{i}]' for i in range(12))  # 2^12 subsets of visited
    with pytest.raises(LimitExceededError):
        compile_automaton(text, max_states=100)


def test_equivalence_on_automata():
    assert equivalent('F near[b] & (!near[b] U near[a])', '!near[b] U (near[a] & F near[b])')
    assert equivalent('!F (near[x] & F (!near[x] & F near[x]))',
                      '!near[x] W (near[x] & (near[x] W G !near[x]))')
    assert not equivalent('F near[a]', 'G near[a]')
    assert equivalent('a -> b', '!a | b')
    a, b = compile_automaton('F near[a]'), compile_automaton('F near[a] | F near[b]')
    assert distinguishing_pair(a, b) is not None


def test_brute_force_exhaustive_two_atoms_length_six():
    # the bound taken literally on a formula mixing every operator
    f = parse_formula('(near[a] U X near[b]) -> (G (near[a] W near[b]) <-> F (near[b] R !near[a]))')
    check_against_evaluator(f, max_len_by_atoms=6, random_traces=0)
    assert len(list(itertools.islice(all_traces(valid_letters(atoms_of(f)), 6), 10**6))) == 5460


def test_every_random_dfa_is_minimal():
    rng = random.Random(500)
    for _ in range(200):
        atoms = default_atoms(rng.randint(1, 5), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 8))
        aut = compile_automaton(f)
        assert aut.num_states == minimal_states(aut, valid_letters(atoms_of(f))), str(f)


def test_on_the_fly_automaton_has_the_same_language_and_dead_states():
    rng = random.Random(11)
    for _ in range(80):
        atoms = default_atoms(rng.randint(1, 4), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 7))
        whole, fly = compile_automaton(f), on_the_fly_automaton(f)
        letters = valid_letters(atoms_of(f))
        assert languages_differ(fly, whole, letters) is None, str(f)
        assert fly.is_satisfiable == whole.is_satisfiable
        for trace in all_traces(letters, 3):  # a state is dead exactly when the minimal one is the sink
            a, b = fly.run(trace)[-1], whole.run(trace)[-1]
            assert (fly.distance_to_accepting(a) is None) == (whole.distance_to_accepting(b) is None)


def test_on_the_fly_expands_only_the_states_asked_about():
    goals = [f'F near[a{i}]' for i in range(12)]
    fly = on_the_fly_automaton(' & '.join(['G !near[b]'] + goals))   # 4,097 states when whole
    edges = fly.edges_from(fly.initial)
    assert len(edges) == 4097   # each subset of goals reached at once, and the sink
    assert fly.distance_to_accepting(fly.initial) == 1
    assert all(fly.distance_to_accepting(e.dst) is not None for e in edges if e.dst != fly.sink)
    assert len(fly._edges_of) == 1   # one letter from acceptance is seen without expanding a state
    with pytest.raises(LimitExceededError):
        compile_automaton(' & '.join(goals))   # the whole automaton keeps its state limit

"""Our automata accept the same language as ltlf2dfa + mona, an independent compiler."""
import random
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from ltl_oracles import (  # noqa: E402
    languages_differ, ltlf2dfa_dfa, minimal_states, mona_available, shrink, valid_letters,
)

from ltl_instruct.core.automaton import compile_automaton, on_the_fly_automaton  # noqa: E402
from ltl_instruct.core.automaton.random_formulas import default_atoms, random_formula  # noqa: E402
from ltl_instruct.core.spec import atoms_of, parse_formula  # noqa: E402

pytestmark = pytest.mark.skipif(not mona_available(),
                                reason='ltlf2dfa needs Debian mona (make test installs it as root)')


def _differ(f):
    atoms = atoms_of(f)
    return languages_differ(compile_automaton(f), ltlf2dfa_dfa(f, atoms),
                            valid_letters(atoms) if atoms else [frozenset()])


def test_oracle_is_not_vacuous():
    # the oracle must catch a wrong automaton: compare F a against G a's DFA
    f, g = parse_formula('F near[a]'), parse_formula('G near[a]')
    assert languages_differ(compile_automaton(f), ltlf2dfa_dfa(g, atoms_of(g)),
                            valid_letters(atoms_of(f))) is not None


def test_same_language_as_ltlf2dfa_on_500_random_formulas():
    rng = random.Random(500)
    failures = []
    for i in range(500):
        atoms = default_atoms(rng.randint(1, 5), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 8))
        witness = _differ(f)
        if witness is not None:
            small = shrink(f, lambda g: _differ(g) is not None)
            failures.append(f'{small}   (from #{i}: {f}; trace {witness})')
    assert not failures, 'add the shrunk formulas to regressions/automaton_formulas.txt:\n' + '\n'.join(
        failures)


LARGE = [
    'G !near[b] & ' + ' & '.join(f'F near[a{i}]' for i in range(5)),         # 33 states
    'F (' + ' <-> '.join(f'near[a{i}]' for i in range(9)) + ')',             # 2^8 cubes as a sum of products
    'F (near[s] & F (pick[x] & F (release[x, t] & F (near[u] & F (pick[y] & F release[y, t])))))'
    ' & G !near[d]',
    '(!near[a1] U near[a0]) & (!near[a2] U near[a1]) & (!near[a3] U near[a2]) & F near[a3]',
    'G (near[a] -> X (!near[a] U near[b])) & F (near[a] & X near[c]) & (near[c] R !near[b])',
]


@pytest.mark.parametrize('text', LARGE)
def test_whole_and_on_the_fly_automata_match_mona_on_larger_tasks(text):
    f = parse_formula(text)
    atoms = atoms_of(f)
    letters = valid_letters(atoms)
    mona = ltlf2dfa_dfa(f, atoms)
    whole = compile_automaton(f)
    assert languages_differ(whole, mona, letters) is None
    assert languages_differ(on_the_fly_automaton(f), mona, letters) is None
    assert whole.num_states == minimal_states(whole, letters)

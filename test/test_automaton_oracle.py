"""Our automata accept the same language as ltlf2dfa + mona, an independent compiler."""
import random
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from ltl_oracles import languages_differ, ltlf2dfa_dfa, mona_available, shrink, valid_letters  # noqa: E402

from ltl_instruct.core.automaton import compile_automaton  # noqa: E402
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

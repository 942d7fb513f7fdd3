"""Shared helper of the offline translator's case tests: translate, compare on automata."""
from __future__ import annotations

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.spec import parse_formula

T = OfflineTranslator()


def check_translation(instruction: str, gold: str) -> tuple[str, ...]:
    """Translate ``instruction``, assert it is equivalent to ``gold`` on automata; return the notes."""
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'
    return got.notes

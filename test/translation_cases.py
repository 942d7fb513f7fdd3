"""Shared helper of the translator's case tests: translate, compare on automata.

``T`` is the default translator (``combined``: the rules and the shipped model, the one users
get), so a case checks what a person would be given: a construction the rules no longer spell
out passes when the model reads it. ``RULES`` is the rules alone, for the cases about what they
refuse (the default may then give the model's reading, flagged).
"""
from __future__ import annotations

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.spec import parse_formula

T = make_translator('combined')
RULES = OfflineTranslator()


def check_translation(instruction: str, gold: str) -> tuple[str, ...]:
    """Translate ``instruction``, assert it is equivalent to ``gold`` on automata; return the notes."""
    got = T.translate(instruction)
    want = parse_formula(gold)
    if not equivalent(got.formula, want):
        offered = [a for a in got.extra.get('alternatives', ()) if _same(a, want)]
        raise AssertionError(f'{instruction!r} -> {got.formula} (flagged: {got.extra.get("flagged")}, '
                             f'the rules refused: {"rules_error" in got.extra}, '
                             f'gold offered: {bool(offered)}, alternatives: {got.extra.get("alternatives")})')
    return got.notes


def _same(text: str, want) -> bool:
    """Whether a formula text is equivalent to ``want`` (False when it does not parse)."""
    try:
        return equivalent(parse_formula(text), want)
    except LtlInstructError:
        return False

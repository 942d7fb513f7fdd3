"""The one interface every translator backend implements.

A translator turns an English instruction into a task formula in the syntax of
``spec/formula.md``. Backends (offline, LLM, learned) are chosen by name through
``ltl_instruct.core.language.make_translator``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

from ltl_instruct.core.errors import LimitExceededError
from ltl_instruct.core.spec import Formula, avoided_referents_of, atoms_of, parse_formula, referents_of
from ltl_instruct.core.spec.parser import DEFAULT_LIMITS


@dataclass(frozen=True)
class Translation:
    """The result of translating one instruction.

    Attributes
    ----------
    instruction: the text as given.
    formula: the task formula (immutable AST).
    backend: name of the backend that produced it.
    notes: remarks for the person (assumptions made, parts corrected).
    extra: backend-specific facts (prompt size, retries, beam scores...), JSON-ready.
    """

    instruction: str
    formula: Formula
    backend: str
    notes: tuple[str, ...] = ()
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def referents(self) -> tuple[str, ...]:
        """Skill-argument descriptors, in order of first appearance."""
        return tuple(str(d) for d in referents_of(self.formula))

    @property
    def avoid(self) -> tuple[str, ...]:
        """Descriptors inside the operand of an explicit negation."""
        return tuple(str(d) for d in avoided_referents_of(self.formula))


@runtime_checkable
class Translator(Protocol):
    """A backend: ``translate`` returns a :class:`Translation` or raises ``TranslationError``."""

    name: str

    def translate(self, instruction: str) -> Translation:
        """Translate one instruction."""
        ...


def check_translation_limits(formula: Formula) -> Formula:
    """Return ``formula`` if its text is within the parser's limits, else raise ``LIMIT_EXCEEDED``.

    A translation is sent on as text and parsed again downstream, so a formula the
    parser would refuse (more than 64 atoms, too deep, too long) is refused here,
    not printed.
    """
    n_atoms = len(atoms_of(formula))
    if n_atoms > DEFAULT_LIMITS.max_atoms:
        raise LimitExceededError(
            f'the translation has {n_atoms} distinct atoms; the limit is {DEFAULT_LIMITS.max_atoms}',
            details={'limit': 'max_atoms', 'value': DEFAULT_LIMITS.max_atoms, 'atoms': n_atoms})
    try:
        parse_formula(str(formula))
    except LimitExceededError as e:
        raise LimitExceededError(f'the translation is too large: {e.message}', details=e.details) from None
    return formula

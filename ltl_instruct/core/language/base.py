"""The one interface every translator backend implements.

A translator turns an English instruction into a task formula in the syntax of
``spec/formula.md``. Backends (offline, LLM, learned) are chosen by name through
``ltl_instruct.core.language.make_translator``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

from ltl_instruct.core.spec import Formula, avoided_referents_of, referents_of


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

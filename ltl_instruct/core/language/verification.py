"""The verification dialog: what a person checks before anything moves, and their answer.

For a :class:`Translation` the person sees the referents it extracted, the
ordered English subgoals (from :func:`ltl_instruct.core.automaton.english.describe_task`)
and how the translator read the words (its notes: words left out as chatter, typos
corrected, verbs read as going somewhere), so nothing it assumed moves the robot unseen.
They answer yes, or correct it in words, or type a formula directly;
:func:`classify_reply` says which.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Optional, Sequence

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.spec import Formula, parse_formula

YES = frozenset({'y', 'yes', 'yep', 'yeah', 'ok', 'okay', 'correct', 'right', 'sure', 'go', 'go ahead',
                 'looks good', 'lgtm', 'confirm', 'confirmed', 'fine', 'good'})
NO = frozenset({'n', 'no', 'nope', 'cancel', 'abort', 'stop', 'quit', 'q'})


@dataclass(frozen=True)
class Verification:
    """The text a person checks for one translation.

    Attributes
    ----------
    formula: the formula as printed.
    referents: English noun phrases of the referents.
    avoid: English noun phrases of what is avoided.
    subgoals: ordered English subgoals, then whole-task constraints and notes.
    satisfiable: whether any plan can satisfy the task.
    reading: the translator's notes on how it read the words ("left out 'for me'").
    warnings: the parts of the instruction it could not read, and what it did with them
        (guessed at, or left out); shown first, since the plan may miss what they asked for.
    """

    formula: str
    referents: tuple[str, ...]
    avoid: tuple[str, ...]
    subgoals: tuple[str, ...]
    satisfiable: bool
    reading: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    alternatives: tuple[str, ...] = ()   # other readings of the same words (combined backend)

    def text(self) -> str:
        """Lines to show the person."""
        lines = [f'Task formula: {self.formula}']
        if self.referents:
            lines.append('Referents: ' + '; '.join(self.referents))
        if self.avoid:
            lines.append('Avoid: ' + '; '.join(self.avoid))
        lines.extend(self.subgoals)
        lines.extend(reading_lines(self.reading, self.warnings))
        lines.extend(f'Alternative {k}: {a}' for k, a in enumerate(self.alternatives, 1))
        take = ', "alternative N" to take another reading' if self.alternatives else ''
        lines.append(f'Is this right? Answer yes, correct it in words{take}, '
                     'or type a formula (prefix "formula:").')
        return '\n'.join(lines)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'formula': self.formula, 'referents': list(self.referents), 'avoid': list(self.avoid),
                'subgoals': list(self.subgoals), 'satisfiable': self.satisfiable,
                'reading': list(self.reading), 'warnings': list(self.warnings),
                'alternatives': list(self.alternatives)}


def reading_lines(notes: Sequence[str], warnings: Sequence[str] = ()) -> list[str]:
    """Turn the translator's notes into lines for the person: what it could not read first (``Warning:``)."""
    return [f'Warning: {w}' for w in warnings] + [f'Note: {n}' for n in notes if n not in warnings]


def warnings_of(translation: Translation) -> tuple[str, ...]:
    """Return the notes of a translation on parts it could not read (``extra['unread']``), if any."""
    unread = translation.extra.get('unread', ()) if isinstance(translation.extra, dict) else ()
    return tuple(str(u) for u in unread)


def best_reading_of(error: LtlInstructError, instruction: str, backend: str = 'offline'
                    ) -> Optional[Translation]:
    """Return the best reading a refusal carries (``details['best_reading']``) as a translation, or None.

    The reading leaves out the parts that could not be placed; they become its warnings
    (``extra['unread']``), so the dialog shows them first and the person decides.
    """
    text = error.details.get('best_reading') if isinstance(error.details, dict) else None
    if not isinstance(text, str):
        return None
    try:
        formula = parse_formula(text)
    except LtlInstructError:
        return None
    left_out = [str(u) for u in error.details.get('left_out') or ()] or [error.message]
    return Translation(instruction, formula, backend, (), {'unread': left_out, 'refused': error.message})


def verification_for(translation: Translation | Formula) -> Verification:
    """Build the referents and English subgoals of a translation (the automaton's English)."""
    from ltl_instruct.core.automaton.english import describe_task
    formula = translation.formula if isinstance(translation, Translation) else translation
    reading = translation.notes if isinstance(translation, Translation) else ()
    warnings = warnings_of(translation) if isinstance(translation, Translation) else ()
    alternatives = alternatives_of(translation) if isinstance(translation, Translation) else ()
    desc = describe_task(formula)
    return Verification(desc.formula, desc.referents, desc.avoid,
                        tuple(desc.subgoals) + tuple(desc.throughout) + tuple(desc.notes), desc.satisfiable,
                        tuple(reading), warnings, alternatives)


def alternatives_of(translation: Translation) -> tuple[str, ...]:
    """Return the other readings a translation offers (``extra['alternatives']``), if any."""
    alts = translation.extra.get('alternatives', ()) if isinstance(translation.extra, dict) else ()
    return tuple(str(a) for a in alts)


_ALTERNATIVE_RE = re.compile(r'(?:take |use )?(?:the )?alt(?:ernative)?\s*#?([1-9])')


@dataclass(frozen=True)
class Reply:
    """A person's answer: ``kind`` is ``yes``, ``no``, ``formula``, ``alternative`` or ``correction``."""

    kind: str
    text: str = ''
    formula: Optional[Formula] = None
    index: int = 0   # 1-based, for ``alternative``


def classify_reply(reply: str) -> Reply:
    """Read a person's answer to the verification text.

    ``yes``-like words accept; ``no``-like words cancel; ``formula: ...`` (or text
    that parses as a formula with at least one skill atom) replaces the formula;
    anything else is a correction in words.
    """
    text = ' '.join(reply.strip().split())
    low = text.lower().rstrip('.!')
    if low in YES:
        return Reply('yes')
    if low in NO:
        return Reply('no')
    alt = _ALTERNATIVE_RE.fullmatch(low)
    if alt:
        return Reply('alternative', text, index=int(alt.group(1)))
    body = text[len('formula:'):].strip() if low.startswith('formula:') else text
    if low.startswith('formula:') or any(c in body for c in '[]&|'):
        try:
            return Reply('formula', body, parse_formula(body))
        except LtlInstructError:
            if low.startswith('formula:'):
                raise
    return Reply('correction', text)

"""One training or test example of the learned translator: text, mentions and a lifted formula.

A *mention* is a character span of the instruction that names one thing, with its spatial
description ("the sofa behind the pillar"). Each mention fills a *slot* (``s1``, ``s2``...) of
the *lifted formula*, a formula in the syntax of ``spec/formula.md`` whose descriptors are slot
names (``F (near[s1] & F near[s2]) & G !near[s3]``). Slots are numbered in the order in which
their first mention appears in the text. ``slots`` gives each slot's descriptor in our syntax
(``sofa::isbehind(pillar)``), so that the gold formula is the lifted one with slots replaced.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from ltl_instruct.core.spec import Descriptor, Formula, parse_descriptor, parse_formula, rename_descriptors

SLOT_RE = re.compile(r'^s[1-9][0-9]*$')


@dataclass(frozen=True)
class Mention:
    """A span ``text[start:end]`` naming the thing in ``slot``."""

    start: int
    end: int
    slot: str


@dataclass(frozen=True)
class TaggedExample:
    """An instruction, its mentions, its lifted formula and each slot's descriptor.

    Attributes
    ----------
    text: the instruction as a person would type it.
    lifted: formula text over slot names (``near[s1]``, ``release[s1, s2]``).
    mentions: spans of ``text``, in text order; every slot of ``lifted`` has at least one.
    slots: slot -> descriptor text in our syntax.
    source: where it came from (``generator:<construct>``, ``drone-planning.jsonl:12``).
    conventions: ``(option, value)`` pairs of the conventions its formula follows where they are
        not the defaults (``features.CONVENTIONS``: a data set's reading of words read two ways).
    """

    text: str
    lifted: str
    mentions: tuple[Mention, ...]
    slots: dict[str, str] = field(hash=False)
    source: str = ''
    conventions: tuple[tuple[str, str], ...] = ()

    def formula(self) -> Formula:
        """Return the grounded formula: the lifted one with each slot replaced by its descriptor."""
        lifted = parse_formula(self.lifted)
        mapping = {Descriptor(s): parse_descriptor(d) for s, d in self.slots.items()}
        return rename_descriptors(lifted, mapping)


def check_example(ex: TaggedExample) -> None:
    """Raise ``ValueError`` when the example is inconsistent (spans, slot order, formula)."""
    last = -1
    seen: list[str] = []
    for m in ex.mentions:
        if not (0 <= m.start < m.end <= len(ex.text)) or m.start < last:
            raise ValueError(f'bad or overlapping span {m} in {ex.text!r}')
        if not SLOT_RE.match(m.slot):
            raise ValueError(f'bad slot name {m.slot!r}')
        last = m.end
        if m.slot not in seen:
            seen.append(m.slot)
    if seen != [f's{k}' for k in range(1, len(seen) + 1)]:
        raise ValueError(f'slots not numbered in order of first mention: {seen}')
    used = set(re.findall(r'\bs[1-9][0-9]*\b', ex.lifted))
    if used - set(seen):
        raise ValueError(f'formula slots {sorted(used - set(seen))} have no mention')
    if set(ex.slots) != set(seen):
        raise ValueError(f'slots {sorted(ex.slots)} do not match mentions {seen}')
    ex.formula()

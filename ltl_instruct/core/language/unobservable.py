"""Conditions no task formula can state: events the robot cannot observe, and the clock.

"Wait there until I call you", "go in once the door opens", "stay for ten minutes": a task
formula speaks of places reached, things picked up and put down, so a reader either drops such
a condition or makes a place of it (``near[door_opens]``). Either way the plan does not wait for
it, so the reading goes on **flagged** with a note saying so (:func:`unobservable_conditions`).
The phrases are data (``unobservable.yaml``).
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from pathlib import Path

import yaml

from ltl_instruct.core.language.text import tokenize

_TABLE = Path(__file__).with_name('unobservable.yaml')


@dataclass(frozen=True)
class Condition:
    """One kind of condition no formula states (an entry of ``unobservable.yaml``)."""

    pattern: re.Pattern[str]
    note: str


@functools.lru_cache(maxsize=1)
def table() -> tuple[Condition, ...]:
    """Return the phrases of ``unobservable.yaml``, compiled."""
    entries = yaml.safe_load(_TABLE.read_text(encoding='utf-8'))
    return tuple(Condition(re.compile(e['pattern']), e['note']) for e in entries)


def unobservable_conditions(instruction: str) -> list[str]:
    """Return a note for each condition of the instruction that no task formula can state."""
    text = ' '.join(tokenize(instruction))
    notes: dict[str, str] = {}   # phrase -> note: the first entry naming a phrase speaks for it
    for c in table():
        for m in c.pattern.finditer(text):
            notes.setdefault(m.group(0).strip(), c.note.format(phrase=m.group(0).strip()))
    return list(dict.fromkeys(notes.values()))

"""What an instruction says that no task formula can: places named by where someone is, events, the clock.

A task formula names places of the map, things picked up and put down. Where the person stands
or where the robot started is none of them ("bring me", "come back", "here"), nor is a person's
call, a door opening or the time ("wait there until I call you", "once the door opens", "for ten
minutes"). A reader can only leave such a thing out ("Bring me the cup." picks the cup up; "go to
the shed and come back" ends at the shed; the wait is dropped) or make a place of it
(``near[door_opens]``): a task the person did not ask for, so the reading goes on **flagged**,
with a note saying what the plan leaves out and how to say it (:func:`unstated`). The phrases are
data (``deixis.yaml``); a place the person names ("come back to the porch", "bring it to me, I'm
at the desk") is no such phrase.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import yaml

from ltl_instruct.core.language.text import tokenize
from ltl_instruct.core.spec import Atom, Formula, iter_subformulas, referents_of

_TABLE = Path(__file__).with_name('deixis.yaml')

# "I'm at the desk", "we are in the lounge" (tokenized: "i am", "we are"): the person says where they
# are; the readers make it the place.
_SPEAKER_PLACED = re.compile(r"\b(?:i am|we are)\s+(?:at|in|on|by|near|inside|next|beside|"
                             r"sitting|standing|upstairs|downstairs|over)\b")

# Words that negate a phrase within two words before it ("never go back", "don't come back").
_NEGATIONS = frozenset({'never', 'not', 'no', 'without', 'cannot'})


@dataclass(frozen=True)
class Deixis:
    """One kind of phrase saying what no formula can (an entry of ``deixis.yaml``)."""

    pattern: re.Pattern[str]
    whose: str
    note: str
    picked: bool = False
    unless: Optional[re.Pattern[str]] = None
    negatable: bool = True


@functools.lru_cache(maxsize=1)
def table() -> tuple[Deixis, ...]:
    """Return the phrases of ``deixis.yaml``, compiled."""
    entries = yaml.safe_load(_TABLE.read_text(encoding='utf-8'))
    return tuple(Deixis(re.compile(e['pattern']), e['whose'], e['note'], bool(e.get('picked', False)),
                        re.compile(e['unless']) if e.get('unless') else None, bool(e.get('negatable', True)))
                 for e in entries)


def unstated(instruction: str, formula: Formula) -> list[str]:
    """Return a note for each thing the instruction says that the formula cannot state or leaves out."""
    text = ' '.join(tokenize(instruction))   # the readers' normalisation: "I'm" is "i am", typos fixed
    speaker_placed = bool(_SPEAKER_PLACED.search(text))
    open_pick = _picks_without_release(formula)
    referents = [str(r) for r in referents_of(formula)]
    notes: dict[str, str] = {}   # phrase -> note: the first entry naming a phrase speaks for it
    for entry in table():
        if entry.whose == 'speaker' and speaker_placed or entry.picked and not open_pick or \
                entry.unless is not None and any(entry.unless.search(r) for r in referents):
            continue
        said = next((m for m in entry.pattern.finditer(text)
                     if not (entry.negatable and _negated(text, m.start()))), None)
        if said is not None:
            phrase = said.group(0).strip()
            notes.setdefault(phrase, entry.note.format(phrase=phrase))
    return list(dict.fromkeys(notes.values()))


def _negated(text: str, start: int) -> bool:
    """Tell whether one of the two words before ``start`` negates the phrase."""
    return any(w in _NEGATIONS for w in text[:start].split()[-2:])


def _picks_without_release(formula: Formula) -> bool:
    """Tell whether the formula picks a thing up that it never puts down."""
    atoms = [n for n in iter_subformulas(formula) if isinstance(n, Atom)]
    picked = {a.args[0] for a in atoms if a.skill == 'pick'}
    released = {a.args[0] for a in atoms if a.skill == 'release'}
    return bool(picked - released)

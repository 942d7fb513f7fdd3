"""Graceful degradation of the offline translator: what to do with a clause the rules cannot read.

A long instruction often holds one clause in words no rule was written for ("cool down at
the bench", "wipe down the table"). Failing the whole instruction for it throws away
everything that was read; reading it wrongly moves the robot somewhere it was not sent.
This module decides between the two, by what the words could carry:

- a clause holding a word that constrains the task (a negation, an avoid or stay verb, an
  order or time word, a count: :func:`ltl_instruct.core.language.chatter.carries_constraint`)
  is never dropped nor guessed: the translator still raises ``TranslationError`` naming it,
  since an avoidance or an order silently lost is worse than no plan; so is a correction
  the rules could not apply ("I meant ..."), whose replaced words are unknown;
- otherwise, if the clause ends in places (a noun phrase, or a list of them, after words
  the rules do not know), it is read as going there (:func:`salvage_places`);
- otherwise it is left out.

Either way the clause is recorded as *unread* (:class:`Unread`): the translation's notes say
what was guessed or left out, and the verification dialog shows these first, as warnings,
before the person accepts the plan. The rest of the instruction must stand on its own: an
instruction of nothing but such clauses is still an error.
"""
from __future__ import annotations

import copy
import dataclasses
from dataclasses import dataclass
from typing import Any, Optional, Sequence

from ltl_instruct.core.language import chatter
from ltl_instruct.core.language.phrases import PhraseParser, is_name_word
from ltl_instruct.core.language.text import PUNCT

# Words after which a noun phrase is a place one goes to or acts at ("cool down at the bench").
_PLACE_LEADS = frozenset({'at', 'to', 'by', 'in', 'into', 'on', 'onto', 'near', 'over', 'past', 'toward',
                          'towards', 'inside', 'around', 'through', 'beside', 'up', 'down', 'from'})


# Determiners of the places a robot is sent to ("the bench", "my desk"; "an eye on it" is no place).
_DEFINITE = frozenset({'the', 'my', 'your', 'our', 'his', 'her', 'their', 'this', 'that', 'these', 'those'})


# Words that name people or nothing in particular, not a place ("smile at everyone").
_NO_PLACE = frozenset({'everyone', 'everybody', 'someone', 'somebody', 'anyone', 'anybody', 'nobody',
                       'people', 'him', 'her', 'them', 'us', 'me', 'you', 'it', 'yourself', 'something',
                       'anything', 'everything', 'nothing', 'way', 'time', 'moment', 'while', 'bit', 'best'})


# Words in -s before a verb that are no plural subject ("it is", "this", "always").
_NOT_SUBJECTS = frozenset({'is', 'was', 'has', 'does', 'its', 'this', 'his', 'us', 'always', 'perhaps',
                           'thus', 'plus', 'as', 'yes', 'less', 'unless', 'across', 'towards', 'afterwards',
                           'besides'})


@dataclass(frozen=True)
class Unread:
    """A clause the rules could not read, and what the translator did with it.

    Attributes
    ----------
    words: the clause as read (normalised tokens).
    action: ``'guessed'`` (read as going to the places it names) or ``'left out'``.
    reason: the error the rules raised on it.
    """

    words: str
    action: str
    reason: str

    def note(self) -> str:
        """Say what was done with the clause, for the person."""
        if self.action == 'guessed':
            return f'could not read "{self.words}"; guessed it means going there: check this'
        return f'could not read "{self.words}" and left it out: check nothing is missing'


# Words that may mean keeping away from a place, or holding at one, in words the rules do not read
# ("staying clear of X", "X is off limits", "steer around Y"): a clause holding one is never dropped.
_RISKY = frozenset('''
clear away off limits bounds forbidden prohibited banned restricted dangerous danger hazard hazardous unsafe
careful steer staying keeping dodge dodging bypass bypassing skip skipping evade evading avoid avoiding
avoidance except excluding unless without remain remaining wait waiting hold holding stop stopping stay keep
out outside beyond around toward towards careful risky blocked closed reverse backwards
bring bringing take taking carry carrying deliver delivering fetch fetching put putting throw throwing
grab grabbing
'''.split())   # (a delivery left out would drop a goal: refused instead)


# Words that rule a place out ("X is off limits", "never the hall", "stay away"), but not in the
# phrases after them, which rule nothing out ("straight away", "order does not matter").
_PROHIBITIONS = frozenset('''
not never cannot mustn avoid avoiding limits bounds forbidden prohibited banned away clear
'''.split())
_NOT_PROHIBITIONS = frozenset({('straight', 'away'), ('right', 'away'), ('all', 'clear'), ('not', 'matter'),
                               ('never', 'mind'), ('not', 'care'), ('not', 'mind')})


def rules_out_a_place(tokens: Sequence[str]) -> bool:
    """Whether unread words rule a place out: a reading of the instruction must then avoid something."""
    words = [t for t in tokens if t not in PUNCT]
    return any(w in _PROHIBITIONS and tuple(words[max(k - 1, 0):k + 1]) not in _NOT_PROHIBITIONS
               and tuple(words[k:k + 2]) not in _NOT_PROHIBITIONS for k, w in enumerate(words))


def may_degrade(tokens: Sequence[str]) -> bool:
    """Whether a clause the rules could not read may be guessed at or left out (see the module docstring)."""
    words = [t for t in tokens if t not in PUNCT]
    if any(words[k:k + 2] in (['i', 'meant'], ['i', 'mean']) for k in range(len(words) - 1)):
        return False   # a correction the rules could not apply: what it replaces is unknown
    return bool(words) and not chatter.carries_constraint(words) and not _RISKY & set(words)


def salvage_places(words: Sequence[str], parser: PhraseParser) -> Optional[int]:
    """Where the places a clause ends in start, after words the rules do not know ("cool down at the bench").

    The noun phrase (or list of them) must end the clause (``words``, punctuation removed) and
    start at a determiner or after a preposition of place; None where the clause ends
    otherwise ("keep an eye on it"), or where the place is the object of a subject's verb
    ("repeated door openings disturb the temperature").
    """
    for i in range(len(words)):
        if not (words[i] in _DEFINITE or
                i > 0 and words[i - 1] in _PLACE_LEADS and is_name_word(words, i, False)) or \
                words[i] in _NO_PLACE or words[i + 1:i + 2] and words[i + 1] in _NO_PLACE:
            continue
        if i >= 3 and words[i - 1] not in _PLACE_LEADS and words[i - 2].endswith('s') and \
                words[i - 2] not in _NOT_SUBJECTS:
            return None   # "repeated door openings disturb the temperature": a subject and its verb
        nps, _, end = parser.parse_list(words, i)
        if nps and end == len(words) and not any(np.pronoun for np in nps):
            return i
        if nps:
            return None   # the first place does not end the clause: words after it are not read
    return None


def _copy(value: Any, memo: dict[int, Any]) -> Any:
    """Copy the mutable parts of a reader's state (lists, dicts, steps, the task); share the rest.

    Frozen values (descriptors, noun phrases, formulas, strings) are shared, as a deep copy would
    only duplicate them; a mutable object met twice is copied once (``memo``), so that a field
    pointing at a step of the task points at the same step of the copy.
    """
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    key = id(value)
    if key in memo:
        return memo[key]
    if isinstance(value, list):
        items: list[Any] = []
        memo[key] = items
        items.extend(_copy(v, memo) for v in value)
        return items
    if isinstance(value, tuple):
        return tuple(_copy(v, memo) for v in value)
    if isinstance(value, dict):
        table: dict[Any, Any] = {}
        memo[key] = table
        table.update((k, _copy(v, memo)) for k, v in value.items())
        return table
    if dataclasses.is_dataclass(value) and getattr(value, '__dataclass_params__').frozen:
        return value
    if hasattr(value, '__dict__'):
        out = copy.copy(value)
        memo[key] = out
        vars(out).update((k, _copy(v, memo)) for k, v in vars(value).items())
        return out
    return value


class Snapshot:
    """The state of a reader before a clause, to go back to if the clause cannot be read.

    Parameters
    ----------
    reader:
        The clause reader; its fields are copied deeply, together (a field that points at a step
        of the task points at the same step of the copy), but for its phrase parser, rule reader
        and notes.
    notes:
        The translation's notes, which the reader appends to (restored by truncation).
    """

    # kept as they are (the parser's memory of names is harmless; a refusal recorded stays recorded)
    _SHARED = ('phrases', 'rules', 'notes', 'first_error')

    def __init__(self, reader: Any, notes: list[str]) -> None:
        self._reader = reader
        self._notes = notes
        self._n_notes = len(notes)
        memo: dict[int, Any] = {}
        self._state = {k: _copy(v, memo) for k, v in vars(reader).items() if k not in self._SHARED}

    def restore(self) -> None:
        """Put the reader back as it was when the snapshot was taken (once: the copy becomes the reader's)."""
        vars(self._reader).update(self._state)
        del self._notes[self._n_notes:]

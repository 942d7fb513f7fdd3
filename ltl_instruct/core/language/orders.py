"""Order phrases of the offline translator: how people say that goals come in a given order.

The clause reader reads sequences ("then", "after that") itself; this module recognises the
phrases around them that only say something about the order, so that they can be read
wherever they stand in a sentence:

- *strictness markers*: "and not a second earlier", "but no sooner", "and not before": the
  goal just said to come after another must not be reached before it (``!x U y``);
- *order tails*: "in exactly that sequence", "in the order listed", "in that very order",
  "one by one": the goals listed come one after the other;
- *reverse order*: "in reverse order", "backwards", "the other way round" before or after a
  list of goals: the same goals, last first.

Each function works on a token list and says what it found; none adds a place.
"""
from __future__ import annotations

import re
from typing import Optional, Sequence

from ltl_instruct.core.language.phrases import NounPhrase, PhraseParser

# "and not a second earlier", "not any sooner": the last "X after Y" holds strictly.
_TIME_UNITS = frozenset({'second', 'moment', 'minute', 'instant', 'bit', 'sec', 'step', 'minute'})
_EARLIER = frozenset({'earlier', 'sooner', 'before'})


def is_strict_marker(tokens: Sequence[str]) -> bool:
    """Whether a clause only says that the goal before it must not come any earlier.

    "and not a second earlier", "but no sooner", "not before", "and not one moment before",
    "no earlier than that", "not any sooner".
    """
    words = [t for t in tokens if t not in (',', 'and', 'but', 'though', 'just')]
    if not words or words[0] not in ('not', 'no', 'never'):
        return False
    rest = words[1:]
    if rest[:1] in (['a'], ['one'], ['any'], ['even']):
        rest = rest[1:]
        if rest[:1] and rest[0] in _TIME_UNITS:
            rest = rest[1:]
    if not rest or rest[0] not in _EARLIER:
        return False
    rest = rest[1:]
    return rest in ([], ['that'], ['then'], ['than', 'that'], ['than', 'then'], ['it'])


# Tails that put the goals listed in sequence (beyond the plain "in that order").
ORDER_TAILS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('in', 'exactly', 'that', 'sequence'), ('in', 'exactly', 'this', 'sequence'),
    ('in', 'that', 'sequence'), ('in', 'this', 'sequence'), ('in', 'the', 'same', 'sequence'),
    ('in', 'the', 'order', 'listed'), ('in', 'the', 'order', 'i', 'listed'),
    ('in', 'the', 'order', 'i', 'gave'), ('in', 'the', 'order', 'i', 'said'),
    ('in', 'the', 'order', 'i', 'named'), ('in', 'the', 'order', 'i', 'listed', 'them'),
    ('in', 'the', 'order', 'i', 'gave', 'them'), ('in', 'the', 'order', 'i', 'said', 'them'),
    ('in', 'the', 'order', 'i', 'named', 'them'), ('in', 'the', 'order', 'i', 'mentioned', 'them'),
    ('in', 'the', 'order', 'mentioned'), ('in', 'the', 'order', 'named'), ('in', 'the', 'order', 'stated'),
    ('in', 'the', 'order', 'written'), ('in', 'the', 'order', 'shown'),
    ('in', 'that', 'very', 'order'), ('in', 'this', 'very', 'order'), ('in', 'precisely', 'that', 'order'),
    ('in', 'precisely', 'this', 'order'), ('in', 'exactly', 'the', 'order', 'given'),
    ('in', 'exactly', 'the', 'order', 'listed'), ('in', 'the', 'order', 'i', 'mentioned'),
    ('in', 'turn'), ('in', 'succession'),
    ('following', 'that', 'order'), ('following', 'this', 'order'), ('in', 'that', 'particular', 'order'),
    ('in', 'this', 'particular', 'order'), ('in', 'the', 'above', 'order'),
    ('in', 'the', 'sequence', 'given'), ('in', 'the', 'sequence', 'listed'),
), key=lambda t: -len(t)))

# Words that say a list is to be done last first.
REVERSE: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('in', 'reverse', 'order'), ('in', 'reverse'), ('in', 'the', 'reverse', 'order'),
    ('in', 'reversed', 'order'), ('in', 'the', 'opposite', 'order'), ('in', 'opposite', 'order'),
    ('in', 'backwards', 'order'), ('in', 'backward', 'order'), ('backwards',), ('in', 'reverse', 'sequence'),
    ('last', 'to', 'first'), ('from', 'last', 'to', 'first'), ('starting', 'from', 'the', 'last', 'one'),
    ('starting', 'with', 'the', 'last', 'one'), ('back', 'to', 'front'), ('from', 'back', 'to', 'front'),
    ('end', 'to', 'start'), ('from', 'the', 'end'),
), key=lambda t: -len(t)))


def find_phrase(tokens: Sequence[str], phrases: Sequence[tuple[str, ...]], start: int = 0) -> tuple[int, int]:
    """Return ``(i, j)``: the first of ``phrases`` found in ``tokens[start:]`` spans ``i:j``; ``(-1, -1)``."""
    for i in range(start, len(tokens)):
        for p in phrases:
            if p[0] == tokens[i] and tuple(tokens[i:i + len(p)]) == p:
                return i, i + len(p)
    return -1, -1


_POINTERS = frozenset({'these', 'them', 'those', 'all', 'following', 'the'})


def apply_reverse(tokens: list[str], notes: list[str]) -> list[str]:
    """Rewrite "visit these in reverse order: A, B, C" to "visit C, then B, then A" (noted).

    Only where the list follows the order phrase (after a colon or comma); a list said before
    "in reverse order" is reversed by the clause reader, which sees the phrase after it.
    """
    i, j = find_phrase(tokens, REVERSE)
    if i < 0 or j >= len(tokens) or tokens[j] not in (':', ','):
        return tokens
    nps, joiner, end = PhraseParser().parse_list(tokens, j + 1)
    if len(nps) < 2 or joiner == 'or' or end < len(tokens) and tokens[end] not in '.;!?':
        return tokens
    a = i
    while a > 0 and tokens[a - 1] in _POINTERS:
        a -= 1   # "these", "all of them", "the following"
    items = []
    for np in reversed(nps):
        words = [t for t in tokens[np.start:np.end] if t not in ('the', 'a', 'an')]
        items.append(['the'] + words)
    out: list[str] = []
    for k, words in enumerate(items):
        out += ([',', 'then'] if k else []) + words
    names = ', '.join(' '.join(w[1:]) for w in items)
    notes.append(f'the goals listed are visited in reverse order: {names}')
    return tokens[:a] + out + tokens[end:]


# "X comes after Y", "X has to come before Y", "X is after Y": an order stated as a fact.
_ORDER_VERBS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('comes',), ('come',), ('goes',), ('go',), ('is',), ('are',), ('must', 'come'), ('should', 'come'),
    ('has', 'to', 'come'), ('have', 'to', 'come'), ('needs', 'to', 'come'), ('must', 'be'), ('should', 'be'),
    ('has', 'to', 'be'), ('needs', 'to', 'be'), ('will', 'come'), ('must', 'happen'), ('should', 'happen'),
    ('happens',), ('is', 'visited'), ('gets', 'visited'), ('must', 'be', 'visited'),
    ('should', 'be', 'visited'), ('comes', 'only'), ('is', 'only'), ('only', 'comes'),
    ('only',), ('not',), ('but', 'only'), ('and', 'only'), ('but', 'not'), ('and', 'not'),
), key=lambda t: -len(t)))


_VERB_FIRST = frozenset(v[0] for v in _ORDER_VERBS)


# Words between "after"/"once" and the place: "once you've been to the garage".
_EVENT_SKIP = frozenset({'you', 'have', 'been', 'to', 'visited', 'reached', 'gone', 'seen', 'checked', 'at',
                         'got', 'gotten', 'stopped', 'by', 'the', 'robot', 'has', 'is', 'are', 'done',
                         'finished', 'with', 'passed', 'through', 'surveyed', 'arrived', 'in'})


def order_statement(tokens: Sequence[str], parser: PhraseParser, verbless: bool = False
                    ) -> Optional[tuple[NounPhrase, str, NounPhrase]]:
    """Read "X comes after Y" / "X must come before Y": ``(X, 'after' or 'before', Y)``, else None.

    "X only once you've been to Y" and "X not until Y" are "after". The whole clause must be
    the statement (a trailing "too" aside). With ``verbless``, "the sauna after the pool" is one
    too (a verb said in the clause before: "the gym has to come before the pool, and the
    sauna after the pool").
    """
    if not tokens or tokens[0] not in ('the', 'a', 'an', 'my', 'your', 'our'):
        return None
    # the subject ends where the verb starts (the parser would take "comes" into the name)
    at = next((k for k in range(1, min(len(tokens), 12)) if tokens[k] in _VERB_FIRST and any(
        tuple(tokens[k:k + len(v)]) == v for v in _ORDER_VERBS)), -1)
    verb: tuple[str, ...] = ()
    if at < 0 and verbless:
        at = next((k for k in range(1, min(len(tokens), 12)) if tokens[k] in ('after', 'before')), -1)
    elif at >= 0:
        verb = next(v for v in _ORDER_VERBS if tuple(tokens[at:at + len(v)]) == v)
    if at < 0:
        return None
    x = parser.parse(list(tokens[:at]), 0)
    if x is None or x.pronoun or x.end != at:
        return None
    k = at + len(verb)
    if k < len(tokens) and tokens[k] in ('right', 'just', 'only', 'directly', 'always', 'sometime'):
        k += 1
    if k >= len(tokens) or tokens[k] not in ('after', 'before', 'once', 'when', 'until') or \
            tokens[k] == 'until' and 'not' not in verb or \
            tokens[k] in ('once', 'when') and 'only' not in verb:
        return None
    word = 'after' if tokens[k] in ('once', 'when', 'until') else tokens[k]
    if 'not' in verb and tokens[k] != 'until':   # "the shed not before the barn": after it
        word = 'after' if word == 'before' else 'before'
    k += 1
    while k < len(tokens) and tokens[k] in _EVENT_SKIP and tokens[k] != 'the':
        k += 1
    y = parser.parse(tokens, k)
    if y is None or y.pronoun or not _ends_statement(tokens[y.end:]):
        return None
    return x, word, y


def _ends_statement(rest: Sequence[str]) -> bool:
    """Whether nothing but commas, "too" and "though" follows the last place of an order statement."""
    return all(t in (',', 'too', 'though') for t in rest)


def order_statements(tokens: Sequence[str], parser: PhraseParser
                     ) -> Optional[list[tuple[NounPhrase, str, NounPhrase]]]:
    """Read one order statement, or several joined by "and" ("X before Y, and Z after Y"), else None."""
    one = order_statement(tokens, parser)
    if one is not None:
        return [one]
    k = next((k for k in range(2, len(tokens) - 3) if tokens[k] in ('after', 'before')), -1)
    if k > 0:
        j = k + 1 + (tokens[k + 1] == 'both')
        nps, joiner, end = parser.parse_list(list(tokens), j)
        if len(nps) >= 2 and joiner == 'and' and _ends_statement(tokens[end:]):
            # "the window has to come after the den and the hall": after each of them
            each = [order_statement(list(tokens[:k + 1]) + list(tokens[np.start:np.end]), parser)
                    for np in nps]
            if all(o is not None for o in each):
                return [o for o in each if o is not None]
    for k in range(2, len(tokens) - 3):
        if tokens[k] == 'and' or tokens[k] == ',' and tokens[k + 1] in ('the', 'and'):
            j = k + 1 + (tokens[k + 1] == 'and')
            head = order_statement(tokens[:k], parser)
            if head is not None:
                tail = order_statement(tokens[j:], parser, verbless=True)
                if tail is not None:
                    return [head, tail]
    return None


def phrase_at(tokens: Sequence[str], i: int, phrases: Sequence[tuple[str, ...]]) -> int:
    """Return where the first of ``phrases`` that starts at ``tokens[i]`` ends, or -1."""
    for p in phrases:
        if tuple(tokens[i:i + len(p)]) == p:
            return i + len(p)
    return -1


_REPEAT_RE = re.compile(
    r'^(?:and |then |, )*(?:do|repeat|run|redo|go through|complete|make|perform) '
    r'(?:(?:that|this|it|the|whole|entire|all|of|everything|thing|round|loop|route|circuit|sequence|course|'
    r'trip|tour|lap|run|cycle|set|routine|same|again) )*'
    r'(twice|thrice|(?:one|two|three|four|five|\d+) (?:times|more times|times over)|again|once more|one '
    r'more time|'
    r'a second time|twice over)(?: (?:in a row|over|in total|altogether|total))?(?: please)?$')


def repeat_count(tokens: Sequence[str]) -> Optional[int]:
    """How many times in all "do that whole round twice", "repeat it three times", "do it all again" ask for.

    "again", "once more" and "a second time" mean twice in all; "repeat it twice" is read as
    twice in all, as people say it. None where the clause is not such a request.
    """
    m = _REPEAT_RE.match(' '.join(t for t in tokens if t != ','))
    if m is None:
        return None
    w = m.group(1).split()[0]
    if w in ('again', 'once', 'one', 'a') and m.group(1) not in ('one times',):
        return 2
    counts = {'twice': 2, 'thrice': 3, 'two': 2, 'three': 3, 'four': 4, 'five': 5}
    n = counts.get(w) or (int(w) if w.isdigit() else 0)
    if 'more' in m.group(1):
        n += 1   # "do it two more times": three in all
    return n if 1 < n <= 10 else None

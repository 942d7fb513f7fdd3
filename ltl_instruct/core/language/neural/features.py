"""Between text and the networks: mentions as word-piece tags, and tags back to mentions.

The tagger labels every word piece ``O`` (outside), ``B`` (first piece of a mention) or ``I``
(inside one). Each piece of a mention also carries its slot number (1-based; 0 outside), which
the decoder reads. Tags predicted for a new instruction become mentions again here, and each
mention's words become a descriptor (``the sofa behind the pillar`` -> ``sofa::isbehind(pillar)``)
through the same noun-phrase reader the rules use (``phrases.PhraseParser``: one home for the
relation words). Mentions naming the same descriptor share a slot.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Mapping, Optional, Sequence

from ltl_instruct.core.errors import ErrorCode, TranslationError

from ltl_instruct.core.language.neural.encoder import Pieces
from ltl_instruct.core.language.neural.examples import Mention, TaggedExample
from ltl_instruct.core.language.neural.grammar import MAX_SLOTS

if TYPE_CHECKING:
    from ltl_instruct.core.language.phrases import PhraseParser
    from ltl_instruct.core.spec import Descriptor

TAG_O, TAG_B, TAG_I = 0, 1, 2
N_TAGS = 3
# Conventions where the same words are read two ways (the rules' options of the same names, with
# their defaults): the decoder is told which one an instruction follows, so that data sets that
# read "avoid X" as until the goal (drone-planning) or "after" as a condition (lifted.csv) do not
# contradict the others in training. Each entry: option, default, the other reading.
CONVENTIONS = (('avoid_scope', 'global', 'goal'), ('once_scope', 'run', 'next'),
               ('after_scope', 'goal', 'conditional'))


def convention_vector(options: Mapping[str, str]) -> list[float]:
    """One 0/1 entry per convention of :data:`CONVENTIONS`: 1 where ``options`` picks the other reading.

    Raises ``TranslationError`` (``INVALID_INPUT``) on a value that is neither reading.
    """
    out = []
    for name, default, other in CONVENTIONS:
        value = options.get(name, default)
        if value not in (default, other):
            raise TranslationError(f'{name} must be {default!r} or {other!r}, not {value!r}',
                                   ErrorCode.INVALID_INPUT)
        out.append(1.0 if value == other else 0.0)
    return out


def piece_tags(pieces: Pieces, mentions: Sequence[Mention]) -> tuple[list[int], list[int]]:
    """Tag and slot number of every piece, from gold mentions."""
    tags = [TAG_O] * len(pieces.ids)
    slots = [0] * len(pieces.ids)
    for m in mentions:
        k = int(m.slot[1:])
        if k > MAX_SLOTS:
            continue
        first = True
        for i, (a, b) in enumerate(pieces.offsets):
            if b > a and a >= m.start and b <= m.end:
                tags[i] = TAG_B if first else TAG_I
                slots[i] = k
                first = False
    return tags, slots


@dataclass(frozen=True)
class FoundMention:
    """A mention the tagger found: its span, words, descriptor text and slot."""

    start: int
    end: int
    text: str
    descriptor: str
    slot: str


def spans_from_tags(pieces: Pieces, tags: Sequence[int]) -> list[tuple[int, int]]:
    """Character spans of the mentions in a tag sequence (an ``I`` without ``B`` starts one)."""
    spans: list[list[int]] = []
    prev = TAG_O
    for (a, b), tag in zip(pieces.offsets, tags):
        if b <= a:
            prev = TAG_O
            continue
        if tag == TAG_B or (tag == TAG_I and prev == TAG_O):
            spans.append([a, b])
        elif tag == TAG_I:
            spans[-1][1] = b
        prev = tag
    return [(a, b) for a, b in spans]


_NAME_RE = re.compile(r'[^a-z0-9]+')


def descriptor_of(words: str, landmarks: Sequence[str] = (), digits: bool = False) -> Optional[str]:
    """Descriptor text of a mention's words, or None when they name nothing."""
    from ltl_instruct.core.language.phrases import PhraseParser
    from ltl_instruct.core.language.text import tokenize
    tokens = tokenize(words)
    if not tokens:
        return None
    parser = PhraseParser(landmarks=landmarks, digits=digits)
    phrase = parser.parse(tokens, 0)
    if phrase is not None and phrase.end >= len(tokens) - 1:
        return str(phrase.descriptor)
    if phrase is not None:   # "the cup from the kitchen", "the cup in the kitchen"
        d = _with_source(phrase.descriptor, tokens, phrase.end, parser)
        if d is not None:
            return str(d)
    name = _NAME_RE.sub('_', ' '.join(t for t in tokens if t not in _ARTICLES).lower()).strip('_')
    if not name or not name[0].isalpha():
        return None
    return name


def _with_source(d: Descriptor, tokens: Sequence[str], i: int, parser: PhraseParser) -> Optional[Descriptor]:
    """Return the thing ``d`` with where it is taken from (``tokens[i:]``), as the rules read it, or None.

    A source ("from the closet", "off the couch") is a relation of the thing; a location ("in the
    kitchen") says where to look and is left out of its name, as the rules leave it out.
    """
    from ltl_instruct.core.language.phrases import location_phrase, source_relation
    from ltl_instruct.core.spec import Descriptor
    source = source_relation(tokens, i, parser)
    if source is not None and source[1] >= len(tokens) - 1:
        return Descriptor(d.name, d.relations + (source[0],))
    if location_phrase(tokens, i, parser) >= len(tokens) - 1:
        return d
    return None


_ARTICLES = frozenset({'the', 'a', 'an', 'this', 'that', 'my', 'your', 'our'})


def _name_words(name: str) -> set[str]:
    """Words of a snake_case name, number words as digits ("landmark_one" and "landmark_1" agree)."""
    from ltl_instruct.core.language.text import NUMBER_WORDS
    return {str(NUMBER_WORDS[w]) if w in NUMBER_WORDS else w for w in name.split('_') if w}


def snap_to_landmark(descriptor: str, landmarks: Sequence[str]) -> str:
    """Return the landmark a plain name means, when the map's names are known ("green area" -> green_room).

    The landmark sharing the most words with the name, if it shares at least half of its own
    words and no other landmark shares as many; otherwise the name as said. Descriptors with
    relations are kept as they are.
    """
    if not landmarks or descriptor in landmarks or '::' in descriptor:
        return descriptor
    words = _name_words(descriptor)
    scored = sorted(((len(words & _name_words(lm)) / len(_name_words(lm) or {''}), lm) for lm in landmarks),
                    reverse=True)
    best, name = scored[0]
    if best >= 0.5 and (len(scored) == 1 or scored[1][0] < best):
        return name
    return descriptor


def mentions_from_tags(text: str, pieces: Pieces, tags: Sequence[int], landmarks: Sequence[str] = (),
                       digits: bool = False) -> list[FoundMention]:
    """Mentions of a tagged text; the same descriptor gets the same slot, numbered by first mention."""
    out: list[FoundMention] = []
    slot_of: dict[str, str] = {}
    for a, b in spans_from_tags(pieces, tags):
        a, b = _whole_words(text, a, b)
        words = text[a:b]
        d = descriptor_of(words, landmarks, digits)
        if d is None:
            continue
        d = snap_to_landmark(d, landmarks)
        if d not in slot_of:
            if len(slot_of) >= MAX_SLOTS:
                continue
            slot_of[d] = f's{len(slot_of) + 1}'
        out.append(FoundMention(a, b, words, d, slot_of[d]))
    return out


def _whole_words(text: str, a: int, b: int) -> tuple[int, int]:
    """Widen a span to the words it touches.

    A mention tagged on a word's first pieces ("v" of "vvv") names the whole word.
    """
    while a > 0 and text[a - 1].isalnum():
        a -= 1
    while b < len(text) and text[b].isalnum():
        b += 1
    return a, b


def slot_numbers(pieces: Pieces, mentions: Sequence[FoundMention]) -> list[int]:
    """Slot number of every piece (0 outside mentions), for found mentions."""
    return piece_tags(pieces, [Mention(m.start, m.end, m.slot) for m in mentions])[1]


def example_tags(ex: TaggedExample, pieces: Pieces) -> tuple[list[int], list[int]]:
    """Gold tags and slot numbers of a training example."""
    return piece_tags(pieces, ex.mentions)

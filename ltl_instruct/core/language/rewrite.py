"""Token rewrites before clause reading: list positions and self-corrections.

Both are resolved by rewriting the token list, so the clause reader only ever
sees the final intent:

- "There's an umbrella, a backpack and a pair of boots. Bring the first one to
  the coat rack." -> "bring the umbrella to the coat rack" (also "the last two",
  "the middle one", "the other two", "the one right before the plant", "them in
  reverse order").
- "Go to the fridge - no wait, I meant the freezer." -> "go to the freezer";
  "forget the garage, do the laundry room instead"; "never mind the avoiding
  part"; "the couch is fine"; "scratch that, twice is enough"; "do it the
  other way round".
"""
from __future__ import annotations

import re
from typing import Optional

from ltl_instruct.core.errors import TranslationError
from ltl_instruct.core.language import chatter
from ltl_instruct.core.language.phrases import (
    COLOURS, DETERMINERS, NAME_VERBS, PLACEHOLDER_ADJECTIVES, STOPWORDS, NounPhrase, PhraseParser,
    is_name_word, match_relation, singular,
)
from ltl_instruct.core.language.text import NUMBER_WORDS, ORDINALS, PUNCT, bare_label, is_label
from ltl_instruct.core.spec import Descriptor

_LIST_INTROS = frozenset({'see', 'has', 'have', 'is', 'are', ':', 'of', 'list', 'here', 'got', 'spot',
                          'notice', 'find', ',', 'from', 'among', 'options', 'choices', 'pass', 'out', 'pass',
                          'passing', 'past', 'remember', 'you', 'at'})
_LIST_END = frozenset({':', '.', ',', ';', '!', '?', 'here', 'lying', 'from', 'in', 'around', 'on', 'over',
                       'there', '-', 'are', 'sit', 'stand', 'lie', 'out', 'about', 'lying', 'sitting',
                       'standing', 'nearby', 'available', 'left', 'waiting', 'close', 'by', 'at', 'near',
                       'i', 'we', 'that', 'you', 'parked', 'lined', 'for', 'which', 'earlier', 'were', 'was',
                       'yesterday', 'along', 'against', 'under', 'behind', 'beside', 'inside', 'up',
                       'down', 'my', 'our', 'each'})   # "the vase, the candle and the frame I showed you?"
# ("a hairbrush and a little china dog my mother gave me": who gave it, a clause of its own)
# Words that say where the listed things are ("... out in the corridor", "... by the door").
_WHERE_LISTED = frozenset({'out', 'in', 'on', 'over', 'at', 'by', 'around', 'along', 'inside', 'under',
                           'behind', 'beside', 'near', 'outside', 'down', 'up', 'lying', 'sitting',
                           'standing', 'parked'})
# Nouns that only stand for a listed thing after a position word ("the second place I mentioned").
_POSITION_NOUNS = frozenset({'one', 'item', 'thing', 'place', 'spot', 'stop', 'location', 'object', 'option',
                             'destination', 'choice', 'point', 'bit'})
_REF_WORDS = frozenset(ORDINALS) | {'last', 'middle', 'other', 'others', 'remaining', 'reverse', 'before',
                                    'after', 'former', 'latter', 'them', 'all'}


# What may follow "all" that makes it mean the whole list ("all of them", "all three", "them all").
_ALL_OF = frozenset({'of', 'two', 'three', 'four', 'five', 'in', 'them', 'those', 'these', '.', ','})


def _refers_to_list(tail: list[str]) -> bool:
    """Whether words after a list point into it ("the second one", "all three"; not "all I need is")."""
    return any(t in _REF_WORDS and not (t == 'all' and k + 1 < len(tail) and tail[k + 1] not in _ALL_OF and
                                        tail[k - 1:k] != ['them'])
               for k, t in enumerate(tail))


def _np_text(tokens: list[str], np: NounPhrase) -> list[str]:
    span = tokens[np.start:np.end]
    while span and span[0] in DETERMINERS:
        span = span[1:]
    return ['the'] + span


_LEAD_ADVERBS = frozenset({'earlier', 'before', 'so', 'ok', 'okay', 'now', 'also', 'again', 'well', 'right',
                           'first', 'today', 'yesterday', 'above', 'previously', 'already'})


def _find_list(tokens: list[str]) -> Optional[tuple[int, int, list[NounPhrase], str]]:
    """Find the first enumeration of three (or two, with "and") noun phrases, and its category."""
    parser = PhraseParser()
    starts = [0] + [i + 1 for i, t in enumerate(tokens) if t in _LIST_INTROS]
    # "I left a notebook, a pen and a ruler...": after a pronoun subject and its verb
    # "earlier I mentioned a, b and c", "I have left a, b, c", "in the garage I keep a, b, c"
    starts += [i + 2 + (tokens[i + 1:i + 2] in (['have'], ['had'], ['just'], ['also']))
               for i, t in enumerate(tokens) if t in ('i', 'we', 'they') and (
        i == 0 or tokens[i - 1] in PUNCT or tokens[i - 1] in _LEAD_ADVERBS and (
            i == 1 or tokens[i - 2] in PUNCT) or tokens[i + 1:i + 2] in (
            ['keep'], ['have'], ['left'], ['stored'], ['parked'], ['own'], ['got']))]
    # "painters are in the east hallway, the lobby and the stairwell": the places where something is
    starts += [i + 1 for i, t in enumerate(tokens) if t in ('in', 'at') and i > 1 and tokens[i - 1] in (
        'are', 'is', 'were', 'was')]
    lead = next((k for k, t in enumerate(tokens) if t not in _LEAD_ADVERBS and t != ','), 0)
    if lead:
        starts.append(lead)   # "ok so the fridge, the microwave, the toaster. go to the last one"
    starts.sort()
    for s in starts:
        if s >= len(tokens):
            continue
        if tokens[s] in chatter.PREPOSITIONS or tokens[s] in ('about', 'for'):
            continue   # "the bins I told you about, the red one and ...": no list starts at "about"
        nps, joiner, end = parser.parse_list(tokens, s)
        if len(nps) > 3 and tokens[end:end + 1] in (['them'], ['these'], ['those'], ['all']) and \
                nps[-1].end == nps[-1].start + 1 and tokens[nps[-2].end:nps[-1].start] == [',']:
            # "the pass, the bar, the host stand - hit them in reverse order": a verb, no fourth item
            end = nps[-1].start - 1
            nps = nps[:-1]
        if len(nps) < 3 and not (len(nps) == 2 and joiner == 'and'):
            continue
        if end < len(tokens) and tokens[end] not in _LIST_END and not (
                # "the pharmacy the lab and the blood bank go to the third one": the request said right
                # after the list, as speech runs on (a position in it is named)
                (tokens[end] in _VERBS or tokens[end] in chatter.HESITATIONS) and
                _refers_to_list(tokens[end:]) and (s == 0 or tokens[s - 1] in PUNCT or
                                                   tokens[s - 1] in ('is', 'are', 'there') or all(
                    t in ('okay', 'ok', 'so', 'right', 'well', 'now', 'um', 'uh', 'er', 'erm', ',')
                    for t in tokens[:s])) and
                all(t not in PUNCT for t in tokens[s:end] if t != ',')) and not (
                # "carousels 3, 5, 7 and 9 need inspection": numbered things (not "the lamps and the rugs")
                tokens[end] in ('need', 'needs') and (len(nps) > 2 or all(
                    np.descriptor.name.rpartition('_')[2].isdigit() for np in nps))) and not (
                # "a lamp, a kettle and a dryer to return": what is to be done with them
                tokens[end] == 'to' and len(nps) >= 3 and tokens[end + 1:end + 2] != [] and
                tokens[end + 1] not in DETERMINERS):
            continue
        colon = next((k for k in range(end + 1, len(tokens)) if tokens[k] in PUNCT), 0)
        if end < len(tokens) and tokens[end] == ',' and colon and tokens[colon] == ':' and colon - end < 5:
            continue   # "trampoline, pool, swing set: ...": the list goes on in words not read as a name
        if tokens[nps[0].end:nps[0].end + 1] == [','] and any(
                t in NUMBER_WORDS and t != 'one' for t in tokens[s:nps[0].end]):
            continue   # "name two rooms, the den and the study": the count names the list that follows
        # the category before a colon: "three chairs: a red one by the desk, ..."
        category = ''
        if s >= 2 and tokens[s - 1] == ':' or s >= 3 and tokens[s - 1] == ',' and \
                tokens[s - 3] in NUMBER_WORDS:
            category = singular(tokens[s - 2])   # "three chairs: a red one...", "two doors, a red one..."
            # ("3 printers on this floor: the color one, ...": the count said in digits)
            q = next((q for q in range(s - 2, max(-1, s - 8), -1) if tokens[q] in NUMBER_WORDS or
                      tokens[q].isdigit() and len(tokens[q]) == 1), -1)
            counted = parser.parse(tokens, q + 1) if q >= 0 else None
            if counted is not None and counted.end <= s - 1:
                category = _kind_name(counted)   # "three bins by the gate: a green one, ..."
        elif s >= 2 and tokens[s - 1] == 'are' and tokens[s - 2].endswith('s'):
            # "storage rooms are A, B and C": the kind said before "are"
            back = max((k for k in range(s - 1) if tokens[k] in PUNCT), default=-1)
            kind = parser.parse(tokens, back + 1)
            if kind is not None and kind.end == s - 1 and not kind.descriptor.relations:
                category = _kind_name(kind)
        elif s >= 4 and tokens[s - 1] == 'are':
            # "the escalators I'm worried about are number 1, number 4 and number 6": the kind, then
            # who said it
            back = max((k for k in range(s - 1) if tokens[k] in PUNCT), default=-1)
            kind = parser.parse(tokens, back + 1)
            if kind is not None and not kind.descriptor.relations and kind.head.endswith('s') and \
                    kind.end < s - 2 and tokens[kind.end] in ('i', 'we', 'you', 'that', 'which') and \
                    not set(tokens[kind.end:s - 1]) & chatter.PLACE_RULE_WORDS:
                category = _kind_name(kind)
        elif s >= 2 and tokens[s - 1] == ',' and s != lead:
            # "two carts in the corridor, a housekeeping cart and a minibar cart": the count names them
            back = max((k for k in range(s - 1) if tokens[k] in PUNCT), default=-1)
            q = next((q for q in range(s - 2, back, -1) if tokens[q] in NUMBER_WORDS and tokens[q] != 'one' or
                      tokens[q].isdigit() and len(tokens[q]) == 1 and tokens[q] != '1'), -1)
            counted = parser.parse(tokens, q + 1) if q >= 0 else None
            if counted is None or counted.end > s - 1 or _count_of(tokens[q]) != len(nps):
                continue
            category = _kind_name(counted)
        return s, end, nps, category
    return None


def _the_described_one(tokens: list[str], nps: list[NounPhrase], tail: list[str], category: str) -> list[str]:
    """Name in full "the blue one" of a scene list ("a red one by the desk, a blue one by the door").

    Only where one listed thing alone has the word: "the blue chair by the door", the place it
    was described by kept.
    """
    items = [[category if w == 'one' else w for w in _np_text(tokens, np)] for np in nps]
    out: list[str] = []
    k = 0
    while k < len(tail):
        if k + 2 < len(tail) and tail[k] in DETERMINERS and tail[k + 2] == 'one':
            word = tail[k + 1]
            hits = [it for it in items if word in it[1:2]]
            if len(hits) == 1:
                out += hits[0]
                k += 3
                continue
        out.append(tail[k])
        k += 1
    return out


def _kind_name(counted: NounPhrase) -> str:
    """Return the kind a count names, as one word ("two shopping carts": shopping_cart)."""
    words = counted.descriptor.name.split('_')
    if words[-1] != counted.head:
        return singular(counted.head)
    return '_'.join(words[:-1] + [singular(words[-1])])


def _count_of(word: str) -> int:
    return NUMBER_WORDS.get(word, int(word) if word.isdigit() else 0)


_MENTIONED: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('i', 'mentioned'), ('i', 'just', 'mentioned'), ('i', 'said'), ('i', 'listed'), ('i', 'named'),
    ('i', 'described'), ('i', 'told', 'you', 'about'), ('you', 'saw'), ('we', 'talked', 'about'),
    ('on', 'the', 'list'), ('in', 'the', 'list'), ('from', 'the', 'list'), ('from', 'before'),
    ('i', 'listed', 'earlier'), ('i', 'mentioned', 'earlier'), ('i', 'mentioned', 'before'),
    ('on', 'this', 'list'), ('on', 'that', 'list'), ('in', 'this', 'list'), ('of', 'the', 'list'),
    ('of', 'this', 'list'), ('i', 'listed', 'first'), ('i', 'named', 'first'), ('i', 'mentioned', 'first'),
    ('of', 'these'), ('of', 'those'), ('of', 'the', 'following'), ('in', 'the', 'following', 'list'),
), key=lambda t: -len(t)))


def _drop_mentions(tail: list[str]) -> list[str]:
    """Remove "(that) I mentioned" after a position word: "the second item I mentioned".

    ("The one I named first" is the first one already: see :func:`_say_positions`.)
    """
    out: list[str] = []
    i = 0
    while i < len(tail):
        out.append(tail[i])
        i += 1
        if out[-1] in _POSITION_NOUNS or out[-1] in ORDINALS or out[-1] in (
                'last', 'latter', 'former', 'middle', 'things', 'items', 'ones', 'places', 'spots', 'stops'):
            j = i + (1 if i < len(tail) and tail[i] in ('that', 'which') else 0)
            for m in _MENTIONED:
                if tuple(tail[j:j + len(m)]) == m:
                    i = j + len(m)
                    break
    return out


_POSITION_SAID = tuple((re.compile(p), r) for p, r in (
    # "visit number two and then number three": the second one, the third one
    (r'\b(?P<v>visit|to|check|then|and|survey|inspect|grab|take|bring|avoid|get|fetch|pick|put|move) '
     r'(?:number|item|stop|no) (?P<n>one|two|three|four|five|six)\b', lambda m: m.group('v') + ' the ' + {
         'one': 'first', 'two': 'second', 'three': 'third', 'four': 'fourth', 'five': 'fifth',
         'six': 'sixth'}[m.group('n')] + ' one'),
    # "whichever I mentioned last", "the one I said first"
    (r'\b(?:whichever|whatever|the one|the thing|the item)(?: one)? (?:i|you) '
     r'(?:mentioned|said|named|listed) '
     r'(?P<w>last|first|second|third|fourth|fifth)\b', r'the \g<w> one'),
    # "whatever comes after the notice board"
    (r'\b(?:whatever|whichever|what|the one that|the one which) (?:comes|is|sits|stands) '
     r'(?P<w>right after|after|right before|before|next to) '
     r'(?=the\b)', r'the one \g<w> '),
    # "I'm looking at a barn, a silo and a tractor": the list of a scene
    (r'(?:^|(?<=[.;!?] ))(?:i am|we are) (?:looking at|seeing|facing|in front of) '
     r'(?=(?:a|an|two|three|some) )',
     'there is '),
    # "i see a hat a scarf and some gloves", "my hoodie my backpack and my shoes": a list said without commas
    (r'\b(?P<a>(?:a|an|some|the|my|our|your) [a-z]+(?: [a-z]+)?) (?=(?:a|an|some|the|my|our|your) [a-z]+'
     r'(?: [a-z]+)? (?:(?:a|an|some|the|my|our|your) [a-z]+(?: [a-z]+)? )*and (?:a|an|some|the|my|our|your) '
     r'[a-z]+)',
     lambda m: m.group('a') + (' , ' if not set(m.group('a').split()[1:]) & _NOT_LISTED else ' ')),
    # "backwards from how I said them", "in the opposite order to the way I listed them": the order said
    (r'\b(?P<r>in reverse order|in the reverse order|in the opposite order|in opposite order|in reverse|'
     r'backwards|back to front) (?:from|to|of|compared to) (?:how|the way|the order|what) (?:i|we) '
     r'(?:said|listed|named|gave|mentioned|wrote|read)(?: (?:them|it|those|these|that))?'
     r'(?: (?:out|down|to you|before|earlier))?\b', r'\g<r>'),
    # "in the reverse of that order", "last to first", "backwards": in reverse order
    (r'\b(?:in the reverse of that order|in the opposite order|in reverse|from last to first|last to first|'
     r'backwards|back to front)(?! order)\b', 'in reverse order'),
    # "the one in between", "the one in (the) middle": the middle one
    (r'\bthe one in (?:between|(?:the )?middle)\b', 'the middle one'),
    # "do them backwards, gate first": the last thing listed said again as the start (it was merged
    # with the first thing, "bathroom_gate")
    (r'\bin reverse order (?:, |- )(?:(?:so |i e )?(?:the )?(?P<x>[a-z]+(?: [a-z]+){0,2}) first|'
     r'(?:starting|beginning|start|begin) (?:with|at|from) (?:the )?(?P<y>[a-z]+(?: [a-z]+){0,2}))'
     r'(?= [.;!?]|$)',
     lambda m: 'in reverse order' if _last_listed(m.string[:m.start()], m.group('x') or m.group('y'))
     else m.group(0)),
    # "start from the last one and finish on the first one" after a list: the list in reverse order
    (r'(?:^|(?<=[.;!?] ))(?:and |so |now )?(?:start|begin)(?:ing)? (?:from|with|at|on) the last(?: one)?'
     r'(?: ,)?(?: (?:and |then )?(?:finish|end)(?:ing)? (?:on|with|at|in) the first(?: one)?)?(?= [.;!?]|$)',
     'do them in reverse order'),
    # "the first and last of those": the first and the last
    (r'\bthe (?P<a>first|second|third) and (?P<b>last|second|third|fourth|fifth)\b'
     r'(?! (?:things|ones|items|places|stops|one|two)\b)', r'the \g<a> and the \g<b>'),
    # "the outer two": the first and the last
    (r'\bthe (?:outer|outside|two outer|end) (?:two|ones|two ones)\b', 'the first one and the last one'),
))


_LAST_LISTED = re.compile(r'\band (?:the |a |an |my |our )?([a-z ]+?) [.;:!?] ')


def _last_listed(before: str, said: str) -> bool:
    """Whether ``said`` ends the last thing of the last list in ``before`` ("..., the lift and the gate")."""
    found = _LAST_LISTED.findall(before + ' ')
    return bool(found) and found[-1].split()[-1] == said.split()[-1]


# Words that end no listed thing ("go to the first one and avoid the other two").
_NOT_LISTED = frozenset('''
one ones first second third last other two three and or then go to visit avoid bring take put is are of
between in on near by behind under next at from into onto beside above below with for over inside outside
left right front that which there here it them up down away
'''.split())


def _say_positions(tokens: list[str]) -> list[str]:
    """Say list positions the way the resolver reads them ("number two" is "the second one")."""
    if not {'number', 'item', 'stop', 'no', 'mentioned', 'said', 'named', 'listed', 'comes', 'outer',
            'outside', 'end', 'is', 'sits', 'stands', 'looking', 'seeing', 'facing', 'front', 'and',
            'reverse', 'opposite', 'backwards', 'between', 'last'} & set(tokens):
        return tokens
    text = ' '.join(tokens)
    new = text
    for pattern, repl in _POSITION_SAID:
        new = pattern.sub(repl, new)
    return new.split() if new != text else tokens


def _names_label(words: list[str], k: int) -> bool:
    """Whether the number ``words[k]`` labels the noun before it ("then aisle 3"), no list position."""
    before = words[k - 1] if k > 0 else ''
    return before.isalpha() and before not in _NOT_LABELLING


# Words before a number that make it a position in a list ("number 2", "item 3").
_POSITION_WORDS = frozenset({'number', 'item', 'stop', 'no', 'point', 'step', 'entry', 'line', 'option',
                             'choice', 'thing', 'place'})


_WHERE_WORDS = frozenset({'on', 'by', 'in', 'under', 'behind', 'next', 'near', 'beside', 'above', 'below',
                          'inside', 'at', 'against', 'outside', 'underneath', 'beneath'})
# Words that may stand for the kind of a thing listed before ("another on the windowsill", "a third one").
_KIND_AGAIN = frozenset({'another', 'one', 'second', 'third', 'fourth'})


def _say_kind_again(tokens: list[str]) -> list[str]:
    """Name the kind of "another", "one", "a third" in a list of things told apart by where they are.

    "there's a cup on the desk, another on the windowsill and one under the chair": each is a cup.
    """
    if not _KIND_AGAIN & set(tokens):
        return tokens
    out = list(tokens)
    kind = ''
    k = 0
    while k < len(out):
        t = out[k]
        if t in '.;!?':
            kind = ''
        elif t in ('a', 'an') and k + 2 < len(out) and out[k + 2] in _WHERE_WORDS and \
                out[k + 1] not in ORDINALS and out[k + 1] not in ('one', 'another', 'other') and \
                is_name_word(out, k + 1, False) and not kind:
            kind = out[k + 1]   # "a cup on the desk"
        elif kind and k > 0 and out[k - 1] in (',', 'and'):
            said = 2 if out[k:k + 2] == ['another', 'one'] or out[k] == 'a' and out[k + 1:k + 2] and \
                out[k + 1] in ('second', 'third', 'fourth') else 1 if out[k] in ('another', 'one') else 0
            if said == 2 and out[k] == 'a' and out[k + 2:k + 3] == ['one']:
                said = 3   # "a third one under the stairs"
            if said and out[k + said:k + said + 1] and out[k + said] in _WHERE_WORDS:
                out[k:k + said] = ['a', kind]
                k += 2
                continue
        k += 1
    return out


# What may follow "the second item" and say it is one of those listed before ("... I mentioned").
_LISTED_TAILS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('i', 'mentioned'), ('i', 'said'), ('i', 'listed'), ('i', 'named'), ('i', 'gave', 'you'),
    ('you', 'visited'), ('you', 'went', 'to'), ('on', 'the', 'list'), ('from', 'the', 'list'),
    ('in', 'the', 'list'), ('on', 'that', 'list'), ('from', 'before'), ('from', 'earlier'),
    ('i', 'just', 'mentioned'), ('i', 'just', 'said'), ('mentioned',), ('listed',),
    ('i', 'mentioned', 'earlier'), ('i', 'mentioned', 'before'), ('i', 'mentioned', 'first'),
), key=lambda t: -len(t)))


def _refer_to_goals_listed(tokens: list[str], notes: list[str]) -> list[str]:
    """Resolve "the second item I mentioned" to the second of the places listed before it.

    "go to the den, the hall and the garage, then return to the second item I mentioned": the
    list is the goals themselves (no scene list before), so the reference is to them. Only a
    position noun after the ordinal ("item", "one", "place"...) with nothing left unread; a
    position past the list's end is a :class:`TranslationError`.
    """
    parser = PhraseParser()
    for r in range(1, len(tokens) - 1):
        if tokens[r - 1] != 'the' or not (tokens[r] in ORDINALS or tokens[r] in ('last', 'middle')) or \
                tokens[r + 1] not in _POSITION_NOUNS:
            continue
        end = r + 2
        tail = next((t for t in _LISTED_TAILS if tuple(tokens[end:end + len(t)]) == t), ())
        end += len(tail)
        if tokens[r + 1] != 'item' and not tail or r > 1 and tokens[r - 2] in _RETRACT_VERBS | _CANCEL:
            continue   # "the second one" alone: the list readers' part; "ignore the last thing": a correction
        if end < len(tokens) and tokens[end] not in PUNCT and \
                tokens[end] not in ('and', 'then', 'please', 'again', 'too'):
            continue
        listed = _last_list_before(parser, tokens, r - 1)
        if len(listed) < 2:
            if tail or tokens[r + 1] == 'item':
                said = ' '.join(tokens[r - 1:end])   # "the first item on the list" is no place's name
                raise TranslationError(f'"{said}": found no list of places before it', details={'part': said})
            continue
        n = len(listed) if tokens[r] == 'last' else (len(listed) + 1) // 2 if tokens[r] == 'middle' \
            else ORDINALS[tokens[r]]
        said = ' '.join(tokens[r - 1:end])
        if tokens[r] == 'middle' and len(listed) % 2 == 0 or n > len(listed):
            raise TranslationError(f'"{said}": the list before it has {len(listed)} places',
                                   details={'part': said})
        np = listed[n - 1]
        notes.append(f'"{said}" read as "{" ".join(tokens[np[0]:np[1]])}"')
        return _refer_to_goals_listed(tokens[:r - 1] + tokens[np[0]:np[1]] + tokens[end:], notes)
    return tokens


def _last_list_before(parser: 'PhraseParser', tokens: list[str], stop: int) -> list[tuple[int, int]]:
    """Spans of the noun phrases of the last list ("the den, the hall and the garage") before ``stop``."""
    best: list[tuple[int, int]] = []
    i = 0
    while i < stop:
        if tokens[i] not in ('the', 'a', 'an', 'my', 'our', 'your'):
            i += 1
            continue
        spans: list[tuple[int, int]] = []
        j = i
        while j < stop and tokens[j] in ('the', 'a', 'an', 'my', 'our', 'your'):
            np = parser.parse(tokens[:stop], j)
            if np is None or np.end <= j or np.descriptor.relations:
                break
            spans.append((j, np.end))
            j = np.end
            k = j
            while k < stop and tokens[k] in (',', 'and', 'then'):
                k += 1
            if k == j:
                break
            j = k
        if len(spans) >= 2:
            best = spans
        i = max(i + 1, spans[-1][1] if spans else i + 1)
    return best


def resolve_list_references(tokens: list[str], notes: list[str]) -> list[str]:
    """Replace references by list position ("the second one") with the phrase they point to.

    Only applies where an enumeration is followed by such a reference; the
    enumeration itself only sets the scene and is removed.
    """
    tokens = _say_kind_again(_say_positions(tokens))
    found = _find_list(tokens)
    if found is None:
        tokens = _refer_to_goals_listed(tokens, notes)
        for k in range(len(tokens) - 2):
            if k > 0 and tokens[k - 1] in ('do', 'handle', 'finish', 'complete', 'from', 'of', 'avoid',
                                           'visit', 'to', 'near', 'check') and tokens[k] == 'the' and \
                    tokens[k + 1] in ('first', 'last') and tokens[k + 2] in NUMBER_WORDS and \
                    tokens[k + 2] not in ('one', 'once', 'twice', 'thrice') and (
                    k + 3 >= len(tokens) or tokens[k + 3] in PUNCT or tokens[k + 3] in (
                        'for', 'and', 'then', 'now', 'please', 'only', 'first')):
                # "just do the first two for now", "keep away from the first two": positions in a list
                # that was not found
                said = ' '.join(tokens[k:k + 3])
                raise TranslationError(f'"{said}": found no list they are part of', details={'part': said})
        return tokens
    s, end, nps, category = found
    tail = tokens[end:]
    if tail and tail[0] not in PUNCT and any(t in PUNCT for t in tail):
        tail = tail[next(k for k, t in enumerate(tail) if t in PUNCT):]
    elif tail and tail[0] in _WHERE_LISTED:
        # "there's a commode, a hoist and a wheelchair out in the corridor go to the second one": where
        # they are sets the scene, the request starts at its verb (said without a full stop)
        verb = next((k for k in range(2, len(tail)) if tail[k] in _VERBS and tail[k - 1] not in DETERMINERS),
                    0)
        if verb:
            tail = ['.'] + tail[verb:]
    start = max((k for k in range(s - 1) if tokens[k] in '.;!?'), default=-1) + 1
    ahead = s >= 2 and tokens[s - 1] == ':' and any(t in ORDINALS or t in ('last', 'middle') for t in tokens[
        start:s - 1])   # "the first and third things on this list: ..."
    refers = _refers_to_list(tail)
    # a number is a position, unless the things listed are labelled with it ("rows 4, 5 and 6 ... skip 5")
    labels = {np.descriptor.name.rpartition('_')[2] for np in nps}
    if not refers and not any(t.isdigit() and t not in labels and not _names_label(tail, k)
                              for k, t in enumerate(tail)) and not ahead:
        heads = {np.head for np in nps}
        if s == 0 and end < len(tokens) and tokens[end] == ':' and any(t in heads for t in tail) and \
                not any(t in NAME_VERBS for t in tokens[:end]):
            # "a hammer, a saw, a drill: bring the saw to the bench": the list only sets the scene
            notes.append('list of ' + ', '.join(str(np.descriptor) for np in nps) + ': the scene')
            return tokens[end + 1:]
        if category and any(tokens[np.end - 1] == 'one' or np.pronoun == 'one' for np in nps):
            # "two doors, a red one and a blue one. Go through the blue one": the ones are doors; the
            # enumeration only sets the scene
            notes.append(f'"one" read as "{category}"')
            keep = max((k for k in range(s) if tokens[k] in '.;!?'), default=-1)
            if tokens[keep + 1:keep + 2] and tokens[keep + 1] in _VERBS | {'check', 'inspect', 'survey'} and \
                    tokens[s - 1] == ':':
                # "visit each of the three sheds: the red one, the green one and the blue one": the list is
                # what to visit
                listed = [category if t == 'one' and tokens[k - 1] in DETERMINERS | PLACEHOLDER_ADJECTIVES
                          else t for k, t in enumerate(tokens[s:end], s)]
                verb_end = next((k for k in range(keep + 1, s) if tokens[k] in DETERMINERS or tokens[k] in (
                    'each', 'all', 'both', 'every', 'these', 'those', 'them') or tokens[k] in NUMBER_WORDS),
                    s)
                return tokens[:verb_end] + listed + tail
            tail = _the_described_one(tokens, nps, tail, category)
            return tokens[:keep + 1] + [category if t == 'one' and k > 0 and tail[k - 1] not in DETERMINERS
                                        else t for k, t in enumerate(tail)]
        return tokens
    items = []
    if nps[-1].descriptor.relations and not any(np.descriptor.relations for np in nps[:-1]):
        # "a mug, a plate and a bowl on the counter": where they all are, not which bowl
        rel = next((k for k in range(nps[-1].start + 1, nps[-1].end) if tokens[k] not in DETERMINERS and
                    not is_name_word(tokens, k, True)), nps[-1].end)
        nps[-1] = NounPhrase(Descriptor(nps[-1].descriptor.name), nps[-1].start, rel, nps[-1].head)
    bare = category and all(len(_np_text(tokens, np)) == 2 for np in nps)
    for np in nps:
        words = _np_text(tokens, np)
        if category and 'one' in words:
            words = [category if w == 'one' else w for w in words]
        elif bare and (len(words[1]) == 1 or words[1].isdigit()):
            words = ['the'] + category.split('_') + words[1:]   # "rooms are A, B and C": room b
        elif category and len(words) == 3 and words[1] in ('number', 'no') and words[2].isdigit():
            words = ['the'] + category.split('_') + words[2:]   # "escalators are number 1, ...": escalator 1
        elif bare and words[1] in COLOURS:
            words = words + category.split('_')   # "three bins: red, blue and green": the blue bin
        items.append(words)
    used: set[int] = set()
    tail = _drop_mentions(tail)

    def joined(idx: list[int], sep: str = 'and') -> list[str]:
        out: list[str] = []
        for k, i in enumerate(idx):
            used.add(i)
            if k:
                out += [',', sep] if sep == 'then' else [sep]
            out += items[i]
        return out

    # the kind all the listed things share ("hangar 1, hangar 2, hangar 3": hangar)
    kinds = {it[-2] for it in items if len(it) >= 3 and (len(it[-1]) == 1 or it[-1].isdigit())}
    kind = kinds.pop() if len(kinds) == 1 and all(len(it) >= 3 for it in items) else ''
    if not kind and len({np.head for np in nps}) == 1 and all(np.descriptor.relations for np in nps):
        kind = nps[0].head   # "a cart by the window, a cart behind the counter, ...: the second cart"

    def resolve(tail: list[str]) -> list[str]:
        out: list[str] = []
        i = 0
        n = len(items)
        while i < len(tail):
            t = tail[i]
            nxt = tail[i + 1] if i + 1 < len(tail) else ''
            if t == 'the' and nxt == 'one' and i + 2 < len(tail) and (
                    tail[i + 2] in ORDINALS or tail[i + 2] in ('last', 'middle')) and (
                    i + 3 >= len(tail) or tail[i + 3] in PUNCT or tail[i + 3] in (
                        'and', 'then', 'or', 'exactly', 'twice', 'thrice', 'once', 'at', 'first', 'last') or
                    tail[i + 3] in NUMBER_WORDS):
                tail = tail[:i + 1] + tail[i + 2:i + 3] + ['one'] + tail[i + 3:]   # "the one (I listed) last"
                nxt = tail[i + 1]
            if t == 'the' and nxt:
                w = tail[i + 2] if i + 2 < len(tail) else ''
                one = 1 if w in _POSITION_NOUNS else 0
                # "the second", "the latter twice": no noun follows the position word
                ends = not w or w in PUNCT or one or w in ('and', 'then', 'to', 'in', 'on', 'or') or \
                    not is_name_word(tail, i + 2, False)
                if not ends and kind and singular(w) == kind and (nxt in ORDINALS or nxt in (
                        'last', 'middle')):
                    # "hangars 1, 2 and 3: the third hangar on that list": the kind the list named
                    after = i + 3
                    said = next((m for m in _MENTIONED if tuple(tail[after:after + len(m)]) == m), ())
                    if after == len(tail) or tail[after] in PUNCT or tail[after] in (
                            'and', 'then', 'or') or said:
                        tail = tail[:i + 2] + ['one'] + tail[after + len(said):]
                        w, one, ends = 'one', 1, True
                if nxt == 'second' and tail[i + 2:i + 4] == ['to', 'last'] and n >= 2:
                    # "the second to last (one)"
                    out += joined([n - 2])
                    i += 4 + (1 if tail[i + 4:i + 5] in (['one'], ['item'], ['thing']) else 0)
                    continue
                if nxt in ORDINALS and ends and not (nxt == 'first' and w in NUMBER_WORDS and w != 'one'):
                    idx = ORDINALS[nxt] - 1
                    if idx >= n:
                        raise TranslationError(f'"the {nxt}" points past the end of a list of {n}',
                                               details={'part': f'the {nxt}'})
                    out += joined([idx])
                    i += 2 + one
                    continue
                if nxt == 'last' and w in ('two', 'three', 'four') and NUMBER_WORDS[w] <= n:
                    k = NUMBER_WORDS[w]
                    out += joined(list(range(n - k, n)))
                    i += 3
                    continue
                if nxt == 'first' and w in ('two', 'three', 'four') and NUMBER_WORDS[w] <= n:
                    out += joined(list(range(NUMBER_WORDS[w])))
                    i += 3
                    continue
                if nxt in ('latter', 'former') and n != 2:
                    raise TranslationError(f'"the {nxt}" needs a list of two, not of {n}',
                                           details={'part': f'the {nxt}'})
                if nxt in ('last', 'latter') and ends:
                    out += joined([n - 1])
                    i += 2 + one
                    continue
                if nxt == 'former':
                    out += joined([0])
                    i += 2
                    continue
                if nxt in ('one', 'item', 'thing') and tail[i + 2:i + 4] == ['at', 'the'] and \
                        tail[i + 4:i + 5] in (['start'], ['beginning'], ['end'], ['top'], ['bottom']) and (
                        i + 5 >= len(tail) or tail[i + 5] in PUNCT or tail[i + 5] in ('and', 'then', 'or')):
                    # "the item I listed at the start": the first one (at the end: the last)
                    out += joined([0] if tail[i + 4] in ('start', 'beginning', 'top') else [n - 1])
                    i += 5
                    continue
                if nxt == 'one' and tail[i + 2:i + 5] == ['in', 'the', 'middle'] and n % 2 == 1:
                    out += joined([n // 2])
                    i += 5
                    continue
                if nxt == 'middle' and n % 2 == 1:
                    out += joined([n // 2])
                    i += 2 + one
                    continue
                if nxt in ('other', 'others', 'remaining') or (
                        nxt == 'rest' and (not w or w in PUNCT or w == 'of' or not is_name_word(
                            tail, i + 2, False))):
                    if nxt == 'rest' and tail[i + 2:i + 4] == ['of', 'them']:
                        i += 2
                    said = ' ' + ' '.join(tail[:i]) + ' '
                    rest_idx = [k for k in range(n) if k not in used and not (
                        # "the checkout comes last, after the others": the others than the one named
                        ' ' + ' '.join(t for t in items[k] if t not in DETERMINERS) + ' ' in said)]
                    out += joined(rest_idx)
                    i += 2 + (1 if w in ('two', 'three', 'ones', 'one') else 0)
                    continue
                if nxt == 'one' and w in ('right', 'just', 'immediately', 'before', 'after', 'directly'):
                    j = i + 2
                    while j < len(tail) and tail[j] in ('right', 'just', 'immediately', 'directly'):
                        j += 1
                    if j < len(tail) and tail[j] in ('before', 'after'):
                        parser = PhraseParser()
                        ref = parser.parse(tail, j + 1)
                        if ref is not None:
                            k = next((m for m, it in enumerate(items) if it[-1] == ref.head), -1)
                            if k >= 0:
                                k2 = k - 1 if tail[j] == 'before' else k + 1
                                if 0 <= k2 < n:
                                    out += joined([k2])
                                    i = ref.end
                                    continue
            if t in ORDINALS and (i == 0 or tail[i - 1] in (',', 'then', 'and', ':')) and (
                    not nxt or nxt in PUNCT or nxt in ('and', 'then', 'one', 'ones', 'things', 'items', 'in',
                                                       'or', 'but')):
                out += joined([ORDINALS[t] - 1])
                i += 2 if nxt in ('one', 'ones', 'things', 'items') else 1
                continue
            if t == 'the' and nxt in COLOURS and tail[i + 2:i + 3] == ['one']:
                # "a red door, a green door and a blue door. Go to the green one"
                idx = [m for m, it in enumerate(items) if nxt in it]
                if len(idx) == 1:
                    out += joined(idx)
                    i += 3
                    continue
            if t == 'them' and nxt == 'in' and tail[i + 2:i + 4] == ['reverse', 'order']:
                out += joined(list(range(n - 1, -1, -1)), 'then')
                i += 4
                continue
            if t == 'all':
                # "all three in reverse order", "all of them in reverse order"
                j = i + 1
                if j < len(tail) and tail[j] in NUMBER_WORDS and NUMBER_WORDS[tail[j]] == n:
                    j += 1
                if tail[j:j + 2] == ['of', 'them']:
                    j += 2
                if j > i + 1 and tail[j:j + 3] == ['in', 'reverse', 'order']:
                    out += joined(list(range(n - 1, -1, -1)), 'then')
                    i = j + 3
                    continue
            if t == 'them' and nxt == 'in' and tail[i + 2:i + 4] == ['that', 'order']:
                out += joined(list(range(n)), 'then')
                i += 4
                continue
            if t in ('them', 'all') and (nxt in ('all',) or t == 'them'):
                out += joined(list(range(n)))
                i += 2 if nxt == 'all' else 1
                continue
            out.append(t)
            i += 1
        return out

    if not refers and ahead:
        # "keep clear of the first and third things on this list: a wheelchair, a cart, a hamper"
        head = _drop_mentions(tokens[start:s - 1])
        notes.append('list of ' + ', '.join(' '.join(it[1:]) for it in items) + ': positions resolved')
        return tokens[:start] + resolve(head) + tail
    out = resolve(tail)
    notes.append('list of ' + ', '.join(' '.join(it[1:]) for it in items) + ': positions resolved')
    # earlier sentences stay; the sentence that holds the list only sets the scene
    keep = max((k for k in range(s) if tokens[k] in '.;!?'), default=-1)
    first = next((k for k, t in enumerate(out) if t not in PUNCT), len(out))
    stop = next((k for k in range(end, len(tokens)) if tokens[k] in '.;!?'), len(tokens))
    if {'visit', 'check'} & set(tokens[keep + 1:stop]) and out[first:first + 1] and \
            out[first] in DETERMINERS and out[:1] and out[0] in '.;!?':
        # "you've got a, b and c to visit. c comes last, after the others": the list is the task
        return tokens[:stop] + out
    return tokens[:keep + 1] + out


# ------------------------------------------------------------------ self-corrections

_NOT_A_NAME_END = frozenset({'to', 'at', 'in', 'on', 'by', 'of', 'and', 'or', 'then', 'i', 'you', 'we', 'is',
                             'are', 'go', 'not', 'the', 'a', 'an', 'that', 'what', 'it', 'do', 'if'})
_MARKERS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('no', 'wait'), ('oh', 'wait'), ('wait',), ('sorry',), ('er',), ('um',), ('uh',), ('i', 'mean'),
    ('i', 'meant'), ('actually',), ('scratch', 'that'), ('forget',), ('ignore',), ('disregard',),
    ('never', 'mind'),
    ('hmm',), ('make', 'that'), ('correction',), ('oops',), ('rather',), ('no',),
    ('no', 'sorry'), ('sorry', 'no'), ('no', 'no'), ('erm',), ('uhh',), ('umm',), ('ah',), ('my', 'bad'),
    ('my', 'mistake'), ('or', 'rather'), ('or', 'actually'), ('or', 'better'), ('on', 'second', 'thought'),
    ('on', 'second', 'thoughts'), ('on', 'reflection'), ('come', 'to', 'think', 'of', 'it'),
    ('change', 'of', 'plan'),
    ('change', 'of', 'plans'), ('let', 'me', 'rephrase'), ('wait', 'no'), ('hold', 'on'), ('scratch',),
    ('cross', 'off'), ('skip',), ('omit',), ('leave', 'out'), ('make', 'it'), ('hang', 'on'),
    ('hang', 'on', 'a', 'sec'), ('hold', 'on', 'a', 'sec'), ('hang', 'on', 'a', 'second'), ('ugh',),
    ('no', 'hang', 'on'), ('no', 'hold', 'on'), ('oh', 'hang', 'on'), ('no', 'actually'), ('no', 'i', 'mean'),
    ('no', 'make', 'that'), ('no', 'rather'), ('no', 'make', 'it'), ('ehm',), ('mm',), ('mmm',),
    ('scrap', 'that'), ('scrap',), ('just', 'kidding'), ('only', 'kidding'), ('ehh',), ('eh',),
    # "ah no, I say it wrong: the mill before the lathe"
    ('i', 'say', 'it', 'wrong'), ('i', 'said', 'it', 'wrong'), ('i', 'got', 'it', 'wrong'),
    ('i', 'say', 'wrong'), ('i', 'said', 'wrong'), ('i', 'was', 'wrong'), ('i', 'said', 'that', 'wrong'),
    # formal apologies open a correction as "sorry" does ("My apologies, I meant the microcentrifuge")
    ('my', 'apologies'), ('apologies',), ('i', 'beg', 'your', 'pardon'), ('pardon',), ('pardon', 'me'),
), key=lambda m: -len(m)))
_CANCEL = frozenset({'forget', 'ignore', 'disregard', 'scratch', 'never', 'cancel', 'drop', 'skip', 'cross',
                     'omit', 'leave', 'scrap'})
# Markers that restate a whole clause ("on second thought, bring it to the couch").
_RESTATE = frozenset({'on', 'come', 'change', 'let', 'actually', 'hmm', 'wait', 'sorry', 'no', 'oh', 'rather',
                      'or', 'er', 'erm', 'um', 'uh', 'ah', 'i', 'oops', 'my', 'correction', 'ehm', 'mm',
                      'mmm', 'just', 'only'})
# Words that start a clause of their own (the verbs of goals and deliveries).
_VERBS = NAME_VERBS | {'go', 'head', 'visit', 'bring', 'take', 'put', 'move', 'drive', 'fly', 'walk',
                       'deliver', 'carry', 'return', 'avoid'}
# Words before a number that do not make it a label (_names_label): no noun, a verb, a position word.
_NOT_LABELLING = _NOT_LISTED | _VERBS | _POSITION_WORDS


# Markers that correct even where no comma sets them off, right after a name ("the couch sorry to the
# bed", "the armchair no wait the rocking chair"), as unpunctuated speech has them.
_BARE_MARKERS = frozenset({('sorry',), ('no', 'wait'), ('wait', 'no'), ('no', 'sorry'), ('sorry', 'no'),
                           ('i', 'mean'), ('i', 'meant'), ('no', 'actually'), ('no', 'make', 'that'),
                           ('no', 'make', 'it'), ('or', 'rather'), ('no', 'no'), ('oops',), ('correction',),
                           ('my', 'bad'), ('no', 'i', 'mean')})


# Words after the thing a scope's clause names ("avoid the canteen while you carry it").
_SCOPE_WORDS = frozenset({'while', 'until', 'till', 'on', 'when', 'after', 'before', 'during', 'as', 'once'})
# The verb of a replacement said again ("forget the dog, avoid the cat").
_REPLACED_VERB_WORDS = frozenset({'avoid', 'stay', 'keep', 'away', 'from', 'clear', 'of', 'steer', 'go', 'to',
                                  'visit', 'near', 'instead', 'just', 'off', 'out'})


def _marker_at(tokens: list[str], i: int) -> int:
    if i > 0 and tokens[i - 1] not in PUNCT and tokens[i - 1] not in ('hmm', 'oh', 'wait', 'actually', 'er',
                                                                      'um', 'sorry', 'no') and not (
            # "..., she's gone out, so forget about the cat": the reason, then the correction
            tokens[i - 1] == 'so' and i > 1 and tokens[i - 2] == ',') and not (
            # "Oh, and ignore what I said about the lift": "and" opens the sentence, the retraction follows
            tokens[i - 1] in ('and', 'also') and (i == 1 or tokens[i - 2] in PUNCT) and
            tokens[i] in ('forget', 'ignore', 'scratch', 'scrap', 'never')):
        bare = next((m for m in _BARE_MARKERS if tuple(tokens[i:i + len(m)]) == m), None)
        if bare is None or tokens[i - 1] in DETERMINERS or tokens[i - 1] in _NOT_A_NAME_END or \
                i + len(bare) >= len(tokens) or tokens[i + len(bare)] in PUNCT:
            return 0
        return len(bare) if len(bare) > 1 or bare != ('no', 'no') else 2
    for m in _MARKERS:
        if tuple(tokens[i:i + len(m)]) == m:
            if m == ('i', 'mean') and tokens[i + 2:i + 3] in (['it'], ['that'], ['this'], ['business']) and (
                    i + 3 == len(tokens) or tokens[i + 3] in PUNCT):
                return 0   # "Never go near the pit. I mean it.": emphasis, nothing corrected
            if m == ('no',) and i + 1 < len(tokens) and tokens[i + 1] not in (',', ':') and not (
                    i > 0 and tokens[i - 1] in '.;!?' and tokens[i + 1] == 'the' and i + 2 < len(tokens) and
                    tokens[i + 2] in ('one', 'other', 'ones')):
                return 0   # (but "... . no the one on the right of it": a correction, the comma left out)
            if m in (('ignore',), ('disregard',)) and i == 0:
                return 0
            if m == ('forget',) and i == 0:
                return 0
            if m[0] in ('skip', 'omit', 'scratch', 'cross', 'leave', 'scrap') and m not in (
                    ('scratch', 'that'), ('scrap', 'that')) and (
                    i == 0 or tokens[i - 1] not in '.;!?'):
                return 0   # only a sentence of its own cancels ("Scratch the pantry.")
            if m == ('leave', 'out') and i + 2 < len(tokens) and tokens[i + 2] == 'of':
                return 0
            return len(m)
    return 0


# Words that open a sentence and name nothing ("hm, no, the lounge").
_NOT_BARE = chatter.HESITATIONS | chatter.INTERJECTIONS | frozenset(
    m[0] for m in _MARKERS) | chatter.STATEMENT_SUBJECTS | {'you', 'please', 'ok', 'okay', 'yes', 'yeah'}


def _np_spans(tokens: list[str]) -> list[NounPhrase]:
    """Top-level noun phrases introduced by a determiner or after a verb particle."""
    parser = PhraseParser()
    out: list[NounPhrase] = []
    i = 0
    while i < len(tokens):
        after = tokens[i - 1] if i > 0 else ''
        if tokens[i] in DETERMINERS or after in ('to', 'by', 'at', 'visit', 'avoid', ',') or (
                # "Pool, then gym. Wait, reverse that": names said bare at the start of a sentence
                (i == 0 or after in '.;!?') and tokens[i] not in _VERBS and tokens[i] not in _NOT_BARE and
                is_name_word(tokens, i, False)) or (
                i > 0 and tokens[i - 1] in ('then', 'and', 'or', 'from', 'near') and
                tokens[i] not in _VERBS and is_name_word(tokens, i, False)):
            np = parser.parse(tokens, i)
            if np is not None and np.end > i and not np.pronoun:
                out.append(np)
                i = np.end
                continue
        i += 1
    return out


def _strip_corr(seg: list[str]) -> list[str]:
    if seg[:4] in (['the', 'other', 'one', ','], ['no', 'the', 'other', 'one']) and len(seg) > 4:
        seg = seg[4:] if seg[3] == ',' else seg[5:]   # "no no, the other one, the green door"
    while seg and seg[0] in (',', 'i', 'mean', 'meant', 'just', 'wait', 'no', 'actually', 'sorry', 'er',
                             'um', 'hmm', 'oh', 'make', 'that', 'rather', 'go', 'to', 'do', 'instead', 'it'):
        if seg[0] == 'it' and (len(seg) < 2 or seg[1] in PUNCT or seg[1] in ('is', 'was')):
            break
        if seg[0] == 'that' and len(seg) > 1 and seg[1] == 'is':
            break
        if seg[0] == 'go' and len(seg) > 1 and seg[1] not in ('to',):
            break
        if seg[0] == 'make' and not (len(seg) > 1 and seg[1] in ('that', 'it')):
            break
        if seg[0] == 'make' and seg[1] == 'it':
            seg = seg[1:]   # "make it the taxi rank": "it" goes with "make"
        seg = seg[1:]
    for k in range(1, len(seg) - 1):
        if seg[k] == ',' and seg[k + 1] == 'not' and seg[k + 2:k + 3] and seg[k + 2] in DETERMINERS:
            seg = seg[:k]   # "the shaking incubator, not the static one": what it is not, said again
            break
    while seg and seg[-1] in (',', 'instead', 'please', 'then', 'rather') or seg[-2:] in (
            ['i', 'mean'], ['i', 'meant'], ['after', 'all']):
        seg = seg[:-2] if seg[-1] in ('mean', 'meant', 'all') else seg[:-1]
    return seg


def _relabel(prev: list[str], new: list[str]) -> Optional[list[str]]:
    """'... checked stairwell A. I meant stairwell C': the last thing of that kind with another label."""
    words = new[1:] if new[:1] and new[0] in DETERMINERS else new
    if len(words) < 2 or not is_label(words[-1]) or not all(w.isalpha() for w in words[:-1]):
        return None
    kind = words[:-1]
    n = len(kind)
    for p in range(len(prev) - n - 1, -1, -1):
        if prev[p:p + n] == kind and is_label(prev[p + n]) and (p + n + 1 == len(prev) or prev[
                p + n + 1] in PUNCT or prev[p + n + 1] in _AFTER_LABEL):
            return None if prev[p + n].lower() == words[-1].lower() else \
                prev[:p + n] + [words[-1]] + prev[p + n + 1:]
    return None


# Words that may follow a labelled name ("stairwell A first", "dock 3 and then ...").
_AFTER_LABEL = frozenset({'and', 'or', 'then', 'first', 'last', 'next', 'before', 'after', 'until', 'till',
                          'on', 'in', 'at', 'but', 'twice', 'once', 'again', 'only', 'exactly'})


def _numbered(head: str) -> bool:
    """Whether a name's last word is a number ("table 4", "room twelve"): a place's label."""
    return head.isdigit() or head in NUMBER_WORDS


# Words before the place a thing is put ("put the book on the desk"): a correction of a bare name
# replaces that place.
_PLACING_WORDS = frozenset({'on', 'in', 'into', 'onto', 'at', 'to'})


def _replace_np(prev: list[str], new: list[str]) -> Optional[list[str]]:
    """Replace in ``prev`` the phrase ``new`` corrects (same head noun, else the last phrase)."""
    pron = 'it' if 'it' in new else 'them' if 'them' in new else ''
    if pron and ('one' in new or new[:1] and new[0] in DETERMINERS):
        # "the chair behind the desk, or rather the one in front of it": it is the desk (and so in
        # "the bin next to the rack, no, I meant the bin behind it")
        spans = _np_spans(prev)
        if spans and spans[-1].descriptor.relations:
            ref = PhraseParser().parse(prev, spans[-1].start)
            # (not the "the" of "to the left of": the thing it is left of)
            rel_at = next((k for k in range(spans[-1].start + 1, spans[-1].end) if prev[k] in DETERMINERS and
                           prev[k + 1:k + 2] not in (['left'], ['right'], ['front'], ['middle'], ['side'])),
                          -1)
            if ref is not None and rel_at > 0:
                inner = PhraseParser().parse(prev, rel_at)
                if inner is not None:
                    k = new.index(pron)
                    new = new[:k] + prev[rel_at:inner.end] + new[k + 1:]
    relabelled = _relabel(prev, new)
    if relabelled is not None:
        return relabelled
    parser = PhraseParser()
    np = parser.parse(new, 0)
    if np is None or np.end != len(new):
        return None
    spans = _np_spans(prev)
    if not spans:
        return None
    target = next((sp for sp in reversed(spans) if sp.head == np.head), None)
    if target is None and np.pronoun == 'one' and new[1:2] and new[1] in COLOURS:
        # "the green towel to the bathroom, wait no, the yellow one": the one that had a colour
        coloured = [sp for sp in spans if prev[sp.start + 1:sp.start + 2] and prev[sp.start + 1] in COLOURS]
        if len(coloured) == 1:
            sp = coloured[0]
            return prev[:sp.start + 1] + [new[1]] + prev[sp.start + 2:]
    if target is None:
        # a noun inside a phrase: "put the book on the shelf, uh, the top shelf I mean"
        inner = PhraseParser()
        for sp in reversed(spans):
            for p in range(sp.end - 1, sp.start, -1):
                if prev[p] in DETERMINERS:
                    sub = inner.parse(prev, p)
                    if sub is not None and sub.head == np.head and not sub.pronoun:
                        return prev[:p] + new + prev[sub.end:]
    if target is None:
        # no phrase with the same head: one of the same number ("the glasses ... the cups I mean")
        plural = singular(np.head) != np.head
        if not _numbered(np.head) and np.head not in chatter.PLACE_HEADS and not np.pronoun:
            # "bring the dessert menus to table 4, no wait, the wine list": a numbered place is corrected by
            # a number or a place, the thing carried by a thing
            things = [sp for sp in spans if not _numbered(sp.head)]
            spans = things or spans
        same = [sp for sp in spans if (singular(sp.head) != sp.head) == plural]
        target = same[-1] if len(same) == 1 and np.pronoun != 'one' else spans[-1]
        if target.descriptor.relations and np.pronoun != 'one' and not np.descriptor.relations:
            # "put the book on the desk. I mean the nightstand": the noun named last
            p = max((p for p in range(target.start + 1, target.end) if prev[p] in DETERMINERS), default=-1)
            sub = PhraseParser().parse(prev, p) if p > 0 else None
            if sub is not None and not sub.pronoun and sub.end == target.end and (
                    singular(sub.head) != sub.head) == plural:
                if prev[p - 1] not in _PLACING_WORDS or prev[p - 2:p] in (['next', 'to'], ['close', 'to']):
                    # "the lamp left of the TV, sorry, I meant the front desk": the lamp left of the desk,
                    # or the desk? Nothing says (only a thing put "on" or "in" a place is its destination)
                    return None
                return prev[:p] + new + prev[sub.end:]
    new_words = new
    if target.head == np.head and target.descriptor.relations and not np.descriptor.relations and \
            np.pronoun != 'one' and len([w for w in new if w not in DETERMINERS]) > 1:
        return _renamed(prev, target, new, np)   # only the name is corrected, not where it is
    if np.pronoun == 'one' or 'one' in new[:np.end]:
        old = prev[target.start:target.end]
        old_name_end = target.start
        while old_name_end < target.end and (old[old_name_end - target.start] in DETERMINERS or
                                             old_name_end == target.start):
            old_name_end += 1
        old_head = [w for w in prev[target.start:target.end] if w not in DETERMINERS]
        k = new.index('one')
        name = []
        for m, w in enumerate(old_head):
            if w in ('behind', 'between', 'next', 'on', 'under', 'in', 'above', 'below', 'by', 'near',
                     'beside', 'to', 'that', 'which') or w in ('left', 'right') and \
                    old_head[m + 1:m + 2] == ['of']:
                break
            name.append(w)
        adjectives = k > 0 and any(w not in DETERMINERS for w in new[:k])
        if adjectives:
            # "the blue recycling bin ... make that the green one": the new adjective replaces the old
            while len(name) > 1 and name[0] in PLACEHOLDER_ADJECTIVES:
                name = name[1:]
            said = {w for w in new[:k] if w not in DETERMINERS}
            while len(name) > 1 and name[0] in said:
                name = name[1:]   # "the second floor lounge ... the third floor one": floor said again
        new_words = new[:k] + name + new[k + 1:]
    start, end = target.start, target.end
    # an either-or group is corrected as a whole ("the sofa or the armchair ... just the sofa")
    for sp in spans:
        if sp.end < len(prev) and prev[sp.end] == 'or' and sp.end + 1 <= start <= sp.end + 2:
            start = min(start, sp.start)
        if sp.start > end and prev[end:sp.start] in (['or'], ['or', 'the']):
            end = sp.end
        if start <= sp.start and sp.start - end <= 1 and end < len(prev) and prev[end] == 'or':
            end = max(end, sp.end)
    return prev[:start] + new_words + prev[end:]


def _relation_start(prev: list[str], target: NounPhrase) -> Optional[int]:
    """Return where the relations of the phrase ``target`` start in ``prev`` ("under the bar"), or None."""
    return next((k for k in range(target.start + 1, target.end)
                 if prev[k] in ('that', 'which') or match_relation(prev, k) is not None), None)


def _renamed(prev: list[str], hit: NounPhrase, new: list[str], new_np: NounPhrase) -> list[str]:
    """Put ``new`` for the phrase ``hit``; where only the thing is said again, its place stays.

    "the blue stool under the bar ... make that the red stool": the red stool under the bar.
    """
    cut = _relation_start(prev, hit) if hit.descriptor.relations and not new_np.descriptor.relations else None
    return prev[:hit.start] + new + prev[cut if cut is not None else hit.end:]


def _step_start(prev: list[str], pos: int) -> int:
    """Where the step holding token ``pos`` starts: its verb, after a stop or a connective.

    -1 where there is none, or where a connective comes first ("go to the hall, then the gym": the gym
    is one goal of a list, not a step of its own).
    """
    for a in range(pos - 1, -1, -1):
        if prev[a] in PUNCT or prev[a] in ('and', 'then', 'or'):
            return -1
        if prev[a] in _VERBS and (a == 0 or prev[a - 1] in PUNCT or
                                  prev[a - 1] in ('and', 'then', 'but', 'so')):
            return a
    return -1


def _replace_step(prev: list[str], pos: int, rest: list[str], notes: list[str]) -> Optional[list[str]]:
    """Read "forget that" + what follows, where that replaces the whole last step, not one of its places.

    "bring a cup to the sink. forget that, go to the host stand instead": the delivery is gone (it
    was the sink replaced); "avoid the kitchen. scratch that, go to the garage": the avoidance is gone
    (it was "avoid the garage"); "bring a high chair to table 8 - ignore that, Luca's sorting it": a
    statement follows, the step is dropped (it was "bring a high chair to luca"). None where the step's
    verb is not found or what follows is neither a command nor a statement.
    """
    said = list(rest)
    while said and said[0] in (',', 'just', 'instead', 'and', 'so', 'then'):
        said = said[1:]
    words = [t for t in said if t not in PUNCT]
    if not words:
        return None
    command = words[0] in _VERBS and words[1:2] not in (['it'], ['them'])
    statement = not command and (_stated(words) or chatter.is_person_statement(words) or len(words) > 2 and (
        words[0] not in DETERMINERS and words[0] not in _VERBS and
        words[1] in ('is', 'are', 'was', 'has', 'have') and not chatter.carries_constraint(words)))
    if not command and not statement:
        return None
    a = _step_start(prev, pos)
    if a < 0:
        return None
    b = pos
    while b < len(prev) and prev[b] not in '.;!?':
        b += 1
    if command:
        notes.append(f'"{" ".join(prev[a:b])}" replaced by "{" ".join(said)}"')
        return prev[:a] + said + prev[b:]
    notes.append(f'"{" ".join(prev[a:b])}" dropped; left out "{" ".join(words)}" (asks for nothing)')
    while a > 0 and prev[a - 1] in ('and', 'but', 'then', ','):
        a -= 1
    return prev[:a] + prev[b:]


def _clause_open(prev: list[str], pos: int) -> int:
    """Where the clause holding ``prev[pos]`` opens: the last stop or connective before it (-1: none)."""
    return max((q for q in range(pos) if prev[q] in PUNCT or prev[q] in ('and', 'then', 'but')), default=-1)


def _remove_clause(prev: list[str], pos: int, narrow: bool = False, command: bool = False) -> list[str]:
    """Remove the clause around token ``pos`` (from the connective before it to the next stop).

    With ``narrow``, the next connective (``,``, ``then``, ``and``) also ends it: one goal of a list.
    With ``command``, a connective that opens a new command ends it ("stay away from X and head to Y").
    """
    a = _clause_open(prev, pos) + 1
    while a > 0 and prev[a - 1] in ('and', 'but', 'then', ','):
        a -= 1
    b = pos
    while b < len(prev) and prev[b] not in '.;!?' and not (
            narrow and b > pos and prev[b] in (',', 'then', 'and')) and not (
            command and b > pos and prev[b] in (',', 'then', 'and') and _command_after(prev, b)):
        b += 1
    if command and a == 0 and b < len(prev) and prev[b] not in '.;!?':
        b += 1   # the clause opened the instruction: its joiner to the next goes with it
        while b < len(prev) and prev[b] in ('and', 'then', ','):
            b += 1
    return prev[:a] + prev[b:]


_AVOID_WORDS = ('avoid', 'never', 'away', 'clear', 'not', 'off')
_PREPS = frozenset({'on', 'in', 'into', 'onto', 'at', 'under', 'behind', 'beside', 'by', 'inside', 'near'})


_EXCEPT: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('skipping',), ('except',), ('except', 'for'), ('excluding',), ('apart', 'from'), ('other', 'than'),
    ('but', 'not'), ('leaving', 'out'), ('minus',), ('but', 'skip'), ('but', 'leave', 'out'), ('not',),
), key=lambda t: -len(t)))


def apply_exclusions(tokens: list[str], notes: list[str]) -> list[str]:
    """Drop a listed goal the same sentence excludes ("the oak, the elm and the pine, but not the elm")."""
    if not any(t in ('skipping', 'except', 'excluding', 'apart', 'other', 'not', 'leaving', 'minus', 'skip')
               for t in tokens):
        return tokens
    out = list(tokens)
    i = 0
    while i < len(out):
        m = next((m for m in _EXCEPT if tuple(out[i:i + len(m)]) == m), None)
        if m is None or i == 0 or out[i - 1] not in (',', 'and') and m[0] != 'but':
            i += 1
            continue
        start = i - 1 if out[i - 1] in (',', 'and') else i
        ex = PhraseParser().parse(out, i + len(m))
        end = ex.end if ex is not None else i
        if ex is None or ex.pronoun or (end < len(out) and out[end] not in PUNCT):
            i += 1
            continue
        sent = max((k for k in range(start) if out[k] in '.;!?'), default=-1) + 1
        listed = [sp for sp in _np_spans(out[sent:start]) if sp.descriptor == ex.descriptor]
        if not listed:
            i += 1
            continue
        a, b = sent + listed[-1].start, sent + listed[-1].end
        # the separator before it goes too ("the oak, the elm and the pine")
        if a > 0 and out[a - 1] in (',', 'and'):
            a -= 1
            if out[a - 1:a] == [','] and out[b:b + 1] == ['and']:
                a -= 1
        elif out[b:b + 1] in ([','], ['and']):
            b += 1
        notes.append(f'{ex.descriptor} left out of the list, as asked')
        out = out[:a] + out[b:start] + out[end:]
        i = a
    return out


def _clause_cut(seg: list[str], joiners: tuple[str, ...]) -> int:
    """Where a comma and one of ``joiners`` start the next clause of a correction (-1: nowhere)."""
    return next((k for k in range(1, len(seg) - 1) if seg[k] == ',' and seg[k + 1] in joiners), -1)


_CLEFT = re.compile(
    r'\b(?:it is|it s|its) (?P<x>(?:the|my|your|our|that) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?:that |which )?'
    r'(?:you |we |the robot )?(?:(?:need|have|ought|want|got) to |should |must |gotta |are to |can not |'
    r'cannot |(?:i|we) (?:want|need) you (?:to )?(?:stay |keep )?)?(?:avoid|stay away from|keep away from|'
    r'steer clear of|keep clear of|stay clear of|out of|away from)'
    r'(?= [,.;!?]|$)')


# "forget the lobby bar thing", "forget about the road part": the thing itself
_THING_PART = re.compile(r'\b(?P<v>forget|ignore|scratch|scrap|drop|skip)(?: about)? '
                         r'(?P<x>the (?!(?:last|first|second|third|other|whole|same|previous|final|next)\b)'
                         r'(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?:thing|part|bit)\b')
# "forget what I said about the roses": forget the roses
_SAID_ABOUT = re.compile(r'\b(forget|ignore|scratch|disregard) (?:what i said|what i told you|'
                         r'everything i said|the bit|the part|the stuff) about\b')
# "it's the trough behind the gate I want": the trough behind the gate (the goal, said at length)
_CLEFT_GOAL = re.compile(
    r'\b(?:it is|it s|its) (?P<x>(?:the|my|your|our) [a-z0-9_ ]*?[a-z0-9_]+) (?:that |which )?(?:i|we) '
    r'(?:want|need|meant|mean|wanted|needed|am after|was after|were after|are after)(?= [,.;!?]|$)')
_MEANT = re.compile(r'\bi (?:wanted|want|meant|was going|was trying|should have|ought to have|should \'ve) '
                    r'(?:to )?(?:say|said|write|written|tell|type|typed)\b')
_NP_RE = r'(?:the|my|your|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+'
# "better you start from the printer and finish with the copier": the route, said plainly
_START_FINISH = re.compile(rf'\b(?:(?:it is )?better |maybe |instead )?(?:you )?(?:start|begin) '
                           rf'(?:from|with|at) '
                           rf'(?P<a>{_NP_RE}) and (?:then )?(?:finish|end) (?:with|at|up at) (?P<b>{_NP_RE})')
_DROP_RULE = re.compile(r'\b(?:drop|remove|lose|ditch) '
                        r'(?=(?:that|the) (?:condition|order|ordering|rule|sequence)\b)')
_INSTEAD_GO = re.compile(rf'(?<=[,.;!?] )instead of (?P<x>(?:the |my |your |our )?(?:[a-z0-9_]+ ){{0,2}}?'
                         rf'[a-z0-9_]+) (?:, )?(?:you )?(?:go to|visit|head to|use|take) (?P<y>{_NP_RE})'
                         rf'(?= [,.;!?]|$)')
_SWAP_WORDS = frozenset({'swap', 'switch', 'replace', 'exchange', 'trade', 'change', 'substitute'})
_SWAP = re.compile(rf'\b(?:{"|".join(sorted(_SWAP_WORDS))}) (?P<x>{_NP_RE}) (?:for|with|to|by) '
                   rf'(?P<y>{_NP_RE})(?= [,.;!?]|$)')


def _uncleft(tokens: list[str]) -> list[str]:
    """Say plainly what a correction says at length, so it can be read as one.

    "it is the cat you need to avoid" is "avoid the cat"; "I wanted to say" is "I meant".
    """
    if not ({'it', 'its', 'i', 'start', 'begin', 'drop', 'remove', 'lose', 'ditch', 'thing', 'part', 'bit',
             'about', 'instead'} | _SWAP_WORDS) & set(tokens):
        return tokens
    text = ' '.join(tokens)
    new = _MEANT.sub('i meant', _CLEFT.sub(lambda m: f'avoid {m.group("x")}', text))
    new = _CLEFT_GOAL.sub(lambda m: m.group('x'), new)
    new = _START_FINISH.sub(lambda m: f'go to {m.group("a")} then {m.group("b")}', new)
    # "swap the shed for the patio": the patio instead of the shed
    new = _SWAP.sub(lambda m: f'{m.group("y")} instead of {m.group("x")}', new)
    # "instead of the saw go to the drill press": the drill press instead of the saw
    new = _INSTEAD_GO.sub(lambda m: f'{m.group("y")} instead of {m.group("x")}', new)
    new = _DROP_RULE.sub('forget ', new)   # "drop that condition": cancel it
    new = _THING_PART.sub(lambda m: f'{m.group("v")} {m.group("x")}', new)
    new = _SAID_ABOUT.sub(r'\1', new)
    return new.split() if new != text else tokens


_CHOICE_WORDS = frozenset({'choice', 'choices', 'option', 'options', 'alternatives', 'alternative', 'either'})


def _forget_choice(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Replace the alternatives said before by the one named ("A or B ... forget the choice, just B")."""
    k = 1 if seg[:1] == [','] else 0
    if seg[k:k + 1] and seg[k] in _CANCEL:
        k += 1 + (seg[k:k + 2] == ['never', 'mind'])
    if seg[k:k + 1] not in (['the'], ['that']) or seg[k + 1:k + 2] == [] or seg[k + 1] not in _CHOICE_WORDS:
        return None
    k += 2 + (seg[k + 2:k + 3] == ['or'])   # "the either or"
    if seg[k:k + 1] != [',']:
        return None
    k += 1
    while seg[k:k + 1] and seg[k] in ('just', 'only', 'go', 'to', 'do', 'visit'):
        k += 1
    new = seg[k:]
    while new and new[-1] in ('then', 'instead', 'please', ','):
        new = new[:-1]
    np = PhraseParser().parse(new, 0) if new else None
    if np is None or np.end != len(new) or np.pronoun:
        return None
    spans = _np_spans(prev)
    for n, sp in enumerate(spans):
        if sp.head != np.head:
            continue
        a = b = n   # the spans joined to it by "or"
        while a > 0 and spans[a - 1].end + 1 == spans[a].start and prev[spans[a].start - 1] == 'or':
            a -= 1
        while b + 1 < len(spans) and spans[b].end + 1 == spans[b + 1].start and prev[spans[b].end] == 'or':
            b += 1
        if a == b:
            continue
        start = spans[a].start - (prev[spans[a].start - 1:spans[a].start] == ['either'])
        notes.append(f'correction: "{" ".join(prev[start:spans[b].end])}" is now "{" ".join(new)}"')
        return prev[:start] + new + prev[spans[b].end:]
    return None


_RETRACT_VERBS = frozenset({'forget', 'ignore', 'disregard', 'scratch', 'scrap', 'cancel'})


def apply_corrections(tokens: list[str], notes: list[str]) -> list[str]:
    """Apply self-corrections so only the final intent remains."""
    tokens = _actually_first(_uncleft(tokens))
    said: list[str] = []
    skip = 0
    for k, t in enumerate(tokens):
        if skip:
            skip -= 1
            continue
        if t == 'not' and tokens[k + 1:k + 3] in (['that', 'one'], ['this', 'one']) and \
                tokens[k + 3:k + 5] in ([',', 'the'], [',', 'it']) and k > 1 and tokens[k - 1] == ',' and \
                tokens[k - 2] in ('no', 'sorry', 'wait', 'oops', 'actually'):
            skip = 3   # "no, not that one, the one behind the door": what it corrects, then what it is
            continue
        if t == 'disregard':
            t = 'ignore'   # "disregard the south one": a retraction, read as "ignore" is
        if t == 'actually' and said and said[-1] not in PUNCT and (
                tokens[k + 1:k + 2] in (['just'], ['only']) and 'or' in said or
                tokens[k + 1:k + 2] in (['skip'], ['forget'], ['scratch'], ['ignore'], ['disregard'])):
            said.append(',')   # "the day room or the ward kitchen actually just the kitchen": spoken
        if t == 'please' and tokens[k + 1:k + 2] and tokens[k + 1] in _RETRACT_VERBS and (
                k == 0 or tokens[k - 1] in PUNCT):
            continue   # "No, please disregard that restriction": the retraction, said politely
        if t == ';' and any(said[-n:-n + 1] and said[-n] in _RETRACT_VERBS and
                            said[-n + 1] in ('that', 'this') for n in range(2, 5)):
            t = ','   # "disregard that restriction; visit it twice": what replaces it follows
        said.append(t)
        if t == 'no' and tokens[k + 1:k + 2] == ['not'] and k > 0 and (
                tokens[k - 1] in PUNCT or tokens[k - 1] in chatter.HESITATIONS or
                tokens[k + 2:k + 3] == ['the']):
            # ", no not the couch, the armchair": "no" then what it corrects (spoken: "the den no not the
            # den")
            if said[-2] not in PUNCT and said[-2] not in chatter.HESITATIONS:
                said.insert(len(said) - 1, ',')
            said.append(',')
    return _apply_corrections(_retract_all(_not_then_verb(said), notes), notes)


def _not_then_verb(tokens: list[str]) -> list[str]:
    """'land at the mortuary um no not the mortuary land at the dock': a comma before the step said again."""
    for i in range(len(tokens) - 4):
        if tokens[i:i + 3] == ['no', ',', 'not'] and i + 3 < len(tokens) and tokens[i + 3] in DETERMINERS:
            v = next((v for v in range(i + 5, min(len(tokens) - 1, i + 10)) if tokens[v] in _VERBS), 0)
            np = PhraseParser().parse(tokens[:v], i + 3) if v else None
            if np is not None and np.end == v and tokens[v - 1] not in PUNCT:
                return tokens[:v] + [','] + tokens[v:]
    return tokens


# What "all that was said" is called in a retraction ("ignore all of that", "forget everything I said").
_ALL_SAID = tuple(sorted((
    ('all', 'of', 'that'), ('all', 'that'), ('all', 'of', 'this'), ('all', 'this'), ('all', 'of', 'it'),
    ('everything',), ('everything', 'i', 'said'), ('everything', 'i', 'just', 'said'),
    ('all', 'of', 'the', 'above'), ('the', 'above'), ('everything', 'above'), ('what', 'i', 'said'),
    ('what', 'i', 'just', 'said'), ('all', 'i', 'said'), ('all', 'i', 'just', 'said'),
    ('everything', 'i', 'told', 'you'), ('all', 'those', 'instructions'), ('those', 'instructions'),
    ('all', 'those', 'steps'), ('the', 'whole', 'thing'), ('the', 'lot'), ('all', 'of', 'those'),
), key=lambda m: -len(m)))


# What says the whole request comes again ("let me rethink that: ...", "let me start again.").
_START_AGAIN: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('let', 'me', 'rethink', 'that'), ('let', 'me', 'rethink', 'this'), ('let', 'me', 'rethink'),
    ('let', 'me', 'start', 'again'), ('let', 'me', 'start', 'over'), ('let', 'me', 'try', 'again'),
    ('let', 'me', 'try', 'that', 'again'), ('let', 'me', 'say', 'that', 'again'), ('start', 'again'),
    ('starting', 'again'), ('start', 'over'), ('starting', 'over'), ('from', 'the', 'top'), ('new', 'plan'),
    ('let', 'me', 'think', 'again'), ('let', 'me', 'redo', 'that'),
), key=lambda m: -len(m)))
# Where a take-back of everything may start, and what may come just before it.
_TAKE_BACK_FIRST = frozenset(m[0] for m in _START_AGAIN) | _RETRACT_VERBS
_BEFORE_TAKE_BACK = PUNCT | {'no', 'wait', 'actually', 'so', 'oh', 'okay', 'ok', 'just'}


def _taken_back_at_end(tokens: list[str]) -> Optional[str]:
    """Return the words that take the whole request back at its end ("... Forget everything."), or None.

    "never mind all of that", "ignore everything I said", "cancel that": nothing is left to do.
    """
    end = len(tokens)
    while end and (tokens[end - 1] in PUNCT or tokens[end - 1] in ('please', 'thanks')):
        end -= 1
    for i in range(end):
        if i and tokens[i - 1] not in PUNCT | {'no', 'actually', 'so', 'oh', 'okay', 'ok', 'just', 'and'}:
            continue
        j = i + 2 if tokens[i:i + 2] == ['never', 'mind'] else i + 1 if tokens[i] in _RETRACT_VERBS else 0
        if not j:
            continue
        j += tokens[j:j + 1] == ['about']
        what = tuple(tokens[j:end])
        if what in _ALL_SAID or what in (('it', 'all'), ('all',)) or \
                tokens[i] == 'cancel' and what in (('that',), ('it',), ('this',), ('the', 'order'),
                                                   ('the', 'request'), ('the', 'task')):
            return ' '.join(tokens[i:end])
    return None


def _retract_all(tokens: list[str], notes: list[str]) -> list[str]:
    """Retract all said before: 'go to A, then B. Please ignore all of that and simply go to C'.

    The whole of what was said before is retracted (its goals and its rules alike: the speaker
    takes it all back), but only where a new request follows the retraction. A retraction of
    everything that ends the instruction leaves nothing to do: a :class:`TranslationError`
    says so (a robot must not carry out what was taken back). Other retractions that end the
    instruction are left to the readers of corrections.
    """
    gone = _taken_back_at_end(tokens)
    if gone is not None:
        raise TranslationError(f'everything was taken back ("{gone}"): there is nothing to do',
                               details={'part': gone})
    for i in range(1, len(tokens)):
        if tokens[i] not in _TAKE_BACK_FIRST or tokens[i - 1] not in _BEFORE_TAKE_BACK:
            continue
        again = next((m for m in _START_AGAIN if tuple(tokens[i:i + len(m)]) == m), None)
        if again is not None:   # "... . Let me rethink that. The window first, then ...": all again
            k = i + len(again)
        else:                   # "... . Please ignore all of that and simply go to C"
            said = next((m for m in _ALL_SAID if tuple(tokens[i + 1:i + 1 + len(m)]) == m), None) \
                if tokens[i] in _RETRACT_VERBS else None
            if said is None:
                continue
            k = i + 1 + len(said)
            while k < len(tokens) and tokens[k] in ('before', 'earlier', 'above', 'so', 'far', 'then'):
                k += 1
        phrase = ' '.join(tokens[i:k])
        if k >= len(tokens) or tokens[k] not in (',', ';', ':', '.', '!', '?', 'and', '-'):
            continue
        while k < len(tokens) and (tokens[k] in PUNCT or tokens[k] in ('and', 'simply', 'instead', 'rather')):
            k += 1
        rest = tokens[k:]
        if len([w for w in rest if w not in PUNCT]) >= 2:
            notes.append(f'took back everything said before "{phrase}"')
            return _retract_all(rest, notes)
    return tokens


def _actually_first(tokens: list[str]) -> list[str]:
    """Say a trailing "actually" first: "D or E... just D actually, and" -> "..., actually, just D, and".

    Only after a short part of its own that starts with "just" or "only" after a comma (a correction
    that keeps one of what was said), so the marker is found where corrections start.
    """
    if 'actually' not in tokens:
        return tokens
    for i, t in enumerate(tokens):
        if t != 'actually' or i < 3 or tokens[i - 1] in PUNCT or i + 1 < len(tokens) and \
                tokens[i + 1] not in PUNCT:
            continue
        c = next((k for k in range(i - 1, max(i - 7, -1), -1) if tokens[k] in PUNCT), -1)
        if c > 0 and tokens[c] == ',' and tokens[c + 1] in ('just', 'only') and i - c > 2:
            return tokens[:c + 1] + ['actually', ','] + tokens[c + 1:i] + tokens[i + 1:]
    return tokens


def _apply_corrections(tokens: list[str], notes: list[str]) -> list[str]:
    i = 0
    out = list(tokens)
    guard = 0
    while i < len(out) and guard < 50:
        guard += 1
        if 0 < i and out[i - 1] in '.;!?' and out[i] in DETERMINERS and not _marker_at(out, i):
            # "avoid the dog. the dog's fine, just avoid the sprinklers": said with no marker
            stop = next((k for k in range(i, len(out)) if out[k] in '.;!?'), len(out))
            fine = _fine_after_all(out[:i], out[i:stop], notes)
            if fine is not None:
                out = fine + out[stop:]
                i = len(fine)
                continue
        if 1 < i and out[i - 1] in '.;!?' and out[i - 2] not in PUNCT and out[i] in _VERBS:
            # "Land on the bench. Land on the bird table instead.": the sentence replaces the step before
            # (not where a correction before it has already dropped that step: "no wait, that's closed.")
            stop = next((k for k in range(i, len(out)) if out[k] in '.;!?'), len(out))
            if out[stop - 1] == 'instead' and stop - i > 2 and ',' not in out[i:stop]:
                result = _correct(out[:i], 'actually', [','] + out[i:stop], notes)
                if result is not None:
                    out = result + out[stop:]
                    i = len(result)
                    continue
        m = _marker_at(out, i)
        if not m or i == 0 and out[i] not in ('actually',):
            i += 1
            continue
        prev = out[:i]
        while prev and prev[-1] in (',', 'hmm', 'oh', 'eh', 'uh', 'um', 'er', 'erm', 'ah') or \
                prev[-2:] == [',', 'so']:
            prev = prev[:-1]
        j = i + m
        stop = j
        while stop < len(out) and out[stop] not in '.;!?':
            stop += 1
        seg = out[j:stop]
        after = out[stop:]
        marker = out[i]
        lead = 1 if seg[:1] == [','] else 0
        rel = match_relation(seg, lead + 1) if seg[lead:lead + 1] == ['not'] else None
        if rel is not None and seg[rel[1]:rel[1] + 1] == [','] and match_relation(seg, rel[1] + 1):
            # "sorry, not behind, in front of the press": what it was not, then what it is
            seg = seg[:lead] + seg[rel[1] + 1:]
        c = seg.index(',', lead) if ',' in seg[lead:] else -1
        said = seg[lead:c] if c <= lead or seg[lead] in DETERMINERS | chatter.STATEMENT_SUBJECTS else \
            ['the'] + seg[lead:c]   # "milk is already in there": a name said without its article
        chosen = _forget_choice(prev, seg, notes)
        if chosen is not None:
            # "A or B, then C. Actually forget the choice, just B": the alternatives become B
            out = chosen + after
            i = len(chosen)
            continue
        moved = _moved(prev, seg, notes)   # "no wait, it's in front of the shed, my mistake"
        if moved is not None:
            out = moved + after
            i = len(moved)
            continue
        stated = c > lead and _stated(said)
        so = 1 if seg[c + 1:c + 2] == ['so'] else 0
        if stated and c + 1 + so < len(seg) and (
                seg[c + 1 + so] in _VERBS or seg[c + 1 + so] in ('the', 'my', 'your', 'our') and
                'instead' in seg[c + 1 + so:]) and marker not in _CANCEL:
            # "actually it has been washed already, (so) put it in the dryer": the reason, then the step
            notes.append(f'took "{" ".join(seg[lead:c])}" as a description of the scene, not a task')
            out = out[:j] + ([','] if out[j - 1] not in PUNCT else []) + seg[c + 1 + so:] + after
            continue   # ("no, the saw is broken, go to the drill press": not "no go to")
        if c > lead and seg[c + 1:c + 2] and seg[c + 1] in _CANCEL and \
                seg[c + 2:] in (['that'], ['it'], ['about', 'that'], ['about', 'it']):
            # "actually the fireplace is off, forget that": "that" is the avoidance the remark takes back
            fine = _fine_after_all(prev, seg[lead:c], notes)
            if fine is not None:
                out = fine + after
                i = len(fine)
                continue
        if stated and _marker_at(seg, c + 1):
            # "wait, the milk is already in there, I meant the juice": the reason, then the correction
            notes.append(f'took "{" ".join(seg[lead:c])}" as a description of the scene, not a task')
            out = prev + [','] + _forget_what_was_said(prev, said, seg[c + 1:]) + after
            i = len(prev) + 1
            continue
        result = _correct(prev, marker, seg, notes)
        cut = _clause_cut(seg, ('then', 'and', 'but'))
        if result is None and cut > 0:
            # "then the scanner, no, the fax machine, then my desk": the correction ends at the clause
            result = _correct(prev, marker, seg[:cut], notes)
            if result is not None:
                result = result + seg[cut:]
        cut = next((k for k in range(lead + 2, len(seg) - 2) if seg[k] in ('and', 'then', 'but') and
                    seg[k - 1] not in PUNCT and (seg[k + 1] in _COMMAND_START or 'then' in seg[k:k + 2])), -1)
        if result is None and cut > 0 and seg[lead] in ('just', 'only'):
            # "... actually just the kitchen and don't go near the trolley": spoken, the correction ends
            # where the next command starts
            result = _correct(prev, marker, seg[:cut], notes)
            if result is not None:
                result = result + [','] + seg[cut:]
        cut = next((k for k in range(lead + 2, len(seg) - 2) if seg[k] == ',' and seg[k + 1] in _VERBS), -1)
        if result is None and cut > 0 and seg[lead] in DETERMINERS:
            named = seg[lead:cut]
            if any(seg[k:k + len(named)] == named for k in range(cut + 2, len(seg) - len(named) + 1)):
                # "avoid the puddle, sorry, I meant the dog, avoid the dog while you've got the bag": the
                # step said again in full replaces the one corrected
                result = _correct(prev, marker, [','] + seg[cut + 1:], notes)
            else:
                # "avoid the puddle, sorry, the dog, go to the den": the correction ends where a step starts
                result = _correct(prev, marker, seg[:cut], notes)
                if result is not None:
                    result = result + seg[cut:]
        if result is None:
            # not a correction we understand: drop the marker word and read on
            comma = [','] if prev and prev[-1] not in PUNCT else []
            # (but a verb of leaving out stays: "go to the garage, forget the kitchen" never makes
            # the kitchen a goal)
            kept = [marker] if marker in _CANCEL and marker != 'never' and seg[:1] != [','] else []
            said = prev[max((k for k, t in enumerate(prev) if t in '.;!?'), default=-1) + 1:]
            if (out[i:j] in (['i', 'meant'], ['no', 'i', 'mean']) and seg[:1] != [','] or
                    out[i:j] == ['i', 'mean'] and seg[:1] and seg[0] in DETERMINERS) and \
                    _RELATION_WORDS & set(said):
                # "the lamp left of the TV, sorry, I meant the desk": the lamp or its landmark? never
                # guessed (a goal of its own); "the plotter ... I meant the laminator" reads on
                kept = out[i:j]
            out = prev + comma + kept + seg + after
            i = len(prev) + len(comma) + len(kept)   # (a marker right after it is read: "ah no, ...")
            continue
        out = result + after
        i = len(result)
    return out


# Words that place a thing by another ("the lamp left of the TV"): a correction after one may mean either.
_RELATION_WORDS = frozenset({'left', 'right', 'behind', 'front', 'next', 'between', 'under', 'beside', 'by',
                             'near', 'above', 'below', 'beneath', 'underneath'})


def _forget_what_was_said(prev: list[str], said: list[str], rest: list[str]) -> list[str]:
    """Read "forget that" after a remark ("the fireplace is off") as forgetting what the remark is about.

    ``said`` is the remark ("the fireplace is off"), ``rest`` the correction after it; a bare
    "forget that" ("scratch that", "never mind that", "ignore it") becomes "forget" the thing
    the remark names, if a step said before names it too (else "that" is the last thing said).
    """
    m = _marker_at([','] + rest, 1)   # (read as after a comma: "forget" opens no request here)
    what = [t for t in rest[m:] if t not in PUNCT]
    if not m or rest[0] not in _CANCEL or what not in (
            [], ['that'], ['it'], ['about', 'that'], ['about', 'it']):
        return rest
    if rest[:2] == ['never', 'mind'] and not what:
        return rest   # "never mind" alone may take the whole request back
    end = _np_end(said)
    # (or said with no article, as the task names it: "aisle 7 is off")
    subject = next((w for w in (said[:end], said[1:end] if said[:1] == ['the'] else [])
                    if w and any(prev[k:k + len(w)] == w for k in range(len(prev)))), None)
    if subject is None:
        return rest
    return ['forget'] + subject + [t for t in rest[m:] if t in PUNCT]


_RETRACT: tuple[tuple[str, ...], ...] = (
    ('do', 'not', 'need', 'to', 'avoid'), ('do', 'not', 'have', 'to', 'avoid'), ('no', 'need', 'to', 'avoid'),
    ('need', 'not', 'avoid'), ('do', 'not', 'bother', 'avoiding'),
    ('no', 'need', 'to', 'stay', 'away', 'from'),
    ('do', 'not', 'need', 'to', 'stay', 'away', 'from'), ('can', 'go', 'near'), ('it', 'is', 'safe'),
    ('do', 'not', 'worry', 'about'), ('so', 'it', 'is', 'fine'), ('so', 'it', 'is', 'ok'),
    ('so', 'it', 'is', 'okay'), ('so', 'that', 'is', 'fine'), ('never', 'mind', 'about'),
    ('nevermind', 'about'),
    # "that makes no sense, you obviously need the stairs": the thing avoided is needed after all
    ('you', 'need'), ('you', 'obviously', 'need'), ('you', 'will', 'need'), ('you', 'have', 'to', 'use'),
    ('you', 'need', 'to', 'use'), ('you', 'must', 'use'), ('you', 'have', 'to', 'take'),
    ('you', 'need', 'to', 'take'), ('you', 'have', 'to', 'go', 'through'),
    ('you', 'need', 'to', 'go', 'through'),
) + tuple((verb, 'the', what, part)   # "drop the avoidance part"
          for verb in ('drop', 'forget', 'ignore', 'skip', 'scratch', 'remove', 'cancel')
          for what in ('avoidance', 'avoid', 'avoiding', 'keep', 'away') for part in ('part', 'bit'))


def _retract_avoidance(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """'..., you don't need to avoid it (after all)': the avoidance of it is dropped from ``prev``."""
    at = next((k for k in range(len(seg)) for r in _RETRACT if tuple(seg[k:k + len(r)]) == r), -1)
    if at < 0:
        return _fine_after_all(prev, seg, notes)
    r = next(r for r in _RETRACT if tuple(seg[at:at + len(r)]) == r)
    named = PhraseParser().parse(seg, at + len(r))
    head = named.head if named is not None and not named.pronoun else ''
    return _drop_avoidance(prev, seg, at, at + len(r), head, notes)


def _fine_after_all(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """'keep away from the stove and the bin, actually the bin is fine': the bin no longer avoided."""
    parser = PhraseParser()
    for k in range(len(seg)):
        if seg[k] not in DETERMINERS or k > 0 and seg[k - 1] not in PUNCT and seg[k - 1] not in (
                'actually', 'but', 'and', 'so', 'well', 'oh'):
            continue
        named = parser.parse(seg, k)
        if named is None or named.pronoun or seg[named.end:named.end + 1] not in (['is'], ['are']):
            continue
        e = named.end + 1
        if seg[e:e + 1] in (['actually'], ['totally'], ['perfectly'], ['all'], ['completely'], ['now']):
            e += 1
        if seg[e:e + 1] == ['been'] and seg[e + 1:e + 2] in (['fixed'], ['repaired'], ['cleared'],
                                                             ['cleaned']):
            e += 1   # "the elevator's been fixed"
        if seg[e:e + 2] in (['turned', 'off'], ['switched', 'off']):
            e += 1   # "the heater's switched off"
        if seg[e:e + 1] == ['off'] and seg[e + 1:e + 2] not in (['limits'], ['-'], ['to'], ['from']):
            pass   # "the fireplace is off": what made it a danger is gone (not "off limits")
        elif seg[e:e + 1] not in (['fine'], ['ok'], ['okay'], ['alright'], ['safe'], ['fixed'], ['repaired'],
                                  ['cleared'], ['acceptable'], ['allowed'], ['permitted']) and \
                seg[e:e + 2] not in (['no', 'problem'], ['not', 'a'], ['no', 'longer']):
            continue
        if seg[e:e + 2] == ['not', 'a'] and seg[e + 2:e + 3] not in (['problem'], ['hazard'], ['danger']):
            continue
        if seg[e:e + 2] == ['no', 'longer'] and seg[e + 2:e + 3] not in (
                ['a'], ['dangerous'], ['blocked'], ['off'], ['wet'], ['closed']):
            continue
        end = e + 1
        while end < len(seg) and seg[end] != ',' and not _opens_command(seg, end):
            end += 1   # "the stairs are fine now that the gate is up": the reason goes with it
        return _drop_avoidance(prev, seg, k, end, named.head, notes)
    return None


def _remove_from_list(prev: list[str], p: int, sp: NounPhrase) -> Optional[list[str]]:
    """``prev`` without the phrase ``sp`` (found from ``prev[p]`` on) where it is one of a list."""
    a, b = p + sp.start, p + sp.end
    if a >= 2 and prev[a - 1] in ('and', 'or', ',') and prev[a - 2] not in PUNCT and prev[a - 2] not in (
            'and', 'or'):
        return prev[:a - 1] + prev[b:]   # "the island and the stools": the stools taken out
    if b + 1 < len(prev) and prev[b] in ('and', 'or', ',') and prev[b + 1] in DETERMINERS:
        return prev[:a] + prev[b + 1:]
    return None


_WORRIED = (('i', 'am', 'worried', 'about'), ('we', 'are', 'worried', 'about'),
            ('i', 'am', 'bothered', 'about'),
            ('i', 'am', 'thinking', 'of'), ('that', 'is', 'the', 'problem'), ('that', 'is', 'the', 'worry'),
            ('that', 'is', 'the', 'danger'), ('that', 'is', 'dangerous'), ('you', 'need', 'to', 'avoid'),
            ('you', 'should', 'avoid'), ('to', 'avoid'), ('that', 'needs', 'avoiding'))


def _said_replaced(seg: list[str]) -> bool:
    """Whether a correction names what it replaces ("do the dining room instead of the kitchen")."""
    return any(seg[k:k + 2] in (['instead', 'of'], ['rather', 'than']) for k in range(len(seg) - 2))


def _cleft_avoidance(part: list[str]) -> list[str]:
    """After an avoidance taken back, "it's the stairs I'm worried about" / "it's Y that's wet" avoid Y."""
    if part[:2] != ['it', 'is'] or len(part) < 5:
        return part
    named = PhraseParser().parse(part, 2)
    if named is None or named.pronoun:
        return part
    rest = tuple(part[named.end:])
    if rest in _WORRIED or rest[:1] == ('that',) and rest[1:2] in (('is',), ('are',)) and len(rest) <= 4 and (
            rest[-1] in chatter.STATES and all(w in chatter.DEGREE_WORDS for w in rest[2:-1])):
        return ['avoid'] + part[2:named.end]
    return part


def _drop_avoidance(prev: list[str], seg: list[str], at: int, end: int, head: str, notes: list[str]
                    ) -> Optional[list[str]]:
    """Remove from ``prev`` the avoidance of the phrase with ``head`` (any, without); keep seg's orders."""
    avoid_at = [p for p in range(len(prev)) if prev[p] in _AVOID_WORDS]
    for p in reversed(avoid_at):
        # only what the avoidance clause names ("keep away from the heater and go to the sofa": not the sofa)
        q = next((q for q in range(p + 1, len(prev)) if prev[q] in '.;!?' or prev[q] in (
            ',', 'and', 'then', 'but') and _command_after(prev, q)), len(prev))
        spans = [sp for sp in _np_spans(prev[p:q]) if not head or sp.head == head]
        if spans:
            notes.append('the avoidance was retracted')
            leads = (['just'], ['but'], ['and'], ['so'], ['only'], ['then'])
            parts = [_cleft_avoidance(c[1:] if c[:1] in leads else c)
                     for c in _split_commas(seg[:at]) + _split_commas(seg[end:])]
            # what else is said is kept: a command, or any part holding a rule ("just don't go near X")
            kept = [c for c in parts if c and not _stated(c) and (
                c[0] in _COMMAND_START or chatter.carries_constraint(c))]
            a, b = p + spans[0].start, p + spans[0].end
            opens = _clause_open(prev, p)
            if len(kept) == 1 and (b < len(prev) and prev[b] in _SCOPE_WORDS or any(
                    prev[q] in _SCOPE_WORDS for q in range(opens + 1, p))):
                # "avoid the dog while you carry it. the dog's fine, just avoid the sprinklers": in its place
                # (and "while you carry it avoid the cat - I mean avoid the dog, the cat's fine")
                said = _strip_corr(kept[0]) if kept[0][:1] in (['i'], ['sorry'], ['no']) else kept[0]
                lead = next((k for k in range(len(said)) if said[k] not in _REPLACED_VERB_WORDS), 0)
                np = PhraseParser().parse(said, lead) if lead else None
                if np is not None and np.end == len(said) and not np.pronoun and \
                        _clause_kind(said[:lead]) == 'avoid':
                    notes[-1] = f'"{" ".join(prev[a:b])}" replaced by "{" ".join(said[lead:])}" ' \
                        '(its scope kept)'
                    return prev[:a] + said[lead:] + prev[b:]
            return (_remove_from_list(prev, p, spans[0]) or _remove_clause(prev, p, command=True)) + [
                t for c in kept for t in [','] + c]
    return None


# The words that join a command to a remark before it ("the cat is fine just don't go near the fish tank":
# no comma between them); the words a command starts with are _COMMAND_START.
_COMMAND_JOINERS = frozenset({'just', 'but', 'and', 'so', 'only', 'instead', 'then'})


def _opens_command(seg: list[str], k: int) -> bool:
    """Whether a command starts at ``seg[k]``, after a remark ("..., the cat is fine just avoid X")."""
    if k < len(seg) and seg[k] in _COMMAND_JOINERS:
        k += 1
    return k < len(seg) and seg[k] in _COMMAND_START and (
        seg[k] != 'do' or seg[k + 1:k + 2] in (['not'], ['never']))


def _command_after(seg: list[str], k: int) -> bool:
    """Whether a command of its own starts right after the connective ``seg[k]`` ("..., head to Y")."""
    return _opens_command(seg, k + 1) and seg[k + 1] not in _COMMAND_JOINERS


def _split_commas(seg: list[str]) -> list[list[str]]:
    out: list[list[str]] = [[]]
    for t in seg:
        if t == ',':
            out.append([])
        else:
            out[-1].append(t)
    return [c for c in out if c]


def _np_end(words: list[str]) -> int:
    np = PhraseParser().parse(words, 0) if words and words[0] in DETERMINERS else None
    return np.end if np is not None else 0


def _stated(words: list[str]) -> bool:
    """Whether ``words`` describe the scene ("the milk is already in there") rather than ask for something."""
    return chatter.is_statement(words, _np_end(words))


# Verbs of keeping away that a restatement may start with ("keep the dog out... I mean, keep away from it").
_KEEP_VERBS = frozenset({'keep', 'stay', 'steer'})
_AVOID_VERBS = _KEEP_VERBS | {'avoid'}
# Words a command starts with ("avoid" is one of _VERBS).
_COMMAND_START = _VERBS | _KEEP_VERBS | {'do', 'never'}
_DELIVERY = frozenset({'put', 'place', 'bring', 'take', 'throw', 'toss', 'move', 'carry', 'deliver', 'drop',
                       'leave', 'set', 'stash', 'store', 'dump', 'load', 'unload', 'hang', 'return', 'stick'})


def _restate(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Restate a clause: 'bring the blanket to the bedroom. On second thought, bring it to the couch'."""
    if not seg or seg[0] not in _VERBS | _KEEP_VERBS:
        return None
    end = len(prev)
    while end > 0 and prev[end - 1] in PUNCT:
        end -= 1
    b = end
    while b > 0 and not (prev[b - 1] in '.;!?' or prev[b - 1] in (',', 'then', 'and') and b < len(prev) and
                         prev[b] in _VERBS):
        b -= 1
    if b < end and prev[b] != seg[0]:
        # "on the way to the hall avoid the stairs, no wait, avoid the door": the verb said again
        # ("keep away from the microwave. scratch that, stay away from the toaster": the same rule)
        b = next((p for p in range(end - 1, b, -1) if prev[p] == seg[0] == 'avoid' or
                  prev[p] in _AVOID_VERBS and seg[0] in _AVOID_VERBS), b)
    if b < end and prev[b] != seg[0] and prev[b] in _DELIVERY and seg[0] in _DELIVERY:
        pass   # "throw away the papers. no, actually, put them in the recycling bin": the delivery again
    elif b >= end or prev[b] != seg[0] and not (prev[b] in _AVOID_VERBS and seg[0] in _AVOID_VERBS):
        return None
    old = prev[b:end]
    new = list(seg)
    if len(new) > 2 and new[-1] == 'instead':
        new = new[:-1]   # "no, take the yellow towel instead": the rest of the step as said
    for k in range(1, len(new) - 1):
        if new[k:k + 2] in (['instead', 'of'], ['rather', 'than']) or new[k] == 'not' and new[k - 1] == ',':
            new = new[:k - (new[k - 1] == ',')]   # "I meant avoid X, not the fan": what it replaces
            break
    d_new = next((k for k in range(1, min(len(new), 4)) if new[k] in DETERMINERS), -1)
    d_old = next((k for k in range(1, min(len(old), 4)) if old[k] in DETERMINERS), -1)
    j = next((j for j in range(d_new + 1, min(len(new), d_new + 4)) if new[j] == 'one'), -1) \
        if d_new > 0 else -1
    scoped = False
    if d_new > 0 and d_old > 0 and new[0] == old[0] and new[1:d_new] == old[1:d_old]:
        # the same verb on another thing: the rest of the old step as said. "bring the remote on
        # the couch to the stand. no, bring the one on the armchair" (or "the blue one"); "avoid
        # the canteen while you carry it - no wait, avoid the lobby"
        obj = PhraseParser().parse(old, d_old)
        other = PhraseParser().parse(new, d_new)
        if obj is not None and other is not None and not obj.pronoun and other.end == len(new):
            if j > 0:
                new = new[:j] + [obj.head] + new[j + 1:] + old[obj.end:]
            elif obj.end < len(old) and old[obj.end] in _SCOPE_WORDS | {'to', 'into', 'onto', 'in', 'on'}:
                new, scoped = new + old[obj.end:], True
    if not scoped and any(t in ('it', 'them') for t in new):
        k = 1
        while k < len(old) and old[k] in ('up', 'me', 'us', 'over', 'back', 'away', 'out'):
            k += 1
        obj = PhraseParser().parse(old, k, destination_stops=True)
        if obj is not None and not obj.pronoun:
            at = next(j for j, t in enumerate(new) if t in ('it', 'them'))
            new = new[:at] + old[k:obj.end] + new[at + 1:]
    notes.append(f'"{" ".join(old).strip(" .")}" replaced by "{" ".join(new)}"')
    while prev[:b] and prev[b - 1] in (',', 'then', 'and'):
        b -= 1
    head = prev[:b]
    return head + ([','] if head and head[-1] not in PUNCT else []) + new + prev[end:]


# How a place still to be avoided is said in the passive ("only the boiler needs to be avoided").
_AVOIDED_SAID = [w.split() for w in ('needs to be avoided', 'need to be avoided', 'should be avoided',
                                     'must be avoided', 'is to be avoided', 'needs avoiding', 'is off limits',
                                     'has to be avoided')]


def _only_this(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Keep one goal of a list: 'visit the museum and the zoo. Actually, just the zoo'."""
    words = [t for t in seg if t not in PUNCT]
    if len(words) > 2 and words[-1] == 'only' and words[0] in DETERMINERS:
        words = ['only'] + words[:-1]   # "actually, the east one only"
    elif len(words) > 2 and words[-1] == 'only' and not DETERMINERS & set(words):
        bare = PhraseParser().parse(words[:-1], 0)
        if bare is not None and not bare.pronoun and bare.end == len(words) - 1:
            words = ['only'] + words[:-1]   # "correction: north stairwell only"
    if not words or words[0] not in ('just', 'only'):
        return None
    passive = next((k for k in range(2, len(words) - 1) if words[k:] in _AVOIDED_SAID), -1)
    if passive > 0 and words[1] in DETERMINERS:
        words = ['only', 'avoid'] + words[1:passive]   # "only the steam generator needs to be avoided"
    if words[1:2] == ['avoid'] and len(words) > 3 and words[2] in DETERMINERS and 'avoid' in prev:
        # "..., so just avoid the steam generator": one of the places avoided before is kept
        words = ['just'] + words[2:]
    if words[1:3] in (['go', 'to'], ['head', 'to'], ['visit', 'the']) and len(words) > 3:
        words = ['just'] + words[3 if words[1] != 'visit' else 2:]   # "just go to the north one"
    if len(words) == 2 and bare_label(words[1]):
        return _only_label(prev, words[1], notes)   # "check-in island D or E ... just D"
    np = PhraseParser().parse(words, 1)
    spans = _np_spans(prev)
    if np is not None and np.pronoun == 'one' and np.end == len(words) == 4 and \
            words[1:2] in (['the'], ['that']):
        # "the north entrance or the south entrance ... just the north one": the one that was north
        same = [sp for sp in spans if [w for w in prev[sp.start:sp.end] if w not in DETERMINERS and
                                       w != 'either'][:1] == [words[2]]]
        if len(same) == 1 and len([w for w in prev[same[0].start:same[0].end] if w not in DETERMINERS and
                                   w != 'either']) == 1 and prev[same[0].end:same[0].end + 1] == ['or']:
            # "the north or south entrance": the north entrance
            nxt = next((sp for sp in spans if sp.start > same[0].end), None)
            if nxt is not None and nxt.end - nxt.start >= 2:
                name = ['the', words[2]] + [w for w in prev[nxt.start:nxt.end] if w not in DETERMINERS][1:]
                notes.append(f'only the {words[2]} one kept of that choice')
                return prev[:same[0].start] + name + prev[nxt.end:]
        elif len(same) == 1:
            np = same[0]
    if np is None or np.end != len(words) and np not in spans or np.pronoun:
        return None
    hit = next((k for k in range(len(spans) - 1, -1, -1) if spans[k].descriptor == np.descriptor), -1)
    if hit < 0 and not np.descriptor.relations:
        # "the day room or the ward kitchen ... just the kitchen": the one name that ends in it
        ends = [k for k, sp in enumerate(spans) if sp.descriptor.name.endswith('_' + np.descriptor.name)]
        hit = ends[0] if len(ends) == 1 else -1
    if hit < 0:
        return _only_this_side(prev, words[np.start:np.end], spans, notes)
    # the list it is in: phrases joined by "," / "and" / "or" only
    a = b = hit
    while a > 0 and all(t in (',', 'and', 'or', 'the') for t in prev[spans[a - 1].end:spans[a].start]):
        a -= 1
    while b + 1 < len(spans) and all(t in (',', 'and', 'or', 'the')
                                     for t in prev[spans[b].end:spans[b + 1].start]):
        b += 1
    if a == b:
        return None
    notes.append(f'only {np.descriptor} kept of that list')
    return prev[:spans[a].start] + prev[spans[hit].start:spans[hit].end] + prev[spans[b].end:]


def _only_label(prev: list[str], label: str, notes: list[str]) -> Optional[list[str]]:
    """Keep one label of "check-in island D or E" ("... just D"): the kind named with it stays."""
    for p in range(len(prev) - 2, 0, -1):
        a, b = prev[p - 1], prev[p + 1]
        if prev[p] == 'or' and p >= 2 and p + 2 < len(prev) and prev[p + 1] == prev[p - 2] and \
                bare_label(a) and bare_label(prev[p + 2]):
            b = prev[p + 2]   # "room 4 or room 5" (the kind said again)
            if label not in (a, b) or prev[p + 3:p + 4] in (['or'], [',']):
                return None
            notes.append(f'only {label} kept of that choice')
            return prev[:p - 1] + [label] + prev[p + 3:]
        if prev[p] != 'or' or not (bare_label(a) and bare_label(b)) or label not in (a, b) or \
                prev[p - 2:p - 1] in (['or'], [',']) or prev[p + 2:p + 3] in (['or'], [',', 'or']):
            continue
        if p < 2 or prev[p - 2] in PUNCT or prev[p - 2] in STOPWORDS:
            return None   # no kind before the labels
        notes.append(f'only {label} kept of that choice')
        return prev[:p - 1] + [label] + prev[p + 2:]
    return None


def _only_this_side(prev: list[str], named: list[str], spans: list[NounPhrase], notes: list[str]
                    ) -> Optional[list[str]]:
    """Keep one of 'north or south stairwell' named in full ("... north stairwell only")."""
    named = [w for w in named if w not in DETERMINERS]
    if len(named) < 2:
        return None
    for k, sp in enumerate(spans[:-1]):
        nxt = spans[k + 1]
        words = [w for w in prev[sp.start:sp.end] if w not in DETERMINERS and w != 'either']
        other = [w for w in prev[nxt.start:nxt.end] if w not in DETERMINERS]
        if words == named[:1] and prev[sp.end:nxt.start] in (['or'], ['and']) and \
                len(other) == len(named) and other[1:] == named[1:]:
            notes.append(f'only the {" ".join(named)} kept of that choice')
            return prev[:sp.start] + ['the'] + named + prev[nxt.end:]
    return None


def _swap(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Swap two goals: 'go to a, then b, then c. wait, swap b and c' -> 'go to a, then c, then b'."""
    words = [t for t in seg if t not in PUNCT]
    if not words or words[0] not in ('swap', 'switch', 'flip', 'exchange', 'reverse', 'interchange'):
        return None
    k = 1
    while k < len(words) and words[k] in ('the', 'order', 'of', 'around', 'round'):
        k += 1
    if words[k:k + 2] in (['last', 'two'], ['first', 'two'], ['final', 'two']) and not [
            t for t in words[k + 2:] if t not in ('around', 'round', 'please', 'instead', 'stops', 'goals',
                                                  'places', 'ones', 'over', 'of', 'them', 'those', 'these')]:
        # "swap the last two around": the last two goals named
        spans = _np_spans(prev)
        if len(spans) < 2:
            return None
        a, b = spans[-2:] if words[k] != 'first' else spans[:2]
        notes.append(f'{a.descriptor} and {b.descriptor} swapped')
        return prev[:a.start] + prev[b.start:b.end] + prev[a.end:b.start] + prev[a.start:a.end] + prev[b.end:]
    if words[k:] and not [t for t in words[k:] if t not in (
            'those', 'them', 'these', 'two', 'the', 'around', 'round', 'please', 'instead', 'over')] and (
            words[k] in ('those', 'them', 'these') or words[k:k + 2] == ['the', 'two']):
        # "go to a then b. actually, switch those": the only two goals named
        spans = _np_spans(prev)
        if len(spans) != 2:
            return None
        a, b = spans
        notes.append(f'{a.descriptor} and {b.descriptor} swapped')
        return prev[:a.start] + prev[b.start:b.end] + prev[a.end:b.start] + prev[a.start:a.end] + prev[b.end:]
    if words[k:k + 1] in (['that'], ['it']):
        # "go to a and then b. hmm, flip that, b first": the last two goals, the one said first now
        spans = _np_spans(prev)
        said = words[k + 1:]
        if said[-1:] in (['first'], ['last']):
            np = PhraseParser().parse(said, 0)
            if np is None or np.end != len(said) - 1:
                return None
            moved = None if len(spans) < 2 else spans[-1] if said[-1] == 'first' else spans[-2]
            said = [] if moved is not None and np.head == moved.head else said
        if len(spans) < 2 or [t for t in said if t not in ('around', 'round', 'please', 'instead')]:
            return None
        a, b = spans[-2:]
        notes.append(f'{a.descriptor} and {b.descriptor} swapped')
        return prev[:a.start] + prev[b.start:b.end] + prev[a.end:b.start] + prev[a.start:a.end] + prev[b.end:]
    nps, _, end = PhraseParser().parse_list(words, k)
    if len(nps) != 2 or [t for t in words[end:] if t not in ('around', 'round', 'please', 'instead')]:
        return None
    spans = _np_spans(prev)
    hits = [next((sp for sp in reversed(spans) if sp.descriptor == np.descriptor or sp.head == np.head), None)
            for np in nps]
    if hits[0] is None or hits[1] is None or hits[0].start == hits[1].start:
        return None
    a, b = sorted(hits, key=lambda sp: sp.start)
    notes.append(f'{nps[0].descriptor} and {nps[1].descriptor} swapped')
    return prev[:a.start] + prev[b.start:b.end] + prev[a.end:b.start] + prev[a.start:a.end] + prev[b.end:]


_GOES = (('goes',), ('should', 'go'), ('belongs',), ('needs', 'to', 'go'), ('has', 'to', 'go'), ('go',),
         ('must', 'go'), ('is', 'for'), ('is', 'going'))


def _goes_to(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Change a destination: 'bring the mug to the desk. wait, the mug goes to the sink': to the sink."""
    words = [t for t in seg if t not in PUNCT]
    # "take the cryobox to the tank. sorry, it should go to the cold room": "it" is the thing carried
    it = words[:1] in (['it'], ['they']) and any(tuple(words[1:1 + len(v)]) == v for v in _GOES)
    if not words or words[0] not in DETERMINERS and not it:
        return None
    parser = PhraseParser()
    at = next((k for k in range(1, len(words)) if any(tuple(words[k:k + len(v)]) == v for v in _GOES)), -1)
    obj = None if it else parser.parse(words[:at], 0, destination_stops=True) if at > 0 else None
    if not it and (obj is None or obj.pronoun or obj.end != at):
        return None   # (the verb found first: the parser would take "goes" into the name)
    verb = next(v for v in _GOES if tuple(words[at:at + len(v)]) == v)
    k = at + len(verb)
    if k >= len(words) or words[k] not in _PREPS | {'to'}:
        return None
    dest = parser.parse(words, k + 1)
    if dest is None or dest.end != len(words):
        return None
    if it:
        hit = next((sp for sp in reversed(_np_spans(prev))
                    if sp.start > 0 and prev[sp.start - 1] in _DELIVERY), None)
        obj = hit
    else:
        hit = next((sp for sp in reversed(_np_spans(prev))
                    if sp.descriptor == obj.descriptor or sp.head == obj.head),
                   None)
    if hit is None or hit.end >= len(prev) or prev[hit.end] not in _PREPS | {'to'}:
        return None
    old = parser.parse(prev, hit.end + 1)
    if old is None or old.pronoun:
        return None
    notes.append(f'{obj.descriptor} goes to {dest.descriptor} instead')
    return prev[:hit.end + 1] + words[k + 1:dest.end] + prev[old.end:]


# Words said before the two places of a reordering ("do the oven before you do the fridge").
_BEFORE_MOVED = _VERBS | {'do', 'to', 'at', 'by', 'over', 'up', 'just'}
_BEFORE_ANCHOR = _VERBS | {'do', 'to', 'at', 'by', 'you'}   # ("go" is one of _VERBS)


def _reorder_pair(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Move one goal of the sequence said before next to another: the order of the two corrected.

    "go to the fridge, then the oven, then the table. wait, no, do the oven before the fridge" (or "the
    oven first, then the fridge", "the fridge after the oven"): the oven goes right before the fridge,
    the rest of the sequence stays as said. Both must be goals of one sentence of ``prev``.
    """
    words = [t for t in seg if t not in PUNCT or t == ',']
    while words and words[-1] in (',', 'instead', 'please'):
        words = words[:-1]
    k = 0
    while k < len(words) and words[k] in _BEFORE_MOVED:
        k += 1
    parser = PhraseParser()
    first = parser.parse(words, k)
    if first is None or first.pronoun:
        return None
    e = first.end
    if words[e:e + 1] in (['before'], ['after']):
        rel, e = words[e], e + 1
    elif words[e:e + 2] == ['ahead', 'of']:
        rel, e = 'before', e + 2
    elif words[e:e + 3] in (['first', ',', 'then'], ['first', 'and', 'then'], ['first', ',', 'and']):
        rel, e = 'before', e + 3
        e += words[e:e + 1] == ['then']   # "first, and then"
    else:
        return None
    k2 = e
    while k2 < len(words) and words[k2] in _BEFORE_ANCHOR:
        k2 += 1   # "the oven before you do the fridge"
    second = parser.parse(words, k2)
    if second is None or second.pronoun or second.end != len(words):
        return None
    spans = _np_spans(prev)
    hit = [next((sp for sp in reversed(spans) if sp.descriptor == np.descriptor), None)
           for np in (first, second)]
    if hit[0] is None or hit[1] is None or hit[0].start == hit[1].start:
        return None
    moved, anchor = hit
    if any(prev[p] in '.;!?' for p in range(min(moved.start, anchor.start), max(moved.end, anchor.end))):
        return None
    if (rel == 'before') == (moved.start < anchor.start):
        return None   # already in that order: not a reordering
    if not all(prev[p - 1] in (',', 'then', 'and', 'to', 'visit') for p in (moved.start, anchor.start)):
        return None   # goals of a sequence ("go to X, then Y"), not things of a delivery or a rule
    said = prev[moved.start:moved.end]
    a, b = moved.start, moved.end
    joiners = (',', 'then', 'and')
    if prev[a - 1] in joiners:
        while prev[a - 1] in joiners:
            a -= 1   # ", and then the oven": its joiner goes with it
    else:
        while b < len(prev) and prev[b] in joiners:
            b += 1   # "go to the fridge, then ...": the first goal, the joiner after it goes
    rest = prev[:a] + prev[b:]
    # (before: the anchor comes first, so it has not moved; after: it comes later)
    at = anchor.start if anchor.start < a else anchor.end - (b - a)
    out = rest[:at] + said + [',', 'then'] + rest[at:] if rel == 'before' else \
        rest[:at] + [',', 'then'] + said + rest[at:]
    notes.append(f'{first.descriptor} moved {rel} {second.descriptor}')
    return out


def _first_instead(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Move a goal first: 'go to the pool, then the gym. Actually, do the gym first'."""
    words = [t for t in seg if t not in PUNCT]
    f = words.index('first') if 'first' in words[1:-1] else -1
    if f > 0 and words[-1] in ('after', 'afterwards', 'second', 'next', 'last', 'later') and \
            words[f + 1:f + 2] == ['and']:
        words = words[:f + 1]   # "door first and the whiteboard after"
    if not words or words[-1] != 'first':
        return None
    k = 0
    while k < len(words) and words[k] in _VERBS | {'do', 'to', 'at', 'by', 'over', 'up'}:
        k += 1
    np = PhraseParser().parse(words, k)
    if np is None or np.end != len(words) - 1 or np.pronoun:
        return None
    hit = next((sp for sp in reversed(_np_spans(prev)) if sp.descriptor == np.descriptor), None)
    if hit is None:
        return None
    sent = max((p for p in range(hit.start) if prev[p] in '.;!?'), default=-1) + 1
    rest = _remove_clause(prev, hit.start, narrow=True)
    body = rest[sent:]
    while body and body[0] in (',', 'then', 'and'):
        body = body[1:]
    notes.append(f'{np.descriptor} moved first')
    return rest[:sent] + ['go', 'to'] + words[k:np.end] + [',', 'then'] + body


_APOLOGIES = frozenset({('sorry',), ('my', 'mistake'), ('my', 'bad'), ('oops',), ('sorry', 'about', 'that'),
                        ('my', 'apologies'), ('apologies',), ('silly', 'me')})


def _ordinal_target(words: list[str]) -> Optional[int]:
    """Return the list place a cancelled phrase names ("the second one", "the first stop"), else None."""
    w = [t for t in words if t not in ('the', 'that')]
    if len(w) in (1, 2) and w[0] in ORDINALS and w[0] != 'last' and (len(w) == 1 or w[1] in (
            'one', 'stop', 'place', 'goal', 'item', 'thing', 'location', 'spot', 'room')):
        return ORDINALS[w[0]]
    return None


_LEAVE_BE = (('where', 'it', 'is'), ('where', 'they', 'are'), ('alone',), ('be',),
             ('where', 'it', 'was'), ('where', 'they', 'were'))


def _leave_be(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Cancel a delivery: 'bring the mop to the hall. actually, leave the mop where it is, go to the hall'."""
    if seg[:1] != ['leave']:
        return None
    at, tail = next(((j, t) for j in range(2, len(seg)) for t in _LEAVE_BE
                     if tuple(seg[j:j + len(t)]) == t), (-1, ()))
    np = PhraseParser().parse(seg[:at], 1) if at > 0 else None
    if np is None or np.pronoun or np.end != at:
        return None
    k = np.end + len(tail)
    if k < len(seg) and seg[k] != ',':
        return None
    hit = next((sp for sp in reversed(_np_spans(prev))
                if sp.descriptor == np.descriptor or sp.head == np.head), None)
    if hit is None:
        return None
    rest = seg[k + 1:]
    while rest and rest[0] in ('just', 'simply', 'only', 'and', 'but', 'then', ','):
        rest = rest[1:]
    notes.append(f'the delivery of {np.descriptor} was cancelled')
    kept = _remove_clause(prev, hit.start)
    return kept + ([','] if kept and kept[-1] not in PUNCT and rest else []) + rest


_INSERT_LEADS = frozenset({'add', 'also', 'just', 'stop', 'at', 'to', 'by', 'swing', 'pop', 'and', 'please',
                           'in'})


def _insert_between(prev: list[str], seg: list[str]) -> Optional[list[str]]:
    """'go to the garage, then the driveway. wait, stop at the mailbox in between': between the two."""
    words = [t for t in seg if t not in PUNCT]
    k = next((k for k in range(len(words) - 1) if words[k:k + 2] == ['in', 'between'] or
              words[k:k + 2] == ['between', 'them'] or words[k:k + 2] == ['between', 'those']), -1)
    if k < 0 or [t for t in words[k + 2:] if t not in ('them', 'those', 'the', 'two', 'both')]:
        return None
    lead = 0
    while lead < k and words[lead] in _VERBS | _INSERT_LEADS:
        lead += 1
    np = PhraseParser().parse(words, lead)
    if np is None or np.end != k or np.pronoun:
        return None
    end = max((p for p in range(len(prev)) if prev[p] in '.;!?' and p < len(prev) - 1), default=-1)
    sentence_start = end + 1
    at = max((p for p in range(sentence_start, len(prev)) if prev[p] == 'then'), default=-1)
    if at < 0:
        return None
    return prev[:at + 1] + words[lead:np.end] + [',', 'then'] + prev[at + 1:]


_ORDER_WORDS = frozenset({'the order', 'that order', 'the ordering', 'the sequence', 'that condition',
                          'the condition', 'the rule', 'that rule', 'the order part', 'that ordering',
                          'that sequence', 'the ordering part', 'the order bit'})


def _drop_order(prev: list[str]) -> Optional[list[str]]:
    """Say the last sentence's order as a plain list ("the porch before the yard": and the yard)."""
    start = max((p for p in range(len(prev) - 1) if prev[p] in '.;!?'), default=-1) + 1
    at = max((p for p in range(start, len(prev)) if prev[p] in ('before', 'after', 'then')), default=-1)
    if at < 0:
        return None
    k = at - 1 if at > 0 and prev[at - 1] in ('only', 'not', 'and', ',') else at
    if prev[k] in ('only', 'not') and at + 1 < len(prev) and prev[at] in ('before', 'after'):
        # "go to the lab only after the prep room": that condition goes, the goal stays
        end = next((p for p in range(at, len(prev)) if prev[p] in PUNCT), len(prev))
        return prev[:k] + prev[end:]
    return prev[:k] + ['and'] + prev[at + 1:]


def _said_after_cancel(kept: list[str], rest: list[str], notes: list[str]) -> list[str]:
    """Keep what follows "never mind the order, ...": a step said again is dropped, anything else read on.

    "just go to the chapel" after "head to the chapel only after X" says the kept goal again; "and
    avoid the gym" or "go to the gym" is a new request (it was silently lost).
    """
    while rest and rest[0] in ('just', 'simply', 'so', 'then', 'and', 'instead'):
        rest = rest[1:]
    if not rest:
        return []
    named = {np.head for np in _np_spans(kept)}
    spans = _np_spans(rest)
    if rest[0] in _VERBS and rest[0] not in _AVOID_VERBS and spans and spans[0].start <= 3 and \
            spans[-1].end == len(rest) and all(np.head in named for np in spans) and \
            not (chatter.PLACE_RULE_WORDS & set(rest)):
        notes.append(f'"{" ".join(rest)}" says the kept step again')
        return []
    end = [] if kept and kept[-1] in '.;!?' else ['.']
    return end + rest


# Words around "both" in "nah, make it both", "actually no, go to both of them".
_BOTH_FILLERS = frozenset({'just', 'actually', 'no', 'make', 'it', 'do', 'go', 'to', 'visit', 'of', 'them',
                           'then', 'instead'})


def _renumber(prev: list[str], seg: list[str]) -> Optional[list[str]]:
    """'dock four. no, five', 'room 204, sorry, 206': the number in the name said last is replaced."""
    words = [t for t in seg if t not in PUNCT and t not in ('make', 'it', 'that', 'just', 'no', 'sorry')]
    if len(words) == 1 and len(words[0]) == 1 and words[0].isalpha() and words[0].lower() != 'i':
        # "conf rm A. sorry, B": the letter of the name said last (a letter label is kept in capitals)
        p = next((p for p in range(len(prev) - 1, -1, -1) if len(prev[p]) == 1 and prev[p].isupper()), -1)
        if p <= 0 or prev[p - 1] in DETERMINERS or prev[p - 1] in PUNCT or not prev[p - 1].isalpha() or \
                prev[p].lower() == words[0].lower():
            return None
        return prev[:p] + [words[0].upper()] + prev[p + 1:]
    if len(words) != 1 or not (words[0].isdigit() or words[0] in NUMBER_WORDS) or \
            words[0] in ('once', 'twice', 'thrice'):
        return None
    p = next((p for p in range(len(prev) - 1, -1, -1) if prev[p].isdigit() or prev[p] in NUMBER_WORDS), -1)
    if p <= 0 or prev[p + 1:p + 2] in (['times'], ['time']) or prev[p] in ('once', 'twice', 'thrice') or \
            prev[p - 1] in DETERMINERS or prev[p].isdigit() != words[0].isdigit():
        return None
    return prev[:p] + words + prev[p + 1:]


def _neither(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Drop a choice taken back: 'the stairs or the lift, scratch that, neither, just go to room 204'."""
    words = [t for t in seg if t != ',']
    if words[:1] not in (['neither'], ['none']) or 'or' not in prev:
        return None
    rest = words[3:] if words[1:3] in (['of', 'them'], ['of', 'those']) else words[1:]
    while rest and rest[0] in ('just', 'instead', 'then', 'so'):
        rest = rest[1:]
    if not rest or rest[0] not in _VERBS:
        return None
    pos = max(p for p, t in enumerate(prev) if t == 'or')
    notes.append('the choice was dropped')
    kept = _remove_clause(prev, pos)
    return kept + ([','] if kept and kept[-1] not in PUNCT else []) + rest


def _moved(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Say again where the thing is: 'the trailer behind the shed. No wait, it's in front of the shed'."""
    words = [t for t in seg if t not in PUNCT]
    while words[-2:] in (['my', 'mistake'], ['my', 'bad'], ['i', 'think']) or \
            words[-1:] in (['sorry'], ['oops']):
        words = words[:-2] if words[-1] in ('mistake', 'bad', 'think') else words[:-1]
    if words[:2] != ['it', 'is'] or len(words) < 4:
        return None
    k = 4 if words[2:4] == ['the', 'one'] else 2
    if match_relation(words, k) is None:
        return None
    spans = _np_spans(prev)
    if not spans or not spans[-1].descriptor.relations:
        return None
    new = _replace_np(prev, ['the', 'one'] + words[k:])
    if new is not None:
        notes.append(f'corrected to "the one {" ".join(words[k:])}"')
    return new


def _replace_choice(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Replace the last either-or by the one said now.

    "the blue recliner or the grey one. hmm, make that the grey one or the footstool".
    """
    words = [t for t in seg if t not in PUNCT]
    while words[:2] in (['make', 'that'], ['make', 'it']) or words[:1] in (['hmm'], ['no'], ['actually']):
        words = words[2:] if words[0] == 'make' else words[1:]
    if 'or' not in words or not words or words[0] not in DETERMINERS:
        return None
    parser = PhraseParser()
    first = parser.parse(words, 0)
    if first is None or first.pronoun not in (None, '', 'one') or words[first.end:first.end + 1] != ['or']:
        return None
    second = parser.parse(words, first.end + 1)
    if second is None or second.pronoun not in (None, '', 'one') or second.end != len(words):
        return None
    spans = [sp for sp in (parser.parse(prev, i) for i in range(len(prev)) if prev[i] in DETERMINERS)
             if sp is not None and sp.pronoun in (None, '', 'one')]
    for a, b in zip(reversed(spans[:-1]), reversed(spans[1:])):
        if prev[a.end:b.start] in (['or'], [',', 'or']) and not [
                t for t in prev[b.end:] if t not in PUNCT and t not in ('instead', 'please')]:
            head = next((t for t in (prev[a.end - 1], prev[b.end - 1]) if t not in ('one', 'ones')), None)
            new = [head if t == 'one' and head is not None else t for t in words]
            notes.append(f'the choice was replaced by "{" ".join(new)}"')
            start = a.start - 1 if a.start > 0 and prev[a.start - 1] == 'either' else a.start
            return prev[:start] + new + prev[b.end:]
    return None


def _clause_kind(words: list[str]) -> str:
    """Whether the words before a name ask to avoid it ('avoid'), to go there ('go') or neither ('')."""
    if {'avoid', 'away', 'clear', 'steer', 'never', 'not', 'out'} & set(words):
        return 'avoid'
    return 'go' if {'go', 'visit', 'head', 'drive', 'fly', 'walk'} & set(words) else ''


def _order_restated(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Say again an ordering corrected ("visit A before B. Ah no, I say it wrong: B before A").

    The correction is two places joined by "before" or "after", as the sentence before joined them
    (both named there); that sentence is said again with the new order, its verb kept.
    """
    words = [t for t in seg if t not in PUNCT]
    word = next((t for t in words if t in ('before', 'after')), '')
    if not word:
        return None
    parser = PhraseParser()
    a = parser.parse(words, 0)
    if a is None or a.pronoun or words[a.end:a.end + 1] != [word]:
        return None
    b = parser.parse(words, a.end + 1)
    if b is None or b.pronoun or b.end != len(words):
        return None
    body = len(prev) - 1 if prev and prev[-1] in '.;!?' else len(prev)
    start = max((k for k in range(body) if prev[k] in '.;!?'), default=-1) + 1
    sentence = prev[start:]
    heads = {np.head for np in _np_spans(sentence)}
    if word not in sentence or not {a.head, b.head} <= heads:
        return None
    verb = next((k for k, t in enumerate(sentence) if t in DETERMINERS), 0)
    if not verb or not any(t in _VERBS for t in sentence[:verb]):
        return None
    notes.append(f'"{" ".join(t for t in sentence if t not in PUNCT)}" said again as "{" ".join(words)}"')
    return prev[:start] + sentence[:verb] + words + [t for t in sentence[-1:] if t in PUNCT]


def _scope_corrected(prev: list[str], seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """'only after the kitchen - scratch that, only after the print room': the scope's place replaced."""
    k = 1 if seg[:1] == [','] else 0
    k += 1 if seg[k:k + 1] == ['only'] else 0
    if k >= len(seg) or seg[k] not in ('before', 'after', 'until') or seg[k] not in prev:
        return None
    new_np = PhraseParser().parse(seg, k + 1)
    p = max(j for j in range(len(prev)) if prev[j] == seg[k])
    old = PhraseParser().parse(prev, p + 1)
    if new_np is None or old is None or old.pronoun or [t for t in seg[new_np.end:] if t not in PUNCT]:
        return None
    notes.append(f'corrected to "{" ".join(seg[k:new_np.end])}"')
    return prev[:p] + seg[k:new_np.end] + prev[old.end:]


def _without_state_not(words: list[str]) -> list[str]:
    """Words without a "not" that says how a thing is ("the autoclave is not running"), no rule."""
    return [w for k, w in enumerate(words) if not (
        w == 'not' and 0 < k < len(words) - 1 and words[k - 1] in ('is', 'are', 'was', 'were') and
        (words[k + 1].endswith('ing') and words[k + 1] not in ('going', 'coming', 'visiting', 'entering') or
         words[k + 1] in chatter.STATES))]


def _cancel_then_only(prev: list[str], marker: str, seg: list[str], notes: list[str]) -> Optional[list[str]]:
    """Keep one of a choice: 'A or B. Actually, disregard the south one: the north loading door only'."""
    words = list(seg[1:] if seg[:1] == [','] else seg)
    if marker not in _CANCEL:
        if words[:1] not in (['ignore'], ['forget'], ['skip'], ['scratch'], ['drop']):
            return None
        words = words[1:]
    gone = PhraseParser().parse(words, 0)
    if gone is None or gone.end >= len(words) or words[gone.end] not in (',', ':'):
        return None
    kept = [t for t in words[gone.end + 1:] if t not in PUNCT]
    if kept[-1:] == ['only']:
        kept = kept[:-1]
    elif kept[:1] in (['just'], ['only']):
        kept = kept[1:]
    else:
        return None
    np = PhraseParser().parse(kept, 0)
    if np is None or np.end != len(kept) or np.pronoun or 'or' not in prev:
        return None
    return _only_this(prev, ['just'] + kept, notes)


# Words that make a story after a correction hold a rule (it is not left out as asking for nothing).
_STORY_RULE_WORDS = chatter.PLACE_RULE_WORDS | {'before', 'after', 'first', 'last'}


def _correct(prev: list[str], marker: str, seg: list[str], notes: list[str]) -> Optional[list[str]]:
    scoped = _scope_corrected(prev, seg, notes)
    if scoped is not None:
        return scoped
    only = _cancel_then_only(prev, marker, seg, notes)
    if only is not None:
        return only
    lead = 1 if seg[:1] == [','] else 0
    for said in (['the', 'opposite', ','], ['the', 'other', 'way', 'round', ','],
                 ['the', 'other', 'way', 'around', ',']):
        if seg[lead:lead + len(said)] == said and len(seg) > lead + len(said) + 2:
            # "no, the opposite, first the office then the bench": the order reversed, then said again
            seg = seg[:lead] + ['the', 'opposite']
            break
    c = max((k for k, t in enumerate(seg) if t == ','), default=-1)
    fine = seg[c + 1:]
    if c > lead + 2 and 3 <= len(fine) <= 4 and fine[-2] in ('is', 'are') and fine[-1] in (
            'fine', 'ok', 'okay', 'alright', 'safe') and fine[0] not in DETERMINERS and \
            all(is_name_word(fine, k, k > 0) for k in range(len(fine) - 2)):
        seg = seg[:c]   # "no, avoid the grinding station, wash is ok": the one replaced, said by a word
    reordered = _order_restated(prev, seg, notes)
    if reordered is not None:
        return reordered
    # ("room 4 or 5, no, just 5": one of the choice kept, not a number corrected)
    just = [t for t in seg if t not in PUNCT][:1] in (['just'], ['only'])
    numbered = None if just else _renumber(prev, seg)
    if numbered is not None:
        notes.append('the number was corrected')
        return numbered
    neither = _neither(prev, seg, notes)
    if neither is not None:
        return neither
    prev_spans = _np_spans(prev) if marker in _CANCEL else []
    named = {w for sp in prev_spans for w in prev[sp.start:sp.end]}
    if marker in _CANCEL and seg[:1] == [','] and len(seg) > 2 and seg[1] in _VERBS and named:
        # "bring a cup to the sink. scratch that, head to the garage": the whole step replaced
        step = _replace_step(prev, prev_spans[-1].start, seg, notes)
        if step is not None:
            return step
    if marker in _CANCEL and seg[:1] == [','] and len(seg) > 2 and (
            seg[1] in DETERMINERS or seg[1] in _VERBS or seg[1] in named):
        # "scratch that, the observatory dome", "scratch that, bay two": what replaces it
        marker = 'no'
        if seg[1] not in DETERMINERS and seg[1] not in _VERBS:
            seg = [','] + ['the'] + seg[1:]
    said_no = marker == 'no' or 'no' in seg[:3]
    words = [t for t in seg if t not in PUNCT]
    # "never mind the order", "hmm, drop that condition, just go to the lab": what was cancelled
    k = 0 if marker in _CANCEL else 2 if words[:2] == ['never', 'mind'] else \
        1 if words[:1] and words[0] in _CANCEL else -1
    if k >= 0 and ' '.join(words[k:k + 2]) in _ORDER_WORDS:
        unordered = _drop_order(prev)
        if unordered is not None:
            notes.append('the order was dropped')
            return unordered + _said_after_cancel(unordered, words[k + 2:], notes)
    choice = _replace_choice(prev, seg, notes) if marker in ('make', 'hmm', 'actually', 'no', 'sorry', 'wait',
                                                             'or', 'i', 'oops', 'my') else None
    if choice is not None:
        return choice
    between = _insert_between(prev, seg)
    if between is not None:
        notes.append('a stop was added between the last two')
        return between
    both = [t for t in seg if t not in PUNCT and t not in _BOTH_FILLERS]
    order: list[str] = []
    if both[:1] == ['both'] and both[-1:] == ['first'] and 'or' in prev and ',' in seg:
        # "the seat or the chair. scratch that, go to both, seat first": both, in that order
        order = [','] + seg[len(seg) - seg[::-1].index(',') :]
        both = ['both']
    if both == ['both'] and 'or' in prev:
        # "the kitchen or the dining room - nah, make it both": each of them
        at = max(k for k, t in enumerate(prev) if t == 'or')
        out = prev[:at] + ['and'] + prev[at + 1:]
        start = max((k for k in range(at) if out[k] in '.;!?'), default=-1) + 1
        out = out[:start] + [t for t in out[start:at] if t != 'either'] + out[at:]
        notes.append('the choice was made both')
        if order:
            end = len(out) - 1 if out and out[-1] in '.;!?' else len(out)
            out = out[:end] + order + out[end:]
        return out
    stripped = True
    while stripped:   # "hmm, on second thought, ...": markers in a row
        stripped = False
        while seg and (seg[0] in (',', ':', 'actually', 'wait', 'sorry', 'hmm', 'oh', 'er', 'um', 'uh', 'erm',
                                  'ah', 'oops') or seg[0] == 'no' and seg[1:2] == [',']):
            seg, stripped = seg[1:], True
        for m in _MARKERS:
            if len(m) > 1 and tuple(seg[:len(m)]) == m and m[0] not in _CANCEL and m != ('make', 'that'):
                marker, seg, stripped = m[0], seg[len(m):], True
                break
        for wrong in (['that', 'is', 'wrong'], ['that', 'was', 'wrong'], ['that', 'is', 'not', 'right'],
                      ['i', 'got', 'that', 'wrong'], ['that', 'is', 'a', 'mistake'], ['wrong', 'one'],
                      ['that', 'makes', 'no', 'sense'], ['that', 'does', 'not', 'make', 'sense'],
                      ['that', 'is', 'silly'], ['that', 'is', 'nonsense'],
                      ['wrong', 'colour'], ['wrong', 'color'], ['wrong', 'room'], ['wrong', 'place']):
            if seg[:len(wrong)] == wrong and seg[len(wrong):len(wrong) + 1] == [',']:
                seg, stripped = seg[len(wrong) + 1:], True   # "no, sorry, that's wrong, avoid the hall"
        for lead in (['just', 'make', 'it'], ['make', 'it'], ['just', 'make', 'that']):
            if seg[:len(lead)] == lead and seg[len(lead):len(lead) + 1] and seg[len(lead)] in DETERMINERS:
                # "actually just make it the taxi rank": the phrase alone ("just" kept: only that)
                seg, stripped = (['just'] if lead[0] == 'just' else []) + seg[len(lead):], True
        cut = seg.index(',') if ',' in seg else -1
        go = cut + 1 + (seg[cut + 1:cut + 2] == ['so'])
        said = _without_state_not(seg[:cut]) if cut > 2 else []
        if cut > 2 and seg[go:go + 1] and (seg[go] in ('just', 'do', 'only') or seg[go] in _VERBS) and \
                _stated(said) and not chatter.carries_constraint(said) and \
                (not {sp.head for sp in _np_spans(seg[:cut])} & {sp.head for sp in _np_spans(prev)} or
                 _said_replaced(seg[go:]) or seg[go] in ('just', 'only') and 'avoid' in prev):
            # "actually it's chucking it down, just go to the conservatory": the reason asks for nothing
            notes.append(f'left out "{" ".join(seg[:cut])}" (asks for nothing)')
            seg, stripped = seg[go:], True
        instead_of_all = 'instead' in seg and seg[-1] in ('either', 'both', 'them', 'those')
        if seg[:1] == ['not'] and len(seg) > 2 or instead_of_all:
            # "the workshop or the basement, actually not the basement, the attic", "make it the
            # gazebo instead of either"
            choice = _replace_alternatives(prev, _strip_corr(seg))
            if choice is not None:
                notes.append(f'corrected the choice: {" ".join(seg)}')
                return choice
        if seg[:1] == ['not'] and len(seg) > 2:
            # "wait, no, not the freezer, I meant the cooler": what is corrected, named before the correction
            named = PhraseParser().parse(seg, 1)
            swapped = None if named is None else _replace_named(prev, seg, named) if not named.pronoun else \
                _replace_one(prev, seg, named, notes) or (
                    _replace_named(prev, seg, named) if named.descriptor.relations else None)
            if swapped is not None:
                notes.append(f'corrected: {" ".join(seg)}')
                return swapped
            if named is not None and not named.pronoun and seg[named.end:named.end + 1] == [','] and any(
                    sp.head == named.head for sp in _np_spans(prev)):
                seg, stripped = seg[named.end + 1:], True
    for k in range(1, len(seg) - 1):
        if seg[k] != ',':
            continue
        end = next((j for j in range(k + 1, len(seg)) if seg[j] == ','), len(seg))
        tail = seg[k + 1:end]
        gone = PhraseParser().parse(tail, 1) if tail[:1] in (['forget'], ['ignore'], ['skip'], ['drop']) \
            else None
        if gone is not None and not gone.pronoun and gone.end == len(tail) and end == len(seg) and any(
                sp.head == gone.head for sp in _np_spans(prev)) and not any(
                sp.head == gone.head for sp in _np_spans(seg[:k])):
            # "no, just the gazebo, forget the fountain": what the correction replaces, said again
            notes.append(f'"{" ".join(tail)}" read as part of the correction')
            seg = seg[:k]
            break
        if _cleft_avoidance(tail) is not tail:
            continue   # "the kitchen's fine, it's the floor that's wet": says what to avoid instead
        if tuple(tail) in _APOLOGIES or tail[:1] == ['same'] and len(tail) <= 4 or (
                _stated(tail) or chatter.is_story(tail, _VERBS) and not _STORY_RULE_WORDS & set(tail)) and \
                not [t for t in seg[end:] if t not in PUNCT]:
            # "I meant the cooler, sorry, it's been a long day": the apology and the reason ask for nothing
            dropped = ' '.join(t for t in seg[k + 1:] if t not in PUNCT)
            notes.append(f'left out "{dropped}" (asks for nothing)')
            seg = seg[:k]
            break
    words = [t for t in seg if t not in PUNCT]
    if said_no and len(words) in (3, 4) and words[0] in ('that', 'it') and \
            words[1] in ('is', 'was', 'will') and (
                words[-1] in chatter.STATES or len(words) == 4 and words[2] in ('too', 'far', 'much')):
        # ("no, that's too small": a judgement that drops it)
        # "go to the staff room. hmm, no, that's locked. go to the lounge instead": that goal is dropped
        spans = _np_spans(prev)
        if spans:
            notes.append(f'{spans[-1].descriptor} dropped ("{" ".join(words)}")')
            return _remove_clause(prev, spans[-1].start, narrow=True)
    retracted = _retract_avoidance(prev, seg, notes) or _leave_be(prev, seg, notes)
    if retracted is not None:
        return retracted
    swapped = _swap(prev, seg, notes) or _goes_to(prev, seg, notes)
    if swapped is not None:
        return swapped
    only = _only_this(prev, seg, notes) if seg[:1] in (['just'], ['only']) else None
    if only is not None:
        return only   # "the north or south entrance ... just go to the north one"
    if seg[:1] in (['just'], ['simply']) and len(seg) > 1 and seg[1] in _VERBS and marker in _RESTATE:
        # "go to the kitchen, grab a snack... no, just go to the kitchen, then the hall": the sentence again
        said = len(prev)
        while said and prev[said - 1] in PUNCT:
            said -= 1   # "go to the garden. actually, just go to X": the sentence before its full stop
        start = max((k for k in range(said) if prev[k] in '.;!?'), default=-1) + 1
        notes.append(f'"{" ".join(prev[start:said])}" replaced by "{" ".join(seg[1:])}"')
        return prev[:start] + seg[1:]
    reordered = _reorder_pair(prev, seg, notes) or _first_instead(prev, seg, notes)
    # (before a restatement: "actually, go to X first", "do X before Y")
    if reordered is not None:
        return reordered
    if marker in _RESTATE:
        restated = _restate(prev, seg, notes)
        if restated is not None:
            return restated
    if seg and seg[0] in _CANCEL and marker not in _CANCEL and marker != 'never' and (
            seg[0] != 'never' or seg[1:2] == ['mind']):   # "no, never go to the hall" is a rule, kept
        marker, seg = seg[0], seg[1:]
    s = ' '.join(seg)
    if marker in _CANCEL or marker == 'never':
        # "forget the garage, do the laundry room instead" / "ignore the last thing, go to X instead"
        if seg and seg[0] == 'mind':
            seg = seg[1:]
        if marker in ('skip', 'drop', 'cancel') and seg and ',' not in seg:
            seg = seg + [',']
        if seg and seg[0] == 'that' or marker in ('scratch', 'scrap'):
            seg = seg[1:] if seg and seg[0] == 'that' else seg
        said = seg[1:] if seg[:1] == [','] else seg
        if said[:1] and said[0] in _AVOID_VERBS:
            restated = _restate(prev, said, notes)   # "scratch that, stay away from the toaster instead"
            if restated is not None:
                return restated
        k = seg.index(',') if ',' in seg else len(seg)
        k = next((j for j in range(k) if seg[j] in ('and', 'then') and j + 1 < len(seg) and (
            seg[j + 1] in _VERBS | {'do'} or seg[j + 1] in ('just', 'simply', 'only', 'instead') and
            seg[j + 2:j + 3] and seg[j + 2] in _VERBS | {'do', 'hit'})), k)   # "skip the gym and just go ..."
        target, rest = seg[:k], seg[k + 1:]
        while len(target) > 1 and target[-1] in ('completely', 'entirely', 'altogether', 'totally'):
            target = target[:-1]   # "skip the middle one completely"
        if target[:1] == ['about'] and len(target) > 1:
            target = target[1:]   # "forget about the oven"
        if seg and seg[0] in _VERBS and seg[0] not in ('drop', 'leave') and marker in (
                'never', 'forget', 'ignore', 'scratch', 'scrap'):
            target, rest = [], seg   # "never mind, go to the porch": the last goal is replaced
        tgt = ' '.join(target)
        if any(w in tgt for w in ('avoid', 'avoiding', 'avoidance')):
            pos = next((p for p in range(len(prev) - 1, -1, -1) if prev[p] in _AVOID_WORDS), -1)
            if pos < 0:
                return None
            notes.append('the avoidance was retracted')
            return _remove_clause(prev, pos) + rest
        if rest[:1] and rest[0] in ('it', 'they', 'that', 'those') and ',' in rest and \
                chatter.is_statement(rest[:rest.index(',')]) and not chatter.has_constraint_word(
                    rest[:rest.index(',')]):
            # "ignore what I said about the lift, it's fine, avoid the stairs": why, then the replacement
            rest = rest[rest.index(',') + 1:]
        new = _strip_corr(rest)
        if new and new[0] not in DETERMINERS and new[0] not in _VERBS and len(new) <= 4 and all(
                w.isalpha() and w not in chatter.CONSTRAINT_WORDS and w not in PUNCT for w in new):
            new = ['the'] + new   # "scratch that, broom closet": a name said without its article
        count_fix = _count_correction(prev, seg)
        if count_fix is not None:
            notes.append('the count was corrected')
            # "visit it three times - scratch that, twice is plenty - and then go to my office"
            cut = _clause_cut(seg, ('then', 'and'))
            return count_fix + (seg[cut:] if cut > 0 else [])
        if tgt in ('', 'the last thing', 'the last one', 'the last part', 'that last part', 'that', 'it',
                   'the last bit', 'that last one', 'last thing', 'last part', 'that part', 'that last bit',
                   'last bit', 'the last step', 'that last step', 'the last instruction'):
            stop = max((p for p in range(len(prev)) if prev[p] in '.;!?'), default=-1)
            fine = _fine_after_all(prev[:stop + 1], prev[stop + 1:], notes) if tgt in ('', 'that', 'it') and \
                stop >= 0 else None
            if fine is not None:
                # "... . oh, the heater is switched off, ignore that": the remark takes the avoidance back
                return fine + ([','] + rest if rest else [])
            spans = _np_spans(prev)
            if not spans:
                return None
            last = spans[-1]
            step = _replace_step(prev, last.start, rest, notes)
            if step is not None:
                return step
            if len(new) > 1 and new[0] in _VERBS and new[1] in ('it', 'them'):
                # "put the bowl on the counter. scratch that, put it in the dishwasher": the whole
                # step again, with "it" the thing of the step it replaces
                start = max((p for p in range(last.start) if prev[p] in '.;!?' or prev[p] == 'then'),
                            default=-1) + 1
                obj_end = next((p for p in range(start + 2, len(prev)) if prev[p] in (
                    'on', 'in', 'into', 'onto', 'to', 'at', 'inside', 'over', 'away', 'back', '.', ',')),
                    len(prev))
                if prev[start] in _VERBS and start + 1 < obj_end and prev[start + 1] in DETERMINERS:
                    notes.append('the last step was replaced')
                    return prev[:start] + new[:1] + prev[start + 1:obj_end] + new[2:]
            if len(new) > 1 and new[0] in _VERBS and new[1] not in ('it', 'them') and last.start > 0 and \
                    prev[last.start - 1] == new[0]:
                new = new[1:]   # "..., and avoid the hall. ignore the last thing, avoid the den instead"
            if new:
                notes.append('the last goal was replaced')
                return prev[:last.start] + new + prev[last.end:]
            notes.append('the last goal was dropped')
            return _remove_clause(prev, last.start)
        spans = _np_spans(prev)
        parser = PhraseParser()
        nth = _ordinal_target(target)
        w = [t for t in target if t not in ('the', 'that')]
        if nth is None and not new and w[:1] == ['middle'] and w[1:] in ([], ['one'], ['stop'], ['place']):
            # "go to a, b, then c. scratch the middle one": the middle one of the list said last
            start = max((p for p in range(len(prev)) if prev[p] in '.;!?' and any(
                sp.start > p for sp in spans)), default=-1)
            listed = [sp for sp in spans if sp.start > start]
            if len(listed) >= 3 and len(listed) % 2 == 1:
                nth = spans.index(listed[len(listed) // 2]) + 1
        if nth is not None and not new:
            # "visit a, b and c. wait, forget the second one": the goal at that place of the list
            if not 0 < nth <= len(spans):
                return None
            hit = spans[nth - 1]
            notes.append(f'"{tgt}" ({hit.descriptor}) was dropped')
            return _remove_from_list(prev, 0, hit) or _remove_clause(prev, hit.start, narrow=True)
        tnp = parser.parse(target, 0)
        if tnp is None and len(target) == 1 and is_label(target[0]):
            # "survey rows 4, 5 and 6. actually skip 5": the one with that label
            labelled = [sp for sp in spans if sp.descriptor.name.endswith('_' + target[0].lower())]
            if len(labelled) == 1:
                tnp = labelled[0]
        if tnp is None:
            return None
        hit = next((sp for sp in reversed(spans)
                    if sp.descriptor == tnp.descriptor or sp.head == tnp.head), None)
        if hit is None and not tnp.pronoun and not tnp.descriptor.relations:
            # "stay off the atrium floor. scratch the atrium, ...": the one name that starts so
            short = tnp.descriptor.name + '_'
            named = {sp.descriptor for sp in spans if sp.descriptor.name.startswith(short)}
            hit = next((sp for sp in reversed(spans) if sp.descriptor in named), None) if len(named) == 1 \
                else None
        if hit is None and tnp.pronoun == 'one' and tnp.end == len(target):
            # "the left elevator or the right one. no, forget the right one": the words said again
            at = next((p for p in range(len(prev) - len(target), -1, -1)
                       if prev[p:p + len(target)] == target), -1)
            hit = parser.parse(prev, at) if at >= 0 else None
        if hit is None and marker in ('skip', 'omit', 'scratch', 'cross', 'leave'):
            notes.append(f'"{marker} {tgt}": no goal there')   # nothing given to cancel
            return prev + ([','] if prev and prev[-1] not in PUNCT and rest else []) + rest
        if hit is None:
            return None
        if new and _stated(new):
            new = []   # "never mind the dog, it is outside": a reason, not a replacement
        lead = next((k for k in range(len(new)) if new[k] not in _REPLACED_VERB_WORDS), len(new))
        said = _clause_kind(prev[max((p for p in range(hit.start) if prev[p] in '.;!?,' or prev[p] in (
            'and', 'then')), default=-1) + 1:hit.start])
        told = rest[:next((k for k in range(len(rest)) if rest[k] not in _REPLACED_VERB_WORDS), len(rest))]
        if new and said and _clause_kind(told) not in ('', said):
            # "avoid the dog. never mind the dog, go to the car": the avoidance dropped, a goal added
            notes.append(f'"{tgt}" was dropped')
            kept = _remove_clause(prev, hit.start, narrow=True)
            return kept + ([','] if kept and kept[-1] not in PUNCT else []) + rest
        if 0 < lead < len(new) and new[lead] in DETERMINERS:
            np = parser.parse(new, lead)
            if np is not None and np.end == len(new) and not np.pronoun:
                new = new[lead:]   # "forget the dog, avoid the cat": the thing replaced, its verb kept
        if new:
            notes.append(f'"{tgt}" was replaced')
            return prev[:hit.start] + new + prev[hit.end:]
        notes.append(f'"{tgt}" was dropped')
        if (prev[hit.end:hit.end + 1] == ['or'] or prev[hit.start - 1:hit.start] == ['or']) and not [
                t for k, t in enumerate(prev[hit.end:-1], hit.end)
                if t in '.;!?' and prev[k + 1] not in PUNCT]:
            # "go to the fountain or the gazebo. forget the fountain": one option taken out
            kept = _remove_from_list(prev, 0, hit)
            if kept is not None:
                return kept
        return _remove_clause(prev, hit.start, narrow=True)
    # "the couch is fine, just avoid the rug"
    if ' is fine' in s or ' is okay' in s or ' is ok' in s or ' are fine' in s:
        k = next(p for p in range(len(seg)) if seg[p] in ('is', 'are'))
        parser = PhraseParser()
        tnp = parser.parse(seg, 0)
        count_fix = _count_correction(prev, seg[:k]) if tnp is None else None
        if count_fix is not None:
            notes.append('the count was corrected')   # "three times. no, twice is fine"
            return count_fix
        rest = seg[k + 2:]
        if tnp is not None:
            for sp in reversed(_np_spans(prev)):
                opens = _clause_open(prev, sp.start)
                if sp.head == tnp.head and _clause_kind(prev[opens + 1:sp.start]) == 'avoid':
                    # (only an avoidance: "go to the sofa. actually the sofa is fine" drops no goal)
                    notes.append(f'avoiding {tnp.descriptor} was retracted')
                    prev = _remove_clause(prev, sp.start)
                    break
        return prev + ([','] if prev and prev[-1] not in PUNCT else []) + rest
    words = [t for t in seg if t not in PUNCT]
    if words in (['the', 'opposite'], ['opposite'], ['the', 'contrary']):
        s = 'the other way'   # "go to A and after to B... no, the opposite"
    if 'other way' in s or 'reverse' in s or 'opposite order' in s or 'backward' in s or 'wrong way' in s or \
            'mixed up' in s or 'mixed that up' in s or 'wrong order' in s or 'mixed them up' in s:
        spans = _np_spans(prev)
        if len(spans) < 2:
            return None
        out = list(prev)
        texts = [prev[sp.start:sp.end] for sp in spans]
        for sp, txt in reversed(list(zip(spans, reversed(texts)))):
            out[sp.start:sp.end] = txt
        notes.append('the order was reversed')
        return out
    count_fix = _count_correction(prev, seg)
    if count_fix is not None:
        notes.append('the count was corrected')
        return count_fix
    if seg and seg[0] == 'not' and ',' in seg:
        # "wait, not the kitchen, the dining room"
        k = seg.index(',')
        seg = seg[k + 1:] + ['not'] + seg[1:k]
    for lead in (['it', 'is', 'actually'], ['it', 'is', 'really'], ['it', 'is'], ['they', 'are', 'actually'],
                 ['they', 'are'], ['actually']):
        if seg[:len(lead)] == lead and seg[len(lead):len(lead) + 1] and seg[len(lead)] in _PREPS:
            seg = seg[len(lead):]   # "the box on the top shelf, no, it's actually on the bottom one"
            break
    if seg and seg[0] in ('before', 'after', 'until') and len(seg) > 1 and seg[0] in prev:
        # "don't go to the library before noon, sorry, before the park": the phrase after the same word
        new_np = PhraseParser().parse(seg, 1)
        p = max(k for k in range(len(prev)) if prev[k] == seg[0])
        old = PhraseParser().parse(prev, p + 1)
        if new_np is not None and old is not None and not old.pronoun and not [
                t for t in seg[new_np.end:] if t not in PUNCT]:
            notes.append(f'corrected to "{" ".join(seg[:new_np.end])}"')
            return prev[:p] + seg[:new_np.end] + prev[old.end:]
    if seg and seg[0] in _PREPS and len(seg) > 1:
        # "put the jar on the table - no, on the counter": the phrase after the same kind of word
        new_np = PhraseParser().parse(seg, 1)
        after = seg[new_np.end:] if new_np is not None else []
        if new_np is not None and (new_np.end == len(_strip_corr(seg)) or not [
                t for t in after if t not in PUNCT] or after[:1] == [','] and len(after) > 2 and (
                after[1] in _VERBS or after[1] in ('and', 'then', 'but'))):
            for p in range(len(prev) - 1, -1, -1):
                if prev[p] in _PREPS:
                    old = PhraseParser().parse(prev, p + 1)
                    if old is not None and not old.pronoun:
                        notes.append(f'corrected to "{" ".join(seg[:new_np.end])}"')
                        return prev[:p] + seg[:new_np.end] + prev[old.end:] + (
                            after if [t for t in after if t not in PUNCT] else [])
    for k in range(len(seg) - 1):
        if seg[k:k + 2] in (['instead', 'of'], ['rather', 'than']):
            seg = seg[:k] + ['not'] + seg[k + 2:]   # "the garden instead of the porch"
            break
    if 'not' in seg:
        k = seg.index('not')
        lead = _strip_corr(seg[:k])
        word = lead[0] if lead and lead[0] in ('after', 'before', 'until') else ''
        old = [t for t in seg[k + 1:] if t not in PUNCT]
        if word and old[:1] != [word]:
            old = [word] + old   # "I meant after the cafe, not the library": not after the library
        if word and old[0] == word:
            parser = PhraseParser()
            onp, nnp = parser.parse(old, 1), parser.parse(lead, 1)
            at = next((p for p in range(len(prev) - 1, -1, -1) if prev[p] == word), -1)
            here = parser.parse(prev, at + 1) if at >= 0 else None
            if onp is not None and nnp is not None and nnp.end == len(lead) and onp.end == len(old) and \
                    here is not None and not here.pronoun and (here.descriptor == onp.descriptor or
                                                               here.head == onp.head):
                # the scope's place is corrected, not a goal of the same name
                notes.append(f'corrected to "{" ".join(lead)}"')
                return prev[:at + 1] + lead[1:] + prev[here.end:]
        # "the freezer, not the fridge"
        new, old = _strip_corr(seg[:k]), seg[k + 1:]
        while new and new[0] in _VERBS | {'to', 'at', 'by', 'over', 'from', 'go', 'away', 'clear', 'of',
                                          'stay', 'keep'}:
            new = new[1:]   # "I meant avoid the radiator, not the fan": the verb is the one said before
        old = [t for t in old if t not in PUNCT]
        parser = PhraseParser()
        onp, nnp = parser.parse(old, 0), parser.parse(new, 0) if new else None
        if onp is not None and nnp is not None and nnp.end == len(new):
            hit = next((sp for sp in reversed(_np_spans(prev))
                        if sp.descriptor == onp.descriptor or sp.head == onp.head), None)
            if hit is None and not onp.pronoun:
                # "the pepper grinder, not the salt": the thing named by part of its name
                said = set(onp.descriptor.name.split('_'))
                hit = next((sp for sp in reversed(_np_spans(prev))
                            if said <= set(sp.descriptor.name.split('_'))), None)
            if hit is not None:
                notes.append(f'corrected to "{" ".join(new)}"')
                return prev[:hit.start] + new + prev[hit.end:]
    only = _only_this(prev, seg, notes)
    if only is not None:
        return only
    new = _strip_corr(seg)
    if not new:
        return prev
    spans = _np_spans(prev)
    if spans and new[0] not in DETERMINERS:
        # "only after the principal's office - sorry, only after the front office": the words
        # before the phrase said again
        last = spans[-1]
        for n in (3, 2, 1):
            if len(new) > n and last.start >= n and new[:n] == prev[last.start - n:last.start] and \
                    new[n] in DETERMINERS and not {'or', 'and', 'then', ','} & set(new[:n]):
                new = new[n:]
                break
    replaced = _replace_alternatives(prev, new)
    if replaced is not None:
        notes.append(f'corrected the choice to "{" ".join(new)}"')
        return replaced
    replaced = _replace_sequence(prev, new)
    if replaced is not None:
        notes.append(f'corrected the order of places to "{" ".join(new)}"')
        return replaced
    replaced = _replace_relation(prev, new)
    if replaced is not None:
        notes.append(f'corrected the place to "{" ".join(new)}"')
        return replaced
    replaced = _replace_np(prev, new)
    if replaced is not None:
        notes.append(f'corrected to "{" ".join(new)}"')
        return replaced
    return None


def _replace_named(prev: list[str], seg: list[str], named: NounPhrase) -> Optional[list[str]]:
    """Replace the phrase named in "..., not the pot, the pan" (its place kept if none is said)."""
    if seg[named.end:named.end + 1] != [',']:
        return None
    new = _strip_corr(seg[named.end + 1:])
    nnp = PhraseParser().parse(new, 0) if new else None
    if nnp is not None and nnp.end == len(new) and nnp.pronoun == 'one' and new[:2] == ['the', 'one'] and \
            match_relation(new, 2) is not None:
        # "the lamp on the dresser. wait, not the dresser (not the one on the dresser), the one on the
        # bedside table": the thing said before ("the one": the lamp), its place corrected
        spans = _np_spans(prev)
        hit = next((sp for sp in reversed(spans) if sp.descriptor.relations == named.descriptor.relations
                    if named.pronoun == 'one' and named.descriptor.relations), None) or \
            next((sp for sp in reversed(spans) if not named.pronoun and (sp.head == named.head or any(
                prev[k] == named.head for k in range(sp.start, sp.end)))), None)
        cut = _relation_start(prev, hit) if hit is not None else None
        if hit is None or cut is None:
            return None
        return prev[:hit.start] + prev[hit.start:cut] + new[2:] + prev[hit.end:]
    if nnp is None or nnp.end != len(new) or nnp.pronoun:
        return None
    spans = _np_spans(prev)
    hit = next((sp for sp in reversed(spans) if sp.head == named.head or
                sp.descriptor.name == named.descriptor.name), None)
    if hit is None:
        # "put the blanket on the bed, wait, not the bed, the sofa": a phrase inside a phrase
        parser = PhraseParser()
        inner = (parser.parse(prev, p) for sp in reversed(spans) for p in range(sp.end - 1, sp.start, -1)
                 if prev[p] in DETERMINERS)
        hit = next((sub for sub in inner if sub is not None and not sub.pronoun and sub.head == named.head),
                   None)
    # "take the pot on the stove ..., not the pot, the pan": the pan on the stove
    return None if hit is None else _renamed(prev, hit, new, nnp)


def _replace_one(prev: list[str], seg: list[str], named: NounPhrase, notes: list[str]) -> Optional[list[str]]:
    """Replace the thing named by its adjective: "the blue blanket ..., not the blue one, the tartan one".

    The adjectives of the phrase it is not ("the blue one") find the thing said before ("the
    blue blanket"); the new phrase takes its noun where it says "one" ("the tartan one": the
    tartan blanket), and its place where it says none. A statement after it, about the thing
    replaced ("..., the blue one's in the wash"), asks for nothing and is left out, noted.
    """
    said = [w for w in seg[named.start:named.end] if w not in DETERMINERS and w != 'one']
    if not said or seg[named.end:named.end + 1] != [',']:
        return None
    rest = seg[named.end + 1:]
    c = rest.index(',') if ',' in rest else len(rest)
    new, tail = _strip_corr(rest[:c]), [t for t in rest[c + 1:] if t not in PUNCT]
    if tail and (chatter.carries_constraint(tail) or not _stated(tail)):
        return None   # only a statement may follow: what else is said is read as said
    nnp = PhraseParser().parse(new, 0) if new else None
    if nnp is None or nnp.end != len(new):
        return None
    n = len(said)
    hit = next((sp for sp in reversed(_np_spans(prev)) if not sp.pronoun and
                prev[sp.start + 1:sp.start + 1 + n] == said and sp.start + 1 + n < sp.end and
                prev[sp.start] in DETERMINERS), None)
    if hit is None:
        return None
    cut = _relation_start(prev, hit)
    noun = prev[hit.start + 1 + n:cut if cut is not None else hit.end]
    if nnp.pronoun == 'one' or new[-1] == 'one':
        k = len(new) - 1 - new[::-1].index('one')
        new = new[:k] + noun + new[k + 1:]
    if tail:
        notes.append(f'left out "{" ".join(tail)}" (asks for nothing)')
    keep = cut if cut is not None and not nnp.descriptor.relations else hit.end
    return prev[:hit.start] + new + prev[keep:]


def _or_group(prev: list[str]) -> Optional[tuple[int, int, list[NounPhrase]]]:
    """Find the last either-or group of phrases in ``prev`` ("the gazebo or the shed"): start, end, parts."""
    spans = _np_spans(prev)
    for k in range(len(spans) - 1, 0, -1):
        a, b = spans[k - 1], spans[k]
        if prev[a.end:b.start] == ['or']:
            group = [a, b]
            m = k - 1
            while m > 0 and prev[spans[m - 1].end:spans[m].start] in (['or'], [','], [',', 'or']):
                m -= 1
                group.insert(0, spans[m])
            start = group[0].start - (prev[group[0].start - 1:group[0].start] == ['either'])
            return start, b.end, group
    return None


def _replace_alternatives(prev: list[str], new: list[str]) -> Optional[list[str]]:
    """Correct a choice: "A or B ... make that A or C" (the new group), "... not B, C" (one of them)."""
    group = _or_group(prev)
    if group is None:
        return None
    start, end, nps = group
    if new[:1] == ['not']:
        parser = PhraseParser()
        old = parser.parse(new, 1)
        if old is None or new[old.end:old.end + 1] != [',']:
            return None
        words = _strip_corr(new[old.end + 1:])
        rep = PhraseParser().parse(words, 0)
        if rep is None or rep.end != len(words):
            return None
        hit = next((sp for sp in nps if sp.descriptor == old.descriptor or sp.head == old.head), None)
        if hit is None:
            return None
        return prev[:hit.start] + words + prev[hit.end:]
    for tail in (['instead', 'of', 'either'], ['instead', 'of', 'either', 'of', 'them'],
                 ['instead', 'of', 'both'], ['instead', 'of', 'them'], ['instead', 'of', 'those']):
        if new[-len(tail):] == tail:
            one = PhraseParser().parse(new, 0)
            if one is not None and one.end == len(new) - len(tail):
                # "make it the gazebo instead of either": the whole choice is replaced
                return prev[:start] + new[:one.end] + prev[end:]
    if 'or' not in new:
        return None
    said, _, stop = PhraseParser().parse_list(new, 0)
    if len(said) < 2 or stop != len(new):
        return None
    return prev[:start] + new + prev[end:]


_THEN_JOINS = ([',', 'then'], ['then'], ['and', 'then'], [',', 'and', 'then'])


def _sequence_of(words: list[str], start: int) -> tuple[list[NounPhrase], int]:
    """Return the places said in order from ``words[start]`` ("the attic, then the cellar"), and their end."""
    parser = PhraseParser()
    out: list[NounPhrase] = []
    k = start
    while True:
        np = parser.parse(words, k)
        if np is None or np.pronoun:
            break
        out.append(np)
        k = np.end
        join = next((j for j in _THEN_JOINS if words[k:k + len(j)] == j), None)
        if join is None or k + len(join) >= len(words):
            break
        k += len(join)
    return out, (out[-1].end if out else start)


def _replace_sequence(prev: list[str], new: list[str]) -> Optional[list[str]]:
    """Correct a route: "go to A, then B. sorry, I meant C, then D": the places said last in order."""
    said, end = _sequence_of(new, 0)
    if len(said) < 2 or end != len(new) or not prev or prev[-1] not in '.;!?':
        return None   # (within the sentence, "..., no, the garage, then the gate" goes on after it)
    spans = _np_spans(prev)
    for k in range(len(spans) - 1, 0, -1):
        run, stop = _sequence_of(prev, spans[k - len(said) + 1].start) if k - len(said) + 1 >= 0 else ([], 0)
        if len(run) == len(said) and stop == spans[k].end:
            before = run[0].start
            if any(prev[before - len(j):before] == j for j in _THEN_JOINS):
                # "go to A, then B, then C. sorry, I meant D, then E": which two does it replace?
                said_new = ' '.join(new)
                raise TranslationError(f'"{said_new}" corrects a route of more places than it names',
                                       details={'part': said_new})
            return prev[:before] + new + prev[stop:]
    return None


def _replace_relation(prev: list[str], new: list[str]) -> Optional[list[str]]:
    """Correct where the last described thing is ("the cart behind the desk, sorry, in front of it").

    ``new`` is a relation said again ("in front of it", "next to the eyewash station", "it's on
    the shelf, not under it"): it replaces the relations of the last phrase that has some.
    """
    if new[:2] == ['it', 'is']:
        new = new[2:]
    k = next((i for i, t in enumerate(new) if t == ','), len(new))
    if new[k + 1:k + 2] == ['not']:
        new = new[:k]   # "..., not under it": what it replaces
    if not new or match_relation(new, 0) is None:
        return None
    target = next((sp for sp in reversed(_np_spans(prev)) if sp.descriptor.relations), None)
    cut = _relation_start(prev, target) if target is not None else None
    if target is None or cut is None:
        return None
    if 'it' in new:
        obj = next((m for m in range(cut, target.end) if prev[m] in DETERMINERS), None)
        if obj is None:
            return None
        i = new.index('it')
        new = new[:i] + prev[obj:target.end] + new[i + 1:]
    return prev[:cut] + new + prev[target.end:]


_COUNT_MODS: tuple[tuple[str, ...], ...] = (
    ('at', 'least'), ('at', 'most'), ('exactly',), ('only',), ('just',), ('no', 'more', 'than'),
    ('not', 'more', 'than'), ('no', 'less', 'than'), ('up', 'to'), ('precisely',), ('more', 'than'),
    ('no', 'fewer', 'than'))
# Modifiers that bound a count from above ("don't go there more than once"): said in a prohibition.
_BOUNDS = (('more', 'than'), ('no', 'more', 'than'), ('not', 'more', 'than'))


# Verbs between a bare number and "enough" ("three's plenty", "two will do").
_ENOUGH_VERBS = frozenset({'is', 's', 'will', 'would', 'should', 'are'})
# A bound said after the corrected count ("once is enough, but no more than that"): exactly that many.
_NO_MORE: tuple[tuple[str, ...], ...] = (('no', 'more', 'than', 'that'), ('not', 'more', 'than', 'that'),
                                         ('but', 'no', 'more'), ('and', 'no', 'more'), ('not', 'more'),
                                         ('never', 'more'), ('no', 'more', 'than', 'once'))


def _number(word: str) -> bool:
    """Whether a word is a number ("three", "4": "lobby 3 times. no, make it 4")."""
    return word in NUMBER_WORDS or word.isdigit() and len(word) <= 2


def _count_correction(prev: list[str], seg: list[str]) -> Optional[list[str]]:
    """'visit X twice. no wait, exactly once': the count said before is replaced (with its modifier)."""
    counts = ('once', 'twice', 'thrice')
    while seg[-1:] in (['please'], [','], ['then']) and len(seg) > 2:
        seg = seg[:-1]   # "Correction: three times, please."
    if seg[:1] == ['not'] and ',' in seg[1:5]:
        seg = seg[seg.index(',') + 1:]   # "no wait, not twice, once": the count after the comma
    words = [t for t in seg if t not in PUNCT]
    if len(words) > 2 and _number(words[0]) and words[0] not in counts and words[1] in _ENOUGH_VERBS and \
            {'enough', 'plenty', 'fine', 'sufficient', 'do', 'ok', 'okay'} & set(words[2:4]) and (
            'times' in prev or any(t in counts for t in prev)):
        seg = [seg[0], 'times'] + seg[1:]   # "four times. no, three's plenty": three times
        words = [t for t in seg if t not in PUNCT]
    if len(words) == 1 and _number(words[0]) and words[0] not in counts and (
            'times' in prev or any(t in counts for t in prev)):
        seg = words = [words[0], 'times']   # "two times, no, make it three": three times
    new = next((k for k, w in enumerate(seg) if w in counts or (_number(w) and k + 1 < len(seg)
                                                                and seg[k + 1] == 'times')), -1)
    bare = bool(words) and (words[-1] in counts or words[-1] == 'times') and len(words) <= 4
    said = {'enough', 'instead', 'is', 'make', 'only', 'just', 'exactly', 'least', 'most'} & set(seg)
    if new < 0 or not (said or bare):
        return None
    mod = next((m for m in _COUNT_MODS if tuple(seg[new - len(m):new]) == m), ())
    again = next((k for k in range(new + 1, len(seg)) if seg[k] == seg[new] and seg[new] in counts), -1)
    if again > 0 and mod in ((), ('just',), ('only',)) and seg[again - 1] in ('exactly', 'precisely'):
        new, mod = again, (seg[again - 1],)   # "make it just the once - exactly once": said again, exactly
    if not mod and any(tuple(seg[k:k + len(m)]) == m for k in range(new + 1, len(seg)) for m in _NO_MORE):
        mod = ('exactly',)   # "actually once is enough, but no more than that": exactly once
    new_words = list(mod) + seg[new:new + (1 if seg[new] in counts else 2)]
    tail = seg[new + (1 if seg[new] in counts else 2):]
    if not (tail[:1] == [','] and tail[1:2] and tail[1] in ('then', 'and', 'after', 'but', 'and', 'before') or
            tail[:1] in (['then'], ['and'])):
        tail = []   # "twice, no, make that three times, then go back to the desk": the rest is read on
    for p in range(len(prev) - 1, -1, -1):
        end = p + 1 if prev[p] in counts else (p + 1 if prev[p] == 'times' and p > 0 and
                                               _number(prev[p - 1]) else -1)
        if end < 0:
            continue
        start = p if prev[p] in counts else p - 1
        old_mod = next((m for m in _COUNT_MODS if tuple(prev[start - len(m):start]) == m), ())
        cut = start - len(old_mod)
        if old_mod in _BOUNDS and mod and mod not in _BOUNDS:
            # "don't go to the gym more than once. wait, exactly once": the prohibition is now a goal
            cs = max((k for k in range(cut) if prev[k] in PUNCT), default=-1) + 1
            neg = 2 if prev[cs:cs + 2] == ['do', 'not'] else 1 if prev[cs:cs + 1] == ['never'] else 0
            if neg:
                return prev[:cs] + prev[cs + neg:cut] + new_words + prev[end:] + tail
        if mod == ('just',) and not old_mod:
            new_words = new_words[1:]   # "three times. no, make that just twice": twice, not "only"
        return prev[:cut] + new_words + prev[end:] + tail
    return None

"""Noun phrases to referent descriptors, and the lexicon the offline translator reads by.

A noun phrase such as "the vase next to the lamp that's on the table behind the
couch" becomes the descriptor ``vase::isnextto(lamp::isabove(table::isbehind(couch)))``:
each trailing modifier attaches to the nearest noun before it; ``and`` followed by
another relation ("left of the counter and in front of the fridge") chains a second
relation on the same noun; ``between`` takes two noun phrases.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

from ltl_instruct.core.language.text import NUMBER_WORDS, ORDINALS, PUNCT
from ltl_instruct.core.spec import Descriptor, Relation

DETERMINERS = frozenset({'the', 'a', 'an', 'my', 'your', 'our', 'his', 'her', 'their', 'these', 'those',
                         'some', 'any', 'each', 'both', 'either', 'this'})

# Token sequences that introduce a spatial relation, longest first when matched.
RELATION_PHRASES: tuple[tuple[tuple[str, ...], str], ...] = tuple(sorted((
    (('between',), 'isbetween'), (('in', 'between'), 'isbetween'),
    (('on', 'top', 'of'), 'isabove'), (('on', 'the', 'top', 'of'), 'isabove'), (('on',), 'isabove'),
    (('onto',), 'isabove'), (('above',), 'isabove'), (('over',), 'isabove'), (('atop',), 'isabove'),
    (('under',), 'isbelow'), (('underneath',), 'isbelow'),
    (('below',), 'isbelow'), (('beneath',), 'isbelow'),
    (('to', 'the', 'left', 'of'), 'isleftof'), (('left', 'of'), 'isleftof'),
    (('on', 'the', 'left', 'of'), 'isleftof'), (('to', 'left', 'of'), 'isleftof'),
    (('on', 'the', 'left', 'side', 'of'), 'isleftof'),
    (('to', 'the', 'right', 'of'), 'isrightof'), (('right', 'of'), 'isrightof'),
    (('on', 'the', 'right', 'of'), 'isrightof'), (('to', 'right', 'of'), 'isrightof'),
    (('on', 'the', 'right', 'side', 'of'), 'isrightof'),
    (('in', 'front', 'of'), 'isinfrontof'), (('infront', 'of'), 'isinfrontof'),
    (('behind',), 'isbehind'), (('in', 'back', 'of'), 'isbehind'), (('at', 'the', 'back', 'of'), 'isbehind'),
    (('next', 'to'), 'isnextto'), (('by',), 'isnextto'), (('beside',), 'isnextto'),
    (('besides',), 'isnextto'), (('near',), 'isnextto'), (('close', 'to'), 'isnextto'),
    (('adjacent', 'to'), 'isnextto'), (('nearby',), 'isnextto'),
    (('closest', 'to'), 'isnextto'), (('nearest', 'to'), 'isnextto'), (('nearest',), 'isnextto'),
    (('across', 'from'), 'isinfrontof'), (('opposite',), 'isinfrontof'), (('opposite', 'to'), 'isinfrontof'),
    (('facing',), 'isinfrontof'),
    # as learners of English say them ("the table at right of the lathe", "the cabinet behind of the bench")
    (('at', 'right', 'of'), 'isrightof'), (('at', 'the', 'right', 'of'), 'isrightof'),
    (('on', 'right', 'of'), 'isrightof'), (('at', 'left', 'of'), 'isleftof'),
    (('at', 'the', 'left', 'of'), 'isleftof'), (('on', 'left', 'of'), 'isleftof'),
    (('behind', 'of'), 'isbehind'), (('under', 'of'), 'isbelow'), (('in', 'front', 'to'), 'isinfrontof'),
), key=lambda p: -len(p[0])))

# Destination prepositions: in "put X on Y" they end the object, they are not relations.
DESTINATION_PREPS = frozenset({'on', 'onto', 'in', 'into', 'at', 'to', 'over', 'inside', 'by'})

# "a pair of boots", "a bag of chips": 'of' stays inside the name after these.
CONTAINER_WORDS = frozenset({'pair', 'bag', 'box', 'bottle', 'cup', 'can', 'piece', 'set', 'bunch',
                             'stack', 'glass', 'jar', 'pile', 'bowl', 'plate', 'pack', 'packet', 'roll',
                             'sheet', 'slice', 'loaf', 'carton', 'tub', 'bar', 'basket', 'bucket', 'crate',
                             'tray', 'tin', 'mug', 'pot', 'jug', 'sack', 'case', 'bundle', 'ream', 'tube'})

# "each of a, b and c", "the following locations a, b": words before the names themselves.
LIST_HEADS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('each', 'of'), ('all', 'of'), ('both', 'of'), ('any', 'of'), ('all', 'the', 'following', 'locations'),
    ('the', 'following', 'locations'), ('the', 'following', 'places'), ('all', 'locations'),
    ('all', 'places'), ('all', 'the', 'places'), ('places',), ('the', 'places'), ('landmarks',),
    ('all', 'landmarks'),
    ('the', 'locations'), ('locations',), ('all', 'the', 'locations'), ('the', 'following'),
    ('any', 'locations', 'among'), ('any', 'of', 'the', 'locations'), ('none', 'among'), ('none', 'of'),
    ('either', 'one', 'among'), ('one', 'among'), ('any', 'one', 'among'), ('either', 'of'), ('any', 'of'),
), key=lambda t: -len(t)))

# List heads that make a list a choice ("either of the red door and the blue door").
CHOICE_HEADS: tuple[tuple[str, ...], ...] = (
    ('either', 'of'), ('any', 'of'), ('one', 'of'), ('any', 'one', 'of'), ('either', 'one', 'of'),
    ('whichever', 'of'), ('one', 'among'), ('any', 'one', 'among'), ('either', 'one', 'among'),
    ('any', 'locations', 'among'), ('any', 'of', 'the', 'locations'))

# Words that introduce a relative clause before a relation ("that's on", "which is behind").
RELATIVE_LEADS: tuple[tuple[str, ...], ...] = (
    ('that', 'is', 'right'), ('that', 'is'), ('which', 'is'), ('that', 'are'), ('which', 'are'),
    ('that', 'sits'), ('that', 'is', 'sitting'), ('that', 'is', 'lying'), ('sitting',), ('located',),
    ('placed',), ('standing',), ('lying',), ('right',), ('just',), ('directly',), ('the', 'one'),
    ('hanging',), ('resting',), ('leaning',), ('parked',), ('stored',), ('kept',), ('found',),
    ('that', 'hangs'), ('that', 'sits'), ('that', 'stands'), ('that', 'lies'),
)
# Participles of where a thing was put ("the crate stacked on the pallet", "the van parked by the gate").
_PLACED = ('stacked', 'piled', 'mounted', 'propped', 'perched', 'sat', 'tucked', 'stashed', 'hung',
           'sitting', 'lying', 'standing', 'resting', 'leaning', 'hanging', 'parked', 'stored', 'kept',
           'placed',
           'located', 'positioned', 'balanced', 'wedged', 'installed', 'waiting', 'stuck', 'fixed')
RELATIVE_LEADS = tuple(sorted(set(RELATIVE_LEADS) | {
    lead + (w,) + right for lead in ((), ('that', 'is'), ('which', 'is'), ('that', 'are'), ('which', 'are'),
                                     ('that', 'was'), ('that', 'were'))
    for w in _PLACED for right in ((), ('right',), ('just',), ('directly',))} | {
    lead + (right,) for lead in (('that', 'is'), ('which', 'is'), ('that', 'are'), ('which', 'are'))
    for right in ('right', 'just', 'directly')}, key=lambda t: -len(t)))

# Words that are never part of a name.
STOPWORDS = frozenset('''
lying somebody someone still somewhere
and or then to from at in into on onto with for until while before after when once but so if of as because
also too again there here please it them that which who whom where is are be been being was were you i we
me us he she they finally instead order every all way time times twice thrice exactly least most more
backwards than no not never do does did go going gone went get got visit visited reach reached the a an my
your our this these those some any each both either neither can could would will should must may might shall
has have had make sure just now first lastly last next then around up down off out over through past via
whichever whatever wherever matter care which else other others until till avoid avoiding away stay keep clear
while carrying holding its their own yes yeah okay ok hmm um uh er oh wait sorry actually mean meant
fine enough again cannot cant dont one along throughout entire whole during without except only
always directly immediately ever never by near behind between above under below beneath beside
unless except whenever since because though although otherwise later afterwards afterward means thereafter
something anything everything nothing someone anyone anymore forever staying keeping steering remaining
followed remain forth altogether
'''.split()) - {'one'}

# Words after "the order" that make it the order of the steps ("the order given", "the order matters").
_ORDER_SAID = frozenset({
    'given', 'listed', 'said', 'shown', 'mentioned', 'stated', 'named', 'written', 'matters', 'doesnt',
    'isnt', 'counts', 'changes', 'stays', 'does', 'is', 'was', 'of', 'in', 'from', 'above', 'below',
    'specified', 'provided', 'indicated', 'presented', 'important', 'required', 'needed', 'described'})

# "the roof of the library" -> library_roof: parts named before their whole.
PART_WORDS = frozenset('''
roof top side front back door entrance exit corner end edge middle center centre bottom base foot gate
window wall floor lobby steps stairs porch yard garden balcony
'''.split())

# Prepositions said again before the next alternative of a list ("over the lake or over the forest").
LIST_PREPOSITIONS = frozenset({'to', 'over', 'through', 'past', 'into', 'onto', 'towards', 'toward', 'by'})

# "location b", "landmark c": a generic noun before a known landmark name
PLACE_NOUNS = frozenset({'location', 'landmark', 'place', 'waypoint', 'point'})

# Words before "one" that make it a placeholder ("the blue one") rather than a number ("landmark one").
# Colour words ("the yellow one" corrects the thing said with a colour).
COLOURS = frozenset('''
red blue green yellow orange purple pink brown black white grey gray silver gold golden beige navy teal
cream tan maroon violet turquoise cyan magenta lilac lavender ivory khaki olive charcoal crimson
'''.split())
PLACEHOLDER_ADJECTIVES = COLOURS | frozenset('''
big small large little
tall short long round square other same left right near far front back upper lower top bottom middle new old
wooden metal plastic glass open closed empty full clean dirty dark light first second third last closest
nearest farthest furthest next previous main north south east west northern southern eastern western inner
outer side central rear upstairs downstairs spare tiny huge heavy light narrow wide broken new older newer
'''.split())

LY_NOUNS = frozenset({'family', 'assembly', 'supply', 'jelly', 'belly', 'trolley', 'pulley', 'valley',
                      'alley',
                      'butterfly', 'dragonfly', 'lily', 'holly', 'bully', 'rally', 'gully', 'folly', 'doily',
                      'freshly', 'newly', 'recently'})

NAME_VERBS = frozenset('''
go goes head visit navigate move drive fly walk run come return check find locate reach get bring take put
place leave drop toss throw carry deliver grab pick fetch survey land stop swing patrol charge stand make
'''.split())


# Words before "of" that are no thing named after a whole ("one of the boxes", "the rest of them").
_NOT_OF_NAMES = frozenset('''
one ones lot lots number kind sort type types couple rest most some none half part parts way ways time times
bit amount plenty dozen dozens pair group row line list series full left right ahead north south east west
inside outside
'''.split())


def _of_name(words: Sequence[str], tokens: Sequence[str], j: int) -> bool:
    """Whether "<words> of <tokens[j:]>" names one thing by its whole ("the machine of welding")."""
    if words[-1] in _NOT_OF_NAMES or words[-1] in NUMBER_WORDS or words[-1] in CONTAINER_WORDS:
        return False
    if j < len(tokens) and tokens[j] in ('the', 'a', 'an'):
        j += 1
    return j < len(tokens) and tokens[j] not in STOPWORDS and tokens[j] not in PUNCT and \
        tokens[j] not in NUMBER_WORDS and not tokens[j].isdigit()


def _of_plural(tokens: Sequence[str], j: int) -> bool:
    """Whether ``tokens[j]`` is a bare plural ending a name after "of" ("the hall of mirrors")."""
    w = tokens[j]
    nxt = tokens[j + 1] if j + 1 < len(tokens) else ''
    return len(w) > 4 and w.endswith('s') and not w.endswith(('ss', 'us', 'is')) and w.isalpha() and \
        w not in STOPWORDS and w not in NUMBER_WORDS and (nxt in PUNCT or nxt in STOPWORDS or nxt == '')


def with_article(name: str) -> str:
    """Return ``name`` with "the" before it, unless it has a determiner or is a number ("204")."""
    return name if name.split()[0] in DETERMINERS or name[0].isdigit() else 'the ' + name


@dataclass(frozen=True)
class NounPhrase:
    """A parsed noun phrase: its descriptor and the token span it came from.

    Attributes
    ----------
    descriptor: the referent descriptor.
    start, end: token span ``[start, end)`` in the token list parsed.
    head: the last word of the head name (``cup`` in ``red_cup``), used to match corrections.
    pronoun: the pronoun or placeholder it stands for (``it``, ``there``, ``one``), else ``''``.
    """

    descriptor: Descriptor
    start: int
    end: int
    head: str
    pronoun: str = ''


# Words in -ing that name a kind of place or thing before a noun ("shelving unit", "loading bay").
_ING_NAMES = frozenset('''
shelving dining sitting living washing parking loading landing waiting meeting changing shipping receiving
packing sewing reading boarding charging vending cutting potting planting filing drying ironing recycling
storing counting sorting welding printing cooling heating lighting seating nursing
'''.split())


def match_relation(tokens: Sequence[str], i: int) -> Optional[tuple[str, int]]:
    """Return the comparator a relation phrase at ``tokens[i]`` introduces, and the index after it."""
    for words, comparator in RELATION_PHRASES:
        n = len(words)
        if tuple(tokens[i:i + n]) == words:
            if words == ('over',) and i + 1 < len(tokens) and tokens[i + 1] in ('to', 'there', 'here'):
                continue
            nxt = tokens[i + n] if i + n < len(tokens) else ''
            if nxt == 'first' and i + n + 1 < len(tokens):
                nxt = tokens[i + n + 1]   # "by first visiting X"
            if nxt.endswith('ing') and nxt not in ('ceiling', 'building', 'railing', 'painting') and not (
                    # "between shelving unit 4 and the wall", "by parking lot B": a name said bare
                    nxt in _ING_NAMES and i + n + 1 < len(tokens) and tokens[i + n + 1] not in PUNCT and
                    tokens[i + n + 1] not in DETERMINERS):
                continue  # "by passing through X" is a manner, not a place
            return comparator, i + n
    return None


_LEADS_BY_FIRST: dict[str, list[tuple[str, ...]]] = {}
for _lead in RELATIVE_LEADS:
    _LEADS_BY_FIRST.setdefault(_lead[0], []).append(_lead)   # longest first, as RELATIVE_LEADS is


def _relative_lead(tokens: Sequence[str], i: int) -> int:
    """Length of a relative-clause lead-in at ``i`` that is followed by a relation, else 0."""
    if i >= len(tokens):
        return 0
    for lead in _LEADS_BY_FIRST.get(tokens[i], ()):
        n = len(lead)
        if tuple(tokens[i:i + n]) == lead and match_relation(tokens, i + n) is not None:
            return n
    return 0


# Verbs of the people at a numbered place, said right after its number ("table 4 wants ketchup").
NUMBER_SUBJECT_VERBS = frozenset({'wants', 'want', 'wanted', 'needs', 'need', 'needed', 'asked', 'asks',
                                  'ordered', 'requested', 'says', 'said', 'complained'})
# Words after a numbered name ("table 4 wants ..."): the name's subject's verb, never more of its name.
_VERBS_AFTER_NUMBER = NUMBER_SUBJECT_VERBS | {'orders', 'would', 'called', 'just'}


# Verbs after a person named with an article or after a comma ("the boss wants ...", ", Marco gets ...").
_VERBS_AFTER_PERSON = frozenset({'wants', 'needs', 'gets', 'hates', 'says', 'thinks', 'worries', 'wanted',
                                 'needed', 'said'})
_BEFORE_PERSON = DETERMINERS | {','}
# Adverbs in -ly seen between an article and an adjective ("the really big box"): no adjective of a name.
_LY_ADVERBS = frozenset({'really', 'fairly', 'truly', 'extremely', 'particularly', 'especially', 'actually',
                         'nearly', 'mostly', 'totally', 'completely', 'slightly', 'terribly', 'awfully',
                         'incredibly', 'reasonably', 'relatively', 'entirely', 'absolutely', 'usually',
                         'probably', 'definitely', 'certainly', 'possibly', 'exactly', 'quickly', 'carefully',
                         'slowly', 'gently', 'quietly', 'simply', 'currently', 'normally', 'originally'})


CAN_DETERMINERS = frozenset({'the', 'a', 'an', 'that', 'this', 'each', 'every', 'my', 'your', 'our',
                             'empty', 'old', 'open', 'tin', 'paint', 'trash', 'garbage', 'watering'})


# Adverbs of place: after a name they say where the thing is or goes ("the basket upstairs").
_PLACE_ADVERBS = frozenset({'upstairs', 'downstairs', 'outside', 'outdoors', 'indoors'})


def is_name_word(tokens: Sequence[str], i: int, have_name: bool) -> bool:
    """Whether ``tokens[i]`` can be part of an object's name."""
    if i >= len(tokens):
        return False
    w = tokens[i]
    if w in PUNCT or not w.replace('_', '').isalnum():
        return False
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ''
    if w in ORDINALS:
        return nxt not in PUNCT and nxt not in STOPWORDS and nxt != '' and nxt not in ('one',)
    if w == 'one':
        return nxt not in ('times', 'time', 'more')
    if w == 'order' and not have_name and i > 0 and tokens[i - 1] in DETERMINERS and \
            tokens[i - 2:i - 1] not in (['in'], ['any'], ['same']) and nxt.isalpha() and \
            nxt not in STOPWORDS and nxt not in _ORDER_SAID:
        return True   # "the order picker", "the order desk": a thing; "in the order given" is no name
    if w == 'can':   # "the soda can", "the can" are things; "you can go" is not
        after_det = i > 0 and tokens[i - 1] in CAN_DETERMINERS
        return (have_name or after_det) and nxt not in ('you', 'i', 'we', 'go', 'be', 'not', 'wait', 'come',
                                                        'stay', 'do', 'have', 'get', 'see', 'hold', 'only',
                                                        'also', 'still', 'always', 'never', 'just')
    if w in ('once', 'twice', 'thrice') or have_name and w in ('anywhere', 'everywhere', 'nowhere'):
        return False   # ("the glass harp anywhere along the way": "anywhere" ends the name)
    if w in ('stays', 'remains') and have_name and nxt in ('put', 'here', 'there', 'where', 'on', 'off', 'in',
                                                           'inside', 'outside', 'behind', 'as', 'untouched',
                                                           'closed', 'shut', 'open', '', ',', '.'):
        return False   # "the cola stays put", "the lamp stays on": the thing, then what is said of it
    if w in ('comes', 'goes') and have_name and nxt in ('first', 'last', 'next', 'second', 'third', 'before',
                                                        'after', 'later', 'earlier', 'at', 'in', 'into',
                                                        'only'):
        return False   # "the checkout comes last", "the lamp goes in the box"
    if w == 'till':
        return True   # "the till", "till 4": the counter (tokenize made every other "till" "until")
    if have_name and w in _VERBS_AFTER_NUMBER and i > 0 and (
            tokens[i - 1].isdigit() or tokens[i - 1] in NUMBER_WORDS):
        return False   # "table 4 wants ketchup", "room 12 asked for towels": the number ends the name
    if w in ('need', 'needs') and have_name and (nxt.endswith('ing') or nxt in (
            'to', 'a', 'an', 'some', 'inspection', 'attention', 'help', 'work', 'repair', 'repairs')):
        return False   # "carousels 3, 5 and 9 need inspection", "the dock needs cleaning": the name ends
    if have_name and w in _VERBS_AFTER_PERSON and (i == 1 or i > 1 and tokens[i - 2] in _BEFORE_PERSON):
        return False   # "the boss wants no robots in the lobby", "Marco gets chatty": a verb, not a name
    if w in NUMBER_WORDS or w.isdigit():
        # ("bay 6 more than once": the label, then the bound; "the hall 3 more times" is a count)
        return have_name and nxt not in ('times', 'time', 'separate') and (
            nxt != 'more' or tokens[i + 2:i + 3] == ['than'])
    if w == 'other' and not have_name and nxt not in STOPWORDS and nxt not in PUNCT and nxt and \
            nxt not in NUMBER_WORDS and nxt not in ('ones', 'one'):
        return True   # "the other desk"
    if w == 'time' and i > 0 and tokens[i - 1] in ('the', 'a', 'my', 'our', 'your') and nxt.isalpha() and \
            nxt not in STOPWORDS and nxt not in NUMBER_WORDS and not nxt.endswith('ly'):
        return True   # "the time clock", "a time sheet": a thing named for time (not "the time you ...")
    if w in STOPWORDS:
        return False
    if have_name and w in _PLACE_ADVERBS:
        return False   # "the laundry basket upstairs to the bedroom": where it is or goes, not its name
    if w.endswith('ly') and len(w) > 5 and w not in LY_NOUNS:
        # adverbs ("quickly", "carefully") are not names; an adjective is, between an article and a noun
        # ("a woolly hat", "the curly wig"; not "the really big box")
        return i > 0 and tokens[i - 1] in DETERMINERS and w not in _LY_ADVERBS and nxt.isalpha() and \
            not nxt.endswith('ly') and nxt not in STOPWORDS
    return True


def singular(word: str) -> str:
    """Crude singular of a plural noun (``chairs`` -> ``chair``, ``boxes`` -> ``box``)."""
    if word.endswith('ies') and len(word) > 4:
        return word[:-3] + 'y'
    if word.endswith(('ches', 'shes', 'xes', 'sses')):
        return word[:-2]
    if word.endswith('s') and not word.endswith('ss') and len(word) > 3:
        return word[:-1]
    return word


def name_of(words: Sequence[str], digits: bool = False) -> str:
    """Snake-case name from name words; a number stays as written ("aisle seven", "dock 3").

    With ``digits`` a cardinal number word after a noun becomes digits ("landmark one":
    ``landmark_1``, as the drone-planning data set names its landmarks).
    """
    out = []
    for k, w in enumerate(w.lower() for w in words):   # acronyms ("the IT office") are upper case
        if digits and k > 0 and w in NUMBER_WORDS and w not in ('once', 'twice', 'thrice'):
            w = str(NUMBER_WORDS[w])
        out.append(w)
    name = '_'.join(out)
    if name and not name[0].isalpha():
        name = 'n_' + name
    return name


def _attach(d: Descriptor, appositive: Descriptor, same: bool = False) -> Optional[Descriptor]:
    """``d`` with the relations of ``appositive`` added to the noun inside it that it names again.

    The noun matched is the one named last (deepest first), with the same head word and
    a name that the appositive's name ends ("tall_cabinet" ... "the cabinet"), and
    that has no relations of its own; None if there is none. With ``same`` ("the printer
    by the window, the one left of the desk") the relations are added to ``d`` itself.
    """
    if same and d.name == appositive.name:
        extra = tuple(r for r in appositive.relations if r not in d.relations)
        return Descriptor(d.name, d.relations + extra)
    for k, rel in reversed(list(enumerate(d.relations))):
        for a, arg in reversed(list(enumerate(rel.args))):
            inner = _attach(arg, appositive)
            if inner is not None:
                args = rel.args[:a] + (inner,) + rel.args[a + 1:]
                rels = d.relations[:k] + (Relation(rel.comparator, args),) + d.relations[k + 1:]
                return Descriptor(d.name, rels)
    if d.relations or not (d.name == appositive.name or d.name.endswith('_' + appositive.name)):
        return None
    return Descriptor(d.name, appositive.relations)


class PhraseParser:
    """Parses noun phrases in a token list; remembers the last ones for pronouns and "the one"."""

    def __init__(self, landmarks: Sequence[str] = (), digits: bool = False) -> None:
        self.digits = digits   # number words in names become digits (see name_of)
        self.last: Optional[NounPhrase] = None
        self.last_plural: Optional[NounPhrase] = None   # "the dirty towels ... the clean ones"
        self._last_key: tuple[str, ...] = ()
        self._before_last: Optional[NounPhrase] = None
        # known landmark names, as token tuples, longest first ("a", "red room", "landmark_1")
        self.landmarks = sorted({tuple(name.replace('_', ' ').split()) for name in landmarks},
                                key=lambda t: -len(t))

    def _landmark(self, tokens: Sequence[str], i: int) -> Optional[tuple[str, ...]]:
        for words in self.landmarks:
            if tuple(tokens[i:i + len(words)]) == words:
                return words
        return None

    def parse(self, tokens: Sequence[str], i: int, destination_stops: bool = False,
              depth: int = 0) -> Optional[NounPhrase]:
        """Parse one noun phrase starting at ``tokens[i]``; None if there is none.

        Parameters
        ----------
        tokens:
            The token list.
        i:
            Where the phrase starts (determiners are skipped).
        destination_stops:
            True for the object of put/place verbs: a bare destination preposition
            ("on", "in", "at") ends the phrase instead of starting a relation.
        depth:
            Nesting level, bounded so hostile input cannot recurse deeply.
        """
        if depth > 8:
            return None
        if depth == 0:
            # the same phrase read again ("then the drawer under it", tried by several readers):
            # its pronouns mean what they meant the first time, not the phrase itself
            key = tuple(tokens[i:i + 12])
            if key == self._last_key:
                self.last = self._before_last
            else:
                self._last_key, self._before_last = key, self.last
        start = i
        for head in LIST_HEADS:
            if tuple(tokens[i:i + len(head)]) == head and i + len(head) < len(tokens):
                i += len(head)
                break
        if self.landmarks:
            j = i + 1 if i < len(tokens) and tokens[i] == 'the' else i
            if j + 1 < len(tokens) and tokens[j] in PLACE_NOUNS and self._landmark(tokens, j + 1) is not None:
                j += 1   # "location b": the landmark b
            lm = self._landmark(tokens, j)
            if lm is not None:
                np = NounPhrase(Descriptor(name_of(list(lm), self.digits)), start, j + len(lm), lm[-1])
                if depth == 0:
                    self.last = np
                return np
        while i < len(tokens) and tokens[i] in DETERMINERS and not (
                self.landmarks and self._landmark(tokens, i)):
            i += 1
        words: list[str] = []
        pronoun = ''
        if depth > 0 and i + 1 < len(tokens) and tokens[i] in ('that', 'this') and tokens[i + 1] not in (
                'is', 'one', 'ones') and is_name_word(tokens, i + 1, False) and \
                not match_relation(tokens, i + 1):
            # "the filing cabinet behind that desk": the desk said before (with its own description)
            inner = self.parse(tokens, i + 1, destination_stops, depth + 1)
            last = self.last
            if inner is not None and not inner.descriptor.relations and last is not None and \
                    last.descriptor.relations and last.descriptor.name == inner.descriptor.name:
                return NounPhrase(last.descriptor, start, inner.end, inner.head)
            if inner is not None:
                return NounPhrase(inner.descriptor, start, inner.end, inner.head, inner.pronoun)
        if i < len(tokens) and tokens[i] in ('it', 'them', 'there', 'that', 'here') and not (
                tokens[i] == 'that' and i + 1 < len(tokens) and tokens[i + 1] == 'is'):
            pronoun = tokens[i]
            i += 1
        else:
            while is_name_word(tokens, i, bool(words)) and not (
                    words and (match_relation(tokens, i) or _relative_lead(tokens, i))) and not (
                    destination_stops and words and tokens[i] in ('back', 'away', 'down')
                    and i + 1 < len(tokens) and tokens[i + 1] in DESTINATION_PREPS):
                words.append(tokens[i])
                i += 1
                if i + 1 < len(tokens) and tokens[i] == 'of' and (words[-1] in CONTAINER_WORDS or _of_plural(
                        tokens, i + 1)):
                    words.append('of')   # "the hall of mirrors", "the Hall of Kings": one name, said so
                    i += 1
            sides = (('on', 'the'), ('to', 'the'), ('on', 'your'), ('to', 'your'))
            if words and tuple(tokens[i:i + 2]) in sides \
                    and i + 2 < len(tokens) and tokens[i + 2] in ('left', 'right') and (
                    i + 3 >= len(tokens) or tokens[i + 3] not in ('of', 'side')):
                words = [tokens[i + 2]] + words   # "the lamp on the left" is the left lamp
                i += 3
            if words and i + 1 < len(tokens) and tokens[i] == 'of' and depth < 8 and (
                    words[-1] in PART_WORDS or _of_name(words, tokens, i + 1)):
                # "the roof of the library" -> library_roof; as learners name things, "the machine of
                # welding" -> welding_machine, "the office of supervisor" -> supervisor_office
                whole = self.parse(tokens, i + 1, destination_stops, depth + 1)
                if whole is not None and not whole.descriptor.relations and not whole.pronoun:
                    words = whole.descriptor.name.split('_') + words
                    i = whole.end
        if words in (['spot'], ['somewhere'], ['place'], ['point'], ['location'], ['area'], ['anywhere'],
                     ['anyplace']) and i + 1 < len(
                tokens) and (tokens[i] in ('in', 'on', 'inside', 'at', 'of') or tokens[i] == 'near' and
                             words in (['anywhere'], ['somewhere'])) and depth < 8:   # ("anywhere near it")
            inner = self.parse(tokens, i + 1, destination_stops, depth)
            if inner is not None:
                return NounPhrase(inner.descriptor, start, inner.end, inner.head, inner.pronoun)
        if not words and not pronoun:
            return None
        if pronoun:
            if self.last is None:
                return None
            ref = self.last
            return NounPhrase(ref.descriptor, start, i, ref.head, pronoun)
        one = words[-1] in ('one', 'ones') and (len(words) == 1 or words[-2] in PLACEHOLDER_ADJECTIVES) and \
            (words[-1] == 'one' or len(words) > 1)   # "the north vine rows or the south ones"
        if one:
            last = self.last
            if words[-1] == 'ones' and last is not None and singular(last.head) == last.head and \
                    self.last_plural is not None:
                last = self.last_plural   # "the dirty towels to the hamper, the clean ones ...": towels
            base = last.descriptor.name if last is not None else ''
            if len(words) == 1:
                words = base.split('_') if base else words
            elif last is not None:
                named = last.descriptor.name.split('_')
                if len(words) == 2 and len(named) > 2 and named[0] in PLACEHOLDER_ADJECTIVES and not any(
                        w in PLACEHOLDER_ADJECTIVES for w in named[1:]):
                    # "the left loading door or the right one": one is the loading door
                    words = words[:-1] + named[1:]
                else:
                    words = words[:-1] + [last.head]
        head = words[-1]
        relations: list[Relation] = []
        while i < len(tokens):
            j = i
            if tokens[j] == ',' and j + 1 < len(tokens) and tokens[j + 1] in ('which', 'that') and \
                    _relative_lead(tokens, j + 1):
                j += 1   # "the pantry, which is next to the kitchen"
            lead = _relative_lead(tokens, j) + (j - i)
            j = i
            if not lead and relations and tokens[j] in ('and', 'but') and \
                    tokens[j + 1:j + 3] != ['the', 'one']:
                # (but "the lamp by the sink and the one by the door" is a second lamp)
                lead = 1 + _relative_lead(tokens, j + 1) if match_relation(tokens, j + 1 + _relative_lead(
                    tokens, j + 1)) else 0
            j += lead
            rel = match_relation(tokens, j)
            if rel is None:
                break
            comparator, k = rel
            if not lead and (destination_stops and tokens[j] in DESTINATION_PREPS or
                             tokens[j] in ('onto', 'into')):
                break   # "move the plant onto the sill": where it goes, never where it is
            arg1 = self.parse(tokens, k, destination_stops, depth + 1)
            if arg1 is None:
                break
            if comparator == 'isbetween':
                if arg1.end < len(tokens) and tokens[arg1.end] == 'and':
                    arg2 = self.parse(tokens, arg1.end + 1, destination_stops, depth + 1)
                else:
                    arg2 = None
                if arg2 is None:
                    break
                relations.append(Relation(comparator, (arg1.descriptor, arg2.descriptor)))
                i = arg2.end
            else:
                target = arg1.descriptor
                if arg1.pronoun in ('it', 'that') and target.relations and target.name == name_of(
                        words, self.digits) and len(target.relations[0].args) == 1:
                    # "the chair left of the board or the chair right of it": it is the board
                    target = target.relations[0].args[0]
                relations.append(Relation(comparator, (target,)))
                i = arg1.end
        np = NounPhrase(Descriptor(name_of(words, self.digits), tuple(relations)), start, i, head,
                        'one' if one else '')
        if depth == 0 and not (tokens[start] == words[0] and words[0] in NAME_VERBS):
            self.last = np   # not a verb tried as a noun ("bring me the blue one": one is not a bring)
            if singular(head) != head:
                self.last_plural = np
        return np

    def parse_list(self, tokens: Sequence[str], i: int, destination_stops: bool = False
                   ) -> tuple[list[NounPhrase], str, int]:
        """Parse "X, Y and Z" / "X or Y" / "either X or Y" / "both X and Y".

        Returns
        -------
        (phrases, joiner, end): joiner is ``'and'``, ``'or'`` or ``''`` for a single phrase.
        """
        joiner = ''
        # "either of X and Y", "any one of X, Y and Z": one of them, however they are joined
        choice = any(tuple(tokens[i:i + len(h)]) == h for h in CHOICE_HEADS)
        if i < len(tokens) and tokens[i] in ('either', 'both') and tokens[i + 1:i + 2] != ['of']:
            i += 1
        phrases: list[NounPhrase] = []
        first = self.parse(tokens, i, destination_stops)
        if first is None:
            return [], '', i
        phrases.append(first)
        i = first.end
        while i < len(tokens):
            j = i
            sep = ''
            if tokens[j] == ',':
                j += 1
                sep = 'and'
            if tuple(tokens[j:j + 3]) in (('as', 'well', 'as'), ('along', 'with', 'the')) or \
                    tokens[j:j + 1] == ['plus']:
                j += 1 if tokens[j] == 'plus' else (3 if tokens[j] == 'as' else 2)   # "X as well as Y"
                sep = 'and'
            if j < len(tokens) and tokens[j] in ('and', 'or', 'nor'):
                sep = 'or' if tokens[j] == 'or' else 'and'
                j += 1
            if not sep and self.landmarks and self._landmark(tokens, j) is not None:
                sep = 'and'
            if not sep:
                break
            if j < len(tokens) and tokens[j] in ('then', 'after', 'finally', 'also'):
                break
            if sep == 'or' and j + 1 < len(tokens) and tokens[j] in LIST_PREPOSITIONS and i > 0 and \
                    tokens[phrases[0].start - 1] == tokens[j]:
                j += 1   # "over the lake or over the forest": the preposition said again
            nxt = self.parse(tokens, j, destination_stops)
            if nxt is None or nxt.pronoun in ('there', 'it', 'them', 'that', 'here'):
                break
            if sep == 'and' and tokens[i] == ',' and j == i + 1 and nxt.descriptor.relations and \
                    nxt.pronoun in ('', 'one') and not ((tokens[j] in ('one', 'a', 'an') or
                                                         tokens[j:j + 2] == ['the', 'one']) and
                                                        phrases[-1].pronoun == 'one'):
                # (but "one by the sink, one under the skylight", "a red one by X, a blue one by Y", "the
                # one by the window, the one by the sink" are lists)
                # "the box on the tall cabinet, the cabinet that's left of the heater": the same cabinet
                merged = _attach(phrases[-1].descriptor, nxt.descriptor, nxt.pronoun == 'one')
                if merged is not None:
                    phrases[-1] = NounPhrase(merged, phrases[-1].start, nxt.end, phrases[-1].head)
                    i = nxt.end
                    continue
            if tokens[i] == ',' and j == i + 1 and tokens[j] not in DETERMINERS and \
                    nxt.end < len(tokens) and tokens[nxt.end] in ('is', 'are', 'was', 'has', 'have', 'wants',
                                                                  'needs', 'will'):
                break   # "to the conservatory, Arthur's waiting": a clause of its own, no item of the list
            if j < len(tokens) and tokens[j] in NAME_VERBS and not (
                    nxt.end < len(tokens) and tokens[nxt.end] == ':' and nxt.end - j > 1 and
                    tokens[j + 1] not in DETERMINERS):
                break   # (but "trampoline, pool, swing set: ...": a name that starts with a verb's word)
            phrases.append(nxt)
            joiner = sep if sep == 'or' or not joiner else joiner
            i = nxt.end
        if choice and len(phrases) > 1:
            joiner = 'or'
        kind = phrases[0].descriptor
        if joiner == 'or' and len(phrases) > 2 and not kind.relations and not phrases[0].pronoun and all(
                p.pronoun == 'one' and p.descriptor.name.endswith('_' + kind.name) for p in phrases[1:]):
            phrases = phrases[1:]   # "either lounge, the big one or the little one": the kind, then which
        return phrases, joiner, i


# Nouns after "in" that name no place ("in this strict order", "in a row", "in any case").
_NOT_PLACES = frozenset({'order', 'sequence', 'turn', 'row', 'way', 'case', 'fact', 'addition', 'time',
                         'general', 'advance', 'total', 'particular', 'reverse', 'meantime', 'end', 'future',
                         'morning',
                         'evening', 'afternoon', 'night', 'process', 'hurry', 'moment', 'minute', 'manner'})
# Parts of a place where a thing is ("at the end of the hall", "in the corner of the room").
_PART_OF_PLACE = frozenset({'end', 'far', 'top', 'bottom', 'corner', 'side', 'edge', 'foot', 'head', 'middle',
                            'center', 'centre', 'back', 'front', 'rear', 'entrance', 'near'})


def location_phrase(tokens: Sequence[str], i: int, parser: 'PhraseParser') -> int:
    """Where a phrase saying *where* a thing is ends ("in the closet", "at the end of the hall"), or -1.

    No comparator says "inside" ("isin" is none of ours), so such a phrase names where to
    look, not which thing: the translator reads the thing without it (and notes so).
    """
    if i >= len(tokens):
        return -1
    w = tokens[i]
    if w in _PLACE_ADVERBS:
        return i + 1
    if w == 'down' and tokens[i + 1:i + 2] == ['the'] and \
            tokens[i + 2:i + 3] in (['hall'], ['hallway'], ['corridor']):
        return i + 3
    k = i
    if w in ('in', 'at', 'on') and tokens[i + 1:i + 2] == ['the'] and i + 3 < len(tokens) and \
            tokens[i + 2] in _PART_OF_PLACE and tokens[i + 3] in ('of', 'end'):
        k = i + 4 if tokens[i + 3] == 'of' else (i + 5 if tokens[i + 4:i + 5] == ['of'] else -1)
        if k < 0:
            return -1
    elif w in ('in', 'inside', 'within') and i + 1 < len(tokens) and tokens[i + 1] in DETERMINERS and \
            not _NOT_PLACES & set(tokens[i + 1:i + 5]):
        k = i + 1
    else:
        return -1
    np = parser.parse(tokens, k)
    return np.end if np is not None and not np.pronoun else -1


def source_relation(tokens: Sequence[str], i: int, parser: 'PhraseParser') -> Optional[tuple[Relation, int]]:
    """Where a carried thing is taken from, said after it, as a relation of it, and the index after it.

    "from the closet" and "out of the closet": nearness (``isnextto``); "off the couch" and
    "off of the couch": on it (``isabove``); "from under the sofa": that relation. The one home of
    this reading for the rules and the learned translator; None when no source is said at ``i``.
    """
    w = tokens[i] if i < len(tokens) else ''
    if w == 'from':
        rel = match_relation(tokens, i + 1)
        if rel is not None and rel[0] != 'isnextto':
            comparator, k = rel   # "the remote from under the sofa"
        else:
            comparator, k = 'isnextto', i + 1
    elif w == 'off':
        comparator, k = 'isabove', i + 2 if tokens[i + 1:i + 2] == ['of'] else i + 1
    elif w == 'out' and tokens[i + 1:i + 2] == ['of']:
        comparator, k = 'isnextto', i + 2
    else:
        return None
    src = parser.parse(tokens, k, destination_stops=True)
    if src is None or src.pronoun:
        return None
    return Relation(comparator, (src.descriptor,)), src.end

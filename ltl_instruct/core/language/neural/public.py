"""The public human-written data sets: fixed train/test splits and tagged training examples.

Sets (names of the API), read from ``shared/datasets`` beside the repository (or the folder
named by the environment variable ``LTL_INSTRUCT_DATASETS``); every proposition ``p`` becomes
``near[p]`` (gold formulas in our syntax):

- ``drone``: efficient-eng-2-ltl ``drone-planning.jsonl`` (infix; ``purple_room``,
  ``landmark_1``, ``third_floor``... as they are).
- ``cleanup``: efficient-eng-2-ltl ``clean-up.jsonl`` (prefix, capital letters read from the
  ``canonical`` field): ``B`` blue_room, ``C`` green_room, ``R`` red_room, ``Y`` yellow_room,
  ``X`` blue_room_with_chair, ``Z`` green_room_with_chair ("go to the blue/green room with
  chair": push the chair into that room; a compound proposition, kept in the splits but never
  aligned to mentions, as no one span of the text names it).
- ``pick_and_place``: efficient-eng-2-ltl ``pick-and-place.jsonl`` (G-rules kept as they are):
  ``S`` scan, ``A`` cube ("any cubes"), ``R``/``B``/``C``/``Y`` non_red_cube, non_blue_cube,
  non_green_cube, non_yellow_cube ("any non red cubes"): the canonical words in snake case,
  singular, without "any".
- ``lifted``: lang2ltl ``lifted.csv`` (letters ``a b c d h`` are the propositions).
- ``lifted_formula``: the same file with a formula hold-out (below).
- ``providence``: lang2ltl ``providence_500.csv``; landmark names in snake case without
  punctuation (``Citizen's Bank`` -> ``citizens_bank``, ``Thayer St`` -> ``thayer_st``).
- ``cleanup_l2l``: lang2ltl ``cleanup.csv`` (the clean-up letters, with ``D`` for red_room).

Rows that cannot be read are skipped and counted (``DataSet.skipped``), never turned into
wrong examples.

Splits (fixed; version ``v1``): an item is in the test split when
``int(sha256(f'ltl_instruct-translate-test-v1|{group}|{key}').hexdigest()[:8], 16) / 2**32``
is below the set's fraction (0.2; 0.25 for ``cleanup`` and ``cleanup_l2l``, whose many repeated
utterances would leave the clean-up test split under 600 items at 0.2). ``key`` is the utterance
lower-cased with white space collapsed, so copies of one utterance never straddle the split. ``group`` is the
set's name, except that ``cleanup_l2l`` uses ``cleanup`` (its utterances are a cleaned copy of
clean-up.jsonl's, and must fall on the same side) and ``lifted_formula`` hashes the formula's
*structure* instead of the utterance: the ``ltl_formula`` column with each letter replaced by
its order of first appearance (``& F a F b`` -> ``& F 1 F 2``), so that whole formula
structures are held out (fraction 0.2 of structures).

A validation split is carved out of the train split the same way (salt group ``valid|<group>``,
fraction 0.1 of the non-test keys; ``lifted`` and ``lifted_formula`` share theirs): it is never
trained on, and is where the combined translator's policy is chosen (``bench.translator_policy``),
so the test splits stay unseen by every choice.

Training (:func:`tagged_examples`) uses the train split of the set minus every item whose
utterance is a test or validation key of any set (the sets share phrases such as "go to the red room"); for
``lifted`` (and ``lifted_formula``) it uses the intersection of both train splits: neither
held-out utterances nor held-out formula structures are ever seen in training.

Mentions: for each training item the spans of the utterance that name each proposition are
found by set-specific patterns (number words and digits for landmarks, ordinals and the typos of
the data for floors, colour words alone for clean-up rooms, letters for lifted, names in any case
for providence, "scan" and the scanning motion described, "non red blocks" / "cubes that are not
red" / "blocks except the red ones" for pick-and-place), each span taking a leading determiner
("the purple room"). The data's own colour words are read as it uses them: "pink" is the clean-up
red room (42 of the 'go to the pink room' rows are ``F R``), "orange" the pick-and-place red cubes
(48 of 56 rows with it are ``R``). All mentions of all
propositions are tagged. An item is skipped (and counted, with its reason) when a proposition of
the gold formula is not found, when the text names a proposition of the set that the gold formula
lacks (a label error or a reference we cannot place), or when a lifted letter ``a`` may be the
article.
"""
from __future__ import annotations

import collections
import csv
import dataclasses
import functools
import hashlib
import json
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable, Optional

from ltl_instruct.core.errors import InvalidInputError, LtlInstructError
from ltl_instruct.core.language.datasets import DataSet, Example, parse_prefix_ltl
from ltl_instruct.core.language.neural.examples import Mention, TaggedExample, check_example
from ltl_instruct.core.spec import Descriptor, Formula, parse_formula, referents_of, rename_descriptors

# the conventions of each set's formulas, as options of the translators (rules and model) that
# read them; bench.translation_public and bench.translator_policy give them to both
SET_OPTIONS: dict[str, dict[str, str]] = {
    'drone': {'avoid_scope': 'goal', 'numbers': 'digits'},
    'cleanup': {'onway_scope': 'run'},
    'cleanup_l2l': {'onway_scope': 'run'},
    'lifted': {'once_scope': 'next', 'after_scope': 'conditional'},
    'lifted_formula': {'once_scope': 'next', 'after_scope': 'conditional'},
}
SETS: tuple[str, ...] = ('drone', 'cleanup', 'pick_and_place', 'lifted', 'lifted_formula',
                         'providence', 'cleanup_l2l')
SALT = 'ltl_instruct-translate-test-v1'
# clean-up repeats its utterances, so 0.2 of its keys gives only 542 test items; 0.25 gives 665
FRACTION: dict[str, float] = {name: 0.25 if name in ('cleanup', 'cleanup_l2l') else 0.2 for name in SETS}
ENV_VAR = 'LTL_INSTRUCT_DATASETS'

_FILES = {
    'drone': 'efficient-eng-2-ltl/drone-planning.jsonl',
    'cleanup': 'efficient-eng-2-ltl/clean-up.jsonl',
    'pick_and_place': 'efficient-eng-2-ltl/pick-and-place.jsonl',
    'lifted': 'lang2ltl/lifted.csv',
    'lifted_formula': 'lang2ltl/lifted.csv',
    'providence': 'lang2ltl/providence_500.csv',
    'cleanup_l2l': 'lang2ltl/cleanup.csv',
}
_GROUP = {'cleanup_l2l': 'cleanup'}
VALID_FRACTION = 0.1

CLEANUP_LETTERS = {'B': 'blue_room', 'C': 'green_room', 'R': 'red_room', 'Y': 'yellow_room',
                   'X': 'blue_room_with_chair', 'Z': 'green_room_with_chair'}
CLEANUP_L2L_LETTERS = {'B': 'blue_room', 'C': 'green_room', 'D': 'red_room', 'Y': 'yellow_room'}
PICK_LETTERS = {'S': 'scan', 'A': 'cube', 'R': 'non_red_cube', 'B': 'non_blue_cube',
                'C': 'non_green_cube', 'Y': 'non_yellow_cube'}


def datasets_root() -> Optional[Path]:
    """Return the folder of the public data sets (``$LTL_INSTRUCT_DATASETS``, ``../shared/datasets``)."""
    env = os.environ.get(ENV_VAR)
    if env:
        p = Path(env)
        return p if p.is_dir() else None
    p = Path(__file__).resolve().parents[4].parent / 'shared' / 'datasets'
    return p if p.is_dir() else None


def normalise(text: str) -> str:
    """Return the split key of an utterance: lower case, white space collapsed."""
    return ' '.join(text.lower().split())


def in_test(group: str, key: str, fraction: float) -> bool:
    """Whether ``key`` of ``group`` falls in the test split."""
    h = hashlib.sha256(f'{SALT}|{group}|{key}'.encode('utf-8')).hexdigest()
    return int(h[:8], 16) / 2 ** 32 < fraction


@dataclass(frozen=True)
class _Item:
    text: str
    formula: Formula
    source: str
    structure: str = ''   # lifted only: the formula with letters numbered


# ---------------------------------------------------------------------------- readers

def _canonical(f: Formula) -> Formula:
    """Return the formula as our parser reads its text (``a & (b & c)`` becomes ``a & b & c``)."""
    return parse_formula(str(f))


def _letters_formula(raw: str, letters: dict[str, str]) -> Formula:
    toks = []
    for t in raw.split():
        if t in letters:
            toks.append(letters[t])
        elif t.isalpha() and t.isupper() and t not in ('F', 'G', 'U'):
            raise LtlInstructError(f'unknown letter {t!r}')
        else:
            toks.append(t)
    return parse_prefix_ltl(' '.join(toks))


def _read_jsonl(path: Path, letters: Optional[dict[str, str]]) -> tuple[list[_Item], list[str]]:
    items, skipped = [], []
    for n, line in enumerate(path.read_text(encoding='utf-8').splitlines(), 1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
            raw, text = d['raw_ltl'], d['natural']
            if not isinstance(text, str) or not text.strip():
                raise ValueError('empty utterance')
            f = parse_formula(raw) if letters is None else _letters_formula(raw, letters)
            items.append(_Item(text, _canonical(f), f'{path.name}:{n}'))
        except (ValueError, KeyError, TypeError, AttributeError, LtlInstructError) as e:
            skipped.append(f'{path.name}:{n}: {e}')
    return items, skipped


def _structure(raw: str) -> str:
    order: dict[str, str] = {}
    out = []
    for t in raw.split():
        if len(t) == 1 and t.islower() and t not in ('i', 'e'):
            t = order.setdefault(t, str(len(order) + 1))
        out.append(t)
    return ' '.join(out)


def _read_csv(path: Path, text_col: str, ltl_col: str,
              convert: Callable[[str], Formula], structure: bool = False) -> tuple[list[_Item], list[str]]:
    items, skipped = [], []
    with path.open(encoding='utf-8', newline='') as fh:
        reader = csv.DictReader(fh)
        for row in reader:
            n = reader.line_num
            try:
                text, raw = row[text_col], row[ltl_col]
                if not isinstance(text, str) or not text.strip() or not isinstance(raw, str):
                    raise ValueError('empty utterance or formula')
                items.append(_Item(text, _canonical(convert(raw)), f'{path.name}:{n}',
                                   _structure(raw) if structure else ''))
            except (ValueError, KeyError, TypeError, AttributeError, LtlInstructError) as e:
                skipped.append(f'{path.name}:{n}: {e}')
    return items, skipped


def snake(name: str) -> str:
    """Return a landmark name as a descriptor: ``Citizen's Bank`` -> ``citizens_bank``."""
    s = re.sub(r"['’]", '', name.lower())
    s = re.sub(r'[^a-z0-9]+', '_', s).strip('_')
    if not s or not s[0].isalpha():
        raise ValueError(f'cannot name landmark {name!r}')
    return s


_PROV_OPS = {'F', 'G', 'X', 'U', '!', '&', '|', '(', ')', '~'}


def _providence_tokens(raw: str) -> list[tuple[bool, str]]:
    """Operators and landmark names of a providence formula: ``(is_name, text)``."""
    out: list[tuple[bool, str]] = []
    run: list[str] = []
    for t in re.sub(r'([()!&|~])', r' \1 ', raw).split():
        if t in _PROV_OPS:
            if run:
                out.append((True, ' '.join(run)))
                run = []
            out.append((False, t))
        else:
            run.append(t)
    if run:
        out.append((True, ' '.join(run)))
    return out


def _providence_formula(raw: str) -> Formula:
    return parse_formula(' '.join(snake(t) if is_name else t for is_name, t in _providence_tokens(raw)))


@functools.lru_cache(maxsize=32)
def _read(name: str, root: Path) -> tuple[tuple[_Item, ...], tuple[str, ...]]:
    path = root / _FILES[name]
    if not path.is_file():
        raise InvalidInputError(f'data set {name!r} not found: {path}')
    if name == 'drone':
        items, skipped = _read_jsonl(path, None)
    elif name == 'cleanup':
        items, skipped = _read_jsonl(path, CLEANUP_LETTERS)
    elif name == 'pick_and_place':
        items, skipped = _read_jsonl(path, PICK_LETTERS)
    elif name in ('lifted', 'lifted_formula'):
        items, skipped = _read_csv(path, 'utterance', 'ltl_formula', parse_prefix_ltl, structure=True)
    elif name == 'providence':
        items, skipped = _read_csv(path, 'Sentence', 'LTL', _providence_formula)
    else:
        items, skipped = _read_csv(path, 'Language Command', 'LTL Formula',
                                   lambda raw: _letters_formula(raw, CLEANUP_L2L_LETTERS))
    return tuple(items), tuple(skipped)


def _root(root: Optional[Path]) -> Path:
    r = Path(root) if root is not None else datasets_root()
    if r is None or not r.is_dir():
        raise InvalidInputError(f'public data sets not found (set {ENV_VAR} or place them in '
                                '../shared/datasets)')
    return r


def _check_name(name: str) -> None:
    if name not in SETS:
        raise InvalidInputError(f'unknown public set {name!r}; one of {", ".join(SETS)}')


def _is_test(name: str, item: _Item) -> bool:
    if name == 'lifted_formula':
        return in_test(name, item.structure, FRACTION[name])
    return in_test(_GROUP.get(name, name), normalise(item.text), FRACTION[name])


def _is_valid(name: str, item: _Item) -> bool:
    group = 'lifted' if name == 'lifted_formula' else _GROUP.get(name, name)
    return not _is_test(name, item) and in_test(f'valid|{group}', normalise(item.text), VALID_FRACTION)


def _split_of(name: str, item: _Item) -> str:
    return 'test' if _is_test(name, item) else 'valid' if _is_valid(name, item) else 'train'


def read_split(name: str, split: str, root: Optional[Path] = None) -> DataSet:
    """Read the ``train``, ``valid`` or ``test`` split of a public set, gold formulas in our syntax.

    ``landmarks`` lists every proposition name of the set (all splits); ``skipped`` the rows
    that could not be read.

    Raises
    ------
    InvalidInputError
        Unknown set or split, or the data sets are not found.
    """
    _check_name(name)
    if split not in ('train', 'valid', 'test'):
        raise InvalidInputError(f"split must be 'train', 'valid' or 'test', not {split!r}")
    items, skipped = _read(name, _root(root))
    ds = DataSet(f'{name}:{split}', skipped=list(skipped))
    ds.examples = [Example(it.text, it.formula, it.source) for it in items if _split_of(name, it) == split]
    ds.landmarks = tuple(sorted({str(d) for it in items for d in referents_of(it.formula)}))
    return ds


@functools.lru_cache(maxsize=4)
def _held_out_keys(root: Path) -> frozenset[str]:
    """Utterance keys of every set's test and validation splits."""
    keys: set[str] = set()
    for name in SETS:
        if not (root / _FILES[name]).is_file():
            continue
        items, _ = _read(name, root)
        keys.update(normalise(it.text) for it in items if _split_of(name, it) != 'train')
    return frozenset(keys)


def _train_items(name: str, root: Path) -> list[_Item]:
    """Training items: the train split, minus held-out keys of every set (and both lifted hold-outs)."""
    items, _ = _read(name, root)
    held_out = _held_out_keys(root)
    names = ('lifted', 'lifted_formula') if name in ('lifted', 'lifted_formula') else (name,)
    return [it for it in items if normalise(it.text) not in held_out
            and all(_split_of(n, it) == 'train' for n in names)]


# ---------------------------------------------------------------------------- mentions

_DET = r'(?:\b(?:the|a|an)\s+)?'
_NUM = {'one': '1', 'two': '2', 'three': '3', '1': '1', '2': '2', '3': '3'}
_ORD = {'first': 'first', 'onest': 'first', 'one st': 'first', '1st': 'first', 'one': 'first', '1': 'first',
        'second': 'second', 'twond': 'second', '2nd': 'second', 'two': 'second', '2': 'second',
        'third': 'third', 'threerd': 'third', '3rd': 'third', 'three': 'third', '3': 'third'}

# a finder: text -> (mentions as (start, end, descriptor) in text order, whether any is unsure)
_Finder = Callable[[str], tuple[list[tuple[int, int, str]], bool]]


def _scan(text: str, patterns: Iterable[tuple[re.Pattern[str], Callable[[re.Match[str]], str]]]
          ) -> list[tuple[int, int, str]]:
    found: list[tuple[int, int, str]] = []
    for pat, name in patterns:
        for m in pat.finditer(text):
            found.append((m.start(), m.end(), name(m)))
    found.sort(key=lambda t: (t[0], -(t[1] - t[0])))
    out: list[tuple[int, int, str]] = []
    for s, e, d in found:   # leftmost-longest, no overlaps
        if out and s < out[-1][1]:
            continue
        out.append((s, e, d))
    return out


_DRONE = [
    (re.compile(_DET + r'\b(purple|orange|red|green|yellow|blue)\s+room\b', re.I),
     lambda m: f'{m.group(1).lower()}_room'),
    (re.compile(_DET + r'\b(first|onest|one\s+st|1st|second|twond|2nd|third|threerd|3rd)\s+(?:floor|level)\b',
                re.I), lambda m: f'{_ORD[" ".join(m.group(1).lower().split())]}_floor'),
    (re.compile(_DET + r'\b(?:floor|level)\s+(one|two|three|1|2|3)\b', re.I),
     lambda m: f'{_ORD[m.group(1).lower()]}_floor'),
    (re.compile(_DET + r'\b(?:landmark|landark|land\s+mark)\s*(one|two|three|1|2|3)\b', re.I),
     lambda m: f'landmark_{_NUM[m.group(1).lower()]}'),
]


# The floor words 'onest', 'one st', 'twond', 'threerd' of drone-planning.jsonl carry no
# information: with one floor in the gold formula and one such word in the text, the gold floor is
# first, second and third equally often (52/52/52 for 'onest', 66/66/66 for 'twond'). An item
# that uses one is skipped rather than tagged with a floor the text does not give.
_FLOOR_TYPO = re.compile(r'\b(?:onest|one\s+st|twond|threerd)\s+(?:floor|level)', re.I)


def _find_drone(text: str) -> tuple[list[tuple[int, int, str]], bool]:
    return _scan(text, _DRONE), bool(_FLOOR_TYPO.search(text))


_ROOM_NOUN = r'(?:rooms?|areas?|regions?|rectangles?|squares?|spaces?|zones?|sections?|boxe?s?|one|part|side)'
_SIZE = r'(?:(?:small|smaller|large|larger|big|bigger|little|long|tiny|square|rectangular)\s+)?'


def _colour_finder(colours: dict[str, str]) -> _Finder:
    pat = re.compile(_DET + _SIZE + r'\b(' + '|'.join(colours) + r')\b'
                     + r'(?:\s+(?:colou?red\s+)?(?:rectangular\s+|square\s+)?' + _ROOM_NOUN + r'\b)?', re.I)

    def find(text: str) -> tuple[list[tuple[int, int, str]], bool]:
        return _scan(text, [(pat, lambda m: colours[m.group(1).lower()])]), False
    return find


_find_cleanup = _colour_finder({'blue': 'blue_room', 'green': 'green_room', 'red': 'red_room',
                                'pink': 'red_room', 'yellow': 'yellow_room'})

_CUBE = r'(?:blocks?|cubes?|objects?|pieces?|items?|ones)'
_CDET = r'(?:\b(?:the|a|an|any|all(?:\s+of)?(?:\s+the)?|each|every)\s+)?'
_COL = r'(red|orange|blue|green|yellow)'   # the red cubes are called orange in 48 rows of R
_PICK_COLOUR = {'red': 'red', 'orange': 'red', 'blue': 'blue', 'green': 'green', 'yellow': 'yellow'}
_NOT = r'(?:(?:that|which)\s+)?(?:(?:are|is)\s*(?:not|n\s*\'?\s*t)|(?:aren|isn)\s*\'?\s*t)\s+'


def _non(m: re.Match[str]) -> str:
    return f'non_{_PICK_COLOUR[m.group(1).lower()]}_cube'


_PICK = [
    (re.compile(r'\b(?:scan|scans|scanning|scanned|search|searches|searching|sweep|sweeping|look|looking'
                r'|check|checking)\b', re.I), lambda m: 'scan'),
    # the scanning motion described ("move back and forth", "swing side to side", "watch for")
    (re.compile(r'\b(?:move|moving|swing|swinging|hover|hovering|sweep|sweeping|go|going)'
                r'(?:\s+(?:your|the)\s+arm)?\s+(?:back\s+and\s+(?:forth|fourth)|side\s+to\s+side'
                r'|left\s+and\s+right|right\s+and\s+left|from\s+(?:left\s+to\s+right|right\s+to\s+left))\b'
                r'|\b(?:watch|watching|wait|waiting)\s+for\b', re.I), lambda m: 'scan'),
    (re.compile(_CDET + r'\bnon\s*-?\s*' + _COL + r'\s+(?:colou?red\s+)?' + _CUBE + r'\b', re.I), _non),
    (re.compile(_CDET + r'\b' + _CUBE + r'\s+' + _NOT + _COL + r'\b', re.I), _non),
    (re.compile(_CDET + r'\b' + _CUBE + r'(?:\s+[a-z]+){0,3}?\s+(?:except|but)\s+(?:for\s+)?(?:the\s+)?'
                + _COL + r'(?:\s+' + _CUBE + r')?\b', re.I), _non),
]
_PLAIN_CUBE = re.compile(_CDET + r'\b(?:blocks?|cubes?)\b', re.I)


def _find_pick(text: str) -> tuple[list[tuple[int, int, str]], bool]:
    found = _scan(text, _PICK)
    if not any(d.startswith('non_') for _, _, d in found):
        found = _scan(text, _PICK + [(_PLAIN_CUBE, lambda m: 'cube')])
    return found, False


_ARTICLE_NEXT = {'single', 'finite', 'time', 'location', 'locations', 'place', 'number', 'total', 'few',
                 'lot',
                 'certain', 'particular', 'specific', 'new', 'different', 'point', 'moment', 'row', 'given',
                 'spot', 'waypoint', 'minimum', 'maximum', 'second', 'couple', 'way', 'loop', 'round'}
_PROP_NEXT = {
    '', 'an', 'and', 'at', 'then',
    'exactly', 'more', 'is', 'you', 'only', 'but', 'until', 'once', 'less', 'or',
    'again', 'any', 'on', 'while', 'three', 'visit', 'first', 'four', 'equal', 'do', 'without', 'before',
    'five', 'one', 'for', 'go', 'infinitely', 'followed', 'twice', 'occurs', 'till', 'zero', 'two', 'right',
    'has', 'make', 'forever', 'to', 'must', 'repeatedly', 'are', 'in', 'as', 'not', 'finally', 'should',
    'ensure', 'never', 'means', 'happens', 'locks', 'hold', 'proceed', 'sometime', 'afterward',
    'afterwards', 'also', 'cannot', 'ever', 'unless', 'after', 'when', 'otherwise', 'thrice', 'six',
    'leave', 'happen', 'holds', 'can', 'from', 'this', 'complete', 'no', 'occur', 'reach', 'immediately',
    'was', 'will', 'have', 'has', 'if', 'so', 'so', 'next', 'with', 'even', 'always', 'eventually',
    'several', 'many', 'multiple', 'over', 'just', 'up', 'there', 'too', 'yet', 'atleast', 'precisely',
    'constantly', 'continuously', 'periodically', 'endlessly', 'indefinitely', 'nonstop', 'frequently',
    'becomes', 'remains', 'stays', 'being', 'be', 'happening', 'seen', 'visited', 'turns', 'gets',
    'later', 'subsequently', 'thereafter', 'never', 'again', 'by', 'into', 'after',
}


def _find_lifted(text: str) -> tuple[list[tuple[int, int, str]], bool]:
    toks = list(re.finditer(r"[A-Za-z']+", text))
    found: list[tuple[int, int, str]] = []
    unsure = False
    for k, m in enumerate(toks):
        t = m.group(0)
        if t not in ('a', 'b', 'c', 'd', 'h'):
            continue
        if t == 'a':
            nxt = toks[k + 1].group(0).lower() if k + 1 < len(toks) else ''
            nxt2 = toks[k + 2].group(0).lower() if k + 2 < len(toks) else ''
            if nxt in ('finite', 'infinite'):
                if nxt2 in ('number', 'amount'):
                    continue
            elif nxt in _ARTICLE_NEXT:
                continue
            elif nxt not in _PROP_NEXT and nxt not in ('b', 'c', 'd', 'h'):
                unsure = True
        found.append((m.start(), m.end(), t))
    return found, unsure


def _providence_finder(names: Iterable[str]) -> _Finder:
    patterns = []
    for name in sorted(set(names), key=len, reverse=True):
        # any case; an apostrophe may be written, dropped or spaced ("citizens bank")
        words = [re.escape(w) for w in name.split()]
        body = r'\s+'.join(words).replace("\\'", r"\s*'?\s*").replace("'", r"\s*'?\s*")
        pat = re.compile(r'(?:\bthe\s+)?\b' + body + r'\b', re.I)
        patterns.append((pat, (lambda d: lambda m: d)(snake(name))))

    def find(text: str) -> tuple[list[tuple[int, int, str]], bool]:
        return _scan(text, patterns), False
    return find


def _finder(name: str, root: Optional[Path] = None) -> _Finder:
    if name == 'drone':
        return _find_drone
    if name in ('cleanup', 'cleanup_l2l'):
        return _find_cleanup
    if name == 'pick_and_place':
        return _find_pick
    if name in ('lifted', 'lifted_formula'):
        return _find_lifted
    return _providence_finder(_surface_names(_root(root)).values())


def align(name: str, text: str, formula: Formula, source: str = '',
          finder: Optional[_Finder] = None) -> TaggedExample | str:
    """Tag the mentions of the gold formula's propositions in ``text``; a reason string when unsure."""
    find = finder or _finder(name)
    gold = [str(d) for d in referents_of(formula)]
    if any(d.endswith('_with_chair') for d in gold):
        return 'compound proposition (room with chair)'
    found, unsure = find(text)
    if unsure:
        return 'unsure mention (article a, or a floor typo word)'
    extra = sorted({d for _, _, d in found} - set(gold))
    if extra:
        return 'names a proposition the gold formula lacks'
    missing = [d for d in gold if d not in {f for _, _, f in found}]
    if missing:
        return 'a proposition of the gold formula is not named'
    slots: dict[str, str] = {}
    mentions = []
    for s, e, d in found:
        slot = slots.setdefault(d, f's{len(slots) + 1}')
        mentions.append(Mention(s, e, slot))
    lifted = rename_descriptors(formula, {Descriptor(d): Descriptor(s) for d, s in slots.items()})
    ex = TaggedExample(text, str(lifted), tuple(mentions), {s: d for d, s in slots.items()}, source)
    try:
        check_example(ex)
        if str(ex.formula()) != str(formula):
            return 'internal: lifted formula does not give the gold one back'
    except (ValueError, LtlInstructError) as e:
        return f'internal: {e}'
    return ex


def tagged_examples(name: str, root: Optional[Path] = None) -> tuple[list[TaggedExample], int]:
    """Tagged training examples of a set's TRAIN split, and how many train items were skipped.

    ``lifted`` and ``lifted_formula`` give the same examples: the intersection of both train
    splits. Items whose utterance is a test key of any set are left out (not counted as
    skipped); see :func:`alignment_report` for the reasons of the skips.
    """
    _check_name(name)
    examples, reasons = _tagged('lifted' if name == 'lifted_formula' else name, _root(root))
    return list(examples), sum(reasons.values())


def alignment_report(name: str, root: Optional[Path] = None) -> dict[str, int]:
    """Why training items of a set were skipped: reason -> count."""
    _check_name(name)
    return dict(_tagged('lifted' if name == 'lifted_formula' else name, _root(root))[1])


@functools.lru_cache(maxsize=16)
def _tagged(name: str, root: Path) -> tuple[tuple[TaggedExample, ...], collections.Counter[str]]:
    _check_name(name)
    items = _train_items(name, root)
    find = _finder(name, root)
    conventions = tuple((k, v) for k, v in SET_OPTIONS.get(name, {}).items() if k != 'numbers')
    out: list[TaggedExample] = []
    reasons: collections.Counter[str] = collections.Counter()
    for it in items:
        got = align(name, it.text, it.formula, it.source, find)
        if isinstance(got, str):
            reasons[got] += 1
        else:
            out.append(dataclasses.replace(got, conventions=conventions))
    return tuple(out), reasons


def _surface_names(root: Path) -> dict[str, str]:
    """Map each providence descriptor to its landmark name as the formulas write it."""
    names: dict[str, str] = {}
    with (root / _FILES['providence']).open(encoding='utf-8', newline='') as fh:
        for row in csv.DictReader(fh):
            for is_name, t in _providence_tokens(row.get('LTL') or ''):
                if is_name:
                    try:
                        names[snake(t)] = t
                    except ValueError:
                        pass
    return names

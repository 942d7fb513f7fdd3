"""Training data for the learned translator: random English instructions with their lifted formulas.

Each example composes one to four *constructs* (a sequence of steps, deliveries, ordering,
avoidance, either-or, counting, rules over the run, patrolling...) and renders them with phrases
drawn from ``phrasings.yaml``: verbs, connectives, requesters, chatter, spatial relations and a
vocabulary of names. The code only composes; every English phrase and every formula shape lives in
that table. Formulas follow the dev set's conventions (``CONVENTIONS.md``) and the offline
translator's output for the same construct.

Run ``python -m ltl_instruct.core.language.neural.generator --n 20 --seed 1`` to read a few.
"""
from __future__ import annotations

import argparse
import json
import random
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Optional, Sequence, Union

import yaml

from ltl_instruct.core.language.neural.examples import Mention, TaggedExample

PHRASINGS_PATH = Path(__file__).with_name('phrasings.yaml')

_PLACEHOLDER = re.compile(r'\{(\w*)\}')
_THING_KEYS = ('A', 'B', 'C', 'D', 'W')
_PUNCT_TABLE = str.maketrans('', '', ',.;:!?')
_ENTITY_RE = re.compile(r'\be(\d+)\b')

# How often each step kind starts or continues a chain, and each rule is added.
_STEP_WEIGHTS = {'visit': 10, 'revisit': 1, 'either': 2, 'twice': 1.2, 'three_times': 0.8, 'pick': 2.5,
                 'deliver': 3.5, 'throw_away': 1, 'deliver_avoid': 1, 'deliver_after_avoid': 0.6,
                 'after_avoid': 1, 'correction': 1.5, 'speaker': 0.5, 'correction_object': 0.4,
                 'correction_dest': 0.4}
_SOURCE_RATE = 0.2   # carried things said with where they are taken from ("the cup from the kitchen")
_RULE_WEIGHTS = {'unordered': 1.5, 'unordered3': 0.7, 'sequence_list': 0.8, 'before': 1.5, 'not_until': 1.2,
                 'stay_until': 0.8, 'weak_first': 0.5, 'avoid_global': 3, 'avoid_tail': 2.5,
                 'avoid_onway': 1.2,
                 'avoid_after': 1, 'xor': 1, 'at_most_once': 0.8, 'exactly_once': 0.8, 'exactly_twice': 0.6,
                 'at_least_n': 0.5, 'at_most_n': 0.5, 'exactly_n': 0.5,
                 'whenever': 1, 'if_then': 0.8, 'patrol': 0.8, 'patrol1': 0.6, 'route_twice': 0.4,
                 'before_that': 1, 'swap_order': 0.6, 'either_order': 0.4, 'drop_correction': 0.6,
                 'count_correction': 0.3, 'avoid_retract': 0.5, 'avoid_cancel': 0.4, 'list_first': 0.4,
                 'list_second': 0.5, 'list_third': 0.4, 'list_before_last': 0.2, 'list_reverse': 0.3,
                 'list_ends': 0.3, 'list_middle_avoid': 0.2, 'list_deliver': 0.3, 'list_deliver_first': 0.2,
                 'deliver_either': 0.5, 'deliver_either_dest': 0.5, 'deliver_two': 0.6, 'deliver_too': 0.4,
                 'deliver_twice_limit': 0.2, 'avoid_leg': 0.8, 'avoid_until_then': 0.5,
                 'avoid_until_reached': 0.6, 'not_until_both': 0.4, 'either_avoid': 0.3,
                 'ordered3': 0.7, 'ordered4': 0.5, 'strict2': 0.4, 'strict3': 0.4, 'strict4': 0.3}
# Steps fit for a drone.
_DRONE_STEPS = ('visit', 'visit', 'visit', 'revisit', 'either', 'twice', 'three_times', 'after_avoid',
                'correction')
# Constructs that are not step or rule names: styles of the whole example.
STYLE_NAMES = ('sequence', 'drone', 'lifted', 'appositive', 'spatial', 'source', 'chatter', 'typos')
CONSTRUCTS = tuple(_STEP_WEIGHTS) + tuple(_RULE_WEIGHTS) + STYLE_NAMES


@dataclass(frozen=True)
class _Template:
    """A compiled phrase: literal text and placeholder names, in order."""

    parts: tuple[tuple[bool, str], ...]   # (is_placeholder, text or name)
    requestable: bool                     # may follow "I want you to ..."
    plain: frozenset[str]                 # things said without a relation (one would be misread)


def _compile(text: str, relation_words: frozenset[str] = frozenset()) -> _Template:
    requestable = not text.startswith('^')
    text = text.lstrip('^')
    parts: list[tuple[bool, str]] = []
    pos = 0
    for m in _PLACEHOLDER.finditer(text):
        if m.start() > pos:
            parts.append((False, text[pos:m.start()]))
        parts.append((True, m.group(1)))
        pos = m.end()
    if pos < len(text):
        parts.append((False, text[pos:]))
    plain = set()
    for (is_ph, name), (next_ph, after) in zip(parts, parts[1:]):
        words = after.split()
        if is_ph and not next_ph and words and words[0] in relation_words:
            plain.add(name)
    return _Template(tuple(parts), requestable, frozenset(plain))


def snake(words: str) -> str:
    """Return the descriptor name of a name said in words (``Citizen's Bank`` -> ``citizens_bank``)."""
    s = re.sub(r"['\u2019]", '', words.lower())
    s = re.sub(r'[^a-z0-9]+', '_', s).strip('_')
    return s


@dataclass(frozen=True)
class _Thing:
    """A thing the instruction names: its mention text and its descriptor."""

    text: str
    desc: str


class _Tables:
    """The phrase tables of ``phrasings.yaml``, compiled."""

    def __init__(self, path: Path = PHRASINGS_PATH) -> None:
        with open(path, encoding='utf-8') as f:
            raw = yaml.safe_load(f)
        self.raw = raw
        rw = frozenset(raw['relation_first_words'])
        self.steps = {name: {'chain': tuple(spec['chain']),
                             'things': tuple(sorted(spec['things'].items())),
                             'revisitable': bool(spec.get('revisitable', False)),
                             'text': tuple(_compile(t, rw) for t in spec['text']),
                             'mid': tuple(_compile(t, rw) for t in spec['text'] if not t.startswith('^')),
                             'bare': tuple(_compile(t, rw) for t in spec.get('bare', ()))}
                      for name, spec in raw['steps'].items()}
        self.rules = {name: {'formula': spec.get('formula', ''), 'count': spec.get('count'),
                             'things': dict(spec.get('things', {})),
                             'text': tuple(_compile(t, rw) for t in spec['text'])}
                      for name, spec in raw['rules'].items()}
        self.requesters = tuple(raw['requesters'])
        self.drone_requesters = tuple(raw['drone_requesters'])
        self.relations = {c: tuple(p) for c, p in raw['relations'].items()}
        self.comparators = tuple(self.relations)
        self.appositives = tuple(_compile(t) for t in raw['appositives'])
        places = raw['rooms'] + raw['furniture'] + raw['office'] + raw['warehouse']
        self.places = tuple(places)
        self.rooms = frozenset(raw['rooms'])
        self.anchors = tuple(raw['furniture'] + raw['office'] + raw['rooms'][:20])
        self.destinations = tuple(raw['furniture'] + raw['office'] + raw['rooms'] + raw['warehouse'][:8])
        self.coloured = frozenset(raw['coloured'])
        for name in ('steps', 'rules'):
            missing = set(getattr(self, name)) - set(_STEP_WEIGHTS if name == 'steps' else _RULE_WEIGHTS)
            if missing:
                raise ValueError(f'phrasings.yaml {name} without weights: {sorted(missing)}')

    def vocabulary_size(self) -> int:
        """Count the distinct base names (before colours, numbers and relations)."""
        r = self.raw
        names = set(self.places) | set(r['objects']) | set(r['outdoor']) | set(r['proper'])
        return len(names) + len(r['numbered']) + len(r['floor_places']) + len(r['letters'])


_TABLES: Optional[_Tables] = None


def tables() -> _Tables:
    """Return the phrase tables, loaded once."""
    global _TABLES
    if _TABLES is None:
        _TABLES = _Tables()
    return _TABLES


Segment = Union[str, int]   # literal text, or the id of a thing (a mention)


class Generator:
    """Random instructions with lifted formulas; deterministic for a seed.

    Parameters
    ----------
    seed:
        Seed of the random choices.
    clean:
        No typos, chatter, dropped punctuation or case changes (for checks against the offline
        translator).
    max_parts:
        The most constructs (a chain of steps counts once) one example composes, 1 to 4.
    """

    def __init__(self, seed: int = 0, clean: bool = False, max_parts: int = 4) -> None:
        self.rng = random.Random(seed)
        self.t = tables()
        self.clean = clean
        self.max_parts = max(1, min(4, max_parts))
        self._step_names = tuple(_STEP_WEIGHTS)
        self._step_w = tuple(_STEP_WEIGHTS.values())
        self._rule_names = tuple(_RULE_WEIGHTS)
        self._rule_w = tuple(_RULE_WEIGHTS.values())

    # ---- names ---------------------------------------------------------------------------

    def _det(self) -> str:
        return self.rng.choice(self.t.raw['determiners'])

    def _base_name(self, role: str) -> tuple[str, str, bool]:
        """Return (words, descriptor name, takes a determiner) of a fresh name for ``role``.

        Sets ``self._relatable`` when the name is of a thing that a spatial relation may describe.
        """
        self._relatable = False
        rng, raw = self.rng, self.t.raw
        if self.style == 'lifted':
            letter = rng.choice(raw['letters'])
            return letter, letter, False
        r = rng.random()
        if self.style == 'drone':
            if r < 0.45:
                words = rng.choice(raw['outdoor'])
            elif r < 0.6:
                return self._proper()
            elif r < 0.78:
                return self._numbered()
            elif r < 0.9:
                words = f"{rng.choice(raw['ordinals'])} {rng.choice(raw['floor_places'])}"
            else:
                words = f"{rng.choice(raw['colours'])} {rng.choice(raw['coloured'])}"
            self._relatable = True
            return words, snake(words), True
        self._relatable = True
        if role == 'object':
            words = rng.choice(raw['objects'])
        elif role == 'dest':
            words = rng.choice(self.t.destinations)
        elif r < 0.06:
            return self._proper()
        elif r < 0.13:
            return self._numbered()
        elif r < 0.16:
            words = f"{rng.choice(raw['ordinals'])} {rng.choice(raw['floor_places'])}"
            return words, snake(words), True
        elif r < 0.21:
            words = rng.choice(raw['outdoor'])
        else:
            words = rng.choice(self.t.places)
            self._relatable = words not in self.t.rooms
        words = self._adjective(words)
        return words, snake(words), True

    def _adjective(self, words: str) -> str:
        rng, raw = self.rng, self.t.raw
        r = rng.random()
        if words in self.t.coloured and r < 0.3:
            return f"{rng.choice(raw['colours'])} {words}"
        if r > 0.93 and ' ' not in words:
            return f"{rng.choice(raw['materials'])} {words}"
        return words

    def _proper(self) -> tuple[str, str, bool]:
        self._relatable = False
        words = self.rng.choice(self.t.raw['proper'])
        return words, snake(words), False

    def _numbered(self) -> tuple[str, str, bool]:
        rng, raw = self.rng, self.t.raw
        head = rng.choice(raw['numbered'])
        num = str(rng.randint(1, 12)) if rng.random() < 0.6 else rng.choice(raw['number_words'])
        words = f'{head} {num}'
        return words, snake(words), False

    def _anchor(self, exclude: str) -> tuple[str, str]:
        """Return (text with determiner, descriptor) of a thing that another is placed by."""
        rng = self.rng
        for _ in range(5):
            words = self._adjective(rng.choice(self.t.anchors))
            if snake(words) != exclude:
                break
        return f'the {words}', snake(words)

    def _relation(self, head: str) -> tuple[str, str]:
        """Return (English, descriptor suffix) of one relation for the thing named ``head``."""
        rng, t = self.rng, self.t
        comparator = rng.choice(t.comparators)
        phrase = rng.choice(t.relations[comparator])
        self.used.add('spatial')
        if comparator == 'isbetween':
            a_text, a_desc = self._anchor(head)
            b_text, b_desc = self._anchor(a_desc)
            if b_desc == a_desc:
                b_text, b_desc = 'the wall', 'wall'
            return f'{phrase} {a_text} and {b_text}', f'::isbetween({a_desc}, {b_desc})'
        a_text, a_desc = self._anchor(head)
        if rng.random() < 0.25:   # a second level on the anchor, or a second relation on the head
            if rng.random() < 0.75:
                c2 = rng.choice([c for c in t.comparators if c != 'isbetween'])
                p2 = rng.choice(t.relations[c2])
                lead = rng.choice(t.raw['relative_leads'])
                b_text, b_desc = self._anchor(a_desc)
                return (f'{phrase} {a_text} {lead}{p2} {b_text}',
                        f'::{comparator}({a_desc}::{c2}({b_desc}))')
            c2 = rng.choice([c for c in t.comparators if c not in ('isbetween', comparator)])
            p2 = rng.choice(t.relations[c2])
            b_text, b_desc = self._anchor(a_desc)
            return f'{phrase} {a_text} and {p2} {b_text}', f'::{comparator}({a_desc})::{c2}({b_desc})'
        return f'{phrase} {a_text}', f'::{comparator}({a_desc})'

    def _source(self, text: str, name: str) -> tuple[str, str]:
        """Return (English, descriptor) of a carried thing said with where it is taken from."""
        rng, sources = self.rng, self.t.raw['sources']
        comparator = rng.choice(tuple(sources))
        a_text, a_desc = self._anchor(name)
        self.used.add('source')
        text = f'{text} {rng.choice(sources[comparator])} {a_text}'
        return text, name if comparator == 'none' else f'{name}::{comparator}({a_desc})'

    def _thing(self, role: str, plain: bool = False) -> int:
        """Make a new thing for ``role`` ('place', 'object', 'dest'); return its id."""
        rng = self.rng
        for _ in range(8):
            words, name, det = self._base_name(role)
            if name not in self.names:
                break
        text = f'{self._det() if role == "object" else "the"} {words}' if det else words
        desc = name
        if role == 'object' and self._relatable and not plain and rng.random() < _SOURCE_RATE:
            text, desc = self._source(text, name)
        elif self._relatable and not plain and rng.random() < self.rel_rate:
            rel_text, rel_desc = self._relation(name)
            desc = name + rel_desc
            if role != 'object' and rng.random() < 0.12:   # not in "throw X out", "bring X to Y"
                tpl = rng.choice(self.t.appositives)
                text = ''.join(self._fill(p, {'X': text, 'R': rel_text}) for p in tpl.parts)
                self.used.add('appositive')
            else:
                text = f'{text} {rel_text}'
        self.names.add(desc)
        self.names.add(name)
        self.things.append(_Thing(text, desc))
        return len(self.things) - 1

    @staticmethod
    def _fill(part: tuple[bool, str], values: dict[str, str]) -> str:
        return values[part[1]] if part[0] else part[1]

    # ---- phrases -------------------------------------------------------------------------

    def _verb(self, key: str) -> str:
        raw = self.t.raw
        if key == 'V':
            return self.rng.choice(raw['drone_verbs'] if self.style == 'drone' else raw['visit_verbs'])
        if key == 'AV':
            return self.rng.choice(raw['avoid_verbs'])
        if key == 'NAV':
            return self.rng.choice(raw['neg_avoid_verbs'])
        if key == 'ALWAYS':
            return self.rng.choice(raw['always_suffixes'])
        if key == 'N':
            return self.count_text
        raise KeyError(key)

    def _render(self, tpl: _Template, ids: dict[str, int]) -> list[Segment]:
        out: list[Segment] = []
        for is_ph, val in tpl.parts:
            if not is_ph:
                out.append(val)
            elif val in ids:
                out.append(ids[val])
            else:
                out.append(self._verb(val))
        return out

    @staticmethod
    def _formula(template: str, ids: dict[str, int]) -> str:
        for key in _THING_KEYS:
            if key in ids:
                template = template.replace('{' + key + '}', f'e{ids[key]}')
        return template

    # ---- steps and rules -----------------------------------------------------------------

    def _step(self, kind: str, prev: list[int]) -> tuple[list[Segment], list[str], bool]:
        """Return the segments (verb form or bare), chain links and requestability of one step.

        The step's ``things`` in ``phrasings.yaml`` say what each placeholder names: 'place',
        'object' (carried), 'dest' (where it is put), a '!' for no spatial relation, or
        'previous' (a thing this sequence named before).
        """
        spec = self.t.steps[kind]
        rng = self.rng
        if prev and spec['bare'] and rng.random() < 0.45:
            tpl = rng.choice(spec['bare'])
            bare = True
        else:   # a step after the first continues the sentence: no "I need you at X" there
            tpl = rng.choice(spec['mid'] if prev and spec['mid'] else spec['text'])
            bare = False
        ids: dict[str, int] = {}
        for key, role in spec['things']:
            if role == 'previous':
                ids[key] = rng.choice(prev)
            else:
                plain = role.endswith('!') or key in tpl.plain
                ids[key] = self._thing(role.rstrip('!'), plain=plain)
        segs = self._render(tpl, ids)
        links = [self._formula(link, ids) for link in spec['chain']]
        if spec['revisitable']:
            self._visited.append(ids['A'])
        return segs, links, bare or tpl.requestable

    def _chain(self) -> tuple[list[Segment], str, list[str], bool]:
        """Return the text, formula, construct names and requestability of a sequence of steps."""
        rng, raw = self.rng, self.t.raw
        k = rng.choices((1, 2, 3, 4, 5), (40, 30, 18, 8, 4))[0]
        names: list[str] = ['sequence'] if k > 1 else []
        segs: list[Segment] = []
        links: list[str] = []
        self._visited = []
        requestable = True
        for i in range(k):
            if self.style == 'drone':
                kind = rng.choice(_DRONE_STEPS)
            else:
                kind = rng.choices(self._step_names, self._step_w)[0]
            if kind == 'revisit' and not self._visited:
                kind = 'visit'
            step_segs, step_links, req = self._step(kind, list(self._visited))
            if kind not in names:
                names.append(kind)
            if i == 0:
                first = rng.choice(raw['first_words']) if k > 1 else ''
                segs.append(first)
                requestable = req and not (step_segs and isinstance(step_segs[0], int))
            else:
                bare = not isinstance(step_segs[0], str) or not step_segs[0].strip()
                if i == k - 1 and k > 2 and rng.random() < 0.5:
                    conn = rng.choice(raw['final_connectives'])
                elif bare:
                    conn = rng.choice(raw['then_connectives_bare'])
                else:
                    conn = rng.choice(raw['then_connectives'])
                segs.append(conn)
            segs.extend(step_segs)
            links.extend(step_links)
        return segs, _chain_formula(links), names, requestable

    def _rule(self, name: str) -> tuple[list[Segment], str, bool]:
        """Render one rule; its ``things`` say each placeholder's role as in a step (default 'place').

        A placeholder of the text that the formula leaves out (a list item not chosen, a
        corrected name) is a thing too, named without a relation.
        """
        spec = self.t.rules[name]
        ids: dict[str, int] = {}
        tpl = self.rng.choice(spec['text'])
        said = {val for is_ph, val in tpl.parts if is_ph}
        formula = spec['formula']
        if spec['count']:
            n = self.rng.randint(2, 9)
            formula = _count_formula(spec['count'], n)
            self.count_text = str(n) if self.rng.random() < 0.5 else self.t.raw['number_words'][n - 1]
        for key in _THING_KEYS:
            in_formula = '{' + key + '}' in formula
            if not in_formula and key not in said:
                continue
            role = spec['things'].get(key, 'place')
            plain = role.endswith('!') or not in_formula or key in tpl.plain or self.rng.random() < 0.5
            ids[key] = self._thing(role.rstrip('!'), plain=plain)
        return self._render(tpl, ids), self._formula(formula, ids), tpl.requestable

    # ---- one example ---------------------------------------------------------------------

    def example(self) -> TaggedExample:
        """Generate one example."""
        rng, raw = self.rng, self.t.raw
        r = rng.random()
        self.style = 'lifted' if r < 0.07 else 'drone' if r < 0.17 else 'plain'
        self.rel_rate = 0.0 if self.style == 'lifted' else 0.2 if self.style == 'drone' else 0.3
        self.things: list[_Thing] = []
        self.names: set[str] = set()
        self.used: set[str] = set()
        n_parts = rng.choices((1, 2, 3, 4), (35, 35, 20, 10))[0]
        n_parts = min(n_parts, self.max_parts)
        clauses: list[tuple[list[Segment], bool, str]] = []   # segments, requestable, rule name
        formulas: list[str] = []
        names: list[str] = []
        if rng.random() < 0.75:
            segs, f, chain_names, req = self._chain()
            clauses.append((segs, req, ''))
            formulas.append(f)
            names.extend(chain_names)
            n_parts -= 1
        for _ in range(n_parts):
            if self.style == 'drone':
                name = rng.choice(('avoid_global', 'avoid_global', 'avoid_onway', 'unordered', 'before',
                                   'sequence_list', 'patrol1', 'exactly_once', 'at_most_once'))
            else:
                name = rng.choices(self._rule_names, self._rule_w)[0]
            if name == 'avoid_tail' and not any(c[2] == '' for c in clauses):
                name = 'avoid_global'   # a tail follows a sequence of steps
            segs, f, req = self._rule(name)
            if name == 'avoid_global' and clauses and rng.random() < 0.25:
                clauses.insert(0, (segs, False, name))
            else:
                clauses.append((segs, req, name))
            formulas.append(f)
            if name not in names:
                names.append(name)
        body: list[Segment] = []
        for i, (segs, _req, name) in enumerate(clauses):
            if i:
                pool = raw['tail_connectives'] if name == 'avoid_tail' else \
                    raw['but_connectives'] if name.startswith('avoid') else raw['and_connectives']
                body.append(rng.choice(pool))
            body.extend(segs)
        if clauses[0][1] and rng.random() < 0.6:
            req = rng.choice(self.t.drone_requesters if self.style == 'drone' else self.t.requesters)
            head, _, tail = req.partition('{}')
            body = [head] + body + [tail]
        if self.style in ('drone', 'lifted'):
            names.append(self.style)
        names.extend(sorted(self.used))
        if not self.clean and rng.random() < 0.25:
            names.append('chatter')
            if rng.random() < 0.6:
                body.insert(0, rng.choice(raw['chatter_before']))
            else:
                body.append(rng.choice(raw['chatter_after']))
        typos = not self.clean and rng.random() < 0.5
        if typos:
            body, made = self._typos(body)
            if made:
                names.append('typos')
        return self._assemble(body, formulas, names)

    def _typos(self, body: list[Segment]) -> tuple[list[Segment], bool]:
        """Put a swapped, dropped or doubled letter into some words (rarely in a mention)."""
        rng = self.rng
        made = False
        out: list[Segment] = []
        for seg in body:
            if isinstance(seg, int):
                thing = self.things[seg]
                if rng.random() < 0.03:
                    words = thing.text.split(' ')
                    j = rng.randrange(len(words))
                    new = _typo(words[j], rng)
                    if new != words[j]:
                        words[j] = new
                        self.things[seg] = _Thing(' '.join(words), thing.desc)
                        made = True
                out.append(seg)
                continue
            words = seg.split(' ')
            for j, w in enumerate(words):
                if len(w) >= 4 and rng.random() < 0.08:
                    new = _typo(w, rng)
                    made = made or new != w
                    words[j] = new
            out.append(' '.join(words))
        return out, made

    def _assemble(self, body: list[Segment], formulas: list[str], names: list[str]) -> TaggedExample:
        rng = self.rng
        lower = not self.clean and rng.random() < 0.2
        nopunct = not self.clean and rng.random() < 0.12
        cap = not lower and rng.random() < 0.45
        text = ''
        spans: list[tuple[int, int, int]] = []
        for seg in body:
            if isinstance(seg, int):
                piece = self.things[seg].text
            else:
                piece = seg
            if lower:
                piece = piece.lower()
            if nopunct:
                piece = piece.translate(_PUNCT_TABLE)
            if not piece:
                continue
            if not isinstance(seg, int):
                piece = re.sub(' {2,}', ' ', piece)
                if (not text or text.endswith(' ')) and piece.startswith(' '):
                    piece = piece.lstrip(' ')
                if not piece:
                    continue
            else:
                if text and not text.endswith(' ') and text[-1].isalnum():
                    text += ' '
                spans.append((len(text), len(text) + len(piece), seg))
            text += piece
        text = text.rstrip()
        if cap and text and text[0].islower() and not (spans and spans[0][0] == 0):
            text = text[0].upper() + text[1:]
        slot_of: dict[int, str] = {}
        slots: dict[str, str] = {}
        mentions: list[Mention] = []
        for start, end, tid in spans:
            if tid not in slot_of:
                slot_of[tid] = f's{len(slot_of) + 1}'
                slots[slot_of[tid]] = self.things[tid].desc
            mentions.append(Mention(start, end, slot_of[tid]))
        parts = [f'({f})' if _top_level_binary(f) else f for f in formulas]
        lifted = _ENTITY_RE.sub(lambda m: slot_of[int(m.group(1))], ' & '.join(parts))
        return TaggedExample(text=text, lifted=lifted, mentions=tuple(mentions), slots=slots,
                             source='generator:' + '+'.join(names))


def _typo(word: str, rng: random.Random) -> str:
    """Swap, drop or double one letter of ``word``, never its first letter."""
    letters = [i for i in range(1, len(word)) if word[i].isalpha()]
    if len(letters) < 2:
        return word
    i = rng.choice(letters)
    op = rng.randrange(3)
    if op == 0 and i + 1 < len(word) and word[i + 1].isalpha():
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    if op == 1:
        return word[:i] + word[i + 1:]
    return word[:i] + word[i] + word[i:]


def _count_formula(builder: str, n: int) -> str:
    """Return the formula (over ``{A}``) of ``n`` visits: ``task.at_least`` / ``at_most`` / ``exactly``."""
    from ltl_instruct.core.language import task
    from ltl_instruct.core.spec import parse_formula
    counted = getattr(task, builder)(parse_formula('near[counted_place]'), n)
    return str(counted).replace('counted_place', '{A}')


def _top_level_binary(formula: str) -> bool:
    """Tell whether ``formula`` has an or, until or implication outside all brackets."""
    depth = 0
    for i, ch in enumerate(formula):
        if ch in '([':
            depth += 1
        elif ch in ')]':
            depth -= 1
        elif depth == 0 and (ch in '|>' or (ch in 'UW' and formula[i - 1:i + 2] in (' U ', ' W '))):
            return True
    return False


def _chain_formula(links: Sequence[str]) -> str:
    """Return ``F (l1 & F (l2 & ...))`` of chain links; a link ``U g`` holds ``g`` until the rest."""
    def body(i: int) -> str:
        link = links[i]
        if link.startswith('U '):
            return f'({link[2:]} U ({body(i + 1)}))'
        if i == len(links) - 1:
            return link
        rest = body(i + 1)
        if links[i + 1].startswith('U '):
            return f'{link} & {rest}'
        return f'{link} & F {_paren(rest)}'
    return f'F {_paren(body(0))}'


def _paren(f: str) -> str:
    if re.fullmatch(r'[!a-z_]+\[[^\]]*\]', f) or (f.startswith('(') and _balanced_outer(f)):
        return f
    return f'({f})'


def _balanced_outer(f: str) -> bool:
    depth = 0
    for i, ch in enumerate(f):
        if ch == '(':
            depth += 1
        elif ch == ')':
            depth -= 1
            if depth == 0 and i != len(f) - 1:
                return False
    return True


def generate(n: int, seed: int = 0, clean: bool = False, max_parts: int = 4) -> list[TaggedExample]:
    """Generate ``n`` examples, the same ones for the same seed (see :class:`Generator`)."""
    gen = Generator(seed, clean=clean, max_parts=max_parts)
    return [gen.example() for _ in range(n)]


def main(argv: Optional[Sequence[str]] = None) -> None:
    """Print generated examples as JSON lines (text, lifted, formula, mentions)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--n', type=int, default=20)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--clean', action='store_true', help='no typos, chatter or case changes')
    args = ap.parse_args(argv)
    for ex in generate(args.n, args.seed, clean=args.clean):
        print(json.dumps({'text': ex.text, 'lifted': ex.lifted, 'formula': str(ex.formula()),
                          'mentions': [[ex.text[m.start:m.end], m.slot, ex.slots[m.slot]]
                                       for m in ex.mentions],
                          'source': ex.source}, ensure_ascii=False))


if __name__ == '__main__':
    main()

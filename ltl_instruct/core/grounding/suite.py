"""Generated grounding suites: random scenes with distractors, descriptors, and a reference evaluator.

Used by the tests and by ``bench/grounding.py``. Scenes place small objects of a few
classes (several of each class, in different colours: distractors) on a 0.4 m grid,
never in neighbouring cells, some raised above the floor, so that every comparator has
clear margins: axis offsets are 0 or at least 0.2 m (threshold 0.1 m), centre
distances avoid 1.0 m.

Descriptors are generated from true relations of a target object (so most denote at
least one object), nested up to depth 3, covering every comparator; some are random.
The expected answer comes from :func:`reference_resolve`, a direct, loop-by-loop
transcription of the comparator table of ``spec/formula.md``, independent of the
vectorised resolver.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Optional, Sequence

from ltl_instruct.core.grounding.rsm import Instance
from ltl_instruct.core.spec import COMPARATORS as _ARITY, Descriptor, Relation
from ltl_instruct.core.world.scene import Scene, scene_from_dict

CLASSES = ('chair', 'box', 'lamp', 'cup', 'plant', 'book', 'bin', 'vase')
COLOURS = ('red', 'blue', 'green', 'yellow')
GRID = 0.4
COMPARATORS = tuple(sorted(_ARITY))


@dataclass(frozen=True)
class SuiteCase:
    """One descriptor and the ids of the objects it denotes (by the reference evaluator)."""

    descriptor: Descriptor
    expected: frozenset[str]


def random_scene(rng: random.Random, n_objects: int = 24, cells: int = 16) -> Scene:
    """Return a scene of ``n_objects`` coloured objects on a ``cells`` x ``cells`` grid of 0.4 m."""
    free = [(i, j) for i in range(1, cells - 1) for j in range(1, cells - 1)]
    rng.shuffle(free)
    taken: set[tuple[int, int]] = set()
    objects = []
    for i, j in free:
        if len(objects) >= n_objects:
            break
        if any((i + di, j + dj) in taken for di in (-1, 0, 1) for dj in (-1, 0, 1)):
            continue
        taken.add((i, j))
        cls = CLASSES[len(objects) % len(CLASSES)] if len(objects) < len(CLASSES) else rng.choice(CLASSES)
        colour = rng.choice(COLOURS)
        height = rng.choice((0.2, 0.6))
        raised = rng.random() < 0.25
        z = (1.0 if height == 0.2 else 1.2) if raised else height / 2.0
        objects.append({'label': f'{colour} {cls}', 'center': [i * GRID, j * GRID, z],
                        'size': [0.3, 0.3, height]})
    side = cells * GRID
    return scene_from_dict({'name': 'suite', 'bounds': {'min': [-0.4, -0.4, 0.0], 'max': [side, side, 3.0]},
                            'objects': objects})


# ---------------------------------------------------------------------------- reference
def _named(name: str, obj: Instance) -> bool:
    words = name.split('_')
    label = obj.label.split()
    return words[-1] == label[-1] and all(w in label[:-1] for w in words[:-1])


def _holds(comparator: str, a: Sequence[float], b: Sequence[float], c: Optional[Sequence[float]],
           axis_t: float = 0.1, next_t: float = 1.0, between_t: float = 0.5) -> bool:
    if comparator == 'isabove':
        return a[2] - b[2] >= axis_t
    if comparator == 'isbelow':
        return b[2] - a[2] > axis_t
    if comparator == 'isleftof':
        return a[1] - b[1] >= axis_t
    if comparator == 'isrightof':
        return b[1] - a[1] > axis_t
    if comparator == 'isinfrontof':
        return b[0] - a[0] > axis_t
    if comparator == 'isbehind':
        return a[0] - b[0] >= axis_t
    if comparator == 'isnextto':
        return math.dist(a, b) < next_t
    assert c is not None
    seg = [c[k] - b[k] for k in range(3)]
    len2 = sum(v * v for v in seg)
    if len2 == 0.0:
        return False
    s = sum((a[k] - b[k]) * seg[k] for k in range(3)) / len2
    if s < 0.0 or s > 1.0:
        return False
    foot = [b[k] + s * seg[k] for k in range(3)]
    return math.dist(a, foot) <= between_t


def reference_resolve(d: Descriptor, objects: Sequence[Instance]) -> frozenset[str]:
    """Ids of the objects ``d`` denotes: names, then every relation with some anchor (never itself)."""
    out = set()
    rel_anchors = [[[x for x in objects if x.id in ids]
                    for ids in (reference_resolve(arg, objects) for arg in rel.args)]
                   for rel in d.relations]
    for o in objects:
        if not _named(d.name, o):
            continue
        ok = True
        for rel, anchors in zip(d.relations, rel_anchors):
            if rel.comparator == 'isbetween':
                found = any(_holds('isbetween', o.center, b.center, c.center)
                            for b in anchors[0] for c in anchors[1]
                            if b.id != o.id and c.id != o.id and b.id != c.id)
            else:
                found = any(_holds(rel.comparator, o.center, b.center, None)
                            for b in anchors[0] if b.id != o.id)
            if not found:
                ok = False
                break
        if ok:
            out.add(o.id)
    return frozenset(out)


# ---------------------------------------------------------------------------- generation
def _name_of(o: Instance, rng: random.Random) -> str:
    colour, cls = o.label.split()
    return f'{colour}_{cls}' if rng.random() < 0.5 else cls


def _describe(target: Instance, objects: Sequence[Instance], depth: int, rng: random.Random,
              comparator: Optional[str] = None) -> Descriptor:
    """Return a descriptor of ``depth`` that ``target`` satisfies (a bare name when no relation fits)."""
    name = _name_of(target, rng)
    if depth == 0:
        return Descriptor(name)
    comps = [comparator] if comparator else list(COMPARATORS)
    rng.shuffle(comps)
    for comp in comps:
        if comp == 'isbetween':
            pairs = [(b, c) for b in objects for c in objects
                     if len({b.id, c.id, target.id}) == 3
                     and _holds(comp, target.center, b.center, c.center)]
            if not pairs:
                continue
            b, c = rng.choice(pairs)
            first = _describe(b, objects, depth - 1, rng)
            second = _describe(c, objects, rng.randint(0, depth - 1), rng)
            return Descriptor(name, (Relation(comp, (first, second)),))
        anchors = [b for b in objects if b.id != target.id and _holds(comp, target.center, b.center, None)]
        if not anchors:
            continue
        b = rng.choice(anchors)
        return Descriptor(name, (Relation(comp, (_describe(b, objects, depth - 1, rng),)),))
    return Descriptor(name)


def _random_descriptor(objects: Sequence[Instance], depth: int, rng: random.Random) -> Descriptor:
    name = _name_of(rng.choice(objects), rng)
    if depth == 0:
        return Descriptor(name)
    comp = rng.choice(COMPARATORS)
    n_args = 2 if comp == 'isbetween' else 1
    args = tuple(_random_descriptor(objects, depth - 1 if k == 0 else rng.randint(0, depth - 1), rng)
                 for k in range(n_args))
    return Descriptor(name, (Relation(comp, args),))


def generate_suite(objects: Sequence[Instance], n: int, rng: random.Random,
                   max_depth: int = 3) -> list[SuiteCase]:
    """``n`` descriptors over ``objects`` (depth 0..max_depth, every comparator) with expected ids."""
    cases = []
    for k in range(n):
        depth = 1 + k % max_depth if k % 10 else 0
        if rng.random() < 0.8:
            comp = COMPARATORS[k % len(COMPARATORS)]
            d = _describe(rng.choice(objects), objects, depth, rng, comp)
        else:
            d = _random_descriptor(objects, depth, rng)
        cases.append(SuiteCase(d, reference_resolve(d, objects)))
    return cases

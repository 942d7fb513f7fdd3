"""Atom regions and task progression maps (TPSM), evaluated exactly from guards.

``near[x]`` holds where the robot centre is within the nearness threshold of the box of
any instance ``x`` resolved to (:mod:`ltl_instruct.core.world.near` measures it). An
:class:`AtomRegion` holds those instances; a :class:`RegionSet` evaluates the atoms at
points, vectorised (N points) or one point at a time with a *margin*: the distance by
which the point may move before any atom changes value (the planner's edge checks use
it to step through regions exactly).

A :class:`TaskProgressionMap` is the symbolic TPSM of one automaton transition: the
``goal`` guard (letters that take the automaton to the next state) and the ``allowed``
guard (letters that keep it where it is), over near-atoms; everything else is avoided.
Event atoms (``pick``, ``release``) are never true while driving, so guards are first
restricted to letters without events (:func:`navigation_guard`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterable, Mapping, Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton.guards import Cube, Guard
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.spec.ast import Atom
from ltl_instruct.core.world import near

GOAL, NEUTRAL, AVOID = 1, 0, -1


@dataclass(frozen=True)
class AtomRegion:
    """Where one near-atom holds: within ``radius`` [m] of any instance box.

    Attributes
    ----------
    key: the atom text, e.g. ``near[red_sofa]``.
    centers: instance box centres [m], each (x, y, z).
    sizes: instance box sizes [m], each (sx, sy, sz) (zeros for a point).
    radius: nearness threshold [m].
    """

    key: str
    centers: tuple[tuple[float, float, float], ...]
    sizes: tuple[tuple[float, float, float], ...]
    radius: float

    def __post_init__(self) -> None:
        if len(self.centers) != len(self.sizes):
            raise InvalidInputError(
                f'region {self.key}: {len(self.centers)} centres, {len(self.sizes)} sizes')
        vals = [v for c in self.centers for v in c] + [v for s in self.sizes for v in s] + [self.radius]
        if not all(isinstance(v, (int, float)) and math.isfinite(v) for v in vals) or self.radius < 0 \
                or any(v < 0 for s in self.sizes for v in s):
            raise InvalidInputError(f'region {self.key}: centres, sizes and radius must be finite (>= 0)')

    def distance(self, points: np.ndarray, dims: int) -> np.ndarray:
        """Distance [m] from points (N, >=dims) to the nearest instance box, shape (N,); inf if none."""
        return near.box_distance(points, np.asarray(self.centers), np.asarray(self.sizes), dims)

    def only(self, index: int) -> 'AtomRegion':
        """Return the same region restricted to one instance."""
        return AtomRegion(self.key, (self.centers[index],), (self.sizes[index],), self.radius)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'atom': self.key, 'radius': self.radius,
                'instances': [{'center': list(c), 'size': list(s)} for c, s in zip(self.centers, self.sizes)]}

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'AtomRegion':
        """Inverse of :meth:`to_dict`."""
        try:
            inst = list(d.get('instances', []))
            centers = tuple(_vec3(i['center']) for i in inst)
            sizes = tuple(_vec3(i.get('size', (0.0, 0.0, 0.0))) for i in inst)
            return AtomRegion(str(d['atom']), centers, sizes, float(d['radius']))
        except (KeyError, TypeError, ValueError) as e:
            raise InvalidInputError(f'malformed region: {e}') from e


def _vec3(v: Any) -> tuple[float, float, float]:
    vals = [float(x) for x in v]
    if len(vals) == 2:
        vals.append(0.0)
    if len(vals) != 3:
        raise ValueError(f'expected 2 or 3 numbers, got {v!r}')
    return (vals[0], vals[1], vals[2])


def near_atom_of(descriptor_text: str) -> str:
    """Return the key of the near-atom of a descriptor text: ``red_sofa`` -> ``near[red_sofa]``."""
    return f'near[{descriptor_text}]'


def regions_for(atoms: Iterable[Atom], referent_map: ReferentMap, radius: float) -> tuple[AtomRegion, ...]:
    """Build the regions of the near-atoms among ``atoms`` from the referent map's instances.

    A descriptor with no instance gives an empty region (the atom is false everywhere).
    """
    out: dict[str, AtomRegion] = {}
    for a in atoms:
        if a.skill != 'near' or a.key in out:
            continue
        inst = referent_map.instances(str(a.args[0]))
        out[a.key] = AtomRegion(a.key, tuple(i.center for i in inst), tuple(i.size for i in inst), radius)
    return tuple(out[k] for k in sorted(out))


# --------------------------------------------------------------------------- guards over keys

KeyCube = tuple[frozenset[str], frozenset[str]]


def navigation_guard(guard: Guard) -> Guard:
    """Restrict a guard to letters with no event atom true (what holds while driving)."""
    cubes = []
    for c in guard.cubes:
        if any(a.is_event for a in c.pos):
            continue
        cubes.append(Cube(c.pos, frozenset(a for a in c.neg if not a.is_event)))
    return Guard.of(cubes)


def skill_guard(guard: Guard, event: Atom) -> Guard:
    """Restrict a guard to the letters in which ``event`` (and no other event) is true."""
    cubes = []
    for c in guard.cubes:
        if event in c.neg or any(a.is_event and a != event for a in c.pos):
            continue
        cubes.append(Cube(c.pos - {event}, frozenset(a for a in c.neg if not a.is_event)))
    return Guard.of(cubes)


def key_cubes(guard: Guard) -> tuple[KeyCube, ...]:
    """Return the guard's cubes as (true keys, false keys)."""
    return tuple((frozenset(a.key for a in c.pos), frozenset(a.key for a in c.neg)) for c in guard.cubes)


def guard_keys(guard: Guard) -> frozenset[str]:
    """Keys of the atoms a guard mentions."""
    return frozenset(a.key for a in guard.atoms)


class RegionSet:
    """The regions of a set of near-atoms, evaluated in ``dims`` dimensions."""

    def __init__(self, regions: Sequence[AtomRegion], dims: int) -> None:
        self.regions = tuple(regions)
        self.dims = dims
        self.by_key = {r.key: r for r in self.regions}
        # regions of the same boxes (an atom and its margins) share one distance
        boxes: dict[tuple, int] = {}
        self._box_of = [boxes.setdefault((r.centers, r.sizes), len(boxes)) for r in self.regions]
        self._unique = [next(r for r in self.regions if (r.centers, r.sizes) == k) for k in boxes]
        self._corners = tuple(near.box_corners(r.centers, r.sizes, dims) for r in self._unique)

    def valuation(self, points: np.ndarray) -> dict[str, np.ndarray]:
        """Atom key -> whether it holds at each point (N, >=dims), each shape (N,)."""
        dist = [r.distance(points, self.dims) for r in self._unique]
        return {r.key: near.is_near(dist[b], r.radius) for r, b in zip(self.regions, self._box_of)}

    def nearest(self, p: Sequence[float]) -> list[float]:
        """Distance [m] from point ``p`` to each region's nearest instance box (inf: no instance)."""
        dist = [near.point_distance(p, corners) for corners in self._corners]
        return [dist[b] for b in self._box_of]

    def letter_and_margin(self, p: Sequence[float]) -> tuple[frozenset[str], float]:
        """Return the true keys at ``p``, and how far [m] ``p`` may move before any changes."""
        nearest = self.nearest(p)
        true = []
        margin = math.inf
        for i, r in enumerate(self.regions):
            dist = nearest[i]
            if near.is_near(dist, r.radius):
                true.append(r.key)
            if dist != math.inf:
                margin = min(margin, abs(dist - r.radius))
        return frozenset(true), margin


def eval_key_cubes(cubes: Sequence[KeyCube], letter: frozenset[str]) -> bool:
    """Whether a letter (set of true keys) satisfies a guard given as key cubes."""
    for pos, neg in cubes:
        if pos <= letter and not (neg & letter):
            return True
    return False


def eval_guard_vectorised(cubes: Sequence[KeyCube], valuation: Mapping[str, np.ndarray],
                          n: int) -> np.ndarray:
    """Whether each of ``n`` points satisfies a guard, given the atom valuation; shape (n,).

    Atoms missing from ``valuation`` are false.
    """
    out = np.zeros(n, dtype=bool)
    false = np.zeros(n, dtype=bool)
    for pos, neg in cubes:
        c = np.ones(n, dtype=bool)
        for k in pos:
            c &= valuation.get(k, false)
        for k in neg:
            c &= ~valuation.get(k, false)
        out |= c
    return out


# --------------------------------------------------------------------------- TPSM

@dataclass(frozen=True)
class TaskProgressionMap:
    """The symbolic TPSM of one transition: goal and allowed guards over atom regions."""

    goal: Guard
    allowed: Guard
    regions: tuple[AtomRegion, ...]
    dims: int

    def classify(self, points: np.ndarray) -> np.ndarray:
        """Value per point (N, >=dims): 1 goal, -1 avoid, 0 allowed (neutral); shape (N,) int8."""
        p = np.atleast_2d(np.asarray(points, dtype=float))
        val = RegionSet(self.regions, self.dims).valuation(p)
        goal = eval_guard_vectorised(key_cubes(self.goal), val, len(p))
        allowed = eval_guard_vectorised(key_cubes(self.allowed), val, len(p))
        out = np.full(len(p), AVOID, dtype=np.int8)
        out[allowed] = NEUTRAL
        out[goal] = GOAL
        return out

    def render(self, bounds_min: Sequence[float], bounds_max: Sequence[float], spacing: float = 0.25,
               z: float = 0.0, max_points: int = 2_000_000) -> tuple[np.ndarray, np.ndarray]:
        """Render the TPSM as points for people and RViz: a grid over the bounds.

        Returns
        -------
        points: positions [m], shape (N, 3) (a ground map is drawn at height ``z``).
        values: shape (N,) int8: 1 goal, -1 avoid, 0 neutral.
        """
        if not (spacing > 0 and math.isfinite(spacing)):
            raise InvalidInputError(f'TPSM spacing must be positive, got {spacing}')
        axes = [np.arange(bounds_min[k], bounds_max[k] + 1e-9, spacing) for k in range(self.dims)]
        count = int(np.prod([len(a) for a in axes]))
        if count > max_points:
            raise InvalidInputError(f'the TPSM would have {count} points; use a coarser spacing')
        mesh = np.stack(np.meshgrid(*axes, indexing='ij'), axis=-1).reshape(-1, self.dims)
        values = self.classify(mesh)
        if self.dims == 2:
            mesh = np.column_stack([mesh, np.full(len(mesh), z)])
        return mesh, values


def atoms_needed(*guards: Guard, extra: Optional[Iterable[Atom]] = None) -> list[Atom]:
    """List the non-event atoms of some guards (and ``extra``), in a stable order."""
    seen: dict[str, Atom] = {}
    for g in guards:
        for a in g.atoms:
            if not a.is_event:
                seen.setdefault(a.key, a)
    for a in extra or ():
        seen.setdefault(a.key, a)
    return [seen[k] for k in sorted(seen)]

"""One navigation segment: a symbolic TPSM in, a path into its goal region out.

A :class:`SegmentRequest` is JSON-ready (it is what the ``fmt_planner`` node receives as
``plan_request``): the start, the regions of the atoms that matter, the ``goal`` and
``allowed`` guards over them, the bounds and the planner settings. :func:`solve_segment`
answers it with FMT* in process and returns a :class:`SegmentResult`: a path whose every
point but the last keeps the automaton where it is (free, and ``allowed`` holds) and
whose last point is the first one in the goal region, or a typed failure
(``START_OCCUPIED``, ``GOAL_OCCUPIED``, ``NO_VALID_PATH``, ``TIMEOUT``).

Edges are checked exactly against obstacles (a slab test per inflated box). Against
regions, a point's margin (its distance to the nearest region boundary) certifies a
ball in which no atom changes, so the check steps over that ball; near a boundary it
steps by ``check_resolution`` (1 cm by default), so no avoid region thicker than that
can be jumped.

Margins (issue 21: plans a controller can finish). With ``goal_margin`` > 0 the path
goes on past the goal region's edge, where the automaton takes the transition, until it
is ``goal_margin`` deep (the goal's near atoms at ``threshold - goal_margin``); that tail
keeps to ``hold``, the next state's self-loop, so the automaton stays where the
transition took it. With ``avoid_margin`` > 0 every atom a guard needs false is kept
false at ``threshold + avoid_margin``. Both are evaluated as extra regions of the same
boxes with those radii, so the edge checks stay exact. When the goal region's free part
is too thin, the margin is capped at the deepest goal point found; when no path keeps a
margin but a plain one exists, the margin is dropped. Either way the result says which
margins it kept and warns.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton.guards import Guard
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError, PlanningError
from ltl_instruct.core.planning.fmt import FmtSettings, GoalSpec, plan_motion
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.regions import (
    AtomRegion, KeyCube, RegionSet, TaskProgressionMap, eval_guard_vectorised, eval_key_cubes, guard_keys,
    key_cubes,
)
from ltl_instruct.core.world import near

TARGET_KEY = '__target__'
DEEP = '@deep'   # suffix of a goal atom's region shrunk by the goal margin
LEFT = '@left'   # suffix of the region being left, grown by the goal margin
WIDE = '@wide'   # suffix of an atom's region grown by the avoid margin
MAX_REGIONS = 256
MAX_INSTANCES = 4096
MAX_CUBES = 4096


def _guard_from(d: Any, what: str) -> Guard:
    if not isinstance(d, Mapping):
        raise InvalidInputError(f'segment request: {what} must be a guard object')
    cubes = d.get('cubes')
    if not isinstance(cubes, list) or len(cubes) > MAX_CUBES:
        raise InvalidInputError(f'segment request: {what}.cubes must be a list of at most {MAX_CUBES}')
    try:
        return Guard.from_dict(d)
    except LtlInstructError as e:
        raise InvalidInputError(f'segment request: {what}: {e.message}') from e
    except (ValueError, TypeError, AttributeError) as e:
        raise InvalidInputError(f'segment request: {what}: {e}') from e


def _point(v: Any, dims: int, what: str) -> tuple[float, ...]:
    try:
        vals = tuple(float(x) for x in v)
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f'segment request: {what} must be a list of numbers') from e
    if len(vals) < dims or not all(math.isfinite(x) for x in vals[:dims]):
        raise InvalidInputError(f'segment request: {what} needs {dims} finite numbers, got {list(vals)}')
    return vals[:dims]


@dataclass(frozen=True)
class SegmentRequest:
    """A symbolic TPSM to plan through.

    Attributes
    ----------
    id: ties the request to its task (``<instruction id>/<n>``).
    start: start position [m], shape (dims,).
    dims: 2 (ground) or 3 (drone).
    regions: regions of every near-atom the guards mention.
    goal: letters that take the automaton to the next state.
    allowed: letters that keep it in the current state.
    settings: motion-planner settings.
    target: optional ``(atom key, instance index)``: the goal also needs that instance.
    bounds_min, bounds_max: optional limits [m] (within the world's).
    transition: ``(state, next state)`` of the automaton, for messages.
    hold: letters that keep the automaton in the next state (its self-loop): where the
        path may go on after the goal's edge to reach ``goal_margin``; None: within the goal.
    goal_margin: how deep [m] the path ends inside the goal region (0: at its edge).
    avoid_margin: how far [m] outside the regions a guard needs false the path stays.
    """

    id: str
    start: tuple[float, ...]
    dims: int
    regions: tuple[AtomRegion, ...]
    goal: Guard
    allowed: Guard
    settings: FmtSettings = field(default_factory=FmtSettings)
    target: Optional[tuple[str, int]] = None
    bounds_min: Optional[tuple[float, ...]] = None
    bounds_max: Optional[tuple[float, ...]] = None
    transition: tuple[int, int] = (-1, -1)
    hold: Optional[Guard] = None
    goal_margin: float = 0.0
    avoid_margin: float = 0.0

    def describe(self) -> str:
        """``transition 0 -> 1 (goal: near[a], allowed: !near[b])`` for messages."""
        what = f'segment {self.id!r}' if self.transition == (-1, -1) else \
            f'transition {self.transition[0]} -> {self.transition[1]}'
        return f'{what} (goal: {self.goal}, allowed: {self.allowed})'

    def tpsm(self) -> TaskProgressionMap:
        """Return the request's task progression map (render it for RViz with ``.render``)."""
        return TaskProgressionMap(self.goal, self.allowed, self.regions, self.dims)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict (the ``request`` of a ``plan_request`` payload)."""
        d: dict[str, Any] = {
            'id': self.id, 'start': list(self.start), 'dims': self.dims,
            'regions': [r.to_dict() for r in self.regions],
            'goal': self.goal.to_dict(), 'allowed': self.allowed.to_dict(),
            'settings': self.settings.to_dict(), 'transition': list(self.transition),
            'target': None if self.target is None else {'atom': self.target[0], 'instance': self.target[1]},
        }
        if self.bounds_min is not None and self.bounds_max is not None:
            d['bounds'] = {'min': list(self.bounds_min), 'max': list(self.bounds_max)}
        if self.hold is not None:
            d['hold'] = self.hold.to_dict()
        d.update(goal_margin=self.goal_margin, avoid_margin=self.avoid_margin)
        return d

    @staticmethod
    def from_dict(d: Any) -> 'SegmentRequest':
        """Validate and build a request from JSON data.

        Raises
        ------
        InvalidInputError
            On a missing or malformed field, non-finite numbers, a guard atom with no
            region, or sizes over the limits.
        """
        if not isinstance(d, Mapping):
            raise InvalidInputError('segment request must be a JSON object')
        dims = d.get('dims')
        if dims not in (2, 3):
            raise InvalidInputError(f'segment request: dims must be 2 or 3, got {dims!r}')
        start = _point(d.get('start'), dims, 'start')
        raw_regions = d.get('regions', [])
        if not isinstance(raw_regions, list) or len(raw_regions) > MAX_REGIONS:
            raise InvalidInputError(f'segment request: regions must be a list of at most {MAX_REGIONS}')
        regions = tuple(AtomRegion.from_dict(r) if isinstance(r, Mapping) else _bad_region(r)
                        for r in raw_regions)
        if sum(len(r.centers) for r in regions) > MAX_INSTANCES:
            raise InvalidInputError(f'segment request: more than {MAX_INSTANCES} instances')
        goal = _guard_from(d.get('goal'), 'goal')
        allowed = _guard_from(d.get('allowed'), 'allowed')
        hold = _guard_from(d['hold'], 'hold') if d.get('hold') is not None else None
        margins = [near.check_margin(d.get(k, 0.0), f'segment request: {k}')
                   for k in ('goal_margin', 'avoid_margin')]
        known = {r.key for r in regions}
        mentioned = guard_keys(goal) | guard_keys(allowed) | (guard_keys(hold) if hold is not None else set())
        missing = sorted(k for k in mentioned if k not in known and not k.startswith(('pick[', 'release[')))
        if missing:
            raise InvalidInputError(f'segment request: no region for {", ".join(missing)}')
        settings_d = d.get('settings') or {}
        if not isinstance(settings_d, Mapping):
            raise InvalidInputError('segment request: settings must be an object')
        settings = FmtSettings.from_dict(settings_d)
        target = None
        t = d.get('target')
        if t is not None:
            if not isinstance(t, Mapping) or t.get('atom') not in known \
                    or not isinstance(t.get('instance'), int):
                raise InvalidInputError('segment request: target must name a region and an instance index')
            region = next(r for r in regions if r.key == t['atom'])
            if not 0 <= t['instance'] < len(region.centers):
                raise InvalidInputError('segment request: target instance index out of range')
            target = (str(t['atom']), int(t['instance']))
        bmin = bmax = None
        if d.get('bounds') is not None:
            b = d['bounds']
            if not isinstance(b, Mapping):
                raise InvalidInputError('segment request: bounds must be {min, max}')
            bmin, bmax = _point(b.get('min'), dims, 'bounds.min'), _point(b.get('max'), dims, 'bounds.max')
        tr = d.get('transition', [-1, -1])
        if not (isinstance(tr, (list, tuple)) and len(tr) == 2 and all(isinstance(x, int) for x in tr)):
            raise InvalidInputError('segment request: transition must be two integers')
        rid = d.get('id', '')
        if not isinstance(rid, str) or len(rid) > 400:
            raise InvalidInputError('segment request: id must be text (at most 400 characters)')
        return SegmentRequest(rid, start, dims, regions, goal, allowed, settings, target, bmin, bmax,
                              (int(tr[0]), int(tr[1])), hold, margins[0], margins[1])


def _bad_region(r: Any) -> AtomRegion:
    raise InvalidInputError(f'segment request: a region must be an object, got {type(r).__name__}')


@dataclass(frozen=True, eq=False)
class SegmentResult:
    """A solved segment or a typed failure.

    Attributes
    ----------
    request_id: the request's id.
    waypoints: the simplified path [m], shape (N, dims), N >= 2; None on failure.
    points: the same path resampled at ``path_spacing`` [m], always shape (M, 3) (a ground
        path at z = 0), ready for a ``nav_msgs/Path``; None on failure.
    length: path length [m] (0 on failure).
    error: the typed failure, or None.
    seconds: wall-clock time of the whole solve [s].
    planner_seconds: time inside OMPL [s].
    goal_margin, avoid_margin: the margins [m] the path keeps (those asked for, or less
        where the warnings say why).
    warnings: margins not kept, for people.
    """

    request_id: str
    waypoints: Optional[np.ndarray]
    points: Optional[np.ndarray]
    length: float = 0.0
    error: Optional[LtlInstructError] = None
    seconds: float = 0.0
    planner_seconds: float = 0.0
    goal_margin: float = 0.0
    avoid_margin: float = 0.0
    warnings: tuple[str, ...] = ()

    @property
    def ok(self) -> bool:
        """Whether a path was found."""
        return self.waypoints is not None and self.error is None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        d: dict[str, Any] = {'request_id': self.request_id, 'ok': self.ok, 'length': self.length,
                             'seconds': self.seconds, 'planner_seconds': self.planner_seconds}
        if self.waypoints is not None:
            d['waypoints'] = np.round(self.waypoints, 6).tolist()
            d.update(goal_margin=self.goal_margin, avoid_margin=self.avoid_margin,
                     warnings=list(self.warnings))
        if self.error is not None:
            d['error'] = self.error.to_dict()
        return d

    @staticmethod
    def failure(request_id: str, error: LtlInstructError, seconds: float = 0.0) -> 'SegmentResult':
        """Make a failed result."""
        return SegmentResult(request_id, None, None, 0.0, error, seconds)

    @staticmethod
    def from_waypoints(request_id: str, waypoints: np.ndarray, spacing: float = 0.05) -> 'SegmentResult':
        """Make a result from a path received from elsewhere (e.g. over DDS)."""
        w = np.asarray(waypoints, dtype=float)
        if w.ndim != 2 or len(w) < 1 or not np.all(np.isfinite(w)):
            raise InvalidInputError('a segment path must be a non-empty (N, dims) array of finite numbers')
        if len(w) == 1:
            w = np.vstack([w, w])
        dense = resample(w, spacing) if spacing > 0 else w
        return SegmentResult(request_id, w, as_xyz(dense), path_length(w))

    def with_margins_of(self, d: Any) -> 'SegmentResult':
        """Return this result with the margins and warnings of a received ``to_dict`` (checked)."""
        if not isinstance(d, Mapping):
            return self
        gm = near.check_margin(d.get('goal_margin', 0.0), 'segment result: goal_margin')
        am = near.check_margin(d.get('avoid_margin', 0.0), 'segment result: avoid_margin')
        warnings = d.get('warnings') or []
        if not isinstance(warnings, list) or not all(isinstance(w, str) for w in warnings):
            raise InvalidInputError('segment result: warnings must be a list of text')
        return replace(self, goal_margin=gm, avoid_margin=am, warnings=tuple(w[:500] for w in warnings[:20]))


# --------------------------------------------------------------------------- path helpers

def as_xyz(points: np.ndarray) -> np.ndarray:
    """Pad 2D points (N, 2) with z = 0 to (N, 3); 3D points are returned as they are."""
    p = np.asarray(points, dtype=float)
    return np.column_stack([p, np.zeros(len(p))]) if p.ndim == 2 and p.shape[1] == 2 else p


def path_length(points: np.ndarray) -> float:
    """Length [m] of a polyline (N, dims)."""
    p = np.asarray(points, dtype=float)
    return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum()) if len(p) > 1 else 0.0


def resample(points: np.ndarray, spacing: float) -> np.ndarray:
    """Resample a polyline (N, dims): keep every vertex, add points so no gap exceeds ``spacing`` [m]."""
    p = np.asarray(points, dtype=float)
    if len(p) < 2:
        return p.copy()
    out = [p[:1]]
    for a, b in zip(p[:-1], p[1:]):
        n = max(1, int(math.ceil(float(np.linalg.norm(b - a)) / spacing - 1e-9)))
        t = np.arange(1, n + 1, dtype=float)[:, None] / n
        out.append(a + t * (b - a))
    return np.vstack(out)


def _rename(cubes: Sequence[KeyCube], pos: Mapping[str, str], neg: Mapping[str, str]) -> tuple[KeyCube, ...]:
    """Return key cubes with true keys renamed by ``pos`` and false keys by ``neg`` (others kept)."""
    return tuple((frozenset(pos.get(k, k) for k in p), frozenset(neg.get(k, k) for k in n)) for p, n in cubes)


def _meet(a: Sequence[KeyCube], b: Sequence[KeyCube]) -> tuple[KeyCube, ...]:
    """Return the conjunction of two guards given as key cubes (contradictory cubes dropped)."""
    out = []
    for pa, na in a:
        for pb, nb in b:
            pos, neg = pa | pb, na | nb
            if not pos & neg:
                out.append((pos, neg))
    return tuple(out)


def _margin_regions(regions: Sequence[AtomRegion], keys: Iterable[str], suffix: str,
                    change: float) -> tuple[list[AtomRegion], dict[str, str]]:
    """Return the regions of the same boxes with the radius changed by ``change`` [m], and the renaming."""
    by_key = {r.key: r for r in regions}
    if change == 0:
        return [], {}
    out = [replace(by_key[k], key=k + suffix, radius=max(by_key[k].radius + change, 0.0))
           for k in sorted(set(keys)) if k in by_key]
    return out, {r.key[:-len(suffix)]: r.key for r in out}


class SegmentProblem:
    """The validity, goal and edge checks of one request in one world (shared by FMT*, RRT*, grid).

    Key cubes (guards over region keys): ``plain_goal_cubes`` is where the automaton takes
    the transition; ``entry_cubes`` the same with the atoms it needs false kept at the
    avoid margin; ``goal_cubes`` where the path ends (goal atoms ``goal_margin`` deep, and
    ``hold`` when the path goes on past the edge); ``allowed_cubes`` and ``hold_cubes``
    where the path may be before and after the edge. Without margins they are the
    request's guards.
    """

    def __init__(self, request: SegmentRequest, world: PlanningWorld) -> None:
        if request.dims != world.dims:
            raise InvalidInputError(f'the request is {request.dims}D but the map is {world.dims}D')
        self.request = request
        self.world = world
        regions = list(request.regions)
        self.region_keys = frozenset(r.key for r in regions)   # the atoms (no target, no margins)
        plain: tuple[KeyCube, ...] = key_cubes(request.goal)
        if request.target is not None:
            key, index = request.target
            region = next((r for r in regions if r.key == key), None)
            if region is None or not 0 <= index < len(region.centers):
                raise InvalidInputError(f'target {request.target} names no instance')
            regions.append(replace(region.only(index), key=TARGET_KEY))
            plain = tuple((pos | {TARGET_KEY}, neg) for pos, neg in plain)
        self._set_cubes(regions, plain)
        lo = np.asarray(world.bounds_min, dtype=float)
        hi = np.asarray(world.bounds_max, dtype=float)
        if request.bounds_min is not None and request.bounds_max is not None:
            lo = np.maximum(lo, request.bounds_min)
            hi = np.minimum(hi, request.bounds_max)
        self.lo, self.hi = lo, hi
        self._bounds = tuple(zip(lo.tolist(), hi.tolist()))   # Python floats: the callbacks compare often
        self.resolution = request.settings.check_resolution
        self._radius_of = {r.key: r.radius for r in self.regions.regions}

    def _set_cubes(self, regions: list[AtomRegion], plain: tuple[KeyCube, ...]) -> None:
        """Build the regions and cube sets.

        The goal margin takes the path into the regions the goal needs true, and as far
        out of those it is leaving (false in the goal, true in the allowed guard). The
        avoid margin is for the other atoms a guard needs false.
        """
        r = self.request
        allowed = key_cubes(r.allowed)
        hold = key_cubes(r.hold) if r.hold is not None else None
        goal_keys = {k for pos, _ in plain for k in pos}
        self.leaving_keys = {k for _, neg in plain for k in neg} & {k for pos, _ in allowed for k in pos}
        avoided = {k for cubes in (plain, allowed, hold or ()) for _, neg in cubes for k in neg} \
            - goal_keys - {k for pos, _ in allowed for k in pos}
        deep_regions, deep = _margin_regions(regions, goal_keys, DEEP, -r.goal_margin)
        left_regions, left = _margin_regions(regions, self.leaving_keys, LEFT, r.goal_margin)
        wide_regions, wide = _margin_regions(regions, avoided, WIDE, r.avoid_margin)
        self.regions = RegionSet(regions + deep_regions + left_regions + wide_regions, self.world.dims)
        self.plain_goal_cubes = plain
        self.entry_cubes = _rename(plain, {}, wide)
        self.allowed_cubes = _rename(allowed, {}, wide)
        self.hold_cubes = _rename(hold, {}, wide) if hold is not None else self.entry_cubes
        self.goal_cubes = _rename(plain, deep, {**wide, **left})
        if r.goal_margin > 0 and hold is not None:
            self.goal_cubes = _meet(self.goal_cubes, self.hold_cubes)
        self.valid_cubes = self.allowed_cubes + self.entry_cubes

    # -- points
    def letter(self, p: Sequence[float]) -> frozenset[str]:
        """Return the true atom keys at a point."""
        return self.regions.letter_and_margin(p)[0]

    def in_bounds(self, p: Sequence[float]) -> bool:
        """Inside the request's bounds."""
        for (lo, hi), x in zip(self._bounds, p):
            if not lo <= x <= hi:
                return False
        return True

    def state_valid(self, p: Sequence[float]) -> bool:
        """Free, in bounds, and the letter is allowed or in the goal."""
        if not self.in_bounds(p) or not self.world.point_free(p):
            return False
        return eval_key_cubes(self.valid_cubes, self.letter(p))

    def in_goal(self, p: Sequence[float]) -> bool:
        """Whether the path may end at ``p`` (the goal, with its margins)."""
        return eval_key_cubes(self.goal_cubes, self.letter(p))

    def in_plain_goal(self, p: Sequence[float]) -> bool:
        """Whether the automaton takes the transition at ``p`` (the goal without margins)."""
        return eval_key_cubes(self.plain_goal_cubes, self.letter(p))

    def goal_lower_bound(self, p: Sequence[float]) -> float:
        """Return a lower bound of the distance [m] from ``p`` to the goal region."""
        nearest = dict(zip((r.key for r in self.regions.regions), self.regions.nearest(p)))
        best = math.inf
        for pos, _ in self.goal_cubes:
            need = 0.0
            for k in pos:
                need = max(need, nearest.get(k, math.inf) - self._radius_of.get(k, 0.0))
            best = min(best, need)
        return max(best, 0.0) if best != math.inf else 1e9

    def motion_valid(self, a: Sequence[float], b: Sequence[float]) -> bool:
        """Whether every point of the straight motion a -> b is valid.

        Obstacle boxes and bounds are checked exactly (slab test; the bounds are convex).
        Regions are checked by marching: each step is the distance by which no atom can
        change (exact), but at least ``check_resolution`` near a region boundary. An
        occupancy lookup is checked cell by cell at that resolution too.
        """
        dims = self.world.dims
        if not self.in_bounds(a) or not self.in_bounds(b) or self.world.segment_hits_box(a, b):
            return False
        length = math.sqrt(sum((b[k] - a[k]) ** 2 for k in range(dims)))
        lookup = self.world.lookup is not None
        floor = self.resolution if not lookup else min(self.resolution, self.world.lookup.resolution / 2)
        s = 0.0
        while True:
            t = s / length if length > 0 else 1.0
            p = tuple(a[k] + t * (b[k] - a[k]) for k in range(dims))
            letter, margin = self.regions.letter_and_margin(p)
            if not eval_key_cubes(self.valid_cubes, letter):
                return False
            if lookup and self.world.clearance(p) < 0:
                return False
            if s >= length:
                return True
            step = floor if lookup else max(margin, floor)
            s = min(length, s + step)

    # -- vectorised
    def classify(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Return ``(valid, goal)`` flags for points (N, dims), each shape (N,)."""
        flags = self._flags(points)
        return flags['free'] & flags['valid'], flags['free'] & flags['goal']

    def _flags(self, points: np.ndarray) -> dict[str, np.ndarray]:
        """Return per point (N, dims): free, and whether each cube set holds; each shape (N,)."""
        p = np.atleast_2d(np.asarray(points, dtype=float))
        val = self.regions.valuation(p)
        inb = np.all((p[:, :self.world.dims] >= self.lo) & (p[:, :self.world.dims] <= self.hi), axis=1)
        cubes = {'valid': self.valid_cubes, 'goal': self.goal_cubes, 'plain': self.plain_goal_cubes,
                 'entry': self.entry_cubes, 'allowed': self.allowed_cubes, 'hold': self.hold_cubes}
        out = {name: eval_guard_vectorised(c, val, len(p)) for name, c in cubes.items()}
        out['free'] = self.world.is_free(p) & inb
        return out

    def goal_depth(self, points: np.ndarray) -> np.ndarray:
        """How deep [m] points (N, dims) lie in the goal, per cube the least over its atoms.

        An atom the cube needs true counts its depth inside its region; one it is leaving,
        how far outside. The best cube the point satisfies counts; shape (N,); ``-inf``
        outside the goal, ``inf`` for a goal with no atom to enter or leave.
        """
        p = np.atleast_2d(np.asarray(points, dtype=float))
        by_key = self.regions.by_key
        val = self.regions.valuation(p)
        best = np.full(len(p), -np.inf)
        for pos, neg in self.plain_goal_cubes:
            depth = np.full(len(p), np.inf)
            for k in pos | (neg & self.leaving_keys):
                region = by_key[k]
                inside = near.depth(region.distance(p, self.world.dims), region.radius)
                depth = np.minimum(depth, inside if k in pos else -inside)
            inside = eval_guard_vectorised(((pos, neg),), val, len(p))
            best = np.where(inside, np.maximum(best, depth), best)
        return best

    def sample_goal(self, count: int, seed: int, batches: int = 24,
                    batch: int = 4096) -> tuple[np.ndarray, bool]:
        """Return up to ``count`` valid goal points (M, dims), and whether a plain goal point was seen.

        Rejection sampling in the boxes of the plain goal's near regions (for a cube of
        several atoms, each box of its atom with the fewest instances, cut to the
        bounding box of the other atoms' regions that meet it), so that with margins the
        points drawn are those the same request without margins draws: when none of them
        is in the plain goal either, that request is blocked too.
        """
        rng = np.random.default_rng(seed)
        dims = self.world.dims
        boxes: list[tuple[np.ndarray, np.ndarray]] = []
        for pos, _ in self.plain_goal_cubes:
            candidates = [self.regions.by_key[k] for k in pos if k in self.regions.by_key]
            if not candidates:
                boxes.append((self.lo, self.hi))
                continue
            region = min(candidates, key=lambda r: len(r.centers))
            for c, s in zip(region.centers, region.sizes):
                lo, hi = near.region_box(c, s, region.radius, dims)
                lo, hi = np.maximum(lo, self.lo), np.minimum(hi, self.hi)
                for other in candidates:        # a conjunction: where the other regions may hold too
                    if other is not region and np.all(lo <= hi):
                        lo, hi = _clip_to_region(lo, hi, other, dims)
                if np.all(lo <= hi):
                    boxes.append((lo, hi))
        if not boxes:
            return np.zeros((0, dims)), False
        vol = np.array([float(np.prod(np.maximum(h - lo_, 1e-3))) for lo_, h in boxes])
        found: list[np.ndarray] = [np.zeros((0, dims))]
        total, plain_seen = 0, False
        for _ in range(batches):
            which = rng.choice(len(boxes), size=batch, p=vol / vol.sum())
            lo = np.array([boxes[i][0] for i in which])
            hi = np.array([boxes[i][1] for i in which])
            pts = lo + rng.random((batch, dims)) * (hi - lo)
            f = self._flags(pts)
            goal = f['free'] & f['goal']
            plain_seen = plain_seen or bool((f['free'] & f['plain']).any())
            found.append(pts[goal])
            total += int(goal.sum())
            if total >= count:
                break
        return np.vstack(found)[:count], plain_seen

    def first_goal_prefix(self, points: np.ndarray) -> Optional[np.ndarray]:
        """Cut the densified path where it may end: at its first goal point after the edge.

        The automaton takes the transition at the first point in the plain goal (the
        edge); points before it must be allowed, the edge must be an entry point, and
        with a goal margin the points after it must hold the next state until the path
        is deep enough. Returns None if it never gets there, or if a point is out of
        place (the sampled check found what the edge checks could not: a sliver of a
        region thinner than ``check_resolution``, or a path that leaves the goal early).
        """
        dense = resample(points, self.resolution)
        f = self._flags(dense)
        edges = np.flatnonzero(f['plain'][1:]) + 1
        if len(edges) == 0:
            return None
        k = int(edges[0])
        if not (f['free'] & f['allowed'])[1:k].all() or not (f['free'][k] and f['entry'][k]):
            return None
        if f['goal'][k]:
            return dense[:k + 1]
        ends = np.flatnonzero(f['goal'][k + 1:]) + k + 1
        if len(ends) == 0:
            return None
        e = int(ends[0])
        return dense[:e + 1] if (f['free'] & f['hold'])[k + 1:e + 1].all() else None

    def goal_projections(self, points: np.ndarray) -> np.ndarray:
        """Return, for each point (M, dims), its nearest point of every goal atom's near-ball; (M, C, dims).

        One column per instance of every atom a goal cube needs true (its near region
        shrunk by the goal margin where there is one); a point inside a ball is its own
        projection.
        """
        dims = self.world.dims
        a = np.atleast_2d(np.asarray(points, dtype=float))[:, :dims]
        cols = []
        for pos, _ in self.goal_cubes:
            for k in pos:
                region = self.regions.by_key.get(k)
                if region is None or not region.centers:
                    continue
                c = np.asarray(region.centers, dtype=float)[:, :dims]
                h = np.asarray(region.sizes, dtype=float)[:, :dims] / 2.0
                q = np.clip(a[:, None, :], (c - h)[None], (c + h)[None])          # (M, I, dims)
                d = np.linalg.norm(a[:, None, :] - q, axis=2, keepdims=True)
                r = region.radius * (1.0 - 1e-6)
                scale = np.where(d <= r, 1.0, r / np.maximum(d, 1e-300))
                cols.append(q + (a[:, None, :] - q) * scale)
        return np.concatenate(cols, axis=1) if cols else np.zeros((len(a), 0, dims))

    def refine_end(self, path: np.ndarray, pool: np.ndarray, max_checks: int = 400) -> np.ndarray:
        """Re-choose where the path enters the goal: the cheapest straight exit from any vertex.

        Candidates, for every vertex of the path (resampled at 10 cm): its projections on
        the goal's near-balls and its three nearest goal samples of ``pool``. They are
        ranked at once by the cost of the path to the vertex plus the straight exit, and
        checked cheapest first; the first valid one is the best (at most ``max_checks``).
        """
        path = resample(path, 0.1)
        prefix = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(path, axis=0), axis=1))])
        best_cost = prefix[-1]
        verts = path[:-1]
        cands = self.goal_projections(verts)
        if len(pool):
            dist = np.linalg.norm(verts[:, None, :] - pool[None], axis=2)
            nearest = np.argsort(dist, axis=1)[:, :3]
            cands = np.concatenate([cands, pool[nearest]], axis=1)
        if cands.shape[1] == 0:
            return _drop_collinear(path)
        cost = prefix[:-1, None] + np.linalg.norm(cands - verts[:, None, :], axis=2)
        order = np.argsort(cost, axis=None)
        for flat in order[:max_checks]:
            i, j = divmod(int(flat), cands.shape[1])
            if cost[i, j] >= best_cost - 1e-9:
                break
            a, q = tuple(verts[i]), tuple(cands[i, j])
            if not self.state_valid(q) or not self.motion_valid(a, q):
                continue
            cut = self.first_goal_prefix(np.vstack([verts[i], cands[i, j]]))
            if cut is None:
                continue
            return _drop_collinear(np.vstack([path[:i + 1], cut[-1:]]))
        return _drop_collinear(path)

    def shortcut(self, path: np.ndarray, rounds: int = 4, spacing: float = 0.5,
                 pool: Optional[np.ndarray] = None, window: int = 60) -> np.ndarray:
        """Shorten a path (ending at its first goal point) without leaving the valid space."""
        best = path
        for r in range(rounds):
            pts = resample(best, spacing / (2 ** max(0, r - 1))) if r > 0 else best
            out = [pts[0]]
            i = 0
            n = len(pts)
            while i < n - 1:
                j = min(n - 1, i + window)
                while j > i + 1 and not self.motion_valid(pts[i], pts[j]):
                    j -= 1
                out.append(pts[j])
                i = j
            if pool is not None:
                out = list(self.refine_end(np.asarray(out), pool))
            cand = np.asarray(out)
            cut = self.first_goal_prefix(cand)
            if cut is None:
                break
            cand = _drop_collinear(cut)
            if path_length(cand) < path_length(best) - 1e-9:
                best = cand
            elif r > 0:
                break
        return best


DIRECT_TRIES = 8   # goal samples, nearest first, tried as straight ways before FMT* runs


def _direct_path(problem: SegmentProblem, start: tuple[float, ...],
                 samples: np.ndarray) -> Optional[np.ndarray]:
    """Return the straight way from ``start`` to one of its nearest goal samples if valid, else None."""
    a = np.asarray(start, dtype=float)
    for i in np.argsort(np.linalg.norm(samples - a, axis=1))[:DIRECT_TRIES]:
        q = tuple(float(x) for x in samples[i])
        if problem.motion_valid(start, q):
            cut = problem.first_goal_prefix(np.vstack([a, samples[i]]))
            if cut is not None:
                return _drop_collinear(cut)
    return None


GRID_MAX_CELLS = 250_000   # a larger 2D map is planned by FMT* alone
GRID_DETOUR = 1.3          # the grid is tried when FMT*'s path is this many times the straight way


def _shorter_on_grid(problem: SegmentProblem, path: np.ndarray, pool: np.ndarray) -> np.ndarray:
    """Return the grid's path where it is shorter than ``path`` and checked valid (2D), else ``path``.

    Tried only where FMT*'s path is ``GRID_DETOUR`` times the straight way to the nearest
    goal sample or longer: a detour, perhaps round a passage its samples missed. The grid
    path (``FmtSettings.grid_cell``) is shortcut as FMT*'s was, then checked as every path
    is: each straight move valid and the goal entered where the segment may end.
    """
    s = problem.request.settings
    if s.grid_cell <= 0 or len(problem.lo) != 2 or len(pool) == 0:
        return path
    length = path_length(path)
    if length < GRID_DETOUR * float(np.linalg.norm(pool - path[0], axis=1).min()):
        return path
    from ltl_instruct.core.planning.grid import grid_path
    raw = grid_path(problem, path[0], s.grid_cell, GRID_MAX_CELLS, _shorter_ways_box(path[0], pool, length))
    if raw is None:
        return path
    cand = _drop_collinear(raw)
    if s.simplify:
        cand = problem.shortcut(cand, pool=pool)
    if path_length(cand) >= length - 1e-6:
        return path
    if not all(problem.motion_valid(a, b) for a, b in zip(cand[:-1], cand[1:])):
        return path
    cut = problem.first_goal_prefix(cand)
    return path if cut is None else _drop_collinear(cut)


def _shorter_ways_box(start: np.ndarray, goals: np.ndarray, length: float) -> tuple[np.ndarray, np.ndarray]:
    """Return the box (lo, hi) [m] holding every way from ``start`` to a goal shorter than ``length``.

    Such a way lies in the ellipse with foci the start and its goal whose axes sum to the
    length (as in informed sampling); the box holds each goal's ellipse (none for a goal
    farther than the length), grown by 0.5 m for goal points between the samples.
    """
    a = length / 2.0
    focal = np.linalg.norm(goals - start[None], axis=1) / 2.0
    reach = focal <= a   # a goal farther than the length has no such way: no ellipse
    if reach.any():
        goals, focal = goals[reach], focal[reach]
    else:
        goals, focal = goals[[np.argmin(focal)]], focal.min(keepdims=True)
    centre = (start[None] + goals) / 2.0
    b = np.sqrt(np.maximum(a * a - focal * focal, 0.0))
    u = (goals - start[None]) / np.maximum(2.0 * focal, 1e-9)[:, None]
    half = np.sqrt(a * a * u * u + (b * b)[:, None] * (1.0 - u * u))   # the ellipse's half extent per axis
    return (centre - half).min(axis=0) - 0.5, (centre + half).max(axis=0) + 0.5


def _clip_to_region(lo: np.ndarray, hi: np.ndarray, region: AtomRegion,
                    dims: int) -> tuple[np.ndarray, np.ndarray]:
    """Cut the box lo..hi to the bounding box of the parts of ``region`` that meet it (empty: lo > hi)."""
    parts = [near.region_box(c, s, region.radius, dims) for c, s in zip(region.centers, region.sizes)]
    meet = [(a, b) for a, b in parts if np.all(a <= hi) and np.all(b >= lo)]
    if not meet:
        return lo, lo - 1.0
    low = np.min([a for a, _ in meet], axis=0)
    high = np.max([b for _, b in meet], axis=0)
    return np.maximum(lo, low), np.minimum(hi, high)


def _drop_collinear(points: np.ndarray, tol: float = 1e-9) -> np.ndarray:
    """Remove repeated points, and interior points where the path goes straight on.

    A point is dropped when the step out of it keeps the direction of the step into it:
    the sine of the angle between them is at most ``tol`` (and they do not turn back). The
    test is relative to the steps' lengths, so a densified polyline (steps of 1 cm) shrinks
    back to its corners and keeps every one of them: a corner of 0.2 degrees, split in two
    by the densifying, once passed an absolute test and the straight cut clipped an
    obstacle by 4 mm (a plan the independent check refused).
    """
    if len(points) <= 2:
        return points
    step = np.linalg.norm(np.diff(points, axis=0), axis=1)
    keep = np.concatenate([[True], step >= tol])       # drop a point equal to the one before
    keep[-1] = True
    pts = points[keep]
    if len(pts) <= 2:
        return pts
    ab, bc = pts[1:-1] - pts[:-2], pts[2:] - pts[1:-1]
    n1, n2 = np.linalg.norm(ab, axis=1), np.linalg.norm(bc, axis=1)
    dot = np.einsum('ij,ij->i', ab, bc)
    cross = np.abs(ab[:, 0] * bc[:, 1] - ab[:, 1] * bc[:, 0]) if pts.shape[1] == 2 \
        else np.linalg.norm(np.cross(ab, bc), axis=1)
    straight = (dot > 0.0) & (cross <= tol * n1 * n2)
    return pts[np.concatenate([[True], ~straight, [True]])]


SolveFn = Callable[[SegmentRequest], SegmentResult]


def solve_segment(request: SegmentRequest, world: PlanningWorld,
                  settings: Optional[FmtSettings] = None) -> SegmentResult:
    """Plan one segment in process with FMT* (or RRT*); never raises for a planning failure.

    ``settings`` overrides ``request.settings`` when given. The margins are kept where
    a path can keep them; a segment that has a path without them never fails because
    of them: the result keeps less (capped at the deepest free goal point, or dropped)
    and says so in its warnings. Bad input (a request that does not fit the world)
    raises :class:`InvalidInputError`.
    """
    t0 = time.monotonic()
    if settings is not None:
        request = replace(request, settings=settings)
    result, plain_fails_too = _solve_once(request, world)
    if not result.ok and not plain_fails_too and (request.goal_margin > 0 or request.avoid_margin > 0):
        result = _solve_with_less_margin(request, world)
    return replace(result, seconds=time.monotonic() - t0)


def _solve_with_less_margin(request: SegmentRequest, world: PlanningWorld) -> SegmentResult:
    """Solve without margins; if that works, keep as much margin as a path allows, and warn."""
    result = _solve_once(replace(request, goal_margin=0.0, avoid_margin=0.0), world)[0]
    if not result.ok:
        return result   # the segment fails whatever the margins: its own failure
    for gm, am in _fallback_margins(request, world):
        better = _solve_once(replace(request, goal_margin=gm, avoid_margin=am), world)[0]
        if better.ok:
            result = better
            break
    return replace(result, warnings=_margin_warnings(request, result))


def _fallback_margins(request: SegmentRequest, world: PlanningWorld) -> list[tuple[float, float]]:
    """Return the (goal, avoid) margins [m] to try, most first, after the requested ones failed.

    The goal margin is capped at the deepest free goal point sampled (less 1 cm, so the
    deep region keeps some room): a thin goal region is entered as deep as it allows.
    """
    plain = SegmentProblem(replace(request, goal_margin=0.0, avoid_margin=0.0), world)
    samples = plain.sample_goal(max(request.settings.goal_samples, 512), request.settings.seed)[0]
    deepest = float(plain.goal_depth(samples).max()) if len(samples) else 0.0
    cap = round(min(request.goal_margin, max(deepest - 0.01, 0.0)), 4)
    tried = {(request.goal_margin, request.avoid_margin), (0.0, 0.0)}
    out = []
    for pair in ((cap, request.avoid_margin), (cap, 0.0), (0.0, request.avoid_margin)):
        if pair not in tried:
            tried.add(pair)
            out.append(pair)
    return out


def _margin_warnings(request: SegmentRequest, result: SegmentResult) -> tuple[str, ...]:
    """Say which margins a result keeps less of than the request asked for."""
    out = []
    if result.goal_margin < request.goal_margin:
        out.append(f'{request.describe()}: the goal is reached {result.goal_margin:.2f} m deep, not '
                   f'{request.goal_margin:.2f} m (goal_margin): no reachable free part of it is deeper')
    if result.avoid_margin < request.avoid_margin:
        out.append(f'{request.describe()}: regions to avoid are passed closer than '
                   f'{request.avoid_margin:.2f} m (avoid_margin): free space leaves no path that keeps it')
    return tuple(out)


def _solve_once(request: SegmentRequest, world: PlanningWorld) -> tuple[SegmentResult, bool]:
    """Plan one segment with the request's margins exactly; a typed failure if none is found.

    Also says whether the failure is certain without margins too (a start in collision,
    or in a plain region to avoid; no plain goal point among the goal samples), so that
    the request is not solved again for nothing.
    """
    t0 = time.monotonic()
    s = request.settings
    problem = SegmentProblem(request, world)
    start = tuple(float(x) for x in request.start[:world.dims])
    where = request.describe()
    fmt_start = ', '.join(f'{x:.2f}' for x in start)

    def fail(code: ErrorCode, why: str, plain_too: bool = False,
             **details: Any) -> tuple[SegmentResult, bool]:
        facts = {'transition': list(request.transition), 'start': list(start), **details}
        err = PlanningError(f'{where}: {why}', code, details=facts)
        return SegmentResult.failure(request.id, err, time.monotonic() - t0), plain_too

    if len(start) != world.dims or not all(math.isfinite(x) for x in start):
        raise InvalidInputError(f'start must be {world.dims} finite numbers, got {request.start}')
    if not problem.in_bounds(start) or world.clearance(start) < 0:
        return fail(ErrorCode.START_OCCUPIED,
                    f'the start ({fmt_start}) is in collision or outside the map '
                    f'(obstacles grown by the robot radius {world.robot_radius} m)', True)
    if problem.in_plain_goal(start):   # the transition happens where the robot is: nothing to drive
        w = np.array([start, start])
        return SegmentResult(request.id, w, as_xyz(w), 0.0, None, time.monotonic() - t0), False
    letter = problem.letter(start)
    if not eval_key_cubes(problem.allowed_cubes, letter):
        return fail(ErrorCode.START_OCCUPIED,
                    f'the start ({fmt_start}) lies in a region to avoid (atoms true there: '
                    f'{", ".join(sorted(k for k in letter if k in problem.region_keys)) or "none"})',
                    not eval_key_cubes(key_cubes(request.allowed), letter))
    samples, plain_seen = problem.sample_goal(s.goal_samples, s.seed)
    if len(samples) == 0:
        return fail(ErrorCode.GOAL_OCCUPIED, 'every goal region is blocked: no free point satisfies the goal',
                    not plain_seen)
    direct = _direct_path(problem, start, samples) if s.direct and s.planner == 'fmt' else None
    if direct is not None:   # a straight way into the goal: nothing for FMT* to find
        path = problem.shortcut(direct, pool=samples) if s.simplify else direct
        return _result(request, path, t0, 0.0), False
    goal = GoalSpec(problem.in_goal, problem.goal_lower_bound, samples)
    outcome = plan_motion(world.dims, problem.lo, problem.hi, start, problem.state_valid,
                          problem.motion_valid, goal, s)
    if outcome.points is None:
        if outcome.timed_out:
            return fail(ErrorCode.TIMEOUT, f'no path within the time limit of {s.time_limit} s '
                        f'({s.num_samples} samples)', planner_status=outcome.status)
        return fail(ErrorCode.NO_VALID_PATH, f'no path from ({fmt_start}) reaches the goal region without '
                    f'entering an obstacle or a region to avoid ({s.num_samples} samples)',
                    planner_status=outcome.status)
    raw = np.vstack([np.asarray(start)[None], outcome.points[1:]])
    cut = problem.first_goal_prefix(raw)
    if cut is None:
        return fail(ErrorCode.NO_VALID_PATH, 'the planner\'s path does not reach the goal region')
    path = _drop_collinear(cut)
    if s.simplify:
        path = problem.shortcut(path, pool=samples)
    path = _shorter_on_grid(problem, path, samples)
    return _result(request, path, t0, outcome.seconds), False


def _result(request: SegmentRequest, path: np.ndarray, t0: float, planner_seconds: float) -> SegmentResult:
    """Return the result of a planned path: its waypoints, the dense path, its length and times."""
    spacing = request.settings.path_spacing
    dense = resample(path, spacing) if spacing > 0 else path
    return SegmentResult(request.id, path, as_xyz(dense), path_length(path), None, time.monotonic() - t0,
                         planner_seconds, request.goal_margin, request.avoid_margin)

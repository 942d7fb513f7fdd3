"""Search: explore a scene with the robot's camera until the task's referents resolve (issue 18).

From the robot's start pose the search looks around (a panorama of ``headings`` camera
views), fuses the frames into a :class:`SemanticMap` and grounds the task formula on the
map's instances. While a required descriptor is ``UNKNOWN_REFERENT`` or ``NO_MATCH`` it
moves to a frontier (:mod:`coverage`) and looks again, along the way every
``view_spacing`` metres and at the goal, re-grounding after every panorama:

- ``gain`` (the default) picks the frontier with the most unseen cells in sight per
  metre of travel: ``gain * exp(-decay * travel)``, travel first from the grid's
  shortest paths, then, for the ``shortlist`` best, the FMT* path to it;
- ``nearest`` picks the frontier nearest by travel (the classic baseline).

Every move is planned by the package's FMT* segment solver with the task's avoidance
constraints: the regions ``near[x]`` of the descriptors the task avoids (those only
under a negation), as far as the map holds them, are the segment's regions to avoid
(``avoid_margin`` outside), and a move is cut short when a view reveals an avoided
region its rest would enter. Obstacles are the scene's (the planner's world), as a robot
with a local obstacle map would know them; the referents come only from the camera.

The search ends when every required descriptor resolves (resolved or ambiguous), when
no frontier is reachable with a gain of at least ``min_gain`` cells (the map is
complete: a descriptor still unresolved then ends ``NO_MATCH``, with the explanation),
or after ``max_moves`` moves.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Callable, Optional, Sequence, Union

import numpy as np

from ltl_instruct.core.automaton.guards import Cube, Guard
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.comparators import GroundingParams
from ltl_instruct.core.grounding.coverage import (
    Coverage, PlaneGrid, frontier_cells, seen_cells, sight_blocking_cells, travel_field, view_gain,
)
from ltl_instruct.core.grounding.resolve import ground_formula
from ltl_instruct.core.grounding.rsm import Grounding, Outcome, ReferentMap
from ltl_instruct.core.grounding.semantic_map import SemanticMap
from ltl_instruct.core.grounding.survey import survey_params
from ltl_instruct.core.planning.fmt import FmtSettings
from ltl_instruct.core.planning.occupancy import PlanningWorld, world_from_scene
from ltl_instruct.core.planning.regions import AtomRegion
from ltl_instruct.core.planning.segment import SegmentRequest, SegmentResult, path_length, solve_segment
from ltl_instruct.core.spec import Formula, near, parse_formula
from ltl_instruct.core.world import near as nearness
from ltl_instruct.core.world.camera import SyntheticCamera
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import Scene

STRATEGIES = ('gain', 'nearest')
_GOAL_ATOM = near('search_goal')
_UNRESOLVED = (Outcome.UNKNOWN_REFERENT, Outcome.NO_MATCH)
GOAL_RADIUS = 0.2
"""A move ends within this distance [m] of its frontier goal."""


@dataclass(frozen=True)
class SearchParams:
    """Settings of a search.

    Attributes
    ----------
    strategy: ``gain`` (information gain per metre) or ``nearest`` (nearest frontier).
    headings: camera views per panorama, evenly around (4 views of 90 degrees: all round).
    view_spacing: a panorama every this many metres of travel [m], and at each goal.
    sensor_range: camera range, and the reach of the gain estimate [m].
    width, height: camera image size [px].
    cell: cell of the plane grid [m] (the map's voxel size is kept at least this fine).
    min_gain: least unseen cells in sight for a frontier to be worth a move.
    decay: the gain-per-metre score of a frontier is ``gain * exp(-decay * travel)`` (per
        metre [1/m], as Gonzalez-Banos and Latombe weigh it); 0: ``gain / (travel + view_cost)``.
    view_cost: travel [m] a panorama is worth in the second form.
    shortlist: frontiers planned with FMT* per move (the best by grid travel).
    max_moves: moves before the search gives up.
    revisit: frontiers closer than this to where a panorama was taken are not goals [m]
        (what the gain estimate counts there is out of the camera's sight).
    near_threshold, avoid_margin: the regions to avoid: ``near[x]`` radius [m], and how far
        outside them [m] the path stays.
    fmt: motion-planner settings of each move.
    grounding: comparator settings of the re-grounding.
    """

    strategy: str = 'gain'
    headings: int = 4
    view_spacing: float = 2.0
    sensor_range: float = 6.0
    width: int = 160
    height: int = 120
    cell: float = 0.1
    min_gain: int = 30
    view_cost: float = 2.0
    decay: float = 0.3
    shortlist: int = 3
    max_moves: int = 40
    revisit: float = 1.0
    near_threshold: float = nearness.DEFAULT_NEAR_THRESHOLD
    avoid_margin: float = nearness.DEFAULT_AVOID_MARGIN
    fmt: FmtSettings = field(default_factory=lambda: FmtSettings(num_samples=1500, time_limit=2.0))
    grounding: GroundingParams = field(default_factory=GroundingParams)

    def __post_init__(self) -> None:
        if self.strategy not in STRATEGIES:
            raise InvalidInputError(f'strategy must be one of {STRATEGIES}, got {self.strategy!r}')
        if not 1 <= self.headings <= 16 or not 1 <= self.shortlist <= 20 or not 0 <= self.max_moves <= 1000:
            raise InvalidInputError('headings must be in 1..16, shortlist in 1..20, max_moves in 0..1000')
        for name in ('view_spacing', 'sensor_range', 'cell'):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise InvalidInputError(f'{name} must be a positive number [m], got {v!r}')
        nearness.check_threshold(self.near_threshold)
        nearness.check_margin(self.avoid_margin, 'avoid_margin')


@dataclass(frozen=True, eq=False)
class SearchResult:
    """How a search went.

    Attributes
    ----------
    referent_map: the formula grounded on the final map (unresolved after a complete
        search: ``NO_MATCH``, with why).
    sought: the required descriptors unresolved at the start.
    views: robot poses (x [m], y [m], yaw [rad]) of every camera view, in order.
    path: the robot's path [m], shape (N, 2), from the start.
    travel: its length [m].
    area_seen: floor area whose column the camera observed [m^2].
    complete: no reachable frontier was left (the map holds all the robot can see).
    reason: why the search ended: ``resolved``, ``complete`` or ``max_moves``.
    moves: frontier goals driven to.
    seen: the cells seen, bool (nx, ny) over ``grid``.
    grid: the plane grid of ``seen``.
    semantic_map: the map the camera built.
    """

    referent_map: ReferentMap
    sought: tuple[str, ...]
    views: tuple[tuple[float, float, float], ...]
    path: np.ndarray
    travel: float
    area_seen: float
    complete: bool
    reason: str
    moves: int
    seen: np.ndarray
    grid: PlaneGrid
    semantic_map: SemanticMap

    def summary(self) -> dict:
        """JSON-ready figures (no arrays but the path)."""
        return {'sought': list(self.sought), 'views': len(self.views), 'moves': self.moves,
                'travel_m': round(self.travel, 3), 'area_seen_m2': round(self.area_seen, 2),
                'complete': self.complete, 'reason': self.reason,
                'path': np.round(self.path, 3).tolist()}


def unresolved(rmap: ReferentMap) -> tuple[str, ...]:
    """Return the required descriptors of a referent map that denote nothing (unknown or no match)."""
    return tuple(t for t, g in rmap.groundings.items() if g.required and g.outcome in _UNRESOLVED)


def avoid_regions(rmap: ReferentMap, radius: float) -> tuple[AtomRegion, ...]:
    """Return the ``near[x]`` regions of the avoided (not required) descriptors that denote instances."""
    out = []
    for text, g in sorted(rmap.groundings.items()):
        if not g.required and g.instances:
            key = f'near[{text}]'
            out.append(AtomRegion(key, tuple(i.center for i in g.instances),
                                  tuple(i.size for i in g.instances), radius))
    return tuple(out)


def _avoid_guard(regions: Sequence[AtomRegion], with_goal: bool) -> Guard:
    """``near[search_goal] & !near[a] & ...`` (or without the goal): a move's goal or allowed letters."""
    from ltl_instruct.core.spec import parse_descriptor
    neg = frozenset(near(parse_descriptor(r.key[5:-1])) for r in regions)
    pos = frozenset([_GOAL_ATOM]) if with_goal else frozenset()
    return Guard.of([Cube(pos, neg)])


def move_request(start: Sequence[float], goal: Sequence[float], avoid: Sequence[AtomRegion],
                 params: SearchParams, request_id: str = 'search') -> SegmentRequest:
    """Return the request of a move from ``start`` to ``GOAL_RADIUS`` from ``goal`` [m], outside ``avoid``.

    The regions to avoid are kept ``params.avoid_margin`` outside, where free space allows.
    """
    target = AtomRegion(_GOAL_ATOM.key, ((float(goal[0]), float(goal[1]), 0.0),), ((0.0, 0.0, 0.0),),
                        GOAL_RADIUS)
    return SegmentRequest(request_id, (float(start[0]), float(start[1])), 2, (target,) + tuple(avoid),
                          _avoid_guard(avoid, True), _avoid_guard(avoid, False), params.fmt,
                          avoid_margin=params.avoid_margin)


def plan_move(world: PlanningWorld, start: Sequence[float], goal: Sequence[float],
              avoid: Sequence[AtomRegion], params: SearchParams, request_id: str = 'search') -> SegmentResult:
    """Plan with FMT* from ``start`` to within ``GOAL_RADIUS`` of ``goal`` [m], staying out of ``avoid``."""
    return solve_segment(move_request(start, goal, avoid, params, request_id), world)


def avoid_mask(grid: PlaneGrid, regions: Sequence[AtomRegion], margin: float) -> np.ndarray:
    """Cells within a region to avoid, grown by ``margin`` [m]; bool (nx, ny)."""
    mask = np.zeros(grid.shape, dtype=bool)
    pts = grid.centers().reshape(-1, 2)
    for r in regions:
        d = r.distance(pts, 2).reshape(grid.shape)
        mask |= d <= r.radius + margin
    return mask


def frontier_goals(coverage: Coverage, free: np.ndarray, position: Sequence[float],
                   regions: Sequence[AtomRegion], looked: np.ndarray, failed: set[tuple[int, int]],
                   params: SearchParams) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Frontier goals [m] (K, 2) a robot at ``position`` can reach, their gains (K,) and grid travel [m] (K,).

    Parameters
    ----------
    coverage: what the camera saw, over the grid of ``free``.
    free: cells a robot may stand in, bool (nx, ny).
    regions: the regions to avoid (never walked through, with ``params.avoid_margin``).
    looked: positions (L, 2) [m] frontiers closer than ``params.revisit`` to are no goals.
    failed: cells (ix, iy) whose goals could not be planned to: never goals again.
    """
    grid = coverage.grid
    walkable = free & ~avoid_mask(grid, regions, params.avoid_margin)
    # a robot that stands in a margin (the planner keeps it where free space allows) walks out of it
    around = np.linalg.norm(grid.centers() - np.asarray(position, dtype=float)[:2], axis=2)
    walkable |= free & (around <= params.avoid_margin + 2 * grid.cell) & ~avoid_mask(grid, regions, 0.0)
    dist = travel_field(walkable, grid, position)
    cells = np.argwhere(frontier_cells(coverage.seen, coverage.blocks) & walkable & np.isfinite(dist))
    cells = _thin(cells, max(1, int(round(0.5 / grid.cell))))
    cells = np.array([c for c in cells.tolist() if tuple(c) not in failed], dtype=np.int64).reshape(-1, 2)
    if cells.size == 0:
        return np.zeros((0, 2)), np.zeros(0, dtype=np.int64), np.zeros(0)
    pts = grid.centers()[cells[:, 0], cells[:, 1]]
    looked = np.asarray(looked, dtype=float).reshape(-1, 2)
    if len(looked):
        fresh = np.min(np.linalg.norm(pts[:, None] - looked[None], axis=2), axis=1) > params.revisit
        pts, cells = pts[fresh], cells[fresh]
    gain = view_gain(pts, grid, coverage.seen, coverage.blocks, params.sensor_range)
    keep = gain >= params.min_gain
    return pts[keep], gain[keep], dist[cells[keep, 0], cells[keep, 1]]


def frontier_score(gain: np.ndarray, travel: np.ndarray, params: SearchParams) -> np.ndarray:
    """Score frontier goals by gain (K,) and travel [m] (K,): the higher the better."""
    if params.decay > 0:
        return gain * np.exp(-params.decay * travel)
    return gain / (travel + params.view_cost)


def choose_move(candidates: Callable[[], tuple[np.ndarray, np.ndarray, np.ndarray]],
                plan: Callable[[np.ndarray], SegmentResult], failed: set[tuple[int, int]], grid: PlaneGrid,
                params: SearchParams) -> Optional[SegmentResult]:
    """Plan to the next frontier goal; None when none is left (the map is complete).

    ``candidates()`` gives the goals, gains and grid travel (:func:`frontier_goals`, read
    again after failures); ``plan(goal)`` plans a move with FMT*. The ``shortlist`` best
    by grid travel are planned and the best by gain per metre of path is chosen; the
    cells of goals that cannot be planned to are added to ``failed``.
    """
    while True:
        pts, gain, dist = candidates()
        if len(pts) == 0:
            return None
        if params.strategy == 'nearest':
            order = np.argsort(dist, kind='stable')[:1]
        else:
            order = np.argsort(-frontier_score(gain, dist, params), kind='stable')[:params.shortlist]
        best, best_score = None, -math.inf
        for goal, g in zip(pts[order], gain[order]):
            result = plan(goal)
            if not result.ok:
                ix, iy = grid.index(goal[None])
                failed.add((int(ix[0]), int(iy[0])))
                continue
            score = float(frontier_score(np.array([g]), np.array([result.length]), params)[0])
            if score > best_score:
                best, best_score = result, score
        if best is not None:
            return best


class _Explorer:
    """The search's state: the map, the robot's pose, the path and views so far."""

    def __init__(self, scene: Scene, start: Pose, formula: Formula, params: SearchParams) -> None:
        self.scene, self.formula, self.params = scene, formula, params
        self.world: PlanningWorld = world_from_scene(scene)
        if self.world.dims != 2:
            raise InvalidInputError('search explores with a ground robot (a scene whose robot is ground)')
        self.camera = SyntheticCamera(scene, params.width, params.height, max_range=params.sensor_range)
        map_params = survey_params(scene)
        self.smap = SemanticMap(self.camera.classes, replace(
            map_params, voxel_size=min(map_params.voxel_size, params.cell), max_range=params.sensor_range))
        self.grid = PlaneGrid.over(scene.bounds_min, scene.bounds_max, params.cell)
        self.free = self.world.is_free(self.grid.centers().reshape(-1, 2)).reshape(self.grid.shape)
        self.pose = start
        self.path: list[tuple[float, float]] = [(start.position[0], start.position[1])]
        self.views: list[tuple[float, float, float]] = []
        self.failed: set[tuple[int, int]] = set()
        self.travel = 0.0
        self.moves = 0
        self.rmap = self.look()

    # ------------------------------------------------------------------ seeing
    def look(self) -> ReferentMap:
        """Take a panorama where the robot stands, fuse it, and re-ground the formula."""
        for h in range(self.params.headings):
            yaw = self.pose.yaw + 2.0 * math.pi * h / self.params.headings
            frame = self.camera.render(Pose(self.pose.position, yaw))
            self.smap.integrate(frame.depth, frame.labels, frame.intrinsics, frame.t_map_body)
            self.views.append((self.pose.position[0], self.pose.position[1], yaw))
        self.rmap = ground_formula(self.formula, self.smap.instances(), self.params.grounding)
        return self.rmap

    def seen(self) -> np.ndarray:
        """Cells seen so far, bool (nx, ny)."""
        return seen_cells(self.smap, self.grid)

    # ------------------------------------------------------------------ choosing
    def coverage(self) -> Coverage:
        """Return what the camera saw so far, over the plane grid."""
        blocks = sight_blocking_cells(self.smap, self.grid, self.camera.mount.height)
        return Coverage(self.grid, self.seen(), blocks)

    def candidates(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Frontier goals [m] (K, 2) the robot can reach, their gains (K,) and grid travel [m] (K,)."""
        regions = avoid_regions(self.rmap, self.params.near_threshold)
        return frontier_goals(self.coverage(), self.free, self.pose.position, regions,
                              np.asarray(self.views)[:, :2], self.failed, self.params)

    def choose(self) -> Optional[SegmentResult]:
        """Plan to the next frontier goal; None when none is left (the map is complete)."""
        return choose_move(self.candidates, self.plan, self.failed, self.grid, self.params)

    def plan(self, goal: np.ndarray) -> SegmentResult:
        """FMT* from the robot to ``goal`` [m], never near an avoided region."""
        avoid = avoid_regions(self.rmap, self.params.near_threshold)
        return plan_move(self.world, self.pose.position, goal, avoid, self.params, f'search/{self.moves}')

    # ------------------------------------------------------------------ moving
    def drive(self, result: SegmentResult) -> None:
        """Follow a planned path, looking around every ``view_spacing`` m and at its end.

        Stops early when every referent resolved, or when a view reveals an avoided
        region the rest of the path would enter (the next move is planned around it).
        """
        pts = np.asarray(result.points)[:, :2]
        self.moves += 1
        since = 0.0
        for k in range(1, len(pts)):
            step = float(np.linalg.norm(pts[k] - pts[k - 1]))
            self.travel += step
            since += step
            self.path.append((float(pts[k, 0]), float(pts[k, 1])))
            last = k == len(pts) - 1
            if since < self.params.view_spacing and not last:
                continue
            since = 0.0
            heading = math.atan2(*(pts[k] - pts[k - 1])[::-1]) if step > 0 else self.pose.yaw
            self.pose = Pose((float(pts[k, 0]), float(pts[k, 1]), 0.0), heading)
            self.look()
            if not unresolved(self.rmap) or (not last and self._enters_avoided(pts[k:])):
                return

    def _enters_avoided(self, rest: np.ndarray) -> bool:
        regions = avoid_regions(self.rmap, self.params.near_threshold)
        return any(bool(np.any(r.distance(rest, 2) <= r.radius)) for r in regions)


def _thin(cells: np.ndarray, block: int) -> np.ndarray:
    """One cell (N, 2) per ``block`` x ``block`` square of cells: the first in order."""
    if cells.size == 0:
        return cells.reshape(0, 2)
    _, first = np.unique(cells // block, axis=0, return_index=True)
    return cells[np.sort(first)]


def search_referents(scene: Scene, formula: Union[Formula, str], start: Optional[Pose] = None,
                     params: SearchParams = SearchParams()) -> SearchResult:
    """Explore ``scene`` from ``start`` (default: the scene's) until the formula's referents resolve.

    Parameters
    ----------
    scene: the world the simulated camera renders; its obstacles are the planner's.
    formula: the task; its required descriptors are sought, its avoided ones avoided.
    start: the robot's pose (position [m], yaw [rad]).
    params: strategy, camera and planner settings.

    Raises
    ------
    InvalidInputError
        On a drone scene or bad settings.
    """
    f = parse_formula(formula) if isinstance(formula, str) else formula
    if start is None:
        start = Pose(tuple(float(v) for v in scene.robot.start), 0.0)  # type: ignore[arg-type]
    ex = _Explorer(scene, start, f, params)
    sought = unresolved(ex.rmap)
    reason = 'resolved'
    while unresolved(ex.rmap):
        if ex.moves >= params.max_moves:
            reason = 'max_moves'
            break
        move = ex.choose()
        if move is None:
            reason = 'complete'
            break
        ex.drive(move)
    seen = ex.seen()
    area = float(seen.sum()) * params.cell ** 2
    rmap = ex.rmap if reason != 'complete' else after_complete_search(ex.rmap, area, f'{len(ex.views)} views')
    return SearchResult(rmap, sought, tuple(ex.views), np.asarray(ex.path), path_length(np.asarray(ex.path)),
                        area, reason == 'complete', reason, ex.moves, seen, ex.grid, ex.smap)


def after_complete_search(rmap: ReferentMap, area: float, looks: str) -> ReferentMap:
    """Make required descriptors still unresolved ``NO_MATCH``: the whole reachable map was searched.

    ``area`` [m^2] is the area seen, ``looks`` how (``12 views``), for the explanation.
    """
    out = dict(rmap.groundings)
    for text in unresolved(rmap):
        g = rmap.groundings[text]
        why = (f'searched the whole reachable map ({area:.1f} m^2 seen in {looks}, no frontier left): '
               f'nothing there is "{text}"',) + g.explanation
        out[text] = Grounding(g.descriptor, Outcome.NO_MATCH, g.instances, why, g.required)
    return ReferentMap(out)

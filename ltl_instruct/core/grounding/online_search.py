"""Search driven from outside, one move at a time: the node graph's search (issue 18).

:func:`search.search_referents` runs a whole search with a simulated camera. In the
node graph the robot, its camera and the semantic map are elsewhere: the grounder
publishes what the camera has covered (:class:`coverage.Coverage`) and the task's
referent map, the robot drives on its own. :class:`OnlineSearch` keeps the rest of a
search's state (where moves ended, goals that could not be planned to, travel) and
makes each decision with the same functions as the offline search: the next frontier
goal (:func:`search.frontier_goals`, :func:`search.choose_move`: gain per metre, the
shortlist planned with FMT* by the caller's ``plan``, the task's avoided regions kept),
and, when no frontier is left, the ``NO_MATCH`` referent map with its explanation.

The camera looks one way (the robot's heading), not all round as the offline search's
panoramas do, so a frontier is no goal within ``revisit`` of where the robot stands
(it cannot look behind itself by standing still) or of where a move ended.
"""
from __future__ import annotations

import math
from typing import Callable, Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.comparators import GroundingParams
from ltl_instruct.core.grounding.coverage import Coverage, PlaneGrid
from ltl_instruct.core.grounding.resolve import Resolver
from ltl_instruct.core.grounding.rsm import Instance, ReferentMap
from ltl_instruct.core.grounding.search import (
    SearchParams, after_complete_search, avoid_regions, choose_move, frontier_goals, move_request, unresolved,
)
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.segment import SegmentRequest, SegmentResult
from ltl_instruct.core.spec import parse_descriptor

MAX_GRID_CELLS = 4_000_000


def findable(descriptor: str, labels: Sequence[str], params: GroundingParams = GroundingParams()) -> bool:
    """Tell whether a camera that detects ``labels`` could ever resolve ``descriptor``.

    Every name in the descriptor (its head and those of its relations' arguments) must
    name one of the labels, as the grounding would match it (synonyms included). A
    segmenter with a closed set of classes cannot find a ``unicorn``: searching for it
    would be a waste of a whole exploration.
    """
    d = parse_descriptor(descriptor)
    known = [Instance(f'class_{k}', str(label), (0.0, 0.0, 0.0), (0.1, 0.1, 0.1))
             for k, label in enumerate(labels)]
    if not known:
        return False
    resolver = Resolver(known, params)
    return all(len(resolver.named(name)) > 0 for name in d.names())


class OnlineSearch:
    """One search in the node graph: choose moves from the coverage and referent map it is given.

    Parameters
    ----------
    world: the planning world (obstacles and bounds); a ground robot's (2D).
    params: strategy and gain settings (``cell`` is the coverage grid's, ``sensor_range``
        the reach of the gain estimate).
    start: where the robot stands [m] (x, y, ...).
    """

    def __init__(self, world: PlanningWorld, params: SearchParams, start: Sequence[float]) -> None:
        if world.dims != 2:
            raise InvalidInputError('search explores with a ground robot (2D planning)')
        self.world, self.params = world, params
        self.grid = PlaneGrid.over(world.bounds_min, world.bounds_max, params.cell)
        if self.grid.shape[0] * self.grid.shape[1] > MAX_GRID_CELLS:
            raise InvalidInputError(f'the map is too large to search at {params.cell} m cells')
        self.free = world.is_free(self.grid.centers().reshape(-1, 2)).reshape(self.grid.shape)
        self.path: list[tuple[float, float]] = [(float(start[0]), float(start[1]))]
        self.ends: list[tuple[float, float]] = []
        self.failed: set[tuple[int, int]] = set()
        self.moves = 0
        self.travel = 0.0

    def next_move(self, coverage: Coverage, rmap: ReferentMap, position: Sequence[float],
                  plan: Callable[[SegmentRequest], SegmentResult]) -> Optional[SegmentResult]:
        """Plan the next move; None when no reachable frontier is left (the map is complete).

        ``plan`` solves a segment request (FMT*, in the graph: the ``fmt_planner`` node).
        """
        cov = coverage.on(self.grid)
        here = (float(position[0]), float(position[1]))
        regions = avoid_regions(rmap, self.params.near_threshold)
        looked = np.asarray(self.ends + [here], dtype=float)

        def candidates() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            return frontier_goals(cov, self.free, here, regions, looked, self.failed, self.params)

        def plan_to(goal: np.ndarray) -> SegmentResult:
            return plan(move_request(here, goal, regions, self.params, f'search/{self.moves}'))

        return choose_move(candidates, plan_to, self.failed, self.grid, self.params)

    def moved(self, goal: Sequence[float], driven: np.ndarray) -> None:
        """Record a move that ended: its goal [m] and the positions driven (N, >=2) [m]."""
        self.moves += 1
        self.ends.append((float(goal[0]), float(goal[1])))
        pts = np.asarray(driven, dtype=float)
        for p in (pts if pts.ndim == 2 and pts.shape[1] >= 2 else ()):
            last = self.path[-1]
            step = math.hypot(p[0] - last[0], p[1] - last[1])
            if step > 1e-3:
                self.travel += step
                self.path.append((float(p[0]), float(p[1])))

    def report(self, coverage: Coverage, rmap: ReferentMap) -> dict:
        """JSON-ready state for a ``searching`` status: what is sought, the area seen, moves, travel."""
        return {'sought': list(unresolved(rmap)), 'area_seen_m2': round(self.area_seen(coverage), 2),
                'moves': self.moves, 'travel_m': round(self.travel, 2)}

    def complete(self, coverage: Coverage, rmap: ReferentMap) -> ReferentMap:
        """Return the referent map of a search that found no frontier left: the unresolved ``NO_MATCH``."""
        return after_complete_search(rmap, self.area_seen(coverage), f'{self.moves} moves')

    def area_seen(self, coverage: Coverage) -> float:
        """Floor area seen inside the world's bounds [m^2]."""
        return coverage.on(self.grid).area_seen

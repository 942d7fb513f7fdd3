"""The node graph's search for a referent the camera has not seen yet (``task_progression``'s part).

When an instruction's referent map leaves a required descriptor ``UNKNOWN_REFERENT`` or
``NO_MATCH`` and the grounder says the camera could find it (``searchable``),
``task_progression`` explores before it plans: each move goes to a frontier of what the
camera has covered (``search/coverage`` from the grounder), chosen and planned by
:class:`~ltl_instruct.core.grounding.online_search.OnlineSearch` through the same
``fmt_planner`` as the task's segments, with the task's avoided regions as regions to
avoid. The move is published on ``plan``, and the robot drives it while the grounder
integrates frames. The search ends when a new revision of the referent map resolves
(the task is then planned as usual, from where the robot is), when no frontier is left
(the instruction fails ``NO_MATCH``, explained), or after ``search_max_moves`` moves or
``search_timeout`` seconds (it fails with the grounding's error, saying so). Each move
is announced with a non-terminal ``searching`` status: what is sought, the area seen,
the moves and the travel so far, and the move's goal.

This module is a mixin of :class:`~ltl_instruct.nodes.task_progression.TaskProgressionNode`:
it uses the node's lock, pose, publishers and ``_remote_solve``.
"""
from __future__ import annotations

import threading
import time
from typing import Any, Optional

import numpy as np
from nav_msgs.msg import OccupancyGrid

from ltl_instruct import conversions as conv
from ltl_instruct.core.errors import ErrorCode, LtlInstructError
from ltl_instruct.core.grounding.coverage import Coverage
from ltl_instruct.core.grounding.online_search import OnlineSearch
from ltl_instruct.core.grounding.resolve import grounding_error
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.grounding.search import GOAL_RADIUS, SearchParams, avoid_regions
from ltl_instruct.nodes.common import ParamSpec, latched_qos

SEARCH_PARAMS = (
    ParamSpec('search', True, 'explore for a required referent the camera could find but has not seen yet '
              '(UNKNOWN_REFERENT or NO_MATCH) before planning'),
    ParamSpec('search_max_moves', 40, 'moves a search makes before it gives up', 0, 1000),
    ParamSpec('search_timeout', 600.0, 'wall-clock budget of one search [s]', 1.0, 36000.0),
    ParamSpec('search_shortlist', 1, 'frontiers planned per move (each a plan_request to fmt_planner); the '
              'best by travel along the planned path is taken', 1, 20),
    ParamSpec('search_sensor_range', 6.0, 'reach of the camera in the gain estimate of a frontier [m]',
              0.5, 100.0),
)
_UNRESOLVED = (ErrorCode.UNKNOWN_REFERENT, ErrorCode.NO_MATCH)
_POLL = 0.1          # [s] between looks at the pose while a move is driven
_STALL = 10.0        # [s] a move whose robot made no progress this long has ended
_LOOK = 3.0          # [s] at most spent waiting for frames taken at a move's end
_COVERAGE_WAIT = 5.0  # [s] at most waited for a first coverage


class SearchMixin:
    """Search before planning (see the module docstring)."""

    params: dict[str, Any]
    _lock: threading.RLock
    _pending: dict[str, Any]

    def _subscribe_search(self) -> None:
        """Subscribe to the camera's coverage (call once, from ``__init__``)."""
        self._coverage: Optional[Coverage] = None
        self._coverage_count = 0
        self._coverage_come = threading.Condition(self._lock)
        subscribe = self.create_subscription  # type: ignore[attr-defined]
        subscribe(OccupancyGrid, 'search/coverage', self.on_coverage, latched_qos(1))

    def on_coverage(self, msg: OccupancyGrid) -> None:
        """Keep what the camera has covered (the grounder sends it while a referent is unresolved)."""
        try:
            cov = conv.coverage_from_msg(msg)
        except LtlInstructError as e:
            self.get_logger().warning(f'search/coverage rejected: {e.message}')  # type: ignore[attr-defined]
            return
        with self._coverage_come:
            self._coverage = cov
            self._coverage_count += 1
            self._coverage_come.notify_all()

    # ------------------------------------------------------------------ the search
    def _search(self, iid: str, rdata: dict[str, Any], error: LtlInstructError) -> Optional[dict[str, Any]]:
        """Explore until the referent map resolves; return it (None when the instruction was dropped).

        Raises ``error`` at once when no search is possible, the explained ``NO_MATCH`` when
        the map is complete, and ``error`` with the reason when the search gives up.
        """
        if not self._may_search(rdata, error):
            raise error
        world = self._world_or_error()  # type: ignore[attr-defined]
        p = self.params
        params = SearchParams(max_moves=p['search_max_moves'], shortlist=p['search_shortlist'],
                              sensor_range=p['search_sensor_range'])
        search = OnlineSearch(world, params, self._current_pose())  # type: ignore[attr-defined]
        deadline = time.monotonic() + self.params['search_timeout']
        with self._lock:
            self._supersede(iid)   # type: ignore[attr-defined]  # the robot is taken over
        ended = False
        try:
            while True:
                rdata = self._latest_rmap(iid, rdata)
                if rdata.get('ok', False):
                    ended = True
                    return rdata
                if self._dropped(iid) or self._closing.is_set():  # type: ignore[attr-defined]
                    return None
                self._search_step(iid, search, rdata, error, deadline)
        finally:
            if not ended:
                self._stop_robot()

    def _may_search(self, rdata: dict[str, Any], error: LtlInstructError) -> bool:
        return bool(self.params['search'] and error.code in _UNRESOLVED and rdata.get('searchable')
                    and self.params['robot_kind'] == 'ground' and isinstance(rdata.get('referent_map'), dict))

    def _search_step(self, iid: str, search: OnlineSearch, rdata: dict[str, Any], error: LtlInstructError,
                     deadline: float) -> None:
        """Choose, announce and drive one move (raises when the search ends without the referent)."""
        cov = self._wait_coverage()
        if cov is None:
            raise LtlInstructError(f'{error.message} (no coverage came from the camera to search with)',
                                   error.code, details=error.details)
        rmap = ReferentMap.from_dict(rdata['referent_map'])
        if search.moves >= self.params['search_max_moves'] or time.monotonic() > deadline:
            raise LtlInstructError(f'{error.message} (the search gave up after {search.moves} moves, '
                                   f'{search.area_seen(cov):.1f} m^2 seen)', error.code,
                                   details=error.details)
        solve = self._remote_solve  # type: ignore[attr-defined]
        move = search.next_move(cov, rmap, self._current_pose(),  # type: ignore[attr-defined]
                                lambda request: solve(iid, request, 2))
        if move is None:
            raise grounding_error(search.complete(cov, rmap)) or error
        goal = np.asarray(move.points)[-1, :2]
        self.publish_status(iid, 'searching', False,  # type: ignore[attr-defined]
                            goal=[round(float(v), 3) for v in goal], **search.report(cov, rmap))
        search.moved(goal, self._drive(iid, np.asarray(move.points), deadline))

    def _latest_rmap(self, iid: str, rdata: dict[str, Any]) -> dict[str, Any]:
        with self._lock:
            p = self._pending.get(iid)
            newer = p.rmap if p is not None and p.rmap is not None else rdata
        return newer if conv.revision_of(newer) >= conv.revision_of(rdata) else rdata

    def _wait_coverage(self) -> Optional[Coverage]:
        with self._coverage_come:
            self._coverage_come.wait_for(lambda: self._coverage is not None, timeout=_COVERAGE_WAIT)
            return self._coverage

    def _drive(self, iid: str, points: np.ndarray, deadline: float) -> np.ndarray:
        """Publish a move and follow the robot until it ends; return the positions passed (N, 3) [m].

        A move ends at its goal (then frames taken there are waited for), when the referent
        map resolves, when the robot makes no progress, when a new referent map puts an
        avoided region on the rest of it, or when the instruction is dropped.
        """
        self.plan_pub.publish(conv.path_msg(points, conv.stamp_from_key(next(self._stamps)),  # type: ignore
                                            self.frames.map))  # type: ignore[attr-defined]
        driven = [self._current_pose()]  # type: ignore[attr-defined]
        revision, progress_at = -1, time.monotonic()
        while not self._closing.is_set() and time.monotonic() < deadline:  # type: ignore[attr-defined]
            time.sleep(_POLL)
            here = self._current_pose()  # type: ignore[attr-defined]
            if np.linalg.norm(here[:2] - driven[-1][:2]) > 0.05:
                driven.append(here)
                progress_at = time.monotonic()
            rdata = self._latest_rmap(iid, {})
            if rdata.get('ok', False) or self._dropped(iid):  # type: ignore[attr-defined]
                break
            if np.linalg.norm(here[:2] - points[-1, :2]) <= GOAL_RADIUS + 0.1:
                self._wait_frames()
                break
            if time.monotonic() - progress_at > _STALL:
                break
            if conv.revision_of(rdata) != revision:
                revision = conv.revision_of(rdata)
                if self._enters_avoided(rdata, points, here):
                    break
        return np.asarray(driven)

    def _enters_avoided(self, rdata: dict[str, Any], points: np.ndarray, here: np.ndarray) -> bool:
        """Whether the rest of a move (from the point nearest ``here``) enters a region the task avoids."""
        if not isinstance(rdata.get('referent_map'), dict):
            return False
        regions = avoid_regions(ReferentMap.from_dict(rdata['referent_map']), self.params['near_threshold'])
        rest = points[int(np.argmin(np.linalg.norm(points[:, :2] - here[:2], axis=1))):, :2]
        return any(bool(np.any(r.distance(rest, 2) <= r.radius)) for r in regions)

    def _wait_frames(self) -> None:
        """Wait until two more coverages came (frames taken where the robot now stands), or ``_LOOK`` s."""
        with self._coverage_come:
            target = self._coverage_count + 2
            self._coverage_come.wait_for(lambda: self._coverage_count >= target, timeout=_LOOK)

    def _stop_robot(self) -> None:
        """Publish an empty plan: the robot stands still (a search that ended without a task plan)."""
        self.plan_pub.publish(conv.path_msg(np.zeros((0, 3)),  # type: ignore[attr-defined]
                                            conv.stamp_from_key(next(self._stamps)),  # type: ignore
                                            self.frames.map))  # type: ignore[attr-defined]

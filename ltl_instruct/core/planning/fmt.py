"""The one module that talks to OMPL: FMT* (and RRT* for comparison) in R^2 or R^3.

OMPL's camelCase stays in here. The caller gives plain Python callables: whether a
point is valid, whether a straight motion is valid, whether a point is in the goal and
a lower bound of its distance to the goal, and a pool of goal samples (the goal is a
sampleable region, not a point). Never BFMT (it crashes in the Python bindings).

Reproducibility: OMPL's global RNG is reseeded before every plan, so a fixed
``seed`` gives the same path in any process, whatever was planned before.
"""
from __future__ import annotations

import gc
import math
import time
from dataclasses import asdict, dataclass, fields
from typing import Any, Callable, Mapping, Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import InvalidInputError

PLANNERS = ('fmt', 'rrtstar', 'default')


@dataclass(frozen=True)
class FmtSettings:
    """Motion-planner settings.

    Attributes
    ----------
    num_samples: FMT* samples per segment.
    radius_multiplier: FMT* neighbourhood radius multiplier (> 0).
    heuristics: FMT* expands towards the goal first (cost-to-go heuristic).
    use_k_nearest: FMT* connects k nearest neighbours instead of a radius.
    cache_cc: FMT* caches collision checks.
    extended_fmt: FMT* adds samples when it fails (then it runs to the time limit).
    time_limit: wall-clock limit per segment [s].
    seed: seed of OMPL's sampler and of the goal sampler.
    check_resolution: smallest step [m] of an edge check near a region boundary (obstacles
        are checked exactly): no avoid region thicker than this can be jumped.
    path_spacing: spacing [m] of the returned dense path (0: only the waypoints).
    simplify: shortcut the path (never leaving the allowed space).
    planner: ``fmt``, ``rrtstar`` (RRT* runs for the whole time limit) or ``default``
        (what OMPL's ``SimpleSetup`` chooses: RRTConnect, the benchmarks' peer).
    goal_samples: goal states drawn for the sampleable goal region.
    direct: first try the straight way from the start to each of the nearest goal samples
        (``segment.DIRECT_TRIES``); FMT* runs only when none is valid. FMT* only (the other
        planners are the benchmarks' peers, timed as OMPL runs them).
    grid_cell: cell [m] of a grid path that a 2D segment whose FMT* path makes a detour is also
        given (Dijkstra over the cells whose centres are valid, then the same shortcutting); the
        shorter path wins. It finds a passage a few cells wide that the samples miss. 0: FMT*
        alone.
    """

    num_samples: int = 5000
    radius_multiplier: float = 1.1
    heuristics: bool = True
    use_k_nearest: bool = True
    cache_cc: bool = True
    extended_fmt: bool = False
    time_limit: float = 5.0
    seed: int = 0
    check_resolution: float = 0.01
    path_spacing: float = 0.05
    simplify: bool = True
    planner: str = 'fmt'
    goal_samples: int = 64
    direct: bool = True
    grid_cell: float = 0.05

    def __post_init__(self) -> None:
        checks = [
            (isinstance(self.num_samples, int) and 10 <= self.num_samples <= 1_000_000, 'num_samples'),
            (_pos(self.radius_multiplier) and self.radius_multiplier <= 100, 'radius_multiplier'),
            (_pos(self.time_limit) and self.time_limit <= 3600, 'time_limit'),
            (isinstance(self.seed, int) and 0 <= self.seed < 2 ** 31, 'seed'),
            (_pos(self.check_resolution), 'check_resolution'),
            (isinstance(self.path_spacing, (int, float)) and math.isfinite(self.path_spacing)
             and self.path_spacing >= 0, 'path_spacing'),
            (self.planner in PLANNERS, 'planner'),
            (isinstance(self.goal_samples, int) and 1 <= self.goal_samples <= 100_000, 'goal_samples'),
            (self.grid_cell == 0 or _pos(self.grid_cell) and 0.01 <= self.grid_cell <= 10, 'grid_cell'),
        ]
        for ok, name in checks:
            if not ok:
                raise InvalidInputError(f'bad planner setting {name}={getattr(self, name)!r}',
                                        details={'setting': name})

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return asdict(self)

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'FmtSettings':
        """Inverse of :meth:`to_dict` (unknown keys are an error)."""
        names = {f.name for f in fields(FmtSettings)}
        unknown = set(d) - names
        if unknown:
            raise InvalidInputError(f'unknown planner settings: {", ".join(sorted(unknown))}')
        try:
            return FmtSettings(**dict(d))
        except TypeError as e:
            raise InvalidInputError(f'bad planner settings: {e}') from e


def _pos(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) and x > 0


@dataclass(frozen=True)
class GoalSpec:
    """A sampleable goal region for the motion planner.

    Attributes
    ----------
    contains: whether a point (tuple of dims floats) is in the goal.
    lower_bound: a lower bound of a point's distance [m] to the goal (0 allowed).
    samples: valid goal points [m], shape (M, dims), M >= 1.
    """

    contains: Callable[[Sequence[float]], bool]
    lower_bound: Callable[[Sequence[float]], float]
    samples: np.ndarray


@dataclass(frozen=True)
class MotionOutcome:
    """What the motion planner returned: ``points`` (N, dims) [m] or None, and OMPL's status."""

    points: Optional[np.ndarray]
    status: str
    seconds: float
    timed_out: bool


def plan_motion(dims: int, bounds_min: Sequence[float], bounds_max: Sequence[float],
                start: Sequence[float], state_valid: Callable[[Sequence[float]], bool],
                motion_valid: Callable[[Sequence[float], Sequence[float]], bool],
                goal: GoalSpec, settings: FmtSettings) -> MotionOutcome:
    """Plan with FMT* (or RRT*) from ``start`` into the goal region; None when it fails."""
    import ompl.base as ob
    import ompl.geometric as og
    import ompl.util as ou

    ou.setLogLevel(ou.LOG_NONE)  # reseeding prints a warning; failures are reported by us
    ou.RNG.setSeed(int(settings.seed) + 1)
    space = ob.RealVectorStateSpace(dims)
    bounds = ob.RealVectorBounds(dims)
    for k in range(dims):
        bounds.setLow(k, float(bounds_min[k]))
        bounds.setHigh(k, float(bounds_max[k]))
    space.setBounds(bounds)
    si = ob.SpaceInformation(space)
    if dims == 2:   # the callback runs for every sample: no generator
        si.setStateValidityChecker(lambda s: bool(state_valid((s[0], s[1]))))
    else:
        si.setStateValidityChecker(lambda s: bool(state_valid((s[0], s[1], s[2]))))

    motion_cls, goal_cls = _ompl_classes()
    motion = motion_cls(si, motion_valid, dims)
    si.setMotionValidator(motion)
    si.setup()
    goal_region = goal_cls(si, goal, np.asarray(goal.samples, dtype=float), dims)
    goal_region.setThreshold(1e-9)  # OMPL needs a positive threshold: distance 0 is "in"
    pdef = ob.ProblemDefinition(si)
    s0 = space.allocState()
    for k in range(dims):
        s0[k] = float(start[k])
    pdef.addStartState(s0)
    pdef.setGoal(goal_region)
    if settings.planner == 'default':
        pdef.clearGoal()
        return _plan_default(si, s0, goal_region, settings)
    pdef.setOptimizationObjective(ob.PathLengthOptimizationObjective(si))
    if settings.planner == 'fmt':
        planner = og.FMT(si)
        planner.setNumSamples(int(settings.num_samples))
        planner.setRadiusMultiplier(float(settings.radius_multiplier))
        planner.setHeuristics(bool(settings.heuristics))
        planner.setNearestK(bool(settings.use_k_nearest))
        planner.setCacheCC(bool(settings.cache_cc))
        planner.setExtendedFMT(bool(settings.extended_fmt))
    else:
        planner = og.RRTstar(si)
    planner.setProblemDefinition(pdef)
    planner.setup()
    t0 = time.monotonic()
    status = planner.solve(float(settings.time_limit))
    seconds = time.monotonic() - t0
    status_text = str(status)
    points: Optional[np.ndarray] = None
    if pdef.hasExactSolution():
        path = pdef.getSolutionPath()
        points = np.array([[path.getState(i)[k] for k in range(dims)] for i in range(path.getStateCount())])
    timed_out = seconds >= float(settings.time_limit) * 0.98 and points is None
    # break the Python <-> C++ reference cycles so nothing outlives the call
    planner.clear()
    pdef.clearGoal()
    del planner, pdef, goal_region, motion, si, space, s0
    gc.collect(1)   # the young generations only: a full pass cost 30 ms with a large automaton alive
    return MotionOutcome(points, status_text, seconds, timed_out)


_CLASSES: list[type] = []


def _ompl_classes() -> tuple[type, type]:
    """Return OMPL's motion validator and sampleable goal region, subclassed once per process.

    Classes made inside ``plan_motion`` were garbage in reference cycles after every segment,
    which only a full collection frees (30 ms a segment in a process holding a large automaton).
    """
    if _CLASSES:
        return _CLASSES[0], _CLASSES[1]
    import ompl.base as ob

    class _Motion(ob.MotionValidator):
        def __init__(self, si: Any, motion_valid: Callable[[Sequence[float], Sequence[float]], bool],
                     dims: int) -> None:
            super().__init__(si)
            self._valid, self._dims = motion_valid, dims

        def checkMotion(self, s1: Any, s2: Any, *rest: Any) -> bool:  # noqa: N802 - OMPL's name
            d = self._dims
            return bool(self._valid(tuple(s1[k] for k in range(d)), tuple(s2[k] for k in range(d))))

    class _Goal(ob.GoalSampleableRegion):
        def __init__(self, si: Any, goal: GoalSpec, samples: np.ndarray, dims: int) -> None:
            super().__init__(si)
            self._goal, self._samples, self._dims, self._next = goal, samples, dims, 0

        def distanceGoal(self, s: Any) -> float:  # noqa: N802
            p = tuple(s[k] for k in range(self._dims))
            if self._goal.contains(p):
                return 0.0
            return max(float(self._goal.lower_bound(p)), 1e-6)

        def sampleGoal(self, s: Any) -> None:  # noqa: N802
            row = self._samples[self._next % len(self._samples)]
            self._next += 1
            for k in range(self._dims):
                s[k] = float(row[k])

        def maxSampleCount(self) -> int:  # noqa: N802
            return int(len(self._samples))

    _CLASSES.extend((_Motion, _Goal))
    return _Motion, _Goal


def _plan_default(si: Any, s0: Any, goal_region: Any, settings: FmtSettings) -> MotionOutcome:
    """Plan with OMPL's default planner for the problem (``SimpleSetup`` chooses; no objective)."""
    import ompl.geometric as og
    dims = si.getStateDimension()
    ss = og.SimpleSetup(si)
    ss.setStartState(s0)
    ss.setGoal(goal_region)
    t0 = time.monotonic()
    status = ss.solve(float(settings.time_limit))
    seconds = time.monotonic() - t0
    points: Optional[np.ndarray] = None
    if ss.haveExactSolutionPath():
        path = ss.getSolutionPath()
        points = np.array([[path.getState(i)[k] for k in range(dims)] for i in range(path.getStateCount())])
    status_text = f'{ss.getPlanner().getName()}: {status}'
    timed_out = seconds >= float(settings.time_limit) * 0.98 and points is None
    ss.clear()
    ss.getProblemDefinition().clearGoal()
    del ss
    gc.collect(1)
    return MotionOutcome(points, status_text, seconds, timed_out)

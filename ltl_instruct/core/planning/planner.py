"""The progressive task planner: automaton transitions, one FMT* segment each, skills between.

From the automaton state reached at the robot's start, the planner picks a transition
towards acceptance (fewest remaining transitions first, then the nearest goal region),
builds its task progression map (goal = the edge's guard, allowed = the state's
self-loop, both restricted to letters without events) and asks a segment solver for a
path from where the last segment ended. Skills (``pick``, ``release``) are inserted
where an edge needs one: the robot first drives, staying in its state, to where the
skill can happen (near the object to pick, near the destination to release), then the
skill's letter takes the transition. When a segment fails, or everything after it
does, the search backtracks: to the goal region's other parts (cubes), to each
instance of the referent, then to other transitions. Several instances of a referent
form one goal region, so FMT* reaches the cheapest first.

The solver is pluggable (:data:`~ltl_instruct.core.planning.segment.SolveFn`): in
process it is FMT*; a ROS node plugs in one that sends the request over DDS. The
result of every segment is re-run through the automaton before it is used, and the
whole plan is checked by :func:`~ltl_instruct.core.planning.verify.verify_plan`
before it is returned.

Every segment asks for the margins of the settings: each goal region entered
``goal_margin`` deep (the path goes on past the edge, in the state the edge led to),
each region to avoid passed ``avoid_margin`` outside. A segment keeps less only where
the free space leaves no path that keeps them, and the plan's warnings say so. A start
inside an inflated obstacle (a robot touching a wall) is moved to the nearest free point
within ``start_shift``, with a warning.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any, Iterator, Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton import Automaton
from ltl_instruct.core.automaton.guards import Cube, Guard
from ltl_instruct.core.errors import (
    ErrorCode, InvalidInputError, LtlInstructError, PlanningError, UnsatisfiableError,
)
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.planning.fmt import FmtSettings
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.regions import (
    AtomRegion, RegionSet, atoms_needed, eval_key_cubes, key_cubes, navigation_guard, regions_for,
    skill_guard,
)
from ltl_instruct.core.planning.segment import SegmentRequest, SegmentResult, SolveFn, resample, solve_segment
from ltl_instruct.core.planning.junctions import shorten_junctions
from ltl_instruct.core.planning.taskplan import NAVIGATE, SKILL, PlanStep, TaskPlan, Verification
from ltl_instruct.core.planning.verify import verify_plan
from ltl_instruct.core.spec.ast import Atom
from ltl_instruct.core.world.near import (
    DEFAULT_AVOID_MARGIN, DEFAULT_GOAL_MARGIN, DEFAULT_NEAR_THRESHOLD, check_margin, check_threshold,
)


@dataclass(frozen=True)
class PlannerSettings:
    """Task-planner settings.

    Attributes
    ----------
    near_threshold: ``near[x]`` holds within this distance [m] of an instance's box
        (:data:`~ltl_instruct.core.world.near.DEFAULT_NEAR_THRESHOLD` by default).
    goal_margin: how deep [m] each goal region is entered (where the region allows).
    avoid_margin: how far [m] outside each region to avoid the path stays (where free
        space allows).
    start_shift: how far [m] a start inside an obstacle may be moved to free space
        (farther: ``START_OCCUPIED``).
    fmt: motion-planner settings for every segment.
    max_segments: segment solves before the search gives up (``TIMEOUT``).
    time_budget: wall-clock budget of the whole search [s] (``TIMEOUT``).
    max_alternatives: alternative goal regions / instances tried per transition after
        the first choice led nowhere.
    verify_spacing: sample spacing [m] of the independent check (at most 0.05).
    shorten_junctions: after the search, move where consecutive segments meet, inside
        each goal region, to shorten the whole task
        (:mod:`~ltl_instruct.core.planning.junctions`); the plan as searched is kept if
        the moved one fails the check.
    """

    near_threshold: float = DEFAULT_NEAR_THRESHOLD
    fmt: FmtSettings = field(default_factory=FmtSettings)
    max_segments: int = 60
    time_budget: float = 60.0
    max_alternatives: int = 4
    verify_spacing: float = 0.05
    goal_margin: float = DEFAULT_GOAL_MARGIN
    avoid_margin: float = DEFAULT_AVOID_MARGIN
    start_shift: float = 0.5
    shorten_junctions: bool = True

    def __post_init__(self) -> None:
        check_threshold(self.near_threshold)
        check_margin(self.goal_margin, 'goal_margin')
        check_margin(self.avoid_margin, 'avoid_margin')
        check_margin(self.start_shift, 'start_shift')
        if not (isinstance(self.max_segments, int) and self.max_segments >= 1):
            raise InvalidInputError('max_segments must be a positive integer')
        if not (isinstance(self.time_budget, (int, float)) and self.time_budget > 0):
            raise InvalidInputError('time_budget must be positive')
        if not (0 < self.verify_spacing <= 0.05):
            raise InvalidInputError('verify_spacing must be in (0, 0.05] m')


@dataclass
class _Attempt:
    goal: Guard
    target: Optional[tuple[str, int]]
    label: str


@dataclass
class _Candidate:
    """A transition to try: drive into ``goal`` (then do ``event`` if any)."""

    edge_dst: int
    event: Optional[Atom]
    goal: Guard              # over near-atoms, for the navigation
    rank: tuple


class _Search:
    def __init__(self, automaton: Automaton, referent_map: ReferentMap, world: PlanningWorld,
                 settings: PlannerSettings, solve: SolveFn, request_id: str) -> None:
        self.aut = automaton
        self.world = world
        self.settings = settings
        self.solve = solve
        self.request_id = request_id
        self.dims = world.dims
        extra: list[Atom] = []
        for a in automaton.atoms:
            if a.skill == 'pick':
                extra.append(Atom('near', (a.args[0],)))
            elif a.skill == 'release':
                extra.append(Atom('near', (a.args[1],)))
        self.all_regions = regions_for(list(automaton.atoms) + extra, referent_map, settings.near_threshold)
        self.region_of = {r.key: r for r in self.all_regions}
        self.regions = RegionSet(self.all_regions, self.dims)
        self.solves = 0
        self.failures: list[LtlInstructError] = []
        self.t0 = time.monotonic()
        self.out_of_budget = False
        self.nearest_at: tuple = ((), [])
        apart = _regions_apart(self.all_regions, self.dims)
        self.map_letters = automaton.letters_without((a, b) for a in automaton.atoms for b in automaton.atoms
                                                     if (a.key, b.key) in apart)

    # ------------------------------------------------------------------ helpers
    def letter_keys(self, p: np.ndarray) -> frozenset[str]:
        return self.regions.letter_and_margin(tuple(p))[0]

    def letter_atoms(self, keys: frozenset[str]) -> frozenset[Atom]:
        return frozenset(a for a in self.aut.atoms if a.key in keys)

    def goal_distance(self, p: np.ndarray, goal: Guard) -> float:
        if self.nearest_at[0] != tuple(p):
            self.nearest_at = (tuple(p), dict(zip((r.key for r in self.all_regions),
                                                  self.regions.nearest(tuple(p)))))
        nearest = self.nearest_at[1]
        best = math.inf
        for pos, _ in key_cubes(goal):
            need = 0.0
            for k in pos:
                need = max(need, nearest.get(k, math.inf) - self.settings.near_threshold)
            best = min(best, need)
        return max(best, 0.0)

    def request(self, start: np.ndarray, goal: Guard, allowed: Guard, transition: tuple[int, int],
                target: Optional[tuple[str, int]]) -> SegmentRequest:
        keys = {a.key for a in goal.atoms | allowed.atoms if not a.is_event}
        regions = tuple(self.region_of[k] if k in self.region_of else AtomRegion(k, (), (), 0.0)
                        for k in sorted(keys))
        rid = f'{self.request_id}/{self.solves}'
        hold = navigation_guard(self.aut.self_loop(transition[1]))   # where the path may go on into the goal
        s = self.settings
        return SegmentRequest(rid, tuple(float(x) for x in start[:self.dims]), self.dims, regions, goal,
                              allowed, s.fmt, target, None, None, transition, hold, s.goal_margin,
                              s.avoid_margin)

    def budget_left(self) -> bool:
        if self.solves >= self.settings.max_segments or \
                time.monotonic() - self.t0 > self.settings.time_budget:
            self.out_of_budget = True
        return not self.out_of_budget

    def run_states(self, state: int, waypoints: np.ndarray) -> list[int]:
        """Automaton states along a path from ``state`` (the first point is not read again)."""
        dense = resample(waypoints, self.settings.verify_spacing)[1:]
        states = [state]
        for p in dense:
            states.append(self.aut.step(states[-1], self.letter_atoms(self.letter_keys(p))))
        return states

    # ------------------------------------------------------------------ candidates
    def candidates(self, state: int, holding: Optional[str], pos: np.ndarray) -> list[_Candidate]:
        out = []
        allowed = navigation_guard(self.aut.self_loop(state))
        moves = [e for e in self.aut.edges_from(state) if e.dst != state]
        for e in [e for e in moves if e.meets(self.map_letters)] or moves:   # those the map's letters take
            if e.dst == self.aut.sink:
                continue
            dist = self.aut.distance_to_accepting(e.dst)
            if dist is None:
                continue
            nav = navigation_guard(e.guard)
            if not nav.is_false:
                out.append(_Candidate(e.dst, None, nav, (dist, self.goal_distance(pos, nav), 0)))
            events = {a for c in e.guard.cubes for a in c.pos if a.is_event}
            for ev in sorted(events, key=lambda a: a.key):
                if ev.skill == 'pick' and holding is not None:
                    continue
                if ev.skill == 'release' and holding != str(ev.args[0]):
                    continue
                g = skill_guard(e.guard, ev)
                if g.is_false:
                    continue
                site_atom = Atom('near', (ev.args[0] if ev.skill == 'pick' else ev.args[1],))
                site = allowed.meet(g).meet(Guard((Cube(frozenset({site_atom})),)))
                if site.is_false:
                    continue
                out.append(_Candidate(e.dst, ev, site, (dist, self.goal_distance(pos, site), 1)))
        out.sort(key=lambda c: c.rank)
        return out

    def attempts(self, goal: Guard) -> Iterator[_Attempt]:
        yield _Attempt(goal, None, 'any goal region')
        extra = 0
        if len(goal.cubes) > 1:
            for c in goal.cubes:
                if extra >= self.settings.max_alternatives:
                    return
                extra += 1
                yield _Attempt(Guard((c,)), None, f'goal region {c}')
        keys = sorted({a.key for c in goal.cubes for a in c.pos if a.key in self.region_of},
                      key=lambda k: -len(self.region_of[k].centers))
        if keys and len(self.region_of[keys[0]].centers) > 1:
            for i in range(len(self.region_of[keys[0]].centers)):
                if extra >= self.settings.max_alternatives:
                    return
                extra += 1
                yield _Attempt(goal, (keys[0], i), f'instance {i} of {keys[0]}')

    # ------------------------------------------------------------------ search
    def navigate(self, state: int, pos: np.ndarray, goal: Guard, dst: int,
                 target: Optional[tuple[str, int]]) -> Optional[PlanStep]:
        allowed = navigation_guard(self.aut.self_loop(state))
        if not self.budget_left():
            return None
        req = self.request(pos, goal, allowed, (state, dst), target)
        self.solves += 1
        t = time.monotonic()
        try:
            result: SegmentResult = self.solve(req)
        except LtlInstructError as e:
            self.failures.append(e)
            return None
        if not result.ok:
            assert result.error is not None
            self.failures.append(result.error)
            return None
        w = np.asarray(result.waypoints, dtype=float)[:, :self.dims]
        if np.linalg.norm(w[0] - pos) > 1e-6:
            self.failures.append(PlanningError(
                f'{req.describe()}: the returned path does not start at the robot', ErrorCode.NO_VALID_PATH))
            return None
        states = self.run_states(state, w)
        if not _one_transition(states, state, dst):
            self.failures.append(PlanningError(
                f'{req.describe()}: the returned path does not take the automaton to {dst} '
                f'(it went {state} -> {states[-1]})', ErrorCode.NO_VALID_PATH))
            return None
        return PlanStep(NAVIGATE, state, dst, w, '', str(goal), str(allowed), req,
                        float(np.linalg.norm(np.diff(w, axis=0), axis=1).sum()), time.monotonic() - t,
                        result.goal_margin, result.avoid_margin, result.warnings)

    def search(self, state: int, pos: np.ndarray, holding: Optional[str],
               visited: frozenset) -> Optional[list[PlanStep]]:
        if state in self.aut.accepting:
            return []
        for cand in self.candidates(state, holding, pos):
            first = True
            for attempt in self.attempts(cand.goal):
                if not self.budget_left():
                    return None
                steps = self.realise(state, pos, holding, cand, attempt)
                if steps is None:
                    if first:
                        break  # the whole goal failed: its parts will too
                    continue
                first = False
                after = steps[-1]
                new_holding = holding
                if cand.event is not None:
                    new_holding = str(cand.event.args[0]) if cand.event.skill == 'pick' else None
                key = (after.state_after, new_holding)
                if key in visited:
                    continue
                rest = self.search(after.state_after, after.end, new_holding, visited | {key})
                if rest is not None:
                    return steps + rest
        return None

    def realise(self, state: int, pos: np.ndarray, holding: Optional[str], cand: _Candidate,
                attempt: _Attempt) -> Optional[list[PlanStep]]:
        if cand.event is None:
            step = self.navigate(state, pos, attempt.goal, cand.edge_dst, attempt.target)
            return None if step is None else [step]
        steps: list[PlanStep] = []
        here = pos
        if not eval_key_cubes(key_cubes(attempt.goal), self.letter_keys(here)) or attempt.target is not None:
            step = self.navigate(state, here, attempt.goal, state, attempt.target)
            if step is None:
                return None
            steps.append(step)
            here = step.end
        letter = self.letter_atoms(self.letter_keys(here)) | {cand.event}
        after = self.aut.step(state, letter)
        if after != cand.edge_dst:
            self.failures.append(PlanningError(
                f'{cand.event.key} at ({", ".join(f"{x:.2f}" for x in here)}) leads to state {after}, '
                f'not {cand.edge_dst}', ErrorCode.NO_VALID_PATH))
            return None
        steps.append(PlanStep(SKILL, state, after, here[None].copy(), cand.event.key))
        return steps


def _one_transition(states: Sequence[int], state: int, dst: int) -> bool:
    """Whether a run stays in ``state``, then (at the goal's edge) moves to ``dst`` and stays there."""
    k = next((i for i, s in enumerate(states) if s != state), len(states))
    return states[-1] == dst and all(s == dst for s in states[k:])


def _regions_apart(regions: Sequence[AtomRegion], dims: int) -> set[tuple[str, str]]:
    """Pairs of region keys that hold at no common point: no two instance boxes lie within both radii."""
    out = set()
    for r in regions:
        for q in regions:
            if r.key < q.key and r.centers and q.centers and not any(
                    math.dist([0.0] * dims, [max(0.0, abs(c1[i] - c2[i]) - (s1[i] + s2[i]) / 2)
                                             for i in range(dims)]) <= r.radius + q.radius
                    for c1, s1 in zip(r.centers, r.sizes) for c2, s2 in zip(q.centers, q.sizes)):
                out |= {(r.key, q.key), (q.key, r.key)}
    return out


def _failure_error(search: _Search, formula: str) -> LtlInstructError:
    fails = search.failures
    details: dict[str, Any] = {'failures': [f.to_dict() for f in fails[:20]],
                               'segments_solved': search.solves}
    if search.out_of_budget:
        lead = fails[0].message if fails else 'no segment was solved'
        return PlanningError(f'gave up after {search.solves} segments / {search.settings.time_budget} s '
                             f'without a plan for "{formula}" (first failure: {lead})', ErrorCode.TIMEOUT,
                             details)
    if not fails:
        return PlanningError(f'no transition of "{formula}" can be attempted from here (a release needs '
                             'its object in hand, a pick needs a free hand)', ErrorCode.NO_VALID_PATH,
                             details)
    seen: list[str] = []
    empty = sorted(r.key for r in search.all_regions if not r.centers)
    if empty:
        seen.append(f'nothing in the referent map for {", ".join(empty)} (false everywhere)')
        details['empty_regions'] = empty
    for f in fails:
        if f.message not in seen:
            seen.append(f.message)
    codes = {f.code for f in fails}
    code = ErrorCode.GOAL_OCCUPIED if codes == {ErrorCode.GOAL_OCCUPIED} else (
        ErrorCode.START_OCCUPIED if codes == {ErrorCode.START_OCCUPIED} else fails[0].code)
    if code not in (ErrorCode.GOAL_OCCUPIED, ErrorCode.START_OCCUPIED, ErrorCode.TIMEOUT):
        code = ErrorCode.NO_VALID_PATH
    return PlanningError(f'no plan satisfies "{formula}": ' + '; '.join(seen[:3])
                         + (f' (and {len(seen) - 3} more)' if len(seen) > 3 else ''), code, details)


def plan_task(automaton: Automaton, referent_map: ReferentMap, world: PlanningWorld,
              start: Sequence[float], settings: Optional[PlannerSettings] = None,
              solve: Optional[SolveFn] = None, request_id: str = 'plan',
              initial_state: Optional[int] = None) -> TaskPlan:
    """Plan and verify a task.

    Parameters
    ----------
    automaton: the task's automaton.
    referent_map: instances of every descriptor (``near[x]`` regions).
    world: obstacles and bounds (2D or 3D).
    start: robot position [m], shape (>= dims,).
    settings: planner settings.
    solve: segment solver; default FMT* in process.
    request_id: prefix of every segment request's id.
    initial_state: plan from this automaton state instead of the initial one (replanning
        during execution); the letter at ``start`` is then not read again.

    Raises
    ------
    UnsatisfiableError
        (``UNSATISFIABLE``) if no trace satisfies the formula.
    PlanningError
        ``START_OCCUPIED`` (start in collision with no free point within
        ``settings.start_shift``, or already violating the task),
        ``GOAL_OCCUPIED`` (every goal region blocked), ``NO_VALID_PATH``, ``TIMEOUT``, or
        ``VERIFICATION_FAILED``; the message says which transition and why.
    InvalidInputError
        For a start that is not finite numbers.
    """
    settings = settings or PlannerSettings()
    dims = world.dims
    try:
        p0 = np.asarray([float(x) for x in start], dtype=float)
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f'start must be numbers, got {start!r}') from e
    if p0.shape[0] < dims or not np.all(np.isfinite(p0[:dims])):
        raise InvalidInputError(f'start must be {dims} finite numbers, got {list(start)}')
    p0 = p0[:dims]
    formula = str(automaton.formula)
    if not automaton.is_satisfiable:
        raise UnsatisfiableError(f'the task "{formula}" can never be completed: no sequence of steps '
                                 'satisfies it', details={'formula': formula})
    p0, warnings = _free_start(world, p0, settings.start_shift)
    fmt = settings.fmt
    solver: SolveFn = solve if solve is not None else (lambda req: solve_segment(req, world, fmt))
    search = _Search(automaton, referent_map, world, settings, solver, request_id)
    t0 = time.monotonic()
    if initial_state is None:
        state = automaton.step(automaton.initial, search.letter_atoms(search.letter_keys(p0)))
    else:
        state = int(initial_state)
    if state == automaton.sink or automaton.distance_to_accepting(state) is None:
        raise PlanningError(f'the start already violates "{formula}" (atoms true there: '
                            f'{", ".join(sorted(search.letter_keys(p0))) or "none"})',
                            ErrorCode.START_OCCUPIED,
                            details={'start': p0.tolist()})
    steps = search.search(state, p0, None, frozenset({(state, None)}))
    if steps is None:
        raise _failure_error(search, formula)
    verification = _verified(steps, p0, automaton, referent_map, world, settings, initial_state)
    if settings.shorten_junctions and verification.ok:
        shorter = shorten_junctions(steps, world, fmt.seed)
        if any(a is not b for a, b in zip(shorter, steps)):
            checked = _verified(shorter, p0, automaton, referent_map, world, settings, initial_state)
            if checked.ok:
                steps, verification = shorter, checked
    if not verification.ok:
        raise PlanningError(f'the plan for "{formula}" failed the independent check: {verification.reason}',
                            ErrorCode.VERIFICATION_FAILED, details={'verification': verification.to_dict()})
    stats = {'segments_solved': search.solves, 'segment_failures': len(search.failures),
             'seconds': round(time.monotonic() - t0, 4)}
    warnings += [w for s in steps for w in s.warnings]
    nearness = {'near_threshold': settings.near_threshold, 'goal_margin': settings.goal_margin,
                'avoid_margin': settings.avoid_margin}
    return TaskPlan(formula, p0, dims, tuple(steps), 'planned' if steps else 'satisfied', verification, stats,
                    tuple(warnings), nearness)


def _verified(steps: Sequence[PlanStep], p0: np.ndarray, automaton: Automaton, referent_map: ReferentMap,
              world: PlanningWorld, settings: PlannerSettings, initial_state: Optional[int]) -> Verification:
    """Run the independent check of a plan's steps."""
    return verify_plan(steps, p0, automaton, referent_map, world, settings.near_threshold,
                       settings.verify_spacing, initial_state=initial_state)


def _free_start(world: PlanningWorld, p0: np.ndarray, shift: float) -> tuple[np.ndarray, list[str]]:
    """Return the start, moved to the nearest free point when it is in an obstacle, and a warning.

    Raises
    ------
    PlanningError
        ``START_OCCUPIED`` when no free point lies within ``shift`` [m].
    """
    where = ', '.join(f'{x:.2f}' for x in p0)
    free = world.nearest_free(p0, shift)
    if free is None:
        raise PlanningError(f'the start ({where}) is in collision or outside the map, with no free point '
                            f'within {shift} m', ErrorCode.START_OCCUPIED, details={'start': p0.tolist()})
    if np.array_equal(free, p0):
        return p0, []
    moved = float(np.linalg.norm(free - p0))
    return free, [f'the start ({where}) is in an obstacle grown by the robot radius or outside the map: '
                  f'the plan starts {moved:.2f} m away at ({", ".join(f"{x:.2f}" for x in free)})']


def referent_regions(automaton: Automaton, referent_map: ReferentMap,
                     threshold: float) -> tuple[AtomRegion, ...]:
    """Return the regions of every near-atom of a task (including where its skills happen)."""
    extra = []
    for a in automaton.atoms:
        if a.is_event:
            extra.append(Atom('near', (a.args[0] if a.skill == 'pick' else a.args[1],)))
    atoms = atoms_needed(*(e.guard for e in automaton.edges()), extra=extra) + list(automaton.atoms)
    return regions_for(atoms, referent_map, threshold)

"""The independent check every plan passes before it is returned.

It shares no region code with the planner: atoms are evaluated here from the referent
map's instances (with :mod:`ltl_instruct.core.world.near`, the one definition of
``near`` that the planner and the monitor use too), obstacles from the world's boxes as given
(Euclidean clearance to the robot radius, not the planner's inflated boxes), on the
path resampled at ``spacing`` (5 cm by default). The trace is the letter at the start,
then one letter per path sample (the first sample of a step is where the previous one
ended, so it is not read twice), and for a skill the atoms at the robot's position
plus the skill's event atom. The automaton must accept it.

Margins: every navigate step must end at least as deep in its goal as it says it does
(its ``goal_margin``: the least of threshold - distance over the near atoms of the goal
cube it ends in), and every sample must stay its ``avoid_margin`` outside the regions
that the automaton edge it takes needs false (except the atoms the step's goal or its
allowed guard needs true: the path is heading into those, or leaving them). The depth
of every goal is reported.
"""
from __future__ import annotations

from typing import AbstractSet, Iterable, Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton import Automaton
from ltl_instruct.core.automaton.guards import Guard
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.segment import resample
from ltl_instruct.core.planning.taskplan import NAVIGATE, PlanStep, Verification
from ltl_instruct.core.spec.ast import Atom
from ltl_instruct.core.spec.parser import parse_formula
from ltl_instruct.core.world import near


MARGIN_TOLERANCE = 1e-3
"""How far [m] a sample may lie inside an avoid margin: edges are checked every 1 cm near a
boundary, and a straight 1 cm chord of a region of radius >= 0.1 m dips less than this into it."""


def _atom_distances(atoms: Iterable[Atom], referent_map: ReferentMap, points: np.ndarray,
                    dims: int) -> dict[Atom, np.ndarray]:
    """Near-atom -> distance [m] from each point (N, dims) to its nearest instance box (referent map)."""
    return {a: near.instances_distance(referent_map.instances(str(a.args[0])), points, dims)
            for a in atoms if a.skill == 'near'}


def _atom_truth(atoms: Sequence[Atom], referent_map: ReferentMap, points: np.ndarray, dims: int,
                threshold: float) -> dict[Atom, np.ndarray]:
    """Near-atom -> truth at each point (N, dims), from the referent map."""
    dist = _atom_distances(atoms, referent_map, points, dims)
    return {a: near.is_near(d, threshold) for a, d in dist.items()}


def _near(referent_map: ReferentMap, descriptor: str, point: np.ndarray, dims: int, threshold: float) -> bool:
    return bool(near.near_instances(referent_map.instances(descriptor), point[None], dims, threshold)[0])


def _collision(world: PlanningWorld, points: np.ndarray) -> np.ndarray:
    """Flag samples (N, dims) where the robot would hit something or leave the bounds; shape (N,)."""
    d = world.dims
    lo = np.asarray(world.bounds_min) - 1e-9
    hi = np.asarray(world.bounds_max) + 1e-9
    bad = ~np.all((points >= lo) & (points <= hi), axis=1)
    for box in world.obstacles:
        bad |= box.distance(points, dims=d) < world.robot_radius - 1e-9
    if world.lookup is not None:
        bad |= world.lookup.is_blocked(points)
    return bad


def verify_plan(steps: Sequence[PlanStep], start: np.ndarray, automaton: Automaton,
                referent_map: ReferentMap, world: PlanningWorld, near_threshold: float,
                spacing: float = 0.05, initial_state: Optional[int] = None) -> Verification:
    """Check a plan: the trace is accepted, no sample collides, skills happen where they can.

    Parameters
    ----------
    steps: the plan's steps.
    start: the robot's start position [m], shape (>= dims,).
    automaton: the task's automaton (the trace starts in its initial state).
    referent_map: where every descriptor's instances are.
    world: obstacles and bounds.
    near_threshold: the nearness threshold of ``near[x]`` [m].
    spacing: largest gap [m] between path samples (at most 0.05 for a verified plan).
    initial_state: check from this automaton state, with the letter at ``start`` already
        read (a plan made during execution); default: the initial state, reading it.
    """
    dims = world.dims
    atoms = automaton.atoms
    pos = np.asarray(start, dtype=float)[:dims]
    letters: list[frozenset[Atom]] = []
    samples: list[np.ndarray] = [pos[None]]
    reasons: list[str] = []
    continuous = True
    skills_ok = True
    holding: Optional[str] = None
    max_gap = 0.0
    navigated: list[tuple[int, PlanStep, int, np.ndarray]] = []   # (index, step, its first letter, samples)
    if initial_state is None:
        start_truth = _atom_truth(atoms, referent_map, pos[None], dims, near_threshold)
        letters.append(frozenset(a for a, v in start_truth.items() if v[0]))
    for n, step in enumerate(steps):
        w = np.asarray(step.waypoints, dtype=float)[:, :dims]
        if step.kind == NAVIGATE:
            if np.linalg.norm(w[0] - pos) > 1e-6:
                continuous = False
                reasons.append(f'step {n} starts at {np.round(w[0], 3).tolist()}, '
                               f'not where the robot is ({np.round(pos, 3).tolist()})')
            dense = resample(np.vstack([pos[None], w[1:]]), spacing)
            if len(dense) > 1:
                max_gap = max(max_gap, float(np.linalg.norm(np.diff(dense, axis=0), axis=1).max()))
            pts = dense[1:]
            navigated.append((n, step, len(letters), pts))
            truth = _atom_truth(atoms, referent_map, pts, dims, near_threshold)
            for i in range(len(pts)):
                letters.append(frozenset(a for a, v in truth.items() if v[i]))
            samples.append(pts)
            pos = dense[-1]
        else:
            if len(w) and np.linalg.norm(w[-1] - pos) > 1e-6:
                continuous = False
                reasons.append(f'skill step {n} is not where the robot is')
            event = _event_of(step.skill, atoms)
            if event is None:
                skills_ok = False
                reasons.append(f'step {n}: unknown skill {step.skill!r}')
                continue
            obj = str(event.args[0])
            if event.skill == 'pick':
                if holding is not None:
                    skills_ok = False
                    reasons.append(f'step {n}: pick {obj} while holding {holding}')
                if not _near(referent_map, obj, pos, dims, near_threshold):
                    skills_ok = False
                    reasons.append(f'step {n}: pick {obj} from farther than {near_threshold} m')
                holding = obj
            else:
                dest = str(event.args[1])
                if holding != obj:
                    skills_ok = False
                    reasons.append(f'step {n}: release {obj} but holding {holding}')
                if not _near(referent_map, dest, pos, dims, near_threshold):
                    skills_ok = False
                    reasons.append(f'step {n}: release at {dest} from farther than {near_threshold} m')
                holding = None
            truth = _atom_truth(atoms, referent_map, pos[None], dims, near_threshold)
            letters.append(frozenset(a for a, v in truth.items() if v[0]) | {event})
    allpts = np.vstack(samples)
    bad = _collision(world, allpts)
    collision_free = not bad.any()
    if not collision_free:
        i = int(np.flatnonzero(bad)[0])
        reasons.append(f'sample {i} at {np.round(allpts[i], 3).tolist()} is in an obstacle or out of bounds')
    run = [automaton.initial if initial_state is None else int(initial_state)]
    for letter in letters:
        run.append(automaton.step(run[-1], letter))
    accepted = run[-1] in automaton.accepting
    if not accepted:
        if automaton.sink is not None and automaton.sink in run:
            i = max(0, run.index(automaton.sink) - 1)
            text = ', '.join(sorted(a.key for a in letters[i])) if i < len(letters) else ''
            reasons.append(f'trace letter {i} ({text or "no atom"}) violates the task')
        else:
            reasons.append(f'the trace ends in state {run[-1]}, which is not accepting')
    if max_gap > spacing + 1e-9:
        reasons.append(f'path samples {max_gap:.3f} m apart, more than {spacing} m')
    margin_reasons, depths = _check_margins(navigated, letters, run, automaton, referent_map, dims,
                                            near_threshold)
    reasons += margin_reasons
    ok = accepted and collision_free and skills_ok and continuous and max_gap <= spacing + 1e-9 \
        and not margin_reasons
    return Verification(ok, accepted, collision_free, skills_ok, continuous, len(letters), max_gap,
                        run[-1], '; '.join(reasons), not margin_reasons, depths)


def _check_margins(navigated: Sequence[tuple[int, PlanStep, int, np.ndarray]],
                   letters: Sequence[frozenset], run: Sequence[int], automaton: Automaton,
                   referent_map: ReferentMap, dims: int,
                   threshold: float) -> tuple[list[str], tuple[Optional[float], ...]]:
    """Check every navigate step's margins; return what is wrong and the depth of each goal."""
    reasons: list[str] = []
    depths: list[Optional[float]] = []
    for n, step, first, pts in navigated:
        goal, allowed = (step.request.goal, step.request.allowed) if step.request is not None else \
            (_edge_guard(automaton, step.state_before, step.state_after),
             automaton.self_loop(step.state_before))
        dist = _atom_distances(set(automaton.atoms) | goal.atoms, referent_map, pts, dims)
        staying = {a for c in allowed.cubes for a in c.pos}   # what the step may leave
        depth = _goal_depth(goal, {a: float(d[-1]) for a, d in dist.items()}, threshold, staying)
        depths.append(depth)
        if depth is not None and depth < step.goal_margin - 1e-6:
            reasons.append(f'step {n} ends {depth:.3f} m deep in its goal, not its goal margin '
                           f'{step.goal_margin} m')
        if step.avoid_margin <= 0:
            continue
        exempt = staying | {a for c in goal.cubes for a in c.pos}
        for j in range(len(pts)):
            edge = _edge_guard(automaton, run[first + j], run[first + j + 1])
            close = [a.key for a in _needed_false(edge, letters[first + j]) - exempt
                     if a in dist and dist[a][j] < threshold + step.avoid_margin - MARGIN_TOLERANCE]
            if close:
                reasons.append(f'step {n} passes within its avoid margin {step.avoid_margin} m of '
                               f'{", ".join(sorted(close))} at {np.round(pts[j], 3).tolist()}')
                break
    return reasons, tuple(depths)


def _edge_guard(automaton: Automaton, state: int, dst: int) -> Guard:
    """Return the guard of the edge ``state`` -> ``dst`` (false when there is none)."""
    return next((e.guard for e in automaton.edges_from(state) if e.dst == dst), Guard(()))


def _needed_false(guard: Guard, letter: frozenset) -> frozenset:
    """Return the atoms every cube of ``guard`` that ``letter`` satisfies needs false."""
    needed: Optional[frozenset] = None
    for c in guard.cubes:
        if c.pos <= letter and not (c.neg & letter):
            needed = c.neg if needed is None else needed & c.neg
    return needed or frozenset()


def _goal_depth(goal: Guard, distance: dict[Atom, float], threshold: float,
                leaving: AbstractSet[Atom]) -> Optional[float]:
    """How deep [m] a point lies in a goal: of the cubes it satisfies, the best least depth of their atoms.

    An atom a cube needs true counts how deep inside its region the point is; one it
    needs false among ``leaving`` (the regions the step starts in), how far outside.
    ``distance`` holds the point's distance [m] to every near atom's boxes; a cube with an
    event atom, or no region to enter or leave, gives nothing.
    """
    best: Optional[float] = None
    for c in goal.cubes:
        ahead = c.pos | (c.neg & leaving)
        if not ahead or not all(a in distance for a in c.pos | c.neg):
            continue
        if not all(near.is_near(distance[a], threshold) for a in c.pos) \
                or any(near.is_near(distance[a], threshold) for a in c.neg):
            continue
        depth = min(float(near.depth(distance[a], threshold)) * (1 if a in c.pos else -1) for a in ahead)
        best = depth if best is None else max(best, depth)
    return best


def _event_of(key: str, atoms: Sequence[Atom]) -> Optional[Atom]:
    for a in atoms:
        if a.key == key and a.is_event:
            return a
    try:
        f = parse_formula(key)
    except LtlInstructError:  # an unparsable skill is reported by the caller
        return None
    return f if isinstance(f, Atom) and f.is_event else None

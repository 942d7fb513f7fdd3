"""The independent check every plan passes before it is returned.

It shares no region code with the planner: atoms are evaluated here from the referent
map's instances (with :mod:`ltl_instruct.core.world.near`, the one definition of
``near`` that the planner and the monitor use too), obstacles from the world's boxes as given
(Euclidean clearance to the robot radius, not the planner's inflated boxes), on the
path resampled at ``spacing`` (5 cm by default). The trace is the letter at the start,
then one letter per path sample (the first sample of a step is where the previous one
ended, so it is not read twice), and for a skill the atoms at the robot's position
plus the skill's event atom. The automaton must accept it.
"""
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton import Automaton
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.segment import resample
from ltl_instruct.core.planning.taskplan import NAVIGATE, PlanStep, Verification
from ltl_instruct.core.spec.ast import Atom
from ltl_instruct.core.spec.parser import parse_formula
from ltl_instruct.core.world import near


def _atom_truth(atoms: Sequence[Atom], referent_map: ReferentMap, points: np.ndarray, dims: int,
                threshold: float) -> dict[Atom, np.ndarray]:
    """Near-atom -> truth at each point (N, dims), from the referent map."""
    out = {}
    for a in atoms:
        if a.skill != 'near':
            continue
        out[a] = near.near_instances(referent_map.instances(str(a.args[0])), points, dims, threshold)
    return out


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
    ok = accepted and collision_free and skills_ok and continuous and max_gap <= spacing + 1e-9
    return Verification(ok, accepted, collision_free, skills_ok, continuous, len(letters), max_gap,
                        run[-1], '; '.join(reasons))


def _event_of(key: str, atoms: Sequence[Atom]) -> Optional[Atom]:
    for a in atoms:
        if a.key == key and a.is_event:
            return a
    try:
        f = parse_formula(key)
    except LtlInstructError:  # an unparsable skill is reported by the caller
        return None
    return f if isinstance(f, Atom) and f.is_event else None

"""Where consecutive segments meet: the goal point of each region chosen for the whole task.

Each segment is planned from where the last one ended, so on its own it ends at the goal
point nearest its start, which may be a detour for the segment after it (a goal region
entered on the near side, then crossed again to leave on the far side). After the
search, each junction between two navigate steps is moved, inside the first step's goal
(with the margins that step keeps), to shorten the last leg into it plus the first leg
out of it: candidates are goal points on the straight line between the two legs' outer
vertices, the projections of those vertices on the goal's near-balls, and goal samples,
tried cheapest first. A move is kept only if both legs pass their own segment's checks
again (free, allowed, the first step still ends at its first goal point past the edge
and ``goal_margin`` deep, the second reaches its goal where it did before); the whole
plan is then verified as always, and the planner falls back to the plan as searched if
that check fails.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Optional, Sequence

import numpy as np

from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.segment import SegmentProblem, path_length
from ltl_instruct.core.planning.taskplan import NAVIGATE, PlanStep

MAX_TRIES = 60
"""Candidate junctions checked per junction (cheapest first)."""


def _problem(step: PlanStep, world: PlanningWorld) -> SegmentProblem:
    """Return the checks of a step's segment, with the margins the step keeps."""
    assert step.request is not None
    req = replace(step.request, goal_margin=step.goal_margin, avoid_margin=step.avoid_margin)
    return SegmentProblem(req, world)


def _candidates(first: SegmentProblem, v: np.ndarray, w: np.ndarray, seed: int) -> np.ndarray:
    """Possible junctions (M, dims): goal points on v -> w, projections of v and w, goal samples."""
    line = v + np.linspace(0.0, 1.0, 41)[:, None] * (w - v)
    proj = first.goal_projections(np.vstack([v, w])).reshape(-1, len(v))
    samples = first.sample_goal(256, seed, batches=4)[0]
    pts = np.vstack([line, proj, samples])
    valid, goal = first.classify(pts)
    return pts[valid & goal]


def _move(a: PlanStep, b: PlanStep, world: PlanningWorld, seed: int) -> Optional[tuple[PlanStep, PlanStep]]:
    """Return the two steps with their junction moved to shorten them, or None if no move helps."""
    first, second = _problem(a, world), _problem(b, world)
    v, p, w = a.waypoints[-2], a.waypoints[-1], b.waypoints[1]
    now = float(np.linalg.norm(p - v) + np.linalg.norm(w - p))
    cands = _candidates(first, v, w, seed)
    if not len(cands):
        return None
    cost = np.linalg.norm(cands - v, axis=1) + np.linalg.norm(w - cands, axis=1)
    for k in np.argsort(cost)[:MAX_TRIES]:
        if cost[k] >= now - 1e-6:
            return None
        q = cands[k]
        if not first.motion_valid(tuple(v), tuple(q)):
            continue
        cut = first.first_goal_prefix(np.vstack([a.waypoints[:-1], q]))
        if cut is None:
            continue
        q = cut[-1]
        new_a = np.vstack([a.waypoints[:-1], q])
        new_b = np.vstack([q, b.waypoints[1:]])
        if second.in_plain_goal(tuple(q)) or not second.state_valid(tuple(q)) \
                or not second.motion_valid(tuple(q), tuple(w)):
            continue
        again = second.first_goal_prefix(new_b)
        if again is None or np.linalg.norm(again[-1] - new_b[-1]) > 1e-9:
            continue      # the second step would reach its goal elsewhere: keep it as it was
        if path_length(new_a) + path_length(new_b) >= a.length + b.length - 1e-6:
            continue
        return (replace(a, waypoints=new_a, length=path_length(new_a)),
                replace(b, waypoints=new_b, length=path_length(new_b)))
    return None


def shorten_junctions(steps: Sequence[PlanStep], world: PlanningWorld, seed: int = 0,
                      rounds: int = 2) -> list[PlanStep]:
    """Move each junction of two consecutive navigate steps to shorten the task (see the module doc)."""
    out = list(steps)
    for _ in range(rounds):
        moved = False
        for i in range(len(out) - 1):
            a, b = out[i], out[i + 1]
            if a.kind != NAVIGATE or b.kind != NAVIGATE or a.request is None or b.request is None \
                    or len(a.waypoints) < 2 or len(b.waypoints) < 2 or a.length <= 0 or b.length <= 0:
                continue
            pair = _move(a, b, world, seed)
            if pair is not None:
                out[i], out[i + 1] = pair
                moved = True
        if not moved:
            break
    return out

"""Task plans: the steps (navigate along waypoints, or a skill) and what they do to the automaton.

Values only; :mod:`~ltl_instruct.core.planning.planner` builds them and
:mod:`~ltl_instruct.core.planning.verify` checks them. Positions are in the ``map``
frame [m]; a ground plan has 2D waypoints (x, y), a drone plan 3D (x, y, z).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from ltl_instruct.core.planning.segment import SegmentRequest

NAVIGATE = 'navigate'
SKILL = 'skill'


@dataclass(frozen=True, eq=False)
class PlanStep:
    """One step of a plan.

    Attributes
    ----------
    kind: ``navigate`` or ``skill``.
    state_before, state_after: automaton states around the step.
    waypoints: navigate: the path [m], shape (N, dims), N >= 2, starting where the
        previous step ended; skill: the robot position, shape (1, dims).
    skill: the event atom of a skill step (``pick[cup]``), else ''.
    goal, allowed: the guards of the segment (text), for people.
    request: the segment request a navigate step answered (regions and guards).
    length: path length [m] (0 for a skill).
    seconds: time spent planning this step [s].
    goal_margin, avoid_margin: the margins [m] a navigate step keeps (the plan check
        holds it to them): how deep it ends in its goal, how far it stays from regions
        to avoid.
    warnings: why a navigate step keeps less margin than asked for.
    """

    kind: str
    state_before: int
    state_after: int
    waypoints: np.ndarray
    skill: str = ''
    goal: str = ''
    allowed: str = ''
    request: Optional[SegmentRequest] = None
    length: float = 0.0
    seconds: float = 0.0
    goal_margin: float = 0.0
    avoid_margin: float = 0.0
    warnings: tuple[str, ...] = ()

    @property
    def end(self) -> np.ndarray:
        """Where the robot is after the step [m], shape (dims,)."""
        return np.asarray(self.waypoints[-1], dtype=float)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        d: dict[str, Any] = {'kind': self.kind, 'state_before': self.state_before,
                             'state_after': self.state_after}
        if self.kind == NAVIGATE:
            d.update(waypoints=np.round(self.waypoints, 4).tolist(), length=round(self.length, 4),
                     goal=self.goal, allowed=self.allowed, goal_margin=self.goal_margin,
                     avoid_margin=self.avoid_margin)
        else:
            d.update(skill=self.skill, position=np.round(self.waypoints[-1], 4).tolist())
        return d


@dataclass(frozen=True)
class Verification:
    """The independent check of a plan.

    Attributes
    ----------
    ok: every check passed.
    accepted: the automaton accepts the plan's trace.
    collision_free: no sample lies in an obstacle (grown by the robot radius) or out of bounds.
    skills_ok: every pick/release happens near its object / destination, in order.
    continuous: every navigate step starts where the robot is.
    num_samples: letters in the trace.
    max_spacing: largest gap [m] between consecutive path samples.
    final_state: automaton state at the end of the trace.
    reason: why it failed ('' when ok).
    margins_ok: every navigate step ends as deep in its goal, and stays as far from the
        regions its automaton edges need false, as it says it does.
    goal_depths: per navigate step, how deep [m] its end lies in its goal (the least over
        the regions the goal needs it in, and how far out of those it is leaving; None for
        a goal with neither).
    """

    ok: bool
    accepted: bool
    collision_free: bool
    skills_ok: bool
    continuous: bool
    num_samples: int
    max_spacing: float
    final_state: int
    reason: str = ''
    margins_ok: bool = True
    goal_depths: tuple[Optional[float], ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'ok': self.ok, 'accepted': self.accepted, 'collision_free': self.collision_free,
                'skills_ok': self.skills_ok, 'continuous': self.continuous,
                'num_samples': self.num_samples, 'max_spacing': round(self.max_spacing, 5),
                'final_state': self.final_state, 'reason': self.reason, 'margins_ok': self.margins_ok,
                'goal_depths': [None if d is None else round(d, 4) for d in self.goal_depths]}


@dataclass(frozen=True, eq=False)
class TaskPlan:
    """A verified plan for a task formula.

    Attributes
    ----------
    formula: the task, as text.
    start: start position [m], shape (dims,).
    dims: 2 or 3.
    steps: the steps, in order (empty when the start already satisfies the task).
    status: ``planned``, or ``satisfied`` when nothing needs doing.
    verification: the independent check (always run before a plan is returned).
    stats: counters (segments solved, failures, seconds).
    warnings: what the plan does less well than asked, for people (a start moved out of
        an obstacle, a margin not kept).
    nearness: the ``near_threshold``, ``goal_margin`` and ``avoid_margin`` [m] it was made with.
    """

    formula: str
    start: np.ndarray
    dims: int
    steps: tuple[PlanStep, ...]
    status: str
    verification: Verification
    stats: dict[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    nearness: dict[str, float] = field(default_factory=dict)

    @property
    def length(self) -> float:
        """Total path length [m]."""
        return float(sum(s.length for s in self.steps))

    @property
    def states(self) -> list[int]:
        """Automaton states along the plan: before the first step, then after each."""
        if not self.steps:
            return [self.verification.final_state]
        return [self.steps[0].state_before] + [s.state_after for s in self.steps]

    def path(self) -> np.ndarray:
        """Return the whole path [m], shape (N, dims) (the start alone when there is no step)."""
        parts = [np.asarray(self.start, dtype=float)[None, :self.dims]]
        for s in self.steps:
            if s.kind == NAVIGATE:
                parts.append(s.waypoints[1:])
        return np.vstack(parts)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict: status, steps, automaton states, length, verification."""
        return {'status': self.status, 'formula': self.formula,
                'start': np.round(self.start, 4).tolist(), 'dims': self.dims,
                'length': round(self.length, 4), 'automaton_states': self.states,
                'steps': [s.to_dict() for s in self.steps],
                'verification': self.verification.to_dict(), 'stats': dict(self.stats),
                'warnings': list(self.warnings), 'nearness': dict(self.nearness)}

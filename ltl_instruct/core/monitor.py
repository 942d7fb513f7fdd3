"""Execution monitoring: progress the task automaton with the robot's pose and skill events.

While the robot moves, every new pose (and every pick or release that succeeded) is
turned into a letter (the set of atoms true there) and read by the automaton. The
verdict is

- ``satisfied`` when the automaton is in an accepting state (the robot may stop),
- ``violated`` when acceptance is no longer reachable (with the atoms that did it),
- ``progressing`` otherwise.

``near[x]`` is true within ``near_threshold`` [m] of the box of an instance that the
descriptor ``x`` resolved to in the referent map (in the plane for a ground robot,
``dims=2``; in 3D for a drone), measured by :mod:`ltl_instruct.core.world.near` as the
planner and the plan check measure it. This module never imports rclpy.
"""
from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import AbstractSet, Iterable, Optional, Sequence

import numpy as np

from ltl_instruct.core.automaton import Automaton
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.rsm import Instance, ReferentMap
from ltl_instruct.core.spec import Atom
from ltl_instruct.core.world import near

# the longest move read between two poses [m]: a longer one (odometry of 1e9 m) is refused, since
# reading it every few centimetres would take the node's time and memory without end
MAX_MOVE_M = 1000.0


class Verdict(str, enum.Enum):
    """Where the task stands during execution."""

    PROGRESSING = 'progressing'
    SATISFIED = 'satisfied'
    VIOLATED = 'violated'


@dataclass(frozen=True)
class MonitorReport:
    """The result of reading one letter.

    Attributes
    ----------
    step: number of letters read so far (1 after the first).
    state: automaton state after the letter.
    previous_state: automaton state before it.
    verdict: progressing, satisfied or violated.
    letter: keys of the atoms true in the letter, sorted.
    blamed_atoms: on a violation, the atoms whose truth caused it (keys, sorted);
        empty otherwise, or when the violation came from an atom being false.
    """

    step: int
    state: int
    previous_state: int
    verdict: Verdict
    letter: tuple[str, ...]
    blamed_atoms: tuple[str, ...] = ()

    @property
    def changed(self) -> bool:
        """True when the automaton moved to another state."""
        return self.state != self.previous_state

    def to_dict(self) -> dict:
        """JSON-ready dict."""
        return {'step': self.step, 'state': self.state, 'previous_state': self.previous_state,
                'verdict': self.verdict.value, 'letter': list(self.letter),
                'blamed_atoms': list(self.blamed_atoms)}


@dataclass(frozen=True)
class LetterMaker:
    """Turns a position and the events of a step into a letter over an automaton's atoms.

    Attributes
    ----------
    atoms: the automaton's atoms.
    referent_map: instances per descriptor text.
    near_threshold: nearness radius [m].
    dims: 2 (ground robot, distances in the plane) or 3 (drone).
    """

    atoms: tuple[Atom, ...]
    referent_map: ReferentMap
    near_threshold: float = near.DEFAULT_NEAR_THRESHOLD
    dims: int = 2
    _near: tuple[tuple[Atom, tuple[Instance, ...]], ...] = field(init=False, default=())

    def __post_init__(self) -> None:
        near.check_threshold(self.near_threshold)
        if self.dims not in (2, 3):
            raise InvalidInputError(f'dims must be 2 or 3, got {self.dims}')
        instances = tuple((a, self.referent_map.instances(str(a.args[0])))
                          for a in self.atoms if a.skill == 'near')
        object.__setattr__(self, '_near', instances)

    def letter(self, position: Sequence[float], events: Iterable[Atom] = ()) -> frozenset[Atom]:
        """Atoms true at ``position`` [m] (shape (3,)), plus the given event atoms.

        Raises
        ------
        InvalidInputError
            On a position that is not 3 finite numbers, or more than one event.
        """
        p = np.asarray(position, dtype=float)
        if p.shape != (3,) or not np.all(np.isfinite(p)):
            raise InvalidInputError(f'a position must be 3 finite numbers, got {position!r}')
        true = {a for a, insts in self._near
                if near.near_instances(insts, p, self.dims, self.near_threshold)[0]}
        ev = [e for e in events if e in self.atoms]
        if len(ev) > 1:
            raise InvalidInputError('at most one pick or release per step: '
                                    + ', '.join(e.key for e in ev))
        true.update(ev)
        return frozenset(true)


class ExecutionMonitor:
    """Progresses an automaton along the executed trace and reports a verdict per letter.

    Parameters
    ----------
    automaton: the task automaton.
    letters: how positions and events become letters.
    state: the automaton state to start from (its initial state by default); the
        first letter read is the one at the robot's start pose.
    """

    def __init__(self, automaton: Automaton, letters: LetterMaker,
                 state: Optional[int] = None) -> None:
        self.automaton = automaton
        self.letters = letters
        self.state = automaton.initial if state is None else int(state)
        if not 0 <= self.state < automaton.num_states:
            raise InvalidInputError(f'no automaton state {state}')
        self.steps = 0
        self.last: Optional[MonitorReport] = None

    def verdict_of(self, state: int) -> Verdict:
        """Return the verdict of being in ``state``."""
        if state in self.automaton.accepting:
            return Verdict.SATISFIED
        if self.automaton.distance_to_accepting(state) is None:
            return Verdict.VIOLATED
        return Verdict.PROGRESSING

    def with_referent_map(self, referent_map: ReferentMap) -> 'ExecutionMonitor':
        """Return a monitor in the same state that reads letters with a new referent map."""
        m = ExecutionMonitor(self.automaton, LetterMaker(
            self.letters.atoms, referent_map, self.letters.near_threshold, self.letters.dims),
            self.state)
        m.steps, m.last = self.steps, self.last
        return m

    def update(self, position: Sequence[float], events: Iterable[Atom] = ()) -> MonitorReport:
        """Read the letter at ``position`` [m] with ``events``; return the report.

        Once violated, the monitor stays violated (the sink absorbs); once satisfied
        it keeps reading (a later letter may still break an obligation in a
        non-accepting continuation, which the automaton tracks).
        """
        letter = self.letters.letter(position, events)
        return self.read(letter)

    def update_along(self, start: Sequence[float], end: Sequence[float], events: Iterable[Atom] = (),
                     spacing: float = 0.05, via: Sequence[Sequence[float]] = ()) -> MonitorReport:
        """Read the letters along the move ``start`` -> ``via``... -> ``end`` [m], every ``spacing`` [m].

        Poses come at a finite rate; a fast robot would otherwise step over a thin region
        between two of them. The move is straight unless ``via`` gives the corners it
        turned at (:class:`PlanTrace` knows them when both poses lie on the plan).
        ``start`` was read already; ``events`` belong to the last letter. Reading stops at
        the first letter that satisfies or violates the task; the report says whether the
        state changed anywhere along the move.

        Raises
        ------
        InvalidInputError
            On non-finite positions, ``spacing`` <= 0, or a move longer than :data:`MAX_MOVE_M`.
        """
        corners = [np.asarray(p, dtype=float) for p in (start, *via, end)]
        if any(c.shape != (3,) or not np.all(np.isfinite(c)) for c in corners):
            raise InvalidInputError('positions must be 3 finite numbers')
        if not spacing > 0:
            raise InvalidInputError(f'spacing must be positive, got {spacing}')
        length = sum(float(np.linalg.norm(b - a)) for a, b in zip(corners, corners[1:]))
        if not length <= MAX_MOVE_M:
            raise InvalidInputError(f'a move of {length:.3g} m between two poses is longer than '
                                    f'{MAX_MOVE_M:g} m: the pose is not read')
        events = list(events)
        points = [a + (b - a) * (k / n) for a, b in zip(corners, corners[1:])
                  for n in [max(1, int(np.ceil(float(np.linalg.norm(b - a)) / spacing)))]
                  for k in range(1, n + 1)]
        first_state = self.state
        report: Optional[MonitorReport] = None
        for j, p in enumerate(points):
            report = self.update(p, events if j == len(points) - 1 else ())
            if report.verdict is not Verdict.PROGRESSING:
                break
        assert report is not None
        if report.previous_state != first_state:   # say what the whole move did
            report = MonitorReport(report.step, report.state, first_state, report.verdict, report.letter,
                                   report.blamed_atoms)
        return report

    def read(self, letter: AbstractSet[Atom]) -> MonitorReport:
        """Read an already-built letter; return the report."""
        before = self.state
        after = self.automaton.step(before, letter)
        verdict = self.verdict_of(after)
        blamed: tuple[str, ...] = ()
        if verdict is Verdict.VIOLATED and self.verdict_of(before) is not Verdict.VIOLATED:
            blamed = self._blame(before, letter)
        self.state = after
        self.steps += 1
        self.last = MonitorReport(self.steps, after, before, verdict,
                                  tuple(sorted(a.key for a in letter)), blamed)
        return self.last

    def _blame(self, state: int, letter: AbstractSet[Atom]) -> tuple[str, ...]:
        """Atoms of ``letter`` without which the step would not have been fatal."""
        out = []
        for a in letter:
            alt = self.automaton.step(state, frozenset(letter) - {a})
            if self.automaton.distance_to_accepting(alt) is not None:
                out.append(a.key)
        return tuple(sorted(out))


class PlanTrace:
    """Where along its plan the robot is, to fill the gap between two odometry poses.

    Odometry can come late and in bursts, or be dropped, from a busy node's queue; a
    straight line between two poses far apart cuts the corners the robot turned at, and
    can miss the region it turned in. A robot follows its plan, so when both poses lie
    on the plan (within ``tolerance`` [m]), in order along it, the move between them is
    taken to be the plan's, corners included. Otherwise the move is read as straight.

    Parameters
    ----------
    path: the plan's points (N, 3) [m].
    tolerance: how far from the plan a pose may be and still be on it [m].
    dims: 2 for a ground robot (heights are not compared), 3 for a drone.
    """

    def __init__(self, path: np.ndarray, tolerance: float = 0.1, dims: int = 3) -> None:
        p = np.array(path, dtype=float)
        if p.ndim != 2 or p.shape[1] != 3 or len(p) == 0 or not np.all(np.isfinite(p)):
            raise InvalidInputError('a plan trace needs finite points of shape (N, 3)')
        if not (tolerance > 0 and math.isfinite(tolerance)):
            raise InvalidInputError(f'tolerance must be positive, got {tolerance}')
        if dims not in (2, 3):
            raise InvalidInputError(f'dims must be 2 or 3, got {dims}')
        self.dims = dims
        self.path = p
        self.tolerance = float(tolerance)
        self._s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p[:, :dims], axis=0), axis=1))])
        self.cursor: Optional[float] = None   # arc length of the last pose, when it was on the plan
        self._reached = 0.0                   # the farthest arc length a pose was on the plan at

    def locate(self, position: Sequence[float], after: float = 0.0) -> Optional[float]:
        """Return the least arc length >= ``after`` [m] whose plan point is within tolerance, or None."""
        q = np.asarray(position, dtype=float)[:self.dims]
        path = self.path[:, :self.dims]
        if len(path) == 1:
            ok = float(np.linalg.norm(q - path[0])) <= self.tolerance
            return 0.0 if ok else None
        a, b = path[:-1], path[1:]
        ab = b - a
        length2 = np.einsum('ij,ij->i', ab, ab)
        t = np.where(length2 > 1e-18, np.einsum('ij,ij->i', q - a, ab) / np.maximum(length2, 1e-18), 0.0)
        seg_len = np.sqrt(length2)
        # no earlier than ``after`` on each segment
        t_min = np.where(seg_len > 1e-9, (after - self._s[:-1]) / np.maximum(seg_len, 1e-9), 0.0)
        t = np.clip(np.maximum(t, t_min), 0.0, 1.0)
        near = np.linalg.norm(a + ab * t[:, None] - q, axis=1) <= self.tolerance
        s = self._s[:-1] + t * seg_len
        ok = near & (s >= after - 1e-9)
        if not ok.any():
            return None
        return float(s[np.flatnonzero(ok)[0]])

    def start(self, position: Sequence[float]) -> None:
        """Place the first pose."""
        self.cursor = self.locate(position)
        self._reached = self.cursor or 0.0

    def via(self, position: Sequence[float]) -> list[np.ndarray]:
        """Return the plan's points passed between the last pose and ``position``; move on to it.

        Empty when the move is to be read as straight: either pose off the plan, or
        ``position`` on it only behind where the robot has been.
        """
        last = self.cursor
        self.cursor = self.locate(position, self._reached)
        if self.cursor is not None:
            self._reached = self.cursor
        if last is None or self.cursor is None:
            return []
        inside = (self._s > last + 1e-9) & (self._s < self.cursor - 1e-9)
        return [self.path[i] for i in np.flatnonzero(inside)]

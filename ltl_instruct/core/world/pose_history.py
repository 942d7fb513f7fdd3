"""The robot's recent poses by time stamp: where the robot was when a camera frame was taken.

A camera frame and the odometry come on different topics at different rates. The pose
of a frame's stamp is interpolated between the odometry poses on either side of it
(position linearly, yaw along the shorter turn), when one of them lies within
``tolerance`` seconds of it; a stamp before the oldest pose takes the oldest, within the
tolerance. A stamp past the newest pose has no pose *yet* (:meth:`PoseHistory.waiting`):
its odometry may still be on its way, and the newest pose could be a turn behind.
Stamps are integer nanoseconds (as ``builtin_interfaces/Time`` gives them).
"""
from __future__ import annotations

import bisect
import math
from typing import Optional

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world.robot import Pose


class PoseHistory:
    """The last ``size`` poses by stamp [ns]; :meth:`at` looks one up, ``tolerance`` [s] from them at most."""

    def __init__(self, size: int = 200, tolerance: float = 0.1) -> None:
        if not 1 <= size <= 100_000 or not (math.isfinite(tolerance) and tolerance >= 0):
            raise InvalidInputError('pose history: size must be in 1..100000 and tolerance a number >= 0 [s]')
        self.size = size
        self.tolerance_ns = int(tolerance * 1e9)
        self._stamps: list[int] = []
        self._poses: list[Pose] = []

    def __len__(self) -> int:
        return len(self._stamps)

    def add(self, stamp: int, pose: Pose) -> None:
        """Keep a pose (a repeated stamp replaces the one kept)."""
        k = bisect.bisect_left(self._stamps, stamp)
        if k < len(self._stamps) and self._stamps[k] == stamp:
            self._poses[k] = pose
            return
        self._stamps.insert(k, int(stamp))
        self._poses.insert(k, pose)
        if len(self._stamps) > self.size:
            del self._stamps[0], self._poses[0]

    def at(self, stamp: int) -> Optional[Pose]:
        """Return the pose at ``stamp`` [ns], or None when no pose lies within the tolerance of it."""
        if not self._stamps:
            return None
        k = bisect.bisect_left(self._stamps, stamp)
        if k < len(self._stamps) and self._stamps[k] == stamp:
            return self._poses[k]
        if k == len(self._stamps):
            return None
        if k == 0:
            return self._poses[0] if self._stamps[0] - stamp <= self.tolerance_ns else None
        t0, t1 = self._stamps[k - 1], self._stamps[k]
        if min(stamp - t0, t1 - stamp) > self.tolerance_ns:
            return None
        return _between(self._poses[k - 1], self._poses[k], (stamp - t0) / (t1 - t0))

    def waiting(self, stamp: int) -> bool:
        """Tell whether ``stamp`` [ns] is newer than every pose kept (its odometry may still come)."""
        return not self._stamps or stamp > self._stamps[-1]


def _between(a: Pose, b: Pose, f: float) -> Pose:
    """Return the pose a fraction ``f`` of the way from ``a`` to ``b``."""
    turn = math.remainder(b.yaw - a.yaw, 2.0 * math.pi)
    position = tuple(pa + f * (pb - pa) for pa, pb in zip(a.position, b.position))
    return Pose(position, a.yaw + f * turn)  # type: ignore[arg-type]

"""A kinematic robot and the simulated world it acts in (the ``sim_world`` node's core).

The robot follows a path exactly, at a bounded speed: each step moves it a distance
``max_speed * dt`` [m] along the polyline and turns it to face the direction of travel
(a ground robot moves in the plane at its start height; a drone in 3D). It can stop at a
path index to carry out a skill, then go on.

:class:`SimulatedWorld` adds the objects: pick and release move an object with the
robot, and the occupancy grid the simulator publishes as ``map`` is rasterised from the
scene's blocking geometry. Units are metres and radians, in the ``map`` frame.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.core.world import near
from ltl_instruct.core.world.scene import Scene, SceneObject


@dataclass(frozen=True)
class Pose:
    """A robot pose: ``position`` [m] shape (3,), ``yaw`` [rad] about +z."""

    position: tuple[float, float, float]
    yaw: float = 0.0

    @property
    def xyz(self) -> np.ndarray:
        """Position as an array [m], shape (3,)."""
        return np.asarray(self.position, dtype=float)


def compose_planar(parent: Pose, child: Pose) -> Pose:
    """Return ``child`` (a pose in a frame placed at ``parent``) in the parent's frame.

    The frame is turned by ``parent.yaw`` about +z and moved by ``parent.position`` [m].
    """
    c, s = math.cos(parent.yaw), math.sin(parent.yaw)
    x, y, z = child.position
    px, py, pz = parent.position
    yaw = math.atan2(math.sin(parent.yaw + child.yaw), math.cos(parent.yaw + child.yaw))
    return Pose((px + c * x - s * y, py + s * x + c * y, pz + z), yaw)


@dataclass(frozen=True)
class SkillOutcome:
    """What a pick or release did.

    Attributes
    ----------
    skill: ``pick`` or ``release``.
    object_id: the scene object picked or released ('' if none was found).
    target_id: where it was released ('' for pick).
    ok: whether the skill succeeded.
    error_code: an :class:`ErrorCode` value when it failed, else ''.
    reason: human-readable explanation.
    """

    skill: str
    object_id: str
    target_id: str
    ok: bool
    error_code: str = ''
    reason: str = ''


def validate_path(points: np.ndarray, dims: int = 3) -> np.ndarray:
    """Check a path: shape (N, 3) with N >= 1 and finite values [m]; return it as float.

    Raises
    ------
    InvalidInputError
        On a wrong shape, an empty path, or NaN/inf coordinates.
    """
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or p.shape[0] < 1:
        raise InvalidInputError(f'a path must have shape (N, 3) with N >= 1, got {p.shape}')
    if not np.all(np.isfinite(p[:, :dims])):
        raise InvalidInputError('a path contains NaN or infinite coordinates')
    return p


class KinematicRobot:
    """A robot that tracks a polyline exactly at bounded speed.

    Parameters
    ----------
    start: initial position [m], shape (3,).
    yaw: initial heading [rad].
    max_speed: speed along the path [m/s], > 0.
    planar: True for a ground robot (z stays at the start height).
    """

    def __init__(self, start: Sequence[float], yaw: float = 0.0, max_speed: float = 1.0,
                 planar: bool = True) -> None:
        if not max_speed > 0.0 or not math.isfinite(max_speed):
            raise InvalidInputError(f'max_speed must be a positive number, got {max_speed}')
        s = np.asarray(start, dtype=float)
        if s.shape != (3,) or not np.all(np.isfinite(s)):
            raise InvalidInputError(f'start must be 3 finite numbers, got {start!r}')
        self._position = s.copy()
        self._yaw = float(yaw)
        self.max_speed = float(max_speed)
        self.planar = planar
        self._path: Optional[np.ndarray] = None
        self._segment = 0              # index of the path point the robot heads for
        self._stop_at: set[int] = set()  # path indices where the robot must stop
        self._paused = False
        self._travelled = 0.0
        self._offset = 0                   # points driven back along the trail before the path
        self._trail: list[np.ndarray] = []  # path vertices reached (the last TRAIL_LENGTH), across plans
        self.corners: list[Pose] = []       # path corners passed in the last step()

    # ------------------------------------------------------------------ state
    @property
    def pose(self) -> Pose:
        """Current pose."""
        return Pose(tuple(float(v) for v in self._position), self._yaw)  # type: ignore[arg-type]

    @property
    def path_index(self) -> int:
        """Index of the last point of the followed path reached (-1 with no path, or before it)."""
        return -1 if self._path is None else self._segment - 1 - self._offset

    @property
    def is_moving(self) -> bool:
        """True while a path is being followed and the robot is not paused."""
        return self._path is not None and not self._paused and self._segment < len(self._path)

    @property
    def is_done(self) -> bool:
        """True once the end of the current path is reached (or there is none)."""
        return self._path is None or self._segment >= len(self._path)

    @property
    def travelled(self) -> float:
        """Distance driven since construction [m]."""
        return self._travelled

    # ------------------------------------------------------------------ commands
    def follow(self, points: np.ndarray, stop_at: Sequence[int] = ()) -> None:
        """Start following ``points`` (N, 3) [m]; stop at the given path indices.

        A new plan usually starts where the robot was when planning began, a little
        behind where it is now. If that start lies on the way the robot has just driven
        (within ``REJOIN_TOLERANCE``), the robot drives back along that way to it: a
        straight line back could cut a corner the old path went around. Otherwise it
        drives straight to the first point.
        """
        p = validate_path(points, 2 if self.planar else 3)
        if self.planar:
            p = p.copy()
            p[:, 2] = self._position[2]
        back = self._way_back_to(p[0])
        self._offset = len(back)
        self._path = np.vstack([back, p]) if len(back) else p
        self._segment = 0
        self._stop_at = {int(i) + self._offset for i in stop_at if 0 <= int(i) < len(p)}
        self._paused = False
        self._remember(self._position.copy())   # the trail goes on across plans (a burst of them)

    REJOIN_TOLERANCE = 0.25   # [m]
    TRAIL_LENGTH = 4000       # path vertices remembered

    def _remember(self, point: np.ndarray) -> None:
        """Add a reached point to the trail (the last ``TRAIL_LENGTH`` are kept)."""
        self._trail.append(point)
        if len(self._trail) > self.TRAIL_LENGTH:
            del self._trail[:len(self._trail) - self.TRAIL_LENGTH]

    def _way_back_to(self, target: np.ndarray) -> np.ndarray:
        """Points (K, 3) retracing the driven trail from here back to near ``target`` (K may be 0).

        The most recent stretch of the trail that passes within ``REJOIN_TOLERANCE`` of the
        target is the one retraced: in a burst of plans, one may start where the robot was
        before the plan it is following now came.
        """
        trail = np.asarray(self._trail + [self._position.copy()], dtype=float)
        if len(trail) < 2:
            return np.zeros((0, 3))
        a, ab = trail[:-1], np.diff(trail, axis=0)
        t = np.clip(((target - a) * ab).sum(axis=1) / np.maximum((ab * ab).sum(axis=1), 1e-12), 0.0, 1.0)
        q = a + t[:, None] * ab
        near = np.flatnonzero(np.linalg.norm(q - target, axis=1) <= self.REJOIN_TOLERANCE)
        if len(near) == 0:
            return np.zeros((0, 3))
        i = int(near[-1])
        # from the current position back over the vertices after segment i, to q
        return np.vstack([trail[:i:-1], q[i][None, :]])

    def add_stop(self, index: int) -> bool:
        """Stop at path index ``index``; if it was already passed, stop now. Return True if in time."""
        if self._path is None:
            return False
        index = int(index) + self._offset
        if index >= self._segment:
            self._stop_at.add(index)
            return True
        self._paused = True
        return False

    def stop(self) -> None:
        """Drop the current path and stand still."""
        self._path = None
        self._segment = 0
        self._offset = 0
        self._stop_at.clear()
        self._paused = False

    def pause(self) -> None:
        """Hold position without dropping the path."""
        self._paused = True

    def resume(self) -> None:
        """Go on along the path after a pause or a stop point."""
        self._paused = False

    @property
    def is_paused(self) -> bool:
        """True while holding at a stop point or after :meth:`pause`."""
        return self._paused

    TURN_ANGLE = 0.01   # [rad] a path vertex turning more than this is a corner

    def step(self, dt: float) -> Pose:
        """Advance ``dt`` [s] along the path; return the new pose.

        The corners passed on the way are kept in :attr:`corners`: whoever reads the
        trace as straight moves between poses (the execution monitor) needs them, or a
        long step (a slow tick) cuts the corner and can miss the region turned in.
        """
        self.corners = []
        if not dt > 0.0 or self._path is None or self._paused:
            return self.pose
        budget = self.max_speed * dt
        while budget > 1e-12 and self._segment < len(self._path):
            target = self._path[self._segment]
            delta = target - self._position
            dist = float(np.linalg.norm(delta))
            if dist > 1e-9:
                heading = math.atan2(delta[1], delta[0])
                if math.hypot(delta[0], delta[1]) > 1e-6:
                    self._yaw = heading
            if dist <= budget:
                self._position = target.copy()
                self._remember(target.copy())
                self._travelled += dist
                budget -= dist
                reached = self._segment
                self._segment += 1
                if reached in self._stop_at:
                    self._stop_at.discard(reached)
                    self._paused = True
                    break
                if budget > 1e-12 and self._turns_at(reached, delta):
                    self.corners.append(self.pose)
            else:
                self._position = self._position + delta * (budget / dist)
                self._travelled += budget
                budget = 0.0
        return self.pose

    def _turns_at(self, index: int, incoming: np.ndarray) -> bool:
        """Whether the path turns at vertex ``index`` (reached along ``incoming``)."""
        if self._path is None or index + 1 >= len(self._path):
            return False
        outgoing = self._path[index + 1] - self._path[index]
        a, b = float(np.linalg.norm(incoming)), float(np.linalg.norm(outgoing))
        if a < 1e-9 or b < 1e-9:
            return False
        cos = float(np.dot(incoming, outgoing)) / (a * b)
        return math.acos(max(-1.0, min(1.0, cos))) > self.TURN_ANGLE


class SimulatedWorld:
    """A scene, a kinematic robot in it, and objects that pick and release move.

    Parameters
    ----------
    scene: the world.
    max_speed: robot speed [m/s].
    reach: how far from an object's box [m] the robot may pick it or release onto it (by
        default the nearness threshold: where the task says the robot is near it).
    max_pick_size: objects larger than this on any axis [m] cannot be picked.
    """

    def __init__(self, scene: Scene, max_speed: float = 1.0, reach: float = near.DEFAULT_NEAR_THRESHOLD,
                 max_pick_size: float = 1.0) -> None:
        self.scene = scene
        self.robot = KinematicRobot(scene.robot.start, max_speed=max_speed,
                                    planar=scene.robot.kind == 'ground')
        self.reach = float(reach)
        self.max_pick_size = float(max_pick_size)
        self._objects: dict[str, SceneObject] = {o.id: o for o in scene.objects}
        self.carried: Optional[str] = None
        self._carry_offset = np.zeros(3)

    # ------------------------------------------------------------------ objects
    def objects(self) -> tuple[SceneObject, ...]:
        """Every object at its current position (a carried one moves with the robot)."""
        return tuple(self._objects.values())

    def current_scene(self) -> Scene:
        """Return the scene with objects at their current positions (for the camera)."""
        return replace(self.scene, objects=self.objects())

    def step(self, dt: float) -> Pose:
        """Advance the robot ``dt`` [s]; a carried object moves with it."""
        pose = self.robot.step(dt)
        if self.carried is not None:
            o = self._objects[self.carried]
            c = pose.xyz + self._carry_offset
            self._objects[self.carried] = replace(o, center=tuple(float(v) for v in c))
        return pose

    def _distance_to(self, o: SceneObject, point: np.ndarray) -> float:
        dims = 3 if self.scene.robot.kind == 'drone' else 2
        size = o.size if o.size is not None else (0.0, 0.0, 0.0)
        return float(near.box_distance(point, np.asarray([o.center]), np.asarray([size]), dims)[0])

    def find_object(self, object_id: str = '', near_point: Optional[Sequence[float]] = None,
                    name: str = '') -> Optional[SceneObject]:
        """Find the object ``object_id``, else the one matching ``name`` nearest ``near_point``.

        ``name`` is a snake_case descriptor name (``plush_toy`` matches ``green plush toy``).
        """
        if object_id in self._objects:
            return self._objects[object_id]
        candidates = list(self._objects.values())
        if name:
            words = set(name.split('_'))
            candidates = [o for o in candidates if words <= set(o.id.split('_'))]
        if not candidates:
            return None
        if near_point is None:
            return candidates[0] if len(candidates) == 1 else None
        p = np.asarray(near_point, dtype=float)
        return min(candidates, key=lambda o: float(np.linalg.norm(np.asarray(o.center) - p)))

    def pick(self, obj: Optional[SceneObject]) -> SkillOutcome:
        """Pick ``obj`` up if the robot is within reach, holds nothing, and it is small enough."""
        if obj is None:
            return SkillOutcome('pick', '', '', False, ErrorCode.UNKNOWN_REFERENT.value,
                                'no such object in the simulated world')
        if self.carried is not None:
            return SkillOutcome('pick', obj.id, '', False, ErrorCode.SKILL_FAILED.value,
                                f'already carrying {self.carried}')
        if obj.size is not None and max(obj.size) > self.max_pick_size:
            return SkillOutcome('pick', obj.id, '', False, ErrorCode.SKILL_FAILED.value,
                                f'{obj.id} is too large to pick ({max(obj.size):.2f} m)')
        d = self._distance_to(obj, self.robot.pose.xyz)
        if not near.is_near(d, self.reach):
            return SkillOutcome('pick', obj.id, '', False, ErrorCode.SKILL_FAILED.value,
                                f'{obj.id} is out of reach ({d:.2f} m > {self.reach:.2f} m)')
        self.carried = obj.id
        height = obj.size[2] if obj.size is not None else 0.0
        # carried on top of the robot's body
        self._carry_offset = np.array([0.0, 0.0, 0.5 + height / 2.0])
        self._objects[obj.id] = replace(obj, on=None)
        self.step(1e-9)
        return SkillOutcome('pick', obj.id, '', True, '', f'picked {obj.id}')

    def release(self, obj: Optional[SceneObject], target: Optional[SceneObject]) -> SkillOutcome:
        """Put the carried ``obj`` on ``target`` if the robot is within reach of it."""
        oid = obj.id if obj is not None else ''
        if obj is None or self.carried != obj.id:
            return SkillOutcome('release', oid, target.id if target else '', False,
                                ErrorCode.SKILL_FAILED.value,
                                f'not carrying {oid or "that object"} (carrying {self.carried})')
        if target is None:
            return SkillOutcome('release', oid, '', False, ErrorCode.UNKNOWN_REFERENT.value,
                                'no such release target in the simulated world')
        d = self._distance_to(target, self.robot.pose.xyz)
        if not near.is_near(d, self.reach):
            return SkillOutcome('release', oid, target.id, False, ErrorCode.SKILL_FAILED.value,
                                f'{target.id} is out of reach ({d:.2f} m > {self.reach:.2f} m)')
        top = target.center[2] + (target.size[2] / 2.0 if target.size is not None else 0.0)
        half = obj.size[2] / 2.0 if obj.size is not None else 0.0
        self._objects[oid] = replace(obj, center=(target.center[0], target.center[1], top + half),
                                     on=target.label)
        self.carried = None
        return SkillOutcome('release', oid, target.id, True, '', f'released {oid} on {target.id}')


@dataclass(frozen=True)
class OccupancyRaster:
    """A 2D occupancy grid: ``cells`` (H, W) int8, 100 occupied / 0 free, row-major from ``origin``.

    Attributes
    ----------
    cells: occupancy values, shape (height, width); cell (r, c) covers
        x in [origin_x + c*res, origin_x + (c+1)*res), y likewise with r.
    resolution: cell size [m].
    origin: (x, y) of the corner of cell (0, 0) [m].
    """

    cells: np.ndarray
    resolution: float
    origin: tuple[float, float]

    @property
    def width(self) -> int:
        """Number of columns (x)."""
        return int(self.cells.shape[1])

    @property
    def height(self) -> int:
        """Number of rows (y)."""
        return int(self.cells.shape[0])


def rasterize_scene(scene: Scene, resolution: float = 0.1) -> OccupancyRaster:
    """Rasterise the scene's blocking geometry (not inflated) into an occupancy grid.

    A cell is occupied (100) when its centre lies in a blocking box; for a drone the
    projection of every blocking box is drawn (a top view). Other cells are free (0).

    Raises
    ------
    InvalidInputError
        If ``resolution`` is not a positive number or the grid would exceed 16 M cells.
    """
    if not resolution > 0.0 or not math.isfinite(resolution):
        raise InvalidInputError(f'map resolution must be positive, got {resolution}')
    lo = np.asarray(scene.bounds_min[:2], dtype=float)
    hi = np.asarray(scene.bounds_max[:2], dtype=float)
    w, h = (int(math.ceil(v)) for v in (hi - lo) / resolution)
    if w * h > 16_000_000:
        raise LtlInstructError(f'map of {w}x{h} cells is too large', ErrorCode.LIMIT_EXCEEDED)
    cells = np.zeros((h, w), dtype=np.int8)
    xs = lo[0] + (np.arange(w) + 0.5) * resolution
    ys = lo[1] + (np.arange(h) + 0.5) * resolution
    for box in scene.blocking_boxes():
        bl, bh = box.lo[:2], box.hi[:2]
        cols = np.nonzero((xs >= bl[0]) & (xs <= bh[0]))[0]
        rows = np.nonzero((ys >= bl[1]) & (ys <= bh[1]))[0]
        if cols.size and rows.size:
            cells[rows[0]:rows[-1] + 1, cols[0]:cols[-1] + 1] = 100
    return OccupancyRaster(cells, float(resolution), (float(lo[0]), float(lo[1])))


def obstacle_points(scene: Scene, spacing: float = 1.0) -> np.ndarray:
    """Points [m] filling every blocking box on a grid of ``spacing``, shape (N, 3) float32.

    The 3D map a drone's planner reads (``map_cloud``); each box contributes at least
    its corners and centre, so thin boxes are never lost.
    """
    if not spacing > 0.0:
        raise InvalidInputError(f'spacing must be positive, got {spacing}')
    chunks = []
    for box in scene.blocking_boxes():
        axes = [np.linspace(lo, hi, max(2, int(math.ceil((hi - lo) / spacing)) + 1))
                for lo, hi in zip(box.lo, box.hi)]
        g = np.stack(np.meshgrid(*axes, indexing='ij'), axis=-1).reshape(-1, 3)
        chunks.append(g)
        chunks.append(np.asarray(box.center, dtype=float)[None, :])
    if not chunks:
        return np.zeros((0, 3), dtype=np.float32)
    return np.concatenate(chunks).astype(np.float32)

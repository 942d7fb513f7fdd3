"""The collision model the planner uses: free space of a robot centre, from a scene or a map.

A :class:`PlanningWorld` holds the planning bounds (the robot centre stays inside
them), the static boxes the robot must not enter (as given, not inflated) and their
inflation by the robot radius, and optionally an occupancy lookup built from an
occupancy grid (2D) or an obstacle point cloud (3D). A ground robot plans in (x, y),
a drone in (x, y, z) inside its altitude band.

The robot is a disc (a ball for a drone) of the robot radius: a point is blocked where
it lies within the radius of a box (Euclidean distance to the box, the boundary
blocked), so a box grows into a rounded box, not a bigger box, and a diagonal gap that
the disc fits through stays open. This is the plan check's own definition
(:mod:`~ltl_instruct.core.planning.verify`) and the occupancy grid's (a Euclidean
distance transform). Boxes are indexed once per world by the (x, y) cells their
rounded boxes overlap, so point and segment checks test a few boxes exactly
(:func:`~ltl_instruct.core.world.near.segment_box_distance` for a segment). Besides
"is this point free", the world gives a *clearance*: a radius around a free point
inside which every point is free, which lets edge checks skip through open space
exactly and still sample finely near obstacles. Units are metres, in the ``map`` frame.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np
from scipy import ndimage

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world import near
from ltl_instruct.core.world.scene import Box, Scene

MAX_LOOKUP_CELLS = 40_000_000


@dataclass(frozen=True, eq=False)
class OccupancyLookup:
    """An inflated occupancy grid: ``blocked[i_x, i_y(, i_z)]`` is True where the centre may not be.

    Attributes
    ----------
    blocked: bool array, shape (nx, ny) or (nx, ny, nz), indexed x first.
    origin: corner of cell 0 [m], shape (dims,).
    resolution: cell size [m].
    """

    blocked: np.ndarray
    origin: tuple[float, ...]
    resolution: float

    def is_blocked(self, points: np.ndarray) -> np.ndarray:
        """Whether points (N, dims) fall in a blocked cell (outside the grid counts as blocked)."""
        p = np.atleast_2d(points)[:, :self.blocked.ndim]
        idx = np.floor((p - np.asarray(self.origin)) / self.resolution).astype(np.int64)
        shape = np.asarray(self.blocked.shape)
        inside = np.all((idx >= 0) & (idx < shape), axis=1)
        out = np.ones(len(p), dtype=bool)
        if inside.any():
            ii = idx[inside]
            out[inside] = self.blocked[tuple(ii.T)]
        return out


@dataclass(frozen=True, eq=False)
class PlanningWorld:
    """Where the robot centre may be.

    Attributes
    ----------
    dims: 2 (ground: x, y) or 3 (drone: x, y, z).
    bounds_min, bounds_max: the box the robot centre stays in [m], each shape (dims,).
    robot_radius: the robot's radius [m]: the centre stays farther than this from every box.
    obstacles: blocking boxes as given (not inflated).
    lookup: optional inflated occupancy grid (from a map message).
    """

    dims: int
    bounds_min: tuple[float, ...]
    bounds_max: tuple[float, ...]
    robot_radius: float = 0.3
    obstacles: tuple[Box, ...] = ()
    lookup: Optional[OccupancyLookup] = None
    _lo: np.ndarray = field(init=False, repr=False)
    _hi: np.ndarray = field(init=False, repr=False)
    _boxes: tuple = field(init=False, repr=False)      # bounding boxes of the rounded boxes
    _raw: tuple = field(init=False, repr=False)        # the boxes as given, (lo, hi) per box
    _raw_lo: np.ndarray = field(init=False, repr=False)
    _raw_hi: np.ndarray = field(init=False, repr=False)
    _cell: tuple = field(init=False, repr=False)       # (cell size [m], nx, ny) of the box index
    _buckets: tuple = field(init=False, repr=False)    # per (x, y) cell: indices of the boxes over it

    def __post_init__(self) -> None:
        if self.dims not in (2, 3):
            raise InvalidInputError(f'planning dimension must be 2 or 3, got {self.dims}')
        lo_b = np.asarray(self.bounds_min, dtype=float)
        hi_b = np.asarray(self.bounds_max, dtype=float)
        if lo_b.shape != (self.dims,) or hi_b.shape != (self.dims,) or not np.all(np.isfinite(lo_b)) \
                or not np.all(np.isfinite(hi_b)) or np.any(lo_b > hi_b):
            raise InvalidInputError(f'bad planning bounds {self.bounds_min} .. {self.bounds_max}')
        r = float(self.robot_radius)
        if not (math.isfinite(r) and r >= 0.0):
            raise InvalidInputError(f'robot radius must be a non-negative number, got {self.robot_radius}')
        if self.obstacles:
            raw_lo = np.array([b.lo[:self.dims] for b in self.obstacles], dtype=float)
            raw_hi = np.array([b.hi[:self.dims] for b in self.obstacles], dtype=float)
        else:
            raw_lo = np.zeros((0, self.dims))
            raw_hi = np.zeros((0, self.dims))
        lo, hi = raw_lo - r, raw_hi + r
        object.__setattr__(self, '_raw_lo', raw_lo)
        object.__setattr__(self, '_raw_hi', raw_hi)
        raw = tuple((tuple(a), tuple(b)) for a, b in zip(raw_lo.tolist(), raw_hi.tolist()))
        object.__setattr__(self, '_raw', raw)
        object.__setattr__(self, '_lo', lo)
        object.__setattr__(self, '_hi', hi)
        boxes = tuple((tuple(a), tuple(b)) for a, b in zip(lo.tolist(), hi.tolist()))
        object.__setattr__(self, '_boxes', boxes)
        self._build_cell_index()

    def _build_cell_index(self) -> None:
        """Bucket the inflated boxes by the (x, y) cells they overlap, for point queries.

        About 4,000 cells over the bounds (at least 0.25 m each, and at most 4,097 along
        either axis); a point is tested only
        against the boxes of its cell, so a validity check costs a few box tests, not one
        per obstacle.
        """
        span = [max(self.bounds_max[k] - self.bounds_min[k], 1e-6) for k in range(2)]
        cell = max(0.25, math.sqrt(span[0] * span[1] / 4096.0), max(span) / 4096.0)   # a thin map too
        nx, ny = (int(math.ceil(span[k] / cell)) + 1 for k in range(2))
        buckets: list[list[int]] = [[] for _ in range(nx * ny)]
        for i, (lo, hi) in enumerate(self._boxes):
            x0, y0 = self._cell_of(lo[0], lo[1], cell, nx, ny)
            x1, y1 = self._cell_of(hi[0], hi[1], cell, nx, ny)
            for cx in range(x0, x1 + 1):
                for cy in range(y0, y1 + 1):
                    buckets[cx * ny + cy].append(i)
        object.__setattr__(self, '_cell', (cell, nx, ny))
        object.__setattr__(self, '_buckets', tuple(tuple(b) for b in buckets))

    def _cell_of(self, x: float, y: float, cell: float, nx: int, ny: int) -> tuple[int, int]:
        cx = min(nx - 1, max(0, int((x - self.bounds_min[0]) // cell)))
        cy = min(ny - 1, max(0, int((y - self.bounds_min[1]) // cell)))
        return cx, cy

    # ------------------------------------------------------------------ vectorised
    @property
    def inflated_boxes(self) -> tuple[np.ndarray, np.ndarray]:
        """Corners ``(lo, hi)`` [m] of the bounding boxes of the rounded obstacles, each shape (K, dims)."""
        return self._lo, self._hi

    def box_gap(self, points: np.ndarray) -> np.ndarray:
        """Distance [m] from each point (N, >=dims) to the nearest box as given; shape (N,), inf if none.

        Boxes out of the radius of the points' bounding box are skipped: a point farther
        than the radius from every box may get any distance above the radius instead.
        """
        p = np.atleast_2d(np.asarray(points, dtype=float))[:, :self.dims]
        out = np.full(len(p), np.inf)
        if not len(self._raw_lo) or not len(p):
            return out
        finite = p[np.all(np.isfinite(p), axis=1)]
        if not len(finite):
            return out
        lo, hi = finite.min(axis=0), finite.max(axis=0)   # only boxes within reach of the points
        near_pts = np.all((self._lo <= hi) & (self._hi >= lo), axis=1)
        if not near_pts.all():
            out[:] = self.robot_radius + 1.0       # farther than the radius from every box
        raw_lo, raw_hi = self._raw_lo[near_pts], self._raw_hi[near_pts]
        if not len(raw_lo):
            return out
        step = max(1, 2_000_000 // (len(raw_lo) * self.dims))   # bounded memory
        for s in range(0, len(p), step):
            q = p[s:s + step, None, :]
            gap = np.maximum(np.maximum(raw_lo[None] - q, q - raw_hi[None]), 0.0)
            out[s:s + step] = np.minimum(out[s:s + step], np.sqrt((gap * gap).sum(axis=2).min(axis=1)))
        return out

    def in_bounds(self, points: np.ndarray) -> np.ndarray:
        """Whether points (N, >=dims) lie inside the planning bounds."""
        p = np.atleast_2d(np.asarray(points, dtype=float))[:, :self.dims]
        return np.all((p >= np.asarray(self.bounds_min)) & (p <= np.asarray(self.bounds_max)), axis=1) \
            & np.all(np.isfinite(p), axis=1)

    def is_free(self, points: np.ndarray) -> np.ndarray:
        """Whether the robot centre may be at each point (N, >=dims): in bounds, clear of every box."""
        p = np.atleast_2d(np.asarray(points, dtype=float))[:, :self.dims]
        ok = self.in_bounds(p)
        if len(self._lo):
            ok &= self.box_gap(p) > self.robot_radius
        if self.lookup is not None:
            ok &= ~self.lookup.is_blocked(p)
        return ok

    # ------------------------------------------------------------------ scalar (planner callbacks)
    def point_free(self, p: Sequence[float]) -> bool:
        """Whether the robot centre may be at ``p``: in bounds and farther than the radius from every box.

        The same answer as ``clearance(p) >= 0``, from the boxes of ``p``'s cell only.
        """
        d = self.dims
        for k in range(d):
            if not (self.bounds_min[k] <= p[k] <= self.bounds_max[k]):
                return False
        cell, nx, ny = self._cell
        cx, cy = self._cell_of(p[0], p[1], cell, nx, ny)
        boxes, raw, r2 = self._boxes, self._raw, self.robot_radius ** 2
        for i in self._buckets[cx * ny + cy]:
            lo, hi = boxes[i]
            if all(lo[k] <= p[k] <= hi[k] for k in range(d)) \
                    and near.point_distance(p, raw[i:i + 1]) ** 2 <= r2:
                return False
        if self.lookup is not None and self.lookup.is_blocked(np.asarray(p[:d], dtype=float)[None])[0]:
            return False
        return True

    def clearance(self, p: Sequence[float]) -> float:
        """Return a radius [m] around ``p`` in which every point is free; -1 if ``p`` is not free.

        Exact for bounds and boxes (distance to the nearest box less the robot radius, or
        to a bound); an occupancy lookup gives 0 for a free point (its cells are checked
        one by one).
        """
        d = self.dims
        best = math.inf
        for k in range(d):
            x = p[k]
            if not (self.bounds_min[k] <= x <= self.bounds_max[k]):
                return -1.0
            best = min(best, x - self.bounds_min[k], self.bounds_max[k] - x)
        to_box = near.point_distance(p, self._raw) - self.robot_radius   # at the radius counts as inside
        if to_box <= 0.0:
            return -1.0
        best = min(best, to_box)
        if self.lookup is not None:
            if self.lookup.is_blocked(np.asarray(p[:d], dtype=float)[None])[0]:
                return -1.0
            best = 0.0  # free, but no certified radius: the caller samples finely
        return best

    def nearest_free(self, p: Sequence[float], max_distance: float,
                     step: float = 0.01) -> Optional[np.ndarray]:
        """Return the free point nearest ``p`` [m] within ``max_distance`` [m] (to ``step``), or None.

        ``p`` itself when it is free; else the first free point on circles (2D) or spheres
        (3D) of radius ``step``, ``2 step``... around it, each sampled about ``step`` apart.
        """
        c = np.asarray(p, dtype=float)[:self.dims]
        if self.is_free(c[None])[0]:
            return c
        for r in np.arange(step, max_distance + step / 2, step):
            ring = c + r * _directions(self.dims, max(8, int(math.ceil(2 * math.pi * r / step))))
            free = np.flatnonzero(self.is_free(ring))
            if len(free):
                return ring[free[0]]
        return None

    def _boxes_over(self, lo: Sequence[float], hi: Sequence[float]) -> Sequence[int]:
        """Return indices of the boxes that may overlap the (x, y) rectangle lo..hi (a superset)."""
        cell, nx, ny = self._cell
        x0, y0 = self._cell_of(lo[0], lo[1], cell, nx, ny)
        x1, y1 = self._cell_of(hi[0], hi[1], cell, nx, ny)
        if (x1 - x0 + 1) * (y1 - y0 + 1) == 1:
            return self._buckets[x0 * ny + y0]
        if (x1 - x0 + 1) * (y1 - y0 + 1) > len(self._boxes):
            return range(len(self._boxes))
        out: set[int] = set()
        for cx in range(x0, x1 + 1):
            for cy in range(y0, y1 + 1):
                out.update(self._buckets[cx * ny + cy])
        return sorted(out)

    def segment_hits_box(self, a: Sequence[float], b: Sequence[float]) -> bool:
        """Whether the straight segment a -> b comes within the robot radius of a box (exact).

        A slab test against each candidate's bounding box first, then the segment's exact
        distance to the box.
        """
        d = self.dims
        seg_lo = [min(a[k], b[k]) for k in range(d)]
        seg_hi = [max(a[k], b[k]) for k in range(d)]
        for i in self._boxes_over(seg_lo, seg_hi):
            lo, hi = self._boxes[i]
            if any(seg_hi[k] < lo[k] or seg_lo[k] > hi[k] for k in range(d)):
                continue
            t0, t1 = 0.0, 1.0
            for k in range(d):
                delta = b[k] - a[k]
                if delta == 0.0:
                    if a[k] < lo[k] or a[k] > hi[k]:
                        t0, t1 = 1.0, 0.0
                        break
                    continue
                u = (lo[k] - a[k]) / delta
                v = (hi[k] - a[k]) / delta
                if u > v:
                    u, v = v, u
                t0 = max(t0, u)
                t1 = min(t1, v)
                if t0 > t1:
                    break
            if t0 <= t1 and near.segment_box_distance(a, b, *self._raw[i]) <= self.robot_radius:
                return True
        return False


def _directions(dims: int, around: int) -> np.ndarray:
    """Return unit vectors, evenly spread: ``around`` on a circle (2D), or about as dense on a sphere (3D)."""
    if dims == 2:
        a = np.arange(around) * (2 * math.pi / around)
        return np.column_stack([np.cos(a), np.sin(a)])
    n = max(2, around * around // 3)   # a Fibonacci sphere: spacing about that of the circle
    z = 1.0 - (np.arange(n) + 0.5) * (2.0 / n)
    a = np.arange(n) * math.pi * (3.0 - math.sqrt(5.0))
    rho = np.sqrt(1.0 - z * z)
    return np.column_stack([rho * np.cos(a), rho * np.sin(a), z])


# --------------------------------------------------------------------------- factories

def world_from_scene(scene: Scene, robot_radius: Optional[float] = None) -> PlanningWorld:
    """Build the planning world of a scene: its blocking boxes, inflated by the robot radius.

    A ground robot plans in (x, y) inside the scene bounds shrunk by its radius; a drone
    in (x, y, z) with z inside its altitude band (or the scene's z bounds).
    """
    r = scene.robot.radius if robot_radius is None else float(robot_radius)
    dims = scene.robot.dims
    lo = [scene.bounds_min[k] + r for k in range(dims)]
    hi = [scene.bounds_max[k] - r for k in range(dims)]
    if dims == 3 and scene.altitude is not None:
        lo[2] = max(lo[2], scene.altitude[0])
        hi[2] = min(hi[2], scene.altitude[1])
    for k in range(dims):
        if lo[k] > hi[k]:
            raise InvalidInputError(f'{scene.source}: the robot (radius {r} m) does not fit in the bounds')
    return PlanningWorld(dims, tuple(lo), tuple(hi), r, scene.blocking_boxes())


def _inflate(blocked: np.ndarray, resolution: float, radius: float) -> np.ndarray:
    """Grow blocked cells by ``radius`` [m] (Euclidean, between cell centres)."""
    if radius <= 0.0 or not blocked.any():
        return blocked
    dist = ndimage.distance_transform_edt(~blocked, sampling=resolution)
    return dist <= radius + 1e-9


def world_from_occupancy(cells: np.ndarray, resolution: float, origin: Sequence[float],
                         robot_radius: float = 0.3, occupied_threshold: int = 50) -> PlanningWorld:
    """Build a 2D world from an occupancy grid (``nav_msgs/OccupancyGrid`` layout).

    Parameters
    ----------
    cells: occupancy values, shape (height, width): row r is y, column c is x; values
        >= ``occupied_threshold`` and unknown (< 0) cells are blocked.
    resolution: cell size [m].
    origin: (x, y) of the corner of cell (0, 0) [m].
    robot_radius: inflation [m].
    """
    grid = np.asarray(cells)
    if grid.ndim != 2 or grid.size == 0:
        raise InvalidInputError(f'an occupancy grid must be a non-empty 2D array, got shape {grid.shape}')
    if not (resolution > 0 and math.isfinite(resolution)):
        raise InvalidInputError(f'map resolution must be positive, got {resolution}')
    if grid.size > MAX_LOOKUP_CELLS:
        raise InvalidInputError(f'the map has {grid.size} cells, more than {MAX_LOOKUP_CELLS}')
    ox, oy = float(origin[0]), float(origin[1])
    blocked = ((grid >= occupied_threshold) | (grid < 0)).T  # x first
    blocked = _inflate(blocked, resolution, float(robot_radius))
    nx, ny = blocked.shape
    lookup = OccupancyLookup(blocked, (ox, oy), float(resolution))
    return PlanningWorld(2, (ox, oy), (ox + nx * resolution - 1e-9, oy + ny * resolution - 1e-9),
                         float(robot_radius), (), lookup)


def world_from_points(points: np.ndarray, voxel: float = 0.2, robot_radius: float = 0.3,
                      bounds_min: Optional[Sequence[float]] = None,
                      bounds_max: Optional[Sequence[float]] = None) -> PlanningWorld:
    """Build a 3D world from obstacle points (a drone's map cloud), voxelised and inflated.

    Parameters
    ----------
    points: obstacle points [m], shape (N, 3).
    voxel: voxel size [m].
    robot_radius: inflation [m].
    bounds_min, bounds_max: planning bounds [m], shape (3,); default: the points' extent
        grown by one voxel.
    """
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    p = p[np.all(np.isfinite(p), axis=1)]
    if len(p) == 0:
        raise InvalidInputError('the 3D map has no finite points')
    if not (voxel > 0 and math.isfinite(voxel)):
        raise InvalidInputError(f'voxel size must be positive, got {voxel}')
    lo = np.asarray(bounds_min, dtype=float) if bounds_min is not None else p.min(axis=0) - voxel
    hi = np.asarray(bounds_max, dtype=float) if bounds_max is not None else p.max(axis=0) + voxel
    shape = np.ceil((hi - lo) / voxel).astype(int) + 1
    if np.prod(shape.astype(float)) > MAX_LOOKUP_CELLS:
        raise InvalidInputError(f'the 3D map would need {int(np.prod(shape))} voxels; use a larger voxel')
    blocked = np.zeros(tuple(shape), dtype=bool)
    idx = np.floor((p - lo) / voxel).astype(int)
    keep = np.all((idx >= 0) & (idx < shape), axis=1)
    blocked[tuple(idx[keep].T)] = True
    blocked = _inflate(blocked, voxel, float(robot_radius))
    return PlanningWorld(3, tuple(lo.tolist()), tuple(hi.tolist()), float(robot_radius), (),
                         OccupancyLookup(blocked, tuple(lo.tolist()), float(voxel)))

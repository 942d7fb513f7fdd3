"""What a ground robot's camera has covered, in the plane: seen cells, frontiers, view gain, travel fields.

The search (:mod:`search`) reads the voxel :class:`SemanticMap` through this module as a
2D grid over the scene's bounds (``cell`` [m] square cells, index ``[ix, iy]``):

- a cell is *seen* when a voxel of its column between ``band`` heights was observed
  (free or a surface);
- a cell *blocks sight* when a voxel of its column at the camera's height holds a
  surface (walls; tables and chairs are seen over);
- a *frontier* is a seen cell that does not block sight, next to a cell not seen.

The gain of a view pose is the number of unseen cells a ray from it reaches within the
sensor range before it meets a cell that blocks sight (unseen cells let rays through:
the estimate is optimistic, as frontier exploration usually is). Travel fields are
8-connected shortest-path distances [m] over the cells a robot may stand in.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np
from scipy import ndimage
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.semantic_map import SemanticMap


@dataclass(frozen=True)
class PlaneGrid:
    """A 2D grid over the bounds: ``origin`` [m] of cell [0, 0]'s corner, ``cell`` [m], ``shape`` (nx, ny)."""

    origin: tuple[float, float]
    cell: float
    shape: tuple[int, int]

    @staticmethod
    def over(bounds_min: Sequence[float], bounds_max: Sequence[float], cell: float) -> 'PlaneGrid':
        """Return the grid that covers the (x, y) box of some bounds [m]."""
        nx = max(1, int(math.ceil((bounds_max[0] - bounds_min[0]) / cell)))
        ny = max(1, int(math.ceil((bounds_max[1] - bounds_min[1]) / cell)))
        return PlaneGrid((float(bounds_min[0]), float(bounds_min[1])), float(cell), (nx, ny))

    def centers(self) -> np.ndarray:
        """Cell centres [m], shape (nx, ny, 2)."""
        xs = self.origin[0] + (np.arange(self.shape[0]) + 0.5) * self.cell
        ys = self.origin[1] + (np.arange(self.shape[1]) + 0.5) * self.cell
        return np.stack(np.meshgrid(xs, ys, indexing='ij'), axis=-1)

    def index(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Cell indices (ix, iy) of points (N, >=2) [m], clipped into the grid."""
        p = np.atleast_2d(np.asarray(points, dtype=float))
        ix = np.clip(((p[:, 0] - self.origin[0]) / self.cell).astype(np.int64), 0, self.shape[0] - 1)
        iy = np.clip(((p[:, 1] - self.origin[1]) / self.cell).astype(np.int64), 0, self.shape[1] - 1)
        return ix, iy


def _column_any(smap: SemanticMap, grid: PlaneGrid, mask: np.ndarray, z_lo: float, z_hi: float) -> np.ndarray:
    """Cells (nx, ny) of ``grid`` over which some voxel of ``mask`` has its centre height in [z_lo, z_hi]."""
    out = np.zeros(grid.shape, dtype=bool)
    if not mask.size:
        return out
    vs = smap.params.voxel_size
    z = (np.arange(mask.shape[2]) + smap.origin[2] + 0.5) * vs
    band = (z >= z_lo) & (z <= z_hi)
    if not band.any():
        return out
    cols = np.argwhere(mask[:, :, band].any(axis=2))
    if cols.size == 0:
        return out
    ix, iy = grid.index((cols + smap.origin[:2] + 0.5) * vs)
    out[ix, iy] = True
    return out


def seen_cells(smap: SemanticMap, grid: PlaneGrid, band: tuple[float, float] = (0.3, 1.8)) -> np.ndarray:
    """Cells whose column was observed between ``band`` heights [m]; bool (nx, ny)."""
    return _column_any(smap, grid, smap.observed, band[0], band[1])


def sight_blocking_cells(smap: SemanticMap, grid: PlaneGrid, eye_height: float) -> np.ndarray:
    """Cells with a surface at the camera's height (within 0.15 m) [m]; bool (nx, ny)."""
    return _column_any(smap, grid, smap.occupied, eye_height - 0.15, eye_height + 0.15)


def frontier_cells(seen: np.ndarray, blocks: np.ndarray) -> np.ndarray:
    """Seen cells that do not block sight, with an unseen 8-neighbour; bool (nx, ny)."""
    unseen = ndimage.binary_dilation(~seen, structure=np.ones((3, 3), dtype=bool))
    return seen & ~blocks & unseen


def view_gain(points: np.ndarray, grid: PlaneGrid, seen: np.ndarray, blocks: np.ndarray,
              sensor_range: float, rays: int = 72) -> np.ndarray:
    """Unseen cells visible from each view point (K, >=2) [m] within ``sensor_range`` [m]; int (K,)."""
    p = np.atleast_2d(np.asarray(points, dtype=float))[:, :2]
    if len(p) == 0:
        return np.zeros(0, dtype=np.int64)
    a = np.linspace(0.0, 2.0 * math.pi, rays, endpoint=False)
    steps = np.arange(1, int(sensor_range / (grid.cell * 0.5)) + 1) * grid.cell * 0.5
    d = np.stack([np.cos(a), np.sin(a)], axis=-1)
    pts = p[:, None, None, :] + d[None, :, None, :] * steps[None, None, :, None]   # (K, R, S, 2)
    lo = np.asarray(grid.origin)
    hi = lo + np.asarray(grid.shape) * grid.cell
    inside = np.all((pts >= lo) & (pts < hi), axis=-1)
    ix, iy = grid.index(pts.reshape(-1, 2))
    ix, iy = ix.reshape(inside.shape), iy.reshape(inside.shape)
    stopped = np.maximum.accumulate(blocks[ix, iy] | ~inside, axis=2)
    hit = ~stopped & ~seen[ix, iy]
    flat = ix * grid.shape[1] + iy
    k = np.broadcast_to(np.arange(len(p))[:, None, None], hit.shape)
    pairs = np.unique(k[hit] * (grid.shape[0] * grid.shape[1]) + flat[hit])
    return np.bincount(pairs // (grid.shape[0] * grid.shape[1]), minlength=len(p))


def travel_field(free: np.ndarray, grid: PlaneGrid, start: Sequence[float]) -> np.ndarray:
    """Return the 8-connected travel [m] from ``start`` over ``free`` cells (nx, ny); inf: unreachable."""
    nx, ny = free.shape
    ids = np.arange(nx * ny).reshape(nx, ny)
    rows, cols, w = [], [], []
    for dx, dy in ((1, 0), (0, 1), (1, 1), (1, -1)):
        x0, x1, y0, y1 = max(0, -dx), nx - max(0, dx), max(0, -dy), ny - max(0, dy)
        a, b = ids[x0:x1, y0:y1], ids[x0 + dx:x1 + dx, y0 + dy:y1 + dy]
        ok = free.ravel()[a.ravel()] & free.ravel()[b.ravel()]
        rows.append(a.ravel()[ok])
        cols.append(b.ravel()[ok])
        w.append(np.full(int(ok.sum()), math.hypot(dx, dy) * grid.cell))
    graph = coo_matrix((np.concatenate(w), (np.concatenate(rows), np.concatenate(cols))),
                       shape=(nx * ny, nx * ny)).tocsr()
    cells, offsets = _start_cells(free, grid, start)
    dist = np.atleast_2d(dijkstra(graph, directed=False, indices=[int(ids[c]) for c in cells]))
    return (dist + offsets[:, None]).min(axis=0).reshape(nx, ny)


def _start_cells(free: np.ndarray, grid: PlaneGrid, start: Sequence[float],
                 rings: int = 3) -> tuple[list[tuple[int, int]], np.ndarray]:
    """Return the cells travel starts from and the distance [m] to each: the start's own cell if free.

    A robot whose disc clears every obstacle may still sit in a cell whose centre does
    not (near a corner); travel then starts from the free cells within ``rings`` cells.
    """
    ix, iy = grid.index(np.asarray([start], dtype=float))
    x, y = int(ix[0]), int(iy[0])
    if free[x, y]:
        return [(x, y)], np.zeros(1)
    centres = grid.centers()
    for k in range(1, rings + 1):
        cells = [(i, j) for i in range(max(0, x - k), min(free.shape[0], x + k + 1))
                 for j in range(max(0, y - k), min(free.shape[1], y + k + 1)) if free[i, j]]
        if cells:
            off = np.array([float(np.hypot(*(centres[i, j][:2] - np.asarray(start[:2], dtype=float))))
                            for i, j in cells])
            return cells, off
    return [(x, y)], np.zeros(1)


UNSEEN, SEEN, BLOCKS_SIGHT = -1, 0, 100
"""Cell values of a coverage grid as a message carries it (``nav_msgs/OccupancyGrid`` style)."""


@dataclass(frozen=True, eq=False)
class Coverage:
    """What a camera has covered in the plane: ``seen`` and ``blocks`` (bool (nx, ny)) over ``grid``."""

    grid: PlaneGrid
    seen: np.ndarray
    blocks: np.ndarray

    @property
    def area_seen(self) -> float:
        """Floor area seen [m^2]."""
        return float(self.seen.sum()) * self.grid.cell ** 2

    def cells(self) -> np.ndarray:
        """Give each cell as int8 (nx, ny): ``UNSEEN``, ``SEEN`` or ``BLOCKS_SIGHT`` (seen, and it blocks)."""
        out = np.full(self.grid.shape, UNSEEN, dtype=np.int8)
        out[self.seen] = SEEN
        out[self.seen & self.blocks] = BLOCKS_SIGHT
        return out

    @staticmethod
    def from_cells(grid: PlaneGrid, cells: np.ndarray) -> 'Coverage':
        """Inverse of :meth:`cells` (any value other than ``SEEN`` or ``BLOCKS_SIGHT`` is unseen).

        Raises
        ------
        InvalidInputError
            When the cells' shape is not the grid's.
        """
        c = np.asarray(cells)
        if c.shape != grid.shape:
            raise InvalidInputError(f'coverage cells {c.shape} do not match the grid {grid.shape}')
        blocks = c == BLOCKS_SIGHT
        return Coverage(grid, (c == SEEN) | blocks, blocks)

    def on(self, grid: PlaneGrid) -> 'Coverage':
        """Return this coverage resampled onto another grid (by cell centre; outside: unseen)."""
        centers = grid.centers().reshape(-1, 2)
        lo = np.asarray(self.grid.origin)
        hi = lo + np.asarray(self.grid.shape) * self.grid.cell
        inside = np.all((centers >= lo) & (centers < hi), axis=1)
        ix, iy = self.grid.index(centers)
        seen = (self.seen[ix, iy] & inside).reshape(grid.shape)
        blocks = (self.blocks[ix, iy] & inside).reshape(grid.shape)
        return Coverage(grid, seen, blocks)


def map_coverage(smap: SemanticMap, eye_height: float, cell: Optional[float] = None) -> Coverage:
    """Return the coverage of a semantic map over its own (x, y) extent (``cell`` [m]: its voxel size)."""
    vs = smap.params.voxel_size
    size = float(cell or vs)
    if not smap.observed.size:
        return Coverage(PlaneGrid((0.0, 0.0), size, (1, 1)), np.zeros((1, 1), bool), np.zeros((1, 1), bool))
    lo = smap.origin[:2] * vs
    hi = (smap.origin[:2] + np.asarray(smap.shape[:2])) * vs
    grid = PlaneGrid.over(lo, hi, size)
    return Coverage(grid, seen_cells(smap, grid), sight_blocking_cells(smap, grid, eye_height))

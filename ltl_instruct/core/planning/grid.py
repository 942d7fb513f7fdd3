"""The fine-grid optimum of a segment, the yardstick of the planner's path lengths.

The segment's constraints (free, and ``allowed`` or ``goal`` holds) are evaluated at
the centres of a regular grid over the planning bounds (5 cm cells by default); cells
are joined to their 8 (2D) or 26 (3D) neighbours when every cell of the move's box is
valid, with Euclidean step costs, and Dijkstra finds the cheapest way from the start
into any goal cell. An 8-connected grid path is itself up to about 8 % longer than the
true shortest path, so a ratio of planner length to grid length near or below 1 means
the planner is close to optimal.

The same grid gives the planner a second candidate path in 2D (``grid_path``): FMT*'s
samples can miss a passage a few cells wide that the grid finds.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional

import numpy as np
from scipy.sparse import coo_matrix, csr_matrix
from scipy.sparse.csgraph import dijkstra

from ltl_instruct.core.errors import InvalidInputError

if TYPE_CHECKING:
    from ltl_instruct.core.planning.occupancy import PlanningWorld
    from ltl_instruct.core.planning.segment import SegmentProblem, SegmentRequest

MAX_GRID_CELLS = 3_000_000


@dataclass
class _Grid:
    """The grid of one segment: cell centres, goal cells and its moves, the start's last (node n)."""

    centres: np.ndarray
    goal: np.ndarray
    graph: csr_matrix


def _build(problem: SegmentProblem, start: np.ndarray, cell: float, max_cells: int,
           box: Optional[tuple[np.ndarray, np.ndarray]] = None) -> Optional[_Grid]:
    """Return the grid of ``problem`` from ``start``, or None when it has no cell or no move from the start.

    ``box`` (lo, hi) [m] limits the grid to part of the problem's bounds.

    Raises
    ------
    InvalidInputError
        If the grid would exceed ``max_cells`` cells.
    """
    dims = len(problem.lo)
    lo, hi = problem.lo, problem.hi
    if box is not None:
        lo, hi = np.maximum(lo, box[0]), np.minimum(hi, box[1])
    axes = [np.arange(lo[k] + cell / 2, hi[k], cell) for k in range(dims)]
    shape = tuple(len(a) for a in axes)
    n = int(np.prod(shape))
    if n == 0:
        return None
    if n > max_cells:
        raise InvalidInputError(f'grid of {n} cells is too large; use cells coarser than {cell} m')
    centres = np.stack(np.meshgrid(*axes, indexing='ij'), axis=-1).reshape(-1, dims)
    valid_flat, goal_flat = problem.classify(centres)
    valid = valid_flat.reshape(shape)
    index = np.arange(n).reshape(shape)
    rows, cols, costs = [], [], []
    offsets = [o for o in itertools.product((-1, 0, 1), repeat=dims) if o > (0,) * dims]
    for o in offsets:
        src = tuple(slice(max(0, -d), shape[k] - max(0, d)) for k, d in enumerate(o))
        ok = np.ones(tuple(s.stop - s.start for s in src), dtype=bool)
        # every cell of the move's box: the sub-offsets of o
        for sub in itertools.product(*[(0, d) if d else (0,) for d in o]):
            sl = tuple(slice(s.start + e, s.stop + e) for s, e in zip(src, sub))
            ok &= valid[sl]
        dst = tuple(slice(s.start + d, s.stop + d) for s, d in zip(src, o))
        rows.append(index[src][ok])
        cols.append(index[dst][ok])
        costs.append(np.full(int(ok.sum()), cell * math.sqrt(sum(d * d for d in o))))
    # join the start to the valid cells around it with straight, checked moves
    reach = 1.5 * cell * math.sqrt(dims)
    near = np.flatnonzero(valid_flat & (np.linalg.norm(centres - start, axis=1) <= reach))
    entries = [(int(i), float(np.linalg.norm(centres[i] - start))) for i in near
               if problem.motion_valid(tuple(start), tuple(centres[i]))]
    if not entries:
        return None
    rows.append(np.full(len(entries), n))
    cols.append(np.asarray([i for i, _ in entries]))
    costs.append(np.asarray([d for _, d in entries]))
    graph = coo_matrix((np.concatenate(costs), (np.concatenate(rows), np.concatenate(cols))),
                       shape=(n + 1, n + 1)).tocsr()
    return _Grid(centres, goal_flat, graph)


def _shortest(grid: _Grid) -> tuple[float, list[int]]:
    """Return the cost to the nearest goal cell and the cells of the way there, or (inf, []).

    Dijkstra from the start, a node joined to its moves.
    """
    n = len(grid.centres)
    dist, preds = dijkstra(grid.graph, directed=False, indices=n, return_predecessors=True)
    goal_cells = np.flatnonzero(grid.goal)
    if len(goal_cells) == 0 or not np.isfinite(dist[goal_cells].min()):
        return math.inf, []
    best = int(goal_cells[int(np.argmin(dist[goal_cells]))])
    chain = [best]
    while preds[chain[-1]] >= 0 and preds[chain[-1]] != n:
        chain.append(int(preds[chain[-1]]))
    return float(dist[best]), chain[::-1]


def grid_optimum(request: SegmentRequest, world: PlanningWorld, cell: float = 0.05) -> Optional[float]:
    """Length [m] of the shortest grid path of the segment, or None when the grid finds none.

    Raises
    ------
    InvalidInputError
        If the grid would exceed ``MAX_GRID_CELLS`` cells (use a coarser ``cell``).
    """
    from ltl_instruct.core.planning.segment import SegmentProblem
    problem = SegmentProblem(request, world)
    start = np.asarray(request.start[:world.dims], dtype=float)
    if problem.in_goal(tuple(start)):
        return 0.0
    grid = _build(problem, start, cell, MAX_GRID_CELLS)
    if grid is None:
        return None
    cost = _shortest(grid)[0]
    return cost if math.isfinite(cost) else None


def grid_path(problem: SegmentProblem, start: np.ndarray, cell: float, max_cells: int,
              box: Optional[tuple[np.ndarray, np.ndarray]] = None) -> Optional[np.ndarray]:
    """Waypoints of the shortest grid path from ``start`` into the goal (start, cell centres), or None.

    The grid covers ``box`` (lo, hi) [m] of the bounds when given. None also when the grid
    would exceed ``max_cells`` cells: the caller plans without it.
    """
    try:
        grid = _build(problem, np.asarray(start, dtype=float), cell, max_cells, box)
    except InvalidInputError:
        return None
    if grid is None:
        return None
    cost, chain = _shortest(grid)
    if not math.isfinite(cost):
        return None
    return np.vstack([np.asarray(start, dtype=float)[None], grid.centres[chain]])

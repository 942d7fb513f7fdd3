"""The fine-grid optimum of a segment, the yardstick of the planner's path lengths.

The segment's constraints (free, and ``allowed`` or ``goal`` holds) are evaluated at
the centres of a regular grid over the planning bounds (5 cm cells by default); cells
are joined to their 8 (2D) or 26 (3D) neighbours when every cell of the move's box is
valid, with Euclidean step costs, and Dijkstra finds the cheapest way from the start
into any goal cell. An 8-connected grid path is itself up to about 8 % longer than the
true shortest path, so a ratio of planner length to grid length near or below 1 means
the planner is close to optimal.
"""
from __future__ import annotations

import itertools
import math
from typing import Optional

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.segment import SegmentProblem, SegmentRequest

MAX_GRID_CELLS = 3_000_000


def grid_optimum(request: SegmentRequest, world: PlanningWorld, cell: float = 0.05) -> Optional[float]:
    """Length [m] of the shortest grid path of the segment, or None when the grid finds none.

    Raises
    ------
    InvalidInputError
        If the grid would exceed ``MAX_GRID_CELLS`` cells (use a coarser ``cell``).
    """
    problem = SegmentProblem(request, world)
    dims = world.dims
    lo, hi = problem.lo, problem.hi
    axes = [np.arange(lo[k] + cell / 2, hi[k], cell) for k in range(dims)]
    shape = tuple(len(a) for a in axes)
    n = int(np.prod(shape))
    if n == 0:
        return None
    if n > MAX_GRID_CELLS:
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
    r = np.concatenate(rows)
    c = np.concatenate(cols)
    w = np.concatenate(costs)
    graph = coo_matrix((w, (r, c)), shape=(n, n)).tocsr()
    start = np.asarray(request.start[:dims], dtype=float)
    if problem.in_goal(tuple(start)):
        return 0.0
    # join the start to the valid cells around it with straight, checked moves
    reach = 1.5 * cell * math.sqrt(dims)
    near = np.flatnonzero(valid_flat & (np.linalg.norm(centres - start, axis=1) <= reach))
    entries = [(int(i), float(np.linalg.norm(centres[i] - start))) for i in near
               if problem.motion_valid(tuple(start), tuple(centres[i]))]
    if not entries:
        return None
    dist = dijkstra(graph, directed=False, indices=[i for i, _ in entries])
    total = dist + np.asarray([d for _, d in entries])[:, None]
    best = total.min(axis=0)[goal_flat]
    if len(best) == 0 or not np.isfinite(best.min()):
        return None
    return float(best.min())

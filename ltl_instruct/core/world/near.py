"""The geometry of ``near[x]``: distance to instance boxes, the threshold, the margins.

``near[x]`` holds where the robot centre is within the nearness threshold [m] of the box
of any instance ``x`` resolved to: the Euclidean distance from the point to the box (0
inside it), in the plane for a ground robot (``dims=2``) and in space for a drone
(``dims=3``). A point object is a box of size 0. The boundary counts as near.

Every part of the package that asks "is the robot near x" measures with this module:
the planner's regions, the plan check, the execution monitor, the simulator's reach,
the grounding's instances and the pictures. They cannot disagree on a point.

Margins make plans that a controller can finish: a goal region is entered at least
``goal_margin`` deep (distance <= threshold - goal_margin), a region to avoid is passed
at least ``avoid_margin`` outside it (distance >= threshold + avoid_margin), where free
space allows. The depth of a point in a region is ``threshold - distance``.
"""
from __future__ import annotations

import math
from typing import Any, Iterable, Sequence

import numpy as np

from ltl_instruct.core.errors import InvalidInputError

DEFAULT_NEAR_THRESHOLD = 1.0
"""``near[x]`` radius [m] (LIMP uses about 1 m on the ground; the same serves drones)."""
DEFAULT_GOAL_MARGIN = 0.2
"""How deep [m] a planned path enters its goal region, where the region allows."""
DEFAULT_AVOID_MARGIN = 0.1
"""How far [m] outside a region to avoid a planned path stays, where free space allows."""
MAX_MARGIN = 10.0
"""Largest margin accepted [m]."""

Corners = tuple[tuple[tuple[float, ...], tuple[float, ...]], ...]


def check_threshold(value: Any, what: str = 'near_threshold') -> float:
    """Return a nearness threshold [m] as a float; raise ``INVALID_INPUT`` unless finite and > 0."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or value <= 0:
        raise InvalidInputError(f'{what} must be a positive number [m], got {value!r}')
    return float(value)


def check_margin(value: Any, what: str) -> float:
    """Return a margin [m] as a float; raise ``INVALID_INPUT`` unless in [0, ``MAX_MARGIN``]."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not 0.0 <= value <= MAX_MARGIN:
        raise InvalidInputError(f'{what} must be a number in [0, {MAX_MARGIN}] m, got {value!r}')
    return float(value)


def box_distance(points: np.ndarray, centers: np.ndarray, sizes: np.ndarray, dims: int) -> np.ndarray:
    """Distance [m] from each point to the nearest of some boxes (0 inside one).

    Parameters
    ----------
    points: shape (N, >= dims) or (>= dims,) [m].
    centers: box centres, shape (M, >= dims) [m].
    sizes: full box sizes, shape (M, >= dims) [m] (zeros for a point).
    dims: 2 (in the plane) or 3.

    Returns
    -------
    Shape (N,); ``inf`` everywhere when there is no box (M = 0).
    """
    p = np.atleast_2d(np.asarray(points, dtype=float))[:, :dims]
    c = np.asarray(centers, dtype=float)
    if c.size == 0:
        return np.full(len(p), np.inf)
    c = c.reshape(len(c), -1)[:, :dims]
    h = np.asarray(sizes, dtype=float).reshape(len(c), -1)[:, :dims] / 2.0
    gap = np.maximum(np.abs(p[:, None, :] - c[None]) - h[None], 0.0)
    return np.sqrt((gap ** 2).sum(axis=2)).min(axis=1)


def instances_distance(instances: Iterable[Any], points: np.ndarray, dims: int) -> np.ndarray:
    """Distance [m] from points (N, >= dims) to the nearest box of some instances; shape (N,).

    An instance is anything with ``center`` and ``size`` (each 3 numbers [m]).
    """
    boxes = list(instances)
    centers = np.asarray([b.center for b in boxes], dtype=float)
    sizes = np.asarray([b.size for b in boxes], dtype=float)
    return box_distance(points, centers, sizes, dims)


def is_near(distance: Any, threshold: float = DEFAULT_NEAR_THRESHOLD) -> Any:
    """Whether a distance [m] (a number or an array) is within the threshold: the ``near`` predicate."""
    return distance <= threshold


def near_instances(instances: Iterable[Any], points: np.ndarray, dims: int,
                   threshold: float = DEFAULT_NEAR_THRESHOLD) -> np.ndarray:
    """Whether each point (N, >= dims) is near any of the instances; shape (N,) bool."""
    return is_near(instances_distance(instances, points, dims), threshold)


def depth(distance: Any, threshold: float = DEFAULT_NEAR_THRESHOLD) -> Any:
    """How far [m] inside a near region a point at ``distance`` from the box lies (< 0 outside)."""
    return threshold - distance


def box_corners(centers: Sequence[Sequence[float]], sizes: Sequence[Sequence[float]],
                dims: int) -> Corners:
    """Return the (lo, hi) corners [m] of boxes, as plain tuples for :func:`point_distance`."""
    return tuple((tuple(c[k] - s[k] / 2.0 for k in range(dims)),
                  tuple(c[k] + s[k] / 2.0 for k in range(dims))) for c, s in zip(centers, sizes))


def point_distance(p: Sequence[float], corners: Corners) -> float:
    """Distance [m] from one point to the nearest box given by :func:`box_corners` (inf if none).

    Plain Python: one point at a time is the planner's edge check, where numpy's call
    overhead would dominate. Agrees with :func:`box_distance` to rounding.
    """
    best = math.inf
    for lo, hi in corners:
        s = _squared_box_distance(p, lo, hi)
        if s < best:
            best = s
    return math.sqrt(best) if best != math.inf else math.inf


def _squared_box_distance(p: Sequence[float], lo: Sequence[float], hi: Sequence[float]) -> float:
    """Squared distance [m^2] from one point to the box lo..hi (plain Python, for the hot loops)."""
    s = 0.0
    for k in range(len(lo)):
        x = p[k]
        if x < lo[k]:
            s += (lo[k] - x) ** 2
        elif x > hi[k]:
            s += (x - hi[k]) ** 2
    return s


def segment_box_distance(a: Sequence[float], b: Sequence[float], lo: Sequence[float],
                         hi: Sequence[float]) -> float:
    """Distance [m] between the straight segment a -> b and the box lo..hi (0 where they meet).

    Plain Python, for one segment at a time (the planner's edge check). The squared
    distance from the point at ``t`` in [0, 1] to the box is a convex piecewise quadratic
    in ``t``, its pieces split where an axis enters or leaves the box's slab: the least
    is at a piece's own minimum, clipped to the piece, so it is exact.
    """
    n = len(lo)
    d = [b[k] - a[k] for k in range(n)]
    ts = [0.0, 1.0]
    for k in range(n):
        if d[k] != 0.0:
            for edge in (lo[k], hi[k]):
                t = (edge - a[k]) / d[k]
                if 0.0 < t < 1.0:
                    ts.append(t)
    ts.sort()
    best = math.inf
    for t0, t1 in zip(ts, ts[1:]):
        tm = 0.5 * (t0 + t1)
        quad = lin = 0.0
        for k in range(n):
            x = a[k] + tm * d[k]
            if x < lo[k]:
                c = a[k] - lo[k]
            elif x > hi[k]:
                c = a[k] - hi[k]
            else:
                continue
            quad += d[k] * d[k]
            lin += c * d[k]
        t = t0 if quad == 0.0 else min(t1, max(t0, -lin / quad))
        s = _squared_box_distance([a[k] + t * d[k] for k in range(n)], lo, hi)
        if s < best:
            best = s
            if s == 0.0:
                break
    return math.sqrt(best)


def nearest_box_point(p: np.ndarray, center: Sequence[float], size: Sequence[float]) -> np.ndarray:
    """Return the point of a box nearest to ``p`` [m] (``p`` itself inside), shape of ``p``."""
    dims = len(p)
    c = np.asarray(center[:dims], dtype=float)
    h = np.asarray(size[:dims], dtype=float) / 2.0
    return np.clip(p, c - h, c + h)


def region_box(center: Sequence[float], size: Sequence[float], radius: float,
               dims: int) -> tuple[np.ndarray, np.ndarray]:
    """Return the corners (lo, hi) [m], each shape (dims,), of the box that holds a near region."""
    c = np.asarray(center[:dims], dtype=float)
    h = np.asarray(size[:dims], dtype=float) / 2.0 + radius
    return c - h, c + h


def outline_xy(center: Sequence[float], size: Sequence[float], radius: float,
               arc_points: int = 12) -> np.ndarray:
    """Return the boundary of a near region in the plane: the box grown by ``radius`` [m].

    A closed polygon (the first point repeated last), shape (M, 2) [m]: the box's sides
    moved out by ``radius`` joined by quarter circles (just the box when ``radius`` is 0).
    """
    c = np.asarray(center[:2], dtype=float)
    h = np.asarray(size[:2], dtype=float) / 2.0
    out = []
    for k, (sx, sy) in enumerate(((1, 1), (-1, 1), (-1, -1), (1, -1))):
        a = np.linspace(k * math.pi / 2, (k + 1) * math.pi / 2, arc_points)
        corner = c + h * np.array([sx, sy])
        out.append(corner + radius * np.column_stack([np.cos(a), np.sin(a)]))
    ring = np.vstack(out)
    return np.vstack([ring, ring[:1]])

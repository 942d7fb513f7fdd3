"""A persistent 3D voxel semantic map built from RGB-D + label frames (after HLSM), and its objects.

Per voxel the map keeps whether it is occupied, its class distribution, whether it has
ever been observed, how many frames saw a surface in it (``hits``) and its evidence.
Each frame observes the voxels its rays reach: the voxels that hold back-projected points
get the frame's label distribution, the voxels clearly in front of the measured surface
become free, and the update rule of HLSM (Blukis et al.) keeps everything else:

    V_t = V^_t * O^_t + V_{t-1} * (1 - O^_t),      O_t = max(O_{t-1}, O^_t)

The class distribution of a voxel is stored compactly as its mode and the mode's
probability (class 0: occupied by something that is no object: floor, walls), which is
all that instance extraction reads; this keeps a voxel at 9 bytes whatever the number
of classes, and a frame's update independent of it.

Evidence is what HLSM calls observability, kept per voxel: +1 for a frame that saw a
surface in it, -1 for a frame that saw through it (where the object should have been
seen and was not), clamped to +-``max_evidence`` so that as many frames undo it.

Instances are objects, not pieces of objects: the voxels ever labelled with a class are
split into connected fragments, and the fragments of one object are fused by overlap,
unseen gaps and a size prior (:mod:`fusion`). A fragment whose voxels' mean evidence is
below ``min_evidence`` is dropped whole before fusion: later views saw through it, and
the few voxels they did not reach are no object of their own. An instance's centre and
extent are the box of its voxels with positive evidence, its confidence the mean class
probability of those voxels and its observations the most frames any of them was seen
in. Frontier voxels are observed free voxels next to unobserved space.

The grid grows as frames reach new space, so a map needs no bounds up front. Units are
metres in the ``map`` frame; camera conventions are those of :mod:`camera`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Mapping, Optional, Sequence

import numpy as np
from scipy import ndimage

from ltl_instruct.core.errors import InvalidInputError, LimitExceededError
from ltl_instruct.core.grounding.fusion import Fragment, FusionParams, fragments, fuse
from ltl_instruct.core.grounding.rsm import Instance
from ltl_instruct.core.world.camera import (
    CameraIntrinsics, CameraMount, camera_body_pose, optical_pose, rotate,
)
from ltl_instruct.core.world.scene import MAX_SCENE_EXTENT_M, slug

MAX_VOXELS = 60_000_000
_CHUNK = 32   # the grid grows in chunks of this many voxels per axis


@dataclass(frozen=True)
class SemanticMapParams:
    """Settings of a :class:`SemanticMap`.

    Attributes
    ----------
    voxel_size: edge of a voxel [m].
    max_range: depths beyond this are ignored [m].
    min_cluster_voxels: instances with fewer supported voxels are dropped as noise.
    min_class_score: least class score for a voxel to count as that class.
    pixel_stride: integrate every n-th pixel in each direction (1: all; 2 keeps a point
        every ~1 cm at 3 m for a 640 px wide 90 degree camera, far denser than the voxels).
    max_evidence: a voxel's evidence (frames that saw a surface in it minus frames that
        saw through it) is clamped to +-this, so that as many frames undo it.
    min_evidence: connected pieces of an object whose voxels' mean evidence is below this
        are removed: later views saw through where they should have seen them.
    fusion: how far fragments of one object are fused (:class:`FusionParams`).
    """

    voxel_size: float = 0.1
    max_range: float = 8.0
    min_cluster_voxels: int = 4
    min_class_score: float = 0.5
    pixel_stride: int = 2
    max_evidence: int = 3
    min_evidence: float = 0.5
    fusion: FusionParams = FusionParams()

    def __post_init__(self) -> None:
        for name in ('voxel_size', 'max_range'):
            v = getattr(self, name)
            if not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
                raise InvalidInputError(f'{name} must be a positive number, got {v!r}')
        if self.min_cluster_voxels < 1 or self.pixel_stride < 1:
            raise InvalidInputError('min_cluster_voxels and pixel_stride must be >= 1')
        if not 1 <= self.max_evidence <= 100 or not math.isfinite(self.min_evidence):
            raise InvalidInputError('max_evidence must be in 1..100 and min_evidence finite')


@dataclass(frozen=True)
class MapInstance:
    """An instance with the evidence behind it.

    Attributes
    ----------
    instance: id, label, centre and extent [m] (the box of its supported voxels),
        confidence (mean class probability of those voxels), observations (frames that
        saw it: the most any of its voxels was seen).
    voxels: its supported voxels (evidence > 0).
    fragments: connected pieces fused into it.
    evidence: mean evidence of every voxel of its pieces, seen-through ones included,
        in [min_evidence, max_evidence].
    """

    instance: Instance
    voxels: int
    fragments: int
    evidence: float


class SemanticMap:
    """Persistent voxel map of occupancy, class distributions (mode and probability) and observedness.

    Parameters
    ----------
    classes: class id (as in label images) -> label text; unknown ids become ``class_<id>``.
    params: voxel size, range and clustering settings.
    mount: camera placement on the robot, for robot poses given to :meth:`integrate`.
    """

    def __init__(self, classes: Optional[Mapping[int, str]] = None,
                 params: SemanticMapParams = SemanticMapParams(), mount: CameraMount = CameraMount()) -> None:
        self.params = params
        self.mount = mount
        self.class_names: dict[int, str] = {int(k): str(v) for k, v in (classes or {}).items()}
        self._column: dict[int, int] = {}           # class id -> score column (>= 1)
        self._column_names: list[str] = ['']        # column -> label text (0: not an object)
        self.origin = np.zeros(3, dtype=np.int64)   # voxel index of grid cell [0, 0, 0]
        self.occupied = np.zeros((0, 0, 0), dtype=bool)        # last observation saw a surface
        self.label = np.zeros((0, 0, 0), dtype=np.int16)        # mode of the class distribution (column)
        self.label_prob = np.zeros((0, 0, 0), dtype=np.float16)  # probability of the mode
        self.observed = np.zeros((0, 0, 0), dtype=bool)
        self.hits = np.zeros((0, 0, 0), dtype=np.uint16)                # frames that saw a surface here
        self.evidence = np.zeros((0, 0, 0), dtype=np.int8)              # hits - see-throughs, clamped
        self.frames = 0
        self._ray_cache: dict[tuple[CameraIntrinsics, int], np.ndarray] = {}

    # ------------------------------------------------------------------ grid
    @property
    def shape(self) -> tuple[int, int, int]:
        """Grid size in voxels (nx, ny, nz)."""
        return self.observed.shape  # type: ignore[return-value]

    def voxel_centers(self, idx: np.ndarray) -> np.ndarray:
        """Centres [m] (N, 3) of grid cells (N, 3)."""
        return (idx + self.origin + 0.5) * self.params.voxel_size

    def _ensure(self, lo: np.ndarray, hi: np.ndarray) -> None:
        """Grow the grid so that global voxel indices lo..hi (inclusive) are inside it."""
        cur_lo = self.origin
        cur_hi = self.origin + np.array(self.shape) - 1
        if self.observed.size and np.all(lo >= cur_lo) and np.all(hi <= cur_hi):
            return
        # grow a side by at least the camera's range (at most 10 m; 1 m vertically), so that a
        # robot moving about re-allocates the grid rarely (growth copies the whole grid); only
        # as far as needed when that margin would take the grid past its limit
        vs = self.params.voxel_size
        pad = np.array([math.ceil(min(self.params.max_range, 10.0) / vs)] * 2 + [math.ceil(1.0 / vs)])
        new_lo, new_hi = self._grown(lo, hi, pad)
        shape = tuple(int(v) for v in new_hi - new_lo + 1)
        if math.prod(shape) > MAX_VOXELS:
            new_lo, new_hi = self._grown(lo, hi, np.zeros(3, dtype=np.int64))
            shape = tuple(int(v) for v in new_hi - new_lo + 1)
        if math.prod(shape) > MAX_VOXELS:
            raise LimitExceededError(f'the semantic map would grow to {shape} voxels (limit {MAX_VOXELS})')
        names = ('occupied', 'label', 'label_prob', 'observed', 'hits', 'evidence')
        grown = {n: np.zeros(shape, dtype=getattr(self, n).dtype) for n in names}
        if self.observed.size:
            o = self.origin - new_lo
            sl = tuple(slice(int(o[i]), int(o[i]) + self.shape[i]) for i in range(3))
            for n in names:
                grown[n][sl] = getattr(self, n)
        for n in names:
            setattr(self, n, grown[n])
        self.origin = new_lo

    def _grown(self, lo: np.ndarray, hi: np.ndarray, pad: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Grid bounds that hold the grid and lo..hi, with ``pad`` voxels more on each side grown."""
        if self.observed.size:
            cur_lo, cur_hi = self.origin, self.origin + np.array(self.shape) - 1
            new_lo = np.where(lo < cur_lo, np.minimum(lo, cur_lo - pad), cur_lo)
            new_hi = np.where(hi > cur_hi, np.maximum(hi, cur_hi + pad), cur_hi)
        else:
            new_lo, new_hi = lo - pad, hi + pad
        return np.floor_divide(new_lo, _CHUNK) * _CHUNK, (np.floor_divide(new_hi, _CHUNK) + 1) * _CHUNK - 1

    def name_classes(self, classes: Mapping[int, str]) -> None:
        """Learn label texts of class ids, also of classes integrated before their name came."""
        for cid, label in classes.items():
            self.class_names[int(cid)] = str(label)
            col = self._column.get(int(cid))
            if col is not None:
                self._column_names[col] = str(label)

    def _columns_for(self, class_ids: np.ndarray) -> np.ndarray:
        """Score columns of label ids (<= 0 -> column 0), adding columns for new classes."""
        if class_ids.size == 0:
            return np.zeros(0, dtype=np.int64)
        ids = np.where(class_ids > 0, class_ids, 0)
        top = int(ids.max())
        if top > 10_000_000:
            raise InvalidInputError(f'label id {top} is out of range (at most 10,000,000)')
        present = np.flatnonzero(np.bincount(ids, minlength=top + 1))
        lut = np.zeros(top + 1, dtype=np.int64)
        for cid in present.tolist():
            if cid == 0:
                continue
            col = self._column.get(cid)
            if col is None:
                col = len(self._column_names)
                self._column[cid] = col
                self._column_names.append(self.class_names.get(cid, f'class_{cid}'))
            lut[cid] = col
        return lut[ids]

    # ------------------------------------------------------------------ integration
    def integrate(self, depth: np.ndarray, labels: np.ndarray, intrinsics: Any, pose: Any) -> int:
        """Integrate one frame; return the number of voxels it observed.

        Parameters
        ----------
        depth: float (H, W) [m], optical-frame z; NaN, inf or <= 0 where there is no return.
        labels: int (H, W) class ids (0: no object).
        intrinsics: :class:`CameraIntrinsics` or ``(width, height, fx, fy, cx, cy)``.
        pose: robot pose (``position`` [m], ``yaw`` [rad]; the mount is applied) or
            (4, 4) ``T_map_body`` of the camera.

        Raises
        ------
        InvalidInputError
            On shapes that do not match, a NaN pose or malformed intrinsics.
        """
        k = CameraIntrinsics.coerce(intrinsics)
        depth = np.asarray(depth)
        labels = np.asarray(labels)
        if depth.shape != (k.height, k.width) or labels.shape != depth.shape:
            raise InvalidInputError(f'depth {depth.shape} and labels {labels.shape} must both be '
                                    f'({k.height}, {k.width}) as the intrinsics say')
        if not np.issubdtype(labels.dtype, np.integer) or not np.issubdtype(depth.dtype, np.number):
            raise InvalidInputError('depth must be numeric and labels integer')
        t_opt = optical_pose(camera_body_pose(pose, self.mount))
        if not np.all(np.isfinite(t_opt)) or np.abs(t_opt[:3, 3]).max() > MAX_SCENE_EXTENT_M:
            raise InvalidInputError(f'camera pose at {np.round(t_opt[:3, 3], 3).tolist()} is not finite or '
                                    f'beyond the largest scene ({MAX_SCENE_EXTENT_M:g} m)')
        s = self.params.pixel_stride
        d = depth[::s, ::s].astype(np.float32)
        valid = np.isfinite(d) & (d > 0) & (d <= self.params.max_range)
        pts, ids = self._surface_points(depth, labels, k, t_opt, valid)
        self.frames += 1
        if pts.shape[0] == 0:
            return 0
        # the observed space lies in the hull of the camera and the points: grow to its box
        vox = np.floor(pts * np.float32(1.0 / self.params.voxel_size)).astype(np.int64)
        cam_vox = np.floor(t_opt[:3, 3] / self.params.voxel_size).astype(np.int64)
        lo = np.minimum(vox.min(axis=0), cam_vox)
        hi = np.maximum(vox.max(axis=0), cam_vox)
        self._ensure(lo, hi)
        cols = self._columns_for(ids)
        sub_lo = lo - self.origin
        sl = tuple(slice(int(sub_lo[i]), int(sub_lo[i] + hi[i] - lo[i] + 1)) for i in range(3))
        # free space is judged against the nearest surface around each pixel: a voxel whose centre
        # projects next to an object's silhouette is not carved by the background one pixel away
        depth_img = ndimage.minimum_filter(np.where(valid, d, np.float32(-np.inf)), size=3, mode='nearest')
        free = self._free_space(lo, hi, t_opt, k, depth_img)
        self._see_through(free, sl, lo, t_opt, k, depth_img)
        return int(free.sum()) + self._add_surface(vox - lo, cols, sl, hi - lo + 1)

    def _surface_points(self, depth: np.ndarray, labels: np.ndarray, k: CameraIntrinsics, t_opt: np.ndarray,
                        valid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Back-projected points [m] (N, 3) of a frame and their label ids (N,).

        Every ``pixel_stride``-th pixel (``valid``: those of them with a depth in range),
        and every pixel beyond the depth at which strided samples lie more than a voxel
        apart: a far surface is then still sampled densely enough to fill its voxels
        without holes (holes cut it into pieces). Each point moves 1 % of a voxel along its
        ray, into the object it lies on: a surface on a voxel face (a seat at 0.9 m) then
        fills the voxel behind it, not the one in front, by rounding that would otherwise
        change from pixel to pixel.
        """
        s, vs = self.params.pixel_stride, self.params.voxel_size
        d = depth[::s, ::s].astype(np.float32)[valid]
        rays, ids = self._rays(k, s)[valid], labels[::s, ::s][valid]
        far = np.float32(vs * min(k.fx, k.fy) / s)
        if s > 1 and d.size and d.max() > far:
            full = depth.astype(np.float32)
            with np.errstate(invalid='ignore'):
                extra = (full > far) & (full <= self.params.max_range)
            extra[::s, ::s] = False
            d = np.concatenate([d, full[extra]])
            rays = np.concatenate([rays, self._rays(k, 1)[extra]])
            ids = np.concatenate([ids, labels[extra]])
        rot = t_opt[:3, :3].astype(np.float32)
        pts = rotate(rays, rot) * (d[:, None] + np.float32(0.01 * vs)) + t_opt[:3, 3].astype(np.float32)
        return pts, np.asarray(ids, dtype=np.int64)

    def _free_space(self, lo: np.ndarray, hi: np.ndarray, t_opt: np.ndarray, k: CameraIntrinsics,
                    depth: np.ndarray) -> np.ndarray:
        """Voxels of the box lo..hi whose centre projects in front of the measured surface."""
        vs, s = self.params.voxel_size, self.params.pixel_stride
        box = hi - lo + 1
        r = t_opt[:3, :3].T                                        # map -> optical
        tr = -r @ t_opt[:3, 3]
        axes = [((np.arange(box[i]) + lo[i] + 0.5) * vs).astype(np.float32) for i in range(3)]
        shp = [(-1, 1, 1), (1, -1, 1), (1, 1, -1)]
        opt = [sum(np.float32(r[j, i]) * axes[i].reshape(shp[i]) for i in range(3)) + np.float32(tr[j])
               for j in range(3)]                                 # 3 x (bx, by, bz)
        zc = opt[2]
        h, w = depth.shape
        with np.errstate(divide='ignore', invalid='ignore'):
            inv_z = np.float32(1.0) / zc
            u = (opt[0] * inv_z * np.float32(k.fx / s) + np.float32(k.cx / s))
            v = (opt[1] * inv_z * np.float32(k.fy / s) + np.float32(k.cy / s))
            inview = (zc > 1e-3) & (u >= 0) & (u < w) & (v >= 0) & (v < h)
        dm = np.full(zc.shape, -np.inf, dtype=np.float32)
        dm[inview] = depth[v[inview].astype(np.int64), u[inview].astype(np.int64)]
        return zc < dm - np.float32(vs * 0.87)                     # -inf (no return) is never free

    def _see_through(self, free: np.ndarray, sl: tuple[slice, ...], lo: np.ndarray, t_opt: np.ndarray,
                     k: CameraIntrinsics, depth: np.ndarray) -> None:
        """Mark free space observed; a voxel once hit loses evidence (and its surface) when seen through.

        A surface voxel counts as seen through only when all its corners lie in front of the
        measured surface: a ray through its centre may graze past the object surface that
        fills the voxel's lower half. ``free`` keeps only what this frame made free.
        """
        sub_ev = self.evidence[sl]
        held = np.argwhere(free & (self.hits[sl] > 0))
        if held.size:
            through = self._corners_in_front(held, lo, t_opt, k, self.params.pixel_stride, depth)
            free[tuple(held[~through].T)] = False
            ix = tuple(held[through].T)
            sub_ev[ix] = np.maximum(sub_ev[ix] - 1, -self.params.max_evidence)
        self.occupied[sl][free] = False
        self.observed[sl] |= free

    def _add_surface(self, local: np.ndarray, cols: np.ndarray, sl: tuple[slice, ...],
                     box: np.ndarray) -> int:
        """Give the voxels that hold points (box indices (N, 3)) their label distribution; count them."""
        ncol = len(self._column_names)
        flat = (local[:, 0] * box[1] + local[:, 1]) * box[2] + local[:, 2]
        cells, inv = np.unique(flat, return_inverse=True)
        counts = np.bincount(inv * ncol + cols, minlength=cells.size * ncol).reshape(cells.size, ncol)
        mode = np.argmax(counts, axis=1)
        prob = counts[np.arange(cells.size), mode] / counts.sum(axis=1)
        ix = np.unravel_index(cells, tuple(int(b) for b in box))
        self.occupied[sl][ix] = True
        self.label[sl][ix] = mode.astype(np.int16)
        self.label_prob[sl][ix] = prob.astype(np.float16)
        self.observed[sl][ix] = True
        sub_hits, sub_ev = self.hits[sl], self.evidence[sl]
        sub_hits[ix] = np.minimum(sub_hits[ix].astype(np.int64) + 1, 65535).astype(np.uint16)
        sub_ev[ix] = np.minimum(sub_ev[ix] + 1, self.params.max_evidence)
        return int(cells.size)

    def _corners_in_front(self, cells: np.ndarray, lo: np.ndarray, t_opt: np.ndarray, k: CameraIntrinsics,
                          stride: int, depth: np.ndarray) -> np.ndarray:
        """Whether all 8 corners of box cells (N, 3) lie in front of the measured depth."""
        vs = self.params.voxel_size
        centers = (cells + lo + 0.5) * vs
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
        corners = centers[:, None, :] + signs[None] * (0.5 * vs)             # (N, 8, 3)
        r = t_opt[:3, :3].T
        opt = rotate(corners - t_opt[:3, 3], r)
        z = opt[..., 2]
        h, w = depth.shape
        with np.errstate(divide='ignore', invalid='ignore'):
            u = np.floor((opt[..., 0] / z * k.fx + k.cx) / stride)
            v = np.floor((opt[..., 1] / z * k.fy + k.cy) / stride)
        ok = (z > 1e-3) & (u >= 0) & (u < w) & (v >= 0) & (v < h)
        meas = np.full(z.shape, -np.inf)
        meas[ok] = depth[v[ok].astype(np.int64), u[ok].astype(np.int64)]
        return np.all(ok & (z < meas - 0.02), axis=1)

    def _rays(self, k: CameraIntrinsics, stride: int) -> np.ndarray:
        key = (k, stride)
        if key not in self._ray_cache:
            if len(self._ray_cache) >= 4:
                self._ray_cache.clear()
            self._ray_cache[key] = k.pixel_rays(stride).astype(np.float32)
        return self._ray_cache[key]

    # ------------------------------------------------------------------ queries
    @property
    def column_labels(self) -> tuple[str, ...]:
        """Label text of every class column (column 0: not an object)."""
        return tuple(self._column_names)

    def instances(self) -> tuple[Instance, ...]:
        """Object instances, one per fused object; ids ``det_<label>_<n>``, ordered by position."""
        return tuple(r.instance for r in self.instance_records())

    def instance_records(self) -> tuple[MapInstance, ...]:
        """Object instances with their evidence (see the module docstring), ordered as :meth:`instances`."""
        if len(self._column_names) <= 1 or not self.observed.size:
            return ()
        cells = np.argwhere(self.label > 0)          # a label is only ever given with a hit
        cells = cells[self.label_prob[tuple(cells.T)] >= self.params.min_class_score]
        if cells.shape[0] == 0:
            return ()
        live = []
        for frag in fragments(cells, self.label[tuple(cells.T)].astype(np.int64)):
            ev = self.evidence[tuple(frag.cells.T)]
            if float(ev.mean()) >= self.params.min_evidence:
                kept = frag.cells[ev > 0]
                live.append((Fragment(frag.column, kept, kept.min(axis=0), kept.max(axis=0)), ev))
        groups = fuse([f for f, _ in live], self._free_share, self.params.fusion)
        found = [self._record([live[k] for k in g]) for g in groups]
        return self._named([r for r in found if r.voxels >= self.params.min_cluster_voxels])

    def _record(self, parts: Sequence[tuple[Fragment, np.ndarray]]) -> MapInstance:
        """One instance from fused fragments (with the evidence of all their voxels); id filled in later."""
        vs = self.params.voxel_size
        cells = np.concatenate([f.cells for f, _ in parts])
        ix = tuple(cells.T)
        lo = (cells.min(axis=0) + self.origin) * vs
        hi = (cells.max(axis=0) + self.origin + 1) * vs
        inst = Instance('', self._column_names[parts[0][0].column],
                        tuple(round(float(v), 4) for v in (lo + hi) / 2),  # type: ignore[arg-type]
                        tuple(round(float(v), 4) for v in hi - lo),  # type: ignore[arg-type]
                        round(float(self.label_prob[ix].astype(np.float64).mean()), 4),
                        int(self.hits[ix].max()))
        evidence = float(np.concatenate([ev for _, ev in parts]).astype(np.float64).mean())
        return MapInstance(inst, int(cells.shape[0]), len(parts), round(evidence, 4))

    @staticmethod
    def _named(found: Sequence[MapInstance]) -> tuple[MapInstance, ...]:
        """Give ids ``det_<label>_<n>``, numbered per label by position (x, then y); labels sorted."""
        out: list[MapInstance] = []
        for label in sorted({r.instance.label for r in found}):
            same = sorted((r for r in found if r.instance.label == label),
                          key=lambda r: (round(r.instance.center[0], 3), round(r.instance.center[1], 3)))
            out += [replace(r, instance=replace(r.instance, id=f'det_{slug(label)}_{n}'))
                    for n, r in enumerate(same, start=1)]
        return tuple(out)

    def _free_share(self, lo: np.ndarray, hi: np.ndarray) -> float:
        """Share of the voxels of the grid box lo..hi (inclusive) observed free; 0 for an empty box."""
        if np.any(hi < lo):
            return 0.0
        sl = tuple(slice(int(lo[i]), int(hi[i]) + 1) for i in range(3))
        return float(np.mean(self.observed[sl] & ~self.occupied[sl]))

    def frontiers(self, z_range: Optional[Sequence[float]] = None) -> np.ndarray:
        """Centres [m] (N, 3) of observed free voxels with an unobserved 6-neighbour.

        ``z_range`` (min, max) [m] keeps voxels whose centre height lies in it (for a
        ground robot, a band above the floor). The grid's outer faces count as unobserved.
        """
        if not self.observed.size:
            return np.zeros((0, 3))
        free = self.observed & ~self.occupied
        unobs = np.pad(~self.observed, 1, constant_values=True)
        near_unobs = np.zeros_like(free)
        for axis in range(3):
            for shift in (-1, 1):
                near_unobs |= np.roll(unobs, shift, axis=axis)[1:-1, 1:-1, 1:-1]
        idx = np.argwhere(free & near_unobs)
        centers = self.voxel_centers(idx)
        if z_range is not None:
            keep = (centers[:, 2] >= z_range[0]) & (centers[:, 2] <= z_range[1])
            centers = centers[keep]
        return centers

"""A persistent 3D voxel semantic map built from RGB-D + label frames (after HLSM).

Per voxel the map keeps whether it is occupied, its class distribution and whether it
has ever been observed. Each frame observes the voxels its rays reach: the voxels that
hold back-projected points get the frame's label distribution, the voxels clearly in
front of the measured surface become free, and the update rule of HLSM (Blukis et al.)
keeps everything else:

    V_t = V^_t * O^_t + V_{t-1} * (1 - O^_t),      O_t = max(O_{t-1}, O^_t)

The class distribution of a voxel is stored compactly as its mode and the mode's
probability (class 0: occupied by something that is no object: floor, walls), which is
all that instance extraction reads; this keeps a voxel at 8 bytes whatever the number
of classes, and a frame's update independent of it.

Instances are extracted per class by density clustering of the object voxels (open3d
DBSCAN); each has a centre and extent (the box of its voxels), a confidence (the mean
class probability of its voxels) and a number of observations (frames that saw it).
Frontier voxels are observed free voxels next to unobserved space.

The grid grows as frames reach new space, so a map needs no bounds up front. Units are
metres in the ``map`` frame; camera conventions are those of :mod:`camera`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import InvalidInputError, LimitExceededError
from ltl_instruct.core.grounding.rsm import Instance
from ltl_instruct.core.world.camera import CameraIntrinsics, CameraMount, camera_body_pose, optical_pose
from ltl_instruct.core.world.scene import slug

MAX_VOXELS = 60_000_000
_CHUNK = 32   # the grid grows in chunks of this many voxels per axis


@dataclass(frozen=True)
class SemanticMapParams:
    """Settings of a :class:`SemanticMap`.

    Attributes
    ----------
    voxel_size: edge of a voxel [m].
    max_range: depths beyond this are ignored [m].
    min_cluster_voxels: smaller clusters are dropped as noise.
    min_class_score: least class score for a voxel to count as that class.
    pixel_stride: integrate every n-th pixel in each direction (1: all; 2 keeps a point
        every ~1 cm at 3 m for a 640 px wide 90 degree camera, far denser than the voxels).
    """

    voxel_size: float = 0.1
    max_range: float = 8.0
    min_cluster_voxels: int = 4
    min_class_score: float = 0.5
    pixel_stride: int = 2

    def __post_init__(self) -> None:
        for name in ('voxel_size', 'max_range'):
            v = getattr(self, name)
            if not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
                raise InvalidInputError(f'{name} must be a positive number, got {v!r}')
        if self.min_cluster_voxels < 1 or self.pixel_stride < 1:
            raise InvalidInputError('min_cluster_voxels and pixel_stride must be >= 1')


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
        self.hits = np.zeros((0, 0, 0), dtype=np.uint16)
        self.frames = 0
        self._ray_cache: Optional[tuple[Any, np.ndarray]] = None

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
        # grow a side by at least the camera's range (1 m vertically), so that a robot moving
        # about re-allocates the grid rarely: growth copies the whole grid
        vs = self.params.voxel_size
        pad = np.array([math.ceil(self.params.max_range / vs)] * 2 + [math.ceil(1.0 / vs)])
        if self.observed.size:
            new_lo = np.where(lo < cur_lo, np.minimum(lo, cur_lo - pad), cur_lo)
            new_hi = np.where(hi > cur_hi, np.maximum(hi, cur_hi + pad), cur_hi)
        else:
            new_lo, new_hi = lo - pad, hi + pad
        new_lo = (np.floor_divide(new_lo, _CHUNK)) * _CHUNK
        new_hi = (np.floor_divide(new_hi, _CHUNK) + 1) * _CHUNK - 1
        shape = tuple(int(v) for v in new_hi - new_lo + 1)
        if shape[0] * shape[1] * shape[2] > MAX_VOXELS:
            raise LimitExceededError(f'the semantic map would grow to {shape} voxels (limit {MAX_VOXELS})')
        names = ('occupied', 'label', 'label_prob', 'observed', 'hits')
        grown = {n: np.zeros(shape, dtype=getattr(self, n).dtype) for n in names}
        if self.observed.size:
            o = self.origin - new_lo
            sl = tuple(slice(int(o[i]), int(o[i]) + self.shape[i]) for i in range(3))
            for n in names:
                grown[n][sl] = getattr(self, n)
        for n in names:
            setattr(self, n, grown[n])
        self.origin = new_lo

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
        vs = self.params.voxel_size
        s = self.params.pixel_stride
        d = depth[::s, ::s].astype(np.float32)
        lab = labels[::s, ::s]
        rays = self._rays(k, s)                                           # (h, w, 3), z = 1
        valid = np.isfinite(d) & (d > 0) & (d <= self.params.max_range)
        rot = t_opt[:3, :3].astype(np.float32)
        cam = t_opt[:3, 3]
        # points in map = (R @ ray) * depth + t; R @ ray per pixel is fixed for the frame
        dirs = rays[valid] @ rot.T
        pts = dirs * d[valid][:, None] + cam.astype(np.float32)
        self.frames += 1
        if pts.shape[0] == 0:
            return 0
        # the observed space lies in the hull of the camera and the points: grow to its box
        vox = np.floor(pts * np.float32(1.0 / vs)).astype(np.int64)
        cam_vox = np.floor(cam / vs).astype(np.int64)
        lo = np.minimum(vox.min(axis=0), cam_vox)
        hi = np.maximum(vox.max(axis=0), cam_vox)
        self._ensure(lo, hi)
        cols = self._columns_for(np.asarray(lab[valid], dtype=np.int64))
        ncol = len(self._column_names)
        sub_lo = lo - self.origin
        box = hi - lo + 1
        sl = tuple(slice(int(sub_lo[i]), int(sub_lo[i] + box[i])) for i in range(3))
        # -- free space: voxels of the box whose centre projects in front of the surface
        r = t_opt[:3, :3].T                                        # map -> optical
        tr = -r @ cam
        axes = [((np.arange(box[i]) + lo[i] + 0.5) * vs).astype(np.float32) for i in range(3)]
        shp = [(-1, 1, 1), (1, -1, 1), (1, 1, -1)]
        opt = [sum(np.float32(r[j, i]) * axes[i].reshape(shp[i]) for i in range(3)) + np.float32(tr[j])
               for j in range(3)]                                 # 3 x (bx, by, bz)
        zc = opt[2]
        h, w = d.shape
        with np.errstate(divide='ignore', invalid='ignore'):
            inv_z = np.float32(1.0) / zc
            u = (opt[0] * inv_z * np.float32(k.fx / s) + np.float32(k.cx / s))
            v = (opt[1] * inv_z * np.float32(k.fy / s) + np.float32(k.cy / s))
            inview = (zc > 1e-3) & (u >= 0) & (u < w) & (v >= 0) & (v < h)
        dm_img = np.where(valid, d, np.float32(-np.inf))
        dm = np.full(zc.shape, -np.inf, dtype=np.float32)
        dm[inview] = dm_img[v[inview].astype(np.int64), u[inview].astype(np.int64)]
        free = zc < dm - np.float32(vs * 0.87)                     # -inf (no return) is never free
        sub_occ = self.occupied[sl]
        # an occupied voxel is freed only when all its corners lie in front of the surface: a ray
        # through its centre may graze past the object surface that fills the voxel's lower half
        held = np.argwhere(free & sub_occ)
        if held.size:
            keep = ~self._corners_in_front(held, lo, t_opt, k, s, dm_img)
            free[tuple(held[keep].T)] = False
        sub_occ[free] = False
        self.observed[sl] |= free
        # -- occupied: label distribution of the points in each voxel of the box
        local = vox - lo
        flat = (local[:, 0] * box[1] + local[:, 1]) * box[2] + local[:, 2]
        cells, inv = np.unique(flat, return_inverse=True)
        counts = np.bincount(inv * ncol + cols, minlength=cells.size * ncol).reshape(cells.size, ncol)
        mode = np.argmax(counts, axis=1)
        prob = counts[np.arange(cells.size), mode] / counts.sum(axis=1)
        ix = np.unravel_index(cells, tuple(int(b) for b in box))
        sub_occ[ix] = True
        self.label[sl][ix] = mode.astype(np.int16)
        self.label_prob[sl][ix] = prob.astype(np.float16)
        self.observed[sl][ix] = True
        sub_hits = self.hits[sl]
        sub_hits[ix] = np.minimum(sub_hits[ix].astype(np.int64) + 1, 65535).astype(np.uint16)
        return int(free.sum()) + int(cells.size)

    def _corners_in_front(self, cells: np.ndarray, lo: np.ndarray, t_opt: np.ndarray, k: CameraIntrinsics,
                          stride: int, depth: np.ndarray) -> np.ndarray:
        """Whether all 8 corners of box cells (N, 3) lie in front of the measured depth."""
        vs = self.params.voxel_size
        centers = (cells + lo + 0.5) * vs
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
        corners = centers[:, None, :] + signs[None] * (0.5 * vs)             # (N, 8, 3)
        r = t_opt[:3, :3].T
        opt = (corners - t_opt[:3, 3]) @ r.T
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
        if self._ray_cache is None or self._ray_cache[0] != key:
            self._ray_cache = (key, k.pixel_rays(stride).astype(np.float32))
        return self._ray_cache[1]

    # ------------------------------------------------------------------ queries
    @property
    def column_labels(self) -> tuple[str, ...]:
        """Label text of every class column (column 0: not an object)."""
        return tuple(self._column_names)

    def instances(self) -> tuple[Instance, ...]:
        """Object instances, clustered per class; ids ``det_<label>_<n>``, ordered by position."""
        import open3d as o3d
        if len(self._column_names) <= 1 or not self.observed.size:
            return ()
        vs = self.params.voxel_size
        objects = self.occupied & (self.label > 0) & (self.label_prob >= self.params.min_class_score)
        cand = np.argwhere(objects)
        cand_label = self.label[tuple(cand.T)]
        out: list[Instance] = []
        for col in range(1, len(self._column_names)):
            idx = cand[cand_label == col]
            if idx.shape[0] < self.params.min_cluster_voxels:
                continue
            centers = self.voxel_centers(idx)
            pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(centers))
            cluster = np.asarray(pcd.cluster_dbscan(eps=vs * 1.8, min_points=1, print_progress=False))
            label = self._column_names[col]
            found = []
            for c in range(int(cluster.max(initial=-1)) + 1):
                members = cluster == c
                if members.sum() < self.params.min_cluster_voxels:
                    continue
                cidx = idx[members]
                pts = centers[members]
                lo, hi = pts.min(axis=0) - vs / 2, pts.max(axis=0) + vs / 2
                conf = float(self.label_prob[tuple(cidx.T)].astype(np.float64).mean())
                obs = int(self.hits[tuple(cidx.T)].max())
                found.append(((lo + hi) / 2, hi - lo, conf, obs))
            found.sort(key=lambda f: (round(float(f[0][0]), 3), round(float(f[0][1]), 3)))
            for n, (center, size, conf, obs) in enumerate(found, start=1):
                out.append(Instance(f'det_{slug(label)}_{n}', label,
                                    tuple(round(float(v), 4) for v in center),  # type: ignore[arg-type]
                                    tuple(round(float(v), 4) for v in size),  # type: ignore[arg-type]
                                    round(conf, 4), obs))
        return tuple(out)

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

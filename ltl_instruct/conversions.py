"""Every ROS message <-> core type conversion, in one place.

Nodes call these and nothing else to read or build messages, so the core never sees a
message type and the message layouts are tested once. Covered:

- JSON payloads on ``std_msgs/String`` (schema name + version + instruction ``id``),
  with size limits and typed errors;
- ``nav_msgs/Path`` <-> points (N, 3) [m];
- ``nav_msgs/Odometry`` -> :class:`~ltl_instruct.core.world.robot.Pose` (NaN rejected), in the
  map frame (:func:`odometry_in_map`: a pose in another frame is a ``FRAME_MISMATCH``);
- ``nav_msgs/OccupancyGrid`` <-> :class:`~ltl_instruct.core.world.robot.OccupancyRaster`, and
  <-> :class:`~ltl_instruct.core.grounding.coverage.Coverage` (what the camera has seen);
- ``sensor_msgs/PointCloud2`` <-> float32 fields (packed with numpy: no sensor_msgs_py);
- ``sensor_msgs/Image`` <-> numpy (rgb8/bgr8/rgba8/bgra8; depth 32FC1 [m] or 16UC1 [mm], read as
  metres; 32SC1 labels), ``CameraInfo``;
- ``visualization_msgs/MarkerArray`` of a referent map.

Message packages are plain Python; this module does not import rclpy.
"""
from __future__ import annotations

import array
import json
import math
from typing import Any, Mapping, Optional, Sequence

import numpy as np
from builtin_interfaces.msg import Time
from geometry_msgs.msg import Point, PoseStamped, Quaternion
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from sensor_msgs.msg import CameraInfo, Image, PointCloud2, PointField
from std_msgs.msg import Header, String
from visualization_msgs.msg import Marker, MarkerArray

from ltl_instruct.core.errors import FrameMismatchError, InvalidInputError
from ltl_instruct.core.grounding.coverage import Coverage, PlaneGrid
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.payloads import (  # noqa: F401  (the payload parsing lives in the core; re-exported)
    INSTRUCTION, MAX_PAYLOAD_BYTES, SCHEMA_VERSION, parse_json_payload, read_cancel, read_instruction,
    revision_of, salvage_id, timing_of,
    safe_id as _safe_id,
)
from ltl_instruct.core.planning import PlanningWorld
from ltl_instruct.core.world.robot import OccupancyRaster, Pose, compose_planar
from ltl_instruct.core.world.scene import MAX_SCENE_EXTENT_M, Box

FRAME_ID = 'map'

# schema names of the JSON payloads (design.md "Nodes and topics")
TASK_SPEC = 'ltl_instruct/task_spec'
VERIFICATION_REQUEST = 'ltl_instruct/verification_request'
VERIFICATION_REPLY = 'ltl_instruct/verification_reply'
REFERENT_MAP = 'ltl_instruct/referent_map'
PLAN_REQUEST = 'ltl_instruct/plan_request'
SEGMENT_STATUS = 'ltl_instruct/segment_status'
TASK_PLAN = 'ltl_instruct/task_plan'
TASK_STATUS = 'ltl_instruct/task_status'
SKILL_REQUEST = 'ltl_instruct/skill_request'
SKILL_RESULT = 'ltl_instruct/skill_result'
LABEL_CLASSES = 'ltl_instruct/label_classes'
TRANSLATOR_STATUS = 'ltl_instruct/translator_status'


# ---------------------------------------------------------------------------- JSON payloads
def _finite_json(obj: Any) -> Any:
    """Replace non-finite floats (not valid JSON) by None, recursively."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {str(k): _finite_json(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_finite_json(v) for v in obj]
    if isinstance(obj, np.generic):
        return _finite_json(obj.item())
    if isinstance(obj, np.ndarray):
        return _finite_json(obj.tolist())
    return obj


def payload(schema: str, instruction_id: str, **fields: Any) -> dict[str, Any]:
    """Return a JSON payload dict: ``{'schema', 'version', 'id', **fields}``."""
    d: dict[str, Any] = {'schema': schema, 'version': SCHEMA_VERSION, 'id': instruction_id}
    d.update(fields)
    return d


def json_msg(data: Mapping[str, Any]) -> String:
    """Return a ``std_msgs/String`` holding ``data`` as compact JSON (non-finite floats -> null)."""
    return String(data=json.dumps(_finite_json(dict(data)), separators=(',', ':'), allow_nan=False))


# ---------------------------------------------------------------------------- time
def stamp_key(stamp: Time) -> int:
    """Return a stamp as integer nanoseconds (a key that survives the round trip through a message)."""
    return int(stamp.sec) * 1_000_000_000 + int(stamp.nanosec)


def stamp_from_key(key: int) -> Time:
    """Inverse of :func:`stamp_key`."""
    return Time(sec=int(key // 1_000_000_000), nanosec=int(key % 1_000_000_000))


# ---------------------------------------------------------------------------- poses, paths
def yaw_to_quaternion(yaw: float) -> Quaternion:
    """Return the unit quaternion of a rotation ``yaw`` [rad] about +z."""
    return Quaternion(x=0.0, y=0.0, z=math.sin(yaw / 2.0), w=math.cos(yaw / 2.0))


def quaternion_to_yaw(q: Quaternion) -> float:
    """Yaw [rad] of a quaternion (rotation about +z; roll and pitch ignored)."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def path_headings(points: np.ndarray) -> np.ndarray:
    """Yaw [rad] per point facing the next one (the last keeps the previous), shape (N,)."""
    p = np.asarray(points, dtype=float)
    n = len(p)
    yaw = np.zeros(n)
    if n >= 2:
        d = np.diff(p[:, :2], axis=0)
        seg = np.arctan2(d[:, 1], d[:, 0])
        still = np.hypot(d[:, 0], d[:, 1]) < 1e-9
        for i in range(n - 1):  # a vertical or zero step keeps the previous heading
            seg[i] = seg[i - 1] if still[i] and i > 0 else seg[i]
        yaw[:-1] = seg
        yaw[-1] = seg[-1]
    return yaw


def path_msg(points: np.ndarray, stamp: Optional[Time] = None, frame_id: str = FRAME_ID) -> Path:
    """Return a ``nav_msgs/Path`` through ``points`` (N, 3) [m], each pose facing the next point."""
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg = Path(header=header)
    for (x, y, z), yaw in zip(p, path_headings(p)):
        ps = PoseStamped(header=header)
        ps.pose.position = Point(x=float(x), y=float(y), z=float(z))
        ps.pose.orientation = yaw_to_quaternion(float(yaw))
        msg.poses.append(ps)
    return msg


def path_points(msg: Path, check_finite: bool = True) -> np.ndarray:
    """Positions of a ``nav_msgs/Path`` [m], shape (N, 3).

    Raises
    ------
    InvalidInputError
        If ``check_finite`` and a coordinate is NaN or infinite.
    """
    pts = np.array([[ps.pose.position.x, ps.pose.position.y, ps.pose.position.z]
                    for ps in msg.poses], dtype=float).reshape(-1, 3)
    if check_finite and not np.all(np.isfinite(pts)):
        raise InvalidInputError('path contains NaN or infinite coordinates')
    return pts


def odometry_msg(pose: Pose, stamp: Optional[Time] = None, velocity: Sequence[float] = (0.0, 0.0, 0.0),
                 frame_id: str = FRAME_ID, child_frame_id: str = 'base_link') -> Odometry:
    """Return a ``nav_msgs/Odometry`` of ``pose`` with linear ``velocity`` [m/s] in the map frame."""
    msg = Odometry()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.child_frame_id = child_frame_id
    x, y, z = pose.position
    msg.pose.pose.position = Point(x=float(x), y=float(y), z=float(z))
    msg.pose.pose.orientation = yaw_to_quaternion(pose.yaw)
    vx, vy, vz = (float(v) for v in velocity)
    msg.twist.twist.linear.x, msg.twist.twist.linear.y, msg.twist.twist.linear.z = vx, vy, vz
    return msg


def pose_stamped_msg(pose: Pose, stamp: Optional[Time] = None, frame_id: str = FRAME_ID) -> PoseStamped:
    """Return a ``geometry_msgs/PoseStamped`` of ``pose``."""
    msg = PoseStamped(header=Header(stamp=stamp or Time(), frame_id=frame_id))
    x, y, z = pose.position
    msg.pose.position = Point(x=float(x), y=float(y), z=float(z))
    msg.pose.orientation = yaw_to_quaternion(pose.yaw)
    return msg


def pose_stamped_pose(msg: PoseStamped) -> Pose:
    """Return the pose of a ``PoseStamped``.

    Raises
    ------
    InvalidInputError
        On NaN or infinite values.
    """
    p, q = msg.pose.position, msg.pose.orientation
    if not all(math.isfinite(v) for v in (p.x, p.y, p.z, q.x, q.y, q.z, q.w)):
        raise InvalidInputError('pose contains NaN or infinite values')
    return Pose((float(p.x), float(p.y), float(p.z)), quaternion_to_yaw(q))


def odometry_pose(msg: Odometry) -> Pose:
    """Return the pose in an odometry message.

    Raises
    ------
    InvalidInputError
        On a NaN or infinite position or orientation.
    """
    p = msg.pose.pose.position
    q = msg.pose.pose.orientation
    values = (p.x, p.y, p.z, q.x, q.y, q.z, q.w)
    if not all(math.isfinite(v) for v in values):
        raise InvalidInputError('odometry contains NaN or infinite values')
    return Pose((float(p.x), float(p.y), float(p.z)), quaternion_to_yaw(q))


def parse_planar_pose(text: str) -> Optional[Pose]:
    """Return the pose of ``"x,y,yaw"`` [m, m, rad] (None for ""); a parameter's text.

    Raises
    ------
    InvalidInputError
        Unless three finite numbers.
    """
    if not text.strip():
        return None
    try:
        x, y, yaw = (float(v) for v in text.split(','))
    except ValueError:
        raise InvalidInputError(f'expected "x,y,yaw", got {text!r}') from None
    if not all(math.isfinite(v) for v in (x, y, yaw)):
        raise InvalidInputError(f'"x,y,yaw" must be finite, got {text!r}')
    return Pose((x, y, 0.0), yaw)


def odometry_in_map(msg: Odometry, map_frame: str, odom_frame: str, map_to_odom: Optional[Pose]) -> Pose:
    """Return the odometry's pose in ``map_frame``.

    A pose in ``map_frame`` is taken as it is; one in ``odom_frame`` is moved by the fixed
    ``map_to_odom`` (the odom frame's pose in the map) when one is given.

    Raises
    ------
    FrameMismatchError
        For any other frame (the message names both): planning from it would be wrong.
    InvalidInputError
        On NaN or infinite values.
    """
    frame = msg.header.frame_id
    pose = odometry_pose(msg)
    if frame == map_frame:
        return pose
    if frame == odom_frame and map_to_odom is not None:
        return compose_planar(map_to_odom, pose)
    expected = [map_frame] + ([odom_frame] if map_to_odom is not None else [])
    hint = '' if map_to_odom is not None else f' (set map_to_odom to take poses in {odom_frame!r})'
    raise FrameMismatchError(f'odometry is in frame {frame!r}, expected {" or ".join(map(repr, expected))}'
                             f'{hint}', details={'frame': frame, 'expected': expected})


def check_map_frame(msg: Any, map_frame: str, what: str) -> None:
    """Refuse a map (``what``: its topic) that is not in the frame the tasks are planned in.

    Raises
    ------
    FrameMismatchError
        Naming both frames: a map in another frame (or in none) would put every obstacle wrong.
    """
    frame = msg.header.frame_id
    if frame != map_frame:
        raise FrameMismatchError(f'{what} is in frame {frame!r}, expected {map_frame!r}',
                                 details={'frame': frame, 'expected': [map_frame]})


# ---------------------------------------------------------------------------- occupancy grid
def occupancy_grid_msg(raster: OccupancyRaster, stamp: Optional[Time] = None,
                       frame_id: str = FRAME_ID) -> OccupancyGrid:
    """Return a ``nav_msgs/OccupancyGrid`` of ``raster`` (row-major, origin at cell (0, 0)'s corner)."""
    msg = OccupancyGrid()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.info.resolution = float(raster.resolution)
    msg.info.width = raster.width
    msg.info.height = raster.height
    msg.info.origin.position = Point(x=raster.origin[0], y=raster.origin[1], z=0.0)
    msg.info.origin.orientation = Quaternion(w=1.0)
    msg.data = raster.cells.astype(np.int8).ravel().tolist()
    return msg


def occupancy_raster(msg: OccupancyGrid) -> OccupancyRaster:
    """Return the grid of an ``OccupancyGrid`` message (origin rotation must be identity).

    Raises
    ------
    InvalidInputError
        On an empty grid, a data length that does not match, a non-positive or
        non-finite resolution, a rotated origin, or a map beyond the largest scene extent.
    """
    info = msg.info
    w, h = int(info.width), int(info.height)
    if w == 0 or h == 0:
        raise InvalidInputError('the map is empty (0 cells)')
    if not (info.resolution > 0.0 and math.isfinite(info.resolution)):
        raise InvalidInputError(f'map resolution must be positive, got {info.resolution}')
    if len(msg.data) != w * h:
        raise InvalidInputError(f'map data has {len(msg.data)} cells, expected {w}x{h}')
    q = info.origin.orientation
    if abs(quaternion_to_yaw(q)) > 1e-6:
        raise InvalidInputError('rotated map origins are not supported')
    o = info.origin.position
    if not (math.isfinite(o.x) and math.isfinite(o.y)):
        raise InvalidInputError('map origin is not finite')
    far = max(abs(o.x), abs(o.y), abs(o.x + w * info.resolution), abs(o.y + h * info.resolution))
    if max(w, h) * info.resolution > MAX_SCENE_EXTENT_M or far > MAX_SCENE_EXTENT_M:
        raise InvalidInputError(f'the map spans {w * info.resolution:g} x {h * info.resolution:g} m from '
                                f'({o.x:g}, {o.y:g}): beyond the largest scene ({MAX_SCENE_EXTENT_M:g} m)')
    cells = np.asarray(msg.data, dtype=np.int8).reshape(h, w)
    return OccupancyRaster(cells, float(info.resolution), (float(o.x), float(o.y)))


def coverage_msg(coverage: Coverage, stamp: Optional[Time] = None, frame_id: str = FRAME_ID) -> OccupancyGrid:
    """Return what a camera covered as an ``OccupancyGrid``: -1 unseen, 0 seen, 100 seen, blocking sight."""
    g = coverage.grid
    msg = OccupancyGrid()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.info.resolution = float(g.cell)
    msg.info.width, msg.info.height = int(g.shape[0]), int(g.shape[1])
    msg.info.origin.position = Point(x=float(g.origin[0]), y=float(g.origin[1]), z=0.0)
    msg.info.origin.orientation = Quaternion(w=1.0)
    msg.data = array.array('b', np.ascontiguousarray(coverage.cells().T).tobytes())
    return msg


def coverage_from_msg(msg: OccupancyGrid) -> Coverage:
    """Inverse of :func:`coverage_msg`.

    Raises
    ------
    InvalidInputError
        On an empty grid, a data length that does not match, or a bad resolution or origin.
    """
    raster = occupancy_raster(msg)
    grid = PlaneGrid(raster.origin, raster.resolution, (raster.width, raster.height))
    return Coverage.from_cells(grid, raster.cells.T)


def occupied_rectangles(cells: np.ndarray, occupied_threshold: int = 50) -> list[tuple[int, int, int, int]]:
    """Cover the blocked cells of a grid with rectangles ``(row0, row1, col0, col1)`` (ends excluded).

    Blocked: values >= ``occupied_threshold`` or unknown (< 0). Runs of blocked cells in a
    row are merged with the rectangle above them when they span the same columns, so walls
    and furniture become a few rectangles (exact: every blocked cell is covered, no free one).
    """
    blocked = (cells >= occupied_threshold) | (cells < 0)
    rects: list[list[int]] = []
    open_by_span: dict[tuple[int, int], list[int]] = {}
    for r in range(blocked.shape[0]):
        row = np.concatenate([[False], blocked[r], [False]])
        edges = np.flatnonzero(row[1:] != row[:-1])
        spans = list(zip(edges[::2].tolist(), edges[1::2].tolist()))
        still_open: dict[tuple[int, int], list[int]] = {}
        for span in spans:
            rect = open_by_span.get(span)
            if rect is not None and rect[1] == r:
                rect[1] = r + 1
            else:
                rect = [r, r + 1, span[0], span[1]]
                rects.append(rect)
            still_open[span] = rect
        open_by_span = still_open
    return [tuple(x) for x in rects]  # type: ignore[misc]


def planning_world_from_grid(msg: OccupancyGrid, robot_radius: float) -> PlanningWorld:
    """Return the 2D planning world of an occupancy grid: blocked cells as exact boxes, inflated.

    Occupied (>= 50) and unknown (< 0) cells are blocked. They are merged into rectangles
    (:func:`occupied_rectangles`) so the planner checks a few boxes exactly instead of
    looking cells up: the same free space, much faster.

    Raises
    ------
    InvalidInputError
        On an empty or malformed grid.
    """
    raster = occupancy_raster(msg)
    res = raster.resolution
    ox, oy = raster.origin
    boxes = []
    for r0, r1, c0, c1 in occupied_rectangles(raster.cells):
        lo = (ox + c0 * res, oy + r0 * res)
        hi = (ox + c1 * res, oy + r1 * res)
        boxes.append(Box(((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, 0.0),
                         (hi[0] - lo[0], hi[1] - lo[1], 1.0)))
    bmin = (ox + robot_radius, oy + robot_radius)
    bmax = (ox + raster.width * res - robot_radius, oy + raster.height * res - robot_radius)
    if bmin[0] > bmax[0] or bmin[1] > bmax[1]:
        raise InvalidInputError('the map is smaller than the robot')
    return PlanningWorld(2, bmin, bmax, float(robot_radius), tuple(boxes))


def parse_bounds(text: str) -> Optional[tuple[tuple[float, float, float], tuple[float, float, float]]]:
    """Parse ``'xmin,ymin,zmin,xmax,ymax,zmax'`` [m] ('' -> None).

    Raises
    ------
    InvalidInputError
        Unless six finite numbers with min below max on every axis.
    """
    if not text.strip():
        return None
    try:
        v = [float(x) for x in text.split(',')]
    except ValueError:
        raise InvalidInputError(f'bounds must be six numbers xmin,ymin,zmin,xmax,ymax,zmax, '
                                f'got {text!r}') from None
    if len(v) != 6 or not all(math.isfinite(x) for x in v) or any(v[k] >= v[k + 3] for k in range(3)):
        raise InvalidInputError(f'bounds must be six finite numbers with min < max, got {text!r}')
    return (v[0], v[1], v[2]), (v[3], v[4], v[5])


def planning_world_from_cloud(msg: PointCloud2, voxel: float, robot_radius: float,
                              bounds: Optional[tuple[Sequence[float], Sequence[float]]] = None,
                              ) -> PlanningWorld:
    """Return the 3D planning world of an obstacle cloud inside ``bounds`` [m].

    The points are voxelised (cells of ``voxel`` [m]); the occupied voxels are merged into
    boxes (rectangles per layer, stacked where they repeat), which the planner checks
    exactly and fast; boxes are inflated by ``robot_radius``. Default bounds: the points'
    extent grown by one voxel.

    Raises
    ------
    InvalidInputError
        On an empty or malformed cloud, a bad voxel size, or too many voxels.
    """
    points = point_cloud_xyz(msg).astype(float)
    if len(points) == 0:
        raise InvalidInputError('the 3D map is empty (0 points)')
    if not (voxel > 0 and math.isfinite(voxel)):
        raise InvalidInputError(f'voxel size must be positive, got {voxel}')
    lo = points.min(axis=0)
    shape = np.floor((points.max(axis=0) - lo) / voxel).astype(int) + 1
    if float(np.prod(shape.astype(float))) > 50_000_000:
        raise InvalidInputError(f'the 3D map would need {int(np.prod(shape))} voxels; use a larger voxel')
    idx = np.minimum(np.floor((points - lo) / voxel).astype(int), shape - 1)
    blocked = np.zeros(tuple(shape), dtype=bool)
    blocked[idx[:, 0], idx[:, 1], idx[:, 2]] = True
    boxes: list[Box] = []
    stacks: dict[tuple[int, int, int, int], list[int]] = {}
    for z in range(shape[2]):
        layer = np.where(blocked[:, :, z].T, 100, 0).astype(np.int8)   # rows y, columns x
        still: dict[tuple[int, int, int, int], list[int]] = {}
        for rect in occupied_rectangles(layer):
            stack = stacks.get(rect)
            if stack is not None and stack[1] == z:
                stack[1] = z + 1
            else:
                stack = [z, z + 1]
            still[rect] = stack
        for rect, stack in stacks.items():   # stacks that did not go on are finished
            if still.get(rect) is not stack:
                boxes.append(_voxel_box(lo, voxel, rect, stack))
        stacks = still
    boxes.extend(_voxel_box(lo, voxel, rect, stack) for rect, stack in stacks.items())
    if bounds is None:
        bmin, bmax = tuple(lo - voxel), tuple(lo + (shape + 1) * voxel)
    else:
        bmin, bmax = tuple(bounds[0]), tuple(bounds[1])
    return PlanningWorld(3, tuple(float(v) for v in bmin), tuple(float(v) for v in bmax),
                         float(robot_radius), tuple(boxes))


def _voxel_box(lo: np.ndarray, voxel: float, rect: tuple[int, int, int, int], stack: list[int]) -> Box:
    r0, r1, c0, c1 = rect   # rows are y, columns are x
    a = lo + voxel * np.array([c0, r0, stack[0]], dtype=float)
    b = lo + voxel * np.array([c1, r1, stack[1]], dtype=float)
    return Box(tuple(float(v) for v in (a + b) / 2), tuple(float(v) for v in b - a))


# ---------------------------------------------------------------------------- point clouds
def point_cloud_msg(points: np.ndarray, values: Optional[Mapping[str, np.ndarray]] = None,
                    stamp: Optional[Time] = None, frame_id: str = FRAME_ID) -> PointCloud2:
    """Return an unorganised ``PointCloud2`` with float32 fields x, y, z and any extra ``values``.

    Parameters
    ----------
    points: positions [m], shape (N, 3).
    values: extra per-point float fields, each shape (N,) (e.g. ``{'value': ...}``).
    """
    p = np.asarray(points, dtype=np.float32).reshape(-1, 3)
    names = ['x', 'y', 'z'] + list(values or {})
    cols = [p[:, 0], p[:, 1], p[:, 2]] + [np.asarray(v, dtype=np.float32).reshape(-1)
                                          for v in (values or {}).values()]
    for c in cols:
        if c.shape[0] != p.shape[0]:
            raise InvalidInputError('every point-cloud field needs one value per point')
    rec = np.zeros(p.shape[0], dtype=[(n, '<f4') for n in names])
    for n, c in zip(names, cols):
        rec[n] = c
    msg = PointCloud2()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.height = 1
    msg.width = int(p.shape[0])
    msg.fields = [PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
                  for i, n in enumerate(names)]
    msg.is_bigendian = False
    msg.point_step = 4 * len(names)
    msg.row_step = msg.point_step * msg.width
    msg.is_dense = True
    msg.data = rec.tobytes()
    return msg


def point_cloud_fields(msg: PointCloud2) -> dict[str, np.ndarray]:
    """Every FLOAT32 field of a little-endian ``PointCloud2`` as a float32 array, shape (N,).

    Raises
    ------
    InvalidInputError
        On big-endian data, a non-float32 field, a field outside the point or a name empty or
        repeated, or a data size that does not match.
    """
    if msg.is_bigendian:
        raise InvalidInputError('big-endian point clouds are not supported')
    n = int(msg.width) * int(msg.height)
    if len(msg.data) != n * int(msg.point_step):
        raise InvalidInputError(f'point cloud data has {len(msg.data)} bytes, expected '
                                f'{n} x {msg.point_step}')
    dtype = {'names': [], 'formats': [], 'offsets': [], 'itemsize': int(msg.point_step)}
    for f in msg.fields:
        if f.datatype != PointField.FLOAT32 or f.count != 1:
            raise InvalidInputError(f'point-cloud field {f.name!r} is not a single float32')
        if int(f.offset) + 4 > int(msg.point_step):
            raise InvalidInputError(f'point-cloud field {f.name!r} at byte {f.offset} does not fit in a '
                                    f'point of {msg.point_step} bytes')
        if not f.name or f.name in dtype['names']:
            raise InvalidInputError(f'point-cloud field name {f.name!r} is empty or repeated')
        dtype['names'].append(f.name)
        dtype['formats'].append('<f4')
        dtype['offsets'].append(int(f.offset))
    rec = np.frombuffer(bytes(msg.data), dtype=np.dtype(dtype), count=n)
    return {name: np.array(rec[name]) for name in dtype['names']}


def point_cloud_xyz(msg: PointCloud2) -> np.ndarray:
    """Positions of a ``PointCloud2`` [m], shape (N, 3) float32, non-finite rows dropped."""
    f = point_cloud_fields(msg)
    if not {'x', 'y', 'z'} <= set(f):
        raise InvalidInputError('point cloud lacks x, y or z')
    p = np.stack([f['x'], f['y'], f['z']], axis=1)
    return p[np.all(np.isfinite(p), axis=1)]


# ---------------------------------------------------------------------------- images
_ENCODINGS = {'rgb8': (np.uint8, 3), 'bgr8': (np.uint8, 3), 'rgba8': (np.uint8, 4), 'bgra8': (np.uint8, 4),
              '32FC1': (np.float32, 1), '32SC1': (np.int32, 1), 'mono8': (np.uint8, 1),
              '16UC1': (np.uint16, 1)}
DEPTH_ENCODINGS = ('32FC1', '16UC1')


def image_msg(array: np.ndarray, encoding: str, stamp: Optional[Time] = None,
              frame_id: str = 'camera_optical') -> Image:
    """Return an ``Image`` of ``array``: rgb8 (H, W, 3) uint8, 32FC1 (H, W) depth [m], 32SC1 labels."""
    if encoding not in _ENCODINGS:
        raise InvalidInputError(f'unsupported image encoding {encoding!r}')
    dtype, channels = _ENCODINGS[encoding]
    a = np.ascontiguousarray(np.asarray(array), dtype=np.dtype(dtype).newbyteorder('<'))
    if (channels == 1 and a.ndim != 2) or (channels > 1 and (a.ndim != 3 or a.shape[2] != channels)):
        shape = '(H, W, %d)' % channels if channels > 1 else '(H, W)'
        raise InvalidInputError(f'{encoding} image needs shape {shape}, got {a.shape}')
    msg = Image()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.height, msg.width = int(a.shape[0]), int(a.shape[1])
    msg.encoding = encoding
    msg.is_bigendian = 0
    msg.step = int(a.shape[1] * a.itemsize * channels)
    msg.data = a.tobytes()
    return msg


def image_array(msg: Image) -> np.ndarray:
    """Return the pixels of a ``sensor_msgs/Image`` (encodings as in :func:`image_msg`).

    Raises
    ------
    InvalidInputError
        On an unsupported encoding or a size that does not match.
    """
    if msg.encoding not in _ENCODINGS:
        raise InvalidInputError(f'unsupported image encoding {msg.encoding!r}')
    dtype, channels = _ENCODINGS[msg.encoding]
    dt = np.dtype(dtype).newbyteorder('>' if msg.is_bigendian else '<')
    row = msg.width * channels * dt.itemsize
    if msg.step < row or len(msg.data) != msg.step * msg.height:
        raise InvalidInputError(f'image data of {len(msg.data)} bytes does not match '
                                f'{msg.height} rows of {msg.step} bytes')
    raw = np.frombuffer(bytes(msg.data), dtype=np.uint8).reshape(msg.height, msg.step)[:, :row]
    a = np.ascontiguousarray(raw).view(dt).reshape(msg.height, msg.width, channels)
    return (a[:, :, 0] if channels == 1 else a).astype(dt.newbyteorder('='))


def depth_array(msg: Image) -> np.ndarray:
    """Return a depth image in metres, float32 (H, W), NaN where there is no return.

    REP 118: ``32FC1`` is in metres (NaN or inf: no return), ``16UC1`` in millimetres
    (0: no return).

    Raises
    ------
    InvalidInputError
        On another encoding, or a size that does not match.
    """
    if msg.encoding not in DEPTH_ENCODINGS:
        raise InvalidInputError(f'depth images must be 32FC1 [m] or 16UC1 [mm], got {msg.encoding!r}')
    raw = image_array(msg)
    if msg.encoding == '16UC1':
        return np.where(raw > 0, raw.astype(np.float32) * np.float32(0.001), np.float32(np.nan))
    return raw.astype(np.float32, copy=False)


def depth_msg(depth: np.ndarray, encoding: str = '32FC1', stamp: Optional[Time] = None,
              frame_id: str = 'camera_optical') -> Image:
    """Return a depth ``Image`` of metres (H, W) (NaN: none) as ``32FC1`` [m] or ``16UC1`` [mm, 0: none]."""
    if encoding not in DEPTH_ENCODINGS:
        raise InvalidInputError(f'depth images must be 32FC1 or 16UC1, got {encoding!r}')
    d = np.asarray(depth, dtype=np.float32)
    if encoding == '16UC1':
        with np.errstate(invalid='ignore'):
            mm = np.where(np.isfinite(d) & (d > 0), np.rint(d * 1000.0), 0.0)
        d = np.clip(mm, 0, 65535).astype(np.uint16)
    return image_msg(d, encoding, stamp, frame_id)


def rgb_array(msg: Image) -> np.ndarray:
    """Return a colour image as uint8 RGB (H, W, 3) from rgb8, bgr8, rgba8 or bgra8.

    Raises
    ------
    InvalidInputError
        On another encoding, or a size that does not match.
    """
    if msg.encoding not in ('rgb8', 'bgr8', 'rgba8', 'bgra8'):
        raise InvalidInputError(f'colour images must be rgb8, bgr8, rgba8 or bgra8, got {msg.encoding!r}')
    a = image_array(msg)[:, :, :3]
    return np.ascontiguousarray(a[:, :, ::-1] if msg.encoding.startswith('bgr') else a)


def camera_info_msg(width: int, height: int, fx: float, fy: float, cx: float, cy: float,
                    stamp: Optional[Time] = None, frame_id: str = 'camera_optical') -> CameraInfo:
    """Return a ``CameraInfo`` of a pinhole camera without distortion (intrinsics in pixels)."""
    msg = CameraInfo()
    msg.header = Header(stamp=stamp or Time(), frame_id=frame_id)
    msg.width, msg.height = int(width), int(height)
    msg.distortion_model = 'plumb_bob'
    msg.d = [0.0] * 5
    msg.k = [float(fx), 0.0, float(cx), 0.0, float(fy), float(cy), 0.0, 0.0, 1.0]
    msg.r = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    msg.p = [float(fx), 0.0, float(cx), 0.0, 0.0, float(fy), float(cy), 0.0, 0.0, 0.0, 1.0, 0.0]
    return msg


def camera_intrinsics(msg: CameraInfo) -> tuple[int, int, float, float, float, float]:
    """``(width, height, fx, fy, cx, cy)`` of a ``CameraInfo``.

    Raises
    ------
    InvalidInputError
        On a zero size or non-finite/non-positive focal lengths.
    """
    k = list(msg.k)
    fx, fy, cx, cy = k[0], k[4], k[2], k[5]
    if msg.width == 0 or msg.height == 0 or not all(math.isfinite(v) for v in (fx, fy, cx, cy)) \
            or fx <= 0 or fy <= 0:
        raise InvalidInputError('camera_info has no valid intrinsics')
    return int(msg.width), int(msg.height), float(fx), float(fy), float(cx), float(cy)


# ---------------------------------------------------------------------------- markers
def referent_markers(rmap: ReferentMap, stamp: Optional[Time] = None,
                     namespace: str = 'referents', frame_id: Optional[str] = None) -> MarkerArray:
    """One cube and one text marker per resolved instance (green: resolved, orange: ambiguous).

    ``frame_id`` overrides the referent map's frame (a robot's prefixed map frame).
    """
    out = MarkerArray()
    frame = frame_id or rmap.frame_id
    clear = Marker(action=Marker.DELETEALL)
    clear.header = Header(stamp=stamp or Time(), frame_id=frame)
    out.markers.append(clear)
    mid = 0
    for descriptor, g in sorted(rmap.groundings.items()):
        for inst in g.instances:
            for kind in (Marker.CUBE, Marker.TEXT_VIEW_FACING):
                m = Marker()
                m.header = Header(stamp=stamp or Time(), frame_id=frame)
                m.ns, m.id, m.type, m.action = namespace, mid, kind, Marker.ADD
                mid += 1
                x, y, z = inst.center
                m.pose.position = Point(x=float(x), y=float(y), z=float(z))
                m.pose.orientation = Quaternion(w=1.0)
                sx, sy, sz = (max(float(s), 0.1) for s in inst.size)
                ok = g.outcome.value == 'RESOLVED'
                rgba = (0.1, 0.8, 0.2, 0.6) if ok else (1.0, 0.6, 0.0, 0.6)
                m.color.r, m.color.g, m.color.b, m.color.a = rgba
                if kind == Marker.CUBE:
                    m.scale.x, m.scale.y, m.scale.z = sx, sy, sz
                else:
                    m.pose.position.z = float(z) + sz / 2.0 + 0.3
                    m.scale.z = 0.3
                    m.text = f'{descriptor} ({inst.id})'
                out.markers.append(m)
    return out

"""``referent_grounder``: resolve a task's referent descriptors in the semantic map.

Instances come from a known object list (the ``scene`` parameter: a built-in scene
name or a scene file, as a pre-built map) and, with ``use_camera``, from the camera:
every depth (``32FC1`` [m] or ``16UC1`` [mm], REP 118) + label frame with its intrinsics
(``CameraInfo`` K) is integrated into a persistent semantic map from the camera's pose:
the robot's ``odom`` pose at the frame's stamp (interpolated) composed with the fixed
camera extrinsic (``camera_x/y/z/yaw/pitch``). For each ``task_spec`` the descriptors are resolved with
the 3D spatial comparators and the result published on ``referent_map`` (latched
JSON, with the instruction's ``id``; ``ok: false`` with a typed error such as
``UNKNOWN_REFERENT`` when a descriptor resolves to nothing) and as RViz markers.

When new detections change what a recent task's descriptors resolve to, a new
``revision`` of its referent map is published, and ``task_progression`` replans (or,
while it searches for a referent, plans the task). A referent map that leaves a required
descriptor unresolved says whether the camera could find it (``searchable``: a camera is
on and each name matches a class of its label images); while one does, every integrated
frame also publishes what the camera has covered on ``search/coverage`` (latched
``nav_msgs/OccupancyGrid``: -1 unseen, 0 seen, 100 seen and blocking sight), which
``task_progression`` explores.

Each task spec is grounded once (by id): the translator sends the specs in flight again
whenever a reader of ``task_spec`` (re)starts, and a repeat is not grounded again. The
subscription is volatile, so a restarted grounder grounds only what is still in flight.
"""
from __future__ import annotations

import sys
import threading
import time
from collections import OrderedDict
from typing import Any, Optional

import numpy as np
from nav_msgs.msg import OccupancyGrid, Odometry
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from ltl_instruct import conversions as conv
from ltl_instruct.core import grounding
from ltl_instruct.core.errors import ErrorCode, LtlInstructError
from ltl_instruct.core.grounding.coverage import map_coverage
from ltl_instruct.core.grounding.detectors import load_labeller
from ltl_instruct.core.grounding.online_search import findable
from ltl_instruct.core.grounding.search import unresolved
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.spec import Formula, parse_descriptor, parse_formula
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.camera import CameraMount
from ltl_instruct.core.world.pose_history import PoseHistory
from ltl_instruct.nodes.common import (
    ParamSpec, declare_parameters, frames_of, latched_qos, reliable_qos, run_node, sensor_qos,
    subscribe_any_reliability,
)

PARAMS = (
    ParamSpec('scene', '', 'known objects: built-in scene name or scene file ("" = camera only)'),
    ParamSpec('use_camera', True, 'integrate camera frames (depth + labels) into the semantic map'),
    ParamSpec('camera_min_interval', 0.5, 'least time between two integrated frames [s]', 0.0, 60.0),
    ParamSpec('voxel_size', 0.1, 'edge of a semantic-map voxel [m]', 0.02, 2.0),
    ParamSpec('merge_distance', 0.75, 'a detection this close to a known object of its label is that '
              'object [m]', 0.0, 10.0),
    ParamSpec('axis_threshold', 0.1, 'threshold of above/below/left/right/front/behind [m]', 0.0, 50.0),
    ParamSpec('nextto_threshold', 1.0, 'isnextto holds below this distance [m]', 0.0, 50.0),
    ParamSpec('between_threshold', 0.5, 'isbetween holds within this distance of the segment [m]', 0.0, 50.0),
    ParamSpec('viewpoint', 'origin', 'frame of reference of the comparators', choices=('origin', 'robot')),
    ParamSpec('use_embeddings', False, 'also match names with the packaged sentence-embedding model'),
    ParamSpec('camera_x', 0.0, 'camera extrinsic: ahead of the robot\'s odometry position [m]', -10.0, 10.0),
    ParamSpec('camera_y', 0.0, 'camera extrinsic: left of the robot\'s position [m]', -10.0, 10.0),
    ParamSpec('camera_z', 1.0, 'camera extrinsic: height above the robot\'s position [m]', -10.0, 10.0),
    ParamSpec('camera_yaw', 0.0, 'camera extrinsic: turned left of the robot\'s heading [rad]',
              -3.1416, 3.1416),
    ParamSpec('camera_pitch', 0.0, 'camera extrinsic: pitched down [rad]', -1.5708, 1.5708),
    ParamSpec('detector', 'labels', 'where object classes come from: the label images of a segmenter '
              '(labels), or the RGB images through an open-vocabulary detector queried with the tasks\' '
              'referent names (owlvit, owlv2; weights from detector_model_dir)',
              choices=('labels', 'owlvit', 'owlv2')),
    ParamSpec('detector_model_dir', '', 'folder of the detector\'s weights (save_pretrained output)'),
    ParamSpec('segmenter_model_dir', '', 'folder of SAM\'s weights ("" = a detection\'s box is its mask)'),
    ParamSpec('detector_threshold', 0.1, 'least score of a detection', 0.0, 1.0),
    ParamSpec('pose_tolerance', 0.1, 'a frame is integrated with the odometry pose of its stamp, '
              'interpolated, when one lies within this time of it [s]', 0.0, 10.0),
)
# read at each grounding or frame; the known objects, the map's voxels and the embedding model are read-only
RUNTIME = frozenset({'camera_min_interval', 'merge_distance', 'axis_threshold', 'nextto_threshold',
                     'between_threshold', 'viewpoint'})
GROUNDED_MEMORY = 10_000   # task ids remembered, so that a spec sent again is not grounded twice
TASKS_FOLLOWED = 4         # the latest tasks grounded again on every frame (one may be searching)


class ReferentGrounderNode(Node):
    """Task spec (and camera frames) in, referent semantic map out."""

    def __init__(self) -> None:
        super().__init__('referent_grounder')
        self.params = declare_parameters(self, PARAMS, RUNTIME)
        self.frames = frames_of(self.params)
        self._map_to_odom = conv.parse_planar_pose(self.params['map_to_odom'])
        self._lock = threading.Lock()
        self._known = grounding.instances_from_scene(resolve_scene(self.params['scene'])) \
            if self.params['scene'] else ()
        self._semantic_map: Any = self._make_semantic_map() if self.params['use_camera'] else None
        self._labeller: Any = None            # RGB -> label images (detector other than labels)
        self._model_error: Optional[LtlInstructError] = None
        self._detected: tuple = ()   # new detections, extracted after each integrated frame
        self._pose: Any = None
        self._info: Optional[CameraInfo] = None
        self._labels: Optional[Image] = None
        self._poses = PoseHistory(tolerance=self.params['pose_tolerance'])   # odometry, by stamp
        self._frame: Optional[tuple[Image, Image, CameraInfo]] = None   # waits for the odometry of its stamp
        self._last_frame = 0.0
        self._tasks: OrderedDict[str, dict[str, Any]] = OrderedDict()   # the latest grounded tasks, by id
        self._grounded: OrderedDict[str, None] = OrderedDict()   # ids grounded already
        self.rmap_pub = self.create_publisher(String, 'referent_map', latched_qos())
        self.marker_pub = self.create_publisher(MarkerArray, 'referent_map/markers', latched_qos(1))
        self.coverage_pub = self.create_publisher(OccupancyGrid, 'search/coverage', latched_qos(1))
        self.create_subscription(String, 'task_spec', self.on_task_spec, reliable_qos())
        subscribe_any_reliability(self, Odometry, 'odom', self.on_odom, 10)
        if self._semantic_map is not None:
            self.create_subscription(CameraInfo, 'camera/color/camera_info', self.on_info, sensor_qos())
            self._subscribe_classes_source()
            self.create_subscription(Image, 'camera/depth/image_raw', self.on_depth, sensor_qos())
            self.create_subscription(String, 'camera/labels/classes', self.on_classes, latched_qos(1))
        self.get_logger().info(f'referent_grounder: {len(self._known)} known objects, '
                               f'camera {"on" if self._semantic_map is not None else "off"}')

    def _subscribe_classes_source(self) -> None:
        """Subscribe to the label images, or load the detector and subscribe to the RGB images."""
        p = self.params
        if p['detector'] == 'labels':
            self.create_subscription(Image, 'camera/labels/image_raw', self.on_labels, sensor_qos())
            return
        try:
            self._labeller = load_labeller(p['detector'], p['detector_model_dir'], p['segmenter_model_dir'],
                                           p['detector_threshold'])
        except LtlInstructError as e:   # the node keeps running: each unresolved task says why
            self._model_error = e
            self.get_logger().error(f'detector {p["detector"]} not loaded: {e.message}')
        self.create_subscription(Image, 'camera/color/image_raw', self.on_labels, sensor_qos())

    def _make_semantic_map(self) -> Any:
        semantic_map = getattr(grounding, 'SemanticMap', None)
        if semantic_map is None:
            self.get_logger().warning('no semantic map in this build: grounding uses the known objects only')
            return None
        p = self.params
        mount = CameraMount(height=p['camera_z'], pitch=p['camera_pitch'], x=p['camera_x'], y=p['camera_y'],
                            yaw=p['camera_yaw'])
        return semantic_map(params=grounding.SemanticMapParams(voxel_size=p['voxel_size']), mount=mount)

    # ------------------------------------------------------------------ grounding
    def _instances(self) -> tuple:
        return tuple(self._known) + self._detected

    def _new_detections(self, detected: tuple) -> tuple:
        """Keep the detections that are not a known object seen again (same label, centres close)."""
        limit = self.params['merge_distance']
        out = []
        for d in detected:
            same = [k for k in self._known if k.label.lower() == d.label.lower()
                    and float(np.linalg.norm(np.subtract(k.center, d.center))) <= limit + max(k.size) / 2]
            if not same:
                out.append(d)
        return tuple(out)

    def _ground(self, formula: Formula) -> ReferentMap:
        return grounding.ground_formula(formula, self._instances(), self._grounding_params())

    def _grounding_params(self) -> Any:
        viewpoint = None
        if self.params['viewpoint'] == 'robot' and self._pose is not None:
            viewpoint = tuple(self._pose.position) + (self._pose.yaw,)
        p = self.params
        return grounding.GroundingParams(axis_threshold=p['axis_threshold'],
                                         nextto_threshold=p['nextto_threshold'],
                                         between_threshold=p['between_threshold'], viewpoint=viewpoint,
                                         use_embeddings=p['use_embeddings'])

    def on_task_spec(self, msg: String) -> None:
        """Ground a task's descriptors and publish its referent map (failed specs are skipped)."""
        try:
            spec = conv.parse_json_payload(msg.data, conv.TASK_SPEC)
        except LtlInstructError as e:
            self.get_logger().warning(f'task spec rejected: {e.message}')   # task_progression reports it
            return
        if not spec.get('ok') or not isinstance(spec.get('formula'), str) or self._seen(spec['id']):
            return
        iid = spec['id']
        t0 = time.monotonic()
        try:
            formula = parse_formula(spec['formula'])
            with self._lock:
                rmap = self._ground(formula)
            error = self._with_model_error(grounding.grounding_error(rmap))
        except LtlInstructError as e:
            self._publish(iid, None, 0, time.monotonic() - t0, e)
            return
        except Exception as e:  # noqa: BLE001 - a bug must not kill the node or lose the instruction
            self._publish(iid, None, 0, time.monotonic() - t0,
                          LtlInstructError(f'internal error: {e!r}', ErrorCode.INTERNAL_ERROR))
            return
        with self._lock:
            self._tasks[iid] = {'id': iid, 'formula': formula, 'rmap': rmap, 'revision': 0}
            while len(self._tasks) > TASKS_FOLLOWED:
                self._tasks.popitem(last=False)
        self._publish(iid, rmap, 0, time.monotonic() - t0, error)
        if error is not None:
            self._publish_coverage()

    def _with_model_error(self, error: Optional[LtlInstructError]) -> Optional[LtlInstructError]:
        """Make an unresolved referent a ``MODEL_ERROR`` when the detector could not be loaded."""
        if error is None or self._model_error is None:
            return error
        return LtlInstructError(f'{error.message}; the camera detects nothing: {self._model_error.message}',
                                ErrorCode.MODEL_ERROR, details=error.details)

    def _seen(self, iid: str) -> bool:
        """Tell whether ``iid`` was grounded already (a spec sent again); remember it if not."""
        if iid in self._grounded:
            return True
        self._grounded[iid] = None
        while len(self._grounded) > GROUNDED_MEMORY:
            self._grounded.popitem(last=False)
        return False

    def _publish(self, iid: str, rmap: Optional[ReferentMap], revision: int, seconds: float,
                 error: Optional[LtlInstructError]) -> None:
        fields: dict[str, Any] = dict(ok=error is None, revision=revision, timing={'ground_s': seconds})
        if rmap is not None:
            fields['referent_map'] = rmap.to_dict()
            fields['searchable'] = error is not None and self._searchable(rmap)
            self.marker_pub.publish(conv.referent_markers(rmap, self.get_clock().now().to_msg(),
                                                          frame_id=self.frames.map))
        if error is not None:
            fields['error'] = error.to_dict()
            self.get_logger().warning(f'{iid}: [{error.code.value}] {error.message}')
        self.rmap_pub.publish(conv.json_msg(conv.payload(conv.REFERENT_MAP, iid, **fields)))

    # ------------------------------------------------------------------ camera
    def on_odom(self, msg: Odometry) -> None:
        """Keep the robot pose (the camera's pose at each frame's stamp, and the viewpoint)."""
        try:
            self._pose = conv.odometry_in_map(msg, self.frames.map, self.frames.odom, self._map_to_odom)
        except LtlInstructError:
            return   # task_progression reports bad odometry; the last good pose is kept
        self._poses.add(conv.stamp_key(msg.header.stamp), self._pose)
        if self._frame is not None:
            self._integrate_frame()

    def on_classes(self, msg: String) -> None:
        """Learn the class table of the label images (class id -> label text)."""
        try:
            data = conv.parse_json_payload(msg.data, conv.LABEL_CLASSES)
            table = {int(k): str(v) for k, v in dict(data['classes']).items()}
        except (LtlInstructError, KeyError, TypeError, ValueError) as e:
            self.get_logger().warning(f'label classes rejected: {e}')
            return
        if self._semantic_map is not None:
            with self._lock:
                self._semantic_map.name_classes(table)

    def on_info(self, msg: CameraInfo) -> None:
        """Keep the latest intrinsics."""
        self._info = msg

    def on_labels(self, msg: Image) -> None:
        """Keep the latest label (with a detector: RGB) image, paired with the depth image of its stamp."""
        self._labels = msg

    def on_depth(self, msg: Image) -> None:
        """Integrate a depth + labels frame; republish the running task's map if it changed."""
        now = time.monotonic()
        if now - self._last_frame < self.params['camera_min_interval'] or self._model_error is not None:
            return
        key = conv.stamp_key(msg.header.stamp)
        labels, info = self._labels, self._info
        if labels is None or info is None or conv.stamp_key(labels.header.stamp) != key:
            return
        self._last_frame = now
        self._frame = (msg, labels, info)
        self._integrate_frame()

    def _integrate_frame(self) -> None:
        """Integrate the waiting frame with the robot's pose at its stamp (the mount is the extrinsic).

        A frame newer than the newest odometry waits for it; one with no odometry near its
        stamp is dropped.
        """
        assert self._frame is not None
        depth_msg, labels, info = self._frame
        key = conv.stamp_key(depth_msg.header.stamp)
        pose = self._poses.at(key)
        if pose is None:
            if not self._poses.waiting(key):
                self._frame = None
            return
        self._frame = None
        now = time.monotonic()
        try:
            depth = conv.depth_array(depth_msg)
            label_img = self._label_image(labels, depth)
            intrinsics = conv.camera_intrinsics(info)
            with self._lock:
                self._semantic_map.integrate(depth, label_img, intrinsics, pose)
                # clustering is the slow part: done here, per frame, not per instruction
                self._detected = self._new_detections(tuple(self._semantic_map.instances()))
                changed = [(t['id'], t['revision'] + 1, self._reground(t)) for t in self._tasks.values()]
            for iid, revision, rmap in changed:
                if rmap is not None:
                    error = grounding.grounding_error(rmap)
                    self._publish(iid, rmap, revision, time.monotonic() - now, error)
            self._publish_coverage()
        except LtlInstructError as e:
            self.get_logger().warning(f'camera frame rejected: {e.message}')

    def _label_image(self, msg: Image, depth: np.ndarray) -> np.ndarray:
        """Return the label image of a frame: as sent, or detected in its RGB image (the tasks' names)."""
        if self._labeller is None:
            return conv.image_array(msg)
        with self._lock:
            queries = sorted({name for t in self._tasks.values() for text in t['rmap'].groundings
                              for name in parse_descriptor(text).names()})
        labels = self._labeller.labels(conv.rgb_array(msg), queries, depth)
        with self._lock:
            self._semantic_map.name_classes(self._labeller.classes)
        return labels

    def _reground(self, task: dict[str, Any]) -> Optional[ReferentMap]:
        """Ground a followed task again (lock held); return its new referent map, or None when unchanged."""
        rmap = self._ground(task['formula'])
        if rmap.to_dict() == task['rmap'].to_dict():
            return None
        task['rmap'] = rmap
        task['revision'] += 1
        return rmap

    # ------------------------------------------------------------------ search
    def _searchable(self, rmap: ReferentMap) -> bool:
        """Tell whether the camera could find every required descriptor that denotes nothing yet.

        Only with a camera, and only names of the classes its label images hold: a search
        for a name no class matches would explore the whole map for nothing.
        """
        if self._semantic_map is None or self._model_error is not None:
            return False
        if self._labeller is not None:
            return True   # an open-vocabulary detector is asked for every name
        labels = list(self._semantic_map.class_names.values())
        params = self._grounding_params()
        return all(findable(text, labels, params) for text in unresolved(rmap))

    def _publish_coverage(self) -> None:
        """Publish what the camera has covered while a followed task is unresolved (the graph searches)."""
        if self._semantic_map is None:
            return
        with self._lock:
            if not any(unresolved(t['rmap']) for t in self._tasks.values()):
                return
            cov = map_coverage(self._semantic_map, self._semantic_map.mount.height)
        self.coverage_pub.publish(conv.coverage_msg(cov, self.get_clock().now().to_msg()))


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``referent_grounder`` console script."""
    return run_node(ReferentGrounderNode, args)


if __name__ == '__main__':
    sys.exit(main())

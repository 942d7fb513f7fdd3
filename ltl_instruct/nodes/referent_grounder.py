"""``referent_grounder``: resolve a task's referent descriptors in the semantic map.

Instances come from a known object list (the ``scene`` parameter: a built-in scene
name or a scene file, as a pre-built map) and, with ``use_camera``, from the camera:
every depth + label frame with its intrinsics and the robot's pose is integrated into
a persistent semantic map. For each ``task_spec`` the descriptors are resolved with
the 3D spatial comparators and the result published on ``referent_map`` (latched
JSON, with the instruction's ``id``; ``ok: false`` with a typed error such as
``UNKNOWN_REFERENT`` when a descriptor resolves to nothing) and as RViz markers.

When new detections change what the running task's descriptors resolve to, a new
``revision`` of its referent map is published, and ``task_progression`` replans.

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
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from ltl_instruct import conversions as conv
from ltl_instruct.core import grounding
from ltl_instruct.core.errors import ErrorCode, LtlInstructError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.spec import Formula, parse_formula
from ltl_instruct.core.world.builtin import resolve_scene
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
)
# read at each grounding or frame; the known objects, the map's voxels and the embedding model are read-only
RUNTIME = frozenset({'camera_min_interval', 'merge_distance', 'axis_threshold', 'nextto_threshold',
                     'between_threshold', 'viewpoint'})
GROUNDED_MEMORY = 10_000   # task ids remembered, so that a spec sent again is not grounded twice


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
        self._detected: tuple = ()   # new detections, extracted after each integrated frame
        self._pose: Any = None
        self._info: Optional[CameraInfo] = None
        self._labels: Optional[Image] = None
        self._camera_poses: dict[int, Any] = {}
        self._last_frame = 0.0
        self._task: Optional[dict[str, Any]] = None   # the latest grounded task
        self._grounded: OrderedDict[str, None] = OrderedDict()   # ids grounded already
        self.rmap_pub = self.create_publisher(String, 'referent_map', latched_qos())
        self.marker_pub = self.create_publisher(MarkerArray, 'referent_map/markers', latched_qos(1))
        self.create_subscription(String, 'task_spec', self.on_task_spec, reliable_qos())
        subscribe_any_reliability(self, Odometry, 'odom', self.on_odom, 10)
        if self._semantic_map is not None:
            self.create_subscription(CameraInfo, 'camera/color/camera_info', self.on_info, sensor_qos())
            self.create_subscription(Image, 'camera/labels/image_raw', self.on_labels, sensor_qos())
            self.create_subscription(Image, 'camera/depth/image_raw', self.on_depth, sensor_qos())
            self.create_subscription(PoseStamped, 'camera/pose', self.on_camera_pose, sensor_qos())
            self.create_subscription(String, 'camera/labels/classes', self.on_classes, latched_qos(1))
        self.get_logger().info(f'referent_grounder: {len(self._known)} known objects, '
                               f'camera {"on" if self._semantic_map is not None else "off"}')

    def _make_semantic_map(self) -> Any:
        semantic_map = getattr(grounding, 'SemanticMap', None)
        if semantic_map is None:
            self.get_logger().warning('no semantic map in this build: grounding uses the known objects only')
            return None
        return semantic_map(params=grounding.SemanticMapParams(voxel_size=self.params['voxel_size']))

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
            error = grounding.grounding_error(rmap)
        except LtlInstructError as e:
            self._publish(iid, None, 0, time.monotonic() - t0, e)
            return
        except Exception as e:  # noqa: BLE001 - a bug must not kill the node or lose the instruction
            self._publish(iid, None, 0, time.monotonic() - t0,
                          LtlInstructError(f'internal error: {e!r}', ErrorCode.INTERNAL_ERROR))
            return
        with self._lock:
            self._task = {'id': iid, 'formula': formula, 'rmap': rmap, 'revision': 0}
        self._publish(iid, rmap, 0, time.monotonic() - t0, error)

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
            self.marker_pub.publish(conv.referent_markers(rmap, self.get_clock().now().to_msg(),
                                                          frame_id=self.frames.map))
        if error is not None:
            fields['error'] = error.to_dict()
            self.get_logger().warning(f'{iid}: [{error.code.value}] {error.message}')
        self.rmap_pub.publish(conv.json_msg(conv.payload(conv.REFERENT_MAP, iid, **fields)))

    # ------------------------------------------------------------------ camera
    def on_odom(self, msg: Odometry) -> None:
        """Keep the robot pose (the camera's pose, and the viewpoint when it is the robot)."""
        try:
            self._pose = conv.odometry_in_map(msg, self.frames.map, self.frames.odom, self._map_to_odom)
        except LtlInstructError:
            pass   # task_progression reports bad odometry; the last good pose is kept

    def on_camera_pose(self, msg: PoseStamped) -> None:
        """Keep the pose each camera frame was taken from (by stamp; the last few only)."""
        try:
            pose = conv.pose_stamped_pose(msg)
        except LtlInstructError:
            return
        self._camera_poses[conv.stamp_key(msg.header.stamp)] = pose
        while len(self._camera_poses) > 20:
            self._camera_poses.pop(next(iter(self._camera_poses)))

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
                self._semantic_map.class_names.update(table)

    def on_info(self, msg: CameraInfo) -> None:
        """Keep the latest intrinsics."""
        self._info = msg

    def on_labels(self, msg: Image) -> None:
        """Keep the latest label image (paired with the depth image of the same stamp)."""
        self._labels = msg

    def on_depth(self, msg: Image) -> None:
        """Integrate a depth + labels frame; republish the running task's map if it changed."""
        now = time.monotonic()
        if now - self._last_frame < self.params['camera_min_interval']:
            return
        key = conv.stamp_key(msg.header.stamp)
        labels, info, pose = self._labels, self._info, self._camera_poses.get(key)
        if labels is None or info is None or pose is None or conv.stamp_key(labels.header.stamp) != key:
            return
        self._last_frame = now
        try:
            depth = conv.image_array(msg)
            label_img = conv.image_array(labels)
            intrinsics = conv.camera_intrinsics(info)
            with self._lock:
                self._semantic_map.integrate(depth, label_img, intrinsics, pose)
                # clustering is the slow part: done here, per frame, not per instruction
                self._detected = self._new_detections(tuple(self._semantic_map.instances()))
                task = self._task
                if task is None:
                    return
                rmap = self._ground(task['formula'])
                if rmap.to_dict() == task['rmap'].to_dict():
                    return
                task['rmap'] = rmap
                task['revision'] += 1
                revision = task['revision']
            self._publish(task['id'], rmap, revision, time.monotonic() - now, grounding.grounding_error(rmap))
        except LtlInstructError as e:
            self.get_logger().warning(f'camera frame rejected: {e.message}')


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``referent_grounder`` console script."""
    return run_node(ReferentGrounderNode, args)


if __name__ == '__main__':
    sys.exit(main())

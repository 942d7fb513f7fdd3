"""``sim_world``: a kinematic simulator for the demo and the tests.

Publishes the scene's occupancy ``map`` (latched; plus ``map_cloud`` for a drone),
``odom`` at ``rate_hz``, and camera frames from the synthetic camera: RGB, depth
(``depth_encoding``: 32FC1 [m] or 16UC1 [mm]), class labels (32SC1) with their class
table (``camera/labels/classes``, latched JSON) and ``camera_info``, each frame stamped
with the stamp of the odometry whose pose it shows (the camera is mounted 1 m above the
robot's position, looking along its heading: the grounder's default extrinsic). It
follows each ``plan`` (nav_msgs/Path) at ``max_speed``, stops at the path index of
every ``skill/request`` (pick, release), carries it out in the simulated world (a
picked object moves with the robot) and reports on ``skill/result``. Bad input (NaN in
a plan, garbage JSON) is logged and dropped.

The simulation steps on the steady clock. With ``publish_clock`` it publishes its
simulated time on ``/clock`` (``time_scale`` times faster than the wall clock) and stamps
every message with it, so that nodes run with ``use_sim_time`` live in simulated time.
"""
from __future__ import annotations

import sys
import time
from typing import Any, Optional

import numpy as np
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.time import Time
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CameraInfo, Image, PointCloud2
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.world import near
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.robot import SimulatedWorld, obstacle_points, rasterize_scene
from ltl_instruct.nodes.common import (
    ODOM_DEPTH, ParamSpec, declare_parameters, frames_of, latched_qos, reliable_qos, run_node, sensor_qos,
    steady_timer,
)

_EARLY_PLANS = 8   # plans whose skill requests may wait for them at once

PARAMS = (
    ParamSpec('scene', 'apartment', 'built-in scene name or path of a scene file'),
    ParamSpec('rate_hz', 20.0, 'simulation and odometry rate [Hz]', 1.0, 200.0),
    ParamSpec('time_scale', 1.0, 'simulated seconds per wall-clock second', 0.1, 50.0),
    ParamSpec('max_speed', 1.0, 'robot speed along the plan [m/s]', 0.05, 20.0),
    ParamSpec('map_resolution', 0.1, 'occupancy grid cell size [m]', 0.02, 2.0),
    ParamSpec('cloud_spacing', 1.0, 'point spacing of the 3D map_cloud for a drone [m]', 0.1, 10.0),
    ParamSpec('camera_rate_hz', 2.0, 'camera frame rate [Hz]; 0 turns the camera off', 0.0, 30.0),
    ParamSpec('camera_width', 160, 'camera image width [px]', 16, 1920),
    ParamSpec('camera_height', 120, 'camera image height [px]', 12, 1080),
    ParamSpec('camera_range', 12.0, 'farthest depth the camera returns [m]', 0.5, 500.0),
    ParamSpec('depth_encoding', '32FC1', 'depth image encoding (REP 118): 32FC1 [m] or 16UC1 [mm]',
              choices=('32FC1', '16UC1')),
    ParamSpec('reach', near.DEFAULT_NEAR_THRESHOLD,
              'how far from an object the robot may pick or release [m]', 0.1, 5.0),
    ParamSpec('skill_duration', 0.5, 'simulated time a pick or release takes [s]', 0.0, 30.0),
    ParamSpec('publish_clock', False, 'publish the simulated time on /clock and stamp every message with '
              'it (for nodes run with use_sim_time)'),
)
# read at each tick or skill (max_speed and reach are handed to the world when set); the rest is read-only
RUNTIME = frozenset({'time_scale', 'max_speed', 'reach', 'skill_duration'})
CLOCK_QOS = QoSProfile(depth=1)   # reliable, volatile: matches rclpy's best-effort /clock readers


class SimWorldNode(Node):
    """The simulator: world in, map/odom/camera/skill results out."""

    def __init__(self) -> None:
        super().__init__('sim_world')
        self.params = declare_parameters(self, PARAMS, RUNTIME, on_change=self._on_parameter)
        self.frames = frames_of(self.params)
        self.scene = resolve_scene(self.params['scene'])
        self.world = SimulatedWorld(self.scene, max_speed=self.params['max_speed'],
                                    reach=self.params['reach'])
        self._plan_key: Optional[int] = None
        # skill requests of the followed plan: (path index, request); -1: where the robot is now
        self._pending: list[tuple[int, dict[str, Any]]] = []
        # requests that came before their plan (another topic: DDS does not order them): by plan stamp
        self._early: dict[int, list[tuple[int, dict[str, Any]]]] = {}
        self._skill_busy_until = 0.0
        self._last_tick = time.monotonic()
        self._sim_ns = 0   # simulated time [ns] (published on /clock with publish_clock)
        self._odom_stamp: Any = None   # the stamp of the last odometry: the pose the camera renders from
        self._classes_sent: Optional[dict[str, str]] = None
        self._camera = self._make_camera()

        self.map_pub = self.create_publisher(OccupancyGrid, 'map', latched_qos(1))
        self.cloud_pub = self.create_publisher(PointCloud2, 'map_cloud', latched_qos(1))
        self.odom_pub = self.create_publisher(Odometry, 'odom', reliable_qos(ODOM_DEPTH))
        self.result_pub = self.create_publisher(String, 'skill/result', reliable_qos())
        self.rgb_pub = self.create_publisher(Image, 'camera/color/image_raw', sensor_qos())
        self.depth_pub = self.create_publisher(Image, 'camera/depth/image_raw', sensor_qos())
        self.labels_pub = self.create_publisher(Image, 'camera/labels/image_raw', sensor_qos())
        self.info_pub = self.create_publisher(CameraInfo, 'camera/color/camera_info', sensor_qos())
        self.classes_pub = self.create_publisher(String, 'camera/labels/classes', latched_qos(1))
        self.clock_pub = self.create_publisher(Clock, '/clock', CLOCK_QOS) \
            if self.params['publish_clock'] else None
        self.create_subscription(Path, 'plan', self.on_plan, latched_qos(1))
        self.create_subscription(String, 'skill/request', self.on_skill_request, reliable_qos())
        self.publish_map()
        steady_timer(self, 1.0 / self.params['rate_hz'], self.on_tick)
        if self._camera is not None and self.params['camera_rate_hz'] > 0.0:
            steady_timer(self, 1.0 / self.params['camera_rate_hz'], self.on_camera)
        self.get_logger().info(f'sim_world: scene {self.scene.name} ({len(self.scene.objects)} objects), '
                               f'robot {self.scene.robot.kind} at {self.scene.robot.start}')

    # ------------------------------------------------------------------ set-up
    def _on_parameter(self, name: str, value: object) -> None:
        """Hand a parameter set at runtime to the world that holds it."""
        if name == 'max_speed':
            self.world.robot.max_speed = float(value)   # type: ignore[arg-type]
        elif name == 'reach':
            self.world.reach = float(value)   # type: ignore[arg-type]

    def _stamp(self) -> Any:
        """Return the stamp of a message sent now: the simulated time it publishes, or the node clock."""
        if self.clock_pub is not None:
            return Time(nanoseconds=self._sim_ns).to_msg()
        return self.get_clock().now().to_msg()

    def _make_camera(self) -> Any:
        if self.params['camera_rate_hz'] <= 0.0:
            return None
        try:
            from ltl_instruct.core.world.camera import SyntheticCamera
        except ImportError as e:  # the camera module is optional for the simulator
            self.get_logger().warning(f'no synthetic camera ({e}); camera topics are off')
            return None
        try:
            return SyntheticCamera(self.scene, width=self.params['camera_width'],
                                   height=self.params['camera_height'], max_range=self.params['camera_range'])
        except LtlInstructError as e:
            self.get_logger().warning(f'synthetic camera could not start: {e}; camera topics are off')
            return None

    def publish_map(self) -> None:
        """Publish the latched occupancy grid (and, for a drone, the 3D obstacle cloud)."""
        stamp = self._stamp()
        self.map_pub.publish(conv.occupancy_grid_msg(
            rasterize_scene(self.scene, self.params['map_resolution']), stamp, self.frames.map))
        if self.scene.robot.kind == 'drone':
            self.cloud_pub.publish(conv.point_cloud_msg(
                obstacle_points(self.scene, self.params['cloud_spacing']), stamp=stamp,
                frame_id=self.frames.map))

    # ------------------------------------------------------------------ callbacks
    def on_plan(self, msg: Path) -> None:
        """Follow a new plan (an empty one stops the robot)."""
        try:
            points = conv.path_points(msg)
        except LtlInstructError as e:
            self.get_logger().warning(f'plan rejected: {e.message}')
            return
        self._pending.clear()
        self._plan_key = conv.stamp_key(msg.header.stamp)
        early = self._early.pop(self._plan_key, [])
        for stamp in [k for k in self._early if k < self._plan_key]:
            del self._early[stamp]   # their plan was replaced before it came
        if len(points) == 0:
            self.world.robot.stop()
            return
        self.world.robot.follow(points)
        self.get_logger().info(f'following a plan of {len(points)} poses')
        for index, req in early:
            self._queue(index, req)

    def on_skill_request(self, msg: String) -> None:
        """Queue a pick or release at a path index of its plan.

        The plan comes on ``plan`` and its skill requests on ``skill/request``; DDS does not
        order two topics, so a request may come first. It is held until its plan comes
        (plan stamps grow); one for a plan already replaced is dropped.
        """
        try:
            req = conv.parse_json_payload(msg.data, conv.SKILL_REQUEST)
            skill = req['skill']
            index = int(req['path_index'])
            if skill not in ('pick', 'release') or not isinstance(req.get('args'), list):
                raise ValueError(f'bad skill request {skill!r}')
            stamp = None if req.get('plan_stamp') is None else int(req['plan_stamp'])
        except (LtlInstructError, KeyError, ValueError, TypeError, OverflowError) as e:   # int(Infinity)
            self.get_logger().warning(f'skill request rejected: {e!r}')
            return
        if stamp is None or stamp == self._plan_key:
            self._queue(index, req)
        elif self._plan_key is None or stamp > self._plan_key:
            if stamp not in self._early and len(self._early) >= _EARLY_PLANS:
                del self._early[min(self._early)]
            self._early.setdefault(stamp, []).append((index, req))
        else:
            self.get_logger().warning(f'{req["id"]}: {skill} request for a plan already replaced: dropped')

    def _queue(self, index: int, req: dict[str, Any]) -> None:
        if not self.world.robot.add_stop(index):   # already passed: carried out where the robot is
            self.world.robot.pause()
            index = -1
        self._pending.append((index, req))

    def on_tick(self) -> None:
        """Advance the simulation and publish odometry; carry out a skill at a stop."""
        now = time.monotonic()
        dt = min(now - self._last_tick, 0.5) * self.params['time_scale']
        self._last_tick = now
        self._sim_ns += int(dt * 1e9)
        if self.clock_pub is not None:
            self.clock_pub.publish(Clock(clock=Time(nanoseconds=self._sim_ns).to_msg()))
        robot = self.world.robot
        if robot.is_paused and now >= self._skill_busy_until:
            due = [k for k, (i, _) in enumerate(self._pending) if i <= robot.path_index]
            if due:
                first = min(due, key=lambda k: self._pending[k][0])   # by index, then arrival
                self._do_skill(self._pending.pop(first)[1])
                self._skill_busy_until = now + self.params['skill_duration'] / self.params['time_scale']
            elif not any(i == robot.path_index for i, _ in self._pending):
                robot.resume()
        before = robot.pose.xyz
        pose = self.world.step(dt)
        velocity = (pose.xyz - before) / dt if dt > 0 else np.zeros(3)
        stamp = self._stamp()
        # a slow tick (a loaded machine, a large time_scale) moves the robot far: the corners
        # passed go out first, so that straight moves between poses follow the path, each with
        # its own stamp between the last tick's and this one's; a camera frame has the stamp of
        # the last pose, and a corner sharing it was taken for the frame's pose by the grounder
        corner_stamps = _between_stamps(self._odom_stamp, stamp, len(robot.corners))
        for corner, corner_stamp in zip(robot.corners, corner_stamps):
            self.odom_pub.publish(self._odometry(corner, corner_stamp, velocity))
        self.odom_pub.publish(self._odometry(pose, stamp, velocity))
        self._odom_stamp = stamp

    def _odometry(self, pose: Any, stamp: Any, velocity: np.ndarray) -> Odometry:
        return conv.odometry_msg(pose, stamp, velocity, self.frames.map, self.frames.base_link)

    def _do_skill(self, req: dict[str, Any]) -> None:
        targets = req.get('targets') or []
        args = [str(a) for a in req['args']]

        def resolve(i: int) -> Any:
            t = targets[i] if i < len(targets) and isinstance(targets[i], dict) else {}
            name = args[i].split('::')[0] if i < len(args) else ''
            return self.world.find_object(str(t.get('id', '')), t.get('center'), name)

        if req['skill'] == 'pick':
            outcome = self.world.pick(resolve(0))
        else:
            outcome = self.world.release(resolve(0), resolve(1))
        self.get_logger().info(f'{req["skill"]}: {outcome.reason}')
        self.result_pub.publish(conv.json_msg(conv.payload(
            conv.SKILL_RESULT, req['id'], skill=req['skill'], args=args, ok=outcome.ok,
            object_id=outcome.object_id, target_id=outcome.target_id,
            path_index=req.get('path_index'), plan_stamp=req.get('plan_stamp'),
            error={'code': outcome.error_code, 'message': outcome.reason} if not outcome.ok else None)))

    def on_camera(self) -> None:
        """Render and publish one RGB-D + labels frame from the robot's pose."""
        pose = self.world.robot.pose
        try:
            frame = self._camera.render(pose, scene=self.world.current_scene())
        except LtlInstructError as e:
            self.get_logger().warning(f'camera: {e.message}')
            return
        # the robot moves only in on_tick: the frame shows the pose of the last odometry, and has its stamp
        stamp = self._odom_stamp or self._stamp()
        classes = {str(k): v for k, v in sorted(frame.classes.items())}
        if classes != self._classes_sent:
            self.classes_pub.publish(conv.json_msg(conv.payload(conv.LABEL_CLASSES, 'camera',
                                                                classes=classes)))
            self._classes_sent = classes
        k, cam = frame.intrinsics, self.frames.camera
        self.info_pub.publish(conv.camera_info_msg(k.width, k.height, k.fx, k.fy, k.cx, k.cy, stamp, cam))
        self.rgb_pub.publish(conv.image_msg(frame.rgb, 'rgb8', stamp, cam))
        self.labels_pub.publish(conv.image_msg(frame.labels, '32SC1', stamp, cam))
        self.depth_pub.publish(conv.depth_msg(frame.depth, self.params['depth_encoding'], stamp, cam))


def _between_stamps(before: Any, after: Any, count: int) -> list[Any]:
    """Return ``count`` stamps strictly between two stamps (all ``after`` where they lie too close)."""
    end = conv.stamp_key(after)
    start = conv.stamp_key(before) if before is not None else end
    if end - start <= count:
        return [after] * count
    return [conv.stamp_from_key(start + (end - start) * (k + 1) // (count + 1)) for k in range(count)]


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``sim_world`` console script."""
    return run_node(SimWorldNode, args)


if __name__ == '__main__':
    sys.exit(main())

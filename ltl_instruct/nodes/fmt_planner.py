"""``fmt_planner``: FMT* (OMPL) for one task-progression segment at a time.

Reads the static map (``map``, nav_msgs/OccupancyGrid, for a ground robot; or
``map_cloud``, a PointCloud2 of obstacle points, for a drone) and answers every
``plan_request`` (the symbolic TPSM: regions of the atoms that matter plus the
``goal`` and ``allowed`` guards) with a ``plan_segment`` (nav_msgs/Path whose header
stamp echoes the request's ``stamp``) and a JSON verdict on ``~/status`` (``ok`` or a
typed error: ``START_OCCUPIED``, ``GOAL_OCCUPIED``, ``NO_VALID_PATH``, ``TIMEOUT``,
``INVALID_INPUT`` when no valid map has come...). A malformed map is logged and
ignored: the last good one stays. A path is published only on success. Requests
are served one at a time, in order, in a worker thread.

Requests are idempotent by ``request_id``: the sender may repeat a request it has no
answer to (a message sent before discovery matched the two nodes is lost); a repeat
of a request still queued or being planned is dropped, and a repeat of an answered
one gets the same answer again, without planning twice.
"""
from __future__ import annotations

import json
import queue
import sys
import threading
import time
from collections import OrderedDict
from dataclasses import replace
from typing import Any, Optional

import numpy as np
from nav_msgs.msg import OccupancyGrid, Path
from rclpy.node import Node
from sensor_msgs.msg import PointCloud2
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.core import planning
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.nodes.common import (
    ParamSpec, declare_parameters, frames_of, latched_qos, reliable_qos, run_node,
)

PARAMS = (
    ParamSpec('robot_radius', 0.3, 'obstacles are inflated by this much [m]', 0.0, 10.0),
    ParamSpec('num_samples', 3000, 'FMT* samples per segment', 10, 1000000),
    ParamSpec('radius_multiplier', 1.1, 'FMT* neighbourhood radius multiplier', 0.1, 100.0),
    ParamSpec('heuristics', True, 'FMT* expands towards the goal first'),
    ParamSpec('time_limit', 2.0, 'planning time per segment [s]', 0.05, 3600.0),
    ParamSpec('seed', 0, 'seed of the samplers (a fixed seed gives the same path)', 0, 2 ** 31 - 1),
    ParamSpec('path_spacing', 0.1, 'largest distance between two published poses [m]', 0.01, 5.0),
    ParamSpec('cloud_voxel', 1.0, 'voxel size used to rebuild 3D obstacles from map_cloud [m]', 0.05, 10.0),
    ParamSpec('bounds', '', '3D planning bounds "xmin,ymin,zmin,xmax,ymax,zmax" [m] for map_cloud '
              '("" = the extent of the points)'),
    ParamSpec('max_queue', 256, 'requests waiting at most; more fail with TIMEOUT', 1, 100000),
    ParamSpec('map_timeout', 5.0, 'how long a request waits for a first map [s]', 0.0, 600.0),
)

# read at each request, so they may be set while the node runs; the map's inflation and bounds are read-only
RUNTIME = frozenset({'num_samples', 'radius_multiplier', 'heuristics', 'time_limit', 'seed', 'path_spacing',
                     'max_queue', 'map_timeout'})
REMEMBERED_ANSWERS = 512   # answers kept for repeated requests (a few per instruction)


class FmtPlannerNode(Node):
    """Map + plan_request in, plan_segment + status out."""

    def __init__(self) -> None:
        super().__init__('fmt_planner')
        self.params = declare_parameters(self, PARAMS, RUNTIME)
        self.frames = frames_of(self.params)
        self._bounds = conv.parse_bounds(self.params['bounds'])
        # one world per planning dimension: 2 from map (ground), 3 from map_cloud (drone)
        self._worlds: dict[int, tuple[Any, LtlInstructError]] = {
            d: (None, InvalidInputError(f'no {"map" if d == 2 else "map_cloud"} received yet'))
            for d in (2, 3)}
        self._received: set[int] = set()   # dimensions a map (good or rejected) has come for
        self._lock = threading.Lock()
        self._map_come = threading.Condition(self._lock)
        self._jobs: queue.Queue = queue.Queue()
        self._closing = threading.Event()
        # request_id -> None while queued or planning, then (path or None, status) as sent
        self._answers: OrderedDict[str, Optional[tuple[Optional[Path], String]]] = OrderedDict()
        self.segment_pub = self.create_publisher(Path, 'plan_segment', reliable_qos())
        self.status_pub = self.create_publisher(String, '~/status', reliable_qos())
        self.create_subscription(OccupancyGrid, 'map', self.on_map, latched_qos(1))
        self.create_subscription(PointCloud2, 'map_cloud', self.on_map_cloud, latched_qos(1))
        self.create_subscription(String, 'plan_request', self.on_plan_request, reliable_qos())
        self._worker = threading.Thread(target=self._work, name='fmt', daemon=True)
        self._worker.start()

    # ------------------------------------------------------------------ maps
    def on_map(self, msg: OccupancyGrid) -> None:
        """Use a new 2D occupancy grid (an empty or malformed one is rejected; the last good one stays)."""
        try:
            world = conv.planning_world_from_grid(msg, self.params['robot_radius'])
            conv.check_map_frame(msg, self.frames.map, 'map')
        except LtlInstructError as e:
            self._set_world(2, None, e)
            return
        self._set_world(2, world, None)
        info = msg.info
        self.get_logger().info(f'map: {info.width}x{info.height} cells of {info.resolution:.3f} m')

    def on_map_cloud(self, msg: PointCloud2) -> None:
        """Use a new 3D obstacle cloud (for a drone)."""
        try:
            world = conv.planning_world_from_cloud(msg, self.params['cloud_voxel'],
                                                   self.params['robot_radius'], self._bounds)
            conv.check_map_frame(msg, self.frames.map, 'map_cloud')
        except LtlInstructError as e:
            self._set_world(3, None, e)
            return
        self._set_world(3, world, None)
        self.get_logger().info(f'map_cloud: {msg.width * msg.height} obstacle points')

    def _set_world(self, dims: int, world: Any, error: Optional[LtlInstructError]) -> None:
        """Use a new world; a rejected map is ignored, but is the error as long as no good one came."""
        with self._lock:
            if world is not None or self._worlds[dims][0] is None:
                self._worlds[dims] = (world, error or InvalidInputError('no map'))
            self._received.add(dims)
            self._map_come.notify_all()
        if error is not None:
            self.get_logger().warning(f'map rejected (the last good one stays): '
                                      f'[{error.code.value}] {error.message}')

    # ------------------------------------------------------------------ requests
    def on_plan_request(self, msg: String) -> None:
        """Queue a request (answered in order by the worker thread); answer a repeat from memory."""
        rid = _request_id(msg.data)
        if rid:
            with self._lock:
                if rid in self._answers:
                    answer = self._answers[rid]
                    if answer is not None:   # answered already: the sender missed it, send it again
                        self._send(*answer)
                    return
                self._answers[rid] = None
                while len(self._answers) > REMEMBERED_ANSWERS:
                    self._answers.popitem(last=False)
        if self._jobs.qsize() >= self.params['max_queue']:
            self._reply_error(msg.data, LtlInstructError('planner queue is full', ErrorCode.TIMEOUT))
            return
        self._jobs.put(msg.data)

    def _send(self, path: Optional[Path], status: String) -> None:
        if path is not None:
            self.segment_pub.publish(path)
        self.status_pub.publish(status)

    def _answer(self, rid: str, path: Optional[Path], status: String) -> None:
        """Send an answer and remember it for a repeat of the same request."""
        if rid:
            with self._lock:
                self._answers[rid] = (path, status)
        self._send(path, status)

    def close(self) -> None:
        """Stop the worker thread."""
        self._closing.set()
        self._jobs.put(None)

    def _work(self) -> None:
        while not self._closing.is_set():
            text = self._jobs.get()
            if text is None:
                return
            try:
                self._serve(text)
            except LtlInstructError as e:
                self._reply_error(text, e)
            except Exception as e:  # noqa: BLE001 - a bug must not kill the planner
                self.get_logger().error(f'internal error: {e!r}')
                self._reply_error(text, LtlInstructError(f'internal error: {e!r}', ErrorCode.INTERNAL_ERROR))

    def _serve(self, text: str) -> None:
        data = conv.parse_json_payload(text, conv.PLAN_REQUEST)
        stamp = data.get('stamp')
        if not isinstance(stamp, int) or stamp < 0:
            raise InvalidInputError('plan_request needs a non-negative integer "stamp"')
        request = planning.SegmentRequest.from_dict(data.get('request') or {})
        with self._lock:   # a planner that has just started waits a little for its latched map
            self._map_come.wait_for(lambda: request.dims in self._received or self._closing.is_set(),
                                    timeout=self.params['map_timeout'])
            world, world_error = self._worlds[request.dims]
        if world is None:
            raise world_error
        t0 = time.monotonic()
        p = self.params
        settings = replace(request.settings, num_samples=p['num_samples'],
                           radius_multiplier=p['radius_multiplier'], heuristics=p['heuristics'],
                           time_limit=p['time_limit'], seed=p['seed'], path_spacing=p['path_spacing'])
        result = planning.solve_segment(request, world, settings)
        seconds = time.monotonic() - t0
        body = dict(request_id=data.get('request_id', ''), stamp=stamp, ok=result.ok,
                    plan_s=seconds, result=result.to_dict())
        path = None
        if result.ok:
            # the stamp is the request's (task_progression's clock): it pairs the segment with its request
            path = conv.path_msg(_as_3d(result.points), conv.stamp_from_key(stamp), self.frames.map)
        else:
            body['error'] = result.error.to_dict() if result.error is not None else None
        self._answer(str(body['request_id']), path,
                     conv.json_msg(conv.payload(conv.SEGMENT_STATUS, data['id'], **body)))

    def _reply_error(self, text: str, error: LtlInstructError) -> None:
        iid = conv.salvage_id(text) or 'unidentified'
        rid = _request_id(text)
        self.get_logger().warning(f'{iid}: [{error.code.value}] {error.message}')
        self._answer(rid, None, conv.json_msg(conv.payload(
            conv.SEGMENT_STATUS, iid, request_id=rid, ok=False, error=error.to_dict())))


def _request_id(text: str) -> str:
    """Return the ``request_id`` of a plan_request payload ('' when it has none or is not JSON)."""
    try:
        d = json.loads(text)
    except (ValueError, RecursionError):
        return ''
    rid = d.get('request_id') if isinstance(d, dict) else None
    return rid[:400] if isinstance(rid, str) else ''


def _as_3d(points: np.ndarray) -> np.ndarray:
    """Pad a 2D path (N, 2) with z = 0 [m]; a 3D one is returned as is."""
    p = np.asarray(points, dtype=float)
    return p if p.shape[1] == 3 else np.column_stack([p[:, :2], np.zeros(len(p))])


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``fmt_planner`` console script."""
    return run_node(FmtPlannerNode, args)


if __name__ == '__main__':
    sys.exit(main())

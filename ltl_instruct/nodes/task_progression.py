"""``task_progression``: automaton, task progression maps, progressive planning, monitoring.

For every instruction it waits for the ``task_spec`` and the ``referent_map`` with the
same ``id``, compiles the formula into an automaton, and plans progressively: each
navigation transition becomes a ``plan_request`` (the symbolic TPSM) that the
``fmt_planner`` node answers with a ``plan_segment``. The whole plan is checked
against the automaton before it is published (``plan``, ``task_plan``, ``tpsm``).

Every instruction's first ``task_status`` is ``received`` (with the id the translator
gave it); its planning ends with exactly one terminal status (``planned``, ``satisfied``
when nothing has to move, ``failed`` with a typed error code, or ``cancelled``).
Execution statuses follow with ``phase: execution``: the robot's odometry and skill
results are read by the automaton (``progressing``, then one terminal ``satisfied``,
``violated`` with the atoms that did it, ``failed``, ``superseded`` by a newer plan, or
``cancelled``). A new referent map for the running task, or a failed skill, triggers a
replan from the current automaton state and pose. ``cancel`` (an id) ends an instruction
where it is; a cancelled execution stops the robot (an empty ``plan``).

A restarted ``task_progression`` reads only new task specs (volatile): the translator
sends again those in flight, an executing one with the automaton state to resume from,
and a spec this node has already ended is answered with its statuses again (``repeat``).

Planning runs in one worker thread (instructions are served in order); callbacks
stay short, so odometry and segment replies are handled while a plan is being made.
"""
from __future__ import annotations

import itertools
import math
import pathlib
import queue
import sys
import threading
import time
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from sensor_msgs.msg import PointCloud2
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.core import planning
from ltl_instruct.core.automaton import Automaton, compile_automaton
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError, PlanningError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.lifecycle import (
    CANCELLED, EXECUTION, MEMORY, PLANNED, PLANNING, RECEIVED, SUPERSEDED, StatusMemory,
)
from ltl_instruct.core.monitor import ExecutionMonitor, LetterMaker, PlanTrace, Verdict
from ltl_instruct.core.spec import Atom, parse_formula
from ltl_instruct.core.world import near
from ltl_instruct.nodes.common import (
    ODOM_DEPTH, ParamSpec, StampSource, declare_parameters, frames_of, latched_qos, reliable_qos, run_node,
    steady_timer, subscribe_any_reliability,
)
from ltl_instruct.nodes.search_driver import SEARCH_PARAMS, SearchMixin

PARAMS = (
    ParamSpec('near_threshold', near.DEFAULT_NEAR_THRESHOLD, 'nearness radius of near[x] [m]', 0.05, 50.0),
    ParamSpec('goal_margin', near.DEFAULT_GOAL_MARGIN,
              'each goal region is entered this deep [m] (less, with a warning, where it is thinner)',
              0.0, near.MAX_MARGIN),
    ParamSpec('avoid_margin', near.DEFAULT_AVOID_MARGIN, 'regions to avoid are passed this far outside [m] '
              '(less, with a warning, where free space does not allow it)', 0.0, near.MAX_MARGIN),
    ParamSpec('robot_kind', 'ground', 'ground (2D planning) or drone (3D)', choices=('ground', 'drone')),
    ParamSpec('grounding_timeout', 10.0, 'how long a task spec waits for its referent map [s]', 0.5, 600.0),
    ParamSpec('segment_timeout', 10.0, 'how long to wait for one plan_segment [s]', 0.5, 600.0),
    ParamSpec('segment_resend', 1.0, 'repeat an unanswered plan_request this often [s] (the planner '
              'answers a repeat once)', 0.05, 600.0),
    ParamSpec('map_timeout', 10.0, 'how long planning waits for a first map [s]', 0.0, 600.0),
    ParamSpec('odom_timeout', 5.0, 'how long planning waits for a first odometry pose [s]', 0.1, 600.0),
    ParamSpec('max_segments', 60, 'segment solves before planning gives up (TIMEOUT)', 1, 100000),
    ParamSpec('time_budget', 60.0, 'wall-clock budget of one plan [s]', 0.1, 3600.0),
    ParamSpec('robot_radius', 0.3, 'obstacle inflation for the plan check [m]', 0.0, 10.0),
    ParamSpec('cloud_voxel', 1.0, 'voxel size of the 3D map from map_cloud [m]', 0.05, 10.0),
    ParamSpec('bounds', '', '3D bounds "xmin,ymin,zmin,xmax,ymax,zmax" [m] for map_cloud ("" = its extent)'),
    ParamSpec('max_replans', 3, 'replans allowed per instruction during execution', 0, 100),
    ParamSpec('tpsm_spacing', 0.25, 'point spacing of the tpsm cloud [m]', 0.05, 5.0),
    ParamSpec('trace_tolerance', 0.25, 'odometry poses this close to the plan are on it: the monitor '
              'reads the move between two of them along the plan [m]', 0.01, 10.0),
    ParamSpec('state_dir', '', 'folder where the statuses of each instruction are kept across a restart of '
              'this node ("" = in memory only; bringup gives one when it restarts nodes)'),
) + SEARCH_PARAMS + (
    ParamSpec('start_x', float('nan'), 'start x when no odometry comes [m] (nan: wait for odom)'),
    ParamSpec('start_y', float('nan'), 'start y when no odometry comes [m]'),
    ParamSpec('start_z', 0.0, 'start z when no odometry comes [m]'),
)

# may be set while the node runs (each is read at its next use: the next plan, request or pose);
# the rest shape what is built at start (the robot, its map, its journal) and are read-only
RUNTIME = frozenset({'near_threshold', 'goal_margin', 'avoid_margin', 'grounding_timeout', 'segment_timeout',
                     'segment_resend', 'map_timeout', 'odom_timeout', 'max_segments', 'time_budget',
                     'max_replans', 'tpsm_spacing', 'trace_tolerance'})
NO_INSTRUCTION = 'no-instruction'   # the id of input rejected while no task runs


@dataclass
class _Pending:
    """An instruction waiting for its task spec and referent map."""

    iid: str
    spec: Optional[dict[str, Any]] = None
    rmap: Optional[dict[str, Any]] = None
    since: float = field(default_factory=time.monotonic)   # waiting for a referent map since
    queued: bool = False
    resume: Optional[dict[str, Any]] = None   # planned by an earlier run of this node: resume from here


@dataclass
class _Active:
    """The task being executed and monitored."""

    iid: str
    automaton: Automaton
    referent_map: ReferentMap
    monitor: ExecutionMonitor
    plan_stamp: int
    rmap_revision: int
    plan: Any = None
    replans: int = 0
    trace: Optional[PlanTrace] = None
    finished: bool = False
    events: list = field(default_factory=list)
    last_position: Optional[np.ndarray] = None


class TaskProgressionNode(SearchMixin, Node):
    """Task spec + referent map in, verified plan and task status out."""

    def __init__(self) -> None:
        super().__init__('task_progression')
        self.params = declare_parameters(self, [p for p in PARAMS if not p.name.startswith('start_')],
                                         RUNTIME)
        self.frames = frames_of(self.params)
        self._map_to_odom = conv.parse_planar_pose(self.params['map_to_odom'])
        self._odom_error: Optional[LtlInstructError] = None   # why the last odometry was rejected
        self.start_override = self._start_override()
        self._lock = threading.RLock()
        self._pending: dict[str, _Pending] = {}
        self._memory = StatusMemory(journal=self._journal_path())   # what was said about each id, by phase
        self._cancelled: OrderedDict[str, None] = OrderedDict()   # cancels of ids not seen yet
        self._jobs: queue.Queue = queue.Queue()
        self._pose: Optional[np.ndarray] = None
        self._pose_event = threading.Event()
        self._active: Optional[_Active] = None
        self._segments: dict[str, dict[str, Any]] = {}   # request_id -> segment status
        self._paths: dict[int, np.ndarray] = {}          # stamp key -> segment points
        self._segment_cond = threading.Condition(self._lock)
        self._stamps = StampSource(self)   # plan and request stamps: the node clock (sim time or wall)
        self._unidentified = itertools.count(1)
        self._last_input_warning = 0.0
        self._closing = threading.Event()
        self._bounds = conv.parse_bounds(self.params['bounds'])
        self._world: Any = None
        self._world_error: LtlInstructError = InvalidInputError('no map received yet')
        self._map_received = False          # a map came (good or rejected)
        self._planners_come = 0   # planners matched so far (one more after each restart)
        self._map_come = threading.Condition(self._lock)

        self.status_pub = self.create_publisher(String, 'task_status', latched_qos())
        self.plan_pub = self.create_publisher(Path, 'plan', latched_qos(1))
        self.task_plan_pub = self.create_publisher(String, 'task_plan', latched_qos(1))
        self.tpsm_pub = self.create_publisher(PointCloud2, 'tpsm', latched_qos(1))
        self.request_pub = self.create_publisher(String, 'plan_request', reliable_qos(),
                                                 event_callbacks=PublisherEventCallbacks(
                                                     matched=self.on_planner_matched))
        self.skill_pub = self.create_publisher(String, 'skill/request', reliable_qos())
        # volatile: after a restart, the translator sends again what is in flight (not the ended history)
        self.create_subscription(String, 'task_spec', self.on_task_spec, reliable_qos())
        self.create_subscription(String, 'referent_map', self.on_referent_map, latched_qos(),
                                 event_callbacks=SubscriptionEventCallbacks(matched=self.on_grounder_matched))
        self.create_subscription(String, 'cancel', self.on_cancel, reliable_qos())
        subscribe_any_reliability(self, Odometry, 'odom', self.on_odom, ODOM_DEPTH)
        self.create_subscription(Path, 'plan_segment', self.on_plan_segment, reliable_qos())
        self.create_subscription(String, 'fmt_planner/status', self.on_segment_status, reliable_qos())
        self.create_subscription(String, 'skill/result', self.on_skill_result, reliable_qos())
        if self.params['robot_kind'] == 'drone':
            self.create_subscription(PointCloud2, 'map_cloud', self.on_map_cloud, latched_qos(1))
        else:
            self.create_subscription(OccupancyGrid, 'map', self.on_map, latched_qos(1))
        self._subscribe_search()
        steady_timer(self, 0.25, self.on_timer)
        self._worker = threading.Thread(target=self._work, name='plan', daemon=True)
        self._worker.start()

    def _journal_path(self) -> Optional[pathlib.Path]:
        """Return the file that keeps this node's statuses across a restart (None without ``state_dir``)."""
        if not self.params['state_dir']:
            return None
        folder = pathlib.Path(self.params['state_dir'])
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise InvalidInputError(f'parameter state_dir: cannot use {folder}: {e}') from None
        return folder / (self.get_fully_qualified_name().strip('/').replace('/', '.') + '.status.jsonl')

    def _start_override(self) -> Optional[np.ndarray]:
        values = []
        for name in ('start_x', 'start_y', 'start_z'):
            spec = next(p for p in PARAMS if p.name == name)
            self.declare_parameter(name, spec.default, spec.descriptor(read_only=True))
            v = self.get_parameter(name).value
            values.append(float(v) if isinstance(v, (int, float)) else float('nan'))
        if math.isnan(values[0]) or math.isnan(values[1]):
            return None
        if not all(math.isfinite(v) for v in values):
            raise InvalidInputError('start_x/start_y/start_z must be finite')
        return np.asarray(values)

    # ------------------------------------------------------------------ status
    def publish_status(self, iid: str, status: str, terminal: bool, phase: str = PLANNING,
                       error: Optional[LtlInstructError] = None, **fields: Any) -> None:
        """Publish one ``task_status``; nothing is sent in a phase that has ended (one terminal each)."""
        body = dict(status=status, terminal=terminal, phase=phase,
                    error=error.to_dict() if error is not None else None, **fields)
        with self._lock:
            if not self._memory.admit(iid, body):
                return
            if terminal:
                self._pending.pop(iid, None)
        if error is not None:
            self.get_logger().warning(f'{iid}: {status} [{error.code.value}] {error.message}')
        else:
            self.get_logger().info(f'{iid}: {status}')
        self._send_status(iid, body)

    def _send_status(self, iid: str, body: dict[str, Any]) -> None:
        self.status_pub.publish(conv.json_msg(conv.payload(conv.TASK_STATUS, iid, **body)))

    def _fail(self, iid: str, error: LtlInstructError, **fields: Any) -> None:
        self.publish_status(iid, 'failed', True, error=error, **fields)

    def _input_warning(self, iid: str, error: LtlInstructError) -> None:
        """Publish a non-terminal report of rejected input (NaN odometry...), at most 2 per second."""
        now = time.monotonic()
        if now - self._last_input_warning < 0.5:
            return
        self._last_input_warning = now
        self.publish_status(iid, 'input_rejected', False, phase='input', error=error)

    # ------------------------------------------------------------------ inputs
    def on_task_spec(self, msg: String) -> None:
        """Take a translated instruction (or a failed translation)."""
        try:
            spec = conv.parse_json_payload(msg.data, conv.TASK_SPEC)
        except LtlInstructError as e:
            iid = conv.salvage_id(msg.data) or f'unidentified-{next(self._unidentified)}'
            self._fail(iid, e, stage='task_spec')
            return
        iid = spec['id']
        with self._lock:   # held while 'received' goes out: no other status of this id can precede it
            resume = self._resume_point(iid, spec)
            if resume is None and (self._memory.ended(iid) or self._memory.ended(iid, EXECUTION)):
                for body in self._memory.repeat(iid):   # the translator missed how it ended
                    self._send_status(iid, body)
                return
            if iid in self._pending and self._pending[iid].spec is not None:
                return                                  # sent again while it is being served
            if resume is None and not self._memory.knows(iid):
                self.publish_status(iid, RECEIVED, False, instruction=str(spec.get('instruction', '')),
                                    id_source=str(spec.get('id_source', 'sender')))
            self._take_spec(iid, spec, resume)

    def _resume_point(self, iid: str, spec: dict[str, Any]) -> Optional[dict[str, Any]]:
        """Return where to resume a task an earlier run of this node planned (lock held), or None.

        The journal says it was executing (its last automaton state), or, without a journal,
        the translator does (``resume`` in the spec it sends again).
        """
        pending = self._pending.get(iid)
        if (pending is not None and pending.spec is not None) or \
                (self._active is not None and self._active.iid == iid):
            return None                                 # this run serves it
        executing = self._memory.executing(iid)
        if executing is not None and executing.get('automaton_state') is not None:
            return {'automaton_state': executing['automaton_state']}
        resume = spec.get('resume')
        if isinstance(resume, dict) and not self._memory.ended(iid, EXECUTION) and \
                self._memory.ended(iid) in (None, PLANNED):
            return resume
        return {'automaton_state': None} if executing is not None else None

    def _take_spec(self, iid: str, spec: dict[str, Any], resume: Optional[dict[str, Any]]) -> None:
        """Queue a new spec (lock held): it fails, is cancelled, or waits for its referent map."""
        phase = EXECUTION if resume is not None else PLANNING
        if iid in self._cancelled:
            del self._cancelled[iid]
            self.publish_status(iid, CANCELLED, True, phase=phase, reason='cancelled before it was served')
        elif not spec.get('ok', False):
            err = spec.get('error') or {}
            self.publish_status(iid, 'failed', True, phase=phase, stage='translation',
                                error=_error_from_dict(err, ErrorCode.TRANSLATION_ERROR),
                                instruction=spec.get('instruction', ''))
        elif not isinstance(spec.get('formula'), str):
            self.publish_status(iid, 'failed', True, phase=phase, stage='task_spec',
                                error=InvalidInputError('task spec has no formula'))
        else:
            p = self._pending.setdefault(iid, _Pending(iid))
            p.spec, p.resume, p.since = spec, resume, time.monotonic()
            self._maybe_queue(p)

    def on_referent_map(self, msg: String) -> None:
        """Groundings for an instruction (or a new revision for the running task)."""
        try:
            data = conv.parse_json_payload(msg.data, conv.REFERENT_MAP)
        except LtlInstructError as e:
            self.get_logger().warning(f'referent map rejected: {e.message}')
            return
        iid = data['id']
        with self._lock:
            active = self._active
            if active is not None and active.iid == iid and not active.finished:
                if conv.revision_of(data) > active.rmap_revision and data.get('ok', False):
                    self._jobs.put(('replan', iid, data, 'the referent map changed'))
                return
            if self._memory.ended(iid) not in (None, PLANNED) or self._memory.ended(iid, EXECUTION):
                return   # over (one planned by an earlier run of this node may still be resumed)
            p = self._pending.setdefault(iid, _Pending(iid))
            if p.rmap is None or conv.revision_of(data) >= conv.revision_of(p.rmap):
                p.rmap = data   # a search waits for a newer revision that resolves
            self._maybe_queue(p)

    def _maybe_queue(self, p: _Pending) -> None:
        if p.spec is not None and p.rmap is not None and not p.queued:
            p.queued = True
            self._jobs.put(('plan' if p.resume is None else 'resume', p.iid, None, ''))

    def on_cancel(self, msg: String) -> None:
        """End the named instruction where it is: waiting, being planned, or executing."""
        try:
            iid = conv.read_cancel(msg.data)
        except LtlInstructError as e:
            self.publish_status(conv.salvage_id(msg.data) or NO_INSTRUCTION, 'cancel_rejected', False,
                                phase='input', error=e)
            return
        with self._lock:
            active, pending = self._active, self._pending.get(iid)
            if active is not None and active.iid == iid and not active.finished:
                active.finished = True
                stop = conv.path_msg(np.zeros((0, 3)), conv.stamp_from_key(next(self._stamps)),
                                     self.frames.map)
                self.plan_pub.publish(stop)                                   # an empty plan stops the robot
                self.publish_status(iid, CANCELLED, True, phase=EXECUTION)
            elif pending is not None and pending.spec is not None:
                phase = EXECUTION if pending.resume is not None else PLANNING
                self._pending.pop(iid, None)
                self.publish_status(iid, CANCELLED, True, phase=phase)       # a plan being made is dropped
            elif self._memory.knows(iid):
                ended = self._memory.ended(iid, EXECUTION) or self._memory.ended(iid)
                self.publish_status(iid, 'cancel_rejected', False, phase='input', error=InvalidInputError(
                    f'{iid} cannot be cancelled: it has ended ({ended})'))
            else:   # not here yet (being translated, or on its way): cancelled when it comes
                self._cancelled[iid] = None
                while len(self._cancelled) > MEMORY:
                    self._cancelled.popitem(last=False)
                self.get_logger().info(f'{iid}: cancel noted; it will end when it comes')

    def on_map(self, msg: OccupancyGrid) -> None:
        """Keep the 2D world the plans are checked against (a malformed map is reported and ignored)."""
        try:
            world = conv.planning_world_from_grid(msg, self.params['robot_radius'])
            conv.check_map_frame(msg, self.frames.map, 'map')
        except LtlInstructError as e:
            self._reject_map(e)
            return
        self._set_world(world)

    def _set_world(self, world: Any) -> None:
        with self._lock:
            self._world = world
            self._map_received = True
            self._map_come.notify_all()

    def _reject_map(self, error: LtlInstructError) -> None:
        """Report a malformed map (``input_rejected``); the last good one stays.

        Until a good map has come, this one's error is why nothing can be planned.
        """
        with self._lock:
            if self._world is None:
                self._world_error = error
            self._map_received = True
            self._map_come.notify_all()
            iid = self._active.iid if self._active is not None else NO_INSTRUCTION
        self.publish_status(iid, 'input_rejected', False, phase='input', error=error)

    def on_map_cloud(self, msg: PointCloud2) -> None:
        """Keep the 3D world of a drone (a malformed cloud is reported and ignored)."""
        try:
            world = conv.planning_world_from_cloud(msg, self.params['cloud_voxel'],
                                                   self.params['robot_radius'], self._bounds)
            conv.check_map_frame(msg, self.frames.map, 'map_cloud')
        except LtlInstructError as e:
            self._reject_map(e)
            return
        self._set_world(world)

    def on_odom(self, msg: Odometry) -> None:
        """Keep the pose; progress the running task's automaton."""
        try:
            pose = conv.odometry_in_map(msg, self.frames.map, self.frames.odom, self._map_to_odom)
        except LtlInstructError as e:
            self._odom_error = e
            with self._lock:
                iid = self._active.iid if self._active is not None else NO_INSTRUCTION
            self._input_warning(iid, e)
            return
        with self._lock:
            self._pose = pose.xyz
            self._pose_event.set()
            active = self._active
            if active is None or active.finished:
                return
            event = active.events.pop(0) if active.events else None
            try:
                if active.last_position is None:
                    active.trace.start(self._pose)
                    report = active.monitor.update(self._pose, [event] if event is not None else [])
                else:   # every 5 cm of the move since the last pose (along the plan where it was
                    # on it): no region is stepped over, whatever poses a busy queue dropped
                    report = active.monitor.update_along(active.last_position, self._pose,
                                                         [event] if event is not None else [],
                                                         via=active.trace.via(self._pose))
                active.last_position = self._pose
            except LtlInstructError as e:
                self._input_warning(active.iid, e)
                return
            if report.verdict is Verdict.PROGRESSING and not report.changed:
                return
            if report.verdict is not Verdict.PROGRESSING:
                active.finished = True
            plan = active.plan
        if report.changed and report.verdict is Verdict.PROGRESSING:
            self._publish_tpsm(plan, report.state)
        self.publish_status(active.iid, report.verdict.value, report.verdict is not Verdict.PROGRESSING,
                            phase=EXECUTION, automaton_state=report.state, monitor=report.to_dict())

    def on_plan_segment(self, msg: Path) -> None:
        """Store a segment from the planner, matched to its request by the header stamp."""
        try:
            points = conv.path_points(msg)
        except LtlInstructError as e:
            self.get_logger().warning(f'plan_segment rejected: {e.message}')
            return
        with self._segment_cond:
            self._paths[conv.stamp_key(msg.header.stamp)] = points
            self._segment_cond.notify_all()

    def on_segment_status(self, msg: String) -> None:
        """Store the planner's verdict on one request (ok, or a typed error)."""
        try:
            data = conv.parse_json_payload(msg.data, conv.SEGMENT_STATUS)
        except LtlInstructError as e:
            self.get_logger().warning(f'segment status rejected: {e.message}')
            return
        with self._segment_cond:
            self._segments[str(data.get('request_id', ''))] = data
            self._segment_cond.notify_all()

    def on_skill_result(self, msg: String) -> None:
        """Handle the end of a pick or release: an event for the automaton, or a replan."""
        try:
            data = conv.parse_json_payload(msg.data, conv.SKILL_RESULT)
            skill, args = data['skill'], [str(a) for a in data['args']]
            atom = parse_formula(f'{skill}[{", ".join(args)}]')
            if not isinstance(atom, Atom):
                raise InvalidInputError('skill result does not name one atom')
        except (LtlInstructError, KeyError, TypeError) as e:
            self.get_logger().warning(f'skill result rejected: {e}')
            return
        with self._lock:
            active = self._active
            if active is None or active.iid != data['id'] or active.finished:
                return
            if data.get('ok'):   # done is done, whichever plan asked for it
                active.events.append(atom)
                return
            if data.get('plan_stamp') is not None and data['plan_stamp'] != active.plan_stamp:
                self.get_logger().warning(f'{data["id"]}: {skill} of a replaced plan failed; '
                                          'the current plan stands')
                return
            err = _error_from_dict(data.get('error') or {}, ErrorCode.SKILL_FAILED)
        self.publish_status(data['id'], 'skill_failed', False, phase='execution', error=err)
        self._jobs.put(('replan', data['id'], None, f'{skill} failed: {err.message}'))

    def on_timer(self) -> None:
        """Fail instructions whose referent map never came; forget stale replies."""
        now = time.monotonic()
        late = []
        with self._lock:
            for p in list(self._pending.values()):
                if not p.queued and p.spec is not None and now - p.since > self.params['grounding_timeout']:
                    late.append((p.iid, EXECUTION if p.resume is not None else PLANNING))
                elif p.spec is None and now - p.since > 10 * self.params['grounding_timeout']:
                    del self._pending[p.iid]   # a referent map whose task spec never came
            # replies that came after their request timed out
            while len(self._segments) > 1000:
                self._segments.pop(next(iter(self._segments)))
            while len(self._paths) > 1000:
                self._paths.pop(next(iter(self._paths)))
        for iid, phase in late:
            self.publish_status(iid, 'failed', True, phase=phase, stage='grounding', error=LtlInstructError(
                'no referent map came for this instruction in time', ErrorCode.TIMEOUT))

    def on_grounder_matched(self, info: Any) -> None:
        """Give the specs still waiting the whole ``grounding_timeout`` again when a grounder comes (back).

        DDS notices a killed node only when its lease ends (20 s), so its return, not its
        death, is what is seen in time.
        """
        if info.current_count_change > 0:
            with self._lock:
                for p in self._pending.values():
                    p.since = time.monotonic()

    def on_planner_matched(self, info: Any) -> None:
        """Send a waiting request to a planner that has come (back), with a new deadline."""
        if info.current_count_change > 0:
            with self._segment_cond:
                self._planners_come += 1
                self._segment_cond.notify_all()

    # ------------------------------------------------------------------ planning (worker thread)
    def close(self) -> None:
        """Stop the worker thread."""
        self._closing.set()
        self._jobs.put(None)
        with self._segment_cond:
            self._segment_cond.notify_all()

    def _work(self) -> None:
        while not self._closing.is_set():
            job = self._jobs.get()
            if job is None:
                return
            kind, iid, data, reason = job
            try:
                if kind == 'replan':
                    self._replan(iid, data, reason)
                else:
                    self._plan_instruction(iid)
            except Exception as e:  # noqa: BLE001 - a bug must not kill the worker or lose the instruction
                if not isinstance(e, LtlInstructError):
                    self.get_logger().error(f'internal error on {iid}: {e!r}')
                    e = LtlInstructError(f'internal error: {e!r}', ErrorCode.INTERNAL_ERROR)
                if kind == 'plan':
                    self._fail(iid, e)
                else:   # a failed replan leaves the running plan; a failed resume ends the execution
                    self.publish_status(iid, 'failed', kind == 'resume', phase=EXECUTION, error=e)

    def _dropped(self, iid: str) -> bool:
        """Tell whether a plan still being made for ``iid`` is to be dropped.

        It is when the instruction was cancelled, or its execution has ended (superseded,
        cancelled, or done while a replan was being made).
        """
        return self._memory.ended(iid) == CANCELLED or self._memory.ended(iid, EXECUTION) is not None

    def _current_pose(self) -> np.ndarray:
        if self.start_override is not None and self._pose is None:
            return self.start_override
        if not self._pose_event.wait(self.params['odom_timeout']):
            if self._odom_error is not None:   # odometry came, but none of it could be used
                raise type(self._odom_error)(f'no usable odometry: {self._odom_error.message}',
                                             details=self._odom_error.details)
            raise InvalidInputError('no odometry received: cannot plan from an unknown pose')
        with self._lock:
            assert self._pose is not None
            return self._pose.copy()

    def _plan_instruction(self, iid: str) -> None:
        with self._lock:
            p = self._pending.get(iid)
            if p is None or p.spec is None or p.rmap is None:
                return
            spec, rdata = p.spec, p.rmap
        timing = {**conv.timing_of(spec), **conv.timing_of(rdata)}
        t0 = time.monotonic()
        formula = parse_formula(spec['formula'])
        automaton = compile_automaton(formula)
        timing['automaton_s'] = time.monotonic() - t0
        if not automaton.is_satisfiable:
            raise LtlInstructError(f'the task "{formula}" can never be completed: no sequence of steps '
                                   'satisfies it', ErrorCode.UNSATISFIABLE, details={'formula': str(formula)})
        if not rdata.get('ok', False):   # explore for what is not seen yet, where that can help
            unresolved = _error_from_dict(rdata.get('error') or {}, ErrorCode.UNKNOWN_REFERENT)
            found = self._search(iid, rdata, unresolved)
            if found is None:
                return
            rdata = found
        rmap = ReferentMap.from_dict(rdata.get('referent_map') or {})
        start = self._current_pose()
        state, mode = None, 'plan'
        if p.resume is not None:   # planned by an earlier run of this node: on from the last state heard
            state, mode = _resume_state(p.resume, automaton), 'resume'
        self._plan_and_publish(iid, automaton, rmap, start, state, timing,
                               conv.revision_of(rdata), replans=0, mode=mode)

    def _replan(self, iid: str, rdata: Optional[dict[str, Any]], reason: str) -> None:
        with self._lock:
            active = self._active
            if active is None or active.iid != iid or active.finished:
                return
            if active.replans >= self.params['max_replans']:
                active.finished = True
                err: Optional[LtlInstructError] = PlanningError(
                    f'gave up after {active.replans} replans ({reason})', ErrorCode.NO_VALID_PATH)
            else:
                err = None
            rmap, revision = active.referent_map, active.rmap_revision
            if rdata is not None:
                rmap = ReferentMap.from_dict(rdata.get('referent_map') or {})
                revision = conv.revision_of(rdata, revision)
            state = active.monitor.state
            replans = active.replans + 1
        if err is not None:
            self.publish_status(iid, 'failed', True, phase=EXECUTION, error=err)
            return
        self.publish_status(iid, 'replanning', False, phase=EXECUTION, reason=reason, automaton_state=state)
        start = self._current_pose()
        self._plan_and_publish(iid, active.automaton, rmap, start, state, {}, revision, replans,
                               mode='replan')

    def _letters(self, automaton: Automaton, rmap: ReferentMap) -> LetterMaker:
        dims = 3 if self.params['robot_kind'] == 'drone' else 2
        return LetterMaker(automaton.atoms, rmap, self.params['near_threshold'], dims)

    def _world_or_error(self) -> Any:
        with self._lock:   # just started: the latched map (a large cloud for a drone) may be on its way
            self._map_come.wait_for(lambda: self._map_received or self._closing.is_set(),
                                    timeout=self.params['map_timeout'])
            if self._world is None:
                raise InvalidInputError(f'cannot plan without a valid map: {self._world_error.message}')
            return self._world

    def _plan_and_publish(self, iid: str, automaton: Automaton, rmap: ReferentMap, start: np.ndarray,
                          state: Optional[int], timing: dict[str, float], revision: int,
                          replans: int, mode: str = 'plan') -> None:
        """Plan (from ``state``, or the initial state when None), then publish everything and monitor.

        ``mode``: ``plan`` for a new instruction (its planning ends here), ``replan`` or
        ``resume`` for an executing one (execution statuses only).
        """
        world = self._world_or_error()
        plan = self._make_plan(iid, automaton, rmap, world, start, state, timing)
        if plan.status == 'satisfied' or not plan.steps:
            self._publish_satisfied(iid, automaton, timing, mode)
            return
        stamp = next(self._stamps)
        letters = self._letters(automaton, rmap)
        path, skills = _path_and_skills(plan, rmap)
        fields = dict(formula=str(automaton.formula), timing=timing, plan_stamp=stamp,
                      num_poses=int(len(path)), length_m=round(plan.length, 3), num_skills=len(skills),
                      automaton_states=plan.states, verification=plan.verification.to_dict(),
                      warnings=list(plan.warnings))
        with self._lock:   # a cancel comes before the plan is out (dropped) or after (it stops the robot)
            if self._dropped(iid):
                return
            self._supersede(iid)
            monitor = ExecutionMonitor(automaton, letters, automaton.initial if state is None else state)
            self._active = _Active(iid, automaton, rmap, monitor, stamp, revision, plan, replans,
                                   PlanTrace(path, self.params['trace_tolerance'], letters.dims))
            self._publish_plan(iid, plan, path, skills, stamp, revision)
            if mode == 'plan':
                self.publish_status(iid, 'planned', True, **fields)
            else:
                if mode == 'resume':
                    fields['reason'] = 'resumed by a restarted task_progression'
                self.publish_status(iid, 'replanned', False, phase=EXECUTION, **fields)
        self._publish_tpsm(plan, plan.steps[0].state_before)

    def _publish_plan(self, iid: str, plan: Any, path: np.ndarray, skills: list[dict[str, Any]], stamp: int,
                      revision: int) -> None:
        self.plan_pub.publish(conv.path_msg(path, conv.stamp_from_key(stamp), self.frames.map))
        self.task_plan_pub.publish(conv.json_msg(conv.payload(
            conv.TASK_PLAN, iid, plan_stamp=stamp, revision=revision, skills=skills, **plan.to_dict())))
        for skill in skills:
            self.skill_pub.publish(conv.json_msg(conv.payload(
                conv.SKILL_REQUEST, iid, plan_stamp=stamp, **skill)))

    def _make_plan(self, iid: str, automaton: Automaton, rmap: ReferentMap, world: Any, start: np.ndarray,
                   state: Optional[int], timing: dict[str, float]) -> Any:
        p = self.params
        settings = planning.PlannerSettings(near_threshold=p['near_threshold'], goal_margin=p['goal_margin'],
                                            avoid_margin=p['avoid_margin'], max_segments=p['max_segments'],
                                            time_budget=p['time_budget'])
        t0 = time.monotonic()
        plan = planning.plan_task(automaton, rmap, world, start, settings,
                                  solve=lambda request: self._remote_solve(iid, request, world.dims),
                                  request_id=iid, initial_state=state)
        timing['plan_s'] = time.monotonic() - t0   # every segment over DDS, and the plan check
        return plan

    def _publish_satisfied(self, iid: str, automaton: Automaton, timing: dict[str, float], mode: str) -> None:
        """End planning ``satisfied`` (the task holds where the robot is), or the execution."""
        if mode == 'plan':
            self.publish_status(iid, 'satisfied', True, formula=str(automaton.formula), timing=timing,
                                reason='the task already holds at the robot\'s pose')
            return
        with self._lock:
            if self._active is not None and self._active.iid == iid:
                self._active.finished = True
        self.publish_status(iid, 'satisfied', True, phase=EXECUTION)

    def _supersede(self, iid: str) -> None:
        """End the running execution of another instruction (lock held): a newer plan replaces it."""
        old = self._active
        if old is not None and old.iid != iid and not old.finished:
            old.finished = True
            self.publish_status(old.iid, SUPERSEDED, True, phase=EXECUTION, superseded_by=iid)

    def _remote_solve(self, iid: str, request: Any, dims: int) -> Any:
        """Send one ``plan_request`` and wait for the planner's answer (bounded by ``segment_timeout``)."""
        stamp = next(self._stamps)
        rid = f'{request.id}#{stamp}'
        msg = conv.json_msg(conv.payload(
            conv.PLAN_REQUEST, iid, request_id=rid, stamp=stamp, request=request.to_dict()))
        deadline = time.monotonic() + self.params['segment_timeout']
        resend_at = 0.0
        with self._segment_cond:
            planners = self._planners_come
            while not self._closing.is_set() and not self._dropped(iid):
                now = time.monotonic()
                if self._planners_come != planners:   # a planner (re)started: it gets the whole timeout
                    planners, resend_at = self._planners_come, 0.0
                    deadline = now + self.params['segment_timeout']
                # a request sent before discovery has matched us with a planner is lost:
                # send only to a listening planner, and repeat while unanswered
                if now >= resend_at and self.request_pub.get_subscription_count() > 0:
                    self.request_pub.publish(msg)
                    resend_at = now + self.params['segment_resend']
                status = self._segments.get(rid)
                if status is not None and (not status.get('ok') or stamp in self._paths):
                    self._segments.pop(rid, None)
                    points = self._paths.pop(stamp, None)
                    if not status.get('ok') or points is None or len(points) == 0:
                        err = _error_from_dict(status.get('error') or {}, ErrorCode.NO_VALID_PATH)
                        return planning.SegmentResult.failure(request.id, err)
                    result = planning.SegmentResult.from_waypoints(request.id, points[:, :dims], spacing=0.0)
                    return result.with_margins_of(status.get('result'))
                left = deadline - time.monotonic()
                if left <= 0:
                    break
                self._segment_cond.wait(min(left, 0.05 if resend_at == 0.0 else 0.2))
        listening = '' if self.request_pub.get_subscription_count() else ' (no fmt_planner is listening)'
        return planning.SegmentResult.failure(request.id, LtlInstructError(
            f'{request.describe()}: no plan_segment within {self.params["segment_timeout"]} s{listening}',
            ErrorCode.TIMEOUT))

    def _publish_tpsm(self, plan: Any, state: int) -> None:
        """Publish the TPSM of the navigate step leaving ``state`` (1 goal, -1 avoid, 0 neutral)."""
        step = next((s for s in plan.steps if s.kind == planning.NAVIGATE and s.state_before == state
                     and s.request is not None), None)
        with self._lock:
            world = self._world
        if step is None or world is None:
            return
        req = step.request
        tpsm = planning.TaskProgressionMap(req.goal, req.allowed, req.regions, req.dims)
        lo, hi = np.asarray(world.bounds_min), np.asarray(world.bounds_max)
        spacing = max(self.params['tpsm_spacing'], float(np.prod(hi - lo) / 200_000) ** (1.0 / len(lo)))
        try:
            points, values = tpsm.render(lo, hi, spacing)
        except LtlInstructError as e:
            self.get_logger().warning(f'tpsm not rendered: {e.message}')
            return
        self.tpsm_pub.publish(conv.point_cloud_msg(points, {'value': values.astype(np.float32)},
                                                   conv.stamp_from_key(next(self._stamps)), self.frames.map))


def _path_and_skills(plan: Any, rmap: ReferentMap) -> tuple[np.ndarray, list[dict[str, Any]]]:
    """Return the plan's path (N, 3) [m] and a skill request body per skill step (with its path index)."""
    path = plan.path()
    if path.shape[1] == 2:
        path = np.column_stack([path, np.zeros(len(path))])
    skills: list[dict[str, Any]] = []
    index = 0
    for step in plan.steps:
        if step.kind == planning.NAVIGATE:
            index += len(step.waypoints) - 1
            continue
        atom = parse_formula(step.skill)
        if not isinstance(atom, Atom):
            continue
        where = np.asarray(step.waypoints[-1], dtype=float)
        targets = []
        for arg in atom.args:
            insts = rmap.instances(str(arg))
            best = min(insts, key=lambda i: float(i.distance(where, dims=len(where))[0]), default=None)
            targets.append({'id': best.id, 'center': list(best.center)} if best is not None else {})
        skills.append({'skill': atom.skill, 'args': [str(a) for a in atom.args], 'targets': targets,
                       'path_index': index, 'position': where.tolist(),
                       'state_before': step.state_before, 'state_after': step.state_after})
    return path, skills


def _resume_state(resume: dict[str, Any], automaton: Automaton) -> int:
    """Return the automaton state a resumed task goes on from (the initial one when unknown)."""
    state = resume.get('automaton_state')
    valid = isinstance(state, int) and not isinstance(state, bool) and 0 <= state < automaton.num_states
    return state if valid else automaton.initial


def _error_from_dict(err: Any, default: ErrorCode) -> LtlInstructError:
    """Return the error a peer's payload describes; anything malformed in it falls back to ``default``."""
    if not isinstance(err, dict):
        err = {}
    try:
        code = ErrorCode(err.get('code', default.value))
    except (ValueError, TypeError):
        code = default
    return LtlInstructError(str(err.get('message', code.value))[:2000], code,
                            details=err.get('details') if isinstance(err.get('details'), dict) else None)


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``task_progression`` console script."""
    return run_node(TaskProgressionNode, args, threads=4)


if __name__ == '__main__':
    sys.exit(main())

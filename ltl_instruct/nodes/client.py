"""A client of the node graph: send instructions, collect what the nodes publish.

Used by ``ltl-instruct demo``, the pipeline benchmark and the DDS tests. It owns one
rclpy node spun in a background thread, so callers simply call :meth:`GraphClient.send`
and wait on :meth:`GraphClient.wait_terminal` (every wait has a timeout).
"""
from __future__ import annotations

import itertools
import os
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

import numpy as np
import rclpy
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.context import Context
from rclpy.exceptions import InvalidHandle
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.core.errors import InvalidInputError, LtlInstructError, ErrorCode
from ltl_instruct.core.lifecycle import PLANNING, RECEIVED
from ltl_instruct.nodes.common import latched_qos, reliable_qos


@dataclass
class Received:
    """Everything the client has heard, by instruction id where there is one.

    ``statuses``: id -> every task_status payload in arrival order; ``plans``: plan
    stamp key -> points (N, 3) [m]; ``odom``: (time [s], position (3,)) pairs.
    """

    statuses: dict[str, list[dict[str, Any]]] = field(default_factory=dict)
    specs: dict[str, dict[str, Any]] = field(default_factory=dict)
    verifications: dict[str, dict[str, Any]] = field(default_factory=dict)
    referent_maps: dict[str, dict[str, Any]] = field(default_factory=dict)
    task_plans: dict[str, dict[str, Any]] = field(default_factory=dict)
    plans: dict[int, np.ndarray] = field(default_factory=dict)
    skill_results: list[dict[str, Any]] = field(default_factory=list)
    odom: list[tuple[float, np.ndarray]] = field(default_factory=list)
    map: Optional[OccupancyGrid] = None
    coverage: Optional[OccupancyGrid] = None   # the latest of what the camera covered (while searching)
    translator: dict[str, Any] = field(default_factory=dict)   # the latest ltl_translator/status
    arrival: dict[tuple[str, str], float] = field(default_factory=dict)


class GraphClient:
    """Publishes instructions and records statuses, plans and odometry.

    Parameters
    ----------
    name: node name (a random suffix keeps several clients apart).
    record_odom: keep every odometry position (for drawing the driven path).
    namespace: the robot's namespace (``/r1``); its topics are those of the nodes started in it.
    """

    def __init__(self, name: str = 'ltl_instruct_client', record_odom: bool = False,
                 namespace: str = '') -> None:
        self.context = Context()
        rclpy.init(context=self.context, args=[])
        self.node = rclpy.create_node(f'{name}_{os.urandom(3).hex()}', context=self.context,
                                      namespace=namespace or None)
        self.received = Received()
        self.record_odom = record_odom
        self._cond = threading.Condition()
        self._closing = threading.Event()
        self._ids = itertools.count(1)
        self._prefix = os.urandom(3).hex()
        n = self.node
        # latched: a translator that restarts reads again what it had not finished
        self.instruction_pub = n.create_publisher(String, 'instruction', latched_qos())
        self.cancel_pub = n.create_publisher(String, 'cancel', reliable_qos())
        self.reply_pub = n.create_publisher(String, 'verification/reply', reliable_qos())
        self.task_spec_pub = n.create_publisher(String, 'task_spec', latched_qos())
        self.odom_pub = n.create_publisher(Odometry, 'odom', reliable_qos(10))
        self.map_pub = n.create_publisher(OccupancyGrid, 'map', latched_qos(1))
        n.create_subscription(String, 'task_status', self._on_status, latched_qos())
        n.create_subscription(String, 'ltl_translator/status', self._on_translator, latched_qos(1))
        n.create_subscription(String, 'task_spec', self._keyed('specs'), latched_qos())
        n.create_subscription(String, 'verification/request', self._keyed('verifications'), latched_qos())
        n.create_subscription(String, 'referent_map', self._keyed('referent_maps'), latched_qos())
        n.create_subscription(String, 'task_plan', self._keyed('task_plans'), latched_qos(1))
        n.create_subscription(Path, 'plan', self._on_plan, latched_qos(1))
        n.create_subscription(String, 'skill/result', self._on_skill_result, reliable_qos())
        n.create_subscription(Odometry, 'odom', self._on_odom, reliable_qos(10))
        n.create_subscription(OccupancyGrid, 'map', self._on_map, latched_qos(1))
        n.create_subscription(OccupancyGrid, 'search/coverage', self._on_coverage, latched_qos(1))
        # one thread runs every callback: once it is joined, none can touch the node being destroyed
        # (a pool's callback could: rclpy's executor.shutdown does not wait for them)
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.node)
        self._thread = threading.Thread(target=self._spin, name='client-spin', daemon=True)
        self._thread.start()

    # ------------------------------------------------------------------ lifecycle
    def _spin(self) -> None:
        while self.context.ok() and not self._closing.is_set():
            try:
                self._executor.spin_once(timeout_sec=0.1)
            except InvalidHandle:
                # rclpy: a publisher or subscription another thread destroyed (a test's helper) while
                # this thread built its wait set; it is gone now, and the next wait set has no trace of it
                continue
            except Exception:  # noqa: BLE001 - shutting down
                return

    def close(self) -> None:
        """Stop spinning and shut this client's context down.

        The spinning thread (which runs every callback) is joined before the node is destroyed: a
        callback still running would otherwise touch the destroyed node ("The following exception
        was never retrieved: cannot use Destroyable because destruction was requested", seen at the
        end of a demo).
        """
        self._closing.set()
        self._thread.join(timeout=5.0)
        self._executor.shutdown(timeout_sec=2.0)
        self.node.destroy_node()
        rclpy.try_shutdown(context=self.context)

    def __enter__(self) -> 'GraphClient':
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------ callbacks
    def _record(self, kind: str, iid: str) -> None:
        self.received.arrival.setdefault((kind, iid), time.monotonic())

    @staticmethod
    def _payload(msg: String, schema: Optional[str] = None) -> Optional[dict[str, Any]]:
        """Return the message's JSON payload (of ``schema``, when given), or None for one that is not."""
        try:
            return conv.parse_json_payload(msg.data, schema)
        except LtlInstructError:
            return None

    def _keyed(self, attr: str) -> Callable[[String], None]:
        def on_message(msg: String) -> None:
            data = self._payload(msg)
            if data is None:
                return
            with self._cond:
                getattr(self.received, attr)[data['id']] = data
                self._record(attr, data['id'])
                self._cond.notify_all()
        return on_message

    def _on_status(self, msg: String) -> None:
        data = self._payload(msg, conv.TASK_STATUS)
        if data is None:
            return
        with self._cond:
            self.received.statuses.setdefault(data['id'], []).append(data)
            if data.get('terminal'):
                self._record('terminal', data['id'])
            self._cond.notify_all()

    def _on_translator(self, msg: String) -> None:
        data = self._payload(msg, conv.TRANSLATOR_STATUS)
        if data is None:
            return
        with self._cond:
            self.received.translator = data
            self._cond.notify_all()

    def _on_plan(self, msg: Path) -> None:
        with self._cond:
            self.received.plans[conv.stamp_key(msg.header.stamp)] = conv.path_points(msg, check_finite=False)
            self._cond.notify_all()

    def _on_skill_result(self, msg: String) -> None:
        data = self._payload(msg, conv.SKILL_RESULT)
        if data is None:
            return
        with self._cond:
            self.received.skill_results.append(data)
            self._cond.notify_all()

    def _on_odom(self, msg: Odometry) -> None:
        if not self.record_odom:
            return
        try:
            pose = conv.odometry_pose(msg)
        except LtlInstructError:
            return
        with self._cond:
            self.received.odom.append((time.monotonic(), pose.xyz))

    def _on_map(self, msg: OccupancyGrid) -> None:
        with self._cond:
            self.received.map = msg
            self._cond.notify_all()

    def _on_coverage(self, msg: OccupancyGrid) -> None:
        with self._cond:
            self.received.coverage = msg

    # ------------------------------------------------------------------ actions
    def wait_until(self, predicate: Callable[[], Any], timeout: float) -> Any:
        """Wait until ``predicate()`` is truthy or an array (checked under the lock); return it, or None."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                value = predicate()
                if isinstance(value, np.ndarray) or value:   # an array (a plan) counts when present
                    return value
                left = deadline - time.monotonic()
                if left <= 0:
                    return None
                self._cond.wait(min(left, 0.1))

    def keyed(self, kind: str, iid: str, timeout: float = 10.0) -> dict[str, Any]:
        """Return the ``kind`` message (``specs``, ``verifications``, ``referent_maps``...) of ``iid``.

        Waits for it. Topics arrive apart: under load this client's reader of ``task_spec`` can
        match the translator's writer after the instruction's terminal status has come (seen in a
        fresh-clone CI run: 0.7 s later), and the latched spec then arrives late. Raises
        ``KeyError`` when none has come within ``timeout`` seconds.
        """
        value = self.wait_until(lambda: getattr(self.received, kind).get(iid), timeout)
        if value is None:
            raise KeyError(f'no {kind} message for {iid} within {timeout} s')
        return value

    def missing(self, need_sim: bool = False, need_planner: bool = True) -> list[str]:
        """Return the pipeline parts not listening yet, as seen from this client (empty: all are)."""
        # the translator listens to instruction; the grounder and task_progression listen to
        # task_spec (besides this client); the planner listens to plan_request
        checks = [('ltl_translator (instruction)', self.instruction_pub.get_subscription_count() >= 1),
                  ('ltl_translator (its backend loaded)',
                   self.received.translator.get('state') in ('ready', 'failed')),
                  ('grounder and task_progression (task_spec)',
                   self.node.count_subscribers('task_spec') >= 3),
                  ('referent_grounder (referent_map)', self.node.count_publishers('referent_map') >= 1),
                  ('task_progression (task_status)', self.node.count_publishers('task_status') >= 1)]
        if need_planner:
            checks.append(('fmt_planner (plan_request)', self.node.count_subscribers('plan_request') >= 1))
        if need_sim:
            checks.append(('a map', self.received.map is not None))
        return [name for name, ok in checks if not ok]

    def wait_for_graph(self, timeout: float = 20.0, need_sim: bool = False,
                       need_planner: bool = True) -> bool:
        """Wait until the pipeline nodes listen (with ``need_sim``, also until the map has come).

        An instruction published before the translator listens is lost (reliable, volatile
        QoS), so wait for this before the first ``send``. It also waits until the translator
        has loaded its backend (``ltl_translator/status``): an instruction sent earlier would
        wait in its queue, and its time would count the model's loading.
        """
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if not self.missing(need_sim, need_planner):
                return True
            time.sleep(0.05)
        return False

    def new_id(self) -> str:
        """Return a fresh instruction id."""
        return f'client-{self._prefix}-{next(self._ids)}'

    def send(self, text: Optional[str] = None, formula: Optional[str] = None,
             iid: Optional[str] = None) -> str:
        """Publish an instruction (English ``text`` or a ``formula``); return its id."""
        if text is None and formula is None:
            raise InvalidInputError('send needs text or a formula')
        iid = iid or self.new_id()
        fields: dict[str, Any] = {}
        if text is not None:
            fields['text'] = text
        if formula is not None:
            fields['formula'] = formula
        self._record('sent', iid)
        self.instruction_pub.publish(conv.json_msg(conv.payload(conv.INSTRUCTION, iid, **fields)))
        return iid

    def send_raw(self, text: str) -> None:
        """Publish ``text`` on ``instruction`` as it is (plain English or garbage)."""
        self.instruction_pub.publish(String(data=text))

    def reply(self, iid: str, accept: bool) -> None:
        """Answer a verification request."""
        self.reply_pub.publish(conv.json_msg(conv.payload(conv.VERIFICATION_REPLY, iid, accept=accept)))

    def cancel(self, iid: str) -> None:
        """Publish a cancel for ``iid`` (as plain text)."""
        self.cancel_pub.publish(String(data=iid))

    def terminal(self, iid: str, phase: str = PLANNING) -> Optional[dict[str, Any]]:
        """Return the terminal status of ``phase`` (planning, execution) of ``iid`` if it has come."""
        for s in self.received.statuses.get(iid, []):
            if s.get('terminal') and s.get('phase') == phase:
                return s
        return None

    def terminals(self, iid: str, phase: str = PLANNING) -> list[dict[str, Any]]:
        """Return every terminal status of ``phase`` of ``iid``, but repeats (one is expected)."""
        return [s for s in self.received.statuses.get(iid, [])
                if s.get('terminal') and s.get('phase') == phase and not s.get('repeat')]

    def ids_for(self, text: str) -> list[str]:
        """Return the ids that ``received`` statuses gave to an instruction ``text``."""
        return sorted({iid for iid, statuses in self.received.statuses.items() for s in statuses
                       if s.get('status') == RECEIVED and s.get('instruction') == text})

    def wait_terminal(self, iid: str, timeout: float = 30.0, phase: str = PLANNING) -> dict[str, Any]:
        """Wait for the terminal status of ``phase`` of ``iid`` (planning: planned, satisfied, failed...).

        Raises
        ------
        LtlInstructError
            (TIMEOUT) if none comes in time.
        """
        s = self.wait_until(lambda: self.terminal(iid, phase), timeout)
        if s is None:
            raise LtlInstructError(f'no terminal {phase} task_status for {iid} within {timeout} s',
                                   ErrorCode.TIMEOUT)
        return s

    def wait_status(self, iid: str, status: str, timeout: float = 60.0) -> Optional[dict[str, Any]]:
        """Wait for a status named ``status`` (e.g. ``satisfied`` during execution) for ``iid``."""
        return self.wait_until(
            lambda: next((s for s in self.received.statuses.get(iid, []) if s.get('status') == status), None),
            timeout)

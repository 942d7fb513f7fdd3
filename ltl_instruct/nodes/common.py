"""What every ltl_instruct node shares: named QoS profiles, parameters, the main idiom.

QoS (as Nav2 names them):

- :func:`latched_qos`: reliable + transient-local. Late subscribers get the last
  value. Publishers keep ``depth`` values (default 64) so a burst of instructions is
  not overwritten before every reader has it; a late reader with depth 1 still gets
  only the newest.
- :func:`reliable_qos`: reliable + volatile, for requests and results.
- :func:`sensor_qos`: best effort, depth 5, for camera frames and odometry.

Parameters are declared from :class:`ParamSpec` with a description and a range, and
validated (a bad value stops the node at start with a clear message, never later).
Those a node names as ``runtime`` may be changed while it runs (``set_parameters``),
validated the same way; every other one is declared read-only, so a ``set`` is refused.
Every node also declares :data:`COMMON_PARAMS` (the robot's frame prefix and odom offset, and
how many threads its numeric libraries may use, applied when they are declared).

Time: header stamps come from the node clock (:class:`StampSource`), so ``use_sim_time``
with a ``/clock`` publisher (``sim_world publish_clock:=true``) stamps everything in
simulated time; timers that measure waiting use the steady clock (:func:`steady_timer`),
so they run whether or not a ``/clock`` comes.
"""
from __future__ import annotations

import faulthandler
import math
import os
import re
import signal
import sys
import threading
import time
import traceback
from dataclasses import dataclass
from typing import Any, Callable, Collection, Iterator, Optional, Sequence

import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor, SetParametersResult
from rclpy.clock import Clock, ClockType
from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.signals import SignalHandlerOptions
from rclpy.utilities import get_default_context
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

from ltl_instruct.core.compute_threads import limit_compute_threads
from ltl_instruct.core.errors import InvalidInputError

BURST_DEPTH = 64
# the execution monitor reads the trace as straight moves between odometry poses: a pose
# dropped from a queue while a node was busy would cut a corner, so the queue is deep
ODOM_DEPTH = 50


def latched_qos(depth: int = BURST_DEPTH) -> QoSProfile:
    """Reliable, transient-local, keep-last ``depth``: late subscribers get the last value."""
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=depth,
                      reliability=ReliabilityPolicy.RELIABLE,
                      durability=DurabilityPolicy.TRANSIENT_LOCAL)


def reliable_qos(depth: int = BURST_DEPTH) -> QoSProfile:
    """Reliable, volatile, keep-last ``depth``: requests and results."""
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=depth,
                      reliability=ReliabilityPolicy.RELIABLE,
                      durability=DurabilityPolicy.VOLATILE)


def sensor_qos(depth: int = 5) -> QoSProfile:
    """Best effort, volatile: camera frames and odometry, where only the newest matters."""
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=depth,
                      reliability=ReliabilityPolicy.BEST_EFFORT,
                      durability=DurabilityPolicy.VOLATILE)


@dataclass(frozen=True)
class ParamSpec:
    """One node parameter: name, default (fixes the type), description, and range.

    ``low``/``high`` bound numbers (inclusive); ``choices`` lists allowed strings.
    """

    name: str
    default: Any
    description: str
    low: Optional[float] = None
    high: Optional[float] = None
    choices: tuple[str, ...] = ()
    pattern: str = ''

    def descriptor(self, read_only: bool = False) -> ParameterDescriptor:
        """Return the ``ParameterDescriptor`` with description and range (and read-only flag)."""
        text = self.description
        if self.choices:
            text += f' (one of: {", ".join(self.choices)})'
        d = ParameterDescriptor(description=text, read_only=read_only)
        if isinstance(self.default, bool):
            return d
        if isinstance(self.default, int) and self.low is not None and self.high is not None:
            d.integer_range = [IntegerRange(from_value=int(self.low), to_value=int(self.high), step=0)]
        elif isinstance(self.default, float) and self.low is not None and self.high is not None:
            d.floating_point_range = [FloatingPointRange(from_value=float(self.low),
                                                         to_value=float(self.high), step=0.0)]
        return d

    def check(self, value: Any) -> Any:
        """Validate ``value``; return it (ints widened to float for float parameters).

        Raises
        ------
        InvalidInputError
            On a wrong type, a value out of range, or a string not in ``choices``.
        """
        if isinstance(self.default, float) and isinstance(value, int) and not isinstance(value, bool):
            value = float(value)
        if type(value) is not type(self.default):
            raise InvalidInputError(f'parameter {self.name}: expected {type(self.default).__name__}, '
                                    f'got {value!r}')
        if isinstance(value, float) and not math.isfinite(value):
            raise InvalidInputError(f'parameter {self.name}: must be finite, got {value}')
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if (self.low is not None and value < self.low) or (self.high is not None and value > self.high):
                raise InvalidInputError(f'parameter {self.name}={value} outside [{self.low}, {self.high}]')
        if self.choices and value not in self.choices:
            raise InvalidInputError(f'parameter {self.name}={value!r} not one of {self.choices}')
        if self.pattern and not re.fullmatch(self.pattern, value):
            raise InvalidInputError(f'parameter {self.name}={value!r} does not match {self.pattern}')
        return value


COMMON_PARAMS = (
    ParamSpec('frame_prefix', '', 'prefix of every frame id this robot\'s nodes use and expect '
              '("r1/" gives r1/map, r1/odom, r1/base_link; "" = none)', pattern=r'([A-Za-z0-9_]+/)*'),
    ParamSpec('map_to_odom', '', 'fixed pose "x,y,yaw" [m, m, rad] of the odom frame in the map frame: '
              'odometry in the odom frame is moved into the map frame by it ("" = odometry must be in map)',
              pattern=r'|\s*[-+0-9.eE]+\s*,\s*[-+0-9.eE]+\s*,\s*[-+0-9.eE]+\s*'),
    ParamSpec('compute_threads', 1, 'threads BLAS, OpenMP and torch may each use in this node\'s process '
              '(0 = their default, one per core): one keeps the nodes of a small computer from contending',
              low=0, high=256),
)


@dataclass(frozen=True)
class Frames:
    """The frame ids of one robot: the REP 105 names with its prefix."""

    prefix: str = ''

    @property
    def map(self) -> str:
        """The global frame of plans, maps and regions."""
        return f'{self.prefix}map'

    @property
    def odom(self) -> str:
        """The odometry frame (moved into ``map`` by ``map_to_odom``)."""
        return f'{self.prefix}odom'

    @property
    def base_link(self) -> str:
        """The robot body frame (odometry's child frame)."""
        return f'{self.prefix}base_link'

    @property
    def camera(self) -> str:
        """The camera's optical frame."""
        return f'{self.prefix}camera_optical'


def frames_of(params: dict[str, Any]) -> Frames:
    """Return the robot's frames from a node's declared parameters."""
    return Frames(str(params.get('frame_prefix', '')))


def declare_parameters(node: Node, specs: Sequence[ParamSpec], runtime: Collection[str] = (),
                       on_change: Optional[Callable[[str, Any], None]] = None) -> dict[str, Any]:
    """Declare every parameter (and :data:`COMMON_PARAMS`); return the validated values by name.

    Parameters named in ``runtime`` may be set while the node runs: a new value is
    validated by its :class:`ParamSpec` (refused with the reason when invalid), then
    written into the returned dict (which the node reads at each use) and passed to
    ``on_change``. Every other parameter is read-only.

    Raises
    ------
    InvalidInputError
        If a value given on the command line or in a parameters file is invalid.
    """
    values: dict[str, Any] = {}
    by_name = {s.name: s for s in tuple(specs) + COMMON_PARAMS}
    for spec in by_name.values():
        try:
            node.declare_parameter(spec.name, spec.default,
                                   spec.descriptor(read_only=spec.name not in runtime))
        except (InvalidParameterValueException, InvalidParameterTypeException) as e:
            raise InvalidInputError(f'parameter {spec.name}: {e}') from None
        values[spec.name] = spec.check(node.get_parameter(spec.name).value)
    limit_compute_threads(values['compute_threads'])
    live = {name: by_name[name] for name in runtime if name in by_name}

    def on_set(parameters: list) -> SetParametersResult:
        try:
            checked = [(p.name, live[p.name].check(p.value)) for p in parameters if p.name in live]
        except InvalidInputError as e:
            return SetParametersResult(successful=False, reason=e.message)
        for name, value in checked:
            values[name] = value
            if on_change is not None:
                on_change(name, value)
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(on_set)
    return values


def steady_timer(node: Node, period: float, callback: Callable[[], None]) -> Any:
    """Create a timer on the steady clock: it fires under ``use_sim_time`` whether ``/clock`` runs or not."""
    return node.create_timer(period, callback, clock=Clock(clock_type=ClockType.STEADY_TIME))


class StampSource:
    """Header stamps from the node clock, strictly increasing (each one also keys a plan or a request).

    Under ``use_sim_time`` they are simulated time; two stamps asked for within the same
    clock tick (or before the first ``/clock``) are made one nanosecond apart.
    """

    def __init__(self, node: Node) -> None:
        self._clock = node.get_clock()
        self._last = 0
        self._lock = threading.Lock()

    def __iter__(self) -> Iterator[int]:
        return self

    def __next__(self) -> int:
        """Return the next stamp [ns]: the clock's now, or one more than the last one."""
        with self._lock:
            self._last = max(self._clock.now().nanoseconds, self._last + 1)
            return self._last


class _SampleFilter:
    """Let each sample through once, in order: the same odometry may come on two subscriptions."""

    def __init__(self) -> None:
        self._last: Optional[tuple[int, int]] = None
        self._lock = threading.Lock()

    def admit(self, info: Any) -> bool:
        """Tell whether a sample (by its source time and sequence number) is new and not older."""
        key = (int(info.get('source_timestamp', 0)), int(info.get('publication_sequence_number', 0)))
        with self._lock:
            last = self._last
            if last is not None and (key == last or (key[0] <= last[0] and key[1] <= last[1])):
                return False
            self._last = key
            return True


def subscribe_any_reliability(node: Node, msg_type: Any, topic: str, callback: Callable[[Any], None],
                              depth: int) -> None:
    """Subscribe ``topic`` so that reliable and best-effort publishers are both heard.

    A reliable subscription matches only reliable publishers; a best-effort one matches
    both, but turns a reliable publisher's stream best effort. Both are made: a reliable
    publisher is heard reliably (its samples also come on the best-effort one and are
    dropped as repeats), a best-effort one on the best-effort subscription.
    """
    seen = _SampleFilter()

    def on_message(msg: Any, info: Any) -> None:
        if seen.admit(info):
            callback(msg)

    quiet = SubscriptionEventCallbacks(incompatible_qos=lambda event: None)
    node.create_subscription(msg_type, topic, on_message, reliable_qos(depth), event_callbacks=quiet)
    node.create_subscription(msg_type, topic, on_message, sensor_qos(depth))


STOP_GRACE_S = 1.5   # [s] after a stop signal the process ends by then, even if its clean-up is stuck


def run_node(make_node: Callable[[], Node], args: Optional[Sequence[str]] = None,
             threads: int = 2) -> int:
    """Run the node idiom: init, build, spin (multi-threaded), clean shutdown on Ctrl-C or SIGTERM.

    The stop is this process's own, not rclpy's: SIGINT and SIGTERM set an event the main
    thread waits on (the executor spins in a thread of its own) and start a watchdog, so a
    clean-up that blocks (a callback at work, a DDS call) cannot keep the node alive past
    :data:`STOP_GRACE_S`. The node is not destroyed (see the comment in the code). The process
    then ends at once with its exit status (2 when the parameters are invalid, 1 after a
    crash, 0 after a signal): see :func:`_end_process`.
    """
    stop = _StopSignals()
    faulthandler.register(signal.SIGUSR1, all_threads=True)   # `kill -USR1 <pid>`: every thread's stack
    rclpy.init(args=list(args) if args is not None else None,
               signal_handler_options=SignalHandlerOptions.NO)
    node: Optional[Node] = None
    spinner: Optional[threading.Thread] = None
    status = 0
    try:
        node = make_node()
        if not stop.is_set():
            spinner = _spin_until(node, threads, stop)
    except InvalidInputError as e:
        print(f'error [{e.code.value}]: {e.message}', file=sys.stderr)
        status = 2
    except Exception:  # noqa: BLE001 - a crash: its traceback, and the status of one
        traceback.print_exc()
        status = 1
    finally:
        stop.arm_watchdog(status)
        if node is not None:
            close = getattr(node, 'close', None)
            if callable(close):
                close()
        shutdown_context()   # the executor's wait ends
        if spinner is not None:
            spinner.join(timeout=STOP_GRACE_S)
    # No destroy_node: tearing the DDS participant down blocked, holding the GIL, after peers had been
    # SIGKILLed (Fast DDS); the process ends now, and its peers see it gone as after any exit.
    _end_process(status)
    return status


def shutdown_context() -> None:
    """Shut the default ROS context down (the executor's wait ends), without finalising rcl logging.

    ``rclpy.try_shutdown`` ends with ``rclpy_logging_fini``, which holds the GIL while it waits for
    rcl's logging lock; a thread that is logging at that moment waits for the GIL. In a fresh-clone
    CI run sim_world's main thread stayed there, the stop watchdog could not run, and only the
    faulthandler timer ended the process (status 1). The process ends with ``os._exit`` right after
    this, so logging needs no finalising: it is left as it is.
    """
    context = get_default_context()
    context._logging_initialized = False   # rclpy has no public way to skip the logging fini
    rclpy.try_shutdown()


def _spin_until(node: Node, threads: int, stop: '_StopSignals') -> threading.Thread:
    """Spin ``node`` in a thread until a stop signal and return that thread (a failed executor raises)."""
    failed: list[BaseException] = []

    def spin() -> None:
        try:
            executor = MultiThreadedExecutor(num_threads=threads)
            executor.add_node(node)
            executor.spin()
        except ExternalShutdownException:
            pass
        except BaseException as e:  # noqa: BLE001 - handed to the main thread
            failed.append(e)
        stop.set()

    spinner = threading.Thread(target=spin, name='executor', daemon=True)
    spinner.start()
    while not stop.wait(0.5):
        pass
    if failed and not stop.signalled:
        raise failed[0]
    return spinner


class _StopSignals:
    """SIGINT and SIGTERM as an event (handled in the main thread, between its waits), with a watchdog."""

    def __init__(self) -> None:
        self._event = threading.Event()
        self.signalled = False
        self._watchdog: Optional[threading.Thread] = None
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self._on_signal)

    def _on_signal(self, signum: int, frame: Any) -> None:
        self.signalled = True
        self.arm_watchdog(0)
        self._event.set()

    def set(self) -> None:
        """Ask the main thread to stop (the executor ended)."""
        self._event.set()

    def is_set(self) -> bool:
        """Tell whether a stop was asked for."""
        return self._event.is_set()

    def wait(self, timeout: float) -> bool:
        """Wait up to ``timeout`` seconds for a stop; tell whether one came."""
        return self._event.wait(timeout)

    def arm_watchdog(self, status: int) -> None:
        """End the process with ``status`` after :data:`STOP_GRACE_S`, every thread's stack in its log."""
        if self._watchdog is not None:
            return

        # a thread that holds the GIL in C code would keep this one asleep: faulthandler's own thread
        # needs no GIL, and ends the process (status 1, the stacks in the log) a second later
        faulthandler.dump_traceback_later(STOP_GRACE_S + 1.0, exit=True)

        def expire() -> None:
            time.sleep(STOP_GRACE_S)
            print(f'clean-up still running after {STOP_GRACE_S} s: ending now; the threads were at',
                  file=sys.stderr, flush=True)
            faulthandler.dump_traceback(all_threads=True)
            _end_process(status)

        self._watchdog = threading.Thread(target=expire, name='stop-watchdog', daemon=True)
        self._watchdog.start()


def _end_process(status: int) -> None:
    """End the process now, without waiting for threads still at work.

    A worker in the middle of a long computation (an FMT* solve with a long time limit, an
    automaton compilation running to its deadline) or an executor callback still running (a
    camera frame being rendered) would hold the stop up for as long as it runs, and a thread
    returning from OMPL into a finalizing interpreter aborted it (SIGABRT). Their work is not
    lost: a restarted node gets it again from its peers. The node and the ROS context are
    already shut down here.
    """
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)

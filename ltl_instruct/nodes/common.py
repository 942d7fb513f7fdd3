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
"""
from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

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

    def descriptor(self) -> ParameterDescriptor:
        """Return the ``ParameterDescriptor`` with description and range."""
        text = self.description
        if self.choices:
            text += f' (one of: {", ".join(self.choices)})'
        d = ParameterDescriptor(description=text)
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
        return value


def declare_parameters(node: Node, specs: Sequence[ParamSpec]) -> dict[str, Any]:
    """Declare every parameter with its descriptor; return the validated values by name.

    Raises
    ------
    InvalidInputError
        If a value given on the command line or in a parameters file is invalid.
    """
    values: dict[str, Any] = {}
    for spec in specs:
        try:
            node.declare_parameter(spec.name, spec.default, spec.descriptor())
        except (InvalidParameterValueException, InvalidParameterTypeException) as e:
            raise InvalidInputError(f'parameter {spec.name}: {e}') from None
        values[spec.name] = spec.check(node.get_parameter(spec.name).value)
    return values


def run_node(make_node: Callable[[], Node], args: Optional[Sequence[str]] = None,
             threads: int = 2) -> int:
    """Run the node idiom: init, build, spin (multi-threaded), clean shutdown on Ctrl-C or SIGTERM.

    The process then ends at once with its exit status (2 when the parameters are invalid,
    0 after a signal): see :func:`_end_process`. A signal that comes while the node is still
    starting, or while the executor builds its wait set, is a stop too, not a crash.
    """
    rclpy.init(args=list(args) if args is not None else None)
    node: Optional[Node] = None
    status = 0
    try:
        node = make_node()
        executor = MultiThreadedExecutor(num_threads=threads)
        executor.add_node(node)
        executor.spin()
    except InvalidInputError as e:
        print(f'error [{e.code.value}]: {e.message}', file=sys.stderr)
        status = 2
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except Exception:  # noqa: BLE001 - re-raised unless a signal shut the context down under it
        # rclpy raises RCLError ("the given context is not valid") from a wait set built as the signal
        # came, and the executor's constructor fails on a context shut down while the node was starting
        if rclpy.ok():
            raise
    finally:
        if node is not None:
            close = getattr(node, 'close', None)
            if callable(close):
                close()
            node.destroy_node()
        rclpy.try_shutdown()
    _end_process(status)
    return status


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

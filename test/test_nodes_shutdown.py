"""Issue 21: every node stops on SIGINT or SIGTERM, idle or busy, and exits 0.

Two graphs of the five nodes. In the busy one, each node is in the middle of its longest
work when the signals come: the translator and ``task_progression`` compile an automaton
that runs to its 5 s deadline, the planner runs FMT* with a 60 s time limit, the simulator
renders large camera frames 10 times a second and the grounder integrates each of them.
Half the nodes get SIGINT and half SIGTERM, swapped between the two graphs, all at once
(as bringup's Ctrl-C does). The stop times are printed.
"""
from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time

import pytest
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, default_params_file

# issue 21: within 2 s of the signal, busy or not (measured here under a load of 81, nice 10:
# 0.17-0.73 s idle, 0.33-1.68 s busy; before the nodes ended their process at once, a busy
# translator took 5-8 s, the simulator 11-15 s, and the planner aborted, SIGABRT)
STOP_BOUND_S = 2.0
UNTIL_CHAIN = ' U '.join(f'near[a{i}]' for i in range(20))   # its automaton runs to the 5 s deadline
BUSY = {'fmt_planner': {'time_limit': 60.0, 'num_samples': 300000},
        'sim_world': {'camera_rate_hz': 10.0, 'camera_width': 640, 'camera_height': 480},
        'referent_grounder': {'camera_min_interval': 0.0},
        'ltl_translator': {'backend': 'offline'}}
IDLE = {'sim_world': {'camera_rate_hz': 0.0}, 'ltl_translator': {'backend': 'offline'}}


@pytest.fixture()
def domain(monkeypatch):
    """A private ROS domain for this test's graph (the environment is restored after it)."""
    monkeypatch.setenv('ROS_DOMAIN_ID', str(random.randint(120, 229)))
    monkeypatch.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'LOCALHOST')


def _signals(first: signal.Signals) -> dict[str, signal.Signals]:
    other = signal.SIGTERM if first == signal.SIGINT else signal.SIGINT
    return {name: first if k % 2 == 0 else other for k, name in enumerate(ALL_NODES)}


def _stop_all(g: NodeGraph, signals: dict[str, signal.Signals]) -> dict[str, tuple[float, int]]:
    """Signal every node at once; return each one's (seconds to exit, exit status)."""
    t0 = time.monotonic()
    for name, sig in signals.items():
        os.killpg(g.processes[name].pid, sig)
    out: dict[str, tuple[float, int]] = {}
    while len(out) < len(signals) and time.monotonic() - t0 < 30.0:
        for name, p in g.processes.items():
            if name not in out and p.poll() is not None:
                out[name] = (time.monotonic() - t0, p.returncode)
        time.sleep(0.02)
    return out


def _make_busy(client) -> None:
    """Give each node its longest work (see the module's doc)."""
    from ltl_instruct.core.automaton.guards import Cube, Guard
    from ltl_instruct.core.planning import AtomRegion, FmtSettings, SegmentRequest
    from ltl_instruct.core.spec import Atom, Descriptor
    from ltl_instruct.nodes.common import latched_qos, reliable_qos
    client.send(formula=UNTIL_CHAIN)                                   # the translator compiles it
    client.task_spec_pub.publish(conv.json_msg(conv.payload(           # task_progression compiles it
        conv.TASK_SPEC, 'busy-spec', ok=True, formula=UNTIL_CHAIN, instruction='')))
    rmap = client.node.create_publisher(String, 'referent_map', latched_qos())
    rmap.publish(conv.json_msg(conv.payload(conv.REFERENT_MAP, 'busy-spec', ok=True, revision=0,
                                            referent_map={'groundings': {}})))
    tv = Atom('near', (Descriptor('tv'),))
    request = SegmentRequest('busy/0', (1.5, 1.5), 2, (AtomRegion('near[tv]', ((7.5, 7.7, 0.6),),
                                                                  ((1.2, 0.2, 0.7),), 1.0),),
                             Guard((Cube(frozenset({tv}), frozenset()),)),
                             Guard((Cube(frozenset(), frozenset({tv})),)), FmtSettings(), transition=(0, 1))
    planner = client.node.create_publisher(String, 'plan_request', reliable_qos())
    client.wait_until(lambda: planner.get_subscription_count() >= 1 or None, 20.0)
    planner.publish(conv.json_msg(conv.payload(conv.PLAN_REQUEST, 'busy', request_id='busy/0#1', stamp=1,
                                               request=request.to_dict())))


@pytest.mark.parametrize('busy', [False, True], ids=['idle', 'busy'])
def test_every_node_stops_within_the_bound_on_sigint_or_sigterm(domain, tmp_path, busy):
    from ltl_instruct.nodes.client import GraphClient
    g = NodeGraph(ALL_NODES, default_params_file(), BUSY if busy else IDLE, log_dir=tmp_path).start()
    try:
        with GraphClient('shutdown_client') as client:
            assert client.wait_for_graph(timeout=180.0, need_sim=True), client.missing(need_sim=True)
            if busy:
                _make_busy(client)
                time.sleep(1.5)    # each is in the middle of it now (it has seconds more to go)
        stopped = _stop_all(g, _signals(signal.SIGTERM if busy else signal.SIGINT))
    finally:
        g.stop()
    print({name: f'{s:.2f} s, exit {rc}' for name, (s, rc) in stopped.items()})
    logs = {p.stem: p.read_text(errors='replace')[-1500:] for p in tmp_path.glob('*.log')}
    assert set(stopped) == set(ALL_NODES), (stopped, logs)
    slow = {name: s for name, (s, _) in stopped.items() if s > STOP_BOUND_S}
    assert not slow, (slow, logs)
    assert all(rc == 0 for _, rc in stopped.values()), (stopped, logs)


def test_the_context_shuts_down_without_finalising_logging(tmp_path):
    """A node process's stop never enters rclpy's logging fini (it held the GIL in a CI run)."""
    script = tmp_path / 'stop.py'
    script.write_text(
        'import rclpy\n'
        'from rclpy.impl.implementation_singleton import rclpy_implementation as impl\n'
        'from ltl_instruct.nodes.common import shutdown_context\n'
        'def refuse():\n'
        '    raise SystemExit("logging fini called")\n'
        'impl.rclpy_logging_fini = refuse\n'
        'rclpy.init()\n'
        'node = rclpy.create_node("stopping")\n'
        'shutdown_context()\n'
        'assert not rclpy.ok()\n'
        'node.get_logger().info("still logs after the stop")\n'
        'print("stopped")\n', encoding='utf-8')
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and 'stopped' in done.stdout, done.stderr

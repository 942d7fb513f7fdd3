"""plan_request delivery over DDS: a late planner still gets the request, a repeat is answered once.

A ``plan_request`` published before discovery has matched ``task_progression`` with
``fmt_planner`` is lost (reliable, volatile QoS). ``task_progression`` therefore sends
only to a listening planner and repeats an unanswered request; the planner answers a
repeat of a request it has answered from memory, without planning again.
"""
from __future__ import annotations

import json
import os
import random
import time

import pytest
from nav_msgs.msg import Path
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.commands.bringup import NodeGraph, default_params_file
from ltl_instruct.core.automaton.guards import Cube, Guard
from ltl_instruct.core.planning import AtomRegion, FmtSettings, SegmentRequest
from ltl_instruct.core.spec import Atom, Descriptor

OVERRIDES = {'sim_world': {'time_scale': 8.0, 'camera_rate_hz': 0.0},
             'referent_grounder': {'use_camera': False}}


@pytest.fixture()
def ros_env(tmp_path):
    env = {'ROS_DOMAIN_ID': str(random.randint(120, 229)), 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'}
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        yield env, tmp_path
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def test_a_planner_that_starts_late_still_plans_the_waiting_instruction(ros_env):
    env, logs = ros_env
    from ltl_instruct.nodes.client import GraphClient
    nodes = NodeGraph(['sim_world', 'ltl_translator', 'referent_grounder', 'task_progression'],
                      default_params_file(), OVERRIDES, env=env, log_dir=logs).start()
    planner = NodeGraph(['fmt_planner'], default_params_file(), env=env, log_dir=logs)
    try:
        with GraphClient('late_planner_client') as client:
            # everything but the planner listens (an instruction sent before the translator
            # listens would be lost: that, not the planner, once made this test time out)
            assert client.wait_for_graph(timeout=180.0, need_sim=True, need_planner=False), \
                (client.missing(need_sim=True, need_planner=False), _logs(logs))
            iid = client.send(formula='F near[tv]')
            time.sleep(2.0)                    # task_progression is waiting for a planner now
            assert client.terminal(iid) is None, client.received.statuses.get(iid)
            planner.start()
            # a liveness bound, not a speed figure: a planner process starting on a loaded
            # 2-core machine (imports, discovery, the first map) has taken over 20 s
            status = client.wait_until(lambda: client.terminal(iid), 60.0)
            assert status is not None, ('no terminal status', client.received.statuses.get(iid), _logs(logs))
            assert status['status'] == 'planned', (status.get('error'), _logs(logs))
            assert not nodes.dead() and not planner.dead()
    finally:
        planner.stop()
        nodes.stop()


def _logs(logs) -> str:
    return '\n'.join(f'--- {p.name}\n{p.read_text(errors="replace")[-3000:]}'
                     for p in sorted(logs.glob('*.log')))


def _request() -> SegmentRequest:
    tv = Atom('near', (Descriptor('tv'),))
    goal = Guard((Cube(frozenset({tv}), frozenset()),))
    allowed = Guard((Cube(frozenset(), frozenset({tv})),))
    region = AtomRegion('near[tv]', ((7.5, 7.7, 0.6),), ((1.2, 0.2, 0.7),), 1.0)
    return SegmentRequest('repeat/0', (1.5, 1.5), 2, (region,), goal, allowed,
                          FmtSettings(num_samples=1000, seed=1), transition=(0, 1))


def test_a_repeated_request_is_answered_again_from_memory(ros_env):
    env, logs = ros_env
    from ltl_instruct.nodes.client import GraphClient
    from ltl_instruct.nodes.common import reliable_qos
    g = NodeGraph(['sim_world', 'fmt_planner'], default_params_file(), OVERRIDES, env=env,
                  log_dir=logs).start()
    try:
        with GraphClient('repeat_client') as client:
            statuses: list[dict] = []
            paths: list[Path] = []
            client.node.create_subscription(
                String, 'fmt_planner/status', lambda m: statuses.append(json.loads(m.data)), reliable_qos())
            client.node.create_subscription(Path, 'plan_segment', paths.append, reliable_qos())
            pub = client.node.create_publisher(String, 'plan_request', reliable_qos())
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline and (pub.get_subscription_count() < 1
                                                   or client.received.map is None):
                time.sleep(0.05)
            time.sleep(1.0)   # the planner has the map too
            msg = conv.json_msg(conv.payload(conv.PLAN_REQUEST, 'repeat', request_id='repeat/0#7', stamp=7,
                                             request=_request().to_dict()))
            for _ in range(3):          # repeats while it is queued or planning are dropped
                pub.publish(msg)
            assert client.wait_until(lambda: statuses, 20.0), (logs / 'fmt_planner.log').read_text()
            time.sleep(1.0)
            assert len(statuses) == 1 and statuses[0]['ok'], statuses
            pub.publish(msg)           # answered: the same answer again, not a new plan
            assert client.wait_until(lambda: len(statuses) == 2 or None, 10.0)
            assert statuses[1] == statuses[0]
            assert client.wait_until(lambda: len(paths) == 2 or None, 5.0)
            assert conv.path_points(paths[0]).tolist() == conv.path_points(paths[1]).tolist()
            assert not g.dead()
    finally:
        g.stop()

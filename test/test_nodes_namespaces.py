"""Two robots on one graph, each in its namespace: real node processes over DDS.

Robot ``/r1`` (the apartment) runs on the simulator's ``/clock``; robot ``/r2`` (a small
room of its own) on the wall clock. Both read the same parameters file (``/**/<node>``
keys), with their own frame prefix. The same instruction goes to both: each plans to its
own lamp, hears only its own statuses, and stamps its headers from its own node clock.
Parameters are set through each node's parameter service from this (another) process.
"""
from __future__ import annotations

import time

import numpy as np
import pytest
from nav_msgs.msg import Odometry, Path
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import GetParameters, SetParameters
from rosgraph_msgs.msg import Clock

from ltl_instruct import conversions as conv
from ltl_instruct.commands.bringup import (
    ALL_NODES, NodeGraph, default_params_file, merge_overrides, robot_overrides, scene_overrides,
)
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.nodes.common import latched_qos, reliable_qos
from ros_env import fresh_domain_id, private_domain

DOMAIN_ID = fresh_domain_id(0x5EEE)
NEAR = 1.0
ROOM = """name: small_room
bounds: {min: [0.0, 0.0, 0.0], max: [8.0, 6.0, 3.0]}
robot: {kind: ground, start: [1.0, 1.0, 0.0], radius: 0.3}
obstacles:
  - {center: [4.0, 0.1, 1.25], size: [8.0, 0.2, 2.5]}
  - {center: [4.0, 5.9, 1.25], size: [8.0, 0.2, 2.5]}
  - {center: [0.1, 3.0, 1.25], size: [0.2, 6.0, 2.5]}
  - {center: [7.9, 3.0, 1.25], size: [0.2, 6.0, 2.5]}
objects:
  - {label: lamp, center: [2.0, 4.8, 0.8], size: [0.3, 0.3, 1.6]}
  - {label: piano, center: [6.0, 4.0, 0.6], size: [1.5, 0.6, 1.2]}
"""
SHARED = ('/clock', '/rosout', '/parameter_events')


@pytest.fixture(scope='module')
def robots(tmp_path_factory):
    with private_domain(DOMAIN_ID):
        from ltl_instruct.nodes.client import GraphClient
        logs = tmp_path_factory.mktemp('node_logs')
        room = tmp_path_factory.mktemp('scene') / 'small_room.yaml'
        room.write_text(ROOM)
        quiet = {'sim_world': {'camera_rate_hz': 0.0, 'time_scale': 4.0, 'max_speed': 1.5},
                 'referent_grounder': {'use_camera': False}, 'ltl_translator': {'backend': 'offline'},
                 'task_progression': {'near_threshold': NEAR}}
        setups = {'/r1': ('apartment', 'r1/', True), '/r2': (str(room), 'r2/', False)}
        graphs, clients = {}, {}
        try:
            for ns, (scene, prefix, sim_time) in setups.items():
                overrides = merge_overrides(scene_overrides(scene), quiet, robot_overrides(prefix, sim_time))
                graphs[ns] = NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs,
                                       namespace=ns).start()
            for ns in setups:
                clients[ns] = GraphClient('ns_client', namespace=ns)
            for ns, client in clients.items():
                assert client.wait_for_graph(timeout=180.0, need_sim=True), (ns, _logs(logs))
            yield graphs, clients, room
        finally:
            for client in clients.values():
                client.close()
            codes = {ns: g.stop() for ns, g in graphs.items()}
            assert all(c == 0 for by_node in codes.values() for c in by_node.values()), (codes, _logs(logs))


def _logs(logs) -> str:
    return '\n'.join(f'--- {p.name}\n' + p.read_text(errors='replace')[-2000:]
                     for p in sorted(logs.glob('*.log')))


def _record(client, msg_type, topic, qos):
    """Subscribe ``topic`` on the client's node; return the list the messages go into."""
    got: list = []
    client.node.create_subscription(msg_type, topic, got.append, qos)
    return got


def test_same_instruction_each_robot_its_own_plan_and_nothing_crosses(robots):
    graphs, clients, room = robots
    c1, c2 = clients['/r1'], clients['/r2']
    i1, i2 = c1.send(text='go to the lamp'), c2.send(text='go to the lamp')
    s1, s2 = c1.wait_terminal(i1, timeout=60.0), c2.wait_terminal(i2, timeout=60.0)
    assert s1['status'] == 'planned' and s2['status'] == 'planned', (s1, s2)
    # the piano is only in r2's room: r1's grounder never hears of it
    i3 = c1.send(text='go to the piano')
    s3 = c1.wait_terminal(i3, timeout=60.0)
    assert s3['status'] == 'failed' and s3['error']['code'] == 'UNKNOWN_REFERENT', s3
    # no status, spec or referent map of one robot reached the other's namespace
    assert set(c1.received.statuses) == {i1, i3} and set(c2.received.statuses) == {i2}
    assert set(c1.received.referent_maps) <= {i1, i3} and set(c2.received.referent_maps) == {i2}
    # each plan ends at its own robot's lamp, in its own frame
    for client, status, scene, frame in ((c1, s1, resolve_scene('apartment'), 'r1/map'),
                                         (c2, s2, resolve_scene(str(room)), 'r2/map')):
        plan = client.wait_until(lambda: client.received.plans.get(status['plan_stamp']), 5.0)
        lamp = next(o for o in scene.objects if o.label == 'lamp')
        assert lamp.box.distance(plan[-1], dims=2)[0] <= NEAR, (frame, plan[-1])
        assert client.keyed('specs', status['id'])['formula'] == 'F near[lamp]'
    # every topic our nodes publish or read is in their namespace (or shared by ROS itself)
    for ns, client in clients.items():
        for node in ALL_NODES:
            for get in (client.node.get_publisher_names_and_types_by_node,
                        client.node.get_subscriber_names_and_types_by_node):
                topics = [t for t, _ in get(node, ns)]
                assert topics, (ns, node)
                stray = [t for t in topics if not t.startswith(ns + '/') and t not in SHARED]
                assert not stray, (ns, node, stray)
    assert not any(g.dead() for g in graphs.values())


def test_headers_are_stamped_by_each_robots_node_clock(robots):
    graphs, clients, _ = robots
    c1, c2 = clients['/r1'], clients['/r2']
    clock = _record(c1, Clock, '/clock', reliable_qos(10))
    plans = {ns: _record(c, Path, 'plan', latched_qos(1)) for ns, c in clients.items()}
    odom = {ns: _record(c, Odometry, 'odom', reliable_qos(10)) for ns, c in clients.items()}
    i1, i2 = c1.send(formula='F near[table]'), c2.send(formula='F near[piano]')
    assert c1.wait_terminal(i1, timeout=60.0)['status'] == 'planned'
    assert c2.wait_terminal(i2, timeout=60.0)['status'] == 'planned'
    assert c1.wait_until(lambda: len(clock) > 5 and all(plans.values()) and all(odom.values()), 10.0)
    sim_now = conv.stamp_key(clock[-1].clock) / 1e9
    wall = time.time()
    # r1 runs on /clock: simulated seconds since its simulator started (4x the wall clock), not wall time
    for msg in (plans['/r1'][-1], odom['/r1'][-1]):
        t = conv.stamp_key(msg.header.stamp) / 1e9
        assert 0.0 < t <= sim_now + 1.0 and wall - t > 1e6, (t, sim_now)
        assert msg.header.frame_id == 'r1/map'
    # r2 runs on the wall clock
    for msg in (plans['/r2'][-1], odom['/r2'][-1]):
        assert abs(conv.stamp_key(msg.header.stamp) / 1e9 - wall) < 60.0
        assert msg.header.frame_id == 'r2/map'


def _call(client, service_type, name, request, timeout=10.0):
    cli = client.node.create_client(service_type, name)
    assert cli.wait_for_service(timeout_sec=timeout), name
    future = cli.call_async(request)
    assert client.wait_until(future.done, timeout), name
    return future.result()


def _set(client, node, name, value):
    if isinstance(value, bool):
        v = ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=value)
    elif isinstance(value, float):
        v = ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=value)
    else:
        v = ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=value)
    answer = _call(client, SetParameters, f'{node}/set_parameters',
                   SetParameters.Request(parameters=[Parameter(name=name, value=v)]))
    return answer.results[0]


def test_parameters_set_at_runtime_where_safe_and_refused_elsewhere(robots):
    _, clients, _ = robots
    c2 = clients['/r2']
    # read-only: the robot's kind shapes the planner built at start
    refused = _set(c2, 'task_progression', 'robot_kind', 'drone')
    assert not refused.successful and 'read-only' in refused.reason
    # out of range: refused with the range
    bad = _set(c2, 'task_progression', 'goal_margin', 50.0)
    assert not bad.successful
    # a runtime parameter is taken, and read back
    ok = _set(c2, 'task_progression', 'goal_margin', 0.15)
    assert ok.successful, ok.reason
    got = _call(c2, GetParameters, 'task_progression/get_parameters',
                GetParameters.Request(names=['goal_margin']))
    assert got.values[0].double_value == pytest.approx(0.15)
    # and it changes what the node does: the simulator drives at the new speed
    assert _set(c2, 'sim_world', 'max_speed', 0.4).successful
    odom = _record(c2, Odometry, 'odom', reliable_qos(50))
    iid = c2.send(formula='F near[lamp] & F near[piano]')
    assert c2.wait_terminal(iid, timeout=60.0)['status'] == 'planned'

    def moving():
        speeds = [float(np.linalg.norm([m.twist.twist.linear.x, m.twist.twist.linear.y])) for m in odom]
        return [v for v in speeds if v > 0.05]

    # about 3 m at 0.4 m/s of simulated time, 4x faster than the wall clock: ~2 s, 40 poses at 20 Hz
    assert c2.wait_until(lambda: len(moving()) > 10, 30.0)
    assert 0.3 <= max(moving()) <= 0.4 * 1.05, moving()   # was 1.5 m/s


def test_odometry_in_a_foreign_frame_is_rejected_on_task_status(robots):
    _, clients, _ = robots
    c2 = clients['/r2']
    pub = c2.node.create_publisher(Odometry, 'odom', reliable_qos(10))

    def rejected():
        return next((s for ss in c2.received.statuses.values() for s in ss
                     if s.get('status') == 'input_rejected'
                     and (s.get('error') or {}).get('code') == 'FRAME_MISMATCH'), None)

    def send():
        pub.publish(conv.odometry_msg(Pose((1.0, 1.0, 0.0)), frame_id='r1/map'))
        return rejected()

    status = c2.wait_until(send, 10.0)
    assert status is not None
    assert status['error']['details'] == {'frame': 'r1/map', 'expected': ['r2/map']}
    assert 'r1/map' in status['error']['message'] and 'r2/map' in status['error']['message']


def _conditions(ns: str, node: str) -> set[str]:
    """The table's "when" values that hold for ``node`` of robot ``ns`` as the fixture starts it."""
    held = {'always', 'ground'}
    if ns == '/r1':   # on simulated time: the simulator makes the clock, the others read it
        held.add('publish_clock' if node == 'sim_world' else 'use_sim_time')
    return held


def _qos_text(profile) -> str:
    from rclpy.qos import DurabilityPolicy, ReliabilityPolicy
    if profile.reliability == ReliabilityPolicy.BEST_EFFORT:
        return 'best effort'
    return 'latched' if profile.durability == DurabilityPolicy.TRANSIENT_LOCAL else 'reliable'


def test_readme_interface_table_matches_the_running_nodes(robots):
    """Each endpoint the nodes have on the graph is a README table row, and each row that applies is one."""
    from readme_tables import read_table
    from rclpy.topic_endpoint_info import TopicEndpointTypeEnum
    rows = read_table('topics')
    _, clients, _ = robots
    for ns, client in clients.items():
        node = client.node
        seen = set()
        for topic, _ in node.get_topic_names_and_types():
            if topic in ('/rosout', '/parameter_events'):
                continue
            endpoints = node.get_publishers_info_by_topic(topic) + node.get_subscriptions_info_by_topic(topic)
            for info in endpoints:
                if info.node_namespace != ns or info.node_name not in ALL_NODES:
                    continue   # this test's clients, the other robot
                kind = 'pub' if info.endpoint_type == TopicEndpointTypeEnum.PUBLISHER else 'sub'
                name = topic if topic in SHARED else topic[len(ns) + 1:]
                seen.add((info.node_name, kind, name, info.topic_type.replace('/msg/', '/'),
                          _qos_text(info.qos_profile)))
        expected = set()
        for r in rows:
            nodes = ALL_NODES if r['node'] == 'every node' else (r['node'],)
            for n in nodes:
                if r['when'] in _conditions(ns, n):
                    expected.add((n, r['pub/sub'], r['topic'], r['type'], r['QoS'].rsplit(' ', 1)[0]))
        assert seen == expected, (ns, sorted(seen - expected), sorted(expected - seen))

"""Frames, odometry QoS, stamps and namespaces: the shared node helpers, with real rclpy.

The QoS test runs two rclpy contexts in this process that talk over DDS (localhost, a
test-private domain): a best-effort odometry publisher must be heard by the nodes'
odometry subscription (a reliable-only one would never match it), and a reliable one
heard once per message.
"""
from __future__ import annotations

import math
import os
import random
import threading
import time

import pytest
import rclpy
from nav_msgs.msg import Odometry
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor

from ltl_instruct import conversions as conv
from ltl_instruct.commands.bringup import file_parameters, node_command, normalize_namespace
from ltl_instruct.core.errors import ErrorCode, InvalidInputError
from ltl_instruct.core.world.robot import Pose, compose_planar
from ltl_instruct.nodes.common import (
    COMMON_PARAMS, Frames, StampSource, reliable_qos, sensor_qos, subscribe_any_reliability,
)

DOMAIN_ID = random.Random(os.getpid() ^ int(time.time()) ^ 0xf00d).randint(120, 229)


def test_odometry_in_the_map_frame_is_taken_as_it_is():
    msg = conv.odometry_msg(Pose((1.0, 2.0, 0.0), 0.5), frame_id='r1/map')
    pose = conv.odometry_in_map(msg, 'r1/map', 'r1/odom', None)
    assert pose.position == (1.0, 2.0, 0.0) and pose.yaw == pytest.approx(0.5)


def test_odometry_in_odom_is_moved_by_the_fixed_map_to_odom_pose():
    offset = conv.parse_planar_pose('10, 5, 1.5707963267948966')
    msg = conv.odometry_msg(Pose((1.0, 0.0, 0.2), 0.0), frame_id='odom')
    pose = conv.odometry_in_map(msg, 'map', 'odom', offset)
    # one metre along odom's x is one metre along map's y when odom is turned a quarter turn
    assert pose.position == pytest.approx((10.0, 6.0, 0.2))
    assert pose.yaw == pytest.approx(math.pi / 2)


@pytest.mark.parametrize('frame, offset', [('odom', None), ('r2/map', None), ('', None),
                                           ('base_link', '0,0,0')])
def test_odometry_in_a_frame_the_robot_cannot_place_names_the_frames(frame, offset):
    msg = conv.odometry_msg(Pose((1.0, 2.0, 0.0)), frame_id=frame)
    with pytest.raises(InvalidInputError) as e:
        conv.odometry_in_map(msg, 'map', 'odom', conv.parse_planar_pose(offset or ''))
    assert e.value.code == ErrorCode.FRAME_MISMATCH
    assert e.value.details['frame'] == frame and 'map' in e.value.details['expected']
    assert repr(frame) in e.value.message


@pytest.mark.parametrize('text', ['1,2', 'a,b,c', '1,2,nan', '1,2,3,4'])
def test_map_to_odom_must_be_three_finite_numbers(text):
    with pytest.raises(InvalidInputError):
        conv.parse_planar_pose(text)


def test_compose_planar_inverts_with_the_opposite_turn():
    a = Pose((3.0, -1.0, 0.0), 2.0)
    back = compose_planar(Pose((0.0, 0.0, 0.0), -2.0), compose_planar(Pose((0.0, 0.0, 0.0), 2.0), a))
    assert back.position == pytest.approx(a.position) and back.yaw == pytest.approx(a.yaw)


def test_frame_prefix_parameter_accepts_prefixes_and_refuses_the_rest():
    spec = next(p for p in COMMON_PARAMS if p.name == 'frame_prefix')
    for good in ('', 'r1/', 'fleet/r_2/'):
        assert spec.check(good) == good
    for bad in ('r1', '/r1/', 'r 1/', 'r1//'):
        with pytest.raises(InvalidInputError):
            spec.check(bad)
    f = Frames('r1/')
    assert (f.map, f.odom, f.base_link) == ('r1/map', 'r1/odom', 'r1/base_link')
    assert f.camera == 'r1/camera_optical'


def test_namespaces_are_made_absolute_and_checked():
    assert normalize_namespace('r1') == '/r1' and normalize_namespace('/fleet/r1/') == '/fleet/r1'
    assert normalize_namespace('') == ''
    for bad in ('1robot', 'r-1', 'r 1'):
        with pytest.raises(InvalidInputError):
            normalize_namespace(bad)
    cmd = node_command('sim_world', None, {'rate_hz': 5.0}, 'r1', 'debug')
    args = cmd[cmd.index('--ros-args') + 1:]
    assert args == ['-r', '__ns:=/r1', '--log-level', 'debug', '-p', 'rate_hz:=5.0']


def test_file_parameters_merges_wildcard_sections_as_rcl_does():
    params = {'/**': {'ros__parameters': {'frame_prefix': 'a/', 'x': 1}},
              '/**/sim_world': {'ros__parameters': {'x': 2}},
              'fmt_planner': {'ros__parameters': {'y': 3}}}
    assert file_parameters(params, 'sim_world') == {'frame_prefix': 'a/', 'x': 2}
    assert file_parameters(params, 'fmt_planner') == {'frame_prefix': 'a/', 'x': 1, 'y': 3}


def _spin(executor, stop) -> None:
    while not stop.is_set():
        executor.spin_once(timeout_sec=0.05)


@pytest.fixture
def two_contexts(monkeypatch):
    monkeypatch.setenv('ROS_DOMAIN_ID', str(DOMAIN_ID))
    monkeypatch.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'LOCALHOST')
    monkeypatch.delenv('ROS_LOCALHOST_ONLY', raising=False)
    made = []
    for _ in range(2):
        ctx = Context()
        rclpy.init(context=ctx, args=[])
        node = rclpy.create_node(f'qos_{os.urandom(3).hex()}', context=ctx)
        ex = SingleThreadedExecutor(context=ctx)
        ex.add_node(node)
        stop = threading.Event()
        thread = threading.Thread(target=_spin, args=(ex, stop), daemon=True)
        thread.start()
        made.append((ctx, node, ex, stop, thread))
    yield made[0][1], made[1][1]
    for ctx, node, ex, stop, thread in made:
        stop.set()
        thread.join(timeout=5.0)
        ex.shutdown(timeout_sec=2.0)
        node.destroy_node()
        rclpy.try_shutdown(context=ctx)


@pytest.mark.parametrize('qos', ['best_effort', 'reliable'])
def test_odometry_subscription_hears_both_reliabilities_once_each(two_contexts, qos):
    listener, talker = two_contexts
    got: list = []
    subscribe_any_reliability(listener, Odometry, 'odom', got.append, 50)
    profile = sensor_qos(50) if qos == 'best_effort' else reliable_qos(50)
    pub = talker.create_publisher(Odometry, 'odom', profile)
    deadline = time.monotonic() + 10.0
    while pub.get_subscription_count() < (1 if qos == 'best_effort' else 2) and time.monotonic() < deadline:
        time.sleep(0.05)
    for i in range(20):
        pub.publish(conv.odometry_msg(Pose((float(i), 0.0, 0.0)), frame_id='map'))
        time.sleep(0.01)
    deadline = time.monotonic() + 5.0
    while len(got) < 20 and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)   # a repeat from the second subscription would come by now
    xs = [m.pose.pose.position.x for m in got]
    assert xs == sorted(set(xs)), xs               # each once, in order
    assert len(xs) >= (18 if qos == 'best_effort' else 20), xs   # best effort may drop one on a loaded host


def test_stamps_follow_the_node_clock_and_always_grow(two_contexts):
    node, _ = two_contexts
    stamps = StampSource(node)
    values = [next(stamps) for _ in range(1000)]
    assert all(b > a for a, b in zip(values, values[1:]))
    assert abs(values[-1] / 1e9 - time.time()) < 5.0


@pytest.mark.parametrize('args, says', [(['--namespace', '1bad'], "namespace '1bad'"),
                                        (['--frame-prefix', 'r1'], 'frame_prefix')])
def test_bringup_refuses_a_bad_namespace_or_frame_prefix_before_starting_anything(args, says):
    import subprocess
    import sys
    from pathlib import Path
    repo = Path(__file__).resolve().parent.parent
    proc = subprocess.run([sys.executable, '-m', 'ltl_instruct', 'bringup', *args], capture_output=True,
                          text=True, timeout=120, env=dict(os.environ, PYTHONPATH=str(repo)))
    assert proc.returncode == 2 and says in proc.stderr and 'started' not in proc.stdout, proc

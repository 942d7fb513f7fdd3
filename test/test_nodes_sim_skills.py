"""``sim_world`` and the order of its inputs: a plan on ``plan``, its skills on ``skill/request``.

DDS does not order two topics, so the skill requests of a plan can reach the simulator
before the plan does (a CI run saw it: the pick was tried where the robot stood, failed,
and the whole task was carried out a second time after the replan). The real node is
driven here through its callbacks, in the order a test names, with its clock stepped
by hand; its skill results are read from what it publishes.
"""
from __future__ import annotations

import json
import time

import numpy as np
import pytest

rclpy = pytest.importorskip('rclpy')

from std_msgs.msg import String  # noqa: E402

from ltl_instruct import conversions as conv  # noqa: E402

TOY = (6.5, 10.5)      # green_plush_toy in the apartment scene
BASKET = (4.0, 9.0)    # basket


class _Recorder:
    def __init__(self) -> None:
        self.results: list[dict] = []

    def publish(self, msg: String) -> None:
        self.results.append(json.loads(msg.data))


@pytest.fixture()
def sim():
    rclpy.init(args=['--ros-args', '-p', 'camera_rate_hz:=0.0', '-p', 'skill_duration:=0.0',
                     '-p', 'max_speed:=5.0'])
    from ltl_instruct.nodes.sim_world import SimWorldNode
    try:
        node = SimWorldNode()
        node.result_pub = _Recorder()
        yield node
        node.destroy_node()
    finally:
        rclpy.shutdown()


def _path(stamp: int) -> tuple:
    """A straight path start -> toy -> basket, and the path indices of the toy and the basket."""
    start = np.array([1.5, 1.5])
    legs = [np.linspace(start, TOY, 12), np.linspace(TOY, BASKET, 6)[1:]]
    xy = np.vstack(legs)
    points = np.column_stack([xy, np.zeros(len(xy))])
    return conv.path_msg(points, conv.stamp_from_key(stamp)), 11, len(points) - 1


def _request(stamp, skill, args, index, iid='t-1') -> String:
    return conv.json_msg(conv.payload(conv.SKILL_REQUEST, iid, plan_stamp=stamp, skill=skill,
                                      args=args, targets=[], path_index=index))


def _run(node, seconds=6.0) -> None:
    """Step the simulation by hand (0.05 s of wall time per tick, sped up by the time scale)."""
    node.params['time_scale'] = 50.0
    end = time.monotonic() + seconds
    while time.monotonic() < end and len(node.result_pub.results) < 2:
        node._last_tick = time.monotonic() - 0.05
        node.on_tick()


def _skills(node) -> list[tuple[str, bool]]:
    return [(r['skill'], r['ok']) for r in node.result_pub.results]


def _ask_pick_and_place(sim, stamp, at_toy, at_basket) -> None:
    sim.on_skill_request(_request(stamp, 'pick', ['green_plush_toy'], at_toy))
    sim.on_skill_request(_request(stamp, 'release', ['green_plush_toy', 'basket'], at_basket))


def _done_once(sim) -> None:
    _run(sim)
    assert _skills(sim) == [('pick', True), ('release', True)], sim.result_pub.results


def test_skill_requests_in_order_are_carried_out_at_their_stops(sim):
    stamp = 1_000
    plan, at_toy, at_basket = _path(stamp)
    sim.on_plan(plan)
    _ask_pick_and_place(sim, stamp, at_toy, at_basket)
    _done_once(sim)


def test_skill_requests_that_come_before_their_plan_wait_for_it(sim):
    stamp = 2_000
    plan, at_toy, at_basket = _path(stamp)
    _ask_pick_and_place(sim, stamp, at_toy, at_basket)
    _run(sim, seconds=0.3)            # nothing is tried before the plan is here
    assert sim.result_pub.results == []
    sim.on_plan(plan)
    _done_once(sim)


def test_a_request_for_a_replaced_plan_is_dropped(sim):
    old, new = 3_000, 3_001
    plan_old, at_toy, _ = _path(old)
    plan_new, at_toy, at_basket = _path(new)
    sim.on_plan(plan_old)
    sim.on_plan(plan_new)
    sim.on_skill_request(_request(old, 'pick', ['green_plush_toy'], 0))   # late, for the old plan
    _ask_pick_and_place(sim, new, at_toy, at_basket)
    _done_once(sim)


def test_two_stops_already_passed_are_both_carried_out_in_order(sim):
    stamp = 4_000
    plan, _, _ = _path(stamp)
    sim.on_plan(plan)
    # no object at the start: both are tried there, in the order asked, and fail with reasons
    sim.on_skill_request(_request(stamp, 'pick', ['green_plush_toy'], -5))
    sim.on_skill_request(_request(stamp, 'release', ['green_plush_toy', 'basket'], -3))
    _run(sim)
    assert _skills(sim) == [('pick', False), ('release', False)], sim.result_pub.results
    assert all(r['error']['message'] for r in sim.result_pub.results)


def test_a_slow_tick_publishes_the_corners_passed_before_the_pose(sim):
    class Odom:
        def __init__(self):
            self.poses = []

        def publish(self, msg):
            self.poses.append(conv.odometry_pose(msg).xyz[:2].round(3).tolist())

    sim.odom_pub = Odom()
    plan, _, _ = _path(5_000)
    sim.on_plan(plan)
    sim.params['time_scale'] = 50.0
    sim._last_tick = time.monotonic() - 0.5     # a stalled tick: 25 simulated seconds
    sim.on_tick()
    assert sim.odom_pub.poses == [list(TOY), list(BASKET)]

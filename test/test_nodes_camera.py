"""The camera path over DDS: the simulator's RGB-D + label frames are the grounder's only source.

The referent grounder starts with no known objects (``scene: ''``); everything it can
ground comes from the synthetic camera of ``sim_world`` integrated into its semantic map.
"""
from __future__ import annotations

import time

import pytest

from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, default_params_file
from ltl_instruct.core.world.builtin import resolve_scene
from ros_env import fresh_domain_id, private_domain


@pytest.fixture(scope='module')
def camera_graph(tmp_path_factory):
    with private_domain(fresh_domain_id(7)):
        from ltl_instruct.nodes.client import GraphClient
        logs = tmp_path_factory.mktemp('camera_logs')
        # depth in millimetres (16UC1), as most depth cameras send it: read as metres by the grounder
        overrides = {'sim_world': {'camera_rate_hz': 4.0, 'time_scale': 4.0, 'depth_encoding': '16UC1'},
                     'referent_grounder': {'scene': '', 'use_camera': True, 'camera_min_interval': 0.1},
                     'task_progression': {'search': False},   # the search has its own test
                     'ltl_translator': {'backend': 'offline'}}   # formulas are sent: no model to wait for
        g = NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs).start()
        client = GraphClient('camera_test')
        try:
            assert client.wait_for_graph(timeout=180.0, need_sim=True)
            yield g, client
        finally:
            client.close()
            g.stop()


def test_an_object_seen_by_the_camera_is_grounded_and_planned_to(camera_graph):
    g, client = camera_graph
    pillar = resolve_scene('apartment').object_by_id('pillar')   # in view from the start pose
    status = None
    deadline = time.monotonic() + 20.0
    while time.monotonic() < deadline:      # the first frames take a moment to arrive
        iid = client.send(formula='F near[pillar]')
        status = client.wait_terminal(iid, timeout=20.0)
        if status['status'] != 'failed':
            break
        time.sleep(0.5)
    assert status is not None and status['status'] in ('planned', 'satisfied'), status
    groundings = client.keyed('referent_maps', iid)['referent_map']['groundings']
    found = groundings['pillar']['instances']
    assert found and all(i['id'].startswith('det_') for i in found)      # detections, not a list
    assert min(abs(i['center'][0] - pillar.center[0]) + abs(i['center'][1] - pillar.center[1])
               for i in found) < 0.5


def test_an_object_never_seen_is_unknown(camera_graph):
    g, client = camera_graph
    iid = client.send(formula='F near[fridge]')          # behind walls, in another room
    status = client.wait_terminal(iid, timeout=20.0)
    assert status['status'] == 'failed' and status['error']['code'] == 'UNKNOWN_REFERENT'
    assert not g.dead()


def test_the_corners_a_tick_passed_get_their_own_stamps():
    # a frame carries the stamp of the tick's last pose; a corner sharing that stamp was read as the
    # frame's pose when the grounder took the frame between the corner's odometry and the last pose's
    # (a vase placed 1.5 m off on a loaded machine)
    from ltl_instruct import conversions as conv
    from ltl_instruct.nodes.sim_world import _between_stamps
    before, after = conv.stamp_from_key(1_000_000_000), conv.stamp_from_key(1_300_000_000)
    keys = [conv.stamp_key(s) for s in _between_stamps(before, after, 3)]
    assert keys == sorted(set(keys)) and 1_000_000_000 < keys[0] and keys[-1] < 1_300_000_000
    assert _between_stamps(None, after, 2) == [after, after]   # the first tick: nothing before it

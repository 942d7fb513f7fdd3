"""Bringup: node command lines, parameter specs, and a clean stop on Ctrl-C."""
from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, default_params_file, node_command
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.nodes.common import ParamSpec

REPO = Path(__file__).resolve().parent.parent


def test_node_command_passes_the_params_file_and_overrides():
    cmd = node_command('sim_world', Path('/x/p.yaml'), {'scene': 'city_block', 'use_camera': False})
    assert cmd[:3] == [sys.executable, '-m', 'ltl_instruct.nodes.sim_world']
    assert cmd[3:] == ['--ros-args', '--params-file', '/x/p.yaml', '-p', 'scene:=city_block',
                       '-p', 'use_camera:=false']


def test_default_params_file_is_the_packaged_config():
    assert default_params_file() == REPO / 'config' / 'ltl_instruct.yaml'


def test_unknown_nodes_are_refused():
    with pytest.raises(InvalidInputError):
        NodeGraph(['sim_world', 'teleporter'])


def test_param_spec_checks_type_range_and_choices():
    speed = ParamSpec('max_speed', 1.0, 'speed [m/s]', 0.05, 20.0)
    assert speed.check(2) == 2.0
    for bad in (0.0, 25.0, float('nan'), 'fast', True):
        with pytest.raises(InvalidInputError):
            speed.check(bad)
    kind = ParamSpec('robot_kind', 'ground', 'kind', choices=('ground', 'drone'))
    assert kind.check('drone') == 'drone'
    with pytest.raises(InvalidInputError):
        kind.check('boat')
    d = speed.descriptor()
    assert d.floating_point_range[0].from_value == 0.05 and 'speed' in d.description
    assert ParamSpec('n', 5, 'count', 1, 10).descriptor().integer_range[0].to_value == 10


def test_bringup_starts_nodes_and_stops_them_cleanly_on_ctrl_c(tmp_path):
    env = dict(os.environ, ROS_DOMAIN_ID=str(random.randint(120, 229)),
               ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONPATH=str(REPO))
    proc = subprocess.Popen([sys.executable, '-m', 'ltl_instruct.cli', 'bringup', '--sim',
                             '--nodes', 'sim_world', '--log-dir', str(tmp_path)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True)
    try:
        deadline = time.monotonic() + 30
        log = tmp_path / 'sim_world.log'
        while time.monotonic() < deadline and not (log.is_file() and 'sim_world: scene' in log.read_text()):
            time.sleep(0.2)
        assert proc.poll() is None
        os.killpg(proc.pid, signal.SIGINT)
        out, _ = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 0, out
    assert "stopped: {'sim_world': 0}" in out
    assert 'sim_world: scene apartment' in (tmp_path / 'sim_world.log').read_text()


def test_all_nodes_are_console_scripts():
    text = (REPO / 'setup.py').read_text()
    for node in ALL_NODES:
        assert f"'{node}'" in text


def test_scene_overrides_tell_every_node_about_the_robot():
    from ltl_instruct.commands.bringup import scene_overrides
    ground = scene_overrides('apartment')
    assert ground['sim_world']['scene'] == ground['referent_grounder']['scene'] == 'apartment'
    assert ground['task_progression']['robot_kind'] == 'ground' and 'bounds' not in ground['fmt_planner']
    drone = scene_overrides('city_block')
    assert drone['task_progression']['robot_kind'] == 'drone'
    assert drone['fmt_planner']['bounds'] == drone['task_progression']['bounds'] == '0.5,0.5,2,119.5,99.5,30'


def test_a_translator_backend_that_cannot_start_fails_each_instruction_not_the_node(tmp_path):
    """A learned backend with no model: typed MODEL_ERROR on task_spec per instruction, node alive."""
    domain = str(random.randint(120, 229))
    env = {'ROS_DOMAIN_ID': domain, 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'}
    overrides = {'ltl_translator': {'backend': 'learned', 'model_path': str(tmp_path / 'no_such_model.pt')}}
    g = NodeGraph(['ltl_translator'], default_params_file(), overrides, env=env, log_dir=tmp_path).start()
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        from ltl_instruct.nodes.client import GraphClient
        with GraphClient('broken_backend_client') as client:
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline and client.instruction_pub.get_subscription_count() < 1:
                time.sleep(0.05)
            state = client.wait_until(lambda: client.received.translator.get('state') == 'failed'
                                      and client.received.translator, 20.0)
            specs = []
            for text in ('go to the sofa', 'then the fridge'):
                iid = client.send(text=text)
                specs.append(client.wait_until(lambda: client.received.specs.get(iid), 20.0))
            assert not g.dead(), (tmp_path / 'ltl_translator.log').read_text()
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
        codes = g.stop()
    assert state and state['code'] == 'MODEL_ERROR' and state['reason'], state   # said before any instruction
    for spec in specs:
        assert spec is not None and spec['ok'] is False, spec
        assert spec['error']['code'] == 'MODEL_ERROR' and spec['error']['message'], spec
    assert codes == {'ltl_translator': 0}


def test_restarts_back_off_doubling_with_each_quick_crash_and_respawn_is_the_default():
    import argparse

    from ltl_instruct.commands.bringup import RestartPolicy, add_arguments
    policy = RestartPolicy(first_delay=0.5, max_delay=3.0)
    assert [policy.delay(n) for n in (1, 2, 3, 4, 5)] == [0.5, 1.0, 2.0, 3.0, 3.0]
    parser = argparse.ArgumentParser()
    add_arguments(parser)
    assert parser.parse_args([]).respawn and not parser.parse_args(['--no-respawn']).respawn


def test_a_node_whose_parameters_are_invalid_is_not_restarted(tmp_path):
    from ltl_instruct.commands.bringup import RestartPolicy
    env = {'ROS_DOMAIN_ID': str(random.randint(120, 229)), 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'}
    said = []
    g = NodeGraph(['fmt_planner'], default_params_file(), {'fmt_planner': {'num_samples': 5}}, env=env,
                  log_dir=tmp_path, restart=RestartPolicy(first_delay=0.1), say=said.append).start()
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not g.given_up():
            time.sleep(0.1)
    finally:
        g.stop()
    # exit status 2 is a configuration error: restarting would only fail again
    log = (tmp_path / 'fmt_planner.log').read_text()
    assert g.given_up() == {'fmt_planner': 2} and not g.restarts, (said, log)
    assert 'not restarted (its parameters are invalid)' in said[-1]
    assert g.state_dir is not None and not g.state_dir.exists()   # the run's state folder is removed

"""Packaging: ``pip install .`` into a prefix gives what ``ros2 run`` and ``ros2 launch`` look for.

``ros2 run ltl_instruct <node>`` resolves the package prefix through the ament index
(``share/ament_index/resource_index/packages/ltl_instruct``) and runs
``<prefix>/lib/ltl_instruct/<node>``. This test installs the package into a temporary
prefix and resolves everything with ament_index_python the same way.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from ltl_instruct.commands.bringup import ALL_NODES

REPO = Path(__file__).resolve().parent.parent


@pytest.fixture(scope='module')
def prefix(tmp_path_factory):
    prefix = tmp_path_factory.mktemp('prefix')
    proc = subprocess.run(
        # --ignore-installed: never touch an installation in the running environment (pip would
        # otherwise uninstall an editable install of the package before installing into the prefix)
        [sys.executable, '-m', 'pip', 'install', '--quiet', '--no-deps', '--no-build-isolation',
         '--ignore-installed', '--no-warn-script-location', '--prefix', str(prefix), str(REPO)],
        capture_output=True, text=True, timeout=300, cwd=tmp_path_factory.mktemp('cwd'))
    assert proc.returncode == 0, proc.stderr[-3000:]
    return prefix


def _resolve(prefix: Path, code: str) -> str:
    env = dict(os.environ, AMENT_PREFIX_PATH=str(prefix))
    proc = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, env=env, timeout=60)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.strip()


def test_ament_index_finds_the_package_and_its_share(prefix):
    out = _resolve(prefix, 'from ament_index_python.packages import get_package_prefix, '
                           'get_package_share_directory as s; print(get_package_prefix("ltl_instruct")); '
                           'print(s("ltl_instruct"))')
    pkg_prefix, share = out.splitlines()
    assert Path(pkg_prefix) == prefix
    share = Path(share)
    assert (share / 'package.xml').is_file()
    assert (share / 'launch' / 'ltl_instruct.launch.py').is_file()
    params = yaml.safe_load((share / 'config' / 'ltl_instruct.yaml').read_text())
    assert set(ALL_NODES) <= set(params)
    assert all('ros__parameters' in params[n] for n in ALL_NODES)


@pytest.mark.parametrize('node', ALL_NODES)
def test_ros2_run_finds_each_node_executable(prefix, node):
    # ros2 run: <package prefix>/lib/<package>/<executable>, and it must be executable
    exe = Path(_resolve(prefix, 'from ament_index_python.packages import get_package_prefix; '
                                'print(get_package_prefix("ltl_instruct"))')) / 'lib' / 'ltl_instruct' / node
    assert exe.is_file() and os.access(exe, os.X_OK)


def test_installed_node_executable_starts_and_rejects_bad_parameters(prefix):
    """Run one installed node the way ros2 run would, with an out-of-range parameter: exit 2, clear error."""
    site = next(prefix.glob('lib/python3*/site-packages'))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(site)] + sys.path[1:]),
               ROS_DOMAIN_ID='231', ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')
    exe = prefix / 'lib' / 'ltl_instruct' / 'sim_world'
    proc = subprocess.run([str(exe), '--ros-args', '-p', 'rate_hz:=-5.0'], capture_output=True,
                          text=True, env=env, timeout=60)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    assert 'rate_hz' in proc.stderr


def test_launch_file_names_every_node():
    text = (REPO / 'launch' / 'ltl_instruct.launch.py').read_text()
    compile(text, 'ltl_instruct.launch.py', 'exec')
    for node in ALL_NODES:
        assert f"'{node}'" in text


def test_params_file_matches_declared_parameters():
    """Every key of config/ltl_instruct.yaml is a declared parameter, valid for its node."""
    from ltl_instruct.nodes import (fmt_planner, ltl_translator, referent_grounder, sim_world,
                                    task_progression)
    modules = {'ltl_translator': ltl_translator, 'referent_grounder': referent_grounder,
               'task_progression': task_progression, 'fmt_planner': fmt_planner, 'sim_world': sim_world}
    params = yaml.safe_load((REPO / 'config' / 'ltl_instruct.yaml').read_text())
    for node, module in modules.items():
        specs = {p.name: p for p in module.PARAMS}
        for key, value in params[node]['ros__parameters'].items():
            assert key in specs, f'{node}.{key} is not declared'
            specs[key].check(value)

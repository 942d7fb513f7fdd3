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
    # keyed /**/<node>: the file applies to each node in any namespace
    assert {f'/**/{n}' for n in ALL_NODES} <= set(params)
    assert all('ros__parameters' in params[f'/**/{n}'] for n in ALL_NODES)


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


def _run_launch_file(monkeypatch, arguments: dict) -> list:
    """Execute the launch file against small stand-ins for ``launch`` / ``launch_ros`` (not on PyPI).

    The stand-ins record what the file asks for; the file's own logic (which nodes, which
    parameters) runs for real.
    """
    import types

    class Recorded:
        def __init__(self, *args, **kwargs):
            self.args, self.kwargs = args, kwargs

    class LaunchConfiguration:
        def __init__(self, name):
            self.name = name

        def perform(self, context):
            return context[self.name]

    modules = {
        'launch': types.SimpleNamespace(LaunchDescription=lambda actions: actions),
        'launch.actions': types.SimpleNamespace(DeclareLaunchArgument=Recorded, OpaqueFunction=Recorded),
        'launch.substitutions': types.SimpleNamespace(LaunchConfiguration=LaunchConfiguration),
        'launch_ros': types.SimpleNamespace(),
        'launch_ros.actions': types.SimpleNamespace(Node=Recorded),
        'ament_index_python.packages': types.SimpleNamespace(
            get_package_share_directory=lambda pkg: str(REPO)),
    }
    for name, module in modules.items():
        monkeypatch.setitem(sys.modules, name, module)
    namespace: dict = {}
    path = REPO / 'launch' / 'ltl_instruct.launch.py'
    exec(compile(path.read_text(), str(path), 'exec'), namespace)
    actions = namespace['generate_launch_description']()
    declared = {a.args[0]: a.kwargs['default_value'] for a in actions if 'default_value' in a.kwargs}
    context = dict(declared, **arguments)
    opaque = [a for a in actions if 'function' in a.kwargs]
    assert len(opaque) == 1
    return opaque[0].kwargs['function'](context)


def test_launch_file_gives_each_node_the_scene_parameters_as_bringup_does(monkeypatch):
    from ltl_instruct.commands.bringup import scene_overrides
    ground = _run_launch_file(monkeypatch, {})
    assert sorted(n.kwargs['name'] for n in ground) == sorted(set(ALL_NODES) - {'sim_world'})
    drone = _run_launch_file(monkeypatch, {'sim': 'true', 'scene': 'city_block'})
    assert sorted(n.kwargs['name'] for n in drone) == sorted(ALL_NODES)
    expected = scene_overrides('city_block')
    for node in drone:
        params_file, overrides = node.kwargs['parameters']
        assert params_file == str(REPO / 'config' / 'ltl_instruct.yaml')
        overrides.pop('state_dir', None)   # respawn is on: task_progression keeps a journal
        assert overrides == expected.get(node.kwargs['name'], {})
        assert node.kwargs['respawn'] is True and node.kwargs['respawn_delay'] == 1.0
        assert node.kwargs['namespace'] == '' and node.kwargs['ros_arguments'] == ['--log-level', 'info']
    planner = next(n for n in drone if n.kwargs['name'] == 'task_progression')
    assert planner.kwargs['parameters'][1]['robot_kind'] == 'drone'
    still = _run_launch_file(monkeypatch, {'respawn': 'false'})
    assert all(n.kwargs['respawn'] is False and 'state_dir' not in n.kwargs['parameters'][1] for n in still)


def test_launch_file_namespaces_one_robot_on_its_clock_and_frames(monkeypatch):
    """namespace, frame_prefix, use_sim_time and log_level reach every node as bringup gives them."""
    nodes = _run_launch_file(monkeypatch, {'sim': 'true', 'namespace': 'r1', 'frame_prefix': 'r1/',
                                           'use_sim_time': 'true', 'log_level': 'debug'})
    assert sorted(n.kwargs['name'] for n in nodes) == sorted(ALL_NODES)
    for node in nodes:
        name, overrides = node.kwargs['name'], node.kwargs['parameters'][1]
        assert node.kwargs['namespace'] == '/r1'
        assert node.kwargs['ros_arguments'] == ['--log-level', 'debug']
        assert overrides['frame_prefix'] == 'r1/'
        if name == 'sim_world':   # the simulator makes the clock the others read
            assert overrides['publish_clock'] is True and 'use_sim_time' not in overrides
        else:
            assert overrides['use_sim_time'] is True


def test_params_file_matches_declared_parameters():
    """Every key of config/ltl_instruct.yaml is a declared parameter, valid for its node."""
    from ltl_instruct.nodes import (fmt_planner, ltl_translator, referent_grounder, sim_world,
                                    task_progression)
    modules = {'ltl_translator': ltl_translator, 'referent_grounder': referent_grounder,
               'task_progression': task_progression, 'fmt_planner': fmt_planner, 'sim_world': sim_world}
    from ltl_instruct.commands.bringup import file_parameters
    from ltl_instruct.nodes.common import COMMON_PARAMS
    params = yaml.safe_load((REPO / 'config' / 'ltl_instruct.yaml').read_text())
    for node, module in modules.items():
        specs = {p.name: p for p in module.PARAMS + COMMON_PARAMS}
        for key, value in file_parameters(params, node).items():
            assert key in specs, f'{node}.{key} is not declared'
            specs[key].check(value)


def _imported_modules(paths) -> set[str]:
    """Top-level modules imported by the Python files under ``paths`` (absolute imports only)."""
    import ast
    names: set[str] = set()
    for path in paths:
        for f in ([path] if path.is_file() else sorted(path.rglob('*.py'))):
            for node in ast.walk(ast.parse(f.read_text(), str(f))):
                if isinstance(node, ast.Import):
                    names.update(a.name.split('.')[0] for a in node.names)
                elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                    names.add(node.module.split('.')[0])
    local = {'ltl_instruct', 'bench', 'translation_cases', 'ltl_oracles', 'learned_synthetic',
             'readme_tables', 'search_scenes', 'ros_env'}
    return {n for n in names if n not in sys.stdlib_module_names and n not in local}


def test_package_xml_declares_every_import():
    """Each third-party module imported is provided by a key package.xml declares (rosdep or pip key)."""
    import xml.etree.ElementTree as ElementTree
    table = yaml.safe_load((REPO / 'test' / 'package_imports.yaml').read_text())
    root = ElementTree.parse(REPO / 'package.xml').getroot()
    exec_keys = {e.text for e in root.iter('exec_depend')}
    test_keys = {e.text for e in root.iter('test_depend')}
    runtime = _imported_modules([REPO / 'ltl_instruct', REPO / 'launch' / 'ltl_instruct.launch.py'])
    unknown = runtime - set(table['exec'])
    assert not unknown, f'imported by ltl_instruct but not in test/package_imports.yaml: {unknown}'
    assert {table['exec'][m] for m in runtime} <= exec_keys
    tests = _imported_modules([REPO / 'test', REPO / 'bench']) - runtime
    unknown = tests - set(table['exec']) - set(table['test'])
    assert not unknown, f'imported by the tests but not in test/package_imports.yaml: {unknown}'
    assert {table['test'][m] for m in tests if m in table['test']} <= test_keys | exec_keys
    # every pip key has its rosdep rule (a pip package) in rosdep/ltl_instruct.yaml
    rules = yaml.safe_load((REPO / 'rosdep' / 'ltl_instruct.yaml').read_text())
    for key in sorted(k for k in exec_keys | test_keys if k.endswith('-pip')):
        assert rules[key]['ubuntu']['pip']['packages'], key


def _table_default(value) -> str:
    if isinstance(value, bool):
        return 'true' if value else 'false'
    return '""' if value == '' else str(value)


def _table_range(spec) -> str:
    if spec.choices:
        return ' | '.join(spec.choices)
    return f'{spec.low:g} .. {spec.high:g}' if spec.low is not None else ''


def test_readme_parameter_table_matches_what_each_node_declares():
    from readme_tables import read_table

    from ltl_instruct.nodes import (fmt_planner, ltl_translator, referent_grounder, sim_world,
                                    task_progression)
    from ltl_instruct.nodes.common import COMMON_PARAMS
    modules = {'ltl_translator': ltl_translator, 'referent_grounder': referent_grounder,
               'task_progression': task_progression, 'fmt_planner': fmt_planner, 'sim_world': sim_world}
    expected = {('every node', p.name): (p, False) for p in COMMON_PARAMS}
    for node, module in modules.items():
        assert set(module.RUNTIME) <= {p.name for p in module.PARAMS}, node
        expected.update({(node, p.name): (p, p.name in module.RUNTIME) for p in module.PARAMS})
    rows = {(r['node'], r['parameter']): r for r in read_table('parameters')}
    assert set(rows) == set(expected), set(rows) ^ set(expected)
    for key, (spec, runtime) in expected.items():
        row = rows[key]
        assert row['default'] == _table_default(spec.default), (key, row['default'])
        assert row['range'] == _table_range(spec), (key, row['range'])
        assert row['at runtime'] == ('set' if runtime else 'read-only'), key


def _published_statuses() -> set[str]:
    """Every ``status`` task_progression can publish: the literal or constant given to publish_status.

    Its search (``search_driver.SearchMixin``, a base class of the node) publishes through it too.
    """
    import ast
    from ltl_instruct.core import lifecycle
    from ltl_instruct.core.monitor import Verdict
    nodes = REPO / 'ltl_instruct' / 'nodes'
    trees = [ast.parse((nodes / f).read_text()) for f in ('task_progression.py', 'search_driver.py')]
    found: set[str] = set()
    for node in (n for tree in trees for n in ast.walk(tree)):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)):
            continue
        if node.func.attr == '_fail':
            found.add('failed')
        if node.func.attr != 'publish_status' or len(node.args) < 2:
            continue
        arg = node.args[1]
        if isinstance(arg, ast.Constant):
            found.add(arg.value)
        elif isinstance(arg, ast.Name):
            found.add(getattr(lifecycle, arg.id))
        else:   # the monitor's verdict
            assert 'verdict' in ast.unparse(arg), ast.unparse(arg)
            found.update(v.value for v in Verdict)
    return found


def test_readme_status_table_names_every_status_task_progression_publishes():
    from readme_tables import read_table
    documented = {r['status'] for r in read_table('statuses')}
    published = _published_statuses()
    assert published == documented, published ^ documented

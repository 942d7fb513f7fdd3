"""The core library never imports rclpy (design.md): checked on the source and at run time."""
import ast
import subprocess
import sys
from pathlib import Path

CORE = Path(__file__).resolve().parents[1] / 'ltl_instruct' / 'core'
ROS_MODULES = ('rclpy', 'std_msgs', 'nav_msgs', 'sensor_msgs', 'geometry_msgs', 'visualization_msgs',
               'builtin_interfaces', 'rosidl_runtime_py')


def test_no_core_module_imports_ros():
    offenders = []
    for path in CORE.rglob('*.py'):
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            offenders += [f'{path.relative_to(CORE)}: {n}' for n in names
                          if n.split('.')[0] in ROS_MODULES]
    assert not offenders, offenders


def test_importing_every_core_module_loads_no_ros():
    modules = sorted('ltl_instruct.' + '.'.join(p.relative_to(CORE.parent).with_suffix('').parts)
                     for p in CORE.rglob('*.py'))
    modules = [m.replace('.__init__', '') for m in modules]
    code = ('import importlib, sys\n'
            f'for m in {modules!r}:\n'
            '    importlib.import_module(m)\n'
            f'bad = [m for m in sys.modules if m.split(".")[0] in {ROS_MODULES!r}]\n'
            'print(bad)\n'
            'sys.exit(1 if bad else 0)\n')
    r = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr

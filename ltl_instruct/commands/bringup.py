"""``ltl-instruct bringup``: start every node as its own process (no ``ros2`` CLI needed).

Each node runs as ``python -m ltl_instruct.nodes.<name> --ros-args --params-file FILE``
with the parameters of ``config/ltl_instruct.yaml`` (or ``--params FILE``). Ctrl-C (or
SIGTERM) stops them cleanly: SIGINT first, then SIGTERM, then SIGKILL after a grace
period. :class:`NodeGraph` is the same machinery for the demo and the tests.
"""
from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import IO, Mapping, Optional, Sequence

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.scene import Scene

PIPELINE_NODES = ('ltl_translator', 'referent_grounder', 'task_progression', 'fmt_planner')
SIM_NODE = 'sim_world'
ALL_NODES = PIPELINE_NODES + (SIM_NODE,)
PACKAGE = 'ltl_instruct'
PARAMS_FILE_NAME = 'ltl_instruct.yaml'


def default_params_file() -> Path:
    """``config/ltl_instruct.yaml``: from the source tree, else the installed share directory."""
    here = Path(__file__).resolve().parent.parent.parent / 'config' / PARAMS_FILE_NAME
    if here.is_file():
        return here
    try:
        from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
        try:
            share = Path(get_package_share_directory(PACKAGE)) / 'config' / PARAMS_FILE_NAME
            if share.is_file():
                return share
        except PackageNotFoundError:
            pass
    except ImportError:
        pass
    raise InvalidInputError(f'cannot find {PARAMS_FILE_NAME}: pass --params FILE')


def node_command(name: str, params_file: Optional[Path] = None,
                 overrides: Optional[Mapping[str, object]] = None) -> list[str]:
    """Return the command line that starts node ``name`` with a parameters file and ``-p`` overrides."""
    cmd = [sys.executable, '-m', f'{PACKAGE}.nodes.{name}', '--ros-args']
    if params_file is not None:
        cmd += ['--params-file', str(params_file)]
    for key, value in (overrides or {}).items():
        text = str(value).lower() if isinstance(value, bool) else str(value)
        cmd += ['-p', f'{key}:={text or repr("")}']   # an empty string must be written as ''
    return cmd


class NodeGraph:
    """A set of node processes, started together and stopped together.

    Parameters
    ----------
    nodes: names of the nodes to start.
    params_file: the ROS parameters file every node reads.
    overrides: per node name, parameters to set on its command line.
    env: extra environment variables (``ROS_DOMAIN_ID``...).
    log_dir: where each node's output goes (``<log_dir>/<node>.log``); None: inherit.
    """

    def __init__(self, nodes: Sequence[str], params_file: Optional[Path] = None,
                 overrides: Optional[Mapping[str, Mapping[str, object]]] = None,
                 env: Optional[Mapping[str, str]] = None, log_dir: Optional[Path] = None) -> None:
        unknown = [n for n in nodes if n not in ALL_NODES]
        if unknown:
            raise InvalidInputError(f'unknown node(s) {unknown} (known: {", ".join(ALL_NODES)})')
        self.nodes = tuple(nodes)
        self.params_file = params_file
        self.overrides = {k: dict(v) for k, v in (overrides or {}).items()}
        self.env = dict(os.environ)
        repo_root = str(Path(__file__).resolve().parent.parent.parent)
        self.env['PYTHONPATH'] = os.pathsep.join(
            p for p in (repo_root, self.env.get('PYTHONPATH', '')) if p)
        self.env['PYTHONUNBUFFERED'] = '1'
        self.env.update(env or {})
        self.log_dir = log_dir
        self.processes: dict[str, subprocess.Popen] = {}
        self._logs: list[IO[bytes]] = []

    def start(self) -> 'NodeGraph':
        """Start every node (each in its own process group)."""
        if self.log_dir is not None:
            self.log_dir.mkdir(parents=True, exist_ok=True)
        for name in self.nodes:
            out: Optional[IO[bytes]] = None
            if self.log_dir is not None:
                out = open(self.log_dir / f'{name}.log', 'wb')
                self._logs.append(out)
            self.processes[name] = subprocess.Popen(
                node_command(name, self.params_file, self.overrides.get(name)), env=self.env,
                stdout=out, stderr=subprocess.STDOUT if out is not None else None,
                start_new_session=True)
        return self

    def dead(self) -> dict[str, int]:
        """Nodes that have exited, with their exit status."""
        return {n: p.returncode for n, p in self.processes.items() if p.poll() is not None}

    def stop(self, grace: float = 5.0) -> dict[str, Optional[int]]:
        """Stop every node: SIGINT, then SIGTERM, then SIGKILL; return the exit statuses."""
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
            alive = [p for p in self.processes.values() if p.poll() is None]
            if not alive:
                break
            for p in alive:
                try:
                    os.killpg(p.pid, sig)
                except ProcessLookupError:
                    pass
            deadline = time.monotonic() + (grace if sig != signal.SIGKILL else 2.0)
            while time.monotonic() < deadline and any(p.poll() is None for p in alive):
                time.sleep(0.05)
        for f in self._logs:
            f.close()
        self._logs.clear()
        return {n: p.poll() for n, p in self.processes.items()}

    def __enter__(self) -> 'NodeGraph':
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()


def flight_bounds(scene: Scene) -> str:
    """Return ``'xmin,ymin,zmin,xmax,ymax,zmax'`` [m] a drone's centre may use (bounds and altitude band)."""
    r = scene.robot.radius
    lo = [scene.bounds_min[k] + r for k in range(3)]
    hi = [scene.bounds_max[k] - r for k in range(3)]
    if scene.altitude is not None:
        lo[2], hi[2] = max(lo[2], scene.altitude[0]), min(hi[2], scene.altitude[1])
    return ','.join(f'{v:g}' for v in lo + hi)


def scene_overrides(name_or_path: str) -> dict[str, dict[str, object]]:
    """Return the per-node parameters for a scene.

    The simulator and the grounder load it; the planner side gets the robot's kind and
    radius (and, for a drone, the flight volume that the 3D map does not carry).
    """
    scene = resolve_scene(name_or_path)
    arg = str(Path(name_or_path).resolve()) if Path(name_or_path).is_file() else name_or_path
    radius = float(scene.robot.radius)
    out: dict[str, dict[str, object]] = {
        SIM_NODE: {'scene': arg},
        'referent_grounder': {'scene': arg},
        'task_progression': {'robot_kind': scene.robot.kind, 'robot_radius': radius},
        'fmt_planner': {'robot_radius': radius},
    }
    if scene.robot.kind == 'drone':
        out['task_progression']['bounds'] = out['fmt_planner']['bounds'] = flight_bounds(scene)
    return out


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``ltl-instruct bringup``."""
    parser.add_argument('--sim', action='store_true', help='also start the simulator (sim_world)')
    parser.add_argument('--params', type=Path, default=None,
                        help='ROS parameters file (default: config/ltl_instruct.yaml)')
    parser.add_argument('--scene', default=None,
                        help='built-in scene name or scene file for the simulator and the grounder')
    parser.add_argument('--nodes', default=None,
                        help=f'comma-separated subset of nodes (default: {",".join(ALL_NODES)})')
    parser.add_argument('--log-dir', type=Path, default=None,
                        help='write each node\'s output to DIR/<node>.log instead of this terminal')


def run(args: argparse.Namespace) -> int:
    """Start the nodes and wait until Ctrl-C, or until one of them exits."""
    params = args.params or default_params_file()
    if not Path(params).is_file():
        raise InvalidInputError(f'parameters file {params} does not exist')
    nodes = list(PIPELINE_NODES) + ([SIM_NODE] if args.sim else [])
    if args.nodes:
        nodes = [n.strip() for n in args.nodes.split(',') if n.strip()]
    overrides: dict[str, dict[str, object]] = {}
    if args.scene:
        overrides = scene_overrides(args.scene)
    graph = NodeGraph(nodes, Path(params), overrides, log_dir=args.log_dir)
    stop = {'now': False}

    def on_signal(signum: int, frame: object) -> None:
        stop['now'] = True

    signal.signal(signal.SIGTERM, on_signal)
    # a shell's background job starts with SIGINT ignored, and Python then never raises
    # KeyboardInterrupt: Ctrl-C (or kill -INT) must stop the graph however bringup was started
    signal.signal(signal.SIGINT, signal.default_int_handler)
    graph.start()
    print(f'started {", ".join(nodes)} (parameters: {params}); Ctrl-C stops them', flush=True)
    status = 0
    try:
        while not stop['now']:
            dead = graph.dead()
            if dead:
                print(f'node(s) exited: {dead}; stopping the rest', file=sys.stderr)
                status = 1
                break
            time.sleep(0.2)
    except KeyboardInterrupt:
        pass
    finally:
        codes = graph.stop()
        print(f'stopped: {codes}', flush=True)
    return status

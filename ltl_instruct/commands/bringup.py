"""``ltl-instruct bringup``: start every node as its own process (no ``ros2`` CLI needed).

Each node runs as ``python -m ltl_instruct.nodes.<name> --ros-args --params-file FILE``
with the parameters of ``config/ltl_instruct.yaml`` (or ``--params FILE``). Ctrl-C (or
SIGTERM) stops them cleanly: SIGINT first, then SIGTERM, then SIGKILL after a grace
period. :class:`NodeGraph` is the same machinery for the demo and the tests.

With a :class:`RestartPolicy` (``bringup`` has one unless ``--no-respawn``), a node that
dies is started again after a back-off that doubles with each quick crash in a row; a
node that crashes too often, or exits 2 (its parameters are invalid: it would only fail
again), is not, and ``bringup`` then stops the rest.

``--namespace r1`` starts every node in ``/r1`` (``-r __ns:=/r1``): all its topics are
relative, so several robots share one graph without hearing each other; the parameters
file's ``/**/<node>`` keys apply in any namespace. ``--frame-prefix r1/`` prefixes every
frame id, ``--use-sim-time`` runs the nodes on the simulator's ``/clock``.
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Callable, Mapping, Optional, Sequence

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.scene import Scene

PIPELINE_NODES = ('ltl_translator', 'referent_grounder', 'task_progression', 'fmt_planner')
SIM_NODE = 'sim_world'
ALL_NODES = PIPELINE_NODES + (SIM_NODE,)
PACKAGE = 'ltl_instruct'
PARAMS_FILE_NAME = 'ltl_instruct.yaml'
INVALID_PARAMETERS = 2   # the exit status of a node whose parameters are invalid (nodes.common.run_node)


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


LOG_LEVELS = ('debug', 'info', 'warn', 'error', 'fatal')


def normalize_namespace(namespace: str) -> str:
    """Return ``namespace`` as an absolute ROS namespace (``r1`` -> ``/r1``; ``''`` -> ``''``).

    Raises
    ------
    InvalidInputError
        Unless made of ROS name tokens (letters, digits, ``_``; no leading digit) joined by ``/``.
    """
    text = namespace.strip().strip('/')
    if not text:
        return ''
    if not all(re.fullmatch(r'[A-Za-z_][A-Za-z0-9_]*', part) for part in text.split('/')):
        raise InvalidInputError(f'namespace {namespace!r} is not a valid ROS namespace')
    return '/' + text


def file_parameters(params: Mapping[str, object], node: str) -> dict[str, object]:
    """Return what a parameters file (loaded YAML) gives node ``node`` in any namespace.

    ``/**`` applies to every node, then ``/**/<node>`` (and a bare ``<node>``, for a node in
    the root namespace) over it, as rcl merges them.
    """
    out: dict[str, object] = {}
    for key in ('/**', node, f'/**/{node}'):
        section = params.get(key)
        if isinstance(section, dict):
            out.update(section.get('ros__parameters') or {})
    return out


def node_command(name: str, params_file: Optional[Path] = None,
                 overrides: Optional[Mapping[str, object]] = None, namespace: str = '',
                 log_level: str = '') -> list[str]:
    """Return the command line that starts node ``name`` with a parameters file and ``-p`` overrides."""
    cmd = [sys.executable, '-m', f'{PACKAGE}.nodes.{name}', '--ros-args']
    if namespace:
        cmd += ['-r', f'__ns:={normalize_namespace(namespace)}']
    if log_level:
        cmd += ['--log-level', log_level]
    if params_file is not None:
        cmd += ['--params-file', str(params_file)]
    for key, value in (overrides or {}).items():
        text = str(value).lower() if isinstance(value, bool) else str(value)
        cmd += ['-p', f'{key}:={text or repr("")}']   # an empty string must be written as ''
    return cmd


@dataclass(frozen=True)
class RestartPolicy:
    """When a node that died is started again.

    A crash within ``stable_after`` seconds of the node's start is a quick one; the
    back-off doubles with each quick crash in a row, from ``first_delay`` up to
    ``max_delay`` [s], and after ``max_quick_restarts`` of them the node is given up.
    """

    first_delay: float = 0.5
    max_delay: float = 10.0
    max_quick_restarts: int = 5
    stable_after: float = 30.0

    def delay(self, quick_crashes: int) -> float:
        """Return the back-off [s] before a restart after ``quick_crashes`` quick crashes in a row."""
        return min(self.first_delay * 2.0 ** max(quick_crashes - 1, 0), self.max_delay)


@dataclass
class Restart:
    """One restart of a node: why, when, after how long a back-off."""

    node: str
    exit_status: int
    ran_s: float          # how long the dead process had run [s]
    delay_s: float        # back-off before the new process [s]
    count: int            # restarts of this node so far, this one included
    due: float = 0.0      # time.monotonic() when the back-off is over
    at: float = 0.0       # time.monotonic() when the new process started


def _say(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


class NodeGraph:
    """A set of node processes, started together and stopped together.

    Parameters
    ----------
    nodes: names of the nodes to start.
    params_file: the ROS parameters file every node reads.
    overrides: per node name, parameters to set on its command line.
    env: extra environment variables (``ROS_DOMAIN_ID``...).
    log_dir: where each node's output goes (``<log_dir>/<node>.log``); None: inherit.
    restart: restart a node that dies (None: a dead node stays dead).
    say: where restarts are reported (default: stderr).
    state_dir: where a node keeps what it must remember across its restart (``task_progression``'s
        statuses); None: a temporary folder for this run when nodes are restarted, else none.
    namespace: the namespace of every node (``''``: the root); logs are then ``<ns>.<node>.log``.
    log_level: the nodes' log level (``''``: their default).
    prefix: a command every node is started under (``ip netns exec NAME``: a network namespace).
    """

    def __init__(self, nodes: Sequence[str], params_file: Optional[Path] = None,
                 overrides: Optional[Mapping[str, Mapping[str, object]]] = None,
                 env: Optional[Mapping[str, str]] = None, log_dir: Optional[Path] = None,
                 restart: Optional[RestartPolicy] = None, say: Callable[[str], None] = _say,
                 state_dir: Optional[Path] = None, namespace: str = '', log_level: str = '',
                 prefix: Sequence[str] = ()) -> None:
        unknown = [n for n in nodes if n not in ALL_NODES]
        if unknown:
            raise InvalidInputError(f'unknown node(s) {unknown} (known: {", ".join(ALL_NODES)})')
        self.nodes = tuple(nodes)
        self.namespace = normalize_namespace(namespace)
        if log_level and log_level not in LOG_LEVELS:
            raise InvalidInputError(f'log level {log_level!r} is not one of {", ".join(LOG_LEVELS)}')
        self.log_level = log_level
        self.prefix = list(prefix)
        self.params_file = params_file
        self.overrides = {k: dict(v) for k, v in (overrides or {}).items()}
        self.env = dict(os.environ)
        repo_root = str(Path(__file__).resolve().parent.parent.parent)
        self.env['PYTHONPATH'] = os.pathsep.join(
            p for p in (repo_root, self.env.get('PYTHONPATH', '')) if p)
        self.env['PYTHONUNBUFFERED'] = '1'
        self.env.update(env or {})
        self.log_dir = log_dir
        self.restart = restart
        self.say = say
        self.state_dir = state_dir
        self._own_state_dir = False
        self.processes: dict[str, subprocess.Popen] = {}
        self.restarts: list[Restart] = []
        self._logs: list[IO[bytes]] = []
        self._started: dict[str, float] = {}
        self._quick: dict[str, int] = {}          # quick crashes in a row, per node
        self._due: dict[str, Restart] = {}        # restarts waiting for their back-off
        self._given_up: dict[str, int] = {}
        self._lock = threading.Lock()
        self._stopping = threading.Event()
        self._supervisor: Optional[threading.Thread] = None

    def start(self) -> 'NodeGraph':
        """Start every node (each in its own process group), and the supervisor if nodes are restarted."""
        if self.log_dir is not None:
            self.log_dir.mkdir(parents=True, exist_ok=True)
        if self.state_dir is None and self.restart is not None:
            self.state_dir, self._own_state_dir = Path(tempfile.mkdtemp(prefix='ltl_instruct-state-')), True
        if self.state_dir is not None:
            self.overrides.setdefault('task_progression', {}).setdefault('state_dir', str(self.state_dir))
        with self._lock:
            for name in self.nodes:
                self._spawn(name, 'wb')
        if self.restart is not None:
            self._supervisor = threading.Thread(target=self._supervise, name='respawn', daemon=True)
            self._supervisor.start()
        return self

    def _spawn(self, name: str, mode: str) -> None:
        """Start node ``name`` (lock held); a restarted one appends to its log."""
        out: Optional[IO[bytes]] = None
        if self.log_dir is not None:
            out = open(self.log_path(name), mode)
            self._logs.append(out)
        self.processes[name] = subprocess.Popen(
            self.prefix + node_command(name, self.params_file, self.overrides.get(name), self.namespace,
                                       self.log_level),
            env=self.env,
            stdout=out, stderr=subprocess.STDOUT if out is not None else None,
            start_new_session=True)
        self._started[name] = time.monotonic()

    def log_path(self, name: str) -> Path:
        """Return where node ``name``'s output goes (under ``log_dir``)."""
        assert self.log_dir is not None
        prefix = self.namespace.strip('/').replace('/', '.')
        return self.log_dir / (f'{prefix}.{name}.log' if prefix else f'{name}.log')

    def dead(self) -> dict[str, int]:
        """Nodes that have exited (and are not running again yet), with their exit status."""
        with self._lock:
            return {n: p.returncode for n, p in self.processes.items() if p.poll() is not None}

    def given_up(self) -> dict[str, int]:
        """Nodes that died and will not be restarted, with their exit status (without a policy: all dead)."""
        if self.restart is None:
            return self.dead()
        with self._lock:
            return dict(self._given_up)

    def _supervise(self) -> None:
        while not self._stopping.wait(0.1):
            with self._lock:
                if not self._stopping.is_set():
                    self._check()

    def _check(self) -> None:
        """Schedule a restart for each node that died, start those whose back-off is over (lock held)."""
        now = time.monotonic()
        assert self.restart is not None
        for name, proc in self.processes.items():
            code = proc.poll()
            if code is None or name in self._due or name in self._given_up:
                continue
            ran = now - self._started[name]
            self._quick[name] = self._quick.get(name, 0) + 1 if ran < self.restart.stable_after else 1
            if code == INVALID_PARAMETERS or self._quick[name] > self.restart.max_quick_restarts:
                why = 'its parameters are invalid' if code == INVALID_PARAMETERS else \
                    f'{self._quick[name] - 1} quick restarts in a row'
                self.say(f'{name} exited with status {code}; not restarted ({why})')
                self._given_up[name] = code
                continue
            delay = self.restart.delay(self._quick[name])
            count = sum(r.node == name for r in self.restarts) + 1
            self._due[name] = Restart(name, code, ran, delay, count, due=now + delay)
            self.say(f'{name} exited with status {code} after {ran:.1f} s; restart {count} in {delay:.1f} s')
        for name, r in list(self._due.items()):
            if now >= r.due:
                del self._due[name]
                self._spawn(name, 'ab')
                r.at = time.monotonic()
                self.restarts.append(r)
                self.say(f'{name} restarted (pid {self.processes[name].pid}, restart {r.count})')

    def stop(self, grace: float = 5.0) -> dict[str, Optional[int]]:
        """Stop every node: SIGINT, then SIGTERM, then SIGKILL; return the exit statuses."""
        self._stopping.set()
        if self._supervisor is not None:
            self._supervisor.join(timeout=5.0)
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
            alive = [p for p in self.processes.values() if p.poll() is None]
            if not alive:
                break
            for p in alive:
                try:
                    if sig != signal.SIGINT:   # still there: its log gets every thread's stack first
                        os.killpg(p.pid, signal.SIGUSR1)
                        time.sleep(0.1)
                    os.killpg(p.pid, sig)
                except ProcessLookupError:
                    pass
            deadline = time.monotonic() + (grace if sig != signal.SIGKILL else 2.0)
            while time.monotonic() < deadline and any(p.poll() is None for p in alive):
                time.sleep(0.05)
        for f in self._logs:
            f.close()
        self._logs.clear()
        if self._own_state_dir and self.state_dir is not None:
            shutil.rmtree(self.state_dir, ignore_errors=True)
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


def robot_overrides(frame_prefix: str = '', use_sim_time: bool = False) -> dict[str, dict[str, object]]:
    """Return the per-node parameters of one robot on a shared graph: its frames and its clock.

    With ``use_sim_time`` the simulator publishes ``/clock`` and every other node reads it.
    """
    out: dict[str, dict[str, object]] = {name: {} for name in ALL_NODES}
    for name in ALL_NODES:
        if frame_prefix:
            out[name]['frame_prefix'] = frame_prefix
        if use_sim_time:
            out[name].update({'publish_clock': True} if name == SIM_NODE else {'use_sim_time': True})
    return {name: values for name, values in out.items() if values}


def merge_overrides(*layers: Mapping[str, Mapping[str, object]]) -> dict[str, dict[str, object]]:
    """Return per-node parameters with each layer's values over the earlier ones'."""
    out: dict[str, dict[str, object]] = {}
    for layer in layers:
        for name, values in layer.items():
            out.setdefault(name, {}).update(values)
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
    parser.add_argument('--respawn', action=argparse.BooleanOptionalAction, default=True,
                        help='restart a node that dies, after a back-off (default); --no-respawn stops '
                             'every node when one exits')
    parser.add_argument('--state-dir', type=Path, default=None,
                        help='folder where a restarted node finds what it must remember (default: a '
                             'temporary one for this run, with --respawn)')
    parser.add_argument('--namespace', default='',
                        help='start every node in this namespace (one robot of several on a graph)')
    parser.add_argument('--frame-prefix', default='',
                        help='prefix of every frame id (e.g. r1/ for r1/map, r1/odom, r1/base_link)')
    parser.add_argument('--use-sim-time', action='store_true',
                        help='the simulator publishes /clock and the other nodes run on it')
    parser.add_argument('--log-level', default=None, choices=LOG_LEVELS,
                        help='log level of every node (default: info)')
    parser.add_argument('--max-restarts', type=int, default=RestartPolicy.max_quick_restarts,
                        help='quick crashes in a row (within 30 s of a start) before a node is given up '
                             '(default %(default)s)')


def run(args: argparse.Namespace) -> int:
    """Start the nodes and wait until Ctrl-C, or until one of them exits."""
    params = args.params or default_params_file()
    if not Path(params).is_file():
        raise InvalidInputError(f'parameters file {params} does not exist')
    nodes = list(PIPELINE_NODES) + ([SIM_NODE] if args.sim else [])
    if args.nodes:
        nodes = [n.strip() for n in args.nodes.split(',') if n.strip()]
    if args.frame_prefix:   # checked here, not by five nodes that would each exit 2
        from ltl_instruct.nodes.common import COMMON_PARAMS
        next(p for p in COMMON_PARAMS if p.name == 'frame_prefix').check(args.frame_prefix)
    overrides = merge_overrides(scene_overrides(args.scene) if args.scene else {},
                                robot_overrides(args.frame_prefix, args.use_sim_time))
    if args.max_restarts < 0:
        raise InvalidInputError(f'--max-restarts must be 0 or more, not {args.max_restarts}')
    restart = RestartPolicy(max_quick_restarts=args.max_restarts) if args.respawn else None
    graph = NodeGraph(nodes, Path(params), overrides, log_dir=args.log_dir, restart=restart,
                      state_dir=args.state_dir, namespace=args.namespace, log_level=args.log_level or '')
    stop = {'now': False}

    def on_signal(signum: int, frame: object) -> None:
        stop['now'] = True

    signal.signal(signal.SIGTERM, on_signal)
    # a shell's background job starts with SIGINT ignored, and Python then never raises
    # KeyboardInterrupt: Ctrl-C (or kill -INT) must stop the graph however bringup was started
    signal.signal(signal.SIGINT, signal.default_int_handler)
    graph.start()
    respawn = 'restarted when they die' if restart else 'not restarted (--no-respawn)'
    where = f' in {graph.namespace}' if graph.namespace else ''
    print(f'started {", ".join(nodes)}{where} (parameters: {params}; {respawn}); Ctrl-C stops them',
          flush=True)
    status = 0
    try:
        while not stop['now']:
            gone = graph.given_up()
            if gone:
                print(f'node(s) exited: {gone}; stopping the rest', file=sys.stderr)
                status = 1
                break
            time.sleep(0.2)
    except KeyboardInterrupt:
        pass
    finally:
        codes = graph.stop()
        print(f'stopped: {codes}', flush=True)
    return status

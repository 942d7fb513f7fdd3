"""Issue 21's long fuzzing run: hypothesis-generated inputs against every entry point a user reaches.

Run: ``.venv/bin/python -m bench.fuzz [--minutes 8] [--examples 700]`` (``make fuzz``).

Targets: formula text (``ltl-instruct formula``), English (the translator node's backend),
scene files, and every message type a node subscribes to, handed to the real node callbacks
in this process (the five nodes are built here on a private ROS domain; nothing is sent over
DDS): instruction, task_spec, referent_map, cancel, odometry, plan_segment, segment status,
skill result and request, plan, map, map_cloud, camera frames (info, labels, depth, the odometry of
their stamp), label classes, plan_request, verification reply, task_status.

An input passes when its target returns or raises a typed error (``LtlInstructError``), within
10 s and 1 GiB more memory. Anything else is counted (tracebacks, hangs), printed, and written
to ``--out`` (default ``test/regressions/fuzz_found.jsonl``) as a case for
``test/test_fuzz_regressions.py``. Target: 0 tracebacks and 0 hangs on 5,000 inputs or more.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import resource
import signal
import sys
import tempfile
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from hypothesis import HealthCheck, given, settings, strategies as st

HANG_S = 10                    # CPU seconds
HANG_WALL_S = 60
HANG_KB = 1024 * 1024          # 1 GiB, in ru_maxrss units (KiB)
REGRESSIONS = Path(__file__).resolve().parent.parent / 'test' / 'regressions' / 'fuzz_found.jsonl'

# ---------------------------------------------------------------------------- strategies
FLOATS = st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                   st.sampled_from([0.0, 1.0, -1.0, 5.0, 1e9]))
INTS = st.one_of(st.integers(-2 ** 70, 2 ** 70), st.integers(-3, 300))
JSON_SCALARS = st.one_of(st.none(), st.booleans(), INTS, FLOATS, st.text(max_size=30),
                         st.sampled_from(['F near[sofa]', 'near[', 'pick', 'planning', 'execution',
                                          'x' * 3000]))
JSON_VALUES = st.recursive(JSON_SCALARS,
                           lambda c: st.one_of(st.lists(c, max_size=4),
                                               st.dictionaries(st.text(max_size=8), c, max_size=4)),
                           max_leaves=12)
FORMULA_ATOMS = st.sampled_from(['near[a]', 'near[b]', 'pick[c]', 'release[c, d]', 'near[e::isabove(f)]',
                                 'near[sofa]', 'near[g::isbetween(h, i)]', 'true', 'false', 'near[]',
                                 'near[a'])
FORMULA_OPS = st.sampled_from(['!', 'F ', 'G ', 'X ', '~', '(', ')', ' & ', ' | ', ' -> ', ' <-> ', ' U ',
                               ' R ', ' W ', ' '])
FORMULAS = st.one_of(
    st.lists(st.one_of(FORMULA_ATOMS, FORMULA_OPS), max_size=60).map(''.join),
    st.builds(lambda op, n, k: 'F (' + op.join(f'near[a{i % k}]' for i in range(n)) + ')',
              st.sampled_from([' & ', ' | ', ' <-> ', ' U ', ' -> ']), st.integers(1, 24),
              st.integers(1, 30)),
    st.text(max_size=80))
WORDS = st.sampled_from(['go', 'to', 'the', 'kitchen', 'then', 'never', 'avoid', 'after', 'before', 'twice',
                         'times', 'visit', 'bring', 'cup', 'table', 'sofa', 'behind', 'pick', 'up', 'put',
                         'it', 'no', 'wait', 'I', 'meant', 'only', 'once', 'and', 'or', ',', '.', 'first',
                         'second', 'last', 'until', 'while', 'carrying', 'each', 'room', 'at', 'least',
                         'most', 'exactly', '3', '-2', '1e9', '\u00e9', '\U0001f600', "don't", 'forget',
                         'everything'])
ENGLISH = st.one_of(st.lists(st.one_of(WORDS, st.text(max_size=6)), max_size=40).map(' '.join),
                    st.text(max_size=120))
SCENE_NUMBER = st.one_of(INTS, FLOATS, st.booleans(), st.none(), st.text(max_size=4))
SCENE_VEC = st.one_of(st.lists(SCENE_NUMBER, max_size=4), SCENE_NUMBER)
SCENE_ROBOT = st.fixed_dictionaries({}, optional={'kind': st.sampled_from(['ground', 'drone', 'boat', 3]),
                                                  'start': SCENE_VEC, 'radius': SCENE_NUMBER})
SCENE_OBJECT = st.fixed_dictionaries({'label': JSON_SCALARS, 'center': SCENE_VEC},
                                     optional={'on': JSON_SCALARS, 'size': SCENE_VEC,
                                               'passable': JSON_SCALARS})
SCENES = st.fixed_dictionaries({}, optional={
    'name': JSON_SCALARS,
    'bounds': st.one_of(st.fixed_dictionaries({'min': SCENE_VEC, 'max': SCENE_VEC}), SCENE_NUMBER),
    'robot': st.one_of(SCENE_ROBOT, SCENE_NUMBER),
    'obstacles': st.lists(st.fixed_dictionaries({'center': SCENE_VEC, 'size': SCENE_VEC}), max_size=4),
    'objects': st.lists(SCENE_OBJECT, max_size=4),
    'altitude': st.one_of(st.fixed_dictionaries({'min': SCENE_NUMBER, 'max': SCENE_NUMBER}), SCENE_NUMBER)})

SCHEMAS = {'task_spec': 'task_spec', 'referent_map': 'referent_map', 'skill/result': 'skill_result',
           'skill/request': 'skill_request', 'fmt_planner/status': 'segment_status',
           'plan_request': 'plan_request',
           'verification/reply': 'verification_reply', 'task_status': 'task_status',
           'camera/labels/classes': 'label_classes', 'instruction': 'instruction', 'cancel': 'cancel'}
FIELDS = ['ok', 'formula', 'error', 'revision', 'referent_map', 'skill', 'args', 'path_index', 'plan_stamp',
          'targets', 'request_id', 'stamp', 'request', 'result', 'accept', 'status', 'phase', 'terminal',
          'automaton_state', 'classes', 'text', 'timing', 'resume', 'id_source', 'instruction']


@st.composite
def payloads(draw: Any, topic: str) -> str:
    """A JSON payload for ``topic``: its schema (mostly), an id, and fields of any type; or broken text."""
    kind = draw(st.integers(0, 9))
    if kind == 0:
        return draw(st.text(max_size=200))
    data: dict[str, Any] = {}
    if draw(st.booleans()) or kind > 3:
        data['schema'] = draw(st.sampled_from([f'ltl_instruct/{SCHEMAS[topic]}', 'x'])) if kind > 2 else 5
        data['version'] = draw(st.sampled_from([1, 1, 1, 2, None, '1']))
    data['id'] = draw(st.one_of(st.sampled_from(['fz-1', 'fz-2']), JSON_SCALARS))
    for name in draw(st.lists(st.sampled_from(FIELDS), max_size=6, unique=True)):
        data[name] = draw(JSON_VALUES)
    if draw(st.integers(0, 4)) == 0:   # a well-formed inner referent map or request, one field wrong
        instance = {'id': 'a', 'center': draw(JSON_VALUES)}
        grounding = {'descriptor': 'a', 'outcome': 'RESOLVED', 'instances': [instance]}
        data['referent_map'] = {'groundings': {'near[a]': grounding}}
        data['request'] = {'dims': 2, 'start': [1.0, 1.0], 'regions': draw(JSON_VALUES),
                           'goal': draw(JSON_VALUES), 'allowed': draw(JSON_VALUES)}
    text = json.dumps(data, allow_nan=True)
    if kind == 1:
        text = text[:draw(st.integers(0, len(text)))]
    return text


def _set_floats(draw: Any, obj: Any, names: str) -> None:
    for name in names:
        setattr(obj, name, draw(FLOATS))


@st.composite
def odometry(draw: Any) -> Any:
    """Odometry with any float in its pose."""
    from nav_msgs.msg import Odometry
    msg = Odometry()
    _set_floats(draw, msg.pose.pose.position, 'xyz')
    _set_floats(draw, msg.pose.pose.orientation, 'xyzw')
    return msg


@st.composite
def paths(draw: Any) -> Any:
    """A Path of any floats and length."""
    from geometry_msgs.msg import PoseStamped
    from nav_msgs.msg import Path
    msg = Path()
    msg.header.stamp.sec = draw(st.integers(0, 2 ** 31 - 1))
    for _ in range(draw(st.integers(0, 30))):
        ps = PoseStamped()
        _set_floats(draw, ps.pose.position, 'xyz')
        msg.poses.append(ps)
    return msg


@st.composite
def grids(draw: Any) -> Any:
    """An OccupancyGrid with any size, resolution, origin and data."""
    from nav_msgs.msg import OccupancyGrid
    msg = OccupancyGrid()
    msg.info.width, msg.info.height = draw(st.integers(0, 400)), draw(st.integers(0, 400))
    msg.info.resolution = draw(st.floats(allow_nan=True, allow_infinity=True, width=32))
    _set_floats(draw, msg.info.origin.position, 'xy')
    msg.info.origin.orientation.w = draw(st.sampled_from([1.0, 0.0, float('nan')]))
    n = msg.info.width * msg.info.height + draw(st.sampled_from([0, 0, 0, 1, -1]))
    cell = draw(st.sampled_from([0, 100, -1, 50, 127, -128]))
    msg.data = [cell] * max(0, min(n, 200_000)) if n > 0 else []
    return msg


@st.composite
def clouds(draw: Any) -> Any:
    """A PointCloud2 with any layout and bytes."""
    from sensor_msgs.msg import PointCloud2, PointField
    msg = PointCloud2()
    msg.height, msg.width = draw(st.integers(0, 3)), draw(st.integers(0, 300))
    msg.fields = [PointField(name=draw(st.sampled_from(['x', 'y', 'z', 'q', ''])),
                             offset=draw(st.integers(0, 40)), count=draw(st.integers(0, 3)),
                             datatype=draw(st.sampled_from([7, 7, 7, 8, 2, 0, 99])))
                  for _ in range(draw(st.integers(0, 4)))]
    msg.point_step = draw(st.sampled_from([12, 16, 0, 1, 4]))
    msg.row_step = msg.point_step * msg.width
    msg.is_bigendian = draw(st.booleans())
    msg.data = draw(st.binary(max_size=4000))
    return msg


@st.composite
def camera_frames(draw: Any) -> list[tuple[str, Any]]:
    """Camera info, a label and a depth image and odometry, all of one stamp, any of them malformed."""
    from sensor_msgs.msg import CameraInfo, Image
    w, h = draw(st.integers(0, 24)), draw(st.integers(0, 18))
    info = CameraInfo(width=draw(st.sampled_from([w, w, 0, 10_000])), height=h)
    info.k = [draw(FLOATS) for _ in range(9)]
    odom = draw(odometry())   # the pose of the frame: the odometry of its stamp
    odom.header.frame_id = 'map'
    odom.header.stamp.sec = draw(st.integers(0, 2))
    out: list[tuple[str, Any]] = [('odom', odom), ('camera/color/camera_info', info)]
    stamp = out[0][1].header.stamp
    for topic, encoding in (('camera/labels/image_raw', '32SC1'), ('camera/depth/image_raw', '32FC1')):
        img = Image(width=w, height=h,
                    encoding=draw(st.sampled_from([encoding, encoding, 'rgb8', 'x', '16UC1'])))
        img.header.stamp = stamp
        img.step = draw(st.sampled_from([w * 4, w * 4, 0, w * 4 + 3]))
        img.is_bigendian = draw(st.sampled_from([0, 0, 1]))
        size = img.step * h + draw(st.sampled_from([0, 0, 0, 1, -1]))
        if encoding == '32FC1' and draw(st.booleans()):
            import numpy as np
            values = np.full(max(0, size) // 4, draw(FLOATS), dtype=np.float32).tobytes()
            img.data = values + bytes(max(0, size) - len(values))
        else:
            img.data = draw(st.binary(min_size=max(0, size), max_size=max(0, size)))
        out.append((topic, img))
    return out


# ---------------------------------------------------------------------------- the node callbacks
class Nodes:
    """The five nodes, built in this process, and the callback of each subscribed topic."""

    def __init__(self, backend: str = 'combined') -> None:
        import rclpy

        from ltl_instruct.nodes.fmt_planner import FmtPlannerNode
        from ltl_instruct.nodes.ltl_translator import LtlTranslatorNode
        from ltl_instruct.nodes.referent_grounder import ReferentGrounderNode
        from ltl_instruct.nodes.sim_world import SimWorldNode
        from ltl_instruct.nodes.task_progression import TaskProgressionNode
        rclpy.init(args=['--ros-args', '-p', f'backend:={backend}', '-p', 'camera_min_interval:=0.0',
                         '-p', 'scene:=apartment',
                         '-p', 'camera_rate_hz:=0.0', '-p', 'odom_timeout:=0.1', '-p', 'map_timeout:=0.1'])
        self.translator, self.grounder = LtlTranslatorNode(), ReferentGrounderNode()
        self.progression, self.planner, self.sim = TaskProgressionNode(), FmtPlannerNode(), SimWorldNode()
        self.internal_errors: list[str] = []
        self.statuses: list[tuple[str, dict[str, Any]]] = []   # every task_status task_progression sent
        self._watch(self.progression, '_send_status')
        deadline = time.monotonic() + 60
        while self.translator._translator is None and self.translator._translator_error is None and \
                time.monotonic() < deadline:   # the backend loads in the worker thread
            time.sleep(0.1)

    def _watch(self, node: Any, method: str) -> None:
        """Record each INTERNAL_ERROR status a node publishes (a bug its worker caught)."""
        original = getattr(node, method)

        def send(iid: str, body: dict[str, Any]) -> None:
            self.statuses.append((iid, body))
            if (body.get('error') or {}).get('code') == 'INTERNAL_ERROR':
                self.internal_errors.append(body['error'].get('message', ''))
            original(iid, body)
        setattr(node, method, send)

    def string_callbacks(self) -> dict[str, list[Callable[[Any], Any]]]:
        """Topic -> the callbacks that read it (String payloads)."""
        t, g, p, s = self.translator, self.grounder, self.progression, self.sim
        return {'instruction': [self.serve_instruction], 'task_spec': [g.on_task_spec, p.on_task_spec],
                'referent_map': [p.on_referent_map], 'cancel': [p.on_cancel],
                'skill/result': [p.on_skill_result],
                'skill/request': [s.on_skill_request], 'fmt_planner/status': [p.on_segment_status],
                'plan_request': [self.serve_plan_request], 'verification/reply': [t.on_reply],
                'task_status': [t.on_status], 'camera/labels/classes': [g.on_classes]}

    def serve_instruction(self, msg: Any) -> None:
        """Take and translate an instruction message in this thread, as the translator's worker does."""
        from ltl_instruct.nodes.ltl_translator import _Job
        fallback = f'fz-{random.getrandbits(32)}'
        self.translator._serve(_Job(self.translator._id_of(fallback, msg.data), fallback, msg.data))

    def serve_plan_request(self, msg: Any) -> None:
        """Take a plan request and plan it in this thread, as the planner's worker does."""
        from ltl_instruct.core.errors import LtlInstructError
        self.planner.on_plan_request(msg)
        while not self.planner._jobs.empty():
            text = self.planner._jobs.get()
            try:
                self.planner._serve(text)
            except LtlInstructError:
                pass

    def typed_callbacks(self) -> dict[str, tuple[str, list[Callable[[Any], Any]]]]:
        """Topic -> (message type, the callbacks that read it) for the typed topics."""
        p, g, f, s = self.progression, self.grounder, self.planner, self.sim
        return {'odom': ('nav_msgs.msg.Odometry', [p.on_odom, g.on_odom]),
                'plan_segment': ('nav_msgs.msg.Path', [p.on_plan_segment]),
                'plan': ('nav_msgs.msg.Path', [s.on_plan]),
                'map': ('nav_msgs.msg.OccupancyGrid', [p.on_map, f.on_map]),
                'map_cloud': ('sensor_msgs.msg.PointCloud2', [p.on_map_cloud, f.on_map_cloud]),
                'camera/color/camera_info': ('sensor_msgs.msg.CameraInfo', [g.on_info]),
                'camera/labels/image_raw': ('sensor_msgs.msg.Image', [g.on_labels]),
                'camera/depth/image_raw': ('sensor_msgs.msg.Image', [g.on_depth])}

    def run(self, target: str, value: Any) -> None:
        """Hand one input to the callbacks of ``target``: a topic, or ``camera frame`` (topic, msg pairs)."""
        import importlib

        from std_msgs.msg import String
        if target == 'camera frame':
            for topic, msg in value:
                self.run(topic, msg)
            return
        strings, typed = self.string_callbacks(), self.typed_callbacks()
        if target in strings:
            for cb in strings[target]:
                cb(String(data=value))
            return
        type_name, callbacks = typed[target]
        if isinstance(value, dict):
            module, name = type_name.rsplit('.', 1)
            value = build(getattr(importlib.import_module(module), name), value)
        for cb in callbacks:
            cb(value)

    def close(self) -> None:
        """Destroy the nodes and shut the context down."""
        import rclpy
        for node in (self.translator, self.grounder, self.progression, self.planner, self.sim):
            close = getattr(node, 'close', None)
            if callable(close):
                close()
            node.destroy_node()
        rclpy.try_shutdown()


def run_case(nodes: Nodes, target: str, value: Any) -> None:
    """Run one stored case (a line of ``test/regressions/fuzz_found.jsonl``) against its target."""
    from ltl_instruct.commands.formula import report
    from ltl_instruct.core.language import make_translator
    from ltl_instruct.core.world.scene import load_scene
    if target == 'formula':
        report(value)
    elif target == 'english':
        make_translator('offline').translate(value)
    elif target == 'scene':
        import yaml
        path = Path(tempfile.mkdtemp(prefix='fuzz_scene_')) / 's.yaml'
        path.write_text(yaml.safe_dump(value, allow_unicode=True))
        load_scene(path)
    else:
        nodes.run(target, value)


# ---------------------------------------------------------------------------- the run
@dataclass
class Tally:
    """Inputs run, and those that broke a target."""

    inputs: dict[str, int] = field(default_factory=dict)
    tracebacks: list[dict[str, Any]] = field(default_factory=list)
    hangs: list[dict[str, Any]] = field(default_factory=list)
    slowest: dict[str, float] = field(default_factory=dict)


class _Hang(Exception):
    pass


def _alarm(signum: int, frame: Any) -> None:
    raise _Hang()


def check(tally: Tally, target: str, run: Callable[[], Any], case: Any) -> None:
    """Run one input: typed errors pass; a traceback, or over 10 s or 1 GiB, is recorded with ``case``.

    The 10 s are CPU time: on this shared 2-core machine, under a load of 80, an English instruction that
    takes 0.7 s of CPU took 10-34 s of wall clock. An input still running after 60 s of wall clock is
    stopped and counted as a hang too.
    """
    from ltl_instruct.core.errors import LtlInstructError
    tally.inputs[target] = tally.inputs.get(target, 0) + 1
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    t0, cpu0 = time.monotonic(), time.process_time()
    signal.setitimer(signal.ITIMER_REAL, HANG_WALL_S, 1.0)   # again each second: a callback may swallow one
    try:
        run()
    except LtlInstructError:
        pass
    except _Hang:
        tally.hangs.append({'target': target, 'input': case, 'why': f'still running after {HANG_WALL_S} s'})
    except Exception:  # noqa: BLE001 - what the run counts
        tally.tracebacks.append({'target': target, 'input': case,
                                 'traceback': traceback.format_exc()[-1500:]})
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
    cpu = time.process_time() - cpu0
    tally.slowest[target] = max(tally.slowest.get(target, 0.0), cpu)
    grown = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - rss0
    if cpu > HANG_S or grown > HANG_KB:
        tally.hangs.append({'target': target, 'input': case,
                            'why': f'{cpu:.1f} s CPU ({time.monotonic() - t0:.1f} s), +{grown // 1024} MiB'})


def _fields(msg: Any) -> Any:
    """A message as plain JSON data (a regression case is stored as this; :func:`build` reads it back)."""
    if hasattr(msg, 'get_fields_and_field_types'):
        return {name: _fields(getattr(msg, name)) for name in msg.get_fields_and_field_types()}
    if isinstance(msg, (bytes, bytearray)) or getattr(msg, 'typecode', None) == 'B':
        return {'hex': bytes(msg).hex()}
    if isinstance(msg, (list, tuple)) or hasattr(msg, 'tolist') or hasattr(msg, 'typecode'):
        return [_fields(v) for v in (msg.tolist() if hasattr(msg, 'tolist') else msg)]
    return msg


def build(cls: Any, data: dict[str, Any]) -> Any:
    """Return a message of type ``cls`` with the fields ``data`` (from :func:`_fields`)."""
    import importlib
    msg = cls()
    types = cls.get_fields_and_field_types()
    for name, value in data.items():
        kind, current = types[name], getattr(msg, name)
        if hasattr(current, 'get_fields_and_field_types'):
            value = build(type(current), value)
        elif kind.startswith('sequence<') and '/' in kind:
            package, type_name = kind[len('sequence<'):-1].split('/')
            element = getattr(importlib.import_module(f'{package}.msg'), type_name)
            value = [build(element, v) for v in value]
        elif isinstance(value, dict) and 'hex' in value:
            value = bytes.fromhex(value['hex'])
        setattr(msg, name, value)
    return msg


def run_all(tally: Tally, examples: int, nodes: Nodes, deadline: float) -> None:
    """Run every target for up to ``examples`` inputs each (fewer once ``deadline`` has passed)."""
    from ltl_instruct.commands.formula import report
    from ltl_instruct.core.language import make_translator
    from ltl_instruct.core.world.scene import load_scene
    import yaml
    fuzz = settings(max_examples=examples, deadline=None, derandomize=False, database=None,
                    suppress_health_check=list(HealthCheck))
    english = make_translator('combined')
    folder = Path(tempfile.mkdtemp(prefix='fuzz_scene_'))

    def target(name: str, strategy: Any, run: Callable[[Any], Any], case: Callable[[Any], Any] = lambda x: x):
        if time.monotonic() >= deadline:
            return
        broken = len(tally.tracebacks) + len(tally.hangs)

        @fuzz
        @given(strategy)
        def go(value: Any) -> None:
            if time.monotonic() < deadline:
                check(tally, name, lambda: run(value), case(value))
        go()
        now_broken = len(tally.tracebacks) + len(tally.hangs) - broken
        print(f'{name}: {tally.inputs.get(name, 0)} inputs, {now_broken} broke it, '
              f'slowest {tally.slowest.get(name, 0.0):.2f} s CPU', flush=True)

    def scene(doc: Any) -> None:
        path = folder / 's.yaml'
        path.write_text(yaml.safe_dump(doc, allow_unicode=True))
        load_scene(path)

    target('formula', FORMULAS, report)
    target('english', ENGLISH, english.translate)
    target('scene', SCENES, scene)
    for topic in nodes.string_callbacks():
        target(topic, payloads(topic), lambda text, t=topic: nodes.run(t, text))
    strategies = {'odom': odometry(), 'plan_segment': paths(), 'plan': paths(), 'map': grids(),
                  'map_cloud': clouds()}
    for topic, strategy in strategies.items():
        target(topic, strategy, lambda msg, t=topic: nodes.run(t, msg), _fields)
    target('camera frame', camera_frames(), lambda parts: nodes.run('camera frame', parts),
           lambda parts: [[t, _fields(m)] for t, m in parts])


def main(argv: list[str]) -> int:
    """Run the fuzzing, print the tally, write what broke; 0 when nothing did."""
    parser = argparse.ArgumentParser(prog='python -m bench.fuzz', description=__doc__.splitlines()[0])
    parser.add_argument('--examples', type=int, default=260,
                        help='inputs per target (default 260, 20 targets)')
    parser.add_argument('--minutes', type=float, default=9.0, help='stop starting targets after this long')
    parser.add_argument('--out', type=Path, default=REGRESSIONS, help='where found cases are appended')
    args = parser.parse_args(argv)
    os.environ['ROS_DOMAIN_ID'] = str(random.randint(120, 229))
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    signal.signal(signal.SIGALRM, _alarm)
    t0 = time.monotonic()
    tally = Tally()
    nodes = Nodes()
    try:
        run_all(tally, args.examples, nodes, t0 + 60 * args.minutes)
    finally:
        nodes.close()
    found = tally.tracebacks + tally.hangs + [{'target': 'worker', 'input': None, 'traceback': m}
                                              for m in nodes.internal_errors]
    for case in found:
        why = case.get('traceback') or case.get('why')
        print(f'--- {case["target"]}: {str(case["input"])[:300]!r}\n{why}')
    if found:
        with open(args.out, 'a', encoding='utf-8') as f:
            for case in tally.tracebacks + tally.hangs:
                f.write(json.dumps({'target': case['target'], 'input': case['input']}, allow_nan=True) + '\n')
    slow = sorted(tally.slowest.items(), key=lambda kv: -kv[1])[:3]
    print(f'inputs: {sum(tally.inputs.values())} over {len(tally.inputs)} targets '
          f'({", ".join(f"{k} {v}" for k, v in tally.inputs.items())})')
    print(f'tracebacks: {len(tally.tracebacks)}, hangs (over {HANG_S} s or 1 GiB): {len(tally.hangs)}, '
          f'internal errors caught by a worker: {len(nodes.internal_errors)}; slowest: '
          + ', '.join(f'{k} {v:.2f} s CPU' for k, v in slow) + f'; {time.monotonic() - t0:.0f} s in all')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

"""Issue 21's graph target: malformed messages on every subscribed topic, with valid instructions among them.

Run: ``.venv/bin/python -m bench.graph_fuzz [--bad 1000] [--good 100] [--seed 0]`` (``make fuzz``).

Starts the five nodes as separate processes (private ROS_DOMAIN_ID, localhost only, respawn
on: a node that died would be restarted, and counted), then sends ``--good`` valid
instructions one after the other, and between them ``--bad`` malformed messages spread over
every topic a node subscribes to: garbage and truncated JSON, JSON that is not an object,
huge strings, wrong types and wrong schema in every field, NaN and infinite poses, paths,
images, camera intrinsics, maps and clouds whose sizes do not match. Target: every valid
instruction gives a result (``planned``, or ``satisfied`` where the robot already is), every
malformed instruction or task spec ends with exactly one terminal status (a typed error),
every malformed cancel and plan request gets its typed refusal, and no node dies or restarts.

The generators are shared with ``test/test_nodes_graph.py``, which runs a scaled-down
version on its own graph.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import signal
import sys
import tempfile
import threading
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional

import numpy as np

# topic -> what a malformed message on it is answered with (data, apart from the code):
# 'terminal': one terminal planning status (the translator or task_progression refuses it, typed);
# 'cancel_rejected': a non-terminal cancel_rejected status; 'segment_status': an ok: false
# fmt_planner/status; None: a logged warning (sensor data, replies, internal results)
ANSWERS: dict[str, Optional[str]] = {
    'instruction': 'terminal', 'task_spec': 'terminal', 'cancel': 'cancel_rejected',
    'plan_request': 'segment_status', 'verification/reply': None, 'task_status': None,
    'referent_map': None, 'skill/result': None, 'skill/request': None, 'fmt_planner/status': None,
    'plan_segment': None, 'plan': None, 'odom': None, 'map': None, 'map_cloud': None,
    'camera/color/camera_info': None, 'camera/labels/image_raw': None, 'camera/depth/image_raw': None,
    'camera/labels/classes': None,
}
# how often each topic is drawn (the instruction-like ones most: they are what users send)
WEIGHTS: dict[str, int] = {
    'instruction': 30, 'task_spec': 12, 'cancel': 6, 'plan_request': 6, 'verification/reply': 3,
    'task_status': 3, 'referent_map': 4, 'skill/result': 3, 'skill/request': 3, 'fmt_planner/status': 2,
    'plan_segment': 3, 'plan': 2, 'odom': 6, 'map': 1, 'map_cloud': 2, 'camera/color/camera_info': 2,
    'camera/labels/image_raw': 2, 'camera/depth/image_raw': 3, 'camera/labels/classes': 2,
}
TYPES: dict[str, str] = dict(
    {t: 'std_msgs.msg.String' for t, a in ANSWERS.items()},
    **{'plan_segment': 'nav_msgs.msg.Path', 'plan': 'nav_msgs.msg.Path', 'odom': 'nav_msgs.msg.Odometry',
       'map': 'nav_msgs.msg.OccupancyGrid', 'map_cloud': 'sensor_msgs.msg.PointCloud2',
       'camera/color/camera_info': 'sensor_msgs.msg.CameraInfo',
       'camera/labels/image_raw': 'sensor_msgs.msg.Image',
       'camera/depth/image_raw': 'sensor_msgs.msg.Image'})
GOOD = (
    'F near[fridge]', 'Go to the bookshelf and then the bed.',
    'F (near[armchair] & F near[plant]) & G !near[tv]',
    'Go to the printer, then the desk.', 'F near[whiteboard]', 'Go to the stove, then the plant.',
    'F (near[sofa::isbehind(pillar)] & F near[computer]) & G !near[door]', 'Go to the wardrobe.',
    'F near[lamp] & G !near[front_door]', 'Visit the armchair, then the kitchen sink, but avoid the tv.',
)
SCALARS: tuple[Any, ...] = (None, True, False, 0, -1, 7, 2 ** 64, 1e308, float('nan'), float('inf'),
                            -float('inf'), '', ' ', 'x' * 3000, [], [1, 'a'], {}, {'a': {'b': []}},
                            '\u00e9\u4e2d\U0001f600', '\x01\x7f')
GARBAGE_CHARS = '{}[]":,\\\x01\x02\x1b\x7f ~`|^\u00e9\u00df\u4e2d\u6587\u0416\U0001f600\U0001f916\u200b\ufeff'


def _json(value: Any) -> str:
    return json.dumps(value, allow_nan=True)


def _garbage(rng: random.Random, n: int) -> str:
    return ''.join(rng.choice(GARBAGE_CHARS) for _ in range(n))


def _huge(rng: random.Random) -> str:
    return rng.choice(['go to the sofa ', 'a', '\u4e2d', '{"a": ']) * rng.choice([700, 5000, 80_000])


def _mutate(rng: random.Random, template: dict[str, Any], breaking: list[tuple[str, list[Any]]]) -> str:
    """Return ``template`` with one breaking change and a few random wrong types in other fields, as text."""
    data = dict(template)
    key, values = rng.choice(breaking)
    value = rng.choice(values)
    if value is _DELETE:
        data.pop(key, None)
    else:
        data[key] = value
    for other in rng.sample(sorted(data), k=min(len(data), rng.randint(0, 2))):
        if other not in ('schema', 'version', 'id', key):
            data[other] = rng.choice(SCALARS)
    text = _json(data)
    if rng.random() < 0.1:   # and now and then cut short
        text = text[:rng.randint(1, max(1, len(text) - 1))]
    return text


_DELETE = object()
WRONG = [None, 5, 1.5, float('nan'), [], {}, True]


def _junk_id(rng: random.Random) -> str:
    return f'junk-{rng.getrandbits(48):012x}'


# ---------------------------------------------------------------------------- JSON topics
def bad_instruction(rng: random.Random, iid: str) -> str:
    """A malformed or impossible instruction message (it must end with one terminal failed status)."""
    kind = rng.randrange(9)
    if kind == 0:
        return _garbage(rng, rng.randint(1, 300))              # not English, not JSON
    if kind == 1:
        return _huge(rng)                                      # over the length limit
    if kind == 2:
        return rng.choice(['null', '42', 'true', '[]', '[1, {"id": "x"}]', 'NaN', '-Infinity', '1e999',
                           '""', '"  "', '{}', '{"id": ""}', '[' * 50_000, '{"id": "' + 'x' * 300 + '"}'])
    if kind == 3:
        return _json({'id': iid, 'text': 'go to the ' + '[' * 20})[:rng.randint(3, 30)]   # truncated JSON
    formulas = ['F (near[sofa] &', ')))', 'near[' * 300, 'F near[sofa] & G !near[sofa]', 'F near[unicorn]',
                ' & '.join(f'F near[a{i}]' for i in range(65)), 'F ' * 250 + 'near[a]',
                'F (' + ' <-> '.join(f'near[a{i}]' for i in range(14)) + ')', 'X' * 20_001,
                'near[' + 'a::isabove(' * 40 + 'b' + ')' * 40 + ']', 'F near[sofa::isbehind(]', 'F near[]']
    template = {'schema': 'ltl_instruct/instruction', 'version': 1, 'id': iid, 'text': 'go to the fridge'}
    breaking: list[tuple[str, list[Any]]] = [
        ('text', WRONG + ['', 'x' * 2001]), ('schema', ['ltl_instruct/task_spec', 5, None, '']),
        ('version', [0, 2, '1', None, float('nan'), 1.5]), ('formula', WRONG + formulas)]
    if kind == 4:   # a formula instead of text: no text field
        template.pop('text')
        return _mutate(rng, template, [('formula', formulas + WRONG)])
    return _mutate(rng, template, breaking)


def bad_task_spec(rng: random.Random, iid: str) -> str:
    """A malformed task spec (task_progression ends it with one terminal failed status)."""
    template = {'schema': 'ltl_instruct/task_spec', 'version': 1, 'id': iid, 'ok': True,
                'formula': 'F near[fridge]', 'instruction': 'go to the fridge', 'referents': ['fridge'],
                'timing': {'translate_s': 0.001}}
    breaking: list[tuple[str, list[Any]]] = [
        ('formula', WRONG + ['F (', 'near[' * 300, 'F near[unicorn]', 'F near[sofa] & G !near[sofa]']),
        ('schema', ['ltl_instruct/instruction', 5, None]), ('version', [2, None, '1', float('inf')]),
        ('ok', [False, 0, None, _DELETE]), ('id', [5, None, '', 'x' * 201, []])]
    if rng.random() < 0.15:
        return rng.choice(['', 'null', '{', '[]', _huge(rng), '{"id": "' + iid + '", "ok": tr'])
    text = _mutate(rng, template, breaking)
    if rng.random() < 0.2:   # a refused spec with a malformed error in it
        errors = WRONG + ['boom', {'code': 5}, {'code': 'NOPE'}, {'code': [1]},
                          {'message': None, 'details': 7}]
        data = dict(template, ok=False, error=rng.choice(errors))
        text = _json(data)
    return text


def bad_cancel(rng: random.Random) -> str:
    """A cancel that names no instruction (it is refused with ``cancel_rejected``)."""
    return rng.choice(['', '   ', 'null', '42', '-1.5', 'true', '[]', '["a"]', '{}', '{"id": 5}',
                       '{"id": null}', '{"id": ""}', '{"id": [1]}', '{"id": ', '"', '[' * 10_000,
                       'x' * rng.randint(201, 5000),
                       _json({'id': 'y' * 300}), 'NaN', '{"id": "' + 'z' * 250 + '"}'])


def _schema_junk(rng: random.Random, schema: str, fields: dict[str, list[Any]]) -> str:
    """A payload of ``schema`` for an id no instruction has, every field drawn from wrong or odd values."""
    data: dict[str, Any] = {'schema': schema, 'version': rng.choice([1, 1, 1, 2, None]), 'id': _junk_id(rng)}
    for key, values in fields.items():
        if rng.random() < 0.8:
            data[key] = rng.choice(values + WRONG)
    text = _json(data)
    kind = rng.random()
    if kind < 0.1:
        return text[:rng.randint(1, max(1, len(text) - 1))]
    if kind < 0.2:
        return rng.choice(['', 'null', '[]', '{', _garbage(rng, 50), _huge(rng)])
    return text


def bad_string(rng: random.Random, topic: str) -> str:
    """A malformed payload for one of the other JSON topics (ids that no instruction has)."""
    num = [float('nan'), float('inf'), -1, 2 ** 70, 1e308]
    if topic == 'verification/reply':
        return _schema_junk(rng, 'ltl_instruct/verification_reply', {'accept': ['yes', 1, None]})
    if topic == 'task_status':
        return _schema_junk(rng, 'ltl_instruct/task_status', {
            'status': ['failed', 5, None], 'phase': ['planning', 'execution', 7],
            'terminal': ['yes', 1, None],
            'automaton_state': num + ['s']})
    if topic == 'referent_map':
        return _schema_junk(rng, 'ltl_instruct/referent_map', {
            'ok': [True, 'yes'], 'revision': num + ['1'], 'referent_map': [
                {'groundings': {'fridge': {'descriptor': 'fridge', 'outcome': 'NOPE'}}},
                {'groundings': {'fridge': {'descriptor': 'fridge', 'outcome': 'RESOLVED',
                                           'instances': [{'id': 'f', 'center': [float('nan'), 0, 0]}]}}},
                {'groundings': 5}]})
    if topic == 'skill/result':
        return _schema_junk(rng, 'ltl_instruct/skill_result', {
            'skill': ['pick', 'fly', 5], 'args': [['a'], 5, [None], ['a]b']], 'ok': [False, 'no'],
            'plan_stamp': num, 'error': [5, {'code': 7}]})
    if topic == 'skill/request':
        return _schema_junk(rng, 'ltl_instruct/skill_request', {
            'skill': ['pick', 'release', 'fly', 3], 'args': [['fridge'], 5, 'a'], 'path_index': num + ['x'],
            'plan_stamp': num + ['x'], 'targets': [5, [7], [{'id': 3, 'center': [float('nan')]}]]})
    if topic == 'fmt_planner/status':
        return _schema_junk(rng, 'ltl_instruct/segment_status', {
            'request_id': [5, 'r#1'], 'ok': [True, 'yes'], 'stamp': num, 'result': [5, {'goal_depth': 'x'}],
            'error': [5, {'code': None}]})
    if topic == 'plan_request':
        request = {'dims': rng.choice([2, 3, 7, None]), 'start': rng.choice([[0, 0], [float('nan'), 1], 'x']),
                   'regions': rng.choice([[], 5, [{'key': 'near[a]', 'centers': [[1e308, 0]]}], [{}] * 300]),
                   'goal': rng.choice([None, 5, {'cubes': 'x'}]),
                   'allowed': rng.choice([None, [], {'cubes': []}])}
        return _schema_junk(rng, 'ltl_instruct/plan_request', {
            'request_id': [_junk_id(rng)], 'stamp': num + [None, 'x'], 'request': [request, 5, [], {}]})
    if topic == 'camera/labels/classes':
        return _schema_junk(rng, 'ltl_instruct/label_classes', {
            'classes': [5, [1, 2], {'x': 'sofa'}, {'1': None}, {'2': ['a']}, {'1e999': 'a'}]})
    raise ValueError(topic)


# ---------------------------------------------------------------------------- typed topics
def _odd(rng: random.Random) -> float:
    return rng.choice([float('nan'), float('inf'), -float('inf')])


def bad_odometry(rng: random.Random) -> Any:
    """Odometry with a NaN or infinite position or orientation value.

    (A finite pose, however absurd, is odometry, not a malformed message: a plan from it may fail.)
    """
    from nav_msgs.msg import Odometry
    msg = Odometry()
    msg.header.frame_id = 'map'
    p, q = msg.pose.pose.position, msg.pose.pose.orientation
    q.w = 1.0
    setattr(rng.choice([p, q]), rng.choice('xyz'), _odd(rng))
    return msg


def bad_path(rng: random.Random, stamp: Any) -> Any:
    """A Path with non-finite or absurd poses."""
    from geometry_msgs.msg import PoseStamped
    from nav_msgs.msg import Path
    msg = Path()
    msg.header.stamp = stamp
    msg.header.frame_id = 'map'
    for k in range(rng.randint(1, 50)):
        ps = PoseStamped()
        ps.pose.position.x, ps.pose.position.y = float(k), 1.0
        ps.pose.orientation.w = 1.0
        msg.poses.append(ps)
    bad = rng.choice(msg.poses)
    setattr(bad.pose.position, rng.choice('xyz'), rng.choice([float('nan'), float('inf'), -float('inf')]))
    return msg


def bad_grid(rng: random.Random) -> Any:
    """An OccupancyGrid whose sizes, resolution or origin are wrong."""
    from nav_msgs.msg import OccupancyGrid
    msg = OccupancyGrid()
    msg.header.frame_id = 'map'
    w, h = rng.choice([(0, 0), (10, 10), (3, 100_000), (1, 1)])
    msg.info.width, msg.info.height = w, h
    msg.info.resolution = rng.choice([0.1, 0.0, -1.0, float('nan'), float('inf'), 1e-30])
    msg.info.origin.orientation.w = 1.0
    msg.info.origin.position.x = rng.choice([0.0, float('nan'), 1e308])
    n = w * h + rng.choice([0, -1, 1, 7])
    msg.data = [rng.choice([0, 100, -1]) for _ in range(max(0, min(n, 1000)))]
    return msg


def bad_cloud(rng: random.Random) -> Any:
    """A PointCloud2 whose layout does not match its data, or with non-finite points."""
    from sensor_msgs.msg import PointCloud2, PointField
    msg = PointCloud2()
    msg.header.frame_id = 'map'
    n = rng.choice([0, 1, 10, 100])
    msg.height, msg.width = 1, n
    kind = rng.choice([PointField.FLOAT32, PointField.FLOAT64, PointField.INT8, 99])
    msg.fields = [PointField(name=c, offset=4 * i, datatype=kind, count=rng.choice([1, 1, 0, 3]))
                  for i, c in enumerate(rng.choice(['xyz', 'xy', 'xyzq', '']))]
    msg.point_step = rng.choice([12, 0, 4, 1000])
    msg.row_step = msg.point_step * n
    values = [1.0, float('nan'), float('inf'), 3e38]
    pts = np.array([[rng.choice(values) for _ in range(3)] for _ in range(n)], dtype=np.float32)
    pts = pts.reshape(-1, 3)
    msg.data = pts.tobytes()[:rng.choice([len(pts.tobytes()), 5, 0])]
    msg.is_bigendian = rng.random() < 0.1
    return msg


def bad_camera_frame(rng: random.Random, stamp: Any) -> list[tuple[str, Any]]:
    """A camera frame (odometry, intrinsics, labels, depth of one stamp) with one or more parts malformed."""
    from ltl_instruct import conversions as conv
    from ltl_instruct.core.world.robot import Pose
    w, h = rng.choice([(8, 6), (16, 12)])
    depth = np.full((h, w), 2.0, dtype=np.float32)
    labels = np.full((h, w), rng.choice([0, 1, 2, 7, -1, 2 ** 31 - 1]), dtype=np.int32)
    pose: Any = conv.odometry_msg(Pose((5.0, 5.0, 1.0), 0.0), stamp)
    info = conv.camera_info_msg(w, h, 10.0, 10.0, w / 2, h / 2, stamp)
    parts = rng.sample(['pose', 'info', 'depth', 'labels', 'values'], k=rng.randint(1, 3))
    if 'values' in parts:
        depth[rng.randrange(h), :] = rng.choice([float('nan'), float('inf'), -5.0, 1e30, 0.0])
    depth_msg = conv.image_msg(depth, '32FC1', stamp)
    labels_msg = conv.image_msg(labels, '32SC1', stamp)
    if 'pose' in parts:
        pose = bad_odometry(rng)
        pose.header.stamp = stamp
    if 'info' in parts:
        info.k = [rng.choice([0.0, -1.0, float('nan'), 1e-300, 1e300]) if i in (0, 2, 4, 5) else v
                  for i, v in enumerate(info.k)]
        info.width, info.height = rng.choice([(0, 0), (w, h), (w * 1000, h), (1, 1)])
    for msg, name in ((depth_msg, 'depth'), (labels_msg, 'labels')):
        if name in parts:
            choice = rng.randrange(4)
            if choice == 0:
                msg.encoding = rng.choice(['bgr8', '', 'rgb8', '64FC1', 'x' * 100])
            elif choice == 1:
                msg.data = bytes(msg.data)[:rng.randint(0, len(msg.data) - 1)]
            elif choice == 2:
                msg.width, msg.height, msg.step = rng.choice([(w * 2, h, w * 4), (0, h, 0), (w, 0, w * 4),
                                                              (w, h, 0)])
            else:
                msg.is_bigendian = 1
    return [('odom', pose), ('camera/color/camera_info', info),
            ('camera/labels/image_raw', labels_msg), ('camera/depth/image_raw', depth_msg)]


# ---------------------------------------------------------------------------- one draw
@dataclass
class Draw:
    """Malformed messages of one draw, all for one topic's answer (a camera frame is four messages)."""

    topic: str
    messages: list[tuple[str, Any]]
    answer: Optional[str]


def draw(rng: random.Random, k: int, stamp: Callable[[], Any]) -> Draw:
    """Draw the ``k``-th malformed message: a topic by :data:`WEIGHTS`, then a message for it."""
    from std_msgs.msg import String
    topics = sorted(WEIGHTS)
    topic = rng.choices(topics, weights=[WEIGHTS[t] for t in topics])[0]
    if topic == 'instruction':
        msgs: list[tuple[str, Any]] = [(topic, String(data=bad_instruction(rng, f'bad-{k}')))]
    elif topic == 'task_spec':
        msgs = [(topic, String(data=bad_task_spec(rng, f'bad-spec-{k}')))]
    elif topic == 'cancel':
        msgs = [(topic, String(data=bad_cancel(rng)))]
    elif topic == 'odom':
        msgs = [(topic, bad_odometry(rng))]
    elif topic in ('plan_segment', 'plan'):
        msgs = [(topic, bad_path(rng, stamp()))]
    elif topic == 'map':
        msgs = [(topic, bad_grid(rng))]
    elif topic == 'map_cloud':
        msgs = [(topic, bad_cloud(rng))]
    elif topic.startswith('camera/') and topic != 'camera/labels/classes':
        topic, msgs = 'camera frame', bad_camera_frame(rng, stamp())
    else:
        msgs = [(topic, String(data=bad_string(rng, topic)))]
    return Draw(topic, msgs, ANSWERS.get(topic))


# ---------------------------------------------------------------------------- the run
@dataclass
class FuzzReport:
    """What one run sent and what came back."""

    good_sent: int = 0
    results: Counter = field(default_factory=Counter)         # terminal status of each valid instruction
    bad_sent: Counter = field(default_factory=Counter)        # malformed messages per topic
    terminal_expected: int = 0                                # instructions + specs (good and bad)
    terminal_ids: int = 0                                     # ids with a terminal planning status
    more_than_one_terminal: list = field(default_factory=list)
    no_terminal: list = field(default_factory=list)           # (id, its statuses) of those with none
    bad_codes: Counter = field(default_factory=Counter)       # error codes of the malformed ones
    cancel_rejected: tuple = (0, 0)                           # (expected, came)
    segment_refusals: tuple = (0, 0)                          # (expected, came)
    slowest_bad_s: float = 0.0
    restarts: list = field(default_factory=list)
    dead: dict = field(default_factory=dict)
    tracebacks: dict = field(default_factory=dict)             # node -> tracebacks in its log
    seconds: float = 0.0

    def target_met(self) -> bool:
        """Tell whether the run met issue 21's target (see the module's doc)."""
        good_ok = sum(self.results[s] for s in ('planned', 'satisfied')) == self.good_sent
        return (good_ok and self.terminal_ids == self.terminal_expected and not self.more_than_one_terminal
                and self.cancel_rejected[0] == self.cancel_rejected[1]
                and self.segment_refusals[0] == self.segment_refusals[1]
                and 'INTERNAL_ERROR' not in self.bad_codes and not self.restarts and not self.dead
                and not any(self.tracebacks.values()))

    def lines(self) -> list[str]:
        """The figures, one per line."""
        return [
            f'valid instructions: {self.good_sent}, results: {dict(self.results)}',
            f'malformed messages: {sum(self.bad_sent.values())} ({dict(sorted(self.bad_sent.items()))})',
            f'instructions and task specs (valid and malformed): {self.terminal_expected}, '
            f'with one terminal status: {self.terminal_ids}, '
            f'with more than one: {len(self.more_than_one_terminal)}; statuses of those with none: '
            f'{self.no_terminal}',
            f'error codes of the malformed ones: {dict(self.bad_codes.most_common())}',
            f'slowest terminal status of a malformed instruction: {self.slowest_bad_s:.2f} s '
            'after it was sent',
            f'cancel_rejected expected/came: {self.cancel_rejected[0]}/{self.cancel_rejected[1]}; '
            f'plan_request refusals expected/came: {self.segment_refusals[0]}/{self.segment_refusals[1]}',
            f'node restarts: {len(self.restarts)} {self.restarts}; dead nodes: {self.dead}; '
            f'tracebacks in the node logs: {self.tracebacks}',
            f'{self.seconds:.1f} s in all; target {"met" if self.target_met() else "MISSED"}',
        ]


class GraphFuzzer:
    """Sends the malformed messages and the valid instructions through a running graph, and counts.

    Parameters
    ----------
    client: a connected :class:`~ltl_instruct.nodes.client.GraphClient`.
    seed: the generators' seed.
    window: instructions (valid or not) sent and not yet ended at most (the topics keep 64).
    """

    def __init__(self, client: Any, seed: int = 0, window: int = 16) -> None:
        from std_msgs.msg import String

        from ltl_instruct.nodes.common import reliable_qos
        self.client = client
        self.rng = random.Random(seed)
        self.window = window
        self._pubs: dict[str, Any] = {}
        self._stamps = iter(range(10 ** 9, 10 ** 18, 7919))
        self.segment_status: list[dict[str, Any]] = []
        self._lock = threading.Lock()
        self._sent_at: dict[str, float] = {}
        self._good: set[str] = set()
        self._before: set[str] = set()
        self._sub = client.node.create_subscription(String, 'fmt_planner/status', self._on_segment_status,
                                                    reliable_qos(256))

    def close(self) -> None:
        """Destroy the publishers and the subscription made on the client's node."""
        for pub in self._pubs.values():
            self.client.node.destroy_publisher(pub)
        self._pubs.clear()
        self.client.node.destroy_subscription(self._sub)

    def _on_segment_status(self, msg: Any) -> None:
        try:
            data = json.loads(msg.data)
        except ValueError:
            return
        if not isinstance(data, dict):   # the fuzzer's own junk on this topic ('null', '42')
            return
        with self._lock:
            self.segment_status.append(data)

    def _publisher(self, topic: str, msg: Any) -> Any:
        """One publisher per topic: latched (it matches every subscription, latched ones too)."""
        if topic not in self._pubs:
            from ltl_instruct.nodes.common import latched_qos
            depth = 1 if topic in ('map', 'map_cloud', 'plan') else 64
            self._pubs[topic] = self.client.node.create_publisher(type(msg), topic, latched_qos(depth))
        return self._pubs[topic]

    def _stamp(self) -> Any:
        from ltl_instruct import conversions as conv
        return conv.stamp_from_key(next(self._stamps))

    def _mine(self, iid: str) -> bool:
        """Tell whether ``iid`` is an instruction of this run: not forged, not one a client sent before it.

        (The ids of the valid ones are known; a malformed one has its own id, or gets one from the
        translator or task_progression. An instruction of an earlier test may still end meanwhile.)
        """
        if iid in self._good:
            return True
        return iid not in self._before and not iid.startswith(('junk-', 'client-'))

    def _new_id(self, d: Draw) -> int:
        """1 when draw ``d`` should end under an id of its own; 0 when it repeats an id sent before.

        An id the nodes cannot take (over 200 characters) is cut to 200, as they report it, so
        ids that share their first 200 characters are one instruction, answered once.
        """
        from ltl_instruct import conversions as conv
        iid = next((conv.salvage_id(msg.data) for _, msg in d.messages if hasattr(msg, 'data')), '')
        if not iid:
            return 1   # the node makes one up
        fresh = iid not in self._bad_ids
        self._bad_ids.add(iid)
        return int(fresh)

    def _ended(self) -> int:
        """Instructions of this run with a terminal planning status."""
        statuses = self.client.received.statuses
        return sum(1 for iid in list(statuses) if self._mine(iid) and self.client.terminal(iid))

    def _wait_window(self, expected: int, timeout: float = 120.0) -> None:
        self.client.wait_until(lambda: expected - self._ended() <= self.window or None, timeout)

    def _wait_matched(self, timeout: float = 20.0) -> None:
        """Wait until every fuzzing publisher has matched its readers (a message sent before is lost)."""
        need = {'instruction': 1, 'task_spec': 2, 'cancel': 1, 'plan_request': 1}
        self.client.wait_until(lambda: all(p.get_subscription_count() >= need.get(t, 1)
                                           for t, p in self._pubs.items()
                                           if t not in ('map_cloud',)) or None, timeout)

    def prepare(self) -> None:
        """Create every publisher before the run, and wait for discovery to match them."""
        import importlib
        for topic, type_name in TYPES.items():
            module, name = type_name.rsplit('.', 1)
            self._publisher(topic, getattr(importlib.import_module(module), name)())
        self._wait_matched()

    def run(self, bad: int, good: int, good_map: Any, log: Callable[[str], None] = print) -> FuzzReport:
        """Send ``good`` valid instructions one after the other, ``bad`` malformed messages among them."""
        report = FuzzReport()
        client = self.client
        t0 = time.monotonic()
        good_ids: list[str] = []
        self._good = set()
        self._bad_ids: set[str] = set()
        self._before = set(client.received.statuses)
        bad_ids_expected = 0
        cancels = planner_refusals = 0
        segment_before = len(self.segment_status)
        cancel_before = self._count_status('cancel_rejected')
        per_good = [bad // good + (1 if k < bad % good else 0) for k in range(good)]
        for k in range(good):
            iid = client.send(formula=GOOD[k % len(GOOD)]) if GOOD[k % len(GOOD)].startswith(('F ', 'G ')) \
                else client.send(text=GOOD[k % len(GOOD)])
            good_ids.append(iid)
            self._good.add(iid)
            report.good_sent += 1
            map_sent = False
            for _ in range(per_good[k]):
                d = draw(self.rng, sum(report.bad_sent.values()), self._stamp)
                if d.topic == 'map':
                    map_sent = True
                for topic, msg in d.messages:
                    self._publisher(topic, msg).publish(msg)
                if d.topic in ('instruction', 'task_spec'):
                    self._sent_at[f'bad-{sum(report.bad_sent.values())}' if d.topic == 'instruction'
                                  else f'bad-spec-{sum(report.bad_sent.values())}'] = time.monotonic()
                report.bad_sent[d.topic] += 1
                if d.answer == 'terminal':
                    bad_ids_expected += self._new_id(d)
                elif d.answer == 'cancel_rejected':
                    cancels += 1
                elif d.answer == 'segment_status':
                    planner_refusals += 1
                self._wait_window(bad_ids_expected + len(good_ids))
                time.sleep(0.002)
            client.wait_terminal(iid, timeout=120.0)
            if map_sent:   # a malformed map replaces the world (documented): the good one comes back first
                self._publisher('map', good_map).publish(good_map)
                time.sleep(0.5)
            status = client.terminal(iid)
            report.results[status['status']] += 1
            if status['status'] not in ('planned', 'satisfied'):
                log(f'valid instruction {GOOD[k % len(GOOD)]!r} ended {status["status"]}: '
                    f'{status.get("error")}')
        report.terminal_expected = bad_ids_expected + len(good_ids)
        client.wait_until(lambda: self._ended() >= report.terminal_expected or None, 60.0)
        client.wait_until(lambda: (len(self.segment_status) - segment_before >= planner_refusals and
                                   self._count_status('cancel_rejected') - cancel_before >= cancels) or None,
                          10.0)
        time.sleep(1.0)   # a second terminal status of any of them would come now
        self._count(report, good_ids, cancels, cancel_before, planner_refusals, segment_before)
        report.seconds = time.monotonic() - t0
        return report

    def _count_status(self, name: str) -> int:
        return sum(1 for statuses in list(self.client.received.statuses.values()) for s in statuses
                   if s.get('status') == name)

    def _count(self, report: FuzzReport, good_ids: list[str], cancels: int, cancel_before: int,
               planner_refusals: int, segment_before: int) -> None:
        client = self.client
        good = set(good_ids)
        for iid, statuses in list(client.received.statuses.items()):
            if not self._mine(iid):
                continue
            ends = client.terminals(iid)
            if not ends:
                if any(s.get('status') != 'cancel_rejected' for s in statuses):   # not a cancel's id only
                    report.no_terminal.append((iid, [s.get('status') for s in statuses]))
                continue
            report.terminal_ids += 1
            if len(ends) > 1:
                report.more_than_one_terminal.append((iid, [s['status'] for s in ends]))
            if iid not in good:
                error = ends[0].get('error') or {}
                report.bad_codes[str(error.get('code', ends[0]['status']))] += 1
                came = client.received.arrival.get(('terminal', iid))
                if iid in self._sent_at and came is not None:
                    report.slowest_bad_s = max(report.slowest_bad_s, came - self._sent_at[iid])
        refusals = [s for s in self.segment_status[segment_before:] if s.get('ok') is False
                    and str(s.get('id')).startswith(('junk-', 'unidentified'))]
        report.cancel_rejected = (cancels, self._count_status('cancel_rejected') - cancel_before)
        report.segment_refusals = (planner_refusals, len(refusals))


def main(argv: list[str]) -> int:
    """Start the graph, run the fuzzer, print the figures; 0 when the target is met."""
    parser = argparse.ArgumentParser(prog='python -m bench.graph_fuzz', description=__doc__.splitlines()[0])
    parser.add_argument('--bad', type=int, default=1000, help='malformed messages (default 1000)')
    parser.add_argument('--good', type=int, default=100, help='valid instructions (default 100)')
    parser.add_argument('--seed', type=int, default=0)
    parser.add_argument('--segment-timeout', type=float, default=60.0,
                        help='task_progression\'s segment_timeout [s] (default 60; FMT* gets a third)')
    parser.add_argument('--backend', default='combined',
                        help='the translator node\'s backend (default combined)')
    args = parser.parse_args(argv)

    os.environ['ROS_DOMAIN_ID'] = str(random.randint(120, 229))
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, RestartPolicy, default_params_file
    from ltl_instruct.nodes.client import GraphClient

    # killed (a time limit's SIGTERM): stop the graph on the way out, not leave its nodes running
    signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(1))
    logs = Path(tempfile.mkdtemp(prefix='bench_graph_fuzz_'))
    # the simulator's camera is off, the grounder's subscriptions to it are on: only malformed frames come
    # FMT* may take 20 s per segment (2 s by default) and a segment may wait 60 s for it (10 s): under a load
    # of 40-80 from other jobs on this 2-core machine, FMT* drew too few samples in 2 s and answers took over
    # 10 s, and valid instructions failed with TIMEOUT, which says nothing about malformed input (a stall
    # still shows, as a TIMEOUT); on a quiet machine a segment takes well under a second either way
    overrides = {'sim_world': {'camera_rate_hz': 0.0}, 'ltl_translator': {'backend': args.backend},
                 'task_progression': {'segment_timeout': args.segment_timeout},
                 'fmt_planner': {'time_limit': args.segment_timeout / 3}}
    restarts: list[str] = []
    graph = NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs,
                      restart=RestartPolicy(), say=restarts.append).start()
    client = GraphClient('bench_graph_fuzz')
    try:
        if not client.wait_for_graph(timeout=180.0, need_sim=True):
            print(f'graph did not come up; logs in {logs}')
            return 1
        # connected is not ready: the translator serves nothing before its backend has loaded
        client.wait_terminal(client.send(formula='F near[unicorn]'), timeout=600.0)
        fuzzer = GraphFuzzer(client, seed=args.seed)
        fuzzer.prepare()
        print(f'graph up; {args.bad} malformed messages among {args.good} valid instructions; logs in {logs}',
              flush=True)
        report = fuzzer.run(args.bad, args.good, client.received.map)
        report.restarts, report.dead = [r.node for r in graph.restarts], graph.dead()
    finally:
        client.close()
        codes = graph.stop()
    report.tracebacks = {p.stem: p.read_text(errors='replace').count('Traceback') for p in logs.glob('*.log')}
    for line in report.lines():
        print(line)
    print(f'exit statuses on SIGINT: {codes}')
    return 0 if report.target_met() and all(c == 0 for c in codes.values()) else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

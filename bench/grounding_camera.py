"""Camera grounding against the object list: one instance per object, centres, descriptors (issue 18).

Run: ``.venv/bin/python -m bench.grounding_camera [--views 8] [--scene NAME_OR_FILE ...] [--verbose]``.

For every built-in scene and a two-room office made here (an occluding wall with a
doorway, three red chairs around a table, two grey chairs side by side, a second room
with a whiteboard), the map is built exactly as ``ltl-instruct ground --views 8`` builds
it (:func:`map_from_views`: 320x240 label + depth views on an ellipse around the scene
centre), then:

- instances per true object: an instance *stands for* an object of its label when the
  object's centre lies in the instance's box or the instance's centre lies in the
  object's box (each grown by half a voxel). Target: exactly one per object. A *split*
  is an object two or more instances stand for, a *merge* an instance that stands for
  two or more objects; *missed* objects have none (often: never in view), *spurious*
  instances stand for nothing;
- centre error of the objects with exactly one instance that stands for them alone
  (target: within 0.15 m);
- descriptors generated from the object list (plain label ``chair``, full label
  ``red_chair``, label + relation to the nearest object of another label
  ``red_chair::isleftof(table)``), resolved against the camera's instances and against
  the object list. A camera answer is correct when its outcome is the object list's and
  its instances stand one-to-one for the same objects.

Prints a table per scene and the totals; exits 1 when a target is missed.

``--speed N`` measures instead what the grounder does with each camera frame, on N
640x480 frames of the apartment taken along a walk through it: read the depth image
(16UC1, millimetres, as a depth camera sends it) and the label image out of their
``sensor_msgs/Image`` messages, look up the odometry pose of the frame's stamp, and
integrate the frame into the semantic map (target: median under 30 ms); and, apart,
extracting the instances from the map afterwards (done once per integrated frame).
Each is reported as p50 / p99 / max. ``--threads N`` is the nodes' ``compute_threads``
(default 1; 0 = the libraries' default), ``--contend K`` runs K processes doing BLAS
products meanwhile, limited the same way: the other nodes of a small computer.
"""
from __future__ import annotations

import argparse
import copy
import math
import os
import random
import statistics
import sys
import time
from collections import Counter
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.grounding import GroundingParams, Instance, Resolver, instances_from_scene
from ltl_instruct.core.grounding.semantic_map import SemanticMap, SemanticMapParams
from ltl_instruct.core.grounding.survey import map_from_views
from ltl_instruct.core.spec import Descriptor, Relation
from ltl_instruct.core.world.builtin import builtin_scene_names, resolve_scene
from ltl_instruct.core.world.camera import CameraIntrinsics, SyntheticCamera
from ltl_instruct.core.world.pose_history import PoseHistory
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import Scene, scene_from_dict, slug

CENTRE_TARGET_M = 0.15
AXIS_WORDS = ('isleftof', 'isrightof', 'isbehind', 'isinfrontof', 'isabove', 'isbelow')
_WALL_H = 2.5


def _wall(x0: float, y0: float, x1: float, y1: float) -> dict:
    """A 0.2 m thick wall from (x0, y0) to (x1, y1) [m] (axis-aligned)."""
    return {'center': [(x0 + x1) / 2, (y0 + y1) / 2, _WALL_H / 2],
            'size': [max(abs(x1 - x0), 0.2), max(abs(y1 - y0), 0.2), _WALL_H]}


def _thing(label: str, x: float, y: float, size: Sequence[float], z: Optional[float] = None) -> dict:
    """An object standing on the floor at (x, y) unless ``z`` (its centre height) is given."""
    return {'label': label, 'center': [x, y, size[2] / 2 if z is None else z], 'size': list(size)}


CHAIR = (0.5, 0.5, 0.9)
OFFICE = {
    'name': 'two_room_office',
    'bounds': {'min': [0.0, 0.0, 0.0], 'max': [12.0, 7.0, 3.0]},
    'robot': {'kind': 'ground', 'start': [1.0, 1.0, 0.0], 'radius': 0.3},
    'obstacles': [_wall(0, 0.1, 12, 0.1), _wall(0, 6.9, 12, 6.9), _wall(0.1, 0, 0.1, 7),
                  _wall(11.9, 0, 11.9, 7),
                  _wall(6.0, 0, 6.0, 4.8), _wall(6.0, 6.0, 6.0, 7.0)],   # doorway at y 4.8..6.0
    'objects': [
        # meeting room (x 0..6): a table with three red chairs and a blue one around it
        _thing('table', 3.0, 3.5, (1.6, 0.9, 0.75)),
        _thing('red chair', 3.0, 4.45, CHAIR), _thing('red chair', 3.0, 2.55, CHAIR),
        _thing('red chair', 1.75, 3.5, CHAIR), _thing('blue chair', 4.25, 3.5, CHAIR),
        _thing('desk', 1.2, 6.35, (1.4, 0.7, 0.75)),
        _thing('computer', 1.2, 6.45, (0.5, 0.3, 0.4), z=0.95),
        _thing('plant', 5.5, 0.6, (0.4, 0.4, 1.0)),
        _thing('bookshelf', 0.45, 1.2, (0.4, 1.5, 1.8)),
        # two chairs side by side, 0.25 m apart
        _thing('grey chair', 4.1, 6.3, CHAIR), _thing('grey chair', 4.85, 6.3, CHAIR),
        # second room (x 6..12), behind the wall
        _thing('whiteboard', 11.75, 3.5, (0.1, 2.0, 1.2), z=1.5),
        _thing('sofa', 9.0, 6.3, (2.0, 0.9, 0.8)),
        _thing('table', 9.0, 3.0, (1.2, 1.2, 0.75)),
        _thing('blue chair', 9.0, 1.95, CHAIR),
        _thing('lamp', 11.4, 6.4, (0.3, 0.3, 1.6)),
        _thing('printer', 7.0, 0.6, (0.5, 0.5, 0.8)),
    ],
}


def office_variant(seed: int) -> Scene:
    """The office with every object moved by up to 6 cm and resized by up to 5 % (seed 0: as drawn).

    The variants keep the benchmark honest about voxel alignment: objects of round sizes at
    round positions put faces exactly on voxel faces.
    """
    rng = random.Random(seed)
    data = copy.deepcopy(OFFICE)
    if seed:
        data['name'] = f'{OFFICE["name"]}~{seed}'
        for o in data['objects']:
            on_floor = math.isclose(o['center'][2], o['size'][2] / 2)
            o['center'][0] += rng.uniform(-0.06, 0.06)
            o['center'][1] += rng.uniform(-0.06, 0.06)
            o['size'] = [v * rng.uniform(0.95, 1.05) for v in o['size']]
            if on_floor:
                o['center'][2] = o['size'][2] / 2
    return scene_from_dict(data)


@dataclass(frozen=True)
class Matching:
    """Which true objects each instance stands for (instance id -> object ids), and back."""

    of_instance: dict[str, tuple[str, ...]]
    of_object: dict[str, tuple[str, ...]]

    def single(self, inst: Instance) -> Optional[str]:
        """The one object an instance stands for alone, else None."""
        objs = self.of_instance.get(inst.id, ())
        return objs[0] if len(objs) == 1 else None


def _inside(point: Sequence[float], box: Instance, grow: float) -> bool:
    c, h = np.asarray(box.center), np.asarray(box.size) / 2 + grow
    return bool(np.all(np.abs(np.asarray(point) - c) <= h))


def match(truth: Sequence[Instance], found: Sequence[Instance], voxel: float) -> Matching:
    """Relate instances and objects of the same label by centre-in-box either way."""
    of_inst = {i.id: tuple(o.id for o in truth if o.label == i.label
                           and (_inside(o.center, i, voxel / 2) or _inside(i.center, o, voxel / 2)))
               for i in found}
    of_obj = {o.id: tuple(i for i, objs in of_inst.items() if o.id in objs) for o in truth}
    return Matching(of_inst, of_obj)


def descriptors(truth: Sequence[Instance]) -> list[Descriptor]:
    """Plain labels, full labels, and label + the clearest axis relation to the nearest other-label object."""
    out: dict[str, Descriptor] = {}
    for o in truth:
        words = slug(o.label).split('_')
        for name in {words[-1], slug(o.label)}:
            out.setdefault(name, Descriptor(name))
        others = [n for n in truth if n.label != o.label]
        if not others:
            continue
        n = min(others, key=lambda a: np.linalg.norm(np.subtract(a.center, o.center)))
        d = np.subtract(o.center, n.center)
        margins = {'isleftof': d[1], 'isrightof': -d[1], 'isbehind': d[0], 'isinfrontof': -d[0],
                   'isabove': d[2], 'isbelow': -d[2]}
        comparator = max(AXIS_WORDS, key=lambda k: margins[k])
        desc = Descriptor(slug(o.label), (Relation(comparator, (Descriptor(slug(n.label)),)),))
        out.setdefault(str(desc), desc)
    return list(out.values())


def _names(d: Descriptor) -> set[str]:
    out = {d.name}
    for r in d.relations:
        for a in r.args:
            out |= _names(a)
    return out


def descriptor_accuracy(truth: Sequence[Instance], found: Sequence[Instance], m: Matching) -> dict:
    """Descriptors right from the camera (as the object list resolves them), in all and among those in view.

    A descriptor is in view when every object its names (and its anchors' names) match was
    seen, i.e. has an instance that stands for it.
    """
    known, seen = Resolver(truth, GroundingParams()), Resolver(found, GroundingParams())
    cases = descriptors(truth)
    wrong, in_view, ok_in_view = [], 0, 0
    for d in cases:
        want = known.resolve(d)
        got = seen.resolve(d)
        ids = sorted(m.single(i) or f'?{i.id}' for i in got.instances)
        right = got.outcome == want.outcome and ids == sorted(i.id for i in want.instances)
        visible = all(m.of_object[truth[k].id] for n in _names(d) for k in known.named(n))
        in_view += visible
        ok_in_view += visible and right
        if not right:
            wrong.append(f'{d}: camera {got.outcome.value} {ids}, list {want.outcome.value} '
                         f'{sorted(i.id for i in want.instances)}' + ('' if visible else ' (not all seen)'))
    return {'ok': len(cases) - len(wrong), 'descriptors': len(cases), 'in_view': in_view,
            'ok_in_view': ok_in_view, 'wrong': wrong}


def object_figures(truth: Sequence[Instance], found: Sequence[Instance], m: Matching) -> dict:
    """Counts of one-to-one objects, splits, merges, missed objects, spurious instances; centre errors."""
    per_obj = Counter(len(v) for v in m.of_object.values())
    alone = sum(len(v) == 1 and len(m.of_instance[v[0]]) == 1 for v in m.of_object.values())
    errors = []
    for o in truth:
        insts = [i for i in found if i.id in m.of_object[o.id]]
        if len(insts) == 1 and m.single(insts[0]) == o.id:
            errors.append(float(np.linalg.norm(np.subtract(insts[0].center, o.center))))
    return {'objects': len(truth), 'instances': len(found), 'one': alone, 'missed': per_obj[0],
            'split': sum(c for k, c in per_obj.items() if k >= 2),
            'merged': sum(len(v) >= 2 for v in m.of_instance.values()),
            'spurious': sum(len(v) == 0 for v in m.of_instance.values()),
            'errors': errors}


def bench_scene(scene: Scene, views: int, verbose: bool) -> Optional[dict]:
    """All figures of one scene, or None when its map cannot be built (printed)."""
    t0 = time.perf_counter()
    try:
        smap = map_from_views(scene, views)
    except LtlInstructError as e:
        print(f'{scene.name}: no map from {views} views: [{e.code.value}] {e.message}')
        return None
    t1 = time.perf_counter()
    found = smap.instances()
    t2 = time.perf_counter()
    truth = instances_from_scene(scene)
    m = match(truth, found, smap.params.voxel_size)
    fig = object_figures(truth, found, m)
    acc = descriptor_accuracy(truth, found, m)
    wrong = acc.pop('wrong')
    fig.update(acc)
    fig['map_s'], fig['instances_s'] = t1 - t0, t2 - t1
    _print_scene(scene.name, fig)
    if verbose:
        _print_details(truth, found, m, wrong)
    return fig


def _print_details(truth: Sequence[Instance], found: Sequence[Instance], m: Matching,
                   wrong: list[str]) -> None:
    by_id = {i.id: i for i in found}
    for o in truth:
        insts = [by_id[i] for i in m.of_object[o.id]]
        errs = ', '.join(f'{np.linalg.norm(np.subtract(i.center, o.center)):.2f} m' for i in insts)
        tail = f' ({errs})' if errs else ''
        print(f'    {o.id:<20} <- {", ".join(i.id for i in insts) or "-"}{tail}')
    for line in wrong:
        print(f'    wrong: {line}')


def _print_scene(name: str, f: dict) -> None:
    err = f['errors']
    within = sum(e <= CENTRE_TARGET_M for e in err)
    centre = (f'centre error median {statistics.median(err):.3f} m, max {max(err):.3f} m, '
              f'{within}/{len(err)} within {CENTRE_TARGET_M} m' if err else 'no one-to-one objects')
    print(f'{name}: {f["objects"]} objects, {f["instances"]} instances; exactly one instance: '
          f'{f["one"]}/{f["objects"]}; split {f["split"]}, merged {f["merged"]}, missed {f["missed"]}, '
          f'spurious {f["spurious"]}')
    print(f'  {centre}')
    print(f'  descriptors right from the camera: {f["ok"]}/{f["descriptors"]}, among those whose objects '
          f'were all seen {f["ok_in_view"]}/{f["in_view"]} (object list: all, by definition)')
    print(f'  map from views {f["map_s"]:.2f} s, instances {f["instances_s"] * 1000:.0f} ms')


def _scenes(names: Sequence[str], variants: int) -> list[Scene]:
    offices = [office_variant(k) for k in range(variants + 1)]
    if names:
        return [offices[0] if n == OFFICE['name'] else resolve_scene(n) for n in names]
    return [resolve_scene(n) for n in builtin_scene_names()] + offices


INTEGRATE_TARGET_MS = 30.0


def _walk(scene: Scene, frames: int) -> list[Pose]:
    """Robot poses every 0.4 m along a closed walk round the apartment's rooms, facing the way."""
    corners = [(1.0, 1.0), (6.0, 1.5), (9.0, 4.5), (6.0, 7.5), (2.0, 6.5), (1.0, 1.0)]
    pts = np.concatenate([np.linspace(a, b, max(2, int(math.dist(a, b) / 0.4)), endpoint=False)
                          for a, b in zip(corners, corners[1:])])
    pts = pts[np.linspace(0, len(pts) - 1, frames).astype(int)]
    yaw = np.arctan2(*(np.roll(pts, -1, axis=0) - pts).T[::-1])
    return [Pose((float(x), float(y), 0.0), float(a)) for (x, y), a in zip(pts, yaw)]


CONTENDER = """
import sys, numpy
from ltl_instruct.core.compute_threads import limit_compute_threads
limit_compute_threads(int(sys.argv[1]))
a = numpy.random.default_rng(0).random((500, 500))
while True:
    a = (a @ a) / 500.0
"""


def _contenders(count: int, threads: int) -> list:
    """Start ``count`` processes doing BLAS products, each limited as the grounder is (other nodes' work)."""
    import subprocess
    return [subprocess.Popen([sys.executable, '-c', CONTENDER, str(threads)]) for _ in range(count)]


def _tail(values: Sequence[float]) -> str:
    ms = sorted(v * 1000.0 for v in values)
    p99 = ms[min(len(ms) - 1, int(math.ceil(0.99 * len(ms))) - 1)]
    return f'p50 {statistics.median(ms):.1f} ms, p99 {p99:.1f} ms, max {ms[-1]:.1f} ms'


def bench_frames(frames: int, threads: int = 1, contend: int = 0) -> int:
    """Time the grounder's work per 640x480 frame (see the module docstring); 1 when over the target."""
    from ltl_instruct import conversions as conv
    from ltl_instruct.core.compute_threads import limit_compute_threads
    limit_compute_threads(threads)
    scene = resolve_scene('apartment')
    camera = SyntheticCamera(scene, 640, 480)
    poses = _walk(scene, frames + 1)
    history = PoseHistory()
    msgs = []
    for k, pose in enumerate(poses):
        frame = camera.render(pose)
        history.add(k * 100_000_000, pose)
        msgs.append((conv.depth_msg(frame.depth, '16UC1'), conv.image_msg(frame.labels, '32SC1'),
                     k * 100_000_000))
    smap = SemanticMap(camera.classes, SemanticMapParams())
    k = CameraIntrinsics.default(640, 480)
    read, integrate, extract, cpu = [], [], [], []
    others = _contenders(contend, threads)
    try:
        time.sleep(1.0 if others else 0.0)
        for depth_msg, labels_msg, stamp in msgs:
            t0, c0 = time.perf_counter(), time.process_time()
            depth, labels, pose = conv.depth_array(depth_msg), conv.image_array(labels_msg), history.at(stamp)
            t1 = time.perf_counter()
            smap.integrate(depth, labels, k, pose)
            t2, c2 = time.perf_counter(), time.process_time()
            smap.instances()
            t3 = time.perf_counter()
            read.append(t1 - t0), integrate.append(t2 - t1), extract.append(t3 - t2), cpu.append(c2 - c0)
    finally:
        for p in others:
            p.kill()
            p.wait()
    total = [a + b for a, b in zip(read[1:], integrate[1:])]   # the first frame allocates the grid
    ms = statistics.median(total) * 1000.0
    load = os.getloadavg()[0] if hasattr(os, 'getloadavg') else float('nan')
    limit = 'the libraries\' default' if threads <= 0 else 'here and in each contender'
    print(f'{frames} frames of 640x480 along a walk through the apartment, '
          f'{len(smap.instances())} instances at the end; compute_threads {threads} ({limit}), '
          f'{contend} contending BLAS processes:')
    print(f'  read the messages and the pose: median {statistics.median(read[1:]) * 1000:.1f} ms')
    print(f'  integrate: {_tail(integrate[1:])}')
    print(f'  messages to map (target < {INTEGRATE_TARGET_MS:.0f} ms): {_tail(total)}; CPU time of this '
          f'process: median {statistics.median(cpu[1:]) * 1000:.1f} ms (load average {load:.1f} on '
          f'{os.cpu_count()} cores)')
    print(f'  instances from the map: {_tail(extract[1:])}')
    return 0 if ms < INTEGRATE_TARGET_MS else 1


def main(argv: list[str]) -> int:
    """Print the figures of every scene and the totals; 1 when a target is missed."""
    ap = argparse.ArgumentParser(prog='bench.grounding_camera')
    ap.add_argument('--views', type=int, default=8, help='survey views per scene (default 8, as ground)')
    ap.add_argument('--scene', action='append', default=[],
                    help=f'a built-in name, a scene file or {OFFICE["name"]} (default: all of them)')
    ap.add_argument('--variants', type=int, default=2,
                    help='also the office with its objects moved a little, this many times (default 2)')
    ap.add_argument('--verbose', action='store_true', help='print the matching and every wrong descriptor')
    ap.add_argument('--speed', type=int, default=0, metavar='N',
                    help='only time the grounder\'s work on N 640x480 frames (see the module docstring)')
    ap.add_argument('--threads', type=int, default=1,
                    help='with --speed: compute_threads of this process and the contenders (0 = default)')
    ap.add_argument('--contend', type=int, default=0,
                    help='with --speed: this many processes doing BLAS products meanwhile (other nodes)')
    args = ap.parse_args(argv)
    if args.speed:
        return bench_frames(args.speed, args.threads, args.contend)
    scenes = _scenes(args.scene, args.variants)
    figs = [f for s in scenes if (f := bench_scene(s, args.views, args.verbose)) is not None]
    if not figs:
        return 1
    keys = ('objects', 'one', 'split', 'merged', 'missed', 'spurious', 'ok', 'descriptors', 'in_view',
            'ok_in_view')
    total = {k: sum(f[k] for f in figs) for k in keys}
    errors = [e for f in figs for e in f['errors']]
    print(f'all: exactly one instance {total["one"]}/{total["objects"]}, split {total["split"]}, '
          f'merged {total["merged"]}, missed {total["missed"]}, spurious {total["spurious"]}; '
          f'centres within {CENTRE_TARGET_M} m {sum(e <= CENTRE_TARGET_M for e in errors)}/{len(errors)}; '
          f'descriptors {total["ok"]}/{total["descriptors"]} = {total["ok"] / total["descriptors"]:.1%}, '
          f'in view {total["ok_in_view"]}/{total["in_view"]} '
          f'= {total["ok_in_view"] / max(total["in_view"], 1):.1%}')
    missed = total['split'] or total['merged'] or any(e > CENTRE_TARGET_M for e in errors)
    return 1 if missed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

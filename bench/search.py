"""Search for referents the robot cannot see from its start: travel to resolve, three ways (issue 18).

Run: ``.venv/bin/python -m bench.search [--scene NAME ...] [--limit N] [--every-start] [--verbose]``.

Scenes: the built-in ``apartment`` (four rooms, archways) and the two-room office of
:mod:`bench.grounding_camera` (an occluding wall with a doorway). Referents: every label
that names exactly one object of the scene and that the start panorama (4 views) does
not resolve: behind a wall, or out of range, from the scene's start (``--every-start``:
also from a start in each other room). Each is sought with ``F near[label]``:

(a) ``gain``: :func:`search_referents`, frontiers by information gain per metre;
(b) ``nearest``: the same search, the nearest frontier each move;
(c) ``oracle``: straight to the nearest pose from which the referent is visible: the
    reachable cell nearest by travel (10 cm grid, 8-connected, from the start) that a
    2D line of sight (walls and objects at camera height block it) joins to the
    object within the sensor range and from which one panorama resolves it; its travel
    is the FMT* path there (the planner the search uses).

A search's answer is correct when the descriptor resolved to exactly one instance and
that instance stands for the object (:func:`bench.grounding_camera.match`). Absent
referents (labels of no object) must end ``NO_MATCH`` after the search, the map complete.

Objects inside a wall (the apartment's doors) are no referent: no pose sees them. An
object the oracle finds no pose for is left out of the travel totals, not of the counts.

Targets: correct >= 95 %, absent NO_MATCH 100 %, total travel of (a) <= 2x (c) and < (b).
Prints a line per referent with ``--verbose``, a table per scene and the totals; exits 1
when a target is missed.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections import Counter
from dataclasses import dataclass, replace
from typing import Optional, Sequence

import numpy as np

from bench.grounding_camera import office_variant, match
from ltl_instruct.core.grounding import instances_from_scene
from ltl_instruct.core.grounding.coverage import PlaneGrid, travel_field
from ltl_instruct.core.grounding.rsm import Instance, Outcome
from ltl_instruct.core.grounding.search import SearchParams, plan_move, search_referents
from ltl_instruct.core.planning.occupancy import world_from_scene
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import Scene, slug

ABSENT = ('piano', 'motorbike')
EXTRA_STARTS = {'apartment': ((15.0, 3.0), (15.0, 12.0), (4.0, 12.0)), 'two_room_office': ((10.0, 5.0),)}
CORRECT_TARGET = 0.95
TRAVEL_TARGET = 2.0


@dataclass(frozen=True)
class Case:
    """One referent sought in one scene: the figures of the three ways."""

    scene: str
    start: str
    referent: str
    correct: dict[str, bool]
    travel: dict[str, float]
    views: dict[str, int]


def _sight_blocks(scene: Scene, grid: PlaneGrid, eye: float, skip: Instance) -> np.ndarray:
    """Cells (nx, ny) a box of the scene covers at camera height, but for the object sought."""
    boxes = list(scene.obstacles) + [o.box for o in scene.objects if o.box is not None]
    out = np.zeros(grid.shape, dtype=bool)
    c = grid.centers()
    for b in boxes:
        lo, hi = b.lo, b.hi
        if not lo[2] <= eye <= hi[2] or np.allclose(b.center, skip.center):
            continue
        out |= np.all((c >= lo[:2]) & (c <= hi[:2]), axis=-1)
    return out


def _in_sight(cells: np.ndarray, grid: PlaneGrid, blocks: np.ndarray, obj: Instance,
              reach: float) -> np.ndarray:
    """Whether a line from each cell's centre (cells (K, 2)) meets the object's footprint within reach [m]."""
    c, h = np.asarray(obj.center[:2]), np.asarray(obj.size[:2]) / 2
    targets = c + np.array([[0, 0], [-1, -1], [-1, 1], [1, -1], [1, 1]]) * h * 0.9     # (T, 2)
    pts = grid.centers()[cells[:, 0], cells[:, 1]]
    t = np.linspace(0.0, 1.0, int(reach / (grid.cell * 0.5)) + 2)
    seg = pts[:, None, None, :] + (targets[None, :, None, :] - pts[:, None, None, :]) * t[None, None, :, None]
    ix, iy = grid.index(seg.reshape(-1, 2))
    hit = blocks[ix, iy].reshape(seg.shape[:3]).any(axis=2)
    near_enough = np.linalg.norm(targets[None] - pts[:, None], axis=2) <= reach
    return np.any(~hit & near_enough, axis=1)


def oracle(scene: Scene, start: Pose, obj: Instance, params: SearchParams,
           checks: int = 50, stride: int = 3) -> Optional[float]:
    """FMT* travel [m] from ``start`` to the nearest pose whose panorama resolves ``obj``; None if none.

    Poses are tried nearest first by grid travel, every ``stride``-th of those in line of
    sight, at most ``checks`` of them (a panorama each).
    """
    world = world_from_scene(scene)
    grid = PlaneGrid.over(scene.bounds_min, scene.bounds_max, params.cell)
    free = world.is_free(grid.centers().reshape(-1, 2)).reshape(grid.shape)
    start = start.position
    dist = travel_field(free, grid, start)
    cells = np.argwhere(np.isfinite(dist))
    cells = cells[np.argsort(dist[cells[:, 0], cells[:, 1]], kind='stable')]
    blocks = _sight_blocks(scene, grid, 1.0, obj)
    cells = cells[_in_sight(cells, grid, blocks, obj, params.sensor_range - 0.5)]
    for cell in cells[::stride][:checks]:   # cells 0.1 m apart: every third, nearest first
        at = grid.centers()[cell[0], cell[1]]
        probe = replace(params, max_moves=0)
        r = search_referents(scene, f'F near[{slug(obj.label)}]', Pose((at[0], at[1], 0.0), 0.0), probe)
        if r.referent_map.get(slug(obj.label)).outcome == Outcome.RESOLVED:
            plan = plan_move(world, start, at, (), params)
            return plan.length if plan.ok else None
    return None


def _correct(scene: Scene, obj: Instance, outcome: Outcome, found: Sequence[Instance], voxel: float) -> bool:
    if outcome != Outcome.RESOLVED or len(found) != 1:
        return False
    m = match([obj], list(found), voxel)
    return m.single(found[0]) == obj.id


def hidden_referents(scene: Scene, start: Pose, params: SearchParams) -> list[Instance]:
    """Objects whose label is theirs alone, in no wall, that the start panorama does not resolve."""
    truth = instances_from_scene(scene)
    counts = Counter(slug(o.label) for o in truth)
    out = []
    walls = [(b.lo - 0.01, b.hi + 0.01) for b in scene.obstacles]
    for o in truth:
        lo, hi = np.subtract(o.center, np.divide(o.size, 2)), np.add(o.center, np.divide(o.size, 2))
        if counts[slug(o.label)] != 1 or any(np.all(lo >= a) and np.all(hi <= b) for a, b in walls):
            continue
        r = search_referents(scene, f'F near[{slug(o.label)}]', start, replace(params, max_moves=0))
        if r.sought:
            out.append(o)
    return out


def seek(scene: Scene, start: Pose, obj: Instance, params: SearchParams) -> Case:
    """Seek one referent three ways."""
    name = slug(obj.label)
    correct, travel, views = {}, {}, {}
    for strategy in ('gain', 'nearest'):
        r = search_referents(scene, f'F near[{name}]', start, replace(params, strategy=strategy))
        g = r.referent_map.get(name)
        correct[strategy] = _correct(scene, obj, g.outcome, g.instances, r.semantic_map.params.voxel_size)
        travel[strategy], views[strategy] = r.travel, len(r.views)
    o = oracle(scene, start, obj, params)
    travel['oracle'] = o if o is not None else float('nan')
    where = f'({start.position[0]:g}, {start.position[1]:g})'
    return Case(scene.name, where, name, correct, travel, views)


def absent(scene: Scene, start: Pose, params: SearchParams) -> list[tuple[str, str, bool, float]]:
    """Search for labels of no object: (label, strategy, ended NO_MATCH on a complete map, travel)."""
    out = []
    for name in ABSENT:
        for strategy in ('gain', 'nearest'):
            r = search_referents(scene, f'F near[{name}]', start, replace(params, strategy=strategy))
            ok = r.referent_map.get(name).outcome == Outcome.NO_MATCH and r.complete
            out.append((name, strategy, ok, r.travel))
    return out


def _scene(name: str) -> Scene:
    return office_variant(0) if name == 'two_room_office' else resolve_scene(name)


def _starts(scene: Scene, every: bool) -> list[Pose]:
    """The scene's start and, with ``every``, one in each other room (apartment, office)."""
    out = [Pose(tuple(float(v) for v in scene.robot.start), 0.0)]  # type: ignore[arg-type]
    if every:
        out += [Pose((x, y, 0.0), 0.0) for x, y in EXTRA_STARTS.get(scene.name, ())]
    return out


def _print_case(c: Case) -> None:
    t = c.travel
    print(f'    {c.start}  {c.referent:<16} '
          f'gain {t["gain"]:5.1f} m ({"ok" if c.correct["gain"] else "WRONG"}), '
          f'nearest {t["nearest"]:5.1f} m ({"ok" if c.correct["nearest"] else "WRONG"}), '
          f'oracle {t["oracle"]:5.1f} m; views {c.views["gain"]} / {c.views["nearest"]}')


def _summary(cases: Sequence[Case], label: str) -> dict:
    """Correct counts, total and median travel of each way, over cases with an oracle."""
    with_oracle = [c for c in cases if np.isfinite(c.travel['oracle'])]
    total = {k: sum(c.travel[k] for c in with_oracle) for k in ('gain', 'nearest', 'oracle')}
    med = {k: statistics.median([c.travel[k] for c in with_oracle]) if with_oracle else float('nan')
           for k in total}
    ok = {k: sum(c.correct[k] for c in cases) for k in ('gain', 'nearest')}
    within = sum(c.travel['gain'] <= TRAVEL_TARGET * c.travel['oracle'] + 1e-9 for c in with_oracle)
    print(f'{label}: {len(cases)} referents not resolved from the start; correct: '
          f'gain {ok["gain"]}/{len(cases)}, nearest {ok["nearest"]}/{len(cases)}')
    print(f'  travel total (median) over {len(with_oracle)} with an oracle: gain {total["gain"]:.1f} m '
          f'({med["gain"]:.1f}), nearest {total["nearest"]:.1f} m ({med["nearest"]:.1f}), '
          f'oracle {total["oracle"]:.1f} m ({med["oracle"]:.1f}); '
          f'gain/oracle {total["gain"] / total["oracle"]:.2f}, '
          f'gain/nearest {total["gain"] / total["nearest"]:.2f}; '
          f'gain within {TRAVEL_TARGET:.0f}x oracle {within}/{len(with_oracle)}')
    return {'n': len(cases), 'ok': ok['gain'], 'total': total}


def main(argv: list[str]) -> int:
    """Print the figures; 1 when a target is missed."""
    ap = argparse.ArgumentParser(prog='bench.search')
    ap.add_argument('--scene', action='append', default=[],
                    help='apartment, two_room_office or a scene file (default: the first two)')
    ap.add_argument('--limit', type=int, default=0, help='at most this many referents per scene (0: all)')
    ap.add_argument('--verbose', action='store_true', help='a line per referent')
    ap.add_argument('--every-start', action='store_true',
                    help="also start in each other room (default: the scene's start only; slow)")
    args = ap.parse_args(argv)
    params = SearchParams()
    cases: list[Case] = []
    absents: list[tuple[str, str, bool, float]] = []
    for name in args.scene or ['apartment', 'two_room_office']:
        t0 = time.perf_counter()
        scene = _scene(name)
        mine, gone = [], []
        for start in _starts(scene, args.every_start):
            for obj in hidden_referents(scene, start, params)[:args.limit or None]:
                mine.append(seek(scene, start, obj, params))
                if args.verbose:
                    _print_case(mine[-1])
            gone += absent(scene, start, params)
        _summary(mine, scene.name)
        print(f'  absent referents NO_MATCH after a complete search: {sum(a[2] for a in gone)}/{len(gone)} '
              f'(travel {", ".join(f"{a[0]}/{a[1]} {a[3]:.1f} m" for a in gone)}); '
              f'{time.perf_counter() - t0:.0f} s')
        cases += mine
        absents += gone
    s = _summary(cases, 'all')
    print(f'  absent referents NO_MATCH: {sum(a[2] for a in absents)}/{len(absents)}')
    missed = (s['ok'] < CORRECT_TARGET * s['n'] or not all(a[2] for a in absents)
              or s['total']['gain'] > TRAVEL_TARGET * s['total']['oracle']
              or s['total']['gain'] >= s['total']['nearest'])
    return 1 if missed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

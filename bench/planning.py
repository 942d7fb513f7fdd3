"""Task and motion planning: a generated suite of (scene, formula) tasks, ground and drone.

Run: ``.venv/bin/python -m bench.planning [--quick] [--seed N] [--json out/bench_planning.json]``.

Scenes are generated in code (seeded): ground rooms with walls (free space checked to be
connected), labelled solid objects spaced so that no object's nearness region closes a
passage, a duplicated label (two instances), a pick-up object, and sometimes a sealed
vault; drone worlds with buildings that block every altitude, towers, trees below the
altitude band and antennas. Tasks cover the mission patterns (visit, sequenced and
ordered visits, global and scoped avoidance, avoid-until, either-or, exactly once / at
most once, pick-and-place) and unsatisfiable ones (automaton-level, an empty goal
region, an unreachable object, a release without a pick).

Figures (issue 3 targets):
- satisfiable tasks solved with verified plans (target 100 %); unsatisfiable ones
  reported as a typed error, never a plan (target 100 %);
- median planning time per task, ground scenes, 5,000 samples (target < 1 s);
- path length / fine-grid optimum per segment (8-connected, 5 cm cells, same
  constraints; drones: 26-connected 10 cm cells) (target median <= 1.05);
- FMT* against OMPL's RRT* given the same time per segment, in the same run (raw planner
  paths, no shortcutting, so the planners themselves are compared);
- goal depth: how far inside its goal region [m] each navigation step ends (issue 21: a
  controller that stops a little short must still complete the task), least and median
  over every endpoint.

``--builtin`` runs representative tasks (sequence, avoidance, until...) on the built-in
scenes (``apartment``, ``city_block``) instead of the generated suite.
"""
from __future__ import annotations

import argparse
import json
import math
import random
import statistics
import sys
import time
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Optional, Union

import numpy as np
from scipy import ndimage

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.planning import (
    FmtSettings, PlannerSettings, SegmentRequest, plan_task, solve_segment, world_from_scene,
)
from ltl_instruct.core.planning.grid import grid_optimum
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.planning.regions import RegionSet, key_cubes
from ltl_instruct.core.spec import parse_formula, referents_of
from ltl_instruct.core.world import near
from ltl_instruct.core.world.builtin import builtin_scene_path
from ltl_instruct.core.world.scene import Scene, load_scene, scene_from_dict, slug

GROUND_LABELS = ['sofa', 'table', 'lamp', 'plant', 'desk', 'shelf', 'tv', 'bed', 'fridge', 'piano']
DRONE_LABELS = ['tower', 'mast', 'crane', 'chimney', 'billboard', 'water tank']


# --------------------------------------------------------------------------- scenes

def _far_from(p: np.ndarray, others: list[np.ndarray], d: float) -> bool:
    return all(np.linalg.norm(p[:2] - q[:2]) >= d for q in others)


def _box_gap(p: np.ndarray, box: dict) -> float:
    return float(near.box_distance(p, np.asarray([box['center']]), np.asarray([box['size']]), 2)[0])


def _connected(scene: Scene, world: PlanningWorld, cell: float = 0.1) -> np.ndarray:
    """Label image of the free space at ``cell`` [m] (2D projection), and its grid axes."""
    lo = np.asarray(world.bounds_min[:2])
    hi = np.asarray(world.bounds_max[:2])
    xs = np.arange(lo[0], hi[0], cell)
    ys = np.arange(lo[1], hi[1], cell)
    gx, gy = np.meshgrid(xs, ys, indexing='ij')
    pts = np.column_stack([gx.ravel(), gy.ravel()])
    if world.dims == 3:
        pts = np.column_stack([pts, np.full(len(pts), (world.bounds_min[2] + world.bounds_max[2]) / 2)])
    free = world.is_free(pts).reshape(gx.shape)
    labels, _ = ndimage.label(free)
    return labels, xs, ys


def ground_scene(rng: random.Random, index: int, vault: bool) -> Optional[dict]:
    """Generate a 16 m x 12 m room with walls, objects and a start; None if it fails the checks."""
    w, h = 16.0, 12.0
    obstacles: list[dict] = []
    for _ in range(2):
        length = rng.uniform(3.0, 5.5)
        if rng.random() < 0.5:
            c = [rng.uniform(3, w - 3), rng.uniform(1.5 + length / 2, h - 1.5 - length / 2), 1.0]
            size = [0.2, length, 2.0]
        else:
            c = [rng.uniform(1.5 + length / 2, w - 1.5 - length / 2), rng.uniform(3, h - 3), 1.0]
            size = [length, 0.2, 2.0]
        obstacles.append({'center': [round(v, 2) for v in c], 'size': [round(v, 2) for v in size]})
    objects: list[dict] = []
    if vault:  # a sealed room in a corner holding the safe
        cx, cy = 1.6, h - 1.6
        for c, s in (([cx, cy + 1.2], [2.6, 0.2]), ([cx, cy - 1.2], [2.6, 0.2]),
                     ([cx - 1.2, cy], [0.2, 2.6]), ([cx + 1.2, cy], [0.2, 2.6])):
            obstacles.append({'center': c + [1.0], 'size': s + [2.0]})
        objects.append({'label': 'safe', 'center': [cx, cy, 0.3], 'size': [0.4, 0.4, 0.6]})
    placed: list[np.ndarray] = []
    labels = rng.sample(GROUND_LABELS, 4) + ['chair', 'chair', 'cup']
    for label in labels:
        for _ in range(400):
            p = np.array([rng.uniform(1.8, w - 1.8), rng.uniform(1.8, h - 1.8)])
            if _far_from(p, placed, 3.4) and all(_box_gap(p, o) >= 2.5 for o in obstacles):
                break
        else:
            return None
        placed.append(p)
        if label == 'cup':
            objects.append({'label': 'cup', 'center': [round(p[0], 2), round(p[1], 2), 0.4],
                            'size': [0.15, 0.15, 0.15], 'passable': True})
        else:
            s = [round(rng.uniform(0.4, 1.0), 2), round(rng.uniform(0.4, 1.0), 2), 0.8]
            objects.append({'label': label, 'center': [round(p[0], 2), round(p[1], 2), 0.4], 'size': s})
    for _ in range(400):
        start = np.array([rng.uniform(0.8, w - 0.8), rng.uniform(0.8, h - 0.8)])
        if _far_from(start, placed, 2.6) and all(_box_gap(start, o) >= 0.8 for o in obstacles):
            break
    else:
        return None
    d = {'name': f'ground_{index}', 'bounds': {'min': [0, 0, 0], 'max': [w, h, 3]},
         'robot': {'kind': 'ground', 'start': [round(start[0], 2), round(start[1], 2), 0.0], 'radius': 0.3},
         'obstacles': obstacles, 'objects': objects}
    return d if _reachable(d) else None


def drone_scene(rng: random.Random, index: int) -> Optional[dict]:
    """Generate a 14 m x 10 m x 5 m block with buildings, objects and a start in the altitude band."""
    w, h = 14.0, 10.0
    obstacles = []
    for _ in range(2):
        fx, fy = rng.uniform(1.0, 2.5), rng.uniform(1.0, 3.0)
        c = [rng.uniform(3, w - 3), rng.uniform(2.5, h - 2.5), 2.5]
        obstacles.append({'center': [round(v, 2) for v in c], 'size': [round(fx, 2), round(fy, 2), 5.0]})
    objects: list[dict] = []
    placed: list[np.ndarray] = []
    labels = rng.sample(DRONE_LABELS, 3) + ['tree', 'antenna', 'parcel']
    for label in labels:
        for _ in range(400):
            p = np.array([rng.uniform(1.8, w - 1.8), rng.uniform(1.8, h - 1.8)])
            if _far_from(p, placed, 3.2) and all(_box_gap(p, o) >= 2.4 for o in obstacles):
                break
        else:
            return None
        placed.append(p)
        if label == 'tree':
            objects.append({'label': 'tree', 'center': [round(p[0], 2), round(p[1], 2), 0.4],
                            'size': [1, 1, 0.8]})
        elif label == 'antenna':
            objects.append({'label': 'antenna', 'center': [round(p[0], 2), round(p[1], 2), 2.0],
                            'size': [0.2, 0.2, 0.4], 'passable': True})
        elif label == 'parcel':
            objects.append({'label': 'parcel', 'center': [round(p[0], 2), round(p[1], 2), 1.2],
                            'size': [0.3, 0.3, 0.3], 'passable': True})
        else:
            objects.append({'label': label, 'center': [round(p[0], 2), round(p[1], 2), 2.0],
                            'size': [round(rng.uniform(0.4, 1.0), 2), round(rng.uniform(0.4, 1.0), 2), 4.0]})
    for _ in range(400):
        start = np.array([rng.uniform(0.8, w - 0.8), rng.uniform(0.8, h - 0.8)])
        if _far_from(start, placed, 2.6) and all(_box_gap(start, o) >= 0.8 for o in obstacles):
            break
    else:
        return None
    d = {'name': f'drone_{index}', 'bounds': {'min': [0, 0, 0], 'max': [w, h, 5]},
         'robot': {'kind': 'drone', 'start': [round(start[0], 2), round(start[1], 2), 2.0], 'radius': 0.25},
         'altitude': {'min': 1.0, 'max': 3.5}, 'obstacles': obstacles, 'objects': objects}
    return d if _reachable(d) else None


def _reachable(d: dict) -> bool:
    """Every object but the safe has free space within 1 m of it connected to the start."""
    scene = scene_from_dict(d)
    world = world_from_scene(scene)
    labels, xs, ys = _connected(scene, world)
    sx = int(np.argmin(np.abs(xs - scene.robot.start[0])))
    sy = int(np.argmin(np.abs(ys - scene.robot.start[1])))
    comp = labels[sx, sy]
    if comp == 0:
        return False
    gx, gy = np.meshgrid(xs, ys, indexing='ij')
    for o in scene.objects:
        if o.label == 'safe':
            continue
        near = (np.hypot(gx - o.center[0], gy - o.center[1]) <= 1.2) & (labels == comp)
        if not near.any():
            return False
    return True


# --------------------------------------------------------------------------- tasks

@dataclass(frozen=True)
class Task:
    """One benchmark task: a scene (generated as a dict, or built in), a formula, its pattern, satisfiable."""

    scene: Union[dict, Scene]
    formula: str
    pattern: str
    satisfiable: bool


def _once(x: str) -> str:
    """At most one visit to ``x``: never near it, away, then near it again."""
    return f'!F (near[{x}] & F (!near[{x}] & F near[{x}]))'


def ground_tasks(scene: dict, rng: random.Random) -> list[Task]:
    """List the mission patterns over the scene's objects."""
    names = [slug(o['label']) for o in scene['objects'] if o['label'] not in ('cup', 'safe', 'chair')]
    a, b, c, d = rng.sample(names, 4)
    t = [
        ('visit', f'F near[{a}]', True),
        ('visit-any-instance', 'F near[chair]', True),
        ('sequenced-visit', f'F near[{a}] & F near[{b}] & F near[{c}]', True),
        ('ordered-visit', f'F (near[{a}] & F (near[{b}] & F near[{c}]))', True),
        ('strictly-ordered', f'F (near[{a}] & F near[{b}]) & (!near[{b}] U near[{a}])', True),
        ('global-avoidance', f'F (near[{a}] & F near[{b}]) & G !near[{c}]', True),
        ('global-avoidance-2', f'F near[{a}] & G !near[{c}] & G !near[{d}]', True),
        ('scoped-avoidance', f'F (near[{a}] & F near[{b}]) & G (near[{a}] -> G !near[chair])', True),
        ('avoid-until', f'!near[{c}] U near[{a}]', True),
        ('avoid-until-then', f'(!near[{b}] U near[{a}]) & F near[{b}]', True),
        ('either-or', f'F near[{a}] | F near[{b}]', True),
        ('either-or-avoid', f'F (near[{a}] | near[{b}]) & G !near[{c}]', True),
        ('exactly-once', f'F (near[{a}] & F near[{b}]) & {_once(a)}', True),
        ('at-most-once', f'F near[{b}] & F near[{c}] & {_once("chair")}', True),
        ('pick-and-place', f'F (pick[cup] & F release[cup, {a}])', True),
        ('pick-and-place-avoid', f'F (near[cup] & F (pick[cup] & F release[cup, {b}])) & G !near[{c}]', True),
        ('unsat-automaton', f'F near[{a}] & G !near[{a}]', False),
        ('unsat-empty-goal', f'F (near[{a}] & near[{b}])', False),
        ('unsat-release-first', f'F release[cup, {a}] & G !pick[cup]', False),
    ]
    if any(o['label'] == 'safe' for o in scene['objects']):
        t.append(('unsat-unreachable', 'F near[safe]', False))
    return [Task(scene, f, p, s) for p, f, s in t]


def drone_tasks(scene: dict, rng: random.Random) -> list[Task]:
    """List the mission patterns for a drone."""
    names = [slug(o['label']) for o in scene['objects'] if o['label'] not in ('tree', 'antenna', 'parcel')]
    a, b, c = rng.sample(names, 3)
    t = [
        ('visit', f'F near[{a}]', True),
        ('visit-low', 'F near[tree]', True),
        ('ordered-visit', f'F (near[{a}] & F (near[{b}] & F near[{c}]))', True),
        ('global-avoidance', f'F (near[{a}] & F near[{b}]) & G !near[antenna]', True),
        ('avoid-until', f'!near[{b}] U near[{a}]', True),
        ('either-or', f'F near[{a}] | F near[{c}]', True),
        ('exactly-once', f'F (near[{a}] & F near[{b}]) & {_once(a)}', True),
        ('delivery', f'F (pick[parcel] & F release[parcel, {c}]) & G !near[antenna]', True),
        ('unsat-automaton', f'F near[{a}] & G !near[{a}]', False),
        ('unsat-empty-goal', f'F (near[{a}] & near[{b}])', False),
    ]
    return [Task(scene, f, p, s) for p, f, s in t]


BUILTIN_TASKS = {
    'apartment': [
        ('visit', 'F near[fridge]'),
        ('ordered-visit', 'F (near[bed] & F (near[fridge] & F near[desk]))'),
        ('global-avoidance', 'F near[computer] & G !near[door]'),
        ('scoped-avoidance', 'F (near[tv] & F near[stove]) & G (near[tv] -> G !near[table])'),
        ('avoid-until', '!near[rug] U near[bookshelf]'),
        ('avoid-until-then', '(!near[pillar] U near[lamp]) & F near[pillar]'),
        ('either-or', 'F near[printer] | F near[nightstand]'),
        ('pick-and-place', 'F (pick[red_ball] & F release[red_ball, coffee_table])'),
    ],
    'city_block': [
        ('visit', 'F near[fountain]'),
        ('ordered-visit', 'F (near[bank] & F near[statue])'),
        ('global-avoidance', 'F near[library] & G !near[tower]'),
        ('avoid-until', '!near[fountain] U near[bus_stop]'),
    ],
}


def builtin_suite() -> list[Task]:
    """Representative tasks on the built-in scenes (all satisfiable)."""
    tasks = []
    for name, patterns in BUILTIN_TASKS.items():
        scene = load_scene(builtin_scene_path(name))
        tasks += [Task(scene, f, p, True) for p, f in patterns]
    return tasks


def goal_depths(plan: Any) -> list[float]:
    """How deep [m] each navigation step ends inside its goal's near regions.

    For the goal cubes the endpoint satisfies: the least depth (threshold - distance to
    the box) over the cube's near atoms, the best cube counting. Steps whose goal has no
    near atom to be near (only regions to leave) give nothing.
    """
    out = []
    for step in plan.steps:
        req = step.request
        if step.kind != 'navigate' or req is None:
            continue
        regions = RegionSet(req.regions, req.dims)
        end = np.asarray(step.end, dtype=float)[None]
        letter = regions.letter_and_margin(tuple(step.end))[0]
        best = None
        for pos, neg in key_cubes(req.goal):
            if not pos or not pos <= letter or neg & letter:
                continue
            depth = min(regions.by_key[k].radius - float(regions.by_key[k].distance(end, req.dims)[0])
                        for k in pos)
            best = depth if best is None else max(best, depth)
        if best is not None:
            out.append(best)
    return out


def referent_map(scene: Scene, formula) -> ReferentMap:
    """Exact label match (every sofa matches ``sofa``)."""
    g = {}
    for d in referents_of(formula):
        inst = tuple(Instance(o.id, o.label, o.center, o.size or (0.0, 0.0, 0.0)) for o in scene.objects
                     if slug(o.label) == d.name or slug(o.label).endswith('_' + d.name))
        g[str(d)] = Grounding(str(d), Outcome.RESOLVED if len(inst) == 1 else Outcome.AMBIGUOUS, inst)
    return ReferentMap(g)


def build_suite(seed: int, n_ground: int, n_drone: int) -> list[Task]:
    """Generate the scenes and their tasks."""
    rng = random.Random(seed)
    tasks: list[Task] = []
    made = 0
    while made < n_ground:
        d = ground_scene(rng, made, vault=made % 3 == 0)
        if d is not None:
            tasks += ground_tasks(d, rng)
            made += 1
    made = 0
    while made < n_drone:
        d = drone_scene(rng, made)
        if d is not None:
            tasks += drone_tasks(d, rng)
            made += 1
    return tasks


# --------------------------------------------------------------------------- running

def _median(xs: list[float]) -> float:
    return statistics.median(xs) if xs else float('nan')


def _pct(xs: list[float], q: float) -> float:
    return float(np.percentile(xs, q)) if xs else float('nan')


def compare_rrtstar(req: SegmentRequest, world: PlanningWorld, settings: FmtSettings) -> dict[str, Any]:
    """Run FMT* and RRT* on one segment, RRT* given FMT*'s time: raw paths, then both shortcut."""
    raw = replace(settings, simplify=False, direct=False)   # the planners' own paths and times
    fmt = solve_segment(req, world, raw)
    budget = max(fmt.planner_seconds, 0.05)
    rrt = solve_segment(req, world, replace(raw, planner='rrtstar', time_limit=budget))
    fmt_s = solve_segment(req, world, settings)
    rrt_s = solve_segment(req, world, replace(settings, planner='rrtstar', time_limit=budget))
    return {'fmt_ok': fmt.ok, 'fmt_length': fmt.length, 'fmt_s': fmt.planner_seconds,
            'rrt_ok': rrt.ok, 'rrt_length': rrt.length, 'rrt_s': rrt.planner_seconds,
            'fmt_short_ok': fmt_s.ok, 'fmt_short_length': fmt_s.length,
            'rrt_short_ok': rrt_s.ok, 'rrt_short_length': rrt_s.length}


def run(tasks: list[Task], samples: int, grid_limit: int, drone_grid_limit: int, rrt_limit: int,
        log: bool) -> dict[str, Any]:
    """Plan every task; measure outcome, time, optimality and the RRT* comparison."""
    settings = PlannerSettings(fmt=FmtSettings(num_samples=samples, seed=0))
    rows = []
    grid_done = 0
    drone_grid_done = 0
    rrt_done = 0
    for i, task in enumerate(tasks):
        scene = task.scene if isinstance(task.scene, Scene) else scene_from_dict(task.scene)
        world = world_from_scene(scene)
        formula = parse_formula(task.formula)
        row: dict[str, Any] = {'scene': scene.name, 'kind': scene.robot.kind, 'pattern': task.pattern,
                               'formula': task.formula, 'satisfiable': task.satisfiable}
        t0 = time.perf_counter()
        try:
            aut = compile_automaton(formula)
            plan = plan_task(aut, referent_map(scene, formula), world, scene.robot.start, settings)
            row.update(planned=True, verified=plan.verification.ok, seconds=time.perf_counter() - t0,
                       length=plan.length, steps=len(plan.steps), segments=plan.stats['segments_solved'],
                       goal_depths=goal_depths(plan), warnings=list(plan.warnings))
            ratios = []
            for step in plan.steps:
                if step.kind != 'navigate' or step.request is None or step.length <= 0.05:
                    continue
                opt = None
                if world.dims == 2 and grid_done < grid_limit:
                    opt = grid_optimum(step.request, world, cell=0.05)
                    grid_done += 1
                elif world.dims == 3 and drone_grid_done < drone_grid_limit:
                    opt = grid_optimum(step.request, world, cell=0.1)
                    drone_grid_done += 1
                if opt is not None and opt > 0:
                    ratios.append(step.length / opt)
                if rrt_done < rrt_limit and world.dims == 2:
                    row.setdefault('rrt', []).append(compare_rrtstar(step.request, world, settings.fmt))
                    rrt_done += 1
            row['ratios'] = ratios
        except LtlInstructError as e:
            row.update(planned=False, verified=False, seconds=time.perf_counter() - t0, code=e.code.value,
                       message=e.message[:300])
        rows.append(row)
        if log:
            tag = 'ok' if row['planned'] else row.get('code')
            good = row['planned'] == task.satisfiable
            print(f'[{i + 1:3d}/{len(tasks)}] {scene.name:10s} {task.pattern:22s} {tag:15s} '
                  f'{row["seconds"]:.2f} s {"" if good else "  <-- UNEXPECTED"}', flush=True)
    return summarise(rows, samples)


def summarise(rows: list[dict[str, Any]], samples: int) -> dict[str, Any]:
    """Compute the figures of the issue's targets."""
    sat = [r for r in rows if r['satisfiable']]
    unsat = [r for r in rows if not r['satisfiable']]
    solved = [r for r in sat if r['planned'] and r['verified']]
    refused = [r for r in unsat if not r['planned']]
    ground_t = [r['seconds'] for r in rows if r['kind'] == 'ground' and r['satisfiable'] and r['planned']]
    drone_t = [r['seconds'] for r in rows if r['kind'] == 'drone' and r['satisfiable'] and r['planned']]
    all_ground_t = [r['seconds'] for r in rows if r['kind'] == 'ground']
    ratios_g = [x for r in rows if r['kind'] == 'ground' for x in r.get('ratios', [])]
    ratios_d = [x for r in rows if r['kind'] == 'drone' for x in r.get('ratios', [])]
    rrt = [c for r in rows for c in r.get('rrt', [])]
    both = [c for c in rrt if c['fmt_ok'] and c['rrt_ok']]
    patterns = sorted({r['pattern'] for r in rows})
    depths = [x for r in rows for x in r.get('goal_depths', [])]
    return {
        'tasks': len(rows), 'satisfiable': len(sat), 'unsatisfiable': len(unsat), 'samples': samples,
        'patterns': patterns,
        'solved_verified': len(solved), 'solved_pct': 100.0 * len(solved) / max(1, len(sat)),
        'unsat_reported': len(refused), 'unsat_pct': 100.0 * len(refused) / max(1, len(unsat)),
        'unsat_codes': sorted({r.get('code', '') for r in refused}),
        'failed_sat': [{k: r.get(k) for k in ('scene', 'pattern', 'formula', 'code', 'message')}
                       for r in sat if not (r['planned'] and r['verified'])],
        'wrongly_planned_unsat': [r['formula'] for r in unsat if r['planned']],
        'ground_median_s': _median(ground_t), 'ground_p90_s': _pct(ground_t, 90),
        'ground_max_s': max(ground_t) if ground_t else float('nan'),
        'ground_median_s_all_tasks': _median(all_ground_t),
        'drone_median_s': _median(drone_t), 'drone_p90_s': _pct(drone_t, 90),
        'ratio_ground_median': _median(ratios_g), 'ratio_ground_p90': _pct(ratios_g, 90),
        'ratio_ground_n': len(ratios_g),
        'ratio_drone_median': _median(ratios_d), 'ratio_drone_p90': _pct(ratios_d, 90),
        'ratio_drone_n': len(ratios_d),
        'rrt_segments': len(rrt),
        'fmt_success_pct': 100.0 * sum(c['fmt_ok'] for c in rrt) / max(1, len(rrt)),
        'rrt_success_pct': 100.0 * sum(c['rrt_ok'] for c in rrt) / max(1, len(rrt)),
        'rrt_over_fmt_length_median': _median([c['rrt_length'] / c['fmt_length'] for c in both
                                               if c['fmt_length'] > 0]),
        'fmt_time_median_s': _median([c['fmt_s'] for c in rrt]),
        'rrt_short_success_pct': 100.0 * sum(c['rrt_short_ok'] for c in rrt) / max(1, len(rrt)),
        'rrt_over_fmt_shortcut_length_median': _median([
            c['rrt_short_length'] / c['fmt_short_length'] for c in rrt
            if c['fmt_short_ok'] and c['rrt_short_ok'] and c['fmt_short_length'] > 0]),
        'goal_depth_min': min(depths) if depths else float('nan'), 'goal_depth_median': _median(depths),
        'goal_endpoints': len(depths), 'plans_with_warnings': sum(bool(r.get('warnings')) for r in rows),
        'total_length_solved': sum(r['length'] for r in solved),
        'rows': [{k: r.get(k) for k in ('scene', 'pattern', 'formula', 'planned', 'seconds', 'length',
                                        'goal_depths', 'warnings')} for r in rows],
    }


def print_summary(s: dict[str, Any]) -> None:
    """Print the figures."""
    print(f"tasks: {s['tasks']} ({s['satisfiable']} satisfiable, {s['unsatisfiable']} unsatisfiable), "
          f"{len(s['patterns'])} patterns, FMT* {s['samples']} samples")
    print(f"satisfiable solved with verified plans: {s['solved_verified']}/{s['satisfiable']} "
          f"= {s['solved_pct']:.1f} %  (target 100 %)")
    print(f"unsatisfiable reported as typed errors: {s['unsat_reported']}/{s['unsatisfiable']} "
          f"= {s['unsat_pct']:.1f} %  (target 100 %; codes {', '.join(s['unsat_codes'])})")
    print(f"ground planning time per task: median {s['ground_median_s']:.3f} s, "
          f"p90 {s['ground_p90_s']:.3f} s, "
          f"max {s['ground_max_s']:.3f} s  (target median < 1 s)")
    print(f"drone planning time per task: median {s['drone_median_s']:.3f} s, p90 {s['drone_p90_s']:.3f} s")
    print(f"path length / grid optimum, ground (5 cm, 8-connected): median {s['ratio_ground_median']:.3f}, "
          f"p90 {s['ratio_ground_p90']:.3f} over {s['ratio_ground_n']} segments  (target median <= 1.05)")
    print(f"path length / grid optimum, drone (10 cm, 26-connected): median {s['ratio_drone_median']:.3f}, "
          f"p90 {s['ratio_drone_p90']:.3f} over {s['ratio_drone_n']} segments")
    print(f"FMT* vs RRT* with FMT*'s time, {s['rrt_segments']} ground segments, raw paths: success "
          f"{s['fmt_success_pct']:.1f} % vs {s['rrt_success_pct']:.1f} %; RRT*/FMT* length median "
          f"{s['rrt_over_fmt_length_median']:.3f}; FMT* time median {s['fmt_time_median_s']:.3f} s")
    print(f"  both shortcut as in plans: RRT* success {s['rrt_short_success_pct']:.1f} %, RRT*/FMT* length "
          f"median {s['rrt_over_fmt_shortcut_length_median']:.3f}")
    print(f"goal depth of navigation endpoints: least {s['goal_depth_min']:.4f} m, median "
          f"{s['goal_depth_median']:.4f} m over {s['goal_endpoints']} endpoints; total path length of "
          f"solved tasks {s['total_length_solved']:.1f} m; plans with warnings (a margin not kept) "
          f"{s['plans_with_warnings']}")
    for f in s['failed_sat']:
        print(f"  not solved: {f['scene']} {f['pattern']}: {f['formula']} "
              f"[{f.get('code')}] {f.get('message')}")
    for f in s['wrongly_planned_unsat']:
        print(f'  planned although unsatisfiable: {f}')


def main(argv: list[str]) -> int:
    """Entry point: ``python -m bench.planning``."""
    ap = argparse.ArgumentParser(prog='bench.planning', description=__doc__.split('\n')[0])
    ap.add_argument('--seed', type=int, default=7)
    ap.add_argument('--ground', type=int, default=9, help='ground scenes (about 19 tasks each)')
    ap.add_argument('--drone', type=int, default=5, help='drone scenes (10 tasks each)')
    ap.add_argument('--samples', type=int, default=5000)
    ap.add_argument('--grid-limit', type=int, default=10_000, help='ground segments compared with the grid')
    ap.add_argument('--drone-grid-limit', type=int, default=20,
                    help='drone segments compared with the 3D grid (about 7 s each)')
    ap.add_argument('--rrt-limit', type=int, default=150, help='ground segments compared with RRT*')
    ap.add_argument('--quick', action='store_true', help='2 ground + 1 drone scenes, fewer comparisons')
    ap.add_argument('--builtin', action='store_true', help='representative tasks on the built-in scenes')
    ap.add_argument('--json', default='out/bench_planning.json', help='where to write the figures')
    ap.add_argument('--verbose', action='store_true', help='one line per task')
    args = ap.parse_args(argv)
    if args.quick:
        args.ground, args.drone, args.grid_limit, args.drone_grid_limit, args.rrt_limit = 2, 1, 20, 3, 10
    t0 = time.perf_counter()
    if args.builtin:   # the city block is too large for a 10 cm 3D grid
        args.drone_grid_limit = 0
    tasks = builtin_suite() if args.builtin else build_suite(args.seed, args.ground, args.drone)
    summary = run(tasks, args.samples, args.grid_limit, args.drone_grid_limit, args.rrt_limit, args.verbose)
    summary['wall_s'] = round(time.perf_counter() - t0, 1)
    print_summary(summary)
    print(f"total wall time {summary['wall_s']} s")
    if args.json:
        write_json(summary, args.json)
    return 0 if summary['solved_pct'] == 100.0 and summary['unsat_pct'] == 100.0 else 1


def write_json(summary: dict, path: str) -> None:
    """Write a benchmark summary as JSON (NaN as null), creating the folder."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(summary, indent=2, default=lambda x: None if isinstance(x, float)
                              and math.isnan(x) else x))


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

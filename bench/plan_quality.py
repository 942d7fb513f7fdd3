"""Plans a person would draw (issue 22): path length and planning time, each beside its peer.

Run: ``.venv/bin/python -m bench.plan_quality [--tasks 100] [--seed 0] [--json out/bench_plan_quality.json]``.

Figures, each printed beside its peer measured in the same run:

- path length: 100 random reachable tasks on the built-in scenes (``apartment``,
  ``city_block``; random free start, random objects, four mission patterns), robot
  radius 0.3 m. Per task, the plan's length over the sum of each segment's grid optimum
  (``core/planning/grid.py``: the same free space, the robot a disc, the same margins,
  from the same segment start; 5 cm 8-connected cells in the apartment, 1 m
  26-connected in the city block). A task is kept when it plans and the grid finds
  every segment too; the others are counted.
- planning time per task (CPU seconds of this process: the shared machine's load
  inflates wall-clock times several fold; every planner here runs on one thread),
  beside OMPL's default planner (``SimpleSetup``'s choice,
  RRTConnect here) on the same segments with the same checks (its raw path, unshortened).
- the README's built-in tasks (``bench.planning.BUILTIN_TASKS``) and the demo's
  instruction on each built-in scene, planned in process as the nodes do (the demo's
  world is the simulator's 10 cm occupancy grid / 1 m cloud, 3,000 samples), 10 runs.
"""
from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from dataclasses import replace
from typing import Any, Optional

import numpy as np

from bench.planning import BUILTIN_TASKS, referent_map, write_json
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.planning import (
    FmtSettings, PlannerSettings, plan_task, solve_segment, world_from_scene,
)
from ltl_instruct.core.planning.grid import grid_optimum
from ltl_instruct.core.planning.occupancy import PlanningWorld
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.builtin import builtin_scene_path
from ltl_instruct.core.world.scene import Scene, load_scene, slug

RADIUS = 0.3
PATTERNS = (
    ('visit', 'F near[{a}]'),
    ('sequence', 'F (near[{a}] & F near[{b}])'),
    ('avoid', 'F near[{a}] & G !near[{b}]'),
    ('avoid-until', '!near[{b}] U near[{a}]'),
)
GRID_CELL = {2: 0.05, 3: 1.0}
DEMO_FORMULAS = {
    'apartment': 'F (near[sofa::isbehind(pillar)] & F near[computer]) & G !near[door]',
    'city_block': 'F (near[fountain] & F near[tower::isleftof(hotel)]) & G !near[bank]',
}


def _labels(scene: Scene) -> list[str]:
    """Labels of the scene's objects as propositions (each once)."""
    return sorted({slug(o.label) for o in scene.objects})


def _random_start(world: PlanningWorld, rng: random.Random) -> tuple[float, ...]:
    for _ in range(10_000):
        p = np.array([rng.uniform(world.bounds_min[k], world.bounds_max[k]) for k in range(world.dims)])
        if world.dims == 3:
            p[2] = rng.uniform(world.bounds_min[2], min(world.bounds_max[2], world.bounds_min[2] + 10.0))
        if world.is_free(p[None])[0]:
            return tuple(float(x) for x in p)
    raise RuntimeError('no free start found')


def random_tasks(n: int, seed: int) -> list[tuple[str, str, str, tuple[float, ...]]]:
    """Draw ``n`` (scene, pattern, formula, start) tasks: about 7 in 10 in the apartment."""
    rng = random.Random(seed)
    scenes = {name: load_scene(builtin_scene_path(name)) for name in ('apartment', 'city_block')}
    worlds = {name: world_from_scene(s, RADIUS) for name, s in scenes.items()}
    out = []
    for _ in range(n):
        name = 'apartment' if rng.random() < 0.7 else 'city_block'
        a, b = rng.sample(_labels(scenes[name]), 2)
        pattern, text = rng.choice(PATTERNS)
        out.append((name, pattern, text.format(a=a, b=b), _random_start(worlds[name], rng)))
    return out


def _median(xs: list[float]) -> float:
    return statistics.median(xs) if xs else float('nan')


def _default_planner_seconds(plan: Any, world: PlanningWorld, fmt: FmtSettings) -> Optional[float]:
    """CPU seconds OMPL's default planner takes on the plan's segments (None if one fails)."""
    c0 = time.process_time()
    for step in plan.steps:
        if step.kind != 'navigate' or step.request is None:
            continue
        res = solve_segment(step.request, world, replace(fmt, planner='default', simplify=False))
        if not res.ok:
            return None
    return time.process_time() - c0


def _grid_total(plan: Any, world: PlanningWorld) -> Optional[float]:
    """Sum of the segments' grid optima, each from the planner's segment start (None if one has none)."""
    total = 0.0
    for step in plan.steps:
        if step.kind != 'navigate' or step.request is None:
            continue
        opt = grid_optimum(step.request, world, cell=GRID_CELL[world.dims])
        if opt is None:
            return None
        total += opt
    return total


def run_random(n: int, seed: int, settings: PlannerSettings, log: bool) -> dict[str, Any]:
    """Plan the random tasks; length against the grid, time against OMPL's default planner."""
    scenes = {name: load_scene(builtin_scene_path(name)) for name in ('apartment', 'city_block')}
    worlds = {name: world_from_scene(s, RADIUS) for name, s in scenes.items()}
    rows = []
    for i, (name, pattern, text, start) in enumerate(random_tasks(n, seed)):
        scene, world = scenes[name], worlds[name]
        formula = parse_formula(text)
        row: dict[str, Any] = {'scene': name, 'pattern': pattern, 'formula': text, 'start': list(start)}
        t0, c0 = time.perf_counter(), time.process_time()
        try:
            plan = plan_task(compile_automaton(formula), referent_map(scene, formula), world, start, settings)
        except LtlInstructError as e:
            row.update(kept=False, why=e.code.value, seconds=time.perf_counter() - t0)
            rows.append(row)
            continue
        row['seconds'] = time.perf_counter() - t0
        row['cpu_s'] = time.process_time() - c0
        row['length'] = plan.length
        grid = _grid_total(plan, world)
        row['grid'] = grid
        row['kept'] = grid is not None and plan.length > 0.05
        row['why'] = '' if row['kept'] else ('no grid path' if grid is None else 'already there')
        row['ratio'] = plan.length / grid if row['kept'] and grid else None
        row['default_s'] = _default_planner_seconds(plan, world, settings.fmt)
        row['goal_depth_min'] = min((d for d in plan.verification.goal_depths if d is not None), default=None)
        rows.append(row)
        if log:
            print(f"[{i + 1:3d}] {name:10s} {pattern:12s} {row['cpu_s']:.2f} s  "
                  f"ratio {row['ratio'] if row['ratio'] is None else round(row['ratio'], 3)}  {text}",
                  flush=True)
    kept = [r for r in rows if r['kept']]
    ratios = [r['ratio'] for r in kept]
    ours = [r['cpu_s'] for r in kept]
    peer = [r['default_s'] for r in kept if r['default_s'] is not None]
    worst = max(kept, key=lambda r: r['ratio']) if kept else None
    depths = [r['goal_depth_min'] for r in kept if r['goal_depth_min'] is not None]
    return {'tasks': len(rows), 'kept': len(kept),
            'dropped': {w: sum(r['why'] == w for r in rows if not r['kept'])
                        for w in sorted({r['why'] for r in rows if not r['kept']})},
            'ratio_median': _median(ratios),
            'ratio_p90': float(np.percentile(ratios, 90)) if ratios else None,
            'ratio_max': max(ratios) if ratios else None,
            'worst': None if worst is None else {k: worst[k] for k in ('scene', 'formula', 'start', 'ratio')},
            'seconds_median': _median(ours), 'seconds_max': max(ours) if ours else None,
            'default_planner_seconds_median': _median(peer),
            'goal_depth_min': min(depths) if depths else None,
            'length_total': sum(r['length'] for r in kept), 'grid_total': sum(r['grid'] for r in kept),
            'rows': rows}


def _node_world(scene: Scene) -> PlanningWorld:
    """The world the ``fmt_planner`` node builds from the simulator's map of the scene."""
    from ltl_instruct import conversions as conv   # message types only; no node is started
    from ltl_instruct.core.world.robot import obstacle_points, rasterize_scene
    if scene.robot.dims == 2:
        return conv.planning_world_from_grid(conv.occupancy_grid_msg(rasterize_scene(scene, 0.1)), RADIUS)
    cloud = conv.point_cloud_msg(obstacle_points(scene, 1.0))
    w = world_from_scene(scene, RADIUS)
    lo = tuple(w.bounds_min) + (0.0,) * 0
    return conv.planning_world_from_cloud(cloud, 1.0, RADIUS, (lo, tuple(w.bounds_max)))


def run_named(runs: int, settings: PlannerSettings, node_settings: PlannerSettings) -> dict[str, Any]:
    """Time the README's built-in tasks and the demo's task (in process, as the nodes plan it)."""
    from ltl_instruct.commands.plan import scene_referent_map
    out: dict[str, Any] = {'builtin': [], 'demo': {}}
    for name, patterns in BUILTIN_TASKS.items():
        scene = load_scene(builtin_scene_path(name))
        world = world_from_scene(scene, RADIUS)
        for pattern, text in patterns:
            formula = parse_formula(text)
            aut = compile_automaton(formula)
            rmap = referent_map(scene, formula)
            times, peer, length = [], None, None
            for _ in range(3):
                c0 = time.process_time()
                plan = plan_task(aut, rmap, world, scene.robot.start, settings)
                times.append(time.process_time() - c0)
                length = plan.length
            peer = _default_planner_seconds(plan, world, settings.fmt)
            out['builtin'].append({'scene': name, 'pattern': pattern, 'formula': text,
                                   'seconds_median': _median(times), 'length': length,
                                   'default_planner_seconds': peer})
    for name, text in DEMO_FORMULAS.items():
        scene = load_scene(builtin_scene_path(name))
        world = _node_world(scene)
        formula = parse_formula(text)
        rmap = scene_referent_map(formula, scene)
        times = []
        for _ in range(runs):
            c0 = time.process_time()
            aut = compile_automaton(formula)
            plan = plan_task(aut, rmap, world, scene.robot.start, node_settings)
            times.append(time.process_time() - c0)
        out['demo'][name] = {'formula': text, 'seconds_median': _median(times), 'seconds_max': max(times),
                             'length': plan.length,
                             'default_planner_seconds':
                                 _default_planner_seconds(plan, world, node_settings.fmt)}
    return out


def print_summary(s: dict[str, Any]) -> None:
    """Print the figures beside their peers."""
    r = s['random']
    print(f"random reachable tasks on the built-in scenes (robot radius {RADIUS} m): {r['kept']} kept of "
          f"{r['tasks']} drawn (dropped: {r['dropped']})")
    print(f"  path length / grid optimum (same disc clearance and margins): median {r['ratio_median']:.3f}, "
          f"p90 {r['ratio_p90']:.3f}, worst {r['ratio_max']:.3f}  (targets <= 1.0, <= 1.10)")
    if r['worst']:
        print(f"    worst: {r['worst']['scene']} {r['worst']['formula']} from "
              f"({', '.join(f'{x:.2f}' for x in r['worst']['start'])})")
    print(f"  total length {r['length_total']:.1f} m vs grid {r['grid_total']:.1f} m")
    print(f"  planning CPU time per task: median {r['seconds_median']:.3f} s, max {r['seconds_max']:.3f} s; "
          f"OMPL default planner on the same segments (raw path): median "
          f"{r['default_planner_seconds_median']:.3f} s")
    print(f"  least goal depth {r['goal_depth_min']:.3f} m (goal margin 0.2 m)")
    print('built-in tasks (README), CPU s, median of 3, beside OMPL\'s default planner on the same segments:')
    for b in s['named']['builtin']:
        peer = b['default_planner_seconds']
        print(f"  {b['scene']:10s} {b['pattern']:18s} {b['seconds_median']:.3f} s  "
              f"(default planner {'-' if peer is None else f'{peer:.3f}'} s)  {b['length']:.1f} m")
    for name, d in s['named']['demo'].items():
        print(f"demo task in process ({name}, the node's world and settings): "
              f"CPU median {d['seconds_median']:.3f} s, "
              f"max {d['seconds_max']:.3f} s, {d['length']:.1f} m (default planner "
              f"{d['default_planner_seconds']:.3f} s)")


def main(argv: list[str]) -> int:
    """Entry point: ``python -m bench.plan_quality``."""
    ap = argparse.ArgumentParser(prog='bench.plan_quality', description=__doc__.split('\n')[0])
    ap.add_argument('--tasks', type=int, default=100)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--runs', type=int, default=10, help='runs of the demo task')
    ap.add_argument('--json', default='out/bench_plan_quality.json')
    ap.add_argument('--verbose', action='store_true')
    args = ap.parse_args(argv)
    settings = PlannerSettings(fmt=FmtSettings(num_samples=5000, seed=0))
    node = PlannerSettings(fmt=FmtSettings(num_samples=3000, time_limit=2.0, path_spacing=0.1, seed=0))
    t0 = time.perf_counter()
    summary = {'random': run_random(args.tasks, args.seed, settings, args.verbose),
               'named': run_named(args.runs, settings, node)}
    summary['wall_s'] = round(time.perf_counter() - t0, 1)
    print_summary(summary)
    print(f"total wall time {summary['wall_s']} s")
    if args.json:
        write_json(summary, args.json)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

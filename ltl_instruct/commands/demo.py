"""``ltl-instruct demo``: the whole system on a built-in scene, end to end.

Starts every node and the simulator as separate processes (on a private
``ROS_DOMAIN_ID``, localhost only), sends the instruction, shows the verification
text (accepted automatically unless ``--interactive``), waits for the verified plan,
lets the simulator execute it until the task is satisfied, writes a PNG of the map,
the regions and the driven path, and prints a short report.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, default_params_file, scene_overrides
from ltl_instruct.commands.plan import add_margin_arguments
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.core.world import near
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.scene import Scene

DEFAULT_INSTRUCTIONS = {
    'apartment': 'Go to the sofa behind the pillar, then go to the computer, '
                 'and never go near a door.',
    'city_block': 'Fly to the fountain, then to the tower left of the hotel, '
                  'and stay away from the bank.',
}
DEFAULT_OUT = Path('out') / 'demo.png'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``ltl-instruct demo``."""
    parser.add_argument('--scene', default='apartment',
                        help='built-in scene (apartment, city_block) or a scene file')
    parser.add_argument('--instruction', default=None, help='the English instruction')
    parser.add_argument('--formula', default=None,
                        help='give a task formula instead of English (skips translation)')
    parser.add_argument('--interactive', action='store_true',
                        help='ask before accepting the formula (otherwise it is accepted automatically)')
    parser.add_argument('--out', type=Path, default=DEFAULT_OUT, help='PNG to write (default out/demo.png)')
    parser.add_argument('--params', type=Path, default=None, help='ROS parameters file')
    parser.add_argument('--speed', type=float, default=4.0,
                        help='simulation speed-up: simulated seconds per second (default 4)')
    parser.add_argument('--timeout', type=float, default=120.0, help='give up after this many seconds')
    parser.add_argument('--log-dir', type=Path, default=None,
                        help='node logs (default: a temporary folder, named in the report)')
    parser.add_argument('--json', action='store_true', help='print the report as JSON')
    parser.add_argument('--search', action='store_true',
                        help='the grounder knows no objects: all come from the camera, and a referent not '
                             'in view is searched for (the picture shows the area seen and the search path)')
    add_margin_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """Run the demo; 0 when the task was satisfied, 1 when it failed, 2 on bad input."""
    scene = resolve_scene(args.scene)
    if args.out != DEFAULT_OUT:   # a path that cannot be written fails now, not after the run
        from ltl_instruct.core.planning.plot import check_output_path
        check_output_path(args.out)
    if not 0.1 <= args.speed <= 50.0:
        raise InvalidInputError('--speed must be within [0.1, 50]')
    margins = {'goal_margin': near.check_margin(args.goal_margin, '--goal-margin'),
               'avoid_margin': near.check_margin(args.avoid_margin, '--avoid-margin')}
    instruction = args.instruction
    if instruction is None and args.formula is None:
        instruction = DEFAULT_INSTRUCTIONS.get(scene.name, DEFAULT_INSTRUCTIONS['apartment'])
    params = args.params or default_params_file()
    log_dir = args.log_dir or Path(tempfile.mkdtemp(prefix='ltl_instruct_demo_'))
    # a private DDS domain on this host: the demo never talks to another robot
    os.environ['ROS_DOMAIN_ID'] = str(random.randint(1, 101))
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    overrides = scene_overrides(args.scene)
    overrides['sim_world']['time_scale'] = float(args.speed)
    overrides['task_progression'].update(margins)
    overrides['ltl_translator'] = {'require_confirmation': bool(args.interactive)}
    if scene.robot.kind == 'drone':
        overrides['sim_world']['max_speed'] = 4.0
    if args.search:
        overrides['referent_grounder'].update(scene='', use_camera=True, camera_min_interval=0.2)
        overrides['sim_world']['camera_rate_hz'] = 4.0
    from ltl_instruct.nodes.client import GraphClient   # rclpy only when the demo runs

    say = (lambda *a: None) if args.json else (lambda *a: print(*a, flush=True))
    say(f'Starting {len(ALL_NODES)} nodes on scene {scene.name!r} (logs: {log_dir}) ...')
    t_start = time.monotonic()
    graph = NodeGraph(ALL_NODES, Path(params), overrides, log_dir=log_dir).start()
    client = GraphClient('ltl_instruct_demo', record_odom=True)
    report: dict[str, Any] = {'scene': scene.name, 'instruction': instruction, 'logs': str(log_dir)}
    try:
        if not client.wait_for_graph(timeout=90.0, need_sim=True):
            raise LtlInstructError(f'the nodes did not come up (exited: {graph.dead()}); see {log_dir}',
                                   ErrorCode.TIMEOUT)
        report['startup_s'] = round(time.monotonic() - t_start, 2)
        status = _run_instruction(client, args, instruction, report, say)
    finally:
        client.close()
        graph.stop()
    out = _draw(scene, report, args.out)
    report['png'] = str(out)
    if args.json:
        print(json.dumps(report, indent=2, default=str))
    else:
        _print_report(report)
    return status


def _run_instruction(client: Any, args: argparse.Namespace, instruction: Optional[str],
                     report: dict[str, Any], say: Any) -> int:
    t0 = time.monotonic()
    iid = client.send(text=instruction, formula=args.formula)
    say(f'Instruction: {instruction or args.formula}')
    verification = client.wait_until(
        lambda: client.received.verifications.get(iid) or _failed(client, iid), 30.0)
    if verification and verification.get('schema') == 'ltl_instruct/verification_request':
        say('\nWhat the robot understood:')
        for line in str(verification.get('verification_text', '')).splitlines():
            say(f'  {line}')
        if args.interactive:
            answer = input('Accept this task? [y/N] ').strip().lower()
            client.reply(iid, answer in ('y', 'yes'))
        else:
            say('  (accepted automatically; use --interactive to confirm yourself)')
    status = client.wait_terminal(iid, timeout=args.timeout)
    _search_report(client, iid, report)
    report['id'] = iid
    report['terminal'] = status
    report['time_to_plan_s'] = round(time.monotonic() - t0, 3)
    spec = client.received.specs.get(iid) or {}
    report['formula'] = spec.get('formula') or status.get('formula')
    report['subgoals'] = (spec.get('description') or {}).get('subgoals', [])
    report['throughout'] = (spec.get('description') or {}).get('throughout', [])
    rmap = client.received.referent_maps.get(iid) or {}
    report['referents'] = {d: [i['id'] for i in g.get('instances', [])]
                           for d, g in ((rmap.get('referent_map') or {}).get('groundings') or {}).items()}
    report['referent_map'] = rmap.get('referent_map') or {}
    if status['status'] not in ('planned', 'satisfied'):   # failed (or cancelled)
        return 1
    if status['status'] == 'satisfied':
        report['execution'] = 'already satisfied at the start'
        return 0
    stamp = status.get('plan_stamp')
    plan = client.wait_until(lambda: client.received.plans.get(stamp), 10.0)
    report['plan'] = plan
    report['task_plan'] = client.received.task_plans.get(iid)
    say(f'\nPlan: {len(plan) if plan is not None else 0} poses; executing in the simulator ...')
    t1 = time.monotonic()
    # the execution's terminal status: satisfied, violated, failed (replans given up)
    done = client.wait_until(lambda: client.terminal(iid, phase='execution'),
                             max(args.timeout - (time.monotonic() - t0), 1.0))
    report['execution_s'] = round(time.monotonic() - t1, 2)
    report['driven'] = np.array([p for _, p in client.received.odom]) if client.received.odom else None
    report['skills'] = [r for r in client.received.skill_results if r.get('id') == iid]
    if done is None:
        report['execution'] = 'timed out before the task was satisfied'
        return 1
    report['execution'] = done['status']
    if done['status'] == 'violated':
        report['violation'] = (done.get('monitor') or {}).get('blamed_atoms')
    return 0 if done['status'] == 'satisfied' else 1


def _search_report(client: Any, iid: str, report: dict[str, Any]) -> None:
    """Keep what a search did: its last ``searching`` status, the path driven so far, the area seen."""
    looks = [s for s in client.received.statuses.get(iid, []) if s.get('status') == 'searching']
    if not looks:
        return
    report['search'] = {k: looks[-1].get(k) for k in ('sought', 'moves', 'travel_m', 'area_seen_m2')}
    report['search_driven'] = np.array([p for _, p in client.received.odom]) if client.received.odom else None
    if client.received.coverage is not None:
        from ltl_instruct import conversions as conv
        report['coverage'] = conv.coverage_from_msg(client.received.coverage)


def _failed(client: Any, iid: str) -> Optional[dict[str, Any]]:
    t = client.terminal(iid)
    return t if t is not None and t.get('status') == 'failed' else None


def _print_report(report: dict[str, Any]) -> None:
    term = report.get('terminal') or {}
    print('\n== ltl_instruct demo report ==')
    print(f'Scene:        {report["scene"]}')
    print(f'Instruction:  {report.get("instruction")}')
    print(f'Formula:      {report.get("formula")}')
    for line in report.get('subgoals', []) + report.get('throughout', []):
        print(f'              {line}')
    if report.get('referents'):
        print('Referents:    ' + '; '.join(f'{d} -> {", ".join(ids) or "nothing"}'
                                           for d, ids in report['referents'].items()))
    search = report.get('search')
    if search:
        print(f'Search:       for {", ".join(search["sought"] or ["-"])}: {search["moves"]} moves, '
              f'{search["travel_m"]} m, {search["area_seen_m2"]} m^2 seen')
    if term.get('status') == 'failed':
        err = term.get('error') or {}
        print(f'Result:       FAILED [{err.get("code")}] {err.get("message")}')
    else:
        plan = report.get('plan')
        if plan is not None and len(plan):
            length = float(np.sum(np.linalg.norm(np.diff(plan, axis=0), axis=1)))
            skills = term.get('num_skills', 0)
            print(f'Plan:         {len(plan)} poses, {length:.1f} m, {skills} skill step(s)')
        for warning in term.get('warnings') or []:
            print(f'Warning:      {warning}')
        for r in report.get('skills', []):
            what = f'{r["skill"]}[{", ".join(r.get("args", []))}]'
            outcome = 'done' if r.get('ok') else f'FAILED ({(r.get("error") or {}).get("message")})'
            print(f'Skill:        {what}: {outcome}')
        print(f'Execution:    {report.get("execution")}'
              + (f' (blamed: {report["violation"]})' if report.get('violation') else '')
              + (f' in {report["execution_s"]} s' if 'execution_s' in report else ''))
    timing = term.get('timing') or {}
    stages = ', '.join(f'{k.removesuffix("_s")} {v * 1000:.0f} ms' for k, v in timing.items()
                       if isinstance(v, (int, float)))
    print(f'Time:         instruction -> plan {report.get("time_to_plan_s", 0):.2f} s ({stages})')
    print(f'Picture:      {report.get("png")}')
    print(f'Node logs:    {report.get("logs")}')


def _avoided(formula: str) -> set[str]:
    """Return the descriptors a formula avoids (none for a formula that does not parse)."""
    from ltl_instruct.core.spec import avoided_referents_of, parse_formula
    try:
        return {str(d) for d in avoided_referents_of(parse_formula(formula))} if formula else set()
    except LtlInstructError:
        return set()


def _draw_regions(ax: Any, report: dict[str, Any], hi: np.ndarray) -> None:
    """Draw where each referent's near[x] holds (avoided ones red), as the planner evaluates it.

    Dashed inside a goal referent's region: where the plan's goal margin has it end.
    """
    nearness = (report.get('task_plan') or {}).get('nearness') or {}
    threshold = float(nearness.get('near_threshold', near.DEFAULT_NEAR_THRESHOLD))
    goal_margin = float(nearness.get('goal_margin', 0.0))
    avoid = _avoided(report.get('formula') or '')
    groundings = (report.get('referent_map') or {}).get('groundings') or {}
    for descriptor, g in groundings.items():
        colour = '#d62728' if descriptor in avoid else '#2ca02c'
        for inst in g.get('instances', []):
            c = np.asarray(inst['center'][:2], dtype=float)
            size = np.asarray(inst.get('size', [0, 0, 0])[:2], dtype=float)
            ring = near.outline_xy(c, size, threshold)
            ax.fill(ring[:, 0], ring[:, 1], facecolor=colour, alpha=0.16, edgecolor=colour, lw=1.2, zorder=4)
            if descriptor not in avoid and 0 < goal_margin < threshold:
                inner = near.outline_xy(c, size, threshold - goal_margin)
                ax.plot(inner[:, 0], inner[:, 1], '--', color=colour, lw=0.8, zorder=4)
            label_y = c[1] + size[1] / 2 + threshold + 0.15
            if label_y > hi[1] - 0.3:
                label_y = c[1] - size[1] / 2 - threshold - 0.4
            ax.annotate(descriptor, (c[0], label_y), fontsize=7.5, ha='center', color=colour,
                        weight='bold', zorder=7)


def _draw_search(ax: Any, report: dict[str, Any]) -> None:
    """Draw the area the camera saw (green) and the search path (black), when there was a search."""
    from matplotlib.colors import ListedColormap
    cov = report.get('coverage')
    if cov is not None:
        g = cov.grid
        x1, y1 = g.origin[0] + g.shape[0] * g.cell, g.origin[1] + g.shape[1] * g.cell
        extent = (g.origin[0], x1, g.origin[1], y1)
        ax.imshow(cov.seen.T.astype(float), origin='lower', extent=extent, interpolation='nearest',
                  cmap=ListedColormap(['#ffffff00', '#8fd18f']), vmin=0, vmax=1, alpha=0.6, zorder=1)
        ax.plot([], [], 's', color='#8fd18f', label='area seen while searching')
    path = report.get('search_driven')
    if path is not None and len(path):
        ax.plot(path[:, 0], path[:, 1], '-', color='k', lw=1.6, zorder=9, label='search path')


def _label_places(objects: Sequence[Any], char_w: float = 0.1,
                  line_h: float = 0.3) -> list[tuple[Any, tuple]]:
    """Place each object's name at its centre, moved up past any name already placed there.

    Larger objects are placed first, so a small one on a counter or a desk moves, not the counter's.
    Sizes are in map metres at the demo's scale (``char_w`` per character, ``line_h`` per line).
    """
    placed: list[tuple[float, float, float]] = []   # x, y, half width
    out = []
    for o in sorted(objects, key=lambda o: -float(np.prod(o.size[:2])) if o.box is not None else 0.0):
        x, y = float(o.center[0]), float(o.center[1])
        half = char_w * len(o.id) / 2
        while any(abs(x - px) < half + ph and abs(y - py) < line_h for px, py, ph in placed):
            y += line_h
        placed.append((x, y, half))
        out.append((o, (x, y)))
    return out


def _draw(scene: Scene, report: dict[str, Any], out: Path) -> Path:
    """Draw the map, the referent regions, the plan and the driven path into ``out``."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from ltl_instruct.core.planning.plot import check_output_path, save_png
    if out == DEFAULT_OUT:   # the default folder is made; a path given is used as given
        out.parent.mkdir(parents=True, exist_ok=True)
    check_output_path(out)
    lo, hi = np.asarray(scene.bounds_min), np.asarray(scene.bounds_max)
    width = 11.0
    fig, ax = plt.subplots(figsize=(width, width * (hi[1] - lo[1]) / (hi[0] - lo[0]) + 1.2))
    for box in scene.obstacles:
        ax.add_patch(Rectangle(box.lo[:2], *box.size[:2], color='0.25', zorder=2))
    for o in scene.objects:
        if o.box is None:
            ax.plot(*o.center[:2], 'o', color='0.45', ms=4, zorder=3)
        else:
            face = '0.88' if o.passable else '0.7'
            ax.add_patch(Rectangle(o.box.lo[:2], *o.size[:2], facecolor=face, edgecolor='0.4', lw=0.6,
                                   zorder=3))
    for o, at in _label_places(scene.objects):
        ax.annotate(o.id, at, fontsize=6.5, ha='center', va='center', color='0.15', zorder=6)
    _draw_regions(ax, report, hi)
    _draw_search(ax, report)
    driven = report.get('driven')
    if driven is not None and len(driven):
        ax.plot(driven[:, 0], driven[:, 1], '-', color='#ff7f0e', lw=4.0, alpha=0.7,
                label='driven path (odometry)', zorder=8)
        ax.plot(*driven[-1, :2], 'o', color='#ff7f0e', ms=8, zorder=10, label='robot at the end')
    plan = report.get('plan')
    if plan is not None and len(plan):
        ax.plot(plan[:, 0], plan[:, 1], '--', color='#1f4e9c', lw=1.3, label='planned path', zorder=9)
    for k, skill in enumerate((report.get('task_plan') or {}).get('skills', [])):
        pos = skill.get('position') or []
        if len(pos) >= 2:
            ax.plot(pos[0], pos[1], '*', color='#9467bd', ms=14, zorder=11,
                    label='pick / release' if k == 0 else None)
            ax.annotate(f'{skill["skill"]}', (pos[0] + 0.25, pos[1] + 0.25), fontsize=8, color='#9467bd',
                        weight='bold', zorder=11)
    start = scene.robot.start
    ax.plot(start[0], start[1], 's', color='k', ms=8, label='start', zorder=10)
    ax.plot([], [], 's', color='#2ca02c', alpha=0.4, label='goal referents (within reach)')
    ax.plot([], [], 's', color='#d62728', alpha=0.4, label='avoided referents')
    ax.plot([], [], '--', color='#2ca02c', lw=0.8, label='goal margin: the plan ends inside')
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect('equal')
    ax.set_xlabel('x [m]')
    ax.set_ylabel('y [m]')
    term = report.get('terminal') or {}
    title = f'"{report["instruction"]}"\n' if report.get('instruction') else ''
    title += str(report.get('formula') or '')
    if term.get('status') == 'failed':
        title += f'\nFAILED: {(term.get("error") or {}).get("code")}'
    else:
        title += f'\nexecution: {report.get("execution", "-")}'
    ax.set_title(title, fontsize=9)
    ax.plot([], [], color='0.25', lw=6, label='walls / obstacles')
    ax.legend(loc='upper center', bbox_to_anchor=(0.5, -0.08), ncol=4, fontsize=8, frameon=False)
    fig.tight_layout()
    return save_png(fig, out, dpi=130)


if __name__ == '__main__':
    from ltl_instruct.cli import main
    sys.exit(main(['demo'] + sys.argv[1:]))

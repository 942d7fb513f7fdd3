"""``ltl-instruct ground --scene FILE --formula F [--views N | --explore] [--json]``: the referent map.

For every skill-argument descriptor of the formula: the instances it resolves to (ids,
labels, positions and extents), the typed outcome and the explanation of why each
candidate passed or failed. Instances come from the scene's object list, or, with
``--views N``, from a voxel semantic map built from N synthetic RGB-D + label views, or,
with ``--explore``, from the map the robot's own camera builds while it searches the
scene from its start pose until the required descriptors resolve (:mod:`search`);
``--png`` then draws the area seen and the search path.
"""
from __future__ import annotations

import argparse
import json
import math
import time
from typing import Any, Optional

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.spec import parse_formula

HELP = "resolve a formula's descriptors in a scene (referent semantic map)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument('--scene', required=True, help='scene file, or the name of a built-in scene')
    parser.add_argument('--formula', required=True, help='task formula (spec/formula.md)')
    parser.add_argument('--views', type=int, default=0,
                        help='build the map from N synthetic camera views instead of the object list')
    parser.add_argument('--explore', action='store_true',
                        help="search with the robot's own camera from its start pose until the descriptors "
                             'resolve')
    parser.add_argument('--start', default=None,
                        help="x,y[,yaw] start pose of --explore [m, rad] (default: the scene robot's start)")
    parser.add_argument('--strategy', default='gain', choices=('gain', 'nearest'),
                        help='--explore: frontier by information gain per metre (default) or the nearest')
    parser.add_argument('--png', default=None,
                        help='--explore: write a picture of the search to this PNG file')
    parser.add_argument('--json', action='store_true', help='print one JSON object')
    parser.add_argument('--viewpoint', default=None,
                        help='x,y,z[,yaw] viewer of the comparators (default: the map origin)')
    parser.add_argument('--threshold', type=float, default=None,
                        help='one threshold [m] for every comparator (default: 0.1 axis, 1.0 next to, '
                             '0.5 between)')
    parser.add_argument('--embeddings', action='store_true',
                        help='also match names by sentence-embedding similarity (offline MiniLM)')


def _viewpoint(text: Optional[str]) -> Optional[tuple[float, ...]]:
    if text is None:
        return None
    return _finite_numbers(text, '--viewpoint', 'x,y,z[,yaw]', (3, 4))


def _finite_numbers(text: str, flag: str, shape: str, counts: tuple[int, int]) -> tuple[float, ...]:
    """Read comma-separated finite numbers, as many as one of ``counts`` (a typed error otherwise)."""
    try:
        vals = tuple(float(v) for v in text.split(','))
    except ValueError as e:
        raise InvalidInputError(f'{flag} must be {shape} numbers, got {text!r}') from e
    if len(vals) not in counts or not all(math.isfinite(v) for v in vals):
        raise InvalidInputError(f'{flag} must be {counts[0]} or {counts[1]} finite numbers, got {text!r}')
    return vals


def parse_start_pose(text: Optional[str], start: tuple[float, ...]) -> Any:
    """``x,y[,yaw]`` -> a robot pose at floor height; the scene's ``start`` (yaw 0) when ``text`` is None."""
    from ltl_instruct.core.world.robot import Pose
    if text is None:
        return Pose((float(start[0]), float(start[1]), 0.0), 0.0)
    vals = _finite_numbers(text, '--start', 'x,y[,yaw]', (2, 3))
    return Pose((vals[0], vals[1], 0.0), vals[2] if len(vals) == 3 else 0.0)


def _explore(scene: Any, formula: Any, params: Any, start: Optional[str], strategy: str,
             png: Optional[str]) -> tuple[Any, dict[str, Any], str]:
    """Search the scene; return the search's referent map, its figures and the source line."""
    from ltl_instruct.core.grounding.search import SearchParams, search_referents
    pose = parse_start_pose(start, scene.robot.start)
    result = search_referents(scene, formula, pose, SearchParams(strategy=strategy, grounding=params))
    figures = result.summary()
    if png:
        from ltl_instruct.core.grounding.search_plot import render_search
        figures['png'] = str(render_search(result, scene, png, title=str(formula)))
    source = (f'semantic map from {len(result.views)} camera views while searching '
              f'({len(result.semantic_map.instances())} instances)')
    return result.referent_map, figures, source


def report(scene_ref: str, formula_text: str, views: int = 0, viewpoint: Optional[str] = None,
           threshold: Optional[float] = None, embeddings: bool = False, explore: bool = False,
           start: Optional[str] = None, strategy: str = 'gain', png: Optional[str] = None) -> dict[str, Any]:
    """Everything the command prints, as a JSON-ready dict."""
    from ltl_instruct.core.grounding import (
        GroundingParams, ground_formula, grounding_error, instances_from_scene,
    )
    from ltl_instruct.core.world.builtin import resolve_scene

    if views < 0 or views > 360:
        raise InvalidInputError(f'--views must be in 0..360, got {views}')
    if explore and views:
        raise InvalidInputError('--explore and --views are two ways to build the map: give one')
    if png and not explore:
        raise InvalidInputError('--png draws the search: it needs --explore')
    if png:
        from ltl_instruct.core.planning.plot import check_output_path
        check_output_path(png)   # before the search: a path that cannot be written fails now
    scene = resolve_scene(scene_ref)
    formula = parse_formula(formula_text)
    params = GroundingParams(threshold=threshold, viewpoint=_viewpoint(viewpoint), use_embeddings=embeddings)
    t0 = time.perf_counter()
    source = 'object list'
    search = None
    if explore:
        rmap, search, source = _explore(scene, formula, params, start, strategy, png)
    elif views:
        from ltl_instruct.core.grounding.survey import map_from_views
        smap = map_from_views(scene, views)
        instances = smap.instances()
        source = f'semantic map from {views} synthetic views ({len(instances)} instances)'
    else:
        instances = instances_from_scene(scene)
    t1 = time.perf_counter()
    if not explore:
        rmap = ground_formula(formula, instances, params)
    t2 = time.perf_counter()
    err = grounding_error(rmap)
    out = {'scene': scene.name, 'formula': str(formula), 'source': source,
           'referent_map': rmap.to_dict(), 'ok': err is None,
           'error': err.to_dict() if err is not None else None,
           'timing': {'map_s': round(t1 - t0, 4), 'ground_s': round(t2 - t1, 4)}}
    if search is not None:
        out['search'] = search
    return out


def _print_search(s: dict[str, Any]) -> None:
    sought = ', '.join(s['sought']) or 'nothing (every required descriptor resolved from the start)'
    print(f"sought:   {sought}")
    print(f"search:   {s['views']} views, {s['moves']} moves, {s['travel_m']:.1f} m travelled, "
          f"{s['area_seen_m2']:.1f} m^2 seen; ended: {s['reason']}")
    if 'png' in s:
        print(f"picture:  {s['png']}")


def run(args: argparse.Namespace) -> int:
    """Print the referent map; exit 0 when every required descriptor resolved, 1 when not."""
    r = report(args.scene, args.formula, args.views, args.viewpoint, args.threshold, args.embeddings,
               args.explore, args.start, args.strategy, args.png)
    if args.json:
        print(json.dumps(r, indent=2))
        return 0 if r['ok'] else 1
    print(f"scene:    {r['scene']}  ({r['source']})")
    print(f"formula:  {r['formula']}")
    if 'search' in r:
        _print_search(r['search'])
    for text, g in r['referent_map']['groundings'].items():
        tag = '' if g['required'] else ' (avoided)'
        print(f"\n{text}{tag}: {g['outcome']}")
        for inst in g['instances']:
            c = ', '.join(f'{v:.2f}' for v in inst['center'])
            s = ', '.join(f'{v:.2f}' for v in inst['size'])
            print(f"  {inst['id']:<20} {inst['label']:<20} at ({c})  size ({s})")
        for line in g['explanation']:
            print(f'    - {line}')
    if r['error']:
        print(f"\nerror [{r['error']['code']}]: {r['error']['message']}")
    return 0 if r['ok'] else 1

"""``ltl-instruct ground --scene FILE --formula F [--views N] [--json]``: the referent semantic map.

For every skill-argument descriptor of the formula: the instances it resolves to (ids,
labels, positions and extents), the typed outcome and the explanation of why each
candidate passed or failed. Instances come from the scene's object list, or, with
``--views N``, from a voxel semantic map built from N synthetic RGB-D + label views.
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
    try:
        vals = tuple(float(v) for v in text.split(','))
    except ValueError as e:
        raise InvalidInputError(f'--viewpoint must be x,y,z[,yaw] numbers, got {text!r}') from e
    if len(vals) not in (3, 4) or not all(math.isfinite(v) for v in vals):
        raise InvalidInputError(f'--viewpoint must be 3 or 4 finite numbers, got {text!r}')
    return vals


def report(scene_ref: str, formula_text: str, views: int = 0, viewpoint: Optional[str] = None,
           threshold: Optional[float] = None, embeddings: bool = False) -> dict[str, Any]:
    """Everything the command prints, as a JSON-ready dict."""
    from ltl_instruct.core.grounding import (
        GroundingParams, ground_formula, grounding_error, instances_from_scene,
    )
    from ltl_instruct.core.world.builtin import resolve_scene

    if views < 0 or views > 360:
        raise InvalidInputError(f'--views must be in 0..360, got {views}')
    scene = resolve_scene(scene_ref)
    formula = parse_formula(formula_text)
    params = GroundingParams(threshold=threshold, viewpoint=_viewpoint(viewpoint), use_embeddings=embeddings)
    t0 = time.perf_counter()
    source = 'object list'
    if views:
        from ltl_instruct.core.grounding.survey import map_from_views
        smap = map_from_views(scene, views)
        instances = smap.instances()
        source = f'semantic map from {views} synthetic views ({len(instances)} instances)'
    else:
        instances = instances_from_scene(scene)
    t1 = time.perf_counter()
    rmap = ground_formula(formula, instances, params)
    t2 = time.perf_counter()
    err = grounding_error(rmap)
    return {'scene': scene.name, 'formula': str(formula), 'source': source,
            'referent_map': rmap.to_dict(), 'ok': err is None,
            'error': err.to_dict() if err is not None else None,
            'timing': {'map_s': round(t1 - t0, 4), 'ground_s': round(t2 - t1, 4)}}


def run(args: argparse.Namespace) -> int:
    """Print the referent map; exit 0 when every required descriptor resolved, 1 when not."""
    r = report(args.scene, args.formula, args.views, args.viewpoint, args.threshold, args.embeddings)
    if args.json:
        print(json.dumps(r, indent=2))
        return 0 if r['ok'] else 1
    print(f"scene:    {r['scene']}  ({r['source']})")
    print(f"formula:  {r['formula']}")
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

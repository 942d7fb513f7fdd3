"""``ltl-instruct plan --scene FILE --formula F``: a verified path for a task formula in a scene.

Referents are resolved against the scene's objects (by the grounding module when it is
installed, else by matching labels: ``sofa`` matches every sofa, ``red_sofa`` only the
red one). The plan is checked independently before it is printed. Exit status: 0
planned (or already satisfied), 1 no plan (unsatisfiable, blocked, no path), 2 bad input.
"""
from __future__ import annotations

import argparse
import json
import sys
from typing import Any, Optional

from ltl_instruct.core.automaton import on_the_fly_automaton
from ltl_instruct.core.errors import ErrorCode, GroundingError, InvalidInputError, LtlInstructError
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.spec import Formula, avoided_referents_of, parse_formula, referents_of
from ltl_instruct.core.world import near
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.scene import Scene, slug

HELP = 'plan a verified path for a formula in a scene'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument('--scene', required=True,
                        help='scene file (YAML or JSON, spec/scene.md), or the name of a built-in scene')
    parser.add_argument('--formula', required=True, help='task formula (spec/formula.md)')
    parser.add_argument('--start', help='start position x,y[,z] [m] (default: the scene robot\'s start)')
    parser.add_argument('--json', action='store_true', help='print the plan as one JSON object')
    parser.add_argument('--png', help='write a picture of the plan to this PNG file')
    parser.add_argument('--near', type=float, default=near.DEFAULT_NEAR_THRESHOLD,
                        help=f'nearness threshold of near[x] [m] (default {near.DEFAULT_NEAR_THRESHOLD})')
    add_margin_arguments(parser)
    parser.add_argument('--samples', type=int, default=5000, help='FMT* samples per segment (default 5000)')
    parser.add_argument('--radius-multiplier', type=float, default=1.1, help='FMT* radius multiplier')
    parser.add_argument('--no-heuristics', action='store_true', help='turn FMT* heuristics off')
    parser.add_argument('--time-limit', type=float, default=5.0, help='seconds per segment (default 5)')
    parser.add_argument('--seed', type=int, default=0, help='sampler seed (same seed, same path)')


def add_margin_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare ``--goal-margin`` and ``--avoid-margin`` (``plan`` and ``demo``)."""
    parser.add_argument('--goal-margin', type=float, default=near.DEFAULT_GOAL_MARGIN,
                        help='enter each goal region this deep [m], so that a controller stopping a '
                             f'little short still completes the task (default {near.DEFAULT_GOAL_MARGIN}; '
                             'less, with a warning, where the region is thinner)')
    parser.add_argument('--avoid-margin', type=float, default=near.DEFAULT_AVOID_MARGIN,
                        help='pass regions to avoid this far outside [m] where free space allows '
                             f'(default {near.DEFAULT_AVOID_MARGIN})')


def label_referent_map(formula: Formula, scene: Scene) -> ReferentMap:
    """Resolve each descriptor of ``formula`` to the scene objects whose label it names.

    ``sofa`` matches ``sofa``, ``red sofa``...; ``red_sofa`` only ``red sofa`` (the
    snake_case label equals the name or ends with ``_<name>``). Spatial relations need
    the grounding module.

    Raises
    ------
    GroundingError
        ``UNKNOWN_REFERENT`` when a referent the task must reach matches no object, or a
        descriptor has relations.
    """
    avoided = {str(d) for d in avoided_referents_of(formula)}
    groundings: dict[str, Grounding] = {}
    labels = sorted({o.label for o in scene.objects})
    for d in referents_of(formula):
        text = str(d)
        if d.relations:
            raise GroundingError(f'"{text}" has spatial relations; resolving them needs the grounding module')
        found = tuple(Instance(o.id, o.label, o.center, o.size or (0.0, 0.0, 0.0))
                      for o in scene.objects
                      if o.id == d.name or slug(o.label) == d.name or slug(o.label).endswith('_' + d.name))
        if not found and text not in avoided:
            raise GroundingError(f'no object in {scene.source} matches "{text}" '
                                 f'(objects: {", ".join(labels) or "none"})', ErrorCode.UNKNOWN_REFERENT,
                                 details={'referent': text})
        outcome = (Outcome.RESOLVED if len(found) == 1 else Outcome.AMBIGUOUS if found
                   else Outcome.UNKNOWN_REFERENT)
        groundings[text] = Grounding(text, outcome, found, (f'label match: {len(found)} object(s)',))
    return ReferentMap(groundings)


def scene_referent_map(formula: Formula, scene: Scene) -> ReferentMap:
    """Resolve the formula's descriptors against the scene's objects with the grounding module.

    Falls back to :func:`label_referent_map` where the grounding module is not installed.

    Raises
    ------
    GroundingError
        When a referent the task must reach resolves to nothing.
    """
    try:
        from ltl_instruct.core.grounding import ground_formula, grounding_error, instances_from_scene
    except ImportError:
        return label_referent_map(formula, scene)
    rmap = ground_formula(formula, instances_from_scene(scene))
    error = grounding_error(rmap)
    if error is not None:
        raise error
    return rmap


def parse_start(text: Optional[str], scene: Scene) -> tuple[float, ...]:
    """``x,y[,z]`` -> position [m]; the scene robot's start when ``text`` is None."""
    if text is None:
        return tuple(scene.robot.start)
    try:
        vals = tuple(float(v) for v in text.split(','))
    except ValueError as e:
        raise InvalidInputError(f'--start must be x,y[,z] numbers, got {text!r}') from e
    if len(vals) not in (2, 3) or not all(v == v and abs(v) != float('inf') for v in vals):
        raise InvalidInputError(f'--start must be 2 or 3 finite numbers, got {text!r}')
    if scene.robot.dims == 3 and len(vals) == 2:
        raise InvalidInputError('a drone start needs x,y,z')
    return vals


def run(args: argparse.Namespace) -> int:
    """Plan, verify, print (and draw); 0 planned, 1 no plan."""
    from ltl_instruct.core.planning import FmtSettings, PlannerSettings, plan_task, world_from_scene

    if len(args.formula) > 10_000:
        raise InvalidInputError('the formula is longer than 10,000 characters')
    if args.png:   # before planning: a path that cannot be written fails now, not after minutes
        from ltl_instruct.core.planning.plot import check_output_path
        check_output_path(args.png)
    scene = resolve_scene(args.scene)
    formula = parse_formula(args.formula)
    start = parse_start(args.start, scene)
    fmt = FmtSettings(num_samples=args.samples, radius_multiplier=args.radius_multiplier,
                      heuristics=not args.no_heuristics, time_limit=args.time_limit, seed=args.seed)
    settings = PlannerSettings(near_threshold=args.near, goal_margin=args.goal_margin,
                               avoid_margin=args.avoid_margin, fmt=fmt)
    world = world_from_scene(scene)
    rmap = scene_referent_map(formula, scene)
    automaton = on_the_fly_automaton(formula)   # states expanded as the planner reaches them
    out: dict[str, Any] = {'scene': scene.name, 'formula': str(formula)}
    try:
        plan = plan_task(automaton, rmap, world, start, settings)
    except LtlInstructError as e:
        if e.code in (ErrorCode.INVALID_INPUT, ErrorCode.PARSE_ERROR, ErrorCode.LIMIT_EXCEEDED):
            raise
        out.update(status='failed', error=e.to_dict())
        if args.json:
            print(json.dumps(out, indent=2))
        else:
            print(f'no plan [{e.code.value}]: {e.message}')
        return 1
    out.update(plan.to_dict())
    out['referents'] = {k: [i.id for i in g.instances] for k, g in rmap.groundings.items()}
    if args.png:
        from ltl_instruct.core.planning.plot import render_plan
        out['png'] = str(render_plan(plan, world, args.png, scene))
    if args.json:
        print(json.dumps(out, indent=2))
        return 0
    v = plan.verification
    print(f'formula:  {plan.formula}')
    print(f'status:   {plan.status}; length {plan.length:.2f} m; automaton states {plan.states}')
    for i, s in enumerate(plan.steps):
        if s.kind == 'navigate':
            print(f'  {i + 1}. navigate {s.state_before} -> {s.state_after}: {len(s.waypoints)} waypoints, '
                  f'{s.length:.2f} m, goal {s.goal}')
        else:
            print(f'  {i + 1}. {s.skill} at ({", ".join(f"{x:.2f}" for x in s.end)}) '
                  f'{s.state_before} -> {s.state_after}')
    print(f'verified: {"yes" if v.ok else "NO: " + v.reason} ({v.num_samples} samples, '
          f'max spacing {v.max_spacing:.3f} m)')
    depths = [d for d in v.goal_depths if d is not None]
    if depths:
        print(f'margins:  every goal entered at least {min(depths):.2f} m deep (goal margin '
              f'{args.goal_margin} m, avoid margin {args.avoid_margin} m)')
    for warning in plan.warnings:
        print(f'WARNING: {warning}')
    if args.png:
        print(f'picture:  {out["png"]}')
    sys.stdout.flush()
    return 0

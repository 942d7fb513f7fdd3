"""Issue 21 item 4: plans a controller can finish (goal and avoid margins, a start touching a wall)."""
from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from bench.planning import referent_map
from ltl_instruct.cli import main
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.guards import Cube, Guard
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.monitor import LetterMaker
from ltl_instruct.core.planning import (
    AtomRegion, FmtSettings, PlannerSettings, PlanningWorld, RegionSet, SegmentRequest, plan_task, resample,
    solve_segment, verify_plan, world_from_scene,
)
from ltl_instruct.core.planning.verify import _atom_truth
from ltl_instruct.core.spec import Atom, Descriptor, parse_formula
from ltl_instruct.core.world import near
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.scene import Box

GM, AM = near.DEFAULT_GOAL_MARGIN, near.DEFAULT_AVOID_MARGIN
TOL = 0.01
SETTINGS = PlannerSettings(fmt=FmtSettings(num_samples=2000, seed=2))
A = Atom('near', (Descriptor('a'),))
B = Atom('near', (Descriptor('b'),))


def _plan(scene, text, settings=SETTINGS, start=None):
    f = parse_formula(text)
    aut, rmap, world = compile_automaton(f), referent_map(scene, f), world_from_scene(scene)
    plan = plan_task(aut, rmap, world, scene.robot.start if start is None else start, settings)
    return plan, aut, rmap, world


def _distance(rmap: ReferentMap, descriptor: str, points: np.ndarray, dims: int) -> np.ndarray:
    """Distance [m] to a descriptor's nearest instance box, by brute force over its instances."""
    return np.min([inst.distance(points, dims) for inst in rmap.instances(descriptor)], axis=0)


BUILTIN_TASKS = [
    ('apartment', 'F (near[bed] & F near[fridge])', ['bed', 'fridge']),
    ('apartment', 'F near[computer] & G !near[door]', ['computer']),
    ('apartment', '!near[rug] U near[bookshelf]', ['bookshelf']),
    ('city_block', 'F (near[bank] & F near[statue])', ['bank', 'statue']),
    ('city_block', 'F near[library] & G !near[tower]', ['library']),
    ('city_block', '!near[fountain] U near[bus_stop]', ['bus_stop']),
]


@pytest.mark.parametrize('scene_name, text, goals', BUILTIN_TASKS)
def test_every_goal_endpoint_lies_goal_margin_inside_its_region(scene_name, text, goals):
    scene = resolve_scene(scene_name)
    plan, aut, rmap, world = _plan(scene, text)
    assert plan.verification.ok and plan.verification.margins_ok, plan.verification.reason
    assert not plan.warnings
    ends = [s.end for s in plan.steps if s.kind == 'navigate']
    assert len(ends) == len(goals)
    for end, goal in zip(ends, goals):
        d = float(_distance(rmap, goal, end[None], world.dims)[0])
        assert d <= near.DEFAULT_NEAR_THRESHOLD - GM + TOL, (goal, d)
    assert min(plan.verification.goal_depths) >= GM - TOL
    # the avoided regions are passed avoid_margin outside (there is room in these scenes)
    path = resample(plan.path(), 0.01)
    for avoided in ('door', 'tower', 'rug', 'fountain'):
        if f'!near[{avoided}]' in text:
            assert _distance(rmap, avoided, path, world.dims).min() >= near.DEFAULT_NEAR_THRESHOLD + AM - TOL


def test_a_region_to_leave_is_left_goal_margin_far():
    scene = resolve_scene('apartment')
    plan, aut, rmap, world = _plan(scene, 'F (near[armchair] & F !near[armchair])')
    assert plan.verification.ok and not plan.warnings
    enter, leave = [s.end for s in plan.steps if s.kind == 'navigate']
    assert float(_distance(rmap, 'armchair', enter[None], 2)[0]) <= near.DEFAULT_NEAR_THRESHOLD - GM + TOL
    assert float(_distance(rmap, 'armchair', leave[None], 2)[0]) >= near.DEFAULT_NEAR_THRESHOLD + GM - TOL
    assert min(plan.verification.goal_depths) >= GM - TOL


def _segment(start=(1.0, 3.0), b_boxes=(), b_radius=0.6, obstacles=(),
             **kw) -> tuple[SegmentRequest, PlanningWorld]:
    goal = Guard((Cube(frozenset({A}), frozenset({B})),))
    allowed = Guard((Cube(frozenset(), frozenset({A, B})),))
    regions = (AtomRegion('near[a]', ((9.0, 3.0, 0.0),), ((0.0, 0.0, 0.0),), 0.8),
               AtomRegion('near[b]', tuple(c for c, _ in b_boxes), tuple(s for _, s in b_boxes), b_radius))
    req = SegmentRequest('m/0', start, 2, regions, goal, allowed, FmtSettings(num_samples=1500, seed=3),
                         transition=(0, 1), goal_margin=GM, avoid_margin=AM, **kw)
    return req, PlanningWorld(2, (0.0, 0.0), (10.0, 6.0), 0.2, tuple(obstacles))


def test_segment_goes_past_the_goal_edge_and_around_the_avoid_margin():
    req, world = _segment(b_boxes=[((5.0, 3.0, 0.0), (0.5, 3.0, 0.0))])
    result = solve_segment(req, world)
    assert result.ok and not result.warnings and (result.goal_margin, result.avoid_margin) == (GM, AM)
    assert np.linalg.norm(result.waypoints[-1] - [9.0, 3.0]) <= 0.8 - GM + 1e-6
    dense = resample(result.waypoints, 0.01)
    to_b = near.box_distance(dense, np.array([[5.0, 3.0, 0.0]]), np.array([[0.5, 3.0, 0.0]]), 2)
    assert to_b.min() >= 0.6 + AM - TOL
    # the same request without margins ends at the edge
    plain = solve_segment(replace(req, goal_margin=0.0, avoid_margin=0.0), world)
    assert np.linalg.norm(plain.waypoints[-1] - [9.0, 3.0]) == pytest.approx(0.8, abs=1e-3)


def test_thin_goal_region_is_entered_as_deep_as_it_allows_with_a_warning():
    # a box round a's point leaves free only 0.8 - (0.5 + 0.2) = 0.1 m of its near region
    req, world = _segment(obstacles=[Box((9.0, 3.0, 0.0), (1.0, 1.0, 1.0))])
    result = solve_segment(req, world)
    assert result.ok and 0.05 < result.goal_margin < GM
    depth = 0.8 - float(np.linalg.norm(result.waypoints[-1] - [9.0, 3.0]))
    assert depth >= result.goal_margin - 1e-6
    assert len(result.warnings) == 1 and 'goal_margin' in result.warnings[0]


def test_thin_goal_regions_in_a_plan_are_capped_not_failed():
    # near_threshold 0.35 with a 0.3 m robot: at most 5 cm of each region is free
    scene = resolve_scene('apartment')
    plan, *_ = _plan(scene, 'F near[fridge]', replace(SETTINGS, near_threshold=0.35))
    assert plan.verification.ok
    assert plan.steps[-1].goal_margin < GM and any('goal_margin' in w for w in plan.warnings)
    assert plan.verification.goal_depths[-1] >= plan.steps[-1].goal_margin - 1e-6


def test_avoid_margin_is_dropped_with_a_warning_where_the_passage_is_too_narrow():
    # a wall with one gap; b's two regions leave 10 cm of it, not enough for the avoid margin
    wall = [Box((5.0, 1.25, 0.0), (0.2, 2.5, 1.0)), Box((5.0, 4.75, 0.0), (0.2, 2.5, 1.0))]
    b = [((5.0, 2.0, 0.0), (0.0, 0.0, 0.0)), ((5.0, 4.0, 0.0), (0.0, 0.0, 0.0))]
    req, world = _segment(b_boxes=b, b_radius=0.95, obstacles=wall)
    result = solve_segment(req, world)
    assert result.ok and result.avoid_margin == 0.0 and result.goal_margin == GM
    assert len(result.warnings) == 1 and 'avoid_margin' in result.warnings[0]


def test_start_touching_a_wall_is_moved_to_free_space_with_a_warning():
    scene = resolve_scene('apartment')
    touching = (0.35, 1.5)   # the outer wall ends at x = 0.2; the robot radius is 0.3
    plan, aut, rmap, world = _plan(scene, 'F near[armchair]', start=touching)
    assert plan.verification.ok
    assert world.is_free(plan.start[None])[0]
    assert 0.1 <= np.linalg.norm(plan.start - touching) <= 0.17
    assert any('start' in w for w in plan.warnings)
    assert plan.to_dict()['warnings'] == list(plan.warnings)


def test_plan_command_reports_the_moved_start_and_takes_the_margins(capsys):
    rc = main(['plan', '--scene', 'apartment', '--formula', 'F near[armchair]', '--start', '0.35,1.5',
               '--samples', '1000', '--goal-margin', '0.3', '--avoid-margin', '0', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and any('start' in w for w in out['warnings'])
    assert out['nearness'] == {'near_threshold': 1.0, 'goal_margin': 0.3, 'avoid_margin': 0.0}
    assert min(out['verification']['goal_depths']) >= 0.3 - 1e-4
    assert main(['plan', '--scene', 'apartment', '--formula', 'F near[armchair]', '--goal-margin', '-1']) == 2


def test_the_check_holds_each_step_to_the_margins_it_claims():
    scene = resolve_scene('apartment')
    plan, aut, rmap, world = _plan(scene, 'F near[computer] & G !near[door]')
    steps = list(plan.steps)
    steps[-1] = replace(steps[-1], goal_margin=0.5)
    v = verify_plan(steps, plan.start, aut, rmap, world, near.DEFAULT_NEAR_THRESHOLD)
    assert not v.ok and not v.margins_ok and 'goal margin' in v.reason
    closest = float(_distance(rmap, 'door', resample(plan.path(), 0.05), 2).min())
    steps[-1] = replace(steps[-1], goal_margin=GM, avoid_margin=closest - near.DEFAULT_NEAR_THRESHOLD + 0.05)
    v = verify_plan(steps, plan.start, aut, rmap, world, near.DEFAULT_NEAR_THRESHOLD)
    assert not v.margins_ok and 'avoid margin' in v.reason and 'near[door]' in v.reason


def test_planner_plan_check_and_monitor_agree_on_near():
    rng = np.random.default_rng(5)
    boxes = [((2.0, 2.0, 0.4), (1.0, 0.5, 0.8)), ((5.0, 1.0, 0.0), (0.0, 0.0, 0.0)),
             ((2.5, 4.0, 1.0), (2.0, 1.0, 2.0))]
    rmap = ReferentMap({'a': Grounding('a', Outcome.AMBIGUOUS, tuple(
        Instance(f'a{i}', 'a', c, s) for i, (c, s) in enumerate(boxes)))})
    # random points, and points exactly on the region's edge (1 m from a face along an axis)
    edge = np.array([[2.0 + 0.5 + 1.0, 2.0, 0.0], [2.0, 2.0 - 0.25 - 1.0, 0.0], [6.0, 1.0, 0.0]])
    pts = np.vstack([np.column_stack([rng.uniform(-1, 8, (400, 2)), np.zeros(400)]), edge])
    for dims in (2, 3):
        planner = RegionSet((AtomRegion('near[a]', tuple(c for c, _ in boxes), tuple(s for _, s in boxes),
                                        1.0),), dims)
        by_planner = planner.valuation(pts)['near[a]']
        scalar = np.array([near.is_near(planner.nearest(tuple(p))[0], 1.0) for p in pts])
        by_check = _atom_truth((A,), rmap, pts, dims, 1.0)[A]
        letters = LetterMaker((A,), rmap, 1.0, dims)
        by_monitor = np.array([A in letters.letter(p) for p in pts])
        assert np.array_equal(by_planner, by_check) and np.array_equal(by_planner, by_monitor)
        assert np.array_equal(by_planner, scalar)
        assert by_planner[-3:].all()   # the edge is near, for all three


def test_margins_travel_in_requests_and_results_and_are_checked():
    req, world = _segment(hold=Guard((Cube(frozenset(), frozenset({B})),)))
    back = SegmentRequest.from_dict(json.loads(json.dumps(req.to_dict())))
    assert back == req
    for bad in ({'goal_margin': -0.1}, {'avoid_margin': 'x'}, {'goal_margin': float('nan')},
                {'hold': {'cubes': [{'pos': ['near[zz]'], 'neg': []}]}}):
        with pytest.raises(InvalidInputError):
            SegmentRequest.from_dict(dict(req.to_dict(), **bad))
    result = solve_segment(req, world)
    received = type(result).from_waypoints('m/0', result.waypoints).with_margins_of(
        json.loads(json.dumps(result.to_dict())))
    assert (received.goal_margin, received.avoid_margin, received.warnings) == (GM, AM, ())
    with pytest.raises(InvalidInputError):
        received.with_margins_of({'goal_margin': 1e9})
    with pytest.raises(InvalidInputError):
        PlannerSettings(goal_margin=-1.0)

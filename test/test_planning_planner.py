"""Planning core: the progressive planner, its backtracking, its typed errors, and the verifier."""
from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from bench.planning import referent_map
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, PlanningError, UnsatisfiableError
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.planning import (
    FmtSettings, PlannerSettings, SegmentResult, plan_task, resample, verify_plan, world_from_scene,
)
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.scene import scene_from_dict

FAST = PlannerSettings(fmt=FmtSettings(num_samples=1500, seed=1))

ROOM = {
    'name': 'room',
    'bounds': {'min': [0, 0, 0], 'max': [20, 12, 3]},
    'robot': {'kind': 'ground', 'start': [1, 1, 0], 'radius': 0.3},
    'obstacles': [{'center': [10, 3, 1], 'size': [0.2, 6, 2]}],
    'objects': [
        {'label': 'red sofa', 'center': [18, 2, 0.4], 'size': [1, 1, 0.8]},
        {'label': 'door', 'center': [14, 4, 0.5], 'size': [0.4, 0.4, 1], 'passable': True},
        {'label': 'cup', 'center': [3, 10, 0.4], 'size': [0.2, 0.2, 0.2], 'passable': True},
        {'label': 'table', 'center': [16, 10, 0.4], 'size': [1, 1, 0.8]},
        {'label': 'chair', 'center': [4, 4, 0.4], 'size': [0.5, 0.5, 0.8]},
        {'label': 'chair', 'center': [15, 7, 0.4], 'size': [0.5, 0.5, 0.8]},
    ],
}


def _plan(text, scene_dict=ROOM, settings=FAST, **kw):
    scene = scene_from_dict(scene_dict)
    f = parse_formula(text)
    aut = compile_automaton(f)
    rmap = referent_map(scene, f)
    world = world_from_scene(scene)
    return plan_task(aut, rmap, world, scene.robot.start, settings, **kw), aut, rmap, world


@pytest.mark.parametrize('text', [
    'F near[sofa]',
    'F (near[chair] & F near[table])',
    'F near[sofa] & G !near[door]',
    '!near[sofa] U near[table]',
    'F near[table] | F near[sofa]',
    'F (pick[cup] & F release[cup, table])',
    'F near[table] & !F (near[chair] & F (!near[chair] & F near[chair]))',
])
def test_mission_patterns_give_verified_plans(text):
    plan, aut, rmap, world = _plan(text)
    assert plan.status == 'planned'
    assert plan.verification.ok and plan.verification.accepted
    assert plan.verification.max_spacing <= 0.05 + 1e-9
    # an independent re-check from the outside agrees
    again = verify_plan(plan.steps, plan.start, aut, rmap, world, FAST.near_threshold)
    assert again.ok
    states = plan.states
    assert states[-1] in aut.accepting
    for a, b in zip(plan.steps, plan.steps[1:]):
        assert a.state_after == b.state_before
        assert np.allclose(a.end, b.waypoints[0])
    d = json.loads(json.dumps(plan.to_dict()))
    assert d['status'] == 'planned' and d['verification']['ok'] and len(d['steps']) == len(plan.steps)


def test_pick_and_place_inserts_skills_near_their_objects():
    plan, aut, rmap, world = _plan('F (pick[cup] & F release[cup, table])')
    kinds = [(s.kind, s.skill) for s in plan.steps]
    assert ('skill', 'pick[cup]') in kinds and ('skill', 'release[cup, table]') in kinds
    pick = next(s for s in plan.steps if s.skill == 'pick[cup]')
    release = next(s for s in plan.steps if s.skill.startswith('release'))
    assert min(i.distance(pick.end[None], 2)[0] for i in rmap.instances('cup')) <= 1.0 + 1e-9
    assert min(i.distance(release.end[None], 2)[0] for i in rmap.instances('table')) <= 1.0 + 1e-9
    assert plan.steps.index(pick) < plan.steps.index(release)


def test_nearest_instance_is_chosen_by_path_cost():
    plan, *_ = _plan('F near[chair]')
    assert np.linalg.norm(plan.steps[-1].end - [4, 4]) < 1.5     # the chair at (4, 4), not (15, 7)


def test_backtracks_to_another_instance_when_the_first_leads_nowhere():
    # After visiting a landmark, the gate is forbidden. The landmark near the start is on the
    # wrong side of the gate: only the far one, reached through the gate first, works.
    scene = {
        'bounds': {'min': [0, 0, 0], 'max': [20, 10, 3]},
        'robot': {'kind': 'ground', 'start': [1, 5, 0], 'radius': 0.3},
        'obstacles': [{'center': [10, 2, 1], 'size': [0.2, 4, 2]},
                      {'center': [10, 8, 1], 'size': [0.2, 4, 2]}],
        'objects': [{'label': 'gate', 'center': [10, 5, 0], 'size': [0.2, 2, 0.1], 'passable': True},
                    {'label': 'statue', 'center': [3, 5, 0.5], 'size': [0.4, 0.4, 1]},
                    {'label': 'statue', 'center': [14, 2, 0.5], 'size': [0.4, 0.4, 1]},
                    {'label': 'bench', 'center': [18, 8, 0.4], 'size': [1, 0.5, 0.8]}],
    }
    text = 'F (near[statue] & F near[bench]) & G (near[statue] -> G !near[gate])'
    plan, aut, rmap, world = _plan(text, scene)
    assert plan.verification.ok
    first = plan.steps[0]
    assert np.linalg.norm(first.end - [14, 2]) < 1.5
    assert plan.stats['segment_failures'] >= 1


def test_unsatisfiable_tasks_give_typed_errors_naming_the_transition():
    with pytest.raises(UnsatisfiableError) as e:
        _plan('F near[sofa] & G !near[sofa]')
    assert e.value.code == ErrorCode.UNSATISFIABLE
    with pytest.raises(PlanningError) as e:
        _plan('F (near[sofa] & near[cup])')       # far apart: the goal region is empty
    assert e.value.code == ErrorCode.GOAL_OCCUPIED and 'transition 0 -> ' in e.value.message
    enclosed = dict(ROOM, obstacles=ROOM['obstacles'] + [
        {'center': [18, 0.5, 1], 'size': [4.0, 0.4, 2]}, {'center': [18, 4.5, 1], 'size': [4.0, 0.4, 2]},
        {'center': [16, 2.5, 1], 'size': [0.4, 4.4, 2]}])
    with pytest.raises(PlanningError) as e:
        _plan('F near[sofa]', enclosed)
    assert e.value.code == ErrorCode.NO_VALID_PATH and 'near[sofa]' in e.value.message


def test_start_that_violates_the_task_or_collides_is_refused():
    near_door = dict(ROOM, robot={'kind': 'ground', 'start': [14, 5, 0], 'radius': 0.3})
    with pytest.raises(PlanningError) as e:
        _plan('F near[sofa] & G !near[door]', near_door)
    assert e.value.code == ErrorCode.START_OCCUPIED
    # no free point within start_shift (0.5 m) of the middle of a 2 m thick block
    block = dict(ROOM, obstacles=ROOM['obstacles'] + [{'center': [6, 6, 1], 'size': [2, 2, 2]}],
                 robot={'kind': 'ground', 'start': [6, 6, 0], 'radius': 0.3})
    with pytest.raises(PlanningError) as e:
        _plan('F near[sofa]', block)
    assert e.value.code == ErrorCode.START_OCCUPIED and '0.5 m' in e.value.message
    scene = scene_from_dict(ROOM)
    aut = compile_automaton('F near[sofa]')
    for bad in ([float('nan'), 1.0], ['a', 'b'], [1.0]):
        with pytest.raises(InvalidInputError):
            plan_task(aut, referent_map(scene, aut.formula), world_from_scene(scene), bad, FAST)


def test_task_already_satisfied_at_the_start_needs_no_step():
    at_sofa = dict(ROOM, robot={'kind': 'ground', 'start': [17, 3.3, 0], 'radius': 0.3})
    plan, *_ = _plan('F near[sofa]', at_sofa)
    assert plan.status == 'satisfied' and plan.steps == () and plan.verification.ok


def test_a_lying_segment_solver_never_yields_a_violating_plan():
    scene = scene_from_dict(ROOM)

    def straight_line(req):  # ignores obstacles and regions: goes straight to the sofa
        return SegmentResult.from_waypoints(req.id, np.array([req.start, (17.5, 3.0)]))

    aut = compile_automaton('F near[sofa] & G !near[door]')
    with pytest.raises(PlanningError):
        plan_task(aut, referent_map(scene, aut.formula), world_from_scene(scene), (12.0, 6.0), FAST,
                  solve=straight_line)


def test_verifier_catches_tampered_plans():
    plan, aut, rmap, world = _plan('F near[sofa] & G !near[door]')
    nav = plan.steps[0]
    # through the door region
    detour = np.vstack([nav.waypoints[:1], [[14.0, 5.0]], nav.waypoints[-1:]])
    v = verify_plan([replace(nav, waypoints=detour)], plan.start, aut, rmap, world, 1.0)
    assert not v.ok and not v.accepted
    # through the wall
    through = np.vstack([nav.waypoints[:1], [[10.0, 3.0]], nav.waypoints[-1:]])
    v = verify_plan([replace(nav, waypoints=through)], plan.start, aut, rmap, world, 1.0)
    assert not v.ok and not v.collision_free
    # stopping short
    short = resample(nav.waypoints, 0.05)[:-20]
    v = verify_plan([replace(nav, waypoints=short)], plan.start, aut, rmap, world, 1.0)
    assert not v.ok and not v.accepted
    # a jump: the step does not start where the robot is
    v = verify_plan([replace(nav, waypoints=nav.waypoints + 0.5)], plan.start, aut, rmap, world, 1.0)
    assert not v.continuous
    # a pick far from the object
    pp, aut2, rmap2, world2 = _plan('F (pick[cup] & F release[cup, table])')
    pick = next(s for s in pp.steps if s.skill == 'pick[cup]')
    v = verify_plan([replace(pick, waypoints=pp.start[None])], pp.start, aut2, rmap2, world2, 1.0)
    assert not v.skills_ok


def test_same_seed_same_plan_and_replanning_from_a_state():
    p1, aut, rmap, world = _plan('F (near[chair] & F near[table])')
    p2, *_ = _plan('F (near[chair] & F near[table])')
    assert len(p1.steps) == len(p2.steps)
    for a, b in zip(p1.steps, p2.steps):
        assert np.array_equal(a.waypoints, b.waypoints)
    mid = p1.steps[0]
    again = plan_task(aut, rmap, world, mid.end, FAST, initial_state=mid.state_after)
    assert again.verification.ok and again.states[-1] in aut.accepting


def test_drone_plans_in_3d_within_the_band():
    drone = {
        'bounds': {'min': [0, 0, 0], 'max': [12, 10, 4]},
        'robot': {'kind': 'drone', 'start': [1, 1, 1.5], 'radius': 0.25},
        'altitude': {'min': 1.0, 'max': 3.0},
        'obstacles': [{'center': [6, 4, 2], 'size': [0.4, 8, 4]}],
        'objects': [{'label': 'tower', 'center': [10, 2, 1.5], 'size': [1, 1, 3]},
                    {'label': 'tree', 'center': [3, 7, 0.4], 'size': [1, 1, 0.8]},
                    {'label': 'antenna', 'center': [9, 8, 2.5], 'size': [0.2, 0.2, 1]}],
    }
    plan, aut, rmap, world = _plan('F (near[tree] & F near[tower]) & G !near[antenna]', drone)
    assert plan.dims == 3 and plan.verification.ok
    path = plan.path()
    assert path.shape[1] == 3 and path[:, 2].min() >= 1.0 - 1e-9 and path[:, 2].max() <= 3.0 + 1e-9


def test_a_referent_with_no_instance_is_named_in_the_error():
    scene = scene_from_dict(ROOM)
    aut = compile_automaton('F near[unicorn]')
    with pytest.raises(PlanningError) as e:
        plan_task(aut, ReferentMap({}), world_from_scene(scene), scene.robot.start, FAST)
    assert 'near[unicorn]' in e.value.message and e.value.details['empty_regions'] == ['near[unicorn]']


@settings(max_examples=15, derandomize=True, deadline=None)
@given(st.floats(0.0, 20.0), st.floats(0.0, 12.0), st.sampled_from(['sofa', 'table', 'chair', 'cup']),
       st.sampled_from(['door', 'chair', 'table']))
def test_random_starts_give_a_verified_plan_or_a_typed_error(x, y, goal, avoid):
    scene = scene_from_dict(dict(ROOM, robot={'kind': 'ground', 'start': [x, y, 0], 'radius': 0.3}))
    text = f'F near[{goal}] & G !near[{avoid}]'
    aut = compile_automaton(text)
    world = world_from_scene(scene)
    try:
        plan = plan_task(aut, referent_map(scene, aut.formula), world, (x, y), FAST)
    except (PlanningError, UnsatisfiableError) as e:
        assert e.code in (ErrorCode.START_OCCUPIED, ErrorCode.GOAL_OCCUPIED, ErrorCode.NO_VALID_PATH,
                          ErrorCode.UNSATISFIABLE)
        return
    assert plan.verification.ok
    assert world.is_free(plan.path()).all()


def test_junctions_are_chosen_for_the_whole_task_and_keep_the_margins():
    """A visit on the way: the junction moves round the first goal towards the second, shortening the plan."""
    scene = dict(ROOM, objects=[{'label': 'lamp', 'center': [6, 6, 0.4], 'size': [0.4, 0.4, 0.8]},
                                {'label': 'plant', 'center': [9, 1, 0.4], 'size': [0.4, 0.4, 0.8]}],
                 obstacles=[])
    greedy = _plan('F (near[lamp] & F near[plant])', scene, replace(FAST, shorten_junctions=False))[0]
    plan, aut, rmap, world = _plan('F (near[lamp] & F near[plant])', scene)
    assert plan.verification.ok and len(plan.steps) == 2
    assert plan.length < greedy.length - 0.05
    assert np.allclose(plan.steps[0].end, plan.steps[1].waypoints[0])
    assert min(plan.verification.goal_depths) >= FAST.goal_margin - 0.01
    again = verify_plan(plan.steps, plan.start, aut, rmap, world, FAST.near_threshold)
    assert again.ok and again.margins_ok

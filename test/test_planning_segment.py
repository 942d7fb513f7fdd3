"""Planning core: one FMT* segment through a symbolic TPSM, and its typed failures."""
from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.automaton.guards import GUARD_TRUE, Cube, Guard
from ltl_instruct.core.errors import ErrorCode, InvalidInputError
from ltl_instruct.core.planning import (
    AtomRegion, FmtSettings, PlanningWorld, SegmentProblem, SegmentRequest, SegmentResult, resample,
    solve_segment,
)
from ltl_instruct.core.planning.grid import grid_optimum
from ltl_instruct.core.spec import Atom, Descriptor
from ltl_instruct.core.world.scene import Box

A = Atom('near', (Descriptor('a'),))
B = Atom('near', (Descriptor('b'),))
FAST = FmtSettings(num_samples=1500, time_limit=5.0, seed=3)


def _goal_a_avoid_b() -> tuple[Guard, Guard]:
    return Guard((Cube(frozenset({A}), frozenset({B})),)), Guard((Cube(frozenset(), frozenset({A, B})),))


def _world(obstacles=()) -> PlanningWorld:
    return PlanningWorld(2, (0.0, 0.0), (10.0, 6.0), 0.2, tuple(obstacles))


def _request(start=(1.0, 3.0), a=(9.0, 3.0), b_boxes=(), b_radius=0.5, settings=FAST, **kw) -> SegmentRequest:
    goal, allowed = _goal_a_avoid_b()
    regions = (AtomRegion('near[a]', (a + (0.0,),), ((0.0, 0.0, 0.0),), 0.8),
               AtomRegion('near[b]', tuple(c for c, _ in b_boxes), tuple(s for _, s in b_boxes), b_radius))
    return SegmentRequest('t/0', start, 2, regions, goal, allowed, settings, transition=(0, 1), **kw)


def _check_path(req: SegmentRequest, world: PlanningWorld, result: SegmentResult) -> None:
    """Every point but the last is free and allowed; the last is the first in the goal (1 cm sampling)."""
    assert result.ok, result.error and result.error.message
    problem = SegmentProblem(req, world)
    w = result.waypoints
    assert np.allclose(w[0], req.start)
    dense = resample(w, 0.01)
    valid, goal = problem.classify(dense)
    assert valid.all()
    assert goal[-1] and not goal[1:-1].any()


def test_straight_segment_is_short_and_ends_at_the_goal_boundary():
    world = _world()
    req = _request()
    result = solve_segment(req, world)
    _check_path(req, world, result)
    assert result.length == pytest.approx(8.0 - 0.8, abs=0.02)
    assert result.points is not None
    assert np.max(np.linalg.norm(np.diff(result.points, axis=0), axis=1)) <= 0.05 + 1e-9


def test_avoid_region_in_the_way_is_circumvented_and_seed_fixes_the_path():
    world = _world()
    req = _request(b_boxes=[((5.0, 3.0, 0.0), (0.5, 3.0, 0.0))], b_radius=0.6)
    r1 = solve_segment(req, world)
    r2 = solve_segment(req, world)
    _check_path(req, world, r1)
    assert np.array_equal(r1.waypoints, r2.waypoints)
    assert r1.length > 7.2
    opt = grid_optimum(req, world, cell=0.05)
    assert opt is not None and r1.length <= 1.05 * opt


def test_a_thin_avoid_band_cannot_be_jumped():
    world = _world()
    # a 4 cm band across the whole map: no path may cross it
    req = _request(b_boxes=[((5.0, 3.0, 0.0), (0.02, 6.0, 0.0))], b_radius=0.01)
    result = solve_segment(req, world)
    assert not result.ok
    assert result.error.code in (ErrorCode.NO_VALID_PATH, ErrorCode.TIMEOUT)
    # with a gap the path goes through the gap
    req = _request(b_boxes=[((5.0, 1.5, 0.0), (0.02, 3.0, 0.0)), ((5.0, 5.5, 0.0), (0.02, 1.0, 0.0))],
                   b_radius=0.01)
    result = solve_segment(req, world)
    _check_path(req, world, result)
    crossing = resample(result.waypoints, 0.01)
    y_at_band = crossing[np.argmin(np.abs(crossing[:, 0] - 5.0)), 1]
    assert 3.0 < y_at_band < 5.0


@pytest.mark.parametrize('dims', [2, 3])
def test_the_grid_box_holds_every_shorter_way(dims):
    # a point of a way from the start to goal g no longer than L has |s - p| + |p - g| <= L
    from ltl_instruct.core.planning.segment import _shorter_ways_box
    rng = np.random.default_rng(dims)
    for _ in range(20):
        start, goals = rng.uniform(-5, 5, dims), rng.uniform(-5, 5, (6, dims))
        length = float(np.linalg.norm(goals - start, axis=1).min()) * rng.uniform(1.0, 3.0)
        lo, hi = _shorter_ways_box(start, goals, length)
        pts = rng.uniform(-20, 20, (20000, dims))
        way = np.linalg.norm(pts - start, axis=1)[:, None] + \
            np.linalg.norm(pts[:, None] - goals[None], axis=2)
        inside = pts[(way <= length).any(axis=1)]
        assert np.all(inside >= lo) and np.all(inside <= hi)
        # within the ball such a way could fill
        assert np.all(lo >= start - length - 0.5 - 1e-9) and np.all(hi <= start + length + 0.5 + 1e-9)


def test_a_straight_way_into_the_goal_is_taken_without_fmt():
    world = _world()
    req = _request()
    direct = solve_segment(req, world)
    _check_path(req, world, direct)
    assert direct.planner_seconds == 0.0   # FMT* never ran
    sampled = solve_segment(req, world, replace(FAST, direct=False))
    assert sampled.planner_seconds > 0.0
    assert direct.length <= sampled.length + 1e-6
    # a wall in the way: no straight way, FMT* plans round it
    walled = _world([Box((5.0, 3.0, 0.0), (0.2, 2.0, 1.0))])
    round_it = solve_segment(req, walled)
    _check_path(req, walled, round_it)
    assert round_it.planner_seconds > 0.0 and round_it.length > 7.2


def test_a_narrow_passage_the_samples_miss_is_found_on_the_grid():
    # a wall across the map with a 0.5 m gap near the straight way (0.1 m of free space for a 0.2 m
    # robot) and a wide one far above: 200 samples miss the gap and go round; the grid finds it
    world = PlanningWorld(2, (0.0, 0.0), (10.0, 12.0), 0.2, (
        Box((5.0, 1.375, 0.0), (0.2, 2.75, 1.0)), Box((5.0, 6.625, 0.0), (0.2, 6.75, 1.0))))
    sparse = FmtSettings(num_samples=200, time_limit=5.0, seed=3, grid_cell=0.0)
    way = dict(start=(1.0, 1.5), a=(9.0, 1.5))
    round_about = solve_segment(_request(settings=sparse, **way), world)
    assert round_about.ok and round_about.length > 12.0
    req = _request(settings=replace(sparse, grid_cell=0.05), **way)
    through = solve_segment(req, world)
    _check_path(req, world, through)
    assert through.length < 8.0
    dense = resample(through.waypoints, 0.01)
    assert 2.75 < dense[np.argmin(np.abs(dense[:, 0] - 5.0)), 1] < 3.25
    assert FmtSettings().grid_cell == 0.05
    with pytest.raises(InvalidInputError):
        FmtSettings(grid_cell=-1.0)


def test_typed_failures_say_which_transition():
    wall = Box((8.0, 3.0, 0.0), (0.2, 6.0, 1.0))
    blocked = solve_segment(_request(), _world([wall]))
    assert blocked.error.code == ErrorCode.NO_VALID_PATH and 'transition 0 -> 1' in blocked.error.message
    inside = solve_segment(_request(a=(9.0, 3.0)), _world([Box((9.0, 3.0, 0.0), (3.0, 3.0, 1.0))]))
    assert inside.error.code == ErrorCode.GOAL_OCCUPIED
    start_hit = solve_segment(_request(start=(5.0, 3.0)), _world([Box((5.0, 3.0, 0.0), (1.0, 1.0, 1.0))]))
    assert start_hit.error.code == ErrorCode.START_OCCUPIED
    start_avoid = solve_segment(_request(start=(5.0, 3.0), b_boxes=[((5.0, 3.0, 0.0), (0.0, 0.0, 0.0))]),
                                _world())
    assert start_avoid.error.code == ErrorCode.START_OCCUPIED and 'avoid' in start_avoid.error.message
    for r in (blocked, inside, start_hit, start_avoid):
        assert r.to_dict()['ok'] is False and r.points is None


def test_start_already_in_the_goal_gives_a_zero_length_step():
    result = solve_segment(_request(start=(8.8, 3.0)), _world())
    assert result.ok and result.length == 0.0 and len(result.waypoints) == 2


def test_request_round_trips_through_json_and_rejects_garbage():
    req = _request(b_boxes=[((5.0, 3.0, 0.0), (0.5, 3.0, 0.0))], target=('near[a]', 0))
    back = SegmentRequest.from_dict(json.loads(json.dumps(req.to_dict())))
    assert back == req
    good = req.to_dict()
    bad_inputs = [None, [], 'x', {}, dict(good, dims=4), dict(good, start=[float('nan'), 0]),
                  dict(good, start='1,2'), dict(good, goal={'cubes': 'no'}),
                  dict(good, goal={'cubes': [{'pos': ['near[[x'], 'neg': []}]}),
                  dict(good, regions=[]), dict(good, regions=[5]), dict(good, settings={'num_samples': -3}),
                  dict(good, settings={'bogus': 1}), dict(good, target={'atom': 'near[zz]', 'instance': 0}),
                  dict(good, target={'atom': 'near[a]', 'instance': 7}), dict(good, id='x' * 5000),
                  dict(good, transition='0->1')]
    for bad in bad_inputs:
        with pytest.raises(InvalidInputError):
            SegmentRequest.from_dict(bad)


def test_target_restricts_the_goal_to_one_instance():
    goal, allowed = _goal_a_avoid_b()
    regions = (AtomRegion('near[a]', ((2.0, 3.0, 0.0), (9.0, 3.0, 0.0)), ((0.0, 0.0, 0.0),) * 2, 0.8),
               AtomRegion('near[b]', (), (), 0.5))
    world = _world()
    near_first = solve_segment(SegmentRequest('t', (1.0, 1.0), 2, regions, goal, allowed, FAST), world)
    assert np.linalg.norm(near_first.waypoints[-1] - [2.0, 3.0]) <= 0.81
    far = solve_segment(SegmentRequest('t', (1.0, 1.0), 2, regions, goal, allowed, FAST,
                                       target=('near[a]', 1)), world)
    assert far.ok and np.linalg.norm(far.waypoints[-1] - [9.0, 3.0]) <= 0.81
    # the other instance is avoided on the way
    dense = resample(far.waypoints, 0.01)
    assert np.linalg.norm(dense[:-1] - [2.0, 3.0], axis=1).min() > 0.8


def test_rrtstar_and_3d_segments_work():
    world3 = PlanningWorld(3, (0.0, 0.0, 1.0), (6.0, 6.0, 3.0), 0.2, (Box((3.0, 2.0, 2.0), (0.4, 4.0, 4.0)),))
    goal = Guard((Cube(frozenset({A})),))
    regions = (AtomRegion('near[a]', ((5.0, 5.0, 2.0),), ((0.2, 0.2, 0.2),), 0.5),)
    for planner in ('fmt', 'rrtstar'):
        s = FmtSettings(num_samples=1500, time_limit=1.0 if planner == 'rrtstar' else 5.0, planner=planner)
        req = SegmentRequest('t', (1.0, 1.0, 2.0), 3, regions, goal, GUARD_TRUE, s)
        result = solve_segment(req, world3)
        assert result.ok, result.error and result.error.message
        assert result.waypoints.shape[1] == 3
        dense = resample(result.waypoints, 0.01)
        assert world3.is_free(dense).all()
    with pytest.raises(InvalidInputError):
        solve_segment(req, _world())   # a 3D request in a 2D world


def test_segment_result_from_received_waypoints():
    r = SegmentResult.from_waypoints('x', np.array([[0.0, 0.0], [1.0, 0.0]]), spacing=0.1)
    assert r.ok and r.length == pytest.approx(1.0) and len(r.points) == 11
    with pytest.raises(InvalidInputError):
        SegmentResult.from_waypoints('x', np.array([[np.nan, 0.0]]))


json_values = st.recursive(
    st.none() | st.booleans() | st.integers(-10, 10) | st.floats(allow_nan=True) | st.text(max_size=12),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
    max_leaves=20)


@settings(max_examples=200, derandomize=True, deadline=None)
@given(st.dictionaries(st.sampled_from(['id', 'start', 'dims', 'regions', 'goal', 'allowed', 'settings',
                                        'target', 'bounds', 'transition']), json_values))
def test_garbage_requests_only_raise_invalid_input(d):
    good = _request().to_dict()
    try:
        SegmentRequest.from_dict(dict(good, **d))
    except InvalidInputError:
        pass


def test_a_shallow_corner_survives_dropping_collinear_points():
    """A corner of 0.2 degrees densified at 1 cm is kept: dropping it cut an obstacle by 4 mm (CI)."""
    from ltl_instruct.core.planning.segment import _drop_collinear
    corner = np.array([[8.1205, 6.8003], [8.9064, 2.8988], [9.1952, 1.4349]])
    dense = resample(corner, 0.01)
    out = _drop_collinear(dense)
    assert len(out) < 10                       # the straight runs are gone
    fine, kept = resample(corner, 0.0005), resample(out, 0.0005)
    gap = max(np.linalg.norm(fine - p, axis=1).min() for p in kept[::5])
    assert gap < 0.001, gap                    # and the path is the same path
    assert len(_drop_collinear(resample(np.array([[0.0, 0.0], [5.0, 1.0]]), 0.01))) == 2

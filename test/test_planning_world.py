"""Planning core: the collision model (scenes, occupancy grids, point clouds) and atom regions."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.guards import Guard
from ltl_instruct.core.errors import InvalidInputError, LtlInstructError
from ltl_instruct.core.grounding.rsm import Instance
from ltl_instruct.core.planning import (
    AVOID, GOAL, NEUTRAL, AtomRegion, RegionSet, TaskProgressionMap, navigation_guard, skill_guard,
    world_from_occupancy, world_from_points, world_from_scene,
)
from ltl_instruct.core.planning.regions import eval_guard_vectorised, eval_key_cubes, key_cubes
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world import near
from ltl_instruct.core.world.scene import scene_from_dict

SCENE = {
    'bounds': {'min': [0, 0, 0], 'max': [10, 8, 3]},
    'robot': {'kind': 'ground', 'start': [1, 1, 0], 'radius': 0.3},
    'obstacles': [{'center': [5, 2, 1], 'size': [0.2, 4, 2]}],
    'objects': [{'label': 'sofa', 'center': [8, 6, 0.4], 'size': [1, 1, 0.8]},
                {'label': 'rug', 'center': [2, 6, 0.0], 'size': [2, 2, 0.01], 'passable': True}],
}


def test_scene_world_inflates_obstacles_and_solid_objects_by_the_robot_radius():
    w = world_from_scene(scene_from_dict(SCENE))
    assert w.dims == 2
    assert w.bounds_min == (0.3, 0.3) and w.bounds_max == (9.7, 7.7)
    # wall x in [4.9, 5.1]: 0.25 m away is blocked, 0.35 m is free
    assert not w.is_free(np.array([[4.65, 2.0]]))[0]
    assert w.is_free(np.array([[4.55, 2.0]]))[0]
    # the sofa is solid, the rug passable
    assert not w.is_free(np.array([[8.0, 6.0]]))[0]
    assert w.is_free(np.array([[2.0, 6.0]]))[0]
    # out of bounds and NaN are never free
    assert not w.is_free(np.array([[0.1, 1.0], [np.nan, 1.0]])).any()


def test_drone_world_plans_inside_the_altitude_band():
    d = dict(SCENE, robot={'kind': 'drone', 'start': [1, 1, 1.5], 'radius': 0.2},
             altitude={'min': 1.0, 'max': 2.5})
    w = world_from_scene(scene_from_dict(d))
    assert w.dims == 3
    assert w.bounds_min[2] == 1.0 and w.bounds_max[2] == 2.5
    assert w.is_free(np.array([[1, 1, 1.5]]))[0]
    assert not w.is_free(np.array([[1, 1, 0.5]]))[0]


@settings(max_examples=150, derandomize=True, deadline=None)
@given(st.floats(0.3, 9.7), st.floats(0.3, 7.7), st.floats(0, 2 * math.pi), st.floats(0, 1))
def test_clearance_certifies_a_free_ball(x, y, angle, frac):
    w = world_from_scene(scene_from_dict(SCENE))
    c = w.clearance((x, y))
    assert (c >= 0) == bool(w.is_free(np.array([[x, y]]))[0])
    if c > 0:
        q = np.array([[x + 0.999 * c * frac * math.cos(angle), y + 0.999 * c * frac * math.sin(angle)]])
        assert w.is_free(q)[0]


@settings(max_examples=60, derandomize=True, deadline=None)
@given(st.integers(0, 10_000), st.sampled_from([2, 3]), st.integers(0, 120))
def test_cell_index_answers_as_the_test_against_every_box(seed, dims, n_boxes):
    """point_free and segment_hits_box use a cell index; brute force over all boxes must agree.

    The robot is a disc (a ball in 3D): blocked within the radius of a box, corners rounded.
    """
    from ltl_instruct.core.planning.occupancy import PlanningWorld
    from ltl_instruct.core.world.scene import Box
    rng = np.random.default_rng(seed)
    size = np.array([30.0, 20.0, 10.0])
    boxes = tuple(Box(tuple(rng.uniform(-2, size + 2)), tuple(rng.uniform(0.01, 4.0, 3)))
                  for _ in range(n_boxes))
    radius = float(rng.uniform(0, 0.5))
    w = PlanningWorld(dims, (0.0,) * dims, tuple(size[:dims]), radius, boxes)
    raw_lo = np.array([b.lo[:dims] for b in boxes]).reshape(-1, dims)
    raw_hi = np.array([b.hi[:dims] for b in boxes]).reshape(-1, dims)
    pts = rng.uniform(-1, size[:dims] + 1, (300, dims))
    # points on the rounded boxes' flat faces, near their corners, and on cell boundaries are the edge cases
    if n_boxes:
        pick = rng.integers(0, n_boxes, 80)
        pts[:40] = raw_lo[pick[:40]] - np.eye(dims)[rng.integers(0, dims, 40)] * radius
        corner = rng.normal(size=(40, dims))
        corner /= np.linalg.norm(corner, axis=1, keepdims=True)
        pts[40:80] = raw_hi[pick[40:]] + np.abs(corner) * radius * rng.choice([0.98, 1.02], (40, 1))
    free = w.is_free(pts)
    for p, f in zip(pts, free):
        gap = np.maximum(np.maximum(raw_lo - p, p - raw_hi), 0.0)
        blocked = bool(np.any(np.sqrt((gap ** 2).sum(axis=1)) <= radius)) if n_boxes else False
        in_bounds = bool(np.all(p >= 0) and np.all(p <= size[:dims]))
        assert w.point_free(tuple(p)) == (in_bounds and not blocked) == (w.clearance(tuple(p)) >= 0) == f
    for a, b in zip(pts[::2], pts[1::2]):   # the index only narrows which boxes get the exact test
        near_box = np.all((np.minimum(a, b) <= raw_hi + radius) & (np.maximum(a, b) >= raw_lo - radius),
                          axis=1)
        least = min((near.segment_box_distance(tuple(a), tuple(b), tuple(lo), tuple(hi))
                     for lo, hi in zip(raw_lo[near_box], raw_hi[near_box])), default=np.inf)
        assert w.segment_hits_box(tuple(a), tuple(b)) == (least <= radius)


@settings(max_examples=200, derandomize=True, deadline=None)
@given(st.integers(0, 10_000), st.sampled_from([2, 3]))
def test_segment_box_distance_is_the_least_over_the_segment(seed, dims):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(-1, 1, dims)
    hi = lo + rng.uniform(0, 1, dims) * (rng.random(dims) > 0.1)   # some flat boxes
    a, b = rng.uniform(-3, 3, dims), rng.uniform(-3, 3, dims)
    if rng.random() < 0.3:
        b[0] = a[0]                                                  # parallel to a face
    along = a + np.linspace(0.0, 1.0, 4001)[:, None] * (b - a)
    sampled = float(near.box_distance(along, ((lo + hi) / 2)[None], (hi - lo)[None], dims).min())
    exact = near.segment_box_distance(tuple(a), tuple(b), tuple(lo), tuple(hi))
    assert exact <= sampled + 1e-12
    assert sampled - exact <= np.linalg.norm(b - a) / 4000      # within the sampling step


def test_a_disc_passes_a_diagonal_gap_that_square_inflation_would_close():
    """Two boxes 0.7 m apart corner to corner: a 0.3 m disc passes, a 0.6 m square would not."""
    from ltl_instruct.core.planning.occupancy import PlanningWorld
    from ltl_instruct.core.world.scene import Box
    gap = 0.7 / math.sqrt(2)
    boxes = (Box((1.0, 1.0, 0.5), (2.0, 2.0, 1.0)), Box((3.0 + gap, 3.0 + gap, 0.5), (2.0, 2.0, 1.0)))
    w = PlanningWorld(2, (-5.0, -5.0), (10.0, 10.0), 0.3, boxes)
    mid = (2.0 + gap / 2, 2.0 + gap / 2)
    assert w.point_free(mid) and w.is_free(np.array([mid]))[0]
    assert abs(w.clearance(mid) - 0.05) < 1e-9
    # the straight line between the two boxes' free sides, through the gap
    assert not w.segment_hits_box((mid[0] - 2.0, mid[1] + 2.0), (mid[0] + 2.0, mid[1] - 2.0))
    assert w.segment_hits_box((mid[0] - 2.0, mid[1] - 2.0), (mid[0] + 2.0, mid[1] + 2.0))


def test_occupancy_grid_world_blocks_occupied_unknown_and_inflated_cells():
    cells = np.zeros((20, 30), dtype=np.int8)   # 3 m x 2 m at 0.1 m
    cells[:, 15] = 100                           # a wall at x in [1.5, 1.6)
    cells[0, 0] = -1                             # unknown corner
    w = world_from_occupancy(cells, 0.1, (0.0, 0.0), robot_radius=0.25)
    assert not w.is_free(np.array([[1.55, 1.0]]))[0]
    assert not w.is_free(np.array([[1.35, 1.0]]))[0]       # within the radius of the wall
    assert w.is_free(np.array([[1.0, 1.0]]))[0]
    assert not w.is_free(np.array([[0.05, 0.05]]))[0]
    assert w.clearance((1.0, 1.0)) == 0.0 and w.clearance((1.55, 1.0)) < 0
    with pytest.raises(InvalidInputError):
        world_from_occupancy(np.zeros((0, 0)), 0.1, (0, 0))
    with pytest.raises(InvalidInputError):
        world_from_occupancy(cells, float('nan'), (0, 0))


def test_point_cloud_world_is_3d_and_inflated():
    pts = np.array([[2.0, y, z] for y in np.arange(0, 4, 0.1) for z in np.arange(0, 3, 0.1)])
    w = world_from_points(pts, voxel=0.1, robot_radius=0.2, bounds_min=(0, 0, 0), bounds_max=(4, 4, 3))
    assert w.dims == 3
    assert not w.is_free(np.array([[2.05, 1.0, 1.0]]))[0]
    assert not w.is_free(np.array([[2.25, 1.0, 1.0]]))[0]
    assert w.is_free(np.array([[3.0, 1.0, 1.0]]))[0]
    with pytest.raises(InvalidInputError):
        world_from_points(np.full((3, 3), np.nan))


# --------------------------------------------------------------------------- regions

@settings(max_examples=100, derandomize=True, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(0, 2)), min_size=1, max_size=20),
       st.floats(0, 3), st.floats(0, 3), st.integers(2, 3))
def test_region_distance_matches_the_referent_map_instances(points, sx, sy, dims):
    inst = [Instance('a', 'a', (1.0, -2.0, 0.5), (sx, sy, 1.0)), Instance('b', 'b', (-3.0, 1.0, 1.0))]
    region = AtomRegion('near[a]', tuple(i.center for i in inst), tuple(i.size for i in inst), 1.0)
    p = np.asarray(points)
    expected = np.min([i.distance(p, dims) for i in inst], axis=0)
    assert np.allclose(region.distance(p, dims), expected)


@settings(max_examples=150, derandomize=True, deadline=None)
@given(st.floats(-4, 4), st.floats(-4, 4), st.floats(0, 2 * math.pi), st.floats(0, 0.999))
def test_letter_margin_means_no_atom_changes_inside_it(x, y, angle, frac):
    regions = RegionSet([AtomRegion('near[a]', ((0.0, 0.0, 0.0),), ((1.0, 2.0, 0.0),), 1.0),
                         AtomRegion('near[b]', ((2.0, 1.0, 0.0), (-2.0, -2.0, 0.0)),
                                    ((0.0, 0.0, 0.0),) * 2, 0.7)],
                        dims=2)
    letter, margin = regions.letter_and_margin((x, y))
    vec = regions.valuation(np.array([[x, y]]))
    assert letter == frozenset(k for k, v in vec.items() if v[0])
    q = (x + frac * margin * math.cos(angle), y + frac * margin * math.sin(angle))
    assert regions.letter_and_margin(q)[0] == letter


def _letters(atoms):
    out = []
    for mask in range(2 ** len(atoms)):
        out.append(frozenset(a for i, a in enumerate(atoms) if mask >> i & 1))
    return out


@pytest.mark.parametrize('text', [
    'F (pick[cup] & F release[cup, table]) & G !near[door]',
    '(!near[a] U (near[a] & pick[x])) | F release[x, a]',
])
def test_navigation_and_skill_guards_agree_with_the_automaton(text):
    aut = compile_automaton(parse_formula(text))
    nav_atoms = [a for a in aut.atoms if not a.is_event]
    events = [a for a in aut.atoms if a.is_event]
    for e in aut.edges():
        nav = key_cubes(navigation_guard(e.guard))
        for letter in _letters(nav_atoms):
            keys = frozenset(a.key for a in letter)
            assert eval_key_cubes(nav, keys) == e.guard.evaluate(letter)
            for ev in events:
                sk = key_cubes(skill_guard(e.guard, ev))
                assert eval_key_cubes(sk, keys) == e.guard.evaluate(letter | {ev})


def test_tpsm_classifies_goal_avoid_and_neutral_points():
    aut = compile_automaton(parse_formula('F near[a] & G !near[b]'))
    s0 = aut.initial
    edge = next(e for e in aut.edges_from(s0) if e.dst not in (s0, aut.sink))
    regions = (AtomRegion('near[a]', ((5.0, 0.0, 0.0),), ((0.0, 0.0, 0.0),), 1.0),
               AtomRegion('near[b]', ((0.0, 5.0, 0.0),), ((0.0, 0.0, 0.0),), 1.0))
    tpsm = TaskProgressionMap(navigation_guard(edge.guard), navigation_guard(aut.self_loop(s0)), regions, 2)
    values = tpsm.classify(np.array([[5.0, 0.5], [0.0, 5.5], [2.0, 2.0]]))
    assert values.tolist() == [GOAL, AVOID, NEUTRAL]
    pts, vals = tpsm.render((0, 0), (6, 6), spacing=0.5)
    assert pts.shape[1] == 3 and len(pts) == len(vals) == 13 * 13
    assert {GOAL, AVOID, NEUTRAL} <= set(vals.tolist())
    with pytest.raises(InvalidInputError):
        tpsm.render((0, 0), (6, 6), spacing=0.0)


def test_guard_evaluation_vectorised_matches_scalar():
    g = Guard.from_dict({'cubes': [{'pos': ['near[a]'], 'neg': ['near[b]']},
                                   {'pos': ['near[c]'], 'neg': []}]})
    cubes = key_cubes(g)
    rng = np.random.default_rng(0)
    val = {k: rng.random(64) < 0.5 for k in ('near[a]', 'near[b]', 'near[c]')}
    vec = eval_guard_vectorised(cubes, val, 64)
    for i in range(64):
        letter = frozenset(k for k, v in val.items() if v[i])
        assert vec[i] == eval_key_cubes(cubes, letter)


def test_region_from_dict_rejects_garbage():
    for bad in [{}, {'atom': 'near[a]', 'radius': 'x'},
                {'atom': 'near[a]', 'radius': 1.0, 'instances': [{'center': [1]}]},
                {'atom': 'near[a]', 'radius': float('nan'), 'instances': []}]:
        with pytest.raises(LtlInstructError):
            AtomRegion.from_dict(bad)
    r = AtomRegion('near[a]', ((1.0, 2.0, 0.0),), ((0.5, 0.5, 0.5),), 1.2)
    assert AtomRegion.from_dict(r.to_dict()) == r

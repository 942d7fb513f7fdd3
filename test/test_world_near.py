"""The one definition of ``near[x]``: distances to boxes, against brute force, and its users agree."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.rsm import Instance
from ltl_instruct.core.world import near
from ltl_instruct.core.world.scene import Box

coords = st.floats(-5.0, 5.0, allow_nan=False)
sizes = st.floats(0.0, 3.0, allow_nan=False)


def _brute_distance(p: np.ndarray, center: np.ndarray, size: np.ndarray, n: int = 41) -> float:
    """Distance to a box from a dense grid over its surface and inside (upper bound, tight to the step)."""
    axes = [np.linspace(c - s / 2, c + s / 2, n) if s > 0 else np.array([c]) for c, s in zip(center, size)]
    grid = np.stack(np.meshgrid(*axes, indexing='ij'), axis=-1).reshape(-1, len(center))
    return float(np.linalg.norm(grid - p, axis=1).min())


@settings(max_examples=150, derandomize=True, deadline=None)
@given(st.tuples(coords, coords, coords), st.tuples(coords, coords, coords), st.tuples(sizes, sizes, sizes),
       st.sampled_from([2, 3]))
def test_box_distance_matches_brute_force(p, c, s, dims):
    p, c, s = np.asarray(p), np.asarray(c), np.asarray(s)
    fast = float(near.box_distance(p, c[None], s[None], dims)[0])
    brute = _brute_distance(p[:dims], c[:dims], s[:dims])
    step = float(np.max(s[:dims])) / 40 * math.sqrt(dims)
    assert fast <= brute + 1e-9 and brute <= fast + step + 1e-9
    # the scalar path agrees with the vectorised one
    assert near.point_distance(tuple(p), near.box_corners([c], [s], dims)) == pytest.approx(fast, abs=1e-12)
    # inside the box is distance 0
    assert float(near.box_distance(c, c[None], s[None], dims)[0]) == 0.0


def test_many_points_many_boxes_take_the_nearest_box():
    rng = np.random.default_rng(0)
    pts = rng.uniform(-5, 5, (200, 3))
    centers = rng.uniform(-5, 5, (7, 3))
    box_sizes = rng.uniform(0, 2, (7, 3))
    d = near.box_distance(pts, centers, box_sizes, 2)
    one_by_one = np.min([near.box_distance(pts, centers[i:i + 1], box_sizes[i:i + 1], 2) for i in range(7)],
                        axis=0)
    assert d.shape == (200,) and np.array_equal(d, one_by_one)
    assert np.all(near.box_distance(pts, np.zeros((0, 3)), np.zeros((0, 3)), 2) == np.inf)


def test_every_box_distance_in_the_package_is_this_one():
    p = np.array([[2.0, 3.5, 0.7], [0.1, 0.1, 0.1]])
    inst = Instance('a', 'a', (1.0, 1.0, 0.5), (1.0, 2.0, 1.0))
    box = Box((1.0, 1.0, 0.5), (1.0, 2.0, 1.0))
    expected = near.box_distance(p, np.array([inst.center]), np.array([inst.size]), 2)
    assert np.array_equal(inst.distance(p, 2), expected)
    assert np.array_equal(box.distance(p, 2), expected)
    assert np.array_equal(near.instances_distance([inst], p, 2), expected)


def test_the_boundary_is_near_and_depth_is_threshold_minus_distance():
    assert near.is_near(1.0, 1.0) and not near.is_near(1.0 + 1e-12, 1.0)
    assert near.depth(0.8, 1.0) == pytest.approx(0.2)
    assert near.near_instances([], np.zeros((3, 2)), 2).tolist() == [False] * 3


def test_thresholds_and_margins_are_validated():
    assert near.check_threshold(near.DEFAULT_NEAR_THRESHOLD) == 1.0
    for bad in (0.0, -1.0, float('nan'), float('inf'), 'x', True):
        with pytest.raises(InvalidInputError):
            near.check_threshold(bad)
    assert near.check_margin(0.0, 'goal_margin') == 0.0
    for bad in (-0.1, float('nan'), near.MAX_MARGIN + 1, None):
        with pytest.raises(InvalidInputError):
            near.check_margin(bad, 'goal_margin')


def test_outline_is_the_region_boundary():
    ring = near.outline_xy((2.0, 1.0), (1.0, 0.5), 0.8)
    d = near.box_distance(ring, np.array([[2.0, 1.0]]), np.array([[1.0, 0.5]]), 2)
    assert np.allclose(d, 0.8) and np.array_equal(ring[0], ring[-1])
    lo, hi = near.region_box((2.0, 1.0, 0.0), (1.0, 0.5, 0.0), 0.8, 2)
    assert np.allclose(lo, [0.7, -0.05]) and np.allclose(hi, [3.3, 2.05])

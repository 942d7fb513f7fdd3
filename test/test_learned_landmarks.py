"""Landmark graphs: names, metric frame, Delaunay edges, k-th shortest and simulated trajectories."""
import math

import networkx as nx
import numpy as np
import pytest

from ltl_instruct.core.errors import InvalidInputError, PlanningError
from ltl_instruct.core.world.landmarks import (
    LandmarkMap, build_landmark_map, delaunay_edges, kth_shortest_path, local_metric_frame,
    shortest_path, simulate_trajectory, snake_case_name, unique_snake_case_names,
)
from learned_synthetic import LAT_LON, NAMES, synthetic_map


def test_snake_case_names_follow_the_grammar():
    assert snake_case_name('Busch-Reisinger Museum') == 'busch_reisinger_museum'
    assert snake_case_name("Joe's Café") == 'joe_s_caf'
    assert snake_case_name('7-Eleven') == 'l_7_eleven'
    assert snake_case_name('Release') == 'release_place'
    assert snake_case_name('!!!') == 'landmark'
    assert unique_snake_case_names(['A b', 'a-b', 'a_b']) == ('a_b', 'a_b_2', 'a_b_3')


def test_metric_frame_scale_and_origin():
    xy = local_metric_frame(np.array([[42.0, -71.0], [42.001, -71.0], [42.0, -71.001]]))
    assert np.allclose(xy.mean(axis=0), 0.0, atol=1e-6)
    assert math.isclose(xy[1, 1] - xy[0, 1], 111.19, rel_tol=2e-3)           # 0.001 deg of latitude
    assert math.isclose(xy[0, 0] - xy[2, 0], 111.19 * math.cos(math.radians(42.0003)), rel_tol=2e-3)


@pytest.mark.parametrize('bad', [np.zeros((0, 2)), np.array([[np.nan, 1.0]]), np.array([[91.0, 0.0]]),
                                 np.zeros((3, 3))])
def test_metric_frame_rejects_bad_centres(bad):
    with pytest.raises(InvalidInputError):
        local_metric_frame(bad)


def test_delaunay_edges_of_a_square_and_a_line():
    square = np.array([[0, 0], [1, 0], [0, 1], [1.0, 1.1]])
    edges = delaunay_edges(square)
    assert {(0, 1), (0, 2), (1, 3), (2, 3)} <= edges and len(edges) == 5
    line = np.array([[0, 0], [2, 0], [1, 0.0]])
    assert delaunay_edges(line) == {(0, 2), (1, 2)}


def test_map_graph_weights_are_lengths_and_round_trip():
    lmap = synthetic_map()
    g = lmap.graph()
    assert nx.is_connected(g)
    for i, j, w in g.edges(data='weight'):
        assert w == pytest.approx(np.linalg.norm(lmap.xy[i] - lmap.xy[j]))
    again = LandmarkMap.from_dict(lmap.to_dict())
    assert again.edges == lmap.edges and again.props == lmap.props and np.allclose(again.xy, lmap.xy)
    with pytest.raises(InvalidInputError):
        LandmarkMap.from_dict({'city': 'x', 'names': ['a'], 'props': ['a'], 'xy': [[0, 0]],
                               'edges': [[0, 5]]})


def test_extra_edges_are_added_and_checked():
    base = build_landmark_map('t', NAMES, LAT_LON)
    far = (0, 5)
    assert far not in base.edges
    assert far in build_landmark_map('t', NAMES, LAT_LON, [(5, 0)]).edges
    with pytest.raises(InvalidInputError):
        build_landmark_map('t', NAMES, LAT_LON, [(0, 9)])


def test_kth_shortest_paths_get_longer():
    lmap = synthetic_map()
    lengths = [lmap.path_length(kth_shortest_path(lmap, 0, 5, k)) for k in (1, 2, 3, 4)]
    assert lengths == sorted(lengths)
    assert kth_shortest_path(lmap, 0, 5, 1) == shortest_path(lmap, 0, 5)
    with pytest.raises(InvalidInputError):
        kth_shortest_path(lmap, 0, 5, 0)
    lonely = LandmarkMap('x', ('a', 'b'), ('a', 'b'), np.zeros((2, 2)), frozenset())
    with pytest.raises(PlanningError):
        shortest_path(lonely, 0, 1)


def test_simulated_trajectories_are_simple_paths_not_always_shortest():
    lmap = synthetic_map()
    rng = np.random.default_rng(7)
    g = lmap.graph()
    not_shortest = 0
    for _ in range(60):
        path = simulate_trajectory(lmap, rng, graph=g)
        assert len(set(path)) == len(path) >= 2
        assert all(tuple(sorted(e)) in lmap.edges for e in zip(path, path[1:]))
        not_shortest += path != shortest_path(lmap, path[0], path[-1])
    assert 10 <= not_shortest <= 55   # k ~ Geometric(0.2): P(k > 1) = 0.8, fewer when few paths exist
    with pytest.raises(InvalidInputError):
        simulate_trajectory(lmap, rng, p=0.0)

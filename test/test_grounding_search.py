"""Search (issue 18): found behind a wall, absent ends NO_MATCH on a full map, avoided stays avoided, CLI."""
from __future__ import annotations

import json

import numpy as np
import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.coverage import PlaneGrid, travel_field, view_gain
from ltl_instruct.core.grounding.rsm import Outcome
from ltl_instruct.core.grounding.search import SearchParams, search_referents
from ltl_instruct.core.world.near import box_distance
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import scene_from_dict


def _wall(x0: float, y0: float, x1: float, y1: float) -> dict:
    return {'center': [(x0 + x1) / 2, (y0 + y1) / 2, 1.25],
            'size': [max(abs(x1 - x0), 0.2), max(abs(y1 - y0), 0.2), 2.5]}


# two rooms (x 0..5 and 5..10) joined by a doorway at y 4.5..6 in the wall at x = 5
ROOMS = {
    'name': 'two_rooms',
    'bounds': {'min': [0, 0, 0], 'max': [10, 6, 3]},
    'robot': {'kind': 'ground', 'start': [1.0, 1.0, 0.0], 'radius': 0.3},
    'obstacles': [_wall(0, 0.1, 10, 0.1), _wall(0, 5.9, 10, 5.9), _wall(0.1, 0, 0.1, 6),
                  _wall(9.9, 0, 9.9, 6), _wall(5.0, 0, 5.0, 4.5)],
    'objects': [{'label': 'vase', 'center': [8.5, 1.0, 0.3], 'size': [0.4, 0.4, 0.6]},
                {'label': 'crate', 'center': [3.0, 3.2, 0.25], 'size': [0.6, 0.6, 0.5]}],
}
FAST = SearchParams(width=120, height=90)


@pytest.fixture(scope='module')
def rooms():
    return scene_from_dict(ROOMS)


@pytest.fixture(scope='module')
def found(rooms):
    return search_referents(rooms, 'F near[vase] & G !near[crate]', params=FAST)


def test_an_object_behind_a_wall_is_found_and_resolves(found):
    g = found.referent_map.get('vase')
    assert found.sought == ('vase',)
    assert g.outcome == Outcome.RESOLVED and found.reason == 'resolved'
    assert np.linalg.norm(np.subtract(g.instances[0].center[:2], (8.5, 1.0))) < 0.3
    assert found.travel > 3.0 and found.moves >= 1      # it had to go through the doorway
    assert np.all(found.path[:, 0] < 9.9)


def test_the_search_path_never_enters_an_avoided_region(found):
    crate = found.referent_map.get('crate')
    assert crate.instances and not crate.required
    d = box_distance(found.path, np.array([[3.0, 3.2, 0.25]]), np.array([[0.6, 0.6, 0.5]]), 2)
    assert d.min() > FAST.near_threshold


def test_an_absent_referent_ends_no_match_after_the_search(rooms):
    r = search_referents(rooms, 'F near[piano]', params=FAST)
    g = r.referent_map.get('piano')
    assert g.outcome == Outcome.NO_MATCH
    assert r.complete and r.reason == 'complete'
    assert 'searched the whole reachable map' in g.explanation[0]
    assert r.area_seen > 40.0          # both rooms (about 50 m^2 inside the walls)
    assert np.any(r.path[:, 0] > 5.5)  # it went into the second room


def test_nearest_frontier_also_finds_it(rooms):
    r = search_referents(rooms, 'F near[vase]', params=SearchParams(strategy='nearest', width=120, height=90))
    assert r.referent_map.get('vase').outcome == Outcome.RESOLVED


def test_a_referent_in_sight_needs_no_travel(rooms):
    r = search_referents(rooms, 'F near[crate]', Pose((1.0, 1.0, 0.0), 0.0), FAST)
    assert r.referent_map.get('crate').outcome == Outcome.RESOLVED
    assert r.travel == 0.0 and r.moves == 0 and len(r.views) == FAST.headings


def test_bad_settings_are_refused():
    with pytest.raises(InvalidInputError):
        SearchParams(strategy='random')
    with pytest.raises(InvalidInputError):
        SearchParams(sensor_range=0.0)


def test_ground_explore_cli(tmp_path, capsys):
    scene = tmp_path / 'rooms.json'
    scene.write_text(json.dumps(ROOMS))
    png = tmp_path / 'search.png'
    rc = main(['ground', '--scene', str(scene), '--formula', 'F near[vase] & G !near[crate]', '--explore',
               '--start', '1.5,1.5,0.5', '--png', str(png)])
    out = capsys.readouterr().out
    assert rc == 0
    assert 'sought:   vase' in out and 'm travelled' in out and 'm^2 seen' in out
    assert png.stat().st_size > 1000
    rc = main(['ground', '--scene', str(scene), '--formula', 'F near[piano]', '--explore', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 1 and out['error']['code'] == 'NO_MATCH' and out['search']['complete']


def test_ground_explore_cli_refuses_views_too(tmp_path):
    assert main(['ground', '--scene', 'apartment', '--formula', 'F near[sofa]', '--explore',
                 '--views', '4']) == 2
    assert main(['ground', '--scene', 'apartment', '--formula', 'F near[sofa]', '--start', 'a,b',
                 '--explore']) == 2
    assert main(['ground', '--scene', 'apartment', '--formula', 'F near[sofa]', '--explore',
                 '--png', str(tmp_path / 'no' / 'x.png')]) == 2


def test_view_gain_counts_unseen_cells_in_sight_only():
    grid = PlaneGrid((0.0, 0.0), 0.1, (40, 20))
    seen = np.zeros(grid.shape, dtype=bool)
    seen[:20] = True                       # the left half was seen
    blocks = np.zeros(grid.shape, dtype=bool)
    open_gain = view_gain(np.array([[1.95, 1.0]]), grid, seen, blocks, 3.0)[0]
    blocks[20, :] = True                   # a wall between the halves
    walled = view_gain(np.array([[1.95, 1.0]]), grid, seen, blocks, 3.0)[0]
    assert open_gain > 100 and walled == 0


def test_travel_field_goes_round_a_wall():
    grid = PlaneGrid((0.0, 0.0), 0.1, (30, 30))
    free = np.ones(grid.shape, dtype=bool)
    free[15, :25] = False                  # a wall with a gap at the top
    d = travel_field(free, grid, (0.55, 0.55))
    assert d[5, 5] == 0.0 and np.isinf(d[15, 0])
    assert d[25, 5] > 2.0 * 2.0            # up to the gap and back down, not 2 m straight

"""The node graph's search without ROS: OnlineSearch fed by a forward-looking camera, coverage, poses.

The loop here stands in for the graph: a camera looking along the robot's heading
(as ``sim_world``'s) integrates a frame every half metre of each move into a semantic
map, the coverage of that map goes through the ``OccupancyGrid`` conversion the
grounder and ``task_progression`` use, and :class:`OnlineSearch` chooses each move.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from ltl_instruct import conversions as conv
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding import SemanticMap, SemanticMapParams, ground_formula
from ltl_instruct.core.grounding.coverage import Coverage, PlaneGrid, map_coverage
from ltl_instruct.core.grounding.online_search import OnlineSearch, findable
from ltl_instruct.core.grounding.rsm import Outcome
from ltl_instruct.core.grounding.search import SearchParams, unresolved
from ltl_instruct.core.planning.segment import solve_segment
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.camera import CameraMount, SyntheticCamera, camera_body_pose
from ltl_instruct.core.world.near import box_distance
from ltl_instruct.core.world.pose_history import PoseHistory
from ltl_instruct.core.world.robot import Pose, rasterize_scene
from ltl_instruct.core.world.scene import scene_from_dict
from search_scenes import SEARCH_ROOMS


def _search(formula: str):
    """Run a search as the graph does; return the final referent map, the search and the driven path."""
    scene = scene_from_dict(SEARCH_ROOMS)
    world = conv.planning_world_from_grid(conv.occupancy_grid_msg(rasterize_scene(scene, 0.1)), 0.3)
    camera = SyntheticCamera(scene, 120, 90, max_range=12.0)
    smap = SemanticMap(camera.classes, SemanticMapParams(voxel_size=0.1))
    f = parse_formula(formula)
    pose = Pose((1.0, 1.0, 0.0), 0.0)

    def look(p: Pose) -> None:
        frame = camera.render(p)
        smap.integrate(frame.depth, frame.labels, frame.intrinsics, p)

    look(pose)
    search = OnlineSearch(world, SearchParams(shortlist=1), pose.position)
    driven = [pose.position[:2]]
    while True:
        rmap = ground_formula(f, smap.instances())
        coverage = conv.coverage_from_msg(conv.coverage_msg(map_coverage(smap, 1.0)))
        if not unresolved(rmap):
            return rmap, search, np.array(driven)
        assert search.moves < 20
        move = search.next_move(coverage, rmap, pose.position, lambda request: solve_segment(request, world))
        if move is None:
            return search.complete(coverage, rmap), search, np.array(driven)
        pts, since, passed = move.points, 0.0, []
        for k in range(1, len(pts)):
            since += float(np.linalg.norm(pts[k, :2] - pts[k - 1, :2]))
            if since >= 0.5 or k == len(pts) - 1:
                d = pts[k, :2] - pts[k - 1, :2]
                pose, since = Pose((float(pts[k, 0]), float(pts[k, 1]), 0.0), math.atan2(d[1], d[0])), 0.0
                look(pose)
                passed.append(pts[k, :2])
        driven += passed
        search.moved(pts[-1], np.array(passed))


def test_a_forward_camera_finds_the_vase_and_keeps_off_the_crate():
    rmap, search, driven = _search('F near[vase] & G !near[crate]')
    vase = rmap.get('vase')
    assert vase.outcome == Outcome.RESOLVED and search.moves >= 2
    assert np.hypot(vase.instances[0].center[0] - 8.5, vase.instances[0].center[1] - 1.0) < 0.4
    assert search.travel > 4.0 and driven[:, 0].max() > 5.0       # through the doorway
    d = box_distance(driven, np.array([[3.0, 1.8, 0.25]]), np.array([[0.6, 0.6, 0.5]]), 2)
    assert d.min() > 1.0 - 0.1
    report = search.report(map_coverage(SemanticMap(), 1.0), rmap)
    assert report['sought'] == [] and report['moves'] == search.moves


def test_a_shut_away_object_ends_no_match_when_no_frontier_is_left():
    rmap, search, _ = _search('F near[piano]')
    piano = rmap.get('piano')
    assert piano.outcome == Outcome.NO_MATCH
    assert piano.explanation[0].startswith('searched the whole reachable map (')
    assert f'in {search.moves} moves' in piano.explanation[0]
    assert 40.0 < float(piano.explanation[0].split('(')[1].split(' m^2')[0]) < 56.0


def test_findable_names_need_a_class_of_the_label_images():
    labels = ['vase', 'red sofa', 'pillar']
    assert findable('vase', labels) and findable('couch::isbehind(pillar)', labels)
    assert not findable('unicorn', labels) and not findable('vase::isleftof(unicorn)', labels)
    assert not findable('vase', [])


def test_coverage_cells_round_trip_and_resample():
    grid = PlaneGrid((0.0, 0.0), 0.5, (4, 2))
    seen = np.array([[1, 0], [1, 1], [0, 0], [1, 0]], dtype=bool)
    blocks = np.zeros_like(seen)
    blocks[1, 1] = True
    cov = Coverage(grid, seen, blocks)
    back = conv.coverage_from_msg(conv.coverage_msg(cov))
    assert np.array_equal(back.seen, seen) and np.array_equal(back.blocks, blocks)
    assert back.area_seen == pytest.approx(4 * 0.25)
    wide = cov.on(PlaneGrid((-1.0, 0.0), 0.25, (12, 4)))   # finer, and reaching past the original
    assert not wide.seen[:4].any() and wide.seen[4, 0] and wide.blocks[6, 2]
    with pytest.raises(InvalidInputError):
        Coverage.from_cells(grid, np.zeros((2, 4)))


def test_pose_history_interpolates_and_waits_for_odometry():
    h = PoseHistory(tolerance=0.1)
    assert h.at(5) is None and h.waiting(5)
    h.add(1_000_000_000, Pose((0.0, 0.0, 0.0), math.pi - 0.1))
    h.add(1_200_000_000, Pose((2.0, 0.0, 0.0), -math.pi + 0.1))
    mid = h.at(1_100_000_000)
    assert mid.position == pytest.approx((1.0, 0.0, 0.0))
    assert abs(math.remainder(mid.yaw - math.pi, 2 * math.pi)) < 1e-9    # the short way round
    assert h.at(1_200_000_000).position[0] == 2.0
    assert h.at(1_300_000_000) is None and h.waiting(1_300_000_000)        # its odometry may come
    assert h.at(950_000_000).position[0] == 0.0 and h.at(800_000_000) is None
    assert not h.waiting(800_000_000)
    with pytest.raises(InvalidInputError):
        PoseHistory(size=0)


def test_camera_extrinsic_is_composed_with_the_robot_pose():
    mount = CameraMount(height=0.5, x=0.2, y=-0.1, yaw=math.pi / 2, pitch=0.0)
    t = camera_body_pose(Pose((1.0, 2.0, 0.0), math.pi / 2), mount)
    assert t[:3, 3] == pytest.approx([1.1, 2.2, 0.5])                    # (0.2, -0.1) turned by 90 degrees
    assert t[:3, 0] == pytest.approx([-1.0, 0.0, 0.0])                   # looking along -x
    with pytest.raises(InvalidInputError):
        CameraMount(height=float('nan'))

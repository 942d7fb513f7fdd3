"""Message <-> core conversions: round trips and typed errors on bad messages."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import Image

from ltl_instruct import conversions as conv
from ltl_instruct.core.errors import InvalidInputError, LimitExceededError
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.robot import Pose, rasterize_scene


def test_json_payload_round_trip_and_schema_checks():
    msg = conv.json_msg(conv.payload(conv.TASK_SPEC, 'abc', formula='F near[x]', value=float('nan')))
    data = conv.parse_json_payload(msg.data, conv.TASK_SPEC)
    assert data['id'] == 'abc' and data['formula'] == 'F near[x]' and data['value'] is None
    with pytest.raises(InvalidInputError):
        conv.parse_json_payload(msg.data, conv.REFERENT_MAP)
    for bad in ('{not json', '[1, 2]', '"text"', json.dumps({'schema': conv.TASK_SPEC, 'version': 1}),
                json.dumps({'schema': conv.TASK_SPEC, 'version': 99, 'id': 'x'}), '[' * 100000):
        with pytest.raises(InvalidInputError):
            conv.parse_json_payload(bad, conv.TASK_SPEC)
    with pytest.raises(LimitExceededError):
        conv.parse_json_payload('x' * 100, max_bytes=10)
    assert conv.salvage_id(json.dumps({'id': 'keep-me', 'schema': 'wrong'})) == 'keep-me'
    assert conv.salvage_id('garbage') == ''


@settings(derandomize=True, max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(-100, 100), st.floats(-100, 100), st.floats(0, 30)),
                min_size=1, max_size=40))
def test_path_round_trip_keeps_points_and_unit_quaternions(points):
    p = np.asarray(points, dtype=float)
    msg = conv.path_msg(p, conv.stamp_from_key(1_234_567_890_123))
    assert msg.header.frame_id == 'map'
    assert conv.stamp_key(msg.header.stamp) == 1_234_567_890_123
    assert np.allclose(conv.path_points(msg), p)
    for ps in msg.poses:
        q = ps.pose.orientation
        assert math.isclose(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2, 1.0, rel_tol=1e-9)


def test_path_with_nan_is_rejected():
    msg = conv.path_msg(np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 0.0]]))
    msg.poses[1].pose.position.x = float('nan')
    with pytest.raises(InvalidInputError):
        conv.path_points(msg)


def test_odometry_round_trip_and_nan_rejected():
    pose = Pose((1.0, -2.0, 0.5), 2.5)
    back = conv.odometry_pose(conv.odometry_msg(pose))
    assert np.allclose(back.position, pose.position) and back.yaw == pytest.approx(2.5)
    msg = conv.odometry_msg(pose)
    msg.pose.pose.position.y = float('nan')
    with pytest.raises(InvalidInputError):
        conv.odometry_pose(msg)


def test_occupancy_grid_round_trip_and_bad_grids():
    raster = rasterize_scene(resolve_scene('apartment'), 0.2)
    back = conv.occupancy_raster(conv.occupancy_grid_msg(raster))
    assert np.array_equal(back.cells, raster.cells) and back.resolution == pytest.approx(0.2)
    assert back.origin == raster.origin
    with pytest.raises(InvalidInputError, match='empty'):
        conv.occupancy_raster(OccupancyGrid())
    msg = conv.occupancy_grid_msg(raster)
    msg.data = msg.data[:-1]
    with pytest.raises(InvalidInputError):
        conv.occupancy_raster(msg)


@pytest.mark.parametrize('origin, resolution', [((1e9, 0.0), 0.05), ((0.0, 0.0), 4e15), ((-2e4, 5.0), 1.0)])
def test_a_map_beyond_the_largest_scene_is_refused_before_any_work(origin, resolution):
    """Fuzz-found (issue 21): a 2-cell map from 1e9 m out to 5e18 m made a cell index of 1.4e14 cells."""
    msg = OccupancyGrid()
    msg.info.width, msg.info.height, msg.info.resolution = 2, 1, resolution
    msg.info.origin.position.x, msg.info.origin.position.y = origin
    msg.info.origin.orientation.w = 1.0
    msg.data = [0, 100]
    with pytest.raises(InvalidInputError, match='beyond the largest scene'):
        conv.planning_world_from_grid(msg, 0.3)


def test_a_map_in_another_frame_is_a_frame_mismatch_naming_both():
    from ltl_instruct.core.errors import FrameMismatchError
    msg = conv.occupancy_grid_msg(rasterize_scene(resolve_scene('apartment'), 0.2), frame_id='r1/map')
    conv.check_map_frame(msg, 'r1/map', 'map')
    for frame in ('map', 'odom', ''):
        msg.header.frame_id = frame
        with pytest.raises(FrameMismatchError, match=f"'{frame}', expected 'r1/map'"):
            conv.check_map_frame(msg, 'r1/map', 'map')


def test_a_long_thin_world_indexes_at_most_4097_cells_along_an_axis():
    from ltl_instruct.core.planning import PlanningWorld
    from ltl_instruct.core.world.scene import Box
    world = PlanningWorld(2, (0.0, 0.0), (9000.0, 0.5), 0.3, (Box((10.0, 0.25, 0.0), (1.0, 0.1, 1.0)),))
    cell, nx, ny = world._cell
    assert nx <= 4097 and ny <= 4097 and nx * ny < 20000
    assert not world.is_free(np.array([[10.0, 0.25]]))[0] and world.is_free(np.array([[100.0, 0.25]]))[0]


def test_point_cloud_round_trip_with_a_value_field():
    rng = np.random.default_rng(0)
    pts = rng.normal(size=(100, 3)).astype(np.float32)
    values = rng.choice([-1.0, 0.0, 1.0], size=100)
    msg = conv.point_cloud_msg(pts, {'value': values})
    assert msg.point_step == 16 and msg.width == 100
    assert [f.name for f in msg.fields] == ['x', 'y', 'z', 'value']
    fields = conv.point_cloud_fields(msg)
    assert np.allclose(conv.point_cloud_xyz(msg), pts) and np.allclose(fields['value'], values)
    with pytest.raises(InvalidInputError):
        conv.point_cloud_msg(pts, {'value': values[:5]})
    msg.data = msg.data[:-4]
    with pytest.raises(InvalidInputError):
        conv.point_cloud_fields(msg)


@pytest.mark.parametrize('encoding,array', [
    ('rgb8', np.arange(4 * 5 * 3, dtype=np.uint8).reshape(4, 5, 3)),
    ('32FC1', np.linspace(0.1, 9.0, 20, dtype=np.float32).reshape(4, 5)),
    ('32SC1', np.arange(20, dtype=np.int32).reshape(4, 5) - 3),
])
def test_image_round_trip(encoding, array):
    msg = conv.image_msg(array, encoding)
    assert msg.encoding == encoding and msg.height == 4 and msg.width == 5
    assert np.array_equal(conv.image_array(msg), array)


def test_bad_images_are_rejected():
    with pytest.raises(InvalidInputError):
        conv.image_msg(np.zeros((4, 5)), 'rgb8')
    with pytest.raises(InvalidInputError):
        conv.image_msg(np.zeros((4, 5)), 'bgr16')
    msg = Image(height=4, width=5, encoding='32FC1', step=20, data=bytes(10))
    with pytest.raises(InvalidInputError):
        conv.image_array(msg)


def test_depth_images_are_read_in_metres_in_both_rep118_encodings():
    metres = np.array([[0.5, 1.234, np.nan], [0.0, 65.0, 2.0]], dtype=np.float32)
    mm = conv.depth_msg(metres, '16UC1')
    assert mm.encoding == '16UC1' and conv.image_array(mm).tolist() == [[500, 1234, 0], [0, 65000, 2000]]
    back = conv.depth_array(mm)                   # millimetres, 0 = no return: metres, NaN
    assert back.dtype == np.float32 and np.allclose(back, [[0.5, 1.234, np.nan], [np.nan, 65.0, 2.0]],
                                                    equal_nan=True)
    raw = conv.image_msg(np.array([[1500, 0]], dtype=np.uint16), '16UC1')
    assert np.allclose(conv.depth_array(raw), [[1.5, np.nan]], equal_nan=True)   # not 1500 m
    assert np.array_equal(conv.depth_array(conv.depth_msg(metres)), metres, equal_nan=True)
    with pytest.raises(InvalidInputError):
        conv.depth_array(conv.image_msg(np.zeros((2, 2), np.uint8), 'mono8'))


def test_colour_images_are_read_as_rgb():
    rgb = np.arange(2 * 3 * 3, dtype=np.uint8).reshape(2, 3, 3)
    assert np.array_equal(conv.rgb_array(conv.image_msg(rgb[:, :, ::-1], 'bgr8')), rgb)
    rgba = np.concatenate([rgb, np.full((2, 3, 1), 255, np.uint8)], axis=2)
    assert np.array_equal(conv.rgb_array(conv.image_msg(rgba, 'rgba8')), rgb)
    with pytest.raises(InvalidInputError):
        conv.rgb_array(conv.image_msg(np.zeros((2, 2), np.float32), '32FC1'))


def test_camera_info_round_trip_and_invalid():
    msg = conv.camera_info_msg(160, 120, 100.0, 101.0, 80.0, 60.0)
    assert conv.camera_intrinsics(msg) == (160, 120, 100.0, 101.0, 80.0, 60.0)
    msg.k[0] = float('nan')
    with pytest.raises(InvalidInputError):
        conv.camera_intrinsics(msg)


def test_referent_markers_one_cube_and_label_per_instance():
    rmap = ReferentMap({'sofa': Grounding('sofa', Outcome.AMBIGUOUS, (
        Instance('sofa_1', 'sofa', (1, 2, 0.4), (2, 1, 0.8)), Instance('sofa_2', 'sofa', (5, 2, 0.4))))})
    markers = conv.referent_markers(rmap).markers
    assert len(markers) == 1 + 4
    assert markers[1].scale.x == 2.0 and markers[2].text == 'sofa (sofa_1)'


@settings(derandomize=True, max_examples=30, deadline=None)
@given(st.integers(0, 2 ** 31 - 1))
def test_occupied_rectangles_cover_exactly_the_blocked_cells(seed):
    rng = np.random.default_rng(seed)
    cells = rng.choice(np.array([0, 100, -1], dtype=np.int8), size=(rng.integers(1, 30), rng.integers(1, 30)),
                       p=[0.6, 0.3, 0.1])
    cover = np.zeros(cells.shape, dtype=int)
    for r0, r1, c0, c1 in conv.occupied_rectangles(cells):
        cover[r0:r1, c0:c1] += 1
    assert np.array_equal(cover, ((cells >= 50) | (cells < 0)).astype(int))   # covered once, nothing free


def test_planning_world_from_grid_matches_the_grid():
    raster = rasterize_scene(resolve_scene('apartment'), 0.1)
    world = conv.planning_world_from_grid(conv.occupancy_grid_msg(raster), robot_radius=0.0)
    assert len(world.obstacles) < 80
    pts = np.random.default_rng(1).uniform([0.05, 0.05], [19.95, 14.95], size=(5000, 2))
    cols = ((pts[:, 0] - raster.origin[0]) / raster.resolution).astype(int)
    rows = ((pts[:, 1] - raster.origin[1]) / raster.resolution).astype(int)
    on_cell_edge = (np.abs(pts / raster.resolution - np.round(pts / raster.resolution)) < 1e-6).any(axis=1)
    free = raster.cells[rows, cols] == 0
    assert np.array_equal(world.is_free(pts)[~on_cell_edge], free[~on_cell_edge])
    inflated = conv.planning_world_from_grid(conv.occupancy_grid_msg(raster), robot_radius=0.3)
    assert not inflated.is_free(np.array([[10.0, 1.0], [10.35, 1.0], [1.5, 0.35]])).any()   # wall + radius
    assert inflated.is_free(np.array([[1.5, 1.5]]))[0]
    with pytest.raises(InvalidInputError):
        conv.planning_world_from_grid(OccupancyGrid(), 0.3)


def test_bounds_text():
    assert conv.parse_bounds('') is None
    assert conv.parse_bounds('0,0,2,120,100,30') == ((0.0, 0.0, 2.0), (120.0, 100.0, 30.0))
    for bad in ('1,2,3', '0,0,0,0,1,1', 'a,b,c,d,e,f', '0,0,0,nan,1,1'):
        with pytest.raises(InvalidInputError):
            conv.parse_bounds(bad)


def test_planning_world_from_cloud_is_boxes_never_freer_than_the_scene():
    from ltl_instruct.core.planning import world_from_scene
    from ltl_instruct.core.world.robot import obstacle_points
    scene = resolve_scene('city_block')
    msg = conv.point_cloud_msg(obstacle_points(scene, 1.0))
    bounds = ((0.5, 0.5, 2.0), (119.5, 99.5, 30.0))
    world = conv.planning_world_from_cloud(msg, 1.0, 0.0, bounds)
    assert world.dims == 3 and len(world.obstacles) <= 2 * len(scene.blocking_boxes())
    truth = world_from_scene(scene, 0.0)
    pts = np.random.default_rng(2).uniform(bounds[0], bounds[1], size=(20000, 3))
    free, true_free = world.is_free(pts), truth.is_free(pts)
    assert not np.any(free & ~true_free)          # conservative: never free inside a building
    assert (free == true_free).mean() > 0.95       # and at most a voxel too cautious
    with pytest.raises(InvalidInputError):
        conv.planning_world_from_cloud(conv.point_cloud_msg(np.zeros((0, 3))), 1.0, 0.5)


def test_a_plan_on_the_simulators_grid_passes_the_independent_check():
    """Fresh-clone CI: F (tv & F lamp) from (8.19, 3.89) cut sofa_2's grown corner by 4 mm (plan refused)."""
    from ltl_instruct.core.automaton import compile_automaton
    from ltl_instruct.core.grounding import ground_formula, instances_from_scene
    from ltl_instruct.core.planning import FmtSettings, PlannerSettings, plan_task
    from ltl_instruct.core.spec import parse_formula
    scene = resolve_scene('apartment')
    world = conv.planning_world_from_grid(conv.occupancy_grid_msg(rasterize_scene(scene, 0.1)), 0.3)
    formula = 'F (near[tv] & F near[lamp])'
    settings = PlannerSettings(near_threshold=1.0, goal_margin=0.2, avoid_margin=0.1,
                               fmt=FmtSettings(num_samples=3000, time_limit=10.0, seed=0, path_spacing=0.1))
    rmap = ground_formula(formula, instances_from_scene(scene))
    start = (8.194808903465262, 3.8935114833525297)
    plan = plan_task(compile_automaton(parse_formula(formula)), rmap, world, start, settings)
    assert plan.verification.ok and plan.verification.collision_free

"""Built-in scenes, the kinematic robot, the simulated world and its occupancy raster."""
from __future__ import annotations

import math

import numpy as np
import pytest

from ltl_instruct.core.errors import InvalidInputError, LtlInstructError, SceneError
from ltl_instruct.core.world.builtin import builtin_scene_names, builtin_scene_path, resolve_scene
from ltl_instruct.core.world.robot import (
    KinematicRobot, SimulatedWorld, obstacle_points, rasterize_scene, validate_path,
)


def test_builtin_scenes_load_and_meet_the_brief():
    assert {'apartment', 'city_block'} <= set(builtin_scene_names())
    apt = resolve_scene('apartment')
    assert apt.robot.kind == 'ground'
    assert len(apt.objects) >= 25
    labels = [o.label for o in apt.objects]
    # several of one kind, told apart only by where they are
    assert labels.count('sofa') == 2 and labels.count('chair') == 3 and labels.count('table') == 2
    city = resolve_scene('city_block')
    assert city.robot.kind == 'drone' and city.altitude is not None
    assert len(city.obstacles) + len(city.blocking_boxes()) > 5


def test_sofas_differ_by_position_relative_to_the_pillar():
    apt = resolve_scene('apartment')
    pillar = apt.object_by_id('pillar')
    xs = sorted(apt.object_by_id(i).center[0] - pillar.center[0] for i in ('sofa_1', 'sofa_2'))
    assert xs[0] < -1.0 and xs[1] > 1.0   # one in front of the pillar, one behind it


def test_robot_start_is_free_and_inside_bounds():
    for name in builtin_scene_names():
        s = resolve_scene(name)
        start = np.asarray(s.robot.start)
        assert np.all(start >= s.bounds_min) and np.all(start <= s.bounds_max)
        dims = s.robot.dims
        for box in s.blocking_boxes():
            assert box.distance(start, dims=dims)[0] > s.robot.radius, (name, box)


def test_unknown_builtin_scene_is_a_typed_error():
    with pytest.raises(SceneError) as e:
        builtin_scene_path('no_such_scene')
    assert 'apartment' in e.value.message
    with pytest.raises(SceneError):
        resolve_scene('../../etc/passwd')


def test_robot_follows_a_path_at_bounded_speed():
    robot = KinematicRobot((0.0, 0.0, 0.0), max_speed=2.0)
    robot.follow(np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [3.0, 4.0, 0.0]]))
    positions = [robot.step(0.1).xyz for _ in range(100)]
    steps = np.linalg.norm(np.diff(positions, axis=0), axis=1)
    assert np.all(steps <= 2.0 * 0.1 + 1e-9)
    assert robot.is_done
    assert np.allclose(robot.pose.xyz, [3.0, 4.0, 0.0])
    assert robot.travelled == pytest.approx(7.0)
    assert robot.pose.yaw == pytest.approx(math.pi / 2)


def test_a_long_step_reports_the_corners_it_passed():
    """Straight moves between the reported poses follow the path, however long the step."""
    robot = KinematicRobot((0.0, 0.0, 0.0), max_speed=1.0)
    straight = np.column_stack([np.linspace(0.0, 3.0, 31), np.zeros(31), np.zeros(31)])
    up = np.column_stack([np.full(20, 3.0), np.linspace(0.2, 4.0, 20), np.zeros(20)])
    back = np.array([[1.0, 4.0, 0.0]])
    robot.follow(np.vstack([straight, up, back]))
    end = robot.step(100.0)        # the whole path in one step
    assert [c.position for c in robot.corners] == [(3.0, 0.0, 0.0), (3.0, 4.0, 0.0)]
    assert np.allclose(end.xyz, [1.0, 4.0, 0.0])
    robot.follow(straight)
    robot.step(1.0)
    assert robot.corners == []     # points on a straight line are no corners
    robot.step(0.0)
    assert robot.corners == []


def test_robot_stops_at_a_skill_index_and_resumes():
    robot = KinematicRobot((0.0, 0.0, 0.0), max_speed=1.0)
    robot.follow(np.array([[1.0, 0, 0], [2.0, 0, 0], [3.0, 0, 0]]), stop_at=[1])
    for _ in range(50):
        robot.step(0.1)
    assert robot.is_paused and np.allclose(robot.pose.xyz, [2.0, 0, 0])
    robot.resume()
    for _ in range(20):
        robot.step(0.1)
    assert robot.is_done and np.allclose(robot.pose.xyz, [3.0, 0, 0])
    # a stop requested after its index was passed pauses at once
    robot.follow(np.array([[4.0, 0, 0], [5.0, 0, 0]]))
    for _ in range(15):
        robot.step(0.1)
    assert robot.add_stop(0) is False and robot.is_paused


def test_ground_robot_stays_in_its_plane():
    robot = KinematicRobot((0.0, 0.0, 0.2), planar=True)
    robot.follow(np.array([[1.0, 1.0, 5.0]]))
    for _ in range(30):
        robot.step(0.1)
    assert robot.pose.position[2] == pytest.approx(0.2)


@pytest.mark.parametrize('bad', [np.zeros((0, 3)), np.zeros((3, 2)), np.array([[0.0, np.nan, 0.0]])])
def test_bad_paths_are_rejected(bad):
    with pytest.raises(InvalidInputError):
        validate_path(bad)
    with pytest.raises(InvalidInputError):
        KinematicRobot((0.0, 0.0, 0.0)).follow(bad)


def test_bad_robot_settings_are_rejected():
    with pytest.raises(InvalidInputError):
        KinematicRobot((0.0, 0.0, 0.0), max_speed=0.0)
    with pytest.raises(InvalidInputError):
        KinematicRobot((0.0, float('nan'), 0.0))


def test_pick_carry_and_release():
    world = SimulatedWorld(resolve_scene('apartment'), max_speed=5.0, reach=1.0)
    toy = world.find_object(name='plush_toy')
    basket = world.find_object('basket')
    assert toy is not None and toy.id == 'green_plush_toy' and basket is not None
    assert not world.pick(toy).ok            # too far from the start pose
    world.robot.follow(np.array([[6.5, 9.6, 0.0]]))
    for _ in range(100):
        world.step(0.1)
    assert world.pick(toy).ok and world.carried == toy.id
    assert not world.pick(basket).ok         # hands full
    world.robot.follow(np.array([[4.0, 9.6, 0.0]]))
    for _ in range(100):
        world.step(0.1)
    carried = world.find_object(toy.id)
    assert np.allclose(carried.center[:2], world.robot.pose.position[:2])   # moved with the robot
    outcome = world.release(world.find_object(toy.id), basket)
    assert outcome.ok and world.carried is None
    placed = world.find_object(toy.id)
    assert placed.center[:2] == basket.center[:2] and placed.center[2] > basket.center[2]
    assert world.current_scene().object_by_id(toy.id).center == placed.center


def test_large_or_unknown_objects_cannot_be_picked():
    world = SimulatedWorld(resolve_scene('apartment'))
    sofa = world.find_object('sofa_1')
    world.robot.follow(np.array([[2.2, 5.9, 0.0]]))
    for _ in range(100):
        world.step(0.1)
    out = world.pick(sofa)
    assert not out.ok and out.error_code == 'SKILL_FAILED' and 'too large' in out.reason
    assert world.pick(None).error_code == 'UNKNOWN_REFERENT'
    assert world.find_object(name='unicorn') is None


def test_rasterized_map_marks_walls_and_leaves_the_start_free():
    scene = resolve_scene('apartment')
    raster = rasterize_scene(scene, 0.1)
    assert raster.cells.shape == (150, 200)

    def cell(x, y):
        return raster.cells[int((y - raster.origin[1]) / raster.resolution),
                            int((x - raster.origin[0]) / raster.resolution)]
    assert cell(10.0, 1.0) == 100          # the wall between living room and kitchen
    assert cell(10.0, 5.5) == 0            # its archway
    assert cell(*scene.robot.start[:2]) == 0
    assert cell(5.0, 5.0) == 0             # a rug is passable
    with pytest.raises(InvalidInputError):
        rasterize_scene(scene, 0.0)
    with pytest.raises(LtlInstructError):
        rasterize_scene(scene, 1e-4)


def test_obstacle_points_fill_every_box():
    scene = resolve_scene('city_block')
    pts = obstacle_points(scene, 2.0)
    assert pts.dtype == np.float32 and pts.shape[1] == 3
    for box in scene.blocking_boxes():
        assert np.any(box.contains(pts, margin=1e-3))


def test_a_new_plan_starting_behind_the_robot_is_joined_along_the_driven_way():
    """The robot went round a corner; the new plan starts before the corner: it drives back round it."""
    robot = KinematicRobot((0.0, 0.0, 0.0), max_speed=1.0)
    robot.follow(np.array([[2.0, 0.0, 0.0], [2.0, 2.0, 0.0]]))
    for _ in range(30):
        robot.step(0.1)                       # at (2, 1): past the corner at (2, 0)
    assert np.allclose(robot.pose.xyz, [2.0, 1.0, 0.0])
    robot.follow(np.array([[1.5, 0.0, 0.0], [1.5, -3.0, 0.0]]), stop_at=[1])
    positions = [robot.step(0.05).xyz for _ in range(200)]
    # back down to the corner, then along the old way to (1.5, 0): never across the inside of the corner
    assert all(not (1.55 < p[0] < 1.95 and 0.05 < p[1] < 0.95) for p in positions)
    assert robot.is_paused and robot.path_index == 1
    assert np.allclose(robot.pose.xyz, [1.5, -3.0, 0.0])
    # a plan that starts away from the driven way is joined straight
    robot.resume()
    robot.follow(np.array([[5.0, 5.0, 0.0]]))
    robot.step(0.1)
    assert robot.path_index == -1 and robot.pose.xyz[1] > -3.0


def test_a_plan_from_before_the_last_one_is_rejoined_along_the_way_driven():
    """In a burst of plans one may start where the robot was before the plan it follows came."""
    robot = KinematicRobot((0.0, 0.0, 0.0), max_speed=1.0)
    robot.follow(np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 4.0, 0.0]]))
    robot.step(6.0)                                           # round the corner to (4, 2)
    robot.follow(np.array([[4.0, 2.0, 0.0], [4.0, 3.0, 0.0]]))
    robot.step(0.5)                                           # (4, 2.5)
    robot.follow(np.array([[2.0, 0.0, 0.0], [2.0, -1.0, 0.0]]))   # planned from (2, 0), before both
    robot.step(100.0)
    # back the way it came, round the corner at (4, 0): not straight across to (2, 0)
    assert robot.travelled == pytest.approx(6.0 + 0.5 + 2.5 + 2.0 + 1.0)
    assert np.allclose(robot.pose.xyz, [2.0, -1.0, 0.0])

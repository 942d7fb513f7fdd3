"""Voxel semantic map: localisation from views, the HLSM update rule, frontiers, bad input."""
from __future__ import annotations

import random
from dataclasses import replace

import numpy as np
import pytest

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding import (
    GroundingParams, Resolver, SemanticMap, ground_formula, instances_from_scene,
)
from ltl_instruct.core.grounding.rsm import Outcome
from ltl_instruct.core.grounding.semantic_map import SemanticMapParams
from ltl_instruct.core.grounding.suite import generate_suite, random_scene
from ltl_instruct.core.grounding import semantic_map
from ltl_instruct.core.grounding.survey import map_from_views, survey_params, survey_poses
from ltl_instruct.core.world.camera import SyntheticCamera
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import scene_from_dict

ROOM = scene_from_dict({'bounds': {'min': [0, 0, 0], 'max': [8, 8, 3]}, 'objects': [
    {'label': 'red sofa', 'center': [4.0, 4.0, 0.4], 'size': [2.0, 0.9, 0.8]},
    {'label': 'chair', 'center': [2.5, 5.5, 0.4], 'size': [0.5, 0.5, 0.8]},
    {'label': 'chair', 'center': [5.5, 2.5, 0.4], 'size': [0.5, 0.5, 0.8]},
    {'label': 'lamp', 'center': [4.0, 4.0, 1.6], 'size': [0.3, 0.3, 0.3]},
    {'label': 'cup', 'center': [2.5, 2.5, 0.1], 'size': [0.2, 0.2, 0.2]}]})


@pytest.fixture(scope='module')
def room_map() -> SemanticMap:
    return map_from_views(ROOM, 8, 240, 180)


def nearest(instances, label, point):
    same = [i for i in instances if i.label == label]
    return min(same, key=lambda i: np.linalg.norm(np.subtract(i.center, point)))


def test_every_object_is_localised_from_eight_views(room_map):
    found = room_map.instances()
    assert sorted(i.label for i in found) == sorted(o.label for o in ROOM.objects)
    for o in ROOM.objects:
        inst = nearest(found, o.label, o.center)
        assert np.linalg.norm(np.subtract(inst.center, o.center)) < 0.15, (o.id, inst)
        assert np.all(np.abs(np.subtract(inst.size, o.size)) <= 0.25)
        assert inst.observations >= 2 and 0.5 <= inst.confidence <= 1.0
    assert len({i.id for i in found}) == len(found) and all(i.id.startswith('det_') for i in found)


def test_grounding_from_the_map_matches_the_known_list(room_map):
    formula = ('F (near[chair::isleftof(couch)] & F near[lamp::isabove(sofa)]) & G !near[cup] '
               '& F near[sofa::isbetween(chair, chair)]')
    known = ground_formula(formula, instances_from_scene(ROOM))
    seen = ground_formula(formula, room_map.instances())
    for key, g in known.groundings.items():
        s = seen.groundings[key]
        assert s.outcome == g.outcome, key
        assert sorted(i.label for i in s.instances) == sorted(i.label for i in g.instances)
    assert known.groundings['chair::isleftof(couch)'].outcome == Outcome.RESOLVED


def test_hlsm_rule_overwrites_what_a_frame_observes_and_keeps_the_rest():
    cam = SyntheticCamera(ROOM, 160, 120)
    smap = SemanticMap(cam.classes)
    view = Pose((0.5, 4.0, 0.0), 0.0)
    f = cam.render(view)
    smap.integrate(f.depth, f.labels, f.intrinsics, view)
    assert any(i.label == 'red sofa' for i in smap.instances())
    # a frame looking away observes nothing of the sofa: it stays in the map
    away = Pose((0.5, 4.0, 0.0), np.pi)
    f = cam.render(away)
    smap.integrate(f.depth, f.labels, f.intrinsics, away)
    assert any(i.label == 'red sofa' for i in smap.instances())
    # the sofa is carried away: the next frames see the floor where it stood
    gone = replace(ROOM, objects=tuple(o for o in ROOM.objects if o.label != 'red sofa'))
    for pose in survey_poses(ROOM, 6):
        f = cam.render(pose, scene=gone)
        smap.integrate(f.depth, f.labels, f.intrinsics, pose)
    assert not any(i.label == 'red sofa' for i in smap.instances())
    assert smap.frames == 8


def test_frontiers_are_observed_free_voxels_next_to_unobserved_space():
    cam = SyntheticCamera(ROOM, 160, 120)
    smap = SemanticMap(cam.classes)
    pose = Pose((1.0, 1.0, 0.0), 0.6)
    f = cam.render(pose)
    smap.integrate(f.depth, f.labels, f.intrinsics, pose)
    front = smap.frontiers()
    assert front.shape[1] == 3 and front.shape[0] > 50
    vs = smap.params.voxel_size
    idx = np.floor(front / vs).astype(int) - smap.origin
    assert np.all(smap.observed[tuple(idx.T)])
    assert not np.any(smap.occupied[tuple(idx.T)])
    band = smap.frontiers(z_range=(0.2, 0.5))
    assert band.shape[0] > 0 and np.all((band[:, 2] >= 0.2) & (band[:, 2] <= 0.5))
    # looking around from the same spot observes more of the space around the robot
    before = int(smap.observed.sum())
    for yaw in (2.0, 3.5, 5.0):
        p = Pose((1.0, 1.0, 0.0), yaw)
        f = cam.render(p)
        smap.integrate(f.depth, f.labels, f.intrinsics, p)
    assert int(smap.observed.sum()) > before
    front = smap.frontiers()
    idx = np.floor(front / vs).astype(int) - smap.origin
    assert np.all(smap.observed[tuple(idx.T)])


def test_unknown_class_ids_and_empty_frames():
    smap = SemanticMap()
    cam = SyntheticCamera(ROOM, 80, 60)
    f = cam.render(Pose((0.5, 4.0, 0.0), 0.0))
    smap.integrate(f.depth, f.labels, f.intrinsics, Pose((0.5, 4.0, 0.0), 0.0))
    assert {i.label for i in smap.instances()} <= {f'class_{k}' for k in cam.classes}
    assert smap.instances()
    assert smap.integrate(np.full((60, 80), np.nan, np.float32), np.zeros((60, 80), np.int32),
                          f.intrinsics, np.eye(4)) == 0


K80 = (80, 60, 40.0, 40.0, 40.0, 30.0)


@pytest.mark.parametrize('depth, labels, intrinsics, pose', [
    (np.zeros((60, 80), np.float32), np.zeros((60, 79), np.int32), K80, np.eye(4)),
    (np.zeros((60, 80), np.float32), np.zeros((60, 80), np.float32), K80, np.eye(4)),
    (np.zeros((60, 80), np.float32), np.zeros((60, 80), np.int32), K80, Pose((np.nan, 0.0, 0.0), 0.0)),
    (np.zeros((60, 80), np.float32), np.zeros((60, 80), np.int32), 'garbage', np.eye(4)),
    # a camera a million kilometres away (odometry gone wild): refused, not a grid of negative size
    (np.full((60, 80), 2.0, np.float32), np.zeros((60, 80), np.int32), K80, Pose((1.0, 1e9, 1e9), 0.0)),
])
def test_bad_frames_are_typed_errors(depth, labels, intrinsics, pose):
    with pytest.raises(InvalidInputError):
        SemanticMap().integrate(depth, labels, intrinsics, pose)


def test_bad_params():
    with pytest.raises(InvalidInputError):
        SemanticMapParams(voxel_size=0.0)
    with pytest.raises(InvalidInputError):
        SemanticMapParams(pixel_stride=0)


def test_survey_voxels_grow_with_the_scene():
    assert survey_params(ROOM).voxel_size == pytest.approx(0.1)
    city = scene_from_dict({'bounds': {'min': [0, 0, 0], 'max': [120, 100, 40]}})
    assert survey_params(city).voxel_size == pytest.approx(0.5)


def test_the_grid_grows_without_its_margin_rather_than_past_its_limit(monkeypatch):
    cam = SyntheticCamera(ROOM, 80, 60)
    pose = Pose((0.5, 4.0, 0.0), 0.0)
    f = cam.render(pose)
    smap = SemanticMap(cam.classes, SemanticMapParams(max_range=10.0))
    # the frame's box fits two million voxels; with 10 m of margin around it, it would not
    monkeypatch.setattr(semantic_map, 'MAX_VOXELS', 2_000_000)
    smap.integrate(f.depth, f.labels, f.intrinsics, pose)
    assert np.prod(smap.shape) <= 2_000_000 and smap.instances()


def test_generated_suite_from_camera_views():
    """A generated scene with distractors: descriptors resolve the same from 8 views as from the list."""
    rng = random.Random(7)
    scene = random_scene(rng, n_objects=16, cells=12)
    truth = instances_from_scene(scene)
    cases = generate_suite(truth, 60, rng)
    smap = map_from_views(scene, 8, 240, 180)
    found = smap.instances()
    assert len(found) == len(truth)
    known, seen = Resolver(truth, GroundingParams()), Resolver(found, GroundingParams())

    def true_id(inst):
        return nearest(truth, inst.label, inst.center).id

    for case in cases:
        assert frozenset(i.id for i in known.resolve(case.descriptor).instances) == case.expected
        got = frozenset(true_id(i) for i in seen.resolve(case.descriptor).instances)
        assert got == case.expected, str(case.descriptor)


def test_classes_named_after_their_frames_take_the_name():
    from ltl_instruct.core.grounding import SemanticMap
    from ltl_instruct.core.world.camera import CameraIntrinsics
    smap = SemanticMap()
    depth = np.full((24, 32), 2.0, dtype=np.float32)
    labels = np.zeros((24, 32), dtype=np.int32)
    labels[8:16, 10:20] = 7
    smap.integrate(depth, labels, CameraIntrinsics.default(32, 24), np.eye(4))
    assert smap.column_labels[1] == 'class_7'
    smap.name_classes({7: 'vase'})
    assert smap.column_labels[1] == 'vase' and smap.class_names[7] == 'vase'

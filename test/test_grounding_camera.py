"""Synthetic RGB-D + label camera: geometry, frame conventions, labels, bad poses."""
from __future__ import annotations

import math

import numpy as np
import pytest

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world.camera import (
    CameraIntrinsics, CameraMount, SyntheticCamera, camera_body_pose, class_table, optical_pose,
)
from ltl_instruct.core.world.robot import Pose
from ltl_instruct.core.world.scene import scene_from_dict

SCENE = scene_from_dict({'bounds': {'min': [0, 0, 0], 'max': [10, 10, 3]},
                         'obstacles': [{'center': [9.5, 5, 1.5], 'size': [0.2, 10, 3]}],
                         'objects': [{'label': 'red sofa', 'center': [5, 5, 1.0], 'size': [1, 1, 2]},
                                     {'label': 'chair', 'center': [5, 8, 0.4], 'size': [0.5, 0.5, 0.8]},
                                     {'label': 'lamp', 'center': [4, 5, 2.5], 'size': [0.2, 0.2, 0.2]}]})


def test_depth_is_optical_z_and_labels_follow_the_class_table():
    cam = SyntheticCamera(SCENE, 160, 120)
    rgb, depth, labels, classes = cam.render(Pose((1.0, 5.0, 0.0), 0.0))
    assert rgb.shape == (120, 160, 3) and rgb.dtype == np.uint8
    assert depth.dtype == np.float32 and labels.dtype == np.int32
    assert classes == class_table(SCENE) == {1: 'chair', 2: 'lamp', 3: 'red sofa'}
    # the optical axis (camera 1 m up, level) hits the sofa's front face at x = 4.5
    assert depth[60, 80] == pytest.approx(3.5, abs=1e-4)
    assert labels[60, 80] == 3
    # depth is the optical z, not the ray length: off-axis pixels on the same face share it
    assert depth[60, 70] == pytest.approx(3.5, abs=1e-4)


def test_left_is_left_and_up_is_up():
    cam = SyntheticCamera(SCENE, 160, 120)
    frame = cam.render(Pose((1.0, 5.0, 0.0), 0.0))
    chair_cols = np.nonzero(frame.labels == 1)[1]
    lamp_rows = np.nonzero(frame.labels == 2)[0]
    assert chair_cols.size and chair_cols.max() < 80      # +y (left) is the left of the image
    assert lamp_rows.size and lamp_rows.max() < 60        # +z (up) is the top of the image
    # the floor fills the bottom rows, with no object label
    assert np.all(frame.labels[-1] == 0) and np.all(np.isfinite(frame.depth[-1]))


def test_back_projection_recovers_the_surface():
    cam = SyntheticCamera(SCENE, 160, 120)
    frame = cam.render(Pose((1.0, 4.0, 0.0), 0.3))
    k = frame.intrinsics
    t = optical_pose(frame.t_map_body)
    v, u = np.nonzero(frame.labels == 3)
    z = frame.depth[v, u]
    p = np.stack([(u + 0.5 - k.cx) / k.fx * z, (v + 0.5 - k.cy) / k.fy * z, z], axis=1)
    p = p @ t[:3, :3].T + t[:3, 3]
    lo, hi = np.array([4.5, 4.5, 0.0]), np.array([5.5, 5.5, 2.0])
    assert np.all(p >= lo - 1e-3) and np.all(p <= hi + 1e-3)


def test_pose_matrix_mount_and_yaw():
    t = camera_body_pose(Pose((1.0, 2.0, 0.0), math.pi / 2), CameraMount(height=0.5, pitch=0.0))
    assert np.allclose(t[:3, 3], [1.0, 2.0, 0.5])
    assert np.allclose(t[:3, 0], [0.0, 1.0, 0.0], atol=1e-12)      # forward is +y
    opt = optical_pose(t)
    assert np.allclose(opt[:3, 2], [0.0, 1.0, 0.0], atol=1e-12)    # optical z = forward
    assert np.allclose(opt[:3, 1], [0.0, 0.0, -1.0], atol=1e-12)   # optical y = down
    down = camera_body_pose(Pose((0.0, 0.0, 0.0), 0.0), CameraMount(pitch=0.5))
    assert down[2, 0] < 0                                           # positive pitch looks down


def test_moved_objects_render_where_they_are_now():
    from dataclasses import replace
    cam = SyntheticCamera(SCENE, 80, 60)
    before = cam.render(Pose((1.0, 5.0, 0.0), 0.0))
    moved = replace(SCENE, objects=tuple(replace(o, center=(2.0, 9.0, 1.0)) if o.label == 'red sofa' else o
                                         for o in SCENE.objects))
    after = cam.render(Pose((1.0, 5.0, 0.0), 0.0), scene=moved)
    assert (before.labels == 3).sum() > 0 and (after.labels == 3).sum() == 0
    assert after.classes == before.classes


@pytest.mark.parametrize('pose', [Pose((float('nan'), 0.0, 0.0), 0.0), Pose((0.0, 0.0, 0.0), float('inf')),
                                  np.full((4, 4), np.nan), np.eye(3), 'here', 2 * np.eye(4)])
def test_bad_poses_are_typed_errors(pose):
    with pytest.raises(InvalidInputError):
        SyntheticCamera(SCENE, 16, 12).render(pose)


def test_bad_intrinsics():
    with pytest.raises(InvalidInputError):
        CameraIntrinsics(0, 10, 1.0, 1.0, 0.0, 0.0)
    with pytest.raises(InvalidInputError):
        CameraIntrinsics.coerce((10, 10, -1.0, 1.0, 5.0, 5.0))
    with pytest.raises(InvalidInputError):
        CameraIntrinsics.coerce('garbage')
    k = CameraIntrinsics.default(160, 120)
    assert (k.width, k.height, k.cx, k.cy) == (160, 120, 80.0, 60.0) and k.fx == pytest.approx(80.0)

"""Build a semantic map of a scene from synthetic camera views (CLI ``--views``, tests, benchmarks).

The views stand on an ellipse inside the scene's bounds, at eye height, each looking at
the scene's centre (so together they see every side of the objects in the middle).
"""
from __future__ import annotations

import math
from typing import Optional

import numpy as np

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.semantic_map import SemanticMap, SemanticMapParams
from ltl_instruct.core.world.camera import SyntheticCamera
from ltl_instruct.core.world.scene import Scene


def survey_poses(scene: Scene, views: int, eye_height: float = 2.2, radius_fraction: float = 0.45,
                 target_height: float = 0.4) -> list[np.ndarray]:
    """Return the camera body poses ``T_map_body`` (4, 4) of ``views`` views around the scene centre.

    Parameters
    ----------
    scene: the scene; the views stand inside its bounds.
    views: number of views (>= 1).
    eye_height: camera height above the floor [m].
    radius_fraction: ellipse half-axes as a fraction of the bounds' extent.
    target_height: height above the floor of the point every view looks at [m].
    """
    if not isinstance(views, int) or views < 1 or views > 1000:
        raise InvalidInputError(f'views must be an integer in 1..1000, got {views!r}')
    lo = np.asarray(scene.bounds_min, dtype=float)
    hi = np.asarray(scene.bounds_max, dtype=float)
    centre = (lo + hi) / 2.0
    half = (hi - lo) / 2.0 * radius_fraction * 2.0
    eye_z = lo[2] + min(eye_height, max(hi[2] - lo[2] - 0.1, 0.5))
    target = np.array([centre[0], centre[1], lo[2] + target_height])
    poses = []
    for k in range(views):
        a = 2.0 * math.pi * k / views + math.pi / views
        eye = np.array([centre[0] + half[0] * math.cos(a), centre[1] + half[1] * math.sin(a), eye_z])
        poses.append(SyntheticCamera.look_at(eye, target))
    return poses


def survey_params(scene: Scene) -> SemanticMapParams:
    """Map settings for a survey of ``scene``: 0.1 m voxels, coarser in a scene wider than 25 m.

    A wide scene gets about 250 voxels across (in steps of 5 cm: 0.5 m for a 120 m city
    block), so that it fits the grid as a room does; the range reaches across the scene.
    """
    size = np.ptp(np.array([scene.bounds_min, scene.bounds_max], dtype=float), axis=0)
    voxel = max(0.1, math.ceil(round(float(size[:2].max()) / 250.0 / 0.05, 6)) * 0.05)
    return SemanticMapParams(voxel_size=voxel, max_range=max(8.0, float(np.linalg.norm(size))))


def map_from_views(scene: Scene, views: int, width: int = 320, height: int = 240,
                   params: Optional[SemanticMapParams] = None) -> SemanticMap:
    """Render ``views`` label + depth frames of ``scene`` and integrate them into a new map.

    ``params`` default to :func:`survey_params` of the scene.
    """
    size = np.ptp(np.array([scene.bounds_min, scene.bounds_max], dtype=float), axis=0)
    camera = SyntheticCamera(scene, width, height, max_range=max(20.0, float(size.max()) * 1.5))
    smap = SemanticMap(camera.classes, params or survey_params(scene))
    for pose in survey_poses(scene, views):
        frame = camera.render(pose)
        smap.integrate(frame.depth, frame.labels, frame.intrinsics, frame.t_map_body)
    return smap

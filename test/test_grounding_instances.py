"""Instances that are objects: fragments fused, neighbours kept apart, contradicted instances removed."""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from ltl_instruct.core.grounding import SemanticMap
from ltl_instruct.core.grounding.fusion import Fragment, FusionParams, box_gaps, fuse, gap_box
from ltl_instruct.core.grounding.semantic_map import MapInstance
from ltl_instruct.core.world.camera import SyntheticCamera
from ltl_instruct.core.world.scene import Scene, scene_from_dict

CHAIR = [0.5, 0.5, 0.9]


def room(*objects: dict) -> Scene:
    return scene_from_dict({'bounds': {'min': [0, 0, 0], 'max': [8, 8, 3]}, 'objects': list(objects)})


def chair(x: float, y: float, label: str = 'red chair') -> dict:
    return {'label': label, 'center': [x, y, 0.45], 'size': CHAIR}


ONE_CHAIR = room(chair(4.0, 4.0))
TWO_CHAIRS = room(chair(3.625, 4.0), chair(4.375, 4.0))     # side by side, 0.25 m apart


def ring_poses(n: int, radius: float, height: float, target=(4.0, 4.0, 0.45)) -> list[np.ndarray]:
    """Camera body poses on a circle around ``target``, each looking at it."""
    out = []
    for k in range(n):
        a = 2.0 * math.pi * k / n
        eye = np.array([target[0] + radius * math.cos(a), target[1] + radius * math.sin(a), height])
        out.append(SyntheticCamera.look_at(eye, np.array(target)))
    return out


def integrate(smap: SemanticMap, cam: SyntheticCamera, poses, scene=None) -> SemanticMap:
    for pose in poses:
        f = cam.render(pose, scene=scene)
        smap.integrate(f.depth, f.labels, f.intrinsics, f.t_map_body)
    return smap


def map_of(scene: Scene, poses) -> SemanticMap:
    cam = SyntheticCamera(scene, 160, 120)
    return integrate(SemanticMap(cam.classes), cam, poses)


def chairs(smap: SemanticMap) -> list[MapInstance]:
    return [r for r in smap.instance_records() if r.instance.label == 'red chair']


def test_one_object_seen_from_eight_views_is_one_instance():
    # far views sample the chair sparsely: its shell falls apart into pieces
    found = chairs(map_of(ONE_CHAIR, ring_poses(8, 6.0, 2.2)))
    assert len(found) == 1
    inst = found[0].instance
    assert np.linalg.norm(np.subtract(inst.center, (4.0, 4.0, 0.45))) <= 0.15
    assert np.all(np.abs(np.subtract(inst.size, CHAIR)) <= 0.15)


def test_front_and_back_of_one_object_are_one_instance():
    """Seen only from in front and behind, below its top: two faces 0.4 m apart, nothing seen between."""
    found = chairs(map_of(ONE_CHAIR, ring_poses(2, 3.0, 0.45)))
    assert len(found) == 1 and found[0].fragments == 2
    assert np.linalg.norm(np.subtract(found[0].instance.center, (4.0, 4.0, 0.45))) <= 0.15


@pytest.mark.parametrize('poses', [ring_poses(8, 6.0, 2.2), ring_poses(8, 3.0, 2.2)])
def test_two_adjacent_same_label_objects_stay_two_instances(poses):
    found = sorted(chairs(map_of(TWO_CHAIRS, poses)), key=lambda r: r.instance.center[0])
    assert len(found) == 2
    for r, x in zip(found, (3.625, 4.375)):
        assert np.linalg.norm(np.subtract(r.instance.center, (x, 4.0, 0.45))) <= 0.15


def test_an_instance_whose_place_later_views_see_empty_is_removed():
    cam = SyntheticCamera(ONE_CHAIR, 160, 120)
    poses = ring_poses(8, 3.0, 2.2)
    smap = integrate(SemanticMap(cam.classes), cam, poses)
    (seen,) = chairs(smap)
    assert seen.evidence == pytest.approx(smap.params.max_evidence, abs=0.5)
    empty = replace(ONE_CHAIR, objects=())
    # one view of the empty place lowers the evidence but does not undo eight views
    integrate(smap, cam, poses[:1], empty)
    (weaker,) = chairs(smap)
    assert weaker.evidence < seen.evidence
    # every view of it does: the whole instance goes, no piece of it is left behind
    integrate(smap, cam, poses, empty)
    assert chairs(smap) == []
    assert smap.frames == 17


def test_counts_and_confidence_are_exposed():
    smap = map_of(ONE_CHAIR, ring_poses(8, 3.0, 2.2))
    (r,) = chairs(smap)
    inst = r.instance
    assert smap.instances() == tuple(x.instance for x in smap.instance_records())
    assert inst.id == 'det_red_chair_1' and inst.observations >= 4
    assert 0.5 <= inst.confidence <= 1.0
    assert r.voxels >= smap.params.min_cluster_voxels and r.fragments >= 1
    assert smap.params.min_evidence <= r.evidence <= smap.params.max_evidence
    assert {'confidence', 'observations'} <= set(inst.to_dict())


# ---------------------------------------------------------------- fusion on boxes of voxels
def frag(lo, hi, column: int = 1) -> Fragment:
    lo, hi = np.array(lo), np.array(hi)
    cells = np.argwhere(np.ones(hi - lo + 1, dtype=bool)) + lo
    return Fragment(column, cells, lo, hi)


def unseen(lo, hi) -> float:
    return 0.0


def seen_free(lo, hi) -> float:
    return 1.0


FRONT, BACK = frag([0, 0, 0], [0, 5, 8]), frag([5, 0, 0], [5, 5, 8])      # faces of one 6-voxel chair


def test_gaps_and_the_box_between():
    assert list(box_gaps(FRONT.lo, FRONT.hi, BACK.lo, BACK.hi)) == [4, -6, -9]
    lo, hi = gap_box(FRONT.lo, FRONT.hi, BACK.lo, BACK.hi)
    assert list(lo) == [1, 0, 0] and list(hi) == [4, 5, 8]


def test_fusion_bridges_an_unseen_inside_but_not_a_seen_gap():
    assert fuse([FRONT, BACK], unseen) == [[0, 1]]
    assert sorted(fuse([FRONT, BACK], seen_free)) == [[0], [1]]


def test_fusion_keeps_labels_apart_and_merges_overlapping_boxes():
    inner = frag([0, 2, 2], [0, 3, 3])
    assert fuse([FRONT, inner], seen_free) == [[0, 1]]                      # a piece inside the other's box
    assert sorted(fuse([FRONT, frag([5, 0, 0], [5, 5, 8], column=2)], unseen)) == [[0], [1]]


def test_size_prior_keeps_two_whole_objects_apart_even_unseen_between():
    a, b = frag([0, 0, 0], [5, 5, 8]), frag([8, 0, 0], [13, 5, 8])          # two chairs, 2 voxels apart
    assert sorted(fuse([a, b], unseen)) == [[0], [1]]
    # a chain of pieces cannot grow one instance past it either
    pieces = [frag([6 * k, 0, 0], [6 * k + 1, 5, 8]) for k in range(4)]
    groups = fuse(pieces, unseen, FusionParams(max_gap=5))
    assert all(len(g) < 4 for g in groups)

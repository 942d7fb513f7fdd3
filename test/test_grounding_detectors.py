"""Open-vocabulary detection and SAM masks: the real transformers code path on tiny random models.

No weights can be downloaded here: each test builds a tiny randomly initialised model
from a config, saves it with ``save_pretrained`` and loads it back through the detector
classes, exactly as real weights in a local directory would be loaded. Random models
give arbitrary boxes, so the tests check shapes, types, ranges and error handling.
"""
from __future__ import annotations

import json

import numpy as np
import pytest

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.core.grounding.detectors import (
    Detection, OpenVocabularyDetector, SamSegmenter, label_image,
)

torch = pytest.importorskip('torch')
transformers = pytest.importorskip('transformers')


def _byte_chars() -> list[str]:
    """The 256 printable characters byte-level BPE uses for bytes (our own construction)."""
    keep = list(range(ord('!'), ord('~') + 1)) + list(range(0xA1, 0xAD)) + list(range(0xAE, 0x100))
    chars, extra = [], 0
    for b in range(256):
        if b in keep:
            chars.append(chr(b))
        else:
            chars.append(chr(256 + extra))
            extra += 1
    return chars


def _tiny_clip_tokenizer(tmp_path):
    chars = _byte_chars()
    tokens = chars + [c + '</w>' for c in chars] + ['<|startoftext|>', '<|endoftext|>']
    (tmp_path / 'vocab.json').write_text(json.dumps({t: i for i, t in enumerate(tokens)}))
    (tmp_path / 'merges.txt').write_text('#version: 0.2\n')
    tok = transformers.CLIPTokenizer(str(tmp_path / 'vocab.json'), str(tmp_path / 'merges.txt'),
                                     model_max_length=16)
    return tok, len(tokens)


def _tiny_owl(tmp, kind):
    tok, vocab = _tiny_clip_tokenizer(tmp)
    torch.manual_seed(0)
    config_cls, model_cls, image_cls, proc_cls = (
        (transformers.OwlViTConfig, transformers.OwlViTForObjectDetection, transformers.OwlViTImageProcessor,
         transformers.OwlViTProcessor) if kind == 'owlvit' else
        (transformers.Owlv2Config, transformers.Owlv2ForObjectDetection, transformers.Owlv2ImageProcessor,
         transformers.Owlv2Processor))
    cfg = config_cls(
        text_config=dict(vocab_size=vocab, hidden_size=32, intermediate_size=37, num_hidden_layers=1,
                         num_attention_heads=2, max_position_embeddings=16),
        vision_config=dict(hidden_size=32, intermediate_size=37, num_hidden_layers=1, num_attention_heads=2,
                           image_size=32, patch_size=8),
        projection_dim=32)   # OWL-ViT's class head compares in the text width
    model = model_cls(cfg)
    if kind == 'owlvit':
        image_proc = image_cls(size={'height': 32, 'width': 32}, crop_size={'height': 32, 'width': 32})
    else:
        image_proc = image_cls(size={'height': 32, 'width': 32})
    proc = proc_cls(image_processor=image_proc, tokenizer=tok)
    out = tmp / 'model'
    model.save_pretrained(out)
    proc.save_pretrained(out)
    return out


@pytest.fixture(scope='module')
def owl_dir(tmp_path_factory):
    return _tiny_owl(tmp_path_factory.mktemp('owl'), 'owlvit')


@pytest.fixture(scope='module')
def owlv2_dir(tmp_path_factory):
    return _tiny_owl(tmp_path_factory.mktemp('owlv2'), 'owlv2')


@pytest.fixture(scope='module')
def sam_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp('sam') / 'model'
    torch.manual_seed(0)
    cfg = transformers.SamConfig(
        vision_config=dict(hidden_size=32, intermediate_size=37, num_hidden_layers=1, num_attention_heads=2,
                           image_size=64, patch_size=16, output_channels=16, window_size=2,
                           global_attn_indexes=[0], mlp_dim=37, num_pos_feats=8),
        prompt_encoder_config=dict(hidden_size=16, image_size=64, patch_size=16, mask_input_channels=4),
        mask_decoder_config=dict(hidden_size=16, mlp_dim=32, num_hidden_layers=1, num_attention_heads=2,
                                 iou_head_hidden_dim=16))
    model = transformers.SamModel(cfg)
    image_proc = transformers.SamImageProcessor(size={'longest_edge': 64},
                                                pad_size={'height': 64, 'width': 64})
    transformers.SamProcessor(image_processor=image_proc).save_pretrained(out)
    model.save_pretrained(out)
    return out


def test_owlvit_detects_through_the_real_code_path(owl_dir):
    det = OpenVocabularyDetector(owl_dir, 'owlvit', score_threshold=0.0)
    rgb = np.random.default_rng(0).integers(0, 255, (48, 64, 3), dtype=np.uint8)
    found = det.detect(rgb, ['red_sofa', 'chair'])
    assert found, 'threshold 0 keeps every box'
    for d in found:
        assert isinstance(d, Detection) and d.label in ('red sofa', 'chair') and 0.0 <= d.score <= 1.0
        x0, y0, x1, y1 = d.box
        assert 0 <= x0 < x1 <= 64 and 0 <= y0 < y1 <= 48
    assert [d.score for d in found] == sorted((d.score for d in found), reverse=True)
    labels = label_image((48, 64), found, {'red sofa': 1, 'chair': 2})
    assert labels.dtype == np.int32 and set(np.unique(labels)) <= {0, 1, 2} and labels.any()


def test_owlv2_boxes_are_in_image_pixels(owlv2_dir):
    det = OpenVocabularyDetector(owlv2_dir, 'owlv2', score_threshold=0.0)
    rgb = np.random.default_rng(2).integers(0, 255, (40, 64, 3), dtype=np.uint8)
    found = det.detect(rgb, ['cup'])
    assert found and all(0 <= d.box[0] < d.box[2] <= 64 and 0 <= d.box[1] < d.box[3] <= 40 for d in found)


def test_detector_input_errors(owl_dir, tmp_path):
    det = OpenVocabularyDetector(owl_dir, 'owlvit')
    with pytest.raises(InvalidInputError):
        det.detect(np.zeros((8, 8), np.uint8), ['a'])
    with pytest.raises(InvalidInputError):
        det.detect(np.zeros((8, 8, 3), np.uint8), [])
    with pytest.raises(InvalidInputError):
        det.detect(np.zeros((8, 8, 3), np.uint8), ['x' * 500])
    with pytest.raises(LtlInstructError) as e:
        OpenVocabularyDetector(tmp_path / 'missing')
    assert e.value.code == ErrorCode.MODEL_ERROR
    (tmp_path / 'empty').mkdir()
    with pytest.raises(LtlInstructError) as e:
        OpenVocabularyDetector(tmp_path / 'empty', 'owlv2')
    assert e.value.code == ErrorCode.MODEL_ERROR
    with pytest.raises(InvalidInputError):
        OpenVocabularyDetector(owl_dir, 'yolo')


def test_sam_masks_from_boxes(sam_dir):
    seg = SamSegmenter(sam_dir)
    rgb = np.random.default_rng(1).integers(0, 255, (48, 64, 3), dtype=np.uint8)
    masks = seg.masks(rgb, [(4, 4, 30, 40), (20, 10, 60, 30)])
    assert masks.shape == (2, 48, 64) and masks.dtype == bool
    assert seg.masks(rgb, []).shape == (0, 48, 64)
    dets = [Detection('cup', 0.9, (4, 4, 30, 40)), Detection('lamp', 0.5, (20, 10, 60, 30))]
    labels = label_image((48, 64), dets, {'cup': 3, 'lamp': 4}, masks)
    assert np.array_equal(labels == 3, masks[0])   # the better detection is painted last


def test_label_image_boxes_and_overlaps():
    dets = [Detection('sofa', 0.4, (0, 0, 10, 10)), Detection('lamp', 0.8, (5, 5, 15, 15)),
            Detection('ghost', 0.9, (0, 0, 20, 20))]
    img = label_image((20, 20), dets, {'sofa': 1, 'lamp': 2})
    assert img[2, 2] == 1 and img[7, 7] == 2 and img[18, 18] == 0
    with pytest.raises(InvalidInputError):
        label_image((20, 20), dets, {'sofa': 1}, np.zeros((1, 20, 20), bool))


# ---------------------------------------------------------------------------- RGB to the semantic map
def test_rgb_labeller_wires_a_random_owlvit_into_the_semantic_map(owl_dir):
    from ltl_instruct.core.grounding import SemanticMap, SemanticMapParams
    from ltl_instruct.core.grounding.detectors import load_labeller
    from ltl_instruct.core.world.builtin import resolve_scene
    from ltl_instruct.core.world.camera import SyntheticCamera
    from ltl_instruct.core.world.robot import Pose
    frame = SyntheticCamera(resolve_scene('apartment'), 64, 48).render(Pose((1.5, 1.5, 0.0), 0.3))
    labeller = load_labeller('owlvit', owl_dir, score_threshold=0.0)
    labels = labeller.labels(frame.rgb, ['red_sofa', 'pillar'])
    assert labels.dtype == np.int32 and labels.shape == (48, 64) and labels.any()
    assert labeller.classes == {1: 'pillar', 2: 'red sofa'} and set(np.unique(labels)) <= {0, 1, 2}
    assert labeller.labels(frame.rgb, []).any() == False           # noqa: E712  (no query, no labels)
    labeller.labels(frame.rgb, ['lamp', 'pillar'])
    assert labeller.classes == {1: 'pillar', 2: 'red sofa', 3: 'lamp'}   # ids stay, new names are added
    smap = SemanticMap(labeller.classes, SemanticMapParams(min_cluster_voxels=1))
    smap.integrate(frame.depth, labels, frame.intrinsics, frame.t_map_body)
    assert {i.label for i in smap.instances()} <= {'pillar', 'red sofa'}


def test_a_detector_that_cannot_load_is_a_model_error(tmp_path):
    from ltl_instruct.core.grounding.detectors import load_labeller
    with pytest.raises(LtlInstructError) as e:
        load_labeller('owlv2', tmp_path / 'no-weights')
    assert e.value.code == ErrorCode.MODEL_ERROR


class _BoxesOfTheLabelImages:
    """A perfect box detector: the boxes of the simulator's label image (one per connected piece)."""

    def __init__(self, classes):
        self.classes, self.image = classes, None

    def detect(self, rgb, queries):
        from scipy import ndimage
        out = []
        for cid, label in self.classes.items():
            if label not in queries:
                continue
            pieces, _ = ndimage.label(self.image == cid)
            for sl in ndimage.find_objects(pieces):
                out.append(Detection(label, 1.0, (sl[1].start, sl[0].start, sl[1].stop, sl[0].stop)))
        return out


def test_boxes_as_masks_still_place_objects_where_the_label_images_do():
    """Accuracy of the path without SAM against the simulator's label images (the truth).

    A detector's box painted as the mask also labels what lies behind the object inside
    the box (a wall behind the pillar became a second and third pillar); cut to the near
    surface in the box by depth, each object is one instance again, with its centre inside
    the object the label images map (not always at its centre: the part of a long sofa
    within 0.5 m of its near end).
    """
    from ltl_instruct.core.grounding import SemanticMap, ground_formula
    from ltl_instruct.core.grounding.detectors import RgbLabeller
    from ltl_instruct.core.grounding.survey import survey_params, survey_poses
    from ltl_instruct.core.world.builtin import resolve_scene
    from ltl_instruct.core.world.camera import SyntheticCamera
    scene = resolve_scene('apartment')
    camera = SyntheticCamera(scene, 160, 120, max_range=30.0)
    oracle = _BoxesOfTheLabelImages(camera.classes)
    labeller = RgbLabeller(oracle)
    names = ['pillar', 'sofa', 'computer']
    exact = SemanticMap(camera.classes, survey_params(scene))
    boxes = SemanticMap({}, survey_params(scene))
    for pose in survey_poses(scene, 8):
        frame = camera.render(pose)
        exact.integrate(frame.depth, frame.labels, frame.intrinsics, pose)
        oracle.image = frame.labels
        boxes.integrate(frame.depth, labeller.labels(frame.rgb, names, frame.depth), frame.intrinsics, pose)
        boxes.name_classes(labeller.classes)
    for name in names:
        want = ground_formula(f'F near[{name}]', exact.instances()).get(name)
        got = ground_formula(f'F near[{name}]', boxes.instances()).get(name)
        assert want.instances and len(got.instances) == len(want.instances), (name, got)
        pairs = zip(sorted(want.instances, key=lambda i: i.center),
                    sorted(got.instances, key=lambda i: i.center))
        for a, b in pairs:   # the same object: the centre in its box (a long sofa is seen in part)
            assert np.all(np.abs(np.subtract(a.center, b.center)) <= np.asarray(a.size) / 2 + 0.1), (a, b)

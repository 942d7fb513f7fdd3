"""Detections to label images: open-vocabulary boxes (OWL-ViT / OWLv2) and SAM masks, via transformers.

The semantic map integrates label images (class id per pixel). A simulator or any
segmenter gives them directly; for plain RGB images this module makes them:

1. :class:`OpenVocabularyDetector` finds boxes of the referent names of a task (text
   queries) with OWL-ViT or OWLv2, loaded from a local directory (no download);
2. :class:`SamSegmenter` turns each box into a mask with SAM (optional; without it the
   box itself is the mask);
3. :func:`label_image` paints the masks into an int32 label image with a class table.

:class:`RgbLabeller` does the three for the referent names of the tasks, with a class
table that grows with the names; without SAM each box is cut to the near surface in it
by depth (:func:`depth_masks`). ``referent_grounder`` uses it with ``detector: owlvit``
or ``owlv2``.

Models load once per detector object; every failure to load or run them is a typed
``MODEL_ERROR``. Images are uint8 (H, W, 3) RGB; boxes are ``(x0, y0, x1, y1)`` in
pixels of that image.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError

MAX_QUERIES = 64


@dataclass(frozen=True)
class Detection:
    """One detected object: ``label`` (the query text), ``score`` in [0, 1], ``box`` (x0, y0, x1, y1) [px]."""

    label: str
    score: float
    box: tuple[float, float, float, float]


def _model_error(what: str, e: Exception) -> LtlInstructError:
    return LtlInstructError(f'{what}: {e}', ErrorCode.MODEL_ERROR)


def _check_image(rgb: Any) -> np.ndarray:
    img = np.asarray(rgb)
    if img.ndim != 3 or img.shape[2] != 3 or img.dtype != np.uint8 or min(img.shape[:2]) < 1:
        raise InvalidInputError(f'expected a uint8 (H, W, 3) RGB image, got {img.dtype} {img.shape}')
    return img


def _model_dir(path: Union[str, Path]) -> str:
    p = Path(path)
    if not p.is_dir():
        raise LtlInstructError(f'model directory {p} does not exist', ErrorCode.MODEL_ERROR)
    os.environ.setdefault('HF_HUB_OFFLINE', '1')
    os.environ.setdefault('TRANSFORMERS_OFFLINE', '1')
    return str(p)


class OpenVocabularyDetector:
    """Text-queried box detector (OWL-ViT or OWLv2) from a local model directory.

    Parameters
    ----------
    model_dir: a directory written by ``save_pretrained`` (model and processor).
    kind: ``owlvit`` or ``owlv2``.
    score_threshold: boxes below this score are dropped.
    """

    def __init__(self, model_dir: Union[str, Path], kind: str = 'owlvit',
                 score_threshold: float = 0.1) -> None:
        if kind not in ('owlvit', 'owlv2'):
            raise InvalidInputError(f'kind must be owlvit or owlv2, got {kind!r}')
        path = _model_dir(model_dir)
        try:
            import torch
            from transformers import (
                Owlv2ForObjectDetection, Owlv2Processor, OwlViTForObjectDetection, OwlViTProcessor,
            )
            model_cls, proc_cls = ((OwlViTForObjectDetection, OwlViTProcessor) if kind == 'owlvit'
                                   else (Owlv2ForObjectDetection, Owlv2Processor))
            self.processor = proc_cls.from_pretrained(path, local_files_only=True)
            self.model = model_cls.from_pretrained(path, local_files_only=True).eval()
        except Exception as e:  # noqa: BLE001 - any load failure is a typed model error
            raise _model_error(f'cannot load {kind} from {path}', e) from e
        self._torch = torch
        self.kind = kind
        self.score_threshold = float(score_threshold)

    def detect(self, rgb: np.ndarray, queries: Sequence[str]) -> list[Detection]:
        """Return boxes of the queried objects in one image, best first.

        Parameters
        ----------
        rgb: uint8 (H, W, 3).
        queries: object names (``red sofa``); a referent's underscores may be kept.
        """
        img = _check_image(rgb)
        texts = [q.replace('_', ' ').strip() for q in queries]
        if not texts or len(texts) > MAX_QUERIES or not all(texts) or any(len(t) > 200 for t in texts):
            raise InvalidInputError(f'expected 1..{MAX_QUERIES} non-empty queries of at most 200 characters')
        try:
            inputs = self.processor(text=[texts], images=img, return_tensors='pt')
            with self._torch.no_grad():
                outputs = self.model(**inputs)
            h, w = img.shape[:2]
            if self.kind == 'owlv2':   # OWLv2 pads to a square: boxes are relative to the padded side
                side = max(h, w)
                target = self._torch.tensor([[side, side]])
            else:
                target = self._torch.tensor([[h, w]])
            post = getattr(self.processor, 'post_process_grounded_object_detection', None) \
                or self.processor.post_process_object_detection
            result = post(outputs=outputs, threshold=self.score_threshold, target_sizes=target)[0]
        except Exception as e:  # noqa: BLE001
            raise _model_error(f'{self.kind} failed on an image', e) from e
        dets = []
        labels = result.get('labels')
        for score, label, box in zip(result['scores'].tolist(), labels.tolist(), result['boxes'].tolist()):
            x0, y0, x1, y1 = (float(v) for v in box)
            x0, x1 = max(0.0, min(x0, x1)), min(float(w), max(x0, x1))
            y0, y1 = max(0.0, min(y0, y1)), min(float(h), max(y0, y1))
            if x1 - x0 < 1.0 or y1 - y0 < 1.0:
                continue
            dets.append(Detection(texts[int(label)], float(score), (x0, y0, x1, y1)))
        dets.sort(key=lambda d: -d.score)
        return dets


class SamSegmenter:
    """Box-prompted masks with SAM from a local model directory (``save_pretrained`` output)."""

    def __init__(self, model_dir: Union[str, Path]) -> None:
        path = _model_dir(model_dir)
        try:
            import torch
            from transformers import SamModel, SamProcessor
            self.processor = SamProcessor.from_pretrained(path, local_files_only=True)
            self.model = SamModel.from_pretrained(path, local_files_only=True).eval()
        except Exception as e:  # noqa: BLE001
            raise _model_error(f'cannot load SAM from {path}', e) from e
        self._torch = torch

    def masks(self, rgb: np.ndarray, boxes: Sequence[Sequence[float]]) -> np.ndarray:
        """Return boolean masks of shape (N, H, W), one per box [px]: the best of SAM's proposals."""
        img = _check_image(rgb)
        h, w = img.shape[:2]
        if len(boxes) == 0:
            return np.zeros((0, h, w), dtype=bool)
        try:
            inputs = self.processor(images=img, input_boxes=[[list(map(float, b)) for b in boxes]],
                                    return_tensors='pt')
            with self._torch.no_grad():
                out = self.model(**inputs, multimask_output=True)
            masks = self.processor.image_processor.post_process_masks(
                out.pred_masks, inputs['original_sizes'], inputs['reshaped_input_sizes'])[0]
            best = out.iou_scores[0].argmax(dim=-1)                  # (N,)
            chosen = masks[self._torch.arange(masks.shape[0]), best]  # (N, H, W)
        except Exception as e:  # noqa: BLE001
            raise _model_error('SAM failed on an image', e) from e
        return chosen.numpy().astype(bool)


def depth_masks(detections: Sequence[Detection], depth: np.ndarray, spread: float = 0.5) -> np.ndarray:
    """Cut each box to the near surface in it: masks (N, H, W) of its pixels within ``spread`` [m] of it.

    Without a segmenter a box is the mask, and it also labels what lies behind the object
    in the box (the wall behind a pillar, the floor beside a chair), which the map then
    keeps as pieces of the object. The near surface is the 20th percentile of the box's
    depths [m]: most of a detector's box is its object, and the object is in front.
    """
    d = np.asarray(depth, dtype=np.float32)
    out = np.zeros((len(detections),) + d.shape, dtype=bool)
    for k, det in enumerate(detections):
        x0, y0 = int(det.box[0]), int(det.box[1])
        x1, y1 = int(np.ceil(det.box[2])), int(np.ceil(det.box[3]))
        patch = d[y0:y1, x0:x1]
        with np.errstate(invalid='ignore'):
            valid = np.isfinite(patch) & (patch > 0)
        if not valid.any():
            continue
        near = float(np.percentile(patch[valid], 20))
        with np.errstate(invalid='ignore'):
            out[k, y0:y1, x0:x1] = valid & (np.abs(patch - near) <= spread)
    return out


def label_image(shape: tuple[int, int], detections: Sequence[Detection], class_ids: Mapping[str, int],
                masks: Optional[np.ndarray] = None) -> np.ndarray:
    """Paint detections into an int32 label image (H, W): higher scores win where they overlap.

    Parameters
    ----------
    shape: (H, W) of the image.
    detections: the boxes; a label missing from ``class_ids`` is skipped.
    class_ids: label text -> class id (>= 1), the table given to the semantic map.
    masks: optional boolean (N, H, W) masks, one per detection; else each box is its mask.
    """
    h, w = shape
    out = np.zeros((h, w), dtype=np.int32)
    if masks is not None and (masks.shape[0] != len(detections) or masks.shape[1:] != (h, w)):
        raise InvalidInputError(f'masks {masks.shape} do not match {len(detections)} detections of {shape}')
    order = sorted(range(len(detections)), key=lambda k: detections[k].score)   # best painted last
    for k in order:
        d = detections[k]
        cid = class_ids.get(d.label)
        if cid is None:
            continue
        if masks is not None:
            out[masks[k]] = cid
        else:
            x0, y0, x1, y1 = d.box
            out[int(y0):int(np.ceil(y1)), int(x0):int(np.ceil(x1))] = cid
    return out


class RgbLabeller:
    """Label images from RGB: the referent names of the tasks as text queries, boxes, masks, class ids.

    The class table grows with the queries: each new name gets the next id (from 1), so a
    semantic map fed with these label images keeps one class per name whatever the
    order of the tasks. Detections of a query are painted with its id
    (:func:`label_image`), through SAM masks when a segmenter is given, else as boxes.

    Parameters
    ----------
    detector: anything with ``detect(rgb, queries) -> list[Detection]``
        (:class:`OpenVocabularyDetector`).
    segmenter: optional, with ``masks(rgb, boxes) -> (N, H, W) bool`` (:class:`SamSegmenter`).
    """

    def __init__(self, detector: Any, segmenter: Optional[Any] = None) -> None:
        self.detector, self.segmenter = detector, segmenter
        self.classes: dict[int, str] = {}
        self._ids: dict[str, int] = {}

    def class_id(self, name: str) -> int:
        """Return the class id of a query (the text a detection is labelled with), adding it when new."""
        text = name.replace('_', ' ').strip()
        if text not in self._ids:
            self._ids[text] = len(self._ids) + 1
            self.classes[self._ids[text]] = text
        return self._ids[text]

    def labels(self, rgb: np.ndarray, queries: Sequence[str],
               depth: Optional[np.ndarray] = None) -> np.ndarray:
        """Return the int32 label image (H, W) of one RGB image for the queried names (no query: all 0).

        Without a segmenter, ``depth`` [m] (H, W) cuts each box to its near surface
        (:func:`depth_masks`).
        """
        img = _check_image(rgb)
        names = sorted({q.replace('_', ' ').strip() for q in queries if q.strip()})[:MAX_QUERIES]
        if not names:
            return np.zeros(img.shape[:2], dtype=np.int32)
        ids = {n: self.class_id(n) for n in names}
        found = self.detector.detect(img, names)
        masks = None
        if self.segmenter is not None and found:
            masks = self.segmenter.masks(img, [d.box for d in found])
        elif depth is not None and np.shape(depth) == img.shape[:2]:
            masks = depth_masks(found, depth)
        return label_image(img.shape[:2], found, ids, masks)


def load_labeller(kind: str, detector_dir: Union[str, Path], segmenter_dir: Union[str, Path] = '',
                  score_threshold: float = 0.1) -> RgbLabeller:
    """Load an :class:`RgbLabeller` from local model directories (``segmenter_dir`` '': boxes as masks).

    Raises
    ------
    LtlInstructError
        ``MODEL_ERROR`` when a model cannot be loaded (transformers missing, no such directory...).
    """
    detector = OpenVocabularyDetector(detector_dir, kind, score_threshold)
    segmenter = SamSegmenter(segmenter_dir) if str(segmenter_dir) else None
    return RgbLabeller(detector, segmenter)

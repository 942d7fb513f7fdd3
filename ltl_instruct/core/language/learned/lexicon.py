"""Which instruction words name which landmarks: the lexical prior of the parser's copy scores.

People name landmarks by (part of) their map names, often loosely: "Cosi" for
"Così", "carmas cafe" for "Carma's Cafe", "Internatoinal House". For every word
of the parser's vocabulary and every landmark, :func:`name_match_matrix` gives
how strongly the word points at that landmark:

    M[w, l] = s(w, l) / (|N_l| * df(w))

where N_l are the content words of landmark l's name (stop words such as "the",
"of", "and" left out), s(w, l) is 1 if w equals a word of N_l after
normalisation (lower case, accents and apostrophes removed, a plural or
possessive "s" dropped), 0.5 if it is a near miss (both at least 5 letters and a
similarity ratio of at least 0.85), else 0, and df(w) the number of landmarks
whose names the word matches (a word shared by several names says less). The
matrix depends only on the map's names and the vocabulary, never on
demonstrations, so it works the same on a map without training data.
"""
from __future__ import annotations

import difflib
import unicodedata
from typing import Sequence

import numpy as np

STOP_WORDS = frozenset({
    'the', 'of', 'and', 'a', 'an', 'at', 'on', 'in', 'to', 'for', 'by', 's', 'de', 'la', 'le',
})
NEAR_MISS_WEIGHT = 0.5
NEAR_MISS_RATIO = 0.85
NEAR_MISS_MIN_LETTERS = 5


def ascii_fold(text: str) -> str:
    """Lower-case ``text`` with accents removed ("Così" -> "cosi")."""
    return unicodedata.normalize('NFKD', text).encode('ascii', 'ignore').decode('ascii').lower()


def normalise_word(word: str) -> str:
    """Match key of a word: no apostrophes, no plural or possessive "s" ("carma's" -> "carma")."""
    w = ascii_fold(word).replace("'", '')
    if len(w) > 3 and w.endswith('s') and not w.endswith('ss'):
        w = w[:-1]
    return w


def name_words(name: str, tokenize) -> list[str]:
    """Normalised content words of a landmark name (stop words removed)."""
    return [k for k in (normalise_word(t) for t in tokenize(name)) if k and k not in STOP_WORDS]


def word_name_score(word: str, name_keys: Sequence[str]) -> float:
    """s(w, l): 1 for an exact match of a name word, NEAR_MISS_WEIGHT for a near miss, else 0."""
    key = normalise_word(word)
    if not key or key in STOP_WORDS:
        return 0.0
    if key in name_keys:
        return 1.0
    if len(key) >= NEAR_MISS_MIN_LETTERS:
        for n in name_keys:
            if len(n) >= NEAR_MISS_MIN_LETTERS and \
                    difflib.SequenceMatcher(None, key, n).ratio() >= NEAR_MISS_RATIO:
                return NEAR_MISS_WEIGHT
    return 0.0


def name_match_matrix(vocabulary: Sequence[str], names: Sequence[str], tokenize) -> np.ndarray:
    """M (len(vocabulary), len(names)) float32, as in the module doc."""
    keys = [name_words(n, tokenize) for n in names]
    m = np.zeros((len(vocabulary), len(names)), dtype=np.float32)
    for w, word in enumerate(vocabulary):
        for landmark, k in enumerate(keys):
            if k:
                m[w, landmark] = word_name_score(word, k) / len(k)
    df = (m > 0).sum(axis=1, keepdims=True)
    return (m / np.maximum(df, 1)).astype(np.float32)

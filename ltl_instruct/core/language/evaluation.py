"""Translation metrics of the LIMP paper's tables, checked on automata.

For each example the translator's formula is compared with the gold one:

- **equivalence**: same language on finite traces (``equivalent`` from
  :mod:`ltl_instruct.core.automaton`), never string equality.
- **temporal alignment**: equivalence once the predicted referents are renamed to
  the gold ones they align with (same position in the referent lists), so a
  misspelt referent does not hide a correct temporal structure.
- **referent WER**: word error rate of the predicted referent list against the
  gold list, each descriptor one word (corpus level: edits / gold words). A refused
  instruction counts with the referents of the ``best_reading`` its error carries (the
  instruction read without the parts that could not be placed), as referent resolution
  is scored apart from the temporal structure in the LIMP paper; without one, every gold
  referent is an error. ``referent_wer_strict`` counts every refusal as all errors.
- **avoidance WER**: the same on the descriptors under an explicit negation.
- **spatial WER**: the same on the descriptors that carry spatial relations.
- **wrong and unflagged**: the share of examples whose translation was returned (not
  refused), is not equivalent to the gold formula, and was not flagged by the backend
  (``Translation.extra['flagged']``): the silent errors. A refusal counts as flagged.

Automata of repeated formulas are compiled once (the public sets repeat a few
hundred formulas thousands of times).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional, Sequence

from ltl_instruct.core.automaton import compile_automaton, distinguishing_pair
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.base import Translation, Translator
from ltl_instruct.core.language.datasets import Example
from ltl_instruct.core.language.verification import best_reading_of
from ltl_instruct.core.spec import (  # noqa: F401  (rename_descriptors is part of this API)
    Descriptor, Formula, avoided_referents_of, referents_of, rename_descriptors,
)


def edit_distance(ref: Sequence[str], hyp: Sequence[str]) -> int:
    """Levenshtein distance between two word sequences."""
    prev = list(range(len(hyp) + 1))
    for i, r in enumerate(ref, 1):
        cur = [i] + [0] * len(hyp)
        for j, h in enumerate(hyp, 1):
            cur[j] = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (r != h))
        prev = cur
    return prev[-1]


class EquivalenceChecker:
    """Automaton equivalence with compiled automata cached by formula text."""

    def __init__(self) -> None:
        self._automata: dict[str, Any] = {}
        self._pairs: dict[tuple[str, str], bool] = {}

    def _automaton(self, f: Formula) -> Any:
        key = str(f)
        if key not in self._automata:
            self._automata[key] = compile_automaton(f)
        return self._automata[key]

    def equivalent(self, f: Formula, g: Formula) -> bool:
        """Whether ``f`` and ``g`` accept the same finite traces."""
        key = (str(f), str(g))
        if key not in self._pairs:
            self._pairs[key] = distinguishing_pair(self._automaton(f), self._automaton(g)) is None
        return self._pairs[key]


@dataclass
class ExampleResult:
    """The outcome for one example."""

    example: Example
    predicted: Optional[Formula]
    error: Optional[str]
    equivalent: bool
    aligned: bool
    seconds: float
    flagged: bool = False   # refused, or returned with extra['flagged'] set

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'source': self.example.source, 'instruction': self.example.instruction,
                'gold': str(self.example.formula),
                'predicted': None if self.predicted is None else str(self.predicted),
                'error': self.error, 'equivalent': self.equivalent, 'temporal_alignment': self.aligned,
                'flagged': self.flagged}


@dataclass
class Scores:
    """Corpus-level figures."""

    count: int = 0
    errors: int = 0
    equivalent: int = 0
    aligned: int = 0
    wrong_unflagged: int = 0   # returned, not equivalent, and not flagged by the backend
    flagged: int = 0           # refused or flagged: the person is asked to check
    ref_edits: int = 0
    ref_words: int = 0
    strict_ref_edits: int = 0   # refusals counted as all errors, best readings ignored
    best_readings: int = 0   # refusals that carried a best reading
    avoid_edits: int = 0
    avoid_words: int = 0
    spatial_edits: int = 0
    spatial_words: int = 0
    seconds: float = 0.0
    max_seconds: float = 0.0
    results: list[ExampleResult] = field(default_factory=list)

    def summary(self) -> dict[str, Any]:
        """Return the metrics as a JSON-ready dict."""
        def rate(a: int, b: int) -> Optional[float]:
            return round(a / b, 4) if b else None
        return {
            'examples': self.count, 'translation_errors': self.errors,
            'equivalence_accuracy': rate(self.equivalent, self.count),
            'temporal_alignment': rate(self.aligned, self.count),
            'wrong_unflagged_share': rate(self.wrong_unflagged, self.count),
            'flagged_share': rate(self.flagged, self.count),
            'refusals_with_best_reading': self.best_readings,
            'referent_wer': rate(self.ref_edits, self.ref_words),
            'referent_wer_strict': rate(self.strict_ref_edits, self.ref_words),
            'avoidance_wer': rate(self.avoid_edits, self.avoid_words),
            'spatial_wer': rate(self.spatial_edits, self.spatial_words),
            'mean_ms_per_instruction': round(1000 * self.seconds / self.count, 3) if self.count else None,
            'max_ms_per_instruction': round(1000 * self.max_seconds, 3),
        }


def _spatial(ds: Sequence[Descriptor]) -> list[str]:
    return [str(d) for d in ds if d.relations]


def evaluate(translator: Translator, examples: Sequence[Example],
             checker: Optional[EquivalenceChecker] = None,
             progress: Optional[Callable[[int], None]] = None) -> Scores:
    """Translate every example and score it against its gold formula."""
    checker = checker or EquivalenceChecker()
    scores = Scores()
    cache: dict[str, Translation | LtlInstructError] = {}
    for k, ex in enumerate(examples):
        started = time.perf_counter()
        got = cache.get(ex.instruction)
        if got is None:
            try:
                got = translator.translate(ex.instruction)
            except LtlInstructError as e:
                got = e
            cache[ex.instruction] = got
        elapsed = time.perf_counter() - started
        scores.count += 1
        scores.seconds += elapsed
        scores.max_seconds = max(scores.max_seconds, elapsed)
        gold_refs = list(referents_of(ex.formula))
        gold_avoid = list(avoided_referents_of(ex.formula))
        if isinstance(got, LtlInstructError):
            scores.errors += 1
            flagged = True
            pred: Optional[Formula] = None
            error: Optional[str] = got.message
            guess = best_reading_of(got, ex.instruction)
            partial = None if guess is None else guess.formula
            scores.best_readings += partial is not None
            pred_refs: list[Descriptor] = [] if partial is None else list(referents_of(partial))
            pred_avoid: list[Descriptor] = [] if partial is None else list(avoided_referents_of(partial))
        else:
            pred, error = got.formula, None
            flagged = bool(got.extra.get('flagged'))
            pred_refs = list(referents_of(pred))
            pred_avoid = list(avoided_referents_of(pred))
        scores.ref_edits += edit_distance([str(d) for d in gold_refs], [str(d) for d in pred_refs])
        scores.ref_words += len(gold_refs)
        scores.strict_ref_edits += len(gold_refs) if pred is None else \
            edit_distance([str(d) for d in gold_refs], [str(d) for d in pred_refs])
        scores.avoid_edits += edit_distance([str(d) for d in gold_avoid], [str(d) for d in pred_avoid])
        scores.avoid_words += len(gold_avoid)
        gs, ps = _spatial(gold_refs), _spatial(pred_refs)
        scores.spatial_edits += edit_distance(gs, ps)
        scores.spatial_words += len(gs)
        eq = aligned = False
        if pred is not None:
            try:
                eq = checker.equivalent(pred, ex.formula)
                aligned = eq
                if not eq and len(pred_refs) == len(gold_refs) and set(pred_refs) != set(gold_refs):
                    mapping = dict(zip(pred_refs, gold_refs))
                    aligned = checker.equivalent(rename_descriptors(pred, mapping), ex.formula)
            except LtlInstructError as e:
                error = f'equivalence check failed: {e.message}'
        scores.equivalent += eq
        scores.aligned += aligned
        scores.wrong_unflagged += pred is not None and not eq and not flagged
        scores.flagged += flagged
        scores.results.append(ExampleResult(ex, pred, error, eq, aligned, elapsed, flagged))
        if progress is not None:
            progress(k)
    return scores

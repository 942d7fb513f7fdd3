"""Evaluation on held-out demonstrations: goal-state accuracy and path metrics, model vs baseline.

For each test instruction, the parser's beam (beam 20) is decoded and the best
program that has a plan on the landmark graph from the demonstration's start is
taken; its plan is the product-graph shortest path (``planning``). The baseline
predicts the final landmark and takes the shortest path there. Against the
demonstrated path D, a predicted path P scores:

* goal-state accuracy: P ends where D ends;
* precision |set(P) & set(D)| / |set(P)| and recall |set(P) & set(D)| / |set(D)|;
* path accuracy: P == D;
* edit distance: Levenshtein distance between the landmark sequences.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Sequence

import networkx as nx
import torch

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.learned.bundle import ParserBundle
from ltl_instruct.core.language.learned.data import Demonstration
from ltl_instruct.core.language.learned.model import pad_batch
from ltl_instruct.core.language.learned.planning import plan_on_landmarks
from ltl_instruct.core.language.learned.programs import program_to_formula


def edit_distance(a: Sequence[int], b: Sequence[int]) -> int:
    """Levenshtein distance (insertions, deletions, substitutions cost 1)."""
    prev = list(range(len(b) + 1))
    for i, x in enumerate(a, 1):
        cur = [i]
        for j, y in enumerate(b, 1):
            cur.append(min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (x != y)))
        prev = cur
    return prev[-1]


@dataclass
class PathScores:
    """Mean scores of predicted paths against demonstrated ones."""

    n: int = 0
    goal_accuracy: float = 0.0
    precision: float = 0.0
    recall: float = 0.0
    path_accuracy: float = 0.0
    edit_distance: float = 0.0
    _sums: dict = field(default_factory=lambda: dict.fromkeys(
        ('goal', 'precision', 'recall', 'exact', 'edit'), 0.0), repr=False)

    def add(self, predicted: Sequence[int], demonstrated: Sequence[int]) -> None:
        """Score one prediction."""
        p, d = set(predicted), set(demonstrated)
        s = self._sums
        s['goal'] += float(bool(predicted) and predicted[-1] == demonstrated[-1])
        s['precision'] += len(p & d) / len(p) if p else 0.0
        s['recall'] += len(p & d) / len(d)
        s['exact'] += float(tuple(predicted) == tuple(demonstrated))
        s['edit'] += edit_distance(predicted, demonstrated)
        self.n += 1
        self.goal_accuracy = s['goal'] / self.n
        self.precision = s['precision'] / self.n
        self.recall = s['recall'] / self.n
        self.path_accuracy = s['exact'] / self.n
        self.edit_distance = s['edit'] / self.n

    def to_dict(self) -> dict:
        """JSON-ready figures."""
        return {'n': self.n, 'goal_accuracy': self.goal_accuracy, 'precision': self.precision,
                'recall': self.recall, 'path_accuracy': self.path_accuracy,
                'edit_distance': self.edit_distance}


def plan_best_program(bundle: ParserBundle, programs: Sequence[tuple[int, ...]],
                      start: int) -> tuple[Optional[tuple[int, ...]], list[int]]:
    """Return the best program of the beam whose plan from ``start`` moves, and that plan.

    A program already satisfied at the start asks nothing of the robot, so it is
    taken only when no program of the beam leads anywhere; ``(None, [start])`` when
    no program has a plan at all.
    """
    standing: Optional[tuple[int, ...]] = None
    for prog in programs:
        try:
            formula = program_to_formula(bundle.out_vocab, prog)
            path = list(plan_on_landmarks(bundle.landmark_map, formula, start).path)
        except LtlInstructError:
            continue
        if len(path) > 1:
            return prog, path
        if standing is None:
            standing = prog
    return standing, [start]


def evaluate(bundle: ParserBundle, demos: Sequence[Demonstration], batch: int = 32) -> dict:
    """Scores of the parser and the baseline on ``demos`` (JSON-ready), plus a few examples."""
    model_scores, baseline_scores = PathScores(), PathScores()
    no_plan = 0
    examples = []
    graph = bundle.landmark_map.graph()
    for lo in range(0, len(demos), batch):
        chunk = demos[lo:lo + batch]
        ids = [bundle.words.encode(d.instruction) for d in chunk]
        with torch.no_grad():
            words_t, lengths = pad_batch(ids)
            states, mask = bundle.parser.encode(words_t, lengths)
            beams = bundle.parser.beam_search(states, mask)
            goals = bundle.baseline(bundle.baseline.bag_of_words(ids)).argmax(dim=1).tolist()
        for d, beam, goal in zip(chunk, beams, goals):
            prog, path = plan_best_program(bundle, beam.programs, d.path[0])
            no_plan += prog is None
            model_scores.add(path, d.path)
            try:
                base_path = list(nx.shortest_path(graph, d.path[0], int(goal), weight='weight'))
            except nx.NetworkXNoPath:
                base_path = [d.path[0]]
            baseline_scores.add(base_path, d.path)
            if len(examples) < 5:
                examples.append({
                    'instruction': d.instruction,
                    'demonstrated': [bundle.landmark_map.props[v] for v in d.path],
                    'formula': str(program_to_formula(bundle.out_vocab, prog)) if prog else None,
                    'planned': [bundle.landmark_map.props[v] for v in path],
                    'baseline': [bundle.landmark_map.props[v] for v in base_path]})
    return {'model': model_scores.to_dict(), 'baseline': baseline_scores.to_dict(),
            'no_plan': no_plan, 'trajectories': len({d.path for d in demos}), 'examples': examples}

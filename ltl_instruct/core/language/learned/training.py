"""Training from trajectories alone: the automaton is the teacher.

Reward of a decoded program z for a demonstration (a landmark path from its start
to its goal), with the automaton as the teacher:

* 0 unless z, progressed along the demonstrated trace, is accepted first at the
  trace's last step (a robot stops at the first accepting point, so a formula
  accepted earlier would not lead it along the demonstration);
* then z is planned from the demonstration's start (shortest walk in the
  product of landmark graph and automaton, ``planning``): 1 if that walk is the
  demonstrated path, ``GOAL_REWARD`` (0.5) if it reaches the demonstrated goal by
  another route (e.g. the map's alternative path, or the shortest one), and 0 if
  it stops elsewhere. This is our choice for "a formula that also accepts an
  alternative path may be rewarded less": rather than testing only the one
  alternative path the data gives, we test the route a robot would actually
  take, which also rules out formulas that merely count steps (``X X X ...``).

Learning: randomised beam search (epsilon-greedy slots, Guu et al. 2017) finds
programs; the objective is maximum marginal likelihood with beta-meritocratic
weights over the rewarded programs: the gradient is sum_z q(z) d log p(z) with
q(z) proportional to R(z) p(z)^beta among the rewarded programs of the beam and
of a per-example memory of the rewarded programs found so far (so a program
found once keeps being trained on). Adam, learning rate 0.001, minibatches of 8.

Rewards are cached per (program, trajectory): decoded programs repeat a lot.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable, Optional, Sequence

import numpy as np
import torch

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.learned.data import Demonstration
from ltl_instruct.core.language.learned.lexicon import name_match_matrix
from ltl_instruct.core.language.learned.model import (
    GoalBaseline, ParserConfig, SemanticParser, WordVocabulary, pad_batch, tokenize,
)
from ltl_instruct.core.language.learned.planning import plan_on_landmarks
from ltl_instruct.core.language.learned.programs import OutputVocabulary, first_acceptance, program_to_formula
from ltl_instruct.core.world.landmarks import LandmarkMap

GOAL_REWARD = 0.5


class RewardCache:
    """Reward of programs for demonstrations, memoised per (program, trajectory) and (program, start)."""

    def __init__(self, vocab: OutputVocabulary, landmark_map: LandmarkMap,
                 goal_reward: float = GOAL_REWARD) -> None:
        self.vocab = vocab
        self.landmark_map = landmark_map
        self.goal_reward = goal_reward
        self._first: dict[tuple[tuple[int, ...], tuple[int, ...]], Optional[int]] = {}
        self._plans: dict[tuple[tuple[int, ...], int], Optional[tuple[int, ...]]] = {}
        self.lookups = 0
        self.misses = 0

    def first_acceptance(self, program: tuple[int, ...], path: tuple[int, ...]) -> Optional[int]:
        """Length of the shortest accepted prefix of ``path`` (cached)."""
        self.lookups += 1
        key = (program, path)
        if key not in self._first:
            self.misses += 1
            self._first[key] = first_acceptance(self.vocab, program, path)
        return self._first[key]

    def plan(self, program: tuple[int, ...], start: int) -> Optional[tuple[int, ...]]:
        """Plan the program from ``start`` (landmark ids), None if it has none (cached)."""
        key = (program, start)
        if key not in self._plans:
            try:
                formula = program_to_formula(self.vocab, program)
                self._plans[key] = plan_on_landmarks(self.landmark_map, formula, start).path
            except LtlInstructError:
                self._plans[key] = None
        return self._plans[key]

    def reward(self, program: tuple[int, ...], demo: Demonstration) -> float:
        """Reward in {0, GOAL_REWARD, 1} of a program for a demonstration (see the module doc)."""
        if self.first_acceptance(program, demo.path) != len(demo.path):
            return 0.0
        planned = self.plan(program, demo.path[0])
        if planned == demo.path:
            return 1.0
        if planned is not None and planned[-1] == demo.path[-1]:
            return self.goal_reward
        return 0.0


@dataclass(frozen=True)
class TrainingConfig:
    """Training settings."""

    epochs: int = 30
    batch: int = 8
    learning_rate: float = 1e-3
    beam: int = 20
    epsilon: float = 0.15          # randomised beam: chance a slot takes a random continuation
    beta: float = 0.5              # meritocratic weight exponent (0 uniform, 1 plain MML)
    memory: int = 8                # rewarded programs remembered per example
    seed: int = 0
    time_limit_s: float = 1080.0   # stop starting new epochs after this (18 min)
    baseline_epochs: int = 60


@dataclass
class TrainingLog:
    """What happened during training (JSON-ready)."""

    epochs_run: int = 0
    seconds: float = 0.0
    mean_reward_per_epoch: list[float] = field(default_factory=list)
    hit_rate_per_epoch: list[float] = field(default_factory=list)
    reward_cache_entries: int = 0

    def to_dict(self) -> dict:
        """JSON-ready dict."""
        return dict(self.__dict__)


def encode_instructions(words: WordVocabulary, demos: Sequence[Demonstration]) -> list[list[int]]:
    """Word ids of each demonstration's instruction."""
    return [words.encode(d.instruction) for d in demos]


class ParserTrainer:
    """Trains one parser epoch by epoch, so that several seeds can be probed and one continued.

    Holds everything a run carries from one epoch to the next: the optimiser, the
    sampling generator and the per-example memory of rewarded programs. Rewards are
    a pure function of (program, trajectory), so several trainers may share one
    :class:`RewardCache`.
    """

    def __init__(self, model: SemanticParser, words: WordVocabulary, demos: Sequence[Demonstration],
                 landmark_map: LandmarkMap, config: TrainingConfig = TrainingConfig(),
                 rewards: Optional[RewardCache] = None) -> None:
        torch.manual_seed(config.seed)
        self.model = model
        self.demos = demos
        self.config = config
        self.rng = np.random.default_rng(config.seed)
        self.rewards = rewards if rewards is not None else RewardCache(model.out_vocab, landmark_map)
        self.optimiser = torch.optim.Adam(model.parameters(), lr=config.learning_rate)
        self.word_ids = encode_instructions(words, demos)
        self.memory: list[dict[tuple[int, ...], float]] = [{} for _ in demos]
        self.log = TrainingLog()

    @property
    def last_reward(self) -> float:
        """Mean top-beam reward over the training data in the last epoch (0 before any)."""
        return self.log.mean_reward_per_epoch[-1] if self.log.mean_reward_per_epoch else 0.0

    def run_epoch(self) -> None:
        """One pass over the demonstrations in a random order, minibatch by minibatch."""
        model, config, demos, memory, rewards = self.model, self.config, self.demos, self.memory, self.rewards
        started = time.monotonic()
        order = self.rng.permutation(len(demos))
        total_reward, hits = 0.0, 0
        model.train()
        for lo in range(0, len(order), config.batch):
            idx = [int(i) for i in order[lo:lo + config.batch]]
            words_t, lengths = pad_batch([self.word_ids[i] for i in idx])
            states, mask = model.encode(words_t, lengths)
            beams = model.beam_search(states.detach(), mask, config.beam, config.epsilon, self.rng)
            programs: list[tuple[int, ...]] = []
            owners: list[int] = []
            weights: list[float] = []
            for row, (i, result) in enumerate(zip(idx, beams)):
                found = {p: rewards.reward(p, demos[i]) for p in result.programs}
                if result.programs:
                    total_reward += found[result.programs[0]]
                for p, r in found.items():
                    if r > 0:
                        memory[i][p] = r
                if len(memory[i]) > config.memory:  # keep the best rewarded, then the shortest
                    kept = sorted(memory[i].items(), key=lambda kv: (-kv[1], len(kv[0])))[:config.memory]
                    memory[i] = dict(kept)
                if memory[i]:
                    hits += 1
                for p, r in memory[i].items():
                    programs.append(p)
                    owners.append(row)
                    weights.append(r)
            if not programs:
                continue
            logp = model.program_log_probs(states, mask, owners, programs)
            owner_t = torch.tensor(owners)
            with torch.no_grad():
                score = torch.log(torch.tensor(weights)) + config.beta * logp
                norm = torch.full((len(idx),), float('-inf')).scatter_reduce(
                    0, owner_t, score, reduce='amax', include_self=True)
                q = torch.exp(score - norm[owner_t])
                total = torch.zeros(len(idx)).index_add(0, owner_t, q)
                q = q / total[owner_t]
            loss = -(q * logp).sum() / len(idx)
            self.optimiser.zero_grad()
            loss.backward()
            torch.nn.utils.clip_grad_norm_(model.parameters(), 5.0)
            self.optimiser.step()
        log = self.log
        log.epochs_run += 1
        log.seconds += time.monotonic() - started
        log.mean_reward_per_epoch.append(total_reward / max(1, len(demos)))
        log.hit_rate_per_epoch.append(hits / max(1, len(demos)))
        log.reward_cache_entries = len(rewards._first)
        model.eval()


def train_parser(model: SemanticParser, words: WordVocabulary, demos: Sequence[Demonstration],
                 landmark_map: LandmarkMap, config: TrainingConfig = TrainingConfig(),
                 progress: Optional[Callable[[str], None]] = None) -> TrainingLog:
    """Train ``model`` in place on (instruction, trajectory) pairs; returns the log."""
    trainer = ParserTrainer(model, words, demos, landmark_map, config)
    started = time.monotonic()
    for epoch in range(config.epochs):
        if time.monotonic() - started > config.time_limit_s:
            break
        trainer.run_epoch()
        if progress:
            progress(epoch_message(trainer, started))
    return trainer.log


def epoch_message(trainer: ParserTrainer, started: float) -> str:
    """Return the progress line after an epoch."""
    log = trainer.log
    return (f'seed {trainer.config.seed} epoch {log.epochs_run}: mean top-beam reward '
            f'{log.mean_reward_per_epoch[-1]:.3f}, examples with a rewarded program '
            f'{log.hit_rate_per_epoch[-1]:.3f}, {time.monotonic() - started:.0f} s')


def train_baseline(baseline: GoalBaseline, words: WordVocabulary, demos: Sequence[Demonstration],
                   epochs: int = 60, seed: int = 0, learning_rate: float = 1e-3) -> None:
    """Train the final-landmark MLP with cross-entropy on the demonstrations' last landmarks."""
    torch.manual_seed(seed)
    rng = np.random.default_rng(seed)
    x = baseline.bag_of_words(encode_instructions(words, demos))
    y = torch.tensor([d.path[-1] for d in demos], dtype=torch.long)
    optimiser = torch.optim.Adam(baseline.parameters(), lr=learning_rate)
    baseline.train()
    for _ in range(epochs):
        order = torch.from_numpy(rng.permutation(len(demos)))
        for lo in range(0, len(order), 8):
            b = order[lo:lo + 8]
            loss = torch.nn.functional.cross_entropy(baseline(x[b]), y[b])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
    baseline.eval()


def new_parser(words: WordVocabulary, out_vocab: OutputVocabulary,
               config: ParserConfig = ParserConfig(), seed: int = 0,
               names: Optional[Sequence[str]] = None, name_match: Optional[np.ndarray] = None
               ) -> SemanticParser:
    """Build a freshly initialised parser (seeded).

    For the copy scores: ``name_match`` if given (see :func:`parser_name_match`; several
    seeds of one map share it), else the matrix of ``names``, the landmarks' names as
    written in the map (default: the propositions with spaces for underscores).
    """
    torch.manual_seed(seed)
    if config.lexical_copy and name_match is None:
        name_match = parser_name_match(words, out_vocab, names)
    return SemanticParser(words.size, out_vocab, config, name_match if config.lexical_copy else None)


def parser_name_match(words: WordVocabulary, out_vocab: OutputVocabulary,
                      names: Optional[Sequence[str]] = None) -> np.ndarray:
    """Return the copy scores' name-match matrix (``lexicon.name_match_matrix``) for a vocabulary and map."""
    if names is None:
        names = [p.replace('_', ' ') for p in out_vocab.props]
    return name_match_matrix(words.words, names, tokenize)

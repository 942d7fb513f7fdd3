"""Train and evaluate a parser for one city of an osm-trajectories folder (what the CLI runs)."""
from __future__ import annotations

import dataclasses
import time
from typing import Callable, Optional

import torch

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.language.learned.bundle import ParserBundle
from ltl_instruct.core.language.learned.data import load_city, split_train_test
from ltl_instruct.core.language.learned.evaluation import evaluate
from ltl_instruct.core.language.learned.model import GoalBaseline, ParserConfig, WordVocabulary
from ltl_instruct.core.language.learned.programs import OutputVocabulary
from ltl_instruct.core.language.learned.training import (
    ParserTrainer, RewardCache, TrainingConfig, epoch_message, new_parser, parser_name_match, train_baseline,
)


# Share of the training time budget that seed probing may use.
PROBE_SHARE = 0.5


def train_city(data_dir: str, city: str, config: TrainingConfig = TrainingConfig(),
               parser_config: ParserConfig = ParserConfig(), threads: int = 2,
               progress: Optional[Callable[[str], None]] = None, restarts: int = 4,
               probe_epochs: int = 4) -> ParserBundle:
    """Train the parser and the baseline on the city's training split; returns the bundle.

    Training on trajectories alone sometimes settles on spurious programs, and the
    run's own training reward shows it, though only after several epochs (the rewards
    of good and stuck seeds are alike for the first three or four). So seeds are
    chosen by successive halving: ``restarts`` parsers (seeds ``seed, seed + 1, ...``)
    are trained ``probe_epochs`` epochs each, the better half by mean top-beam training
    reward in its last epoch is trained ``probe_epochs`` more, and so on until one is
    left, which is trained on to ``config.epochs`` (all within ``config.time_limit_s``; the
    halving rounds stop at ``PROBE_SHARE`` of it and keep the best seed so far).
    No test data is used to choose. The seeds share one reward cache.
    """
    if restarts < 1:
        raise InvalidInputError(f'restarts must be at least 1, got {restarts}')
    if probe_epochs < 0:
        raise InvalidInputError(f'probe_epochs must be at least 0, got {probe_epochs}')
    torch.set_num_threads(max(1, threads))
    started = time.monotonic()
    data = load_city(data_dir, city)
    train, test = split_train_test(data)
    lmap = data.landmark_map(train)
    # the landmark names' words are in the vocabulary too, so that the copy scores know them
    words = WordVocabulary.build([d.instruction for d in train] + list(lmap.names))
    out_vocab = OutputVocabulary(lmap.props)
    rewards = RewardCache(out_vocab, lmap)
    match = parser_name_match(words, out_vocab, lmap.names) if parser_config.lexical_copy else None
    alive = []
    for r in range(restarts if probe_epochs > 0 else 1):
        run_config = dataclasses.replace(config, seed=config.seed + r)
        parser = new_parser(words, out_vocab, parser_config, run_config.seed, name_match=match)
        alive.append(ParserTrainer(parser, words, train, lmap, run_config, rewards))

    def train_to(trainer: ParserTrainer, epochs: int, deadline: float) -> None:
        while trainer.log.epochs_run < min(epochs, config.epochs) and time.monotonic() - started <= deadline:
            trainer.run_epoch()
            if progress:
                progress(epoch_message(trainer, started))

    # Probing may take at most half the time budget: on a loaded machine epochs slow down,
    # and a choice among half-trained seeds is worth less than training the chosen one on.
    probe_deadline = PROBE_SHARE * config.time_limit_s
    rounds: list[dict[int, float]] = []
    target = 0
    while len(alive) > 1:
        target += probe_epochs
        for trainer in alive:
            train_to(trainer, target, probe_deadline)
        rounds.append({t.config.seed: t.last_reward for t in alive})
        ranked = sorted(alive, key=lambda t: (-t.last_reward, t.config.seed))
        out_of_time = time.monotonic() - started > probe_deadline
        alive = ranked[:1] if out_of_time else ranked[:(len(alive) + 1) // 2]
    chosen = alive[0]
    train_to(chosen, config.epochs, config.time_limit_s)
    baseline = GoalBaseline(words.size, lmap.num_landmarks)
    train_baseline(baseline, words, train, config.baseline_epochs, config.seed)
    info = {'city': city, 'train_instructions': len(train), 'test_instructions': len(test),
            'train_trajectories': len({d.path for d in train}),
            'test_trajectories': len({d.path for d in test}),
            'skipped_rows': data.skipped_rows, 'training': chosen.log.to_dict(),
            'training_config': dict(config.__dict__), 'restarts': restarts if probe_epochs > 0 else 1,
            'probe_epochs': probe_epochs, 'chosen_seed': chosen.config.seed,
            'probe_rounds': [{str(k): v for k, v in r.items()} for r in rounds],
            'total_seconds': time.monotonic() - started}
    return ParserBundle(lmap, words, chosen.model, baseline, info)


def evaluate_city(data_dir: str, city: str, bundle: ParserBundle, threads: int = 2) -> dict:
    """Scores on the city's fixed test split (see ``data.split_train_test``)."""
    torch.set_num_threads(max(1, threads))
    data = load_city(data_dir, city)
    _, test = split_train_test(data)
    started = time.monotonic()
    result = evaluate(bundle, test)
    result.update({'city': city, 'test_instructions': len(test), 'skipped_rows': data.skipped_rows,
                   'seconds': time.monotonic() - started})
    return result

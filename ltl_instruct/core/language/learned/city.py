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
    TrainingConfig, new_parser, train_baseline, train_parser,
)


def train_city(data_dir: str, city: str, config: TrainingConfig = TrainingConfig(),
               parser_config: ParserConfig = ParserConfig(), threads: int = 2,
               progress: Optional[Callable[[str], None]] = None, restarts: int = 2) -> ParserBundle:
    """Train the parser and the baseline on the city's training split; returns the bundle.

    With ``restarts`` > 1, the parser is trained from seeds ``seed, seed + 1, ...``
    (each within ``time_limit_s / restarts``) and the run with the highest mean
    top-beam reward on the training data in its last epoch is kept: training on
    trajectories alone sometimes settles on spurious programs, and its own reward
    shows it (no test data is used to choose).
    """
    if restarts < 1:
        raise InvalidInputError(f'restarts must be at least 1, got {restarts}')
    torch.set_num_threads(max(1, threads))
    started = time.monotonic()
    data = load_city(data_dir, city)
    train, test = split_train_test(data)
    lmap = data.landmark_map(train)
    words = WordVocabulary.build([d.instruction for d in train])
    runs = []
    for r in range(restarts):
        run_config = dataclasses.replace(config, seed=config.seed + r,
                                         time_limit_s=config.time_limit_s / restarts)
        parser = new_parser(words, OutputVocabulary(lmap.props), parser_config, run_config.seed)
        log = train_parser(parser, words, train, lmap, run_config, progress)
        final = log.mean_reward_per_epoch[-1] if log.mean_reward_per_epoch else 0.0
        runs.append((final, r, parser, log))
    final, best, parser, log = max(runs, key=lambda run: (run[0], -run[1]))
    baseline = GoalBaseline(words.size, lmap.num_landmarks)
    train_baseline(baseline, words, train, config.baseline_epochs, config.seed)
    info = {'city': city, 'train_instructions': len(train), 'test_instructions': len(test),
            'train_trajectories': len({d.path for d in train}),
            'test_trajectories': len({d.path for d in test}),
            'skipped_rows': data.skipped_rows, 'training': log.to_dict(),
            'training_config': dict(config.__dict__), 'restarts': restarts,
            'chosen_seed': config.seed + best,
            'final_reward_per_restart': [run[0] for run in runs],
            'total_seconds': time.monotonic() - started}
    return ParserBundle(lmap, words, parser, baseline, info)


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

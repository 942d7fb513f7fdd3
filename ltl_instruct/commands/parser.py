"""``ltl-instruct parser train|eval``: a semantic parser learned from trajectories alone (issue 7).

``parser train --city NAME --data DIR --out MODEL`` trains the parser and the
final-landmark baseline on the city's training split and writes one model file;
``parser eval --city NAME --data DIR --model MODEL [--json]`` scores both on the
city's fixed test split (100 trajectories, chosen by hash; see
``core/language/learned/data.py``). DIR is an osm-trajectories folder
(``instructions/<city>.tsv``, ``maps/<city>.json``).
"""
from __future__ import annotations

import argparse
import json
import sys

from ltl_instruct.core.errors import InvalidInputError

HELP = 'train or evaluate a semantic parser learned from trajectories'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the sub-commands ``train`` and ``eval``."""
    sub = parser.add_subparsers(dest='action', metavar='ACTION', required=True)
    train = sub.add_parser('train', help='train a parser (and the baseline) for one city map')
    eval_ = sub.add_parser('eval', help='score a trained parser and the baseline on the test split')
    for p in (train, eval_):
        p.add_argument('--city', required=True,
                       help='city name: DIR/instructions/NAME.tsv, DIR/maps/NAME.json')
        p.add_argument('--data', required=True, help='osm-trajectories folder')
        p.add_argument('--threads', type=int, default=2, help='torch CPU threads (default 2)')
    train.add_argument('--out', required=True, help='model file to write')
    train.add_argument('--epochs', type=int, default=None,
                       help='training epochs (default from TrainingConfig)')
    train.add_argument('--time-limit', type=float, default=None,
                       help='seconds after which no new epoch starts (default 1080)')
    train.add_argument('--seed', type=int, default=0, help='random seed (default 0)')
    train.add_argument('--restarts', type=int, default=4,
                       help='probe this many seeds, train on the one with the best training reward '
                            '(default 4)')
    train.add_argument('--probe-epochs', type=int, default=4,
                       help='epochs per round of successive halving over the seeds (default 4; '
                            '0: one seed, no probing)')
    train.add_argument('--quiet', action='store_true', help='no per-epoch progress')
    eval_.add_argument('--model', required=True, help='model file written by "parser train"')
    eval_.add_argument('--json', action='store_true', help='print one JSON object')


def _train(args: argparse.Namespace) -> int:
    from ltl_instruct.core.language.learned.city import train_city
    from ltl_instruct.core.language.learned.training import TrainingConfig
    overrides: dict = {'seed': args.seed}
    if args.epochs is not None:
        if args.epochs < 1:
            raise InvalidInputError('--epochs must be at least 1')
        overrides['epochs'] = args.epochs
    if args.time_limit is not None:
        if not args.time_limit > 0:
            raise InvalidInputError('--time-limit must be positive')
        overrides['time_limit_s'] = args.time_limit
    config = TrainingConfig(**overrides)
    progress = None if args.quiet else (lambda line: print(line, file=sys.stderr, flush=True))
    bundle = train_city(args.data, args.city, config, threads=args.threads, progress=progress,
                        restarts=args.restarts, probe_epochs=args.probe_epochs)
    bundle.save(args.out)
    info = bundle.info
    print(f"trained {args.city}: {info['train_instructions']} instructions "
          f"({info['train_trajectories']} trajectories; {info['skipped_rows']} rows skipped), "
          f"{info['training']['epochs_run']} epochs in {info['total_seconds']:.0f} s -> {args.out}")
    return 0


def _eval(args: argparse.Namespace) -> int:
    from ltl_instruct.core.language.learned.bundle import ParserBundle
    from ltl_instruct.core.language.learned.city import evaluate_city
    bundle = ParserBundle.load(args.model)
    if bundle.landmark_map.city != args.city:
        raise InvalidInputError(f'the model was trained for {bundle.landmark_map.city!r}, not {args.city!r}')
    result = evaluate_city(args.data, args.city, bundle, threads=args.threads)
    if args.json:
        print(json.dumps(result, indent=2))
        return 0
    print(f"{args.city}: {result['test_instructions']} test instructions over "
          f"{result['trajectories']} held-out trajectories ({result['skipped_rows']} rows skipped)")
    print(f"{'':10s}{'goal acc':>10s}{'precision':>11s}{'recall':>9s}{'path acc':>10s}{'edit dist':>11s}")
    for name in ('model', 'baseline'):
        r = result[name]
        print(f"{name:10s}{r['goal_accuracy']:10.3f}{r['precision']:11.3f}{r['recall']:9.3f}"
              f"{r['path_accuracy']:10.3f}{r['edit_distance']:11.3f}")
    return 0


def run(args: argparse.Namespace) -> int:
    """Run ``train`` or ``eval``."""
    if args.threads < 1:
        raise InvalidInputError('--threads must be at least 1')
    return _train(args) if args.action == 'train' else _eval(args)

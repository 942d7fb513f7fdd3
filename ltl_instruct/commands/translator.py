"""``ltl-instruct translator train``: regenerate the data and retrain the learned translator.

``translator train --out DIR`` generates the training examples, adds the training splits of
the public sets found in ``../shared/datasets`` (or ``LTL_INSTRUCT_DATASETS``), trains the
tagger and decoder on the frozen MiniLM encoder and writes the bundle (``config.json``,
``weights.pt``) to DIR. The bundle shipped in ``ltl_instruct/data/translator`` comes from
this command with its defaults.
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

HELP = 'train the learned translator (tagger and decoder) from generated and public data'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the sub-command ``train``."""
    sub = parser.add_subparsers(dest='action', metavar='ACTION', required=True)
    train = sub.add_parser('train', help='regenerate the data and train; write the bundle to --out')
    train.add_argument('--out', required=True, help='folder to write config.json and weights.pt to')
    train.add_argument('--generated', type=int, default=None, help='generated examples (default 40000)')
    train.add_argument('--epochs', type=int, default=None, help='epochs (default 6)')
    train.add_argument('--sets', default=None,
                       help='public sets whose training splits are added, comma-separated (default all; '
                            '"none" for none)')
    train.add_argument('--public-repeat', type=int, default=None,
                       help='times each public training example is used per epoch (default 2)')
    train.add_argument('--time-limit', type=float, default=None,
                       help='seconds of training, after encoding (default 3600)')
    train.add_argument('--encoder-lr', type=float, default=None,
                       help='fine-tune the encoder layers at this learning rate (default 0: frozen; the '
                            'bundle then also carries encoder.pt)')
    train.add_argument('--seed', type=int, default=0, help='random seed (default 0)')
    train.add_argument('--threads', type=int, default=2, help='torch CPU threads (default 2)')
    train.add_argument('--json', action='store_true', help='print the training facts as JSON')


def run(args: argparse.Namespace) -> int:
    """Train and write the bundle."""
    from dataclasses import replace

    from ltl_instruct.core.language.neural.training import TrainConfig, train
    cfg = TrainConfig(seed=args.seed, threads=args.threads)
    if args.generated is not None:
        cfg = replace(cfg, generated=args.generated)
    if args.epochs is not None:
        cfg = replace(cfg, epochs=args.epochs)
    if args.public_repeat is not None:
        cfg = replace(cfg, public_repeat=args.public_repeat)
    if args.time_limit is not None:
        cfg = replace(cfg, time_budget_s=args.time_limit)
    if args.encoder_lr is not None:
        cfg = replace(cfg, encoder_lr=args.encoder_lr)
    if args.sets is not None:
        cfg = replace(cfg, public_sets=() if args.sets == 'none' else tuple(args.sets.split(',')))
    facts = train(cfg, Path(args.out))
    if args.json:
        print(json.dumps(facts, indent=2))
    else:
        print(f'wrote {args.out}: {facts["examples"]} examples, {facts["seconds"]:.0f} s of training')
    return 0

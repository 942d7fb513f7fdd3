"""Frozen against fine-tuned encoder for the learned translator, at a small, equal budget.

Run: ``.venv/bin/python -m bench.translator_finetune [--generated N] [--epochs E] [--sets cleanup,drone]``.
Both variants train the same tagger and decoder on the same examples (generated ones plus the
public training splits of ``--sets``) for the same epochs; the fine-tuned one also updates the
MiniLM encoder's layers (learning rate ``--encoder-lr``), through the trainer's own
fine-tuning path (``training.fit`` with the encoder, as ``translator train --encoder-lr``). Each
is scored on the test splits of ``--sets`` (temporal alignment, as ``bench.translation_public``),
with its training seconds. The shipped bundle uses the frozen encoder: this bench is the
measurement behind that choice.
"""
from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from typing import Sequence

import torch

from ltl_instruct.core.language.evaluation import evaluate
from ltl_instruct.core.language.neural import public
from ltl_instruct.core.language.neural.encoder import WordPieces, load_encoder, packaged_model_dir
from ltl_instruct.core.language.neural.generator import generate
from ltl_instruct.core.language.neural.model import NetConfig, TranslatorNet
from ltl_instruct.core.language.neural.training import TrainConfig, encode_examples, fit, piece_examples
from ltl_instruct.core.language.neural.translator import NeuralTranslator


def score(translator: NeuralTranslator, sets: Sequence[str]) -> dict[str, float]:
    """Temporal alignment on each set's test split."""
    out = {}
    for name in sets:
        ds = public.read_split(name, 'test')
        translator.landmarks = ds.landmarks
        out[name] = evaluate(translator, ds.examples).summary()['temporal_alignment']
    return out


def main(argv: list[str]) -> int:
    """Train both variants and print their scores and times."""
    ap = argparse.ArgumentParser(prog='bench.translator_finetune', description=__doc__)
    ap.add_argument('--generated', type=int, default=3000)
    ap.add_argument('--epochs', type=int, default=2)
    ap.add_argument('--sets', default='cleanup,drone')
    ap.add_argument('--encoder-lr', type=float, default=3e-5)
    args = ap.parse_args(argv)
    if public.datasets_root() is None:
        print('public data sets not found', file=sys.stderr)
        return 1
    torch.manual_seed(0)
    torch.set_num_threads(2)
    sets = args.sets.split(',')
    examples = generate(args.generated, seed=0)
    for name in sets:
        examples += public.tagged_examples(name)[0]
    model_dir = packaged_model_dir()
    pieces = WordPieces(model_dir)
    cfg = TrainConfig(epochs=args.epochs, batch=32)
    frozen_encoder = load_encoder(model_dir)
    started = time.perf_counter()
    data = encode_examples(examples, frozen_encoder, pieces, log=lambda s: None)
    frozen_net = TranslatorNet(NetConfig())
    fit(frozen_net, data, cfg, log=lambda s: None)
    frozen_s = time.perf_counter() - started
    torch.manual_seed(0)
    tuned_encoder, tuned_net = load_encoder(model_dir), TranslatorNet(NetConfig())
    started = time.perf_counter()
    fit(tuned_net, piece_examples(examples, pieces), replace(cfg, encoder_lr=args.encoder_lr),
        log=lambda s: None, encoder=tuned_encoder)
    tuned_s = time.perf_counter() - started
    for label, net, enc, secs in (('frozen', frozen_net, frozen_encoder, frozen_s),
                                  ('fine-tuned', tuned_net, tuned_encoder, tuned_s)):
        scores = score(NeuralTranslator.from_parts(net, enc, pieces), sets)
        print(f'{label:10s} {len(examples)} examples, {args.epochs} epochs, {secs:.0f} s of training; '
              + '  '.join(f'{k} temporal alignment {v:.3f}' for k, v in scores.items()), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

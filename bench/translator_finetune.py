"""Frozen against fine-tuned encoder for the learned translator, at a small, equal budget.

Run: ``.venv/bin/python -m bench.translator_finetune [--generated N] [--epochs E] [--sets cleanup,drone]``.
Both variants train the same tagger and decoder on the same examples (generated ones plus the
public training splits of ``--sets``) for the same epochs; the fine-tuned one also updates the
MiniLM encoder (learning rate ``--encoder-lr``). Each is scored on the test splits of ``--sets``
(temporal alignment, as ``bench.translation_public``), with its training seconds. The shipped
bundle uses the frozen encoder: this bench is the measurement behind that choice.
"""
from __future__ import annotations

import argparse
import random
import sys
import time
from typing import Sequence

import torch
from torch import nn

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.evaluation import evaluate
from ltl_instruct.core.language.neural import public
from ltl_instruct.core.language.neural.encoder import WordPieces, load_encoder, pad_batch, packaged_model_dir
from ltl_instruct.core.language.neural.examples import TaggedExample
from ltl_instruct.core.language.neural.features import example_tags
from ltl_instruct.core.language.neural.generator import generate
from ltl_instruct.core.language.neural.grammar import MAX_SLOTS, TOKEN_ID
from ltl_instruct.core.language.neural.macros import lifted_tokens
from ltl_instruct.core.language.neural.model import NetConfig, TranslatorNet
from ltl_instruct.core.language.neural.training import MAX_TARGET, TrainConfig, encode_examples, fit, losses
from ltl_instruct.core.language.neural.translator import NeuralTranslator
from ltl_instruct.core.spec import parse_formula


def _fits(ex: TaggedExample) -> bool:
    """The same filter as ``encode_examples``: a lifted formula the decoder can write."""
    try:
        return len(lifted_tokens(parse_formula(ex.lifted))) <= MAX_TARGET and len(ex.slots) <= MAX_SLOTS
    except LtlInstructError:
        return False


def finetune(net: TranslatorNet, encoder: nn.Module, pieces: WordPieces, examples: Sequence[TaggedExample],
             epochs: int, batch: int, lr: float, encoder_lr: float) -> float:
    """Train networks and encoder together; return the seconds spent."""
    rng = random.Random(0)
    opt = torch.optim.Adam([{'params': net.parameters(), 'lr': lr},
                            {'params': encoder.parameters(), 'lr': encoder_lr}])
    started = time.perf_counter()
    data = [ex for ex in examples if _fits(ex)]
    for _ in range(epochs):
        net.train()
        encoder.train()
        order = sorted(data, key=lambda ex: len(ex.text) + rng.random() * 20)
        chunks = [order[k:k + batch] for k in range(0, len(order), batch)]
        rng.shuffle(chunks)
        for chunk in chunks:
            ps = [pieces(ex.text) for ex in chunk]
            ids, mask = pad_batch(ps)
            h = encoder(ids, mask)
            gold = [example_tags(ex, p) for ex, p in zip(chunk, ps)]
            pad = nn.utils.rnn.pad_sequence
            tags = pad([torch.tensor(t) for t, _ in gold], batch_first=True, padding_value=-100)
            slots = pad([torch.tensor(s) for _, s in gold], batch_first=True, padding_value=0)
            targets = pad([torch.tensor([TOKEN_ID[t] for t in lifted_tokens(parse_formula(ex.lifted))])
                           for ex in chunk], batch_first=True, padding_value=-100)
            tag_loss, dec_loss = losses(net, h, mask, tags, slots, targets)
            opt.zero_grad()
            (tag_loss + dec_loss).backward()
            nn.utils.clip_grad_norm_(list(net.parameters()) + list(encoder.parameters()), 5.0)
            opt.step()
    return time.perf_counter() - started


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
    tuned_s = finetune(tuned_net, tuned_encoder, pieces, examples, args.epochs, 32, cfg.lr, args.encoder_lr)
    for label, net, enc, secs in (('frozen', frozen_net, frozen_encoder, frozen_s),
                                  ('fine-tuned', tuned_net, tuned_encoder, tuned_s)):
        scores = score(NeuralTranslator.from_parts(net, enc, pieces), sets)
        print(f'{label:10s} {len(examples)} examples, {args.epochs} epochs, {secs:.0f} s of training; '
              + '  '.join(f'{k} temporal alignment {v:.3f}' for k, v in scores.items()), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

"""Training the tagger and decoder: data, frozen-encoder features, the loop, and the bundle.

``train(TrainConfig(...), out_dir)`` builds the training set (generated examples plus the
training splits of the public sets, never a test split), runs the frozen encoder once over
every text, trains both networks together (cross-entropy on tags + on the prefix tokens,
teacher forcing), and writes a bundle: ``config.json`` (sizes, what it was trained on, how
long) and ``weights.pt`` (the two networks' state dict). The encoder's own weights are not in
the bundle: they come from the packaged model.
"""
from __future__ import annotations

import json
import random
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable, Optional, Sequence

import torch
from torch import nn

from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
from ltl_instruct.core.language.neural.encoder import (
    BertEncoder, WordPieces, load_encoder, pad_batch, packaged_model_dir,
)
from ltl_instruct.core.language.neural.examples import TaggedExample
from ltl_instruct.core.language.neural.features import CONVENTIONS, convention_vector, example_tags
from ltl_instruct.core.language.neural.grammar import MAX_SLOTS, TOKEN_ID, TOKENS
from ltl_instruct.core.language.neural.macros import lifted_tokens
from ltl_instruct.core.language.neural.model import NetConfig, TranslatorNet
from ltl_instruct.core.spec import parse_formula

BUNDLE_CONFIG, BUNDLE_WEIGHTS = 'config.json', 'weights.pt'
MAX_TARGET = 48


@dataclass(frozen=True)
class TrainConfig:
    """What to train on and how long.

    Attributes
    ----------
    generated: number of generated examples.
    public_sets: public sets whose training splits are added (names of ``public.SETS``).
    public_repeat: how many times each public example is repeated (they are few).
    epochs, batch, lr, seed: the optimisation.
    threads: torch threads.
    time_budget_s: training stops after this many seconds (the epoch in progress ends early).
    """

    generated: int = 40000
    public_sets: tuple[str, ...] = ('drone', 'cleanup', 'pick_and_place', 'lifted', 'providence',
                                    'cleanup_l2l')
    public_repeat: int = 2
    epochs: int = 6
    batch: int = 64
    lr: float = 2e-3
    seed: int = 0
    threads: int = 2
    time_budget_s: float = 60 * 60
    net: NetConfig = field(default_factory=lambda: NetConfig(conventions=len(CONVENTIONS)))


@dataclass
class Encoded:
    """One example as tensors: encoder states, tags, slot numbers, target token ids."""

    states: torch.Tensor      # (T, E) float16
    tags: torch.Tensor        # (T,)
    slots: torch.Tensor       # (T,)
    target: torch.Tensor      # (L,)
    conv: torch.Tensor        # (C,) the conventions its formula follows (features.CONVENTIONS)


def training_examples(cfg: TrainConfig, log: Callable[[str], None] = print) -> list[TaggedExample]:
    """Return generated examples plus the public training splits (repeated ``public_repeat`` times)."""
    from ltl_instruct.core.language.neural.generator import generate
    from ltl_instruct.core.language.neural import public
    examples = list(generate(cfg.generated, seed=cfg.seed))
    log(f'generated {len(examples)} examples')
    for name in cfg.public_sets:
        try:
            got, skipped = public.tagged_examples(name)
        except LtlInstructError as e:
            log(f'public set {name} not used: {e}')
            continue
        log(f'public set {name}: {len(got)} training examples ({skipped} skipped)')
        examples.extend(got * cfg.public_repeat)
    return examples


def encode_examples(examples: Sequence[TaggedExample], encoder: BertEncoder, pieces_of: WordPieces,
                    log: Callable[[str], None] = print, batch: int = 64) -> list[Encoded]:
    """Run the frozen encoder once over every distinct text; drop examples that do not fit."""
    texts = sorted({ex.text for ex in examples}, key=len)
    pieces = dict(zip(texts, pieces_of.batch(texts)))
    states: dict[str, torch.Tensor] = {}
    started = time.perf_counter()
    with torch.inference_mode():
        for i in range(0, len(texts), batch):
            chunk = texts[i:i + batch]
            ids, mask = pad_batch([pieces[t] for t in chunk])
            h = encoder(ids, mask)
            for j, t in enumerate(chunk):
                states[t] = h[j, :int(mask[j].sum())].to(torch.float16).clone()
    log(f'encoded {len(texts)} texts in {time.perf_counter() - started:.0f} s')
    out = []
    for ex in examples:
        try:
            tokens = lifted_tokens(parse_formula(ex.lifted))
        except LtlInstructError:
            continue
        if len(tokens) > MAX_TARGET or len(ex.slots) > MAX_SLOTS:
            continue
        tags, slots = example_tags(ex, pieces[ex.text])
        out.append(Encoded(states[ex.text], torch.tensor(tags), torch.tensor(slots),
                           torch.tensor([TOKEN_ID[t] for t in tokens]),
                           torch.tensor(convention_vector(dict(ex.conventions)))))
    return out


def _pad(seqs: Sequence[torch.Tensor], value: float) -> torch.Tensor:
    return nn.utils.rnn.pad_sequence(list(seqs), batch_first=True, padding_value=value)


def batch_tensors(items: Sequence[Encoded]) -> tuple[torch.Tensor, ...]:
    """Pad a batch into ``states, mask, tags, slots, targets, conventions`` (padding ignored by losses)."""
    h = _pad([e.states.float() for e in items], 0.0)
    mask = _pad([torch.ones(len(e.tags), dtype=torch.long) for e in items], 0)
    tags = _pad([e.tags for e in items], -100)
    slots = _pad([e.slots for e in items], 0)
    targets = _pad([e.target for e in items], -100)
    return h, mask, tags, slots, targets, torch.stack([e.conv for e in items])


def _batches(data: Sequence[Encoded], size: int, rng: random.Random) -> list[list[Encoded]]:
    """Batches of similar length (less padding), in random order."""
    order = sorted(range(len(data)), key=lambda i: (len(data[i].tags) + rng.random() * 4))
    batches = [[data[i] for i in order[k:k + size]] for k in range(0, len(order), size)]
    rng.shuffle(batches)
    return batches


def loss_of(net: TranslatorNet, batch: Sequence[Encoded]) -> tuple[torch.Tensor, torch.Tensor]:
    """Tagging and decoding losses of one batch."""
    return losses(net, *batch_tensors(batch))


def losses(net: TranslatorNet, h: torch.Tensor, mask: torch.Tensor, tags: torch.Tensor, slots: torch.Tensor,
           targets: torch.Tensor, conv: Optional[torch.Tensor] = None) -> tuple[torch.Tensor, torch.Tensor]:
    """Tagging and decoding losses from encoder states (frozen or being fine-tuned)."""
    ce = nn.functional.cross_entropy
    tag_loss = ce(net.tagger(h).reshape(-1, 3), tags.reshape(-1), ignore_index=-100)
    logits = net.decoder(h, mask, slots, targets.clamp(min=0), conv)
    dec_loss = ce(logits.reshape(-1, logits.shape[-1]), targets.reshape(-1), ignore_index=-100)
    return tag_loss, dec_loss


def fit(net: TranslatorNet, data: Sequence[Encoded], cfg: TrainConfig,
        log: Callable[[str], None] = print,
        after_epoch: Optional[Callable[[int, dict[str, float]], None]] = None) -> dict[str, float]:
    """Train both networks; returns the last epoch's mean losses and the seconds spent.

    ``after_epoch(epoch, stats)`` runs after each epoch (the trainer saves the bundle there, so
    a run cut short still leaves its last finished epoch).
    """
    rng = random.Random(cfg.seed)
    opt = torch.optim.Adam(net.parameters(), lr=cfg.lr)
    started = time.perf_counter()
    stats = {'tag_loss': 0.0, 'decoder_loss': 0.0}
    for epoch in range(cfg.epochs):
        net.train()
        lr = cfg.lr * (0.5 if epoch >= cfg.epochs * 2 // 3 else 1.0)
        for group in opt.param_groups:
            group['lr'] = lr
        totals, n = [0.0, 0.0], 0
        for batch in _batches(data, cfg.batch, rng):
            tag_loss, dec_loss = loss_of(net, batch)
            opt.zero_grad()
            (tag_loss + dec_loss).backward()
            nn.utils.clip_grad_norm_(net.parameters(), 5.0)
            opt.step()
            totals[0] += float(tag_loss.detach())
            totals[1] += float(dec_loss.detach())
            n += 1
            if time.perf_counter() - started > cfg.time_budget_s:
                break
        stats = {'tag_loss': totals[0] / max(n, 1), 'decoder_loss': totals[1] / max(n, 1)}
        if after_epoch is not None:
            net.eval()
            after_epoch(epoch + 1, stats)
        log(f'epoch {epoch + 1}: tag loss {stats["tag_loss"]:.4f}, decoder loss {stats["decoder_loss"]:.4f}, '
            f'{time.perf_counter() - started:.0f} s')
        if time.perf_counter() - started > cfg.time_budget_s:
            log('time budget reached')
            break
    stats['seconds'] = time.perf_counter() - started
    net.eval()
    return stats


def save_bundle(net: TranslatorNet, out_dir: Path, facts: dict) -> None:
    """Write ``config.json`` and ``weights.pt``."""
    out_dir.mkdir(parents=True, exist_ok=True)
    torch.save({k: v.half() if v.is_floating_point() else v for k, v in net.state_dict().items()},
               out_dir / BUNDLE_WEIGHTS)
    config = {'net': net.config.to_dict(), 'tokens': list(TOKENS), **facts}
    (out_dir / BUNDLE_CONFIG).write_text(json.dumps(config, indent=2) + '\n', encoding='utf-8')


def load_bundle(bundle: Path) -> TranslatorNet:
    """Read the networks of a bundle written by :func:`save_bundle` (float32, eval mode)."""
    config = json.loads((bundle / BUNDLE_CONFIG).read_text(encoding='utf-8'))
    if config.get('tokens') != list(TOKENS):
        raise TranslationError(f'the translator model in {bundle} was trained for another output vocabulary; '
                               f'retrain it with "ltl-instruct translator train"', ErrorCode.MODEL_ERROR)
    net = TranslatorNet(NetConfig(**config['net']))
    state = torch.load(bundle / BUNDLE_WEIGHTS, map_location='cpu', weights_only=True)
    net.load_state_dict({k: v.float() if v.is_floating_point() else v for k, v in state.items()})
    return net.eval()


def train(cfg: TrainConfig, out_dir: Path, encoder_dir: Optional[Path] = None,
          log: Callable[[str], None] = print) -> dict:
    """Build the data, train, write the bundle to ``out_dir``; returns the facts written."""
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    encoder_dir = encoder_dir or packaged_model_dir()
    encoder = load_encoder(encoder_dir)
    examples = training_examples(cfg, log)
    data = encode_examples(examples, encoder, WordPieces(encoder_dir), log)
    log(f'{len(data)} training examples fit the decoder')
    net = TranslatorNet(cfg.net)
    base = {'train_config': {k: v for k, v in asdict(cfg).items() if k != 'net'}, 'examples': len(data)}
    stats = fit(net, data, cfg, log,
                after_epoch=lambda epoch, st: save_bundle(net, out_dir, {**base, 'epochs_done': epoch, **st}))
    facts = {**base, **stats}
    save_bundle(net, out_dir, facts)
    return facts

"""Training the tagger and decoder: data, frozen-encoder features, the loop, and the bundle.

``train(TrainConfig(...), out_dir)`` builds the training set (generated examples plus the
training splits of the public sets, never a test split), runs the frozen encoder once over
every text, trains both networks together (cross-entropy on tags + on the prefix tokens,
teacher forcing), and writes a bundle: ``config.json`` (sizes, what it was trained on, how
long) and ``weights.pt`` (the two networks' state dict). The encoder's own weights come from the
packaged model; with ``encoder_lr > 0`` its layers are fine-tuned with the networks (the encoder
runs in every batch instead of once), and the bundle also carries them, ``encoder.pt`` (float16;
the embeddings stay frozen and are not stored).
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

BUNDLE_CONFIG, BUNDLE_WEIGHTS, BUNDLE_ENCODER = 'config.json', 'weights.pt', 'encoder.pt'
_FROZEN_PARTS = ('word.', 'position.', 'token_type.')   # encoder embeddings, never fine-tuned
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
    encoder_lr: learning rate of the encoder's layers; 0 keeps the encoder frozen.
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
    encoder_lr: float = 0.0
    net: NetConfig = field(default_factory=lambda: NetConfig(conventions=len(CONVENTIONS)))


@dataclass
class Encoded:
    """One example as tensors: encoder states (or, to fine-tune, piece ids), tags, slots, target ids."""

    states: Optional[torch.Tensor]   # (T, E) float16; None when the encoder runs in each batch
    tags: torch.Tensor        # (T,)
    slots: torch.Tensor       # (T,)
    target: torch.Tensor      # (L,)
    conv: torch.Tensor        # (C,) the conventions its formula follows (features.CONVENTIONS)
    ids: Optional[torch.Tensor] = None   # (T,) word-piece ids, when ``states`` is None


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
    return _tensors(examples, pieces, states)


def piece_examples(examples: Sequence[TaggedExample], pieces_of: WordPieces) -> list[Encoded]:
    """Examples as piece ids, for fine-tuning (the encoder runs in each batch); drop those that do not fit."""
    texts = sorted({ex.text for ex in examples}, key=len)
    return _tensors(examples, dict(zip(texts, pieces_of.batch(texts))), None)


def _tensors(examples: Sequence[TaggedExample], pieces: dict, states: Optional[dict[str, torch.Tensor]]
             ) -> list[Encoded]:
    out = []
    for ex in examples:
        try:
            tokens = lifted_tokens(parse_formula(ex.lifted))
        except LtlInstructError:
            continue
        if len(tokens) > MAX_TARGET or len(ex.slots) > MAX_SLOTS:
            continue
        tags, slots = example_tags(ex, pieces[ex.text])
        out.append(Encoded(states[ex.text] if states is not None else None, torch.tensor(tags),
                           torch.tensor(slots), torch.tensor([TOKEN_ID[t] for t in tokens]),
                           torch.tensor(convention_vector(dict(ex.conventions))),
                           None if states is not None else torch.tensor(pieces[ex.text].ids)))
    return out


def _pad(seqs: Sequence[torch.Tensor], value: float) -> torch.Tensor:
    return nn.utils.rnn.pad_sequence(list(seqs), batch_first=True, padding_value=value)


def batch_tensors(items: Sequence[Encoded], encoder: Optional[nn.Module] = None) -> tuple[torch.Tensor, ...]:
    """Pad a batch into ``states, mask, tags, slots, targets, conventions`` (padding ignored by losses).

    With ``encoder`` the states are computed here, from the items' piece ids (fine-tuning).
    """
    mask = _pad([torch.ones(len(e.tags), dtype=torch.long) for e in items], 0)
    if encoder is None:
        h = _pad([e.states.float() for e in items], 0.0)   # type: ignore[union-attr]
    else:
        h = encoder(_pad([e.ids for e in items], 0).long(), mask)   # type: ignore[misc]
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


def loss_of(net: TranslatorNet, batch: Sequence[Encoded], encoder: Optional[nn.Module] = None
            ) -> tuple[torch.Tensor, torch.Tensor]:
    """Tagging and decoding losses of one batch (through ``encoder`` when it is being fine-tuned)."""
    return losses(net, *batch_tensors(batch, encoder))


def tuned_parameters(encoder: nn.Module) -> dict[str, nn.Parameter]:
    """Return the encoder parameters that fine-tuning updates: all but the embeddings."""
    return {k: v for k, v in encoder.named_parameters() if not k.startswith(_FROZEN_PARTS)}


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
        after_epoch: Optional[Callable[[int, dict[str, float]], None]] = None,
        encoder: Optional[nn.Module] = None) -> dict[str, float]:
    """Train both networks (and ``encoder``'s layers, when given); return the last epoch's losses and seconds.

    ``after_epoch(epoch, stats)`` runs after each epoch (the trainer saves the bundle there, so
    a run cut short still leaves its last finished epoch).
    """
    rng = random.Random(cfg.seed)
    groups: list[dict] = [{'params': list(net.parameters()), 'lr': cfg.lr, 'base': cfg.lr}]
    if encoder is not None:
        for p in encoder.parameters():
            p.requires_grad_(False)
        tuned = list(tuned_parameters(encoder).values())
        for p in tuned:
            p.requires_grad_(True)
        groups.append({'params': tuned, 'lr': cfg.encoder_lr, 'base': cfg.encoder_lr})
    opt = torch.optim.Adam(groups)
    trained = [p for g in groups for p in g['params']]
    started = time.perf_counter()
    stats = {'tag_loss': 0.0, 'decoder_loss': 0.0}
    for epoch in range(cfg.epochs):
        net.train()
        if encoder is not None:
            encoder.train()
        for group in opt.param_groups:
            group['lr'] = group['base'] * (0.5 if epoch >= cfg.epochs * 2 // 3 else 1.0)
        totals, n = [0.0, 0.0], 0
        for batch in _batches(data, cfg.batch, rng):
            tag_loss, dec_loss = loss_of(net, batch, encoder)
            opt.zero_grad()
            (tag_loss + dec_loss).backward()
            nn.utils.clip_grad_norm_(trained, 5.0)
            opt.step()
            totals[0] += float(tag_loss.detach())
            totals[1] += float(dec_loss.detach())
            n += 1
            if time.perf_counter() - started > cfg.time_budget_s:
                break
        stats = {'tag_loss': totals[0] / max(n, 1), 'decoder_loss': totals[1] / max(n, 1)}
        if after_epoch is not None:
            net.eval()
            if encoder is not None:
                encoder.eval()
            after_epoch(epoch + 1, stats)
        log(f'epoch {epoch + 1}: tag loss {stats["tag_loss"]:.4f}, decoder loss {stats["decoder_loss"]:.4f}, '
            f'{time.perf_counter() - started:.0f} s')
        if time.perf_counter() - started > cfg.time_budget_s:
            log('time budget reached')
            break
    stats['seconds'] = time.perf_counter() - started
    net.eval()
    if encoder is not None:
        encoder.eval()
    return stats


def save_bundle(net: TranslatorNet, out_dir: Path, facts: dict, encoder: Optional[nn.Module] = None) -> None:
    """Write ``config.json`` and ``weights.pt`` (and ``encoder.pt``, the fine-tuned encoder layers)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    torch.save({k: v.half() if v.is_floating_point() else v for k, v in net.state_dict().items()},
               out_dir / BUNDLE_WEIGHTS)
    if encoder is not None:
        torch.save({k: v.detach().half() for k, v in tuned_parameters(encoder).items()},
                   out_dir / BUNDLE_ENCODER)
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


def apply_tuned_encoder(bundle: Path, encoder: nn.Module) -> bool:
    """Load a bundle's fine-tuned encoder layers into ``encoder``, if it has them; tell whether it had."""
    path = bundle / BUNDLE_ENCODER
    if not path.is_file():
        return False
    state = torch.load(path, map_location='cpu', weights_only=True)
    expected = set(tuned_parameters(encoder))
    if set(state) != expected:
        raise TranslationError(f'the fine-tuned encoder in {bundle} does not fit the packaged encoder',
                               ErrorCode.MODEL_ERROR)
    encoder.load_state_dict({k: v.float() for k, v in state.items()}, strict=False)
    return True


def train(cfg: TrainConfig, out_dir: Path, encoder_dir: Optional[Path] = None,
          log: Callable[[str], None] = print) -> dict:
    """Build the data, train, write the bundle to ``out_dir``; returns the facts written."""
    torch.manual_seed(cfg.seed)
    torch.set_num_threads(cfg.threads)
    encoder_dir = encoder_dir or packaged_model_dir()
    encoder = load_encoder(encoder_dir)
    examples = training_examples(cfg, log)
    tuned = encoder if cfg.encoder_lr > 0 else None
    if tuned is None:
        data = encode_examples(examples, encoder, WordPieces(encoder_dir), log)
    else:
        data = piece_examples(examples, WordPieces(encoder_dir))
    log(f'{len(data)} training examples fit the decoder')
    net = TranslatorNet(cfg.net)
    base = {'train_config': {k: v for k, v in asdict(cfg).items() if k != 'net'}, 'examples': len(data)}
    stats = fit(net, data, cfg, log, encoder=tuned,
                after_epoch=lambda epoch, st: save_bundle(net, out_dir, {**base, 'epochs_done': epoch, **st},
                                                          tuned))
    facts = {**base, **stats}
    save_bundle(net, out_dir, facts, tuned)
    return facts

"""The two networks on the frozen encoder: a mention tagger and a lifted-formula decoder.

Shapes: encoder states ``H`` are ``(B, T, E)`` (E = 384 for MiniLM), ``mask`` ``(B, T)``.

- **Tagger**: a bidirectional GRU over ``H`` and a linear layer -> ``O/B/I`` logits ``(B, T, 3)``.
- **Decoder**: the memory is ``H`` projected to ``d`` plus a learned embedding of each piece's slot
  number (the mention it belongs to), read by a bidirectional GRU; a GRU cell then emits prefix
  tokens (``grammar.TOKENS``) with dot-product attention over the memory. Slots are output
  tokens ``s1..s12``: the decoder learns *which mention* fills an argument from the slot
  embeddings it attends to, not the names themselves (the lifting of GraFT, done in the
  memory instead of a second encoder pass, so one encoder pass serves both networks).
"""
from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any, Optional

import torch
from torch import nn

from ltl_instruct.core.language.neural.features import N_TAGS
from ltl_instruct.core.language.neural.grammar import BOS, MAX_SLOTS, VOCAB_SIZE


@dataclass(frozen=True)
class NetConfig:
    """Sizes of the two networks."""

    encoder_dim: int = 384
    tagger_hidden: int = 128
    hidden: int = 256
    token_dim: int = 64
    dropout: float = 0.1
    conventions: int = 0          # convention inputs (features.CONVENTIONS); 0: a bundle without them

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready sizes."""
        return asdict(self)


class Tagger(nn.Module):
    """Mention tags of every word piece."""

    def __init__(self, c: NetConfig) -> None:
        super().__init__()
        self.rnn = nn.GRU(c.encoder_dim, c.tagger_hidden, batch_first=True, bidirectional=True)
        self.drop = nn.Dropout(c.dropout)
        self.out = nn.Linear(2 * c.tagger_hidden, N_TAGS)

    def forward(self, h: torch.Tensor) -> torch.Tensor:
        """Tag logits ``(B, T, 3)``."""
        y, _ = self.rnn(self.drop(h))
        return self.out(self.drop(y))


class FormulaDecoder(nn.Module):
    """Prefix tokens of the lifted formula, attending to the slot-marked encoder states."""

    def __init__(self, c: NetConfig) -> None:
        super().__init__()
        d = c.hidden
        self.proj = nn.Linear(c.encoder_dim, d)
        self.slot = nn.Embedding(MAX_SLOTS + 1, d)
        self.conv = nn.Linear(c.conventions, d, bias=False) if c.conventions else None
        self.mem_rnn = nn.GRU(d, d // 2, batch_first=True, bidirectional=True)
        self.init = nn.Linear(d, d)
        self.tok = nn.Embedding(VOCAB_SIZE, c.token_dim)
        self.cell = nn.GRUCell(c.token_dim + d, d)
        self.query = nn.Linear(d, d)
        self.out = nn.Linear(2 * d, VOCAB_SIZE)
        self.drop = nn.Dropout(c.dropout)

    def memory(self, h: torch.Tensor, mask: torch.Tensor, slots: torch.Tensor,
               conv: Optional[torch.Tensor] = None) -> tuple[torch.Tensor, ...]:
        """Memory ``(B, T, d)`` and the initial state ``(B, d)`` and context ``(B, d)``.

        ``conv`` ``(B, C)``: the conventions the instruction follows (none given: the defaults).
        """
        x = torch.tanh(self.proj(h)) + self.slot(slots)
        if self.conv is not None:
            given = conv if conv is not None else h.new_zeros((h.shape[0], self.conv.in_features))
            x = x + self.conv(given).unsqueeze(1)
        x = self.drop(x)
        mem, _ = self.mem_rnn(x)
        m = mask.unsqueeze(-1).to(mem.dtype)
        pooled = (mem * m).sum(1) / m.sum(1).clamp(min=1.0)
        state = torch.tanh(self.init(pooled))
        return mem, state, torch.zeros_like(state)

    def step(self, prev: torch.Tensor, state: torch.Tensor, ctx: torch.Tensor, mem: torch.Tensor,
             mask: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """One token: logits ``(B, V)``, the new state and context."""
        state = self.cell(torch.cat([self.tok(prev), ctx], -1), state)
        scores = (mem @ self.query(state).unsqueeze(-1)).squeeze(-1)
        scores = scores.masked_fill(mask == 0, -1e9)
        ctx = (scores.softmax(-1).unsqueeze(1) @ mem).squeeze(1)
        logits = self.out(self.drop(torch.cat([state, ctx], -1)))
        return logits, state, ctx

    def forward(self, h: torch.Tensor, mask: torch.Tensor, slots: torch.Tensor,
                targets: torch.Tensor, conv: Optional[torch.Tensor] = None) -> torch.Tensor:
        """Teacher-forced logits ``(B, L, V)`` for target ids ``(B, L)`` (padding anything)."""
        mem, state, ctx = self.memory(h, mask, slots, conv)
        prev = torch.full((h.shape[0],), BOS, dtype=torch.long)
        out = []
        for t in range(targets.shape[1]):
            logits, state, ctx = self.step(prev, state, ctx, mem, mask)
            out.append(logits)
            prev = targets[:, t]
        return torch.stack(out, 1)


class TranslatorNet(nn.Module):
    """Tagger and decoder together (saved and loaded as one state dict)."""

    def __init__(self, c: NetConfig) -> None:
        super().__init__()
        self.config = c
        self.tagger = Tagger(c)
        self.decoder = FormulaDecoder(c)

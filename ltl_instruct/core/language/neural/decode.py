"""Grammar-constrained beam search over lifted formulas.

At every step each hypothesis may take only the tokens its :class:`GrammarState` allows, so
every finished hypothesis is a complete formula. Hypotheses are kept by total log-probability;
the search stops when ``beam`` hypotheses are finished or none is left to extend.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import torch

from ltl_instruct.core.language.neural.grammar import BOS, TOKENS, VOCAB_SIZE, GrammarState
from ltl_instruct.core.language.neural.model import FormulaDecoder


@dataclass(frozen=True)
class Hypothesis:
    """A finished prefix sequence and its log-probability."""

    tokens: tuple[str, ...]
    logprob: float


def beam_search(decoder: FormulaDecoder, h: torch.Tensor, mask: torch.Tensor, slots: torch.Tensor,
                n_slots: int, beam: int = 5, max_len: int = 48,
                conv: Optional[torch.Tensor] = None) -> list[Hypothesis]:
    """Best finished hypotheses for one instruction (``h`` is ``(1, T, E)``), best first."""
    mem, state, ctx = decoder.memory(h, mask, slots, conv)
    live = [((), 0.0, GrammarState.start(max_len))]
    prev = torch.tensor([BOS])
    done: list[Hypothesis] = []
    while live and len(done) < beam:
        k = len(live)
        logits, state, ctx = decoder.step(prev, state, ctx, mem.expand(k, -1, -1), mask.expand(k, -1))
        logp = torch.log_softmax(logits, -1)
        allowed = torch.full((k, VOCAB_SIZE), float('-inf'))
        for i, (_, _, g) in enumerate(live):
            allowed[i, g.allowed(n_slots)] = 0.0
        total = (logp + allowed + torch.tensor([s for _, s, _ in live]).unsqueeze(1)).view(-1)
        top = torch.topk(total, min(beam, int(torch.isfinite(total).sum())))
        nxt, rows = [], []
        for score, flat in zip(top.values.tolist(), top.indices.tolist()):
            i, tok = divmod(flat, VOCAB_SIZE)
            toks, _, g = live[i]
            g2 = g.push(tok)
            seq = toks + (TOKENS[tok],)
            if g2.done:
                done.append(Hypothesis(seq, score))
            else:
                nxt.append((seq, score, g2))
                rows.append((i, tok))
        live = nxt[:beam - len(done)] if len(done) < beam else []
        rows = rows[:len(live)]
        if not live:
            break
        idx = torch.tensor([i for i, _ in rows])
        state, ctx = state[idx], ctx[idx]
        prev = torch.tensor([t for _, t in rows])
    done.sort(key=lambda hyp: -hyp.logprob)
    return done

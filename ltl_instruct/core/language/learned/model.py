"""The neural semantic parser: BiLSTM encoder, feed-forward attentive decoder, constrained beam search.

Encoder: word embeddings (12) -> one bidirectional LSTM layer (30 per
direction); the encoder states have shape (B, T, 60).

Decoder: the embeddings (12 each) of the last K = 4 decoded tokens (a START
token pads the left) feed a hidden layer (50, tanh); its output attends over
the encoder states (bilinear scores, softmax over words); hidden and context go
through a second layer (50, tanh) to the logits over output tokens.

Our addition to the original model (``ParserConfig.lexical_copy``, on by
default): landmark tokens also get copy scores from the words that name them.
With M the word-by-landmark name-match matrix of ``lexicon`` (fixed, from the
map's names), alpha the decoder's attention over the words and M_t the row of
the word at position t, the logit of landmark l gains
``c * sum_t alpha_t M_t[l] + m * max_t M_t[l]``: the first term points at the
landmark named where the decoder looks (order), the second at every landmark
the instruction names at all; c and m are learned scalars (both start at 2).
Without it, a seed that does not find the word-landmark alignment early
settles on programs that ignore the landmarks named (every probed seed of
baltimore and philadelphia stayed at a training reward of ~0.04, on programs
such as ``goal F ! F ! F ...``); with it one seed of each reached a test goal
accuracy of 0.63 and 0.78 after six epochs (was 0.05 and 0.13 after full
training). The encoder output carries the match rows after the
BiLSTM states, so every caller passes one tensor. Tokens that
the postfix stack discipline forbids (``programs.allowed_mask``) get -inf, so
every decoded program is a valid formula.

Beam search keeps the ``beam`` best partial programs per instruction; for
training it may be randomised (Guu et al., 2017): each beam slot is, with
probability epsilon, filled by a uniformly drawn allowed continuation instead
of the next best one.

Also here: the instruction tokenizer and word vocabulary, and the baseline (an
MLP over a bag of words that predicts only the final landmark).
"""
from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np
import torch
from torch import nn

from ltl_instruct.core.language.learned.lexicon import ascii_fold
from ltl_instruct.core.language.learned.programs import OutputVocabulary, allowed_mask, stack_effect

PAD, UNK = '<pad>', '<unk>'
_WORD = re.compile(r"[a-z0-9]+(?:'[a-z]+)?")


def tokenize(text: str) -> list[str]:
    """Lower-case words and numbers of an instruction (accents removed: "Così" -> "cosi")."""
    return _WORD.findall(ascii_fold(text))


@dataclass(frozen=True)
class WordVocabulary:
    """Instruction words, index = id; id 0 is padding, id 1 unknown words."""

    words: tuple[str, ...]

    @staticmethod
    def build(texts: Sequence[str], min_count: int = 1) -> 'WordVocabulary':
        """Vocabulary of the words occurring at least ``min_count`` times."""
        counts = Counter(w for t in texts for w in tokenize(t))
        kept = sorted(w for w, c in counts.items() if c >= min_count)
        return WordVocabulary((PAD, UNK) + tuple(kept))

    def encode(self, text: str, max_words: int = 80) -> list[int]:
        """Word ids of a text (at most ``max_words``; at least one, UNK for an empty text)."""
        index = self._index()
        ids = [index.get(w, 1) for w in tokenize(text)[:max_words]]
        return ids or [1]

    def _index(self) -> dict[str, int]:
        cached = self.__dict__.get('_cache')
        if cached is None:
            cached = {w: i for i, w in enumerate(self.words)}
            object.__setattr__(self, '_cache', cached)
        return cached

    @property
    def size(self) -> int:
        """Number of word ids."""
        return len(self.words)


@dataclass(frozen=True)
class ParserConfig:
    """Sizes and decoding settings (defaults from Patel, Pavlick and Tellex, RSS 2020)."""

    embedding: int = 12
    encoder_hidden: int = 30
    decoder_hidden: int = 50
    history: int = 4        # K: decoder input = embeddings of the last K tokens
    max_program: int = 13   # most tokens before END
    beam: int = 20
    lexical_copy: bool = True  # our addition: copy scores from the words that name landmarks


def pad_batch(seqs: Sequence[Sequence[int]], pad: int = 0) -> tuple[torch.Tensor, torch.Tensor]:
    """Right-padded id tensor (B, T) and lengths (B,)."""
    lengths = torch.tensor([len(s) for s in seqs], dtype=torch.long)
    out = torch.full((len(seqs), int(lengths.max())), pad, dtype=torch.long)
    for i, s in enumerate(seqs):
        out[i, :len(s)] = torch.tensor(list(s), dtype=torch.long)
    return out, lengths


@dataclass
class BeamResult:
    """Finished programs for one instruction, best first: token ids (END excluded) and log-prob."""

    programs: list[tuple[int, ...]]
    scores: list[float]


class SemanticParser(nn.Module):
    """BiLSTM encoder + feed-forward decoder over the last K tokens with attention (+ copy scores)."""

    def __init__(self, num_words: int, out_vocab: OutputVocabulary, config: ParserConfig,
                 name_match: Optional[np.ndarray] = None) -> None:
        """Build the network.

        ``name_match`` (num_words, landmarks) is the lexicon matrix (zeros if None; a
        loaded model gets it from its state dict).
        """
        super().__init__()
        self.config = config
        self.out_vocab = out_vocab
        c = config
        self.word_embedding = nn.Embedding(num_words, c.embedding, padding_idx=0)
        self.encoder = nn.LSTM(c.embedding, c.encoder_hidden, batch_first=True, bidirectional=True)
        self.start_id = out_vocab.size  # extra embedding row for START padding
        self.token_embedding = nn.Embedding(out_vocab.size + 1, c.embedding)
        enc = 2 * c.encoder_hidden
        self.hidden = nn.Linear(c.history * c.embedding, c.decoder_hidden)
        self.attention = nn.Linear(c.decoder_hidden, enc, bias=False)
        self.combine = nn.Linear(c.decoder_hidden + enc, c.decoder_hidden)
        self.output = nn.Linear(c.decoder_hidden, out_vocab.size)
        # start from the uniform policy over allowed tokens: a randomly initialised output
        # layer prefers arbitrary long programs, and the search then never meets short ones
        nn.init.normal_(self.output.weight, std=0.01)
        nn.init.zeros_(self.output.bias)
        self._effect = torch.from_numpy(stack_effect(out_vocab))
        self._enc = enc
        n_props = len(out_vocab.props)
        if c.lexical_copy:
            match = torch.zeros(num_words, n_props) if name_match is None else torch.as_tensor(
                np.asarray(name_match, dtype=np.float32))
            if tuple(match.shape) != (num_words, n_props):
                raise ValueError(f'name_match must have shape {(num_words, n_props)}, '
                                 f'got {tuple(match.shape)}')
            self.register_buffer('name_match', match)
            # start with a clear preference for the landmarks the instruction names
            self.copy_weight = nn.Parameter(torch.tensor(2.0))
            self.mention_weight = nn.Parameter(torch.tensor(2.0))

    # ------------------------------------------------------------------ network
    def encode(self, words: torch.Tensor, lengths: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """Encode padded word ids (B, T): encoder output (B, T, 60 [+ landmarks]) and word mask (B, T).

        With ``lexical_copy`` the output is the BiLSTM states followed by each word's
        row of the name-match matrix.
        """
        emb = self.word_embedding(words)
        packed = nn.utils.rnn.pack_padded_sequence(emb, lengths, batch_first=True, enforce_sorted=False)
        out, _ = self.encoder(packed)
        states, _ = nn.utils.rnn.pad_packed_sequence(out, batch_first=True, total_length=words.shape[1])
        mask = torch.arange(words.shape[1])[None, :] < lengths[:, None]
        if self.config.lexical_copy:
            states = torch.cat([states, self.name_match[words]], dim=2)
        return states, mask

    def step_logits(self, states: torch.Tensor, mask: torch.Tensor, history: torch.Tensor) -> torch.Tensor:
        """Unmasked logits (N, V) given encoder output (N, T, ...), mask (N, T), last-K ids (N, K)."""
        enc = states[:, :, :self._enc]
        h = torch.tanh(self.hidden(self.token_embedding(history).flatten(1)))
        scores = torch.einsum('ntd,nd->nt', enc, self.attention(h))
        scores = scores.masked_fill(~mask, float('-inf'))
        alpha = torch.softmax(scores, dim=1)
        context = torch.einsum('nt,ntd->nd', alpha, enc)
        logits = self.output(torch.tanh(self.combine(torch.cat([h, context], dim=1))))
        if not self.config.lexical_copy:
            return logits
        match = states[:, :, self._enc:]
        copied = torch.einsum('nt,ntl->nl', alpha, match)
        mentioned = match.masked_fill(~mask[:, :, None], 0.0).amax(dim=1)
        n_props = match.shape[2]
        bonus = self.copy_weight * copied + self.mention_weight * mentioned
        return torch.cat([logits[:, :n_props] + bonus, logits[:, n_props:]], dim=1)

    def _masked_log_probs(self, states: torch.Tensor, mask: torch.Tensor, history: torch.Tensor,
                          stack: np.ndarray, length: np.ndarray, last: np.ndarray) -> torch.Tensor:
        allowed = torch.from_numpy(allowed_mask(self.out_vocab, stack, length, last, self.config.max_program))
        logits = self.step_logits(states, mask, history).masked_fill(~allowed, float('-inf'))
        return torch.log_softmax(logits, dim=1)

    # ------------------------------------------------------------------ scoring
    def program_log_probs(self, states: torch.Tensor, mask: torch.Tensor, example: Sequence[int],
                          programs: Sequence[Sequence[int]]) -> torch.Tensor:
        """Return log p(program | instruction) for each program (END appended), shape (P,), with gradient.

        ``example[i]`` is the row of ``states`` that program i belongs to.
        """
        end = self.out_vocab.end_id
        seqs = [list(p) + [end] for p in programs]
        n_prog, width = len(seqs), max(len(s) for s in seqs)
        k = self.config.history
        history = np.full((n_prog, width, k), self.start_id, dtype=np.int64)
        stack = np.zeros((n_prog, width), dtype=np.int64)
        length = np.zeros((n_prog, width), dtype=np.int64)
        last = np.full((n_prog, width), -1, dtype=np.int64)
        target = np.full((n_prog, width), end, dtype=np.int64)
        valid = np.zeros((n_prog, width), dtype=bool)
        effect = self._effect.numpy()
        for i, s in enumerate(seqs):
            hist = [self.start_id] * k
            depth = 0
            for t, tok in enumerate(s):
                history[i, t] = hist[-k:]
                stack[i, t], length[i, t] = depth, t
                last[i, t] = hist[-1] if hist[-1] != self.start_id else -1
                target[i, t], valid[i, t] = tok, True
                depth += int(effect[tok])
                hist.append(tok)
        flat = valid.reshape(-1)
        rows = np.repeat(np.asarray(example, dtype=np.int64), width)[flat]
        hist_t = torch.from_numpy(history.reshape(-1, k)[flat])
        logp = self._masked_log_probs(states[rows], mask[rows], hist_t,
                                      stack.reshape(-1)[flat], length.reshape(-1)[flat],
                                      last.reshape(-1)[flat])
        picked = logp.gather(1, torch.from_numpy(target.reshape(-1)[flat])[:, None])[:, 0]
        owner = torch.from_numpy(np.repeat(np.arange(n_prog), width)[flat])
        return torch.zeros(n_prog).index_add(0, owner, picked)

    # ------------------------------------------------------------------ search
    @torch.no_grad()
    def beam_search(self, states: torch.Tensor, mask: torch.Tensor, beam: Optional[int] = None,
                    epsilon: float = 0.0, rng: Optional[np.random.Generator] = None) -> list[BeamResult]:
        """Constrained beam search for each instruction of the batch (states (B, T, 60)).

        Finished programs (those that chose END) stay in the beam and compete with
        the unfinished ones; each step keeps the ``beam`` best. Returns the finished
        programs, best first. With ``epsilon`` > 0 (randomised beam search, for
        exploration during training) each slot takes a random allowed continuation
        with that probability.
        """
        width = beam or self.config.beam
        n_batch = states.shape[0]
        k, vsize, end = self.config.history, self.out_vocab.size, self.out_vocab.end_id
        effect = self._effect.numpy()
        rng = rng or np.random.default_rng(0)
        # hypotheses per instruction: token lists, score, stack, done
        hyps: list[list[tuple[list[int], float, int, bool]]] = [[([], 0.0, 0, False)] for _ in range(n_batch)]
        for _ in range(self.config.max_program + 1):
            live = [(b, j) for b in range(n_batch) for j, h in enumerate(hyps[b]) if not h[3]]
            if not live:
                break
            hist = np.array([([self.start_id] * k + hyps[b][j][0])[-k:] for b, j in live], dtype=np.int64)
            stack = np.array([hyps[b][j][2] for b, j in live], dtype=np.int64)
            length = np.array([len(hyps[b][j][0]) for b, j in live], dtype=np.int64)
            last = np.array([hyps[b][j][0][-1] if hyps[b][j][0] else -1 for b, j in live], dtype=np.int64)
            rows = torch.tensor([b for b, _ in live], dtype=torch.long)
            logp = self._masked_log_probs(states[rows], mask[rows], torch.from_numpy(hist),
                                          stack, length, last).numpy()
            new: list[list[tuple[list[int], float, int, bool]]] = [[h for h in hyps[b] if h[3]]
                                                                   for b in range(n_batch)]
            by_batch: dict[int, list[int]] = {}
            for r, (b, _) in enumerate(live):
                by_batch.setdefault(b, []).append(r)
            for b, rs in by_batch.items():
                cand_scores = np.concatenate([hyps[b][live[r][1]][1] + logp[r] for r in rs])
                finite = np.flatnonzero(np.isfinite(cand_scores))
                slots = width - len(new[b]) if epsilon == 0.0 else width
                order = finite[np.argsort(-cand_scores[finite], kind='stable')]
                if epsilon > 0.0 and len(order) > 1:
                    n_random = int(rng.binomial(min(slots, len(order)), epsilon))
                    top = order[:max(0, slots - n_random)]
                    rest = order[len(top):]
                    extra = rng.choice(rest, size=min(n_random, len(rest)), replace=False)
                    chosen = np.concatenate([top, np.asarray(extra, dtype=np.int64)])
                else:
                    chosen = order[:slots]
                for c in chosen:
                    r, tok = rs[int(c) // vsize], int(c) % vsize
                    toks, _, depth, _ = hyps[b][live[r][1]]
                    if tok == end:
                        new[b].append((toks, float(cand_scores[c]), depth, True))
                    else:
                        new[b].append((toks + [tok], float(cand_scores[c]), depth + int(effect[tok]), False))
                # keep the finished and live hypotheses within the beam width
                new[b].sort(key=lambda h: -h[1])
                new[b] = new[b][:max(width, sum(1 for h in new[b] if h[3]))]
            hyps = new
        results = []
        for b in range(n_batch):
            done = sorted((h for h in hyps[b] if h[3]), key=lambda h: -h[1])[:width]
            results.append(BeamResult([tuple(h[0]) for h in done], [h[1] for h in done]))
        return results


class GoalBaseline(nn.Module):
    """Baseline: bag of words -> MLP (50, tanh) -> the final landmark."""

    def __init__(self, num_words: int, num_landmarks: int, hidden: int = 50) -> None:
        super().__init__()
        self.num_words = num_words
        self.layers = nn.Sequential(nn.Linear(num_words, hidden), nn.Tanh(), nn.Linear(hidden, num_landmarks))

    def bag_of_words(self, word_ids: Sequence[Sequence[int]]) -> torch.Tensor:
        """Normalised word counts (B, num_words)."""
        x = torch.zeros(len(word_ids), self.num_words)
        for i, ids in enumerate(word_ids):
            for w in ids:
                x[i, w] += 1.0
            x[i] /= max(1, len(ids))
        return x

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        """Logits over landmarks (B, n) for bags of words (B, num_words)."""
        return self.layers(x)

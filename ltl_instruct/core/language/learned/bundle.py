"""A trained model file: the map, vocabularies, parser and baseline weights, in one torch file.

Saved with ``torch.save`` as plain dicts, lists, strings, numbers and tensors,
and loaded with ``weights_only=True`` (no code runs on load); a missing,
truncated or foreign file raises ``ModelLoadError`` (code ``MODEL_ERROR``).
"""
from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass, field
from typing import Any

import torch

from ltl_instruct.core.errors import ErrorCode, LtlInstructError
from ltl_instruct.core.language.learned.model import (
    GoalBaseline, ParserConfig, SemanticParser, WordVocabulary,
)
from ltl_instruct.core.language.learned.programs import OutputVocabulary
from ltl_instruct.core.world.landmarks import LandmarkMap

FORMAT = 'ltl_instruct.learned_parser.v1'


class ModelLoadError(LtlInstructError):
    """A model file could not be read or is not a learned-parser model."""

    default_code = ErrorCode.MODEL_ERROR


@dataclass
class ParserBundle:
    """Everything a trained city parser needs at run time."""

    landmark_map: LandmarkMap
    words: WordVocabulary
    parser: SemanticParser
    baseline: GoalBaseline
    info: dict[str, Any] = field(default_factory=dict)

    @property
    def out_vocab(self) -> OutputVocabulary:
        """Output tokens of the parser (the map's propositions and the operators)."""
        return self.parser.out_vocab

    def save(self, path: str) -> None:
        """Write the bundle to ``path`` (parent folders are created)."""
        parent = os.path.dirname(os.path.abspath(path))
        os.makedirs(parent, exist_ok=True)
        payload = {
            'format': FORMAT,
            'map': self.landmark_map.to_dict(),
            'words': list(self.words.words),
            'config': dataclasses.asdict(self.parser.config),
            'parser': self.parser.state_dict(),
            'baseline': self.baseline.state_dict(),
            'info': self.info,
        }
        torch.save(payload, path)

    @staticmethod
    def load(path: str) -> 'ParserBundle':
        """Read a bundle written by :meth:`save`."""
        if not os.path.isfile(path):
            raise ModelLoadError(f'no model file at {path}')
        try:
            payload = torch.load(path, map_location='cpu', weights_only=True)
        except Exception as e:  # torch raises many types for a bad file
            raise ModelLoadError(f'cannot read model file {path}: {type(e).__name__}: {e}') from e
        if not isinstance(payload, dict) or payload.get('format') != FORMAT:
            raise ModelLoadError(f'{path} is not a learned-parser model ({FORMAT})')
        try:
            lmap = LandmarkMap.from_dict(payload['map'])
            words = WordVocabulary(tuple(str(w) for w in payload['words']))
            config = ParserConfig(**payload['config'])
            out_vocab = OutputVocabulary(lmap.props)
            parser = SemanticParser(words.size, out_vocab, config)
            parser.load_state_dict(payload['parser'])
            baseline = GoalBaseline(words.size, lmap.num_landmarks)
            baseline.load_state_dict(payload['baseline'])
        except (KeyError, TypeError, ValueError, RuntimeError, LtlInstructError) as e:
            raise ModelLoadError(f'model file {path} is malformed: {e}') from e
        parser.eval()
        baseline.eval()
        return ParserBundle(lmap, words, parser, baseline, dict(payload.get('info') or {}))

"""Learning to translate from trajectories alone (issue 7).

A neural semantic parser per city map, trained only on pairs of (instruction,
demonstrated landmark trajectory) with the automaton as the teacher; see
``training`` for the reward and ``model`` for the network. ``load_translator``
serves a trained model as the ``learned`` translator backend. Importing this
package does not import torch; the modules that need it do.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ltl_instruct.core.language.learned.translator import LearnedTranslator


def load_translator(model_path: str) -> 'LearnedTranslator':
    """Load the ``learned`` backend for the map a model was trained on (raises ``ModelLoadError``)."""
    from ltl_instruct.core.language.learned.translator import LearnedTranslator
    return LearnedTranslator.from_file(model_path)

"""Language to task formulas: translator backends and the verification text.

Entry point: :func:`make_translator` (``'offline'``, the default; ``'llm'``;
``'learned'``). Every backend returns a :class:`Translation` or raises
``TranslationError`` (or another typed ``LtlInstructError``).
"""
from __future__ import annotations

import importlib
from typing import Any

from ltl_instruct.core.errors import ErrorCode, TranslationError
from ltl_instruct.core.language.base import Translation, Translator  # noqa: F401
from ltl_instruct.core.language.verification import Verification, verification_for  # noqa: F401

BACKENDS = ('offline', 'combined', 'neural', 'llm', 'learned')


def make_translator(backend: str = 'offline', **options: Any) -> Translator:
    """Build a translator backend by name.

    Parameters
    ----------
    backend:
        ``'offline'`` (rules; options ``avoid_scope``, ``once_scope``, ``after_scope``, ``numbers``,
        ``landmarks``), ``'llm'``
        (options of :class:`~ltl_instruct.core.language.llm.LlmTranslator`: ``base_url``,
        ``model``, ``api_key``, ``examples_path``, ``k``, ``retries``, ``timeout_s``...), or
        ``'learned'`` (option ``model_path``; the backend of
        ``ltl_instruct.core.language.learned``), ``'neural'`` (the learned translator of
        ``ltl_instruct.core.language.neural``; options ``model_path``, ``beam``, ``flag_below``,
        ``landmarks``) or ``'combined'`` (rules and learned translator, ``core/language/combined.py``;
        the offline options plus ``model_path``).

    Raises
    ------
    TranslationError
        Unknown backend, bad options, or a backend that is not installed (code ``MODEL_ERROR``).
    """
    if backend == 'offline':
        from ltl_instruct.core.language.offline import OfflineTranslator
        try:
            return OfflineTranslator(**options)
        except TypeError as e:
            raise TranslationError(f'bad option for the offline translator: {e}',
                                   ErrorCode.INVALID_INPUT) from e
    if backend in ('combined', 'neural'):
        return _learned_translator(backend, options)
    if backend == 'llm':
        from ltl_instruct.core.language.llm import LlmTranslator
        try:
            return LlmTranslator(**options)
        except TypeError as e:
            raise TranslationError(f'bad option for the llm translator: {e}', ErrorCode.INVALID_INPUT) from e
    if backend == 'learned':
        model_path = options.get('model_path')
        if not model_path:
            raise TranslationError('the learned backend needs model_path (a trained parser bundle)',
                                   ErrorCode.INVALID_INPUT)
        try:
            module = importlib.import_module('ltl_instruct.core.language.learned')
            loader = getattr(module, 'load_translator')
        except (ImportError, AttributeError) as e:
            raise TranslationError(f'the learned backend is not available: {e}', ErrorCode.MODEL_ERROR) from e
        translator: Translator = loader(str(model_path))
        return translator
    raise TranslationError(f'unknown translator backend {backend!r}; one of {", ".join(BACKENDS)}',
                           ErrorCode.INVALID_INPUT)


def _learned_translator(backend: str, options: dict[str, Any]) -> Translator:
    """Build the ``'neural'`` backend (the learned translator alone) or ``'combined'`` (rules and model)."""
    try:
        if backend == 'neural':
            from ltl_instruct.core.language.neural.translator import NeuralTranslator
            return NeuralTranslator(**options)
        from ltl_instruct.core.language.combined import CombinedTranslator
        return CombinedTranslator(**options)
    except TypeError as e:
        raise TranslationError(f'bad option for the {backend} translator: {e}',
                               ErrorCode.INVALID_INPUT) from e

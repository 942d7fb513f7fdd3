"""The default translator: the rules and the learned model read every instruction, one reading goes on.

Policy (measured on the public sets' held-out splits; see the README, "translate"):

- both read it and agree (the same task once referents are aligned by position): the rules'
  reading, not flagged;
- both read it and disagree: the rules' reading, **flagged**, with the model's reading offered
  as the alternative (the dialog shows both);
- the rules refuse and the model reads it with confidence at least ``takeover`` (the share of
  the beam's probability on its reading): the model's reading, **flagged**, with what the rules
  could not place as a warning; below that, the rules' refusal stands (a guess is not a task);
- the model is missing or fails, the rules read it: the rules' reading, not flagged (as before
  the model existed);
- both refuse: the rules' error.

A flagged translation has ``extra['flagged'] = True`` and its reasons in ``extra['unread']``,
which the verification dialog shows first, before anything moves.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any, Optional, Sequence

from ltl_instruct.core.errors import LtlInstructError, TranslationError
from ltl_instruct.core.language.base import Translation, Translator
from ltl_instruct.core.spec import Formula, format_formula, referents_of, rename_descriptors


def same_task(a: Formula, b: Formula) -> bool:
    """Tell whether two formulas are the same task, once b's referents take a's names by position."""
    from ltl_instruct.core.automaton import equivalent
    try:
        if equivalent(a, b):
            return True
        ra, rb = list(referents_of(a)), list(referents_of(b))
        if len(ra) != len(rb) or ra == rb:
            return False
        return equivalent(a, rename_descriptors(b, dict(zip(rb, ra))))
    except LtlInstructError:
        return False


class CombinedTranslator:
    """Backend ``'combined'``: rules and learned model together (the module docstring's policy)."""

    name = 'combined'

    def __init__(self, model_path: Optional[str] = None, landmarks: Sequence[str] = (),
                 takeover: float = 0.5, **rule_options: Any) -> None:
        from ltl_instruct.core.language.offline import OfflineTranslator
        self.rules = OfflineTranslator(landmarks=landmarks, **rule_options)
        self.takeover = takeover
        self.model: Optional[Translator] = None
        self.model_error = ''
        try:
            from ltl_instruct.core.language.neural.translator import NeuralTranslator
            self.model = NeuralTranslator(model_path, landmarks=landmarks,
                                          digits=rule_options.get('numbers') == 'digits')
        except (LtlInstructError, ImportError) as e:
            self.model_error = str(e)

    def translate(self, instruction: str) -> Translation:
        """Translate with both; return the one reading the policy picks."""
        rules: Optional[Translation] = None
        refusal: Optional[LtlInstructError] = None
        try:
            rules = self.rules.translate(instruction)
        except LtlInstructError as e:
            refusal = e
        model: Optional[Translation] = None
        if self.model is not None and (rules is not None or isinstance(refusal, TranslationError)):
            try:
                model = self.model.translate(instruction)
            except LtlInstructError:
                model = None
        if rules is not None:
            return self._with_rules(rules, model)
        if model is not None and refusal is not None and model.extra.get('confidence', 0.0) >= self.takeover:
            return self._from_model(model, refusal)
        assert refusal is not None
        raise refusal

    def _with_rules(self, rules: Translation, model: Optional[Translation]) -> Translation:
        extra = dict(rules.extra)
        if model is None:
            extra.update(flagged=bool(extra.get('unread')), agreement=None)
            return replace(rules, backend=self.name, extra=extra)
        if same_task(rules.formula, model.formula):
            extra.update(flagged=bool(extra.get('unread')), agreement=True,
                         confidence=model.extra.get('confidence'))
            return replace(rules, backend=self.name, extra=extra)
        alternative = format_formula(model.formula)
        unread = list(extra.get('unread', ())) + [
            f'the learned model reads this differently: {alternative}; check which is meant']
        extra.update(flagged=True, agreement=False, alternatives=[alternative], unread=unread)
        return replace(rules, backend=self.name, extra=extra)

    def _from_model(self, model: Translation, refusal: LtlInstructError) -> Translation:
        extra = dict(model.extra)
        unread = [f'the rules could not read all of it ({refusal.message}); this reading is the '
                  f'learned model\'s: check it']
        best = refusal.details.get('best_reading') if isinstance(refusal.details, dict) else None
        alternatives = list(extra.get('alternatives', ()))
        if isinstance(best, str):
            alternatives.insert(0, best)
        extra.update(flagged=True, agreement=False, unread=unread, alternatives=alternatives,
                     rules_error=refusal.to_dict())
        return replace(model, backend=self.name, extra=extra)

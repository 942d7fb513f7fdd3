"""The default translator: the rules and the learned model read every instruction, one reading goes on.

Policy (measured on the public sets' held-out splits; see the README, "translate"):

- both read it and agree (the same task once referents are aligned by position): the rules'
  reading, not flagged (with the model's names when only the model's are all landmarks given:
  "the green area" is the map's `green_room`);
- both read it and disagree: the rules' reading, **flagged**, with the model's reading offered
  as the alternative (the dialog shows both);
- the rules refuse because words could not be placed (never a count, limit or input rule they
  enforce) and the model reads it with confidence at least ``takeover`` (the share of
  the beam's probability on its reading): the model's reading, **flagged**, with what the rules
  could not place as a warning; below that, or when a name it found is no English word nor a
  landmark given ("qwzx vvv"), the rules' refusal stands (a guess is not a task);
- the model is missing or fails, the rules read it: the rules' reading, not flagged (as before
  the model existed);
- both refuse: the rules' error.

A flagged translation has ``extra['flagged'] = True`` and its reasons in ``extra['unread']``,
which the verification dialog shows first, before anything moves.
"""
from __future__ import annotations

import re
from dataclasses import replace
from typing import Any, Optional, Sequence

from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
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


def _unreadable(refusal: LtlInstructError) -> bool:
    """Tell whether the rules refused because words could not be placed (not a count, limit or input rule)."""
    details = refusal.details if isinstance(refusal.details, dict) else {}
    return refusal.code == ErrorCode.TRANSLATION_ERROR and 'part' in details and 'count' not in details


class CombinedTranslator:
    """Backend ``'combined'``: rules and learned model together (the module docstring's policy)."""

    name = 'combined'

    def __init__(self, model_path: Optional[str] = None, landmarks: Sequence[str] = (),
                 takeover: float = 0.5, **rule_options: Any) -> None:
        from ltl_instruct.core.language.offline import OfflineTranslator
        self.rules = OfflineTranslator(landmarks=landmarks, **rule_options)
        self.takeover = takeover
        self.landmarks = tuple(landmarks)
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
        if model is not None and refusal is not None and _unreadable(refusal) and self._may_take_over(model):
            return self._from_model(model, refusal)
        assert refusal is not None
        raise refusal

    def _may_take_over(self, model: Translation) -> bool:
        """Tell whether the model may stand in for a refusal: confident, every name made of words."""
        if model.extra.get('confidence', 0.0) < self.takeover:
            return False
        from ltl_instruct.core.language.offline import rules_speller
        speller = rules_speller()
        landmarks = set(self.landmarks)
        for mention in model.extra.get('mentions', ()):
            words = re.findall(r'[a-z]+', mention['text'].lower())
            if mention['descriptor'] in landmarks:
                continue
            if not words or not all(speller.known(w) or w in landmarks for w in words):
                return False
        return True

    def _names_the_map(self, t: Translation) -> bool:
        """Tell whether every referent of a reading is a landmark given (the map's own names)."""
        return bool(self.landmarks) and all(r in self.landmarks for r in t.referents)

    def _with_rules(self, rules: Translation, model: Optional[Translation]) -> Translation:
        extra = dict(rules.extra)
        if model is None:
            extra.update(flagged=bool(extra.get('unread')), agreement=None)
            return replace(rules, backend=self.name, extra=extra)
        if same_task(rules.formula, model.formula):
            extra.update(flagged=bool(extra.get('unread')), agreement=True,
                         confidence=model.extra.get('confidence'))
            formula = model.formula if self._names_the_map(model) and not self._names_the_map(rules) \
                else rules.formula
            return replace(rules, formula=formula, backend=self.name, extra=extra)
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

"""The default translator: the rules and the learned model read every instruction, one reading goes on.

Policy (measured on the public sets' held-out splits; see the README, "translate"):

- both read it and agree (the same task once referents are aligned by position): the rules'
  reading, not flagged (with the model's names when only the model's are all landmarks given:
  "the green area" is the map's `green_room`);
- both read it and disagree: the rules' reading, **flagged**, with the model's reading offered
  as the alternative (the dialog shows both); unless the rules guessed or left out part of the
  instruction (a reading that placed every word stands: ``Policy.read_all_stands``) and the
  model is sure of its reading
  (confidence at least ``override``, every mention used, every name made of words or
  landmarks given, no name of more than ``MAX_PLAIN_NAME_WORDS`` words that the phrase reader
  could not split into a thing and its relations) and neither reading counts visits (a place
  named ``COUNTED`` times or more: an earlier model, without count macros, miscounted; the
  current one was measured with and without the guard, ``Policy.counts``):
  then the model's reading, **flagged**, with the rules' as the alternative. Where landmarks
  are given (the map's names) and the rules' reading names something that is none of them while
  the model's names only landmarks, ``takeover`` confidence is enough, as for a refusal: a name
  the map lacks would fail at grounding (``Policy.off_map``);
- the rules refuse because words could not be placed (never a count, limit or input rule they
  enforce) and the model reads it, using every mention, with confidence at least ``takeover`` (the share of
  the beam's probability on its reading): the model's reading, **flagged**, with what the rules
  could not place as a warning; below that, or when a name it found is no English word nor a
  landmark given ("qwzx vvv"), the rules' refusal stands (a guess is not a task);
- the model is missing or fails, the rules read it: the rules' reading, not flagged (as before
  the model existed);
- both refuse: the rules' error.

Whichever reading goes on is also flagged when the instruction says what no formula can state: a
place named by where the person or the robot is ("bring me the cup", "come back"), an event the
robot cannot observe or the clock ("until I call you", "for ten minutes"; all in ``deixis``), and,
where landmarks are given, when it names something that is none of them (grounding would fail:
"without going to any other floors" read as ``!near[other_floors]``).

A flagged translation has ``extra['flagged'] = True`` and its reasons in ``extra['unread']``,
which the verification dialog shows first, before anything moves.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, replace
from typing import Any, Optional, Sequence

from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
from ltl_instruct.core.language.base import Translation, Translator
from ltl_instruct.core.spec import (
    Atom, Formula, avoided_referents_of, format_formula, iter_subformulas, referents_of, rename_descriptors,
)

# Measured on the validation splits and the dev set (bench.translator_policy, readings of the
# shipped model): of the model's sure readings that would have overridden the rules,
# - the 8 where a reading names one place three times or more (counts: "at most three times",
#   "exactly twice") were all wrong, and the rules' reading right;
# - the 2 with a name of more words than any object name, which the phrase reader could not split
#   ("charging_dock_next_to_tv_or_one_next_to_bookshelf") were wrong; of the 64 other overrides,
#   63 were right.
COUNTED = 3
MAX_PLAIN_NAME_WORDS = 3


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


def counts_visits(f: Formula) -> bool:
    """Tell whether a formula names one place ``COUNTED`` times or more (a count of visits)."""
    seen: dict[Atom, int] = {}
    for node in iter_subformulas(f):
        if isinstance(node, Atom):
            seen[node] = seen.get(node, 0) + 1
    return max(seen.values(), default=0) >= COUNTED


def _unreadable(refusal: LtlInstructError) -> bool:
    """Tell whether the rules refused because words could not be placed (not a count, limit or input rule)."""
    details = refusal.details if isinstance(refusal.details, dict) else {}
    return refusal.code == ErrorCode.TRANSLATION_ERROR and 'part' in details and 'count' not in details


def _drops_a_rule(refusal: LtlInstructError, model: Translation) -> bool:
    """Tell whether the words the rules could not place rule a place out and the model's reading does not."""
    from ltl_instruct.core.language.fallback import rules_out_a_place
    part = str(refusal.details.get('part', '')) if isinstance(refusal.details, dict) else ''
    return rules_out_a_place(part.split()) and not avoided_referents_of(model.formula)


def _flag_unstated(t: Translation) -> Translation:
    """Flag a reading of what no formula states ("bring me", "come back", "until I call you")."""
    from ltl_instruct.core.language.deixis import unstated
    return _flagged(t, unstated(t.instruction, t.formula))


def _flagged(t: Translation, notes: Sequence[str]) -> Translation:
    """Return the reading flagged with ``notes`` added to its reasons (itself when there are none)."""
    if not notes:
        return t
    extra = dict(t.extra)
    extra.update(flagged=True, unread=list(extra.get('unread', ())) + list(notes))
    return replace(t, extra=extra)


@dataclass(frozen=True)
class Policy:
    """The thresholds of the policy (model confidence: its reading's share of the beam's probability).

    takeover: the rules refused (words they could not place): the model's reading stands in at
        this confidence or more.
    override: the two disagree: the model's reading goes on instead of the rules' at this
        confidence or more (above 1: never). Chosen on the validation splits and the dev set by
        ``bench.translator_policy``; the README gives the figures.
    counts: whether the model may override a reading that counts visits (its own or the rules').
    off_map: where landmarks are given and the rules' reading names something that is not one
        while the model's names only landmarks, the model's reading goes on at ``takeover``
        confidence, as for a refusal (a name the map lacks fails at grounding anyway).
    read_all_stands: a rules' reading that placed every part of the instruction (nothing guessed
        or left out: no ``unread`` in its extra) is never overridden (``off_map`` aside). Chosen
        as the others are (mean .834 against .832 on the validation splits); on the helpers'
        construction tests it stops 56 confident model readings replacing right rules' readings
        ("Never mind, go to the porch." was ``G !near[porch]``).
    rules_kept: a refusal whose unplaced words rule a place out (``fallback.rules_out_a_place``:
        "not", "never", "off limits", "stay away"...) is taken over only by a reading that avoids
        something: "Go to the den, since the kitchen is off limits" was the model's
        ``F (den & F kitchen)``.
    """

    takeover: float = 0.5
    override: float = 0.95
    counts: bool = False
    off_map: bool = True
    read_all_stands: bool = True
    rules_kept: bool = True


# what the rules and the model made of one instruction: (rules' reading, rules' refusal, model's reading)
Readings = tuple[Optional[Translation], Optional[LtlInstructError], Optional[Translation]]


class CombinedTranslator:
    """Backend ``'combined'``: rules and learned model together (the module docstring's policy)."""

    name = 'combined'

    def __init__(self, model_path: Optional[str] = None, landmarks: Sequence[str] = (),
                 takeover: Optional[float] = None, override: Optional[float] = None,
                 **rule_options: Any) -> None:
        from ltl_instruct.core.language.offline import OfflineTranslator
        self.rules = OfflineTranslator(landmarks=landmarks, **rule_options)
        default = Policy()
        self.policy = Policy(default.takeover if takeover is None else takeover,
                             default.override if override is None else override)
        self.landmarks = tuple(landmarks)
        self.model: Optional[Translator] = None
        self.model_error = ''
        try:
            from ltl_instruct.core.language.neural.features import CONVENTIONS
            from ltl_instruct.core.language.neural.translator import NeuralTranslator
            conventions = {name: rule_options[name] for name, _, _ in CONVENTIONS if name in rule_options}
            self.model = NeuralTranslator(model_path, landmarks=landmarks,
                                          digits=rule_options.get('numbers') == 'digits', **conventions)
        except (LtlInstructError, ImportError) as e:
            self.model_error = str(e)

    def translate(self, instruction: str) -> Translation:
        """Translate with both; return the one reading the policy picks."""
        return self.decide(self.read(instruction), self.policy)

    def read(self, instruction: str) -> Readings:
        """Return what the rules and the model make of an instruction (the model only when worth asking)."""
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
        return rules, refusal, model

    def decide(self, readings: Readings, policy: Policy) -> Translation:
        """Pick the one reading that goes on (raises the rules' refusal when none may), flagged as needed."""
        return _flag_unstated(self._flag_off_map(self._pick(readings, policy)))

    def _pick(self, readings: Readings, policy: Policy) -> Translation:
        """Pick the one reading that goes on (raises the rules' refusal when none may)."""
        rules, refusal, model = readings
        if rules is not None:
            if model is not None and self._overrides(rules, model, policy):
                return self._from_model(model, self._differs_note(rules), [format_formula(rules.formula)],
                                        rules_error=None)
            return self._with_rules(rules, model)
        assert refusal is not None
        if model is not None and _unreadable(refusal) and self._sure(model, policy.takeover) and \
                not (policy.rules_kept and _drops_a_rule(refusal, model)):
            best = refusal.details.get('best_reading') if isinstance(refusal.details, dict) else None
            note = (f'the rules could not read all of it ({refusal.message}); this reading is the '
                    f'learned model\'s: check it')
            return self._from_model(model, note, [best] if isinstance(best, str) else [],
                                    rules_error=refusal.to_dict())
        raise refusal

    def _overrides(self, rules: Translation, model: Translation, policy: Policy) -> bool:
        """Tell whether the model's reading goes on instead of the rules' (they disagree; see the module)."""
        if same_task(rules.formula, model.formula):
            return False
        if not policy.counts and (counts_visits(rules.formula) or counts_visits(model.formula)):
            return False
        if policy.off_map and self._names_the_map(model) and not self._names_the_map(rules):
            return self._sure(model, policy.takeover)
        if policy.read_all_stands and not rules.extra.get('unread'):
            return False
        return self._sure(model, policy.override)

    @staticmethod
    def _differs_note(rules: Translation) -> str:
        return (f'the rules read this differently: {format_formula(rules.formula)}; this reading is the '
                f'learned model\'s, which is sure of it: check which is meant')

    def _sure(self, model: Translation, threshold: float) -> bool:
        """Tell whether the model's reading may go on: confident, every mention used, names made of words."""
        if model.extra.get('confidence', 0.0) < threshold or not model.extra.get('complete', True):
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
            if '::' not in mention['descriptor'] and \
                    mention['descriptor'].count('_') >= MAX_PLAIN_NAME_WORDS:
                return False   # a clause read as one name ("the dock by the tv or the one by ...")
        return True

    def _flag_off_map(self, t: Translation) -> Translation:
        """Flag a reading that names something the landmarks given lack (it would fail at grounding)."""
        missing = self._off_map(t)
        return _flagged(t, [f'{", ".join(missing)}: none of the landmarks given; check what is meant']
                        if missing else [])

    def _names_the_map(self, t: Translation) -> bool:
        """Tell whether every referent of a reading is a landmark given (the map's own names)."""
        return bool(self.landmarks) and not self._off_map(t)

    def _off_map(self, t: Translation) -> list[str]:
        """Return the referents of a reading that are none of the landmarks given (none without landmarks)."""
        return [r for r in t.referents if r not in self.landmarks] if self.landmarks else []

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
        extra.update(flagged=True, agreement=False, alternatives=[alternative], unread=unread,
                     confidence=model.extra.get('confidence'))
        return replace(rules, backend=self.name, extra=extra)

    def _from_model(self, model: Translation, note: str, first: list[str],
                    rules_error: Optional[dict]) -> Translation:
        extra = dict(model.extra)
        alternatives = first + [a for a in extra.get('alternatives', ()) if a not in first]
        extra.update(flagged=True, agreement=False, unread=[note], alternatives=alternatives)
        if rules_error is not None:
            extra['rules_error'] = rules_error
        return replace(model, backend=self.name, extra=extra)

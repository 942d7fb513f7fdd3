"""The offline translator: deterministic rules from English instructions to task formulas.

No model, no network: the instruction is normalised into tokens
(:mod:`ltl_instruct.core.language.text`), list references and self-corrections are
resolved by rewriting the tokens (:mod:`ltl_instruct.core.language.rewrite`), the
sentences are cut into clauses at connectives ("then", "but", ", and go..."), and
each clause is read as a goal, a delivery, an avoidance (global or scoped), an
ordering constraint, or a count. Noun phrases become descriptors
(:mod:`ltl_instruct.core.language.phrases`). The clauses build a small task model:
conjoined chains of steps plus constraints, rendered as a formula in the
conventions of the development set (``spatial-temporal-dev/CONVENTIONS.md``).

The word lists live in :mod:`ltl_instruct.core.language.lexicon`, the task model (steps, their
formula, the count builders) in :mod:`ltl_instruct.core.language.task`, idioms rewritten to
plain phrasing in :mod:`ltl_instruct.core.language.idioms`, and rules over the whole run
("whenever X, Y") in :mod:`ltl_instruct.core.language.reactions`.

Whatever the rules cannot place raises :class:`TranslationError` naming the words
left over; nothing is dropped silently.
"""
from __future__ import annotations

import re
import time
from dataclasses import dataclass
from typing import Optional, Sequence

from ltl_instruct.core.errors import ErrorCode, LimitExceededError, LtlInstructError, TranslationError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.language.idioms import rewrite_idioms
from ltl_instruct.core.language.lexicon import (
    AVOID_BY_FIRST_WORD as _AVOID_BY_FIRST, AVOID_FILLER, CLAUSE_OPENING_WORDS, CLAUSE_STARTERS,
    DELIVER_VERBS, EVENT_WORDS, FILLERS, GOAL_PARTICLES, GOAL_VERBS, IGNORED_CLAUSES, NOISE_TAILS,
    NOT_BEFORE_VERB, ORDER_TAILS, PATROL_WORDS, PICK_VERBS, PUT_VERBS, RULE_WORDS, RUN_ON_NOT_AFTER,
    STAY_BY_FIRST_WORD as _STAY_BY_FIRST, STRICT_ORDER_TAILS, STRONG_VERBS, TRASH,
)
from ltl_instruct.core.language.phrases import (
    DETERMINERS as DETS, NAME_VERBS, NounPhrase, PhraseParser, is_name_word,
)
from ltl_instruct.core.language.reactions import RuleReader
from ltl_instruct.core.language.rewrite import apply_corrections, resolve_list_references
from ltl_instruct.core.language.task import (  # noqa: F401  (the count builders are part of this API)
    Step, Task as _Task, at_least, at_most, conjoin as _and, disjoin as _or, exactly, near_atom as _near,
    never_all as _never, render, until_avoid as _until_avoid,
)
from ltl_instruct.core.language.text import NUMBER_WORDS, ORDINALS, PUNCT, tokenize
from ltl_instruct.core.spec import (
    Always, Atom, Descriptor, Eventually, Formula, Implies, Next, Not, Relation, Until, WeakUntil,
)

MAX_INSTRUCTION_CHARS = 2000


@dataclass
class _Clause:
    connector: str          # 'seq', 'and', 'pre', 'or'
    tokens: list[str]
    strict: bool = False    # "..., and only then ...": its goal not before the one before it
    first: bool = False     # "..., go to X first": X before the goals given so far


@dataclass
class _Scope:
    kind: str = 'global'   # global, until, onway, after, carry, after_pick, after_release
    target: Optional[NounPhrase] = None
    event: str = 'near'    # for until: near / pick / release


class OfflineTranslator:
    """Rule-based translator (the default backend): deterministic, no model, milliseconds.

    Parameters
    ----------
    landmarks:
        Names known in advance (a city map, a grid world: ``a``, ``b``, ``red_room``): each is a
        whole noun phrase, even where it looks like an article ("go to a").
    avoid_scope:
        ``'global'`` (default, the development set's convention): "go to X and
        avoid Y" is ``F near[x] & G !near[y]``. ``'goal'`` reads it as the
        drone-planning data set does: Y is avoided at the moment X is reached,
        ``F (near[x] & !near[y])``.
    once_scope:
        ``'run'`` (default, the development set's convention): "visit X only once, then Y"
        allows one visit of X in the whole run. ``'next'`` reads a goal's "once" (and "visit
        each only once", "no revisiting") in a sequence as lang2ltl's strictly ordered visits
        do: X is not visited again before the next goal, ``!x U (x U (!x U y))``; a goal
        with none after it keeps "exactly once".
    """

    name = 'offline'

    def __init__(self, avoid_scope: str = 'global', landmarks: Sequence[str] = (),
                 once_scope: str = 'run') -> None:
        if avoid_scope not in ('global', 'goal'):
            raise TranslationError(f'avoid_scope must be global or goal, not {avoid_scope!r}',
                                   ErrorCode.INVALID_INPUT)
        if once_scope not in ('run', 'next'):
            raise TranslationError(f'once_scope must be run or next, not {once_scope!r}',
                                   ErrorCode.INVALID_INPUT)
        self.avoid_scope = avoid_scope
        self.once_scope = once_scope
        self.landmarks = tuple(landmarks)

    def translate(self, instruction: str) -> Translation:
        """Translate one instruction (raises :class:`TranslationError` naming what it cannot place)."""
        if not isinstance(instruction, str):
            raise TranslationError('the instruction must be text', ErrorCode.INVALID_INPUT)
        if len(instruction) > MAX_INSTRUCTION_CHARS:
            raise LimitExceededError(f'the instruction is {len(instruction)} characters long; '
                                     f'the limit is {MAX_INSTRUCTION_CHARS}')
        started = time.perf_counter()
        tokens = tokenize(instruction)
        if not any(t not in PUNCT for t in tokens):
            raise TranslationError('the instruction is empty', ErrorCode.INVALID_INPUT)
        notes: list[str] = []
        tokens = resolve_list_references(tokens, notes)
        tokens = apply_corrections(tokens, notes)
        tokens = rewrite_idioms(tokens)
        reader = _Reader(self.avoid_scope, notes, self.landmarks, self.once_scope)
        try:
            formula = reader.read(tokens)
        except (IndexError, KeyError, ValueError, AttributeError, RecursionError, AssertionError) as e:
            # a bug in the rules, reported as one (typed), never a crash of the caller
            raise LtlInstructError(f'the offline translator failed on this instruction ({type(e).__name__}: '
                                   f'{e}); please report it', ErrorCode.INTERNAL_ERROR,
                                   {'instruction': instruction}) from e
        elapsed = time.perf_counter() - started
        return Translation(instruction, formula, self.name, tuple(notes),
                           {'seconds': elapsed, 'tokens': ' '.join(tokens)})


def _ordinal_name(tokens: Sequence[str], i: int) -> bool:
    """Whether an ordinal starts a name ("first floor") rather than an adverb ("first head to")."""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ''
    return is_name_word(tokens, i, False) and nxt not in GOAL_VERBS | NAME_VERBS | DELIVER_VERBS | PICK_VERBS


def normalize_counts(rest: list[str]) -> list[str]:
    """Rewrite count idioms to one form: "five or more times" -> "at least five times"."""
    text = ' ' + ' '.join(rest) + ' '
    num = r'(one|two|three|four|five|six|seven|eight|nine|ten|\d+)'
    kinds = '(separate |different |distinct )?'
    text = re.sub(rf' {num} or more than \1 {kinds}times ', r' at least \1 times ', text)
    text = re.sub(rf' {num} or more (separate |different |distinct )?times ', r' at least \1 times ', text)
    text = re.sub(r' at least ((?:\w+ )?(?:times|twice|once|thrice)) or more ', r' at least \1 ', text)
    text = re.sub(rf' ({num} times|twice|once|thrice) or more ', r' at least \1 ', text)
    text = re.sub(r' (?:any )?more or (?:any )?(?:fewer|less) than ', ' exactly ', text)
    return text.split()


def _strip_tails(rest: list[str]) -> tuple[list[str], str]:
    """Remove phrases that add nothing ("at all costs"), and say which order phrase was there.

    The order is ``''`` (none), ``'sequence'`` ("in that order": one after the other) or
    ``'strict'`` ("in that strict order": none before the one it follows).
    """
    order = ''
    changed = True
    while changed and rest:
        changed = False
        for tail in STRICT_ORDER_TAILS + NOISE_TAILS + ORDER_TAILS:
            n = len(tail)
            for i in range(len(rest) - n + 1):
                if tuple(rest[i:i + n]) == tail and (i == 0 or i + n == len(rest)):
                    if tail in STRICT_ORDER_TAILS:
                        order = 'strict'
                    elif tail in ORDER_TAILS:
                        order = order or 'sequence'
                    rest = rest[:i] + rest[i + n:]
                    changed = True
                    break
            if changed:
                break
    return rest, order


def _starts(tokens: Sequence[str], i: int, words: Sequence[str]) -> bool:
    return tuple(tokens[i:i + len(words)]) == tuple(words)


def _find(tokens: Sequence[str], words: Sequence[str], start: int = 0) -> int:
    for i in range(start, len(tokens) - len(words) + 1):
        if _starts(tokens, i, words):
            return i
    return -1


class _Reader:
    """Reads the clauses of one instruction into a :class:`_Task`."""

    def __init__(self, avoid_scope: str, notes: list[str], landmarks: Sequence[str] = (),
                 once_scope: str = 'run') -> None:
        self.once_scope = once_scope
        self.no_revisits = False   # "visit each place only once", "no revisiting"
        self.phrases = PhraseParser(landmarks)
        self.rules = RuleReader(self.phrases)
        self.task = _Task()
        self.avoid_scope = avoid_scope
        self.notes = notes
        self.last_place: Optional[NounPhrase] = None
        self.last_object: Optional[NounPhrase] = None
        self.conditional: Optional[NounPhrase] = None
        self.pending_avoid_at: list[Descriptor] = []
        self.choice: Optional[Descriptor] = None
        self.only = False
        self.saw_action = False
        self.mentions: list[Descriptor] = []
        self.before_target: Optional[Descriptor] = None
        self.strict_chain = False   # "in that strict order" somewhere in the instruction
        self.last_goal: Optional[Step] = None   # the last goal clause's step ("before that" refers to it)
        self.connector = 'and'   # how the goal clause being read joins the one before it
        # global avoidances and the step they were read after (to repair "avoid b ... then go to b")
        self.global_avoids: list[tuple[Descriptor, Optional[Step], Formula]] = []

    # ----------------------------------------------------------------- structure
    def read(self, tokens: list[str]) -> Formula:
        for sentence in self._sentences(tokens):
            self._read_sentence(sentence)
        if not self.saw_action and self.mentions and not self.task.chain:
            # "there's a box behind the couch." alone: nothing to do
            raise TranslationError(f'found no action (go, bring, avoid...) in "{" ".join(tokens)}"',
                                   details={'part': ' '.join(tokens)})
        if not self.saw_action:
            raise TranslationError(f'found no action (go, bring, avoid...) in "{" ".join(tokens)}"',
                                   details={'part': ' '.join(tokens)})
        self._repair_avoid_then_visit()
        if self.strict_chain:
            self._strict_chain()
        self._visits_once()
        if self.pending_avoid_at:
            step = self.task.last_step(('visit',))
            if step is not None:
                step.avoid_at.extend(self.pending_avoid_at)
            else:
                self.task.constraints.extend(_never(self.pending_avoid_at))
        return self.task.formula()

    def _visits_once(self) -> None:
        """Constraints of the goals visited once ("visit a exactly once", "no revisiting"; see once_scope)."""
        chain = self.task.chain
        if self.task.repeat > 1:
            return
        if self.no_revisits:
            for st in chain:
                if st.kind == 'visit' and len(st.targets) == 1:
                    st.once = 'exactly'
        for k, st in enumerate(chain):
            if st.kind != 'visit' or not st.once or len(st.targets) != 1:
                continue
            x = _near(st.targets[0])
            nxt = chain[k + 1] if k + 1 < len(chain) else None
            if self.once_scope == 'next' and nxt is not None and nxt.kind == 'visit' and \
                    st.targets[0] not in nxt.targets:
                # not again before the next goal: !x U (x U (!x U next))
                reach = _or([_near(t) for t in nxt.targets])
                self.task.constraints.append(Until(Not(x), Until(x, Until(Not(x), reach))))
            elif self.once_scope == 'next' and nxt is None and len(chain) > 1:
                pass   # the last goal of a sequence: nothing comes after it to go back from
            elif st.once == 'exactly':
                self.task.constraints.append(exactly(x, 1))
            prev = chain[k - 1] if k > 0 else None
            if self.once_scope == 'next' and prev is not None and prev.kind == 'visit' and \
                    st.targets[0] not in prev.targets:
                # its one visit comes in its turn: not before the goal before it
                self.task.constraints.append(Until(Not(x), _or([_near(t) for t in prev.targets])))

    def _strict_chain(self) -> None:
        """'in that strict order': each goal of the chain only after the one before it."""
        visits = [st for st in self.task.chain if st.kind == 'visit']
        for a, b in zip(visits, visits[1:]):
            for d in b.targets:
                f = Until(Not(_near(d)), _or([_near(t) for t in a.targets]))
                if f not in self.task.constraints and d not in a.targets:
                    self.task.constraints.append(f)

    def _repair_avoid_then_visit(self) -> None:
        """Avoid a place that is also a later goal only on the way there.

        "go to a while avoiding b, then move to b": ``G !near[b]`` would contradict the goal,
        so the avoidance ends where the next goal is reached: ``(!near[b] U near[a]) & ...``.
        """
        goals = {d for st in self.task.chain if st.kind in ('visit', 'deliver') for d in st.targets}
        for d, after, g in self.global_avoids:
            if d not in goals or g not in self.task.constraints:
                continue
            if after is not None and after.kind == 'visit' and d not in after.targets:
                nxt: Optional[Step] = after   # read with this goal: avoided on the way to it
            else:
                nxt = next((st for st in self.task.chain if st.kind == 'visit' and d not in st.targets), None)
            if nxt is None:
                continue
            # from the start until that goal: "b not before a" (as the ordered-visit patterns read it)
            k = self.task.constraints.index(g)
            self.task.constraints[k] = Until(Not(_near(d)), _or([_near(t) for t in nxt.targets]))

    @staticmethod
    def _sentences(tokens: list[str]) -> list[list[str]]:
        out: list[list[str]] = [[]]
        for t in tokens:
            if t in '.;!?':
                if out[-1]:
                    out.append([])
            else:
                out[-1].append(t)
        return [s for s in out if s]

    def _read_sentence(self, tokens: list[str]) -> None:
        while tokens and tokens[0] in (',', ':'):
            tokens = tokens[1:]
        if not tokens:
            return
        if tokens[0] == 'either' or (tokens[0] in ('go', 'you', 'can') and 'either' in tokens[:4]):
            k = _find(tokens, [',', 'or'])
            if k > 0:
                self._read_alternatives([tokens[:k], tokens[k + 2:]])
                return
            k = next((j for j in range(1, len(tokens) - 1) if tokens[j] == 'or' and tokens[j + 1] in
                      GOAL_VERBS | DELIVER_VERBS | PICK_VERBS), -1)
            if k > 0:
                self._read_alternatives([tokens[:k], tokens[k + 1:]])
                return
        # "..., then stay in X or continue to Y": a permission tail, after the goal it follows
        for p in range(len(tokens)):
            tail = ' '.join(tokens[p:]) + ' '
            if (tokens[p] in ('then', 'if', 'once') or p == 0) and self._is_permission(tokens[p:]) and (
                    ' or stay ' in tail or ' or continue ' in tail) and (p > 0 or self.task.chain):
                if p > 0:
                    head = tokens[:p]
                    while head and head[-1] in (',', 'and'):
                        head = head[:-1]
                    self._read_sentence(head)
                self._read_permission(tokens[p:])
                return
        if any(t in RULE_WORDS for t in tokens):
            goals = [d for st in self.task._all_steps() for d in st.targets + st.dests]
            rules = self.rules.read(tokens, goals)
            if rules is not None:
                # "whenever you pass a, check b": rules over the whole run
                self.saw_action = True
                self.task.constraints.extend(rules)
                return
        scope: Optional[_Scope] = None
        clauses = self._clauses(tokens)
        if any(c.connector == 'or' for c in clauses[1:]) and clauses[0].connector != 'or' and \
                not self._is_permission(tokens):
            # "go to a then b, or go to b then a": one of the routes
            groups: list[list[_Clause]] = [[]]
            for c in clauses:
                if c.connector == 'or' and groups[-1]:
                    groups.append([_Clause('and', c.tokens)])
                else:
                    groups[-1].append(c)
            self._read_alternative_clauses(groups)
            return
        for n, clause in enumerate(clauses):
            later = [t for c in clauses[n:] for t in c.tokens]
            first = self._strip_fillers(clause.tokens)
            permits = self._is_permission(first) or self._is_permission(clause.tokens)
            opens = first[:1] in (['if'], ['once']) or first[:2] in (['only', 'if'], ['only', 'once'],
                                                                     ['only', 'when'], ['only', 'after'])
            if (self.task.chain and permits) or (opens and self._is_permission(later)):
                self._read_permission(later)
                return
            scope = self._read_clause(clause, scope)

    def _read_alternatives(self, parts: list[list[str]]) -> None:
        self._read_alternative_clauses([self._clauses(p[1:] if p and p[0] == 'either' else p) for p in parts])

    def _read_alternative_clauses(self, groups: list[list[_Clause]]) -> None:
        self.saw_action = True
        outer = self.task
        chains = []
        for group in groups:
            self.task = _Task()
            scope: Optional[_Scope] = None
            for clause in group:
                scope = self._read_clause(clause, scope)
            chains.append([Step('formula', formula=c) for c in self.task.constraints] + self.task.chain)
        self.task = outer
        self.task.chain.append(Step('any', chains=chains))

    def _clauses(self, tokens: list[str]) -> list[_Clause]:
        clauses: list[_Clause] = [_Clause('and', [])]
        i = 0
        n = len(tokens)
        while i < n:
            t = tokens[i]
            if t not in CLAUSE_OPENING_WORDS:
                clauses[-1].tokens.append(t)   # no boundary can start here (the common case, kept fast)
                i += 1
                continue
            boundary = ''
            skip = 0
            only_then = _starts(tokens, i + 1, ['then']) or _starts(tokens, i + 1, ['after', 'that'])
            if t == 'only' and only_then:
                # "go to a, and only then go to b": b after a, and not before it
                boundary, skip = 'seq', 2 if tokens[i + 1] == 'then' else 3
                if clauses[-1].tokens:
                    clauses.append(_Clause('seq', []))
                clauses[-1].connector, clauses[-1].strict = 'seq', True
                i += skip
                continue
            if t == 'then' and (i + 1 >= n or not _starts(tokens, i + 1, [','])):
                boundary, skip = 'seq', 1
            elif _starts(tokens, i, ['and', 'then']) or _starts(tokens, i, [',', 'then']) or \
                    _starts(tokens, i, [',', 'and', 'then']):
                skip = 3 if tokens[i + 1] == 'and' else 2
                boundary = 'seq'
            elif _starts(tokens, i, ['after', 'that']) or _starts(tokens, i, ['and', 'after', 'that']):
                boundary, skip = 'seq', 2 if t == 'after' else 3
            elif t in ('finally', 'afterwards', 'afterward', 'lastly') or _starts(
                    tokens, i, ['and', 'finally']):
                boundary, skip = 'seq', 1 if t != 'and' else 2
            elif _starts(tokens, i, ['once', 'you', 'are', 'there']) or _starts(
                    tokens, i, ['once', 'there']) or _starts(tokens, i, ['when', 'you', 'are', 'there']) or \
                    _starts(tokens, i, ['once', 'you', 'get', 'there']) or _starts(
                        tokens, i, ['once', 'you', 'reach', 'it']):
                boundary = 'there'
                skip = 2 if tokens[i + 1] == 'there' else 4
            elif (_starts(tokens, i, ['before', 'doing', 'that']) or _starts(tokens, i, ['before', 'that'])
                  ) and (any(c.tokens for c in clauses) or self.task.chain) and \
                    'sure' not in clauses[-1].tokens and \
                    'visited' not in tokens[i:]:
                boundary, skip = 'pre', 3 if tokens[i + 1] == 'doing' else 2
            elif t == 'always' and 0 < i < n - 1 and tokens[i + 1] in ('avoid', 'stay', 'keep') and \
                    tokens[i - 1] not in (',', 'and', 'but', 'while'):
                boundary, skip = 'and', 0
                if clauses[-1].tokens:
                    clauses.append(_Clause('and', []))
                clauses[-1].tokens.append(t)
                i += 1
                continue
            elif 0 < i < n - 1 and self._opens_run_on(tokens, i):
                # "go to a do not go to b": a new clause without a comma
                if clauses[-1].tokens:
                    clauses.append(_Clause('and', []))
                clauses[-1].tokens.append(t)
                i += 1
                continue
            elif t in STRONG_VERBS and 0 < i < n - 1 and tokens[i - 1] not in NOT_BEFORE_VERB and not \
                    tokens[i - 1].endswith('ly') and (
                    tokens[i + 1] in GOAL_PARTICLES or tokens[i + 1] in DETS or (
                        self.phrases.landmarks and self.phrases._landmark(tokens, i + 1) is not None)):
                if clauses[-1].tokens:
                    clauses.append(_Clause('seq', []))
                clauses[-1].tokens.append(t)
                i += 1
                continue
            elif t in (',', 'and', 'but', 'so', 'while', 'or') and i > 0:
                j = i + 1
                while j < n and tokens[j] in (',', 'and', 'but', 'so'):
                    j += 1
                if t == 'while' and j < n and tokens[j] in ('avoiding', 'staying', 'keeping', 'never'):
                    boundary, skip = 'and', 1
                elif t == 'or' and j < n and tokens[j] in GOAL_VERBS | DELIVER_VERBS:
                    boundary, skip = 'or', j - i
                elif j < n and tokens[j] in CLAUSE_STARTERS and t != 'while' and not (
                        tokens[j] in ('at', 'in', 'on', 'twice', 'three', 'exactly', 'order', 'and')
                        and not _starts(tokens, j, ['on', 'the', 'way']) and not _starts(
                            tokens, j, ['on', 'your', 'way'])):
                    boundary, skip = 'and', j - i
            if boundary:
                if clauses[-1].tokens:
                    clauses.append(_Clause(boundary, []))
                elif boundary != 'and':
                    clauses[-1].connector = boundary
                if boundary == 'there':
                    while i + skip < n and tokens[i + skip] == ',':
                        skip += 1
                i += skip
                continue
            clauses[-1].tokens.append(t)
            i += 1
        return [c for c in clauses if c.tokens]

    def _opens_run_on(self, tokens: list[str], i: int) -> bool:
        """Whether a prohibition or an obligation starts at ``i`` right after a noun phrase or a count.

        Typed or transcribed instructions often run clauses together ("never go to a never go to
        b", "visit the den at least once do not go to the hall before the den"); a clause opener
        right after the end of a phrase starts a new clause.
        """
        prev = tokens[i - 1]
        landmark = any(tuple(tokens[i - len(lm):i]) == lm for lm in self.phrases.landmarks)
        if not landmark and (prev in NOT_BEFORE_VERB or prev in PUNCT or prev in RUN_ON_NOT_AFTER):
            return False
        counted = prev in ('once', 'twice', 'thrice', 'times', 'again')
        if not (landmark or counted or is_name_word(tokens, i - 1, True)):
            return False
        nxt = tokens[i + 1]
        if tokens[i] == 'do':
            return nxt in ('not', 'no')
        if tokens[i] == 'never':
            return nxt in AVOID_FILLER or nxt in GOAL_VERBS
        if tokens[i] == 'not':
            return nxt == 'to'   # "visit a not to visit b before a not to visit c before b"
        if tokens[i] == 'leave':
            return nxt in ('and', 'then', ',', 'it', 'there')   # "go to a leave and then come back"
        if tokens[i] in ('ensure', 'make'):
            return tokens[i] == 'ensure' or nxt == 'sure'
        if tokens[i] == 'you':
            verb = tokens[i + 2] if i + 2 < len(tokens) else ''
            return nxt in ('must', 'cannot', 'should', 'have', 'need', 'can', 'may', 'are') and (
                verb in GOAL_VERBS or verb in AVOID_FILLER or verb in ('not', 'never', 'to', 'only'))
        return False

    # ----------------------------------------------------------------- clauses
    def _read_clause(self, clause: _Clause, scope: Optional[_Scope]) -> Optional[_Scope]:
        """Read one clause; returns the scope that carries to the next clause of the sentence."""
        had_chain, n_constraints = bool(self.task.chain), len(self.task.constraints)
        try:
            return self._read_clause_body(clause, scope)
        finally:
            if not had_chain and self.task.chain and self.task.chain_at is None:
                # an until-constraint read in the same clause as its goal comes first
                self.task.chain_at = len(self.task.constraints) if self._until_first(n_constraints) else 0

    def _until_first(self, n: int) -> bool:
        new = self.task.constraints[n:]
        return bool(new) and all(isinstance(c, Until) for c in new) and len(self.task.chain) == 1 and \
            self.task.chain[0].kind == 'visit' and all(
                isinstance(c.right, Atom) and c.right.args[0] in self.task.chain[0].targets for c in new)

    def _read_clause_body(self, clause: _Clause, scope: Optional[_Scope]) -> Optional[_Scope]:
        tokens = self._strip_fillers(clause.tokens)
        if not tokens:
            return scope
        s = ' '.join(tokens)
        if s.startswith('either way'):
            tokens = tokens[2:]
        elif len(tokens) > 2 and tokens[0] == 'either' and tokens[1] in GOAL_VERBS:
            tokens = tokens[1:]   # "either fly over the lake or over the forest": the list says 'or'
        new_scope, tokens = self._leading_scope(tokens)
        if new_scope is not None:
            scope = new_scope
            tokens = self._strip_fillers(tokens)
            if not tokens:
                return scope
        s = ' '.join(tokens)
        if s.endswith((' is fine', ' is okay', ' are fine', ' is ok')) or s in IGNORED_CLAUSES or \
                s.startswith(('because ', 'since ', 'so that ', 'do not want the ', 'i do not want the ',
                              'i do not care', 'as ', 'do not care', 'do not mind', 'i do not mind')):
            return scope
        if tokens == ['visit', 'each', 'place', 'only', 'once']:
            self.no_revisits = True   # the canonical wording of "no revisiting" (see idioms)
            return scope
        if tuple(tokens) in STRICT_ORDER_TAILS:
            self.strict_chain = True   # "in strictly this order, visit a, then b"
            return scope
        if s in ('not both', 'but not both', 'not both of them'):
            self._exclusive_or()
            return scope
        if tokens[0] in ('twice', 'thrice', 'once') or (len(tokens) > 1 and tokens[1] == 'times') or \
                tokens[0] in ('exactly', 'at') and len(tokens) < 5:
            step = self.task.last_step(('visit',))
            if step is not None:
                self.task.chain.remove(step)
                ok, rest = self._read_count(tokens, step.targets[:1])
                if ok and not rest:
                    return scope
                self.task.chain.append(step)
        for lead in (['there', 'is'], ['there', 'are'], ['i', 'see'], ['i', 'can', 'see'], ['we', 'have'],
                     ['here', 'is'], ['where', 'is'], ['you', 'will', 'see'], ['you', 'can', 'see']):
            if _starts(clause.tokens, 0, lead) or _starts(tokens, 0, lead):
                # sets the scene: the things named are remembered for "it" / "there", not goals
                body = tokens[len(lead):] if _starts(tokens, 0, lead) else tokens
                nps, _, _ = self._np_list(body, 0)
                if nps:
                    self.last_object = nps[-1]
                    self.mentions.extend(np.descriptor for np in nps)
                    return scope
        if self._is_permission(tokens):
            self._read_permission(tokens)
            return scope
        if self._read_patrol(tokens):
            self.saw_action = True
            return scope
        if self._read_passive_avoid(tokens):
            self.saw_action = True
            return scope
        for tail in (['are', 'all', 'visited'], ['are', 'visited'], ['is', 'visited'], ['are', 'reached'],
                     ['is', 'reached'], ['get', 'visited'], ['gets', 'visited'], ['are', 'all', 'reached']):
            if tokens[-len(tail):] == tail and len(tokens) > len(tail):
                tokens = ['visit'] + tokens[:-len(tail)]
                break
        raw = [t for t in clause.tokens if t not in PUNCT]
        first_flag = bool(raw) and (raw[-1] == 'first' or raw[:2] == ['but', 'first'] or (
            raw[0] == 'first' and clause.connector == 'and'))
        if self._read_stay_within(tokens):
            return scope
        if tokens[0] == 'only' and len(tokens) > 1 and tokens[1] == 'if':
            tokens = tokens[1:]
        if tokens[0] == 'if':
            self.saw_action = True
            self._read_conditional(tokens)
            return scope
        if tokens[0] in ('travelling', 'traveling', 'going', 'passing', 'via') and self.task.chain and \
                clause.connector == 'and':
            first_flag = True
        if self._avoid_start(tokens) is not None and 'first' in tokens[:4] and self.task.chain:
            first_flag = True
        ordering = tokens[:2] in (['not', 'until'], ['not', 'before'], ['only', 'after'])
        if first_flag and self.task.chain and clause.connector == 'and' and self.conditional is None:
            if self._avoid_start(tokens) is not None and not ordering:
                self.saw_action = True
                self._read_avoid(tokens, _Scope('onway'))
                return scope
            clause = _Clause('pre', clause.tokens, first=True)
        if tokens[0] == 'only' and len(tokens) > 1 and tokens[1] in GOAL_VERBS | DELIVER_VERBS:
            tokens = tokens[1:]
            self.only = True
        if tokens[0] == 'before' and len(tokens) > 2:
            k = self._skip_event_verbs(tokens, 1)
            np = self.phrases.parse(tokens, k)
            if np is not None and np.end == len(tokens) and k > 1:
                self.before_target = np.descriptor   # the next goal comes first, then this
                return scope
        if self._read_ordering(tokens, clause):
            return scope
        if self._avoid_start(tokens) is not None:
            self.saw_action = True
            if clause.connector == 'there' and scope is None and self.last_place is not None:
                scope = _Scope('after', self.last_place)   # "once you're there, never go back to Y"
            self._read_avoid(tokens, scope)
            return scope
        if tokens[0] in ('leave', 'exit') and self._read_leave(tokens[1:]):
            return scope
        if (tokens[0] in DELIVER_VERBS or tokens[0] in PICK_VERBS) and scope is not None and \
                scope.kind == 'after' and scope.target is not None and \
                self.task.find_step(scope.target.descriptor) is None:
            # "when you get to the kitchen, grab a spoon": the kitchen first
            self.task.chain.append(Step('visit', [scope.target.descriptor]))
        if tokens[0] in DELIVER_VERBS or tokens[0] in PICK_VERBS or _starts(tokens, 0, ['throw', 'away']):
            if self._read_delivery(tokens, clause):
                self.saw_action = True
                return scope
        self._read_goal(tokens, clause, scope)
        return scope

    def _read_leave(self, rest: list[str]) -> bool:
        """Read 'leave (X)' after a visit of X: be away from it ("go to a, leave, then go to a again")."""
        last = self.task.last_step(('visit',))
        if last is None or len(last.targets) != 1:
            return False
        target = last.targets[0]
        if rest and rest not in (['it'], ['there'], ['here']):
            nps, _, end = self._np_list(rest, 0)
            if len(nps) != 1 or end != len(rest) or self.task.find_step(nps[0].descriptor) is None:
                return False
            target = nps[0].descriptor
        self.saw_action = True
        self.task.chain.append(Step('leave', [target]))
        return True

    @staticmethod
    def _strip_fillers(tokens: list[str]) -> list[str]:
        i = 0
        adverbs = ('secondly', 'thirdly', 'firstly')
        while i < len(tokens) - 1 and (tokens[i] == 'always' and tokens[i + 1] in GOAL_VERBS or (
                tokens[i] in ORDINALS or tokens[i] in adverbs) and tokens[i + 1] == ','):
            i += 2 if tokens[i + 1] == ',' else 1
        while i < len(tokens) and (tokens[i] in FILLERS or tokens[i] == ',') and not (
                tokens[i] in ORDINALS and _ordinal_name(tokens, i)):
            if tokens[i] == 'make' and not _starts(tokens, i, ['make', 'sure']):
                break
            if tokens[i] == 'i' and i + 1 < len(tokens) and tokens[i + 1] in ('need', 'want', 'would'):
                i += 2
                continue
            if tokens[i] == 'to' and i + 1 < len(tokens) and tokens[i + 1] == 'the':
                break
            i += 1
            if i < len(tokens) - 1 and tokens[i] == 'always' and tokens[i + 1] in GOAL_VERBS:
                i += 1
        out = tokens[i:]
        while out and (out[-1] in (',', 'please', 'too', 'now', 'again', 'thanks', 'first', 'instead', 'ok',
                                   'okay', 'then', 'as', 'well', 'after', 'afterwards', 'afterward') or (
                out[-1] in ('second', 'third', 'fourth', 'fifth') and len(out) > 1 and out[-2] != 'the')):
            if out[-1] == 'well' and len(out) > 1 and out[-2] == 'as':
                out = out[:-2]
                continue
            out = out[:-1]
        return out

    def _leading_scope(self, tokens: list[str]) -> tuple[Optional[_Scope], list[str]]:
        """Scope phrases that open a clause: "on the way to X,", "once you've reached X,", "after ..."."""
        for lead in (['on', 'the', 'way'], ['on', 'your', 'way'], ['along', 'the', 'way'],
                     ['on', 'its', 'way']):
            if _starts(tokens, 0, lead):
                rest = tokens[len(lead):]
                if _starts(rest, 0, ['from', 'there']):
                    rest = rest[2:]
                if rest and rest[0] in ('to', 'towards', 'toward'):
                    np = self.phrases.parse(rest, 1)
                    if np is not None:
                        return _Scope('onway', self._resolve(np, place=True)), rest[np.end:]
                if rest and rest[0] == 'there':
                    return _Scope('onway'), rest[1:]
                if rest and rest[0] == 'back':
                    return _Scope('onway'), rest[1:]
                if lead[0] == 'on' and self.task.chain:
                    return _Scope('onway'), rest   # "go to X, and on the way avoid Y"
                return _Scope('global'), rest
        if tokens[0] in ('once', 'after', 'when', 'while') and len(tokens) > 1:
            sc, end = self._event_phrase(tokens, 1)
            if sc is not None:
                return sc, tokens[end:]
        return None, tokens

    def _event_phrase(self, tokens: list[str], i: int) -> tuple[Optional[_Scope], int]:
        """After "once/after/while": the event (reaching X, picking it up, dropping it off, carrying it)."""
        j = i
        while j < len(tokens) and tokens[j] in ('you', 'have', 'are', 'i', 'it', 'is', 'been', 'the',
                                                'robot'):
            j += 1
        if j >= len(tokens):
            return None, i
        w = tokens[j]
        if w in ('going', 'navigating', 'heading', 'travelling', 'traveling', 'walking', 'flying', 'driving',
                 'moving') and tokens[i - 1] in ('while', 'when'):
            k = j + 1
            while k < len(tokens) and tokens[k] in GOAL_PARTICLES:
                k += 1
            np = self.phrases.parse(tokens, k)
            if np is not None:
                return _Scope('onway', self._resolve(np, place=True), 'while'), np.end
        if w in ('carrying', 'holding', 'transporting', 'bringing', 'taking', 'moving', 'returning'):
            k = j + 1
            np = self.phrases.parse(tokens, k)
            end = np.end if np is not None else k
            if end < len(tokens) and tokens[end] in ('back', 'over'):
                end += 1
            return _Scope('carry'), end
        if w in ('picked', 'grabbed', 'got', 'gotten', 'collected', 'fetched', 'pick', 'grab', 'picking'):
            k = j + 1
            if k < len(tokens) and tokens[k] == 'up':
                k += 1
            np = self.phrases.parse(tokens, k)
            end = np.end if np is not None else k
            if np is not None and not np.pronoun:
                self.last_object = np
            if end < len(tokens) and tokens[end] == 'up':
                end += 1
            return _Scope('after_pick'), end
        if w in ('dropped', 'delivered', 'released', 'put', 'placed', 'left', 'drop', 'deliver', 'dropping',
                 'delivering'):
            k = j + 1
            np = self.phrases.parse(tokens, k)
            end = np.end if np is not None else k
            while end < len(tokens) and tokens[end] in ('off', 'down'):
                end += 1
            return _Scope('after_release'), end
        if tokens[i - 1] == 'while' and w in ('go', 'walk', 'drive', 'fly', 'head', 'move', 'travel', 'get'):
            k = j + 1
            while k < len(tokens) and tokens[k] in GOAL_PARTICLES - {'there', 'here'}:
                k += 1
            if k < len(tokens) and tokens[k] in ('there', 'here'):
                return _Scope('onway'), k + 1
            np = self.phrases.parse(tokens, k)
            if np is not None:
                return _Scope('onway', self._resolve(np, place=True)), np.end
        k = j
        while k < len(tokens) and tokens[k] in NAME_VERBS | GOAL_PARTICLES | EVENT_WORDS:
            if tokens[k] == 'there':
                step = self.task.last_step(('visit', 'deliver'))
                return _Scope('after', self.last_place if step else None), k + 1
            k += 1
        if k == j:
            return None, i
        np = self.phrases.parse(tokens, k)
        if np is None:
            return None, i
        return _Scope('after', self._resolve(np, place=True)), np.end

    def _resolve(self, np: NounPhrase, place: bool = False) -> NounPhrase:
        if np.pronoun in ('there', 'here') and self.last_place is not None:
            return self.last_place
        if np.pronoun in ('it', 'them', 'that') and self.last_object is not None and not place:
            return self.last_object
        if np.pronoun in ('it', 'them', 'that') and place and self.last_place is not None:
            return self.last_place
        return np

    def _np_list(self, tokens: list[str], i: int, place: bool = True, destination_stops: bool = False
                 ) -> tuple[list[NounPhrase], str, int]:
        nps, joiner, end = self.phrases.parse_list(tokens, i, destination_stops)
        nps = [self._resolve(np, place) for np in nps]
        if nps and place:
            self.last_place = nps[-1]
        return nps, joiner, end

    # ----------------------------------------------------------------- kinds of clause
    def _avoid_start(self, tokens: list[str]) -> Optional[int]:
        i = 0
        softeners = ('while', 'and', 'but', 'always', 'also', 'please', 'by', 'just', 'so', 'then')
        while i < len(tokens) - 1 and tokens[i] in softeners:
            i += 1
        for trig in _AVOID_BY_FIRST.get(tokens[i] if i < len(tokens) else '', ()):
            if _starts(tokens, i, trig):
                k = i + len(trig)
                if _starts(tokens, k, ['let']):
                    return None
                while k < len(tokens) and tokens[k] in AVOID_FILLER:
                    k += 1
                return k
        return None

    def _read_avoid(self, tokens: list[str], scope: Optional[_Scope]) -> None:
        k = self._avoid_start(tokens)
        assert k is not None
        nps, _, end = self._np_list(tokens, k, place=False)
        if not nps:
            raise TranslationError(f'could not place what to avoid in "{" ".join(tokens)}"',
                                   details={'part': ' '.join(tokens)})
        targets = [np.descriptor for np in nps]
        rest, _ = _strip_tails([t for t in tokens[end:] if t != ','])
        # "more than once / more than N times" is a count, not an avoidance.
        rest = normalize_counts(rest)
        if _starts(rest, 0, ['at', 'least']) or _starts(rest, 0, ['at', 'most']):
            # "do not visit a at least three times": at most two; "... at most two times": three or more
            n = self._count_word(rest, 2)
            if n is None:
                raise TranslationError(f'could not read the count in "{" ".join(tokens)}"',
                                       details={'part': ' '.join(rest)})
            for d in targets:
                if rest[1] == 'least':
                    self.task.constraints.append(
                        at_most(_near(d), n[0] - 1) if n[0] > 1 else Always(Not(_near(d))))
                else:
                    self.task.chain.extend(
                        [Step('visit', [d]), Step('leave', [d])] * n[0] + [Step('visit', [d])])
            self._check_leftover(rest[n[1]:], tokens)
            return
        if rest and rest[0] == 'exactly' or _starts(rest, 0, ['any', 'fewer', 'than']) or _starts(
                rest, 0, ['fewer', 'than']) or _starts(rest, 0, ['less', 'than']) or _starts(
                rest, 0, ['any', 'less', 'than']):
            # "do not visit a more or fewer than N times" / "never go to a less than N times"
            exact = rest[0] == 'exactly'
            j = 1 if exact else (3 if rest[0] == 'any' else 2)
            n = self._count_word(rest, j)
            if n is None:
                raise TranslationError(f'could not read the count in "{" ".join(tokens)}"',
                                       details={'part': ' '.join(rest)})
            for d in targets:
                if exact:
                    self.task.constraints.append(exactly(_near(d), n[0]))
                else:
                    self.task.chain.extend(
                        [Step('visit', [d]), Step('leave', [d])] * (n[0] - 1) + [Step('visit', [d])])
            self._check_leftover(rest[n[1]:], tokens)
            return
        again = bool({'revisit', 'revisiting', 'reenter'} & set(tokens[:k]))
        if again or rest and rest[0] in ('anymore', 'again') or (
                _starts(rest, 0, ['any', 'more']) and len(rest) == 2):
            visits = {d: sum(1 for st in self.task.chain if st.kind == 'visit' and st.targets == [d])
                      for d in targets}
            if all(visits.values()):
                for d, n_visits in visits.items():   # "visit a twice and never again": exactly that many
                    if n_visits == 1:
                        # "go to a, then b, without returning to a": a once (see once_scope)
                        step = self.task.find_step(d)
                        assert step is not None
                        step.once = 'exactly'
                    else:
                        self.task.constraints.append(at_most(_near(d), n_visits))
                return
        for lead in (['on', 'any', 'more', 'than'], ['on', 'more', 'than'], ['any', 'more', 'than'],
                     ['more', 'than']):
            if _starts(rest, 0, lead):
                rest = ['more', 'than'] + rest[len(lead):]
                break
        if _starts(rest, 0, ['more', 'than']):
            j = 2
            n = self._count_word(rest, j)
            if n is None:
                raise TranslationError(f'could not read the count in "{" ".join(tokens)}"',
                                       details={'part': ' '.join(rest)})
            for d in targets:
                self.task.constraints.append(at_most(_near(d), n[0]))
            self._check_leftover(rest[n[1]:], tokens)
            return
        if rest and rest[0] in ('through', 'via') and len(nps) == 1:
            # "avoid going to X through Y": Y is avoided on the way to X
            via, _, vend = self._np_list(rest, 1, place=False)
            if via:
                goal = nps[0].descriptor
                step = self.task.find_step(goal)
                if step is None:
                    step = Step('visit', [goal])
                    self.task.chain.append(step)
                step.avoid_until.extend(v.descriptor for v in via)
                self._check_leftover(rest[vend:], tokens)
                return
        if len(rest) > 1 and rest[0] == 'to' and rest[1] in GOAL_VERBS and rest[1] not in (
                'be', 'you', 'i', 'can', 'could', 'would', 'will', 'then', 'and', 'to', 'up', 'down', 'back'):
            # "always avoid the cellar to get to the porch": the goal, with the avoidance read as if after it
            self._read_goal(rest[1:], _Clause('and', rest[1:]), None)
            rest = []
        local, rest = self._trailing_scope(rest)
        if local is not None:
            scope = local
        elif scope is None and 'through' in tokens[:k] and len(self.task.chain) == 1 and (
                {'without', 'avoid', 'avoiding', 'not', 'never'} & set(tokens[:k])):
            scope = _Scope('onway')   # "go to X, avoid going through Y": on the way to X
        harmless = ('at', 'all', 'times', 'the', 'whole', 'time', 'entire', 'ever', 'please', 'way', 'along',
                    'throughout', 'any', 'point', 'either', 'too', 'as', 'well', 'again', 'forever',
                    'anymore', 'costs', 'instant', 'moment')
        leftover = [t for t in rest if t not in harmless]
        if leftover and leftover[0] not in ('when', 'while'):
            raise TranslationError(f'could not place "{" ".join(leftover)}" in "{" ".join(tokens)}"',
                                   details={'part': ' '.join(leftover)})
        self._apply_avoid(targets, scope)

    def _trailing_scope(self, rest: list[str]) -> tuple[Optional[_Scope], list[str]]:
        if not rest:
            return None, rest
        if rest[0] == 'without' and len(rest) > 2 and rest[1] in ('visiting', 'reaching', 'going', 'first'):
            rest = ['until'] + rest[1:]
        if rest[0] == 'until' or rest[0] == 'before' or _starts(rest, 0, ['unless']):
            j = 1
            while j < len(rest) and rest[j] in ('you', 'have', 'i', 'we', 'are', 'been', 'the', 'robot',
                                                'has', 'after', 'finally', 'first', 'successfully'):
                j += 1
            event = 'near'
            if j < len(rest) and rest[j] in ('got', 'gotten', 'picked', 'grabbed', 'collected', 'fetched',
                                             'get', 'pick', 'grab', 'retrieved'):
                if self.last_object is not None and (j + 1 >= len(rest) or rest[j + 1] in (
                        'it', 'them', 'up')):
                    return _Scope('until', self.last_object, 'pick'), []
                event = 'pick' if rest[j] not in ('got', 'gotten', 'get') else 'near'
            skippable = NAME_VERBS | GOAL_PARTICLES | EVENT_WORDS | {'picked', 'grabbed', 'up'}
            while j < len(rest) and rest[j] not in ('there', 'here') and rest[j] in skippable:
                j += 1
            nps, _, end = self._np_list(rest, j)
            if nps:
                return _Scope('until', nps[0], event), rest[end:]
        if _starts(rest, 0, ['on', 'the', 'way']) or _starts(rest, 0, ['on', 'your', 'way']) or \
                _starts(rest, 0, ['along', 'the', 'way']):
            sc, rem = self._leading_scope(rest)
            if sc is not None and _starts(rest, 0, ['along', 'the', 'way']):
                return _Scope('global'), rem
            return sc, rem
        if rest[0] in ('while', 'when', 'after', 'once'):
            sc, end = self._event_phrase(rest, 1)
            if sc is not None:
                return sc, rest[end:]
        return None, rest

    def _apply_avoid(self, targets: list[Descriptor], scope: Optional[_Scope]) -> None:
        if self.choice is not None:
            step = self.task.last_step(('visit',))
            if step is not None and self.choice in step.targets:
                chains = []
                for d in step.targets:
                    extra = [Step('formula', formula=f) for f in _never(targets)] if d == self.choice else []
                    chains.append(extra + [Step('visit', [d])])
                step.kind, step.targets, step.chains = 'any', [], chains
            self.choice = None
            return
        kind = scope.kind if scope is not None else 'global'
        if kind == 'until' and scope is not None and scope.target is not None:
            d = scope.target.descriptor
            known = self.task.find_step(d, scope.target.head)
            if known is not None and d not in known.targets + known.dests and known.targets:
                d = known.targets[0]  # "the landmark" names the goal already given
            if scope.event == 'pick':
                self.task.constraints.append(_until_avoid(targets, Atom('pick', (d,))))
            else:
                self.task.constraints.append(_until_avoid(targets, _near(d)))
                if self.task.find_step(d) is None and not self.task.chain:
                    self.task.chain.append(Step('visit', [d]))  # so that "then ..." comes after it
            return
        if kind == 'onway' and self.avoid_scope == 'goal' and scope is not None and scope.event == 'while' \
                and scope.target is not None:
            step = self.task.find_step(scope.target.descriptor)
            if step is None:
                step = Step('visit', [scope.target.descriptor])
                self.task.chain.append(step)
            step.avoid_at.extend(targets)
            return
        if kind == 'onway':
            step: Optional[Step]
            if scope is not None and scope.target is not None:
                step = self.task.find_step(scope.target.descriptor)
                if step is None:
                    step = Step('visit', [scope.target.descriptor])
                    self.task.chain.append(step)
            else:
                step = self.task.last_step(('visit', 'deliver'))
            if step is None:
                self.task.constraints.extend(_never(targets))
            elif step.kind == 'deliver':
                step.carry_avoid.extend(targets)
            else:
                step.avoid_until.extend(targets)
            return
        if kind == 'carry':
            step = self.task.last_step(('deliver',))
            if step is not None:
                step.carry_avoid.extend(targets)
                return
        if kind == 'after_pick':
            step = self.task.last_step(('deliver', 'pick'))
            if step is not None:
                step.after_pick_avoid.extend(targets)
                return
        if kind == 'after_release':
            step = self.task.last_step(('deliver',))
            if step is not None:
                step.after_release_avoid.extend(targets)
                return
        if kind == 'after' and scope is not None and scope.target is not None:
            step = self.task.find_step(scope.target.descriptor, scope.target.head)
            if step is None and not self.task.chain:
                # no goal to hang it on: "once you have visited a, avoid b" holds whenever a happens
                a = _near(scope.target.descriptor)
                never = _and(*_never(targets))
                assert never is not None
                self.task.constraints.append(Always(Implies(a, Next(never))))
                return
            if step is None:
                step = Step('visit', [scope.target.descriptor])
                self.task.chain.append(step)
            if step.kind == 'deliver':
                step.after_release_avoid.extend(targets)
            else:
                step.avoid_after.extend(targets)
            return
        if self.avoid_scope == 'global':
            for d in targets:
                g = Always(Not(_near(d)))
                self.global_avoids.append((d, self.task.last_step(('visit', 'deliver')), g))
        if self.avoid_scope == 'goal':
            step = self.task.last_step(('visit',))
            if step is not None and step is self.task.chain[-1]:
                step.avoid_at.extend(targets)
            else:
                self.pending_avoid_at.extend(targets)
            return
        self.task.constraints.extend(_never(targets))

    def _read_passive_avoid(self, tokens: list[str]) -> bool:
        """Read passive avoidance: 'a and b cannot be visited', 'none of a, b are visited'."""
        none = tokens[:1] == ['none']
        nps, _, end = self._np_list(tokens, 0, place=False)
        if not nps:
            return False
        rest = tokens[end:]
        neg = ('cannot', 'never', 'not')
        if not (none and rest[:1] in (['are'], ['is'], ['can'], ['should'], ['must']) or
                any(w in rest[:3] for w in neg) and rest[:1] != ['is'] and rest and rest[0] in (
                    'cannot', 'can', 'should', 'must', 'may', 'are', 'is', 'will', 'shall')):
            return False
        if not any(w in rest for w in ('visited', 'reached', 'true', 'entered', 'approached', 'seen', 'hold',
                                       'occur', 'happen', 'touched', 'gone', 'passed')):
            return False
        self.task.constraints.extend(_never([np.descriptor for np in nps]))
        return True

    def _read_patrol(self, tokens: list[str]) -> bool:
        """'keep visiting a and b without stopping', 'visit a infinitely often' -> ``G F near[a] & ...``."""
        if self._avoid_start(tokens) is not None and not {'stop', 'stopping', 'cease', 'quit'} & set(tokens):
            return False
        s = ' ' + ' '.join(tokens) + ' '
        marks = (' infinitely', ' infinite ', ' forever', ' keep visiting ', ' keep going to ',
                 ' not stop visiting ',
                 ' never stop visiting ', ' without stopping', ' repeatedly', ' continuously', ' endlessly',
                 ' over and over', ' frequent ', ' keep on visiting ', ' indefinitely', ' again and again',
                 ' keep revisiting ', ' continually', ' constantly', ' unlimited ', ' perpetually',
                 ' continue to stop ', ' continue visiting ', ' continue going ', ' not stop ',
                 ' cannot stop ', ' never stop ', ' keep on ', ' continue moving ', ' continue to visit ',
                 ' continue to go ', ' keep going between ', ' back and forth ', ' cycle through ',
                 ' ever stop ', ' cease ', ' always visiting ', ' finite number of times ', ' keep moving ',
                 ' keep patrolling ', ' continue patrolling ')
        if not any(m in s for m in marks):
            return False
        nps: list[NounPhrase] = []
        i = 0
        while i < len(tokens):
            if tokens[i] in DETS and not self.phrases.landmarks or (self.phrases.landmarks and
                                                                    self.phrases._landmark(tokens, i)):
                found, _, end = self._np_list(tokens, i)
                if found:
                    nps.extend(found)
                    i = end
                    continue
            if tokens[i] not in PATROL_WORDS and not any(tokens[i] in m.split() for m in marks):
                return False   # words the patrol reading would drop: leave them to the other readers
            i += 1
        if not nps:
            return False
        for np in nps:
            self.task.constraints.append(Always(Eventually(_near(np.descriptor))))
        return True

    @staticmethod
    def _is_permission(tokens: list[str]) -> bool:
        s = ' ' + ' '.join(tokens) + ' '
        return any(p in s for p in (' you can ', ' you may ', ' stay put ', ' be done ', ' free to ',
                                    ' you are allowed ', ' it is okay to ', ' it is fine to ', ' or stop ',
                                    ' stay there ', ' can then ', ' may then ', ' or stay ', ' can now ',
                                    ' or continue ')
                   ) and ' not ' not in s and ' can only ' not in s and ' there until ' not in s

    def _read_permission(self, tokens: list[str]) -> None:
        """'...then you can go to Y': an avoidance of Y that was pending ends where the goal is reached."""
        names = set()
        start = next((i for i, t in enumerate(tokens)
                      if t in ('can', 'may', 'free', 'allowed', 'or', 'then')), 0)
        for i in range(start, len(tokens)):
            if tokens[i] in DETS or (i > 0 and tokens[i - 1] in ('to', 'visit', 'enter', 'at')):
                np = self.phrases.parse(tokens, i)
                if np is not None and not np.pronoun:
                    names.add(np.descriptor)
        steps = [st for st in self.task.chain if st.kind == 'visit']
        if not steps:
            return
        for st in steps:
            moved = [d for d in st.avoid_at if d in names]
            if moved:
                st.avoid_at = [d for d in st.avoid_at if d not in names]
                st.avoid_until.extend(moved)
        moved = [d for d in self.pending_avoid_at if d in names]
        if moved:
            self.pending_avoid_at = [d for d in self.pending_avoid_at if d not in names]
            steps[-1].avoid_until.extend(moved)
        # "once you reach X you may go to Y": Y is not allowed before X
        targets = {d for st in self.task.chain for d in st.targets}
        avoided = {d for st in steps for d in st.avoid_until + st.avoid_at}
        never = {c.operand.operand.args[0] for c in self.task.constraints
                 if isinstance(c, Always) and isinstance(c.operand, Not)
                 and isinstance(c.operand.operand, Atom)}
        for d in sorted(names - targets - avoided - never, key=str):
            steps[-1].avoid_until.append(d)
        for f in list(self.task.constraints):
            if isinstance(f, Always) and isinstance(f.operand, Not) and \
                    isinstance(f.operand.operand, Atom) and f.operand.operand.args[0] in names:
                self.task.constraints.remove(f)
                steps[-1].avoid_until.append(f.operand.operand.args[0])

    def _read_stay_within(self, tokens: list[str]) -> bool:
        """'stay on the third floor [while going to X]' -> ``G near[floor]``; '... until Y' -> ``U``."""
        if tokens and tokens[0] in ('while', 'and', 'but', 'by', 'always'):
            tokens = tokens[1:]
        leads = _STAY_BY_FIRST.get(tokens[0] if tokens else '', ())
        if len(tokens) > 1 and tokens[0] in ('staying', 'remaining', 'keeping', 'stay', 'remain') and \
                tokens[1] in ('in', 'on', 'within', 'inside'):
            leads = (tuple(tokens[:2]),)
        if len(tokens) > 3 and tokens[0] in ('wait', 'stay', 'remain') and tokens[1] in ('there', 'here') \
                and tokens[2] in ('until', 'till'):
            # "go to the hall and wait there until you see the guard": at the goal, until then
            step = self.task.last_step(('visit',))
            j = self._skip_event_verbs(tokens, 3)
            more, _, e2 = self._np_list(tokens, j)
            if step is None or not more or e2 != len(tokens):
                return False
            step.hold_until.append(more[0].descriptor)
            return True
        for lead in leads:
            if _starts(tokens, 0, lead):
                nps, _, end = self._np_list(tokens, len(lead))
                if not nps:
                    return False
                self.saw_action = True
                rest = [t for t in tokens[end:] if t != ',']
                region = _and(*[_near(np.descriptor) for np in nps])
                assert region is not None
                if rest and rest[0] in ('until', 'till', 'before') or _starts(rest, 0, ['as', 'long', 'as']):
                    j = 3 if rest[0] == 'as' else 1
                    j = self._skip_event_verbs(rest, j)
                    more, _, e2 = self._np_list(rest, j)
                    if more:
                        self.task.constraints.append(Until(region, _near(more[0].descriptor)))
                        return True
                self.task.constraints.append(Always(region))
                while rest and rest[0] in ('while', 'and', 'to', 'as', 'when', 'but', 'then'):
                    rest = rest[1:]
                if rest:
                    self._read_goal(rest, _Clause('and', rest), None)
                return True
        return False

    def _exclusive_or(self) -> None:
        """'X or Y but not both': one of them, and never the other."""
        step = self.task.last_step(('visit',))
        if step is None or len(step.targets) < 2:
            raise TranslationError('"not both" needs two alternatives before it',
                                   details={'part': 'not both'})
        chains = []
        for d in step.targets:
            others = [o for o in step.targets if o != d]
            chains.append([Step('formula', formula=f) for f in _never(others)] + [Step('visit', [d])])
        step.kind, step.targets, step.chains = 'any', [], chains

    def _read_conditional(self, tokens: list[str]) -> None:
        """Read 'if you go into X at all, check Y first' as ``!near[x] W near[y]``."""
        j = 1
        while j < len(tokens) and tokens[j] in NAME_VERBS | GOAL_PARTICLES | EVENT_WORDS | {
                'you', 'ever', 'want', 'do', 'choose', 'pick', 'decide', 'reach', 'are', 'have', 'already'}:
            j += 1
        np = self.phrases.parse(tokens, j)
        if np is None:
            raise TranslationError(f'could not place the condition "{" ".join(tokens)}"',
                                   details={'part': ' '.join(tokens)})
        rest = [t for t in tokens[np.end:] if t not in ('at', 'all')]
        if 'choose' in tokens[:j] or 'pick' in tokens[:j] or 'decide' in tokens[:j]:
            # "if you choose X, avoid Y": the avoidance binds only that alternative.
            rest = self._strip_fillers(rest)
            step = self.task.last_step(('visit',))
            if not rest and step is not None and np.descriptor in step.targets:
                self.choice = np.descriptor
                return
            if step is None or np.descriptor not in step.targets or self._avoid_start(rest) is None:
                raise TranslationError(f'could not place the condition "{" ".join(tokens)}"',
                                       details={'part': ' '.join(tokens)})
            k = self._avoid_start(rest)
            assert k is not None
            nps, _, _ = self._np_list(rest, k, place=False)
            chains = []
            for d in step.targets:
                extra = [Step('formula', formula=f) for f in _never([n.descriptor for n in nps])] \
                    if d == np.descriptor else []
                chains.append(extra + [Step('visit', [d])])
            step.kind, step.targets, step.chains = 'any', [], chains
            return
        rest = self._strip_fillers(rest)
        if self._is_permission(rest):
            return
        if not rest and tokens[j - 1] in ('reached', 'reach', 'arrived', 'arrive', 'are', 'get', 'got',
                                          'been'):
            return  # "if you reached X, (then you may ...)": a condition for a permission
        k = 0
        while k < len(rest) and rest[k] in NAME_VERBS | GOAL_PARTICLES:
            k += 1
        first = self.phrases.parse(rest, k)
        if first is None:
            self.conditional = np
            return
        self.task.constraints.append(WeakUntil(Not(_near(np.descriptor)), _near(first.descriptor)))

    def _read_ordering(self, tokens: list[str], clause: _Clause) -> bool:
        """Read 'only after X', 'not before X', 'not until you've been to X and Y', 'X before that'."""
        s = tokens
        k = -1
        for lead in (['only', 'after'], ['not', 'before'], ['not', 'until'], ['but', 'only', 'after'],
                     ['only', 'once'], ['only', 'when'], ['not', 'till']):
            if _starts(s, 0, lead):
                k = len(lead)
                break
        if k >= 0:
            prev = self.task.last_step(('visit', 'deliver'))
            if prev is None:
                return False
            picked = any(w in s[k:k + 4] for w in ('picked', 'grabbed', 'collected', 'fetched'))
            k = self._skip_event_verbs(s, k)
            if picked:
                while k < len(s) and s[k] in ('up', 'picked', 'grabbed', 'collected', 'fetched'):
                    k += 1
                obj = self.phrases.parse(s, k)
                if obj is None:
                    return False
                obj = self._resolve(obj)
                for x in prev.targets:
                    self.task.constraints.append(Until(Not(_near(x)), Atom('pick', (obj.descriptor,))))
                self.task.chain.insert(self.task.chain.index(prev), Step('pick', [obj.descriptor]))
                self._check_leftover(s[obj.end:], s)
                return True
            nps, _, end = self._np_list(s, k)
            if not nps:
                return False
            for x in prev.targets:
                for np in nps:
                    self.task.constraints.append(Until(Not(_near(x)), _near(np.descriptor)))
            self._check_leftover(s[end:], s)
            return True
        if s[-2:] == ['before', 'that'] or s[-3:] == ['before', 'doing', 'that']:
            prev = self.task.last_step(('visit', 'deliver'))
            k = self._skip_event_verbs(s, 2)
            nps, _, end = self._np_list(s, k)
            if prev is None or not nps:
                return False
            for x in prev.targets:
                for np in nps:
                    self.task.constraints.append(Until(Not(_near(x)), _near(np.descriptor)))
            return True
        return False

    @staticmethod
    def _skip_event_verbs(s: list[str], k: int) -> int:
        while k < len(s) and s[k] in NAME_VERBS | GOAL_PARTICLES | EVENT_WORDS | {
                'you', 'have', 'i', 'are', 'both', 'robot', 'has', 'make', 'sure', 'first'}:
            k += 1
        return k

    def _check_leftover(self, rest: list[str], whole: list[str]) -> None:
        rest = [t for t in rest if t not in (',', 'please', 'first', 'too', 'again', 'then')]
        if rest:
            raise TranslationError(f'could not place "{" ".join(rest)}" in "{" ".join(whole)}"',
                                   details={'part': ' '.join(rest)})

    def _count_word(self, tokens: list[str], i: int) -> Optional[tuple[int, int]]:
        """Return the count at ``tokens[i]`` (once, twice, three times) and where it ends."""
        if i >= len(tokens):
            return None
        w = tokens[i]
        if w in ('once', 'twice', 'thrice'):
            return NUMBER_WORDS[w], i + 1
        units = ('times', 'time', 'occasions', 'visits', 'instances', 'separate', 'different', 'distinct')
        if (w in NUMBER_WORDS or w.isdigit()) and i + 1 < len(tokens) and tokens[i + 1] in units:
            k = i + 1
            while k < len(tokens) and tokens[k] in units:
                k += 1
            return (int(w) if w.isdigit() else NUMBER_WORDS[w]), k
        if w in ('on', 'in') and i + 1 < len(tokens):
            j = i + 1
            if tokens[j] in NUMBER_WORDS or tokens[j].isdigit():
                n = int(tokens[j]) if tokens[j].isdigit() else NUMBER_WORDS[tokens[j]]
                k = j + 1
                while k < len(tokens) and tokens[k] in ('separate', 'different', 'distinct', 'occasions',
                                                        'instances', 'times', 'visits', 'occasion'):
                    k += 1
                if k > j + 1:
                    return n, k
        return None

    def _read_count(self, rest: list[str], targets: list[Descriptor]) -> tuple[bool, list[str]]:
        """Read counting phrases after a goal: at least / at most / exactly / N times / in a row."""
        rest = normalize_counts(rest)
        mode = 'at_least'
        i = 0
        if _starts(rest, 0, ['exactly']) or _starts(rest, 0, ['only']) or _starts(rest, 0, ['just']):
            mode, i = 'exactly', 1
        elif _starts(rest, 0, ['at', 'least']) or _starts(rest, 0, ['no', 'less', 'than']) or _starts(
                rest, 0, ['not', 'less', 'than']) or _starts(rest, 0, ['no', 'fewer', 'than']):
            mode, i = 'at_least', 2 if rest[0] == 'at' else 3
        elif _starts(rest, 0, ['at', 'most']) or _starts(rest, 0, ['no', 'more', 'than']) or _starts(
                rest, 0, ['not', 'more', 'than']) or _starts(rest, 0, ['max']) or _starts(
                rest, 0, ['maximum']) or _starts(rest, 0, ['up', 'to']):
            mode, i = 'at_most', 2 if rest[0] in ('at', 'up') else (1 if rest[0] in ('max', 'maximum') else 3)
        c = self._count_word(rest, i)
        if c is None:
            return False, rest
        n, end = c
        if rest[i] == 'once' and end < len(rest) and rest[end] in ('you', 'i', 'we', 'the', 'it', 'that'):
            return False, rest   # "once you have been to a": a conjunction, no count
            self.task.repeat = n
            return True, rest[end + 3:]
        if self.only and mode == 'at_least' and i == 0:
            mode = 'exactly'   # "only visit a once"
        for d in targets:
            x = _near(d)
            known = self.task.find_step(d)
            if n == 1 and mode in ('exactly', 'at_most') and known is not None and known.kind == 'visit' and \
                    known.targets == [d]:
                known.once = 'exactly'   # "go to a, then b; visit each of them only once"
                continue
            if n == 1 and mode in ('exactly', 'at_least') and not (mode == 'at_least' and i > 0):
                # "visit a exactly once", "go to a once, then b": see once_scope
                self.task.chain.append(Step('visit', [d], once='exactly' if mode == 'exactly' else 'plain'))
            elif mode == 'at_least':
                for k in range(n):
                    if k:
                        self.task.chain.append(Step('leave', [d]))
                    self.task.chain.append(Step('visit', [d]))
            elif mode == 'exactly':
                self.task.constraints.append(exactly(x, n))
                self.task.chain.append(Step('visit', [d]))
            else:
                self.task.constraints.append(at_most(x, n))
        return True, rest[end:]

    def _read_delivery(self, tokens: list[str], clause: _Clause) -> bool:
        """Read a delivery, and a second one said with the verb left out.

        "Put the plate in the sink and the cup in the dishwasher": both, in either order.
        """
        dests = ('in', 'on', 'into', 'onto', 'to', 'at', 'inside')
        if tokens[0] in PUT_VERBS | {'bring', 'take', 'carry', 'move', 'deliver'}:
            for k in range(2, len(tokens) - 3):
                if tokens[k] == 'and' and tokens[k + 1] in DETS and \
                        any(t in dests for t in tokens[1:k]) and any(t in dests for t in tokens[k + 2:]):
                    n = len(self.task.chain)
                    if not (self._read_delivery_one(tokens[:k], clause) and
                            self._read_delivery_one(tokens[:1] + tokens[k + 1:], clause)):
                        return False
                    if len(self.task.chain) == n + 2:   # both, in either order
                        first, second = self.task.chain[n:]
                        self.task.chain[n:] = [Step('all', chains=[[first], [second]])]
                    return True
        return self._read_delivery_one(tokens, clause)

    def _read_delivery_one(self, tokens: list[str], clause: _Clause) -> bool:
        verb = tokens[0]
        k = 1
        implicit_dest: Optional[Descriptor] = None
        binned = verb in ('bin', 'dump', 'chuck') and 'in' not in tokens
        if verb == 'throw' and 'away' in tokens[:4] or binned:
            implicit_dest = TRASH
        if _starts(tokens, 0, ['pick', 'up']) or _starts(tokens, 0, ['throw', 'away']) or _starts(
                tokens, 0, ['throw', 'out']):
            k = 2
        elif tokens[0] == 'get' and _starts(tokens, 1, ['rid', 'of']):
            k, implicit_dest = 3, TRASH
        while k < len(tokens) and tokens[k] in ('me', 'up', 'back', 'off', 'down', 'us'):
            k += 1
        objs, joiner, end = self._np_list(tokens, k, place=False, destination_stops=verb in PUT_VERBS)
        if not objs:
            return False
        rest = tokens[end:]
        if rest and rest[0] == 'from' and len(objs) == 1:
            # "the blanket from the closet": where the object is, as a nearness relation
            src = self.phrases.parse(rest, 1, destination_stops=True)
            if src is not None and not src.pronoun:
                o = objs[0]
                d = Descriptor(o.descriptor.name, o.descriptor.relations + (
                    Relation('isnextto', (src.descriptor,)),))
                objs = [NounPhrase(d, o.start, o.end, o.head)]
                self.notes.append(f'"from {src.descriptor}" read as {d}')
                rest = rest[src.end:]
        for o in objs:
            self.last_object = o
        while rest and rest[0] in ('up', 'back', 'over', 'away', 'out', 'down', 'off', 'along'):
            if rest[0] == 'away' and verb in ('throw', 'toss', 'put'):
                implicit_dest = TRASH
            rest = rest[1:]
        if verb in PICK_VERBS and (not rest or rest[0] not in ('to', 'into', 'in', 'on', 'onto', 'at')):
            # a plain pick; a following "and bring it to X" turns it into a delivery.
            for o in objs:
                self.task.chain.append(Step('pick', [o.descriptor]))
            self._check_leftover(rest, tokens)
            return True
        dests: list[NounPhrase] = []
        if rest and rest[0] in ('there', 'here') and self.last_place is not None:
            dests, rest = [self.last_place], rest[1:]
        elif rest and rest[0] in ('to', 'into', 'in', 'on', 'onto', 'at', 'inside', 'by', 'next',
                                  'under', 'near', 'beside', 'over', 'with'):
            j = 1
            if _starts(rest, 0, ['next', 'to']):
                j = 2
            while j < len(rest) and rest[j] in ('the', 'top', 'of') and _starts(rest, j, ['top', 'of']):
                j += 2
            if j < len(rest) and rest[j] in ('me', 'us'):
                j += 1
                if j < len(rest) and rest[j] in ('at', 'by', 'in', 'near', 'next'):
                    j += 2 if _starts(rest, j, ['next', 'to']) else 1
            dests, _, dend = self._np_list(rest, j)
            rest = rest[dend:]
        elif implicit_dest is None:
            if verb in ('take', 'bring', 'get', 'fetch', 'grab'):
                dests = []
            else:
                return False
        dest_ds = [d.descriptor for d in dests] or ([implicit_dest] if implicit_dest else [])
        if implicit_dest is not None and not dests:
            self.notes.append('"throw away" releases the object at the implicit trash_can')
        if not dest_ds:
            self._check_leftover(rest, tokens)
            for o in objs:
                self.task.chain.append(Step('pick', [o.descriptor]))
            return True
        ok, rest = self._read_count(rest, dest_ds)
        without = []
        if rest and rest[0] == 'without':
            without, rest = rest, []
        rest = [t for t in rest if t not in (',', 'too', 'please', 'instead', 'as', 'well', 'again')]
        if rest and rest[0] in ('while', 'when', 'on', 'along', 'and', 'without'):
            sc, rem = self._trailing_scope(rest)
            if sc is None and rest[0] == 'and':
                pass
            rest = rem
        if rest[:1] in (['after'], ['once']) or rest[:2] == ['only', 'after']:
            # "deliver the letter to the mailbox (only) after you have visited the post office": that first
            k = self._skip_event_verbs(rest, 2 if rest[0] == 'only' else 1)
            first, _, end = self._np_list(rest, k)
            if first and end == len(rest):
                self.task.chain.extend(Step('visit', [np.descriptor]) for np in first)
                rest = []
        self._check_leftover(rest, tokens)
        # "pick up X and put it on Y": the pick step becomes the delivery.
        obj_ds = [o.descriptor for o in objs]
        last = self.task.chain[-1] if self.task.chain else None
        if last is not None and last.kind == 'pick' and last.targets[0] in obj_ds and len(obj_ds) == 1:
            last.kind, last.dests = 'deliver', list(dest_ds)
            if without:
                self._read_avoid(without, _Scope('carry'))
            return True
        steps = [Step('deliver', [o], list(dest_ds)) for o in obj_ds]
        if len(steps) == 1:
            self.task.chain.append(steps[0])
        else:
            self.task.chain.append(Step('any' if joiner == 'or' else 'all', chains=[[s] for s in steps]))
        if without:   # "take it to X without passing Y": while carrying it
            self._read_avoid(without, _Scope('carry'))
        return True

    def _read_goal(self, tokens: list[str], clause: _Clause, scope: Optional[_Scope]) -> None:
        k = 0
        if _starts(tokens, 0, ['take', 'off']):
            k = 2
            while k < len(tokens) and tokens[k] in ('and', ','):
                k += 1
        patrol_from = False
        if _starts(tokens, 0, ['go', 'to', 'or', 'through']):
            k = 4
        while k < len(tokens) and (tokens[k] in GOAL_VERBS or tokens[k] in GOAL_PARTICLES) and not (
                tokens[k] in ORDINALS and _ordinal_name(tokens, k)) and not (
                tokens[k] in ('there', 'here') and (k + 1 >= len(tokens) or tokens[k + 1] not in DETS)
        ) and not (tokens[k] == 'back' and k + 1 < len(tokens)
                   and tokens[k + 1] in ('door', 'gate', 'yard', 'room', 'porch')):
            if tokens[k] in ('from', 'through', 'via') and k > 0:
                patrol_from = True
            k += 1
        nps, joiner, end = self._np_list(tokens, k)
        if not nps:
            raise TranslationError(f'could not place "{" ".join(tokens)}"',
                                   details={'part': ' '.join(tokens)})
        if k > 0 or clause.connector in ('seq', 'pre', 'or'):
            self.saw_action = True
        rest, ordered_tail = _strip_tails([t for t in tokens[end:] if t != ','])
        targets = [np.descriptor for np in nps]
        if patrol_from and rest and rest[0] == 'to':
            more, _, e2 = self._np_list(rest, 1)
            if more:
                targets += [np.descriptor for np in more]
                joiner = 'then'
                rest = rest[e2:]
        # "X in that order" / "in any order"
        ordered = bool(ordered_tail)
        strict = clause.strict
        if ordered_tail == 'strict':
            self.strict_chain = True
        for phrase in (['in', 'that', 'order'], ['in', 'order'], ['in', 'this', 'order'],
                       ['one', 'after', 'the', 'other']):
            if _starts(rest, 0, phrase):
                ordered, rest = True, rest[len(phrase):]
        for phrase in (['in', 'any', 'order'], ['order', 'does', 'not', 'matter'],
                       ['in', 'whatever', 'order'],
                       ['in', 'either', 'order'], ['whichever'], ['i', 'do', 'not', 'care', 'which'],
                       ['in', 'arbitrary', 'order'], ['in', 'no', 'particular', 'order']):
            if _starts(rest, 0, phrase):
                rest = rest[len(phrase):]
        rest = [t for t in rest if t != ',']
        c = self._count_word(rest, 0)
        if c is not None and _starts(rest, c[1], ['in', 'a', 'row']):
            self.task.repeat = c[0]
            rest = rest[c[1] + 3:]
        if scope is not None and scope.kind == 'after' and scope.target is not None and \
                self.task.find_step(scope.target.descriptor) is None:
            # "after you visit a, go to b": a first (a rule when said as one: see reactions)
            self.task.chain.append(Step('visit', [scope.target.descriptor]))
        counted, rest = self._read_count(rest, targets)
        if counted:
            if len(rest) > 1 and rest[0] == 'and' and rest[1] in DETS:
                self._read_goal(['visit'] + rest[1:], _Clause('seq', rest[1:]), None)
                return
            self._goal_trailer(rest, tokens, targets)
            return
        tail: list[Step] = []
        same = next((st for st in self.task.chain if st.kind == 'visit' and st.targets == targets), None)
        if clause.first and same is not None and len(targets) == 1 and not rest:
            # "go to the fridge, then the oven. actually, go to the oven first": the oven moves first
            self.task.chain = [same] + [st for st in self.task.chain if st is not same]
            self.last_goal = same
            return
        if clause.connector == 'pre' and self.task.chain:
            # "..., before that, go to X": X before the goal of the clause before
            chain = self.task.chain
            k = 0 if clause.first else next((i for i, st in enumerate(chain) if st is self.last_goal),
                                            len(chain) - 1)   # "..., but go to X first": before them all
            tail, self.task.chain = chain[k:], chain[:k]
            self._add_targets(targets, joiner, ordered)
        else:
            before = self.task.last_step(('visit', 'deliver'))
            self._add_targets(targets, joiner, ordered)
            if strict:
                self._strict_order(before, targets, joiner)
        new_step = self.task.chain[-1]
        self.connector = clause.connector
        if self.before_target is not None:
            known = next((st for st in self.task.chain[:-1] if st.kind == 'visit'
                          and st.targets == [self.before_target]), None)
            if known is not None:
                # "visit b, but before visiting b you must visit a": a moves before that b
                new = self.task.chain.pop()
                self.task.chain.insert(self.task.chain.index(known), new)
            else:
                self.task.chain.append(Step('visit', [self.before_target]))
                targets = [self.task.chain[-1].targets[0]]
            self.before_target = None
        self._goal_trailer(rest, tokens, targets)
        self.task.chain.extend(tail)
        self.last_goal = new_step
        if self.conditional is not None:
            self.task.constraints.append(WeakUntil(Not(_near(self.conditional.descriptor)),
                                                   _near(targets[0])))
            self.task.chain = [st for st in self.task.chain if st is not new_step]
            self.conditional = None

    def _after_goals(self, moved: Step, others: list[Descriptor], again: bool) -> None:
        """'go to X after Y': Y then X; a Y or an X given as a goal before is that goal, not a new one.

        Unless said again ("go back to X after Y"): then X is visited once more.
        """
        chain = self.task.chain
        known = {tuple(st.targets) for st in chain if st.kind == 'visit'}
        new = [d for d in others if (d,) not in known]
        same = next((st for st in chain if st.kind == 'visit' and st.targets == moved.targets), None)
        if same is not None and moved.kind == 'visit' and not again:
            # "go to c after b. go to b after a": a goes before the b already given
            k = chain.index(same)
            chain[k:k] = [Step('visit', [d]) for d in new]
            return
        chain.extend(Step('visit', [d]) for d in new)
        chain.append(moved)

    def _strict_order(self, before: Optional[Step], targets: list[Descriptor], joiner: str) -> None:
        """'go to a, and only then go to b': this clause's goals not before the goal before them."""
        prev = before.targets if before is not None and before.kind == 'visit' else (
            before.dests if before is not None else [])
        if prev:
            for d in targets if joiner == 'or' else targets[:1]:
                self.task.constraints.append(Until(Not(_near(d)), _or([_near(p) for p in prev])))

    def _add_targets(self, targets: list[Descriptor], joiner: str, ordered: bool) -> None:
        if len(targets) == 1 or joiner == 'or':
            self.task.chain.append(Step('visit', list(targets)))
        elif ordered or joiner == 'then':
            self.task.chain.extend(Step('visit', [t]) for t in targets)
        else:
            self.task.chain.append(Step('all', chains=[[Step('visit', [t])] for t in targets]))

    def _goal_trailer(self, rest: list[str], whole: list[str], targets: list[Descriptor]) -> None:
        """Read what may follow a goal: "before Y", "after Y", "through Y", an avoidance."""
        drop = (',', 'please', 'first', 'too', 'again', 'then', 'instead')
        rest = [t for t in rest if t != ',']
        while rest and rest[-1] in drop:
            rest = rest[:-1]
        while rest and rest[0] in drop and not (rest[0] == 'first' and _ordinal_name(rest, 0)):
            rest = rest[1:]
        if not rest:
            return
        only, self.only = self.only, False
        r0 = rest[1:] if rest[0] in ('while', 'and', 'but', 'by', 'then') else rest
        if self._read_stay_within(r0) or (r0 is not rest and self._read_stay_within(rest)):
            return
        if rest[0] == 'only':
            only, rest = True, rest[1:]
        if not rest:
            return
        if rest and rest[0] in ('once', 'when') and len(rest) > 1:
            rest = ['after'] + rest[1:]
        if rest and rest[0] in ('before', 'after', 'through', 'via', 'by', 'past') and len(rest) > 1:
            word = rest[0]
            k = self._skip_event_verbs(rest, 1)
            nps, _, end = self._np_list(rest, k)
            if nps:
                others = [np.descriptor for np in nps]
                moved = self.task.chain.pop()
                if word == 'before' and k > 1:  # "before going to Y": the route order only
                    self.task.chain.append(moved)
                    self.task.chain.extend(Step('visit', [d]) for d in others)
                elif word == 'before':
                    # "A before B" is "B only after A": F b & (!b U a) (the U makes a required)
                    self.task.chain.extend(Step('visit', [d]) for d in others)
                    for d in others:
                        for x in targets:
                            self.task.constraints.append(Until(Not(_near(d)), _near(x)))
                elif only and word == 'after':
                    # "X only after Y": F x & (!x U y), X not in sequence after the goals said before it
                    if self.task.chain and self.connector != 'seq':
                        self.task.chain = [Step('all', chains=[self.task.chain, [moved]])]
                    else:
                        self.task.chain.append(moved)
                    for d in others:
                        for x in targets:
                            self.task.constraints.append(Until(Not(_near(x)), _near(d)))
                elif word == 'after':
                    self._after_goals(moved, others, again=bool({'again', 'back', 'return'} & set(whole)))
                else:
                    self.task.chain.extend(Step('visit', [d]) for d in others)
                    self.task.chain.append(moved)
                self._goal_trailer(rest[end:], whole, targets)
                return
        if rest[0] == 'always' and len(rest) > 2 and rest[1] in ('passing', 'going', 'moving'):
            rest = ['by'] + rest[1:]   # "go to X always passing through Y": by passing through Y
        if rest[0] == 'by' and len(rest) > 2:
            j = 2 if rest[1] == 'first' else 1
            if rest[j].endswith('ing') and rest[j] not in ('avoiding', 'staying', 'remaining', 'keeping'):
                k = self._skip_event_verbs(rest, j + 1)
                nps, _, end = self._np_list(rest, k)
                if nps:
                    moved = self.task.chain.pop()
                    self.task.chain.extend(Step('visit', [np.descriptor]) for np in nps)
                    self.task.chain.append(moved)
                    self._goal_trailer(rest[end:], whole, targets)
                    return
        for lead in (['on', 'your', 'way', 'to'], ['on', 'the', 'way', 'to'], ['and', 'then', 'to'],
                     ['followed', 'by'], ['and', 'then'],
                     ['to', 'get', 'to'], ['in', 'order', 'to', 'get', 'to'], ['to', 'reach'],
                     ['to', 'go', 'to'],
                     ['then', 'to'], ['and', 'to'], ['to']):
            if _starts(rest, 0, lead) and self.task.chain:
                nps, _, end = self._np_list(rest, len(lead))
                if nps:
                    self.task.chain.extend(Step('visit', [np.descriptor]) for np in nps)
                    self._goal_trailer(rest[end:], whole, [np.descriptor for np in nps])
                    return
        if self._avoid_start(rest) is not None or rest[0] in ('while', 'avoiding', 'without'):
            if self._avoid_start(rest) is not None:
                self._read_avoid(rest, None)
                return
        if rest[0] in ('while', 'on', 'along', 'when', 'until'):
            sc, rem = self._trailing_scope(rest)
            if sc is not None and sc.kind == 'global':
                self._check_leftover(rem, whole)
                return
        raise TranslationError(f'could not place "{" ".join(rest)}" in "{" ".join(whole)}"',
                               details={'part': ' '.join(rest)})

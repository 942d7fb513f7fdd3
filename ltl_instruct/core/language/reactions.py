"""Rules that hold whenever something happens: triggers and their responses.

"Whenever you pass the kitchen, check the fridge", "as soon as you reach the door you
must go to the mat", "once you have visited a you cannot go to b": a trigger (an event,
opened by "whenever", "once", "as soon as", "after", "if"...) and a response (a goal or
an avoidance, said in either order with it). Read as rules over the whole run:

- delayed response: ``G (t -> F r)`` ("..., you have to visit b later");
- prompt response: ``G (t -> X r)`` ("immediately", "right after", "at the next time step");
- response said before the trigger ("visit a right before b"): ``G (X b -> a)``;
- avoidance from then on: ``G (t -> X G !r)`` ("once you visit a, never go to b").

When is "after X, do Y" such a rule rather than a sequence? A trigger that is always
a rule ("whenever", "every time", "if") or a prompt response makes one; "after/once/when"
makes one when the response is an obligation ("you must", "you have to", "b must be
visited") or an avoidance, and the trigger is no goal given before (then the clause
reader scopes it to that goal instead). A plain command ("after you visit a, go to b")
stays a sequence, and so, by the conventions, does an avoidance after "after" or said as a
command after an opening "once" ("once you've been to a, stay clear of b": a is a goal, b
avoided after it), unless ``after_scope='conditional'`` asks for the rule. Anything the
rule reader cannot place leaves the sentence to the clause reader (and to its errors).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

from ltl_instruct.core.language.phrases import NAME_VERBS, PhraseParser
from ltl_instruct.core.spec import Always, And, Atom, Descriptor, Eventually, Formula, Implies, Next, Not, Or

# (words, always a rule?)
TRIGGERS: tuple[tuple[tuple[str, ...], bool], ...] = tuple(sorted((
    (('whenever',), True), (('every', 'time'), True), (('each', 'time'), True), (('any', 'time'), True),
    (('anytime',), True), (('if',), True), (('as', 'soon', 'as'), False), (('right', 'after'), False),
    (('immediately', 'after'), False), (('directly', 'after'), False), (('just', 'after'), False),
    (('once',), False), (('after',), False), (('when',), False), (('the', 'moment'), False),
    (('right', 'before'), False), (('immediately', 'before'), False), (('just', 'before'), False),
    (('if', 'and', 'only', 'if'), True), (('only', 'and', 'only', 'if'), True), (('only', 'if'), True),
), key=lambda t: -len(t[0])))
# "b at the next step if and only if a": b exactly when a was just before
IFF_TRIGGERS = frozenset({('if', 'and', 'only', 'if'), ('only', 'and', 'only', 'if')})
# Triggers that make the response prompt by themselves ("as soon as you reach a, go to b").
PROMPT_TRIGGERS = frozenset({('as', 'soon', 'as'), ('right', 'after'), ('immediately', 'after'),
                             ('directly', 'after'), ('just', 'after'), ('the', 'moment')})
# Words after the event's place: "a occurs", "you see a happen".
EVENT_TAIL = frozenset({'occur', 'occurs', 'happen', 'happens', 'hold', 'holds', 'true', 'first', 'already',
                        'there'})
EVENT_TAIL_PHRASES = (('at', 'any', 'time'), ('at', 'all'), ('at', 'any', 'point'), ('ever',))

# Words before the event's place: "you have ever been to", "you arrive at", "you visit".
EVENT_LEAD = frozenset('''
you i we the robot drone have has had ever first already are is been do does did get got gotten reach
reached reaching visit visited visiting go went gone going arrive arrived arriving at to in into enter
entered entering
pass passed passing through by find found come came pass see saw seen observe observed spot spotted touch
touched hit land landed fly flew over step stepped walk walked move moved head headed make made your way
navigate navigated travel travelled traveled want wish decide choose plan
'''.split())

# Words of obligation in a response ("you must", "you have to", "b should be visited").
OBLIGATION = frozenset({'must', 'have', 'has', 'need', 'needs', 'should', 'shall', 'required', 'means',
                        'mean', 'will', 'ought'})
# Words of a response before its goal verb.
RESPONSE_LEAD = frozenset('''
you then must have has to need needs should shall will also make sure ensure that proceed required are is
always ought it means mean be so can may ,
'''.split())
# Timing: immediate words and phrases make a prompt response.
IMMEDIATE: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('immediately',), ('right', 'after', 'that'), ('right', 'after'), ('right', 'away'), ('at', 'once'),
    ('directly', 'after'), ('straight', 'after'), ('the', 'next', 'time', 'step'),
    ('in', 'the', 'next', 'time', 'step'), ('at', 'the', 'next', 'time', 'step'),
    ('at', 'the', 'next', 'step'),
    ('at', 'the', 'very', 'next', 'time', 'step'), ('at', 'the', 'next', 'time', 'instant'),
    ('at', 'the', 'very', 'next', 'time', 'instant'), ('in', 'the', 'very', 'next', 'time', 'instant'),
    ('in', 'the', 'next', 'time', 'instant'), ('in', 'the', 'very', 'next', 'time', 'step'),
    ('immediately', 'afterward'), ('immediately', 'afterwards'), ('immediately', 'after', 'that'),
    ('right', 'next'), ('next',), ('without', 'delay'), ('straight', 'away'), ('straightaway',),
    ('right',), ('directly',), ('in', 'the', 'next', 'step'), ('at', 'the', 'next', 'instant'),
), key=lambda t: -len(t)))
# Timing that adds nothing to "F" ("later", "at least once in the future").
LATER: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('later',), ('afterwards',), ('afterward',), ('after', 'that'), ('after', 'it'), ('in', 'the', 'future'),
    ('some', 'time', 'in', 'the', 'future'), ('sometime', 'in', 'the', 'future'), ('at', 'least', 'once'),
    ('at', 'least', 'one', 'time'), ('once', 'afterwards'), ('once', 'afterward'), ('eventually',),
    ('at', 'some', 'point'), ('too',), ('as', 'well'), ('then',), ('after',), ('some', 'time', 'later'),
    ('sometime',), ('sometime', 'later'), ('in', 'response', 'to', 'it'), ('in', 'response'), ('again',),
    ('from', 'then', 'on'), ('from', 'now', 'on'), ('any', 'more'), ('anymore',), ('ever', 'again'),
    ('at', 'all', 'costs'), ('after', 'this'), ('later', 'on'), ('at', 'any', 'time'), ('ever',),
    ('from', 'that', 'point', 'on'), ('thereafter',), ('also',),
), key=lambda t: -len(t)))
# Timing of a rule, never of a plain command: "you have to visit b in the future".
FUTURE = frozenset({('later',), ('in', 'the', 'future'), ('some', 'time', 'in', 'the', 'future'),
                    ('sometime', 'in', 'the', 'future'), ('later', 'on'), ('some', 'time', 'later')})
# "go nowhere but b": only b next
NOWHERE_BUT: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('go', 'nowhere', 'but'), ('go', 'nowhere', 'else', 'but'), ('go', 'nowhere', 'except'),
    ('go', 'nowhere', 'else', 'except'), ('visit', 'nowhere', 'else', 'except'), ('visit', 'nowhere', 'but'),
    ('visit', 'nowhere', 'else', 'but'), ('visit', 'nowhere', 'except'),
    ('do', 'not', 'go', 'to', 'anywhere', 'but'),
    ('do', 'not', 'go', 'anywhere', 'but'), ('do', 'not', 'go', 'anywhere', 'except'),
    ('do', 'not', 'go', 'to', 'anywhere', 'except'), ('do', 'not', 'go', 'anywhere', 'else', 'but'),
    ('do', 'not', 'go', 'anywhere', 'else', 'except'), ('go', 'nowhere', 'other', 'than'),
), key=lambda t: -len(t)))
BEFORE_THAT: tuple[tuple[str, ...], ...] = (
    ('right', 'before', 'that'), ('immediately', 'before', 'that'), ('just', 'before', 'that'),
    ('right', 'before'), ('immediately', 'before'), ('just', 'before'), ('before', 'that'),
)
# What makes a response an avoidance.
AVOID_LEAD: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('avoid',), ('stay', 'away', 'from'), ('keep', 'away', 'from'), ('cannot',), ('can', 'not'),
    ('can', 'never'), ('must', 'not'), ('must', 'never'), ('should', 'not'), ('should', 'never'), ('never',),
    ('do', 'not'), ('not',), ('may', 'not'), ('are', 'not', 'allowed', 'to'),
    ('are', 'never', 'allowed', 'to'),
    ('stay', 'clear', 'of'), ('keep', 'clear', 'of'), ('stay', 'out', 'of'), ('keep', 'out', 'of'),
    ('steer', 'clear', 'of'),
), key=lambda t: -len(t)))
GOAL_WORDS = NAME_VERBS | frozenset('''
to at by in into over through on the your way find reach visit go head move proceed get arrive enter pass
make walk fly drive travel navigate come return be visited reached there back up down off onto toward towards
'''.split())
# Where "and" starts a new rule ("... and you cannot go to b any other time").
SPLIT_AFTER_AND = frozenset({'you', 'if', 'once', 'whenever', 'after', 'when', 'always', 'immediately',
                             'right', 'every', 'each'})
PASSIVE_AUX = frozenset({'must', 'should', 'has', 'have', 'to', 'needs', 'need', 'will', 'shall', 'is',
                         'also', 'always'})
# Verbs the noun-phrase reader would take for a name ("b must occur").
NOT_PLACES = frozenset({'occur', 'happen', 'hold', 'occurs', 'happens', 'holds', 'visited', 'reached',
                        'true'})
PASSIVE_GOAL = (('be', 'visited'), ('be', 'reached'), ('occur',), ('happen',), ('hold',), ('be', 'true'),
                ('become', 'true'), ('be', 'entered'), ('be', 'observed'), ('be', 'seen'), ('hold', 'true'))


@dataclass
class _Response:
    places: list[Descriptor]
    avoid: bool
    prompt: bool
    before: bool        # said before the trigger: "visit a right before b"
    obliged: bool
    permitted: bool = False   # "you can go to b", "you may ..."


def _match(tokens: Sequence[str], i: int, phrases: Sequence[tuple[str, ...]]) -> int:
    for p in phrases:
        if tuple(tokens[i:i + len(p)]) == p:
            return len(p)
    return 0


def _imperative_avoid(rest: Sequence[str]) -> bool:
    """Whether a response is an avoidance said as a command ("avoid Y", "stay clear of Y", "never go to")."""
    words = [w for w in rest if w != ',']
    while words and words[0] in ('then', 'also', 'just', 'please'):
        words = words[1:]
    return bool(words) and words[0] in ('avoid', 'stay', 'keep', 'steer', 'never', 'do')


class RuleReader:
    """Reads a whole sentence as trigger-response rules, or gives ``None`` to leave it to the clauses."""

    def __init__(self, phrases: PhraseParser, conditional_after: bool = False) -> None:
        self.phrases = phrases
        self.conditional_after = conditional_after   # "after X, avoid Y" as a rule (lang2ltl)

    # ------------------------------------------------------------------ entry
    def read(self, tokens: list[str], goals: Sequence[Descriptor]) -> Optional[list[Formula]]:
        """Formulas of the rules said in ``tokens``, or None when it is not (only) rules.

        ``goals`` are the places already given as goals: a trigger at one of them scopes a
        clause to that goal, which the clause reader does.
        """
        words = list(tokens)
        self.always = False
        while words and words[0] in ('and', 'also', 'then', ','):
            words = words[1:]
        for lead in (['at', 'any', 'point', 'in', 'time'], ['for', 'all', 'times', 'in', 'the', 'future'],
                     ['at', 'all', 'times'], ['for', 'all', 'time'], ['at', 'any', 'time'], ['always']):
            if words[:len(lead)] == lead:
                words, self.always = words[len(lead):], True   # "always, once you see a, ..." is a rule
                while words and words[0] == ',':
                    words = words[1:]
        if not words:
            return None
        out: list[Formula] = []
        for part in self._split(words):
            got = self._rule(part, goals, out)
            if got is None:
                return None
            out.extend(got)
        return out or None

    def _permission(self, words: list[str], goals: Sequence[Descriptor]) -> Optional[list[Formula]]:
        """Read "you can go to a, but you must go to b (right after)": the permitted place triggers."""
        if words[:2] not in (['you', 'can'], ['you', 'may']) or 'but' not in words:
            return None
        k = words.index('but')
        if not any(w in OBLIGATION or w in ('cannot', 'never', 'not') for w in words[k + 1:k + 4]):
            return None
        if self._trigger(words, k) is not None:
            return self._rule(words[k + 1:], goals, [])
        events = [e for e, end in self._events(words, 2) if end == k]
        if not events:
            return None
        return self._respond(words[k + 1:], 0, events[0], 0, True, False, False, goals, said_first=True)

    def _split(self, words: list[str]) -> list[list[str]]:
        """Split rules said one after the other.

        At "and" before a new subject or trigger ("and you cannot..."), or at a second trigger
        once a rule that opened with its trigger is complete ("if a, go to b if b, ...").
        """
        parts: list[list[str]] = [[]]
        i = 0
        while i < len(words):
            w = words[i]
            nxt = words[i + 1] if i + 1 < len(words) else ''
            if w == 'and' and parts[-1] and nxt in SPLIT_AFTER_AND:
                parts.append([])
                i += 1
                continue
            if len(parts[-1]) > 3 and self._trigger_at(words, i) is not None and \
                    self._trigger_at(parts[-1], 0) is not None:
                parts.append([])   # a rule that opened with its trigger is complete: a new one begins
            parts[-1].append(w)
            i += 1
        return [p for p in parts if p]

    # ------------------------------------------------------------------ one rule
    def _rule(self, words: list[str], goals: Sequence[Descriptor], sofar: list[Formula]
              ) -> Optional[list[Formula]]:
        other = self._any_other_time(words, sofar)
        if other is not None:
            return other
        permitted = self._permission(words, goals)
        if permitted is not None:
            return permitted
        found = self._trigger(words)
        if found is None:
            return self._means(words, goals)
        start, end, always, converse = found
        always = always or self.always
        prompt_trigger = tuple(words[start:end]) in PROMPT_TRIGGERS
        iff = tuple(words[start:end]) in IFF_TRIGGERS
        for event, after in self._events(words, end):
            got = self._respond(words, start, event, after, always, converse, prompt_trigger, goals)
            if got is not None:
                if iff and len(got) == 1:
                    # "b next if and only if a": b exactly right after each a
                    rule = got[0]
                    assert isinstance(rule, Always) and isinstance(rule.operand, Implies)
                    reaction = rule.operand.right
                    if isinstance(reaction, Next):
                        got.append(Always(Implies(reaction, rule.operand.left)))
                return got
        return None

    def _respond(self, words: list[str], start: int, event: list[Descriptor], after: int, always: bool,
                 converse: bool, prompt_trigger: bool, goals: Sequence[Descriptor], said_first: bool = False
                 ) -> Optional[list[Formula]]:
        if said_first:
            rest = words
        elif start == 0:
            rest = words[after:]
            while rest and rest[0] in ('then', ','):
                rest = rest[1:]
        else:
            if after != len(words):
                tail = words[after:]
                # the timing of the response may follow the trigger: "go to b as soon as you see a"
                k = 0
                while k < len(tail):
                    n = _match(tail, k, IMMEDIATE + LATER)
                    if not n:
                        return None
                    k += n
            rest = words[:start] + words[after:]
        response = self._response(rest)
        if response is None:
            return None
        response.prompt = response.prompt or prompt_trigger
        if response.permitted and not (response.prompt or response.avoid):
            return None   # "if you reached X, you can go to Y": a permission, for the clause reader
        if converse or response.before:
            # "visit a right before b": b only right after a
            return [Always(Implies(Next(_any(event)), _all_near(response.places)))]
        if not (always or response.prompt or response.obliged or response.avoid):
            return None   # a plain command: "after you visit a, go to b" is a sequence
        if not always and any(d in goals or not d.relations and any(
                g.name.endswith('_' + d.name) for g in goals) for d in event):
            # "once you reach X" scopes the goal X given before ("the bay": the loading bay): the
            # clause reader places it
            return None
        if not always and response.avoid and not self.conditional_after and (
                words[start] == 'after' or words[start] == 'once' and start == 0 and _imperative_avoid(rest)):
            # "after going to X, avoid Y", "once you've been to X, stay clear of Y": X is a goal, Y
            # avoided after it (the clause reader); "once ..., you cannot go to Y" stays a rule
            return None
        t = _any(event)
        if response.avoid:
            never = _conj([Always(Not(_near(d))) for d in response.places])
            return [Always(Implies(t, Next(never)))]
        if response.prompt:
            return [Always(Implies(t, Next(_all_near(response.places))))]
        return [Always(Implies(t, _conj([Eventually(_near(d)) for d in response.places])))]

    def _trigger(self, words: list[str], start: int = 0) -> Optional[tuple[int, int, bool, bool]]:
        """Find the first trigger from ``start``: (start, end, always a rule?, said before its response?)."""
        for i in range(start, len(words)):
            got = self._trigger_at(words, i)
            if got is not None:
                return got
        return None

    @staticmethod
    def _trigger_at(words: list[str], i: int) -> Optional[tuple[int, int, bool, bool]]:
        for trig, always in TRIGGERS:
            if tuple(words[i:i + len(trig)]) == trig:
                prev = words[i - 1] if i > 0 else ''
                if trig == ('once',) and prev in ('exactly', 'only', 'least', 'most', 'at', 'than'):
                    continue   # a count
                if trig in (('any', 'time'), ('each', 'time'), ('every', 'time')) and prev in ('at', 'other'):
                    continue
                nxt = words[i + len(trig)] if i + len(trig) < len(words) else ''
                if nxt in ('that', 'this', 'it', 'afterwards', 'afterward', '') and trig[-1] in ('after',
                                                                                                 'before'):
                    continue   # "right after that" is the response's timing
                return i, i + len(trig), always, trig[-1] == 'before'
        return None

    def _events(self, words: list[str], i: int) -> list[tuple[list[Descriptor], int]]:
        """Read the event at ``words[i:]`` ("you have been to a", "you see the dog happen").

        The whole list of places first, then its first place alone: in "whenever a b must
        follow" (no comma), ``b`` starts the response.
        """
        k = i
        while k < len(words) and words[k] in EVENT_LEAD and not self._place_at(words, k):
            k += 1
        nps, _, end = self.phrases.parse_list(words, k)
        if not nps or any(np.pronoun for np in nps):
            return []
        out = []
        for group, stop in ((nps, end), (nps[:1], nps[0].end)):
            while stop < len(words) and not self._place_at(words, stop) and (
                    words[stop] in EVENT_TAIL or words[stop] == ','
                    or _match(words, stop, EVENT_TAIL_PHRASES)):
                stop += _match(words, stop, EVENT_TAIL_PHRASES) or 1
            if stop < len(words) and words[stop] in ('for', 'in') and not _match(words, stop,
                                                                                 IMMEDIATE + LATER):
                continue
            out.append(([np.descriptor for np in group], stop))
            if len(nps) == 1:
                break
        return out

    def _place_at(self, words: list[str], k: int) -> bool:
        return bool(self.phrases.landmarks) and self.phrases._landmark(words, k) is not None

    def _response(self, words: list[str]) -> Optional[_Response]:
        words = [w for w in words if w != ',']
        prompt = before = future = False
        # timing phrases anywhere in the response
        kept: list[str] = []
        k = 0
        while k < len(words):
            n = _match(words, k, BEFORE_THAT)
            if n:
                before, k = True, k + n
                continue
            n = _match(words, k, IMMEDIATE)
            if n and not self._place_at(words, k):
                prompt, k = True, k + n
                continue
            n = _match(words, k, LATER)
            if n and not self._place_at(words, k):
                future = future or tuple(words[k:k + n]) in FUTURE
                k += n
                continue
            n = _match(words, k, NOWHERE_BUT)
            if n:
                # "go nowhere but b": the very next place is b
                prompt, k = True, k + n
                kept.append('visit')
                continue
            kept.append(words[k])
            k += 1
        words = kept
        if not words:
            return None
        obliged = future or any(w in OBLIGATION for w in words[:4]) or bool(
            {'must', 'should', 'have', 'has', 'need'} & set(words))
        permitted = not obliged and bool({'can', 'may', 'free', 'allowed', 'permitted'} & set(words))
        # avoidance: "you must avoid b", "you cannot go to b", "never go to b"
        j = 0
        while j < len(words) and words[j] in ('you', 'then', 'also', 'that', 'ensure', 'make', 'sure', 'to',
                                              'have', 'has', 'must', 'will', 'should', 'need') and not \
                _match(words, j, AVOID_LEAD):
            j += 1
        n = _match(words, j, AVOID_LEAD)
        if n:
            k = j + n
            while k < len(words) and words[k] in GOAL_WORDS and not self._place_at(words, k):
                k += 1
            nps, _, end = self.phrases.parse_list(words, k)
            if nps and end == len(words) and not any(np.pronoun for np in nps):
                return _Response([np.descriptor for np in nps], True, prompt, before, True)
            return None
        # a goal: "(you must) go to b", "head to b"
        j = 0
        while j < len(words) and (words[j] in RESPONSE_LEAD or words[j] in GOAL_WORDS) and \
                not self._place_at(words, j):
            j += 1
        nps, _, end = self.phrases.parse_list(words, j)
        if nps and not any(np.pronoun or np.descriptor.name in NOT_PLACES for np in nps):
            rest = words[end:]
            if not rest:
                return _Response([np.descriptor for np in nps], False, prompt, before, obliged, permitted)
            # passive: "b must be visited", "b should occur"
            r = 0
            while r < len(rest) and rest[r] in PASSIVE_AUX:
                r += 1
            n = _match(rest, r, PASSIVE_GOAL)
            if n and r + n == len(rest):
                return _Response([np.descriptor for np in nps], False, prompt, before, r > 0)
        return None

    def _means(self, words: list[str], goals: Sequence[Descriptor]) -> Optional[list[Formula]]:
        """Read "visiting a means you have to go to b (afterwards)"."""
        if 'means' not in words:
            return None
        k = words.index('means')
        event = next((e for e, end in self._events(words[:k], 0) if end == k), None)
        if event is None:
            return None
        response = self._response(words[k + 1:])
        if response is None or any(d in goals for d in event):
            return None
        t = _any(event)
        if response.avoid:
            return [Always(Implies(t, Next(_conj([Always(Not(_near(d))) for d in response.places]))))]
        if response.prompt:
            return [Always(Implies(t, Next(_all_near(response.places))))]
        return [Always(Implies(t, _conj([Eventually(_near(d)) for d in response.places])))]

    def _any_other_time(self, words: list[str], sofar: list[Formula]) -> Optional[list[Formula]]:
        """'... and you cannot go to b any other time': b only right after the trigger of the rule before."""
        if words[-3:] != ['any', 'other', 'time'] or not sofar:
            return None
        last = sofar[-1]
        if not (isinstance(last, Always) and isinstance(last.operand, Implies)
                and isinstance(last.operand.right, (Next, Eventually))):
            return None
        response = self._response(words[:-3])
        if response is None or not response.avoid:
            return None
        trigger, reaction = last.operand.left, last.operand.right
        if isinstance(reaction, Eventually):
            # "go to b once you reach a, and never go to b any other time": b right after a, only then
            sofar[-1] = Always(Implies(trigger, Next(reaction.operand)))
        return [Always(Implies(Next(_any(response.places)), trigger))]


def _near(d: Descriptor) -> Atom:
    return Atom('near', (d,))


def _any(ds: Sequence[Descriptor]) -> Formula:
    return _near(ds[0]) if len(ds) == 1 else Or(tuple(_near(d) for d in ds))


def _all_near(ds: Sequence[Descriptor]) -> Formula:
    return _near(ds[0]) if len(ds) == 1 else And(tuple(_near(d) for d in ds))


def _conj(fs: Sequence[Formula]) -> Formula:
    return fs[0] if len(fs) == 1 else And(tuple(fs))

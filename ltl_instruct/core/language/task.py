"""The task model the offline translator builds: chains of steps and constraints, and their formula.

A :class:`Task` holds conjoined constraints and one chain of :class:`Step` values (goals,
deliveries, picks, "leave" steps, or alternatives and unordered groups of sub-chains);
:func:`render` turns a chain into the nested ``F (... & F ...)`` formula of the
development set's conventions. The count builders (:func:`at_least`, :func:`at_most`,
:func:`exactly`) give the formulas of "twice", "at most once", "exactly three times".
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import permutations
from typing import Optional, Sequence

from ltl_instruct.core.errors import LimitExceededError, TranslationError
from ltl_instruct.core.spec import (
    Always, And, Atom, Descriptor, Eventually, Formula, Not, Or, Until, WeakUntil,
)


def near_atom(d: Descriptor) -> Atom:
    """Return ``near[d]``."""
    return Atom('near', (d,))


def conjoin(*parts: Optional[Formula]) -> Optional[Formula]:
    """Conjoin the formulas given (None ones left out, nested conjunctions flattened); None if none."""
    items: list[Formula] = []
    for p in parts:
        if p is None:
            continue
        items.extend(p.operands if isinstance(p, And) else (p,))
    if not items:
        return None
    return items[0] if len(items) == 1 else And(tuple(items))


def disjoin(parts: Sequence[Formula]) -> Formula:
    """Disjoin the formulas given, nested disjunctions flattened."""
    items: list[Formula] = []
    for p in parts:
        items.extend(p.operands if isinstance(p, Or) else (p,))
    return items[0] if len(items) == 1 else Or(tuple(items))


def never_all(ds: Sequence[Descriptor]) -> list[Formula]:
    """Return ``G !near[d]`` for each descriptor."""
    return [Always(Not(near_atom(d))) for d in ds]


MAX_COUNT = 20
"""The largest count an instruction may name ("visit the kitchen 20 times").

Each visit nests the formula four levels deeper; larger counts are refused with
``LIMIT_EXCEEDED`` rather than building formulas no stage downstream can handle.
"""


def check_count(n: object, what: str = 'count') -> int:
    """Return ``n`` if it is a whole number from 0 to :data:`MAX_COUNT`, else raise a typed error.

    Raises
    ------
    LimitExceededError
        ``n`` is larger than :data:`MAX_COUNT`.
    TranslationError
        ``n`` is negative or not a whole number.
    """
    if isinstance(n, bool) or not isinstance(n, int):
        raise TranslationError(f'a {what} must be a whole number of times, not {n!r}',
                               details={'count': str(n)})
    if n < 0:
        raise TranslationError(f'a {what} cannot be negative ({n} times)', details={'count': n})
    if n > MAX_COUNT:
        raise LimitExceededError(f'the {what} {n} is larger than the maximum of {MAX_COUNT} times',
                                 details={'limit': 'max_count', 'value': MAX_COUNT, 'count': n})
    return n


def at_least(x: Formula, n: int, tail: Optional[Formula] = None) -> Formula:
    """``n`` separate visits of ``x`` (then ``tail``): ``F (x & F (!x & F (x ...)))``."""
    check_count(n)
    body: Optional[Formula] = tail
    for k in range(n):
        body = Eventually(conjoin(x, body)) if body is not None else Eventually(x)
        if k < n - 1:
            body = Eventually(And((Not(x), body)))
    assert body is not None
    return body


def at_most(x: Formula, n: int) -> Formula:
    """At most ``n`` separate visits of ``x`` (the development set's convention for n = 1)."""
    check_count(n)
    body: Formula = Always(Not(x))
    for k in range(n):
        inner = WeakUntil(x, body if k == 0 else And((Not(x), body)))
        body = WeakUntil(Not(x), And((x, inner)))
    return body


def exactly(x: Formula, n: int) -> Formula:
    """Exactly ``n`` separate visits of ``x``."""
    check_count(n)
    body: Formula = Until(Not(x), And((x, WeakUntil(x, Always(Not(x))))))
    for _ in range(n - 1):
        body = Until(Not(x), And((x, Until(x, And((Not(x), body))))))
    return body


@dataclass
class Step:
    """One step of a chain (a sequence of things to do, in order).

    kind: ``visit`` (targets are alternatives), ``leave`` (be away from the target),
    ``deliver`` (pick ``targets[0]``, release at one of ``dests``), ``pick``,
    ``all``/``any`` (sub-chains, all of them in any order / one of them), ``formula``.
    """

    kind: str
    targets: list[Descriptor] = field(default_factory=list)
    dests: list[Descriptor] = field(default_factory=list)
    avoid_until: list[Descriptor] = field(default_factory=list)
    avoid_after: list[Descriptor] = field(default_factory=list)
    carry_avoid: list[Descriptor] = field(default_factory=list)
    after_pick_avoid: list[Descriptor] = field(default_factory=list)
    after_release_avoid: list[Descriptor] = field(default_factory=list)
    chains: list[list['Step']] = field(default_factory=list)
    formula: Optional[Formula] = None
    avoid_at: list[Descriptor] = field(default_factory=list)
    once: str = ''   # 'exactly' ("visit a exactly once"), 'plain' ("go to a once, then b"), or ''
    hold_until: list[Descriptor] = field(default_factory=list)   # "wait there until Y": x U y once there
    # "once you reach X, avoid Y until you reach Z": from X on, Y avoided until Z
    avoid_after_until: list[tuple[tuple[Descriptor, ...], Descriptor]] = field(default_factory=list)


def render(steps: Sequence[Step]) -> Optional[Formula]:
    """Return the formula of a chain of steps: each step eventually, the rest after it."""
    if not steps:
        return None
    s, rest = steps[0], list(steps[1:])
    if s.kind == 'all':
        if rest and 1 < len(s.chains) <= 3:
            # "A and B in any order, then C": C after both, so one of the orders of A and B, then C
            orders = [render([st for c in perm for st in c] + rest) for perm in permutations(s.chains)]
            return disjoin([o for o in orders if o is not None])
        parts = [render(list(c) + rest) for c in s.chains]
        return conjoin(*parts)
    if s.kind == 'any':
        alts = [render(list(c) + rest) for c in s.chains]
        return disjoin([a for a in alts if a is not None])
    tail = render(rest)
    if s.kind == 'formula':
        assert s.formula is not None
        return conjoin(tail, s.formula)   # the goals print first; the meaning is the same
    if s.kind == 'leave':
        return Eventually(conjoin(Not(near_atom(s.targets[0])), tail))
    if s.kind == 'visit':
        core: Formula = disjoin([near_atom(t) for t in s.targets])
        if s.hold_until:
            # "wait there until Y, then ...": at X until Y, and the rest after Y
            until = conjoin(near_atom(s.hold_until[0]), tail)
            assert until is not None
            tail = Until(core, until)
        body = conjoin(core, *[Not(near_atom(d)) for d in s.avoid_at], *never_all(s.avoid_after),
                       *[until_avoid(ys, near_atom(z)) for ys, z in s.avoid_after_until], tail)
    elif s.kind == 'pick':
        obj = s.targets[0]
        picked = conjoin(Atom('pick', (obj,)), *never_all(s.after_pick_avoid), tail)
        assert picked is not None
        body = conjoin(near_atom(obj), Eventually(picked))
    else:
        obj = s.targets[0]
        arrivals = []
        for d in s.dests:
            rel = conjoin(Atom('release', (obj, d)), *never_all(s.after_release_avoid), tail)
            arrive = conjoin(near_atom(d), Eventually(rel))
            assert arrive is not None
            if s.carry_avoid:
                arrivals.append(until_avoid(s.carry_avoid, arrive))
            else:
                arrivals.append(Eventually(arrive))
        picked = conjoin(Atom('pick', (obj,)), *never_all(s.after_pick_avoid), disjoin(arrivals))
        body = conjoin(near_atom(obj), Eventually(picked) if picked is not None else None)
    assert body is not None
    if s.avoid_until:
        if s.kind == 'visit':
            reach = until_avoid(s.avoid_until, core)
            return reach if body == core else And((reach, Eventually(body)))
        return until_avoid(s.avoid_until, body)
    return Eventually(body)


def until_avoid(avoid: Sequence[Descriptor], goal: Formula) -> Formula:
    """Return ``(!near[a] & ...) U goal``."""
    guard = conjoin(*[Not(near_atom(d)) for d in avoid])
    assert guard is not None
    return Until(guard, goal)


class Task:
    """Mutable builder of chains and constraints while the clauses are read."""

    def __init__(self) -> None:
        self.chain: list[Step] = []
        self.constraints: list[Formula] = []
        self.repeat = 1
        self.repeat_end: Optional[int] = None   # the goals after this are said after the repeat
        self.chain_at: Optional[int] = None   # constraints printed before the goals (an until read with them)

    def find_step(self, d: Descriptor, head: str = '') -> Optional[Step]:
        """Return the last goal, delivery or pick naming ``d`` (or a name with the word ``head``)."""
        for s in reversed(self._all_steps()):
            if s.kind in ('visit', 'deliver', 'pick'):
                names = s.targets + s.dests
                if d in names or (head and any(head in n.name.split('_') for n in names)):
                    return s
        return None

    def _all_steps(self) -> list[Step]:
        out: list[Step] = []

        def walk(steps: Sequence[Step]) -> None:
            for s in steps:
                out.append(s)
                for c in s.chains:
                    walk(c)
        walk(self.chain)
        return out

    def last_step(self, kinds: tuple[str, ...] = ('visit', 'deliver', 'pick', 'all', 'any')
                  ) -> Optional[Step]:
        """Return the last top-level step of one of these kinds."""
        for s in reversed(self.chain):
            if s.kind in kinds:
                return s
        return None

    def formula(self) -> Formula:
        """Return the task's formula: the constraints and the chain (repeated as asked), conjoined."""
        end = len(self.chain) if self.repeat_end is None else min(self.repeat_end, len(self.chain))
        chain = self.chain[:end] * self.repeat + self.chain[end:]
        at = len(self.constraints) if self.chain_at is None else self.chain_at
        f = conjoin(*self.constraints[:at], render(chain), *self.constraints[at:])
        if f is None:
            raise TranslationError('the instruction names nothing to do and nothing to avoid')
        return f

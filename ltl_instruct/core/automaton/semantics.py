"""A direct recursive evaluator of LTLf semantics: the reference the automata are tested against.

Deliberately naive (it follows the definitions in ``spec/formula.md`` word for
word and shares no code with progression), so agreement is evidence.
"""
from __future__ import annotations

from functools import lru_cache
from typing import AbstractSet, Sequence

from ltl_instruct.core.spec.ast import (
    Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or, Release, Until,
    WeakNext, WeakUntil,
)


def holds(f: Formula, trace: Sequence[AbstractSet[Atom]], i: int = 0) -> bool:
    """Whether the suffix of the non-empty finite ``trace`` from position ``i`` satisfies ``f``."""
    n = len(trace)
    if n == 0:
        raise ValueError('LTLf traces are non-empty')
    frozen = tuple(frozenset(s) for s in trace)

    @lru_cache(maxsize=None)
    def h(g: Formula, k: int) -> bool:
        if isinstance(g, Const):
            return g.value
        if isinstance(g, Atom):
            return g in frozen[k]
        if isinstance(g, Not):
            return not h(g.operand, k)
        if isinstance(g, And):
            return all(h(o, k) for o in g.operands)
        if isinstance(g, Or):
            return any(h(o, k) for o in g.operands)
        if isinstance(g, Implies):
            return (not h(g.left, k)) or h(g.right, k)
        if isinstance(g, Iff):
            return h(g.left, k) == h(g.right, k)
        if isinstance(g, Next):          # strong: a next position must exist
            return k + 1 < n and h(g.operand, k + 1)
        if isinstance(g, WeakNext):      # weak: true at the last position
            return k + 1 >= n or h(g.operand, k + 1)
        if isinstance(g, Eventually):
            return any(h(g.operand, j) for j in range(k, n))
        if isinstance(g, Always):
            return all(h(g.operand, j) for j in range(k, n))
        if isinstance(g, Until):
            return any(h(g.right, j) and all(h(g.left, m) for m in range(k, j)) for j in range(k, n))
        if isinstance(g, WeakUntil):
            return h(Until(g.left, g.right), k) or all(h(g.left, j) for j in range(k, n))
        if isinstance(g, Release):       # b holds until and including the first a, or always
            return all(h(g.right, j) or any(h(g.left, m) for m in range(k, j)) for j in range(k, n))
        raise TypeError(f'not a formula node: {g!r}')

    return h(f, i)

"""Formula progression for finite traces (LTLf), concrete and symbolic.

Semantics (``spec/formula.md``): a formula is read over a finite, non-empty trace
of letters (sets of true atoms). Progression rewrites a formula ``f`` and a letter
``s`` into the formula the *rest* of the trace must satisfy:
``s . rest |= f``  iff  ``rest |= progress(f, s)``. The rest may be empty, so
every operator also has an empty-trace value (:func:`accepts_empty`): ``F``, ``U``
and strong ``X`` are false on the empty trace, ``G``, ``R``, ``W`` and weak next
true. Strong next progresses to ``f & F true`` ("and the trace goes on"), weak next
to ``f | G false`` ("or the trace ends here").

``G`` is kept across steps: ``progress(G p, s) = p(s) & G p``, so an avoidance
constraint holds for the whole trace, not just its first step.

Formulas are first put into negation normal form (:func:`to_nnf`), in which
negation sits only on atoms, so that states compare structurally.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import AbstractSet, Callable

from ltl_instruct.core.errors import ErrorCode, LimitExceededError
from ltl_instruct.core.spec.ast import (
    FALSE, TRUE, Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or,
    Release, Until, WeakNext, WeakUntil, _hash_init, conj, disj,
)

EVENTUALLY_TRUE = Eventually(TRUE)   # the trace goes on (at least one more step)
ALWAYS_FALSE = Always(FALSE)         # the trace ends here


MAX_NNF_SIZE = 20_000
"""Most nodes the negation normal form of a formula may have, counted as a tree.

``a <-> b`` becomes ``a & b | !a & !b``, so each ``<->`` doubles its operands: a
chain of n equivalences grows as 2^n. Larger inputs get ``LIMIT_EXCEEDED`` before
any work is done.
"""


def nnf_size(f: Formula, limit: int = MAX_NNF_SIZE) -> int:
    """Tree size of the negation normal form of ``f`` (capped at ``limit + 1``), computed iteratively."""
    size: dict[int, int] = {}
    stack: list[tuple[Formula, bool]] = [(f, False)]
    while stack:
        node, ready = stack.pop()
        if id(node) in size:
            continue
        kids = node.children()
        if not ready and any(id(k) not in size for k in kids):
            stack.append((node, True))
            stack.extend((k, False) for k in kids if id(k) not in size)
            continue
        total = 1 + sum(size[id(k)] for k in kids)
        if isinstance(node, Iff):  # (a & b) | (!a & !b): both operands twice
            total = 3 + 2 * (size[id(node.left)] + size[id(node.right)])
        elif isinstance(node, WeakUntil):  # !(a W b) == !b U (!a & !b): b twice
            total += size[id(node.right)] + 1
        size[id(node)] = min(total, limit + 1)
    return size[id(f)]


def _nnf_deps(f: Formula, negate: bool) -> list[tuple[Formula, bool]]:
    """Return the (sub-formula, negate) pairs the NNF of ``(f, negate)`` is built from."""
    if isinstance(f, Not):
        return [(f.operand, not negate)]
    if isinstance(f, (And, Or)):
        return [(o, negate) for o in f.operands]
    if isinstance(f, Implies):
        return [(f.left, not negate), (f.right, negate)]
    if isinstance(f, Iff):
        return [(f.left, False), (f.left, True), (f.right, False), (f.right, True)]
    if isinstance(f, (Next, WeakNext, Eventually, Always)):
        return [(f.operand, negate)]
    if isinstance(f, (Until, Release, WeakUntil)):
        return [(f.left, negate), (f.right, negate)]
    return []


def to_nnf(f: Formula, negate: bool = False, max_size: int = MAX_NNF_SIZE) -> Formula:
    """Negation normal form over ``F G X WX U R W & |`` with ``->``/``<->`` expanded.

    Works with an explicit stack (no recursion) and shares the normal form of a
    sub-formula that occurs twice, so deep formulas normalise without
    ``RecursionError``.

    Parameters
    ----------
    f: formula to normalise.
    negate: return the NNF of ``!f`` instead.
    max_size: most nodes the normal form may have (see :data:`MAX_NNF_SIZE`).

    Raises
    ------
    LimitExceededError
        When the normal form would have more than ``max_size`` nodes.
    """
    size = nnf_size(f, max_size)
    if size > max_size:
        raise LimitExceededError(
            f'the formula expands to more than {max_size} nodes when its "->", "<->" and "W" '
            'are written out (each "<->" doubles its operands); simplify the task',
            details={'limit': 'max_nnf_size', 'value': max_size})
    memo: dict[tuple[Formula, bool], Formula] = {}
    stack: list[tuple[Formula, bool, bool]] = [(f, negate, False)]
    while stack:
        node, neg_, ready = stack.pop()
        if (node, neg_) in memo:
            continue
        deps = _nnf_deps(node, neg_)
        if not ready:
            missing = [d for d in deps if d not in memo]
            if missing:
                stack.append((node, neg_, True))
                stack.extend((g, n, False) for g, n in missing)
                continue
        memo[(node, neg_)] = _nnf_node(node, neg_, [memo[d] for d in deps])
    return memo[(f, negate)]


def _nnf_node(f: Formula, negate: bool, parts: list[Formula]) -> Formula:
    """NNF of one node from the NNFs of its dependencies (in :func:`_nnf_deps` order)."""
    if isinstance(f, Const):
        return TRUE if f.value != negate else FALSE
    if isinstance(f, Atom):
        return Not(f) if negate else f
    if isinstance(f, Not):
        return parts[0]
    if isinstance(f, And):
        return disj(*parts) if negate else conj(*parts)
    if isinstance(f, Or):
        return conj(*parts) if negate else disj(*parts)
    if isinstance(f, Implies):  # a -> b == !a | b
        return conj(*parts) if negate else disj(*parts)
    if isinstance(f, Iff):      # (a & b) | (!a & !b)
        a, na, b, nb = parts
        if negate:
            return conj(disj(na, nb), disj(a, b))
        return disj(conj(a, b), conj(na, nb))
    if isinstance(f, Next):
        return WeakNext(parts[0]) if negate else Next(parts[0])
    if isinstance(f, WeakNext):
        return Next(parts[0]) if negate else WeakNext(parts[0])
    if isinstance(f, Eventually):
        return Always(parts[0]) if negate else Eventually(parts[0])
    if isinstance(f, Always):
        return Eventually(parts[0]) if negate else Always(parts[0])
    if isinstance(f, Until):     # !(a U b) == !a R !b
        return Release(*parts) if negate else Until(*parts)
    if isinstance(f, Release):   # !(a R b) == !a U !b
        return Until(*parts) if negate else Release(*parts)
    if isinstance(f, WeakUntil):  # !(a W b) == !b U (!a & !b)
        if negate:
            na, nb = parts
            return Until(nb, conj(na, nb))
        return WeakUntil(*parts)
    raise TypeError(f'not a formula node: {f!r}')


def accepts_empty(f: Formula) -> bool:
    """Whether the empty rest-of-trace satisfies NNF formula ``f`` (trace may end now)."""
    if isinstance(f, Const):
        return f.value
    if isinstance(f, (Atom, Not, Next, Eventually, Until)):
        return False
    if isinstance(f, (WeakNext, Always, Release, WeakUntil)):
        return True
    if isinstance(f, And):
        return all(accepts_empty(o) for o in f.operands)
    if isinstance(f, Or):
        return any(accepts_empty(o) for o in f.operands)
    raise TypeError(f'not an NNF formula node: {f!r}')


@dataclass(frozen=True, eq=True, repr=False)
class Later(Formula):
    """Marks an obligation on the rest of the trace inside a symbolic step formula."""

    operand: Formula
    _hash: int = field(init=False, compare=False, default=0)

    def __post_init__(self) -> None:
        _hash_init(self, self.operand)

    def __hash__(self) -> int:
        return self._hash

    def __str__(self) -> str:
        return f'@({self.operand})'


def step_formula(f: Formula, cache: dict[Formula, Formula] | None = None) -> Formula:
    """Symbolic progression of NNF ``f`` by an unknown letter.

    Returns a boolean combination of current-step literals (atoms, negated atoms)
    and :class:`Later` obligations. Assigning truth values to the atoms and
    replacing ``Later(g)`` by ``g`` gives ``progress(f, letter)``.
    """
    if cache is not None:
        hit = cache.get(f)
        if hit is not None:
            return hit
    r: Formula
    if isinstance(f, (Const, Atom, Not)):
        r = f
    elif isinstance(f, And):
        r = conj(*(step_formula(o, cache) for o in f.operands))
    elif isinstance(f, Or):
        r = disj(*(step_formula(o, cache) for o in f.operands))
    elif isinstance(f, Next):
        r = Later(conj(f.operand, EVENTUALLY_TRUE))
    elif isinstance(f, WeakNext):
        r = Later(disj(f.operand, ALWAYS_FALSE))
    elif isinstance(f, Eventually):
        r = disj(step_formula(f.operand, cache), Later(f))
    elif isinstance(f, Always):
        r = conj(step_formula(f.operand, cache), Later(f))
    elif isinstance(f, (Until, WeakUntil)):
        r = disj(step_formula(f.right, cache), conj(step_formula(f.left, cache), Later(f)))
    elif isinstance(f, Release):
        r = conj(step_formula(f.right, cache), disj(step_formula(f.left, cache), Later(f)))
    else:
        raise TypeError(f'not an NNF formula node: {f!r}')
    if cache is not None:
        cache[f] = r
    return r


def assign(f: Formula, value_of: Callable[[Atom], bool | None]) -> Formula:
    """Substitute known atom values in a step formula (``Later`` nodes untouched).

    ``value_of(atom)`` returns True, False, or None for "still unknown". A sub-formula
    in which nothing changes is returned as it is (no rebuilding, no re-sorting).
    """
    if isinstance(f, Atom):
        v = value_of(f)
        return f if v is None else (TRUE if v else FALSE)
    if isinstance(f, Not):
        v = value_of(f.operand)  # NNF: operand is an atom
        return f if v is None else (FALSE if v else TRUE)
    if isinstance(f, And):
        out = []
        changed = False
        for o in f.operands:
            r = assign(o, value_of)
            if r == FALSE:
                return FALSE
            changed = changed or r is not o
            out.append(r)
        return conj(*out) if changed else f
    if isinstance(f, Or):
        out = []
        changed = False
        for o in f.operands:
            r = assign(o, value_of)
            if r == TRUE:
                return TRUE
            changed = changed or r is not o
            out.append(r)
        return disj(*out) if changed else f
    return f  # Const, Later


def resolve_later(f: Formula) -> Formula:
    """Replace every ``Later(g)`` by ``g``: the next state (no current atoms left)."""
    if isinstance(f, Later):
        return f.operand
    if isinstance(f, And):
        return conj(*(resolve_later(o) for o in f.operands))
    if isinstance(f, Or):
        return disj(*(resolve_later(o) for o in f.operands))
    if isinstance(f, Const):
        return f
    raise ValueError(f'step formula still has a current-step literal: {f}')


def progress(f: Formula, letter: AbstractSet[Atom]) -> Formula:
    """Concrete progression of NNF ``f`` by one letter (the set of true atoms)."""
    s = assign(step_formula(f), lambda a: a in letter)
    return resolve_later(s)


class WorkBudget:
    """Bounds on the work of one automaton compilation: a deadline and an edge count.

    :meth:`check` raises a typed error instead of letting a hostile formula
    (``a0 U a1 U ... U a199``) run for minutes and fill memory.

    Parameters
    ----------
    time_limit_s: seconds the compilation may take (None: no deadline).
    max_edges: edges the whole compilation may produce.
    """

    def __init__(self, time_limit_s: float | None = 5.0, max_edges: int = 200_000) -> None:
        self.time_limit_s = time_limit_s
        self.deadline = None if time_limit_s is None else time.monotonic() + time_limit_s
        self.max_edges = max_edges
        self.edges = 0

    def check(self) -> None:
        """Raise ``TIMEOUT`` once the deadline has passed."""
        if self.deadline is not None and time.monotonic() > self.deadline:
            raise LimitExceededError(
                f'building the automaton took longer than {self.time_limit_s:g} s; '
                'simplify the task', code=ErrorCode.TIMEOUT,
                details={'limit': 'time_limit_s', 'value': self.time_limit_s})

    def add_edges(self, n: int = 1) -> None:
        """Count ``n`` more edges; raise ``LIMIT_EXCEEDED`` past ``max_edges``."""
        self.edges += n
        if self.edges > self.max_edges:
            raise LimitExceededError(
                f'the automaton needs more than {self.max_edges} edges; simplify the task',
                details={'limit': 'max_edges', 'value': self.max_edges})
        self.check()

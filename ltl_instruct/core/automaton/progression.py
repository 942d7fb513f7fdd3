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
from functools import lru_cache
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


def step_atoms(f: Formula) -> frozenset[Atom]:
    """Atoms of a step formula outside ``Later`` obligations (cached on the node)."""
    got = f.__dict__.get('_step_atoms')
    if got is None:
        if isinstance(f, Atom):
            got = frozenset((f,))
        elif isinstance(f, Not):
            got = frozenset((f.operand,))  # type: ignore[arg-type]
        elif isinstance(f, (And, Or)):
            got = frozenset().union(*(step_atoms(o) for o in f.operands))
        else:
            got = frozenset()  # Const, Later
        object.__setattr__(f, '_step_atoms', got)
    return got


def assign_atoms(f: Formula, values: dict[Atom, bool]) -> Formula:
    """:func:`assign` with a dict of values, skipping sub-formulas that hold none of its atoms."""
    if not values or not (step_atoms(f) & values.keys()):
        return f
    if isinstance(f, Atom):
        return TRUE if values[f] else FALSE
    if isinstance(f, Not):
        return FALSE if values[f.operand] else TRUE  # type: ignore[index]
    out = []
    absorbing = FALSE if isinstance(f, And) else TRUE
    for o in f.operands:  # type: ignore[attr-defined]
        r = assign_atoms(o, values)
        if r == absorbing:
            return absorbing
        out.append(r)
    return conj(*out) if isinstance(f, And) else disj(*out)


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


def _is_eventuality(f: Formula) -> bool:
    return isinstance(f, (Eventually, Until, Next, Atom, Not))


class WorkBudget:
    """Bounds on the work of one automaton compilation: a deadline and a cube count.

    Shared by the state canonicaliser and the edge expansion; :meth:`check` raises a
    typed error instead of letting a hostile formula (``a0 <-> a1 <-> ... <-> a13``,
    ``a0 U a1 U ... U a19``) run for minutes and fill memory.

    Parameters
    ----------
    time_limit_s: seconds the compilation may take (None: no deadline).
    max_cubes: cubes (edge-guard terms) the whole compilation may produce.
    max_state_cubes: cubes the disjunctive normal form of one state may have.
    """

    def __init__(self, time_limit_s: float | None = 5.0, max_cubes: int = 50_000,
                 max_state_cubes: int = 512) -> None:
        self.time_limit_s = time_limit_s
        self.deadline = None if time_limit_s is None else time.monotonic() + time_limit_s
        self.max_cubes = max_cubes
        self.max_state_cubes = max_state_cubes
        self.cubes = 0
        self._calls = 0

    def check(self) -> None:
        """Raise ``TIMEOUT`` once the deadline has passed (the clock is read every 64 calls)."""
        self._calls += 1
        if self._calls & 63:
            return
        if self.deadline is not None and time.monotonic() > self.deadline:
            raise LimitExceededError(
                f'building the automaton took longer than {self.time_limit_s:g} s; '
                'simplify the task', code=ErrorCode.TIMEOUT,
                details={'limit': 'time_limit_s', 'value': self.time_limit_s})

    def add_cubes(self, n: int = 1) -> None:
        """Count ``n`` more edge cubes; raise ``LIMIT_EXCEEDED`` past ``max_cubes``."""
        self.cubes += n
        if self.cubes > self.max_cubes:
            raise LimitExceededError(
                f'the automaton needs more than {self.max_cubes} guard terms; simplify the task',
                details={'limit': 'max_cubes', 'value': self.max_cubes})
        self.check()

    def state_cubes(self, n: int) -> None:
        """Check the size of one state's normal form."""
        if n > self.max_state_cubes:
            raise LimitExceededError(
                f'an automaton state needs more than {self.max_state_cubes} alternatives; '
                'simplify the task',
                details={'limit': 'max_state_cubes', 'value': self.max_state_cubes})
        self.check()


def canonical_state(f: Formula, budget: WorkBudget | None = None) -> Formula:
    """Canonical DNF of a state formula over its elementary (temporal or literal) parts.

    Progression alone can build ever-deeper ``&``/``|`` nestings of the same few
    obligations (e.g. for ``(a U b) U c``), so states would never repeat. Writing
    every state as a set of cubes of elementary sub-formulas, with subsumed and
    contradictory cubes dropped, keeps the state space finite and merges
    syntactically different but identical obligations. ``budget`` bounds the
    number of cubes and the time (see :class:`WorkBudget`).
    """
    cubes = _dnf(f, budget or WorkBudget(time_limit_s=None))
    return disj(*(conj(*c) for c in cubes))


def _dnf(f: Formula, budget: WorkBudget) -> list[frozenset[Formula]]:
    if f == TRUE:
        return [frozenset()]
    if f == FALSE:
        return []
    if isinstance(f, Or):
        out: list[frozenset[Formula]] = []
        for o in f.operands:
            out.extend(_dnf(o, budget))
            budget.state_cubes(len(out))
        return _absorb(out, budget)
    if isinstance(f, And):
        acc: list[frozenset[Formula]] = [frozenset()]
        for o in f.operands:
            part = _dnf(o, budget)
            budget.state_cubes(len(acc) * len(part))
            acc = _absorb([a | b for a in acc for b in part if _consistent(a | b)], budget)
            if not acc:
                return []
        return acc
    return [frozenset({f})]


def _consistent(cube: frozenset[Formula]) -> bool:
    for g in cube:
        if isinstance(g, Not) and g.operand in cube:
            return False
    # "the trace ends now" contradicts every obligation that needs one more step
    if ALWAYS_FALSE in cube and any(_is_eventuality(g) for g in cube):
        return False
    return True


def _absorb(cubes: list[frozenset[Formula]], budget: WorkBudget) -> list[frozenset[Formula]]:
    uniq = sorted(set(cubes), key=lambda c: (len(c), sorted(map(str, c))))
    kept: list[frozenset[Formula]] = []
    for c in uniq:
        if not any(k <= c for k in kept):
            kept.append(c)
    if len(kept) > 1:  # semantic absorption: drop a cube that implies another one
        out = []
        for i, c in enumerate(kept):
            budget.check()  # quadratic in the cubes: keep to the deadline
            if not any(j != i and _cube_implies(c, d) and not (j > i and _cube_implies(d, c))
                       for j, d in enumerate(kept)):
                out.append(c)
        kept = out
    return kept


def _cube_implies(c: frozenset[Formula], d: frozenset[Formula]) -> bool:
    return all(any(implies(x, y) for x in c) for y in d)


@lru_cache(maxsize=65536)
def implies(f: Formula, g: Formula) -> bool:
    """Sound, incomplete syntactic implication between NNF formulas (Spot-style rules).

    Used to keep states small: ``F (a & F b) | F b`` is just ``F b``.
    """
    if f == g or g == TRUE or f == FALSE:
        return True
    if isinstance(g, And):
        return all(implies(f, x) for x in g.operands)
    if isinstance(f, Or):
        return all(implies(x, g) for x in f.operands)
    if isinstance(f, And) and any(implies(x, g) for x in f.operands):
        return True
    if isinstance(g, Or) and any(implies(f, x) for x in g.operands):
        return True
    # the rest of a trace may be empty: each rule below holds there too
    if isinstance(g, Eventually):
        if not accepts_empty(f) and implies(f, g.operand):
            return True
        if isinstance(f, Eventually) and implies(f.operand, g):
            return True
        if isinstance(f, Until) and implies(f.right, g):
            return True
    if isinstance(f, Always):
        if accepts_empty(g) and implies(f.operand, g):
            return True
        if isinstance(g, Always) and implies(f.operand, g.operand):
            return True
    if isinstance(f, Until) and isinstance(g, Until):
        return implies(f.left, g.left) and implies(f.right, g.right)
    return False

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

from dataclasses import dataclass, field
from functools import lru_cache
from typing import AbstractSet, Callable

from ltl_instruct.core.spec.ast import (
    FALSE, TRUE, Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or,
    Release, Until, WeakNext, WeakUntil, _hash_init, conj, disj,
)

EVENTUALLY_TRUE = Eventually(TRUE)   # the trace goes on (at least one more step)
ALWAYS_FALSE = Always(FALSE)         # the trace ends here


def to_nnf(f: Formula, negate: bool = False) -> Formula:
    """Negation normal form over ``F G X WX U R W & |`` with ``->``/``<->`` expanded.

    Parameters
    ----------
    f: formula to normalise.
    negate: return the NNF of ``!f`` instead.
    """
    if isinstance(f, Const):
        return TRUE if f.value != negate else FALSE
    if isinstance(f, Atom):
        return Not(f) if negate else f
    if isinstance(f, Not):
        return to_nnf(f.operand, not negate)
    if isinstance(f, And):
        parts = [to_nnf(o, negate) for o in f.operands]
        return disj(*parts) if negate else conj(*parts)
    if isinstance(f, Or):
        parts = [to_nnf(o, negate) for o in f.operands]
        return conj(*parts) if negate else disj(*parts)
    if isinstance(f, Implies):  # a -> b == !a | b
        return to_nnf(Or((Not(f.left), f.right)), negate)
    if isinstance(f, Iff):      # (a & b) | (!a & !b)
        a, b = f.left, f.right
        return to_nnf(Or((And((a, b)), And((Not(a), Not(b))))), negate)
    if isinstance(f, Next):
        return WeakNext(to_nnf(f.operand, True)) if negate else Next(to_nnf(f.operand))
    if isinstance(f, WeakNext):
        return Next(to_nnf(f.operand, True)) if negate else WeakNext(to_nnf(f.operand))
    if isinstance(f, Eventually):
        return Always(to_nnf(f.operand, True)) if negate else Eventually(to_nnf(f.operand))
    if isinstance(f, Always):
        return Eventually(to_nnf(f.operand, True)) if negate else Always(to_nnf(f.operand))
    if isinstance(f, Until):     # !(a U b) == !a R !b
        if negate:
            return Release(to_nnf(f.left, True), to_nnf(f.right, True))
        return Until(to_nnf(f.left), to_nnf(f.right))
    if isinstance(f, Release):   # !(a R b) == !a U !b
        if negate:
            return Until(to_nnf(f.left, True), to_nnf(f.right, True))
        return Release(to_nnf(f.left), to_nnf(f.right))
    if isinstance(f, WeakUntil):  # !(a W b) == !b U (!a & !b)
        if negate:
            nb = to_nnf(f.right, True)
            return Until(nb, conj(to_nnf(f.left, True), nb))
        return WeakUntil(to_nnf(f.left), to_nnf(f.right))
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


def canonical_state(f: Formula) -> Formula:
    """Canonical DNF of a state formula over its elementary (temporal or literal) parts.

    Progression alone can build ever-deeper ``&``/``|`` nestings of the same few
    obligations (e.g. for ``(a U b) U c``), so states would never repeat. Writing
    every state as a set of cubes of elementary sub-formulas, with subsumed and
    contradictory cubes dropped, keeps the state space finite and merges
    syntactically different but identical obligations.
    """
    cubes = _dnf(f)
    return disj(*(conj(*c) for c in cubes))


def _dnf(f: Formula) -> list[frozenset[Formula]]:
    if f == TRUE:
        return [frozenset()]
    if f == FALSE:
        return []
    if isinstance(f, Or):
        out: list[frozenset[Formula]] = []
        for o in f.operands:
            out.extend(_dnf(o))
        return _absorb(out)
    if isinstance(f, And):
        acc: list[frozenset[Formula]] = [frozenset()]
        for o in f.operands:
            part = _dnf(o)
            acc = _absorb([a | b for a in acc for b in part if _consistent(a | b)])
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


def _absorb(cubes: list[frozenset[Formula]]) -> list[frozenset[Formula]]:
    uniq = sorted(set(cubes), key=lambda c: (len(c), sorted(map(str, c))))
    kept: list[frozenset[Formula]] = []
    for c in uniq:
        if not any(k <= c for k in kept):
            kept.append(c)
    if len(kept) > 1:  # semantic absorption: drop a cube that implies another one
        kept = [c for i, c in enumerate(kept)
                if not any(j != i and _cube_implies(c, d) and not (j > i and _cube_implies(d, c))
                           for j, d in enumerate(kept))]
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

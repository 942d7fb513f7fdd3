"""Lifted formulas written in the decoder's language, with task macros where a part is one.

:func:`lifted_tokens` writes a formula as ``grammar.to_prefix`` does, with two rewrites, each
proved on automata (the part and its macro accept the same traces), never guessed from the
formula's shape, so that every data set's way of writing a task is recognised:

- a part over one place that names it three times or more and is equivalent to
  ``task.at_least`` / ``at_most`` / ``exactly`` with a count of 1 to 9 becomes
  ``atleast N x`` / ``atmost N x`` / ``exactly N x``;
- in a conjunction, conjuncts ``(!y U x)`` that chain places x1 -> x2 -> ... -> xk, with the
  conjuncts over those places that the chain implies (``F xk``, a written-out sequence, the
  ordering of non-neighbours), become ``ordered x1 ordered x2 ... xk``, or ``strict ...`` when
  conjuncts ``(!x U (x U (!x U y)))`` also say each place is visited once before the next.

Without the macros, "go to a exactly five times" is a formula of 105 tokens and a strict order of
five places 83: longer than the decoder writes, so such examples were left out of training.
"""
from __future__ import annotations

from typing import Optional, Sequence, Union

from ltl_instruct.core.automaton.dfa import equivalent
from ltl_instruct.core.language.neural.grammar import COUNT_MACROS, COUNTS, Chain, to_prefix
from ltl_instruct.core.language.task import conjoin
from ltl_instruct.core.spec import (
    Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or, Release, Until, WeakUntil,
    iter_subformulas,
)

COUNTED = 3           # a place named this often in one part may be a count of visits
_UNARY = {Eventually: 'F', Always: 'G', Next: 'X', Not: '!'}
_BINARY = {Until: 'U', WeakUntil: 'W', Release: 'R', Implies: '->', Iff: '<->'}
_SAME: dict[tuple[str, str], bool] = {}
Part = Union[Formula, Chain]


def lifted_tokens(f: Formula) -> list[str]:
    """Prefix tokens of a lifted formula, macros used where a part is equivalent to one."""
    out: list[str] = []
    _write(f, out)
    return out


def _same(f: Formula, g: Formula) -> bool:
    key = (str(f), str(g))
    if key not in _SAME:
        if len(_SAME) > 100_000:
            _SAME.clear()
        _SAME[key] = equivalent(f, g)
    return _SAME[key]


def _write(f: Formula, out: list[str]) -> None:
    count = count_macro(f)
    if count is not None:
        name, n, x = count
        out.extend((name, str(n)))
        _write(x, out)
    elif isinstance(f, (Atom, Const)):
        out.extend(to_prefix(f))
    elif type(f) in _UNARY:
        out.append(_UNARY[type(f)])
        _write(f.operand, out)  # type: ignore[attr-defined]
    elif type(f) in _BINARY:
        out.append(_BINARY[type(f)])
        _write(f.left, out)  # type: ignore[attr-defined]
        _write(f.right, out)  # type: ignore[attr-defined]
    elif isinstance(f, (And, Or)):
        parts: Sequence[Part] = with_chains(list(f.operands)) if isinstance(f, And) else f.operands
        out.extend(['&' if isinstance(f, And) else '|'] * (len(parts) - 1))
        for p in parts:
            _write_part(p, out)
    else:
        out.extend(to_prefix(f))   # raises: not a lifted formula


def _write_part(p: Part, out: list[str]) -> None:
    if isinstance(p, Chain):
        kind = 'strict' if p.strict else 'ordered'
        for x in p.items[:-1]:
            out.append(kind)
            _write(x, out)
        p = p.items[-1]
    _write(p, out)


def _atoms(f: Formula) -> list[Atom]:
    return [g for g in iter_subformulas(f) if isinstance(g, Atom)]


def count_macro(f: Formula) -> Optional[tuple[str, int, Atom]]:
    """``(macro, n, place)`` when ``f`` is a count of visits of one place (a macro of ``COUNT_MACROS``)."""
    atoms = _atoms(f)
    if len(atoms) < COUNTED or len(set(atoms)) != 1:
        return None
    x = atoms[0]
    for name, build in COUNT_MACROS.items():
        for n in map(int, COUNTS):
            if _same(build(x, n), f):
                return name, n, x
    return None


def _edge(c: Formula) -> Optional[tuple[Atom, Atom, bool]]:
    """``(x, y, strict)`` for ``(!y U x)`` (x before y) or ``(!x U (x U (!x U y)))`` (x once, before y)."""
    if not isinstance(c, Until) or not isinstance(c.left, Not) or not isinstance(c.left.operand, Atom):
        return None
    y, x = c.left.operand, c.right
    if isinstance(x, Atom):
        return (x, y, False) if x != y else None
    if isinstance(x, Until) and x.left == y and isinstance(x.right, Until) and x.right.left == Not(y):
        nxt = x.right.right
        if isinstance(nxt, Atom) and nxt != y:
            return y, nxt, True
    return None


def _order(edges: set[tuple[Atom, Atom]]) -> Optional[list[Atom]]:
    """Return the places in the one order the edges allow, if consecutive ones are all joined by an edge."""
    nodes = {a for e in edges for a in e}
    before = {n: {a for a, b in edges if b == n} for n in nodes}
    order: list[Atom] = []
    while before:
        first = [n for n, bs in before.items() if not bs]
        if len(first) != 1:
            return None
        order.append(first[0])
        del before[first[0]]
        for bs in before.values():
            bs.discard(first[0])
    if all((a, b) in edges for a, b in zip(order, order[1:])):
        return order
    return None


def with_chains(conjuncts: list[Formula]) -> list[Part]:
    """Return the conjuncts, those making an ordered chain of places replaced by the chain (if equivalent)."""
    found = [(_edge(c), c) for c in conjuncts]
    plain = {(e[0], e[1]) for e, _ in found if e is not None and not e[2]}
    order = _order(plain) if plain else None
    if order is None:
        return list(conjuncts)
    strict_edges = {(e[0], e[1]) for e, _ in found if e is not None and e[2]}
    strict_options = [True, False] if all(p in strict_edges for p in zip(order, order[1:])) else [False]
    for strict in strict_options:
        chain = Chain(strict, tuple(order))
        covered = _covered(chain.formula(), set(order), conjuncts)
        whole = conjoin(*(conjuncts[i] for i in covered))
        if whole is not None and _same(whole, chain.formula()):
            rest: list[Part] = [c for i, c in enumerate(conjuncts) if i not in covered]
            return [chain, *rest]
    return list(conjuncts)


def _covered(chain: Formula, places: set[Atom], conjuncts: Sequence[Formula]) -> list[int]:
    """Return the indices of the conjuncts over ``places`` that ``chain`` implies."""
    out = []
    for i, c in enumerate(conjuncts):
        if set(_atoms(c)) <= places and _same(conjoin(chain, c), chain):  # type: ignore[arg-type]
            out.append(i)
    return out

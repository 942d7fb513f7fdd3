"""A small reduced ordered binary decision diagram (ROBDD) manager.

Nodes are ints: ``0`` is false, ``1`` is true, every other node ``n`` tests the
variable at level ``level(n)`` and has a ``low`` (variable false) and a ``high``
(variable true) child at deeper levels. A unique table makes each Boolean function
over the manager's variables one node (equal functions are equal ints), and
``ite`` (if-then-else, from which every connective is built) is memoised.
Variables are levels ``0, 1, ...`` in creation order: the first created is tested
first.
"""
from __future__ import annotations

from typing import Callable, Iterator

FALSE = 0
TRUE = 1
_TERMINAL_LEVEL = 1 << 30

Literal = tuple[int, bool]
"""A variable level and its value."""


class BDD:
    """The node store: unique table, ``ite`` cache and the operations built on them."""

    def __init__(self) -> None:
        self._level = [_TERMINAL_LEVEL, _TERMINAL_LEVEL]
        self._low = [FALSE, TRUE]
        self._high = [FALSE, TRUE]
        self._unique: dict[tuple[int, int, int], int] = {}
        self._ite: dict[tuple[int, int, int], int] = {}
        self._isop: dict[tuple[int, int], tuple[tuple[tuple[Literal, ...], ...], int]] = {}
        self._paths: dict[int, int] = {FALSE: 0, TRUE: 1}   # nodes never change: kept across calls
        self.num_vars = 0

    # ------------------------------------------------------------------ structure
    def __len__(self) -> int:
        """Nodes in the store, terminals included."""
        return len(self._level)

    def new_var(self) -> int:
        """Add a variable below every existing one; return its level."""
        self.num_vars += 1
        return self.num_vars - 1

    def var(self, level: int) -> int:
        """Return the node of the variable at ``level`` (true when it is true)."""
        return self.mk(level, FALSE, TRUE)

    def level(self, node: int) -> int:
        """Level of the variable a node tests (a large number for the terminals)."""
        return self._level[node]

    def low(self, node: int) -> int:
        """Child taken when the node's variable is false."""
        return self._low[node]

    def high(self, node: int) -> int:
        """Child taken when the node's variable is true."""
        return self._high[node]

    def mk(self, level: int, low: int, high: int) -> int:
        """Return the node testing ``level`` with these children (children lie deeper)."""
        if low == high:
            return low
        key = (level, low, high)
        node = self._unique.get(key)
        if node is None:
            node = len(self._level)
            self._level.append(level)
            self._low.append(low)
            self._high.append(high)
            self._unique[key] = node
        return node

    # ------------------------------------------------------------------ connectives
    def ite(self, f: int, g: int, h: int) -> int:
        """If ``f`` then ``g`` else ``h``."""
        if f == TRUE:
            return g
        if f == FALSE:
            return h
        if g == h:
            return g
        if g == TRUE and h == FALSE:
            return f
        key = (f, g, h)
        hit = self._ite.get(key)
        if hit is not None:
            return hit
        lv = self._level
        top = min(lv[f], lv[g], lv[h])
        f0, f1 = self._cofactors(f, top)
        g0, g1 = self._cofactors(g, top)
        h0, h1 = self._cofactors(h, top)
        r = self.mk(top, self.ite(f0, g0, h0), self.ite(f1, g1, h1))
        self._ite[key] = r
        return r

    def _cofactors(self, node: int, level: int) -> tuple[int, int]:
        if self._level[node] == level:
            return self._low[node], self._high[node]
        return node, node

    def neg(self, f: int) -> int:
        """Not ``f``."""
        return self.ite(f, FALSE, TRUE)

    def conj(self, f: int, g: int) -> int:
        """``f`` and ``g``."""
        return self.ite(f, g, FALSE)

    def disj(self, f: int, g: int) -> int:
        """``f`` or ``g``."""
        return self.ite(f, TRUE, g)

    def iff(self, f: int, g: int) -> int:
        """``f`` if and only if ``g``."""
        return self.ite(f, g, self.neg(g))

    # ------------------------------------------------------------------ queries
    def evaluate(self, f: int, value_of: Callable[[int], bool]) -> bool:
        """Value of ``f`` when each variable (by level) has the value ``value_of(level)``."""
        while f > TRUE:
            f = self._high[f] if value_of(self._level[f]) else self._low[f]
        return f == TRUE

    def support(self, f: int) -> frozenset[int]:
        """Levels of the variables ``f`` depends on."""
        seen: set[int] = set()
        levels: set[int] = set()
        stack = [f]
        while stack:
            n = stack.pop()
            if n <= TRUE or n in seen:
                continue
            seen.add(n)
            levels.add(self._level[n])
            stack += (self._low[n], self._high[n])
        return frozenset(levels)

    def size(self, f: int) -> int:
        """Inner nodes reachable from ``f``."""
        seen: set[int] = set()
        stack = [f]
        while stack:
            n = stack.pop()
            if n > TRUE and n not in seen:
                seen.add(n)
                stack += (self._low[n], self._high[n])
        return len(seen)

    def count_paths(self, f: int) -> int:
        """Paths from ``f`` to ``TRUE`` (the size of the disjoint cover :meth:`paths` gives)."""
        memo = self._paths

        def rec(n: int) -> int:
            got = memo.get(n)
            if got is None:
                got = memo[n] = rec(self._low[n]) + rec(self._high[n])
            return got
        return rec(f)

    def paths(self, f: int) -> Iterator[tuple[Literal, ...]]:
        """Disjoint cubes of ``f``: one per path to ``TRUE``."""
        stack: list[tuple[int, tuple[Literal, ...]]] = [(f, ())]
        while stack:
            n, lits = stack.pop()
            if n == TRUE:
                yield lits
            elif n != FALSE:
                lv = self._level[n]
                stack.append((self._low[n], lits + ((lv, False),)))
                stack.append((self._high[n], lits + ((lv, True),)))

    def isop(self, lower: int, upper: int,
             max_cubes: int = 1 << 62) -> tuple[tuple[Literal, ...], ...]:
        """Return an irredundant sum of products ``c`` with ``lower <= c <= upper`` (Minato-Morreale).

        With ``lower == upper`` it is a compact cover of one function; a larger
        ``upper`` adds letters that do not matter (don't-cares) to make cubes shorter.
        Raises ``OverflowError`` as soon as a cover needs more than ``max_cubes`` cubes.
        """
        return self._isop_rec(lower, upper, max_cubes)[0]

    def _isop_rec(self, lower: int, upper: int,
                  max_cubes: int) -> tuple[tuple[tuple[Literal, ...], ...], int]:
        if lower == FALSE:
            return (), FALSE
        if upper == TRUE:
            return ((),), TRUE
        key = (lower, upper)
        hit = self._isop.get(key)
        if hit is not None:
            return hit
        x = min(self._level[lower], self._level[upper])
        l0, l1 = self._cofactors(lower, x)
        u0, u1 = self._cofactors(upper, x)
        c0, f0 = self._isop_rec(self.conj(l0, self.neg(u1)), u0, max_cubes)
        c1, f1 = self._isop_rec(self.conj(l1, self.neg(u0)), u1, max_cubes)
        rest_lower = self.disj(self.conj(l0, self.neg(f0)), self.conj(l1, self.neg(f1)))
        cs, fs = self._isop_rec(rest_lower, self.conj(u0, u1), max_cubes)
        if len(c0) + len(c1) + len(cs) > max_cubes:
            raise OverflowError(f'more than {max_cubes} cubes')
        cubes = (tuple(c + ((x, False),) for c in c0) + tuple(c + ((x, True),) for c in c1) + cs)
        cover = self.disj(self.mk(x, f0, f1), fs)
        self._isop[key] = (cubes, cover)
        return cubes, cover

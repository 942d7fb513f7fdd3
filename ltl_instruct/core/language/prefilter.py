"""Text a regular expression cannot match without: a cheap test before running it.

The rewriting modules run a few hundred patterns over every sentence, and most of them
cannot match it. :func:`required_text` reads a pattern's syntax tree and returns what any
match must contain, as clauses: each clause is a set of literal strings, and a match holds
at least one string of every clause. :func:`admits` checks that on a text with substring
tests, which costs a small fraction of running the pattern, so a rule whose literal
text is absent is skipped.

The analysis is exact where it answers and silent where it cannot: a branch without a
literal of its own, an optional part, a negative lookaround and a character class give no
clause, so a pattern with nothing certain has no clauses and is always run.
"""
from __future__ import annotations

import re
from re import _constants as c   # type: ignore[attr-defined]
from re import _parser as parser   # type: ignore[attr-defined]
from typing import Any, Iterable

Clauses = tuple[frozenset[str], ...]

# Literal runs shorter than this are too common to tell sentences apart; they are left out.
_MIN_LITERAL = 2


def required_text(pattern: str, limit: int = 4) -> Clauses:
    """Return clauses that every match of ``pattern`` satisfies (see the module docstring).

    At most ``limit`` clauses are kept, those with the longest shortest string first (the
    most selective). A pattern compiled with flags that change what a literal matches
    (``re.IGNORECASE``, ``(?i)``) gets no clauses.
    """
    tree = parser.parse(pattern)
    if tree.state.flags & re.IGNORECASE:
        return ()
    clauses = {cl for cl in _sequence(list(tree)) if cl}
    ranked = sorted(clauses, key=lambda cl: (-min(len(s) for s in cl), sorted(cl)))
    return tuple(ranked[:limit])


def admits(clauses: Clauses, text: str) -> bool:
    """Whether ``text`` holds a string of every clause (else no match of the pattern is possible)."""
    return all(any(s in text for s in clause) for clause in clauses)


def _sequence(items: list[tuple[Any, Any]]) -> list[frozenset[str]]:
    """Clauses of a sequence of pattern items: each run of literals, and each item's own."""
    out: list[frozenset[str]] = []
    run: list[str] = []

    def flush() -> None:
        if len(run) >= _MIN_LITERAL:
            out.append(frozenset({''.join(run)}))
        run.clear()

    for op, av in items:
        if op is c.LITERAL:
            run.append(chr(av))
            continue
        flush()
        out.extend(_item(op, av))
    flush()
    return out


def _item(op: Any, av: Any) -> list[frozenset[str]]:
    """Clauses of one non-literal item."""
    if op is c.SUBPATTERN:
        _group, add_flags, _del_flags, sub = av
        if add_flags & re.IGNORECASE:
            return []
        return _sequence(list(sub))
    if op in (c.MAX_REPEAT, c.MIN_REPEAT, c.POSSESSIVE_REPEAT):
        low, _high, sub = av
        return _sequence(list(sub)) if low >= 1 else []
    if op is c.ASSERT:
        _direction, sub = av
        return _sequence(list(sub))   # what a lookaround sees is in the text too
    if op is c.BRANCH:
        _none, branches = av
        return _branch(branches)
    return []   # classes, anchors, negative lookarounds, back-references: nothing certain


def _branch(branches: Iterable[Any]) -> list[frozenset[str]]:
    """One clause for an alternation: the best clause of every branch, any of which will do."""
    union: set[str] = set()
    for sub in branches:
        own = [cl for cl in _sequence(list(sub)) if cl]
        if not own:
            return []   # a branch that needs no literal: the alternation needs none
        union |= max(own, key=lambda cl: (min(len(s) for s in cl), -len(cl)))
    return [frozenset(union)]

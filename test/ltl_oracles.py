"""Test helpers: exhaustive traces, product checks, and the ltlf2dfa + mona oracle."""
from __future__ import annotations

import itertools
import os
import re
import shutil
import tempfile
from collections import deque
from typing import Iterator, Optional, Sequence

from ltl_instruct.core.spec import (
    FALSE, TRUE, Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or,
    Release, Until, WeakNext, WeakUntil, parse_formula,
)


def valid_letters(atoms: Sequence[Atom]) -> list[frozenset[Atom]]:
    """Every letter over ``atoms`` with at most one event atom true."""
    out = []
    for bits in itertools.product((False, True), repeat=len(atoms)):
        letter = frozenset(a for a, b in zip(atoms, bits) if b)
        if sum(a.is_event for a in letter) <= 1:
            out.append(letter)
    return out


def all_traces(letters: Sequence[frozenset], max_len: int) -> Iterator[tuple]:
    """Every non-empty trace over ``letters`` up to ``max_len``."""
    for n in range(1, max_len + 1):
        yield from itertools.product(letters, repeat=n)


def to_ltlf2dfa_text(f: Formula, names: dict[Atom, str]) -> str:
    """Fully parenthesised text in ltlf2dfa's syntax (W expanded: a W b = (a U b) | G a)."""
    def t(g: Formula) -> str:
        if isinstance(g, Const):
            return 'true' if g.value else 'false'
        if isinstance(g, Atom):
            return names[g]
        if isinstance(g, Not):
            return f'!({t(g.operand)})'
        if isinstance(g, And):
            return '(' + ' & '.join(t(o) for o in g.operands) + ')'
        if isinstance(g, Or):
            return '(' + ' | '.join(t(o) for o in g.operands) + ')'
        if isinstance(g, Implies):
            return f'(({t(g.left)}) -> ({t(g.right)}))'
        if isinstance(g, Iff):
            return f'(({t(g.left)}) <-> ({t(g.right)}))'
        if isinstance(g, Next):
            return f'X({t(g.operand)})'
        if isinstance(g, WeakNext):
            return f'WX({t(g.operand)})'
        if isinstance(g, Eventually):
            return f'F({t(g.operand)})'
        if isinstance(g, Always):
            return f'G({t(g.operand)})'
        if isinstance(g, Until):
            return f'(({t(g.left)}) U ({t(g.right)}))'
        if isinstance(g, Release):
            return f'(({t(g.left)}) R ({t(g.right)}))'
        if isinstance(g, WeakUntil):
            return f'((({t(g.left)}) U ({t(g.right)})) | G({t(g.left)}))'
        raise TypeError(g)
    return t(f)


class MonaDfa:
    """A DFA read from ltlf2dfa's DOT output; guards are evaluated on letters."""

    def __init__(self, dot: str, names: dict[Atom, str]) -> None:
        self.names = dict(names)
        self.accepting: set[str] = set()
        m = re.search(r'node \[shape = doublecircle\];([^\n]*)', dot)
        if m:
            self.accepting = {x.strip() for x in m.group(1).split(';') if x.strip()}
        self.initial = re.search(r'init -> (\w+);', dot).group(1)
        self.edges: dict[str, list[tuple[str, Formula]]] = {}
        for src, dst, label in re.findall(r'(\w+) -> (\w+) \[label="([^"]*)"\];', dot):
            self.edges.setdefault(src, []).append((dst, parse_formula(label)))

    def step(self, s: str, letter: frozenset[Atom]) -> str:
        named = {near(self.names[a]) for a in letter if a in self.names}
        for dst, g in self.edges.get(s, []):
            if _eval_prop(g, named):
                return dst
        raise AssertionError(f'no mona edge from {s}')


def near(name: str) -> Atom:
    from ltl_instruct.core.spec import near as mk
    return mk(name)


def _eval_prop(g: Formula, true_atoms: set) -> bool:
    if isinstance(g, Const):
        return g.value
    if isinstance(g, Atom):
        return g in true_atoms
    if isinstance(g, Not):
        return not _eval_prop(g.operand, true_atoms)
    if isinstance(g, And):
        return all(_eval_prop(o, true_atoms) for o in g.operands)
    if isinstance(g, Or):
        return any(_eval_prop(o, true_atoms) for o in g.operands)
    raise TypeError(g)


def mona_available() -> bool:
    """ltlf2dfa silently returns garbage without mona: check for it."""
    try:
        import ltlf2dfa  # noqa: F401
    except ImportError:
        return False
    return shutil.which('mona') is not None


_TMP: Optional[str] = None


def ltlf2dfa_dfa(f: Formula, atoms: Sequence[Atom]) -> MonaDfa:
    """Compile ``f`` with ltlf2dfa + mona (names p0..pn mapped back to our atoms)."""
    global _TMP
    import ltlf2dfa.ltlf2dfa as core
    from ltlf2dfa.parser.ltlf import LTLfParser
    if _TMP is None:
        _TMP = tempfile.mkdtemp(prefix='ltlf2dfa_')
        core.PACKAGE_DIR = _TMP
    names = {a: f'v{i}' for i, a in enumerate(atoms)}
    dot = LTLfParser()(to_ltlf2dfa_text(f, names)).to_dfa()
    return MonaDfa(dot, names)


def languages_differ(ours, mona: MonaDfa, letters: Sequence[frozenset]) -> Optional[list]:
    """Return a shortest non-empty trace on which the two DFAs disagree, or None."""
    start = (ours.initial, mona.initial)
    q = deque([(start, [])])
    seen = {start}
    while q:
        (s, t), trace = q.popleft()
        if trace and ((s in ours.accepting) != (t in mona.accepting)):
            return trace
        for letter in letters:
            nxt = (ours.step(s, letter), mona.step(t, letter))
            if nxt not in seen:
                seen.add(nxt)
                q.append((nxt, trace + [letter]))
    return None


def minimal_states(aut, letters: Sequence[frozenset]) -> int:
    """States of the minimal DFA of ``aut``'s language: Moore's algorithm over explicit letters."""
    n = aut.num_states
    table = [[aut.step(s, x) for x in letters] for s in range(n)]
    block = [int(s in aut.accepting) for s in range(n)]
    while True:
        sigs: dict[tuple, int] = {}
        new = [sigs.setdefault((block[s],) + tuple(block[t] for t in table[s]), len(sigs))
               for s in range(n)]
        if len(sigs) == len(set(block)):
            return len(sigs)
        block = new


def shrink(f: Formula, still_fails) -> Formula:
    """Greedy shrinking: replace sub-formulas by a child or a constant while it still fails."""
    def candidates(g: Formula) -> Iterator[Formula]:
        yield TRUE
        yield FALSE
        yield from g.children()
        kids = g.children()
        for i, k in enumerate(kids):
            for c in candidates(k):
                new = list(kids)
                new[i] = c
                try:
                    if isinstance(g, (And, Or)):
                        yield type(g)(tuple(new))
                    elif len(new) == 1:
                        yield type(g)(new[0])
                    else:
                        yield type(g)(new[0], new[1])
                except ValueError:
                    continue
    changed = True
    while changed:
        changed = False
        for c in candidates(f):
            if len(str(c)) < len(str(f)) and still_fails(c):
                f = c
                changed = True
                break
    return f


__all__ = ['valid_letters', 'all_traces', 'ltlf2dfa_dfa', 'languages_differ', 'mona_available',
           'minimal_states',
           'shrink', 'to_ltlf2dfa_text', 'TRUE', 'FALSE', 'Always', 'Eventually']
_ = os

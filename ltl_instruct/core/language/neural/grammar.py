"""Lifted formulas as prefix token sequences, and the grammar that decoding obeys.

A lifted formula (``F (near[s1] & F near[s2])``) is written in prefix order:
``F & near s1 F near s2``. Operators take formulas; ``near`` and ``pick`` take one slot,
``release`` two. :class:`GrammarState` tracks what the sequence still needs (a stack of
``FORMULA`` / ``SLOT`` items) and gives the tokens allowed next, so that a decoder that only
takes allowed tokens always ends with a formula that parses (type-constrained decoding).
The length budget is part of the grammar: no token is allowed that could not be completed
within ``max_len`` tokens.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

from ltl_instruct.core.errors import TranslationError
from ltl_instruct.core.language.task import at_least, at_most, conjoin, exactly
from ltl_instruct.core.spec import (
    Always, And, Atom, Const, Descriptor, Eventually, Formula, Iff, Implies, Next, Not, Or, Release,
    Until, WeakUntil, parse_formula,
)

MAX_SLOTS = 12
UNARY = ('F', 'G', 'X', '!')
BINARY = ('&', '|', 'U', 'W', 'R', '->', '<->')
CONSTANTS = ('true', 'false')
SKILLS = {'near': 1, 'pick': 1, 'release': 2}
SLOTS = tuple(f's{k}' for k in range(1, MAX_SLOTS + 1))
# things a task implies without naming them ("throw away the cup": the cup goes in the trash can)
IMPLIED = ('trash_can',)
COUNT_MACROS = {'atleast': at_least, 'atmost': at_most, 'exactly': exactly}
CHAIN_MACROS = ('ordered', 'strict')
COUNTS = tuple(str(n) for n in range(1, 10))
TOKENS: tuple[str, ...] = (UNARY + BINARY + CONSTANTS + tuple(SKILLS) + SLOTS + IMPLIED
                           + tuple(COUNT_MACROS) + CHAIN_MACROS + COUNTS)
TOKEN_ID = {t: i for i, t in enumerate(TOKENS)}
BOS = len(TOKENS)            # start symbol fed to the decoder (never emitted)
VOCAB_SIZE = len(TOKENS) + 1

_UNARY_TYPES = {Eventually: 'F', Always: 'G', Next: 'X', Not: '!'}
_BINARY_TYPES = {Until: 'U', WeakUntil: 'W', Release: 'R', Implies: '->', Iff: '<->'}
_BUILD_UNARY = {'F': Eventually, 'G': Always, 'X': Next, '!': Not}
_BUILD_BINARY = {'U': Until, 'W': WeakUntil, 'R': Release, '->': Implies, '<->': Iff}

FORMULA, SLOT, COUNT = 0, 1, 2


def to_prefix(f: Formula) -> list[str]:
    """Prefix tokens of a lifted formula (n-ary ``&``/``|`` nest to the right)."""
    out: list[str] = []
    stack: list[Formula] = [f]
    while stack:
        g = stack.pop()
        if isinstance(g, Atom):
            if g.skill not in SKILLS or any(str(d) not in SLOTS + IMPLIED for d in g.args):
                raise TranslationError(f'not a lifted atom: {g}')
            out.append(g.skill)
            out.extend(str(d) for d in g.args)
        elif isinstance(g, Const):
            out.append('true' if g.value else 'false')
        elif type(g) in _UNARY_TYPES:
            out.append(_UNARY_TYPES[type(g)])
            stack.append(g.operand)  # type: ignore[attr-defined]
        elif type(g) in _BINARY_TYPES:
            out.append(_BINARY_TYPES[type(g)])
            stack.extend((g.right, g.left))  # type: ignore[attr-defined]
        elif isinstance(g, (And, Or)):
            ops = list(g.operands)
            sym = '&' if isinstance(g, And) else '|'
            out.extend([sym] * (len(ops) - 1))
            stack.extend(reversed(ops))
        else:
            raise TranslationError(f'cannot write {type(g).__name__} as lifted tokens')
    return out


@dataclass(frozen=True)
class Chain:
    """Places in order (``ordered``/``strict`` macros), kept apart until an operator takes them."""

    strict: bool
    items: tuple[Formula, ...]

    def formula(self) -> Formula:
        """``(!x2 U x1) & ... & F xk`` (``strict``: and no second visit of one before the next)."""
        xs = self.items
        parts: list[Formula] = [Until(Not(b), a) for a, b in zip(xs, xs[1:])]
        parts.append(Eventually(xs[-1]))
        if self.strict:
            parts += [Until(Not(a), Until(a, Until(Not(a), b))) for a, b in zip(xs, xs[1:])]
        return conjoin(*parts)  # type: ignore[return-value]


def chain_of(kind: str, first: Formula, rest: 'Formula | Chain') -> Chain:
    """Return the chain ``first`` then ``rest`` (a chain of the same kind goes on, anything else ends it)."""
    strict = kind == 'strict'
    if isinstance(rest, Chain) and rest.strict == strict:
        return Chain(strict, (first,) + rest.items)
    return Chain(strict, (first, _formula(rest)))


def _formula(v: object) -> Formula:
    return v.formula() if isinstance(v, Chain) else v  # type: ignore[return-value]


def from_prefix(tokens: Sequence[str]) -> Formula:
    """Build the formula of a complete prefix sequence (raises ``TranslationError`` if incomplete)."""
    try:
        value = _build(tokens)
    except IndexError:
        value = None
    if not isinstance(value, Formula):
        raise TranslationError(f'incomplete lifted formula: {" ".join(tokens)}')
    return value


def _build(tokens: Sequence[str]) -> Optional[Formula]:
    """Return the formula of a prefix sequence, None if not one (IndexError if an operand is missing)."""
    values: list[object] = []   # built right to left: operands are on top when an operator comes
    for tok in reversed(tokens):
        if tok in SLOTS or tok in IMPLIED:
            values.append(Descriptor(tok))
        elif tok in COUNTS:
            values.append(int(tok))
        elif tok in SKILLS:
            n = SKILLS[tok]
            args = [values.pop() for _ in range(n)]
            values.append(Atom(tok, tuple(args)))  # type: ignore[arg-type]
        elif tok in CONSTANTS:
            values.append(parse_formula(tok))
        elif tok in _BUILD_UNARY:
            values.append(_BUILD_UNARY[tok](_formula(values.pop())))
        elif tok in COUNT_MACROS:
            n, x = values.pop(), _formula(values.pop())
            values.append(COUNT_MACROS[tok](x, n))
        elif tok in CHAIN_MACROS:
            a, b = _formula(values.pop()), values.pop()
            values.append(chain_of(tok, a, b))  # type: ignore[arg-type]
        elif tok in ('&', '|'):
            a, b = _formula(values.pop()), _formula(values.pop())
            values.append((And if tok == '&' else Or)((a, b)))
        elif tok in _BUILD_BINARY:
            a, b = _formula(values.pop()), _formula(values.pop())
            values.append(_BUILD_BINARY[tok](a, b))
        else:
            raise TranslationError(f'unknown lifted token {tok!r}')
    if len(values) != 1 or isinstance(values[0], int):
        return None
    return _formula(values[0])


def _arity(tok: str) -> tuple[int, ...]:
    """Item kinds a token pushes (what it needs next)."""
    if tok in UNARY:
        return (FORMULA,)
    if tok in BINARY or tok in CHAIN_MACROS:
        return (FORMULA, FORMULA)
    if tok in COUNT_MACROS:
        return (COUNT, FORMULA)
    if tok in SKILLS:
        return (SLOT,) * SKILLS[tok]
    return ()


_PUSHES = tuple(_arity(t) for t in TOKENS)
# fewest tokens that complete one item: a formula needs at least 'near sK', a slot one token
_MIN_COST = {FORMULA: 2, SLOT: 1, COUNT: 1}


@dataclass
class GrammarState:
    """What a partial prefix sequence still needs; ``allowed`` gives the next legal token ids."""

    needs: list[int]
    length: int = 0
    max_len: int = 48

    @classmethod
    def start(cls, max_len: int = 48) -> 'GrammarState':
        """Return the state before the first token: one formula needed."""
        return cls([FORMULA], 0, max_len)

    @property
    def done(self) -> bool:
        """True when the sequence is a complete formula."""
        return not self.needs

    def allowed(self, n_slots: int) -> list[int]:
        """Token ids allowed next, given the number of slots the instruction has (0 if done)."""
        if self.done:
            return []
        kind = self.needs[-1]
        if kind == SLOT:
            return [TOKEN_ID[s] for s in SLOTS[:max(n_slots, 1)] + IMPLIED]
        if kind == COUNT:
            return [TOKEN_ID[c] for c in COUNTS]
        budget = self.max_len - self.length - 1
        rest = sum(_MIN_COST[k] for k in self.needs[:-1])
        out = []
        for i, tok in enumerate(TOKENS):
            if tok in SLOTS or tok in IMPLIED or tok in COUNTS:
                continue
            cost = sum(_MIN_COST[k] for k in _PUSHES[i])
            if rest + cost <= budget:
                out.append(i)
        return out

    def push(self, token_id: int) -> 'GrammarState':
        """Return the state after one more token."""
        needs = self.needs[:-1] + list(reversed(_PUSHES[token_id]))
        return GrammarState(needs, self.length + 1, self.max_len)


def slots_used(tokens: Sequence[str]) -> set[str]:
    """Slot names a token sequence uses."""
    return {t for t in tokens if t in SLOTS}


def check_prefix(tokens: Sequence[str], n_slots: Optional[int] = None) -> bool:
    """Tell whether a token sequence is a complete, grammatical lifted formula."""
    state = GrammarState.start(max_len=3 * len(tokens) + 2)   # constants cost 1, not 2
    for tok in tokens:
        if tok not in TOKEN_ID or TOKEN_ID[tok] not in state.allowed(n_slots or MAX_SLOTS):
            return False
        state = state.push(TOKEN_ID[tok])
    return state.done

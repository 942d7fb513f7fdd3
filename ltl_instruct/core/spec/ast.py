"""Immutable abstract syntax of task formulas and composable referent descriptors.

A formula (``spec/formula.md``) is co-safe LTL over skill atoms such as
``near[sofa::isbehind(pillar)]``. Nodes are frozen dataclasses with a hash
computed once, so formulas can be dictionary keys and automaton states.

Construct formulas with the smart constructors :func:`conj`, :func:`disj` and
:func:`neg` when normal forms matter (they flatten, deduplicate, sort and fold
constants); the plain classes keep exactly what was written.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterator, Union

SKILLS: dict[str, int] = {'near': 1, 'pick': 1, 'release': 2}
"""Skill name -> number of descriptor arguments."""

EVENT_SKILLS = frozenset({'pick', 'release'})
"""Skills that are events: true at one step, never two at once."""

COMPARATORS: dict[str, int] = {
    'isbetween': 2, 'isabove': 1, 'isbelow': 1, 'isleftof': 1,
    'isrightof': 1, 'isnextto': 1, 'isinfrontof': 1, 'isbehind': 1,
}
"""Comparator name -> number of descriptor arguments."""

KEYWORDS = frozenset({'true', 'false'}) | frozenset(SKILLS) | frozenset(COMPARATORS)
"""Lower-case words that cannot be names."""


def _hash_init(obj: object, *parts: object) -> None:
    object.__setattr__(obj, '_hash', hash((type(obj).__name__,) + parts))


# --------------------------------------------------------------------------- descriptors

@dataclass(frozen=True, eq=True, repr=False)
class Relation:
    """A comparator applied to argument descriptors, e.g. ``isbetween(a, b)``."""

    comparator: str
    args: tuple['Descriptor', ...]
    _hash: int = field(init=False, compare=False, default=0)

    def __post_init__(self) -> None:
        _hash_init(self, self.comparator, self.args)

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:
        return f'Relation({self})'

    def __str__(self) -> str:
        return f"{self.comparator}({', '.join(str(a) for a in self.args)})"


@dataclass(frozen=True, eq=True, repr=False)
class Descriptor:
    """A composable referent descriptor (CRD): a name and chained relations.

    ``chair::isbetween(laptop, box::isbelow(toy))`` is
    ``Descriptor('chair', (Relation('isbetween', (laptop, box_below_toy)),))``.
    """

    name: str
    relations: tuple[Relation, ...] = ()
    _hash: int = field(init=False, compare=False, default=0)

    def __post_init__(self) -> None:
        _hash_init(self, self.name, self.relations)

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:
        return f'Descriptor({self})'

    def __str__(self) -> str:
        return self.name + ''.join('::' + str(r) for r in self.relations)

    @property
    def depth(self) -> int:
        """Nesting depth: 0 for a bare name, 1 + deepest argument otherwise."""
        if not self.relations:
            return 0
        return 1 + max(a.depth for r in self.relations for a in r.args)

    def names(self) -> Iterator[str]:
        """Yield every object-class name mentioned, this one first."""
        yield self.name
        for r in self.relations:
            for a in r.args:
                yield from a.names()


# --------------------------------------------------------------------------- formulas

class Formula:
    """Base class of formula nodes (all immutable and hashable)."""

    __slots__ = ()
    precedence: int = 100  # for printing: higher binds tighter

    def children(self) -> tuple['Formula', ...]:
        """Direct sub-formulas."""
        return ()

    def __str__(self) -> str:
        text = self.__dict__.get('_text')
        if text is None:  # printed once, then cached: str() is the canonical sort key
            from ltl_instruct.core.spec.printer import format_formula
            text = format_formula(self)
            object.__setattr__(self, '_text', text)
        return text

    def __repr__(self) -> str:
        return f'<{type(self).__name__} {self}>'

    def __and__(self, other: 'Formula') -> 'Formula':
        return conj(self, other)

    def __or__(self, other: 'Formula') -> 'Formula':
        return disj(self, other)

    def __invert__(self) -> 'Formula':
        return neg(self)


@dataclass(frozen=True, eq=True, repr=False)
class Const(Formula):
    """``true`` or ``false``."""

    value: bool
    _hash: int = field(init=False, compare=False, default=0)

    def __post_init__(self) -> None:
        _hash_init(self, self.value)

    def __hash__(self) -> int:
        return self._hash


TRUE = Const(True)
FALSE = Const(False)


@dataclass(frozen=True, eq=True, repr=False)
class Atom(Formula):
    """A skill predicate over descriptors: ``near[x]``, ``pick[x]``, ``release[x, y]``.

    A plain proposition ``p`` of a landmark environment parses to ``near[p]``.
    """

    skill: str
    args: tuple[Descriptor, ...]
    _hash: int = field(init=False, compare=False, default=0)

    def __post_init__(self) -> None:
        _hash_init(self, self.skill, self.args)

    def __hash__(self) -> int:
        return self._hash

    @property
    def is_event(self) -> bool:
        """True for pick and release: true at one step of a trace only."""
        return self.skill in EVENT_SKILLS

    @property
    def key(self) -> str:
        """The atom's text, e.g. ``near[sofa::isbehind(pillar)]`` (a stable id)."""
        return str(self)


def near(name: Union[str, Descriptor]) -> Atom:
    """Build the near-atom of a name or descriptor (``'sofa'`` gives ``near[sofa]``)."""
    return Atom('near', (name if isinstance(name, Descriptor) else Descriptor(name),))


@dataclass(frozen=True, eq=True, repr=False)
class Not(Formula):
    """Negation ``!f`` (``~f`` parses to the same)."""

    operand: Formula
    _hash: int = field(init=False, compare=False, default=0)
    precedence = 90

    def __post_init__(self) -> None:
        _hash_init(self, self.operand)

    def __hash__(self) -> int:
        return self._hash

    def children(self) -> tuple[Formula, ...]:
        """Direct sub-formulas."""
        return (self.operand,)


@dataclass(frozen=True, eq=True, repr=False)
class _Unary(Formula):
    operand: Formula
    _hash: int = field(init=False, compare=False, default=0)
    precedence = 90
    symbol = '?'

    def __post_init__(self) -> None:
        _hash_init(self, self.operand)

    def __hash__(self) -> int:
        return self._hash

    def children(self) -> tuple[Formula, ...]:
        return (self.operand,)


class Next(_Unary):
    """Strong next ``X f``: there is a next step, and f holds from it."""

    symbol = 'X'


class WeakNext(_Unary):
    """Weak next: if there is a next step, f holds from it (prints as ``!X !f``)."""

    symbol = 'WX'


class Eventually(_Unary):
    """``F f``: f holds at some step from now on."""

    symbol = 'F'


class Always(_Unary):
    """``G f``: f holds at every step from now to the end of the trace."""

    symbol = 'G'


@dataclass(frozen=True, eq=True, repr=False)
class _Binary(Formula):
    left: Formula
    right: Formula
    _hash: int = field(init=False, compare=False, default=0)
    symbol = '?'

    def __post_init__(self) -> None:
        _hash_init(self, self.left, self.right)

    def __hash__(self) -> int:
        return self._hash

    def children(self) -> tuple[Formula, ...]:
        return (self.left, self.right)


class Until(_Binary):
    """``a U b``: b holds at some step, and a at every step before it."""

    symbol = 'U'
    precedence = 80


class Release(_Binary):
    """``a R b``: b holds up to and including the first step where a holds (or always)."""

    symbol = 'R'
    precedence = 80


class WeakUntil(_Binary):
    """``a W b``: a U b, or a holds at every step."""

    symbol = 'W'
    precedence = 80


class Implies(_Binary):
    """``a -> b``."""

    symbol = '->'
    precedence = 50


class Iff(_Binary):
    """``a <-> b``."""

    symbol = '<->'
    precedence = 50


@dataclass(frozen=True, eq=True, repr=False)
class _NAry(Formula):
    operands: tuple[Formula, ...]
    _hash: int = field(init=False, compare=False, default=0)
    symbol = '?'

    def __post_init__(self) -> None:
        if len(self.operands) < 2:
            raise ValueError(f'{type(self).__name__} needs at least two operands')
        _hash_init(self, self.operands)

    def __hash__(self) -> int:
        return self._hash

    def children(self) -> tuple[Formula, ...]:
        return self.operands


class And(_NAry):
    """Conjunction of two or more formulas."""

    symbol = '&'
    precedence = 70


class Or(_NAry):
    """Disjunction of two or more formulas."""

    symbol = '|'
    precedence = 60


TEMPORAL_UNARY = (Next, WeakNext, Eventually, Always)
TEMPORAL_BINARY = (Until, Release, WeakUntil)


# --------------------------------------------------------------------------- smart constructors

def _sort_key(f: Formula) -> tuple[int, str]:
    return (0 if isinstance(f, (Atom, Not)) else 1, str(f))


def conj(*operands: Formula) -> Formula:
    """Conjunction, flattened, deduplicated, sorted, with constants folded.

    ``a & !a`` folds to ``false`` for atoms (literal complement).
    """
    items: set[Formula] = set()
    for f in operands:
        parts = f.operands if isinstance(f, And) else (f,)
        for p in parts:
            if p == FALSE:
                return FALSE
            if p != TRUE:
                items.add(p)
    for p in items:
        if isinstance(p, Not) and p.operand in items:
            return FALSE
    if not items:
        return TRUE
    if len(items) == 1:
        return next(iter(items))
    return And(tuple(sorted(items, key=_sort_key)))


def disj(*operands: Formula) -> Formula:
    """Disjunction, flattened, deduplicated, sorted, with constants folded."""
    items: set[Formula] = set()
    for f in operands:
        parts = f.operands if isinstance(f, Or) else (f,)
        for p in parts:
            if p == TRUE:
                return TRUE
            if p != FALSE:
                items.add(p)
    for p in items:
        if isinstance(p, Not) and p.operand in items:
            return TRUE
    if not items:
        return FALSE
    if len(items) == 1:
        return next(iter(items))
    return Or(tuple(sorted(items, key=_sort_key)))


def neg(f: Formula) -> Formula:
    """Negation with constants and double negation folded."""
    if isinstance(f, Const):
        return FALSE if f.value else TRUE
    if isinstance(f, Not):
        return f.operand
    return Not(f)


# --------------------------------------------------------------------------- queries

def iter_subformulas(f: Formula) -> Iterator[Formula]:
    """Yield every node of ``f`` (pre-order), without recursion limits."""
    stack = [f]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(reversed(node.children()))


def atoms_of(f: Formula) -> tuple[Atom, ...]:
    """Distinct atoms of ``f`` in order of first appearance."""
    seen: dict[Atom, None] = {}
    for node in iter_subformulas(f):
        if isinstance(node, Atom):
            seen.setdefault(node, None)
    return tuple(seen)


def rename_descriptors(f: Formula, mapping: dict[Descriptor, Descriptor]) -> Formula:
    """Return ``f`` with every skill argument in ``mapping`` replaced."""
    if isinstance(f, Atom):
        return Atom(f.skill, tuple(mapping.get(d, d) for d in f.args))
    if isinstance(f, Not):
        return Not(rename_descriptors(f.operand, mapping))
    if isinstance(f, _Unary):
        return type(f)(rename_descriptors(f.operand, mapping))
    if isinstance(f, _Binary):
        return type(f)(rename_descriptors(f.left, mapping), rename_descriptors(f.right, mapping))
    if isinstance(f, (And, Or)):
        return type(f)(tuple(rename_descriptors(g, mapping) for g in f.operands))
    return f


def referents_of(f: Formula) -> tuple[Descriptor, ...]:
    """Distinct skill-argument descriptors in order of first appearance."""
    seen: dict[Descriptor, None] = {}
    for a in atoms_of(f):
        for d in a.args:
            seen.setdefault(d, None)
    return tuple(seen)


def avoided_referents_of(f: Formula) -> tuple[Descriptor, ...]:
    """Descriptors that appear inside the operand of an explicit negation."""
    seen: dict[Descriptor, None] = {}
    for node in iter_subformulas(f):
        if isinstance(node, Not):
            for a in atoms_of(node.operand):
                for d in a.args:
                    seen.setdefault(d, None)
    return tuple(seen)


def formula_depth(f: Formula) -> int:
    """Nesting depth of operators (an atom has depth 1)."""
    depth = {}
    order = list(iter_subformulas(f))
    for node in reversed(order):
        kids = node.children()
        depth[id(node)] = 1 + max((depth[id(k)] for k in kids), default=0)
    return depth[id(f)]

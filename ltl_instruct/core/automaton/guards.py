"""Symbolic edge guards: disjunctions of cubes (conjunctions of atom literals).

A guard says which letters take an edge, without listing the 2^n assignments.
Letters are sets of true atoms; at most one event atom (``pick``, ``release``)
is true in a letter, which cubes take into account when checking consistency.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import AbstractSet, Any, Iterable, Mapping

from ltl_instruct.core.spec.ast import Atom
from ltl_instruct.core.spec.parser import parse_formula


@dataclass(frozen=True)
class Cube:
    """A conjunction of literals: every ``pos`` atom true, every ``neg`` atom false."""

    pos: frozenset[Atom] = frozenset()
    neg: frozenset[Atom] = frozenset()

    def evaluate(self, letter: AbstractSet[Atom]) -> bool:
        """Whether the letter satisfies every literal."""
        return self.pos <= letter and not (self.neg & letter)

    @property
    def atoms(self) -> frozenset[Atom]:
        """Atoms the cube constrains."""
        return self.pos | self.neg

    @property
    def consistent(self) -> bool:
        """No atom both true and false, and at most one true event atom."""
        return not (self.pos & self.neg) and sum(a.is_event for a in self.pos) <= 1

    def meet(self, other: 'Cube') -> 'Cube':
        """Conjunction of two cubes (may be inconsistent)."""
        return Cube(self.pos | other.pos, self.neg | other.neg)

    def __str__(self) -> str:
        lits = sorted([a.key for a in self.pos] + ['!' + a.key for a in self.neg],
                      key=lambda t: t.lstrip('!'))
        return ' & '.join(lits) if lits else 'true'


def _simplify(cubes: Iterable[Cube]) -> tuple[Cube, ...]:
    """Merge cubes that differ in one literal, drop subsumed ones; deterministic order."""
    items = set(cubes)
    changed = True
    while changed:  # x & c | !x & c  ->  c, until nothing merges
        changed = False
        for c in list(items):
            if c not in items:
                continue
            for x in c.pos | c.neg:
                if x in c.pos:
                    twin = Cube(c.pos - {x}, c.neg | {x})
                else:
                    twin = Cube(c.pos | {x}, c.neg - {x})
                if twin in items:
                    items -= {c, twin}
                    items.add(Cube(c.pos - {x}, c.neg - {x}))
                    changed = True
                    break
    # drop a cube implied by a more general one (its literals are a superset)
    kept = [c for c in items
            if not any(o is not c and o.pos <= c.pos and o.neg <= c.neg for o in items)]
    return tuple(sorted(kept, key=cube_order))


def cube_order(c: Cube) -> tuple:
    """Sort key of cubes: fewest literals first, then by atom keys."""
    return (len(c.pos) + len(c.neg), sorted(a.key for a in c.pos), sorted(a.key for a in c.neg))


@dataclass(frozen=True)
class Guard:
    """A disjunction of cubes (DNF). No cubes is ``false``; one empty cube is ``true``."""

    cubes: tuple[Cube, ...] = ()

    @staticmethod
    def of(cubes: Iterable[Cube]) -> 'Guard':
        """Build a simplified guard from cubes."""
        return Guard(_simplify(c for c in cubes if c.consistent))

    def evaluate(self, letter: AbstractSet[Atom]) -> bool:
        """Whether the letter satisfies the guard."""
        return any(c.evaluate(letter) for c in self.cubes)

    @property
    def atoms(self) -> frozenset[Atom]:
        """Atoms the guard constrains."""
        out: frozenset[Atom] = frozenset()
        for c in self.cubes:
            out |= c.atoms
        return out

    @property
    def is_false(self) -> bool:
        """No letter satisfies it."""
        return not self.cubes

    @property
    def is_true(self) -> bool:
        """Every letter satisfies it."""
        return any(not c.pos and not c.neg for c in self.cubes)

    def union(self, other: 'Guard') -> 'Guard':
        """Disjunction."""
        return Guard.of(self.cubes + other.cubes)

    def meet(self, other: 'Guard') -> 'Guard':
        """Conjunction (cubes multiplied out, inconsistent ones dropped)."""
        return Guard.of(a.meet(b) for a in self.cubes for b in other.cubes)

    def __str__(self) -> str:
        if self.is_false:
            return 'false'
        if len(self.cubes) == 1:
            return str(self.cubes[0])
        return ' | '.join(f'({c})' if len(c.pos) + len(c.neg) > 1 else str(c) for c in self.cubes)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: ``{'text': ..., 'cubes': [{'pos': [...], 'neg': [...]}]}``."""
        return {'text': str(self),
                'cubes': [{'pos': sorted(a.key for a in c.pos), 'neg': sorted(a.key for a in c.neg)}
                          for c in self.cubes]}

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'Guard':
        """Inverse of :meth:`to_dict` (atoms are parsed with the formula grammar)."""
        def atom(text: str) -> Atom:
            f = parse_formula(text)
            if not isinstance(f, Atom):
                raise ValueError(f'not an atom: {text!r}')
            return f
        return Guard(tuple(Cube(frozenset(atom(t) for t in c.get('pos', [])),
                                frozenset(atom(t) for t in c.get('neg', [])))
                           for c in d.get('cubes', [])))


GUARD_TRUE = Guard((Cube(),))
GUARD_FALSE = Guard(())

"""Seeded random task formulas over every operator, for property tests and benchmarks."""
from __future__ import annotations

import random
from typing import Sequence

from ltl_instruct.core.spec.ast import (
    FALSE, TRUE, Always, And, Atom, Eventually, Formula, Iff, Implies, Next, Not, Or, Release,
    Until, WeakUntil, near,
)

UNARY = (Not, Eventually, Always, Next)
BINARY = (Until, Release, WeakUntil, Implies, Iff)


def default_atoms(n: int, events: bool = False) -> tuple[Atom, ...]:
    """``near[p0] ... near[p{n-1}]``; with ``events`` the last one or two become pick/release."""
    atoms = [near(f'p{i}') for i in range(n)]
    if events and n >= 2:
        atoms[-1] = Atom('pick', atoms[-1].args)
    if events and n >= 3:
        atoms[-2] = Atom('release', (atoms[-2].args[0], atoms[0].args[0]))
    return tuple(atoms)


def random_formula(rng: random.Random, atoms: Sequence[Atom], size: int = 6) -> Formula:
    """Return a random formula with about ``size`` operators over ``atoms`` (all operators used)."""
    if size <= 0:
        r = rng.random()
        if r < 0.05:
            return TRUE if rng.random() < 0.5 else FALSE
        return rng.choice(list(atoms))
    kind = rng.random()
    if kind < 0.35:
        op = rng.choice(UNARY)
        return op(random_formula(rng, atoms, size - 1))
    left = rng.randint(0, size - 1)
    a = random_formula(rng, atoms, left)
    b = random_formula(rng, atoms, size - 1 - left)
    if kind < 0.55:
        return And((a, b))
    if kind < 0.7:
        return Or((a, b))
    return rng.choice(BINARY)(a, b)

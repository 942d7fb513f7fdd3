"""Symbolic LTLf progression: states and guards as BDDs over one shared manager.

A state is a Boolean function over *obligations*: the temporal sub-formulas of the
task (``F g``, ``G g``, ``g U h``, ``X g``...) and the atoms the next letter must
hold, each a BDD variable meaning "the rest of the trace satisfies it". Equal
functions are one node of the manager, so states are hashed canonically without a
normal form. The atoms of the current letter are the first variables (tested
first); obligation variables follow, made when first needed.

Reading one letter (progression, ``spec/formula.md``): every obligation variable of
the state is replaced by its *step* function, a BDD over the current atoms and the
obligations of the rest: ``F g`` steps to ``step(g) | F g``, ``G g`` to
``step(g) & G g``, ``g U h`` to ``step(h) | step(g) & (g U h)``, ``X g`` to
``g & F true`` (the trace goes on). Negation, ``->`` and ``<->`` are Boolean on the
BDDs, so ``a0 <-> ... <-> a19`` stays linear in size. In the substituted function
the nodes below the atom levels are the successor states; the paths to each one,
restricted to letters with at most one event (``pick``, ``release``), are its guard.

A state is accepting when the trace may end there: its function is true with every
obligation at its empty-trace value (``G``, ``R``, ``W``, weak next: true).
"""
from __future__ import annotations

from typing import AbstractSet, Iterable, Optional

from ltl_instruct.core.automaton import bdd as B
from ltl_instruct.core.automaton.guards import Cube, Guard, cube_order
from ltl_instruct.core.automaton.progression import WorkBudget
from ltl_instruct.core.errors import LimitExceededError
from ltl_instruct.core.spec.ast import (
    FALSE, TRUE, Always, And, Atom, Const, Eventually, Formula, Iff, Implies, Next, Not, Or,
    Release, Until, WeakNext, WeakUntil, atoms_of, conj, disj,
)

TRACE_GOES_ON = Eventually(TRUE)
MAX_GUARD_CUBES = 4096
"""Most cubes of a guard written as a sum of products (a chain of 14 ``<->`` needs 8,192)."""
MAX_TEXT_CUBES = 256
"""Guards with more cubes than this are written as nested formulas, not sums of products."""
TEMPORAL = (Next, WeakNext, Eventually, Always, Until, Release, WeakUntil)


def empty_trace_value(f: Formula) -> bool:
    """Whether the empty rest of a trace satisfies obligation ``f`` (an atom or a temporal formula)."""
    return isinstance(f, (WeakNext, Always, Release, WeakUntil))


class Progression:
    """The BDD manager of one task formula: its atoms, obligations, steps and successors.

    Parameters
    ----------
    formula: the task (any operators; no normal form is needed).
    budget: deadline and bounds of the work (see :class:`WorkBudget`).
    max_nodes: most BDD nodes (``LIMIT_EXCEEDED`` past it).
    """

    def __init__(self, formula: Formula, budget: Optional[WorkBudget] = None,
                 max_nodes: int = 500_000) -> None:
        self.formula = formula
        self.budget = budget or WorkBudget(time_limit_s=None)
        self.max_nodes = max_nodes
        self.bdd = B.BDD()
        self.atoms: tuple[Atom, ...] = atoms_of(formula)
        self.atom_level = {a: self.bdd.new_var() for a in self.atoms}
        self.num_atoms = len(self.atoms)
        self.obligations: list[Formula] = []      # level - num_atoms -> obligation
        self._obligation_level: dict[Formula, int] = {}
        self._step_of_level: list[int] = []       # obligation level - num_atoms -> step BDD
        self._step_memo: dict[Formula, int] = {}
        self._lift_memo: dict[Formula, int] = {}
        self._compose_memo: dict[int, int] = {B.FALSE: B.FALSE, B.TRUE: B.TRUE}
        self._accept_memo: dict[int, bool] = {}
        self._one_step_memo: dict[int, int] = {B.FALSE: B.FALSE, B.TRUE: B.TRUE}
        self.valid = self._at_most_one_event()
        self.initial = self.lift(formula)

    # ------------------------------------------------------------------ building
    def _at_most_one_event(self) -> int:
        """Letters with at most one event atom true."""
        m = self.bdd
        none, one = B.TRUE, B.FALSE          # built from the last atom up
        for a in reversed(self.atoms):
            lv = self.atom_level[a]
            if a.is_event:
                none, one = m.mk(lv, none, B.FALSE), m.mk(lv, one, none)
            else:
                none, one = m.mk(lv, none, none), m.mk(lv, one, one)
        return m.disj(none, one)

    def _obligation(self, f: Formula) -> int:
        """Node of the variable "the rest of the trace satisfies ``f``" (made on first use)."""
        lv = self._obligation_level.get(f)
        if lv is None:
            lv = self._obligation_level[f] = self.bdd.new_var()
            self.obligations.append(f)
            self._step_of_level.append(-1)         # computed when first substituted
        return self.bdd.var(lv)

    def lift(self, f: Formula) -> int:
        """BDD of ``f`` as an obligation on the rest of the trace (a state)."""
        hit = self._lift_memo.get(f)
        if hit is not None:
            return hit
        if isinstance(f, (Atom, *TEMPORAL)):
            r = self._obligation(f)
        else:
            r = self._boolean(f, self.lift)
        self._lift_memo[f] = r
        return r

    def _boolean(self, f: Formula, part) -> int:
        m = self.bdd
        if isinstance(f, Const):
            return B.TRUE if f.value else B.FALSE
        if isinstance(f, Not):
            return m.neg(part(f.operand))
        if isinstance(f, And):
            r = B.TRUE
            for o in f.operands:
                r = m.conj(r, part(o))
            return r
        if isinstance(f, Or):
            r = B.FALSE
            for o in f.operands:
                r = m.disj(r, part(o))
            return r
        if isinstance(f, Implies):
            return m.disj(m.neg(part(f.left)), part(f.right))
        if isinstance(f, Iff):
            return m.iff(part(f.left), part(f.right))
        raise TypeError(f'not a formula node: {f!r}')

    def step(self, f: Formula) -> int:
        """BDD of ``f`` read at the current letter: current atoms and obligations of the rest."""
        hit = self._step_memo.get(f)
        if hit is not None:
            return hit
        self.budget.check()
        m = self.bdd
        if isinstance(f, Atom):
            r = m.var(self.atom_level[f])
        elif isinstance(f, Next):
            r = m.conj(self.lift(f.operand), self._obligation(TRACE_GOES_ON))
        elif isinstance(f, WeakNext):
            r = m.disj(self.lift(f.operand), m.neg(self._obligation(TRACE_GOES_ON)))
        elif isinstance(f, Eventually):
            r = m.disj(self.step(f.operand), self._obligation(f))
        elif isinstance(f, Always):
            r = m.conj(self.step(f.operand), self._obligation(f))
        elif isinstance(f, (Until, WeakUntil)):
            r = m.disj(self.step(f.right), m.conj(self.step(f.left), self._obligation(f)))
        elif isinstance(f, Release):
            r = m.conj(self.step(f.right), m.disj(self.step(f.left), self._obligation(f)))
        else:
            r = self._boolean(f, self.step)
        self._step_memo[f] = r
        self._check_size()
        return r

    def _check_size(self) -> None:
        if len(self.bdd) > self.max_nodes:
            raise LimitExceededError(
                f'the automaton needs more than {self.max_nodes} decision-diagram nodes; simplify the task',
                details={'limit': 'max_nodes', 'value': self.max_nodes})

    def _step_of(self, level: int) -> int:
        i = level - self.num_atoms
        s = self._step_of_level[i]
        if s < 0:
            s = self._step_of_level[i] = self.step(self.obligations[i])
        return s

    # ------------------------------------------------------------------ reading letters
    def transition(self, state: int) -> int:
        """Return the state read at an unknown letter: a BDD whose nodes below the atoms are successors."""
        memo = self._compose_memo
        hit = memo.get(state)
        if hit is not None:
            return hit
        m = self.bdd
        self.budget.check()
        r = m.ite(self._step_of(m.level(state)), self.transition(m.high(state)),
                  self.transition(m.low(state)))
        memo[state] = r
        return r

    def successors(self, state: int) -> dict[int, int]:
        """Successor state -> guard (a BDD over atoms; valid letters only) of ``state``."""
        m = self.bdd
        n = self.num_atoms
        memo: dict[int, dict[int, int]] = {}

        def split(node: int) -> dict[int, int]:
            got = memo.get(node)
            if got is not None:
                return got
            lv = m.level(node)
            if lv >= n:
                got = {node: B.TRUE}
            else:
                lo, hi = split(m.low(node)), split(m.high(node))
                got = {t: m.mk(lv, lo.get(t, B.FALSE), hi.get(t, B.FALSE)) for t in lo.keys() | hi.keys()}
                self.budget.check()
            memo[node] = got
            return got

        out = {}
        for t, g in split(self.transition(state)).items():
            g = m.conj(g, self.valid)
            if g != B.FALSE:
                out[t] = g
        self._check_size()
        return out

    def next_state(self, state: int, letter: AbstractSet[Atom]) -> int:
        """Successor of ``state`` after ``letter`` (the set of true atoms)."""
        levels = {self.atom_level[a] for a in letter if a in self.atom_level}
        node = self.transition(state)
        m = self.bdd
        while m.level(node) < self.num_atoms:
            node = m.high(node) if m.level(node) in levels else m.low(node)
        return node

    def accepting(self, state: int) -> bool:
        """Whether the trace may end in ``state``."""
        hit = self._accept_memo.get(state)
        if hit is None:
            obls, n = self.obligations, self.num_atoms
            hit = self._accept_memo[state] = self.bdd.evaluate(
                state, lambda lv: empty_trace_value(obls[lv - n]))
        return hit

    def accepts_in_one_step(self, state: int) -> bool:
        """Whether some valid letter takes ``state`` to an accepting state."""
        return self.bdd.conj(self._one_step(state), self.valid) != B.FALSE

    def _one_step(self, state: int) -> int:
        memo = self._one_step_memo
        hit = memo.get(state)
        if hit is not None:
            return hit
        m = self.bdd
        lv = m.level(state)
        at_end = self._at_end(self._step_of(lv))
        r = m.ite(at_end, self._one_step(m.high(state)), self._one_step(m.low(state)))
        memo[state] = r
        return r

    def _at_end(self, node: int) -> int:
        """``node`` with every obligation at its empty-trace value: a BDD over atoms."""
        m = self.bdd
        n = self.num_atoms
        memo = self._one_step_memo

        def rec(x: int) -> int:
            if x <= B.TRUE:
                return x
            key = -x - 2           # negative keys: results of this restriction
            hit = memo.get(key)
            if hit is not None:
                return hit
            lv = m.level(x)
            if lv >= n:
                r = rec(m.high(x) if empty_trace_value(self.obligations[lv - n]) else m.low(x))
            else:
                r = m.mk(lv, rec(m.low(x)), rec(m.high(x)))
            memo[key] = r
            return r
        return rec(node)

    # ------------------------------------------------------------------ for people
    def guard(self, node: int) -> Guard:
        """Return the guard as cubes (an irredundant cover; letters with two events do not matter)."""
        m = self.bdd
        one = self._single_cube(node)
        if one is not None:
            return Guard((one,))
        try:
            cover = m.isop(node, m.disj(node, m.neg(self.valid)), MAX_GUARD_CUBES)
        except OverflowError:
            raise LimitExceededError(
                f'an automaton guard has more than {MAX_GUARD_CUBES} terms as a sum of products '
                f'({self.guard_formula(node)[:200]}); simplify the task',
                details={'limit': 'max_guard_cubes', 'value': MAX_GUARD_CUBES}) from None
        cubes = []
        for lits in cover:
            pos = frozenset(self.atoms[lv] for lv, v in lits if v)
            neg = frozenset(self.atoms[lv] for lv, v in lits if not v)
            cubes.append(Cube(pos, neg))
        return Guard(tuple(sorted((c for c in cubes if c.consistent), key=cube_order)))

    def _single_cube(self, node: int) -> Optional[Cube]:
        """Return the one cube of a guard whose BDD is a single path (None otherwise)."""
        m = self.bdd
        pos, neg = [], []
        while node > B.TRUE:
            lo, hi = m.low(node), m.high(node)
            if lo == B.FALSE:
                pos.append(self.atoms[m.level(node)])
                node = hi
            elif hi == B.FALSE:
                neg.append(self.atoms[m.level(node)])
                node = lo
            else:
                return None
        if node == B.FALSE:
            return None
        if any(a.is_event for a in pos):
            neg = [a for a in neg if not a.is_event]
        return Cube(frozenset(pos), frozenset(neg))

    def letters_without(self, pairs: Iterable[tuple[Atom, Atom]]) -> int:
        """Return the valid letters in which no pair of these atoms is true together."""
        m = self.bdd
        r = self.valid
        for a, b in pairs:
            if a in self.atom_level and b in self.atom_level:
                r = m.conj(r, m.neg(m.conj(m.var(self.atom_level[a]), m.var(self.atom_level[b]))))
        return r

    def atoms_of(self, node: int) -> frozenset[Atom]:
        """Atoms a guard depends on."""
        return frozenset(self.atoms[lv] for lv in self.bdd.support(node) if lv < self.num_atoms)

    def listable(self, node: int, max_cubes: int = MAX_TEXT_CUBES) -> bool:
        """Whether a guard is short enough to list as cubes (else see :meth:`guard_formula`)."""
        return self.bdd.count_paths(node) <= max_cubes

    def guard_formula(self, node: int) -> str:
        """Write a guard as a nested formula, linear in its BDD where ``x <-> g`` patterns occur (parity)."""
        return str(self.nested_formula(node))

    def _variable(self, level: int) -> Formula:
        return self.atoms[level] if level < self.num_atoms else self.obligations[level - self.num_atoms]

    def nested_formula(self, node: int) -> Formula:
        """Return a BDD as a formula that follows its nodes (shared parts are written once each)."""
        m = self.bdd
        memo: dict[int, Formula] = {B.TRUE: TRUE, B.FALSE: FALSE}

        def rec(n: int) -> Formula:
            got = memo.get(n)
            if got is None:
                x = self._variable(m.level(n))
                lo, hi = m.low(n), m.high(n)
                if lo == B.FALSE:
                    got = conj(x, rec(hi))
                elif hi == B.FALSE:
                    got = conj(Not(x), rec(lo))
                elif hi == B.TRUE:
                    got = disj(x, rec(lo))
                elif lo == B.TRUE:
                    got = disj(Not(x), rec(hi))
                elif hi == m.neg(lo):
                    got = Iff(x, rec(hi))
                else:
                    got = disj(conj(x, rec(hi)), conj(Not(x), rec(lo)))
                memo[n] = got
            return got
        return rec(node)

    def state_formula(self, state: int) -> Formula:
        """Return a formula for a state: the obligations it is made of, as a sum of products."""
        if state == B.FALSE:
            return FALSE
        if state == B.TRUE:
            return TRUE
        if state == self.initial:
            return self.formula
        n = self.num_atoms
        try:
            cover = self.bdd.isop(state, state, MAX_TEXT_CUBES)
        except OverflowError:
            return self.nested_formula(state)
        terms = []
        for lits in cover:
            terms.append(conj(*(self.obligations[lv - n] if v else Not(self.obligations[lv - n])
                                for lv, v in sorted(lits))))
        return disj(*terms)

"""Compile a task formula into a DFA with symbolic guards, by progression.

States are progressed formulas (in negation normal form, with ``&``/``|``
flattened, deduplicated and sorted, so equal obligations meet in one state). The
edges out of a state come from a Shannon expansion of its symbolic step formula
(:func:`~ltl_instruct.core.automaton.progression.step_formula`): the expansion
branches only on atoms that still matter, so a state with n atoms in play costs
far fewer than 2^n evaluations, and each leaf is a cube of the edge's guard.
Event atoms (``pick``, ``release``) are mutually exclusive in a letter.

States that cannot reach acceptance are merged into one rejecting sink. A state
is accepting when the trace may end there (its formula holds on the empty rest).
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import AbstractSet, Any, Iterable, Optional, Sequence

from ltl_instruct.core.automaton.guards import GUARD_FALSE, GUARD_TRUE, Cube, Guard
from ltl_instruct.core.automaton.progression import (
    WorkBudget, accepts_empty, assign_atoms, canonical_state, resolve_later, step_atoms, step_formula,
    to_nnf,
)
from ltl_instruct.core.errors import LimitExceededError, UnsatisfiableError
from ltl_instruct.core.spec.ast import FALSE, Atom, Formula, Not, atoms_of, iter_subformulas
from ltl_instruct.core.spec.parser import parse_formula

DEFAULT_MAX_STATES = 2000
DEFAULT_MAX_CUBES = 50_000
"""Most edge-guard terms (cubes) one compilation may produce, over all states."""
DEFAULT_MAX_STATE_CUBES = 512
"""Most alternatives (DNF cubes) one automaton state may have."""
DEFAULT_TIME_LIMIT_S = 5.0
"""Seconds one compilation may take before it gives up with ``TIMEOUT``."""


@dataclass(frozen=True)
class Edge:
    """A transition ``src -> dst`` taken by the letters that satisfy ``guard``."""

    src: int
    dst: int
    guard: Guard

    @property
    def atoms(self) -> frozenset[Atom]:
        """The atoms this edge constrains."""
        return self.guard.atoms

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'src': self.src, 'dst': self.dst, 'guard': self.guard.to_dict(),
                'atoms': sorted(a.key for a in self.atoms)}


def _current_atoms(f: Formula) -> list[Atom]:
    """Atoms of a step formula outside ``Later`` obligations, outermost first.

    Branching on the outermost atoms first keeps the expansion of nested
    sequences linear: in ``a & (b & (c | @..) | @..) | @..`` a false ``a`` settles
    the whole step at once.
    """
    order: dict[Atom, None] = {}
    frontier = [f]
    while frontier:  # breadth-first
        nxt: list[Formula] = []
        for node in frontier:
            if isinstance(node, Atom):
                order.setdefault(node, None)
            elif isinstance(node, Not):
                order.setdefault(node.operand, None)  # type: ignore[arg-type]
            elif step_atoms(node):   # Later and constants hold no current atoms
                nxt.extend(node.children())
        frontier = nxt
    return list(order)


def _expand(state: Formula, step_cache: dict, next_cache: dict,
            budget: WorkBudget) -> dict[Formula, list[Cube]]:
    """Successor formula -> cubes of letters leading there from ``state``.

    A Shannon expansion of the state's step formula: each branch fixes one atom and
    substitutes only that atom into its parent's residual (untouched sub-formulas are
    shared, not rebuilt); a residual without current atoms is resolved to its
    canonical successor once per compilation (``next_cache``).
    """
    out: dict[Formula, list[Cube]] = {}
    events_in_play = [a for a in atoms_of(state) if a.is_event]

    def rec(f: Formula, values: dict[Atom, bool], forced_false: frozenset[Atom]) -> None:
        budget.check()
        if not step_atoms(f):
            budget.add_cubes()
            nxt = next_cache.get(f)
            if nxt is None:
                nxt = next_cache[f] = canonical_state(resolve_later(f), budget)
            out.setdefault(nxt, []).append(
                Cube(frozenset(a for a, v in values.items() if v),
                     frozenset(a for a, v in values.items() if not v and a not in forced_false)))
            return
        a = _current_atoms(f)[0]
        for v in (True, False):
            new = {a: v}
            forced = forced_false
            if v and a.is_event:  # one event per letter: every other event is false
                others = [e for e in events_in_play if e != a and e not in values]
                for e in others:
                    new[e] = False
                forced = forced | frozenset(others)
            rec(assign_atoms(f, new), {**values, **new}, forced)

    rec(step_formula(state, step_cache), {}, frozenset())
    return out


class Automaton:
    """A DFA over letters (sets of atoms) with symbolic guards.

    Use :func:`compile_automaton` to build one. States are ints ``0..n-1``;
    ``initial`` is 0.
    """

    def __init__(self, formula: Formula, state_formulas: list[Formula],
                 edges: list[list[Edge]], sink: Optional[int]) -> None:
        self.formula = formula
        self.atoms: tuple[Atom, ...] = atoms_of(formula)
        self._states = tuple(state_formulas)
        self._edges = tuple(tuple(e) for e in edges)
        self.initial = 0
        self.sink = sink
        self.accepting: frozenset[int] = frozenset(
            i for i, f in enumerate(state_formulas) if i != sink and accepts_empty(f))
        self._dist = self._distances()

    # -- structure
    @property
    def num_states(self) -> int:
        """Number of states, sink included."""
        return len(self._states)

    def state_formula(self, s: int) -> Formula:
        """Return the progressed formula (obligation on the rest of the trace) state ``s`` stands for."""
        return self._states[s]

    def edges_from(self, s: int) -> tuple[Edge, ...]:
        """Outgoing edges of ``s`` (self-loop included); guards are disjoint and complete."""
        return self._edges[s]

    def edges(self) -> Iterable[Edge]:
        """Every edge."""
        for es in self._edges:
            yield from es

    def self_loop(self, s: int) -> Guard:
        """Guard of the letters that keep the automaton in ``s`` (false if none)."""
        for e in self._edges[s]:
            if e.dst == s:
                return e.guard
        return GUARD_FALSE

    @property
    def is_satisfiable(self) -> bool:
        """Whether some non-empty trace is accepted."""
        return any(self._dist[s] is not None for s in self._successors(self.initial))

    def _successors(self, s: int) -> set[int]:
        return {e.dst for e in self._edges[s]}

    def _distances(self) -> list[Optional[int]]:
        """Fewest edges from each state to an accepting state (None: unreachable)."""
        preds: dict[int, set[int]] = {i: set() for i in range(self.num_states)}
        for es in self._edges:
            for e in es:
                preds[e.dst].add(e.src)
        dist: list[Optional[int]] = [None] * self.num_states
        q = deque()
        for s in self.accepting:
            dist[s] = 0
            q.append(s)
        while q:
            s = q.popleft()
            for p in preds[s]:
                if dist[p] is None:
                    dist[p] = dist[s] + 1  # type: ignore[operator]
                    q.append(p)
        return dist

    def distance_to_accepting(self, s: int) -> Optional[int]:
        """Fewest transitions from ``s`` to an accepting state, or None."""
        return self._dist[s]

    # -- running
    def step(self, s: int, letter: AbstractSet[Atom]) -> int:
        """Return the state after reading ``letter`` (the set of atoms true at this step) in ``s``."""
        if sum(1 for a in letter if a.is_event) > 1:
            raise ValueError('a letter holds at most one event (pick or release): '
                             + ', '.join(sorted(a.key for a in letter if a.is_event)))
        for e in self._edges[s]:
            if e.guard.evaluate(letter):
                return e.dst
        raise AssertionError(f'guards of state {s} do not cover letter {sorted(a.key for a in letter)}')

    def run(self, trace: Sequence[AbstractSet[Atom]]) -> list[int]:
        """States visited: ``[initial, after letter 0, after letter 1, ...]``."""
        states = [self.initial]
        for letter in trace:
            states.append(self.step(states[-1], letter))
        return states

    def accepts(self, trace: Sequence[AbstractSet[Atom]]) -> bool:
        """Whether the non-empty finite trace satisfies the formula."""
        if len(trace) == 0:
            raise ValueError('LTLf traces are non-empty')
        return self.run(trace)[-1] in self.accepting

    def accepting_paths(self, max_paths: int = 64,
                        max_length: Optional[int] = None) -> list[tuple[Edge, ...]]:
        """Return simple edge paths from the initial state to acceptance, shortest first.

        Self-loops are left out (they are the "allowed" part of each step); paths
        stop at the first accepting state, never pass the sink, and never revisit
        a state.
        """
        limit = max_length if max_length is not None else self.num_states
        out: list[tuple[Edge, ...]] = []
        q: deque[tuple[int, tuple[Edge, ...], frozenset[int]]] = deque(
            [(self.initial, (), frozenset({self.initial}))])
        while q and len(out) < max_paths:
            s, path, seen = q.popleft()
            if path and s in self.accepting:
                out.append(path)
                continue
            if len(path) >= limit:
                continue
            for e in self._edges[s]:
                if e.dst == s or e.dst in seen or self._dist[e.dst] is None:
                    continue
                q.append((e.dst, path + (e,), seen | {e.dst}))
        return out

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready description: states, initial, accepting, sink, edges."""
        return {
            'formula': str(self.formula),
            'atoms': [a.key for a in self.atoms],
            'states': [{'id': i, 'formula': str(f), 'accepting': i in self.accepting,
                        'sink': i == self.sink} for i, f in enumerate(self._states)],
            'initial': self.initial,
            'accepting': sorted(self.accepting),
            'sink': self.sink,
            'satisfiable': self.is_satisfiable,
            'edges': [e.to_dict() for e in self.edges()],
        }


def compile_automaton(formula: Formula | str, max_states: int = DEFAULT_MAX_STATES,
                      max_cubes: int = DEFAULT_MAX_CUBES,
                      time_limit_s: Optional[float] = DEFAULT_TIME_LIMIT_S) -> Automaton:
    """Compile a formula (AST or text) into an :class:`Automaton`.

    Parameters
    ----------
    formula: the task, as an AST or text.
    max_states: most automaton states.
    max_cubes: most edge-guard terms over the whole compilation.
    time_limit_s: seconds the compilation may take (None: no deadline).

    Raises
    ------
    FormulaSyntaxError
        If ``formula`` is text that does not parse.
    LimitExceededError
        ``LIMIT_EXCEEDED`` if more than ``max_states`` states, more than ``max_cubes``
        guard terms or more than :data:`DEFAULT_MAX_STATE_CUBES` alternatives in one
        state are needed, or the normal form is too large; ``TIMEOUT`` past ``time_limit_s``.
    """
    f = parse_formula(formula) if isinstance(formula, str) else formula
    try:
        return _compile(f, max_states, WorkBudget(time_limit_s, max_cubes, DEFAULT_MAX_STATE_CUBES))
    except RecursionError:  # a last guard: formulas built in code may nest deeper than parsed ones
        raise LimitExceededError('the formula nests too deeply to compile; simplify the task',
                                 details={'limit': 'recursion'}) from None


def _compile(f: Formula, max_states: int, budget: WorkBudget) -> Automaton:
    init = canonical_state(to_nnf(f), budget)
    index: dict[Formula, int] = {init: 0}
    states: list[Formula] = [init]
    raw: list[dict[int, list[Cube]]] = []
    step_cache: dict = {}
    next_cache: dict = {}
    i = 0
    while i < len(states):
        succ = _expand(states[i], step_cache, next_cache, budget)
        row: dict[int, list[Cube]] = {}
        for nxt, cubes in succ.items():
            j = index.get(nxt)
            if j is None:
                if len(states) >= max_states:
                    raise LimitExceededError(
                        f'the automaton has more than {max_states} states; simplify the task',
                        details={'limit': 'max_states', 'value': max_states})
                j = index[nxt] = len(states)
                states.append(nxt)
            row.setdefault(j, []).extend(cubes)
        raw.append(row)
        i += 1
    budget.check()
    return _merge_dead_states(f, states, raw)


def _merge_dead_states(formula: Formula, states: list[Formula],
                       raw: list[dict[int, list[Cube]]]) -> Automaton:
    n = len(states)
    preds: dict[int, set[int]] = {i: set() for i in range(n)}
    for s, row in enumerate(raw):
        for d in row:
            preds[d].add(s)
    alive = {i for i, f in enumerate(states) if accepts_empty(f)}
    q = deque(alive)
    while q:
        s = q.popleft()
        for p in preds[s]:
            if p not in alive:
                alive.add(p)
                q.append(p)
    if 0 not in alive:  # unsatisfiable: the initial state is the sink
        return Automaton(formula, [states[0]], [[Edge(0, 0, GUARD_TRUE)]], sink=0)
    new_id: dict[int, int] = {}
    formulas: list[Formula] = []
    for i in range(n):  # live states keep discovery order, so the initial state stays 0
        if i in alive:
            new_id[i] = len(formulas)
            formulas.append(states[i])
    sink: Optional[int] = None
    if len(alive) < n:
        sink = len(formulas)
        formulas.append(FALSE)
        for i in range(n):
            new_id.setdefault(i, sink)
    merged: dict[tuple[int, int], list[Cube]] = {}
    for s, row in enumerate(raw):
        if s not in alive:
            continue
        for d, cubes in row.items():
            merged.setdefault((new_id[s], new_id[d]), []).extend(cubes)
    edges: list[list[Edge]] = [[] for _ in formulas]
    for (src, dst), cubes in merged.items():
        edges[src].append(Edge(src, dst, Guard.of(cubes)))
    if sink is not None:
        edges[sink] = [Edge(sink, sink, GUARD_TRUE)]
    for es in edges:
        es.sort(key=lambda e: (e.dst != e.src, e.dst))
    return Automaton(formula, formulas, edges, sink)


def is_satisfiable(formula: Formula | str) -> bool:
    """Whether some finite trace satisfies the formula."""
    return compile_automaton(formula).is_satisfiable


def require_satisfiable(aut: Automaton) -> Automaton:
    """Return ``aut`` or raise :class:`UnsatisfiableError` (no accepting state reachable)."""
    if not aut.is_satisfiable:
        raise UnsatisfiableError(f'the task "{aut.formula}" can never be completed: '
                                 'no sequence of steps satisfies it')
    return aut


def _cubes_meet(a: Guard, b: Guard) -> bool:
    return any(x.meet(y).consistent for x in a.cubes for y in b.cubes)


def equivalent(f: Formula | str, g: Formula | str) -> bool:
    """Whether two formulas accept exactly the same non-empty finite traces.

    Checked on the automata by a search of their product: a reachable pair of
    states that disagree on acceptance is a distinguishing trace.
    """
    return distinguishing_pair(compile_automaton(f), compile_automaton(g)) is None


def distinguishing_pair(a: Automaton, b: Automaton) -> Optional[tuple[int, int]]:
    """Find a reachable product state (after >= 1 letter) where exactly one accepts, or None."""
    start = [(ea.dst, eb.dst) for ea in a.edges_from(a.initial) for eb in b.edges_from(b.initial)
             if _cubes_meet(ea.guard, eb.guard)]
    seen = set(start)
    q = deque(start)
    while q:
        s, t = q.popleft()
        if (s in a.accepting) != (t in b.accepting):
            return (s, t)
        for ea in a.edges_from(s):
            for eb in b.edges_from(t):
                pair = (ea.dst, eb.dst)
                if pair not in seen and _cubes_meet(ea.guard, eb.guard):
                    seen.add(pair)
                    q.append(pair)
    return None


def constrained_atoms(formula: Formula) -> frozenset[Atom]:
    """Atoms of a formula (convenience for callers that only have the formula)."""
    return frozenset(a for a in iter_subformulas(formula) if isinstance(a, Atom))

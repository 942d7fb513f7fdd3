"""Task formulas as DFAs with symbolic (BDD) guards: built whole and minimal, or on demand.

Both kinds explore the same symbolic progression
(:class:`~ltl_instruct.core.automaton.symbolic.Progression`): a state is a BDD over
the formula's obligations, hashed canonically by the manager, and the guard of each
edge is a BDD over the atoms (letters hold at most one event, ``pick`` or
``release``).

- :func:`compile_automaton` explores every reachable state (up to ``max_states``),
  then minimises (Moore's partition refinement on the BDD guards): equivalent states
  are one state, and the states that cannot reach acceptance are one rejecting sink.
- :func:`on_the_fly_automaton` expands a state only when asked for its edges, its
  distance to acceptance or a step out of it. A planner that explores the product of
  automaton and map from the initial state visits a few of the 4,097 states of
  ``G !b & F a1 & ... & F a12``, never the whole automaton.

A state is accepting when the trace may end there (its obligations hold on the empty
rest).
"""
from __future__ import annotations

from collections import deque
from typing import AbstractSet, Any, Iterable, Iterator, Optional, Sequence

from ltl_instruct.core.automaton import bdd as B
from ltl_instruct.core.automaton.guards import GUARD_FALSE, GUARD_TRUE, Guard
from ltl_instruct.core.automaton.progression import WorkBudget
from ltl_instruct.core.automaton.symbolic import Progression
from ltl_instruct.core.errors import LimitExceededError, UnsatisfiableError
from ltl_instruct.core.spec.ast import FALSE, Atom, Formula, Iff, Not, iter_subformulas
from ltl_instruct.core.spec.parser import parse_formula

DEFAULT_MAX_STATES = 2000
DEFAULT_MAX_EDGES = 200_000
"""Most edges one whole compilation may produce, over all states."""
DEFAULT_MAX_NODES = 500_000
"""Most decision-diagram nodes one compilation may make (a memory bound)."""
DEFAULT_TIME_LIMIT_S = 5.0
"""Seconds one compilation may take before it gives up with ``TIMEOUT``."""


class Edge:
    """A transition ``src -> dst`` taken by the letters that satisfy ``guard``.

    The guard is a BDD of the automaton's manager (``node``); :attr:`guard` is its
    irredundant sum of products, made when first asked for.
    """

    __slots__ = ('src', 'dst', 'node', '_prog', '_guard')

    def __init__(self, src: int, dst: int, node: int, prog: Optional[Progression],
                 guard: Optional[Guard] = None) -> None:
        self.src = src
        self.dst = dst
        self.node = node
        self._prog = prog
        self._guard = guard

    @property
    def guard(self) -> Guard:
        """The guard as cubes (disjunctive normal form)."""
        if self._guard is None:
            assert self._prog is not None
            self._guard = self._prog.guard(self.node)
        return self._guard

    @property
    def atoms(self) -> frozenset[Atom]:
        """The atoms this edge constrains."""
        if self._prog is None:
            return self.guard.atoms
        return self._prog.atoms_of(self.node)

    def meets(self, letters: int) -> bool:
        """Whether some letter of ``letters`` (a BDD: :meth:`Automaton.letters_without`) takes the edge."""
        assert self._prog is not None
        return self._prog.bdd.conj(self.node, letters) != B.FALSE

    def holds(self, levels: AbstractSet[int]) -> bool:
        """Whether the letter whose true atoms have these BDD levels takes the edge."""
        assert self._prog is not None
        return self._prog.bdd.evaluate(self.node, levels.__contains__)

    def __repr__(self) -> str:
        return f'Edge({self.src} -> {self.dst}: {self.guard})'

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        if self._prog is not None and not self._prog.listable(self.node):   # too many cubes (a parity, say)
            guard: dict[str, Any] = {'text': self._prog.guard_formula(self.node), 'cubes': None}
        else:
            guard = self.guard.to_dict()   # the guard made once, kept on the edge
        return {'src': self.src, 'dst': self.dst, 'guard': guard, 'atoms': sorted(a.key for a in self.atoms)}


def _check_letter(letter: AbstractSet[Atom]) -> None:
    if sum(1 for a in letter if a.is_event) > 1:
        raise ValueError('a letter holds at most one event (pick or release): '
                         + ', '.join(sorted(a.key for a in letter if a.is_event)))


class Automaton:
    """A DFA over letters (sets of atoms) with symbolic guards, every state known.

    Use :func:`compile_automaton` to build one (minimal). States are ints
    ``0..n-1``; ``initial`` is 0; ``sink`` (if any) is the last state.
    """

    def __init__(self, prog: Progression, nodes: list[int], edges: list[list[Edge]],
                 accepting: Iterable[int], sink: Optional[int]) -> None:
        self.formula = prog.formula
        self.atoms: tuple[Atom, ...] = prog.atoms
        self._prog = prog
        self._nodes = nodes
        self._edges = tuple(tuple(sorted(es, key=lambda e: (e.dst != e.src, e.dst))) for es in edges)
        self.initial = 0
        self.sink = sink
        self.accepting: frozenset[int] = frozenset(accepting)
        self._dist = self._distances()

    # -- structure
    @property
    def num_states(self) -> int:
        """Number of states, sink included."""
        return len(self._nodes)

    def state_formula(self, s: int) -> Formula:
        """Return the obligation on the rest of the trace that state ``s`` stands for."""
        return FALSE if s == self.sink else self._prog.state_formula(self._nodes[s])

    def edges_from(self, s: int) -> tuple[Edge, ...]:
        """Outgoing edges of ``s`` (self-loop first); guards are disjoint and cover every letter."""
        return self._edges[s]

    def edges(self) -> Iterator[Edge]:
        """Every edge."""
        for es in self._edges:
            yield from es

    def self_loop(self, s: int) -> Guard:
        """Guard of the letters that keep the automaton in ``s`` (false if none)."""
        for e in self.edges_from(s):
            if e.dst == s:
                return e.guard
        return GUARD_FALSE

    @property
    def is_satisfiable(self) -> bool:
        """Whether some non-empty trace is accepted."""
        return any(self.distance_to_accepting(e.dst) is not None for e in self.edges_from(self.initial))

    def _distances(self) -> list[Optional[int]]:
        """Fewest edges from each state to an accepting state (None: unreachable)."""
        preds: list[set[int]] = [set() for _ in range(self.num_states)]
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

    def letters_without(self, pairs: Iterable[tuple[Atom, Atom]]) -> int:
        """Return the letters (a BDD for :meth:`Edge.meets`) in which no pair of these atoms holds together.

        A planner passes the pairs of near-atoms whose regions do not meet on its map,
        and so explores only the edges the map can take.
        """
        return self._prog.letters_without(pairs)

    # -- running
    def _levels(self, letter: AbstractSet[Atom]) -> set[int]:
        _check_letter(letter)
        return {self._prog.atom_level[a] for a in letter if a in self._prog.atom_level}

    def step(self, s: int, letter: AbstractSet[Atom]) -> int:
        """Return the state after reading ``letter`` (the set of atoms true at this step) in ``s``."""
        levels = self._levels(letter)
        for e in self.edges_from(s):
            if e.holds(levels):
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
        # a path is taken when it is made, in the order the queue would pop it (breadth first), so
        # the queue never holds the next level of a large automaton (3^10 paths for 10 goals)
        while q and len(out) < max_paths:
            s, path, seen = q.popleft()
            if len(path) >= limit:
                continue
            for e in self.edges_from(s):
                if e.dst == s or e.dst in seen or self.distance_to_accepting(e.dst) is None:
                    continue
                if e.dst in self.accepting:
                    out.append(path + (e,))
                    if len(out) >= max_paths:
                        return out
                elif len(path) + 1 < limit:
                    q.append((e.dst, path + (e,), seen | {e.dst}))
        return out

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready description: states, initial, accepting, sink, edges."""
        return {
            'formula': str(self.formula),
            'atoms': [a.key for a in self.atoms],
            'states': [{'id': i, 'formula': str(self.state_formula(i)), 'accepting': i in self.accepting,
                        'sink': i == self.sink} for i in range(self.num_states)],
            'initial': self.initial,
            'accepting': sorted(self.accepting),
            'sink': self.sink,
            'satisfiable': self.is_satisfiable,
            'edges': [e.to_dict() for e in self.edges()],
        }


class _Accepting:
    """The accepting states of an on-the-fly automaton, decided when asked."""

    def __init__(self, aut: 'OnTheFlyAutomaton') -> None:
        self._aut = aut

    def __contains__(self, s: object) -> bool:
        aut = self._aut
        return isinstance(s, int) and 0 <= s < len(aut._nodes) and aut._prog.accepting(aut._nodes[s])

    def __iter__(self) -> Iterator[int]:
        return (s for s in range(len(self._aut._nodes)) if s in self)

    def __len__(self) -> int:
        return sum(1 for _ in self)


class OnTheFlyAutomaton(Automaton):
    """The same DFA interface, each state expanded only when it is asked about.

    States are numbered in the order they are met (``initial`` 0); ``num_states``
    counts the states met so far. ``sink`` is the state with no obligation left to
    meet (false); other states that cannot reach acceptance have no distance. It is
    not minimised (:func:`compile_automaton` is); ``max_states`` bounds the states met.
    """

    def __init__(self, prog: Progression, max_states: int) -> None:
        self.formula = prog.formula
        self.atoms = prog.atoms
        self._prog = prog
        self.max_states = max_states
        self._nodes: list[int] = []
        self._index: dict[int, int] = {}
        self._edges_of: dict[int, tuple[Edge, ...]] = {}
        self._dist_of: dict[int, Optional[int]] = {}
        self.initial = self._id(prog.initial)
        self.sink = self._id(B.FALSE)
        self.accepting = _Accepting(self)  # type: ignore[assignment]

    def _id(self, node: int) -> int:
        s = self._index.get(node)
        if s is None:
            if len(self._nodes) >= self.max_states:
                raise _state_limit(self.max_states)
            s = self._index[node] = len(self._nodes)
            self._nodes.append(node)
        return s

    @property
    def num_states(self) -> int:
        """States met so far (sink included)."""
        return len(self._nodes)

    def state_formula(self, s: int) -> Formula:
        """Return the obligation on the rest of the trace that state ``s`` stands for."""
        return self._prog.state_formula(self._nodes[s])

    def edges_from(self, s: int) -> tuple[Edge, ...]:
        """Outgoing edges of ``s``, expanded on first call."""
        got = self._edges_of.get(s)
        if got is None:
            succ = self._prog.successors(self._nodes[s])
            es = [Edge(s, self._id(t), g, self._prog) for t, g in succ.items()]
            got = self._edges_of[s] = tuple(sorted(es, key=lambda e: (e.dst != e.src, e.dst)))
        return got

    def edges(self) -> Iterator[Edge]:
        """Every edge of every reachable state (expands them all, up to ``max_states``)."""
        s = 0
        while s < len(self._nodes):
            yield from self.edges_from(s)
            s += 1

    def step(self, s: int, letter: AbstractSet[Atom]) -> int:
        """Return the state after reading ``letter`` in ``s`` (without expanding ``s``)."""
        _check_letter(letter)
        return self._id(self._prog.next_state(self._nodes[s], letter))

    @property
    def is_satisfiable(self) -> bool:
        """Whether some non-empty trace is accepted."""
        return self._search([self.initial], after_one=True) is not None

    def distance_to_accepting(self, s: int) -> Optional[int]:
        """Fewest transitions from ``s`` to an accepting state, or None (searched forward, then kept)."""
        if s not in self._dist_of:
            self._dist_of[s] = self._search([s], after_one=False)
        return self._dist_of[s]

    def _search(self, start: list[int], after_one: bool) -> Optional[int]:
        """Breadth-first: fewest letters from ``start`` to acceptance (at least one if ``after_one``).

        A state from which one letter reaches acceptance is recognised without
        expanding it, so a level is expanded only when none of its states is that close.
        """
        prog = self._prog
        level = list(dict.fromkeys(start))
        seen = set(level)
        depth = 0
        while level:
            if (not after_one or depth > 0) and any(s in self.accepting for s in level):
                return depth
            if any(prog.accepts_in_one_step(self._nodes[s]) for s in level):
                return depth + 1
            nxt = []
            for s in level:
                if s == self.sink:
                    continue
                for e in self.edges_from(s):
                    if e.dst not in seen:
                        seen.add(e.dst)
                        nxt.append(e.dst)
            level = nxt
            depth += 1
        return None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready description of the states met so far."""
        return {
            'formula': str(self.formula), 'atoms': [a.key for a in self.atoms],
            'states': [{'id': i, 'formula': str(self.state_formula(i)), 'accepting': i in self.accepting,
                        'sink': i == self.sink} for i in range(self.num_states)],
            'initial': self.initial, 'accepting': sorted(self.accepting), 'sink': self.sink,
            'edges': [e.to_dict() for s in sorted(self._edges_of) for e in self._edges_of[s]],
        }


def _state_limit(max_states: int) -> LimitExceededError:
    return LimitExceededError(f'the automaton has more than {max_states} states; simplify the task',
                              details={'limit': 'max_states', 'value': max_states})


def _parse(formula: Formula | str) -> Formula:
    return parse_formula(formula) if isinstance(formula, str) else formula


def on_the_fly_automaton(formula: Formula | str, max_states: int = 100_000,
                         time_limit_s: Optional[float] = DEFAULT_TIME_LIMIT_S,
                         max_nodes: int = DEFAULT_MAX_NODES) -> OnTheFlyAutomaton:
    """Return the formula's DFA, its states expanded only when a caller asks about them.

    ``time_limit_s`` bounds building the step functions (made here, once per
    obligation); ``max_states`` bounds the states met later.

    Raises
    ------
    FormulaSyntaxError
        If ``formula`` is text that does not parse.
    LimitExceededError
        ``LIMIT_EXCEEDED`` past ``max_nodes`` decision-diagram nodes, ``TIMEOUT`` past the deadline.
    """
    f = _parse(formula)
    budget = WorkBudget(time_limit_s)
    try:
        prog = Progression(f, budget, max_nodes)
        lv = prog.num_atoms
        while lv < prog.bdd.num_vars:   # every step function (each may add obligations), while bounded
            prog.transition(prog.bdd.var(lv))
            lv += 1
    except RecursionError:
        raise _too_deep() from None
    prog.budget = WorkBudget(None)
    return OnTheFlyAutomaton(prog, max_states)


def _too_deep() -> LimitExceededError:
    return LimitExceededError('the formula nests too deeply to compile; simplify the task',
                              details={'limit': 'recursion'})


def compile_automaton(formula: Formula | str, max_states: int = DEFAULT_MAX_STATES,
                      max_edges: int = DEFAULT_MAX_EDGES,
                      time_limit_s: Optional[float] = DEFAULT_TIME_LIMIT_S,
                      max_nodes: int = DEFAULT_MAX_NODES) -> Automaton:
    """Compile a formula (AST or text) into its minimal :class:`Automaton`.

    Parameters
    ----------
    formula: the task, as an AST or text.
    max_states: most automaton states explored (before minimisation).
    max_edges: most edges over the whole compilation.
    time_limit_s: seconds the compilation may take (None: no deadline).
    max_nodes: most decision-diagram nodes.

    Raises
    ------
    FormulaSyntaxError
        If ``formula`` is text that does not parse.
    LimitExceededError
        ``LIMIT_EXCEEDED`` past ``max_states``, ``max_edges`` or ``max_nodes``;
        ``TIMEOUT`` past ``time_limit_s``.
    """
    f = _parse(formula)
    budget = WorkBudget(time_limit_s, max_edges)
    try:
        prog = Progression(f, budget, max_nodes)
        nodes, succ = _explore(prog, max_states, budget)
        return _minimise(prog, nodes, succ, budget)
    except RecursionError:  # a last guard: formulas built in code may nest deeper than parsed ones
        raise _too_deep() from None


def _explore(prog: Progression, max_states: int,
             budget: WorkBudget) -> tuple[list[int], list[dict[int, int]]]:
    """Every reachable state (BDD nodes, discovery order) and its successors (state id -> guard)."""
    nodes = [prog.initial]
    index = {prog.initial: 0}
    succ: list[dict[int, int]] = []
    i = 0
    while i < len(nodes):
        row: dict[int, int] = {}
        for t, g in prog.successors(nodes[i]).items():
            j = index.get(t)
            if j is None:
                if len(nodes) >= max_states:
                    raise _state_limit(max_states)
                j = index[t] = len(nodes)
                nodes.append(t)
            row[j] = g
        budget.add_edges(len(row))
        succ.append(row)
        i += 1
    return nodes, succ


def _live(prog: Progression, nodes: list[int], succ: list[dict[int, int]]) -> list[bool]:
    """Which states can reach an accepting state."""
    preds: list[list[int]] = [[] for _ in nodes]
    for s, row in enumerate(succ):
        for t in row:
            preds[t].append(s)
    live = [prog.accepting(n) for n in nodes]
    q = deque(s for s, ok in enumerate(live) if ok)
    while q:
        s = q.popleft()
        for p in preds[s]:
            if not live[p]:
                live[p] = True
                q.append(p)
    return live


def _minimise(prog: Progression, nodes: list[int], succ: list[dict[int, int]],
              budget: WorkBudget) -> Automaton:
    """Moore's partition refinement: merge states with the same future; dead states become one sink."""
    m = prog.bdd
    live = _live(prog, nodes, succ)
    if not live[0]:  # unsatisfiable: the initial state is the sink
        return Automaton(prog, [B.FALSE], [[Edge(0, 0, prog.valid, prog, GUARD_TRUE)]], (), 0)
    block = [(0 if not ok else 1 + prog.accepting(n)) for ok, n in zip(live, nodes)]
    count = len(set(block))
    while True:
        sigs: dict[tuple, int] = {}
        new = []
        for s, row in enumerate(succ):
            if not live[s]:
                new.append(-1)
                continue
            merged: dict[int, int] = {}
            for t, g in row.items():
                b = block[t]
                merged[b] = m.disj(merged[b], g) if b in merged else g
            budget.check()
            new.append(sigs.setdefault((block[s], tuple(sorted(merged.items()))), len(sigs)))
        block = new
        if len(sigs) + (not all(live)) == count:
            break
        count = len(sigs) + (not all(live))
    return _quotient(prog, nodes, succ, block, live)


def _quotient(prog: Progression, nodes: list[int], succ: list[dict[int, int]], block: list[int],
              live: list[bool]) -> Automaton:
    """Build the automaton of the blocks: live blocks in discovery order, then the sink."""
    m = prog.bdd
    ids: dict[int, int] = {}
    reps: list[int] = []
    for s, b in enumerate(block):
        if b >= 0 and b not in ids:
            ids[b] = len(reps)
            reps.append(s)
    sink = len(reps) if not all(live) else None
    state_of = [ids[b] if b >= 0 else sink for b in block]
    edges: list[list[Edge]] = []
    for i, s in enumerate(reps):
        merged: dict[int, int] = {}
        for t, g in succ[s].items():
            d = state_of[t]
            merged[d] = m.disj(merged[d], g) if d in merged else g
        edges.append([Edge(i, d, g, prog) for d, g in merged.items()])
    out_nodes = [nodes[s] for s in reps]
    if sink is not None:
        edges.append([Edge(sink, sink, prog.valid, prog, GUARD_TRUE)])
        out_nodes.append(B.FALSE)
    accepting = [i for i, s in enumerate(reps) if prog.accepting(nodes[s])]
    return Automaton(prog, out_nodes, edges, accepting, sink)


def is_satisfiable(formula: Formula | str) -> bool:
    """Whether some finite trace satisfies the formula."""
    return on_the_fly_automaton(formula).is_satisfiable


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

    Decided on the fly: they are equivalent when no non-empty trace satisfies
    ``!(f <-> g)``.
    """
    return not on_the_fly_automaton(Not(Iff(_parse(f), _parse(g)))).is_satisfiable


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


__all__ = ['Automaton', 'Edge', 'GUARD_FALSE', 'GUARD_TRUE', 'OnTheFlyAutomaton', 'compile_automaton',
           'distinguishing_pair', 'equivalent', 'is_satisfiable', 'on_the_fly_automaton',
           'require_satisfiable']

"""Planning with a formula on a landmark graph: shortest path in the graph x automaton product.

A node of the product is (landmark, automaton state after reading the letters
so far). The trace starts with the letter at the start landmark, read from the
automaton's initial state; moving along a graph edge to landmark j reads the
letter ``{near[j]}``. Dijkstra over edge lengths [m] finds the shortest walk
whose trace is accepted; the plan ends at the first accepting product node,
as a robot may stop at the first point where the trace so far is accepted.

The graph's adjacency is built once per map (:attr:`LandmarkMap.adjacency`) and
shared by every plan. Each product node is expanded at most once, so a search
costs at most (landmarks x automaton states) expansions; ``max_expansions``
(:data:`MAX_EXPANSIONS` by default: room for maps 10x the largest city's 15
landmarks with automata of thousands of states) bounds it, and a search that
reaches the bound raises ``LIMIT_EXCEEDED``, not ``NO_VALID_PATH``: it did not
show that no walk exists.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass
from typing import Optional

from ltl_instruct.core.automaton import Automaton, compile_automaton
from ltl_instruct.core.errors import InvalidInputError, LimitExceededError, PlanningError
from ltl_instruct.core.spec import Formula, atoms_of
from ltl_instruct.core.spec.ast import Atom, near
from ltl_instruct.core.world.landmarks import LandmarkMap

MAX_EXPANSIONS = 2_000_000
"""Product nodes the search expands before it gives up with ``LIMIT_EXCEEDED``."""


@dataclass(frozen=True)
class LandmarkPlan:
    """A planned walk over landmarks.

    Attributes
    ----------
    path: landmark node ids visited, start first.
    states: automaton state after each landmark's letter, same length as ``path``.
    length_m: length of the walk [m].
    """

    path: tuple[int, ...]
    states: tuple[int, ...]
    length_m: float


def _letters(lmap: LandmarkMap, aut: Automaton) -> list[frozenset[Atom]]:
    """Return the letter read at each landmark, restricted to the automaton's atoms."""
    known = set(aut.atoms)
    return [frozenset({near(p)}) & known for p in lmap.props]


def plan_on_landmarks(lmap: LandmarkMap, formula: Formula, start: int,
                      automaton: Optional[Automaton] = None,
                      max_expansions: int = MAX_EXPANSIONS) -> LandmarkPlan:
    """Shortest walk from ``start`` whose trace satisfies ``formula`` (LTLf).

    Raises
    ------
    InvalidInputError
        If ``start`` is not a landmark, or the formula names a proposition not on the map.
    PlanningError
        ``NO_VALID_PATH`` if no walk on the graph satisfies the formula.
    LimitExceededError
        ``LIMIT_EXCEEDED`` if the search expanded ``max_expansions`` product nodes
        without reaching acceptance.
    """
    n = lmap.num_landmarks
    if not 0 <= start < n:
        raise InvalidInputError(f'start landmark {start} is not in 0..{n - 1}')
    props = set(lmap.props)
    for a in atoms_of(formula):
        if a.skill != 'near' or len(a.args) != 1 or a.args[0].relations or a.args[0].name not in props:
            raise InvalidInputError(f'{a.key} is not a landmark of map {lmap.city!r}')
    aut = automaton if automaton is not None else compile_automaton(formula)
    letters = _letters(lmap, aut)
    adj = lmap.adjacency
    q0 = aut.step(aut.initial, letters[start])
    best: dict[tuple[int, int], float] = {(start, q0): 0.0}
    parent: dict[tuple[int, int], Optional[tuple[int, int]]] = {(start, q0): None}
    heap: list[tuple[float, int, int, int]] = [(0.0, 0, start, q0)]
    counter = 0
    sink = aut.sink
    while heap:
        d, _, v, q = heapq.heappop(heap)
        if d > best.get((v, q), float('inf')):
            continue
        if q in aut.accepting:
            node: Optional[tuple[int, int]] = (v, q)
            path, states = [], []
            while node is not None:
                path.append(node[0])
                states.append(node[1])
                node = parent[node]
            return LandmarkPlan(tuple(reversed(path)), tuple(reversed(states)), d)
        counter += 1
        if counter > max_expansions:
            raise LimitExceededError(
                f'planning {formula} on map {lmap.city!r} expanded {max_expansions} (landmark, state) '
                f'pairs without an accepted walk ({n} landmarks, {aut.num_states} automaton states)',
                details={'max_expansions': max_expansions, 'landmarks': n})
        for w, length in adj[v]:
            q2 = aut.step(q, letters[w])
            if q2 == sink:
                continue
            nd = d + length
            if nd < best.get((w, q2), float('inf')):
                best[(w, q2)] = nd
                parent[(w, q2)] = (v, q)
                heapq.heappush(heap, (nd, counter, w, q2))
    raise PlanningError(f'no walk on map {lmap.city!r} from {lmap.props[start]} satisfies {formula}')

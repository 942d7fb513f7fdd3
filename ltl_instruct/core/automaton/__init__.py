"""Automata: symbolic progression (BDDs), minimal or on-the-fly DFAs, traces, English."""
from ltl_instruct.core.automaton.dfa import (  # noqa: F401
    Automaton, Edge, OnTheFlyAutomaton, compile_automaton, distinguishing_pair, equivalent,
    is_satisfiable, on_the_fly_automaton, require_satisfiable,
)
from ltl_instruct.core.automaton.guards import GUARD_FALSE, GUARD_TRUE, Cube, Guard  # noqa: F401
from ltl_instruct.core.automaton.progression import accepts_empty, progress, to_nnf  # noqa: F401
from ltl_instruct.core.automaton.semantics import holds  # noqa: F401

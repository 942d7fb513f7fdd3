"""Automata: progression, DFA compilation with symbolic guards, traces, English."""

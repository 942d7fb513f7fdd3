"""Benchmarks of ltl_instruct; ``python -m bench`` runs them all, ``python -m bench.NAME`` one."""

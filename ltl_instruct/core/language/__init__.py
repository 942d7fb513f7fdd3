"""language package of the ltl_instruct core."""

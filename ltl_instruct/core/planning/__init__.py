"""planning package of the ltl_instruct core."""

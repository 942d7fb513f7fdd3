"""ltl_instruct: plain-English robot instructions to verified paths."""

__version__ = '0.1.0'

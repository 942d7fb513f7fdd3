"""Printer for task formulas: the inverse of the parser.

Prints the fewest parentheses the precedence of ``spec/formula.md`` allows
(unary > ``U R W`` > ``&`` > ``|`` > ``-> <->``), so ``parse(print(f)) == f``.
Binary temporal operators and implications are right-associative; a left operand
of the same precedence is parenthesised.

The printer walks the formula with an explicit stack (no recursion), so a formula
of any depth prints without ``RecursionError``; each node's text is cached on the
node (``str(f)`` is the canonical sort key elsewhere).
"""
from __future__ import annotations

from ltl_instruct.core.spec.ast import (
    Atom, Const, Descriptor, Formula, Not, WeakNext, _Binary, _NAry, _Unary,
)


def format_descriptor(d: Descriptor) -> str:
    """``chair::isbetween(sofa, bag)``."""
    return str(d)


def format_formula(f: Formula) -> str:
    """Return the canonical text of ``f`` (parseable by :func:`parse_formula`)."""
    cached = f.__dict__.get('_text')
    if cached is not None:
        return cached
    if all('_text' in k.__dict__ for k in f.children()):  # the common case: one node to print
        text = _fmt(f)
        object.__setattr__(f, '_text', text)
        return text
    # post-order over the nodes whose text is not cached yet
    stack: list[tuple[Formula, bool]] = [(f, False)]
    while stack:
        node, ready = stack.pop()
        if '_text' in node.__dict__:
            continue
        kids = [k for k in node.children() if '_text' not in k.__dict__]
        if ready or not kids:
            object.__setattr__(node, '_text', _fmt(node))
            continue
        stack.append((node, True))
        stack.extend((k, False) for k in kids)
    return f.__dict__['_text']


def _text(f: Formula) -> str:
    return f.__dict__['_text']  # children are printed first by format_formula


def _wrap(f: Formula, min_prec: int) -> str:
    text = _text(f)
    return f'({text})' if f.precedence < min_prec else text


def _fmt(f: Formula) -> str:
    """Text of one node whose children are already printed."""
    if isinstance(f, Const):
        return 'true' if f.value else 'false'
    if isinstance(f, Atom):
        return f"{f.skill}[{', '.join(str(a) for a in f.args)}]"
    if isinstance(f, Not):
        return '!' + _wrap(f.operand, 90)
    if isinstance(f, WeakNext):  # not in the surface syntax: weak next = !X !f
        return '!X !' + _wrap(f.operand, 90)
    if isinstance(f, _Unary):
        return f'{f.symbol} ' + _wrap(f.operand, 90)
    if isinstance(f, _Binary):
        # right-associative: the left operand must bind tighter, the right may be equal
        return f'{_wrap(f.left, f.precedence + 1)} {f.symbol} {_wrap(f.right, f.precedence)}'
    if isinstance(f, _NAry):
        # a nested node of the same class would be flattened by the parser: keep it visible
        # U/R/W inside & or | get parentheses too: not needed by the grammar, but people
        # misread "F b & !b U a" (the parser gives the same AST either way)
        return f' {f.symbol} '.join(_wrap(o, 90 if isinstance(o, _Binary) else f.precedence + 1)
                                    for o in f.operands)
    if type(f).__str__ is not Formula.__str__:  # e.g. progression's Later marker
        return str(f)
    raise TypeError(f'not a formula node: {f!r}')

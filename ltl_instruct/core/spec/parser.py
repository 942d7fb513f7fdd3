"""Parser for the task-formula syntax of ``spec/formula.md``.

A hand-written recursive-descent parser over a small tokenizer. Errors name the
line and column, show the line with a caret under the offending token, and say
what was expected. Limits on length, nesting depth and atom count are checked
before any deep work, so hostile input gets a clear error, never a hang or a
``RecursionError``.

Examples
--------
>>> str(parse_formula('F near[sofa] & G !near[door]'))
'F near[sofa] & G !near[door]'
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable, Optional

from ltl_instruct.core.errors import FormulaSyntaxError, LimitExceededError
from ltl_instruct.core.spec.ast import (
    COMPARATORS, FALSE, KEYWORDS, SKILLS, TRUE, Always, And, Atom, Descriptor, Eventually,
    Formula, Iff, Implies, Next, Not, Or, Release, Relation, Until, WeakUntil,
)


@dataclass(frozen=True)
class ParseLimits:
    """Upper bounds on what the parser accepts.

    Attributes
    ----------
    max_length: characters of formula text.
    max_depth: nesting depth of operators, parentheses and descriptors.
    max_atoms: distinct atoms.
    max_descriptor_depth: nesting of descriptors inside descriptors
        (``a::isabove(b::isabove(c))`` is 2); descriptors are printed and described
        recursively, so this bound keeps them far from Python's recursion limit.
    """

    max_length: int = 20_000
    max_depth: int = 200
    max_atoms: int = 64
    max_descriptor_depth: int = 32


DEFAULT_LIMITS = ParseLimits()

_TOKEN_RE = re.compile(r'''
    (?P<ws>\s+)
  | (?P<op><->|->|::|[()\[\],!~&|])
  | (?P<upper>[FGXURW](?=[FGX]*(?![A-Za-z0-9_])))
  | (?P<name>[A-Za-z_][A-Za-z0-9_]*)
''', re.VERBOSE)

_NAME_RE = re.compile(r'[a-z][a-z0-9_]*\Z')


@dataclass(frozen=True)
class Token:
    """One lexical token: ``kind`` is ``op``, ``upper``, ``name`` or ``end``."""

    kind: str
    text: str
    pos: int


def _line_col(text: str, pos: int) -> tuple[int, int, str]:
    line = text.count('\n', 0, pos) + 1
    start = text.rfind('\n', 0, pos) + 1
    end = text.find('\n', pos)
    end = len(text) if end < 0 else end
    return line, pos - start + 1, text[start:end]


def syntax_error(text: str, pos: int, message: str, expected: str = '') -> FormulaSyntaxError:
    """Build a :class:`FormulaSyntaxError` with line, column and a caret."""
    line, col, line_text = _line_col(text, pos)
    shown = line_text
    offset = col - 1
    if len(shown) > 120:  # keep huge one-line inputs readable: a window around the caret
        lo = max(0, offset - 60)
        shown = ('...' if lo else '') + shown[lo:lo + 120] + '...'
        offset = offset - lo + (3 if lo else 0)
    what = message + (f'; expected {expected}' if expected else '')
    full = f'line {line}, column {col}: {what}\n  {shown}\n  {" " * offset}^'
    return FormulaSyntaxError(full, details={'line': line, 'column': col, 'expected': expected,
                                             'reason': message})


def tokenize(text: str) -> list[Token]:
    """Split formula text into tokens (white space dropped)."""
    tokens: list[Token] = []
    pos = 0
    n = len(text)
    while pos < n:
        m = _TOKEN_RE.match(text, pos)
        if m is None:
            raise syntax_error(text, pos, f'unexpected character {text[pos]!r}',
                               'an operator, a parenthesis, a bracket or a name')
        kind = m.lastgroup or ''
        if kind != 'ws':
            tokens.append(Token(kind, m.group(), pos))
        pos = m.end()
    tokens.append(Token('end', '', n))
    return tokens


class _Parser:
    def __init__(self, text: str, limits: ParseLimits) -> None:
        self.text = text
        self.limits = limits
        self.tokens = tokenize(text)
        self.i = 0
        self.depth = 0
        self.unary_depth = 0
        self.descriptor_depth = 0
        self.atoms: set[Atom] = set()

    # -- helpers
    @property
    def tok(self) -> Token:
        return self.tokens[self.i]

    def advance(self) -> Token:
        t = self.tokens[self.i]
        self.i += 1
        return t

    def error(self, message: str, expected: str = '', tok: Optional[Token] = None) -> FormulaSyntaxError:
        t = tok or self.tok
        return syntax_error(self.text, t.pos, message, expected)

    def describe(self, t: Token) -> str:
        return 'end of input' if t.kind == 'end' else repr(t.text)

    def expect(self, text: str) -> Token:
        if self.tok.text != text or self.tok.kind == 'end':
            raise self.error(f'unexpected {self.describe(self.tok)}', repr(text))
        return self.advance()

    def enter(self) -> None:
        self.depth += 1
        if self.depth > self.limits.max_depth:
            raise LimitExceededError(
                f'formula nests deeper than {self.limits.max_depth} levels '
                f'(at column {_line_col(self.text, self.tok.pos)[1]})',
                details={'limit': 'max_depth', 'value': self.limits.max_depth})

    def leave(self) -> None:
        self.depth -= 1

    # -- grammar
    def parse(self) -> Formula:
        if self.tok.kind == 'end':
            raise self.error('empty formula', 'a formula')
        f = self.implies()
        if self.tok.kind != 'end':
            raise self.error(f'unexpected {self.describe(self.tok)} after a complete formula',
                             "an operator ('&', '|', '->', '<->', 'U', 'R', 'W') or end of input")
        return f

    def implies(self) -> Formula:
        self.enter()
        left = self.or_()
        if self.tok.text in ('->', '<->'):
            op = self.advance().text
            right = self.implies()  # right-associative
            left = Implies(left, right) if op == '->' else Iff(left, right)
        self.leave()
        return left

    def _nary(self, sub: Callable[[], Formula], symbol: str, cls: type) -> Formula:
        items = [sub()]
        while self.tok.kind == 'op' and self.tok.text == symbol:
            self.advance()
            items.append(sub())
        if len(items) == 1:
            return items[0]
        flat: list[Formula] = []
        for f in items:  # associativity is irrelevant: keep one flat node
            flat.extend(f.operands if isinstance(f, cls) else (f,))
        return cls(tuple(flat))

    def or_(self) -> Formula:
        return self._nary(self.and_, '|', Or)

    def and_(self) -> Formula:
        return self._nary(self.until, '&', And)

    def until(self) -> Formula:
        self.enter()
        left = self.unary()
        if self.tok.kind == 'upper' and self.tok.text in ('U', 'R', 'W'):
            op = self.advance().text
            right = self.until()  # right-associative
            cls = {'U': Until, 'R': Release, 'W': WeakUntil}[op]
            left = cls(left, right)
        self.leave()
        return left

    def unary(self) -> Formula:
        t = self.tok
        ops: list[str] = []
        while (t.kind == 'op' and t.text in ('!', '~')) or (t.kind == 'upper' and t.text in 'FGX'):
            ops.append('!' if t.text == '~' else t.text)
            self.advance()
            t = self.tok
            if len(ops) > self.limits.max_depth:
                raise LimitExceededError(
                    f'more than {self.limits.max_depth} unary operators in a row',
                    details={'limit': 'max_depth', 'value': self.limits.max_depth})
        # unary operators nest too: "!!(!!(...))" may hold at most max_depth of them on any
        # path, so the AST stays within about twice max_depth for the stages after the parser
        if ops and self.unary_depth + len(ops) > self.limits.max_depth:
            raise LimitExceededError(
                f'formula nests more than {self.limits.max_depth} unary operators '
                f'(at column {_line_col(self.text, t.pos)[1]})',
                details={'limit': 'max_depth', 'value': self.limits.max_depth})
        self.unary_depth += len(ops)
        f = self.primary()
        self.unary_depth -= len(ops)
        for op in reversed(ops):
            f = {'!': Not, 'F': Eventually, 'G': Always, 'X': Next}[op](f)
        return f

    def primary(self) -> Formula:
        t = self.tok
        if t.kind == 'op' and t.text == '(':
            self.advance()
            self.enter()
            f = self.implies()
            self.leave()
            if self.tok.text != ')':
                raise self.error(f'unexpected {self.describe(self.tok)}',
                                 "')' to close the '(' at column "
                                 f'{_line_col(self.text, t.pos)[1]}')
            self.advance()
            return f
        if t.kind == 'upper':
            raise self.error(f"'{t.text}' is a binary operator and needs a left operand"
                             if t.text in 'URW' else f'unexpected {t.text!r}',
                             'a formula')
        if t.kind != 'name':
            raise self.error(f'unexpected {self.describe(t)}',
                             "a formula: '(', '!', 'F', 'G', 'X', 'true', 'false', a skill or a proposition")
        self.advance()
        if t.text == 'true':
            return TRUE
        if t.text == 'false':
            return FALSE
        if t.text in SKILLS:
            return self.skill_atom(t)
        if self.tok.text == '[':
            raise self.error(f'unknown skill {t.text!r}', "one of 'near', 'pick', 'release'", t)
        self.check_name(t)
        return self.add_atom(Atom('near', (Descriptor(t.text),)), t)

    def add_atom(self, atom: Atom, t: Token) -> Atom:
        self.atoms.add(atom)
        if len(self.atoms) > self.limits.max_atoms:
            raise LimitExceededError(
                f'more than {self.limits.max_atoms} distinct atoms '
                f'(at column {_line_col(self.text, t.pos)[1]})',
                details={'limit': 'max_atoms', 'value': self.limits.max_atoms})
        return atom

    def check_name(self, t: Token) -> None:
        if t.kind != 'name':
            raise self.error(f'unexpected {self.describe(t)}', 'a name', t)
        if t.text in KEYWORDS:
            raise self.error(f'{t.text!r} is a keyword and cannot be a name', 'a name', t)
        if not _NAME_RE.match(t.text):
            raise self.error(f'invalid name {t.text!r}',
                             'a lower-case snake_case name ([a-z][a-z0-9_]*)', t)

    def skill_atom(self, skill_tok: Token) -> Atom:
        skill = skill_tok.text
        if self.tok.text != '[':
            raise self.error(f'unexpected {self.describe(self.tok)} after skill {skill!r}', "'['")
        self.advance()
        args = self.descriptor_list(']')
        arity = SKILLS[skill]
        if len(args) != arity:
            raise self.error(f'{skill}[...] takes {arity} descriptor'
                             f"{'s' if arity > 1 else ''}, got {len(args)}",
                             f'{arity} argument{"s" if arity > 1 else ""}', skill_tok)
        return self.add_atom(Atom(skill, tuple(args)), skill_tok)

    def descriptor_list(self, close: str) -> list[Descriptor]:
        args = [self.descriptor()]
        while self.tok.text == ',':
            self.advance()
            args.append(self.descriptor())
        if self.tok.text != close:
            raise self.error(f'unexpected {self.describe(self.tok)} in argument list',
                             f"',' or '{close}'")
        self.advance()
        return args

    def descriptor(self) -> Descriptor:
        self.enter()
        t = self.tok
        self.descriptor_depth += 1
        if self.descriptor_depth > self.limits.max_descriptor_depth + 1:
            raise LimitExceededError(
                f'descriptors nest deeper than {self.limits.max_descriptor_depth} levels '
                f'(at column {_line_col(self.text, t.pos)[1]})',
                details={'limit': 'max_descriptor_depth', 'value': self.limits.max_descriptor_depth})
        if t.kind == 'upper':  # e.g. near[X]: upper-case single letters are operators
            raise self.error(f'invalid name {t.text!r}', 'a lower-case snake_case name')
        self.check_name(t)
        self.advance()
        relations: list[Relation] = []
        while self.tok.text == '::':
            self.advance()
            c = self.tok
            if c.kind != 'name' or c.text not in COMPARATORS:
                raise self.error(f'unknown comparator {c.text!r}' if c.kind == 'name'
                                 else f'unexpected {self.describe(c)}',
                                 'one of ' + ', '.join(sorted(COMPARATORS)))
            self.advance()
            if self.tok.text != '(':
                raise self.error(f'unexpected {self.describe(self.tok)} after {c.text!r}', "'('")
            self.advance()
            args = self.descriptor_list(')')
            arity = COMPARATORS[c.text]
            if len(args) != arity:
                raise self.error(f'{c.text} takes {arity} descriptor'
                                 f"{'s' if arity > 1 else ''}, got {len(args)}",
                                 f'{arity} argument{"s" if arity > 1 else ""}', c)
            relations.append(Relation(c.text, tuple(args)))
        self.leave()
        self.descriptor_depth -= 1
        return Descriptor(t.text, tuple(relations))


def parse_formula(text: str, limits: ParseLimits = DEFAULT_LIMITS) -> Formula:
    """Parse formula text into an immutable AST.

    Parameters
    ----------
    text:
        Formula in the syntax of ``spec/formula.md``.
    limits:
        Bounds on length, nesting depth and distinct atoms.

    Raises
    ------
    FormulaSyntaxError
        With line, column, a caret and what was expected.
    LimitExceededError
        When the text is longer, deeper or has more atoms than ``limits`` allow.
    """
    if not isinstance(text, str):
        raise FormulaSyntaxError(f'a formula must be text, not {type(text).__name__}')
    if len(text) > limits.max_length:
        raise LimitExceededError(
            f'formula is {len(text)} characters long; the limit is {limits.max_length}',
            details={'limit': 'max_length', 'value': limits.max_length})
    return _Parser(text, limits).parse()


def parse_descriptor(text: str, limits: ParseLimits = DEFAULT_LIMITS) -> Descriptor:
    """Parse a single descriptor such as ``chair::isbetween(sofa, bag)``."""
    if len(text) > limits.max_length:
        raise LimitExceededError(f'descriptor is {len(text)} characters long; '
                                 f'the limit is {limits.max_length}')
    p = _Parser(text, limits)
    d = p.descriptor()
    if p.tok.kind != 'end':
        raise p.error(f'unexpected {p.describe(p.tok)} after a complete descriptor', 'end of input')
    return d

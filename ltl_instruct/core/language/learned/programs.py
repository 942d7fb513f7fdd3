"""Postfix formula programs over a landmark map: vocabulary, type constraints, LTLf checking.

A program is a sequence of output-token ids in postfix order: a landmark token
pushes the proposition ``near[landmark]``; ``F G X !`` pop one formula and push
one; ``U & |`` pop two (left then right) and push one; ``END`` closes a program
whose stack holds exactly one formula. :func:`allowed_mask` is the stack
discipline that the decoder applies at every step, so decoding only yields
valid programs (type-constrained decoding).

:func:`first_acceptance` checks a program on a landmark trace with the LTLf
semantics of ``spec/formula.md`` (strong next; ``G`` up to the end of the
trace), computed on bit masks of trace positions, one trace prefix at a time.
It agrees with the automaton of ``core/automaton`` (a test checks so).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.spec import Formula, conj, disj, neg
from ltl_instruct.core.spec.ast import Always, Eventually, Next, Until, near

UNARY_OPS = ('F', 'G', 'X', '!')
BINARY_OPS = ('U', '&', '|')
OPERATORS = UNARY_OPS + BINARY_OPS
END = '<end>'

# token kinds, used to build masks with numpy
KIND_LANDMARK, KIND_UNARY, KIND_BINARY, KIND_END = 0, 1, 2, 3


@dataclass(frozen=True)
class OutputVocabulary:
    """Output tokens: the map's landmark propositions, then ``F G X ! U & |``, then ``END``.

    Attributes
    ----------
    props: landmark propositions (snake_case), token id = landmark node id.
    """

    props: tuple[str, ...]

    @property
    def tokens(self) -> tuple[str, ...]:
        """All tokens, index = token id."""
        return self.props + OPERATORS + (END,)

    @property
    def size(self) -> int:
        """Number of output tokens."""
        return len(self.props) + len(OPERATORS) + 1

    @property
    def end_id(self) -> int:
        """Token id of END."""
        return self.size - 1

    def kinds(self) -> np.ndarray:
        """Kind of each token (KIND_*), shape (size,)."""
        n = len(self.props)
        return np.array([KIND_LANDMARK] * n + [KIND_UNARY] * len(UNARY_OPS)
                        + [KIND_BINARY] * len(BINARY_OPS) + [KIND_END], dtype=np.int64)

    def op_id(self, op: str) -> int:
        """Token id of an operator symbol."""
        return len(self.props) + OPERATORS.index(op)

    def text(self, program: Sequence[int]) -> str:
        """Space-separated postfix text of a program (END omitted)."""
        toks = self.tokens
        return ' '.join(toks[t] for t in program if t != self.end_id)


def allowed_mask(vocab: OutputVocabulary, stack: np.ndarray, length: np.ndarray,
                 last: np.ndarray, max_len: int) -> np.ndarray:
    """Which tokens may come next, for a batch of partial programs.

    Parameters
    ----------
    stack: formulas on each program's stack, shape (B,).
    length: tokens emitted so far (END not counted), shape (B,).
    last: id of each program's last token, -1 if none, shape (B,).
    max_len: most tokens a program may have before END.

    Returns
    -------
    Boolean array (B, vocab.size). A landmark is allowed only while the program
    can still be closed within ``max_len``; a unary operator needs one operand
    and may not repeat itself (``F F``, ``G G``, ``! !`` say nothing new); a
    binary operator needs two; END needs exactly one formula on the stack; ``F`` and
    ``G`` may not apply directly to ``F`` or ``G``.
    """
    kinds = vocab.kinds()[None, :]
    s = stack[:, None]
    remaining = (max_len - length)[:, None]  # tokens still allowed, this one included
    ok_landmark = (kinds == KIND_LANDMARK) & (s <= remaining - 1) & (remaining >= 1)
    ok_unary = (kinds == KIND_UNARY) & (s >= 1) & (s <= remaining)
    ok_binary = (kinds == KIND_BINARY) & (s >= 2) & (remaining >= 1)
    ok_end = (kinds == KIND_END) & (s == 1)
    mask = ok_landmark | ok_unary | ok_binary | ok_end
    ids = np.arange(vocab.size)[None, :]
    no_repeat = ~((ids == last[:, None]) & (kinds == KIND_UNARY) & (ids != vocab.op_id('X')))
    # F and G directly on F or G: over finite traces F F p = F p, G G p = G p, and
    # F G p = G F p = "p at the last step"; one spelling (none) keeps the search small
    eventually_always = np.isin(ids, [vocab.op_id('F'), vocab.op_id('G')])
    after_fg = np.isin(last, [vocab.op_id('F'), vocab.op_id('G')])[:, None]
    return mask & no_repeat & ~(eventually_always & after_fg)


def stack_effect(vocab: OutputVocabulary) -> np.ndarray:
    """Change of stack size per token, shape (size,)."""
    k = vocab.kinds()
    return np.where(k == KIND_LANDMARK, 1, np.where(k == KIND_BINARY, -1, 0)).astype(np.int64)


def is_valid_program(vocab: OutputVocabulary, program: Sequence[int]) -> bool:
    """Whether ``program`` (END optional at the end) is a well-formed postfix formula."""
    kinds = vocab.kinds()
    s = 0
    body = list(program)
    if body and body[-1] == vocab.end_id:
        body = body[:-1]
    for t in body:
        if not 0 <= t < vocab.size - 1:
            return False
        k = kinds[t]
        if k == KIND_LANDMARK:
            s += 1
        elif k == KIND_UNARY:
            if s < 1:
                return False
        elif s < 2:
            return False
        else:
            s -= 1
    return s == 1


def program_to_formula(vocab: OutputVocabulary, program: Sequence[int]) -> Formula:
    """Build the formula AST of a postfix program; raises ``InvalidInputError`` if malformed."""
    if not is_valid_program(vocab, program):
        raise InvalidInputError(f'not a valid postfix program: {vocab.text(program)!r}')
    n = len(vocab.props)
    stack: list[Formula] = []
    for t in program:
        if t == vocab.end_id:
            break
        if t < n:
            stack.append(near(vocab.props[t]))
            continue
        op = OPERATORS[t - n]
        if op in UNARY_OPS:
            a = stack.pop()
            stack.append({'F': Eventually, 'G': Always, 'X': Next}[op](a) if op != '!' else neg(a))
        else:
            b, a = stack.pop(), stack.pop()
            stack.append(Until(a, b) if op == 'U' else conj(a, b) if op == '&' else disj(a, b))
    return stack[0]


def _truth_on_prefix(vocab: OutputVocabulary, program: Sequence[int], trace: Sequence[int],
                     m: int) -> bool:
    """Whether the trace prefix of length m satisfies the program (LTLf, position 0)."""
    n = len(vocab.props)
    full = (1 << m) - 1
    stack: list[int] = []
    for t in program:
        if t == vocab.end_id:
            break
        if t < n:
            bits = 0
            for i in range(m):
                if trace[i] == t:
                    bits |= 1 << i
            stack.append(bits)
            continue
        op = OPERATORS[t - n]
        if op == '!':
            stack.append(~stack.pop() & full)
        elif op == 'X':   # strong next: position i+1 must exist
            stack.append(stack.pop() >> 1)
        elif op == 'F':   # true at every position up to the last one where the operand holds
            v = stack.pop()
            stack.append((1 << v.bit_length()) - 1 if v else 0)
        elif op == 'G':   # true from just after the last position where the operand fails
            v = ~stack.pop() & full
            stack.append(full & ~((1 << v.bit_length()) - 1))
        else:
            b, a = stack.pop(), stack.pop()
            if op == '&':
                stack.append(a & b)
            elif op == '|':
                stack.append(a | b)
            else:         # a U b, computed backwards: u_i = b_i or (a_i and u_{i+1})
                u, nxt = 0, 0
                for i in range(m - 1, -1, -1):
                    cur = (b >> i) & 1 or ((a >> i) & 1 and nxt)
                    nxt = 1 if cur else 0
                    u |= nxt << i
                stack.append(u)
    return bool(stack[0] & 1)


def first_acceptance(vocab: OutputVocabulary, program: Sequence[int],
                     trace: Sequence[int]) -> Optional[int]:
    """Length of the shortest prefix of ``trace`` (landmark ids) that satisfies the program.

    ``None`` if no non-empty prefix does. The trace's letter at step i is
    ``{near[props[trace[i]]]}``.
    """
    for m in range(1, len(trace) + 1):
        if _truth_on_prefix(vocab, program, trace, m):
            return m
    return None


def accepts(vocab: OutputVocabulary, program: Sequence[int], trace: Sequence[int]) -> bool:
    """Whether the whole (non-empty) trace satisfies the program."""
    if not trace:
        raise InvalidInputError('LTLf traces are non-empty')
    return _truth_on_prefix(vocab, program, trace, len(trace))

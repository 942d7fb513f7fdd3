"""Readers for the language-to-LTL data sets, mapped onto our formula syntax.

- Our development set (``spatial-temporal-dev/dev.jsonl``): formulas already in our syntax.
- efficient-eng-2-ltl (``drone-planning.jsonl`` and friends): ``raw_ltl`` is infix
  with ``~`` negation and landmark propositions (``purple_room``, ``landmark_1``);
  each proposition ``p`` becomes ``near[p]``.
- lang2ltl ``lifted.csv``: prefix LTL over letter propositions ``a, b, c...``;
  operators ``! F G X & | U W R M i e`` (``i`` implies, ``e`` iff, ``M`` strong
  release: ``a M b`` = ``b U (a & b)``); each letter ``p`` becomes ``near[p]``.

Every reader yields :class:`Example` values; a line that cannot be read is
counted in ``skipped`` and never silently turned into a wrong example.
"""
from __future__ import annotations

import csv
import json
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator, Optional

from ltl_instruct.core.errors import FormulaSyntaxError, InvalidInputError, LtlInstructError
from ltl_instruct.core.spec import (
    Always, And, Atom, Descriptor, Eventually, Formula, Iff, Implies, Next, Not, Or, Release, Until,
    WeakUntil, avoided_referents_of, parse_formula, referents_of,
)


@dataclass(frozen=True)
class Example:
    """One instruction with its gold formula.

    Attributes
    ----------
    instruction: the English text.
    formula: the gold formula in our syntax.
    source: ``file:line`` it came from.
    kinds: the kinds of language it exercises (development set only).
    """

    instruction: str
    formula: Formula
    source: str
    kinds: tuple[int, ...] = ()

    @property
    def referents(self) -> tuple[str, ...]:
        """Skill-argument descriptors of the gold formula, in order of first appearance."""
        return tuple(str(d) for d in referents_of(self.formula))

    @property
    def avoid(self) -> tuple[str, ...]:
        """Descriptors under an explicit negation in the gold formula."""
        return tuple(str(d) for d in avoided_referents_of(self.formula))


@dataclass
class DataSet:
    """Examples read from one file, and how many lines were skipped (with reasons)."""

    name: str
    examples: list[Example] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)
    landmarks: tuple[str, ...] = ()   # proposition names given in advance (lifted: a, b, c...)


_BINARY = {'&': 'and', '|': 'or', 'U': 'until', 'W': 'weak', 'R': 'release', 'M': 'strong_release',
           'i': 'implies', 'e': 'iff', '->': 'implies', '<->': 'iff'}
_UNARY = {'!': 'not', '~': 'not', 'F': 'eventually', 'G': 'always', 'X': 'next'}


def parse_prefix_ltl(text: str) -> Formula:
    """Parse lang2ltl's prefix LTL (``& F a F b``) into our AST; letters become ``near[...]``.

    Raises
    ------
    FormulaSyntaxError
        On an unknown token, a missing operand or tokens left over.
    """
    tokens = text.split()
    if not tokens:
        raise FormulaSyntaxError('empty prefix formula')
    pos = 0

    def parse(depth: int) -> Formula:
        nonlocal pos
        if depth > 200:
            raise FormulaSyntaxError('prefix formula nested too deeply')
        if pos >= len(tokens):
            raise FormulaSyntaxError(f'prefix formula ended early: {text!r}')
        tok = tokens[pos]
        pos += 1
        if tok in _UNARY:
            a = parse(depth + 1)
            return {'not': Not, 'eventually': Eventually, 'always': Always, 'next': Next}[_UNARY[tok]](a)
        if tok in _BINARY:
            a = parse(depth + 1)
            b = parse(depth + 1)
            kind = _BINARY[tok]
            if kind == 'and':
                return And((a, b))
            if kind == 'or':
                return Or((a, b))
            if kind == 'until':
                return Until(a, b)
            if kind == 'weak':
                return WeakUntil(a, b)
            if kind == 'release':
                return Release(a, b)
            if kind == 'strong_release':
                return Until(b, And((a, b)))
            if kind == 'implies':
                return Implies(a, b)
            return Iff(a, b)
        if tok == 'true' or tok == 'false':
            return parse_formula(tok)
        if tok.isidentifier() and tok[0].isalpha() and tok.lower() == tok:
            return Atom('near', (Descriptor(tok),))
        raise FormulaSyntaxError(f'unknown token {tok!r} in prefix formula {text!r}')

    f = parse(0)
    if pos != len(tokens):
        raise FormulaSyntaxError(f'tokens left over in prefix formula {text!r}: {" ".join(tokens[pos:])}')
    return f


def read_dev(path: Path) -> DataSet:
    """Read our development set (JSON lines with ``instruction`` and ``formula``)."""
    ds = DataSet(path.name)
    for n, line in enumerate(path.read_text(encoding='utf-8').splitlines(), 1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
            ds.examples.append(Example(d['instruction'], parse_formula(d['formula']), f'{path.name}:{n}',
                                       tuple(d.get('kinds', ()))))
        except (ValueError, KeyError, TypeError, LtlInstructError) as e:
            ds.skipped.append(f'{path.name}:{n}: {e}')
    return ds


def read_efficient_eng(path: Path) -> DataSet:
    """Read efficient-eng-2-ltl JSON lines (``natural``, infix ``raw_ltl``)."""
    ds = DataSet(path.name)
    for n, line in enumerate(path.read_text(encoding='utf-8').splitlines(), 1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
            raw = d['raw_ltl']
            f = parse_formula(raw) if not raw.split()[0] in ('&', '|', 'U') else parse_prefix_ltl(raw)
            ds.examples.append(Example(d['natural'], f, f'{path.name}:{n}'))
        except (ValueError, KeyError, TypeError, IndexError, LtlInstructError) as e:
            ds.skipped.append(f'{path.name}:{n}: {e}')
    return ds


def read_lifted(path: Path) -> DataSet:
    """Read lang2ltl's ``lifted.csv`` (``pattern_type,props,utterance,ltl_formula``)."""
    ds = DataSet(path.name)
    props: set[str] = set()
    with path.open(encoding='utf-8', newline='') as fh:
        for n, row in enumerate(csv.DictReader(fh), 2):
            props.update(re.findall(r"'([a-z][a-z0-9_]*)'", row.get('props') or ''))
            try:
                ds.examples.append(Example(row['utterance'], parse_prefix_ltl(row['ltl_formula']),
                                           f'{path.name}:{n}:{row.get("pattern_type", "")}'))
            except (KeyError, TypeError, AttributeError, LtlInstructError) as e:
                ds.skipped.append(f'{path.name}:{n}: {e}')
    ds.landmarks = tuple(sorted(props))
    return ds


def read_dataset(path: str | Path, kind: Optional[str] = None) -> DataSet:
    """Read a data set, choosing the reader from ``kind`` or from the file's contents.

    Parameters
    ----------
    path:
        The file.
    kind:
        ``dev``, ``efficient-eng`` or ``lifted``; None guesses from the header or first line.
    """
    p = Path(path)
    if not p.is_file():
        raise InvalidInputError(f'no such data file: {p}')
    if kind is None:
        with p.open(encoding='utf-8') as fh:
            first = fh.readline()
        if 'ltl_formula' in first and 'utterance' in first:
            kind = 'lifted'
        elif '"raw_ltl"' in first:
            kind = 'efficient-eng'
        elif '"instruction"' in first and '"formula"' in first:
            kind = 'dev'
        else:
            raise InvalidInputError(f'cannot tell what kind of data set {p} is; pass --kind')
    readers = {'dev': read_dev, 'efficient-eng': read_efficient_eng, 'lifted': read_lifted}
    if kind not in readers:
        raise InvalidInputError(f'unknown data set kind {kind!r}; one of {", ".join(readers)}')
    return readers[kind](p)


# keys an input line may name its instruction with ("text" as on the node's instruction topic)
INSTRUCTION_KEYS = ('instruction', 'text')


def iter_instructions(path: str | Path) -> Iterator[tuple[int, dict]]:
    """Lines of a JSONL file of instructions: ``(line number, object)``; bad lines give ``{'error'}``.

    The instruction is the line's ``instruction`` (or ``text``) string, returned under
    ``instruction``; a bad line that is an object keeps its other fields (an ``id``) beside the error.
    """
    with Path(path).open(encoding='utf-8') as fh:
        for n, line in enumerate(fh, 1):
            if not line.strip():
                continue
            obj: object = None
            try:
                obj = json.loads(line)
                if not isinstance(obj, dict):
                    raise ValueError('each line must be an object with an "instruction" string')
                text = next((obj[k] for k in INSTRUCTION_KEYS if isinstance(obj.get(k), str)), None)
                if text is None:
                    raise ValueError('each line must be an object with an "instruction" string')
                yield n, {**obj, 'instruction': text}
            except (ValueError, RecursionError) as e:   # RecursionError: JSON nested too deep
                kept = {k: v for k, v in obj.items() if k not in INSTRUCTION_KEYS} \
                    if isinstance(obj, dict) else {}
                yield n, {**kept, 'error': {'code': 'INVALID_INPUT', 'message': f'line {n}: {e}'}}

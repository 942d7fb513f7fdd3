"""The literal-text prefilter of the rewriting rules never skips a rule that would match.

``prefilter.required_text`` reads what every match of a pattern must contain; a rule whose
text is absent is skipped without running it. A wrong clause would silently turn a rule
off (the word prefilter it replaced did that to "overfly"), so it is checked three ways:
hand-made patterns, random patterns with strings drawn from them, and every rule of
``idioms`` on the sentences the rewriting sees while the test suite's instructions are
translated.
"""
from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ltl_instruct.core.language import idioms
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.language.prefilter import admits, required_text
from ltl_instruct.core.errors import LtlInstructError


@pytest.mark.parametrize('pattern,text,expected', [
    (r'\bgo to the (?P<x>\w+)', 'please go to the shed', True),
    (r'\bgo to the (?P<x>\w+)', 'please head to the shed', False),
    (r'\boverfl(?:y|ying|ies)\b', "don't overfly the car park", True),   # the word prefilter missed it
    (r'(?:stay|keep) (?:away|clear) from', 'keep clear from it', True),
    (r'(?:stay|keep) (?:away|clear) from', 'keep off it', False),
    (r'(?:at )?most once', 'most once', True),           # an optional part needs nothing
    (r'x(?=ab)', 'xab', True),                            # a lookahead's text is in the text
    (r'go(?! there)', 'go here', True),                   # a negative lookahead needs nothing
    (r'(?i)visit', 'VISIT', True),                        # case-blind: no clauses at all
    (r'(?:a|the|[bc]d) shed', 'bd shed', True),           # a branch with no literal: no clause from it
])
def test_required_text_on_hand_made_patterns(pattern: str, text: str, expected: bool) -> None:
    assert admits(required_text(pattern), text) == expected
    assert expected or re.search(pattern, text) is None   # what is not admitted cannot match


# ------------------------------------------------------------ random patterns, strings drawn from them

_WORDS = ['go', 'to', 'the', 'shed', 'never', 'avoid', 'a', 'ab', ' ', 'x']


def _pattern_and_text(draw: st.DrawFn, depth: int = 0) -> tuple[str, str]:
    """A random pattern and one string it matches, built together."""
    kind = draw(st.sampled_from(['lit', 'lit', 'seq', 'alt', 'opt', 'plus', 'class', 'look', 'nlook']
                                if depth < 3 else ['lit', 'class']))
    if kind == 'lit':
        w = draw(st.sampled_from(_WORDS))
        return re.escape(w), w
    if kind == 'class':
        ch = draw(st.sampled_from('abx'))
        return '[abx]', ch
    if kind == 'seq':
        parts = [_pattern_and_text(draw, depth + 1) for _ in range(draw(st.integers(2, 4)))]
        return ''.join(p for p, _ in parts), ''.join(t for _, t in parts)
    if kind == 'alt':
        parts = [_pattern_and_text(draw, depth + 1) for _ in range(draw(st.integers(2, 3)))]
        pick = draw(st.integers(0, len(parts) - 1))
        return '(?:' + '|'.join(p for p, _ in parts) + ')', parts[pick][1]
    p, t = _pattern_and_text(draw, depth + 1)
    if kind == 'opt':
        return f'(?:{p})?', draw(st.sampled_from(['', t]))
    if kind == 'plus':
        return f'(?:{p}){{1,3}}', t * draw(st.integers(1, 3))
    if kind == 'look':
        return f'(?={p})', ''   # the lookahead's text follows in the text
    return f'(?!{p})', ''


@st.composite
def _drawn(draw: st.DrawFn) -> tuple[str, str]:
    p, t = _pattern_and_text(draw)
    prefix, suffix = draw(st.sampled_from(['', 'go ', 'zz'])), draw(st.sampled_from(['', ' shed', 'ab']))
    return p, prefix + t + suffix


@settings(max_examples=400, deadline=None)
@given(_drawn())
def test_a_pattern_that_matches_a_text_is_always_admitted(case: tuple[str, str]) -> None:
    pattern, text = case
    if re.search(pattern, text):
        assert admits(required_text(pattern), text), (pattern, text, required_text(pattern))


# ------------------------------------------------------------ every idiom rule on real sentences

def _instructions() -> list[str]:
    """Every instruction of the language case tests (the first string of each case tuple)."""
    out: list[str] = []
    for path in sorted(Path(__file__).parent.glob('test_language_*.py')):
        if path.stem == Path(__file__).stem:
            continue
        module = importlib.import_module(path.stem)
        for value in vars(module).values():
            if isinstance(value, list):
                out += [c[0] for c in value if isinstance(c, tuple) and c and isinstance(c[0], str)]
    return out


def test_no_idiom_rule_is_skipped_where_it_would_match(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[str] = []
    real = idioms._rewrite_sentence

    def record(words: list[str]) -> list[str]:
        seen.append(' '.join(words))
        return real(words)

    monkeypatch.setattr(idioms, '_rewrite_sentence', record)
    translator = OfflineTranslator()
    sentences = _instructions()
    assert len(sentences) > 500
    for s in sentences:
        try:
            translator.translate(s)
        except LtlInstructError:
            pass
    matched = 0
    for text in seen:
        for pattern, replacement, needs in idioms._COMPILED:   # all rules in turn, none skipped
            if pattern.search(text):
                matched += 1
                assert admits(needs, text), (pattern.pattern, text, needs)
                text = pattern.sub(replacement, text)
    assert matched > 500   # the rules were really exercised

"""Issue 21: random user input either succeeds or raises an LtlInstructError, in bounded time.

Formulas (grammar-ish, deep, long chains, random tokens), English with numbers and
unicode for the offline translator, and scene YAML documents. Inputs that broke it
once are kept as explicit cases at the end.
"""
import time

import pytest
import yaml
from hypothesis import HealthCheck, given, settings, strategies as st

from ltl_instruct.commands.formula import report
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.payloads import read_cancel, read_instruction
from ltl_instruct.core.world.scene import load_scene

FUZZ = settings(deadline=5000, max_examples=30, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
BOUND_S = 12.0   # compilation gives up after 5 s; printing and English come on top

ATOMS = st.sampled_from(['a', 'b', 'c', 'near[d]', 'pick[e]', 'release[e, f]', 'true', 'false',
                         'near[g::isabove(h)]'])
UNARY = st.sampled_from(['!', '~', 'F ', 'G ', 'X '])
BINARY = st.sampled_from([' & ', ' | ', ' -> ', ' <-> ', ' U ', ' R ', ' W '])
TOKENS = st.sampled_from(['(', ')', '[', ']', ',', '!', '&', '|', '->', '<->', 'U', 'F', 'near', 'a',
                          '::', 'isabove', ' ', 'X', 'true', '\u00e9', '0', 'G'])


@st.composite
def formulas(draw, depth=0):
    """Grammar-ish formula text: nested unary runs, binary chains, parentheses."""
    kind = draw(st.integers(0, 4 if depth < 6 else 0))
    if kind == 0:
        return draw(ATOMS)
    if kind == 1:
        return draw(UNARY) * draw(st.integers(1, 250)) + draw(formulas(depth + 1))
    if kind == 2:
        op = draw(BINARY)
        return op.join(draw(st.lists(formulas(depth + 1), min_size=2, max_size=4)))
    if kind == 3:
        n = draw(st.integers(1, 120))
        op = draw(BINARY)
        return op.join(f'near[a{i % draw(st.integers(1, 70))}]' for i in range(n))
    return '(' + draw(formulas(depth + 1)) + ')'


def _formula_ok(text):
    t = time.monotonic()
    try:
        report(text)
    except LtlInstructError:
        pass
    assert time.monotonic() - t < BOUND_S, text[:200]


@FUZZ
@given(formulas())
def test_fuzz_grammar_formulas(text):
    _formula_ok(text)


@FUZZ
@given(st.lists(TOKENS, max_size=300).map(' '.join))
def test_fuzz_random_tokens(text):
    _formula_ok(text)


@pytest.fixture(scope='module')
def translator():
    return make_translator('offline')


WORDS = st.sampled_from(['visit', 'go', 'to', 'the', 'kitchen', 'hall', 'times', 'time', 'twice', 'never',
                         'avoid', 'then', 'after', 'before', 'at', 'least', 'most', 'exactly', 'and', ',',
                         '.', 'once', 'sofa', 'behind', 'pick', 'up', 'cup', 'put', 'it', 'on', 'table',
                         '\u00fc\u00e9', '\U0001f600', 'x', 'room-3', 'floor'])
NUMBERS = st.one_of(st.integers(-10**7, 10**7).map(str),
                    st.floats(allow_nan=True, allow_infinity=True).map(str),
                    st.sampled_from(['1,000', '2.5', '-3', '\u22122', '0', '20', '21', '1e9', 'NaN']))


@FUZZ
@given(st.lists(st.one_of(WORDS, NUMBERS, st.text(max_size=8)), max_size=60).map(' '.join))
def test_fuzz_english(translator, text):
    t = time.monotonic()
    try:
        translator.translate(text)
    except LtlInstructError:
        pass
    assert time.monotonic() - t < BOUND_S


@settings(deadline=5000, max_examples=10, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(st.sampled_from(['visit the kitchen', 'go to the hall, ', 'avoid the sofa ']),
       st.integers(100, 5000))
def test_fuzz_huge_english(translator, phrase, n):
    try:
        translator.translate(phrase * n)
    except LtlInstructError:
        pass


MESSAGES = st.sampled_from(['null', '42', '[]', 'true', '{}', '{"id": 3}', '"x"', '[[[[', '{"schema": null}'])


@FUZZ
@given(st.one_of(st.text(max_size=200), MESSAGES))
def test_fuzz_instruction_messages(text):
    try:
        read_instruction(text, 'id-1')
    except LtlInstructError:
        pass


@FUZZ
@given(st.one_of(st.text(max_size=300), MESSAGES))
def test_fuzz_cancel_messages(text):
    try:
        iid = read_cancel(text)
    except LtlInstructError:
        return
    assert isinstance(iid, str) and 0 < len(iid) <= 200 and iid == iid.strip()


NUMBER = st.one_of(st.integers(-10**30, 10**30), st.floats(allow_nan=True, allow_infinity=True),
                   st.booleans(), st.none(), st.text(max_size=5))
VEC = st.one_of(st.lists(NUMBER, max_size=4), NUMBER)
SCENE = st.fixed_dictionaries({}, optional={
    'name': st.one_of(st.text(max_size=10), st.integers()),
    'bounds': st.one_of(st.fixed_dictionaries({'min': VEC, 'max': VEC}), NUMBER),
    'robot': st.one_of(st.fixed_dictionaries({}, optional={
        'kind': st.sampled_from(['ground', 'drone', 'boat', 3]), 'start': VEC, 'radius': NUMBER}), NUMBER),
    'obstacles': st.one_of(st.lists(st.fixed_dictionaries({'center': VEC, 'size': VEC}), max_size=3), NUMBER),
    'objects': st.one_of(st.lists(st.fixed_dictionaries({'label': st.one_of(st.text(max_size=8), NUMBER),
                                                         'center': VEC},
                                                        optional={'on': NUMBER, 'passable': NUMBER,
                                                                  'size': VEC}), max_size=3), NUMBER),
    'altitude': st.one_of(st.fixed_dictionaries({'min': NUMBER, 'max': NUMBER}), NUMBER),
    'extra': NUMBER,
})


@FUZZ
@given(SCENE)
def test_fuzz_scene_documents(tmp_path_factory, doc):
    p = tmp_path_factory.mktemp('scene') / 's.yaml'
    p.write_text(yaml.safe_dump(doc, allow_unicode=True))
    try:
        load_scene(p)
    except LtlInstructError:
        pass


@FUZZ
@given(st.binary(max_size=300))
def test_fuzz_scene_bytes(tmp_path_factory, data):
    p = tmp_path_factory.mktemp('scene') / 's.yaml'
    p.write_bytes(b'bounds: {min: [0, 0, 0], max: [20, 15, 3]}\n' + data)
    try:
        load_scene(p)
    except LtlInstructError:
        pass


# --------------------------------------------------------------------------- inputs that broke it

BROKE_FORMULAS = [
    '!' * 199 + 'a',                                                     # RecursionError in the printer
    'F' * 199 + ' a',
    ' <-> '.join(f'a{i % 60}' for i in range(199)),                      # RecursionError in to_nnf
    'F (' + ' <-> '.join(f'near[a{i}]' for i in range(14)) + ')',       # ran past 30 s
    'F (' + ' <-> '.join(f'near[a{i}]' for i in range(20)) + ')',       # 1 GB
    ' U '.join(f'a{i}' for i in range(20)),                              # ran for minutes
    ('!' * 150 + '(') * 4 + 'a' + ')' * 4,                               # 600 unary operators on a path
    'near[' + 'a::isabove(' * 190 + 'b' + ')' * 190 + ']',              # RecursionError in Descriptor.__str__
]


@pytest.mark.parametrize('text', BROKE_FORMULAS)
def test_formulas_that_broke_it(text):
    _formula_ok(text)


@pytest.mark.parametrize('text', ['visit the kitchen 50 times', 'visit the kitchen 1000000 times',
                                  'visit the kitchen -3 times', 'visit the kitchen 2.5 times'])
def test_english_that_broke_it(translator, text):
    with pytest.raises(LtlInstructError):
        translator.translate(text)


@pytest.mark.parametrize('text', ['null', '42', '[]', 'true'])
def test_messages_that_broke_it(text):
    with pytest.raises(LtlInstructError):
        read_instruction(text, 'id-1')


@pytest.mark.parametrize('data', [b'name: caf\xe9\n', b'obstacles: 7\n',
                                  b'robot: {radius: 1' + b'0' * 400 + b'}\n'])
def test_scenes_that_broke_it(tmp_path, data):
    p = tmp_path / 's.yaml'
    p.write_bytes(b'bounds: {min: [0, 0, 0], max: [20, 15, 3]}\n' + data)
    with pytest.raises(LtlInstructError):
        load_scene(p)

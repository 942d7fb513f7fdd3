"""Issue 21: automaton construction is bounded in states, guard terms and time."""
import time

import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.errors import ErrorCode, LimitExceededError, LtlInstructError
from ltl_instruct.core.spec import parse_formula


def _chain(op, n, fmt='near[a{}]'):
    return f' {op} '.join(fmt.format(i) for i in range(n))


@pytest.mark.parametrize('text', [
    _chain('U', 20, 'a{}'),              # ran for minutes on main
    _chain('U', 199, 'a{}').replace('a199', 'a0'),
    _chain('R', 60, 'a{}'),
    '!' * 199 + '(' + ' U '.join(f'a{i % 60}' for i in range(195)) + ')',
    ''.join(f'!(a{i} & ' for i in range(60)) + 'b' + ')' * 60,
])
def test_explosive_formulas_fail_fast_with_a_typed_error(text):
    t = time.monotonic()
    try:
        compile_automaton(parse_formula(text), time_limit_s=2.0)
    except LtlInstructError as e:
        assert e.code in (ErrorCode.LIMIT_EXCEEDED, ErrorCode.TIMEOUT)
    assert time.monotonic() - t < 6.0


def test_cli_iff_chain_compiles_with_linear_guards(capsys):
    # 2^13 cubes as a sum of products; guards are BDDs, written as nested <-> (issue 22)
    assert main(['formula', f'F ({_chain("<->", 14)})']) == 0
    out = capsys.readouterr().out
    assert 'automaton:   2 states' in out
    assert '0 -> 1: near[a0] <-> near[a1] <-> near[a2]' in out


def test_deadline_gives_timeout():
    with pytest.raises(LimitExceededError) as e:
        compile_automaton(_chain('U', 20, 'a{}'), time_limit_s=0.2)
    assert e.value.code == ErrorCode.TIMEOUT
    assert 'longer than 0.2 s' in e.value.message


def test_edge_bound_gives_limit_exceeded():
    with pytest.raises(LimitExceededError) as e:
        compile_automaton('F a & F b & F c & F d & F e', max_edges=5)
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED
    assert e.value.details['limit'] == 'max_edges'


def test_node_bound_gives_limit_exceeded():
    f = parse_formula(' & '.join(f'F (a{i} <-> b{i})' for i in range(12)))
    with pytest.raises(LimitExceededError) as e:
        compile_automaton(f, max_nodes=200)
    assert e.value.details['limit'] == 'max_nodes'


def test_ordinary_tasks_still_compile():
    aut = compile_automaton('F (near[a] & F (near[b] & F near[c])) & G !near[d]')
    assert aut.is_satisfiable
    aut = compile_automaton(f'F ({_chain("<->", 8)})')
    assert aut.is_satisfiable

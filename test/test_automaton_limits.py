"""Issue 21: automaton construction is bounded in states, guard terms and time."""
import time

import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.progression import WorkBudget, canonical_state
from ltl_instruct.core.errors import ErrorCode, LimitExceededError, LtlInstructError
from ltl_instruct.core.spec import parse_formula


def _chain(op, n, fmt='near[a{}]'):
    return f' {op} '.join(fmt.format(i) for i in range(n))


@pytest.mark.parametrize('text', [
    f'F ({_chain("<->", 14)})',          # ran past 30 s on main
    f'F ({_chain("<->", 20)})',          # took 1 GB on main
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


def test_cli_iff_chain_exits_2_quickly(capsys):
    t = time.monotonic()
    assert main(['formula', f'F ({_chain("<->", 14)})']) == 2
    assert time.monotonic() - t < 8.0
    assert 'error [LIMIT_EXCEEDED]' in capsys.readouterr().err


def test_deadline_gives_timeout():
    with pytest.raises(LimitExceededError) as e:
        compile_automaton(_chain('U', 20, 'a{}'), time_limit_s=0.2)
    assert e.value.code == ErrorCode.TIMEOUT
    assert 'longer than 0.2 s' in e.value.message


def test_cube_bound_gives_limit_exceeded():
    with pytest.raises(LimitExceededError) as e:
        compile_automaton('F a & F b & F c & F d & F e', max_cubes=5)
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED
    assert e.value.details['limit'] == 'max_cubes'


def test_state_cube_bound():
    f = parse_formula(' & '.join(f'(a{i} | b{i})' for i in range(12)))
    with pytest.raises(LimitExceededError) as e:
        canonical_state(f, WorkBudget(time_limit_s=None, max_state_cubes=512))
    assert e.value.details['limit'] == 'max_state_cubes'


def test_ordinary_tasks_still_compile():
    aut = compile_automaton('F (near[a] & F (near[b] & F near[c])) & G !near[d]')
    assert aut.is_satisfiable
    aut = compile_automaton(f'F ({_chain("<->", 8)})')
    assert aut.is_satisfiable

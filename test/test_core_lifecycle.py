"""Issues 19 and 21: the instruction lifecycle records, without ROS."""
from ltl_instruct.core.lifecycle import (
    EXECUTION, PLANNING, InstructionLedger, StatusMemory, plain_instruction_id,
)


def _status(iid, status, terminal=False, phase=PLANNING, **fields):
    return dict(id=iid, status=status, terminal=terminal, phase=phase, **fields)


def test_plain_ids_are_the_same_for_the_same_sample_only():
    a = plain_instruction_id(1_700_000_000_000_000_000, 3, 'go to the hall')
    assert a == plain_instruction_id(1_700_000_000_000_000_000, 3, 'go to the hall')
    assert a.startswith('i-') and len(a) == 18
    assert a != plain_instruction_id(1_700_000_000_000_000_000, 4, 'go to the hall')
    assert a != plain_instruction_id(1_700_000_000_000_000_001, 3, 'go to the hall')
    assert plain_instruction_id(None, 3, 'x') is None and plain_instruction_id(5, None, 'x') is None


def test_status_memory_ends_each_phase_once():
    m = StatusMemory()
    assert m.admit('a', _status('a', 'received'))
    assert m.admit('a', _status('a', 'planned', True))
    assert m.ended('a') == 'planned' and m.ended('a', EXECUTION) is None
    assert not m.admit('a', _status('a', 'failed', True))          # planning has ended
    assert m.admit('a', _status('a', 'progressing', phase=EXECUTION, automaton_state=1))
    assert m.admit('a', _status('a', 'superseded', True, EXECUTION, superseded_by='b'))
    assert not m.admit('a', _status('a', 'satisfied', True, EXECUTION))
    assert [s['status'] for s in m.repeat('a')] == ['superseded']
    assert all(s['repeat'] for s in m.repeat('a'))
    assert m.admit('x', _status('x', 'input_rejected', phase='input')) and not m.knows('x')


def test_status_memory_is_bounded():
    m = StatusMemory(limit=3)
    for i in range(5):
        m.admit(str(i), _status(str(i), 'failed', True))
    assert not m.knows('0') and m.knows('4')


def test_ledger_takes_an_instruction_once_and_follows_its_phases():
    led = InstructionLedger()
    assert led.take('a') and not led.take('a')            # the second copy is a repeat
    led.sent('a', {'id': 'a', 'formula': 'F near[x]'})
    assert led.in_flight() == [{'id': 'a', 'formula': 'F near[x]'}]
    led.note_status(_status('a', 'received'))
    led.note_status(_status('a', 'planned', True))
    led.note_status(_status('a', 'progressing', phase=EXECUTION, automaton_state=2))
    assert led.in_flight() == [{'id': 'a', 'formula': 'F near[x]', 'resume': {'automaton_state': 2}}]
    led.note_status(_status('a', 'superseded', True, EXECUTION))
    assert led.ended('a') and led.in_flight() == []
    led.note_status(_status('a', 'replanned', phase=EXECUTION))   # late: the end stands
    assert led.ended('a')


def test_a_restarted_translator_skips_what_ended_and_takes_the_rest():
    led = InstructionLedger()
    # the latched statuses come first: 'a' failed, 'b' is executing, 'c' was only received
    led.note_status(_status('a', 'failed', True))
    led.note_status(_status('b', 'planned', True))
    led.note_status(_status('c', 'received'))
    assert not led.take('a')
    assert led.take('b') and led.take('c') and led.take('d')
    for iid in 'bcd':
        led.sent(iid, {'id': iid})
    assert led.in_flight() == [{'id': 'b', 'resume': {'automaton_state': None}}, {'id': 'c'}, {'id': 'd'}]


def test_a_cancel_heard_before_the_instruction_stops_its_translation():
    led = InstructionLedger()
    led.note_status(_status('a', 'cancelled', True))
    assert not led.take('a') and led.ended('a')


def test_ledger_forgets_ended_instructions_first():
    led = InstructionLedger(limit=3)
    led.take('running')
    led.sent('running', {'id': 'running'})
    for i in range(4):
        led.take(str(i))
        led.note_status(_status(str(i), 'failed', True))
    assert led.in_flight() == [{'id': 'running'}]


def test_the_journal_brings_the_memory_back_after_a_restart(tmp_path):
    journal = tmp_path / 'task_progression.jsonl'
    m = StatusMemory(journal=journal)
    m.admit('a', _status('a', 'received', instruction='go to the hall'))
    m.admit('a', _status('a', 'failed', True, error={'code': 'TIMEOUT', 'message': 'late'}))
    m.admit('b', _status('b', 'planned', True, verification={'big': [0] * 100}))
    m.admit('b', _status('b', 'progressing', phase=EXECUTION, automaton_state=2))
    with open(journal, 'a') as f:
        f.write('{"id": "c", "status": "pla')          # the line a kill cut short
    again = StatusMemory(journal=journal)
    assert again.ended('a') == 'failed' and again.repeat('a')[-1]['error']['code'] == 'TIMEOUT'
    assert again.executing('b') == m.executing('b') and again.executing('b')['automaton_state'] == 2
    assert again.executing('a') is None and not again.knows('c')
    assert 'verification' not in again.repeat('b')[0]                  # the plan is not kept
    assert not again.admit('a', _status('a', 'planned', True))
    assert again.admit('b', _status('b', 'superseded', True, EXECUTION)) and again.executing('b') is None


def test_the_journal_is_compacted_to_what_memory_keeps(tmp_path):
    journal = tmp_path / 'j.jsonl'
    m = StatusMemory(limit=4, journal=journal)
    for i in range(30):
        m.admit(str(i), _status(str(i), 'received'))
        m.admit(str(i), _status(str(i), 'failed', True))
    assert len(journal.read_text().splitlines()) <= 2 * 4 + 2
    again = StatusMemory(limit=4, journal=journal)
    assert again.ended('29') == 'failed' and not again.knows('0')

"""Issue 21: instruction messages are read in the core (no ROS); non-text JSON is invalid input."""
import pytest

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LimitExceededError
from ltl_instruct.core.payloads import parse_json_payload, read_cancel, read_instruction, salvage_id


@pytest.mark.parametrize('text', ['null', '42', '[]', 'true', 'false', '-3.5', '1e999', 'NaN',
                                  ' null ', '[1, 2]', '["go to the hall"]', 'Infinity'])
def test_non_text_json_is_invalid_input(text):
    # 'null' became the task "F near[null]" on main
    with pytest.raises(InvalidInputError) as e:
        read_instruction(text, 'id-1')
    assert e.value.code == ErrorCode.INVALID_INPUT
    assert 'JSON value' in e.value.message


@pytest.mark.parametrize('text', ['go to the hall', '[kitchen] then the hall', '3rd floor, please',
                                  'true north is where the door is', '2 times to the hall'])
def test_english_text_is_read_as_it_is(text):
    assert read_instruction(text, 'id-1') == ('id-1', text, None)


def test_json_string_is_its_text():
    assert read_instruction('"go to the hall"', 'id-1') == ('id-1', 'go to the hall', None)
    with pytest.raises(InvalidInputError):
        read_instruction('"  "', 'id-1')


def test_json_object_payload():
    text = '{"schema": "ltl_instruct/instruction", "version": 1, "id": "a7", "text": "go to the hall"}'
    assert read_instruction(text, 'id-1') == ('a7', 'go to the hall', None)
    text = '{"schema": "ltl_instruct/instruction", "version": 1, "id": "a7", "text": null}'
    with pytest.raises(InvalidInputError) as e:
        read_instruction(text, 'id-1')
    assert e.value.details['id'] == 'a7'


@pytest.mark.parametrize('value', [None, 42, b'go'])
def test_non_string_message_is_invalid(value):
    with pytest.raises(InvalidInputError):
        read_instruction(value, 'id-1')


def test_limits_and_empty():
    with pytest.raises(LimitExceededError):
        read_instruction('x' * 2001, 'id-1')
    with pytest.raises(InvalidInputError):
        read_instruction('   ', 'id-1')


def test_payload_helpers():
    with pytest.raises(InvalidInputError):
        parse_json_payload('null')
    assert salvage_id('{"id": "q1", "schema": 3') == 'q1'


def test_json_object_may_leave_out_schema_version_and_id():
    # issue 19: {"id": ..., "text": ...} is an instruction with its own id
    text = '{"id": "a7", "text": "go to the hall"}'
    assert read_instruction(text, 'id-1') == ('a7', 'go to the hall', None)
    assert read_instruction('{"formula": "F near[hall]"}', 'id-1') == ('id-1', '', 'F near[hall]')
    for bad in ('{"schema": "other", "id": "a7", "text": "go"}', '{"version": 2, "id": "a7", "text": "go"}',
                '{"id": 7, "text": "go"}', '{"id": "", "text": "go"}'):
        with pytest.raises(InvalidInputError):
            read_instruction(bad, 'id-1')


@pytest.mark.parametrize('text, iid', [('a7', 'a7'), ('  client-3  ', 'client-3'), ('{"id": "a7"}', 'a7'),
                                       ('"a7"', 'a7'), ('{"schema": "x", "id": "q"}', 'q')])
def test_cancel_names_an_id(text, iid):
    assert read_cancel(text) == iid


@pytest.mark.parametrize('text', ['', '   ', 'null', '42', '[1]', '{"id": 5}', '{}', '{"id": ""}',
                                  '{"id": "a', 'x' * 201, '"', None, b'a7'])
def test_garbage_cancel_is_invalid_input(text):
    with pytest.raises(InvalidInputError) as e:
        read_cancel(text)
    assert e.value.code == ErrorCode.INVALID_INPUT

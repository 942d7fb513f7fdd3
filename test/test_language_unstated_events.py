"""Events and the clock, which no task formula states ("until I call you", "for ten minutes")."""
from __future__ import annotations

import pytest

from ltl_instruct.core.language.deixis import unstated
from ltl_instruct.core.spec import parse_formula
from translation_cases import T


@pytest.mark.parametrize('instruction, why, kind', [
    ('Walk to the door and wait there until I call you', 'until i call', 'cannot tell when'),
    ('stay in the living room until the dog leaves the kitchen', 'until the dog leaves', 'cannot tell when'),
    ('wait in the hall till we are done', 'until we are done', 'cannot tell when'),
    ('go into the garage once the door opens', 'once the door opens', 'cannot observe'),
    ('stay by the oven until the timer goes off', 'until the timer goes off', 'cannot observe'),
    ('wait at the lab for 5 minutes', 'for 5 minutes', 'no clock'),
    ('hover over the tower for a while, then land', 'for a while', 'no clock'),
    ('go to the kitchen at 5 pm', 'at 5 pm', 'no clock'),
])
def test_a_condition_no_formula_states_gets_a_note(instruction: str, why: str, kind: str) -> None:
    notes = unstated(instruction, parse_formula('F near[door]'))
    assert len(notes) == 1 and notes[0].startswith(f'"{why}": ') and kind in notes[0], notes


@pytest.mark.parametrize('instruction', [
    'stay at the desk until you see the printer',          # a place: the stay-until task
    'avoid the lab until you reach the kitchen',
    'once I am in the kitchen, bring me a cup',              # the person says where they are
    'go to the lab 3 times',
    'visit the shed at least twice',
    'go to the kitchen after the hall',
    'wait at the door until the mail room has been visited',
    'stay at the door until I tell you otherwise',           # the whole run (idioms)
    'patrol the hall until further notice',
])
def test_a_condition_on_places_gets_no_note(instruction: str) -> None:
    assert unstated(instruction, parse_formula('F near[door]')) == []


def test_a_negation_before_an_event_leaves_it_standing() -> None:
    notes = unstated('do not leave the hall until I call you', parse_formula('F near[hall]'))
    assert len(notes) == 1 and notes[0].startswith('"until i call": ')


def test_the_default_translator_flags_the_reading_and_says_why() -> None:
    got = T.translate('go to the door and wait there until I call you')
    assert got.extra['flagged'] is True
    assert any('"until i call"' in u for u in got.extra['unread'])

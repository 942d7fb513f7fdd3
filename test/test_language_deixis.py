"""Places named by where the person or the robot is ("bring me", "come back"): the reading is flagged."""
from __future__ import annotations

import pytest

from ltl_instruct.core.language.deixis import table, unstated
from ltl_instruct.core.spec import parse_formula
from translation_cases import T

PICKED = 'F (near[cup] & F pick[cup])'
DELIVERED = 'F (near[cup] & F (pick[cup] & F (near[sofa] & F release[cup, sofa])))'


@pytest.mark.parametrize('instruction, formula, why', [
    ('Bring me the cup.', PICKED, 'bring me'),
    ('could you fetch us the cup please', PICKED, 'fetch us'),
    ('bring the cup to me', PICKED, 'bring the cup to me'),
    ('take the cup back to me when you are done', PICKED, 'take the cup back to me'),
    ('go to the pantry and bring back the cup', PICKED, 'bring back'),
    ('fetch the cup back', PICKED, 'fetch the cup back'),
    ('check on the dog, then come back to me', 'F near[dog]', 'come back to me'),
    ('go to the shed and come back', 'F near[shed]', 'come back'),
    ('Go to the shed then return.', 'F near[shed]', 'return'),
    ('fly to the mast and head straight back', 'F near[mast]', 'head straight back'),
    ('visit the shed and then go to where you started', 'F near[shed]', 'where you started'),
    ('follow me', 'F near[shed]', 'follow me'),
    ('bring the cup to the sink and then go charge', DELIVERED, 'go charge'),
])
def test_a_place_named_by_where_someone_is_gets_a_note(instruction: str, formula: str, why: str) -> None:
    notes = unstated(instruction, parse_formula(formula))
    assert len(notes) == 1 and notes[0].startswith(f'"{why}": '), notes


@pytest.mark.parametrize('instruction, formula', [
    ('Bring me the cup. I\'m on the sofa.', DELIVERED),      # the person says where they are
    ('bring the cup to me, I am sitting on the sofa', DELIVERED),
    ('Pick up the cup.', PICKED),                             # nothing is handed over
    ('bring me over to the printer', 'F near[printer]'),     # the person is taken along
    ('take me to the kitchen', 'F near[kitchen]'),
    ('Go to the mailbox, then come back to the porch.', 'F (near[mailbox] & F near[porch])'),
    ('Walk to the garage, then come back here to the kitchen.', 'F (near[garage] & F near[kitchen])'),
    ('visit a then leave a and never go back', 'F near[a] & G !near[a]'),
    ("go to the shed, don't come back", 'F near[shed]'),
    ('return the cup to the sink', 'F (near[cup] & F (pick[cup] & F (near[sink] & F release[cup, sink])))'),
    ('go to the kitchen for me', 'F near[kitchen]'),
    ('bring the cup back to the sofa', DELIVERED),
    ('go charge at the dock', 'F near[dock]'),
    ('go to the shed and then go recharge', 'F (near[shed] & F near[charging_station])'),
])
def test_a_place_named_by_name_gets_no_note(instruction: str, formula: str) -> None:
    assert unstated(instruction, parse_formula(formula)) == []


def test_the_table_says_whose_place_each_phrase_names() -> None:
    assert {entry.whose for entry in table()} == {'speaker', 'start', 'robot', 'event', 'clock'}
    assert all('{phrase}' in entry.note for entry in table())


@pytest.mark.parametrize('instruction', ['Bring me the cup.', 'go to the shed and come back'])
def test_the_default_translator_flags_the_reading_and_says_why(instruction: str) -> None:
    got = T.translate(instruction)
    assert got.extra['flagged'] is True
    assert any('no place on the map' in u for u in got.extra['unread'])


def test_the_default_translator_keeps_a_delivery_the_person_placed_unflagged() -> None:
    got = T.translate("Bring me the charger. I'm on the sofa.")
    assert 'release[charger, sofa]' in str(got.formula)
    assert not any('no place on the map' in u for u in got.extra.get('unread', ()))

"""Readings found on blind set G4 (second round): each was misread while the set was still blind.

A restaurant and hotel staff's requests: numbered places said as the people at them, remarks after the
request, corrections and list positions. Each case is a blind item with its writer's formula, or a
sentence of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included).
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import T, check_translation

BLIND_ROUND_G4B = [
    # "A before B, and B before C" with the verb left out: read as with "go to" (the verb said again)
    ('lobby lounge befor the terrace, and the terrace before the bar. got it?',
     'F near[terrace] & (!near[terrace] U near[lobby_lounge]) & F near[bar] & (!near[bar] U near[terrace])'),
    ('the garage before the shed, and the shed before the barn',
     'F near[shed] & (!near[shed] U near[garage]) & F near[barn] & (!near[barn] U near[shed])'),
    # a numbered place said as the people at it ("table 4 wants ketchup"): no goal, and "them" / "there" is it
    ('Table 4 wants ketchup, take the ketchup bottle over to them.',
     'F (near[ketchup_bottle] & F (pick[ketchup_bottle] & F (near[table_4] & F release[ketchup_bottle, '
     'table_4])))'),
    ('Table 17 has a toddler - bring them a high chair or a booster seat.',
     'F (near[high_chair] & F (pick[high_chair] & F (near[table_17] & F release[high_chair, table_17]))) '
     '| F (near[booster_seat] & F (pick[booster_seat] & F (near[table_17] & F '
     'release[booster_seat, table_17])))'),
    ('room 5 is flooded, avoid it', 'G !near[room_5]'),
    ('table 9 asked for the manager. go there', 'F near[table_9]'),
    # "bring them X": the thing, then to whom
    ('go to table 5 and take them the menu',
     'F (near[table_5] & F (near[menu] & F (pick[menu] & F (near[table_5] & F release[menu, table_5]))))'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_G4B)
def test_readings_found_on_blind_set_g4_second_round(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


REFUSED_G4B = [
    # "them" as the destination with no one named before: never the thing carried itself
    'bring them a cup',
    'The guests at table 4 want ketchup, take the ketchup bottle to them.',
]


@pytest.mark.parametrize('instruction', REFUSED_G4B)
def test_refused_on_blind_set_g4_second_round(instruction: str) -> None:
    with pytest.raises(TranslationError):
        T.translate(instruction)

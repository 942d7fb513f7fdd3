"""Readings found on blind set G4 (second round): each was misread while the set was still blind.

A restaurant and hotel staff's requests: numbered places said as the people at them, remarks after the
request, corrections and list positions. Each case is a blind item with its writer's formula, or a
sentence of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included).
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

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
    # "forget / ignore / scratch that" then a command: the whole step is replaced, not one of its places;
    # then a statement ("Luca's sorting it"): the step is dropped
    ("Bring a high chair to table 8 - wait, no, ignore that, Luca's already sorting it. Go to the host stand "
     "instead, the Petersons just walked in with their whole family and there's nobody there to greet them.",
     'F near[host_stand]'),
    ('bring a cup to the sink. Actually, forget that, go to the host stand instead.', 'F near[host_stand]'),
    ('avoid the kitchen. forget that, go to the garage instead.', 'F near[garage]'),
    ('bring a cup to the sink. scratch that, head to the garage.', 'F near[garage]'),
    ('go to the kitchen, then bring the cup to the sink. forget that, go to the garage',
     'F (near[kitchen] & F near[garage])'),
    # a correction by a thing replaces the thing carried, not a numbered place; a place or a number the place
    ('Bring the dessert menus to table 4, no wait, the wine list.',
     'F (near[wine_list] & F (pick[wine_list] & F (near[table_4] & F release[wine_list, table_4])))'),
    ('bring the cup to room 5, no, the kitchen',
     'F (near[cup] & F (pick[cup] & F (near[kitchen] & F release[cup, kitchen])))'),
    ('bring the cup to room 5, no, room 6',
     'F (near[cup] & F (pick[cup] & F (near[room_6] & F release[cup, room_6])))'),
    # a remark after the request on what somebody else wants or is like, or who arrives when: left out
    ('Head to the office, and stop at the bar no more than once, Marco gets chatty.',
     'F near[office] & (!near[bar] W (near[bar] & (near[bar] W G !near[bar])))'),
    ('Put the reserved sign on table 10 please, VIPs in at eight.',
     'F (near[reserved_sign] & F (pick[reserved_sign] & F (near[table_10] & F release[reserved_sign, '
     'table_10])))'),
    ('Bring the bill folder and the card machine to table 23, they want to settle up.',
     'F (near[bill_folder] & F (pick[bill_folder] & F (near[table_23] & F release[bill_folder, table_23]))) '
     '& F (near[card_machine] & F (pick[card_machine] & F (near[table_23] & F '
     'release[card_machine, table_23])))'),
    ('Go to the stool in front of the bar and to the right of the till, the gentleman there wants another.',
     'F near[stool::isinfrontof(bar)::isrightof(till)]'),
    ('go to the lounge, the band gets nervous', 'F near[lounge]'),
    # what pictures are for, the service, "until I call you": no place, left out
    ('Hover above the pool deck for the wedding photos.', 'F near[pool_deck]'),
    ('Circle the rooftop sign three times, marketing wants footage for the website.',
     'F (near[rooftop_sign] & F (!near[rooftop_sign] & F (near[rooftop_sign] & F (!near[rooftop_sign] & F '
     'near[rooftop_sign]))))'),
    ('I want you at the pass exactly twice this service, no more, no less.',
     '!near[pass] U (near[pass] & (near[pass] U (!near[pass] & (!near[pass] U (near[pass] & (near[pass] W G '
     '!near[pass]))))))'),
    ('Could you make your way to the room service lift and wait there until I call you?',
     'F near[room_service_lift]'),
    # a list after "at" in a statement, then its position
    ("We're short at the bar, the terrace and the lobby lounge. Go to the second one.", 'F near[terrace]'),
    ('we are busy at the patio, the bar and the garden. go to the last one.', 'F near[garden]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_G4B)
def test_readings_found_on_blind_set_g4_second_round(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


REFUSED_G4B = [
    # "them" as the destination with no one named before: never the thing carried itself
    'bring them a cup',
    'The guests at table 4 want ketchup, take the ketchup bottle to them.',
    # a remark that names a place after "wants", or a command after "want to", is no remark
    'go to the bar, chef wants the kitchen',
    'go to the bar, they want to go to the garden',
]


@pytest.mark.parametrize('instruction', REFUSED_G4B)
def test_refused_on_blind_set_g4_second_round(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

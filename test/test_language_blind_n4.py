"""Readings found on the blind set N4 (an airport's service robot and apron drone).

Every case is an instruction of the blind set N4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

BLIND_ROUND_N4 = [
    # "once you've been to X, stay clear of Y" said as a command makes X a goal, as "after going to X"
    # does (it was a rule that held only if X was ever reached); "you cannot go to Y" stays a rule
    ("Once you've been to the securty office, stay clear of security lanes 5 and 6 for the rest of the "
     'shift.',
     'F (near[security_office] & G !near[security_lane_5] & G !near[security_lane_6])'),
    ("Once you've been to the office, never go to the kitchen.",
     'F (near[office] & G !near[kitchen])'),
    ('Once you have been to the garden you cannot go to the carpet.',
     'G (near[garden] -> X G !near[carpet])'),
    # "never mind that ordering": the order dropped; what follows is read on unless it says the kept
    # step again (an avoidance after it was silently lost)
    ('Head to the chapel only after the lost & found. Hmm, never mind that ordering, just go to the chapel.',
     'F near[chapel]'),
    ('Go to the lab only after the kitchen. Never mind the order, and avoid the gym.',
     'F near[lab] & G !near[gym]'),
    # "A before B, and B before C" with names said with no article ("lane 1")
    ('Do security lane 2 before lane 1, and lane 1 before the exit lane.',
     'F near[security_lane_1] & (!near[security_lane_1] U near[security_lane_2]) & F near[exit_lane] & '
     '(!near[exit_lane] U near[security_lane_1])'),
    # a bare letter after "or" is one of the same kind ("check-in island A or B"); "the apron door" after
    # "the gate 7 apron door" is that one
    ('Go to check-in island A or B; if you pick B, avoid the oversize baggage drop.',
     'F near[check_in_island_a] | (F near[check_in_island_b] & G !near[oversize_baggage_drop])'),
    ('go to the gate 7 apron door, then out to the fule truck parking, then back to the apron door',
     'F (near[gate_7_apron_door] & F (near[fuel_truck_parking] & F near[gate_7_apron_door]))'),
    # "D or E... just D actually": one label of the choice kept, with its kind
    ('Go to check-in island D or E... just D actually, and stay off the baggage belt on your way there.',
     '!near[baggage_belt] U near[check_in_island_d]'),
    ('Go to check-in island D or E. Actually, just E.', 'F near[check_in_island_e]'),
    ('go to room 4 or 5, no wait, just 5', 'F near[room_5]'),
    # the machine addressed by its kind before a comma ("Service robot, report to ..."): no place
    ('Service robot, report to baggage carousel 3.', 'F near[baggage_carousel_3]'),
    ('Cleaning robot, please go to the kitchen.', 'F near[kitchen]'),
    ('Kitchen robot, then the hall.', 'F (near[kitchen_robot] & F near[hall])'),
    # a verb that names a numbered place after "go to" / a drone verb ("fly over stand 4")
    ('Survey stand 4 exactly once, then land at the hangar 2 pad.',
     '(!near[stand_4] U (near[stand_4] & (near[stand_4] W G !near[stand_4]))) & F (near[stand_4] & F '
     'near[hangar_2_pad])'),
    ('Fly over stand 4, then land at the pad.', 'F (near[stand_4] & F near[pad])'),
    # "until further notice", "per shift", "and wait there for the cleaning crew": how long or how
    # often, or whom it waits for, no place and no event
    ('Go stand at the duty-free entrance until further notice.', 'F near[duty_free_entrance]'),
    ('Check the gate 3 restroom twice per shift.',
     'F (near[gate_3_restroom] & F (!near[gate_3_restroom] & F near[gate_3_restroom]))'),
    ('Proceed to gate 14 and wait there for the cleaning crew.', 'F near[gate_14]'),
    ('Go to gate 14 and wait for the crew, then go to gate 2.', 'F (near[gate_14] & F near[gate_2])'),
    ('Go to gate 14 and wait for me at the door.', 'F (near[gate_14] & F near[door])'),
    # "at least twice each" after two things: each of them, in any order (it was one after the other)
    ("The escalators I'm worried about are number 1, number 4 and number 6. Check the first and the last "
     'one at least twice each.',
     'F (near[escalator_1] & F (!near[escalator_1] & F near[escalator_1])) & F (near[escalator_6] & F '
     '(!near[escalator_6] & F near[escalator_6]))'),
    ('Check the kitchen and the hall twice each, then go to the dock.',
     '(F (near[kitchen] & F (!near[kitchen] & F (near[kitchen] & F (near[hall] & F (!near[hall] & F '
     '(near[hall] & F near[dock]))))))) | (F (near[hall] & F (!near[hall] & F (near[hall] & F '
     '(near[kitchen] & F (!near[kitchen] & F (near[kitchen] & F near[dock])))))))'),
    # list positions: "the third hangar on that list" (the kind the list named, then where it was said);
    # a list that "needs inspection"; "number 1, number 4" in a list of a kind said with who said it
    ('Hangars 1, 2 and 3: fly over the third hangar on that list, then land at the helipad.',
     'F (near[hangar_3] & F near[helipad])'),
    ('Carousels 3, 5, 7 and 9 need inspection. Do the last two, in order.',
     'F (near[carousel_7] & F near[carousel_9])'),
    ('The kitchen, the hall and the dock need cleaning. Go to the last one.', 'F near[dock]'),
    ('The dock needs cleaning, go there.', 'F near[dock]'),
    # "visit Y before you go (anywhere) near it": "it" is the goal said before, not Y (it was Y, and
    # "anywhere" a place next to it, silently)
    ("Go check stand 9, but make sure you've been to the lav service truck before you go anywhere near it.",
     'F near[stand_9] & (!near[stand_9] U near[lav_service_truck])'),
    ('Go to the kitchen, but visit the truck before you go to it.',
     'F near[kitchen] & (!near[kitchen] U near[truck])'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_N4)
def test_readings_found_on_blind_set_n4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# An "it" that can only be the place of its own clause is refused, never read as "Y before Y".
REFUSED_N4 = [
    'Visit the truck before you go to it.',
]


@pytest.mark.parametrize('instruction', REFUSED_N4)
def test_refused_on_blind_set_n4(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

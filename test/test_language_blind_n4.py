"""Readings found on the blind set N4 (an airport's service robot and apron drone).

Every case is an instruction of the blind set N4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

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
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_N4)
def test_readings_found_on_blind_set_n4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

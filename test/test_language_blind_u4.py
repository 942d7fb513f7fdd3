"""Readings found on the blind set U4 (office staff typing quick chat requests to the office robot).

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The whole set stays outside
the repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

BLIND_ROUND_U4 = [
    # well-known office abbreviations are spelled out in names ("conf rm" was conf_room, "exec" exec_suite)
    ('kitchen then conf rm A. wait no, conf rm C',
     'F (near[kitchen] & F near[conference_room_c])'),
    ('if you end up going to the exec suite at all, check w/ the front desk first',
     # "exec" stays as said: A4's writer names it exec_suite, U4's executive_suite
     '!near[exec_suite] W near[front_desk]'),
    ('fly to the 4th fl terrace, stay clear of the glass atrium roof',
     'F near[fourth_floor_terrace] & G !near[glass_atrium_roof]'),
    ('take the package and leave it at either recep or the lobby',
     'F (near[package] & F (pick[package] & (F (near[reception] & F release[package, reception]) | '
     'F (near[lobby] & F release[package, lobby]))))'),
    # "+" and "&" between words are "and" ("kitchenette + copy room" was one place kitchenette_copy_room)
    ('kitchenette + copy room, avoid the stairwel and the freight elevator',
     'F near[kitchenette] & F near[copy_room] & G !near[stairwell] & G !near[freight_elevator]'),
    ('on the front desk: a laptop bag, an umbrella, a water bottle. take the first one to lost & found',
     'F (near[laptop_bag] & F (pick[laptop_bag] & F (near[lost_and_found] & F '
     'release[laptop_bag, lost_and_found])))'),
    # "w/e" is "whatever" (it was "with e")
    ('bring the stapler or the tape dispenser to reception, w/e you find first',
     'F (near[stapler] & F (pick[stapler] & F (near[reception] & F release[stapler, reception]))) | '
     'F (near[tape_dispenser] & F (pick[tape_dispenser] & F (near[reception] & '
     'F release[tape_dispenser, reception])))'),
    # a list with slashes, after a heading that says its order: the order is kept (the heading and its
    # "in this order" were left out, the goals unordered) and "IT" opening an item is the acronym
    # (the "it help desk" was left out as a description of the scene: silently lost)
    ('stops for today, in this order: mail room / supply closet / IT help desk',
     'F (near[mail_room] & F (near[supply_closet] & F near[it_help_desk]))'),
    ('in this order: the pantry, the lobby, the garage',
     'F (near[pantry] & F (near[lobby] & F near[garage]))'),
    ('visit these in the following order: the kitchen, the lobby, the garage',
     'F (near[kitchen] & F (near[lobby] & F near[garage]))'),
    # a bare place, then ", and DO NOT ...": the place is a goal, not the name of the robot addressed
    # (it was dropped silently)
    ("reception - and DO NOT go near the fish tank, it's being cleaned",
     'F near[reception] & G !near[fish_tank]'),
    ('lobby, and never go near the stairwell',
     'F near[lobby] & G !near[stairwell]'),
    # when an event is ("mtg starts at 10", "big all-hands at 3") asks for nothing (it was a goal)
    ('conf rm B, asap pls. mtg starts at 10',
     'F near[conference_room_b]'),
    ('go to the lobby, the meeting starts at 10',
     'F near[lobby]'),
    # "for the 2pm visitor", "for the new visitor": who the visit is for (refused)
    ("go wait by the main entrance for the 2pm visitor, she's signing the lease today",
     'F near[main_entrance]'),
    ('go to the lobby for the new visitor',
     'F near[lobby]'),
    # a task label before a colon ("restock:", "cleanup:") names the job, not a place (it was a goal)
    ('restock: take the coffee pods to the kitchenette, dont go into the kitchenette more than once',
     'F (near[coffee_pods] & F (pick[coffee_pods] & F (near[kitchenette] & '
     'F release[coffee_pods, kitchenette]))) & '
     '(!near[kitchenette] W (near[kitchenette] & (near[kitchenette] W G !near[kitchenette])))'),
    ('cleanup: take the cups to the sink',
     'F (near[cups] & F (pick[cups] & F (near[sink] & F release[cups, sink])))'),
    # the places where something is ("painters are in A, B and C") are a list positions point into
    # ("the first 2" was a place first_two, avoided: silently wrong)
    ('painters are in the east hallway, the lobby and the north stairwell today. keep away from the first 2. '
     'need you at the mail room',
     'F near[mail_room] & G !near[east_hallway] & G !near[lobby]'),
    ('the kids are in the den, the study and the attic. go to the last one',
     'F near[attic]'),
    # a bare letter after a correction marker relabels the name said last ("B" was a place b)
    ('go to conf rm A. sorry, B',
     'F near[conference_room_b]'),
    ('go to the kitchen then gate C, no wait, D',
     'F (near[kitchen] & F near[gate_d])'),
    # three labels or more listed with commas only name one kind each ("conf rms A, B, C": conference_rooms_a)
    ('conf rms A, B, C - go to the first one, stay out of the other two',
     'F near[conference_room_a] & G !near[conference_room_b] & G !near[conference_room_c]'),
    # a count in digits before a list of "ones" names their kind ("3 printers on this floor: the color one":
    # color_floor; "2 chairs in X, one by ..." was refused)
    ('3 printers on this floor: the color one, the black and white one, the big plotter. '
     'check the 1st one twice',
     'F (near[color_printer] & F (!near[color_printer] & F near[color_printer]))'),
    ('2 chairs in conf rm A, one by the window and one behind the door. go to the 2nd one',
     'F near[chair::isbehind(door)]'),
    # "behind that desk": the desk said before, with its description (it was left out as asking nothing:
    # the cabinet was dropped, silently); "need the 2023 invoices pulled" says why (refused)
    ('go to the desk by the window first, then to the filing cabinet behind that desk. '
     'need the 2023 invoices pulled',
     'F (near[desk::isnextto(window)] & F near[filing_cabinet::isbehind(desk::isnextto(window))])'),
    ('go to the shelf by the door, then to the bin next to that shelf',
     'F (near[shelf::isnextto(door)] & F near[bin::isnextto(shelf::isnextto(door))])'),
    ('go to the front desk. need these forms signed today',
     'F near[front_desk]'),
    # "for a min", "for a sec": chat spellings of a short while (refused)
    ('drone - hover by the 3rd fl skylight for a min',
     'F near[third_floor_skylight]'),
    ('when you get a sec, head to the supply closet',
     'F near[supply_closet]'),
    ('when you get a min, head to the supply closet',
     'F near[supply_closet]'),
    # "actually either X or Y is fine": the correction widens the goal to a choice (it was refused)
    ('go to the copier. actually either the copier or the printer is fine',
     'F near[copier] | F near[printer]'),
    ('go to the den. no, either the den or the hall is fine',
     'F near[den] | F near[hall]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_U4)
def test_readings_found_on_blind_set_u4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# Refused, never guessed: positions with no list to point into ("the first two" was a place first_two).
REFUSED_U4 = [
    'keep away from the first two. go to the lobby',
    'go to the lobby and avoid the last two',
]


@pytest.mark.parametrize('instruction', REFUSED_U4)
def test_refused_on_blind_set_u4(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

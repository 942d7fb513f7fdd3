"""Readings found on the blind sets D4 and F4: each was misread while its set was still blind.

D4 is a teenager's chat to a home robot (text speak, "bc", "idc", "jk"); F4 a factory worker who
is no native speaker ("the machine of welding", "maximum one time", "Ah no, I say it wrong").
Each case is an instruction of those sets with its writer's formula, or a sentence of our own
for the same construction; the translator must give a formula equivalent to it on automata
(names included). The whole sets stay outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

BLIND_ROUND_D4 = [
    # a reason said after the request with no comma, in chat spelling ("bc", "cuz"): left out, and
    # it ends the request's words ("put it on the porch bc ..." was left out whole)
    ('ok so go to the garage and grab the basketball and put it on the porch bc my friends r coming '
     'over, then meet me at the trampoline',
     'F (near[garage] & F (near[basketball] & F (pick[basketball] & F (near[porch] & F '
     '(release[basketball, porch] & F near[trampoline])))))'),
    ('go to the porch because my friends are coming over',
     'F near[porch]'),
    ('avoid the dog cuz he bites and go to the shed',
     'F near[shed] & G !near[dog]'),
    ('go to the garage n avoid the dog on the way there bc hes being weird today, once ur in the garage '
     'the dog is fine but stay away from the paint cans theyre open',
     '(!near[dog] U near[garage]) & F (near[garage] & G !near[paint_cans])'),
    # chat spellings of a subject and its verb ("uve been to", "theyre on")
    ('dont go into my sisters room until uve been to the laundry room',
     '!near[sisters_room] U near[laundry_room]'),
    ('go to the mailbox or the garage, either way stay away from the sprinklers theyre on',
     '(F near[mailbox] | F near[garage]) & G !near[sprinklers]'),
    # relations as learners say them: "at right of", "behind of"; the typo "beetwen"
    ('Go to the lathe in front of the window, then to the chair at right of the drill press.',
     'F (near[lathe::isinfrontof(window)] & F near[chair::isrightof(drill_press)])'),
    ('Go to the cabinet behind of the QA bench, but only after you go to the tool crib.',
     'F near[cabinet::isbehind(qa_bench)] & (!near[cabinet::isbehind(qa_bench)] U near[tool_crib])'),
    ('Hover over the tank that is beetwen the silo and the pump house.',
     'F near[tank::isbetween(silo, pump_house)]'),
    # counts: "maximum one time", "exactly two times, not more", "go two times to the X under the Y"
    ('Go in the paint booth maximum one time, the paint is still fresh.',
     '!near[paint_booth] W (near[paint_booth] & (near[paint_booth] W G !near[paint_booth]))'),
    ('You go to the CNC machine exactly two times, not more.',
     '!near[cnc_machine] U (near[cnc_machine] & (near[cnc_machine] U (!near[cnc_machine] & '
     '(!near[cnc_machine] U (near[cnc_machine] & (near[cnc_machine] W G !near[cnc_machine]))))))'),
    ('Go two times to the valve under the big tank.',
     'F (near[valve::isbelow(big_tank)] & F (!near[valve::isbelow(big_tank)] & F '
     'near[valve::isbelow(big_tank)]))'),
    # lists: said without commas after "my"; after "ok so"; a name that starts with a verb's word before
    # a colon ("swing set"); a list of things to bring, after a comma, is no reason ("..., my backpack and
    # my shoes to my bed")
    ('my hoodie my backpack and my shoes are all over the floor, bring the first two to my bed',
     'F (near[hoodie] & F (pick[hoodie] & F (near[bed] & F release[hoodie, bed]))) & F (near[backpack] & F '
     '(pick[backpack] & F (near[bed] & F release[backpack, bed])))'),
    ('bring my hoodie, my backpack and my shoes to my bed',
     'F (near[hoodie] & F (pick[hoodie] & F (near[bed] & F release[hoodie, bed]))) & F (near[backpack] & F '
     '(pick[backpack] & F (near[bed] & F release[backpack, bed]))) & F (near[shoes] & F (pick[shoes] & F '
     '(near[bed] & F release[shoes, bed])))'),
    ('ok so the fridge, the microwave, the toaster. go to the last one',
     'F near[toaster]'),
    ('okay, the sofa, the lamp, the rug. go to the second one',
     'F near[lamp]'),
    ('trampoline, pool, swing set: go to them backwords',
     'F (near[swing_set] & F (near[pool] & F near[trampoline]))'),
    # corrections: "X is fine just don't go near Y" with no comma keeps the new avoidance (it was
    # dropped with the old one); "jk" / "just kidding" retracts; "no the one on the right of it" with
    # the comma left out; "not behind, in front of the press"
    ('stay away from the cat. nvm the cat is fine just dont go near the fish tnak. go to the couch',
     'F near[couch] & G !near[fish_tank]'),
    ('stay away from the cat and the dog. actually the cat is fine but avoid the fish tank. go to the couch',
     'F near[couch] & G !near[dog] & G !near[fish_tank]'),
    ('ok go to the fridge then the pantry n avoid the dog. jk u dont have to avoid the dog',
     'F (near[fridge] & F near[pantry])'),
    ('go to the fridge. just kidding, go to the pantry',
     'F near[pantry]'),
    ('go to the lamp left of my bed. no the one on the rigth of it',
     'F near[lamp::isrightof(bed)]'),
    ('Go to the cart behind the press. Sorry, not behind, in front of the press.',
     'F near[cart::isinfrontof(press)]'),
    # corrections after "ah no" / "ehh no" (the second marker was skipped); "the saw is broken, instead of saw
    # go to the drill press"; "no, the opposite" (the order reversed, not a place "opposite"); "I say it
    # wrong: B before A" says the ordering again; "..., wash is ok" about the place replaced
    ('Go to the lathe two times, then the mill, then the saw. Ah no, the saw is broken, instead of saw go to '
     'the drill press.',
     'F (near[lathe] & F (!near[lathe] & F (near[lathe] & F (near[mill] & F near[drill_press]))))'),
    ('go to the mill, then the saw. no, the saw is broken, go to the drill press instead of the saw.',
     'F near[drill_press]'),
    ('Go to QA bench and after to the office... no, the opposite, first the office then QA bench.',
     'F (near[office] & F near[qa_bench])'),
    ('go to the office and then the desk. no, the opposite.',
     'F (near[desk] & F near[office])'),
    ('Visit the lathe before the milling machine. Ah no, I say it wrong: the milling machine before the '
     'lathe.',
     'F near[lathe] & (!near[lathe] U near[milling_machine])'),
    ('go to the shed after the barn. no, I said it wrong, the barn after the shed.',
     'F (near[shed] & F near[barn])'),
    ('go to the shed and avoid the wash station. ehh no, avoid the grinding station, wash is ok.',
     'F near[shed] & G !near[grinding_station]'),
    # "while you carry X to Y, avoid Z" said first: the delivery, Z avoided while carrying (it was a goal Y
    # with Z avoided throughout, and no delivery)
    ('While you carry the motor to the test bench, avoid the wash station. Ehh no, avoid the grinding '
     'station, wash is ok.',
     'F (near[motor] & F (pick[motor] & (!near[grinding_station] U (near[test_bench] & F release[motor, '
     'test_bench]))))'),
    ('while carrying the box to the hall, stay away from the dog',
     'F (near[box] & F (pick[box] & (!near[dog] U (near[hall] & F release[box, hall]))))'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_D4)
def test_readings_found_on_blind_sets_d4_and_f4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


@pytest.mark.parametrize('instruction', [
    'go to the porch because my friends never go there',   # a reason holding a rule: refused
])
def test_reasons_holding_a_rule_are_refused(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

"""Readings found on the blind sets D4 and F4 in a second round (after test_language_blind_d4.py).

D4 is a teenager's chat to a home robot (text speak, "idc", "idk", "bro"); F4 a factory worker who
is no native speaker ("the machine of welding", "and after bring ...", "for me is the same").
Each case is an instruction of those sets with its writer's formula, or a sentence of our own
for the same construction; the translator must give a formula equivalent to it on automata
(names included). The whole sets stay outside the repository.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_F4 = [
    # "the X of Y" as learners name a thing after its whole or its use: Y_X ("the machine of welding"); a
    # place said so is no remark ("come back to me in the office of supervisor" was left out)
    ('robot, now you go to the machine of welding',
     'F near[welding_machine]'),
    ('Go to the press machine, then to the scrap bin and then come back to me in the office of supervisor. '
     'Never enter the forklift lane.',
     'F (near[press_machine] & F (near[scrap_bin] & F near[supervisor_office])) & G !near[forklift_lane]'),
    ('go to the office of the nurse, then to the pharmacy',
     'F (near[nurse_office] & F near[pharmacy])'),
    ('Drone, go up to the mezzanine of second floor and hover there a bit.',
     'F near[second_floor_mezzanine]'),
    # "after" said for "then": before a request verb ("and after bring ..."), a preposition ("after over
    # X"), alone with its comma ("After, you go to it"), and after a first step marked "first" (each was
    # read as the order reversed, or the delivery as two goals)
    ('Take the finished part to the QA bench, and after bring the report paper to the office.',
     'F (near[finished_part] & F (pick[finished_part] & F (near[qa_bench] & F (release[finished_part, '
     'qa_bench] & F (near[report_paper] & F (pick[report_paper] & F (near[office] & F '
     'release[report_paper, office])))))))'),
    ('First you go to the CNC machine, after you go to the QA bench.',
     'F (near[cnc_machine] & F near[qa_bench])'),
    ('Fly over the paint booth, after over the stock yard, and land on the charging pad.',
     'F (near[paint_booth] & F (near[stock_yard] & F near[charging_pad]))'),
    ('go to the mill after you go to the lathe',
     'F (near[lathe] & F near[mill])'),
    # "don't go to X before Y. After, go to it": it is X, held back until Y (it was Y again, X no goal)
    ("Don't go to the forklift next to the charging station before you visit the shift office. After, you go "
     'to it.',
     'F near[forklift::isnextto(charging_station)] & (!near[forklift::isnextto(charging_station)] U '
     'near[shift_office])'),
    ('stay away from the pond until you have visited the barn, then go to it',
     'F near[pond] & (!near[pond] U near[barn])'),
    # remarks that leave the choice or say nothing more, unmarked: "idc what order", "idk whichever is
    # easier", "for me is the same", "which one is more close", "that's literally it"
    ('go to the pool n the trampoline idc what order',
     'F near[pool] & F near[trampoline]'),
    ('fly to the roof or the treehouse idk whichever is easier',
     'F near[roof] | F near[treehouse]'),
    ('Go to the pallet left of the scale or the pallet in front of the rack, for me is the same.',
     'F near[pallet::isleftof(scale)] | F near[pallet::isinfrontof(rack)]'),
    ('Go to welding station 1 or welding station 2, wich one is more close.',
     'F near[welding_station_1] | F near[welding_station_2]'),
    ('bro just go to the fridge thats literally it',
     'F near[fridge]'),
    # a form of address before the request with no comma ("yo drone fly over ...", "bro just go ...")
    ('yo drone fly over the basketball court real quick',
     'F near[basketball_court]'),
    # list positions: "start from the last one (and finish on the first one)" is the list in reverse order
    # (the middle item was lost, or all but the last); "the one in middle"; bare letters and colours
    # named with the kind the list is of ("storage rooms are A, B and C", "three bins: red, blue ...")
    ('Go to the three machines: mill, lathe, grinder. Start from the last one and finish on the first one.',
     'F (near[grinder] & F (near[lathe] & F near[mill]))'),
    ('Go to the three machines: mill, lathe, grinder. Start from the last one.',
     'F (near[grinder] & F (near[lathe] & F near[mill]))'),
    ('Storage rooms are A, B and C. Go to the one in middle.',
     'F near[storage_room_b]'),
    ('there are three bins: red, blue and green. go to the one in the middle',
     'F near[blue_bin]'),
    # the thing avoided said before "you avoid" ("and the other two you avoid")
    ('Welding station, grinding station, paint booth - go to the first, and the other two you avoid.',
     'F near[welding_station] & G !near[grinding_station] & G !near[paint_booth]'),
    ('go to the shed, but the pond you avoid',
     'F near[shed] & G !near[pond]'),
    # who a delivery is for, at the end ("..., for the visitor"): no place (it was a goal)
    ('Bring the safety helmet and the vest to the entrance, for the visitor.',
     'F (near[safety_helmet] & F (pick[safety_helmet] & F (near[entrance] & F release[safety_helmet, '
     'entrance]))) & F (near[vest] & F (pick[vest] & F (near[entrance] & F release[vest, entrance])))'),
    ('bring the cup to the table for the guest',
     'F (near[cup] & F (pick[cup] & F (near[table] & F release[cup, table])))'),
    # "all the time" / "in whole time" before a rule is "always" (it was "repeatedly", refused)
    ("Go to the paint booth only after the drying oven, and all the time don't go close to the welding "
     'station.',
     'F near[paint_booth] & (!near[paint_booth] U near[drying_oven]) & G !near[welding_station]'),
    ('Go to the CNC machine and after to the deburring station, and all the time stay away of the robot arm '
     'cell.',
     'F (near[cnc_machine] & F near[deburring_station]) & G !near[robot_arm_cell]'),
    ('Go to the lathe, then to the table at right of the lathe. In whole time avoid the oil barrel next to '
     'the door of emergency, it leaks.',
     'F (near[lathe] & F near[table::isrightof(lathe)]) & G !near[oil_barrel::isnextto(emergency_door)]'),
    # "stay far of X" avoids X; "(you must) stay / stand by X" is to be there
    ('Survey the roof of warehouse, but stay far of the chimney.',
     'F near[warehouse_roof] & G !near[chimney]'),
    ('Now you must stay by the QA bench.',
     'F near[qa_bench]'),
    ('go to the shed, then stand next to the gate',
     'F (near[shed] & F near[gate])'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_F4)
def test_readings_found_on_blind_sets_d4_and_f4_second_round(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

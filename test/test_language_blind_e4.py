"""Readings found on the blind sets E4 (a ward nurse speaking to the hospital robot, as speech
recognition writes it down) and H4 (a laboratory manager's formal written instructions).

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The whole sets stay outside
the repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

BLIND_ROUND_E4 = [
    # formal apologies open a correction as "sorry" does ("my apologies" was a place visited after)
    ('Please go to the ultracentrifuge. My apologies, I meant the microcentrifuge.',
     'F near[microcentrifuge]'),
    ('Go to the kettle. I beg your pardon, I meant the toaster.',
     'F near[toaster]'),
    # "I should have said X" is "I meant X" (both racks were visited)
    ('Please go to the rack to the left of the incubator. Sorry, I should have said the rack behind the '
     'incubator.',
     'F near[rack::isbehind(incubator)]'),
    # "it should go to X" after a delivery moves its destination ("it" is the thing carried: was a
    # second goal)
    ('Take the cryobox to the liquid nitrogen tank. I beg your pardon, it should go to the cold room.',
     'F (near[cryobox] & F (pick[cryobox] & F (near[cold_room] & F release[cryobox, cold_room])))'),
    ('bring the mug to the desk. wait, it goes to the sink',
     'F (near[mug] & F (pick[mug] & F (near[sink] & F release[mug, sink])))'),
    # "disregard" retracts as "ignore" does, also said politely and before a semicolon (both counts held)
    ('Visit the water purifier at most once. No, please disregard that restriction; visit it at least twice.',
     'F (near[water_purifier] & F (!near[water_purifier] & F near[water_purifier]))'),
    ('Go to the hall and avoid the stairs. Disregard that, avoid the lift.',
     'F near[hall] & G !near[lift]'),
    # "ignore all of that", "forget everything I said": only what follows stands (the old route stayed)
    ('Go to the glovebox, then the balance, then the freezer. Please ignore all of that and simply go to '
     'the freezer.',
     'F near[freezer]'),
    ('go to the glovebox, then the balance and avoid the hall. no, forget everything I said, just go to '
     'the freezer.',
     'F near[freezer]'),
    # "on reflection" opens a correction as "on second thought" does (a place "reflection" was visited)
    ('Visit the sonicator, the vortex mixer and the heat block, in that order. On reflection, omit the '
     'middle one.',
     'F (near[sonicator] & F near[heat_block])'),
    # a corrected count with "please" after it ("Correction: three times, please": both counts were kept)
    ('Please visit the pH meter twice. Correction: three times, please.',
     'F (near[ph_meter] & F (!near[ph_meter] & F (near[ph_meter] & F (!near[ph_meter] & F '
     'near[ph_meter]))))'),
    # an avoidance narrowed to one of its places ("only X needs to be avoided", "so just avoid X")
    ('Go to the wash room, and avoid the steam generator and the autoclave. On second thought, only the '
     'steam generator needs to be avoided.',
     'F near[wash_room] & G !near[steam_generator]'),
    ('Go to the wash room, and avoid the steam generator and the autoclave. Actually, the autoclave is off, '
     'so just avoid the steam generator.',
     'F near[wash_room] & G !near[steam_generator]'),
    # formal haste and timing ask for nothing ("without delay" was a place avoided; "at this time" refused)
    ('Proceed to the emergency eyewash staton without delay, please.',
     'F near[emergency_eyewash_station]'),
    ('At this time, I would like you to go to the glovebox.',
     'F near[glovebox]'),
    # speech recognition writes a label's number as the word that sounds like it ("bay for" dropped bay 4)
    ('go to the linen cupboard then bay for and keep clear of the oxygen cylinders the whole time',
     'F (near[linen_cupboard] & F near[bay_4]) & G !near[oxygen_cylinders]'),
    ('take the commode to bed for please',
     'F (near[commode] & F (pick[commode] & F (near[bed_4] & F release[commode, bed_4])))'),
    ('if you go into side room to at all you have to go to the hand wash sink first',
     '!near[side_room_2] W near[hand_wash_sink]'),
    ('go to the lab for now', 'F near[lab]'),
    ('bring the chair to the room too',
     'F (near[chair] & F (pick[chair] & F (near[room] & F release[chair, room])))'),
    # "A and E" is the accident and emergency department (the letters were avoided as two places)
    ('go to pharmacy or the dispensary whichever and keep well away from A and E',
     'F (near[pharmacy] | near[dispensary]) & G !near[a_and_e]'),
    ('fly to the second floor blood bank then down to the ground floor A and E',
     'F (near[second_floor_blood_bank] & F near[ground_floor_a_and_e])'),
    ('go to field A and E', 'F near[field_a] & F near[field_e]'),
    # where listed things are, said before the request with no full stop, sets the scene (was a goal)
    ('theres a commode a hoist and a wheelchair out in the corridor go to the second one',
     'F near[hoist]'),
    ('there are a mop, a bucket and a broom in the cupboard bring the last one to the hall',
     'F (near[broom] & F (pick[broom] & F (near[hall] & F release[broom, hall])))'),
    # a list of "the one by X, the one by Y (,) and the one by Z": three things (the first two were one)
    ('Three benches are free: the one by the window, the one by the sink, and the one by the door. Go to '
     'either of the first two.',
     'F near[bench::isnextto(window)] | F near[bench::isnextto(sink)]'),
    ('Three benches are free: the one by the window, the one by the sink and the one by the door. Go to '
     'the first one.',
     'F near[bench::isnextto(window)]'),
    ('go to the lamp by the sink and the one by the door',
     'F near[lamp::isnextto(sink)] & F near[lamp::isnextto(door)]'),
    # "either location is acceptable", "either is acceptable for this test", "either ones fine": remarks
    # (a place "location" was visited after each drop-off; the others were refused)
    ('Return the pipettes to the calibration bench or the tool drawer; either location is acceptable.',
     'F (near[pipettes] & F (pick[pipettes] & (F (near[calibration_bench] & F release[pipettes, '
     'calibration_bench]) | F (near[tool_drawer] & F release[pipettes, tool_drawer]))))'),
    ('Go to the east emergency shower or the west one; either is acceptable for this test.',
     'F near[east_emergency_shower] | F near[west_emergency_shower]'),
    ('go to the med room or pharmacy either ones fine',
     'F near[med_room] | F near[pharmacy]'),
    # "the pit no longer matters" / "does not matter" after the scope's end: free again (the pit was a
    # goal, and "longer_matters" avoided)
    ('Drone, fly to the east gantry. On the way, do not fly over the open pit; once you are at the gantry, '
     'the pit no longer matters.',
     '!near[open_pit] U near[east_gantry]'),
    ('fly to the east gantry. On the way, do not fly over the open pit; once you are at the gantry, the pit '
     'does not matter.',
     '!near[open_pit] U near[east_gantry]'),
    # deliveries stated, then "take them there": the same deliveries said again (each was done twice more)
    ('The clipboard and the lab notebook both belong on the meeting table; please take them there.',
     'F (near[clipboard] & F (pick[clipboard] & F (near[meeting_table] & F release[clipboard, '
     'meeting_table]))) & F (near[lab_notebook] & F (pick[lab_notebook] & F (near[meeting_table] & F '
     'release[lab_notebook, meeting_table])))'),
    # "(either) X then Y or Y then X", with a verb or an article left out: either order (the second
    # route had become a choice between the pharmacy and itself)
    ('either do the lab then the pharmacy or pharmacy then the lab up to you',
     'F (near[lab] & F near[pharmacy]) | F (near[pharmacy] & F near[lab])'),
    ('either go to the lab then the pharmacy or the pharmacy then the lab',
     'F (near[lab] & F near[pharmacy]) | F (near[pharmacy] & F near[lab])'),
    ('go to bay 3 then bay 4 or bay 4 then bay 3, and avoid the hall',
     'F near[bay_3] & F near[bay_4] & G !near[hall]'),
    # formal orders "you are (not) to ...", also with an aside ("You are not, however, to ..."), and "at
    # no point during this task are you to ..." (all refused)
    ('Proceed to the freezer and subsequently to the fume hood. You are not to go near the solvent cabinet '
     'until you have reached the fume hood.',
     'F (near[freezer] & F near[fume_hood]) & (!near[solvent_cabinet] U near[fume_hood])'),
    ('Bring the buffer bottle to bench 3. You are not, however, to collect it before you have signed in at '
     'the front desk.',
     'F (near[buffer_bottle] & F (pick[buffer_bottle] & F (near[bench_3] & F release[buffer_bottle, '
     'bench_3]))) & (!pick[buffer_bottle] U near[front_desk])'),
    ('Bring the buffer bottle to bench 3. You must not, however, collect it before you have signed in at '
     'the front desk.',
     'F (near[buffer_bottle] & F (pick[buffer_bottle] & F (near[bench_3] & F release[buffer_bottle, '
     'bench_3]))) & (!pick[buffer_bottle] U near[front_desk])'),
    ('You are to visit the orbital shaker exaclty twice, no more and no fewer.',
     '!near[orbital_shaker] U (near[orbital_shaker] & (near[orbital_shaker] U (!near[orbital_shaker] & '
     '(!near[orbital_shaker] U (near[orbital_shaker] & (near[orbital_shaker] W G '
     '!near[orbital_shaker]))))))'),
    ('At no point during this task are you to go near the laser table. Please proceed to the optics bench.',
     'F near[optics_bench] & G !near[laser_table]'),
    # "that room" after a room named before is that room ("however," opening a part asks for nothing)
    ('Bring the cell counter into the tissue culture room; however, you are not to enter that room before '
     'visiting the decontamination station.',
     'F (near[cell_counter] & F (pick[cell_counter] & F (near[tissue_culture_room] & F '
     'release[cell_counter, tissue_culture_room]))) & (!near[tissue_culture_room] U '
     'near[decontamination_station])'),
    # the span of the run said after a rule or a count ("for the entire flight", "for the duration of the
    # task", "throughout the flight", "over the course of the run"); "remain clear of" (all refused)
    ('Drone, please survey the roof skylights and remain clear of the overhead crane for the entire flight.',
     'F near[roof_skylights] & G !near[overhead_crane]'),
    ('Proceed to the storeroom, avoiding the wet-lab sink and the eyewash station for the duration of the '
     'task.',
     'F near[storeroom] & G !near[wet_lab_sink] & G !near[eyewash_station]'),
    ('Drone, inspect the ceiling lights, and keep well clear of the sprinkler heads throughout the flight.',
     'F near[ceiling_lights] & G !near[sprinkler_heads]'),
    ('Go to the autoclave three times over the course of the sterilisation run.',
     'F (near[autoclave] & F (!near[autoclave] & F (near[autoclave] & F (!near[autoclave] & F '
     'near[autoclave]))))'),
    ('Remain clear of the sterilisation room untill you have been to the equipment log terminal; '
     'subsequently, proceed to the sterilisation room.',
     '(!near[sterilisation_room] U near[equipment_log_terminal]) & F near[sterilisation_room]'),
    ('go to the den, remaining well away from the hall',
     'F near[den] & G !near[hall]'),
    # "until further instruction", "until you are told otherwise": no event of the task (refused)
    ('Drone, please proceed to the forth floor viewing gallery and hover until further instruction.',
     'F near[fourth_floor_viewing_gallery]'),
    # a list said right before the request, with no full stop, as speech runs on (refused)
    ('okay bay 1 bay 2 and bay 3 um go to the last one I said',
     'F near[bay_3]'),
    ('the pharmacy the lab and the blood bank go to the third one then the first',
     'F (near[blood_bank] & F near[pharmacy])'),
    ('theres the ECG machine the bladder scanner the obs machine and the feeding pump go to the one just '
     'before the feeding pump',
     'F near[obs_machine]'),
    # labelled names said one after another are each a name ("bed 2 bed 4" was one place, bed_2_bed_6)
    ('bed 2 bed 4 and bed 6 go to the first one no wait the second one',
     'F near[bed_4]'),
    ('side room 1 side room 2 and side room 3 go to the middle one',
     'F near[side_room_2]'),
    # counts are no labels ("zero times once twice three times four times" stays a count)
    ('you can visit the den zero times once twice three times four times or five times',
     '!near[den] W (near[den] & (near[den] W (!near[den] & (!near[den] W (near[den] & (near[den] W '
     '(!near[den] & (!near[den] W (near[den] & (near[den] W (!near[den] & (!near[den] W (near[den] & '
     '(near[den] W (!near[den] & (!near[den] W (near[den] & (near[den] W G !near[den]))))))))))))))))))'),
    # speech recognition's slips: "at lease twice" is at least, "bay 4s fine" is "bay 4's fine", "theyve"
    ('swing by the obs machine next to bed 3 at lease twice',
     'F (near[obs_machine::isnextto(bed_3)] & F (!near[obs_machine::isnextto(bed_3)] & F '
     'near[obs_machine::isnextto(bed_3)]))'),
    ('avoid bay 4 um actually bay 4s fine now just keep out of the isolation room and go to the sluice room',
     'F near[sluice_room] & G !near[isolation_room]'),
    # a reason run on after a rule: "they have (got) ..." (refused)
    ('go to the isolation room and after that avoid bay 3 completely theyve got norovirus',
     'F (near[isolation_room] & G !near[bay_3])'),
    # a count said again after "exactly" ("exactly once, just the once" had lost the exactly: silently)
    ('check bay 4 exactly once okay just the once',
     '!near[bay_4] U (near[bay_4] & (near[bay_4] W G !near[bay_4]))'),
    ('check bay 4 exactly once, just the once',
     '!near[bay_4] U (near[bay_4] & (near[bay_4] W G !near[bay_4]))'),
    # a choice narrowed by cancelling one and naming the other ("disregard the south one: the north
    # loading door only"; "forget the south one, just the north one" had kept both, silently)
    ('Go to either the north or the south loading door. Actually, disregard the south one: the north loading '
     'door only.',
     'F near[north_loading_door]'),
    ('Go to either the north or the south loading door. Actually, forget the south one, just the north '
     'loading door.',
     'F near[north_loading_door]'),
    ('go to the den or the hall. forget the hall, the den only.',
     'F near[den]'),
    # "actually just the kitchen" spoken with no comma, the kitchen being the ward kitchen of the choice,
    # and the correction ending where the next command starts (refused; "and then the attic" kept both)
    ('go to the day room or the ward kitchen actually just the kitchen and dont go near the dining trolley '
     'till you get there',
     'F near[ward_kitchen] & (!near[dining_trolley] U near[ward_kitchen])'),
    ('go to the den or the hall, actually just the den and then the attic',
     'F (near[den] & F near[attic])'),
    # a list ended by "each", a passive check ("must be checked on at least two separate occasions"),
    # "bring only the latter", "X and Y require a visit", "the order is at your discretion", "and from
    # there continue to" (all refused)
    ('The spectrophotmeter, the fluorimeter and the plate reader each need attention. Visit the third one at '
     'least twice.',
     'F (near[plate_reader] & F (!near[plate_reader] & F near[plate_reader]))'),
    ('The incubator must be checked on at least two separate occasions; finish at the logbook desk.',
     'F (near[incubator] & F (!near[incubator] & F (near[incubator] & F near[logbook_desk])))'),
    ('Two flasks need moving: a round-bottom flask and an Erlenmeyer flask. For now, bring only the latter '
     'to the fume hood.',
     'F (near[erlenmeyer_flask] & F (pick[erlenmeyer_flask] & F (near[fume_hood] & F '
     'release[erlenmeyer_flask, fume_hood])))'),
    ('Both the freezer farm and the chemical store require a visit today; the order is at your discretion.',
     'F near[freezer_farm] & F near[chemical_store]'),
    ('visit the freezer farm and the chemical store, the order is your call',
     'F near[freezer_farm] & F near[chemical_store]'),
    ('Go to the freezer room, and from there continue to either bench 4 or bench 5.',
     'F (near[freezer_room] & F (near[bench_4] | near[bench_5]))'),
    # formal asides: "in neither case may you pass near X", "do not under any circumstances go near X",
    # "or, alternatively, to X", "I would ask that you ..." (all refused)
    ('Go to the confocal microscope or the plate reader; in neither case may you pass near the MRI magnet.',
     '(F near[confocal_microscope] | F near[plate_reader]) & G !near[mri_magnet]'),
    ('Bring the dewar flask next to the glovebox to the cold room. While you are carrying it, do not under '
     'any circumstances go near the fume hood to the left of the door.',
     'F (near[dewar_flask::isnextto(glovebox)] & F (pick[dewar_flask::isnextto(glovebox)] & '
     '(!near[fume_hood::isleftof(door)] U (near[cold_room] & F release[dewar_flask::isnextto(glovebox), '
     'cold_room]))))'),
    ('Proceed to the glovebox or, alternatively, to the anaerobic chamber. Should you choose the anaerobic '
     'chamber, you must keep away from the gas manifold.',
     'F near[glovebox] | (F near[anaerobic_chamber] & G !near[gas_manifold])'),
    # a reason at the end of the sentence comes after its "there": no doubt what "there" is (refused)
    ('Deliver the sample rack to the sequencing core. After you have set it down there, I would ask that you '
     'stay away from the tissue culture room for the remainder of the task, as they are running a sterility '
     'check this afternoon and any traffic near their door compromises it.',
     'F (near[sample_rack] & F (pick[sample_rack] & F (near[sequencing_core] & F (release[sample_rack, '
     'sequencing_core] & G !near[tissue_culture_room]))))'),
    # spoken run-ons: "take off from the pad hover over X" (the leg was taken into the pad's name,
    # dropped silently); "don't go near X just go straight to Y" (refused)
    ('take off from the pad hover over the outpatients entrance and then land at the hospice',
     'F (near[outpatients_entrance] & F near[hospice])'),
    ('dont go near side room 1 or side room 3 just go straight to the nurses station',
     'F near[nurses_station] & G !near[side_room_1] & G !near[side_room_3]'),
    # "X um no not X VERB at Y", spoken with no commas: the step said again replaces it (refused)
    ('fly to the staff car park then land at the mortuary um no not the mortuary land at the pharmacy '
     'loading dock',
     'F (near[staff_car_park] & F near[pharmacy_loading_dock])'),
    ('go to the den no not the den go to the hall',
     'F near[hall]'),
    # "but if you go to X go to Y first" spoken without a comma binds the choice of X (Y was visited after
    # X, silently)
    ('go to side room 1 or side room 2 but if you go to side room 2 go to the PPE station first',
     'F near[side_room_1] | (F near[side_room_2] & (!near[side_room_2] U near[ppe_station]))'),
    # a statement with a plural subject and its verb after the request is no place to go ("repeated door
    # openings disturb the temperature" had made the temperature a goal, silently)
    ('Enter the cold room at most once; repeated door openings disturb the temperature.',
     '!near[cold_room] W (near[cold_room] & (near[cold_room] W G !near[cold_room]))'),
    # a reason that says how a thing is with "not" ("the autoclave is not running, so only X needs to be
    # avoided"): no rule, the correction after it is read (it was dropped with it: both stayed avoided)
    ('Go to the wash room, and avoid the steam generator and the autoclave. On second thought, the autoclave '
     'is not running, so only the steam generator needs to be avoided.',
     'F near[wash_room] & G !near[steam_generator]'),
    # a labelled place before a bound or a count ("bay 6 more than the one time", "bay 2 the once": "2
    # the" was read as "to the"; "bay 3 actually skip bay 3" spoken without a comma) (all refused)
    ('bring the clean sheets to bay 6 and dont go into bay 6 more than the one time',
     'F (near[clean_sheets] & F (pick[clean_sheets] & F (near[bay_6] & F release[clean_sheets, bay_6]))) & '
     '(!near[bay_6] W (near[bay_6] & (near[bay_6] W G !near[bay_6])))'),
    ('do not go into bay 6 more than twice',
     '!near[bay_6] W (near[bay_6] & (near[bay_6] W (!near[bay_6] & (!near[bay_6] W (near[bay_6] & '
     '(near[bay_6] W G !near[bay_6]))))))'),
    ('go to bay 1 then bay 2 then bay 3 actually skip bay 3 and do the day room instead oh and only go in '
     'bay 2 the once',
     'F (near[bay_1] & F (near[bay_2] & F near[day_room])) & (!near[bay_2] U (near[bay_2] & (near[bay_2] W '
     'G !near[bay_2])))'),
    ('take the towels 2 the cart',
     'F (near[towels] & F (pick[towels] & F (near[cart] & F release[towels, cart])))'),
    # "only one of them though not both" is exclusive; "go over their" is "there" (both refused)
    ('go to the sluice room or the dirty utility only one of them though not both',
     '(F near[sluice_room] & G !near[dirty_utility]) | (F near[dirty_utility] & G !near[sluice_room])'),
    ('the blood gas machine uh go over their',
     'F near[blood_gas_machine]'),
    # laboratory words are words, not slips ("argon" was read as "aragon")
    ('Under no circumstances should you go near the cryogenic storage tanks or the argon manifold today.',
     'G !near[cryogenic_storage_tanks] & G !near[argon_manifold]'),
    ('Of the argon tank, the CO2 incubator and the nitrogen generator, avoid the first entirely and visit '
     'the remaining two in reverse order.',
     'F (near[nitrogen_generator] & F near[co2_incubator]) & G !near[argon_tank]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_E4)
def test_readings_found_on_blind_set_e4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# Refused, never guessed: "that room" with no room named before it is no place that was said.
REFUSED_E4 = [
    'go to the den. do not enter that room before visiting the hall.',
    # a list after "before visiting" is no list that positions point into
    'before visiting the hall the den and the attic visit the garage and never visit it again then visit '
    'the hall before the den',
    # "until they have left": an event, not a reason
    'go to the den and avoid the hall until they have left',
    # a part left out in a sentence before may be what "it" means
    'go to the kitchen, the crew waxed the hall. avoid it',
]


@pytest.mark.parametrize('instruction', REFUSED_E4)
def test_refused_on_blind_set_e4(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

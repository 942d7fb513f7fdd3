"""Offline translator: asides, remarks and phrasings of spoken instructions (sixth round).

Every sentence here was written for these tests (none is taken from a data set). Each case
checks the formula on automata.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.spec import referents_of
from translation_cases import RULES, T, check_translation as _check


REMARKS = [
    ('Visit the den or the hall, your choice, I do not mind which one you pick.',
     'F near[den] | F near[hall]'),
    ('Go to the den or the hall, does not matter which, then the porch.',
     'F ((near[den] | near[hall]) & F near[porch])'),
    ('Take the cups to the sink or the counter, both are fine by me.',
     'F (near[cups] & F (pick[cups] & (F (near[sink] & F release[cups, sink]) | '
     'F (near[counter] & F release[cups, counter]))))'),
    ('Go to the study, take your time.', 'F near[study]'),
    ('Head to the den or the hall; I am fine with whichever room is quieter.', 'F near[den] | F near[hall]'),
    ('Fly to the silo or the mill, whichever is less windy right now.', 'F near[silo] | F near[mill]'),
    ('Carry the knife to the sink, careful, it is sharp.',
     'F (near[knife] & F (pick[knife] & F (near[sink] & F release[knife, sink])))'),
    ('Visit the printer twice, it keeps '
     'jamming.', 'F (near[printer] & F (!near[printer] & F near[printer]))'),
    ('Head to the kennel, they get noisy at night.', 'F near[kennel]'),
    ('Take the mop to the closet and never go near the nursery, there is a baby napping in there.',
     'F (near[mop] & F (pick[mop] & F (near[closet] & F release[mop, closet]))) & G !near[nursery]'),
]


@pytest.mark.parametrize('instruction,gold', REMARKS, ids=[c[0][:30] for c in REMARKS])
def test_remarks_and_reasons_are_left_out(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    assert any('left out' in n or 'description of the scene' in n for n in notes), notes


SPELLING = [
    ('head over to the vaccum cupboard', 'F near[vacuum_cupboard]'),
    ('pls put the flashlite on the shelf',
     'F (near[flashlight] & F (pick[flashlight] & F (near[shelf] & F release[flashlight, shelf])))'),
    ('check the mailbox two tims', 'F (near[mailbox] & F (!near[mailbox] & F near[mailbox]))'),
    ('hover ovr the car park', 'F near[car_park]'),
    ('go to the exit and keep away form the puddle', 'F near[exit] & G !near[puddle]'),
    ('go to the bench nexto the fountain', 'F near[bench::isnextto(fountain)]'),
    ('on ur way to the lobby, avoid the tea trolly', '!near[tea_trolley] U near[lobby]'),
]


@pytest.mark.parametrize('instruction,gold', SPELLING, ids=[c[0][:30] for c in SPELLING])
def test_chat_spellings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


COUNTS = [
    ('Swing by the mailbox a couple of times.', 'F (near[mailbox] & F (!near[mailbox] & F near[mailbox]))'),
    ('Check the gate twice, two separate visits to the '
     'gate.', 'F (near[gate] & F (!near[gate] & F near[gate]))'),
    ('Check the gate three times, three distinct trips.',
     'F (near[gate] & F (!near[gate] & F (near[gate] & F (!near[gate] & F near[gate]))))'),
    ('Only once, mind you, drive to the barn.',
     '!near[barn] U (near[barn] & (near[barn] W G !near[barn]))'),
    ('Go up to the loft just the once.', '!near[loft] U (near[loft] & (near[loft] W G !near[loft]))'),
    ('Visit the attic exactly twice, no more and no less, then the porch.',
     '(!near[attic] U (near[attic] & (near[attic] U (!near[attic] & (!near[attic] U (near[attic] & '
     '(near[attic] W G !near[attic]))))))) & F (near[attic] & F (!near[attic] & F (near[attic] & F '
     'near[porch])))'),
    ('Check the gate at least twice over the course of the evening.',
     'F (near[gate] & F (!near[gate] & F near[gate]))'),
    ('Bring the box to the porch, and never go to the porch more than once while you are at it.',
     'F (near[box] & F (pick[box] & F (near[porch] & F release[box, porch]))) & '
     '(!near[porch] W (near[porch] & (near[porch] W G !near[porch])))'),
    ('Patrol past the gate at least twice, and never go near the vase at any point during the patrol.',
     'F (near[gate] & F (!near[gate] & F near[gate])) & G !near[vase]'),
]


@pytest.mark.parametrize('instruction,gold', COUNTS, ids=[c[0][:30] for c in COUNTS])
def test_count_idioms(instruction: str, gold: str) -> None:
    _check(instruction, gold)


EVENTS = [
    ('Lug the sacks into the shed, and the moment they are off your hands, keep out of the barn.',
     'F (near[sacks] & F (pick[sacks] & F (near[shed] & F (release[sacks, shed] & G !near[barn]))))'),
    ('Carry the box to the shed, and as soon as you have let go of it, keep out of the garden.',
     'F (near[box] & F (pick[box] & F (near[shed] & F (release[box, shed] & G !near[garden]))))'),
    ('Bring the mug to the desk. The minute you have got hold of it, avoid the stairs for the rest '
     'of the task.',
     'F (near[mug] & F (pick[mug] & G !near[stairs] & F (near[desk] & F release[mug, desk])))'),
    ('Fly to the tower for an inspection, and once you have reached it, avoid the lake for the rest '
     'of the flight.',
     'F (near[tower] & G !near[lake])'),
    ('Go to the den and give the rug a wide berth.', 'F near[den] & G !near[rug]'),
    ('Go to the den and do not cut across the lawn.', '!near[lawn] U near[den]'),
    ('Pick up the cup and fly it over to the sink, then land on the pad.',
     'F (near[cup] & F (pick[cup] & F (near[sink] & F (release[cup, sink] & F near[pad]))))'),
    ('Haul the keg to the hatch.', 'F (near[keg] & F (pick[keg] & F (near[hatch] & F release[keg, hatch])))'),
]


@pytest.mark.parametrize('instruction,gold', EVENTS, ids=[c[0][:30] for c in EVENTS])
def test_events_said_at_length(instruction: str, gold: str) -> None:
    _check(instruction, gold)


PLACED = [
    ('Go to the crate stacked on the red pallet.', 'F near[crate::isabove(red_pallet)]'),
    ('Head to the stool that is sitting right underneath the sink.', 'F near[stool::isbelow(sink)]'),
    ('Go to the lamp mounted above the sofa.', 'F near[lamp::isabove(sofa)]'),
    ('Drive to the van parked behind the gate.', 'F near[van::isbehind(gate)]'),
]


@pytest.mark.parametrize('instruction,gold', PLACED, ids=[c[0][:30] for c in PLACED])
def test_where_a_thing_was_put_is_a_relation(instruction: str, gold: str) -> None:
    _check(instruction, gold)


RETRACTIONS = [
    ('Keep away from the gas stove and the bins, actually the bins are fine. Then go to the sink.',
     'F near[sink] & G !near[gas_stove]'),
    ('Avoid the porch while you do this. On second thought, the porch is fine now that it is dry. '
     'Just go to the shed.', 'F near[shed]'),
    ('Take the cups to the sink, and avoid the table. Correction: the table is fine, avoid the oven instead.',
     'F (near[cups] & F (pick[cups] & F (near[sink] & F release[cups, sink]))) & G !near[oven]'),
    ('Avoid the hall and the den, then go to the porch. Actually the den is fine.',
     'F near[porch] & G !near[hall]'),
]


@pytest.mark.parametrize('instruction,gold', RETRACTIONS, ids=[c[0][:30] for c in RETRACTIONS])
def test_a_thing_said_to_be_fine_after_all_is_no_longer_avoided(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    assert 'the avoidance was retracted' in notes


def test_a_thing_said_again_by_its_last_word_is_the_thing_named_before() -> None:
    notes = _check('There is a kitchen island here. Avoid the island and go to the sink.',
                   'F near[sink] & G !near[kitchen_island]')
    assert any('took "island" as the kitchen island' in n for n in notes)
    short = T.translate('Carry the mug to the oak bench, then the plate to the bench.').formula
    full = T.translate('Carry the mug to the oak bench, then the plate to the oak bench.').formula
    assert equivalent(short, full), f'{short} != {full}'
    # a name with a relation, or two longer names that end in it, are left as they are
    _check('Go to the red chair and the blue chair, then the chair.',
           'F (near[red_chair] & F near[chair]) & F (near[blue_chair] & F near[chair])')


TERSE = [
    ('Garage, please. Avoid: the ramp, the bins.', 'F near[garage] & G !near[ramp] & G !near[bins]'),
    ('Route: (1) the boot room, (2) the scullery, (3) the larder.',
     'F (near[boot_room] & F (near[scullery] & F near[larder]))'),
    ('Either the red door or the blue one, your call.', 'F near[red_door] | F near[blue_door]'),
    ('Choose one: the den, the hall or the attic.', 'F near[den] | F near[hall] | F near[attic]'),
    ('The den.', 'F near[den]'),
]


@pytest.mark.parametrize('instruction,gold', TERSE, ids=[c[0][:30] for c in TERSE])
def test_terse_requests_with_the_verb_left_out(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_words_that_are_no_places_are_not_guessed_to_be_one() -> None:
    """The rules (the default gives the model's reading of the statement, flagged: see the README)."""
    for text in ('qwzx vvv', 'My keys fell behind the couch.'):
        try:
            got = RULES.translate(text)
        except Exception:
            continue
        assert not any(d.name.startswith(('qwzx', 'keys')) for d in referents_of(got.formula)), got.formula


PHRASINGS = [
    ('Please take the chair back to the office.',
     'F (near[chair] & F (pick[chair] & F (near[office] & F release[chair, office])))'),
    ('Make a pass over the field exactly twice, then land on the pad.',
     '(!near[field] U (near[field] & (near[field] U (!near[field] & (!near[field] U (near[field] & '
     '(near[field] W G !near[field]))))))) & F (near[field] & F (!near[field] & F (near[field] & F '
     'near[pad])))'),
    ('Drop by either the bakery or the bank, then go '
     'home.', 'F ((near[bakery] | near[bank]) & F near[home])'),
    ('Take the towels down to the chute, and never go near the nursery, there is someone sleeping in there.',
     'F (near[towels] & F (pick[towels] & F (near[chute] & F release[towels, chute]))) & G !near[nursery]'),
]


@pytest.mark.parametrize('instruction,gold', PHRASINGS, ids=[c[0][:30] for c in PHRASINGS])
def test_more_spoken_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_one_after_a_compound_noun_stands_for_the_compound() -> None:
    _check('Either the left loading door or the right one, your call.',
           'F near[left_loading_door] | F near[right_loading_door]')
    _check('Go to the blue coffee mug, not the red one.', 'F near[blue_coffee_mug] & G !near[red_coffee_mug]')
    _check('Go to the big red box or the small one.', 'F near[big_red_box] | F near[small_box]')


def test_hyphenated_verb_particle_compounds_are_one_word_of_a_name() -> None:
    _check('Avoid the fryer, and head to the walk-in larder and then over to the sink.',
           'F (near[walk_in_larder] & F near[sink]) & G !near[fryer]')
    _check('Go to the drop-off point.', 'F near[drop_off_point]')


def test_a_correction_that_names_what_it_corrects_and_apologises() -> None:
    notes = _check('Go to the walk-in larder. Wait, no, not the larder, I meant the walk-in wardrobe, sorry, '
                   'it has been a busy week.', 'F near[walk_in_wardrobe]')
    assert any('left out' in n for n in notes)
    _check('Bring the mug to the den. No, not the den, I meant the study, my mistake.',
           'F (near[mug] & F (pick[mug] & F (near[study] & F release[mug, study])))')


CORRECTIONS = [
    ('Go to the mug on the top shelf, hang on, my mistake, it is actually on the middle shelf, same '
     'mug though.',
     'F near[mug::isabove(middle_shelf)]'),
    ('Could you carry the rug to the hall, oh, hang on, I mean the porch, it needs airing.',
     'F (near[rug] & F (pick[rug] & F (near[porch] & F release[rug, porch])))'),
    ('Bring the cups to the sink, and keep away from the stove. Correction: the stove\'s fine, keep '
     'away from '
     'the kettle instead.',
     'F (near[cups] & F (pick[cups] & F (near[sink] & F release[cups, sink]))) & G !near[kettle]'),
    ('Go to the blue gate or the white gate. Actually, just the white gate; the blue one\'s locked.',
     'F near[white_gate]'),
    ('Go to the mill, then the barn, then the silo. Actually, swap the last two around, I changed my mind.',
     'F (near[mill] & F (near[silo] & F near[barn]))'),
    ('Visit the den, the attic and the porch in that order. Wait, swap the first two.',
     'F (near[attic] & F (near[den] & F near[porch]))'),
]


@pytest.mark.parametrize('instruction,gold', CORRECTIONS, ids=[c[0][:30] for c in CORRECTIONS])
def test_spoken_self_corrections(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_whichever_is_easier_to_reach_is_the_person_s_reason() -> None:
    _check('Go to the bin behind the desk or the one left of the door, whichever is easier to reach.',
           'F near[bin::isbehind(desk)] | F near[bin::isleftof(door)]')


LIST_POSITIONS = [
    ('There are two chairs: one by the window, and one behind the sofa. Sit on the second one, please.',
     'F near[chair::isbehind(sofa)]'),
    ('I have left out a cup, a plate and a fork. Return the middle one to the sink.',
     'F (near[plate] & F (pick[plate] & F (near[sink] & F release[plate, sink])))'),
    ('You will pass a vase, a piano and a clock. Go to the one before the clock.', 'F near[piano]'),
    ('You will pass a vase, a piano and a clock in the hall. Visit the piano first, and after that '
     'the item I '
     'listed at the start.', 'F (near[piano] & F near[vase])'),
    ('Go to the porch, and keep clear of the second and third things on this list: a ladder, a '
     'bucket, a hose.',
     'F near[porch] & G !near[bucket] & G !near[hose]'),
    ('Bring me the last of these: a mug, a spoon, a bowl.', 'F (near[bowl] & F pick[bowl])'),
]


@pytest.mark.parametrize('instruction,gold', LIST_POSITIONS, ids=[c[0][:30] for c in LIST_POSITIONS])
def test_more_references_by_list_position(instruction: str, gold: str) -> None:
    _check(instruction, gold)


DRONE_AND_ERRANDS = [
    ('Drone, once you are in the air, head out to the mast and hold position over it; that is the only stop.',
     'F near[mast]'),
    ('Fly across to the gazebo and hold your position there for a couple of minutes.', 'F near[gazebo]'),
    ('Do not fly over the field until you have inspected the mast, and once that is done, survey '
     'the whole field.',
     '(!near[field] U near[mast]) & F (near[mast] & F near[field])'),
    ('Hover at the turbine, but only once you have made a pass over the pylon.',
     'F near[turbine] & (!near[turbine] U near[pylon])'),
    ('I would love it if you could make your way over to the stool under the sink, no rush at all.',
     'F near[stool::isbelow(sink)]'),
    ('I need you at the counter, but before doing that, make a quick stop at the stockroom.',
     'F (near[stockroom] & F near[counter])'),
    ('Move the fern over to the shelf, it needs more light.',
     'F (near[fern] & F (pick[fern] & F (near[shelf] & F release[fern, shelf])))'),
]


@pytest.mark.parametrize('instruction,gold', DRONE_AND_ERRANDS, ids=[c[0][:30] for c in DRONE_AND_ERRANDS])
def test_drone_phrasings_and_errands(instruction: str, gold: str) -> None:
    _check(instruction, gold)


PICK_GUARDS = [
    ('Bring the charger to the room, but do not pick it up until you have been to the desk.',
     'F (near[charger] & F (pick[charger] & F (near[room] & F release[charger, room]))) & '
     '(!pick[charger] U near[desk])'),
    ('Carry the parcel to the porch, but only grab it after you have visited the gate.',
     'F (near[parcel] & F (pick[parcel] & F (near[porch] & F release[parcel, porch]))) & '
     '(!pick[parcel] U near[gate])'),
    ('Take the tray to the kitchen, and never pick up the tray before you have been to the hall.',
     'F (near[tray] & F (pick[tray] & F (near[kitchen] & F release[tray, kitchen]))) & (!pick[tray] '
     'U near[hall])'),
]


@pytest.mark.parametrize('instruction,gold', PICK_GUARDS, ids=[c[0][:30] for c in PICK_GUARDS])
def test_a_pick_that_must_wait_for_a_visit(instruction: str, gold: str) -> None:
    _check(instruction, gold)


LEGS = [
    ('Go to the barn first, and then the cow shed, and as you head from the barn to the shed, do '
     'not cut across '
     'the orchard.', 'F (near[barn] & (!near[orchard] U near[cow_shed]))'),
    ('Fly out to the mast, and on the return leg to the pad, stay clear of the turbines.',
     'F (near[mast] & (!near[turbines] U near[pad]))'),
    ('On your way to the cellar, avoid the boiler. Sorry, I meant avoid it on the way back from the '
     'cellar to '
     'the garage, not on the way there.', 'F (near[cellar] & (!near[boiler] U near[garage]))'),
    ('Stop at the kiosk first and then make your way to the gate; on the leg between the two, stay '
     'out of the '
     'car park, it is busy.', 'F (near[kiosk] & (!near[car_park] U near[gate]))'),
    ('Go to the attic and then the porch, and stay out of the hall between the two.',
     'F (near[attic] & (!near[hall] U near[porch]))'),
    ('Walk to the pond, then the bench, and while going from the pond to the bench, keep off the grass.',
     'F (near[pond] & (!near[grass] U near[bench]))'),
]


@pytest.mark.parametrize('instruction,gold', LEGS, ids=[c[0][:30] for c in LEGS])
def test_avoidance_on_a_leg_said_in_other_words(instruction: str, gold: str) -> None:
    _check(instruction, gold)


CHOICES = [
    ('Either visit the kiosk exactly once, or go to the fountain at least twice, your choice.',
     '(!near[kiosk] U (near[kiosk] & (near[kiosk] W G !near[kiosk]))) | '
     'F (near[fountain] & F (!near[fountain] & F near[fountain]))'),
    ('Either go to the east gate or the west gate, and on the way there, avoid the kennels, they get noisy.',
     '!near[kennels] U (near[east_gate] | near[west_gate])'),
    ('Head to either the silo or the trough, but do not go near either of them until you have been '
     'to the gate.',
     '(F near[silo] | F near[trough]) & ((!near[silo] & !near[trough]) U near[gate])'),
    ('Go to the den and the hall, and avoid both of them until you have been to the porch.',
     'F near[den] & F near[hall] & ((!near[den] & !near[hall]) U near[porch])'),
    ('Check the east gate or the west gate, just one of them, and avoid the pond.',
     '((F near[east_gate] & G !near[west_gate]) | (F near[west_gate] & G !near[east_gate])) & G !near[pond]'),
    ('Inspect the red shed or the blue shed, only one of them, not both, and keep clear of the pen '
     'throughout.',
     '((F near[red_shed] & G !near[blue_shed]) | (F near[blue_shed] & G !near[red_shed])) & G !near[pen]'),
]


@pytest.mark.parametrize('instruction,gold', CHOICES, ids=[c[0][:30] for c in CHOICES])
def test_choices_said_in_other_words(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_a_place_off_limits_until_an_event() -> None:
    _check('Go to the shed and then the bench. Also, the bench is off limits until you have visited '
           'the reel too.',
           'F (near[shed] & F near[bench]) & (!near[bench] U near[reel])')
    _check('The loft is out of bounds until you have been to the landing. Go to the loft.',
           'F near[loft] & (!near[loft] U near[landing])')


def test_more_everyday_phrasings() -> None:
    _check('Head to the reception desk but skip the cafe.', 'F near[reception_desk]')
    _check('Go to the hall, then the landing; you can stop at the bathroom on the way if you need to.',
           'F (near[hall] & F near[landing])')
    _check('Go to the kiosk at least twice but no more than three times.',
           'F (near[kiosk] & F (!near[kiosk] & F near[kiosk])) & (!near[kiosk] W (near[kiosk] & '
           '(near[kiosk] W '
           '(!near[kiosk] & (!near[kiosk] W (near[kiosk] & (near[kiosk] W (!near[kiosk] & (!near[kiosk] W '
           '(near[kiosk] & (near[kiosk] W G !near[kiosk])))))))))))')
    _check('Pick up the bread from the bakery and bring it home.',
           'F (near[bread::isnextto(bakery)] & F (pick[bread::isnextto(bakery)] & F (near[home] & '
           'F release[bread::isnextto(bakery), home])))')


def test_lists_after_a_verb_and_places_of_destinations() -> None:
    _check('Visit each of the three huts: the red one, the green one and the blue one.',
           'F near[red_hut] & F near[green_hut] & F near[blue_hut]')
    notes = _check('Return the atlas to the shelf in the study.',
                   'F (near[atlas] & F (pick[atlas] & F (near[shelf] & F release[atlas, shelf])))')
    assert any('where shelf is' in n for n in notes)
    _check('Go to the den, no actually the lounge, and then the '
           'hallway.', 'F (near[lounge] & F near[hallway])')


def test_first_and_last_said_afterwards() -> None:
    _check('Visit the bakery, the florist and the bank. The bank has to be last.',
           'F near[bakery] & F near[florist] & F near[bank] & (!near[bank] U near[bakery]) & '
           '(!near[bank] U near[florist])')
    _check('Go to the den and the hall; the hall must come first.',
           'F near[den] & F near[hall] & (!near[den] U near[hall])')


def test_where_a_thing_is_taken_from_and_an_order_word_corrected() -> None:
    _check('Get the keys from under the mat and put them on the hook.',
           'F (near[keys::isbelow(mat)] & F (pick[keys::isbelow(mat)] & F (near[hook] & '
           'F release[keys::isbelow(mat), hook])))')
    _check('Visit the park, then the museum, but you must not go to the museum before noon... sorry, '
           'before the park.', 'F (near[park] & F near[museum]) & (!near[museum] U near[park])')


def test_a_fallback_a_counted_heading_and_no_return() -> None:
    _check('Go to the gym, but if the gym is busy, go to the pool instead.', 'F near[gym] | F near[pool]')
    _check('Two errands: the post office, then the bank.', 'F (near[post_office] & F near[bank])')
    _check('Please visit the storeroom, and do not go back to the storeroom after that.',
           'F near[storeroom] & (!near[storeroom] U (near[storeroom] & '
           '(near[storeroom] W G !near[storeroom])))')


def test_going_back_said_with_a_condition_is_not_a_bound_on_visits() -> None:
    _check('Visit the shed, and never return to it afterwards.',
           'F near[shed] & (!near[shed] U (near[shed] & (near[shed] W G !near[shed])))')
    _check('Go to the kitchen, then the hall. Do not go back to the kitchen until you have been to the '
           'garden.',
           'F (near[kitchen] & F near[hall]) & (!near[kitchen] U near[garden])')


def test_staying_put_beforehand_forever_and_a_relative_clause_after_a_comma() -> None:
    _check("Go to the kitchen. Once you're there, don't leave until you've checked the oven.",
           'F (near[kitchen] & (near[kitchen] U near[oven]))')
    _check("I'd like you to visit the museum, but please go to the cafe beforehand.",
           'F (near[cafe] & F near[museum])')
    _check('Keep visiting the entrance and the exit, forever.', 'G F near[entrance] & G F near[exit]')
    _check('Go to the lift, and keep away from the trolley, which is right next to the stairs.',
           'F near[lift] & G !near[trolley::isnextto(stairs)]')


FOUND_LATE = [
    # "can" is a thing after a determiner, not only in "soda can"
    ('Carry the can to the wall, and keep away from the sofa while carrying it.',
     'F (near[can] & F (pick[can] & (!near[sofa] U (near[wall] & F release[can, wall]))))'),
    ('Pick up the can and then go to the door.', 'F (near[can] & F (pick[can] & F near[door]))'),
    ('You can go to the kitchen.', 'F near[kitchen]'),
    # an avoidance until several places are reached holds until the last of them, in the order said
    ('Avoid the kitchen until you reach the hall and the attic.',
     'F (near[hall] & F near[attic]) & (!near[kitchen] U (near[hall] & (!near[kitchen] U near[attic])))'),
    ('Until you reach the hall and the attic, avoid the kitchen.',
     'F (near[hall] & F near[attic]) & (!near[kitchen] U (near[hall] & (!near[kitchen] U near[attic])))'),
    ('Avoid the kitchen until you reach the hall.', '(!near[kitchen] U near[hall]) & F near[hall]'),
    # a correction that says the whole step again, the thing as a pronoun
    ('Put the mug on the shelf. Scratch that, put it in the sink.',
     'F (near[mug] & F (pick[mug] & F (near[sink] & F release[mug, sink])))'),
    ('Take the plates to the table. Actually, ignore that, just throw them away.',
     'F (near[plates] & F (pick[plates] & F (near[trash_can] & F release[plates, trash_can])))'),
    ('Go to the porch, then put the lamp on the desk. Scratch that, put it by the bed.',
     'F (near[porch] & F (near[lamp] & F (pick[lamp] & F (near[bed] & F release[lamp, bed]))))'),
    ('Go to the garage. Scratch that, go to the shed.', 'F near[shed]'),
    # "the third floor one" for "the second floor lounge": floor is not said twice
    ('Go to the second floor lounge, no wait, the third floor one.', 'F near[third_floor_lounge]'),
    # "too" for "to", and "any one of the three" asks for nothing
    ('Carry the seed bag too the barn.',
     'F (near[seed_bag] & F (pick[seed_bag] & F (near[barn] & F release[seed_bag, barn])))'),
    ('Visit the den, the loft or the attic - any one of the three.',
     'F near[den] | F near[loft] | F near[attic]'),
    ('Visit the den, the loft or the attic, any one of them will do.',
     'F near[den] | F near[loft] | F near[attic]'),
    # an avoidance after the last of several alternative clauses holds for all of them
    ('Either go to the den or go to the hall, and keep away from the dog bowl.',
     '(F near[den] | F near[hall]) & G !near[dog_bowl]'),
    ('Either put the cup in the sink or throw it away, and either way keep away from the cat.',
     'F (near[cup] & F (pick[cup] & (F (near[sink] & F release[cup, sink]) | '
     'F (near[trash_can] & F release[cup, trash_can])))) & G !near[cat]'),
    ('Either go to the den or go to the hall.', 'F near[den] | F near[hall]'),
    # "flip that": the last two goals swapped
    ('Go to the barn and then the silo. Hmm, flip that, silo first.', 'F (near[silo] & F near[barn])'),
    ('Go to the barn and then the silo. Actually, flip that.', 'F (near[silo] & F near[barn])'),
    # a list said after an adverb
    ('Earlier I mentioned the attic, the den and the porch. Go to the last one I mentioned.',
     'F near[porch]'),
    ('Barn, silo, pump house: go to all three in reverse order.',
     'F (near[pump_house] & F (near[silo] & F near[barn]))'),
    ('I listed three rooms: the den, the office and the nursery. Visit the first and second in either '
     'order, but never the third.', 'F near[den] & F near[office] & G !near[nursery]'),
    ("Go to the lobby, but hold off on it until you've been to the coat check.",
     'F near[lobby] & (!near[lobby] U near[coat_check])'),
    ('Hold off on visiting the lab until you have seen the office, then go to the lab.',
     'F (near[office] & F near[lab]) & (!near[lab] U near[office])'),
    ('Before you head to the den, swing by the pantry, and before the pantry, the garage.',
     'F (near[garage] & F (near[pantry] & F near[den]))'),
    ('Go to the bins at most once and to the compost pile at least twice.',
     '(!near[bins] W (near[bins] & (near[bins] W G !near[bins]))) & '
     'F (near[compost_pile] & F (!near[compost_pile] & F near[compost_pile]))'),
    ('Go to the printer, and from there to the copier without going near the stairs.',
     'F (near[printer] & (!near[stairs] U near[copier]))'),
    ('Visit the kiosk before the lounge, and the lounge before the quad.',
     'F (near[lounge] & F near[quad]) & (!near[lounge] U near[kiosk]) & (!near[quad] U near[lounge])'),
    # two letters swapped in a compound of two listed words
    ('Move the toolbox over to the wrokbench.',
     'F (near[toolbox] & F (pick[toolbox] & F (near[workbench] & F release[toolbox, workbench])))'),
    # a last comma part that says why asks for nothing
    ('Fly to the mast, and never fly over the pond, the neighbours complain.',
     'F near[mast] & G !near[pond]'),
    ("Fly out to the pier, and don't ever fly over the marina, we don't have clearance for that.",
     'F near[pier] & G !near[marina]'),
    ("Peek into the study no more than once, my husband's on a call.",
     '!near[study] W (near[study] & (near[study] W G !near[study]))'),
    ("Throw away the paper cup, it's been sitting there for days.",
     'F (near[paper_cup] & F (pick[paper_cup] & F (near[trash_can] & F release[paper_cup, trash_can])))'),
    ('Go to the printer, then the desk - somebody keeps jamming it.', 'F (near[printer] & F near[desk])'),
    ('Bring me the keys, they are on the table.',
     'F (near[keys::isabove(table)] & F pick[keys::isabove(table)])'),
    ('Go to the den, I need you to avoid the hall.', 'F near[den] & G !near[hall]'),
    # fillers and verbs said another way
    ('Could you maybe head over to the piano?', 'F near[piano]'),
    ('Visit the mailbox like at least 2 times today.',
     'F (near[mailbox] & F (!near[mailbox] & F near[mailbox]))'),
    ('Go to the desk, and when you get there carry on to the lobby.', 'F (near[desk] & F near[lobby])'),
    ('Bring the mail in to the kitchen table.',
     'F (near[mail] & F (pick[mail] & F (near[kitchen_table] & F release[mail, kitchen_table])))'),
    ('I need the scalpel brought to the tray.',
     'F (near[scalpel] & F (pick[scalpel] & F (near[tray] & F release[scalpel, tray])))'),
    ('Visit the mailbox twice - eh, make it three times.',
     'F (near[mailbox] & F (!near[mailbox] & F (near[mailbox] & F (!near[mailbox] & F near[mailbox]))))'),
    # "but first a, then b": both before the goal said
    ('I want you at the dock door, but first stop at the office and then the pallet jack.',
     'F (near[office] & F (near[pallet_jack] & F near[dock_door]))'),
    ('Go to the gate, but first go to the shed, then the barn.',
     'F (near[shed] & F (near[barn] & F near[gate]))'),
    ('Go to the gate, but first go to the shed. Then go to the barn.',
     'F (near[shed] & F (near[gate] & F near[barn]))'),
    # a statement about the scene is not a place to go
    ('The kids left stuff everywhere. Visit the swings, then the slide.', 'F (near[swings] & F near[slide])'),
    # corrections: the words before the phrase said again; "the one ..." of the same kind
    ("Go to the classroom, but only after the principal's office - sorry, only after the front office.",
     'F near[classroom] & (!near[classroom] U near[front_office])'),
    ('Bring the remote on the couch to the tv stand. Actually, no, bring the one on the armchair.',
     'F (near[remote::isabove(armchair)] & F (pick[remote::isabove(armchair)] & F (near[tv_stand] & '
     'F release[remote::isabove(armchair), tv_stand])))'),
    ('Bring the red mug to the sink. No, bring the blue one.',
     'F (near[blue_mug] & F (pick[blue_mug] & F (near[sink] & F release[blue_mug, sink])))'),
    ('Go to the red chair. No, go to the blue one.', 'F near[blue_chair]'),
    # "after going to X, avoid Y" (the conventions): X is a step, Y avoided from there on
    ('After going to the coop, avoid the garden. Then go to the tractor.',
     'F (near[coop] & G !near[garden] & F near[tractor])'),
    ('After going to the coop, avoid the garden.', 'F (near[coop] & G !near[garden])'),
    ('Once you have been to the garden you cannot go to the carpet.',
     'G (near[garden] -> X G !near[carpet])'),
    # scopes: the way back, a leg named by a goal said again shorter, after dropping off
    ("Go to the mailbox and then come back to the porch, and while you're returning, avoid the flower bed.",
     'F (near[mailbox] & (!near[flower_bed] U near[porch]))'),
    ('Go to the bench next to the fountain, then the gazebo, and on your way from the bench to the gazebo '
     'stay off the lawn.', 'F (near[bench::isnextto(fountain)] & (!near[lawn] U near[gazebo]))'),
    ("Take the cooler to the table and then go to the car. Once you've dropped off the cooler, stay away "
     'from the lake.',
     'F (near[cooler] & F (pick[cooler] & F (near[table] & F (release[cooler, table] & G !near[lake] & '
     'F near[car]))))'),
    # corrections and list positions found on set F
    ('Go to the printer three times - scratch that, twice is plenty - and then go to my office.',
     'F (near[printer] & F (!near[printer] & F (near[printer] & F near[office])))'),
    ('Go to the pharmacy then the shop, and avoid the ward. Actually, ignore the last thing - avoid the '
     'cafe instead.', 'F (near[pharmacy] & F near[shop]) & G !near[cafe]'),
    ('Entrance, lobby, atrium, courtyard - go to the second to last one.', 'F near[atrium]'),
    ("Fly over the north field, then land on the strip. Don't go near the strip until you've done the "
     'north field.', 'F (near[north_field] & F near[strip]) & (!near[strip] U near[north_field])'),
    # more reasons and remarks, an address, "before anything else" (set G)
    ('Head down to the pier - and on the way there, stay away from the fish market, the gulls go nuts.',
     '!near[fish_market] U near[pier]'),
    ('Go to the paddock, and after going there, avoid the stables, the horses spook easy.',
     'F (near[paddock] & G !near[stables])'),
    ('Visit the bike rack before the gate, the bikes need counting.',
     'F near[gate] & (!near[gate] U near[bike_rack])'),
    ("Bring the tea to the table, I'm not fussy.",
     'F (near[tea] & F (pick[tea] & F (near[table] & F release[tea, table])))'),
    ('Could you go to the tractor or the quad bike? One of them, not fussed.',
     'F near[tractor] | F near[quad_bike]'),
    ('Go to the den, the robot should avoid the hall.', 'F near[den] & G !near[hall]'),
    ('Before anything else go to the nurse station; after that the linen closet.',
     'F (near[nurse_station] & F near[linen_closet])'),
    ('Hotel robot: room service cart first, then the ice machine.',
     'F (near[room_service_cart] & F near[ice_machine])'),
    # "it" in a phrase read again is still what it was the first time
    ('Go to the cabinet left of the sink, then the drawer under it.',
     'F (near[cabinet::isleftof(sink)] & F near[drawer::isbelow(cabinet::isleftof(sink))])'),
]


@pytest.mark.parametrize('instruction,gold', FOUND_LATE)
def test_readings_found_wrong_late(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_after_scope_conditional_reads_after_as_a_rule() -> None:
    from ltl_instruct.core.language.offline import OfflineTranslator
    from ltl_instruct.core.errors import TranslationError
    from ltl_instruct.core.spec import parse_formula
    t = OfflineTranslator(after_scope='conditional')
    got = t.translate('After going to the coop, avoid the garden.').formula
    assert equivalent(got, parse_formula('G (near[coop] -> X G !near[garden])')), got
    with pytest.raises(TranslationError):
        OfflineTranslator(after_scope='sometimes')


# Found on blind sets H and I (our own sentences for what they showed)
FOUND_ROUND_H = [
    # "while you carry it" (present tense) scopes the avoidance to the carrying, not after the drop
    ('Take the kettle to the counter and stay away from the cat while you carry it.',
     'F (near[kettle] & F (pick[kettle] & (!near[cat] U (near[counter] & F release[kettle, counter]))))'),
    ('Bring the trolley to the lift, and while you push it keep clear of the stairs.',
     'F (near[trolley] & F (pick[trolley] & (!near[stairs] U (near[lift] & F release[trolley, lift]))))'),
    # hesitations anywhere, once the corrections they mark have been read
    ('go to the uh supply room, um, then the office', 'F (near[supply_room] & F near[office])'),
    ('Go to the break room. Hm, no, the lounge.', 'F near[lounge]'),
    ('avoid the the stairs and go to the hall', 'F near[hall] & G !near[stairs]'),
    # a possessive keeps its s (no apostrophe); a number stays as written
    ("Go to the manager's office and then locker seven",
     'F (near[managers_office] & F near[locker_seven])'),
    ('go to dock 4', 'F near[dock_4]'),
    # spelling: a name typed twice, "than" for "then", a domain word on a tie, a long vowel slip
    ('Fly over the pier, then the marina. Keep off the beach on the way to the marnia.',
     'F (near[pier] & (!near[beach] U near[marina]))'),
    ('go to the shed, than the pond, and than the gate',
     'F (near[shed] & F (near[pond] & F near[gate]))'),
    ('go to the frige', 'F near[fridge]'),
    ('go to the maintenence room', 'F near[maintenance_room]'),
    # chat spelling and a reason said with no comma before it
    ('take the mugs 2 the sink pls its so messy',
     'F (near[mugs] & F (pick[mugs] & F (near[sink] & F release[mugs, sink])))'),
    ('go 2 the couch im so tired', 'F near[couch]'),
    # "once you have been to X, avoid Y" makes X a goal, as "after going to X" does
    ('Once you have been to the shed, keep away from the pond, then go to the gate.',
     'F (near[shed] & G !near[pond] & F near[gate])'),
    # a slip to a domain word the vocabulary lacks, a dropped double letter, "ping pong" kept
    ('go to the toastr', 'F near[toaster]'),
    ('pick up the remote controler', 'F (near[remote_controller] & F pick[remote_controller])'),
    ('stay away from the ping pong table', 'G !near[ping_pong_table]'),
    # remarks that leave the choice to the robot, said after the alternatives or an avoidance
    ('Go to the bench or the swing, whichever you get to first.', 'F near[bench] | F near[swing]'),
    ('go to the gym or the pool, either one works', 'F near[gym] | F near[pool]'),
    ('Land on the north pad or the south pad, and avoid the mast whichever one you go for.',
     '(F near[north_pad] | F near[south_pad]) & G !near[mast]'),
    # idioms: "go either to X or to Y", "mind X", "once, and only once", "N times minimum",
    # "more then once", "on your way over to", "clocked in at"
    ('head either to the porch or to the shed', 'F near[porch] | F near[shed]'),
    ('go to the sink and mind the cables the whole time', 'F near[sink] & G !near[cables]'),
    ('Stop at the kiosk once, and only once.',
     '!near[kiosk] U (near[kiosk] & (near[kiosk] W G !near[kiosk]))'),
    ('visit the mailbox 2 times minimum', 'F (near[mailbox] & F (!near[mailbox] & F near[mailbox]))'),
    ('do not enter the lab more then once', '!near[lab] W (near[lab] & (near[lab] W G !near[lab]))'),
    ('On your way over to the porch, keep clear of the hose.', '!near[hose] U near[porch]'),
    ('Go to the vault, but only once you have checked in at the front desk.',
     'F near[vault] & (!near[vault] U near[front_desk])'),
    # corrections: the name only (its place kept), the place only, one alternative, the whole choice
    ('Go to the green mug on the shelf. Actually make that the blue mug.',
     'F near[blue_mug::isabove(shelf)]'),
    ('Go to the bike behind the shed, sorry, in front of it.', 'F near[bike::isinfrontof(shed)]'),
    ('Find the lamp next to the sofa, uh, next to the piano I mean.', 'F near[lamp::isnextto(piano)]'),
    ('Go to the box under the desk. Hang on, it is on the desk, not under it.', 'F near[box::isabove(desk)]'),
    ('Go to the porch or the garage, actually not the garage, the shed.', 'F near[porch] | F near[shed]'),
    ('Go to the pool or the gym. Actually make that the gym or the sauna.', 'F near[gym] | F near[sauna]'),
    ('Go to the lift or the stairs - no, not the stairs, make it the ramp.', 'F near[lift] | F near[ramp]'),
    ('Go to the kiosk or the bench... actually just make it the bench.', 'F near[bench]'),
    # "the south ones", "lost and found", "the last 2", labelled lists, forms of address
    ('Fly over either the east solar rows or the west ones.',
     'F near[east_solar_rows] | F near[west_solar_rows]'),
    ('take the wallet to the lost and found', 'F (near[wallet] & F (pick[wallet] & F (near[lost_and_found] & '
     'F release[wallet, lost_and_found])))'),
    ('there is a mop, a bucket and a broom. go to either of the last 2', 'F near[bucket] | F near[broom]'),
    ('Towers A, B and C are on the hill. Inspect the middle one.', 'F near[tower_b]'),
    ('Gates 4, 5 and 6 - go to the last, then the first.', 'F (near[gate_6] & F near[gate_4])'),
    ('Would you go to the piano, dear?', 'F near[piano]'),
    # polite frames, "making your way", "meet me at", "maintain distance", "or else", "whatever you do"
    ('Would you be so kind as to take the vase to the hall table? I would be much obliged.',
     'F (near[vase] & F (pick[vase] & F (near[hall_table] & F release[vase, hall_table])))'),
    ('Would you be a dear and go to the pantry? And do keep away from the oven.',
     'F near[pantry] & G !near[oven]'),
    ('could you start making your way to the lobby', 'F near[lobby]'),
    ('meet me at the gate or the fountain', 'F near[gate] | F near[fountain]'),
    ('fly to the tower and maintain a safe distance from the cables', 'F near[tower] & G !near[cables]'),
    ('go to the red door, or else the blue one', 'F near[red_door] | F near[blue_door]'),
    ('go to the barn but whatever you do keep away from the bull', 'F near[barn] & G !near[bull]'),
    ('go to the shed, and when you are done there go to the porch', 'F (near[shed] & F near[porch])'),
    ('Put the cup either on the shelf or in the sink.',
     'F (near[cup] & F (pick[cup] & (F (near[shelf] & F release[cup, shelf]) | '
     'F (near[sink] & F release[cup, sink]))))'),
    ('The office, please, as quick as you can.', 'F near[office]'),
    # from blind set L: an event said with -ing, back and forth, "no more" after a count, "go sit by",
    # "X last", "grandma's sleeping" (is), "the microwave can wait", "tho"
    ('Go to the deck, but only after stopping at the porch.', 'F near[deck] & (!near[deck] U near[porch])'),
    ('Go back and forth between the sink and the stove twice.',
     'F (near[sink] & F (near[stove] & F (near[sink] & F near[stove])))'),
    ('Visit the printer exactly once, no more.',
     '!near[printer] U (near[printer] & (near[printer] W G !near[printer]))'),
    ('go sit by the fire', 'F near[fire]'),
    ('The hall first, then the den, and the attic last.', 'F (near[hall] & F (near[den] & F near[attic]))'),
    ("avoid the nursery, the baby's sleeping", 'G !near[nursery]'),
    ('The oven can wait: go there only after the sink.', 'F near[oven] & (!near[oven] U near[sink])'),
    ('the pond is off limits tho', 'G !near[pond]'),
    # from blind set M: "scratch that, X" replaces, "your first stop is", "need checking",
    # "wherever's clearer", "X after all", "as long as you never", "that's where I need you"
    ('Fly to the water tower. Scratch that, the grain silo.', 'F near[grain_silo]'),
    ('Bring the ladder to bay one. Scratch that, bay two.',
     'F (near[ladder] & F (pick[ladder] & F (near[bay_two] & F release[ladder, bay_two])))'),
    ('Your first stop is the lab. Your last stop is the lobby.', 'F (near[lab] & F near[lobby])'),
    ('Both the pump and the tank need checking.', 'F near[pump] & F near[tank]'),
    ('Land on the east pad or the west pad, wherever is clearer.', 'F near[east_pad] | F near[west_pad]'),
    ('Go to the desk. No, the door. Sorry, the desk after all.', 'F near[desk]'),
    ('Fly to the weir, as long as you never go over the island.', 'F near[weir] & G !near[island]'),
    ("The fume cupboard behind the sink, that's where I need you.", 'F near[fume_cupboard::isbehind(sink)]'),
    # the delivery an "after dropping off X" names; "while carrying anything" holds for every delivery;
    # "drop the avoidance part"; "the dog's outside" (is)
    ('bring the mug to the sink and then the towel to the rail. after dropping off the mug, keep away '
     'from the oven',
     'F (near[mug] & F (pick[mug] & F (near[sink] & F (release[mug, sink] & G !near[oven] & '
     'F (near[towel] & F (pick[towel] & F (near[rail] & F release[towel, rail])))))))'),
    ('Take the pen and the stapler to the desk, and avoid the printer while you are carrying anything.',
     'F (near[pen] & F (pick[pen] & (!near[printer] U (near[desk] & F release[pen, desk])))) & '
     'F (near[stapler] & F (pick[stapler] & (!near[printer] U (near[desk] & F release[stapler, desk]))))'),
    ('Take the box to the van and avoid the pond while carrying it. Actually, drop the avoidance part.',
     'F (near[box] & F (pick[box] & F (near[van] & F release[box, van])))'),
    ("Put the milk in the fridge and keep clear of the dog while carrying it. Oh wait, I meant the cat, "
     "the dog's outside.",
     'F (near[milk] & F (pick[milk] & (!near[cat] U (near[fridge] & F release[milk, fridge]))))'),
    # "X before you go to Y" is "Y only after X", as "X before Y" (the route order for drone-planning)
    ('Stop at the kiosk before you go to the gate.', 'F near[gate] & (!near[gate] U near[kiosk])'),
    # "behind X and next to Y" describes one thing; "after to" for "then"; "should you", "beforehand"
    ('Find the cart that is behind the shed and next to the hose.',
     'F near[cart::isbehind(shed)::isnextto(hose)]'),
    ('Go first to the bakery, after to the bank.', 'F (near[bakery] & F near[bank])'),
    ('Should you go into the lab at all, stop at the sink beforehand.', '!near[lab] W near[sink]'),
    # "no no, the other one, the X"; "not twice, three times"
    ('Go to the blue gate. No no, the other one, the red gate.', 'F near[red_gate]'),
    ('Go to the bank and then the post office, but only after the cash machine.',
     'F (near[bank] & F near[post_office]) & (!near[bank] U near[cash_machine]) & '
     '(!near[post_office] U near[cash_machine])'),
    # lists of things described as "one by X, one under Y"; a count before a comma list names it
    ('There are three mats: one by the door, one under the sink and one behind the tub. Go to the second.',
     'F near[mat::isbelow(sink)]'),
    ('There are two vans in the yard, a white van and a red van. Go to the second one.', 'F near[red_van]'),
    ('There are two delivery vans: one by the gate, one behind the shed. Go to the second.',
     'F near[delivery_van::isbehind(shed)]'),
    ('There are three mugs: a red one by the sink, a blue one on the shelf and a green one by the kettle. '
     'Bring the blue one to the table.',
     'F (near[blue_mug::isabove(shelf)] & F (pick[blue_mug::isabove(shelf)] & F (near[table] & '
     'F release[blue_mug::isabove(shelf), table])))'),
    # corrections: "not the pot, the pan" (its place kept), "no not X, Y", "instead of either",
    # "the yellow one" for the thing that had a colour
    ('Take the jug on the table to the sink - wait, not the jug, the vase.',
     'F (near[vase::isabove(table)] & F (pick[vase::isabove(table)] & F (near[sink] & '
     'F release[vase::isabove(table), sink])))'),
    ('bring the rug to the hall, no not the hall, the porch',
     'F (near[rug] & F (pick[rug] & F (near[porch] & F release[rug, porch])))'),
    ('Go to the pond or the pier. Actually, make it the boathouse instead of either.', 'F near[boathouse]'),
    ('bring the red cup to the kitchen, wait no, the blue one',
     'F (near[blue_cup] & F (pick[blue_cup] & F (near[kitchen] & F release[blue_cup, kitchen])))'),
    # a made-up agent noun one letter from a common word; "sanding" stays
    ("put the chalk on the techer's desk",
     'F (near[chalk] & F (pick[chalk] & F (near[teachers_desk] & F release[chalk, teachers_desk])))'),
    ('go to the sanding station', 'F near[sanding_station]'),
    # "carry it to X and drop it there" is one delivery; ", fly it up to X" carries it
    ('pick up the box, carry it to the shed and drop it there',
     'F (near[box] & F (pick[box] & F (near[shed] & F release[box, shed])))'),
    ('Pick up the parcel, fly it up to the roof and leave it there.',
     'F (near[parcel] & F (pick[parcel] & F (near[roof] & F release[parcel, roof])))'),
    # the leg between two goals; "from the moment you reach X"; "once it's down"
    ('Go to the lobby, then the lift. Between those two, stay clear of the fountain.',
     'F (near[lobby] & (!near[fountain] U near[lift]))'),
    ('Go to the desk, then the door, then the lab. Between the desk and the door, keep away from the bin.',
     'F (near[desk] & (!near[bin] U (near[door] & F near[lab])))'),
    ('Go to the kiosk. From the moment you have been there, stay away from the pond. Then go to the gate.',
     'F (near[kiosk] & G !near[pond] & F near[gate])'),
    ('go from the second floor to the purple room', 'F (near[second_floor] & F near[purple_room])'),
    ("Put the mug on the shelf, and once it's down stay away from the sink.",
     'F (near[mug] & F (pick[mug] & F (near[shelf] & F (release[mug, shelf] & G !near[sink]))))'),
    # "and the door after that" is the next goal, not an unordered one
    ('go to the sofa, and the door after that', 'F (near[sofa] & F near[door])'),
    # "off the shelf": it is on the shelf
    ('take the book off the shelf and put it on the desk',
     'F (near[book::isabove(shelf)] & F (pick[book::isabove(shelf)] & F (near[desk] & '
     'F release[book::isabove(shelf), desk])))'),
    # "backwards" after a list; "the one I named first"
    ('visit the shed, the barn and the silo backwards', 'F (near[silo] & F (near[barn] & F near[shed]))'),
    ('the oven, the sink and the fridge. go to the one I named first', 'F near[oven]'),
    ('Check the tank twice. No wait, not twice, three times.',
     'F (near[tank] & F (!near[tank] & F (near[tank] & F (!near[tank] & F near[tank]))))'),
]


@pytest.mark.parametrize('instruction,gold', FOUND_ROUND_H)
def test_readings_found_on_blind_sets_h_and_i(instruction: str, gold: str) -> None:
    _check(instruction, gold)


# Found on blind sets P-S (a family robot, a hospital and warehouse, non-native speakers, voice
# transcripts); each sentence here is our own, written for the construction.
FOUND_ROUND_P = [
    # a pause inside a phrase corrects nothing; the word said again around it is read once
    ('Go to the shed, then the, um, the greenhouse.', 'F (near[shed] & F near[greenhouse])'),
    ('I need you at the, uh, the side gate.', 'F near[side_gate]'),
    ('Visit the attic and then, er, the cellar.', 'F (near[attic] & F near[cellar])'),
    ('Avoid the, um, the radiator and go to the sofa.', 'F near[sofa] & G !near[radiator]'),
    # a remark that leaves the choice to the robot, with no comma before it
    ('go to the bench or the swing either one is fine', 'F near[bench] | F near[swing]'),
    ('head to the lamp by the sofa or the lamp by the desk i do not mind which',
     'F near[lamp::isnextto(sofa)] | F near[lamp::isnextto(desk)]'),
    ('Go to the red door or the blue door, what you prefer.', 'F near[red_door] | F near[blue_door]'),
    ('Check the pantry and the cellar, no matter which order.', 'F near[pantry] & F near[cellar]'),
    ('Stop at the east gate or the west gate, you choose.', 'F near[east_gate] | F near[west_gate]'),
    # "after" alone for "then", and "at the end" for "finally"
    ('Go to the gym and after to the pool.', 'F (near[gym] & F near[pool])'),
    ('Visit the bakery and after the florist.', 'F (near[bakery] & F near[florist])'),
    ('Fly over the barn and after land on the silo.', 'F (near[barn] & F near[silo])'),
    ('Go to the hall, then to the study and at the end to the porch.',
     'F (near[hall] & F (near[study] & F near[porch]))'),
    ('After the bakery, go to the bank.', 'F (near[bakery] & F near[bank])'),
    # a route said as a thing to do, done twice
    ('Walk the loop from the porch to the mailbox twice in a row.',
     'F (near[porch] & F (near[mailbox] & F (near[porch] & F near[mailbox])))'),
    ('Do the garage to gate run twice back to back.',
     'F (near[garage] & F (near[gate] & F (near[garage] & F near[gate])))'),
    ('Go from the dock to the shed, then repeat the same route once more.',
     'F (near[dock] & F (near[shed] & F (near[dock] & F near[shed])))'),
    # the carrying said other ways
    ('Bring the tray to the bar, and when you carry it, stay away from the stairs.',
     'F (near[tray] & F (pick[tray] & (!near[stairs] U (near[bar] & F release[tray, bar]))))'),
    ('Pick up the crate and drop it at the dock; during the carrying, avoid the ramp.',
     'F (near[crate] & F (pick[crate] & (!near[ramp] U (near[dock] & F release[crate, dock]))))'),
    ('Wheel the cart over to the lift.',
     'F (near[cart] & F (pick[cart] & F (near[lift] & F release[cart, lift])))'),
    ('Recycle the jam jar.',
     'F (near[jam_jar] & F (pick[jam_jar] & F (near[recycling_bin] & F release[jam_jar, recycling_bin])))'),
    # corrections said without commas, counts corrected, the rest of the instruction kept
    ('take the mug to the desk sorry to the shelf',
     'F (near[mug] & F (pick[mug] & F (near[shelf] & F release[mug, shelf])))'),
    ('go to the stool no wait the bench', 'F near[bench]'),
    ('circle the tower two times no make it three',
     'F (near[tower] & F (!near[tower] & F (near[tower] & F (!near[tower] & F near[tower]))))'),
    ('Visit the well twice, no, make that three times, then go to the barn.',
     'F (near[well] & F (!near[well] & F (near[well] & F (!near[well] & F (near[well] & F near[barn])))))'),
    ('Bring the blue cup to the sink, ehm, the green cup I mean.',
     'F (near[green_cup] & F (pick[green_cup] & F (near[sink] & F release[green_cup, sink])))'),
    # what to avoid corrected in a cleft, the scope kept
    ('Go to the den and keep away from the heater. Actually forget the heater, it is the fan you should '
     'avoid.',
     'F near[den] & G !near[fan]'),
    ('Carry the vase to the shelf and avoid the dog while you carry it - no wait, avoid the cat.',
     'F (near[vase] & F (pick[vase] & (!near[cat] U (near[shelf] & F release[vase, shelf]))))'),
    ('Go to the lamp on the table. Sorry, I wanted to say the lamp under the table.',
     'F near[lamp::isbelow(table)]'),
    # a person's things are named without the person; "one's" is "one is"
    ("Stay away from my sister's guitar and go to the sofa.", 'F near[sofa] & G !near[guitar]'),
    ("Land on the left roof or the right roof, whichever one's free.",
     'F near[left_roof] | F near[right_roof]'),
    # non-native word orders and words
    ('Go to the porch and avoid always the wet paint.', 'F near[porch] & G !near[wet_paint]'),
    ("Visit the shop, and don't approach the bins nor the crates.",
     'F near[shop] & G !near[bins] & G !near[crates]'),
    ('Go to the lobby at maximum one time.', '!near[lobby] W (near[lobby] & (near[lobby] W G !near[lobby]))'),
    ('Check the pump minimum two times.', 'F (near[pump] & F (!near[pump] & F near[pump]))'),
    ('Visit the lab two times exactly, no more and no less.',
     '!near[lab] U (near[lab] & (near[lab] U (!near[lab] & (!near[lab] U (near[lab] & '
     '(near[lab] W G !near[lab]))))))'),
    ('Only when you have been to the sink, you can go to the stove.',
     'F near[stove] & (!near[stove] U near[sink])'),
    ('Only after the gate, go to the barn.', 'F near[barn] & (!near[barn] U near[gate])'),
    ('Drone, fly until the water tower and hover there.', 'F near[water_tower]'),
    ('Go to the chair which is standing at the right side of the window.',
     'F near[chair::isrightof(window)]'),
    ("Never, ever go near the grill. Ever.", 'G !near[grill]'),
    # "bring me" and where the person says they are: the delivery ends there
    ("Bring me the charger. I'm on the sofa.",
     'F (near[charger] & F (pick[charger] & F (near[sofa] & F release[charger, sofa])))'),
    ("I'm at the desk, get me the stapler or the tape",
     'F (near[stapler] & F (pick[stapler] & F (near[desk] & F release[stapler, desk]))) | '
     'F (near[tape] & F (pick[tape] & F (near[desk] & F release[tape, desk])))'),
    ('Bring me the cup.', 'F (near[cup] & F pick[cup])'),
    # where a thing is, said as a statement, describes the thing "it" then names
    ('The mug is on the windowsill; go over to it.', 'F near[mug::isabove(windowsill)]'),
    ('my glasses should be next to the lamp, go to them', 'F near[glasses::isnextto(lamp)]'),
    ('Under the bench there is a ball; go find it.', 'F near[ball::isbelow(bench)]'),
    # the leg of a route named as a stretch, a leg, or the getting there
    ('Go to the porch, then walk to the gate, and on that stretch keep away from the bins.',
     'F (near[porch] & (!near[bins] U near[gate]))'),
    ('After inspecting the roof, fly to the mast; the antenna must be avoided on that leg.',
     'F (near[roof] & (!near[antenna] U near[mast]))'),
    ("Go to the barn, and don't cut through the paddock to get there.", '!near[paddock] U near[barn]'),
    ('go to the shed and dont bump into the mower getting there', '!near[mower] U near[shed]'),
    # an order said as what has to come first, fragments, waiting
    ('Go to the pool, but the shower has to come first.', 'F near[pool] & (!near[pool] U near[shower])'),
    ('Kitchen first, garage after that.', 'F (near[kitchen] & F near[garage])'),
    ("The garden can wait until you've been to the shed.", '!near[garden] U near[shed]'),
    ("Once you've been to the tap, and not before, go to the trough.",
     'F near[trough] & (!near[trough] U near[tap])'),
    ('Wait at the bench or the swing.', 'F near[bench] | F near[swing]'),
    ('Grandpa needs you at the garage door.', 'F near[garage_door]'),
    ('Take yourself over to the study.', 'F near[study]'),
    # counts said as passes, visits needed, a single time
    ('Make two passes over the pond.', 'F (near[pond] & F (!near[pond] & F near[pond]))'),
    ('The hen house needs three visits at minimum.',
     'F (near[hen_house] & F (!near[hen_house] & F (near[hen_house] & F (!near[hen_house] & '
     'F near[hen_house]))))'),
    ('Stop at the gate a single time.', '!near[gate] U (near[gate] & (near[gate] W G !near[gate]))'),
    # where a thing belongs is a delivery; rules that hold the whole time, or from an event on
    ('The scissors go back in the drawer.',
     'F (near[scissors] & F (pick[scissors] & F (near[drawer] & F release[scissors, drawer])))'),
    ('Go to the den. Also, the fireplace is off limits the whole time.', 'F near[den] & G !near[fireplace]'),
    ("Visit the gate, then the barn; the pond is off limits from the moment you've been at the gate.",
     'F (near[gate] & G !near[pond] & F near[barn])'),
    # corrections that keep the rest of the step, swap a goal, or give a reason first
    ('bring the red cup to the table. no, bring the blue cup instead',
     'F (near[blue_cup] & F (pick[blue_cup] & F (near[table] & F release[blue_cup, table])))'),
    ('Go to the bank, then the shop, then home. Actually, swap the shop for the bakery.',
     'F (near[bank] & F (near[bakery] & F near[home]))'),
    ("Put the shirt in the washer. Actually it's been washed already, put it in the closet.",
     'F (near[shirt] & F (pick[shirt] & F (near[closet] & F release[shirt, closet])))'),
    # a rule that binds one alternative only, named as "it" or as "the X one"
    ("Go to the pond or the orchard. If it's the orchard, keep away from the hives.",
     'F near[pond] | F near[orchard] & G !near[hives]'),
    ('Head to the east stairs or the west stairs, but if you go with the west one, avoid the lift.',
     'F near[east_stairs] | F near[west_stairs] & G !near[lift]'),
    # avoiding something until you get there: on the way there
    ('fly to the mast but stay away from the wires until you get there', '!near[wires] U near[mast]'),
    # two things of one kind told apart by a word before the shared noun
    ('Go to the north or the south gate, whichever is open.', 'F near[north_gate] | F near[south_gate]'),
    ('Visit the upstairs and the downstairs bathroom.',
     'F near[upstairs_bathroom] & F near[downstairs_bathroom]'),
    ('Take the white towel to the bath - sorry, the cream one.',
     'F (near[cream_towel] & F (pick[cream_towel] & F (near[bath] & F release[cream_towel, bath])))'),
    # "it" in a thing's own relation is what the last thing was placed by, not that thing
    ('Go to the stool left of the bar or the stool right of it.',
     'F near[stool::isleftof(bar)] | F near[stool::isrightof(bar)]'),
    # a held thing named again in a rule about it; carrying rules over a choice or a list of deliveries
    ("Collect the blood kit and take it to the ward. Don't go to the ward before you have the kit.",
     'F (near[blood_kit] & F (pick[blood_kit] & F (near[ward] & F release[blood_kit, ward]))) & '
     '(!near[ward] U pick[blood_kit])'),
    ('Bring either the mop or the broom to the hall; keep clear of the rug while you carry it.',
     'F (near[mop] & F (pick[mop] & (!near[rug] U (near[hall] & F release[mop, hall])))) | '
     'F (near[broom] & F (pick[broom] & (!near[rug] U (near[hall] & F release[broom, hall]))))'),
    ('Take the cup and the bowl to the sink, and avoid the cat while carrying them.',
     'F (near[cup] & F (pick[cup] & (!near[cat] U (near[sink] & F release[cup, sink])))) & '
     'F (near[bowl] & F (pick[bowl] & (!near[cat] U (near[sink] & F release[bowl, sink]))))'),
    # a correction marked as one; a pause before a new step corrects nothing
    ('Put the plates in the cupboard - correction, put them on the table.',
     'F (near[plates] & F (pick[plates] & F (near[table] & F release[plates, table])))'),
    ('Go to the hall, and then after the hall, um, go to the porch.', 'F (near[hall] & F near[porch])'),
    # counts said before the place or with what follows the last visit
    ('Go exactly one time to the kiosk, after go to the gate.',
     '(!near[kiosk] U (near[kiosk] & (near[kiosk] W G !near[kiosk]))) & F (near[kiosk] & F near[gate])'),
    ('Visit the well at least two times, and after the second time go to the barn.',
     'F (near[well] & F (!near[well] & F (near[well] & F near[barn])))'),
    ('Check the pump at least twice during the round.', 'F (near[pump] & F (!near[pump] & F near[pump]))'),
    # headings and trailing remarks
    ('Go to the lobby. Important: never go near the fountain.', 'F near[lobby] & G !near[fountain]'),
    ('check the sink before the stove i need both checked', 'F near[stove] & (!near[stove] U near[sink])'),
    ('Go to the den or the study; only one of the two, never both of them.',
     'F near[den] & G !near[study] | F near[study] & G !near[den]'),
    # a list of three with "and then" before the last: one after the other
    ('check the boiler, the meter, and then the tap', 'F (near[boiler] & F (near[meter] & F near[tap]))'),
    # list positions said as numbers, as "the one I mentioned last", "whatever comes after", "the outer two"
    ('In the shed there is a rake, a spade and a hoe; check number two and then number three.',
     'F (near[spade] & F near[hoe])'),
    ('I bought apples, pears and plums. Put whichever I mentioned first in the bowl.',
     'F (near[apples] & F (pick[apples] & F (near[bowl] & F release[apples, bowl])))'),
    ("Along the hall there's a clock, a mirror and a vase. Go to whatever comes after the mirror.",
     'F near[vase]'),
    ("On the shelf there's a jar, a tin and a box. Visit the outer two.", 'F near[jar] & F near[box]'),
    # what the person needs where, where they want the robot, what they left
    ('I need both the drill and the saw in the shed.',
     'F (near[drill] & F (pick[drill] & F (near[shed] & F release[drill, shed]))) & '
     'F (near[saw] & F (pick[saw] & F (near[shed] & F release[saw, shed])))'),
    ('The bench is where I want you.', 'F near[bench]'),
    ('I left my keys somewhere around here, can you find them?', 'F near[keys]'),
    # a delivery said twice, across sentences; "throw it out"
    ('Can you get rid of the peel? Just throw it out.',
     'F (near[peel] & F (pick[peel] & F (near[trash_can] & F release[peel, trash_can])))'),
    # drone routes: a flyover of either, a heading, a landing at the end, what is in the grip
    ('Do a flyover of either the dam or the weir, and finish by landing at the hut.',
     'F ((near[dam] | near[weir]) & F near[hut])'),
    ('Route: the quarry, then the mill, ending with a landing at the yard.',
     'F (near[quarry] & F (near[mill] & F near[yard]))'),
    ('Fetch the parcel and drop it off at the depot, keeping away from the mast while it is in your grip.',
     'F (near[parcel] & F (pick[parcel] & (!near[mast] U (near[depot] & F release[parcel, depot]))))'),
    # orders chained with any verb; several things off limits; scenes said as what you look at
    ('Check the tap before the pump, and the pump before the tank.',
     'F near[pump] & (!near[pump] U near[tap]) & F near[tank] & (!near[tank] U near[pump])'),
    ('Go to the den. The stove and the heater are off limits.',
     'F near[den] & G !near[stove] & G !near[heater]'),
    ("I'm looking at a gate, a fence and a shed. Go to the second one.", 'F near[fence]'),
    ('I lost my scarf somewhere around here. Go find it.', 'F near[scarf]'),
    # the leg from one place to the next; until you arrive; one of two, away from the other
    ('Go to the barn. When you leave the barn for the silo, keep away from the pond.',
     'F (near[barn] & (!near[pond] U near[silo]))'),
    ('Drive to the depot and keep away from the crane until you arrive.', '!near[crane] U near[depot]'),
    ('Go to either the left door or the right door - just one of them, stay away from the other.',
     'F near[left_door] & G !near[right_door] | F near[right_door] & G !near[left_door]'),
    ('Either check the tap first and then the hose, or do it the other way round.',
     'F (near[tap] & F near[hose]) | F (near[hose] & F near[tap])'),
    ('Hall, den, porch: go to the last one first, and after it the first one.',
     'F (near[porch] & F near[hall])'),
    ('Climb to the roof, hold there for a bit, then drop down to the yard.', 'F (near[roof] & F near[yard])'),
    # "your" for "you're"; "only go to X once you've": only after; one of a kind, named after a comma
    ('bring the mug to the desk and dont go near the cat while your carrying it',
     'F (near[mug] & F (pick[mug] & (!near[cat] U (near[desk] & F release[mug, desk]))))'),
    ("Visit the lab and then the gym, but only go to the lab once you've been to the office.",
     'F (near[lab] & F near[gym]) & (!near[lab] U near[office])'),
    ('Check one of the sinks, the left sink or the right sink, not both.',
     'F near[left_sink] & G !near[right_sink] | F near[right_sink] & G !near[left_sink]'),
    ("Go to the porch, and from there to the gate don't go near the hedge.",
     'F (near[porch] & (!near[hedge] U near[gate]))'),
    ('Take the box and put it either on the shelf or in the bin.',
     'F (near[box] & F (pick[box] & (F (near[shelf] & F release[box, shelf]) | '
     'F (near[bin] & F release[box, bin]))))'),
    # possessives keep their s
    ("Go to the nurse's office.", 'F near[nurses_office]'),
    # lists in turn; order said as what you have to do first, or as waiting
    ('Go to the gate, the barn, the silo and finally the house.',
     'F (near[gate] & F (near[barn] & F (near[silo] & F near[house])))'),
    ('Go to the study, though you have to visit the hall first.',
     'F near[study] & (!near[study] U near[hall])'),
    ("Wait until you've been to the porch before going into the hall.",
     'F near[hall] & (!near[hall] U near[porch])'),
    ('Keep out of the attic till you have visited both the den and the loft.',
     '(!near[attic] U near[den]) & (!near[attic] U near[loft])'),
    ("You can go to the porch, but not until you've been to both the shed and the gate.",
     'F near[porch] & (!near[porch] U near[shed]) & (!near[porch] U near[gate])'),
    # scopes said other ways
    ('En route to the shed, keep away from the pond.', '!near[pond] U near[shed]'),
    ('Go to the sofa without ever getting close to the heater.', 'F near[sofa] & G !near[heater]'),
    ('Get to the hall. From then on, the stairs are off limits.', 'F (near[hall] & G !near[stairs])'),
    ("Grab the bag and take it to the car. Once it's in your hands, keep away from the dog.",
     'F (near[bag] & F (pick[bag] & G !near[dog] & F (near[car] & F release[bag, car])))'),
    # choices and counts said other ways
    ('Go to one of the two doors, the red door or the blue door, but not to both.',
     'F near[red_door] & G !near[blue_door] | F near[blue_door] & G !near[red_door]'),
    ('Go to the desk; you can stop at the fridge, but never more than once.',
     'F near[desk] & (!near[fridge] W (near[fridge] & (near[fridge] W G !near[fridge])))'),
    ('Go to the den or the hall - nah, make it both.', 'F near[den] & F near[hall]'),
    # deliveries onto things; corrections of a place inside a phrase, or of a colour
    ('Move the lamp onto the desk.',
     'F (near[lamp] & F (pick[lamp] & F (near[desk] & F release[lamp, desk])))'),
    ('Put the towel on the rail, wait, not the rail, the hook.',
     'F (near[towel] & F (pick[towel] & F (near[hook] & F release[towel, hook])))'),
    ('go to the red bin, sry wrong colour, the blue one', 'F near[blue_bin]'),
    # reasons that name what keeps a person busy; "X is next"; "the first one's where I need you"
    ("Go in the study at most once, mum's on a call.",
     '!near[study] W (near[study] & (near[study] W G !near[study]))'),
    ("the shed's next, but not until you've visited the gate", 'F near[shed] & (!near[shed] U near[gate])'),
    ("There's a bench, a swing and a slide. The first one's where I need you - don't go near the others.",
     'F near[bench] & G !near[swing] & G !near[slide]'),
    # inverted and run-on word orders
    ('Bring at my desk the stapler or the tape, one of them is enough.',
     'F (near[stapler] & F (pick[stapler] & F (near[desk] & F release[stapler, desk]))) | '
     'F (near[tape] & F (pick[tape] & F (near[desk] & F release[tape, desk])))'),
    ('Go to the bank and after to the shop, or otherwise go to the park.',
     'F (near[bank] & F near[shop]) | F near[park]'),
    ('on your way to the shed um steer clear of the pond', '!near[pond] U near[shed]'),
    # things named with "stand"; legs said as stretches or "going from A to B"; "though you need not go in"
    ('go to the coat stand next to the door', 'F near[coat_stand::isnextto(door)]'),
    ('Go to the gate, then the barn, and on the stretch from the gate to the barn steer clear of the pond.',
     'F (near[gate] & (!near[pond] U near[barn]))'),
    ('start at the desk then head to the lift, and keep away from the plant going from the desk to the lift',
     'F (near[desk] & (!near[plant] U near[lift]))'),
    ("Only enter the attic after visiting the hall, though you don't have to go into the attic at all.",
     '!near[attic] W near[hall]'),
    # what people are doing, and why, asks nothing of the robot
    ('Could you go to the bench, please? My grandmother is resting there after the long walk.',
     'F near[bench]'),
    ('Visit the orchids and keep clear of the fountain throughout, because the floor around it was waxed.',
     'F near[orchids] & G !near[fountain]'),
    # polite and roundabout ways of asking
    ("I'd be very grateful if you went over to the lost property cupboard.",
     'F near[lost_property_cupboard]'),
    ("I'd rather you didn't reach the shelf before you've stopped at the rack.", '!near[shelf] U near[rack]'),
    ("Keep away from the pond; what I need is for you to get to the shed.", 'F near[shed] & G !near[pond]'),
    ("Go to the gift shop, making sure you've checked the ticket office before that.",
     'F near[gift_shop] & (!near[gift_shop] U near[ticket_office])'),
    ('nip out through the side door and then carry on to the car park',
     'F (near[side_door] & F near[car_park])'),
    ('Head for the hall, and steer round the exhibition.', 'F near[hall] & G !near[exhibition]'),
    ('Keep your distance from the pallets and go to the bay.', 'F near[bay] & G !near[pallets]'),
    ('Please give the hose a wide berth and go over to the pond.', 'F near[pond] & G !near[hose]'),
    ("Go to the garden, and don't stop at the chimes more than once in total.",
     'F near[garden] & (!near[chimes] W (near[chimes] & (near[chimes] W G !near[chimes])))'),
    # "A and B in any order, then C": C after both, so one of the two orders, then C
    ('Stop by the kiosk and the fountain, any order is fine, and then come to the lobby.',
     'F (near[kiosk] & F (near[fountain] & F near[lobby])) | '
     'F (near[fountain] & F (near[kiosk] & F near[lobby]))'),
    # lists said without commas
    ('i see a mug a plate and a bowl. bring the second one to the sink',
     'F (near[plate] & F (pick[plate] & F (near[sink] & F release[plate, sink])))'),
    ('bring the cup the plate and the bowl to the sink',
     'F (near[cup] & F (pick[cup] & F (near[sink] & F release[cup, sink]))) & '
     'F (near[plate] & F (pick[plate] & F (near[sink] & F release[plate, sink]))) & '
     'F (near[bowl] & F (pick[bowl] & F (near[sink] & F release[bowl, sink])))'),
    # the order dropped by a correction; "but hit A and B first, any order"
    ('Go to the gate before the barn. Hmm, never mind the order, just visit both.',
     'F near[gate] & F near[barn]'),
    ('Go to the loft only after the hall. Hmm, drop that condition, just go to the loft.', 'F near[loft]'),
    ('go to the cot but hit the table and the bin first, any order',
     'F near[cot] & (!near[cot] U near[table]) & (!near[cot] U near[bin])'),
    # a delivery "without ever" going near something: never, not only while carrying
    ('Put the cups in the sink without ever going near the cat.',
     'F (near[cups] & F (pick[cups] & F (near[sink] & F release[cups, sink]))) & G !near[cat]'),
    # what people do and how things are, said before or after the request
    ('Customers keep asking about the price. Go to the till.', 'F near[till]'),
    ('Go on to the vault, where the archivist is waiting with a flask of tea.', 'F near[vault]'),
    # the goal that comes last
    ('Visit the shed and the barn, and go to the gate last.',
     'F near[shed] & F near[barn] & F near[gate] & (!near[gate] U near[shed]) & (!near[gate] U near[barn])'),
    ('Visit the shed, the barn and the gate. The gate is your last stop.',
     'F near[shed] & F near[barn] & F near[gate] & (!near[gate] U near[shed]) & (!near[gate] U near[barn])'),
    # names with "of"; a stop on the way; fragments in turn; things thrown out, needing to go, tidied away
    ('Could you head over to the chest of drawers?', 'F near[chest_of_drawers]'),
    ('Head up to the loft, but swing by the bathroom on the way.', 'F (near[bathroom] & F near[loft])'),
    ('shed first, pond second, gate last', 'F (near[shed] & F (near[pond] & F near[gate]))'),
    ('Can you throw the old magazine out?',
     'F (near[old_magazine] & F (pick[old_magazine] & F (near[trash_can] & '
     'F release[old_magazine, trash_can])))'),
    ('The vase on the shelf needs to go to the table.',
     'F (near[vase::isabove(shelf)] & F (pick[vase::isabove(shelf)] & F (near[table] & '
     'F release[vase::isabove(shelf), table])))'),
    ('tidy the books back into the crate',
     'F (near[books] & F (pick[books] & F (near[crate] & F release[books, crate])))'),
    # counts said as stops, "once - exactly once", "no more"; what is dumped; the drone kept clear
    ('Make at least two stops at the gate.', 'F (near[gate] & F (!near[gate] & F near[gate]))'),
    ('Only go to the shed once - exactly once - and afterwards head to the gate.',
     '(!near[shed] U (near[shed] & (near[shed] W G !near[shed]))) & F (near[shed] & F near[gate])'),
    ('Take the bag out to the bin. After you have dumped it, do not go near the hall.',
     'F (near[bag] & F (pick[bag] & F (near[bin] & F (release[bag, bin] & G !near[hall]))))'),
    ('Head for the mast, and keep the drone clear of the wires.', 'F near[mast] & G !near[wires]'),
    # an avoidance taken back "about" it; the way to a goal named by its last word
    ("Go to the den, then the hall, and don't go near the oven. Actually, forget about the oven.",
     'F (near[den] & F near[hall])'),
    ("Fly over the maze, then go to the roof deck, but don't go over the panels on your way to the deck.",
     'F (near[maze] & (!near[panels] U near[roof_deck]))'),
    # more ways of saying where a thing is, counts, scopes and choices
    ('There should be a towel on the rail - go to it.', 'F near[towel::isabove(rail)]'),
    ('Head to the shed after stopping at the tap - and stop there only the one time.',
     '(!near[tap] U (near[tap] & (near[tap] W G !near[tap]))) & F (near[tap] & F near[shed])'),
    ('Head to the hall. You can stop at the fridge if you want, but only once at most.',
     'F near[hall] & (!near[fridge] W (near[fridge] & (near[fridge] W G !near[fridge])))'),
    ('Wait for me by the garden gate.', 'F near[garden_gate]'),
    ('Both the lamp and the desk need a visit, whichever first.', 'F near[lamp] & F near[desk]'),
    ("Visit the sofa, and don't brush against the vase at any point.", 'F near[sofa] & G !near[vase]'),
    ('Head down to the cellar, though you have to hit the switch before you set foot there.',
     'F near[cellar] & (!near[cellar] U near[switch])'),
    ("Go to the bench, but make sure you've hit both the tap and the shed first.",
     'F near[bench] & (!near[bench] U near[tap]) & (!near[bench] U near[shed])'),
    ('Do the pool then the sauna, or the sauna then the pool - your call.',
     'F (near[pool] & F near[sauna]) | F (near[sauna] & F near[pool])'),
    ('The ball rolled behind the sofa. Go to it.', 'F near[ball::isbehind(sofa)]'),
    ('Cereal box back into the cupboard, please.',
     'F (near[cereal_box] & F (pick[cereal_box] & F (near[cupboard] & F release[cereal_box, cupboard])))'),
    # a rule after a dash is never a remark about people; "I just need you at"; "where did X end up"
    ('Find the mop - the baby gate is strictly off limits.', 'F near[mop] & G !near[baby_gate]'),
    ('Stay away from the easel; I just need you at the sink.', 'F near[sink] & G !near[easel]'),
    ("where'd the remote end up? go find it", 'F near[remote]'),
    ('where did I leave my keys? go look for them', 'F near[keys]'),
    # a stop added between the last two
    ('Go to the shed, then the gate. Wait, stop at the well in between.',
     'F (near[shed] & F (near[well] & F near[gate]))'),
    # typos in long words the word list lacks or spells one letter apart
    ('Go to the elevetor.', 'F near[elevator]'),
    ('Check the fire extinguiser.', 'F near[fire_extinguisher]'),
    ('Put the juice in the refridgerator.',
     'F (near[juice] & F (pick[juice] & F (near[refrigerator] & F release[juice, refrigerator])))'),
    ('Throw away the cartons.',
     'F (near[cartons] & F (pick[cartons] & F (near[trash_can] & F release[cartons, trash_can])))'),
]


@pytest.mark.parametrize('instruction,gold', FOUND_ROUND_P)
def test_readings_found_on_blind_sets_p_to_s(instruction: str, gold: str) -> None:
    _check(instruction, gold)

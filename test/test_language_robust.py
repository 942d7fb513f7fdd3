"""Offline translator on language its rules were not written for: chatter, unknown verbs, typos.

Every sentence here was written for these tests. Each case checks the formula on automata
and, where the translator left words out or read a word its own way, that the notes say so
(the person sees the notes before the robot moves).
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.errors import TranslationError
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.language.spelling import Speller
from ltl_instruct.core.spec import parse_formula
from translation_cases import RULES, T, check_translation as _check


UNKNOWN_VERBS = [
    ('Zip over to the printer, then the water cooler.', 'F (near[printer] & F near[water_cooler])'),
    ('Scramble to the third landing.', 'F near[third_landing]'),
    ('Descend into the basement and then the boiler room.', 'F (near[basement] & F near[boiler_room])'),
    ('Cruise past the fountain.', 'F near[fountain]'),
    ('Hover above the blue tarp next to the barn.', 'F near[blue_tarp::isnextto(barn)]'),
    ('Tuck the blanket into the laundry basket.',
     'F (near[blanket] & F (pick[blanket] & F (near[laundry_basket] & F release[blanket, laundry_basket])))'),
    ('Grab the scarf and drape it on the coat hook.',
     'F (near[scarf] & F (pick[scarf] & F (near[coat_hook] & F release[scarf, coat_hook])))'),
    ('Toss out the old newspaper.',
     'F (near[old_newspaper] & F (pick[old_newspaper] & F (near[trash_can] & '
     'F release[old_newspaper, trash_can])))'),
]


@pytest.mark.parametrize('instruction,gold', UNKNOWN_VERBS, ids=[c[0][:30] for c in UNKNOWN_VERBS])
def test_an_unknown_verb_before_a_place_is_read_as_going_there(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    if not instruction.startswith(('Hover', 'Toss')):
        assert any('read' in n for n in notes), notes


CHATTER = [
    ('Morning! Pop over to the greenhouse for me, would you?', 'F near[greenhouse]'),
    ('We are expecting a delivery. Head to the loading bay real quick.', 'F near[loading_bay]'),
    ('The toddler is napping upstairs, so go to the laundry room and avoid the nursery.',
     'F near[laundry_room] & G !near[nursery]'),
    ('Visit the porch, and be gentle: never touch the wind chimes.',
     'F near[porch] & G !near[wind_chimes]'),
    ('Fyi, the ladder is in the garage, so please stay away from it.', 'G !near[ladder]'),
    ('Go to the den this afternoon.', 'F near[den]'),
    ('Check if the side door is locked.', 'F near[side_door]'),
    ('Go to the mailbox, and keep well away from the hedge.', 'F near[mailbox] & G !near[hedge]'),
    ('Your destination is the east stairwell.', 'F near[east_stairwell]'),
    ('Go to the atrium. When you are finished there, head to the elevator lobby.',
     'F (near[atrium] & F near[elevator_lobby])'),
    ('Go have a quick look at the skylight.', 'F near[skylight]'),
    ('Do two laps around the tennis court.',
     'F (near[tennis_court] & F (!near[tennis_court] & F near[tennis_court]))'),
    ('Go to the study, and avoid the rug; the same goes for the vase.',
     'F near[study] & G !near[rug] & G !near[vase]'),
]


@pytest.mark.parametrize('instruction,gold', CHATTER, ids=[c[0][:30] for c in CHATTER])
def test_chatter_is_left_out_and_noted(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_what_is_left_out_is_in_the_notes() -> None:
    notes = T.translate('Hello! The dog is asleep. Go to the pantry for me.').notes
    assert any('hello' in n for n in notes), notes
    assert any('the dog is asleep' in n for n in notes), notes
    assert any('for me' in n for n in notes), notes


@pytest.mark.parametrize('bad', [
    'go to the kitchen and then the pantry unless the stove',   # a leftover place and order word
    'go to the shed and zorble the quigley',                    # not English: a misspelt place?
    'the kettle is on the stove',                              # nothing to do at all
])
def test_leftovers_that_could_mean_something_still_raise(bad: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(bad)


def test_typos_in_names_are_corrected_and_noted() -> None:
    t = T.translate('Go to the bathrom, then the kitchn, then the coutner.')
    assert equivalent(t.formula, parse_formula('F (near[bathroom] & F (near[kitchen] & F near[counter]))'))
    assert any('"coutner" as "counter"' in n for n in t.notes), t.notes


def test_speller_is_conservative() -> None:
    s = Speller()
    assert s.correct('patnry') == 'pantry'      # two letters swapped
    assert s.correct('securty') == 'security'   # a letter dropped
    assert s.correct('linnen') == 'linen'       # a letter doubled
    assert s.correct('leef') == 'leaf'          # a vowel pair spelt as it sounds
    for word in ('futon', 'crib', 'loveseat', 'nightlight', 'blender', 'dumpster', 'copier', 'table'):
        assert s.correct(word) is None, word    # real words, listed or not, stay as they are
    assert s.correct('xqzvbt') is None          # no near word: nothing to guess
    assert Speller(words={}).correct('patnry') is None   # without a word list nothing changes


def test_landmark_names_are_never_corrected() -> None:
    t = OfflineTranslator(landmarks=('patnry',)).translate('go to patnry')
    assert str(t.formula) == 'F near[patnry]'


SCOPES = [
    ('Go to the bakery, and after that keep away from the fountain.',
     'F (near[bakery] & G !near[fountain])'),
    ('Head to the gate and, until you reach it, avoid the mud.', '!near[mud] U near[gate]'),
    ('Visit the cellar, then the attic. After the cellar, never go near the boiler again.',
     'F (near[cellar] & G !near[boiler] & F near[attic])'),
    ('Bring the tray to the sink, and while you have the tray, avoid the dog.',
     'F (near[tray] & F (pick[tray] & (!near[dog] U (near[sink] & F release[tray, sink]))))'),
    ("Don't stroll anywhere near the pond. Go to the bench.", 'F near[bench] & G !near[pond]'),
    ('Go to the hall; you can also stop at the kiosk, but only once.',
     'F near[hall] & (!near[kiosk] W (near[kiosk] & (near[kiosk] W G !near[kiosk])))'),
    ('Before you go anywhere near the nursery, wash up at the sink.',
     'F near[nursery] & (!near[nursery] U near[sink])'),
    ("Go into the lab, but only once you've swung by the locker room.",
     'F near[lab] & (!near[lab] U near[locker_room])'),
]


@pytest.mark.parametrize('instruction,gold', SCOPES, ids=[c[0][:30] for c in SCOPES])
def test_time_words_and_back_references_scope_what_they_say(instruction: str, gold: str) -> None:
    _check(instruction, gold)


CORRECTIONS = [
    ('Go to the shower, no sorry, the bathtub.', 'F near[bathtub]'),
    ('Head to the red armchair... actually, make that the grey one.', 'F near[grey_armchair]'),
    ('Carry the towel to the bathroom. Hmm, on second thought, carry it to the laundry room.',
     'F (near[towel] & F (pick[towel] & F (near[laundry_room] & F release[towel, laundry_room])))'),
    ('Go to the porch, then the shed. Scratch the porch.', 'F near[shed]'),
    ('Go to the lamp left of the bed, or rather the one right of it.', 'F near[lamp::isrightof(bed)]'),
    ('Put the forks in the drawer, erm, the spoons I mean.',
     'F (near[spoons] & F (pick[spoons] & F (near[drawer] & F release[spoons, drawer])))'),
    ('Go to the garage and avoid the car. Oh, forget it, the car is gone, no need to avoid it.',
     'F near[garage]'),
    ('Go to the loft. Change of plan: go to the cellar.', 'F near[cellar]'),
    ('Visit the pond and the barn. Skip the barn and go to the silo.', 'F near[pond] & F near[silo]'),
]


@pytest.mark.parametrize('instruction,gold', CORRECTIONS, ids=[c[0][:30] for c in CORRECTIONS])
def test_self_corrections_keep_the_final_intent(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    assert notes, 'a correction is always noted'


LISTS_AND_NESTING = [
    ('We have a mop, a bucket and a broom in the closet. Bring the third thing I mentioned to the porch.',
     'F (near[broom] & F (pick[broom] & F (near[porch] & F release[broom, porch])))'),
    ('There is a kettle and a toaster. Check the latter three times.',
     'F (near[toaster] & F (!near[toaster] & F (near[toaster] & F (!near[toaster] & F near[toaster]))))'),
    ('Rake, hoe, spade. Leave out the first one and bring the others to the shed.',
     'F (near[hoe] & F (pick[hoe] & F (near[shed] & F release[hoe, shed]))) & '
     'F (near[spade] & F (pick[spade] & F (near[shed] & F release[spade, shed])))'),
    ('Go to the vase on the small table, the table that is next to the window.',
     'F near[vase::isabove(small_table::isnextto(window))]'),
    ('Either the north exit or the south exit will do, just head to one of them.',
     'F near[north_exit] | F near[south_exit]'),
    ('Take the laundry to the utility room, and only go into the utility room once.',
     'F (near[laundry] & F (pick[laundry] & F (near[utility_room] & F release[laundry, utility_room]))) & '
     '(!near[utility_room] W (near[utility_room] & (near[utility_room] W G !near[utility_room])))'),
    ('Visit the gazebo once and only once.',
     '!near[gazebo] U (near[gazebo] & (near[gazebo] W G !near[gazebo]))'),
]


@pytest.mark.parametrize('instruction,gold', LISTS_AND_NESTING, ids=[c[0][:30] for c in LISTS_AND_NESTING])
def test_list_positions_appositives_and_counts(instruction: str, gold: str) -> None:
    _check(instruction, gold)


MORE = [
    ('Scoot to the bookshelf, then the piano.', 'F (near[bookshelf] & F near[piano])'),
    ('Nip over to the corner shop.', 'F near[corner_shop]'),
    ('Park yourself next to the charging dock.', 'F near[charging_dock]'),
    ('Rover: head down to the creek, then up to the ridge.', 'F (near[creek] & F near[ridge])'),
    ('Get rid of the broken lamp.',
     'F (near[broken_lamp] & F (pick[broken_lamp] & F (near[trash_can] & '
     'F release[broken_lamp, trash_can])))'),
    ("Hey there! Hope you're well. Please go to the studio.", 'F near[studio]'),
    ('Go to the pool. Thanks a lot!', 'F near[pool]'),
    ('No rush, but go to the attic at some point.', 'F near[attic]'),
    ('Be careful, the floor is wet. Go to the sink.', 'F near[sink]'),
    ('Whenever you are ready, head to the conference room.', 'F near[conference_room]'),
    ('Go to the shed, and please be quick about it.', 'F near[shed]'),
    ('Go to the studio real fast.', 'F near[studio]'),
    ('Go to the mall and from then on stay away from the parking lot.',
     'F (near[mall] & G !near[parking_lot])'),
    ('Go to the kitchen and avoid the dog. Never mind the dog, it is outside.', 'F near[kitchen]'),
    ('Put the book on the shelf, uh, the top shelf I mean.',
     'F (near[book] & F (pick[book] & F (near[top_shelf] & F release[book, top_shelf])))'),
    ('Check the window exactly once and only once.',
     '!near[window] U (near[window] & (near[window] W G !near[window]))'),
    ('Go to the mug next to the laptop, the laptop on the desk.',
     'F near[mug::isnextto(laptop::isabove(desk))]'),
]


@pytest.mark.parametrize('instruction,gold', MORE, ids=[c[0][:30] for c in MORE])
def test_more_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_a_statement_inside_a_descriptor_is_not_split_off() -> None:
    _check("Go to the bag between the bed and the desk that's next to the window.",
           'F near[bag::isbetween(bed, desk::isnextto(window))]')


def test_the_person_sees_how_the_words_were_read() -> None:
    from ltl_instruct.core.language.verification import verification_for
    text = verification_for(T.translate('Hi! Go to the patnry for me.')).text()
    assert 'Note: read "patnry" as "pantry"' in text and 'Note: left out "for me"' in text


ROUND_TWO = [
    ('Can you get yourself over to the whiteboard?', 'F near[whiteboard]'),
    ('You may only enter the vault after visiting the security office.',
     'F near[vault] & (!near[vault] U near[security_office])'),
    ('Go to the gym, staying well clear of the pool the whole time.', 'F near[gym] & G !near[pool]'),
    ('Under no circumstances go near the server rack. Go to the desk.',
     'F near[desk] & G !near[server_rack]'),
    ('There are two doors, a red one and a blue one. Go through the blue one.', 'F near[blue_door]'),
    ('I have three mugs: a tall one, a short one and a chipped one. Bring the short one to the sink.',
     'F (near[short_mug] & F (pick[short_mug] & F (near[sink] & F release[short_mug, sink])))'),
    ('You will find a vase, a clock and a statue on the shelf. Go to the one in the middle.',
     'F near[clock]'),
    ('Head to the garage; oops, I meant the shed.', 'F near[shed]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_TWO, ids=[c[0][:30] for c in ROUND_TWO])
def test_second_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


ROUND_THREE = [
    ('Carry the plate to the table, avoiding the rug on the way.',
     'F (near[plate] & F (pick[plate] & (!near[rug] U (near[table] & F release[plate, table]))))'),
    ('Go to the porch. From there, stay away from the pond.', 'F (near[porch] & G !near[pond])'),
    ('Go to the kitchen. Wait, not the kitchen, the dining room.', 'F near[dining_room]'),
    ('Put the jar on the table - no, on the counter.',
     'F (near[jar] & F (pick[jar] & F (near[counter] & F release[jar, counter])))'),
    ('Pay the kitchen a visit.', 'F near[kitchen]'),
    ('Check that the oven is off.', 'F near[oven]'),
    ('See if the cat is in the laundry room.', 'F near[laundry_room]'),
    ('Could you make sure the garage door is shut?', 'F near[garage_door]'),
    ('Go to the red chair, the one by the fireplace.', 'F near[red_chair::isnextto(fireplace)]'),
    ('Go to the attic, the basement and the garage, skipping the basement.',
     'F near[attic] & F near[garage]'),
    ('Visit the oak, the elm and the pine, but not the elm.', 'F near[oak] & F near[pine]'),
    ('Go to the couch, wait, make it the loveseat.', 'F near[loveseat]'),
    ('Go to the study, or the library if the study is locked.', 'F near[study] | F near[library]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_THREE, ids=[c[0][:30] for c in ROUND_THREE])
def test_third_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_a_demand_to_ensure_is_not_a_check() -> None:
    got = OfflineTranslator(landmarks=('a', 'b')).translate('ensure that you never reach a or b')
    assert equivalent(got.formula, parse_formula('G !near[a] & G !near[b]'))


ROUND_FOUR = [
    ('Go to the den. You can stop by the bar too, but only once.',
     'F near[den] & (!near[bar] W (near[bar] & (near[bar] W G !near[bar])))'),
    ('Our guests arrive at six, so please tidy up near the sofa.', 'F near[sofa]'),
    ('My keys fell behind the couch. Could you go there?', 'F near[couch]'),
    ('Head to the barn and, until you arrive, keep away from the fence.', '!near[fence] U near[barn]'),
    ('Go to the porch. Before the porch, stop at the mailbox.', 'F (near[mailbox] & F near[porch])'),
    ('Avoid the lawn at all times; what I need is for you to get to the shed.',
     'F near[shed] & G !near[lawn]'),
    ('Go to the left window, or rather the right one.', 'F near[right_window]'),
    ('Here are the stops: bakery, florist, post office. Skip the first one and visit the rest in order.',
     'F (near[florist] & F near[post_office])'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_FOUR, ids=[c[0][:30] for c in ROUND_FOUR])
def test_fourth_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


ROUND_FIVE = [
    ('If you go into the nursery at all, hit the changing table first.',
     '!near[nursery] W near[changing_table]'),
    ('Honestly the easiest thing would be to go to the den.', 'F near[den]'),
    ("I'm not sure where the keys are, maybe check the kitchen drawer.", 'F near[kitchen_drawer]'),
    ('It would be great if you could go to the attic.', 'F near[attic]'),
    ('Do me a favour and go to the porch.', 'F near[porch]'),
    ('Time to head to the garage.', 'F near[garage]'),
    ("Let's visit the greenhouse, then the shed.", 'F (near[greenhouse] & F near[shed])'),
    ('Go to the pantry, which is next to the kitchen.', 'F near[pantry::isnextto(kitchen)]'),
    ('Go to the printer near the window, the one on the left of the desk.',
     'F near[printer::isnextto(window)::isleftof(desk)]'),
    ('Bring the plates to the table, but do not go near the dog until you have put them down.',
     'F (near[plates] & F (pick[plates] & (!near[dog] U (near[table] & F release[plates, table]))))'),
    ('Go to the sink and wash your hands, then go to the table.', 'F (near[sink] & F near[table])'),
    ('Head to the door and knock.', 'F near[door]'),
    ('Go to the fridge, open it, and grab a soda.', 'F (near[fridge] & F (near[soda] & F pick[soda]))'),
    ('Visit the chapel three times but no more.',
     '!near[chapel] U (near[chapel] & (near[chapel] U (!near[chapel] & (!near[chapel] U (near[chapel] & '
     '(near[chapel] U (!near[chapel] & (!near[chapel] U (near[chapel] & '
     '(near[chapel] W G !near[chapel]))))))))))'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_FIVE, ids=[c[0][:30] for c in ROUND_FIVE])
def test_fifth_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_real_words_the_vocabulary_lacks_are_not_corrected() -> None:
    t = T.translate('Grab the goggles and take them to the workbench.')
    assert 'goggles' in str(t.formula) and not any('read "goggles"' in n for n in t.notes)


@pytest.mark.parametrize('instruction,gold', [
    ('Never mind, go to the porch.', 'F near[porch]'),
    ('Go to the den. Never mind, go to the porch.', 'F near[porch]'),
    ("Please don't, under any circumstances, enter the lab.", 'G !near[lab]'),
    ('Ignore the kitchen and go to the hall.', 'F near[hall]'),
])
def test_words_that_take_back_or_stress_are_not_places(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_slips_in_the_words_that_give_structure() -> None:
    _check('Go to the balcony, thne the roof, but nver go near the chimney.',
           'F (near[balcony] & F near[roof]) & G !near[chimney]')


ROUND_SEVEN = [
    ('The kids left their shoes in the hall. Take the shoes to the closet.',
     'F (near[shoes] & F (pick[shoes] & F (near[closet] & F release[shoes, closet])))'),
    ('First stop, the bakery. Second stop, the butcher. Last stop, the florist.',
     'F (near[bakery] & F (near[butcher] & F near[florist]))'),
    ('Go to the pool, then the gym. Hmm, actually do the gym first.', 'F (near[gym] & F near[pool])'),
    ('Water the ferns on the porch and then go to the kitchen.',
     'F (near[ferns::isabove(porch)] & F near[kitchen])'),
    ("There's a red cup, a blue cup, and a green cup. Bring me the blue one.",
     'F (near[blue_cup] & F pick[blue_cup])'),
    ("I spilled coffee by the desk, so avoid the desk and go to the window.",
     'F near[window] & G !near[desk]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_SEVEN, ids=[c[0][:30] for c in ROUND_SEVEN])
def test_seventh_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_there_after_a_choice_is_the_choice() -> None:
    _check('Pick either the red bench or the green bench and go there.',
           'F near[red_bench] | F near[green_bench]')


def test_a_bound_said_with_and_is_no_step_after_the_others() -> None:
    _check('Put the plant on the windowsill, and enter the kitchen only once.',
           'F (near[plant] & F (pick[plant] & F (near[windowsill] & F release[plant, windowsill]))) & '
           '(!near[kitchen] U (near[kitchen] & (near[kitchen] W G !near[kitchen])))')


ROUND_EIGHT = [
    ('Go to the lab, then the office; any order works.', 'F near[lab] & F near[office]'),
    ('Visit the lab and the office, the order is up to you.', 'F near[lab] & F near[office]'),
    ('Keep away from the fence at all times. Your destination: the orchard.',
     'F near[orchard] & G !near[fence]'),
    ('Go to the well, and stay away from the trough until you get there.', '!near[trough] U near[well]'),
    ('Put the book on the desk. Wait, I mean the nightstand.',
     'F (near[book] & F (pick[book] & F (near[nightstand] & F release[book, nightstand])))'),
    ('Head to the shed and avoid the pond. Scratch that last part.', 'F near[shed]'),
    ('Go to the desk, sorry, the other desk.', 'F near[other_desk]'),
    ('Visit the museum and the zoo. Actually, just the zoo.', 'F near[zoo]'),
    ('A hammer, a saw, a drill: bring the saw to the bench.',
     'F (near[saw] & F (pick[saw] & F (near[bench] & F release[saw, bench])))'),
    ('Go to the lamp on the left.', 'F near[left_lamp]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_EIGHT, ids=[c[0][:30] for c in ROUND_EIGHT])
def test_eighth_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


GLUED = [
    ('Go to the attic right away.', 'F near[attic]'),
    ('Go to the basement first thing.', 'F near[basement]'),
    ('Go to the hall, like, right now.', 'F near[hall]'),
    ('Go to the office tomorrow morning.', 'F near[office]'),
    ('Just go to the shed already.', 'F near[shed]'),
    ('Go to the yard and stuff.', 'F near[yard]'),
    ('Get to the roof, pronto.', 'F near[roof]'),
    ('Go to the cellar, if that is ok.', 'F near[cellar]'),
    ('Swing by the mailroom on your way out.', 'F near[mailroom]'),
    ('Dart over to the recycling bins and back.', 'F near[recycling_bins]'),
    ('Go to the lobby and hang out there.', 'F near[lobby]'),
]


@pytest.mark.parametrize('instruction,gold', GLUED, ids=[c[0][:30] for c in GLUED])
def test_words_after_a_place_that_are_no_part_of_its_name(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_timing_words_are_kept_for_the_rules_where_landmarks_are_named() -> None:
    from ltl_instruct.core.language import chatter
    assert chatter.strip_courtesy(['visit', 'b', 'right', 'away'], [], timing=True)[-2:] == ['right', 'away']


ROUND_TEN = [
    ('Can you see whether the kettle is on? Just pop over and check it.', 'F near[kettle]'),
    ('Would you mind visiting the archive and the print shop; either order is fine.',
     'F near[archive] & F near[print_shop]'),
    ('Our in-laws are visiting, so before you go anywhere near the guest room, stop by the linen cupboard.',
     'F near[guest_room] & (!near[guest_room] U near[linen_cupboard])'),
    ('Either the north stairs or the south stairs are fine, just take one of them.',
     'F near[north_stairs] | F near[south_stairs]'),
    ('I put a mug, a plate and a bowl on the counter. Take the third thing I mentioned to the sink.',
     'F (near[bowl] & F (pick[bowl] & F (near[sink] & F release[bowl, sink])))'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_TEN, ids=[c[0][:30] for c in ROUND_TEN])
def test_tenth_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


ROUND_ELEVEN = [
    ('Give the bins a quick check.', 'F near[bins]'),
    ('Lots going on today! Before you head anywhere near the study, check the hallway closet.',
     'F near[study] & (!near[study] U near[hallway_closet])'),
    ('Stay far away from the fireplace throughout; you are going to the armchair.',
     'F near[armchair] & G !near[fireplace]'),
    ('Go to the den but keep clear of the cat bed as well as the plant stand.',
     'F near[den] & G !near[cat_bed] & G !near[plant_stand]'),
    ('Either the front desk or the back desk works, just go to one.',
     'F near[front_desk] | F near[back_desk]'),
    ('Grab the black jacket hanging on the hook and lay it on the bed.',
     'F (near[black_jacket::isabove(hook)] & F (pick[black_jacket::isabove(hook)] & F (near[bed] & '
     'F release[black_jacket::isabove(hook), bed])))'),
    ('A sofa, a table and a rug are in here. Go to the second one.', 'F near[table]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_ELEVEN, ids=[c[0][:30] for c in ROUND_ELEVEN])
def test_eleventh_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_a_wish_that_frames_the_request() -> None:
    _check("I'd love for you to visit the sculpture garden and the gift shop; the order doesn't matter.",
           'F near[sculpture_garden] & F near[gift_shop]')


@pytest.mark.parametrize('chatter_only', ['Thanks!', 'We have guests coming.', 'Be careful.',
                                          'Hi there, how are you?'])
def test_an_instruction_of_chatter_alone_is_still_an_error(chatter_only: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(chatter_only)


ROUND_THIRTEEN = [
    ('Could you run down to the lobby and wait by the front doors?', 'F (near[lobby] & F near[front_doors])'),
    ('Could you please go and get the newspaper from the porch and bring it to me in the study?',
     'F (near[newspaper::isnextto(porch)] & F (pick[newspaper::isnextto(porch)] & F (near[study] & '
     'F release[newspaper::isnextto(porch), study])))'),
    ('Go to the conference room, but before that, grab a marker from the supply cabinet.',
     'F (near[marker::isnextto(supply_cabinet)] & F (pick[marker::isnextto(supply_cabinet)] & '
     'F near[conference_room]))'),
    ('Visit the nurses station, then room twelve, then room fourteen.',
     'F (near[nurses_station] & F (near[room_twelve] & F near[room_fourteen]))'),
    ('Get over to the loading bay as fast as you can.', 'F near[loading_bay]'),
    ('Could you see if there is any mail in the mailbox?', 'F near[mailbox]'),
]


@pytest.mark.parametrize('instruction,gold', ROUND_THIRTEEN, ids=[c[0][:30] for c in ROUND_THIRTEEN])
def test_thirteenth_round_of_unseen_phrasings(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_a_place_after_go_to_is_no_verb() -> None:
    # "grandma" is the place, not a verb; "in the living room" says where she is (no comparator says
    # "inside"), left out of her name and noted
    notes = _check('Go check on grandma in the living room.', 'F near[grandma]')
    assert any('in the living room' in n for n in notes), notes


# A rule is never left out as a remark, a reason or something said about people: the
# instruction is read with it or refused, never without it.
RULES_NEVER_DROPPED = [
    'Go to the den, since the kitchen is off limits.',
    'Find the mop - the baby gate is strictly off limits.',
    'Go to the porch, because the garage is not allowed.',
    'Go to the shed; the kids are never allowed near the pond.',
]


@pytest.mark.parametrize('instruction', RULES_NEVER_DROPPED)
def test_a_rule_is_never_left_out(instruction: str) -> None:
    from ltl_instruct.core.errors import TranslationError
    from ltl_instruct.core.spec import avoided_referents_of
    try:
        got = T.translate(instruction)
    except TranslationError:
        return   # refused: nothing moves without the person's answer
    assert avoided_referents_of(got.formula), f'{instruction!r} -> {got.formula} (a rule was dropped)'

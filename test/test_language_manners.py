"""Offline translator: polite frames, chat spelling, vocatives and list references (seventh round).

Every sentence here was written for these tests (none is taken from a data set). Each case
checks the formula on automata.
"""
from __future__ import annotations

import pytest

from translation_cases import RULES, check_translation as _check


MANNERS = [
    ('Could you be kind enough to bring the cup to the sink?',
     'F (near[cup] & F (pick[cup] & F (near[sink] & F release[cup, sink])))'),
    ('Would you please be so good as to visit the attic.', 'F near[attic]'),
    ('head 2 the garage n then the shed', 'F (near[garage] & F near[shed])'),
    ('stay away from the pond tho', 'G !near[pond]'),
    ('whatever happens never enter the vault. visit the lobby', 'F near[lobby] & G !near[vault]'),
    ('Patrol the hall once and avoid the den, whatever you do.', 'F near[hall] & G !near[den]'),
    ('Mr robot, go to the cellar please.', 'F near[cellar]'),
    ('Dear robot, head over to the porch, thanks.', 'F near[porch]'),
    ('Do not turn up at the clinic before the lab.', 'F near[lab] & (!near[clinic] U near[lab])'),
    ('Circle the water tower twice with the drone.',
     'F (near[water_tower] & F (!near[water_tower] & F near[water_tower]))'),
]


@pytest.mark.parametrize('instruction,gold', MANNERS, ids=[c[0][:30] for c in MANNERS])
def test_polite_frames_and_chat_spelling(instruction: str, gold: str) -> None:
    _check(instruction, gold)


CORRECTIONS = [
    ('go to the bakery then the bank. actually switch those', 'F (near[bank] & F near[bakery])'),
    ('Head to the pier, then the dock. Hmm, swap them around.', 'F (near[dock] & F near[pier])'),
    ('go to gate 2 then gate 4, sorry i meant gate 7 not gate 4', 'F (near[gate_2] & F near[gate_7])'),
    ('Stay away from the lab. No, sorry, that was wrong, stay away from the clinic. Visit the lobby.',
     'F near[lobby] & G !near[clinic]'),
    ('Check the pantry, the cellar and the attic in that order. Wait, skip the first one.',
     'F (near[cellar] & F near[attic])'),
    ('Visit the pool, the spa and the sauna, any order. Hmm, forget the third one.',
     'F near[pool] & F near[spa]'),
    ('Go to the bench or the kiosk. Actually, forget the kiosk.', 'F near[bench]'),
    ('Go to the bench or the kiosk. No, only the kiosk, forget the bench.', 'F near[kiosk]'),
    ('Take the rug to the porch. Actually, leave the rug alone, just go to the porch.', 'F near[porch]'),
]


@pytest.mark.parametrize('instruction,gold', CORRECTIONS, ids=[c[0][:30] for c in CORRECTIONS])
def test_self_corrections(instruction: str, gold: str) -> None:
    _check(instruction, gold)


ORDERS = [
    ('Fly to the mast. Before you do that, circle the barn.', 'F (near[barn] & F near[mast])'),
    ('Take the jug to the shed, but before doing so, stop at the well.',
     'F (near[well] & F (near[jug] & F (pick[jug] & F (near[shed] & F release[jug, shed]))))'),
    ('Go to the loft. Before that, though, swing by the mill.', 'F (near[mill] & F near[loft])'),
    ('You are not permitted in the vault until you have visited the office. Go to the vault.',
     'F near[vault] & (!near[vault] U near[office])'),
    ('You can visit the pool only after the gym.', 'F near[pool] & (!near[pool] U near[gym])'),
    ('Only once you have reached the gate can you go to the yard.',
     'F near[yard] & (!near[yard] U near[gate])'),
    ('Visit the cafe, no earlier than after the library.', 'F near[cafe] & (!near[cafe] U near[library])'),
]


@pytest.mark.parametrize('instruction,gold', ORDERS, ids=[c[0][:30] for c in ORDERS])
def test_orders_said_as_permissions(instruction: str, gold: str) -> None:
    _check(instruction, gold)


COUNTS_AND_OPTIONS = [
    ('Drive out to the kiln on three separate occasions.',
     'F (near[kiln] & F (!near[kiln] & F (near[kiln] & F (!near[kiln] & F near[kiln]))))'),
    ('Visit the shed two different times, then the barn.',
     'F (near[shed] & F (!near[shed] & F (near[shed] & F near[barn])))'),
    ('Do 3 laps around the pond, exactly three.',
     '!near[pond] U (near[pond] & (near[pond] U (!near[pond] & (!near[pond] U (near[pond] & (near[pond] U '
     '(!near[pond] & (!near[pond] U (near[pond] & (near[pond] W G !near[pond]))))))))))'),
    ('Touch down at the helipad or on the lawn.', 'F near[helipad] | F near[lawn]'),
    ('Never go to the bar more than once. Sorry, I mean exactly once.',
     '!near[bar] U (near[bar] & (near[bar] W G !near[bar]))'),
]


@pytest.mark.parametrize('instruction,gold', COUNTS_AND_OPTIONS, ids=[c[0][:30] for c in COUNTS_AND_OPTIONS])
def test_counts_and_options(instruction: str, gold: str) -> None:
    _check(instruction, gold)


SCENE = [
    ('Keep away from the stairs, floor is slippery. Go to the attic.', 'F near[attic] & G !near[stairs]'),
    ('Fly to the barn, then the mill, roof is icy there.', 'F (near[barn] & F near[mill])'),
    ('Walk over to the porta potty.', 'F near[porta_potty]'),
]


@pytest.mark.parametrize('instruction,gold', SCENE, ids=[c[0][:30] for c in SCENE])
def test_scene_without_articles_and_name_words(instruction: str, gold: str) -> None:
    _check(instruction, gold)


LISTS = [
    ('Remember the jug, the lamp and the clock I pointed out? Take the second one to the porch.',
     'F (near[lamp] & F (pick[lamp] & F (near[porch] & F release[lamp, porch])))'),
    ('I showed you the rake, the hoe and the spade. Put the last one in the shed.',
     'F (near[spade] & F (pick[spade] & F (near[shed] & F release[spade, shed])))'),
    ('I will name two rooms, the den and the study. Go to the one I said first twice.',
     'F (near[den] & F (!near[den] & F near[den]))'),
]


@pytest.mark.parametrize('instruction,gold', LISTS, ids=[c[0][:30] for c in LISTS])
def test_list_positions(instruction: str, gold: str) -> None:
    _check(instruction, gold)


def test_once_you_have_it_scopes_the_avoidance_from_the_pick() -> None:
    _check('Fetch the tray. Once you have got it, keep away from the nursery. Leave it on the desk.',
           'F (near[tray] & F (pick[tray] & G !near[nursery] & F (near[desk] & F release[tray, desk])))')
    _check('Pick up the plates. As soon as you are holding them, avoid the lounge. Put them in the sink.',
           'F (near[plates] & F (pick[plates] & G !near[lounge] & F (near[sink] & F release[plates, sink])))')


def test_not_going_back_is_at_most_once() -> None:
    _check("Visit the pantry, and don't keep coming back to the fridge over and over.",
           'F near[pantry] & (!near[fridge] W (near[fridge] & (near[fridge] W G !near[fridge])))')
    _check('Inspect the boiler exactly once. Never keep going back to it.',
           '!near[boiler] U (near[boiler] & (near[boiler] W G !near[boiler]))')


def test_until_one_of_several_places_is_refused_not_guessed() -> None:
    from ltl_instruct.core.errors import TranslationError
    with pytest.raises(TranslationError):
        RULES.translate('Keep off the lawn until you get to the north door or the south door.')


@pytest.mark.parametrize('instruction', [
    'The lamps and the rugs need moving to the loft. Just do the first two for now.',
    'Of the three crates I told you about, the red one, the blue one and the green one, '
    'take the latter away.',
])
def test_positions_without_a_list_are_refused(instruction: str) -> None:
    from ltl_instruct.core.errors import TranslationError
    with pytest.raises(TranslationError):
        RULES.translate(instruction)


def test_correcting_where_a_scope_starts() -> None:
    _check('Visit the pier, then the dock, then the mill. After the pier, avoid the road. '
           'Sorry, I meant after the dock, not the pier.',
           'F (near[pier] & F (near[dock] & G !near[road] & F near[mill]))')


def test_a_goal_said_to_be_closed_is_replaced() -> None:
    _check('Go to the den, then the gym. No wait, that is closed. Go to the pool instead.',
           'F (near[den] & F near[pool])')
    _check('Head to the bakery. Hmm, no, it is shut. Visit the deli instead.', 'F near[deli]')

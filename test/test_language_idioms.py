"""Offline translator: idioms (counts said at length, passives, events) read as their plain phrasing."""
from __future__ import annotations

import time

import pytest

from ltl_instruct.core.errors import TranslationError
from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.language.idioms import rewrite_idioms
from ltl_instruct.core.language.offline import OfflineTranslator, at_least, at_most, exactly
from ltl_instruct.core.language.text import tokenize
from ltl_instruct.core.spec import near, parse_formula

T = OfflineTranslator()

# Sentences written for these tests (not from any data set), with the formula each must be equivalent to.
COUNTS = [
    ('The maximum number of times you can visit the pantry is two.', at_most(near('pantry'), 2)),
    ('You are allowed at most three visits to the garage.', at_most(near('garage'), 3)),
    ('Visiting the nursery more than once is prohibited.', at_most(near('nursery'), 1)),
    ('You can check the oven zero times, once or twice.', at_most(near('oven'), 2)),
    ('Go to the mailbox equal or more than three times.', at_least(near('mailbox'), 3)),
    ('Make at least two separate visits to the greenhouse.', at_least(near('greenhouse'), 2)),
    ('Visit the porch exactly twice, no more, no less.', exactly(near('porch'), 2)),
    ('Never go to the cellar again after you have visited it twice.', at_most(near('cellar'), 2)),
    ('Once you leave the lab for the third time, you cannot come back to it.', at_most(near('lab'), 3)),
    ('Go to the shed, then leave it and repeat this two more times.', at_least(near('shed'), 3)),
    ('You are not allowed to enter the garage more than twice.', at_most(near('garage'), 2)),
    ('You cannot visit the pond three or more times.', at_most(near('pond'), 2)),
    ('You must not visit the pond at least three times.', at_most(near('pond'), 2)),
    ('The minimum number of visits to the barn is three.', at_least(near('barn'), 3)),
    ('Visiting the attic twice locks it for future visits.', at_most(near('attic'), 2)),
    ('You need at least two distinct visits to the library.', at_least(near('library'), 2)),
    ('Check the crib on at most two separate occasions.', at_most(near('crib'), 2)),
    ('Visit the well at least twice while leaving it in between.', at_least(near('well'), 2)),
]


def _reads_as(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


@pytest.mark.parametrize('instruction,gold', COUNTS, ids=[c[0][:40] for c in COUNTS])
def test_counts_said_at_length(instruction: str, gold: object) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, gold), f'{instruction!r} -> {got.formula}'


PHRASINGS = [
    ('The back door must be visited.', 'F near[back_door]'),
    ('The wet floor has to be avoided.', 'G !near[wet_floor]'),
    ('Make sure the shed and the barn are both visited.', 'F near[shed] & F near[barn]'),
    ('Do not go into the office until the printer has been visited.', '!near[office] U near[printer]'),
    ('Stay out of the garden until the gate is reached.', '!near[garden] U near[gate]'),
    ('You are required to go to the lobby.', 'F near[lobby]'),
]


@pytest.mark.parametrize('instruction,gold', PHRASINGS, ids=[c[0][:40] for c in PHRASINGS])
def test_passives_and_frames(instruction: str, gold: str) -> None:
    _reads_as(instruction, gold)


def test_rewrites_keep_sentences_and_plain_text() -> None:
    assert rewrite_idioms(tokenize('Go to the den. Then go to the hall!')) == tokenize(
        'Go to the den. Then go to the hall!')
    assert rewrite_idioms([]) == []
    assert rewrite_idioms(tokenize('visit a two or more times')) == ['visit', 'a', 'at', 'least', 'twice']


@pytest.mark.parametrize('instruction, gold', [
    # a connective that adds a clause was read as a place ("near[furthermore]", "near[top]")
    ('go to the kitchen, furthermore never enter the hall', 'F near[kitchen] & G !near[hall]'),
    ('Go to the kitchen. On top of that, never enter the hall.', 'F near[kitchen] & G !near[hall]'),
    ('go to the kitchen. in addition, avoid the hall', 'F near[kitchen] & G !near[hall]'),
    ('Go to the kitchen. In addition to that, never enter the hall.', 'F near[kitchen] & G !near[hall]'),
    ("go to the kitchen, what's more, keep away from the hall", 'F near[kitchen] & G !near[hall]'),
    ('Go to the porch. Plus, stay out of the garden.', 'F near[porch] & G !near[garden]'),
    # one that offers another was read as a sequence
    ('go to the kitchen, otherwise go to the garage', 'F near[kitchen] | F near[garage]'),
    ('go to the kitchen, alternatively head to the garage', 'F near[kitchen] | F near[garage]'),
    # ... also when it opens the next sentence (its "or" was a sentence of its own, refused)
    ('Go to the kitchen. Otherwise, go to the garage.', 'F near[kitchen] | F near[garage]'),
    ('Go to the kitchen. Or the garage. Avoid the hall.',
     'F (near[kitchen] | near[garage]) & G !near[hall]'),
])
def test_connectives_that_add_or_offer_a_clause(instruction: str, gold: str) -> None:
    _reads_as(instruction, gold)


@pytest.mark.parametrize('instruction, gold', [
    # a place gone through after the goal is said is on the way ("near[passing]" was a goal)
    ('go to the kitchen, passing through the hall', 'F (near[hall] & F near[kitchen])'),
    ('go to the red room and make sure to go through the blue room',
     'F (near[blue_room] & F near[red_room])'),
    ('go to the den, moving through the hall', 'F (near[hall] & F near[den])'),
    # said first, or with its own destination, it is a leg of the route as before
    ('go through the green room to the red room', 'F (near[green_room] & F near[red_room])'),
    ('go to the kitchen and then go through the hall to the garage',
     'F (near[kitchen] & F (near[hall] & F near[garage]))'),
])
def test_a_place_gone_through_is_on_the_way(instruction: str, gold: str) -> None:
    _reads_as(instruction, gold)


@pytest.mark.parametrize('instruction, gold', [
    ('go to the closest chair to the door', 'F near[chair::isnextto(door)]'),
    ('go to the nearest table to the window, then the sofa',
     'F (near[table::isnextto(window)] & F near[sofa])'),
    ('take the closest cup to the sink to the table',
     'F (near[cup::isnextto(sink)] & F (pick[cup::isnextto(sink)] & F (near[table] & '
     'F release[cup::isnextto(sink), table])))'),
])
def test_a_superlative_before_the_noun_is_a_relation(instruction: str, gold: str) -> None:
    # "the closest chair to the door" was a place `closest_chair`, then a goal at the door, unflagged
    _reads_as(instruction, gold)


@pytest.mark.parametrize('instruction', [
    'go to the gym not before going to the kitchen',
    'only after you visit the kitchen you can go to the gym',
    'go to the gym after going to the kitchen do not go to the gym before',
    "visit the gym after you have been to the kitchen, but don't visit the gym earlier",
])
def test_an_order_said_without_commas_or_with_its_ellipsis(instruction: str) -> None:
    # each was refused ("could not place what to avoid in 'not before ...'", "found no action")
    _reads_as(instruction, 'F near[gym] & (!near[gym] U near[kitchen])')


def test_then_you_may_stays_a_permission() -> None:
    # drone-planning's "only if you reached X then you may proceed to Y" lets the robot go on, it
    # does not send it (a first no-comma rule read it as a goal: 16 of its training items changed)
    _reads_as('go to the kitchen avoiding the gym. only if you reached the kitchen then you may proceed to '
              'the gym.', '!near[gym] U near[kitchen]')


def test_a_run_on_chain_of_only_after_is_not_read_as_one_order() -> None:
    # the no-comma "only after E you can ..." must not swallow the next "only after" into E or the goal
    chain = ('only after you visit the den you can go to the hall only after you visit the hall you can '
             'go to the attic')
    gold = parse_formula('(!near[hall] U near[den]) & (!near[attic] U near[hall]) & F near[attic]')
    try:
        got = OfflineTranslator().translate(chain).formula
    except TranslationError:
        return   # refused: the learned model reads it, flagged
    assert equivalent(got, gold), got


def test_between_two_things_of_a_kind_is_no_leg_of_the_route() -> None:
    # "between the two tables" names where a chair is ("on the way there tables" was read)
    assert 'way' not in rewrite_idioms(tokenize('go to the chair between the two tables'))
    leg = 'go to the den, then the attic; between those two, avoid the door'
    assert 'way' in rewrite_idioms(tokenize(leg))


def test_rewrites_stay_fast_on_long_hostile_input() -> None:
    text = ' '.join(['the red room is'] * 120 + ['visited'])
    started = time.perf_counter()
    rewrite_idioms(tokenize(text))
    assert time.perf_counter() - started < 0.5


WAITING_AND_ORDER = [
    ('Wait at the door as long as the courier does not appear.', 'near[door] U near[courier]'),
    ('As long as you do not see the courier, do not leave the porch.', 'near[porch] U near[courier]'),
    ('You can leave the lobby after the guard is seen, otherwise stay at the lobby.',
     'near[lobby] U near[guard]'),
    ('You cannot go anywhere from the dock unless you see the boat.', 'near[dock] U near[boat]'),
    ('Until you see the boat, stay at the dock.', 'near[dock] U near[boat]'),
    ('Visit the pantry, the cellar and the attic in no particular order.',
     'F near[pantry] & F near[cellar] & F near[attic]'),
    ('Go to one of the shed and the barn and then to the other.', 'F near[shed] & F near[barn]'),
    ('Patrol between the gate and the yard again and again.', 'G F near[gate] & G F near[yard]'),
    ('Keep going back and forth between the kitchen and the den.', 'G F near[kitchen] & G F near[den]'),
    ('Do not stop until the bins and the racks are all visited.', 'F near[bins] & F near[racks]'),
    ('Visit the lab, then the office; there can be other places in between.',
     'F (near[lab] & F near[office])'),
    ('Go to the gate, and move on to the lab once you have been to the gate.',
     'F (near[gate] & F near[lab])'),
    ('Visit all four places: the gate, the shed, the barn and the pond.',
     'F near[gate] & F near[shed] & F near[barn] & F near[pond]'),
]


@pytest.mark.parametrize('instruction,gold', WAITING_AND_ORDER, ids=[c[0][:40] for c in WAITING_AND_ORDER])
def test_waiting_order_and_repetition_said_at_length(instruction: str, gold: str) -> None:
    _reads_as(instruction, gold)


STAYING = [
    # staying within a region said many ways
    ('Go to the charging pad and remain within the lab.', 'F near[charging_pad] & G near[lab]'),
    ('Fly to the tower staying on the east side.', 'F near[tower] & G near[east_side]'),
    ('Go to the kiosk by only moving in the atrium.', 'F near[kiosk] & G near[atrium]'),
    ('Without stepping outside of the garden, go to the bench.', 'F near[bench] & G near[garden]'),
    ('Go to the bench without ever leaving the garden.', 'F near[bench] & G near[garden]'),
    ('Go to the bench only through the garden.', 'F near[bench] & G near[garden]'),
    # on the way, first, typed ordinals
    ('Go to the attic while avoiding going through the nursery.', '!near[nursery] U near[attic]'),
    ('Go to the study by first visiting the hall.', 'F (near[hall] & F near[study])'),
    ('Go to the study, but make sure to go to the hall first.', 'F (near[hall] & F near[study])'),
    ('Start on the roof, then go to the 2 nd floor.', 'F (near[roof] & F near[second_floor])'),
    ('Go to level three.', 'F near[level_three]'),   # the name as said (see test_levels_as_floors)
]


def test_levels_as_floors_only_under_the_digits_convention() -> None:
    """'level two' is the name said, but for drone-planning's convention ('numbers=digits'): a floor."""
    from ltl_instruct.core.language.offline import OfflineTranslator
    said = 'Inspect the level two formwork, then go to level four.'
    assert str(OfflineTranslator().translate(said).formula) == \
        'F (near[level_two_formwork] & F near[level_four])'
    assert str(OfflineTranslator(numbers='digits').translate(said).formula) == \
        'F (near[second_floor_formwork] & F near[fourth_floor])'


@pytest.mark.parametrize('instruction,gold', STAYING, ids=[c[0][:40] for c in STAYING])
def test_staying_within_and_on_the_way(instruction: str, gold: str) -> None:
    _reads_as(instruction, gold)


MEETING = [
    ("Meet me at the bike rack, I'll be down in five minutes.", 'F near[bike_rack]'),
    ('meet us by the fountain, then go to the car', 'F (near[fountain] & F near[car])'),
    ('Wait for her at the gate and never go near the pond.', 'F near[gate] & G !near[pond]'),
]


@pytest.mark.parametrize('instruction,gold', MEETING, ids=[c[0][:30] for c in MEETING])
def test_meeting_someone_at_a_place_is_going_there_by_the_rules(instruction: str, gold: str) -> None:
    """'meet me at X', 'wait for her at X': the place is X (the rules read it; the model is not needed)."""
    from ltl_instruct.core.language.offline import OfflineTranslator
    got = OfflineTranslator().translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'

"""Offline translator: rules over the whole run (triggers and responses), strict order, run-on clauses."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.spec import parse_formula

T = OfflineTranslator()

# Sentences written for these tests (not from any data set), with the formula each must be equivalent to.
RULES = [
    # a trigger that is always a rule
    ('Whenever you pass the kitchen, check the fridge.', 'G (near[kitchen] -> F near[fridge])'),
    ('Always, once you see the alarm, go to the exit.', 'G (near[alarm] -> F near[exit])'),
    ('Go to the den, then the hall. Whenever you visit the hall, go to the porch.',
     'F (near[den] & F near[hall]) & G (near[hall] -> F near[porch])'),
    # an obligation after "after/once": a rule; a plain command stays a sequence
    ('You must go to the charger after you visit the workbench.', 'G (near[workbench] -> F near[charger])'),
    ('After you visit the workbench, go to the charger.', 'F (near[workbench] & F near[charger])'),
    ('Visiting the lab means you have to go to the shower afterwards.', 'G (near[lab] -> F near[shower])'),
    ('You can go to the pantry but you have to go to the kitchen later.',
     'G (near[pantry] -> F near[kitchen])'),
    # prompt responses
    ('As soon as you reach the front door, go to the doormat.', 'G (near[front_door] -> X near[doormat])'),
    ('If you see the dog, go to the kennel right after that.', 'G (near[dog] -> X near[kennel])'),
    ('Once you visit the lobby you can go nowhere but the elevator.', 'G (near[lobby] -> X near[elevator])'),
    # avoidance from then on
    ('Once you have been to the garden you cannot go to the carpet.',
     'G (near[garden] -> X G !near[carpet])'),
    # said before the trigger, and both ways
    ('You must visit the gate right before the garage.', 'G (X near[garage] -> near[gate])'),
    ('Go to the sink immediately after you visit the bin, and you cannot go to the sink any other time.',
     'G (near[bin] <-> X near[sink])'),
    # a trigger at a goal given before scopes that goal (the development set's convention)
    ("Go to the counter. Once you've reached the counter, avoid the stove.",
     'F (near[counter] & G !near[stove])'),
]


@pytest.mark.parametrize('instruction,gold', RULES, ids=[c[0][:40] for c in RULES])
def test_rules_over_the_whole_run(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


def test_a_permission_is_no_rule() -> None:
    got = OfflineTranslator(avoid_scope='goal').translate(
        'go to the garage avoiding the shed. if you reached the garage, then you can go to the shed.')
    assert equivalent(got.formula, parse_formula('!near[shed] U near[garage]'))


ORDER = [
    ('Visit the oven, the sink and the fridge in that strict order.',
     '(!near[sink] U near[oven]) & (!near[fridge] U near[sink]) & F near[fridge]'),
    ('Visit the oven, the sink and the fridge in that order.',
     'F (near[oven] & F (near[sink] & F near[fridge]))'),
    ('Go to the garage, and only then go to the attic.', '(!near[attic] U near[garage]) & F near[attic]'),
    ('Visit the library only if you have been to the office.',
     'F near[library] & (!near[library] U near[office])'),
    ('Do not enter the lab if you have not visited the office.', '!near[lab] U near[office]'),
    # run-on clauses, without commas
    ('go to the shed do not go to the barn', 'F near[shed] & G !near[barn]'),
    ('never go to the pool never go to the pond', 'G !near[pool] & G !near[pond]'),
    ('go to the kitchen but keep avoiding the cat', 'F near[kitchen] & G !near[cat]'),
]


@pytest.mark.parametrize('instruction,gold', ORDER, ids=[c[0][:40] for c in ORDER])
def test_order_and_run_on_clauses(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


LANDMARKS = [
    ('whenever a occurs b must occur at the very next time instant', 'G (near[a] -> X near[b])'),
    ('if you visit a make sure you visit b immediately after that if you visit b make sure you have '
     'visited a right before that', 'G (near[a] <-> X near[b])'),
    ('visit a b and c in this strict order', '(!near[b] U near[a]) & (!near[c] U near[b]) & F near[c]'),
    ('never go to a never go to b', 'G !near[a] & G !near[b]'),
    ('b can never be visited once a occurs', 'G (near[a] -> X G !near[b])'),
]


@pytest.mark.parametrize('instruction,gold', LANDMARKS, ids=[c[0][:40] for c in LANDMARKS])
def test_rules_with_known_landmarks(instruction: str, gold: str) -> None:
    got = OfflineTranslator(landmarks=('a', 'b', 'c')).translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


ONCE = [
    # the default (development set) reading: once in the whole run
    ('Visit the porch exactly once, then go to the shed.', {},
     'F (near[porch] & F near[shed]) & (!near[porch] U (near[porch] & (near[porch] W G !near[porch])))'),
    ('Go to the lab, then the office. No revisiting is allowed.', {},
     'F (near[lab] & F near[office]) & (!near[lab] U (near[lab] & (near[lab] W G !near[lab]))) & '
     '(!near[office] U (near[office] & (near[office] W G !near[office])))'),
    # once_scope='next': not again before the next goal; the last goal is visited in its turn
    ('Visit the porch exactly once, then go to the shed.', {'once_scope': 'next'},
     'F (near[porch] & F near[shed]) & (!near[porch] U (near[porch] U (!near[porch] U near[shed])))'),
    ('Visit the kitchen, then the hall, visiting each room only once.', {'once_scope': 'next'},
     '(!near[kitchen] U (near[kitchen] U (!near[kitchen] U near[hall]))) & (!near[hall] U near[kitchen]) & '
     'F near[hall]'),
    ('Go to the kitchen, then go to the hall without returning to the kitchen.', {'once_scope': 'next'},
     'F (near[kitchen] & F near[hall]) & (!near[kitchen] U (near[kitchen] U (!near[kitchen] U near[hall])))'),
    ('Visit the porch exactly once.', {'once_scope': 'next'},
     '!near[porch] U (near[porch] & (near[porch] W G !near[porch]))'),
]


@pytest.mark.parametrize('instruction,options,gold', ONCE, ids=[c[0][:30] + str(c[1]) for c in ONCE])
def test_once_scope(instruction: str, options: dict, gold: str) -> None:
    got = OfflineTranslator(**options).translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


def test_once_scope_is_checked() -> None:
    with pytest.raises(TranslationError):
        OfflineTranslator(once_scope='sometimes')


def test_before_visiting_it_moves_the_new_goal_first() -> None:
    got = T.translate('Visit the shed, but before visiting the shed you must visit the barn.')
    assert equivalent(got.formula, parse_formula('F (near[barn] & F near[shed])'))
    got = T.translate('Go to the gate followed by visiting the pond.')
    assert equivalent(got.formula, parse_formula('F (near[gate] & F near[pond])'))


ROUTES = [
    ('Go to the den then the hall, or go to the hall then the den.',
     'F (near[den] & F near[hall]) | F (near[hall] & F near[den])'),
    ('Go to the shed after the barn. Go to the barn after the gate.',
     'F (near[gate] & F (near[barn] & F near[shed]))'),
    ('Go to the kitchen, then the bedroom. Go to the kitchen again after the bathroom.',
     'F (near[kitchen] & F (near[bedroom] & F (near[bathroom] & F near[kitchen])))'),
    ('Go to the dock, leave, and then go to the dock again.',
     'F (near[dock] & F (!near[dock] & F near[dock]))'),
    ('Visit the lab, then leave the lab and never go back.',
     'F (near[lab] & F !near[lab]) & (!near[lab] U (near[lab] & (near[lab] W G !near[lab])))'),
    ('Always avoid the cellar to get to the porch.', 'F near[porch] & G !near[cellar]'),
    ('Go to the roof always passing through the attic.', 'F (near[attic] & F near[roof])'),
    ('Go to the shed; you can only visit the shed once.',
     '!near[shed] U (near[shed] & (near[shed] W G !near[shed]))'),
]


@pytest.mark.parametrize('instruction,gold', ROUTES, ids=[c[0][:40] for c in ROUTES])
def test_routes_leaving_and_goals_named_again(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


CHAINED = [
    ('Make your way to the den only after going to the hall. Before that, make your way to the hall only '
     'after going to the porch.',
     'F near[den] & (!near[den] U near[hall]) & (!near[hall] U near[porch])'),
    ('Go to the car. Make sure you have visited the mailbox before that, and only go to the gate after '
     'the car.',
     'F near[car] & (!near[car] U near[mailbox]) & F near[gate] & (!near[gate] U near[car])'),
    ('Visit the oven, then the sink, while ensuring not to visit the sink before the oven.',
     'F (near[oven] & F near[sink]) & (!near[sink] U near[oven])'),
    ('Until you have been to the office, you cannot go to the lab.', '!near[lab] U near[office]'),
    ('Seeing the guard unlocks the vault.', '!near[vault] U near[guard]'),
    ('Visit the shed, in turn only visit the shed after the barn.',
     'F near[shed] & (!near[shed] U near[barn])'),
]


@pytest.mark.parametrize('instruction,gold', CHAINED, ids=[c[0][:40] for c in CHAINED])
def test_orderings_chained_and_said_first(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


EVERYDAY = [
    ('Put the plate in the sink and the cup in the dishwasher.',
     'F (near[plate] & F (pick[plate] & F (near[sink] & F release[plate, sink]))) & '
     'F (near[cup] & F (pick[cup] & F (near[dishwasher] & F release[cup, dishwasher])))'),
    ('After you drop off the package at the front desk, go to the elevator.',
     'F (near[package] & F (pick[package] & F (near[front_desk] & F (release[package, front_desk] & '
     'F near[elevator]))))'),
    ('Go to the fridge, then the oven. Actually, go to the oven first.', 'F (near[oven] & F near[fridge])'),
    ('Go to the fridge, then the oven, but go to the sink first.',
     'F (near[sink] & F (near[fridge] & F near[oven]))'),
    ('Go to the living room and wait there until the guard is seen.',
     'F (near[living_room] & (near[living_room] U near[guard]))'),
    ('Either fly over the lake or over the forest, but not both.',
     '(F near[lake] & G !near[forest]) | (F near[forest] & G !near[lake])'),
    ('Keep patrolling the hallway and the lobby.', 'G F near[hallway] & G F near[lobby]'),
    ('Go to the park, stay there until the dog is seen, and then go home.',
     'F (near[park] & (near[park] U (near[dog] & F near[home])))'),
    ('When you get to the kitchen, grab a spoon and bring it to the table.',
     'F (near[kitchen] & F (near[spoon] & F (pick[spoon] & F (near[table] & F release[spoon, table]))))'),
    ('Deliver the letter to the mailbox only after you have visited the post office.',
     'F (near[post_office] & F (near[letter] & F (pick[letter] & F (near[mailbox] & '
     'F release[letter, mailbox]))))'),
    ('The drone must survey the field, then it must land at the base.', 'F (near[field] & F near[base])'),
    ('Go to the balcony, but you can only enter the bedroom once.',
     'F near[balcony] & !F (near[bedroom] & F (!near[bedroom] & F near[bedroom]))'),
]


@pytest.mark.parametrize('instruction,gold', EVERYDAY, ids=[c[0][:40] for c in EVERYDAY])
def test_everyday_phrasings(instruction: str, gold: str) -> None:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'


def test_words_a_reading_would_drop_are_named() -> None:
    # the patrol reading keeps only places: a sentence with more in it is not one
    with pytest.raises(TranslationError) as e:
        T.translate('move the arm back and forth sorting the yellow balls')
    assert 'sorting' in e.value.message
    got = T.translate('Go to the gate and finish by going to the war memorial.')
    assert equivalent(got.formula, parse_formula('F (near[gate] & F near[war_memorial])'))


RULE_VOCAB = ['whenever', 'as', 'soon', 'you', 'visit', 'the', 'door', 'a', 'b', 'go', 'to', 'must', 'right',
              'after', 'before', 'that', 'once', 'only', 'then', 'leave', 'never', 'again', 'each', 'place',
              'exactly', 'twice', 'at', 'most', 'strict', 'order', 'in', 'if', 'and', 'or', 'not', 'until',
              'is', 'visited', 'means', 'stay', 'there', 'wait', 'as', 'long', 'does', 'occur', 'maximum',
              'number', 'of', 'visits', 'three', 'zero', 'times', 'without', 'returning', ',', '.', 'first',
              'later']


@settings(max_examples=300, derandomize=True, deadline=None)
@given(st.lists(st.sampled_from(RULE_VOCAB), min_size=1, max_size=25))
def test_word_salad_of_rules_gives_a_formula_or_a_typed_error(words: list[str]) -> None:
    for translator in (T, OfflineTranslator(landmarks=('a', 'b'), once_scope='next')):
        try:
            t = translator.translate(' '.join(words))
        except LtlInstructError as e:
            assert e.code != ErrorCode.INTERNAL_ERROR, e.message
            continue
        assert t.formula is not None and str(t.formula)

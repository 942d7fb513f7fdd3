"""The shipped learned translator and the combined default, on the readings issue 17 names.

These load the bundle in ``ltl_instruct/data/translator`` (made by ``ltl-instruct translator
train``) and the packaged MiniLM encoder, as a user's ``translate`` does.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.automaton.dfa import equivalent
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.task import at_least, at_most, exactly
from ltl_instruct.core.spec import parse_formula, referents_of


@pytest.fixture(scope='module')
def neural():
    return make_translator('neural')


@pytest.fixture(scope='module')
def combined():
    return make_translator('combined')


@pytest.mark.parametrize('text, formula', [
    ('bring me over to the printer', 'F near[printer]'),
    ('I have to finish my essay, can you find the lamp', 'F near[lamp]'),
    ('go to the kitchen. furthermore, never enter the hall', 'F near[kitchen] & G !near[hall]'),
    ('throw away the banana peel', 'F (near[banana_peel] & F (pick[banana_peel] & F (near[trash_can] & '
     'F release[banana_peel, trash_can])))'),
    ('Find Bookstore and then find Marston Hall', 'F (near[bookstore] & F near[marston_hall])'),
])
def test_the_model_reads_what_the_rules_misread(neural, text, formula):
    assert str(neural.translate(text).formula) == formula


@pytest.mark.parametrize('text, formula', [
    # where a thing is taken from is a description of it, never a destination
    ('fetch me the cup from the kitchen',
     'F (near[cup::isnextto(kitchen)] & F pick[cup::isnextto(kitchen)])'),
    ('grab the blanket out of the closet and bring it to the couch',
     'F (near[blanket::isnextto(closet)] & F (pick[blanket::isnextto(closet)] & F (near[couch] & '
     'F release[blanket::isnextto(closet), couch])))'),
    ('can I have the salt from the counter',
     'F (near[salt::isnextto(counter)] & F pick[salt::isnextto(counter)])'),
    # a request for the speaker is a pick-up: the robot brings it
    ('I need my charger', 'F (near[charger] & F pick[charger])'),
    ('go to the garage, then bring me the toolbox', 'F (near[garage] & F (near[toolbox] & F pick[toolbox]))'),
    ('pick up the green plush toy and put it in the basket',
     'F (near[green_plush_toy] & F (pick[green_plush_toy] & F (near[basket] & '
     'F release[green_plush_toy, basket])))'),
])
def test_household_requests(combined, text, formula):
    assert str(combined.translate(text).formula) == formula


@pytest.mark.parametrize('text, builder, n', [
    ('go to the kitchen exactly three times', exactly, 3),
    ("don't visit the garage more than four times", at_most, 4),
    ('visit the porch at least five times', at_least, 5),
    ('go to the office 2 times at most', at_most, 2),
])
def test_the_model_counts_visits(neural, text, builder, n):
    """Counts are macros of the decoder's language (``atleast N x``...): a count of 5 is 4 tokens."""
    got = neural.translate(text).formula
    place = parse_formula(f'near[{referents_of(got)[0]}]')
    assert equivalent(got, builder(place, n))


@pytest.mark.parametrize('text', [
    'I have to finish my essay, can you find the lamp',
])
def test_combined_flags_a_disagreement_and_offers_both_readings(combined, neural, text):
    t = combined.translate(text)
    assert t.extra['flagged'] and t.extra['agreement'] is False
    rules = str(make_translator('offline').translate(text).formula)
    readings = [str(t.formula)] + list(t.extra['alternatives'])
    assert str(neural.translate(text).formula) in readings and rules in readings
    assert any('read this differently' in w or 'reads this differently' in w for w in t.extra['unread'])


def test_combined_takes_over_a_refusal_flagged(combined):
    t = combined.translate('bring me over to the printer')
    assert str(t.formula) == 'F near[printer]'
    assert t.extra['flagged'] and 'rules could not read' in t.extra['unread'][0]


def test_combined_agreement_is_not_flagged(combined):
    t = combined.translate('go to the sofa, then the door')
    assert str(t.formula) == 'F (near[sofa] & F near[door])'
    assert t.extra['agreement'] is True and not t.extra['flagged']


@pytest.mark.parametrize('text', ['visit the kitchen -3 times', 'visit the kitchen 50 times', 'qwzx vvv'])
def test_rules_refusals_of_counts_and_gibberish_stand(combined, text):
    with pytest.raises(LtlInstructError):
        combined.translate(text)


def test_snaps_names_to_the_landmarks_given():
    t = make_translator('neural', landmarks=('blue_room', 'green_room', 'red_room', 'yellow_room'))
    assert str(t.translate('go to the green area but stay out of the blue one').formula).startswith(
        'F near[green_room]')


def test_the_dialog_offers_the_model_reading_and_takes_it(combined):
    import json
    from ltl_instruct.commands.translate import interactive
    from ltl_instruct.core.language.verification import classify_reply
    assert classify_reply('alternative 1').kind == 'alternative'
    assert classify_reply('take alt 2').index == 2
    assert classify_reply('go to the alternative entrance').kind == 'correction'
    text = 'I have to finish my essay, can you find the lamp'
    other = combined.translate(text).extra['alternatives'][0]
    replies = iter([text, 'alternative 1', 'yes'])
    said: list[str] = []
    assert interactive(combined, lambda _: next(replies), said.append) == 0
    assert f'Alternative 1: {other}' in said[0]
    assert 'read this differently' in said[0] or 'reads this differently' in said[0]
    assert json.loads(said[-1])['formula'] == other


def test_a_bad_alternative_number_is_refused(combined):
    from ltl_instruct.commands.translate import interactive
    replies = iter(['Go to the kitchen. On top of that, never enter the hall', 'alternative 9', 'no'])
    said: list[str] = []
    assert interactive(combined, lambda _: next(replies), said.append) == 1
    assert 'there is no alternative 9' in said


def test_a_reading_cut_at_the_encoder_length_is_flagged(neural):
    long = 'go to the kitchen, then the hall, ' * 20 + 'and finally the garage'
    t = neural.translate(long)
    assert t.extra['flagged'] and any('read only the first' in n for n in t.notes)
    assert not neural.translate('go to the kitchen, then the hall').extra['flagged']

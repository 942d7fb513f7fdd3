"""Readings found on the blind set B4, second round (an elderly widow's home robot and garden drone).

Every case is an instruction of the blind set B4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

BLIND_ROUND_B4B = [
    # "not the blue one, the tartan one": the adjective of what it is not finds the thing said before,
    # the new one takes its noun (and its place); a statement about the old one after it is left out
    ("Bring the blue blanket to the sofa - oh wait, not the blue one, the tartan one, the blue one's in the "
     'wash.',
     'F (near[tartan_blanket] & F (pick[tartan_blanket] & F (near[sofa] & F '
     'release[tartan_blanket, sofa])))'),
    ('Go to the blue door - no wait, not the blue one, the red one.',
     'F near[red_door]'),
    ('Put the big box on the table - no, not the big one, the small one, the big one is too heavy.',
     'F (near[small_box] & F (pick[small_box] & F (near[table] & F release[small_box, table])))'),
    ('Go to the blue mug on the shelf - sorry, not the blue one, the green one.',
     'F near[green_mug::isabove(shelf)]'),
    # "I want you to learn where it lives", "so you remember where they go": nothing to do but remember
    ('Go over to the blue vase on the mantelpiece, would you? My granddaughter Lily made it in her pottery '
     'class and I want you to learn where it lives.',
     'F near[blue_vase::isabove(mantelpiece)]'),
    ('Put the scissors in the drawer, I want you to remember where they go.',
     'F (near[scissors] & F (pick[scissors] & F (near[drawer] & F release[scissors, drawer])))'),
    # "exactly twice, once in the morning and once at night": the count said again, spread over the day
    ("Go to the medecine cabinet exactly twice today, once in the morning and once at night, that's how "
     'often I take my pills.',
     '!near[medicine_cabinet] U (near[medicine_cabinet] & (near[medicine_cabinet] U (!near[medicine_cabinet] '
     '& (!near[medicine_cabinet] U (near[medicine_cabinet] & (near[medicine_cabinet] W G '
     '!near[medicine_cabinet]))))))'),
    ('Go to the shed three times, once in the morning, once at noon and once at night.',
     'F (near[shed] & F (!near[shed] & F (near[shed] & F (!near[shed] & F near[shed]))))'),
    # list positions after a scene: an adjective in -ly ends no list ("a woolly hat"), nor does a clause
    # saying who gave it ("a little china dog my mother gave me")
    ("There's a scarf, a pair of gloves and a woolly hat on the bench by the door. Would you put the last "
     'one in the hall cupboard, please.',
     'F (near[woolly_hat] & F (pick[woolly_hat] & F (near[hall_cupboard] & F release[woolly_hat, '
     'hall_cupboard])))'),
    ("On the dresser there's a jewellery box, a hairbrush and a little china dog my mother gave me. Go to "
     'the last one, please.',
     'F near[little_china_dog]'),
    ('Take the curly wig to the box.',
     'F (near[curly_wig] & F (pick[curly_wig] & F (near[box] & F release[curly_wig, box])))'),
    # "backwards from how I said them"; "but in reverse order" after the list (was read in any order,
    # with a place "reverse")
    ('The hall cupboard, the linen press and the airing cupboard: visit them all, but backwards from how I '
     'said them.',
     'F (near[airing_cupboard] & F (near[linen_press] & F near[hall_cupboard]))'),
    ('Go to the shed, the barn and the pond, in the opposite order to the way I listed them.',
     'F (near[pond] & F (near[barn] & F near[shed]))'),
    ('visit the shed and the barn and the pond, but in reverse order.',
     'F (near[pond] & F (near[barn] & F near[shed]))'),
    # "wait by me on the sofa", "sit with me in the kitchen": go where the person is
    ('Please bring the photo album that\'s on the piano to the coffee table, then come and wait by me on the '
     'sofa.',
     'F (near[photo_album::isabove(piano)] & F (pick[photo_album::isabove(piano)] & F (near[coffee_table] & '
     'F (release[photo_album::isabove(piano), coffee_table] & F near[sofa]))))'),
    ('Go to the hall, then come and sit with me in the kitchen.',
     'F (near[hall] & F near[kitchen])'),
    # "go and put yourself by X": go there
    ("Go and put yourself by the kettle, but only after you've stopped at the fridge, I want to be sure its "
     'door is shut properly.',
     'F near[kettle] & (!near[kettle] U near[fridge])'),
    # "the other one has the sharp knives in it", "One of them has my hearing aid tucked in it": said about
    # things named before, no count and no place
    ('Put the scissors in the drawer under the kitchen counter - sorry, I ment the drawer next to the '
     'cooker, the other one has the sharp knives in it.',
     'F (near[scissors] & F (pick[scissors] & F (near[drawer::isnextto(cooker)] & F release[scissors, '
     'drawer::isnextto(cooker)])))'),
    ('Would you go to the cushion on the sofa or the cushion under the coffee table? One of them has my '
     'hearing aid tucked in it.',
     'F near[cushion::isabove(sofa)] | F near[cushion::isbelow(coffee_table)]'),
    # "she's in one of her moods", "he's in a bad mood" after an avoidance: how it is, not where
    ("Go to the airing cupboard, and please keep well away from the cat, she's in one of her moods today.",
     'F near[airing_cupboard] & G !near[cat]'),
    ('Go to the den, and avoid the dog, he is in a bad mood.',
     'F near[den] & G !near[dog]'),
    # "..., I want to know if ..." after the request: why the visit, asks for nothing
    ("Fly to the washing line, but only after you've been round to the front hedge, I want to know if the "
     'gardener has trimmed it.',
     'F near[washing_line] & (!near[washing_line] U near[front_hedge])'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_B4B)
def test_readings_found_on_blind_set_b4b(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# A time of day is no place: where the onces do not add up to the count, or stand alone, it is refused;
# a remark holding a rule word is refused, never left out.
REFUSED_B4B = [
    'Go to the shed three times, once in the morning and once at night.',
    'Go to the shed, once in the morning.',
    # what the person wants to know holds a rule word: never left out
    'Go to the pond, I want to know if it is not frozen.',
]


@pytest.mark.parametrize('instruction', REFUSED_B4B)
def test_refused_on_blind_set_b4b(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

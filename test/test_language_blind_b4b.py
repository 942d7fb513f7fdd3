"""Readings found on the blind set B4, second round (an elderly widow's home robot and garden drone).

Every case is an instruction of the blind set B4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import T, check_translation

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
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_B4B)
def test_readings_found_on_blind_set_b4b(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# A time of day is no place: where the onces do not add up to the count, or stand alone, it is refused.
REFUSED_B4B = [
    'Go to the shed three times, once in the morning and once at night.',
    'Go to the shed, once in the morning.',
]


@pytest.mark.parametrize('instruction', REFUSED_B4B)
def test_time_of_day_is_refused(instruction: str) -> None:
    with pytest.raises(TranslationError):
        T.translate(instruction)

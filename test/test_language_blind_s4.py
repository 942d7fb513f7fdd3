"""Readings found on the blind set S4 (a care home's staff talking to its robot): each was misread blind.

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The whole set stays outside
the repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_S4 = [
    # an avoidance taken back, then "it's Y that's wet" / "it's Y I'm worried about" names what
    # to avoid instead (Y was left out as a remark: silently no avoidance)
    ("Stay away from the kitchen. Oh, actually no, the kitchen's fine now, it's the laundry floor that's "
     "wet. Go on to the office.",
     'F near[office] & G !near[laundry_floor]'),
    ("Don't go near the lift. Well, the lift's fine actually, it's the stairs I'm worried about. Go up to "
     'the upstairs lounge.',
     'F near[upstairs_lounge] & G !near[stairs]'),
    ('Keep away from the pond, actually the pond is fine, it is the greenhouse that is locked, go to the '
     'shed',
     'F near[shed] & G !near[greenhouse]'),
    # a count corrected, then said again more precisely ("just the once - exactly once"): the precise one
    ('Check the front door three times tonight. Actually make it jsut the once - exactly once - the night '
     'staff will do the rest.',
     '!near[front_door] U (near[front_door] & (near[front_door] W G !near[front_door]))'),
    ('Visit the shed twice. No, make that once, exactly once, and then go to the barn.',
     'F (near[shed] & F near[barn]) & (!near[shed] U (near[shed] & (near[shed] W G !near[shed])))'),
    # "Actually, just go to Y" replaces the sentence before, also after its full stop (Y was added after
    # it), and a reason in front of it ("it's chucking it down, ...") asks for nothing
    ("Go to the garden or the patio. Actually it's chucking it down, just go to the conservatory.",
     'F near[conservatory]'),
    ('Go to the garden. Actually, just go to the conservatory.',
     'F near[conservatory]'),
    ('Go to the garden, then the shed. Actually, just go to the conservatory.',
     'F near[conservatory]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_S4)
def test_readings_found_on_blind_set_s4(instruction: str, gold: str) -> None:
    """Each instruction reads as its writer's formula."""
    check_translation(instruction, gold)

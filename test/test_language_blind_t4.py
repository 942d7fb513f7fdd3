"""Readings found on the blind set T4 (a drone operator at the seaside: shots, passes, corrections).

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The whole set stays outside
the repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_T4 = [
    # goals in any order "and only then" a last one: none of them comes after it (was a plain chain)
    ('Do the harbour mouth and the breakwater first, in any order, and only then the ferry terminal.',
     'F near[ferry_terminal] & (!near[ferry_terminal] U near[harbour_mouth]) & '
     '(!near[ferry_terminal] U near[breakwater])'),
    ('Go to the garage and the shed, and only then the gate.',
     'F near[gate] & (!near[gate] U near[garage]) & (!near[gate] U near[shed])'),
    # a picture asked of a place is a visit there ("get me a shot of X" was a pick of x_shot)
    ('Get me a shot of the old mill.',
     'F near[old_mill]'),
    ('Take a couple of photos of the barn, then land at the pad.',
     'F (near[barn] & F near[pad])'),
    # "I need shots of A and B, don't mind which you do first": both, any order (was refused)
    ("I need shots of the church spire and the clock tower, don't mind which you do first.",
     'F near[church_spire] & F near[clock_tower]'),
    # "after you've done X" is a visit of X, the scope's start (was "when finished": avoided always)
    ("After you've done the church spire, don't go back near the bell tower.",
     'F (near[church_spire] & G !near[bell_tower])'),
    ("Don't fly over the campsite till you've done the dunes.",
     '(!near[campsite] U near[dunes]) & F near[dunes]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_T4)
def test_blind_round_t4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

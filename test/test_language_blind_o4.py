"""Readings found on the blind sets O4 and P4: each was misread while its set was still blind.

Every case is an instruction from those sets (or a sentence of our own for the same construction),
with the formula its writer gave; the translator must now give a formula equivalent to it on
automata (names included). The whole sets stay outside the repository, so that later rounds are
scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_O4 = [
    # a correction of a scope's place, said with its "only" again
    ('Go to the seminar room only after the kitchen - scratch that, only after the print room.',
     'F near[seminar_room] & (!near[seminar_room] U near[print_room])'),
    ('Go to the seminar room only after the kitchen - sorry, only after the print room.',
     'F near[seminar_room] & (!near[seminar_room] U near[print_room])'),
    # a correction naming the thing again with "it" for the landmark said before
    ('Go to the bin next to the bike rack. Hmm, no, I meant the bin behind it.',
     'F near[bin::isbehind(bike_rack)]'),
    # "not the <landmark>, the one <relation> <place>": the thing said before, its place corrected
    ('Go to the lamp on the dresser. Wait, not the dresser, the one on the bedside table.',
     'F near[lamp::isabove(bedside_table)]'),
    ('Go to the lamp on the dresser. Wait, not the one on the dresser, the one on the bedside table.',
     'F near[lamp::isabove(bedside_table)]'),
]


@pytest.mark.parametrize('instruction, gold', BLIND_ROUND_O4)
def test_blind_round_o4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

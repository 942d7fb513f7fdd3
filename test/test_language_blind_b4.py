"""Readings found on the blind set B4 (an elderly widow's home robot and garden drone).

Every case is an instruction of the blind set B4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_B4 = [
    # forms of address and exclamations between a correction marker and what it corrects
    ('Would you go to the kitchen table, please - oh, no, silly me, I meant the breakfast nook, '
     "that's where I have my toast.",
     'F near[breakfast_nook]'),
    ('Please go to the bathroom - no, sorry, dear, I meant the downstairs toilet, the bathroom is being '
     'retiled this week.',
     'F near[downstairs_toilet]'),
    ('Go to the garage, oh dear, no, I meant the shed.',
     'F near[shed]'),
    # an address with an adjective ("little drone", "my dear") names no place
    ('Now, little drone, would you fly out and hover over the bird bath so I can see whether the '
     'blackbirds are back?',
     'F near[bird_bath]'),
    ('Little drone, pick up the shuttlecock on the conservatory roof and drop it on the lawn.',
     'F (near[shuttlecock::isabove(conservatory_roof)] & F (pick[shuttlecock::isabove(conservatory_roof)] '
     '& F (near[lawn] & F release[shuttlecock::isabove(conservatory_roof), lawn])))'),
    ('Go to the porch, my dear, and then the gate.',
     'F (near[porch] & F near[gate])'),
    # an address inside a list of alternatives is no alternative
    ('Either the sun lounger or the garden swing, dear, go to one of them. It\'s such a lovely day.',
     'F near[sun_lounger] | F near[garden_swing]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_B4)
def test_readings_found_on_blind_set_b4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

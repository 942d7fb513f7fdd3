"""Readings found on the blind set G4 (a restaurant and hotel: kitchen, floor and front desk staff).

Each case is an instruction of the set, with the formula its writer gave, or a sentence of our own
for the same construction; the translator must give a formula equivalent to it on automata
(names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import LtlInstructError
from translation_cases import T, check_translation

BLIND_ROUND_G4 = [
    # a verb-particle compound after a determiner is a noun wherever it stands ("the walk-in?"),
    # also written as one word ("the walkin")
    ("can you get to the walk-in? chef's shouting for you",
     'F near[walk_in]'),
    ('Go to the ice machine to the right of the walk-in.',
     'F near[ice_machine::isrightof(walk_in)]'),
    ("Once you've been to the walkin, don't go back near the pass. Then head over to the dish pit.",
     'F (near[walk_in] & G !near[pass] & F near[dish_pit])'),
    ('Take the parcel to the drop-off.',
     'F (near[parcel] & F (pick[parcel] & F (near[drop_off] & F release[parcel, drop_off])))'),
    # who wants the robot, said after the request, names no place: left out (noted); a "first"
    # in it only where the request gives the order itself
    ('Go to the espresso machine behind the bar, Sofia needs a hand with it.',
     'F near[espresso_machine::isbehind(bar)]'),
    ('Lobby lounge, please. Mr. Alvarez would like a word.',
     'F near[lobby_lounge]'),
    ("Don't go out onto the terrace until you've stopped at the host stand, the Garcias want a word first.",
     '!near[terrace] U near[host_stand]'),
    ("Go to the walk-in, but not until you've been to the pass - chef wants to run through the tickets "
     "with you first - and keep away from the dish pit until you've reached the walk-in, they're mopping "
     "back there and it's like an ice rink.",
     'F near[walk_in] & (!near[walk_in] U near[pass]) & (!near[dish_pit] U near[walk_in])'),
    ('Head to the dry store, the manager is asking for you.',
     'F near[dry_store]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_G4)
def test_readings_found_on_blind_set_g4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


def test_a_summons_with_a_first_of_its_own_is_refused() -> None:
    """"..., Maria wants a word first" with no order in the request: never dropped as a remark."""
    with pytest.raises(LtlInstructError):
        T.translate('Go to the bar, Maria wants a word first.')

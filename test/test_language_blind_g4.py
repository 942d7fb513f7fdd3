"""Readings found on the blind set G4 (a restaurant and hotel: kitchen, floor and front desk staff).

Each case is an instruction of the set, with the formula its writer gave, or a sentence of our own
for the same construction; the translator must give a formula equivalent to it on automata
(names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import LtlInstructError
from translation_cases import RULES, check_translation

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
    # "run X (over) to Y" is a delivery (it was two visits, or left out)
    ("Run the menus over to the host stand, and while you've got them, don't go by the terrace doors - "
     "it's pouring and they'll get soaked.",
     'F (near[menus] & F (pick[menus] & (!near[terrace_doors] U (near[host_stand] & F release[menus, '
     'host_stand]))))'),
    ('Run the spare keys to the front desk.',
     'F (near[spare_keys] & F (pick[spare_keys] & F (near[front_desk] & F release[spare_keys, '
     'front_desk])))'),
    ('Run to the kitchen.',
     'F near[kitchen]'),
    # "on your way out to X": on the way to X (it was read over the whole run); "once you're (out)
    # there" after it is from X on
    ("On your way out to the terrace keep away from the host stand, and once you're out there, stay clear "
     'of the patio heaters.',
     '(!near[host_stand] U near[terrace]) & F (near[terrace] & G !near[patio_heaters])'),
    ("On your way to the garden keep away from the shed, and once you're there, avoid the pond.",
     '(!near[shed] U near[garden]) & F (near[garden] & G !near[pond])'),
    # "it's a guide dog" says what the thing named is: no new thing for "it"; "leave it be" after an
    # avoidance says the avoidance again (it was "never go there again" of the last goal)
    ('Go to the bar, then the host stand. Stay away from the dog under table 5 the whole time, please - '
     "it's a guide dog, leave it be.",
     'F (near[bar] & F near[host_stand]) & G !near[dog::isbelow(table_5)]'),
    ('Keep away from the cat, leave it alone, and go to the porch.',
     'F near[porch] & G !near[cat]'),
    # a list of places, then "hit them ...": "hit" is the verb, no fourth item of the list
    ('The pass, the bar, the host stand - hit them in revrse order.',
     'F (near[host_stand] & F (near[bar] & F near[pass]))'),
    ('the shed, the barn, the coop - hit them in that order',
     'F (near[shed] & F (near[barn] & F near[coop]))'),
    # a name that is also a verb ("pass") in a bare list of places is the name
    ('walk-in then pass. oh wait, other way round',
     'F (near[pass] & F near[walk_in])'),
    ('the walk-in then pass',
     'F (near[walk_in] & F near[pass])'),
    # "menu stand" is one name (it was read "stand next to the lift")
    ('go to the menu stand nxt to the lift thats on the left of the reception desk',
     'F near[menu_stand::isnextto(lift::isleftof(reception_desk))]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_G4)
def test_readings_found_on_blind_set_g4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


def test_a_summons_with_a_first_of_its_own_is_refused() -> None:
    """"..., Maria wants a word first" with no order in the request: never dropped as a remark."""
    with pytest.raises(LtlInstructError):
        RULES.translate('Go to the bar, Maria wants a word first.')


def test_not_to_be_disturbed_is_no_place_to_avoid() -> None:
    """"they've asked not to be disturbed" holds a rule word and names no place: refused."""
    with pytest.raises(LtlInstructError):
        RULES.translate("Head to table 2 first. After that, avoid table 3 - they've asked not to be "
                        'disturbed - and then go to the bar.')

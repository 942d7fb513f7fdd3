"""Readings found on the blind set S4 (a care home's staff talking to its robot): each was misread blind.

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The whole set stays outside
the repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

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
    # "round the back", "out the back": roughly where a thing is, no place of its own (the whole
    # drone leg was left out)
    ('Drone, survey the car park first, then hover over the bins round the back, and after that come down at '
     'the staff entrance.',
     'F (near[car_park] & F (near[bins] & F near[staff_entrance]))'),
    ('go to the shed out the back then the gate',
     'F (near[shed] & F near[gate])'),
    # what somebody wants, said as a sentence before the request, is no place ("arthur_wants_his_wellies"
    # was the place every other one waited for)
    ("Arthur wants his wellies. You can head out to the garden, but not till you've been to the boot room "
     'and the front porch - both, any order.',
     'F near[garden] & (!near[garden] U near[boot_room]) & (!near[garden] U near[front_porch])'),
    ('Marco wants a coffee. Go to the kitchen.',
     'F near[kitchen]'),
    # a warning of a mess ("you'll trail mud everywhere!") says why (it was a goal)
    ("Once you've been out in the garden, don't go back near the kitchen - you'll trail mud everywhere! Then "
     'head to the boot room.',
     'F (near[garden] & G !near[kitchen] & F near[boot_room])'),
    # a pet or a person named without an article, with a verb of what it does ("Tiddles scratches"), says
    # why (it was avoided as a place)
    ('Put the flower vase on the table in front of the big window, and don\'t go anywhere near the cat '
     'basket, Tiddles scratches.',
     'F (near[flower_vase] & F (pick[flower_vase] & F (near[table::isinfrontof(big_window)] & '
     'F release[flower_vase, table::isinfrontof(big_window)]))) & G !near[cat_basket]'),
    ('avoid the cat basket, Rex bites strangers', 'G !near[cat_basket]'),
    # "Arthur's waiting" between commas is a clause of its own (Arthur was a second destination)
    ("Take the teapot to the conservatory, Arthur's waiting, and keep away from the stairs while you've got "
     "it - it's hot.",
     'F (near[teapot] & F (pick[teapot] & (!near[stairs] U (near[conservatory] & '
     'F release[teapot, conservatory]))))'),
    # "'s" before a past participle is "has" ("Stan's finished with it" was a place stans_finished)
    ("Could you throw away the old newspaper, love? Stan's finished with it.",
     'F (near[old_newspaper] & F (pick[old_newspaper] & F (near[trash_can] & '
     'F release[old_newspaper, trash_can])))'),
    # ", wherever Joan's sat" after a choice says which one, no place (it was a third alternative)
    ("Take the blanket and put it on the sofa or the recliner, wherever Joan's sat.",
     'F (near[blanket] & F (pick[blanket] & (F (near[sofa] & F release[blanket, sofa]) | '
     'F (near[recliner] & F release[blanket, recliner]))))'),
    ('Go to the lounge or the garden, wherever she is sitting.',
     'F near[lounge] | F near[garden]'),
    # "backwards, gate first": the start of the reversed list said again (it was glued to the first thing
    # listed, "ground_floor_bathroom_gate", as the first goal)
    ('Three places need checking before lunch: the ground floor bathroom, the lift and the garden gate. Do '
     'them backwards, gate first.',
     'F (near[garden_gate] & F (near[lift] & F near[ground_floor_bathroom]))'),
    ('Three places need checking: the bathroom, the lift and the garden gate. Do them backwards, starting '
     'with the gate.',
     'F (near[garden_gate] & F (near[lift] & F near[bathroom]))'),
    # "either lounge, the big one or the little one": the kind, then which (the plain lounge was a
    # third alternative)
    ('Go to either lounge, the big one or the little one, just keep clear of the hoist whichever you pick.',
     '(F near[big_lounge] | F near[little_lounge]) & G !near[hoist]'),
    # "on your wat to": a slip in "on your way to" (a goal "wat" was added and the scope lost)
    ("On your wat to the dinning room keep clear of the mop bucket, there's water everywhere.",
     '!near[mop_bucket] U near[dining_room]'),
    # "wait, do Y instead of X" after a reason that names X ("they're mopping the kitchen - ..."): the
    # reason asks for nothing, Y replaces X (refused)
    ("Go to the laundry, then the kitchen, and keep off the wet floor. Wait, they're mopping the kitchen - "
     'do the dining room instead of the kitchen.',
     'F (near[laundry] & F near[dining_room]) & G !near[wet_floor]'),
    # "the whole way round": the whole way (refused)
    ('Stop at the quiet lounge, then the activity room, and lastly the garden door. And please keep well '
     'away from the stairs the whole way round.',
     'F (near[quiet_lounge] & F (near[activity_room] & F near[garden_door])) & G !near[stairs]'),
]

# A condition on what happens to a thing ("if it gets dropped") is no place to wait for: refused (it
# was read as a weak until on a place "gets_dropped")
REFUSED_S4 = [
    "Take the teapot to the conservatory and keep away from the stairs while you've got it, if it gets "
    "dropped we'll never find it.",
]


@pytest.mark.parametrize('instruction', REFUSED_S4)
def test_refused_on_blind_set_s4(instruction: str) -> None:
    """What cannot be placed is refused, never guessed."""
    with pytest.raises(TranslationError):
        RULES.translate(instruction)


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_S4)
def test_readings_found_on_blind_set_s4(instruction: str, gold: str) -> None:
    """Each instruction reads as its writer's formula."""
    check_translation(instruction, gold)

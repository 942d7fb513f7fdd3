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
    # a remark after "once you're there" ("the ferry's fine") leaves the scope to the command after it
    ("Don't go near the ferry until you're at the harbour mouth. Once you're there the ferry's fine, "
     'but stay off the shipping lane.',
     '(!near[ferry] U near[harbour_mouth]) & F (near[harbour_mouth] & G !near[shipping_lane])'),
    # "on the way out" inside an avoidance is the way there, never left out as courtesy (it was: global)
    ("Fly out to the sandbank - don't go over the seal colony on the way out - then RTH.",
     '(!near[seal_colony] U near[sandbank]) & F (near[sandbank] & F near[home_point])'),
    ('Go to the pier, and avoid the reef on your way out.',
     '!near[reef] U near[pier]'),
    ('Swing by the mailroom on your way out.',
     'F near[mailroom]'),
    # "RTH" (a drone's return to home) goes to the home point (it was a place "rth")
    ('Do a flyover of the campsite and then RTH.',
     'F (near[campsite] & F near[home_point])'),
    # "drop it over X" releases it at X (the release was lost: only a visit of X)
    ('Pick up the bait rig and drop it over the sandbank, the bass are biting out there.',
     'F (near[bait_rig] & F (pick[bait_rig] & F (near[sandbank] & F release[bait_rig, sandbank])))'),
    ('Bring the cup over to the sink.',
     'F (near[cup] & F (pick[cup] & F (near[sink] & F release[cup, sink])))'),
    # the light or the weather as a deadline is a time, no place ("light_goes" was a place to visit first)
    ('Go to the pier, quick, before the light goes!',
     'F near[pier]'),
    ('Survey the field before it gets dark, then land at the pad.',
     'F (near[field] & F near[pad])'),
    # "after the X," with no verb opens a scope at X, a goal (refused); seaside names are spelt right
    ('After the lighthose, stay off the cliffs and do two passes over the bay.',
     'F (near[lighthouse] & G !near[cliffs] & F (near[bay] & F (!near[bay] & F near[bay])))'),
    ('After the garage, keep away from the pond.',
     'F (near[garage] & G !near[pond])'),
    # a story of an earlier pass after the request says why ("pass the sun" was a goal: silently wrong)
    ('hover over the church spire twise, first pass the sun was right behind it',
     'F (near[church_spire] & F (!near[church_spire] & F near[church_spire]))'),
    ('go to the shed, last time the cat was in there',
     'F near[shed]'),
    # "there's kids everywhere" run on after an avoidance says why (refused)
    ('go over to the beach huts n then the rock pools, dont go near the paddling pool theres kids everywhere',
     'F (near[beach_huts] & F near[rock_pools]) & G !near[paddling_pool]'),
    # "X is a (strict) no-fly zone": X kept away from (refused)
    ('The naval base is a strict no-fly zone, keep right away from it. Head to the quarry.',
     'F near[quarry] & G !near[naval_base]'),
    ('The airfield is a no-fly zone. Survey the farm.',
     'F near[farm] & G !near[airfield]'),
    # "Not both though." makes the choice exclusive (refused)
    ('Do the north beach or the south beach. Not both though.',
     '(F near[north_beach] & G !near[south_beach]) | (F near[south_beach] & G !near[north_beach])'),
    # places alone with "in any order" / "in that order" (refused: no action)
    ('Lighthouse then harbour, or harbour then lighthouse - your call.',
     'F (near[lighthouse] & F near[harbour]) | F (near[harbour] & F near[lighthouse])'),
    ('Pier, beach, harbour in that order.',
     'F (near[pier] & F (near[beach] & F near[harbour]))'),
    # "do that lot backwards" is the list said before, reversed; ", starting from X" where X already comes
    # first says it again (refused; then a last visit of X was guessed)
    ('Beach huts, pier, harbour wall... do that lot backwards, starting from the wall.',
     'F (near[harbour_wall] & F (near[pier] & F near[beach_huts]))'),
    ('Go to the den, then the hall, starting with the den.',
     'F (near[den] & F near[hall])'),
    # "X to Y" with no verb opening a sentence is the route (refused: no action)
    ('Lighthouse to harbour wall, then do that same run again straight after.',
     'F (near[lighthouse] & F (near[harbour_wall] & F (near[lighthouse] & F near[harbour_wall])))'),
    ('The pier to the lighthouse, then land at the pad.',
     'F (near[pier] & F (near[lighthouse] & F near[pad]))'),
    # "send it up to X" first thing (no "it" named before) flies the drone there (refused)
    ('Send it up to the clifftop!!',
     'F near[clifftop]'),
    # a heading "... time!" before the request asks for nothing (refused)
    ('Reveal shot time! Start low at the harbour wall and then climb up to the lighthouse lamp room.',
     'F (near[harbour_wall] & F near[lighthouse_lamp_room])'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_T4)
def test_blind_round_t4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

"""Red-team cases of the offline translator: remarks, reasons, statements and corrections that hold a rule.

Each sentence was written to make a rule that leaves words out (a reason after a comma, a remark
about somebody else, a form of address, "for the visitor", ...) fire where the words carry a
constraint. A reading must be right or a refusal (``TranslationError``): never silently wrong
about what to avoid, the order or the count.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

# Read right: the remark or reason is left out, and the rule beside it is kept.
RIGHT: list[tuple[str, str]] = [
    ('go to the kitchen, Marco gets chatty', 'F near[kitchen]'),
    ('go to the kitchen, the dog wants out', 'F near[kitchen]'),
    ('go to the kitchen for the visitor', 'F near[kitchen]'),
    ('go to the kitchen for the visitor and avoid the lobby', 'F near[kitchen] & G !near[lobby]'),
    ('go to the kitchen, the cat is in one of her moods', 'F near[kitchen]'),
    ('go to the kitchen, I want to know if the window is shut', 'F near[kitchen]'),
    ('go to the kitchen, they want to settle up', 'F near[kitchen]'),
    ('go to the bar, the gentleman there wants another', 'F near[bar]'),
    ('go to the bar, VIPs in at eight', 'F near[bar]'),
    ('go to the bar, never the cellar', 'F near[bar] & G !near[cellar]'),
    ('go to the bar, but never the cellar', 'F near[bar] & G !near[cellar]'),
    ('go to the kitchen, the cat is asleep, never the bedroom', 'F near[kitchen] & G !near[bedroom]'),
    ('go to the kitchen, they want to settle up, go to the bar after', 'F (near[kitchen] & F near[bar])'),
    ('go to the kitchen, there is a wasp nest by it, avoid the shed', 'F near[kitchen] & G !near[shed]'),
    # a reason, then "so" and a command without a comma: the reason goes, the command stays (the
    # whole part had been left out as the reason, or its subject read as a goal)
    ('go to the kitchen, my wife is asleep so stay out of the bedroom',
     'F near[kitchen] & G !near[bedroom]'),
    ('go to the kitchen, my wife is asleep, so stay out of the bedroom',
     'F near[kitchen] & G !near[bedroom]'),
    ('go to the kitchen, somebody left the gate open so avoid the garden',
     'F near[kitchen] & G !near[garden]'),
    ('go to the kitchen, the baby is sleeping so avoid the nursery', 'F near[kitchen] & G !near[nursery]'),
    ('go to the kitchen, the cat will scratch so avoid the den', 'F near[kitchen] & G !near[den]'),
    ('go to the kitchen, the cat is in one of her moods so keep out of the bedroom',
     'F near[kitchen] & G !near[bedroom]'),
    ("go to the kitchen, lifeguard's off today so avoid the pool", 'F near[kitchen] & G !near[pool]'),
    ('go to the kitchen, the carer will be here any minute so stay out of the hall',
     'F near[kitchen] & G !near[hall]'),
    ('Take off from the launch pad, fly out to the field station, pick up the sample vial that the team has '
     'left for you there, and subsequently drop it at the rooftop pad on the biology building.',
     'F (near[field_station] & F (near[sample_vial] & F (pick[sample_vial] & F (near[rooftop_pad::isabove('
     'biology_building)] & F release[sample_vial, rooftop_pad::isabove(biology_building)]))))'),
    ('go to the kitchen, Marco gets chatty so avoid the lounge', 'F near[kitchen] & G !near[lounge]'),
    ('go to the kitchen, Marco gets chatty, so avoid the lounge', 'F near[kitchen] & G !near[lounge]'),
    ('go to the bar, VIPs in at eight so avoid the lobby', 'F near[bar] & G !near[lobby]'),
    ('go to the kitchen, marketing wants footage', 'F near[kitchen]'),
    ("go to the kitchen, I don't want the baby woken up", 'F near[kitchen]'),
    # "for the visitor" at the start says who it is for (the visitor was a goal)
    ('for the visitor, avoid the lobby', 'G !near[lobby]'),
    ('go to the little drone pad, then the shed', 'F (near[little_drone_pad] & F near[shed])'),
    ('go to the kitchen, sorry, never the hall', 'F near[kitchen] & G !near[hall]'),
    ('go to the kitchen, the cat is fine, just don\'t go near the fish tank',
     'F near[kitchen] & G !near[fish_tank]'),
    # "no, never ..." is a rule, not "never mind" (it was "go to the hall": the robot went where forbidden)
    ('go to the kitchen, no, never go to the hall', 'F near[kitchen] & G !near[hall]'),
    ('go to the kitchen, no wait, never go to the hall', 'F near[kitchen] & G !near[hall]'),
    ('go to the kitchen, no, never mind, go to the hall', 'F near[hall]'),
    # a verb of leaving out that corrects nothing said before stays ("forget" had been dropped: a goal)
    ('go to the garage, forget the kitchen', 'F near[garage]'),
    ('go to the garage, ignore the kitchen', 'F near[garage]'),
    ('go to the garage and forget the kitchen', 'F near[garage]'),
    ('go to the garage, skip the kitchen', 'F near[garage]'),
    ('go to the kitchen twice, Marco gets chatty',
     'F (near[kitchen] & F (!near[kitchen] & F near[kitchen]))'),
]

# Refused: the part said as a reason or remark holds a rule, a command or a pronoun for a thing it named.
REFUSED: list[str] = [
    'go to the kitchen, we are avoiding the hall today',   # (the avoidance was left out as a reason)
    'go to the kitchen, my only rule is stay out of the garage',
    'go to the kitchen, my one rule: the garage is off limits',
    'go to the kitchen, my husband hates the robot in the study',
    'go to the kitchen, it could never go through the garage',
    'go to the kitchen, it can only use the back door',
    'go to the kitchen, he worries about the study so skip it',
    'go to the kitchen, grandma is sleeping in the den so keep out',
    # "it" is the den / the hall left out with the reason, never the kitchen (G !near[kitchen] before)
    'go to the kitchen, grandma is sleeping in the den so keep out of it',
    'go to the kitchen, the floor crew just waxed the hall so avoid it',
    'go to the kitchen, dad hates the robot near the pool',
    'go to the kitchen, the dog wants out, don\'t let it near the door',
    'go to the kitchen, the cat is in one of her moods, keep out of the bedroom',
    'go to the kitchen, I want to know if you avoided the hall',
    'go to the kitchen, I want to know if the window is shut before you go to the garage',
    'go to the kitchen, they want to settle up before you visit the bar',
    "go to the kitchen, we're keeping out of the hall today",
    'go to the kitchen, she gets anxious if it comes near the nursery',
    'go to the kitchen, the neighbours complain when it goes on the lawn',
    'go to the kitchen, the guests want the library to themselves',
    'go to the kitchen, Marco wants nobody in the lab',   # (a goal "marco_wants_nobody")
    'go to the kitchen, the boss wants no robots in the lobby',   # (a goal "boss_wants")
    'go to the kitchen, Marco gets chatty so stay away from him',   # (G !near[him])
    "go to the kitchen, I'd prefer the hall be avoided",   # (the hall was a goal, "be avoided" left out)
    "go to the kitchen, I don't want the hall visited",   # (left out as a reason)
]


@pytest.mark.parametrize('instruction,gold', RIGHT)
def test_red_team_readings(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


@pytest.mark.parametrize('instruction', REFUSED)
def test_red_team_refusals(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

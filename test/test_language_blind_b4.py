"""Readings found on the blind set B4 (an elderly widow's home robot and garden drone).

Every case is an instruction of the blind set B4, with the formula its writer gave, or a sentence
of our own for the same construction; the translator must give a formula equivalent to it on
automata (names included). The set itself stays outside the repository.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

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
    # a reason after an avoidance, said about people, animals or the thing ("the corner curls up"), and
    # reasons said one after another: left out, never read as more things to avoid
    ('Could you take the teapot to the dining table, and while you\'re carrying it please keep away from '
     'the toy box, Sam leaves his little cars all around it.',
     'F (near[teapot] & F (pick[teapot] & (!near[toy_box] U (near[dining_table] & F release[teapot, '
     'dining_table]))))'),
    ("On your way to the greenhouse, do stay away from the pond, the grandchildren's frogs live in there.",
     '!near[pond] U near[greenhouse]'),
    ('Go to the lamp to the right of the sofa, but keep away from the rug in front of the fireplace, the '
     'corner curls up.',
     'F near[lamp::isrightof(sofa)] & G !near[rug::isinfrontof(fireplace)]'),
    ('Go to the coat stand and then to the shoe cupboard, but keep away form the glass-topped table the '
     'whole time, the grandchildren already chipped it once.',
     'F (near[coat_stand] & F near[shoe_cupboard]) & G !near[glass_topped_table]'),
    ("Bring the cushion that's on the window seat over to the rocking chair, and while you're holding it "
     "don't go near the cat, she thinks every cushion in this house belongs to her, and she has claws "
     'like little fish hooks.',
     'F (near[cushion::isabove(window_seat)] & F (pick[cushion::isabove(window_seat)] & (!near[cat] U '
     '(near[rocking_chair] & F release[cushion::isabove(window_seat), rocking_chair]))))'),
    ('Go to the shed, avoid the pond, Tom leaves his bike next to it.',
     'F near[shed] & G !near[pond]'),
    # "altogether" is no part of a name: "skip X altogether" cancels X, "stay away from X altogether"
    ('Go to the larder, then the back porch, then the garden shed - hmm, actually, skip the back porch '
     'altogether.',
     'F (near[larder] & F near[garden_shed])'),
    ("Put the milk back in the fridge, please, and stay away from the cat flap altogether, she's been "
     'bringing in mice.',
     'F (near[milk] & F (pick[milk] & F (near[fridge] & F release[milk, fridge]))) & G !near[cat_flap]'),
    # a reason, then "so" and the correction: "..., she's gone out, so forget about the cat"
    ('Go to the kitchen and then the dining room, and avoid the cat on the way to the dining room - oh, '
     "she's gone out, so forget about the cat.",
     'F (near[kitchen] & F near[dining_room])'),
    ("go to the kitchen, the door is shut, so forget the kitchen and go to the hall",
     'F near[hall]'),
    ('Please go to the pantry, and avoid the mop bucket - oh, actually, I moved the bucket outside this '
     'morning, so avoid the step stool instead.',
     'F near[pantry] & G !near[step_stool]'),
    ('Go to the pantry and avoid the mop bucket. Actually, the bucket is outside, so avoid the step stool '
     'instead.',
     'F near[pantry] & G !near[step_stool]'),
    # a reason said after a correction, with the person as subject ("I always muddle them up")
    ("I've got a toaster, a kettle and a microwave on the counter. Go to the second one... no, sorry, the "
     'third, I always muddle them up.',
     'F near[microwave]'),
    # an aside between commas ("definitely") keeps the parts on either side apart
    ('Go to the piano or the bureau - actually, make it the bureau, definitely, Lily has been fiddling '
     'with the piano lid.',
     'F near[bureau]'),
    # a sentence ending in "instead" replaces the step before; "no, that's too small" drops it
    ("Land on the garden bench - oh no, it's just been painted! Land on the bird table instead. No, "
     "that's too small; the patio, then.",
     'F near[patio]'),
    ('Go to the garage. Go to the shed instead.',
     'F near[shed]'),
    ('Go to the garage and avoid the pond. Avoid the barn instead.',
     'F near[garage] & G !near[barn]'),
    # a greeting ("good morning") is no place; an emphatic "do" before "be" ("do be gentle")
    ('Good morning, dear. Would you be so kind as to go over to the upright piano? My late husband used to '
     'play it every Sunday after church, so do be gentle around it.',
     'F near[upright_piano]'),
    ('Good evening. Go to the piano.',
     'F near[piano]'),
    # a state checked where the robot goes ("to see that it's locked", "to make sure it is"): no goal
    ("Would you go by the front door to see that it's locked, and then the back door as well? I always "
     'worry about that at night.',
     'F (near[front_door] & F near[back_door])'),
    ('go to the window to see if it is raining',
     'F near[window]'),
    ('go to the front door to make sure it is locked, then the shed',
     'F (near[front_door] & F near[shed])'),
    # "bring in the post", "bring up the basket": the particle before the thing
    ("Bring in the post and put it on the hall table, and please don't go out to the letterbox more than "
     "once, the neighbours will think I'm expecting a parcel.",
     'F (near[post] & F (pick[post] & F (near[hall_table] & F release[post, hall_table]))) & '
     '(!near[letterbox] W (near[letterbox] & (near[letterbox] W G !near[letterbox])))'),
    ('bring up the laundry basket to the bedroom',
     'F (near[laundry_basket] & F (pick[laundry_basket] & F (near[bedroom] & F release[laundry_basket, '
     'bedroom])))'),
    # a sentence after the request about the person ("I'm halfway through it") or about what is in the
    # thing named before ("Lily's flowers are in it"): a story, no goal
    ("Could you bring me the book that's on the bedside table and to the left of the lamp, and put it on "
     "my armchair? I'm halfway through it.",
     'F (near[book::isabove(bedside_table)::isleftof(lamp)] & F (pick[book::isabove(bedside_table)::'
     'isleftof(lamp)] & F (near[armchair] & F release[book::isabove(bedside_table)::isleftof(lamp), '
     'armchair])))'),
    ("Would you go to the television, and please don't go near the vase on the little table next to the "
     "sofa. Lily's flowers are in it.",
     'F near[television] & G !near[vase::isabove(little_table::isnextto(sofa))]'),
    ("Go to the shed. Tom's tools are in there.",
     'F near[shed]'),
    # "..., I'd like to do some mending": after a comma and without "you", the person's own plan
    ("Please move the sewing box from under the bed up onto the dressing table, I'd like to do some "
     'mending.',
     'F (near[sewing_box::isbelow(bed)] & F (pick[sewing_box::isbelow(bed)] & F (near[dressing_table] & F '
     'release[sewing_box::isbelow(bed), dressing_table])))'),
    ('take the mug to the sink, I want to get some sleep',
     'F (near[mug] & F (pick[mug] & F (near[sink] & F release[mug, sink])))'),
    # "..., that's where I keep ...", "that's where she sleeps": why the place matters, no request
    ('Please go to the armchair by the fireplace first, and then the bookcase behind the sofa, that\'s where '
     'I keep all the old photo albums.',
     'F (near[armchair::isnextto(fireplace)] & F near[bookcase::isbehind(sofa)])'),
    # a time word before the purpose ("twice today to check"); grandchildren as the people of a story
    ("The cat's off her food, so pop over to her food bowl at least twice today to check, and stay away "
     "from the sofa cushions, that's where she sleeps.",
     'F (near[food_bowl] & F (!near[food_bowl] & F near[food_bowl])) & G !near[sofa_cushions]'),
    ('Could you put the tv remote on the side table? The grandkids hide it evrey time they visit.',
     'F (near[tv_remote] & F (pick[tv_remote] & F (near[side_table] & F release[tv_remote, side_table])))'),
    # a purpose before a colon ("Just to check the cat has everything: ...") heads the list, names no place
    ('Just to check the cat has everything: go to the cat flap, then her water bowl, and then her basket '
     'next to the boiler, in that order please.',
     'F (near[cat_flap] & F (near[water_bowl] & F near[basket::isnextto(boiler)]))'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_B4)
def test_readings_found_on_blind_set_b4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


# A purpose inside a clause that orders ("not until you've been to X to make sure ...") is left as said:
# the clause reader refuses it rather than reading a goal after the one it orders.
REFUSED_B4 = [
    "You may go and sit by the fire, but not until you've been to the back door and the cat flap to make "
    'sure both of them are shut.',
    "Fly to the washing line, but only after you've been round to the front hedge to check it is trimmed.",
]


@pytest.mark.parametrize('instruction', REFUSED_B4)
def test_purpose_inside_an_ordering_clause_is_refused(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)

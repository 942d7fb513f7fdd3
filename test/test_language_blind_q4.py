"""Readings found on the blind sets Q4 and R4 (homes, a library, a clinic, a gym): each was misread blind.

Every case is an instruction written for this project by a writer who never saw the translator (or
a sentence of our own for the same construction), with the formula its writer gave; the translator
must now give a formula equivalent to it on automata (names included). The sets stay outside the
repository, so that later rounds are scored on language no rule was written for.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_Q4 = [
    # "after that it's ok" after "avoid X until Y": X is free again, as the rule says (X was a goal after
    # Y: silently wrong); "it is okay" is how a thing is, "okay" no courtesy to leave out
    ("Stay away from the crib untill you get to the changing table; after that it's ok.",
     '!near[crib] U near[changing_table]'),
    ("Heads up, there are kids at the playground right now, so don't fly over the playground until you've "
     'scanned the east parking lot. After that it should be empty.',
     '!near[playground] U near[east_parking_lot]'),
    ("Keep away from the shed until you've been to the pond, then it's fine again.",
     '!near[shed] U near[pond]'),
    # "do them in whichever order is quicker": the goals already given, in any order (the last one was
    # visited again)
    ('I need you at the bathroom sink and at the bathtub, do them in whichever order is quicker.',
     'F near[bathroom_sink] & F near[bathtub]'),
    ('Go to the sink and the bathtub. Do them in any order.',
     'F near[sink] & F near[bathtub]'),
    ('Go to the pantry, the porch and the garage, visit all of them in whatever order makes sense.',
     'F near[pantry] & F near[porch] & F near[garage]'),
    # "Oh, and ignore what I said about X, it's fine - avoid Y instead": the retraction after "and"
    # (X stayed avoided: silently wrong), the reason before the replacement left out
    ("Go to the lobby and avoid the elevators. Oh, and ignore what I said about the elevators, they're "
     'fine - avoid the stairwell instead.',
     'F near[lobby] & G !near[stairwell]'),
    ('Go to the den and the attic. And never mind the attic.',
     'F near[den]'),
    # a count corrected with a bare number ("three's plenty") or bounded ("once is enough, but no more
    # than that": exactly once; it was at least once, silently)
    ("Check the oven four times. hmm no, three's plenty.",
     'F (near[oven] & F (!near[oven] & F (near[oven] & F (!near[oven] & F near[oven]))))'),
    ('Check the porch light three times... actually once is enough, but no more than that.',
     '!near[porch_light] U (near[porch_light] & (near[porch_light] W G !near[porch_light]))'),
    ('Visit the mailbox three times. No, twice is enough, and no more.',
     '!near[mailbox] U (near[mailbox] & (near[mailbox] U (!near[mailbox] & (!near[mailbox] U '
     '(near[mailbox] & (near[mailbox] W G !near[mailbox]))))))'),
    # a comparator corrected with "them" for the landmark ("the bike in front of them"): both were goals
    ('Go to the bike behind the treadmills... no sorry, the bike in front of them.',
     'F near[bike::isinfrontof(treadmills)]'),
    ('Go to the chair next to the desks, no, the chair behind them.',
     'F near[chair::isbehind(desks)]'),
    # the avoided thing corrected inside a carrying scope said before it ("while you're carrying it avoid
    # the cat - I mean avoid the dog, the cat's fine"): the scope kept (the dog was avoided always), and
    # "Bring it over" after "I need the laptop on my desk" is that delivery (a second pick was added)
    ("I need the laptop on my desk. Bring it over, and while you're carrying it avoid the cat - sorry, I "
     "mean avoid the dog, the cat's fine, it's the dog that jumps up.",
     'F (near[laptop] & F (pick[laptop] & (!near[dog] U (near[desk] & F release[laptop, desk]))))'),
    ('I need the mug in the sink. Take it over.',
     'F (near[mug] & F (pick[mug] & F (near[sink] & F release[mug, sink])))'),
    # "Don't go to Y before that": Y waits for the goal said before (the negation was lost: Y first)
    ("Go to the kitchen. Don't go to the den before that.",
     'F near[kitchen] & (!near[den] U near[kitchen])'),
    ("Go to the stepladder. Help desk first though, don't go to the stepladder before that.",
     'F near[stepladder] & (!near[stepladder] U near[help_desk])'),
    # "in the order I just said": the order of the list (refused); "stop whatever you're doing and ...":
    # the request follows (refused); "during your rounds": when, not where (refused)
    ('Hit the stove, the toaster oven and the coffee grinder, in the order I just said.',
     'F (near[stove] & F (near[toaster_oven] & F near[coffee_grinder]))'),
    ('Visit the den and the attic in the order I listed them.',
     'F (near[den] & F near[attic])'),
    ("Stop whatever you're doing and come to the patio table.",
     'F near[patio_table]'),
    ('go by the front window three times durring your rounds',
     'F (near[front_window] & F (!near[front_window] & F (near[front_window] & F (!near[front_window] & F '
     'near[front_window]))))'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_Q4)
def test_readings_found_on_blind_sets_q4_r4(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)

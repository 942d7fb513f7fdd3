"""Offline translator: asides, remarks and phrasings of spoken instructions (sixth round).

Every sentence here was written for these tests (none is taken from a data set). Each case
checks the formula on automata.
"""
from __future__ import annotations

import pytest

from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.language.offline import OfflineTranslator
from ltl_instruct.core.spec import parse_formula

T = OfflineTranslator()


def _check(instruction: str, gold: str) -> tuple[str, ...]:
    got = T.translate(instruction)
    assert equivalent(got.formula, parse_formula(gold)), f'{instruction!r} -> {got.formula}'
    return got.notes


REMARKS = [
    ('Visit the den or the hall, your choice, I do not mind which one you pick.',
     'F near[den] | F near[hall]'),
    ('Go to the den or the hall, does not matter which, then the porch.',
     'F ((near[den] | near[hall]) & F near[porch])'),
    ('Take the cups to the sink or the counter, both are fine by me.',
     'F (near[cups] & F (pick[cups] & (F (near[sink] & F release[cups, sink]) | '
     'F (near[counter] & F release[cups, counter]))))'),
    ('Go to the study, take your time.', 'F near[study]'),
    ('Head to the den or the hall; I am fine with whichever room is quieter.', 'F near[den] | F near[hall]'),
    ('Fly to the silo or the mill, whichever is less windy right now.', 'F near[silo] | F near[mill]'),
    ('Carry the knife to the sink, careful, it is sharp.',
     'F (near[knife] & F (pick[knife] & F (near[sink] & F release[knife, sink])))'),
    ('Visit the printer twice, it keeps jamming.', 'F (near[printer] & F (!near[printer] & F near[printer]))'),
    ('Head to the kennel, they get noisy at night.', 'F near[kennel]'),
    ('Take the mop to the closet and never go near the nursery, there is a baby napping in there.',
     'F (near[mop] & F (pick[mop] & F (near[closet] & F release[mop, closet]))) & G !near[nursery]'),
    ('Go to the attic, then the cellar, that order matters to me.', 'F (near[attic] & F near[cellar])'),
]


@pytest.mark.parametrize('instruction,gold', REMARKS, ids=[c[0][:30] for c in REMARKS])
def test_remarks_and_reasons_are_left_out(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    assert any('left out' in n or 'description of the scene' in n for n in notes), notes

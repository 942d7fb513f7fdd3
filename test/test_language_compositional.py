"""Offline translator on generated combinations of constructions it reads alone.

A small deterministic generator (fixed seed, plain Python) builds each instruction from parts
together with its gold formula, written by the dev set's conventions
(``datasets/spatial-temporal-dev/CONVENTIONS.md``): names of several shapes (an adjective and a
noun, a numbered or lettered name, a possessive, a name with a spatial descriptor), goals,
sequences, choices, orderings, global and scoped avoidance, counts, deliveries and
self-corrections, combined two or three at a time in a few sentence shapes each. Every case is
checked on automata. Where a combination has no one clear reading the gold is None and the
translator must refuse it, never guess.
"""
from __future__ import annotations

import random
from typing import Callable, Iterator, Optional

import pytest

from ltl_instruct.core.errors import TranslationError
from translation_cases import RULES, check_translation

# Places: (as said, as named in the formula). Shapes: adjective + noun, numbered, lettered,
# possessive, several words, a floor, and a name with a spatial descriptor.
PLACES = [
    ('the red door', 'red_door'),
    ('aisle 3', 'aisle_3'),
    ('shelf B4', 'shelf_b4'),
    ("the principal's office", 'principals_office'),
    ('the lamp left of the TV', 'lamp::isleftof(tv)'),
    ('the customer service desk', 'customer_service_desk'),
    ('the loading dock', 'loading_dock'),
    ('the front window', 'front_window'),
    ('gate B', 'gate_b'),
    ('the second floor lobby', 'second_floor_lobby'),
    ('the chair next to the fridge', 'chair::isnextto(fridge)'),
    ('the vending machine', 'vending_machine'),
]
# Things to stay away from.
HAZARDS = [
    ('the fireplace', 'fireplace'),
    ('the wet floor sign', 'wet_floor_sign'),
    ('aisle 7', 'aisle_7'),
    ("the janitor's closet", 'janitors_closet'),
    ('the box under the stairs', 'box::isbelow(stairs)'),
    ('the forklift', 'forklift'),
]
# Things to carry.
OBJECTS = [
    ('the blue mug', 'blue_mug'),
    ('the cup on the table', 'cup::isabove(table)'),
    ('the stapler', 'stapler'),
    ("the teacher's laptop", 'teachers_laptop'),
    ('box 12', 'box_12'),
]

Case = tuple[str, str, Optional[str]]   # (id, instruction, gold formula; None: to be refused)


def near(x: str) -> str:
    """The atom of being at ``x``."""
    return f'near[{x}]'


def go(x: str) -> str:
    """Reach ``x``."""
    return f'F near[{x}]'


def seq(*xs: str, tail: str = '') -> str:
    """Visit ``xs`` in order, then ``tail`` (a formula to hold from the last visit on)."""
    inner = f'near[{xs[-1]}]' + (f' & {tail}' if tail else '')
    out = f'F ({inner})' if tail else f'F {inner}'
    for x in reversed(xs[:-1]):
        out = f'F (near[{x}] & {out})'
    return out


def never(x: str) -> str:
    """Never be at ``x``."""
    return f'G !near[{x}]'


def only_after(x: str, y: str) -> str:
    """Not at ``x`` before ``y`` (an until: ``y`` must come)."""
    return f'(!near[{x}] U near[{y}])'


def twice(x: str, tail: str = '') -> str:
    """Two separate visits to ``x`` (then ``tail``)."""
    last = f'F (near[{x}] & {tail})' if tail else f'F near[{x}]'
    return f'F (near[{x}] & F (!near[{x}] & {last}))'


def exactly_once(x: str) -> str:
    """One visit to ``x``, no other."""
    return f'(!near[{x}] U (near[{x}] & (near[{x}] W G !near[{x}])))'


def at_most_once(x: str) -> str:
    """No second visit to ``x``."""
    return f'(!near[{x}] W (near[{x}] & (near[{x}] W G !near[{x}])))'


def deliver(o: str, d: str, tail: str = '', carrying_avoid: str = '') -> str:
    """Bring ``o`` to ``d`` (then ``tail``; ``carrying_avoid`` kept away from while carrying it)."""
    release = f'release[{o}, {d}]'
    last = f'F ({release} & {tail})' if tail else f'F {release}'
    drop = f'near[{d}] & {last}'
    leg = f'(!near[{carrying_avoid}] U ({drop}))' if carrying_avoid else f'F ({drop})'
    return f'F (near[{o}] & F (pick[{o}] & {leg}))'


def cap(s: str) -> str:
    """Capitalise the first letter of a sentence."""
    return s[0].upper() + s[1:]


def short(name: str) -> str:
    """A short form of a formula name for a case id."""
    return name.split('::')[0]


# Each family: a function of named parts to (shape, instruction, gold) triples.
Family = Callable[..., Iterator[tuple[str, str, Optional[str]]]]


def sequences(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Two and three goals in order."""
    (sa, na), (sb, nb), (sc, nc) = a, b, c
    yield 'then', f'Go to {sa}, then {sb}.', seq(na, nb)
    yield 'and-then', f'Go to {sa} and then go to {sb}.', seq(na, nb)
    yield 'after-that', f'Head to {sa}. After that, go to {sb}.', seq(na, nb)
    yield 'first-then', f'First go to {sa}, then go to {sb}.', seq(na, nb)
    yield 'three', f'Visit {sa}, then {sb}, and then {sc}.', seq(na, nb, nc)


def choices(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """A choice, alone, followed by a goal, and with avoidance."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh) = a, b, c, h
    yield 'or', f'Go to {sa} or {sb}.', f'{go(na)} | {go(nb)}'
    yield 'either', f'Go to either {sa} or {sb}.', f'{go(na)} | {go(nb)}'
    yield 'or-then', f'Go to {sa} or {sb}, then {sc}.', f'F ((near[{na}] | near[{nb}]) & F near[{nc}])'
    yield 'either-then', f'Go to either {sa} or {sb}, and then go to {sc}.', \
        f'F ((near[{na}] | near[{nb}]) & F near[{nc}])'
    yield 'then-or', f'Go to {sa}, then to {sb} or {sc}.', f'F (near[{na}] & F (near[{nb}] | near[{nc}]))'
    yield 'or-avoid', f'Go to {sa} or {sb}, and stay away from {sh}.', f'({go(na)} | {go(nb)}) & {never(nh)}'
    yield 'avoid-or', f'Never go near {sh}. Go to either {sa} or {sb}.', \
        f'({go(na)} | {go(nb)}) & {never(nh)}'


def orderings(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Only after, not before, until; with avoidance and with a sequence."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh) = a, b, c, h
    after = f'{go(na)} & {only_after(na, nb)}'
    yield 'only-after', f'Go to {sa}, but only after you have been to {sb}.', after
    yield 'not-before', f'Go to {sa}, but not before you have visited {sb}.', after
    yield 'until', f'Do not go to {sa} until you have been to {sb}.', only_after(na, nb)
    yield 'only-after+never', f'Go to {sa}, but only after {sb}, and never go near {sh}.', \
        f'{go(na)} & {only_after(na, nb)} & {never(nh)}'
    yield 'until+goal', f'Go to {sc}. Do not go to {sa} until you have been to {sc}.', \
        f'{go(nc)} & {only_after(na, nc)}'
    yield 'then+only-after', f'Go to {sa}, then {sb}. Go to {sc} only after {sb}.', \
        f'{seq(na, nb)} & {go(nc)} & {only_after(nc, nb)}'


def avoidance(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Global avoidance with goals and sequences, said before and after them."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh) = a, b, c, h
    yield 'then+never', f'Go to {sa}, then {sb}, and never go near {sh}.', f'{seq(na, nb)} & {never(nh)}'
    yield 'stay-away+and', f'Stay away from {sh} and head to {sa}.', f'{go(na)} & {never(nh)}'
    yield 'avoid.then', f'Avoid {sh}. Go to {sa} and then {sb}.', f'{seq(na, nb)} & {never(nh)}'
    yield 'goal+avoid-all-times', f'Go to {sa}, and keep away from {sh} at all times.', \
        f'{go(na)} & {never(nh)}'
    yield 'three+never', f'Go to {sa}, then {sb}, then {sc}; never go near {sh}.', \
        f'{seq(na, nb, nc)} & {never(nh)}'


def scoped(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Avoidance on the way to a goal, after a goal, and while carrying."""
    (sa, na), (sb, nb), (sh, nh), (so, no) = a, b, h, o
    yield 'on-the-way', f'Go to {sa}, and avoid {sh} on the way there.', f'(!near[{nh}] U near[{na}])'
    yield 'on-the-way-to', f'On the way to {sa}, stay away from {sh}.', f'(!near[{nh}] U near[{na}])'
    yield 'then+on-the-way-to', f'Go to {sa}, then {sb}, and avoid {sh} on the way to {sb}.', \
        f'F (near[{na}] & (!near[{nh}] U near[{nb}]))'
    yield 'once-reached', f'Go to {sa}, then {sb}. Once you have reached {sa}, avoid {sh}.', \
        f'F (near[{na}] & {never(nh)} & F near[{nb}])'
    yield 'after', f'Go to {sa}. After that, avoid {sh} and go to {sb}.', \
        f'F (near[{na}] & {never(nh)} & F near[{nb}])'
    yield 'while-carrying', f'Bring {so} to {sa}, and do not go near {sh} while carrying it.', \
        deliver(no, na, carrying_avoid=nh)
    yield 'after-dropping', f'Take {so} to {sa}. Once you have dropped it off, stay away from {sh}.', \
        deliver(no, na, tail=never(nh))


def counts(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Counts alone, with a goal after them, and with avoidance."""
    (sa, na), (sb, nb), (sh, nh) = a, b, h
    yield 'twice', f'Visit {sa} twice.', twice(na)
    yield 'at-least-twice+then', f'Go to {sa} at least twice, then go to {sb}.', twice(na, go(nb))
    yield 'exactly-once', f'Go to {sa} exactly once.', exactly_once(na)
    yield 'exactly-once+then', f'Visit {sa} exactly once, and after that head to {sb}.', \
        f'{exactly_once(na)} & {seq(na, nb)}'
    yield 'at-most-once+goal', f'Go to {sb}, and go to {sa} at most once.', f'{go(nb)} & {at_most_once(na)}'
    yield 'twice+never', f'Visit {sa} twice and never go near {sh}.', f'{twice(na)} & {never(nh)}'


def deliveries(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Deliveries with a goal before or after, with avoidance, and with a choice of place."""
    (sa, na), (sb, nb), (sh, nh), (so, no) = a, b, h, o
    yield 'bring', f'Bring {so} to {sa}.', deliver(no, na)
    # ("put the cup on the table on X" could put it on the table: the thing said with "that's on")
    yield 'put+then', f"Put {so.replace(' on ', ' that is on ')} on {sa}, then go to {sb}.", \
        deliver(no, na, tail=go(nb))
    yield 'go+then-take', f'Go to {sb}, then take {so} to {sa}.', f'F (near[{nb}] & {deliver(no, na)})'
    yield 'bring+never', f'Bring {so} to {sa} and never go near {sh}.', f'{deliver(no, na)} & {never(nh)}'
    yield 'bring-or', f'Bring {so} to {sa} or {sb}.', \
        f'F (near[{no}] & F (pick[{no}] & (F (near[{na}] & F release[{no}, {na}]) | '\
        f'F (near[{nb}] & F release[{no}, {nb}]))))'


def corrections(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Self-corrections of a goal, a sequence, a choice, an avoidance, a delivery and a count."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh), (so, no) = a, b, c, h, o
    # "the lamp left of the TV, sorry, I meant the desk": the desk, or the lamp left of it? (refused)
    unclear = '::' in na
    yield 'meant', f'Go to {sa}, sorry, I meant {sb}.', None if unclear else go(nb)
    yield 'then-meant', f'Go to {sa}, then {sb}. Sorry, I meant {sc}, not {sb}.', seq(na, nc)
    yield 'make-it-instead', f'Go to {sa}, then {sb}. Actually, make it {sc} instead of {sb}.', seq(na, nc)
    yield 'or-just', f'Go to {sa} or {sb}. Actually, just {sa}.', go(na)
    yield 'or-then-meant', f'Go to {sa} or {sb}, then {sc}. Sorry, I meant {sh}, not {sc}.', \
        f'F ((near[{na}] | near[{nb}]) & F near[{nh}])'
    yield 'avoid-forget', f'Stay away from {sh} and head to {sa}. Hmm, actually {sh} is off, forget that.', \
        go(na)
    yield 'avoid-fine', f'Go to {sa} and avoid {sh}. Actually, {sh} is fine.', go(na)
    yield 'avoid-never-mind', f'Go to {sa}, then {sb}, and avoid {sh}. Never mind the avoiding part.', \
        seq(na, nb)
    yield 'forget-goal', f'Go to {sa}, then {sb}, then {sc}. Forget {sb}.', seq(na, nc)
    yield 'bring-meant', f'Bring {so} to {sa}, sorry, I meant {sb}.', None if unclear else deliver(no, nb)
    yield 'count-scratch', f'Go to {sa} three times, scratch that, twice is enough.', twice(na)


def mixtures(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Three kinds at a time: a choice, an order or a count with a sequence and avoidance."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh), (so, no) = a, b, c, h, o
    choice = f'(near[{na}] | near[{nb}])'
    yield 'or-then+never', f'Go to {sa} or {sb}, then {sc}, and never go near {sh}.', \
        f'F ({choice} & F near[{nc}]) & {never(nh)}'
    yield 'either-then+on-the-way', \
        f'Go to either {sa} or {sb}, then to {sc}, and avoid {sh} on the way to {sc}.', \
        f'F ({choice} & (!near[{nh}] U near[{nc}]))'
    yield 'twice-then+never', f'Visit {sa} twice, then go to {sb}; stay away from {sh} the whole time.', \
        f'{twice(na, go(nb))} & {never(nh)}'
    # (the guard of "only after" is the delivery's first goal, the thing to pick up)
    yield 'bring+only-after', f'Bring {so} to {sa}, but only after you have been to {sb}.', \
        f'{deliver(no, na)} & {only_after(no, nb)}'
    yield 'go-first+bring+never', f'Go to {sb} first, then bring {so} to {sa}, and never go near {sh}.', \
        f'F (near[{nb}] & {deliver(no, na)}) & {never(nh)}'
    yield 'carrying+then', f'Take {so} to {sa}, avoid {sh} while you carry it, and then go to {sb}.', \
        deliver(no, na, tail=go(nb), carrying_avoid=nh)
    yield 'then+only-after', f'Go to {sa} and then {sb}, but only go to {sa} after {sc}.', \
        f'{seq(na, nb)} & {only_after(na, nc)}'
    yield 'or+exactly-once', f'Go to {sa} or {sb}, and visit {sc} exactly once.', \
        f'({go(na)} | {go(nb)}) & {exactly_once(nc)}'
    yield 'three+at-most-once', f'Go to {sa}, then {sb}, then {sc}, and go to {sa} at most once.', \
        f'{seq(na, nb, nc)} & {at_most_once(na)}'
    yield 'then+never+meant', \
        f'Go to {sa}, then {sb}, and never go near {sh}. Sorry, I meant {sc}, not {sb}.', \
        f'{seq(na, nc)} & {never(nh)}'
    yield 'then+bring', f'First go to {sa}, then {sb}. After that, bring {so} to {sc}.', \
        f'F (near[{na}] & F (near[{nb}] & {deliver(no, nc)}))'
    yield 'bring-or+never', f'Bring {so} to either {sa} or {sb}, and keep away from {sh}.', \
        f'F (near[{no}] & F (pick[{no}] & (F (near[{na}] & F release[{no}, {na}]) | '\
        f'F (near[{nb}] & F release[{no}, {nb}])))) & {never(nh)}'
    yield 'until+then', f'Stay away from {sh} until you reach {sa}, then go to {sb}.', \
        f'(!near[{nh}] U near[{na}]) & {seq(na, nb)}'
    yield 'not-before-or', f'Go to {sa}, but not before you have been to {sb} or {sc}.', \
        f'{go(na)} & (!near[{na}] U (near[{nb}] | near[{nc}]))'
    yield 'any-order+then', f'Go to {sa} and {sb}, in any order, then {sc}.', \
        f'F (near[{na}] & F (near[{nb}] & F near[{nc}])) | F (near[{nb}] & F (near[{na}] & F near[{nc}]))'
    yield 'counts-each', f'Visit {sa} exactly once and {sb} twice.', f'{exactly_once(na)} & {twice(nb)}'
    yield 'each-exactly-once', f'Visit {sa} and {sb}, each exactly once.', \
        f'{exactly_once(na)} & {exactly_once(nb)}'


def restatements(a, b, c, h, o) -> Iterator[tuple[str, str, Optional[str]]]:
    """Corrections of a route, a choice, an order, a count and an avoidance inside other kinds."""
    (sa, na), (sb, nb), (sc, nc), (sh, nh), (so, no) = a, b, c, h, o
    yield 'go-first', f'Go to {sa}, then {sb}, then {sc}. Actually, go to {sc} first.', seq(nc, na, nb)
    yield 'twice-no-exactly-once', f'Go to {sa} twice. No wait, exactly once.', exactly_once(na)
    yield 'avoid-instead', f'Go to {sa} and avoid {sh}. Actually, avoid {sc} instead.', \
        f'{go(na)} & {never(nc)}'
    yield 'never-mind-instead', f'Go to {sa}. Never mind, go to {sb} instead.', go(nb)
    yield 'bring-then-meant', f'Bring {so} to {sa} and then go to {sb}. Sorry, I meant {sc}, not {sb}.', \
        deliver(no, na, tail=go(nc))
    yield 'or-meant-or', f'Go to {sa} or {sb}. Sorry, I meant {sa} or {sc}.', f'{go(na)} | {go(nc)}'
    yield 'route-meant-route', f'Go to {sa}, then {sb}. Sorry, I meant {sc}, then {sa}.', seq(nc, na)
    # three places said, two in the correction: which two it replaces is not said (refused)
    yield 'route-meant-shorter', f'Go to {sa}, then {sb}, then {sc}. Sorry, I meant {sh}, then {sa}.', None
    yield 'in-order+on-the-way', \
        f'Go to {sa}, {sb} and {sc} in that order, and avoid {sh} on the way to {sc}.', \
        f'F (near[{na}] & F (near[{nb}] & (!near[{nh}] U near[{nc}])))'
    yield 'but-first', f'Go to {sa}, but first go to {sb}.', seq(nb, na)
    # ("and only then": in that strict order, the last not before the one before it)
    yield 'only-then', f'Go to {sa}, then {sb}, and only then {sc}.', \
        f'{seq(na, nb, nc)} & {only_after(nc, nb)}'
    yield 'before-going', f'Before going to {sa}, stop by {sb}.', seq(nb, na)
    yield 'or-but-not-both', f'Go to {sa} or {sb} but not both.', \
        f'({go(na)} & {never(nb)}) | ({go(nb)} & {never(na)})'
    yield 'bring+then-or', f'Bring {so} to {sa}, then go to {sb} or {sc}.', \
        deliver(no, na, tail=f'(F near[{nb}] | F near[{nc}])')
    yield 'until-picked', f'Pick up {so}, and stay away from {sh} until you have it. Then go to {sa}.', \
        f'F (near[{no}] & F (pick[{no}] & F near[{na}])) & (!near[{nh}] U pick[{no}])'
    yield 'never-two', f'Go to {sa}. Never go near {sh} or {sb}.', f'{go(na)} & {never(nh)} & {never(nb)}'


FAMILIES: list[tuple[str, Family, int]] = [
    ('seq', sequences, 6), ('choice', choices, 6), ('order', orderings, 6), ('avoid', avoidance, 6),
    ('scope', scoped, 6), ('count', counts, 5), ('deliver', deliveries, 6), ('correct', corrections, 5),
    ('mixed', mixtures, 3), ('restate', restatements, 3),
]


def generate(seed: int = 20261205) -> list[Case]:
    """Every generated case: each family's shapes, with names drawn by a fixed seed."""
    rng = random.Random(seed)
    cases: list[Case] = []
    for family, make, draws in FAMILIES:
        for _ in range(draws):
            a, b, c = rng.sample(PLACES, 3)
            h, o = rng.choice(HAZARDS), rng.choice(OBJECTS)
            for shape, text, gold in make(a, b, c, h, o):
                cid = f'{family}-{shape}-' + '-'.join(short(n) for _, n in (a, b, c))
                cases.append((cid, text, gold))
    return cases


CASES = generate()
READ = [c for c in CASES if c[2] is not None]
REFUSED = [c for c in CASES if c[2] is None]


@pytest.mark.parametrize('instruction,gold', [c[1:] for c in READ], ids=[c[0] for c in READ])
def test_generated_combination(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)


@pytest.mark.parametrize('instruction', [c[1] for c in REFUSED], ids=[c[0] for c in REFUSED])
def test_unclear_combination_is_refused(instruction: str) -> None:
    with pytest.raises(TranslationError):
        RULES.translate(instruction)


def test_generator_is_deterministic_and_sized() -> None:
    assert generate() == CASES
    assert 200 <= len(CASES) <= 500
    assert len({c[0] for c in CASES}) == len(CASES)

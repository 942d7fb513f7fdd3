"""Inputs that once broke a node (found by ``bench.fuzz`` and ``bench.graph_fuzz``), replayed.

Each line of ``regressions/fuzz_found.jsonl`` names a target (a topic, ``camera frame``,
``formula``, ``english`` or ``scene``) and the input; it is handed to the real node callbacks
built in this process (no DDS traffic), as ``bench.fuzz`` does. It must return or raise a
typed error, and a task spec must still end with one terminal status.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from ltl_instruct.core.errors import LtlInstructError
from ros_env import fresh_domain_id, private_domain

FOUND = Path(__file__).parent / 'regressions' / 'fuzz_found.jsonl'
CASES = [json.loads(line) for line in FOUND.read_text().splitlines() if line.strip()]


@pytest.fixture(scope='module')
def nodes():
    with private_domain(fresh_domain_id(13)):
        from bench.fuzz import Nodes
        built = Nodes(backend='offline')
        try:
            yield built
        finally:
            built.close()


@pytest.mark.parametrize('case', CASES, ids=[f'{k}-{c["target"]}' for k, c in enumerate(CASES)])
def test_an_input_that_broke_a_node_is_refused_typed(nodes, case):
    from bench.fuzz import run_case
    try:
        run_case(nodes, case['target'], case['input'])
    except LtlInstructError:
        pass
    assert not nodes.internal_errors, nodes.internal_errors
    if case['target'] == 'task_spec':
        iid = json.loads(case['input'])['id']
        ends = [body for i, body in nodes.statuses if i == iid and body.get('terminal')]
        assert len(ends) == 1 and ends[0]['status'] == 'failed', nodes.statuses


@pytest.mark.parametrize('revision', [{'': 282}, 'seven', 2.5, None, True])
def test_a_referent_map_whose_revision_is_not_a_whole_number_twice(nodes, revision):
    """Fuzz-found: the second map for one instruction compared the first one's revision with int()."""
    text = json.dumps({'schema': 'ltl_instruct/referent_map', 'version': 1, 'id': f'rev-{revision!r}',
                       'ok': True, 'revision': revision, 'result': None})
    for _ in range(2):
        nodes.run('referent_map', text)
    assert not nodes.internal_errors, nodes.internal_errors


@pytest.mark.parametrize('timing, expected', [
    (True, {}), (2.5, {}), ([1, 2], {}), (None, {}),
    ({'translate_s': 0.1, 'x': 'slow', 'y': True}, {'translate_s': 0.1})])
def test_the_stage_times_a_payload_carries_are_read_whatever_it_holds(timing, expected):
    """Graph-fuzz-found: a task spec whose "timing" was true ended INTERNAL_ERROR ('bool' has no items)."""
    from ltl_instruct.core.payloads import timing_of
    assert timing_of({'timing': timing}) == expected

"""The instruction lifecycle over DDS (issue 19) and no instruction lost when a node dies (issue 21).

One graph for the module, with respawn on, the rules translator (it starts in a
second, so a restarted translator answers soon) and the simulator at real speed (a
task runs for many seconds, so a newer plan surely supersedes it). The tests that
kill nothing run first; the last one kills each pipeline node once during a burst.

The graph talks over UDP only (``FASTDDS_BUILTIN_TRANSPORTS=UDPv4``): a process killed
with SIGKILL leaves its Fast DDS shared-memory segments and port locks behind, a known
Fast DDS hazard that can stall the next participants on this machine.
"""
from __future__ import annotations

import json
import os
import random
import signal
import time

import pytest
from std_msgs.msg import String

from ltl_instruct.commands.bringup import (
    ALL_NODES, PIPELINE_NODES, NodeGraph, RestartPolicy, default_params_file,
)
from ros_env import fresh_domain_id, private_domain

DOMAIN_ID = fresh_domain_id(0x5EED)
TIMEOUT = 5.0


@pytest.fixture(scope='module')
def graph(tmp_path_factory):
    with private_domain(DOMAIN_ID, transports='UDPv4'):
        yield from _graph(tmp_path_factory.mktemp('lifecycle_logs'))


def _graph(logs):
    from ltl_instruct.nodes.client import GraphClient
    overrides = {'sim_world': {'camera_rate_hz': 0.0}, 'referent_grounder': {'use_camera': False},
                 'ltl_translator': {'backend': 'offline'}}
    restarts = []
    g = NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs,
                  restart=RestartPolicy(first_delay=0.2), say=restarts.append).start()
    client = GraphClient('lifecycle_client')
    try:
        assert client.wait_for_graph(timeout=180.0, need_sim=True), _logs(logs)
        yield g, client, logs
    finally:
        client.close()
        codes = g.stop()
        failed = [n for n, c in codes.items() if c != 0]
        assert not failed, (codes, restarts, _logs(logs, failed))


def _logs(logs, nodes=None) -> str:
    """The end of each node's log (of ``nodes`` only, when given): a stuck node's stacks are there."""
    return '\n'.join(f'--- {p.name}\n{p.read_text(errors="replace")[-3000:]}'
                     for p in sorted(logs.glob('*.log')) if nodes is None or p.stem in nodes)


def test_plain_text_learns_its_id_from_the_first_status(graph):
    g, client, _ = graph
    text = 'please go to the wardrobe'
    client.send_raw(text)
    client.send_raw(json.dumps({'id': 'own-id-1', 'text': 'go to the printer'}))   # no schema: its id is kept
    ids = client.wait_until(lambda: client.ids_for(text), 30.0)
    assert ids and len(ids) == 1, ids
    first = client.received.statuses[ids[0]][0]
    assert first['status'] == 'received' and first['id_source'] == 'assigned', first
    assert client.wait_terminal(ids[0], timeout=30.0)['status'] == 'planned'
    assert client.wait_terminal('own-id-1', timeout=30.0)['status'] == 'planned'
    first = client.received.statuses['own-id-1'][0]
    assert first['status'] == 'received' and first['id_source'] == 'sender', first


def test_a_newer_plan_supersedes_and_a_cancel_stops_the_execution(graph):
    g, client, _ = graph
    tour = client.send(formula='F (near[nightstand] & F near[stove])')   # about a minute at 1 m/s
    assert client.wait_terminal(tour, timeout=30.0)['status'] == 'planned'
    nxt = client.send(formula='F (near[fridge] & F near[bed])')
    planned = client.wait_terminal(nxt, timeout=30.0)
    assert planned['status'] == 'planned', planned
    ended = client.wait_terminal(tour, timeout=TIMEOUT, phase='execution')
    assert ended['status'] == 'superseded' and ended['superseded_by'] == nxt, ended
    client.cancel(nxt)
    cancelled = client.wait_terminal(nxt, timeout=TIMEOUT, phase='execution')
    assert cancelled['status'] == 'cancelled', cancelled
    # the robot is stopped by an empty plan, newer than the cancelled one
    stop = client.wait_until(lambda: [k for k, v in client.received.plans.items()
                                      if len(v) == 0 and k > planned['plan_stamp']], TIMEOUT)
    assert stop, sorted(client.received.plans)
    counts = [len(client.terminals(i, phase)) for i in (tour, nxt) for phase in ('planning', 'execution')]
    assert counts == [1] * 4, counts


def test_a_cancel_that_comes_first_ends_the_instruction_when_it_comes(graph):
    g, client, _ = graph
    iid = f'early-{random.randint(0, 10**6)}'
    client.cancel_pub.publish(String(data=json.dumps({'id': iid})))
    time.sleep(0.5)   # the cancel is there before the instruction
    client.send(formula='F near[lamp]', iid=iid)
    status = client.wait_terminal(iid, timeout=TIMEOUT)
    assert status['status'] == 'cancelled', status
    assert [s['status'] for s in client.received.statuses[iid]] == ['received', 'cancelled']
    client.cancel(iid)   # it has ended: a second cancel is refused, typed
    refused = client.wait_until(lambda: [s for s in client.received.statuses[iid]
                                         if s['status'] == 'cancel_rejected'], TIMEOUT)
    assert refused and refused[0]['error']['code'] == 'INVALID_INPUT' and not refused[0]['terminal']


@pytest.mark.parametrize('garbage', ['', 'null', '42', '[1, 2]', '{"id": 5}', '{"id": ', 'x' * 300])
def test_a_garbage_cancel_gets_a_typed_status_and_harms_nothing(graph, garbage):
    g, client, _ = graph
    before = len(client.received.statuses.get('no-instruction', []))
    client.cancel_pub.publish(String(data=garbage))
    got = client.wait_until(lambda: client.received.statuses.get('no-instruction', [])[before:], TIMEOUT)
    assert got and got[0]['status'] == 'cancel_rejected' and got[0]['error']['code'] == 'INVALID_INPUT', got
    assert not g.dead()


GOALS = ('lamp', 'fridge', 'bed', 'desk', 'tv', 'printer', 'plant', 'stove', 'wardrobe', 'basket',
         'bookshelf', 'armchair', 'whiteboard', 'nightstand', 'trash can', 'computer', 'red ball',
         'kitchen sink', 'filing cabinet', 'coffee machine')


def test_a_burst_of_20_loses_nothing_when_each_node_is_killed_once(graph):
    """Issue 21: each pipeline node killed once (SIGKILL) during a 20-instruction burst, respawn on."""
    g, client, logs = graph
    texts, ids, kills = {}, [], {}
    plan = {2: 'ltl_translator', 6: 'referent_grounder', 10: 'task_progression', 14: 'fmt_planner'}
    for k, goal in enumerate(GOALS):
        if k in plan:
            kills[plan[k]] = time.monotonic()
            os.killpg(g.processes[plan[k]].pid, signal.SIGKILL)
        if k % 4 == 3:   # plain text: its id comes back on 'received'
            texts[f'go to the {goal}'] = None
            client.send_raw(f'go to the {goal}')
        else:
            ids.append(client.send(formula=f'F near[{goal.replace(" ", "_")}]'))
        time.sleep(0.4)
    done = client.wait_until(lambda: all(client.terminal(i) for i in ids + _plain_ids(client, texts)) and
                             len(_plain_ids(client, texts)) == len(texts), 180.0)
    assert done, (_summary(client, ids, texts), _logs(logs))
    everything = ids + _plain_ids(client, texts)
    assert len(everything) == 20 == len(set(everything))
    for iid in everything:   # one end each, named by its id, after 'received'
        assert len(client.terminals(iid)) == 1, client.received.statuses[iid]
        assert client.received.statuses[iid][0]['status'] == 'received'
    assert sorted(r.node for r in g.restarts) == sorted(PIPELINE_NODES), g.restarts
    outcomes = {iid: client.terminal(iid)['status'] for iid in everything}
    bad = [iid for iid, outcome in outcomes.items() if outcome not in ('planned', 'satisfied')]
    assert not bad, ([client.received.statuses[iid] for iid in bad], _logs(logs))
    for r in g.restarts:
        print(f'{r.node}: killed, restarted after {r.at - kills[r.node]:.1f} s')


def _plain_ids(client, texts) -> list:
    out = []
    for text in texts:
        out += client.ids_for(text)
    return out


def _summary(client, ids, texts) -> list:
    return [(i, [s['status'] for s in client.received.statuses.get(i, [])],
             (client.terminal(i) or {}).get('error')) for i in ids + _plain_ids(client, texts)] + \
        [(t, client.ids_for(t)) for t in texts]


def test_translator_and_task_progression_dying_together_carry_out_nothing_twice(graph):
    """Both records of what ended are gone from DDS: task_progression's journal still has them."""
    g, client, logs = graph
    executing = client.send(formula='F (near[whiteboard] & F near[front_door])')   # a long walk
    assert client.wait_terminal(executing, timeout=30.0)['status'] == 'planned'
    before = {iid for iid, statuses in client.received.statuses.items() if client.terminals(iid)}
    for node in ('ltl_translator', 'task_progression'):
        os.killpg(g.processes[node].pid, signal.SIGKILL)
    later = client.send(formula='F near[sofa]')
    assert client.wait_terminal(later, timeout=60.0)['status'] == 'planned', _logs(logs)
    # the running task was resumed by the new task_progression (from its journal), then superseded
    ended = client.wait_terminal(executing, timeout=TIMEOUT, phase='execution')
    assert ended['status'] == 'superseded' and ended['superseded_by'] == later, ended
    assert any(s.get('reason', '').startswith('resumed') for s in client.received.statuses[executing]), \
        [s['status'] for s in client.received.statuses[executing]]
    # the restarted translator sent its whole history again; everything that had ended stays ended
    twice = {iid: [s['status'] for s in client.received.statuses[iid]] for iid in before
             if len(client.terminals(iid)) != 1}
    assert not twice, twice

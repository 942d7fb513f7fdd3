"""The node graph end to end: real rclpy nodes in separate processes over DDS.

The graph (five nodes, the simulator on the built-in apartment) is started once for the
module on a test-private ``ROS_DOMAIN_ID``, localhost only, and stopped in teardown.
Many instructions go through it: good ones, bad ones, a burst of 50.
"""
from __future__ import annotations

import copy
import json
import time

import numpy as np
import pytest
from nav_msgs.msg import OccupancyGrid
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.commands.bringup import ALL_NODES, NodeGraph, default_params_file
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.grounding.rsm import ReferentMap
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.core.world.robot import Pose
from ros_env import fresh_domain_id, private_domain

DOMAIN_ID = fresh_domain_id()
NEAR = 1.0
TIMEOUT = 5.0   # every bad input gets its typed error within this many seconds
STALL = 60.0    # a burst fails when no instruction of it ends for this long


@pytest.fixture(scope='module')
def graph(tmp_path_factory):
    with private_domain(DOMAIN_ID):
        from ltl_instruct.nodes.client import GraphClient
        logs = tmp_path_factory.mktemp('node_logs')
        overrides = {'sim_world': {'time_scale': 8.0, 'max_speed': 1.5, 'camera_rate_hz': 0.0},
                     'referent_grounder': {'use_camera': False},
                     # under a load of 40-80 from other jobs, at nice 10, FMT* drew too few samples in its
                     # 2 s and answers took over 10 s: valid instructions failed with TIMEOUT (a lost request
                     # still shows)
                     'task_progression': {'near_threshold': NEAR, 'segment_timeout': 30.0},
                     'fmt_planner': {'time_limit': 10.0}}
        g = NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs).start()
        client = GraphClient('test_client', record_odom=True)
        try:
            assert client.wait_for_graph(timeout=180.0, need_sim=True), _logs(logs, g)
            # the wait includes the translator's backend (torch, the model) loading, which took over 60 s
            # under that load; the planner and grounder warm up on the first task, charged to no test
            warm = client.wait_terminal(client.send(formula='F near[unicorn]'), timeout=240.0)
            assert warm['status'] == 'failed', warm
            yield g, client, logs
        finally:
            client.close()
            codes = g.stop()
            # every node was alive to the end and stopped cleanly on SIGINT
            assert all(c == 0 for c in codes.values()), (codes, _logs(logs, g))


def _logs(logs, g) -> str:
    out = [f'dead: {g.dead()}']
    for p in sorted(logs.glob('*.log')):
        out.append(f'--- {p.name}\n' + p.read_text(errors='replace')[-3000:])
    return '\n'.join(out)


def _alive(g) -> None:
    assert not g.dead(), g.dead()


def _densify(points: np.ndarray, spacing: float = 0.05) -> np.ndarray:
    out = [points[:1]]
    for a, b in zip(points[:-1], points[1:]):
        n = max(1, int(np.ceil(np.linalg.norm(b - a) / spacing)))
        out.append(a + (b - a) * (np.arange(1, n + 1)[:, None] / n))
    return np.concatenate(out)


def _trace(formula: str, rmap: ReferentMap, points: np.ndarray, skills: list) -> list:
    """Letters along the path, computed here from the referent map (not the nodes' code)."""
    aut = compile_automaton(parse_formula(formula))
    letters = []
    for p in points:
        letter = set()
        for atom in aut.atoms:
            if atom.skill == 'near':
                insts = rmap.instances(str(atom.args[0]))
                if any(inst.distance(p, dims=2)[0] <= NEAR for inst in insts):
                    letter.add(atom)
        letters.append(letter)
    return aut, letters


def test_instruction_yields_a_plan_the_automaton_accepts(graph):
    g, client, _ = graph
    formula = 'F (near[sofa::isbehind(pillar)] & F near[computer]) & G !near[door]'
    iid = client.send(formula=formula)
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned', status
    plan = client.wait_until(lambda: client.received.plans.get(status['plan_stamp']), 5.0)
    assert plan is not None and len(plan) >= 2
    rmap = ReferentMap.from_dict(client.keyed('referent_maps', iid)['referent_map'])
    aut, letters = _trace(formula, rmap, _densify(plan), [])
    assert aut.accepts(letters)
    # the sofa behind the pillar is the one at larger x, never the other
    sofa = rmap.instances('sofa::isbehind(pillar)')
    assert [i.id for i in sofa] == ['sofa_2']
    # and the path stays clear of walls (the map the simulator publishes)
    grid = conv.occupancy_raster(client.received.map)
    dense = _densify(plan)
    cols = ((dense[:, 0] - grid.origin[0]) / grid.resolution).astype(int)
    rows = ((dense[:, 1] - grid.origin[1]) / grid.resolution).astype(int)
    assert np.all(grid.cells[rows, cols] == 0)
    _alive(g)


def test_the_translator_says_it_is_ready_before_anything_is_sent(graph):
    _, client, _ = graph
    state = client.received.translator
    assert state['state'] == 'ready' and state['backend'] == 'combined', state
    assert state['schema'] == 'ltl_instruct/translator_status' and 'model_error' not in state, state


def test_english_instruction_is_translated_planned_and_executed(graph):
    g, client, _ = graph
    iid = client.send(text='go to the fridge')
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned', status
    assert client.keyed('specs', iid)['formula'] == 'F near[fridge]'
    verification = client.keyed('verifications', iid)
    assert 'fridge' in verification['verification_text']
    done = client.wait_status(iid, 'satisfied', timeout=60.0)
    assert done is not None and done['phase'] == 'execution'
    fridge = resolve_scene('apartment').object_by_id('fridge')

    def stopped_near_fridge():
        # the status can overtake the last odometry messages on their way to this client
        return fridge.box.distance(client.received.odom[-1][1], dims=2)[0] <= NEAR + 0.05 or None

    assert client.wait_until(stopped_near_fridge, 5.0), client.received.odom[-1]


@pytest.mark.parametrize('case', ['nonsense', 'unplaceable', 'bad_json', 'bad_instruction_json',
                                  'unknown_referent', 'unsatisfiable', 'huge_text', 'bad_formula'])
def test_bad_instruction_gets_a_typed_error_and_the_next_is_served(graph, case):
    g, client, _ = graph
    t0 = time.monotonic()
    if case == 'nonsense':
        # read as a place name by the translator, then found nowhere by the grounder
        iid = client.send(text='purple monkey dishwasher sideways')
        expected = {'TRANSLATION_ERROR', 'UNKNOWN_REFERENT'}
    elif case == 'unplaceable':
        iid = client.send(text='the the the')
        expected = {'TRANSLATION_ERROR'}
    elif case == 'bad_json':
        iid = 'garbage-spec-1'
        client.task_spec_pub.publish(
            String(data='{"schema": "ltl_instruct/task_spec", "id": "garbage-spec-1", '))
        expected = {'INVALID_INPUT'}
    elif case == 'bad_instruction_json':
        iid = 'bad-instruction-1'
        client.send_raw('{"schema": "ltl_instruct/instruction", "version": 1, "id": "bad-instruction-1", '
                        '"text": 5}')
        expected = {'INVALID_INPUT'}
    elif case == 'unknown_referent':
        iid = client.send(formula='F near[unicorn]')
        expected = {'UNKNOWN_REFERENT'}
    elif case == 'unsatisfiable':
        iid = client.send(formula='F near[sofa] & G !near[sofa]')
        expected = {'UNSATISFIABLE'}
    elif case == 'huge_text':
        iid = client.send(text='go to the sofa ' * 5000)
        expected = {'LIMIT_EXCEEDED'}
    else:
        iid = client.send(formula='F (near[sofa] &')
        expected = {'PARSE_ERROR'}
    status = client.wait_terminal(iid, timeout=TIMEOUT)
    assert time.monotonic() - t0 <= TIMEOUT
    assert status['status'] == 'failed' and status['error']['code'] in expected, status
    assert status['error']['message']
    _alive(g)
    good = client.send(formula='F near[tv]')
    # served: planned, or satisfied at once where the previous case already drove the robot to the tv
    served = client.wait_terminal(good, timeout=30.0)
    assert served['status'] in ('planned', 'satisfied'), served


def test_garbage_without_an_id_still_gets_a_status(graph):
    g, client, _ = graph
    before = sum(len(v) for v in client.received.statuses.values())
    client.task_spec_pub.publish(String(data='\x00\x01 not json at all'))
    got = client.wait_until(lambda: [s for k, v in client.received.statuses.items()
                                     if k.startswith('unidentified')
                                     for s in v if s['error']['code'] == 'INVALID_INPUT'], TIMEOUT)
    assert got and sum(len(v) for v in client.received.statuses.values()) > before
    _alive(g)


def test_nan_odometry_is_reported_and_ignored(graph):
    g, client, _ = graph
    msg = conv.odometry_msg(Pose((float('nan'), 1.0, 0.0), 0.0))
    deadline = time.monotonic() + TIMEOUT
    found = None
    while found is None and time.monotonic() < deadline:
        client.odom_pub.publish(msg)
        found = client.wait_until(lambda: next(
            (s for v in client.received.statuses.values() for s in v
             if s['status'] == 'input_rejected' and s['error']['code'] == 'INVALID_INPUT'), None), 0.5)
    assert found is not None
    _alive(g)
    good = client.send(formula='F near[lamp]')
    assert client.wait_terminal(good, timeout=30.0)['status'] == 'planned'


def test_a_malformed_map_is_reported_and_the_last_good_map_serves_on(graph):
    """A malformed map once replaced the world: every instruction failed until a good map came (fuzzing)."""
    g, client, _ = graph
    good_map = client.received.map
    assert good_map is not None
    before = len(_map_rejections(client))
    bad = OccupancyGrid()
    bad.info.width, bad.info.height, bad.info.resolution = 10, 10, float('nan')
    try:
        for msg in (OccupancyGrid(), bad):                # an empty map, then one with a NaN resolution
            client.map_pub.publish(msg)
            got = client.wait_until(lambda: _map_rejections(client)[before:], TIMEOUT + 5.0)
            assert got and got[-1]['error']['code'] == 'INVALID_INPUT', got
            assert 'map' in got[-1]['error']['message'] and not got[-1]['terminal']
            before = len(_map_rejections(client))
        wrong_frame = copy.deepcopy(good_map)   # issue 19: a good map, but not in the tasks' frame
        wrong_frame.header.frame_id = 'odom'
        client.map_pub.publish(wrong_frame)
        got = client.wait_until(lambda: _map_rejections(client)[before:], TIMEOUT + 5.0)
        assert got and got[-1]['error']['code'] == 'FRAME_MISMATCH', got
        assert "'odom'" in got[-1]['error']['message'] and "'map'" in got[-1]['error']['message'], got
        status = client.wait_terminal(client.send(formula='F near[bed]'), timeout=30.0)
        assert status['status'] in ('planned', 'satisfied'), status
    finally:
        client.map_pub.publish(good_map)
    _alive(g)


def _map_rejections(client) -> list:
    return [s for v in list(client.received.statuses.values()) for s in v
            if s['status'] == 'input_rejected' and 'map' in s['error']['message']]


def test_burst_of_50_instructions_gets_50_terminal_statuses(graph):
    g, client, _ = graph
    kinds = ['F near[fridge]', 'F near[unicorn]', 'F near[sofa] & G !near[sofa]',
             'F (near[tv] & F near[lamp])']
    ids = [client.send(formula=kinds[i % len(kinds)]) for i in range(50)]
    missing = _wait_all_ended(client, ids)
    assert not missing, missing
    for i in ids:
        terminals = client.terminals(i)
        assert len(terminals) == 1, terminals
        assert client.received.statuses[i][0]['status'] == 'received', client.received.statuses[i][0]
    outcomes = [client.terminal(i)['status'] for i in ids]
    # good ones are planned (or already satisfied where the robot stands), bad ones fail
    wrong = [(kinds[k % len(kinds)], client.terminal(i)['status'], client.terminal(i)['error'])
             for k, i in enumerate(ids) if (client.terminal(i)['status'] != 'failed') != (k % 4 in (0, 3))]
    assert not wrong, wrong[:3]
    assert outcomes.count('failed') == 25
    _alive(g)


def _wait_all_ended(client, ids, stall=STALL):
    """Wait until every id has its terminal planning status; return those that have none.

    Instructions are planned one at a time, each FMT* plan taking 0.5 s on a quiet machine and
    5-9 s under a load of 18 (a burst of 50 once needed 117 s there): so the wait fails only when
    no instruction ends for ``stall`` seconds (one is lost, or the graph has stalled), not after a
    fixed total time.
    """
    ended = -1
    while True:
        now = sum(1 for i in ids if client.terminal(i))
        if now == len(ids):
            return []
        if now == ended:
            return [i for i in ids if client.terminal(i) is None]
        ended = now
        client.wait_until(lambda: sum(1 for i in ids if client.terminal(i)) > now or None, stall)


def test_late_subscriber_gets_latched_spec_referent_map_and_plan(graph):
    g, client, _ = graph
    iid = client.send(formula='F near[printer]')
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned'
    from ltl_instruct.nodes.client import GraphClient
    late = GraphClient('late_joiner')
    try:
        got = late.wait_until(lambda: (late.received.specs.get(iid) and late.received.referent_maps.get(iid)
                                       and late.received.plans.get(status['plan_stamp']) is not None
                                       and late.received.task_plans.get(iid) and late.terminal(iid)), 10.0)
        assert got, (list(late.received.specs), list(late.received.referent_maps), list(late.received.plans))
        assert late.terminal(iid)['status'] == 'planned'
    finally:
        late.close()


def test_pick_and_place_is_executed_with_skill_results(graph):
    g, client, _ = graph
    formula = 'F (pick[green_plush_toy] & F release[green_plush_toy, basket])'
    iid = client.send(formula=formula)
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned' and status['num_skills'] == 2, status
    done = client.wait_status(iid, 'satisfied', timeout=60.0)
    assert done is not None, client.received.statuses[iid]
    # (the release result comes on another topic than the status it led to: it may come second)
    client.wait_until(lambda: len([r for r in client.received.skill_results if r['id'] == iid]) >= 2 or None,
                      5.0)
    time.sleep(0.5)   # a third result, were the task carried out twice, would come now
    results = [r for r in client.received.skill_results if r['id'] == iid]
    assert [r['skill'] for r in results] == ['pick', 'release'] and all(r['ok'] for r in results), (
        [(r['skill'], r['ok'], r.get('error')) for r in results],
        [(s['status'], s.get('reason')) for s in client.received.statuses[iid]])


def test_a_late_failure_from_a_replaced_plan_does_not_replan(graph):
    g, client, _ = graph
    iid = client.send(formula='F (near[armchair] & F near[plant])')
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned', status
    from ltl_instruct.nodes.common import reliable_qos
    pub = client.node.create_publisher(String, 'skill/result', reliable_qos())
    try:
        client.wait_until(lambda: pub.get_subscription_count() > 1 or None, 5.0)
        pub.publish(conv.json_msg(conv.payload(
            conv.SKILL_RESULT, iid, skill='pick', args=['plant'], ok=False,
            plan_stamp=status['plan_stamp'] - 1, error={'code': 'SKILL_FAILED', 'message': 'stale'})))
        done = client.wait_status(iid, 'satisfied', timeout=60.0)
    finally:
        client.node.destroy_publisher(pub)
    statuses = [s['status'] for s in client.received.statuses[iid]]
    odom = [(round(t, 2), p.round(2).tolist()) for t, p in client.received.odom[-400::40]]
    plan = client.received.plans.get(status['plan_stamp'])
    assert done is not None and 'skill_failed' not in statuses and 'replanning' not in statuses, (
        statuses, odom, None if plan is None else plan[[0, -1]].round(2).tolist())


def test_task_plan_lists_steps_with_automaton_states(graph):
    g, client, _ = graph
    iid = client.send(formula='F (near[armchair] & F near[plant])')
    assert client.wait_terminal(iid, timeout=30.0)['status'] == 'planned'
    plan = client.wait_until(lambda: client.received.task_plans.get(iid), 5.0)
    assert plan is not None
    text = json.dumps(plan)
    assert 'armchair' in text and 'plant' in text


def test_a_changed_referent_map_triggers_a_replan_from_the_current_state(graph):
    g, client, _ = graph
    formula = 'F (near[fridge] & F (near[nightstand] & F near[wardrobe]))'
    iid = client.send(formula=formula)
    status = client.wait_terminal(iid, timeout=30.0)
    assert status['status'] == 'planned', status
    # a new detection: the wardrobe is elsewhere (revision 1 of this task's referent map)
    rdata = client.keyed('referent_maps', iid)
    rmap = rdata['referent_map']
    rmap['groundings']['wardrobe']['instances'][0]['center'] = [8.5, 9.5, 1.0]
    from ltl_instruct.nodes.common import latched_qos
    pub = client.node.create_publisher(String, 'referent_map', latched_qos())
    try:
        pub.publish(conv.json_msg(conv.payload(conv.REFERENT_MAP, iid, ok=True, revision=1,
                                               referent_map=rmap)))
        outcome = client.wait_until(lambda: next((s for s in client.received.statuses[iid]
                                                  if s['status'] == 'replanned'), None)
                                    or client.terminal(iid, 'execution'), 30.0)
    finally:
        client.node.destroy_publisher(pub)
    statuses = [s['status'] for s in client.received.statuses[iid]]
    replanning = next((s for s in client.received.statuses[iid] if s['status'] == 'replanning'), None)
    assert outcome is not None and replanning is not None, statuses
    assert isinstance(replanning['automaton_state'], int) and replanning['phase'] == 'execution'
    assert len(client.terminals(iid)) == 1
    if outcome['status'] != 'replanned':
        # at 8x (12 m/s) on a loaded machine the robot may finish the old plan first: then the
        # replan is dropped, and the robot is not sent anywhere after its task is done
        time.sleep(2.0)
        statuses = [s['status'] for s in client.received.statuses[iid]]
        assert outcome['status'] == 'satisfied' and 'replanned' not in statuses, statuses
        return
    assert not outcome['terminal']
    new_plan = client.wait_until(lambda: client.received.plans.get(outcome['plan_stamp']), 5.0)
    assert new_plan is not None
    moved = ReferentMap.from_dict(rmap).instances('wardrobe')[0]
    assert moved.distance(new_plan[-1], dims=2)[0] <= NEAR + 1e-6                   # ends at the new place


def test_a_failed_skill_is_reported_and_replanned_then_given_up(graph):
    g, client, _ = graph
    iid = client.send(formula='F pick[bed]')              # the bed is far too large to pick up
    assert client.wait_terminal(iid, timeout=30.0)['status'] == 'planned'
    final = client.wait_until(lambda: next((s for s in client.received.statuses.get(iid, [])
                                            if s['status'] == 'failed' and s['phase'] == 'execution'), None),
                              90.0)
    statuses = [s['status'] for s in client.received.statuses[iid]]
    assert final is not None, statuses
    assert 'skill_failed' in statuses and 'replanning' in statuses
    assert final['error']['code'] == 'NO_VALID_PATH' and 'replans' in final['error']['message']
    failed = [r for r in client.received.skill_results if r['id'] == iid]
    assert failed and all(not r['ok'] and r['error']['code'] == 'SKILL_FAILED' for r in failed)
    _alive(g)


def test_leaving_the_plan_into_an_avoided_region_is_reported_as_a_violation(graph):
    g, client, _ = graph
    # a goal far from where the robot stands: it must not be reached before the push below
    here = client.received.odom[-1][1] if client.received.odom else np.zeros(3)
    scene = resolve_scene('apartment')
    goal = max(('whiteboard', 'stove', 'nightstand', 'fridge'),
               key=lambda o: float(np.linalg.norm(np.asarray(scene.object_by_id(o).center[:2]) - here[:2])))
    iid = client.send(formula=f'F near[{goal}] & G !near[front_door]')
    assert client.wait_terminal(iid, timeout=30.0)['status'] == 'planned'
    # odometry says the robot is at the front door (as if it had been pushed there)
    msg = conv.odometry_msg(Pose((0.6, 5.0, 0.0), 0.0))
    violated = None
    deadline = time.monotonic() + TIMEOUT
    while violated is None and time.monotonic() < deadline:
        client.odom_pub.publish(msg)
        violated = client.wait_status(iid, 'violated', timeout=0.2)
    assert violated is not None, [s['status'] for s in client.received.statuses[iid]]
    assert violated['monitor']['blamed_atoms'] == ['near[front_door]']


def test_tpsm_cloud_marks_goal_and_avoid_regions(graph):
    g, client, _ = graph
    from sensor_msgs.msg import PointCloud2

    from ltl_instruct.nodes.common import latched_qos
    clouds = []
    sub = client.node.create_subscription(PointCloud2, 'tpsm', clouds.append, latched_qos(1))
    try:
        iid = client.send(formula='F near[bookshelf] & G !near[lamp]')
        assert client.wait_terminal(iid, timeout=30.0)['status'] == 'planned'
        scene = resolve_scene('apartment')
        shelf, lamp = scene.object_by_id('bookshelf').box, scene.object_by_id('lamp').box

        def ours():
            # the topic is latched: an earlier task's cloud may come first; ours is the one
            # whose goal region is the bookshelf's
            for cloud in reversed(clouds):
                f = conv.point_cloud_fields(cloud)
                goal = np.stack([f['x'], f['y']], axis=1)[f['value'] == 1.0]
                if len(goal) and np.all(shelf.distance(goal, dims=2) <= NEAR + 1e-6):
                    return f
            return None
        fields = client.wait_until(ours, 10.0)
        assert fields is not None, f'no tpsm cloud with the bookshelf as goal among {len(clouds)}'
        assert set(fields) == {'x', 'y', 'z', 'value'}
        values = set(np.unique(fields['value']).tolist())
        assert values == {-1.0, 0.0, 1.0}
        pts = np.stack([fields['x'], fields['y']], axis=1)
        assert np.all(lamp.distance(pts[fields['value'] == -1.0], dims=2) <= NEAR + 1e-6)
    finally:
        client.node.destroy_subscription(sub)


def test_malformed_messages_on_every_topic_lose_no_instruction(graph):
    """Issue 21's graph target, scaled down (``make fuzz`` runs 1,000 among 100, bench.graph_fuzz)."""
    from bench.graph_fuzz import GraphFuzzer
    g, client, _ = graph
    fuzzer = GraphFuzzer(client, seed=21)
    try:
        fuzzer.prepare()
        report = fuzzer.run(bad=80, good=4, good_map=client.received.map)
    finally:
        fuzzer.close()
    report.dead = g.dead()
    assert report.target_met(), '\n'.join(report.lines())
    assert len(report.bad_sent) >= 12, report.bad_sent   # most topics drawn, instructions most


def test_a_formula_too_large_ends_within_its_budget_and_leaves_no_trace(graph):
    """The formulas that once ran for minutes end (typed) within the compilation budget plus 1 s."""
    from ltl_instruct.core.automaton.dfa import DEFAULT_TIME_LIMIT_S
    g, client, _ = graph
    running = client.send(formula='F (near[whiteboard] & F near[stove])')
    assert client.wait_terminal(running, timeout=30.0)['status'] == 'planned'
    chain = 'F (' + ' <-> '.join(f'near[a{i}]' for i in range(14)) + ')'    # 2^14 terms written out
    until = ' U '.join(f'near[a{i}]' for i in range(20))                     # its automaton takes minutes
    # the chain's automaton is built at once on decision diagrams (3 states): its places, a0..a13,
    # are on no map, so it ends UNKNOWN_REFERENT; before, it ran out of its budget
    for formula, codes in ((chain, {'LIMIT_EXCEEDED', 'TIMEOUT', 'UNKNOWN_REFERENT'}),
                           (until, {'TIMEOUT', 'LIMIT_EXCEEDED'})):
        t0 = time.monotonic()
        iid = client.send(formula=formula)
        status = client.wait_terminal(iid, timeout=DEFAULT_TIME_LIMIT_S + 1.0)
        assert time.monotonic() - t0 <= DEFAULT_TIME_LIMIT_S + 1.0
        assert status['status'] == 'failed' and status['error']['code'] in codes, status
        assert [s['status'] for s in client.received.statuses[iid]] == ['received', 'failed']
    # the running task went on as if they had not been sent; the next one replaces it as usual
    ended = client.terminal(running, 'execution')
    assert ended is None or ended['status'] == 'satisfied', ended
    nxt = client.send(formula='F near[fridge]')
    planned = client.wait_terminal(nxt, timeout=30.0)
    assert planned['status'] in ('planned', 'satisfied'), planned
    assert [s['status'] for s in client.received.statuses[nxt]][:2] == ['received', planned['status']]
    ended = client.wait_terminal(running, timeout=TIMEOUT, phase='execution')
    assert ended['status'] == 'satisfied' or ended.get('superseded_by') == nxt, ended
    _alive(g)

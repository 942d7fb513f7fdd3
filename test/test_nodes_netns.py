"""The pipeline split over two network namespaces joined by a veth pair: DDS over a real link.

Host ``a`` runs the translator and the grounder (and the client that sends instructions);
host ``b`` runs ``task_progression``, ``fmt_planner`` and the simulator. Fast DDS is held
to UDPv4 (its shared-memory transport would otherwise join processes of one machine
whatever their network namespace), so every message between the two halves crosses the
veth. Skipped, with the reason, where ``ip netns`` is not permitted (not root, no
CAP_SYS_ADMIN, a container without it).
"""
from __future__ import annotations

import json
import os
import random
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from ltl_instruct.commands.bringup import NodeGraph, default_params_file

REPO = Path(__file__).resolve().parent.parent
TAG = f'{os.getpid() % 10000}'
HOSTS = {'a': (f'ltla{TAG}', f'va{TAG}', '10.231.7.1'), 'b': (f'ltlb{TAG}', f'vb{TAG}', '10.231.7.2')}
CLIENT = textwrap.dedent('''
    import json, sys
    from ltl_instruct.nodes.client import GraphClient
    client = GraphClient('netns_client')
    try:
        if not client.wait_for_graph(timeout=180.0, need_sim=True):
            print(json.dumps({'missing': client.missing(need_sim=True)}))
            sys.exit(1)
        out = {}
        for text in ('go to the fridge', 'go to the bed but never go near the tv'):
            iid = client.send(text=text)
            status = client.wait_terminal(iid, timeout=90.0)
            plan = client.wait_until(lambda: client.received.plans.get(status.get('plan_stamp')), 10.0)
            out[text] = {'status': status['status'], 'error': status.get('error'),
                         'poses': 0 if plan is None else len(plan)}
        print(json.dumps(out))
    finally:
        client.close()
''')


def _ip(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(['ip', *args], capture_output=True, text=True, timeout=30)


@pytest.fixture(scope='module')
def hosts():
    made = []
    try:
        for ns, _, _ in HOSTS.values():
            r = _ip('netns', 'add', ns)
            if r.returncode != 0:
                pytest.skip(f'ip netns is not permitted here: {r.stderr.strip()}')
            made.append(ns)
        (na, va, ipa), (nb, vb, ipb) = HOSTS['a'], HOSTS['b']
        steps = [('link', 'add', va, 'netns', na, 'type', 'veth', 'peer', 'name', vb, 'netns', nb)]
        for ns, dev, addr in ((na, va, ipa), (nb, vb, ipb)):
            steps += [('-n', ns, 'addr', 'add', f'{addr}/24', 'dev', dev),
                      ('-n', ns, 'link', 'set', dev, 'up'), ('-n', ns, 'link', 'set', 'lo', 'up'),
                      ('-n', ns, 'route', 'add', '224.0.0.0/4', 'dev', dev)]   # DDS discovery (multicast)
        for step in steps:
            r = _ip(*step)
            if r.returncode != 0:
                pytest.skip(f'cannot build the two hosts (ip {" ".join(step)}): {r.stderr.strip()}')
        yield HOSTS
    finally:
        for ns in made:
            _ip('netns', 'del', ns)


def _veth_bytes(ns: str, dev: str) -> int:
    stats = json.loads(_ip('-n', ns, '-j', '-s', 'link', 'show', dev).stdout)[0]['stats64']
    return int(stats['rx']['bytes']) + int(stats['tx']['bytes'])


def test_two_hosts_plan_together_over_the_link(hosts, tmp_path, monkeypatch):
    monkeypatch.setenv('ROS_DOMAIN_ID', str(random.randint(120, 229)))
    monkeypatch.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'SUBNET')
    monkeypatch.delenv('ROS_LOCALHOST_ONLY', raising=False)
    monkeypatch.setenv('FASTDDS_BUILTIN_TRANSPORTS', 'UDPv4')
    (na, va, _), (nb, _, _) = hosts['a'], hosts['b']
    overrides = {'ltl_translator': {'backend': 'offline'}, 'referent_grounder': {'use_camera': False},
                 'sim_world': {'camera_rate_hz': 0.0}}
    before = _veth_bytes(na, va)
    a = NodeGraph(('ltl_translator', 'referent_grounder'), default_params_file(), overrides,
                  log_dir=tmp_path / 'a', prefix=['ip', 'netns', 'exec', na])
    b = NodeGraph(('task_progression', 'fmt_planner', 'sim_world'), default_params_file(), overrides,
                  log_dir=tmp_path / 'b', prefix=['ip', 'netns', 'exec', nb])
    with a, b:
        env = dict(os.environ, PYTHONPATH=str(REPO))
        proc = subprocess.run(['ip', 'netns', 'exec', na, sys.executable, '-c', CLIENT], capture_output=True,
                              text=True, env=env, timeout=300)
        logs = '\n'.join(f'--- {p}\n{p.read_text()[-1500:]}' for p in sorted(tmp_path.rglob('*.log')))
        assert proc.returncode == 0, (proc.stdout, proc.stderr[-2000:], logs)
        assert not a.dead() and not b.dead(), logs
    result = json.loads(proc.stdout.strip().splitlines()[-1])
    for text, got in result.items():
        assert got['status'] == 'planned' and got['poses'] >= 2, (text, got)
    # the halves talked over the veth: the two plans' messages alone are kilobytes
    assert _veth_bytes(na, va) - before > 50_000

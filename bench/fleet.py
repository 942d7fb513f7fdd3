"""Many robots on one graph, each in its namespace (issue 19 benchmark).

Run: ``.venv/bin/python -m bench.fleet [--robots 10] [--rounds 4]``.

First one robot alone (namespace ``/solo``), then ``--robots`` robots at once
(``/r0`` ... ``/r9``), each a full set of five node processes (offline translator,
camera off) on the built-in apartment, on one private ROS_DOMAIN_ID. Every robot sends
its English instructions one at a time, all robots at the same time, and the client of
each robot (in its namespace) measures instruction -> ``plan`` latency. Process start is
not counted. Reported: latency per robot and over all of them against the one robot
alone (target: median within 2x), cross-talk (a status, spec, referent map or plan of
another robot's instruction heard in a namespace: none allowed) and lost instructions
(sent, and no terminal status: none allowed).

DDS discovery: with ``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` Fast DDS finds peers by
unicast to a small range of participant ports, and past about 30 participants on one
host new ones never meet each other (a first run here: robots 5-9 of 10 heard nothing
among their own nodes, the client saw them all). So, when it may (root), the benchmark
runs itself in a private network namespace whose loopback carries multicast, with
``SUBNET`` discovery: every participant meets every other, and nothing leaves the
namespace. ``--no-netns`` keeps the host's network (and ``LOCALHOST`` discovery).
"""
from __future__ import annotations

import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

from bench.pipeline import INSTRUCTIONS

QUIET = {'sim_world': {'camera_rate_hz': 0.0, 'time_scale': 1.0},
         'referent_grounder': {'use_camera': False}, 'ltl_translator': {'backend': 'offline'}}


def _start(namespaces: list[str], logs: Path) -> tuple[list[Any], dict[str, Any]]:
    """Start a graph and a client per namespace; return them once every robot's graph is up."""
    from ltl_instruct.commands.bringup import (
        ALL_NODES, NodeGraph, default_params_file, merge_overrides, robot_overrides,
    )
    from ltl_instruct.nodes.client import GraphClient
    graphs, clients = [], {}
    for ns in namespaces:
        overrides = merge_overrides(QUIET, robot_overrides(ns.strip('/') + '/'))
        graphs.append(NodeGraph(ALL_NODES, default_params_file(), overrides, log_dir=logs,
                                namespace=ns).start())
        clients[ns] = GraphClient('bench_fleet', namespace=ns)
    return graphs, clients


def _drive(client: Any, rounds: int, offset: int, out: dict[str, Any]) -> None:
    """Send ``rounds`` instructions one at a time (two warm-ups first); record latency and ids."""
    out.update(latencies=[], sent=[], failed=[])
    for k in range(rounds + 2):
        text = INSTRUCTIONS[(k + offset) % len(INSTRUCTIONS)]
        t0 = time.monotonic()
        iid = client.send(text=text)
        out['sent'].append(iid)
        try:
            status = client.wait_terminal(iid, timeout=120.0)
        except Exception as e:  # noqa: BLE001 - a lost instruction is a figure, not a crash
            out['failed'].append((text, str(e)))
            continue
        if status['status'] != 'planned':
            out['failed'].append((text, status.get('error')))
            continue
        stamp = status['plan_stamp']
        client.wait_until(lambda: client.received.plans.get(stamp) is not None, 30.0)
        if k >= 2:
            out['latencies'].append(time.monotonic() - t0)


def _run(namespaces: list[str], rounds: int, logs: Path) -> dict[str, dict[str, Any]]:
    """Run every robot at once; return per namespace its latencies, ids sent, failures, what it heard."""
    graphs, clients = _start(namespaces, logs)
    results: dict[str, dict[str, Any]] = {ns: {} for ns in namespaces}
    try:
        t0 = time.monotonic()
        for ns, client in clients.items():
            if not client.wait_for_graph(timeout=600.0, need_sim=True):
                missing = client.missing(need_sim=True)
                raise SystemExit(f'{ns}: graph did not come up ({missing}); logs in {logs}')
        print(f'  {len(namespaces)} robot(s) up in {time.monotonic() - t0:.1f} s (not counted)', flush=True)
        threads = [threading.Thread(target=_drive, args=(clients[ns], rounds, k, results[ns]), daemon=True)
                   for k, ns in enumerate(namespaces)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        # an instruction whose sender stopped waiting may still end: lost is one that never does
        sent = {ns: results[ns]['sent'] for ns in namespaces}
        for ns, client in clients.items():
            client.wait_until(lambda c=client, ids=sent[ns]: all(c.terminal(i) for i in ids), 60.0)
        time.sleep(1.0)   # anything crossing over would have come by now
        for ns, client in clients.items():
            got = client.received
            heard = set(got.statuses) | set(got.specs) | set(got.referent_maps)
            results[ns]['foreign'] = sorted(heard - set(results[ns]['sent']))
            known = {s.get('plan_stamp') for ss in client.received.statuses.values() for s in ss}
            results[ns]['foreign'] += [f'plan {k}' for k in sorted(set(client.received.plans) - known)]
            results[ns]['lost'] = [i for i in results[ns]['sent'] if client.terminal(i) is None]
        for ns, g in zip(namespaces, graphs):
            results[ns]['dead'] = g.dead()
    finally:
        for client in clients.values():
            client.close()
        for g in graphs:
            g.stop()
    return results


def _ms(values: list[float]) -> str:
    return f'{statistics.median(values) * 1000:6.0f} ms' if values else '     - ms'


def _in_private_network(argv: list[str]) -> int:
    """Run this benchmark again in a fresh network namespace with multicast on its loopback.

    Returns its exit status, or -1 when no namespace can be made (not root...).
    """
    name = f'ltlfleet{os.getpid()}'
    if subprocess.run(['ip', 'netns', 'add', name], capture_output=True).returncode != 0:
        return -1
    try:
        for step in (['link', 'set', 'lo', 'up'], ['link', 'set', 'lo', 'multicast', 'on'],
                     ['route', 'add', '224.0.0.0/4', 'dev', 'lo']):
            subprocess.run(['ip', '-n', name, *step], check=True, capture_output=True)
        # UDP only: Fast DDS's shared-memory ports live in /dev/shm, which the namespace shares with
        # every other Fast DDS process of the host (a run logged "Failed init_port ... open_and_lock_file")
        env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE='SUBNET', FASTDDS_BUILTIN_TRANSPORTS='UDPv4')
        return subprocess.run(['ip', 'netns', 'exec', name, sys.executable, '-m', 'bench.fleet', '--no-netns',
                               '--discovery', 'SUBNET', *argv], env=env).returncode
    finally:
        subprocess.run(['ip', 'netns', 'del', name], capture_output=True)


def main(argv: list[str]) -> int:
    """Run the benchmark and print its figures; 0 without cross-talk or loss and with the target met."""
    parser = argparse.ArgumentParser(prog='python -m bench.fleet', description=__doc__.splitlines()[0])
    parser.add_argument('--robots', type=int, default=10, help='robots on the graph at once (default 10)')
    parser.add_argument('--rounds', type=int, default=4, help='timed instructions per robot (default 4)')
    parser.add_argument('--no-netns', action='store_true',
                        help='run on the host network (LOCALHOST discovery: about 5 robots at most)')
    parser.add_argument('--discovery', default='LOCALHOST', help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if not args.no_netns:
        status = _in_private_network(argv)
        if status >= 0:
            return status
        print('cannot make a network namespace (not root?): on the host network, LOCALHOST discovery')
    os.environ['ROS_DOMAIN_ID'] = str(random.randint(120, 229))
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = args.discovery
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    logs = Path(tempfile.mkdtemp(prefix='bench_fleet_'))
    print(f'one robot alone, {args.rounds} instructions; discovery {args.discovery}; logs in {logs}',
          flush=True)
    solo = _run(['/solo'], args.rounds, logs)['/solo']
    print(f'{args.robots} robots at once, {args.rounds} instructions each', flush=True)
    fleet = _run([f'/r{k}' for k in range(args.robots)], args.rounds, logs)
    every = [v for r in fleet.values() for v in r['latencies']]
    print('instruction -> plan latency (median per robot):')
    for ns, r in fleet.items():
        timed, failed = len(r['latencies']), len(r['failed'])
        print(f'  {ns:<6} {_ms(r["latencies"])}  ({timed} timed, {failed} not planned)')
    foreign = sum(len(r['foreign']) for r in fleet.values())
    lost = sum(len(r['lost']) for r in fleet.values()) + len(solo['lost'])
    ratio = statistics.median(every) / statistics.median(solo['latencies']) if every and solo['latencies'] \
        else float('inf')
    print(f'one robot alone: median {_ms(solo["latencies"])}; {args.robots} robots: median {_ms(every)}, '
          f'p90 {sorted(every)[int(0.9 * (len(every) - 1))] * 1000:.0f} ms; ratio {ratio:.2f} (target <= 2)'
          if every else 'no plan was made')
    print(f'cross-talk: {foreign} message(s) of another robot heard; lost instructions: {lost}; '
          f'nodes dead at the end: {sum(len(r["dead"]) for r in fleet.values())}')
    failed = [f for r in fleet.values() for f in r['failed']]
    if failed:
        print(f'not planned: {len(failed)}, e.g. {failed[:3]}')
    return 0 if foreign == 0 and lost == 0 and ratio <= 2.0 else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

"""Automaton construction: our symbolic DFAs beside ltlf2dfa + MONA, measured in the same run.

Run: ``.venv/bin/python -m bench.automaton [--formulas 200] [--json out/bench_automaton.json]``.

What is measured (issue 22):

- Random suite (the seeded formulas of ``test_automaton_oracle``: 1-5 atoms, 1-8
  operators). Ours: :func:`compile_automaton` (the whole minimal DFA), each formula
  in a fresh decision-diagram manager, so nothing is cached from one formula to the
  next (cold). Peer: ltlf2dfa's parser built once before timing (warm), then per
  formula its parse and ``to_dfa`` (MONA program, the ``mona`` process, its DFA to
  DOT); the ``mona`` process alone is reported too. Our conversion of ltlf2dfa's DOT
  for the language check is not timed. Both minimal? Ours is checked by an explicit
  Moore minimisation over every letter (independent of our code), and its number of
  states is set beside MONA's.
- Target cases, each timed alone (median of repeats) beside ltlf2dfa + MONA on the same
  formula: ``G !near[b] & F near[a1] & ... & F near[aN]`` (whole minimal DFA, as
  ``ltl-instruct formula --max-states 5000`` builds it, and JSON of it), a chain of
  ``<->``, the ordered and pick-and-place cases of issue 2.
- Planning: ``ltl-instruct plan --scene apartment`` of the 12-goal task in process
  (text to verified plan; the automaton is explored on the fly), and how much of
  that time is the automaton (everything but the segment solver).
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import random
import statistics
import sys
import time
from pathlib import Path
from typing import Any, Callable, Optional

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.random_formulas import default_atoms, random_formula
from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.spec import atoms_of, parse_formula

APARTMENT_GOALS = ('plant', 'lamp', 'bookshelf', 'tv', 'fridge', 'stove', 'printer', 'desk', 'bed',
                   'nightstand', 'wardrobe', 'whiteboard')


def independent_goals(n: int, avoid: str = 'front_door') -> str:
    """``G !near[avoid] & F near[g1] & ... & F near[gn]`` over apartment objects."""
    return ' & '.join([f'G !near[{avoid}]'] + [f'F near[{g}]' for g in APARTMENT_GOALS[:n]])


def iff_chain(n: int) -> str:
    """``F (near[a0] <-> ... <-> near[a{n-1}])``."""
    return 'F (' + ' <-> '.join(f'near[a{i}]' for i in range(n)) + ')'


def pick_and_place_chain(n_objects: int, avoid: int = 2) -> str:
    """Visit, pick, carry and release a chain of objects (3 distinct atoms per delivery)."""
    def step(i: int) -> str:
        rest = step(i + 1) if i + 1 < n_objects else ''
        tail = f' & F {rest}' if rest else ''
        return f'(near[shelf_{i}] & F (pick[item_{i}] & F release[item_{i}, bin_{i}]{tail}))'
    avoids = ''.join(f' & G !near[door_{k}]' for k in range(avoid))
    return f'F {step(0)}{avoids}'


def ordered_visit(n: int) -> str:
    """Visit landmarks l0..l{n-1} in this order, none before its predecessor (Lang2LTL 'ordered')."""
    parts = [f'F near[l{n - 1}]'] + [f'(!near[l{i + 1}] U near[l{i}])' for i in range(n - 1)]
    return ' & '.join(parts)


def timed(fn: Callable[[], object], repeat: int = 5) -> float:
    """Median wall time [s] of ``fn`` over ``repeat`` runs."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


class Peer:
    """ltlf2dfa + MONA, its parser built once; times its own work only."""

    def __init__(self) -> None:
        sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'test'))
        import ltl_oracles
        self.oracles = ltl_oracles
        self.available = ltl_oracles.mona_available()
        if not self.available:
            return
        import tempfile

        import ltlf2dfa.ltlf2dfa as core
        from ltlf2dfa.parser.ltlf import LTLfParser
        core.PACKAGE_DIR = tempfile.mkdtemp(prefix='ltlf2dfa_')
        self.core = core
        self.parser = LTLfParser()
        self.mona_s = 0.0
        invoke = core.invoke_mona

        def timed_invoke(*a: Any) -> Any:
            t0 = time.perf_counter()
            try:
                return invoke(*a)
            finally:
                self.mona_s += time.perf_counter() - t0
        core.invoke_mona = timed_invoke

    def dot(self, f: Any, atoms: Any) -> tuple[str, float, float]:
        """DOT of the DFA, total seconds, seconds in the mona process."""
        names = {a: f'v{i}' for i, a in enumerate(atoms)}
        text = self.oracles.to_ltlf2dfa_text(f, names)
        before = self.mona_s
        t0 = time.perf_counter()
        dot = self.parser(text).to_dfa()
        return dot, time.perf_counter() - t0, self.mona_s - before

    def mona_only(self, f: Any, atoms: Any) -> tuple[int, float, float]:
        """MONA's DFA without ltlf2dfa's DOT conversion (it simplifies every guard with sympy).

        Returns its states (MONA's count less its extra initial state), total seconds, and
        seconds in the mona process.
        """
        import re
        names = {a: f'v{i}' for i, a in enumerate(atoms)}
        text = self.oracles.to_ltlf2dfa_text(f, names)
        before = self.mona_s
        t0 = time.perf_counter()
        out = self.parser(text).to_dfa(mona_dfa_out=True)
        total = time.perf_counter() - t0
        m = re.search(r'Automaton has (\d+) states', out) if isinstance(out, str) else None
        return (int(m.group(1)) - 1 if m else -1), total, self.mona_s - before

    def dfa(self, f: Any, atoms: Any, dot: str) -> Any:
        """The DOT read back as a DFA (for the language check; not timed)."""
        return self.oracles.MonaDfa(dot, {a: f'v{i}' for i, a in enumerate(atoms)})


def mona_states(dot: str) -> int:
    """States of a DFA in ltlf2dfa's DOT (its ``init`` arrow is not a state)."""
    import re
    return len({s for edge in re.findall(r'(\w+) -> (\w+) \[label', dot) for s in edge} - {'init'})


def random_suite(n: int, peer: Peer) -> dict[str, Any]:
    """Time ours and the peer on ``n`` seeded random formulas; check minimality and languages."""
    rng = random.Random(500)
    ours_s, peer_s, mona_s = [], [], []
    rows = []
    for _ in range(n):
        atoms = default_atoms(rng.randint(1, 5), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 8))
        t0 = time.perf_counter()
        aut = compile_automaton(f)
        ours_s.append(time.perf_counter() - t0)
        letters = peer.oracles.valid_letters(atoms_of(f)) if atoms_of(f) else [frozenset()]
        row = {'formula': str(f), 'states': aut.num_states,
               'minimal_states': peer.oracles.minimal_states(aut, letters)}
        if peer.available:
            dot, total, mona = peer.dot(f, atoms_of(f))
            peer_s.append(total)
            mona_s.append(mona)
            row['mona_states'] = mona_states(dot)
            row['same_language'] = peer.oracles.languages_differ(
                aut, peer.dfa(f, atoms_of(f), dot), letters) is None
        rows.append(row)
    out: dict[str, Any] = {
        'formulas': n, 'ours_ms_per_formula': 1e3 * statistics.mean(ours_s),
        'ours_median_ms': 1e3 * statistics.median(ours_s),
        'non_minimal': sum(r['states'] != r['minimal_states'] for r in rows),
        'mean_states': statistics.mean(r['states'] for r in rows),
        'max_states': max(r['states'] for r in rows)}
    if peer_s:
        out.update(peer_ms_per_formula=1e3 * statistics.mean(peer_s),
                   peer_mona_process_ms_per_formula=1e3 * statistics.mean(mona_s),
                   speedup=sum(peer_s) / sum(ours_s),
                   more_states_than_mona=sum(r['states'] > r['mona_states'] for r in rows),
                   language_differs=sum(not r['same_language'] for r in rows))
    return out


def case(name: str, text: str, peer: Optional[Peer], repeat: int = 5,
         max_states: int = 5000) -> dict[str, Any]:
    """One target formula: our minimal DFA (and its JSON) beside ltlf2dfa + MONA."""
    f = parse_formula(text)

    def build() -> Any:
        return compile_automaton(f, max_states=max_states, max_edges=10**7, time_limit_s=None,
                                 max_nodes=10**8)
    try:
        aut = build()
    except LtlInstructError as e:
        return {'case': name, 'formula': text, 'atoms': len(atoms_of(f)), 'error': e.code.value}
    row: dict[str, Any] = {'case': name, 'formula': text, 'atoms': len(atoms_of(f)), 'states': aut.num_states,
                           'edges': sum(1 for _ in aut.edges())}
    row['ours_s'] = timed(build, repeat)
    if row['edges'] <= 100_000:   # JSON of 535,000 edges (12 goals) takes minutes: not timed
        row['ours_with_json_s'] = timed(lambda: build().to_dict(), 1)
    if peer is not None and peer.available:
        states, total, mona = peer.mona_only(f, atoms_of(f))
        row.update(peer_s=total, peer_mona_process_s=mona, mona_states=states)
    return row


def plan_apartment(text: str) -> dict[str, Any]:
    """``ltl-instruct plan --scene apartment --formula TEXT`` in process: seconds, and the solver's share."""
    from ltl_instruct.cli import main
    from ltl_instruct.core.planning import segment
    solver_s = [0.0]
    solve = segment.solve_segment

    def timed_solve(*a: Any, **k: Any) -> Any:
        t0 = time.perf_counter()
        try:
            return solve(*a, **k)
        finally:
            solver_s[0] += time.perf_counter() - t0
    from ltl_instruct.core.planning import planner
    planner.solve_segment = timed_solve
    buf = io.StringIO()
    t0 = time.perf_counter()
    try:
        with contextlib.redirect_stdout(buf):
            rc = main(['plan', '--scene', 'apartment', '--formula', text])
    finally:
        planner.solve_segment = solve
    total = time.perf_counter() - t0
    return {'formula': text, 'exit': rc, 'seconds': total, 'segment_solver_s': solver_s[0],
            'rest_s': total - solver_s[0], 'verified': 'verified: yes' in buf.getvalue()}


def report_random(s: dict[str, Any]) -> None:
    """Print the random-suite figures, ours beside the peer's."""
    print(f"random suite: {s['formulas']} formulas (1-5 atoms, 1-8 operators), mean states "
          f"{s['mean_states']:.1f}, max {s['max_states']}")
    print(f"  ours (cold, whole minimal DFA): {s['ours_ms_per_formula']:.2f} ms/formula; non-minimal DFAs: "
          f"{s['non_minimal']} (explicit Moore check)")
    if 'speedup' in s:
        print(f"  ltlf2dfa+MONA (parser warm): {s['peer_ms_per_formula']:.2f} ms/formula, of which the mona "
              f"process {s['peer_mona_process_ms_per_formula']:.2f} ms; speed-up {s['speedup']:.1f}x "
              f"(target >= 10x)")
        print(f"  more states than MONA's DFA: {s['more_states_than_mona']}; language differs from MONA's: "
              f"{s['language_differs']}")


def report_case(c: dict[str, Any]) -> None:
    """Print one target case beside the peer."""
    if 'error' in c:
        print(f"{c['case']} | {c['atoms']} | {c['error']}", flush=True)
        return
    peer = (f"{c['peer_s']:.3f} ({c['peer_mona_process_s']:.3f}) | {c['mona_states']}"
            if 'peer_s' in c else '- (not run) | -')
    json_s = f"{c['ours_with_json_s']:.3f}" if 'ours_with_json_s' in c else '-'
    print(f"{c['case']} | {c['atoms']} | {c['states']} | {c['edges']} | {c['ours_s']:.3f} | "
          f"{json_s} | {peer}", flush=True)


def report_plan(p: dict[str, Any]) -> None:
    """Print the planning figure."""
    print(f"plan on the apartment, {p['formula'][:40]}... (12 goals): {p['seconds']:.2f} s end to end "
          f"(segment solver {p['segment_solver_s']:.2f} s, automaton and search {p['rest_s']:.2f} s), "
          f"verified: {p['verified']}", flush=True)


def main(argv: Optional[list[str]] = None) -> int:
    """Measure, print and optionally write JSON."""
    ap = argparse.ArgumentParser(prog='python -m bench.automaton')
    ap.add_argument('--formulas', type=int, default=200, help='random formulas for the comparison')
    ap.add_argument('--goals', type=int, default=12, help='independent goals of the largest case')
    ap.add_argument('--no-plan', action='store_true', help='skip planning on the apartment')
    ap.add_argument('--json', help='write the figures to this JSON file')
    args = ap.parse_args(argv)
    peer = Peer()
    if not peer.available:
        print('ltlf2dfa/mona not available: our figures only')
    r: dict[str, Any] = {'cases': []}
    if args.formulas > 0:
        r['random'] = random_suite(args.formulas, peer)
        report_random(r['random'])
    cases = [(f'{n} independent goals + avoidance', independent_goals(n), 3 if n < 12 else 1, True)
             for n in sorted({8, 10, args.goals})]
    # ltlf2dfa's own Python translation of a long <-> chain ran for minutes: ours only there
    cases += [(f'chain of {n} <->', iff_chain(n), 5, n <= 10) for n in (10, 14, 20)]
    cases += [('pick-and-place chain, 4 deliveries + 2 avoidances', pick_and_place_chain(4), 5, True),
              ('10-landmark ordered visit', ordered_visit(10), 5, True)]
    print('case | atoms | states | edges | ours [s] | ours + JSON [s] | ltlf2dfa to MONA output [s] '
          '(mona process) | MONA states', flush=True)
    for name, text, rep, with_peer in cases:
        r['cases'].append(case(name, text, peer if with_peer else None, rep))
        report_case(r['cases'][-1])
    if not args.no_plan:
        r['plan'] = plan_apartment(independent_goals(args.goals))
        report_plan(r['plan'])
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(r, indent=2))
    return 0


if __name__ == '__main__':
    sys.exit(main())

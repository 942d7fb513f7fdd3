"""Automaton compilation speed: target cases, and side by side with ltlf2dfa + mona.

Run: ``.venv/bin/python -m bench.automaton [--formulas N]``.
Targets (issue 2): a 12-atom pick-and-place chain with two avoidances < 50 ms; a
10-landmark ordered visit < 50 ms; >= 10x faster than ltlf2dfa+mona on the random suite.
"""
from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from pathlib import Path
from typing import Callable

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.random_formulas import default_atoms, random_formula
from ltl_instruct.core.spec import atoms_of, parse_formula


def pick_and_place_chain(n_objects: int, avoid: int = 2) -> str:
    """Visit, pick, carry and release a chain of objects (3 distinct atoms per delivery)."""
    def step(i: int) -> str:
        rest = step(i + 1) if i + 1 < n_objects else ''
        tail = f' & F {rest}' if rest else ''
        return (f'(near[shelf_{i}] & F (pick[item_{i}] & F release[item_{i}, bin_{i}]{tail}))')
    avoids = ''.join(f' & G !near[door_{k}]' for k in range(avoid))
    return f'F {step(0)}{avoids}'


def ordered_visit(n: int) -> str:
    """Visit landmarks l0..l{n-1} in this order, none before its predecessor (Lang2LTL 'ordered')."""
    parts = [f'F near[l{n - 1}]'] + [f'(!near[l{i + 1}] U near[l{i}])' for i in range(n - 1)]
    return ' & '.join(parts)


def sequenced_visit(n: int) -> str:
    """F (l0 & F (l1 & ... F l{n-1}))."""
    text = f'near[l{n - 1}]'
    for i in range(n - 2, -1, -1):
        text = f'near[l{i}] & F ({text})' if i else f'F (near[l{i}] & F ({text}))'
    return text


def timed(fn: Callable[[], object], repeat: int = 7) -> float:
    """Median wall time [s] of ``fn`` over ``repeat`` runs."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main(argv: list[str] | None = None) -> int:
    """Print the figures; return 1 when a target is missed."""
    ap = argparse.ArgumentParser(prog='python -m bench.automaton')
    ap.add_argument('--formulas', type=int, default=300, help='random formulas for the comparison')
    args = ap.parse_args(argv)
    ok = True
    cases = {
        'pick-and-place chain, 4 deliveries (12 atoms) + 2 avoidances': pick_and_place_chain(4),
        'pick-and-place chain, 3 deliveries + 2 avoidances (11 atoms)': pick_and_place_chain(3),
        '10-landmark ordered visit': ordered_visit(10),
        '10-landmark sequenced visit': sequenced_visit(10),
    }
    print('case | atoms | states | median compile [ms] | target')
    for name, text in cases.items():
        f = parse_formula(text)
        aut = compile_automaton(f)
        t = timed(lambda: compile_automaton(f))
        target = name.startswith(('pick-and-place chain, 4', '10-landmark ordered'))
        ok &= (t < 0.05) or not target
        print(f'{name} | {len(atoms_of(f))} | {aut.num_states} | {t * 1e3:.1f} | '
              f'{"< 50 ms " + ("MET" if t < 0.05 else "MISSED") if target else "-"}')

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'test'))
    from ltl_oracles import ltlf2dfa_dfa, mona_available
    if not mona_available():
        print('ltlf2dfa/mona not available: skipping the side-by-side comparison')
        return 0 if ok else 1
    rng = random.Random(500)
    ours = mona = 0.0
    states = []
    for _ in range(args.formulas):
        atoms = default_atoms(rng.randint(1, 5), events=rng.random() < 0.3)
        f = random_formula(rng, atoms, rng.randint(1, 8))
        t0 = time.perf_counter()
        aut = compile_automaton(f)
        ours += time.perf_counter() - t0
        t0 = time.perf_counter()
        ltlf2dfa_dfa(f, atoms)
        mona += time.perf_counter() - t0
        states.append(aut.num_states)
    ratio = mona / ours
    ok &= ratio >= 10
    print(f'random suite: {args.formulas} formulas (1-5 atoms, 1-8 operators), '
          f'mean states {statistics.mean(states):.1f}, max {max(states)}')
    print(f'  ours: {ours * 1e3 / args.formulas:.2f} ms/formula; ltlf2dfa+mona: '
          f'{mona * 1e3 / args.formulas:.2f} ms/formula; speed-up {ratio:.0f}x (target >= 10x: '
          f'{"MET" if ratio >= 10 else "MISSED"})')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())

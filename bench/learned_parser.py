"""Learned parser (issue 7): per-city training time and test figures, model vs baseline.

Run: ``nice .venv/bin/python -m bench.learned_parser [--data DIR] [--cities a,b] [--retrain]``.

For each city of the osm-trajectories folder (default ``../shared/datasets/osm-trajectories``
beside the repository), trains a parser unless ``out/learned/models/<city>.pt`` exists
(or ``--retrain``), then scores the parser and the baseline on the fixed test
split (100 held-out trajectories). Prints one row per city and the averages, and
writes everything to ``out/learned/bench.json``.

Targets: mean goal-state accuracy over the cities >= 0.80; the parser's edit
distance below the baseline's in every city; training <= 20 min per city on 2 cores.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT_DATA = REPO.parent / 'shared' / 'datasets' / 'osm-trajectories'
OUT = REPO / 'out' / 'learned'


def main(argv: list[str]) -> int:
    """Train (where needed) and evaluate each city; print the table."""
    ap = argparse.ArgumentParser(prog='bench.learned_parser')
    ap.add_argument('--data', default=str(DEFAULT_DATA), help='osm-trajectories folder')
    ap.add_argument('--cities', default='', help='comma-separated cities (default: all in DATA/maps)')
    ap.add_argument('--retrain', action='store_true', help='train even where a model file exists')
    ap.add_argument('--epochs', type=int, default=None, help='override the training epochs')
    ap.add_argument('--threads', type=int, default=2, help='torch threads (default 2)')
    args = ap.parse_args(argv)
    maps = Path(args.data) / 'maps'
    if not maps.is_dir():
        print(f'skipped: no dataset at {args.data}')
        return 0
    from ltl_instruct.core.language.learned.bundle import ParserBundle
    from ltl_instruct.core.language.learned.city import evaluate_city, train_city
    from ltl_instruct.core.language.learned.training import TrainingConfig
    cities = [c for c in args.cities.split(',') if c] or sorted(p.stem for p in maps.glob('*.json'))
    (OUT / 'models').mkdir(parents=True, exist_ok=True)
    rows = []
    header = (f"{'city':14s}{'train s':>8s}{'epochs':>7s}{'goal':>7s}{'b.goal':>7s}"
              f"{'prec':>6s}{'b.prec':>7s}{'recall':>7s}{'b.rec':>6s}{'path':>6s}{'b.path':>7s}"
              f"{'edit':>6s}{'b.edit':>7s}")
    print(header, flush=True)
    for city in cities:
        model_path = OUT / 'models' / f'{city}.pt'
        if args.retrain or not model_path.exists():
            config = TrainingConfig() if args.epochs is None else TrainingConfig(epochs=args.epochs)
            started = time.monotonic()
            bundle = train_city(args.data, city, config, threads=args.threads,
                                progress=lambda m, c=city: print(f'  {c}: {m}', file=sys.stderr, flush=True))
            bundle.info['wall_seconds'] = time.monotonic() - started
            bundle.save(str(model_path))
        bundle = ParserBundle.load(str(model_path))
        result = evaluate_city(args.data, city, bundle, threads=args.threads)
        info = bundle.info
        m, b = result['model'], result['baseline']
        train_s = float(info.get('total_seconds', 0.0))
        print(f"{city:14s}{train_s:8.0f}{info['training']['epochs_run']:7d}{m['goal_accuracy']:7.3f}"
              f"{b['goal_accuracy']:7.3f}{m['precision']:6.3f}{b['precision']:7.3f}{m['recall']:7.3f}"
              f"{b['recall']:6.3f}{m['path_accuracy']:6.3f}{b['path_accuracy']:7.3f}"
              f"{m['edit_distance']:6.2f}{b['edit_distance']:7.2f}", flush=True)
        rows.append({'city': city, 'train_seconds': train_s, 'info': info, 'result': result})
    if rows:
        mean_goal = sum(r['result']['model']['goal_accuracy'] for r in rows) / len(rows)
        mean_base = sum(r['result']['baseline']['goal_accuracy'] for r in rows) / len(rows)
        edit_wins = sum(r['result']['model']['edit_distance'] < r['result']['baseline']['edit_distance']
                        for r in rows)
        slowest = max(r['train_seconds'] for r in rows)
        print(f'mean goal-state accuracy: parser {mean_goal:.3f} (target >= 0.80), baseline {mean_base:.3f}')
        print(f'edit distance below the baseline in {edit_wins}/{len(rows)} cities (target: all)')
        print(f'slowest training: {slowest:.0f} s (target <= 1200 s on 2 cores; threads={args.threads})')
        with open(OUT / 'bench.json', 'w') as f:
            json.dump({'rows': rows, 'mean_goal_accuracy': mean_goal,
                       'mean_baseline_goal_accuracy': mean_base, 'edit_distance_wins': edit_wins,
                       'cpu_count': os.cpu_count()}, f, indent=1)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

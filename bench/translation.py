"""Translation benchmark: offline translator accuracy on the public sets, and its speed.

Run: ``.venv/bin/python -m bench.translation [--limit N] [--sets dev,drone,lifted]``.
Targets (issue 5): formula equivalence >= 90% on efficient-eng-2-ltl drone-planning and on
lang2ltl lifted.csv; under 10 ms per instruction offline. Figures are equivalence on
automata (LTLf, finite traces), never string equality. Reads ``../shared/datasets``.
"""
from __future__ import annotations

import argparse
import gc
import random
import statistics
import time
from pathlib import Path

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language.datasets import read_dataset
from ltl_instruct.core.language.evaluation import evaluate
from ltl_instruct.core.language.offline import OfflineTranslator

DATA = Path(__file__).resolve().parents[1].parent / 'shared' / 'datasets'
# each set with the translator options of its conventions (see the README, "translate")
SETS: dict[str, tuple[Path, dict[str, str]]] = {
    'dev': (DATA / 'spatial-temporal-dev' / 'dev.jsonl', {}),
    'drone': (DATA / 'efficient-eng-2-ltl' / 'drone-planning.jsonl',
              {'avoid_scope': 'goal', 'numbers': 'digits'}),
    'lifted': (DATA / 'lang2ltl' / 'lifted.csv', {'once_scope': 'next', 'after_scope': 'conditional'}),
}


def main(argv: list[str]) -> int:
    """Print accuracy and timing per data set; 0 on success, 1 if no data set was found."""
    ap = argparse.ArgumentParser(prog='bench.translation', description=__doc__)
    ap.add_argument('--limit', type=int, default=0, help='random sample per set (0: all)')
    ap.add_argument('--sets', default='dev,drone,lifted')
    args = ap.parse_args(argv)
    ran = 0
    for name in args.sets.split(','):
        path, options = SETS[name]
        if not path.is_file():
            print(f'{name:7s} skipped: {path} not found')
            continue
        ds = read_dataset(path)
        examples = ds.examples
        if args.limit and args.limit < len(examples):
            examples = random.Random(0).sample(examples, args.limit)
        translator = OfflineTranslator(landmarks=ds.landmarks, **options)
        # speed: a pass of translation alone (the scoring pass builds automata, whose garbage
        # collections would land inside unrelated translations)
        gc.collect()
        per = []
        for ex in examples:
            t = time.perf_counter()
            try:
                translator.translate(ex.instruction)
            except LtlInstructError:
                pass
            per.append((time.perf_counter() - t) * 1000)
        per.sort()
        t0 = time.perf_counter()
        s = evaluate(translator, examples)
        wall = time.perf_counter() - t0
        summ = s.summary()
        print(f'{name:7s} n={summ["examples"]:5d}  equivalence={summ["equivalence_accuracy"]:.3f}  '
              f'temporal_alignment={summ["temporal_alignment"]:.3f}  referent_wer={summ["referent_wer"]}  '
              f'avoid_wer={summ["avoidance_wer"]}  errors={summ["translation_errors"]}  '
              f'{" ".join(f"{k}={v}" for k, v in options.items())}')
        p99 = per[int(0.99 * (len(per) - 1))]
        print(f'{"":7s} ms/instruction: median {statistics.median(per):.3f}  p99 {p99:.3f}'
              f'  max {per[-1]:.3f}  (scoring with automata: {wall:.1f} s)')
        ran += 1
    return 0 if ran else 1


if __name__ == '__main__':
    import sys
    sys.exit(main(sys.argv[1:]))

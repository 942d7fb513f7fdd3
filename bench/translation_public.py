"""Translation benchmark on the TEST splits of the public sets (``neural.public``).

Run: ``.venv/bin/python -m bench.translation_public --backend offline [--sets drone,cleanup]
[--limit N] [--json]``. Each set's translator is ``make_translator(backend,
landmarks=<the set's proposition names>, **options)``, with the set's conventions
(``public.SET_OPTIONS``: the rules' options, as in ``bench/translation.py``) given to the rules
and to the model alike (a model trained without convention inputs ignores them). Prints per
set: n, formula equivalence (on automata), temporal alignment, referent WER, the
wrong-and-unflagged share (returned, not equivalent to gold and not flagged by the backend: a
refusal counts as flagged) and the median milliseconds per instruction. Reads
``../shared/datasets`` or ``$LTL_INSTRUCT_DATASETS``; exits 1 when no set was found.
"""
from __future__ import annotations

import argparse
import json
import random
import statistics
import sys
import time
from typing import Any

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.evaluation import evaluate
from ltl_instruct.core.language.neural.features import CONVENTIONS
from ltl_instruct.core.language.neural.public import SET_OPTIONS, SETS, datasets_root, read_split


def set_options(name: str, backend: str) -> dict[str, Any]:
    """A set's conventions (``public.SET_OPTIONS``) as options of ``backend``: the model is told them too."""
    given = SET_OPTIONS.get(name, {})
    if backend in ('offline', 'combined'):
        return dict(given)
    if backend == 'neural':   # the conventions the model is given as inputs (the rules have more)
        inputs = {name for name, _, _ in CONVENTIONS}
        opts: dict[str, Any] = {k: v for k, v in given.items() if k in inputs}
        if given.get('numbers') == 'digits':
            opts['digits'] = True
        return opts
    return {}


def run_set(name: str, backend: str, limit: int = 0, options: dict[str, Any] | None = None) -> dict[str, Any]:
    """Score ``backend`` on the test split of ``name``; a JSON-ready dict of figures."""
    ds = read_split(name, 'test')
    examples = ds.examples
    if limit and limit < len(examples):
        examples = random.Random(0).sample(examples, limit)
    opts = set_options(name, backend)
    opts.update(options or {})
    translator = make_translator(backend, landmarks=ds.landmarks, **opts)
    # speed: one pass of translation alone over the distinct instructions (evaluate caches repeats)
    per_ms = []
    for text in dict.fromkeys(ex.instruction for ex in examples):
        t = time.perf_counter()
        try:
            translator.translate(text)
        except LtlInstructError:
            pass
        per_ms.append(1000 * (time.perf_counter() - t))
    s = evaluate(translator, examples)
    summ = s.summary()
    return {'set': name, 'n': summ['examples'], 'equivalence': summ['equivalence_accuracy'],
            'temporal_alignment': summ['temporal_alignment'], 'referent_wer': summ['referent_wer'],
            'wrong_unflagged': summ['wrong_unflagged_share'], 'refusals': summ['translation_errors'],
            'median_ms': round(statistics.median(per_ms), 3) if per_ms else None,
            'options': opts}


def main(argv: list[str]) -> int:
    """Print the figures per set; 0 on success, 1 if no data set was found."""
    ap = argparse.ArgumentParser(prog='bench.translation_public', description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--backend', default='offline')
    ap.add_argument('--sets', default=','.join(SETS))
    ap.add_argument('--limit', type=int, default=0, help='random sample of each test split (0: all)')
    ap.add_argument('--json', action='store_true', help='one JSON object per set')
    ap.add_argument('--model-path', default=None,
                    help='neural/combined: translator bundle (default: shipped)')
    args = ap.parse_args(argv)
    if datasets_root() is None:
        print('public data sets not found (../shared/datasets or $LTL_INSTRUCT_DATASETS)', file=sys.stderr)
        return 1
    ran = 0
    for name in [n.strip() for n in args.sets.split(',') if n.strip()]:
        try:
            r = run_set(name, args.backend, args.limit,
                        {'model_path': args.model_path} if args.model_path else None)
        except LtlInstructError as e:
            print(f'{name:14s} skipped: {e.message}', file=sys.stderr)
            continue
        ran += 1
        if args.json:
            print(json.dumps(r), flush=True)
            continue
        print(f'{name:14s} n={r["n"]:5d}  equivalence={r["equivalence"]:.3f}  '
              f'temporal_alignment={r["temporal_alignment"]:.3f}  referent_wer={r["referent_wer"]}  '
              f'wrong_unflagged={r["wrong_unflagged"]:.3f}  refusals={r["refusals"]}  '
              f'median_ms={r["median_ms"]}', flush=True)
    return 0 if ran else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

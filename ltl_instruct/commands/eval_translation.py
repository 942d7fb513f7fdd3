"""``ltl-instruct eval-translation --data FILE --backend B [--json]``: score a translator.

Reports the metrics of the LIMP paper's tables (referent, avoidance and spatial
WER; temporal alignment) and plain equivalence accuracy, all checked on automata.
The data sets of ``../shared/datasets`` are read by
:mod:`ltl_instruct.core.language.datasets` (their propositions become ``near[...]``).
"""
from __future__ import annotations

import argparse
import json
import random

from ltl_instruct.commands.translate import _options
from ltl_instruct.commands.translate import warn_without_model
from ltl_instruct.core.language import BACKENDS, make_translator
from ltl_instruct.core.language.datasets import read_dataset
from ltl_instruct.core.language.evaluation import evaluate

HELP = 'score a translator on a dataset (WERs, temporal alignment)'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument('--data', required=True,
                        help='dev.jsonl, an efficient-eng-2-ltl .jsonl or lifted.csv')
    parser.add_argument('--kind', choices=('dev', 'efficient-eng', 'lifted'),
                        help='data set kind (default: guess)')
    parser.add_argument('--backend', default='combined', choices=BACKENDS)
    parser.add_argument('--json', action='store_true', help='print one JSON object')
    parser.add_argument('--limit', type=int, default=0, help='score a random sample of this many (0: all)')
    parser.add_argument('--seed', type=int, default=0, help='seed of the sample')
    parser.add_argument('--failures', type=int, default=0, help='list this many non-equivalent examples')
    parser.add_argument('--model-path', help='learned backend: trained parser bundle')
    parser.add_argument('--base-url', help='llm backend: endpoint')
    parser.add_argument('--model', help='llm backend: model name')
    parser.add_argument('--examples', help='llm backend: example pool')
    parser.add_argument('--timeout', type=float, default=30.0, help='llm backend: per-request timeout [s]')
    parser.add_argument('--avoid-scope', choices=('global', 'goal'), default=None,
                        help='offline: avoidance convention (default: goal for drone-planning, else global)')
    parser.add_argument('--once-scope', choices=('run', 'next'), default=None,
                        help='offline: "only once" convention (default: next for lifted.csv, else run)')
    parser.add_argument('--numbers', choices=('words', 'digits'), default=None,
                        help='offline: numbers in names (default: digits for drone-planning, else words)')
    parser.add_argument('--after-scope', choices=('goal', 'conditional'), default=None,
                        help='offline: "after X, avoid Y" convention (default: conditional for lifted.csv, '
                             'else goal)')
    parser.add_argument('--onway-scope', choices=('goal', 'run'), default=None,
                        help='offline: "go to X without going through Y" convention (default: run for '
                             'clean-up, else goal)')


def run(args: argparse.Namespace) -> int:
    """Print the scores."""
    ds = read_dataset(args.data, args.kind)
    if args.avoid_scope is None:
        args.avoid_scope = 'goal' if 'drone-planning' in ds.name else 'global'
    if args.once_scope is None:
        args.once_scope = 'next' if 'lifted' in ds.name else 'run'
    if args.after_scope is None:
        args.after_scope = 'conditional' if 'lifted' in ds.name else 'goal'
    if args.numbers is None:
        args.numbers = 'digits' if 'drone-planning' in ds.name else 'words'
    if args.onway_scope is None:
        args.onway_scope = 'run' if 'clean' in ds.name else 'goal'
    options = _options(args)
    if args.backend in ('offline', 'combined', 'neural') and ds.landmarks:
        options['landmarks'] = ds.landmarks   # lifted propositions are names given in advance
    translator = make_translator(args.backend, **options)
    warn_without_model(translator)
    examples = ds.examples
    if args.limit and args.limit < len(examples):
        examples = random.Random(args.seed).sample(examples, args.limit)
    scores = evaluate(translator, examples)
    summary = {'data': args.data, 'backend': args.backend, 'skipped_lines': len(ds.skipped),
               **scores.summary()}
    if args.backend in ('offline', 'combined'):
        summary['avoid_scope'] = args.avoid_scope
        summary['once_scope'] = args.once_scope
        summary['after_scope'] = args.after_scope
        summary['numbers'] = args.numbers
        summary['onway_scope'] = args.onway_scope
    failures = [r.to_dict() for r in scores.results if not r.equivalent][:args.failures]
    if args.json:
        print(json.dumps({**summary, 'failures': failures}, indent=2))
        return 0
    for key, value in summary.items():
        print(f'{key:26s} {value}')
    for f in failures:
        print(f"\n{f['source']}: {f['instruction']}\n  gold:      {f['gold']}\n"
              f"  predicted: {f['predicted'] or 'ERROR ' + str(f['error'])}")
    return 0

"""Choose the combined translator's thresholds on data no choice has seen: VALIDATION splits and the dev set.

Run: ``.venv/bin/python -m bench.translator_policy [--sets drone,cleanup,...] [--limit N]
[--model-path DIR] [--json]``.

The rules and the learned model read each instruction once (``CombinedTranslator.read``); every
policy of the grid (``--override`` and ``--takeover`` values, see ``combined.Policy``) is then
replayed on those readings and scored with the same scorer as ``eval-translation``
(``evaluation.evaluate``). Sets: the validation split of each public set (``neural.public``:
carved out of the train split, never trained on; the test splits are never read here) and our
``spatial-temporal-dev`` set (written for this project, the conventions the robot's users
follow; ``dev`` in ``--sets``). Prints, per policy, temporal alignment, the wrong-and-unflagged
share and the flagged share (refused or flagged: how often the person is asked to check) on each
set, and the mean alignment over the sets.
"""
from __future__ import annotations

import argparse
import json
import random
import sys
from pathlib import Path
from typing import Any, Optional, Sequence

from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.language.combined import CombinedTranslator, Policy, Readings
from ltl_instruct.core.language.datasets import Example, read_dev
from ltl_instruct.core.language.evaluation import EquivalenceChecker, evaluate
from ltl_instruct.core.language.neural.public import SETS, datasets_root, read_split

from bench.translation_public import set_options

OVERRIDES = (0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.99, 1.01)
TAKEOVERS = (0.3, 0.5, 0.7)


class _Replay:
    """A translator that answers from readings made once, deciding with one policy."""

    name = 'combined'

    def __init__(self, combined: CombinedTranslator, readings: dict[str, Readings], policy: Policy) -> None:
        self.combined, self.readings, self.policy = combined, readings, policy

    def translate(self, instruction: str) -> Translation:
        return self.combined.decide(self.readings[instruction], self.policy)


def _examples(name: str, limit: int) -> tuple[list[Example], tuple[str, ...]]:
    if name == 'dev':
        ds = read_dev(datasets_root() / 'spatial-temporal-dev' / 'dev.jsonl')   # type: ignore[operator]
        return list(ds.examples), ()
    ds = read_split(name, 'valid')
    examples = list(ds.examples)
    if limit and limit < len(examples):
        examples = random.Random(0).sample(examples, limit)
    return examples, tuple(ds.landmarks)


def score_set(name: str, limit: int, model_path: Optional[str],
              policies: Sequence[Policy]) -> list[dict[str, Any]]:
    """Read one set's instructions once; score every policy on them."""
    examples, landmarks = _examples(name, limit)
    opts = set_options(name, 'combined')
    combined = CombinedTranslator(model_path, landmarks=landmarks, **opts)
    readings = {text: combined.read(text) for text in dict.fromkeys(ex.instruction for ex in examples)}
    checker = EquivalenceChecker()
    out = []
    for policy in policies:
        replay = _Replay(combined, readings, policy)
        summary = evaluate(replay, examples, checker).summary()   # type: ignore[arg-type]
        out.append({'set': name, 'n': summary['examples'], 'takeover': policy.takeover,
                    'override': policy.override, 'counts': policy.counts, 'off_map': policy.off_map,
                    'read_all_stands': policy.read_all_stands, 'rules_kept': policy.rules_kept,
                    'temporal_alignment': summary['temporal_alignment'],
                    'equivalence': summary['equivalence_accuracy'],
                    'wrong_unflagged': summary['wrong_unflagged_share'], 'flagged': summary['flagged_share']})
    return out


def main(argv: list[str]) -> int:
    """Print the figures of each policy; 0 on success, 1 if no data set was found."""
    ap = argparse.ArgumentParser(prog='bench.translator_policy', description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--sets', default=','.join(('dev',) + SETS))
    ap.add_argument('--limit', type=int, default=0, help='random sample of each validation split (0: all)')
    ap.add_argument('--override', default=','.join(map(str, OVERRIDES)))
    ap.add_argument('--takeover', default=','.join(map(str, TAKEOVERS)))
    ap.add_argument('--counts', default='no', help='no, yes or no,yes: may the model override a count')
    ap.add_argument('--off-map', default='yes', help='no, yes or no,yes: Policy.off_map')
    ap.add_argument('--read-all-stands', default='yes', help='no, yes or no,yes: Policy.read_all_stands')
    ap.add_argument('--rules-kept', default='yes', help='no, yes or no,yes: Policy.rules_kept')
    ap.add_argument('--model-path', default=None, help='translator bundle (default: shipped)')
    ap.add_argument('--json', action='store_true', help='one JSON object per set and policy')
    args = ap.parse_args(argv)
    if datasets_root() is None or not Path(datasets_root()).is_dir():   # type: ignore[arg-type]
        print('public data sets not found (../shared/datasets or $LTL_INSTRUCT_DATASETS)', file=sys.stderr)
        return 1
    policies = [Policy(takeover=float(t), override=float(o), counts=c == 'yes', off_map=m == 'yes',
                       read_all_stands=r == 'yes', rules_kept=k == 'yes')
                for k in args.rules_kept.split(',')
                for r in args.read_all_stands.split(',') for m in args.off_map.split(',')
                for c in args.counts.split(',')
                for t in args.takeover.split(',') for o in args.override.split(',')]
    rows: list[dict[str, Any]] = []
    for name in [n.strip() for n in args.sets.split(',') if n.strip()]:
        got = score_set(name, args.limit, args.model_path, policies)
        rows.extend(got)
        if args.json:
            for r in got:
                print(json.dumps(r), flush=True)
    if not args.json:
        _print_table(rows, policies)
    return 0


def _print_table(rows: list[dict[str, Any]], policies: Sequence[Policy]) -> None:
    names = list(dict.fromkeys(r['set'] for r in rows))
    print('takeover override flags   ' + '  '.join(f'{n[:17]:>17s}' for n in names)
          + '   mean TA   (cells: TA / wrong-unflagged / flagged)')
    for p in policies:
        cells, tas = [], []
        for n in names:
            r = next(r for r in rows
                     if r['set'] == n and r['takeover'] == p.takeover and r['override'] == p.override
                     and r['counts'] == p.counts and r['off_map'] == p.off_map
                     and r['read_all_stands'] == p.read_all_stands and r['rules_kept'] == p.rules_kept)
            cells.append(f'{r["temporal_alignment"]:.3f}/{r["wrong_unflagged"]:.3f}/{r["flagged"]:.2f}')
            tas.append(r['temporal_alignment'])
        flags = ''.join(f if on else '-' for f, on in (('c', p.counts), ('m', p.off_map),
                                                       ('r', p.read_all_stands), ('k', p.rules_kept)))
        print(f'{p.takeover:8.2f} {p.override:8.2f} {flags:>6s}  ' + '  '.join(f'{c:>17s}' for c in cells)
              + f'   {sum(tas) / len(tas):.3f}')


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

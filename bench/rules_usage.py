"""Which rewrite rules of the rules translator people's language uses: the evidence for deleting rules.

Run: ``.venv/bin/python -m bench.rules_usage [--list]``.

The rules translator rewrites wordings before it reads them with two tables: ``idioms.RULES``
and ``paraphrase._REWRITES``. This reads every instruction of the public sets' training and
validation splits (written by people; the test splits are never read) and of our dev set
with the rules, and counts, per entry, the instructions in which it changed the text. An entry
that never fires there was written for language only the helpers' construction sets hold.
Stop 28 deleted those of them that no language test needs once the tests read the default
translator (each entry skipped in turn, in a test run recording which entries fire per test):
the model reads those constructions. ``--list`` prints the entries that never fire.
"""
from __future__ import annotations

import argparse
import collections
import sys
from typing import Any

from ltl_instruct.core.errors import LtlInstructError
from ltl_instruct.core.language import idioms, paraphrase
from ltl_instruct.core.language.datasets import read_dev
from ltl_instruct.core.language.neural.public import SETS, datasets_root, read_split
from ltl_instruct.core.language.offline import OfflineTranslator

from bench.translation_public import set_options


class _Counted:
    """A compiled pattern whose ``sub`` counts, per instruction, whether it changed the text."""

    def __init__(self, table: str, index: int, pattern: Any, seen: set[tuple[str, int]]) -> None:
        self.table, self.index, self.pattern, self.seen = table, index, pattern, seen

    def sub(self, repl: Any, text: str, *args: Any) -> str:
        new = self.pattern.sub(repl, text, *args)
        if new != text:
            self.seen.add((self.table, self.index))
        return new


def _instrument(seen: set[tuple[str, int]]) -> tuple[Any, Any]:
    """Wrap both tables' patterns once (the caller restores them); return the originals."""
    old = idioms._COMPILED, paraphrase._REWRITES
    idioms._COMPILED = tuple((_Counted('idioms', i, p, seen), r, needs)
                             for i, (p, r, needs) in enumerate(idioms._COMPILED))
    paraphrase._REWRITES = tuple((_Counted('paraphrase', i, p, seen), r)
                                 for i, (p, r) in enumerate(paraphrase._REWRITES))
    return old


def _corpora() -> list[tuple[str, list[str], tuple[str, ...], dict[str, Any]]]:
    out = []
    for name in SETS:
        for split in ('train', 'valid'):
            ds = read_split(name, split)
            out.append((f'{name}/{split}', [e.instruction for e in ds.examples], tuple(ds.landmarks),
                        set_options(name, 'offline')))
    dev = read_dev(datasets_root() / 'spatial-temporal-dev' / 'dev.jsonl')   # type: ignore[operator]
    out.append(('dev', [e.instruction for e in dev.examples], (), {}))
    return out


def count_usage() -> tuple[collections.Counter[tuple[str, int]], int]:
    """Return, per (table, entry), the instructions it changed; and how many instructions were read."""
    uses: collections.Counter[tuple[str, int]] = collections.Counter()
    read = 0
    seen: set[tuple[str, int]] = set()
    old = _instrument(seen)
    try:
        for _, texts, landmarks, options in _corpora():
            translator = OfflineTranslator(landmarks=landmarks, **options)
            for text in dict.fromkeys(texts):
                seen.clear()
                try:
                    translator.translate(text)
                except LtlInstructError:
                    pass
                uses.update(seen)
                read += 1
    finally:
        idioms._COMPILED, paraphrase._REWRITES = old
    return uses, read


def main(argv: list[str]) -> int:
    """Print per table: entries, entries used by people's language, and (``--list``) the unused ones."""
    ap = argparse.ArgumentParser(prog='bench.rules_usage', description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--list', action='store_true', help='print the entries that never fire')
    args = ap.parse_args(argv)
    if datasets_root() is None:
        print('public data sets not found (../shared/datasets or $LTL_INSTRUCT_DATASETS)', file=sys.stderr)
        return 1
    uses, read = count_usage()
    tables = {'idioms': [r.example for r in idioms.RULES],
              'paraphrase': [p.pattern[:70] for p, _ in paraphrase._REWRITES]}
    print(f'{read} distinct instructions read (training and validation splits, dev set)')
    for table, entries in tables.items():
        used = [i for i in range(len(entries)) if uses[(table, i)]]
        never = len(entries) - len(used)
        print(f'{table:10s} entries {len(entries):4d}  used by people {len(used):4d}  never {never:4d}')
        if args.list:
            for i, e in enumerate(entries):
                if not uses[(table, i)]:
                    print(f'   {table}[{i}] {e}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

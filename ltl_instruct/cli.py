"""The ``ltl-instruct`` command: one sub-command per capability.

Each sub-command lives in ``ltl_instruct/commands/<name>.py`` and exposes
``HELP`` (one line), ``add_arguments(parser)`` and ``run(args) -> int``. This
module only dispatches; it imports a sub-command's module when it is used, so
``ltl-instruct formula`` does not pay for torch or open3d.

Exit status: 0 success, 1 the task failed (e.g. unsatisfiable), 2 bad input.
"""
from __future__ import annotations

import argparse
import importlib
import sys
from typing import Optional, Sequence

from ltl_instruct.core.errors import LtlInstructError

# name -> (module, one-line help); the help is repeated here so `--help` is instant.
COMMANDS: dict[str, tuple[str, str]] = {
    'formula': ('ltl_instruct.commands.formula',
                'parse a task formula; show its automaton and English subgoals'),
    'translate': ('ltl_instruct.commands.translate',
                  'translate English instructions into task formulas'),
    'eval-translation': ('ltl_instruct.commands.eval_translation',
                         'score a translator on a dataset (WERs, temporal alignment)'),
    'ground': ('ltl_instruct.commands.ground',
               'resolve a formula\'s descriptors in a scene (referent semantic map)'),
    'plan': ('ltl_instruct.commands.plan', 'plan a verified path for a formula in a scene'),
    'parser': ('ltl_instruct.commands.parser',
               'train or evaluate a semantic parser learned from trajectories'),
    'bringup': ('ltl_instruct.commands.bringup', 'start every node as its own process'),
    'demo': ('ltl_instruct.commands.demo',
             'run the whole system on a built-in scene and instruction, end to end'),
}


def build_parser() -> argparse.ArgumentParser:
    """Top-level argument parser with every sub-command's arguments."""
    parser = argparse.ArgumentParser(
        prog='ltl-instruct',
        description='Plain-English robot instructions with ordering and avoidance '
                    'constraints, turned into verified paths.')
    sub = parser.add_subparsers(dest='command', metavar='COMMAND')
    for name, (module_name, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        p.set_defaults(_module=module_name)
        if name in _requested(sys.argv[1:]):
            _load(module_name).add_arguments(p)
    return parser


def _requested(argv: Sequence[str]) -> set[str]:
    return {a for a in argv if a in COMMANDS}


def _load(module_name: str):  # noqa: ANN202 - a module object
    return importlib.import_module(module_name)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of the ``ltl-instruct`` console script."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = argparse.ArgumentParser(prog='ltl-instruct', add_help=False)
    full = build_parser()
    if not argv or argv[0] in ('-h', '--help') or argv[0] not in COMMANDS:
        full.print_help()
        return 0 if (not argv or argv[0] in ('-h', '--help')) else 2
    module = _load(COMMANDS[argv[0]][0])
    parser = argparse.ArgumentParser(prog=f'ltl-instruct {argv[0]}',
                                     description=COMMANDS[argv[0]][1])
    module.add_arguments(parser)
    args = parser.parse_args(argv[1:])
    try:
        return int(module.run(args) or 0)
    except LtlInstructError as e:
        print(f'error [{e.code.value}]: {e.message}', file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130


if __name__ == '__main__':
    sys.exit(main())

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
    'translator': ('ltl_instruct.commands.translator',
                   'train the learned translator (tagger and decoder) from generated and public data'),
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


def _overview() -> argparse.ArgumentParser:
    """Top-level parser listing the sub-commands (their own arguments load on use)."""
    parser = argparse.ArgumentParser(
        prog='ltl-instruct',
        description='Plain-English robot instructions with ordering and avoidance '
                    'constraints, turned into verified paths.',
        epilog='Run "ltl-instruct COMMAND --help" for the arguments of a command.')
    sub = parser.add_subparsers(dest='command', metavar='COMMAND')
    for name, (_, help_text) in COMMANDS.items():
        sub.add_parser(name, help=help_text)
    return parser


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of the ``ltl-instruct`` console script."""
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] not in COMMANDS:
        _overview().print_help()
        if argv and argv[0] not in ('-h', '--help'):
            print(f'\nerror: unknown command {argv[0]!r}', file=sys.stderr)
            return 2
        return 0
    module_name, help_text = COMMANDS[argv[0]]
    module = importlib.import_module(module_name)
    parser = argparse.ArgumentParser(prog=f'ltl-instruct {argv[0]}', description=help_text)
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

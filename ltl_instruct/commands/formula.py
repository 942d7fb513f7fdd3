"""``ltl-instruct formula "<formula>" [--json]``: parse, compile and explain a task formula."""
from __future__ import annotations

import argparse
import json

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.automaton.english import describe_task
from ltl_instruct.core.spec import atoms_of, avoided_referents_of, parse_formula, referents_of

HELP = 'parse a task formula; show its automaton and English subgoals'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument('formula', help='task formula in the syntax of spec/formula.md')
    parser.add_argument('--json', action='store_true', help='print one JSON object')
    parser.add_argument('--max-states', type=int, default=2000,
                        help='refuse automata larger than this (default 2000)')


def report(text: str, max_states: int = 2000) -> dict:
    """Everything the command prints, as a JSON-ready dict."""
    f = parse_formula(text)
    aut = compile_automaton(f, max_states=max_states)
    desc = describe_task(aut)
    return {
        'formula': str(f),
        'atoms': [a.key for a in atoms_of(f)],
        'referents': [str(d) for d in referents_of(f)],
        'avoid': [str(d) for d in avoided_referents_of(f)],
        'satisfiable': aut.is_satisfiable,
        'automaton': aut.to_dict(),
        'english': desc.to_dict(),
    }


def run(args: argparse.Namespace) -> int:
    """Print the report; exit 0 when satisfiable, 1 when not (2 on bad input, via the CLI)."""
    r = report(args.formula, args.max_states)
    if args.json:
        print(json.dumps(r, indent=2))
        return 0 if r['satisfiable'] else 1
    aut = r['automaton']
    print(f"formula:     {r['formula']}")
    print(f"atoms:       {', '.join(r['atoms'])}")
    print(f"referents:   {', '.join(r['referents'])}")
    if r['avoid']:
        print(f"avoid:       {', '.join(r['avoid'])}")
    print(f"satisfiable: {'yes' if r['satisfiable'] else 'NO'}")
    print(f"automaton:   {len(aut['states'])} states, initial {aut['initial']}, "
          f"accepting {aut['accepting']}, sink {aut['sink']}")
    for s in aut['states']:
        tag = ' (accepting)' if s['accepting'] else ' (sink)' if s['sink'] else ''
        print(f"  state {s['id']}{tag}: {s['formula']}")
    for e in aut['edges']:
        print(f"  {e['src']} -> {e['dst']}: {e['guard']['text']}")
    print()
    eng = r['english']
    for line in eng['subgoals'] + eng['throughout'] + eng['notes']:
        print(line)
    return 0 if r['satisfiable'] else 1

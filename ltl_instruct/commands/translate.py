"""``ltl-instruct translate``: English instructions to task formulas.

- ``ltl-instruct translate "<instruction>" [--backend B] [--json]``
- ``ltl-instruct translate --input FILE.jsonl --output OUT.jsonl [--backend B]``: each input
  line has an ``instruction``; each output line repeats it and adds ``formula``, ``referents``,
  ``avoid`` and ``subgoals``, or ``error``.
- ``ltl-instruct translate --interactive``: the verification dialog (answer yes, correct in
  words, or type ``formula: ...``).
"""
from __future__ import annotations

import argparse
import json
import sys
from typing import Any, Callable, Optional

from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError
from ltl_instruct.core.language import BACKENDS, Translation, make_translator, verification_for
from ltl_instruct.core.language.datasets import iter_instructions
from ltl_instruct.core.language.verification import (
    Reply, alternatives_of, best_reading_of, classify_reply, warnings_of,
)
from ltl_instruct.core.spec import parse_formula

HELP = 'translate English instructions into task formulas'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument('instruction', nargs='?', help='the instruction (omit with --input or --interactive)')
    parser.add_argument('--backend', default='combined', choices=BACKENDS,
                        help='translator backend (default combined: rules and learned model)')
    parser.add_argument('--json', action='store_true', help='print one JSON object')
    parser.add_argument('--input', help='JSON lines file, one {"instruction": ...} (or {"text": ...}) '
                                        'per line; other fields (an id) are copied to the output')
    parser.add_argument('--output', help='JSON lines file to write (default: standard output)')
    parser.add_argument('--interactive', action='store_true', help='verification dialog on the terminal')
    parser.add_argument('--model-path', help='learned backend: trained parser bundle; neural and combined: '
                                             'translator bundle (default: the one shipped)')
    parser.add_argument('--base-url', help='llm backend: OpenAI-compatible endpoint ending in /v1')
    parser.add_argument('--model', help='llm backend: model name')
    parser.add_argument('--examples', help='llm backend: example pool (JSON lines)')
    parser.add_argument('--timeout', type=float, default=30.0, help='llm backend: per-request timeout [s]')
    parser.add_argument('--avoid-scope', choices=('global', 'goal'), default='global',
                        help='offline backend: "go to X and avoid Y" as G !Y (global) or at X only (goal)')
    parser.add_argument('--once-scope', choices=('run', 'next'), default='run',
                        help='offline backend: "visit X only once, then Y" for the whole run (run) or until '
                             'Y (next, lang2ltl\'s strictly ordered visits)')
    parser.add_argument('--numbers', choices=('words', 'digits'), default='words',
                        help='offline backend: a number in a name as said ("aisle seven": aisle_seven) or as '
                             'digits ("landmark one": landmark_1, drone-planning)')
    parser.add_argument('--after-scope', choices=('goal', 'conditional'), default='goal',
                        help='offline backend: "after going to X, avoid Y" with X a goal (goal) or as a rule '
                             'if X is ever reached (conditional, lang2ltl)')
    parser.add_argument('--onway-scope', choices=('goal', 'run'), default='goal',
                        help='offline backend: "go to X without going through Y" avoids Y until X (goal) or '
                             'for the whole run (run, clean-up)')


def _options(args: argparse.Namespace) -> dict[str, Any]:
    rules = {'avoid_scope': args.avoid_scope, 'once_scope': getattr(args, 'once_scope', 'run'),
             'after_scope': getattr(args, 'after_scope', None) or 'goal',
             'numbers': getattr(args, 'numbers', None) or 'words',
             'onway_scope': getattr(args, 'onway_scope', None) or 'goal'}
    if args.backend == 'offline':
        return rules
    if args.backend == 'combined':
        return {**rules, 'model_path': args.model_path}
    if args.backend in ('learned', 'neural'):
        return {'model_path': args.model_path}
    opts: dict[str, Any] = {'timeout_s': args.timeout}
    for key, value in (('base_url', args.base_url), ('model', args.model), ('examples_path', args.examples)):
        if value:
            opts[key] = value
    return opts


def record(t: Translation) -> dict[str, Any]:
    """Return the JSON record of a translation: formula, referents, avoid, subgoals."""
    # descriptors are written without spaces, as in the data sets' referent lists
    out: dict[str, Any] = {'instruction': t.instruction, 'formula': str(t.formula),
                           'referents': [r.replace(' ', '') for r in t.referents],
                           'avoid': [r.replace(' ', '') for r in t.avoid], 'backend': t.backend}
    try:
        v = verification_for(t)
        out['subgoals'] = list(v.subgoals)
    except LtlInstructError as e:
        out['subgoals'] = []
        out['subgoals_error'] = e.to_dict()
    if t.notes:
        out['notes'] = list(t.notes)
    warnings = warnings_of(t)
    if warnings:
        out['warnings'] = list(warnings)   # parts it could not read (guessed at or left out)
    # the combined and learned backends: whether a person must check this reading, and the others
    for key in ('flagged', 'alternatives', 'confidence'):
        if t.extra.get(key) is not None:
            out[key] = t.extra[key]
    return out


def warn_without_model(translator: object) -> None:
    """Say on stderr when the combined backend runs without its learned model (the rules alone read)."""
    error = getattr(translator, 'model_error', '')
    if error:
        print(f'warning: the learned translator is not loaded, the rules alone read: {error}',
              file=sys.stderr)


def run(args: argparse.Namespace) -> int:
    """Translate one instruction, a file of them, or run the dialog."""
    translator = make_translator(args.backend, **_options(args))
    warn_without_model(translator)
    if args.interactive:
        return interactive(translator, input, print)
    if args.input:
        return _batch(translator, args.input, args.output)
    if not args.instruction:
        raise InvalidInputError('give an instruction, --input FILE, or --interactive')
    try:
        t = translator.translate(args.instruction)
    except LtlInstructError as e:
        guess = best_reading_of(e, args.instruction, translator.name)
        if guess is None:
            raise
        if args.json:
            partial = record(guess)
            print(json.dumps({'instruction': args.instruction, 'error': e.to_dict(),
                              'referents': partial['referents'], 'avoid': partial['avoid']}, indent=2))
        else:
            print(f'error [{e.code.value}]: {e.message}')
            print(f'best reading without that part (not a plan): {guess.formula}')
        return 1
    r = record(t)
    if args.json:
        print(json.dumps(r, indent=2))
        return 0
    print(f"formula:   {r['formula']}")
    print(f"referents: {', '.join(r['referents'])}")
    if r['avoid']:
        print(f"avoid:     {', '.join(r['avoid'])}")
    for line in r['subgoals']:
        print(f'  {line}')
    for warning in r.get('warnings', []):
        print(f'WARNING: {warning}')
    for note in r.get('notes', []):
        if note not in r.get('warnings', []):
            print(f'note: {note}')
    return 0


def _batch(translator: Any, path: str, out_path: Optional[str]) -> int:
    try:
        lines = list(iter_instructions(path))
    except OSError as e:
        raise InvalidInputError(f'cannot read {path}: {e}') from e
    try:
        out = open(out_path, 'w', encoding='utf-8') if out_path else sys.stdout
    except OSError as e:
        raise InvalidInputError(f'cannot write {out_path}: {e.strerror or e}') from None
    failures = 0
    try:
        try:
            for _, obj in lines:
                if 'error' in obj:
                    rec: dict[str, Any] = {'instruction': None, **obj}
                    failures += 1
                else:
                    try:
                        rec = record(translator.translate(obj['instruction']))
                    except LtlInstructError as e:
                        rec = {'instruction': obj['instruction'], 'error': e.to_dict()}
                        guess = best_reading_of(e, obj['instruction'])
                        if guess is not None:   # what the rest of the instruction names, formula withheld
                            partial = record(guess)
                            rec['referents'], rec['avoid'] = partial['referents'], partial['avoid']
                        failures += 1
                    for key, value in obj.items():
                        rec.setdefault(key, value)
                out.write(json.dumps(rec) + '\n')
        finally:
            if out_path:
                out.close()
    except OSError as e:   # a full disk, /dev/full: the write fails with a message, not a traceback
        raise InvalidInputError(f'cannot write {out_path or "standard output"}: {e.strerror or e}') from None
    return 1 if failures else 0


def interactive(translator: Any, ask: Callable[[str], str], say: Callable[[str], None]) -> int:
    """Run the verification dialog: translate, show, accept a yes, a correction, or a formula.

    With the LLM backend a correction is sent back with the previous answer; offline,
    the instruction and the correction are translated again together.
    """
    try:
        instruction = ask('instruction> ').strip()
    except EOFError:
        return 2
    correction_rounds = 0
    t: Optional[Translation] = None
    pending_correction = ''
    person_formula = False   # the person typed or chose the formula: nothing to translate again
    while correction_rounds < 10:
        try:
            if person_formula:
                pass
            elif t is not None and pending_correction and translator.name == 'llm':
                t = translator.translate(instruction, correction=pending_correction, previous=t)
            elif pending_correction:
                t = translator.translate(f'{instruction.rstrip(" .")}. {pending_correction}')
            else:
                t = translator.translate(instruction)
            say(verification_for(t).text())
        except LtlInstructError as e:
            say(f'error [{e.code.value}]: {e.message}')
            guess = best_reading_of(e, instruction, translator.name)
            if guess is not None:
                # the rest of the instruction, read: the person may take it, correct it, or type a formula
                t = guess
                say('Best reading without that part (nothing moves unless you answer yes):')
                say(verification_for(t).text())
            elif t is None:
                say('Rephrase the instruction, or type a formula (prefix "formula:").')
        try:
            reply = classify_reply(ask('reply> '))
        except EOFError:
            return 2
        except LtlInstructError as e:
            say(f'error [{e.code.value}]: {e.message}')
            continue
        if reply.kind == 'yes' and t is not None:
            say(json.dumps(record(t)))
            return 0
        if reply.kind == 'no':
            say('cancelled')
            return 1
        if reply.kind == 'alternative' and t is not None:
            alternatives = alternatives_of(t)
            if not 1 <= reply.index <= len(alternatives):
                say(f'there is no alternative {reply.index}')
                continue
            chosen = alternatives[reply.index - 1]
            reply = Reply('formula', chosen, parse_formula(chosen))
        if reply.kind == 'formula' and reply.formula is not None:
            t = Translation(instruction, reply.formula, 'person')
            pending_correction = ''
            person_formula = True   # shown at the top of the loop, not translated again
            correction_rounds += 1
            continue
        person_formula = False
        pending_correction = reply.text
        correction_rounds += 1
    raise LtlInstructError('too many corrections; start again', ErrorCode.VERIFICATION_FAILED)

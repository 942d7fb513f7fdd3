"""Data set readers, automaton-checked metrics, the translate / eval-translation commands, the dialog."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from ltl_instruct.cli import main
from ltl_instruct.commands.translate import interactive
from ltl_instruct.core.automaton import equivalent
from ltl_instruct.core.errors import FormulaSyntaxError, InvalidInputError, LtlInstructError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.datasets import Example, parse_prefix_ltl, read_dataset
from ltl_instruct.core.language.evaluation import edit_distance, evaluate
from ltl_instruct.core.language.verification import classify_reply, verification_for
from ltl_instruct.core.spec import parse_formula

SHARED = Path(__file__).resolve().parents[1].parent / 'shared' / 'datasets'


def test_prefix_ltl_maps_operators_and_letters() -> None:
    f = parse_prefix_ltl('& U ! b a F b')
    assert equivalent(f, parse_formula('(!near[b] U near[a]) & F near[b]'))
    assert equivalent(parse_prefix_ltl('M a | ! a G a'),
                      parse_formula('(!near[a] | G near[a]) U (near[a] & (!near[a] | G near[a]))'))
    assert equivalent(parse_prefix_ltl('G i a X b'), parse_formula('G (near[a] -> X near[b])'))
    assert equivalent(parse_prefix_ltl('G e a X b'), parse_formula('G (near[a] <-> X near[b])'))
    for bad in ('', '& a', 'F a b', 'F Q'):
        with pytest.raises(FormulaSyntaxError):
            parse_prefix_ltl(bad)


def test_readers_on_small_files(tmp_path: Path) -> None:
    lifted = tmp_path / 'lifted.csv'
    lifted.write_text('pattern_type,props,utterance,ltl_formula\nvisit,[\'a\'],visit a,F a\n'
                      'visit,[\'a\'],broken,F ( a\n')
    ds = read_dataset(lifted)
    assert [e.instruction for e in ds.examples] == ['visit a'] and len(ds.skipped) == 1
    drone = tmp_path / 'drone.jsonl'
    drone.write_text(json.dumps({'natural': 'go to the red room', 'raw_ltl': 'F ( red_room )'}) + '\n{oops\n')
    ds = read_dataset(drone)
    assert str(ds.examples[0].formula) == 'F near[red_room]' and len(ds.skipped) == 1
    other = tmp_path / 'other.txt'
    other.write_text('hello\n')
    with pytest.raises(InvalidInputError):
        read_dataset(other)
    with pytest.raises(InvalidInputError):
        read_dataset(tmp_path / 'missing.jsonl')


def test_edit_distance() -> None:
    assert edit_distance(['a', 'b', 'c'], ['a', 'c']) == 1
    assert edit_distance([], ['x']) == 1
    assert edit_distance(['a'], ['b']) == 1


def test_metrics_are_checked_on_automata_not_strings() -> None:
    ex = [Example('go to the sofa then the door', parse_formula('F (near[sofa] & F near[door])'), 't:1'),
          Example('go to the sofa and the door', parse_formula('F near[sofa] & F near[door]'), 't:2'),
          Example('go to the red sofa', parse_formula('F near[sofa]'), 't:3'),
          Example('go to the flibber quantumly', parse_formula('F near[x]'), 't:4')]
    s = evaluate(make_translator(), ex)
    summary = s.summary()
    assert summary['examples'] == 4 and summary['translation_errors'] == 1
    assert [r.equivalent for r in s.results] == [True, True, False, False]
    assert [r.aligned for r in s.results] == [True, True, True, False]   # red_sofa aligned to sofa
    assert summary['equivalence_accuracy'] == 0.5 and summary['temporal_alignment'] == 0.75
    assert summary['referent_wer'] == pytest.approx(2 / 6, abs=1e-3)


REFUSED = 'go to the kitchen and stay there until the trash bag is in the dumpster, then avoid the hall'


def test_a_refusal_carries_its_best_reading_and_the_metrics_score_its_referents() -> None:
    with pytest.raises(LtlInstructError) as err:
        make_translator().translate(REFUSED)   # still refused: the "until" is not dropped silently
    details = err.value.details
    assert 'stay there until' in details['part'] and 'stay there until' in details['left_out'][0]
    assert equivalent(parse_formula(details['best_reading']),
                      parse_formula('F (near[kitchen] & G !near[hall])'))
    assert details['referents'] == ['kitchen', 'hall'] and details['avoid'] == ['hall']
    gold = parse_formula('F (near[kitchen] & (near[kitchen] U release[trash_bag, dumpster])) & G !near[hall]')
    s = evaluate(make_translator(), [Example(REFUSED, gold, 't:1')]).summary()
    assert s['translation_errors'] == 1 and s['refusals_with_best_reading'] == 1
    assert s['flagged_share'] == 1.0   # a refusal asks the person
    assert s['temporal_alignment'] == 0.0   # a refusal is never aligned
    # gold referents: kitchen, trash_bag, dumpster, hall; the best reading has kitchen and hall
    assert s['referent_wer'] == pytest.approx(2 / 4) and s['referent_wer_strict'] == 1.0


def test_the_dialog_offers_a_refusals_best_reading() -> None:
    replies = iter([REFUSED, 'yes'])
    said: list[str] = []
    assert interactive(make_translator(), lambda _: next(replies), said.append) == 0
    assert said[0].startswith('error [TRANSLATION_ERROR]') and 'Best reading' in said[1]
    assert 'Warning: could not read "stay there until' in said[2]
    final = json.loads(said[-1])
    assert final['referents'] == ['kitchen', 'hall'] and final['warnings']
    replies = iter(['qwzx vvv', 'no'])   # nothing to read: no reading offered
    said = []
    assert interactive(make_translator(), lambda _: next(replies), said.append) == 1
    assert not any('Best reading' in line for line in said)


def test_translate_command_single_and_batch(tmp_path: Path, capsys: Any) -> None:
    assert main(['translate', 'go to the sofa, then the door', '--json']) == 0
    out = json.loads(capsys.readouterr().out)
    assert out['formula'] == 'F (near[sofa] & F near[door])' and out['referents'] == ['sofa', 'door']
    assert out['subgoals'][0].startswith('Subgoal 1')
    src = tmp_path / 'in.jsonl'
    src.write_text('{"instruction": "never go near the stove", "id": 7}\n{"instruction": "qwzx vvv"}\n'
                   'not json\n' + json.dumps({'instruction': REFUSED}) + '\n')
    dst = tmp_path / 'out.jsonl'
    assert main(['translate', '--input', str(src), '--output', str(dst)]) == 1
    rows = [json.loads(x) for x in dst.read_text().splitlines()]
    assert rows[0]['formula'] == 'G !near[stove]' and rows[0]['avoid'] == ['stove'] and rows[0]['id'] == 7
    assert rows[1]['error']['code'] == 'TRANSLATION_ERROR' and rows[1]['instruction'] == 'qwzx vvv'
    assert rows[2]['error']['code'] == 'INVALID_INPUT'
    assert 'referents' not in rows[1]   # nothing read
    assert rows[3]['error']['code'] == 'TRANSLATION_ERROR' and 'formula' not in rows[3]
    assert rows[3]['referents'] == ['kitchen', 'hall'] and rows[3]['avoid'] == ['hall']
    assert main(['translate', REFUSED]) == 1
    assert 'best reading without that part (not a plan): F' in capsys.readouterr().out
    assert main(['translate']) == 2


def test_batch_reads_text_keys_and_keeps_ids_of_bad_lines(tmp_path: Path) -> None:
    src = tmp_path / 'in.jsonl'
    src.write_text('{"id": 1, "text": "go to the lamp"}\n{"id": 2, "instruction": 5}\n'
                   + '[' * 100000 + '\n')
    dst = tmp_path / 'out.jsonl'
    assert main(['translate', '--backend', 'offline', '--input', str(src), '--output', str(dst)]) == 1
    rows = [json.loads(x) for x in dst.read_text().splitlines()]
    assert rows[0]['formula'] == 'F near[lamp]' and rows[0]['id'] == 1
    assert rows[1]['id'] == 2 and rows[1]['error']['code'] == 'INVALID_INPUT'
    assert rows[1]['instruction'] is None
    assert rows[2]['error']['code'] == 'INVALID_INPUT'   # nested too deep: one error line, no traceback


def test_eval_command_on_a_small_file(tmp_path: Path, capsys: Any) -> None:
    data = tmp_path / 'dev.jsonl'
    data.write_text(json.dumps({'instruction': 'go to the lamp', 'formula': 'F near[lamp]'}) + '\n')
    assert main(['eval-translation', '--data', str(data), '--json']) == 0
    out = json.loads(capsys.readouterr().out)
    assert out['equivalence_accuracy'] == 1.0 and out['referent_wer'] == 0.0


def test_verification_text_and_replies() -> None:
    t = make_translator().translate('bring the cup to the sink and never go near the cat')
    v = verification_for(t)
    assert 'the cup' in v.referents and v.avoid == ('the cat',)
    assert any('pick up the cup' in line for line in v.subgoals)
    assert 'Is this right?' in v.text()
    assert classify_reply(' Yes ').kind == 'yes'
    assert classify_reply('no').kind == 'no'
    r = classify_reply('formula: F near[sink]')
    assert r.kind == 'formula' and str(r.formula) == 'F near[sink]'
    assert classify_reply('I meant the blue cup').kind == 'correction'
    with pytest.raises(LtlInstructError):
        classify_reply('formula: F ((')


def test_interactive_dialog_offline_correction_then_yes() -> None:
    replies = iter(['go to the fridge', 'sorry, the freezer', 'yes'])
    said: list[str] = []
    assert interactive(make_translator(), lambda _: next(replies), said.append) == 0
    final = json.loads(said[-1])
    assert final['formula'] == 'F near[freezer]'


def test_interactive_dialog_typed_formula_and_cancel() -> None:
    replies = iter(['go to the fridge', 'formula: F near[oven]', 'no'])
    said: list[str] = []
    assert interactive(make_translator(), lambda _: next(replies), said.append) == 1
    assert any('near[oven]' in s for s in said)


def test_interactive_dialog_keeps_a_typed_formula_when_accepted() -> None:
    # the dialog used to translate the instruction again after a typed formula, so "yes" took the fridge
    replies = iter(['go to the fridge', 'formula: F near[oven]', 'yes'])
    said: list[str] = []
    assert interactive(make_translator(), lambda _: next(replies), said.append) == 0
    assert json.loads(said[-1])['formula'] == 'F near[oven]'
    assert sum('Task formula: F near[oven]' in s for s in said) == 1   # shown once


@pytest.mark.skipif(not (SHARED / 'spatial-temporal-dev' / 'dev.jsonl').is_file(), reason='no ../shared')
def test_development_set_scores() -> None:
    ds = read_dataset(SHARED / 'spatial-temporal-dev' / 'dev.jsonl')
    s = evaluate(make_translator(), ds.examples).summary()
    assert s['examples'] == 120
    assert s['temporal_alignment'] >= 0.9 and s['equivalence_accuracy'] >= 0.9
    assert s['referent_wer'] <= 0.1 and s['avoidance_wer'] <= 0.1

"""English for verification: order and avoidance are stated, unambiguously."""
import json
import subprocess
import sys

from ltl_instruct.core.automaton.english import describe_descriptor, describe_task
from ltl_instruct.core.spec import parse_descriptor


def test_descriptor_phrases_cover_every_comparator():
    cases = {
        'sofa::isbehind(pillar)': 'the sofa behind the pillar',
        'lamp::isabove(table)': 'the lamp above the table',
        'box::isbelow(shelf)': 'the box below the shelf',
        'fridge::isleftof(cabinet)': 'the fridge to the left of the cabinet',
        'bin::isrightof(desk)': 'the bin to the right of the desk',
        'chair::isnextto(window)': 'the chair next to the window',
        'whiteboard::isinfrontof(green_plush_toy)': 'the whiteboard in front of the green plush toy',
        'chair::isbetween(sofa, bag)': 'the chair between the sofa and the bag',
    }
    for text, english in cases.items():
        assert describe_descriptor(parse_descriptor(text)) == english


def test_nested_argument_is_set_off():
    d = parse_descriptor('chair::isbetween(green_laptop, yellow_box::isbelow(play_toy))')
    assert describe_descriptor(d) == ('the chair between the green laptop and the yellow box '
                                      '(the one below the play toy)')


def test_sequence_with_global_avoidance():
    d = describe_task('F (near[sofa::isbehind(pillar)] & F near[computer]) & G !near[door]')
    assert d.subgoals == ('Subgoal 1: go to the sofa behind the pillar.',
                          'Subgoal 2: go to the computer.')
    assert d.throughout == ('Throughout the task: never go near the door.',)
    assert d.referents == ('the sofa behind the pillar', 'the computer', 'the door')


def test_ordering_constraint_says_not_yet():
    d = describe_task('F near[bookshelf] & (!near[bookshelf] U near[brown_desk])')
    assert d.subgoals[0] == 'Subgoal 1: go to the brown desk, and do not go near the bookshelf yet.'
    assert d.subgoals[1] == 'Subgoal 2: go to the bookshelf.'


def test_pick_and_place_subgoals_in_order():
    d = describe_task('F (near[green_plush_toy] & F (pick[green_plush_toy] & F (near[whiteboard] '
                      '& F release[green_plush_toy, whiteboard])))')
    assert [s.split(': ', 1)[1] for s in d.subgoals] == [
        'go to the green plush toy.', 'pick up the green plush toy.', 'go to the whiteboard.',
        'put the green plush toy down at the whiteboard.']


def test_either_or_and_any_order():
    assert describe_task('F (near[a] | near[b])').subgoals == (
        'Subgoal 1: either go to the a, or go to the b.',)
    d = describe_task('F near[a] & F near[b]')
    assert len(d.subgoals) == 2 and d.notes  # says the order is free


def test_unsatisfiable_is_said_plainly():
    d = describe_task('F near[a] & G !near[a]')
    assert not d.satisfiable and not d.subgoals and 'never be completed' in d.notes[0]


def test_formula_command_json_and_exit_codes():
    out = subprocess.run([sys.executable, '-m', 'ltl_instruct', 'formula', '--json',
                          'F near[a] & G !near[b]'], capture_output=True, text=True, check=True)
    r = json.loads(out.stdout)
    assert r['satisfiable'] and r['atoms'] == ['near[a]', 'near[b]']
    assert r['automaton']['initial'] == 0 and r['automaton']['accepting']
    assert all({'src', 'dst', 'guard'} <= set(e) for e in r['automaton']['edges'])
    assert r['english']['subgoals'] == ['Subgoal 1: go to the a.']
    bad = subprocess.run([sys.executable, '-m', 'ltl_instruct', 'formula', 'F near[a'],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and 'column 9' in bad.stderr and '^' in bad.stderr
    unsat = subprocess.run([sys.executable, '-m', 'ltl_instruct', 'formula', 'F a & G !a'],
                           capture_output=True, text=True)
    assert unsat.returncode == 1 and 'satisfiable: NO' in unsat.stdout

"""Execution monitoring: letters from positions, verdicts, blame, and replanning state."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.monitor import ExecutionMonitor, LetterMaker, PlanTrace, Verdict
from ltl_instruct.core.spec import near, parse_formula


def _rmap(**places):
    return ReferentMap({name: Grounding(name, Outcome.RESOLVED, (Instance(name, name, xyz, (0.4, 0.4, 0.4)),))
                        for name, xyz in places.items()})


RMAP = _rmap(sofa=(2.0, 0.0, 0.0), computer=(6.0, 0.0, 0.0), door=(4.0, 3.0, 0.0))


def _monitor(text, rmap=RMAP):
    aut = compile_automaton(parse_formula(text))
    return ExecutionMonitor(aut, LetterMaker(aut.atoms, rmap, near_threshold=1.0, dims=2))


def test_sequence_progresses_then_is_satisfied():
    m = _monitor('F (near[sofa] & F near[computer]) & G !near[door]')
    verdicts = [m.update(p).verdict for p in ([0, 0, 0], [2, 0, 0], [4, 0, 0], [6, 0, 0])]
    assert verdicts == [Verdict.PROGRESSING, Verdict.PROGRESSING, Verdict.PROGRESSING, Verdict.SATISFIED]
    assert m.last is not None and m.last.letter == ('near[computer]',)


def test_wrong_order_is_not_satisfied():
    m = _monitor('F (near[sofa] & F near[computer])')
    assert m.update([6, 0, 0]).verdict is Verdict.PROGRESSING
    assert m.update([2, 0, 0]).verdict is Verdict.PROGRESSING
    assert m.update([6, 0, 0]).verdict is Verdict.SATISFIED


def test_violation_blames_the_atom_that_did_it():
    m = _monitor('F near[computer] & G !near[door]')
    assert m.update([0, 0, 0]).verdict is Verdict.PROGRESSING
    report = m.update([4.0, 2.4, 0.0])
    assert report.verdict is Verdict.VIOLATED and report.blamed_atoms == ('near[door]',)
    assert report.changed
    # the sink absorbs
    assert m.update([6, 0, 0]).verdict is Verdict.VIOLATED


def test_events_are_read_once_and_only_known_ones():
    m = _monitor('F (pick[toy] & F release[toy, basket])', _rmap(toy=(1, 0, 0), basket=(3, 0, 0)))
    pick = parse_formula('pick[toy]')
    release = parse_formula('release[toy, basket]')
    other = parse_formula('pick[cup]')
    assert m.update([1, 0, 0], [other]).verdict is Verdict.PROGRESSING
    assert m.update([1, 0, 0], [pick]).changed
    assert m.update([3, 0, 0], [release]).verdict is Verdict.SATISFIED
    with pytest.raises(InvalidInputError):
        m.letters.letter([0, 0, 0], [pick, release])


def test_nan_positions_are_rejected_and_state_kept():
    m = _monitor('F near[sofa]')
    with pytest.raises(InvalidInputError):
        m.update([np.nan, 0, 0])
    with pytest.raises(InvalidInputError):
        m.update([0, 0])
    assert m.state == m.automaton.initial and m.steps == 0


def test_a_new_referent_map_keeps_the_automaton_state():
    m = _monitor('F (near[sofa] & F near[computer])')
    m.update([2, 0, 0])
    moved = _rmap(sofa=(2.0, 0.0, 0.0), computer=(9.0, 9.0, 0.0))
    m2 = m.with_referent_map(moved)
    assert m2.state == m.state and m2.steps == m.steps
    assert m2.update([6, 0, 0]).verdict is Verdict.PROGRESSING     # the computer is elsewhere now
    assert m2.update([9, 8.5, 0]).verdict is Verdict.SATISFIED


def test_unresolved_descriptors_are_never_near():
    lm = LetterMaker((near('ghost'),), ReferentMap({}), 1.0, 2)
    assert lm.letter([0, 0, 0]) == frozenset()


def test_letter_maker_settings_are_checked():
    with pytest.raises(InvalidInputError):
        LetterMaker((), RMAP, near_threshold=-1.0)
    with pytest.raises(InvalidInputError):
        LetterMaker((), RMAP, dims=4)


@settings(derandomize=True, max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-2, 10), st.floats(-2, 6)), min_size=1, max_size=25))
def test_monitor_agrees_with_the_automaton_on_the_same_trace(xy):
    """The monitor's verdict is exactly the automaton's acceptance of the letters it read."""
    m = _monitor('F (near[sofa] & F near[computer]) & G !near[door]')
    trace = []
    for x, y in xy:
        trace.append(m.letters.letter([x, y, 0.0]))
        report = m.update([x, y, 0.0])
    assert (report.verdict is Verdict.SATISFIED) == m.automaton.accepts(trace)
    assert report.state == m.automaton.run(trace)[-1]


def test_update_along_sees_a_region_between_two_far_apart_poses():
    m = _monitor('F near[computer] & G !near[door]')
    m.update([4.0, 5.0, 0.0])
    # one jump from above the door to below it: the door region lies in between
    report = m.update_along([4.0, 5.0, 0.0], [4.0, 1.0, 0.0])
    assert report.verdict is Verdict.VIOLATED and report.blamed_atoms == ('near[door]',)
    fast = _monitor('F near[sofa]')
    fast.update([0.0, -2.0, 0.0])
    # passing the sofa between two poses still counts
    assert fast.update_along([0.0, -2.0, 0.0], [4.0, 2.0, 0.0]).verdict is Verdict.SATISFIED
    with pytest.raises(InvalidInputError):
        fast.update_along([0, 0, 0], [np.nan, 0, 0])


@pytest.mark.parametrize('far', [1e9, 1e308, -1e308])
def test_a_move_of_absurd_length_is_refused_and_the_monitor_goes_on(far):
    """Odometry at 1e9 m once stalled task_progression: the move was read every 5 cm (1e308: an overflow)."""
    m = _monitor('F near[sofa]')
    m.update([0.0, -2.0, 0.0])
    with pytest.raises(InvalidInputError, match='longer than'):
        m.update_along([0.0, -2.0, 0.0], [far, 0.0, 0.0])
    assert m.update_along([0.0, -2.0, 0.0], [4.0, 2.0, 0.0]).verdict is Verdict.SATISFIED


# a plan that turns at the sofa: (0, -3) -> (2, -1.15) -> (4, -3), densified every 0.1 m
_LEGS = [np.linspace([0.0, -3.0, 0.0], [2.0, -1.15, 0.0], 28),
         np.linspace([2.0, -1.15, 0.0], [4.0, -3.0, 0.0], 28)[1:]]
TURN = np.vstack(_LEGS)


def test_poses_far_apart_on_the_plan_are_read_along_it():
    """A busy node saw the robot only before and after its turn at the sofa: the plan fills the gap."""
    straight = _monitor('F (near[sofa] & F near[computer])')
    straight.update(TURN[3])
    # read as a straight line, the move from before the turn to after it misses the sofa
    assert not straight.update_along(TURN[3], TURN[-4]).changed
    m = _monitor('F (near[sofa] & F near[computer])')
    trace = PlanTrace(TURN, tolerance=0.1, dims=2)
    trace.start(TURN[3])
    m.update(TURN[3])
    via = trace.via(TURN[-4] + [0.03, 0.03, 0.0])            # a little off the plan is still on it
    assert any(np.allclose(v, [2.0, -1.15, 0.0]) for v in via)
    assert m.update_along(TURN[3], TURN[-4], via=via).changed


def test_a_pose_off_the_plan_or_behind_it_is_read_straight():
    trace = PlanTrace(TURN, tolerance=0.1, dims=2)
    trace.start(TURN[10])
    assert trace.via([1.0, 1.0, 0.0]) == []           # off the plan
    assert trace.via(TURN[30]) == []                  # the last pose was off it: straight
    assert len(trace.via(TURN[40])) == 9              # on it again: the points in between
    assert trace.via(TURN[20]) == []                  # behind where the robot has been
    assert trace.cursor is None


def test_a_plan_that_comes_back_is_located_in_order():
    out_and_back = np.vstack([np.linspace([0.0, 0.0, 0.0], [3.0, 0.0, 0.0], 31),
                              np.linspace([3.0, 0.0, 0.0], [0.0, 0.05, 0.0], 31)[1:]])
    trace = PlanTrace(out_and_back, tolerance=0.1, dims=2)
    trace.start([1.0, 0.0, 0.0])
    assert trace.cursor == pytest.approx(1.0)
    trace.via([2.9, 0.0, 0.0])
    assert trace.cursor == pytest.approx(2.9)
    trace.via([1.0, 0.03, 0.0])                       # on the way back, not the way out
    assert trace.cursor == pytest.approx(5.0, abs=0.01)


def test_plan_trace_heights_count_for_a_drone_only():
    path = np.array([[0.0, 0.0, 5.0], [4.0, 0.0, 5.0]])
    assert PlanTrace(path, 0.1, dims=2).locate([1.0, 0.0, 0.0]) == pytest.approx(1.0)
    assert PlanTrace(path, 0.1, dims=3).locate([1.0, 0.0, 0.0]) is None


@pytest.mark.parametrize('bad', [dict(path=np.zeros((0, 3))), dict(path=np.full((2, 3), np.nan)),
                                 dict(path=np.zeros((2, 2))), dict(path=np.zeros((2, 3)), tolerance=0.0),
                                 dict(path=np.zeros((2, 3)), dims=4)])
def test_plan_trace_rejects_bad_input(bad):
    with pytest.raises(InvalidInputError):
        PlanTrace(**bad)

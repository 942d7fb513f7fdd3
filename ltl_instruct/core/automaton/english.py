"""English for verification: what a person checks before the robot moves.

From a formula's automaton this writes the referents the task mentions and the
ordered subgoals along one path to acceptance, e.g.::

    Subgoal 1: go to the green plush toy.
    Subgoal 2: pick up the green plush toy, and do not go near the whiteboard in front
               of the green plush toy yet.

Order and avoidance are read off the automaton, not the formula's text, so what
the person reads is what the planner will do: a goal is the letter that moves
the automaton along the path; a place is "to avoid" in a state when being there
alone sends the automaton to the rejecting sink.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional, Sequence, Union

from ltl_instruct.core.automaton.dfa import Automaton, Edge, compile_automaton
from ltl_instruct.core.automaton.guards import Cube
from ltl_instruct.core.errors import LimitExceededError
from ltl_instruct.core.spec.ast import Atom, Descriptor, Formula, avoided_referents_of, referents_of

_RELATION_WORDS = {
    'isabove': 'above', 'isbelow': 'below', 'isleftof': 'to the left of',
    'isrightof': 'to the right of', 'isnextto': 'next to', 'isinfrontof': 'in front of',
    'isbehind': 'behind',
}


def describe_descriptor(d: Descriptor, article: bool = True) -> str:
    """English noun phrase: ``sofa::isbehind(pillar)`` -> ``the sofa behind the pillar``.

    A nested argument with relations of its own is set off as "(the one ...)" so
    that the attachment is unambiguous.
    """
    head = d.name.replace('_', ' ')
    parts = []
    for r in d.relations:
        args = [_argument(a) for a in r.args]
        if r.comparator == 'isbetween':
            parts.append(f'between {args[0]} and {args[1]}')
        else:
            parts.append(f'{_RELATION_WORDS[r.comparator]} {args[0]}')
    text = head + (' ' + ' and '.join(parts) if parts else '')
    return ('the ' + text) if article else text


def _argument(d: Descriptor) -> str:
    if not d.relations:
        return describe_descriptor(d)
    inner = describe_descriptor(d, article=False)[len(d.name.replace('_', ' ')) + 1:]
    return f'the {d.name.replace("_", " ")} (the one {inner})'


def describe_atom(a: Atom) -> str:
    """Imperative phrase for making an atom true: "go to ...", "pick up ...", "put ... at ..."."""
    if a.skill == 'pick':
        return f'pick up {describe_descriptor(a.args[0])}'
    if a.skill == 'release':
        return f'put {describe_descriptor(a.args[0])} down at {describe_descriptor(a.args[1])}'
    return f'go to {describe_descriptor(a.args[0])}'


def _avoid_phrase(a: Atom) -> str:
    if a.skill == 'pick':
        return f'pick up {describe_descriptor(a.args[0])}'
    if a.skill == 'release':
        return f'put {describe_descriptor(a.args[0])} down at {describe_descriptor(a.args[1])}'
    return f'go near {describe_descriptor(a.args[0])}'


@dataclass(frozen=True)
class TaskDescription:
    """The verification text of a task.

    Attributes
    ----------
    formula: the formula as printed.
    referents: English noun phrase of every skill-argument descriptor.
    avoid: English noun phrase of every descriptor under an explicit negation.
    subgoals: one line per step along the chosen automaton path.
    throughout: constraints that hold for the whole task.
    notes: remarks (order freedom, unsatisfiability).
    satisfiable: whether any plan can satisfy the task.
    """

    formula: str
    referents: tuple[str, ...]
    avoid: tuple[str, ...]
    subgoals: tuple[str, ...]
    throughout: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    satisfiable: bool = True
    path: tuple[int, ...] = field(default=(), compare=False)

    def text(self) -> str:
        """Return the whole description as lines a person reads."""
        lines = [f'Task: {self.formula}']
        if self.referents:
            lines.append('Referents: ' + '; '.join(self.referents))
        lines.extend(self.subgoals)
        lines.extend(self.throughout)
        lines.extend(self.notes)
        return '\n'.join(lines)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'formula': self.formula, 'referents': list(self.referents), 'avoid': list(self.avoid),
                'subgoals': list(self.subgoals), 'throughout': list(self.throughout),
                'notes': list(self.notes), 'satisfiable': self.satisfiable,
                'automaton_path': list(self.path)}


def _goal_cube(edge: Edge) -> list[Cube]:
    return sorted(edge.guard.cubes, key=lambda c: (len(c.pos), len(c.neg)))


def _path_score(path: Sequence[Edge]) -> tuple[int, int, int]:
    pos = [min(len(c.pos) for c in e.guard.cubes) for e in path]
    return (max(pos), sum(pos), len(path))


def forbidden_atoms(aut: Automaton, state: int, goal: Optional[Cube] = None) -> list[Atom]:
    """Atoms whose truth sends the automaton from ``state`` to the rejecting sink.

    Tested against a base letter that is otherwise harmless: one that keeps the
    automaton in ``state`` if there is such a letter, else the goal letter.
    """
    if aut.sink is None:
        return []
    loop = aut.self_loop(state)
    if loop.cubes:
        base = frozenset(loop.cubes[0].pos)
    elif goal is not None:
        base = frozenset(goal.pos)
    else:
        base = frozenset()
    if aut.step(state, base) == aut.sink:
        return []
    out = []
    for a in aut.atoms:
        if a in base or (a.is_event and any(b.is_event for b in base)):
            continue
        if aut.step(state, base | {a}) == aut.sink:
            out.append(a)
    return out


def choose_path(aut: Automaton) -> Optional[tuple[Edge, ...]]:
    """Choose the path to acceptance explained to the person: one skill per step where possible."""
    paths = aut.accepting_paths(max_paths=64)
    if not paths:
        return None
    return min(paths, key=_path_score)


def describe_task(task: Union[Formula, str, Automaton]) -> TaskDescription:
    """Describe a task: its referents and English subgoals (formula text, AST, or automaton)."""
    aut = task if isinstance(task, Automaton) else compile_automaton(task)
    f = aut.formula
    referents = tuple(describe_descriptor(d) for d in referents_of(f))
    avoid = tuple(describe_descriptor(d) for d in avoided_referents_of(f))
    if not aut.is_satisfiable:
        return TaskDescription(str(f), referents, avoid, (), (),
                               ('This task can never be completed: its constraints contradict '
                                'each other, so nothing will be planned.',), False)
    try:
        return _describe_path(aut, referents, avoid)
    except LimitExceededError as e:   # guards too large to write as cubes (a long chain of <->)
        return TaskDescription(str(f), referents, avoid, (), (),
                               (f'Not put in English: {e.message}',), True)


def _describe_path(aut: Automaton, referents: tuple[str, ...], avoid: tuple[str, ...]) -> TaskDescription:
    """Describe the steps along the chosen path to acceptance, and what holds throughout."""
    f = aut.formula
    path = choose_path(aut)
    if not path:  # accepted by any first step (e.g. only "never" constraints)
        forb = forbidden_atoms(aut, aut.initial)
        lines = tuple(f'Throughout: do not {_avoid_phrase(a)}.' for a in forb)
        return TaskDescription(str(f), referents, avoid, ('Nothing to reach: the task holds as it is.',),
                               lines, (), True, (aut.initial,))
    states = [path[0].src] + [e.dst for e in path]
    forb_per_state = [forbidden_atoms(aut, s, _goal_cube(e)[0]) for s, e in zip(states, path)]
    forb_per_state.append(forbidden_atoms(aut, states[-1]))
    always = [a for a in forb_per_state[0] if all(a in fs for fs in forb_per_state)]
    goals_so_far: set[Atom] = set()
    later_goals = [set().union(*(c.pos for c in e.guard.cubes)) for e in path]
    subgoals = []
    for k, edge in enumerate(path):
        cubes = _goal_cube(edge)
        if len(cubes) > 1 and all(len(c.pos) == 1 for c in cubes):
            options = [describe_atom(next(iter(c.pos))) for c in cubes]
            goal = 'either ' + ', or '.join(options)
            pos_atoms = set().union(*(c.pos for c in cubes))
        else:
            c = cubes[0]
            pos_atoms = set(c.pos)
            pos = sorted(c.pos, key=lambda a: (a.skill != 'near', a.key))
            goal = ' and '.join(describe_atom(a) for a in pos) if pos else 'keep going'
            if len(pos) > 1 and any(a.skill == 'near' for a in pos):
                goal += ' (at the same time)'
        extra = []
        forb = [a for a in forb_per_state[k] if a not in always]
        upcoming = set().union(*later_goals[k + 1:]) if k + 1 < len(path) else set()
        for a in forb:
            if a.is_event and a in upcoming:
                continue  # the subgoal order already says it comes later
            if a in goals_so_far:
                extra.append(f'do not {_avoid_phrase(a)} again')
            elif a in upcoming:
                extra.append(f'do not {_avoid_phrase(a)} yet')
            else:
                extra.append(f'do not {_avoid_phrase(a)}')
        if len(cubes) == 1:
            for a in sorted(cubes[0].neg, key=lambda x: x.key):
                if a not in forb and a not in always and a.skill == 'near' and a not in upcoming:
                    extra.append(f'at that moment do not be near {describe_descriptor(a.args[0])}')
        line = f'Subgoal {k + 1}: {goal}'
        if extra:
            line += ', and ' + ', and '.join(extra)
        subgoals.append(line + '.')
        goals_so_far |= pos_atoms
    throughout = tuple(f'Throughout the task: never {_avoid_phrase(a)}.' for a in always)
    notes = _order_notes(aut, path)
    return TaskDescription(str(f), referents, avoid, tuple(subgoals), throughout, notes, True,
                           tuple(states))


def _order_notes(aut: Automaton, path: Sequence[Edge]) -> tuple[str, ...]:
    def goals(p: Sequence[Edge]) -> tuple[Atom, ...]:
        out = []
        for e in p:
            c = _goal_cube(e)[0]
            out.extend(sorted(c.pos, key=lambda a: a.key))
        return tuple(out)
    mine = goals(path)
    for other in aut.accepting_paths(max_paths=64):
        g = goals(other)
        if len(g) == len(mine) and g != mine and sorted(g, key=lambda a: a.key) == sorted(
                mine, key=lambda a: a.key) and _path_score(other)[0] == 1:
            return ('These subgoals may be done in another order too; any order the task allows '
                    'is fine.',)
    return ()

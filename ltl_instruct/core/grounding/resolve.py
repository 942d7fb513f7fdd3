"""Resolve referent descriptors to the instances they denote: the referent semantic map.

A descriptor ``name::rel1(args1)::rel2(args2)`` denotes the instances whose label
matches ``name`` (see :mod:`names`) and that satisfy every relation with at least one
instance of each argument; arguments resolve recursively (``spec/formula.md``). An
instance never serves as its own anchor.

Each resolution carries a typed outcome and a human-readable explanation of why
every candidate passed or failed, for the verification dialog:

- ``UNKNOWN_REFERENT``: nothing of that name (or of a nested argument's name) is known;
- ``NO_MATCH``: candidates exist but none satisfies the relations;
- ``AMBIGUOUS``: several satisfy a descriptor the task needs one of (the planner may
  still choose by cost);
- ``RESOLVED``: exactly one (or, for a descriptor that only occurs under a negation,
  every instance: avoiding "a door" means avoiding all of them).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence, Union

import numpy as np

from ltl_instruct.core.errors import ErrorCode, GroundingError, InvalidInputError, LimitExceededError
from ltl_instruct.core.grounding import comparators as cmp
from ltl_instruct.core.grounding.comparators import GroundingParams
from ltl_instruct.core.grounding.names import NameMatcher
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap
from ltl_instruct.core.language.phrases import PART_WORDS
from ltl_instruct.core.spec import (
    Atom, Descriptor, Formula, Iff, Implies, Not, parse_formula, referents_of,
)
from ltl_instruct.core.world.scene import Scene

MAX_INSTANCES = 100000
_MATCHERS: dict[tuple[bool, float], NameMatcher] = {}


@dataclass(frozen=True)
class Resolution:
    """The instances one descriptor denotes, the outcome, and why."""

    descriptor: str
    outcome: Outcome
    instances: tuple[Instance, ...]
    explanation: tuple[str, ...]


def matcher_for(params: GroundingParams) -> NameMatcher:
    """Return a process-wide name matcher for these parameters (its cache survives between calls)."""
    key = (params.use_embeddings, params.embedding_threshold)
    m = _MATCHERS.get(key)
    if m is None:
        m = _MATCHERS[key] = NameMatcher(params.use_embeddings, params.embedding_threshold)
    return m


def instances_from_scene(scene: Scene) -> tuple[Instance, ...]:
    """Return the known object list of a scene, as instances (confidence 1, no observations)."""
    return tuple(Instance(o.id, o.label, tuple(float(v) for v in o.center),  # type: ignore[arg-type]
                          tuple(float(v) for v in (o.size or (0.0, 0.0, 0.0))))  # type: ignore[arg-type]
                 for o in scene.objects)


def validate_instances(instances: Sequence[Instance]) -> tuple[Instance, ...]:
    """Check ids are unique and positions finite; return the instances as a tuple.

    Raises
    ------
    InvalidInputError
        On a non-finite centre or size, or a repeated id.
    LimitExceededError
        On more than ``MAX_INSTANCES`` instances.
    """
    out = tuple(instances)
    if len(out) > MAX_INSTANCES:
        raise LimitExceededError(f'{len(out)} instances exceed the limit of {MAX_INSTANCES}')
    seen: set[str] = set()
    for inst in out:
        if not isinstance(inst, Instance):
            raise InvalidInputError(f'expected an Instance, got {type(inst).__name__}')
        if len(inst.center) != 3 or not all(math.isfinite(v) for v in inst.center) \
                or len(inst.size) != 3 or not all(math.isfinite(v) and v >= 0 for v in inst.size):
            raise InvalidInputError(f'instance {inst.id!r} has a non-finite centre or size',
                                    details={'instance': inst.id})
        if inst.id in seen:
            raise InvalidInputError(f'instance id {inst.id!r} appears twice', details={'instance': inst.id})
        seen.add(inst.id)
    return out


def _fmt(p: Sequence[float]) -> str:
    return '(' + ', '.join(f'{v:.2f}' for v in p) + ')'


_AXIS_WORDS = {'isabove': 'above', 'isbelow': 'below', 'isleftof': 'left of', 'isrightof': 'right of',
               'isbehind': 'behind', 'isinfrontof': 'in front of'}


class Resolver:
    """Resolves descriptors against a fixed list of instances (memoised per descriptor).

    Parameters
    ----------
    instances: the objects known or detected (ids unique).
    params: comparator thresholds, viewpoint and name matching.
    """

    def __init__(self, instances: Sequence[Instance], params: GroundingParams = GroundingParams()) -> None:
        self.params = params
        self.instances = tuple(i for i in validate_instances(instances)
                               if i.confidence >= params.min_confidence)
        self.centers = np.array([i.center for i in self.instances], dtype=float).reshape(-1, 3)
        self.matcher = matcher_for(params)
        self._memo: dict[Descriptor, tuple[Resolution, np.ndarray]] = {}

    # ------------------------------------------------------------------ names
    def named(self, name: str) -> np.ndarray:
        """Return the indices of the instances that ``name`` names."""
        return np.array([k for k, inst in enumerate(self.instances)
                         if self.matcher.match(name, inst.label, inst.id)[0]], dtype=int)

    def _whole_of_part(self, name: str) -> tuple[str, np.ndarray]:
        """``library_roof`` names no object: the library's, if a library is known.

        The translator writes parts of places before their whole ("the roof of the
        library" -> ``library_roof``); a map rarely holds the part as an object of its
        own, and being near the part means being near the whole.
        """
        whole, _, head = name.rpartition('_')
        if not whole or head not in PART_WORDS:
            return '', np.array([], dtype=int)
        return whole, self.named(whole)

    # ------------------------------------------------------------------ resolution
    def resolve(self, descriptor: Descriptor) -> Resolution:
        """Resolve one descriptor (and, recursively, its arguments)."""
        return self._resolve(descriptor)[0]

    def _resolve(self, d: Descriptor) -> tuple[Resolution, np.ndarray]:
        hit = self._memo.get(d)
        if hit is not None:
            return hit
        text = str(d)
        idx = self.named(d.name)
        part_of = ''
        if idx.size == 0:
            part_of, idx = self._whole_of_part(d.name)
        if idx.size == 0:
            known = sorted({i.label for i in self.instances})
            shown = ', '.join(known[:12]) + (', ...' if len(known) > 12 else '')
            res = Resolution(text, Outcome.UNKNOWN_REFERENT, (),
                             (f'no object named "{d.name}" is known (labels: {shown or "none"})',))
            self._memo[d] = (res, idx)
            return res, idx
        alive = np.ones(idx.size, dtype=bool)
        reasons: list[list[str]] = [[] for _ in range(idx.size)]
        notes: list[str] = []
        outcome_if_empty = Outcome.NO_MATCH
        for rel in d.relations:
            args = [self._resolve(a) for a in rel.args]
            empty = [(a, r) for a, (r, ix) in zip(rel.args, args) if ix.size == 0]
            if empty:
                for a, r in empty:
                    notes.append(f'{rel.comparator}: "{a}" resolves to nothing ({r.outcome.value}): '
                                 + '; '.join(r.explanation[:3]))
                    if r.outcome == Outcome.UNKNOWN_REFERENT:
                        outcome_if_empty = Outcome.UNKNOWN_REFERENT
                alive[:] = False
                continue
            ok, why = self._relation(idx, rel.comparator, [ix for _, ix in args], str(rel))
            alive &= ok
            for k in range(idx.size):
                reasons[k].append(why[k])
        lines = list(notes)
        if part_of:
            lines.append(f'no object is named "{d.name}": taken as a part of the {part_of.replace("_", " ")}')
        for k, j in enumerate(idx):
            inst = self.instances[j]
            verdict = 'passes' if alive[k] else 'fails'
            detail = ('; '.join(reasons[k])) if reasons[k] else 'name matches'
            lines.append(f'{inst.id} ({inst.label}) at {_fmt(inst.center)} {verdict}: {detail}')
        chosen = idx[alive]
        insts = tuple(self.instances[j] for j in chosen)
        if not insts:
            outcome = outcome_if_empty
        elif len(insts) == 1:
            outcome = Outcome.RESOLVED
        else:
            outcome = Outcome.AMBIGUOUS
        res = Resolution(text, outcome, insts, tuple(lines))
        self._memo[d] = (res, chosen)
        return res, chosen

    def _relation(self, idx: np.ndarray, comparator: str, args: list[np.ndarray],
                  rel_text: str) -> tuple[np.ndarray, list[str]]:
        """Which candidates satisfy one relation, and a reason per candidate."""
        a = self.centers[idx]
        t = self.params.threshold_of(comparator)
        ids_a = idx[:, None]
        why: list[str] = []
        if comparator == 'isbetween':
            ib, ic = args
            dist, s = cmp.segment_distances(a, self.centers[ib], self.centers[ic])
            valid = (ids_a[:, :, None] != ib[None, :, None]) & (ids_a[:, :, None] != ic[None, None, :]) \
                & (ib[None, :, None] != ic[None, None, :])
            holds = cmp.between_holds(dist, s, t) & valid
            ok = holds.reshape(idx.size, -1).any(axis=1)
            # closest valid pair whose projection falls inside the segment, for the explanation
            inside = valid & (s >= 0) & (s <= 1)
            score = np.where(inside, dist, np.inf).reshape(idx.size, -1)
            for k in range(idx.size):
                if not valid[k].any():
                    why.append(f'{rel_text}: no pair of other instances to lie between')
                    continue
                flat = int(np.argmin(score[k]))
                m, n = np.unravel_index(flat, dist.shape[1:])
                pair = f'{self.instances[ib[m]].id}-{self.instances[ic[n]].id}'
                if not np.isfinite(score[k, flat]):
                    why.append(f'{rel_text}: projects outside every segment (needs within {t:.2f} m)')
                else:
                    why.append(f'{rel_text}: {dist[k, m, n]:.2f} m from segment {pair} '
                               f'({"<=" if ok[k] else ">"} {t:.2f})')
            return ok, why
        (ib,) = args
        b = self.centers[ib]
        valid = ids_a != ib[None, :]
        if comparator == 'isnextto':
            dist = cmp.pair_distances(a, b)
            holds = (dist < t) & valid
            ok = holds.any(axis=1)
            score = np.where(valid, dist, np.inf)
            for k in range(idx.size):
                if not valid[k].any():
                    why.append(f'{rel_text}: no other instance to compare with')
                    continue
                m = int(np.argmin(score[k]))
                why.append(f'{rel_text}: {dist[k, m]:.2f} m from {self.instances[ib[m]].id} '
                           f'({"<" if ok[k] else ">="} {t:.2f})')
            return ok, why
        if comparator not in cmp.AXIS_COMPARATORS:
            raise GroundingError(f'unknown comparator {comparator!r}', ErrorCode.INVALID_INPUT)
        margin = cmp.axis_margin(comparator, cmp.viewer_offsets(a, b, self.params.viewpoint))
        holds = cmp.axis_holds(comparator, margin, t) & valid
        ok = holds.any(axis=1)
        score = np.where(valid, margin, -np.inf)
        word = _AXIS_WORDS[comparator]
        for k in range(idx.size):
            if not valid[k].any():
                why.append(f'{rel_text}: no other instance to compare with')
                continue
            m = int(np.argmax(score[k]))
            why.append(f'{rel_text}: {margin[k, m]:+.2f} m {word} {self.instances[ib[m]].id} '
                       f'({"meets" if ok[k] else "below"} {t:.2f})')
        return ok, why


def required_referents(formula: Formula) -> set[Descriptor]:
    """Descriptors that occur in an atom with positive polarity (not only under negation)."""
    out: set[Descriptor] = set()
    stack: list[tuple[Formula, bool]] = [(formula, True)]
    while stack:
        f, positive = stack.pop()
        if isinstance(f, Atom):
            if positive:
                out.update(f.args)
        elif isinstance(f, Not):
            stack.append((f.operand, not positive))
        elif isinstance(f, Implies):
            stack.append((f.left, not positive))
            stack.append((f.right, positive))
        elif isinstance(f, Iff):
            for c in f.children():
                stack.append((c, positive))
                stack.append((c, not positive))
        else:
            stack.extend((c, positive) for c in f.children())
    return out


def ground_formula(formula: Union[Formula, str], instances: Sequence[Instance],
                   params: GroundingParams = GroundingParams()) -> ReferentMap:
    """Resolve every skill-argument descriptor of ``formula`` against ``instances``.

    Parameters
    ----------
    formula: a formula (or its text, parsed with :func:`parse_formula`).
    instances: the known or detected objects.
    params: comparator thresholds, viewpoint and name matching.

    Returns
    -------
    ReferentMap
        Keyed by the descriptor text (``str(descriptor)``); one grounding for every
        descriptor that is a skill argument, with its outcome and explanation. A
        descriptor that only occurs under a negation has ``required=False``.

    Raises
    ------
    InvalidInputError
        On malformed instances; ``FormulaSyntaxError`` on malformed formula text.
    """
    f = parse_formula(formula) if isinstance(formula, str) else formula
    if not isinstance(f, Formula):
        raise InvalidInputError(f'expected a formula, got {type(formula).__name__}')
    resolver = Resolver(instances, params)
    required = required_referents(f)
    groundings: dict[str, Grounding] = {}
    for d in referents_of(f):
        r = resolver.resolve(d)
        needed = d in required
        outcome = r.outcome
        explanation = list(r.explanation)
        if not needed and outcome == Outcome.AMBIGUOUS:
            outcome = Outcome.RESOLVED
            explanation.insert(0, f'avoided: all {len(r.instances)} instances count')
        elif needed and outcome == Outcome.AMBIGUOUS:
            explanation.insert(0, f'{len(r.instances)} instances satisfy "{r.descriptor}"; '
                                  'the planner chooses the cheapest to reach')
        groundings[r.descriptor] = Grounding(r.descriptor, outcome, r.instances, tuple(explanation), needed)
    return ReferentMap(groundings)


def grounding_error(rmap: ReferentMap) -> Optional[GroundingError]:
    """Return the error a task's referent map implies, or None.

    A required descriptor that resolved to nothing is an error (``UNKNOWN_REFERENT`` or
    ``NO_MATCH``); ambiguity is not (the planner chooses by cost), and an avoided
    descriptor that denotes nothing is harmless.
    """
    for text, g in rmap.groundings.items():
        if not g.required or g.outcome not in (Outcome.UNKNOWN_REFERENT, Outcome.NO_MATCH):
            continue
        code = ErrorCode.UNKNOWN_REFERENT if g.outcome == Outcome.UNKNOWN_REFERENT else ErrorCode.NO_MATCH
        why = g.explanation[0] if g.explanation else ''
        verb = 'is unknown' if code == ErrorCode.UNKNOWN_REFERENT else 'matches no instance'
        return GroundingError(f'"{text}" {verb}: {why}', code,
                              details={'referent': text, 'explanation': list(g.explanation)})
    return None

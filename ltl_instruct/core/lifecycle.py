"""The life of an instruction on ``task_status``, and who remembers it (no ROS).

An instruction has two phases, and each ends with exactly one terminal status:

- ``planning``: ``received`` first (it names the id, so the sender of plain text learns
  it), then one terminal ``planned``, ``satisfied`` (nothing has to move), ``failed`` or
  ``cancelled``.
- ``execution``, only after ``planned``: ``progressing``, ``replanning``... then one
  terminal ``satisfied``, ``violated``, ``failed``, ``superseded`` (a newer plan replaced
  it) or ``cancelled``.

Two records outlive a node. ``task_progression`` keeps a :class:`StatusMemory` (what it
said about each id: a spec sent again is answered from it, and no phase ends twice),
journaled to a file in the run's state directory so that it survives its own restart;
``ltl_translator`` keeps an :class:`InstructionLedger` (every instruction it took and the
statuses it heard: when a reader of ``task_spec`` restarts, it sends again every spec
still in flight, an executing one with its last automaton state so that planning resumes
from there). A restarted translator rebuilds its ledger from the latched statuses and
the sender's latched instructions.
"""
from __future__ import annotations

import hashlib
import json
import os
from collections import OrderedDict
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional

PLANNING, EXECUTION = 'planning', 'execution'
RECEIVED = 'received'
PLANNED, SATISFIED, FAILED, CANCELLED = 'planned', 'satisfied', 'failed', 'cancelled'
SUPERSEDED, VIOLATED = 'superseded', 'violated'
PLANNING_ENDS = (PLANNED, SATISFIED, FAILED, CANCELLED)
EXECUTION_ENDS = (SATISFIED, VIOLATED, FAILED, SUPERSEDED, CANCELLED)
MEMORY = 10_000   # instructions remembered by each record
# what a remembered status keeps (what a repeat answer and a resumed task need; not the plan)
KEPT_FIELDS = ('status', 'phase', 'terminal', 'error', 'reason', 'stage', 'automaton_state', 'superseded_by',
               'id_source', 'formula', 'plan_stamp')


def plain_instruction_id(source_ns: Any, sequence: Any, text: str) -> Optional[str]:
    """Return the id of a plain-text instruction, or None without the sample's identity.

    It is a digest of the DDS sample's source timestamp [ns] and publication sequence
    number with the text: the same sample read again (by a restarted translator, from the
    sender's transient-local history) gets the same id, so it is not carried out twice.
    """
    if not isinstance(source_ns, int) or not isinstance(sequence, int):
        return None
    digest = hashlib.sha1(f'{source_ns}:{sequence}:{text}'.encode('utf-8', 'replace')).hexdigest()
    return f'i-{digest[:16]}'


def _trim(entries: OrderedDict, limit: int) -> None:
    while len(entries) > limit:
        entries.popitem(last=False)


class StatusMemory:
    """What ``task_progression`` has said about each instruction, phase by phase.

    With a ``journal`` (a file in the run's state directory, given by ``bringup``), each
    status is also appended to it as one JSON line, and read back when the node starts
    again: a restarted ``task_progression`` then still knows what has ended (and answers a
    spec sent again with its statuses, instead of carrying it out twice) and which task was
    executing, from which automaton state.

    Parameters
    ----------
    limit: instructions remembered (the oldest are forgotten first).
    journal: the file, or None to remember in memory only.
    """

    def __init__(self, limit: int = MEMORY, journal: Optional[Path] = None) -> None:
        self._last: OrderedDict[str, dict[str, dict[str, Any]]] = OrderedDict()
        self._limit = limit
        self._journal = journal
        self._lines = 0
        if journal is not None and journal.is_file():
            self._load(journal)

    def admit(self, iid: str, body: dict[str, Any]) -> bool:
        """Record a status about to be published; False when its phase has already ended.

        ``body`` has ``status``, ``phase`` and ``terminal``. Statuses of other phases
        (``input``) are not recorded and always admitted.
        """
        phase = body.get('phase')
        if phase not in (PLANNING, EXECUTION):
            return True
        if self.ended(iid, phase) is not None:
            return False
        record = {k: body[k] for k in KEPT_FIELDS if body.get(k) is not None}
        self._remember(iid, record)
        self._append(iid, record)
        return True

    def _remember(self, iid: str, record: dict[str, Any]) -> None:
        self._last.setdefault(iid, {})[record['phase']] = record
        self._last.move_to_end(iid)
        _trim(self._last, self._limit)

    def knows(self, iid: str) -> bool:
        """Tell whether any status of ``iid`` was published."""
        return iid in self._last

    def ended(self, iid: str, phase: str = PLANNING) -> Optional[str]:
        """Return the terminal status that ended ``phase`` of ``iid``, or None while it runs."""
        last = self._last.get(iid, {}).get(phase)
        return last['status'] if last is not None and last.get('terminal') else None

    def executing(self, iid: str) -> Optional[dict[str, Any]]:
        """Return the last execution status of a planned ``iid`` whose execution has not ended, else None.

        (``{}`` when it was planned and no execution status came yet.)
        """
        if self.ended(iid) != PLANNED or self.ended(iid, EXECUTION) is not None:
            return None
        return dict(self._last[iid].get(EXECUTION, {}))

    def repeat(self, iid: str) -> list[dict[str, Any]]:
        """Return the statuses that answer a repeated spec of ``iid``, marked ``repeat``.

        The end of its execution when that has ended, else the last status of each phase.
        """
        last = self._last.get(iid, {})
        phases = (EXECUTION,) if self.ended(iid, EXECUTION) else (PLANNING, EXECUTION)
        return [dict(last[phase], repeat=True) for phase in phases if phase in last]

    # ------------------------------------------------------------------ the journal
    def _append(self, iid: str, record: dict[str, Any]) -> None:
        if self._journal is None:
            return
        if self._lines >= 2 * self._limit:   # compact: the file keeps what memory keeps
            self._rewrite()
        with open(self._journal, 'a', encoding='utf-8') as f:
            f.write(json.dumps({'id': iid, **record}) + '\n')
        self._lines += 1

    def _rewrite(self) -> None:
        assert self._journal is not None
        tmp = self._journal.with_name(self._journal.name + '.tmp')
        with open(tmp, 'w', encoding='utf-8') as f:
            for iid, phases in self._last.items():
                for record in phases.values():
                    f.write(json.dumps({'id': iid, **record}) + '\n')
        os.replace(tmp, self._journal)
        self._lines = sum(len(phases) for phases in self._last.values())

    def _load(self, journal: Path) -> None:
        with open(journal, encoding='utf-8', errors='replace') as f:
            for line in f:   # a line cut short by a kill is skipped
                try:
                    record = json.loads(line)
                except ValueError:
                    continue
                if _is_record(record):
                    self._remember(record.pop('id'), record)
                    self._lines += 1


def _is_record(record: Any) -> bool:
    return isinstance(record, dict) and isinstance(record.get('id'), str) and \
        record.get('phase') in (PLANNING, EXECUTION) and isinstance(record.get('status'), str)


@dataclass
class _Entry:
    """One instruction in the ledger."""

    phase: str = PLANNING            # planning | execution | ended
    spec: Optional[dict[str, Any]] = None
    taken: bool = False              # this translator took the instruction message
    automaton_state: Optional[int] = None


class InstructionLedger:
    """The translator's record of each instruction: taken, spec sent, phase heard on ``task_status``.

    Parameters
    ----------
    limit: instructions remembered (ended ones are forgotten first).
    """

    def __init__(self, limit: int = MEMORY) -> None:
        self._entries: OrderedDict[str, _Entry] = OrderedDict()
        self._limit = limit

    def take(self, iid: str) -> bool:
        """Record an instruction message; True when it is to be translated.

        False for a repeat (the same id taken already: the message came on both
        subscriptions, or again from the sender's history) and for an instruction that has
        ended (a restarted translator learns that from the latched statuses).
        """
        entry = self._entries.setdefault(iid, _Entry())
        if entry.taken or entry.phase == 'ended':
            return False
        entry.taken = True
        self._forget_old()
        return True

    def sent(self, iid: str, spec: dict[str, Any]) -> None:
        """Record the task spec published for ``iid`` (what is sent again after a restart)."""
        self._entries.setdefault(iid, _Entry(taken=True)).spec = dict(spec)

    def ended(self, iid: str) -> bool:
        """Tell whether the instruction is over: then it is not translated, nor sent again."""
        entry = self._entries.get(iid)
        return entry is not None and entry.phase == 'ended'

    def note_status(self, body: dict[str, Any]) -> None:
        """Follow a ``task_status`` payload (``id``, ``status``, ``phase``, ``terminal``)."""
        iid, phase, status = body.get('id'), body.get('phase'), body.get('status')
        if not isinstance(iid, str) or phase not in (PLANNING, EXECUTION):
            return
        entry = self._entries.setdefault(iid, _Entry())
        if entry.phase == 'ended':
            return
        if phase == EXECUTION:
            entry.phase = 'ended' if body.get('terminal') else EXECUTION
            state = body.get('automaton_state')
            if isinstance(state, int) and not isinstance(state, bool):
                entry.automaton_state = state
        elif body.get('terminal'):
            entry.phase = EXECUTION if status == PLANNED else 'ended'
        self._forget_old()

    def in_flight(self) -> list[dict[str, Any]]:
        """Specs to send again, oldest first; an executing one carries ``resume``.

        ``resume: {"automaton_state": s}`` (None: the initial state) asks a restarted
        ``task_progression`` to plan from there instead of starting the task afresh.
        """
        out = []
        for entry in self._entries.values():
            if entry.spec is None or entry.phase == 'ended':
                continue
            spec = dict(entry.spec)
            if entry.phase == EXECUTION:
                spec['resume'] = {'automaton_state': entry.automaton_state}
            out.append(spec)
        return out

    def _forget_old(self) -> None:
        if len(self._entries) <= self._limit:
            return
        for iid in [k for k, e in self._entries.items() if e.phase == 'ended']:
            if len(self._entries) <= self._limit:
                return
            del self._entries[iid]
        _trim(self._entries, self._limit)

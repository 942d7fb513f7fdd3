"""``ltl_translator``: English instruction -> task formula, shown to a person for checking.

Subscribes ``instruction`` (std_msgs/String): plain English text, or a JSON object
``{"id": ..., "text": ...}`` that may give a ``formula`` instead of text (parsed with the
formula grammar, never run). Each instruction keeps the ``id`` it carries; plain text
gets one made from its DDS sample (:func:`~ltl_instruct.core.lifecycle.plain_instruction_id`),
which ``task_progression`` returns as the first status, ``received``.

Publishes ``verification/request`` (the formula, its referents and the ordered
subgoals in English) and ``task_spec`` (latched JSON). With ``require_confirmation``
the task spec waits for ``verification/reply`` ``{"id", "accept": true|false}``;
otherwise it is accepted at once. A failed translation is still published on
``task_spec`` (``ok: false`` with a typed error), so that ``task_progression`` ends the
instruction with one terminal ``failed`` status: nothing is dropped.

The translator owns each instruction until it ends (:class:`~ltl_instruct.core.lifecycle.
InstructionLedger`, fed by ``task_status``). ``instruction`` is read twice: volatile, so
that any reliable publisher is heard, and transient-local, so that a restarted translator
reads again the sender's latched history and translates what has not ended (the same
sample keeps its id; a repeat is skipped). When a reader of ``task_spec`` (re)starts,
every spec still in flight is sent to it again.

Publishes ``~/status`` (latched JSON): ``state`` is ``loading`` while the backend and its model
load (an instruction is queued meanwhile, and waits), then ``ready``, or ``failed`` with the
typed error each instruction will be answered with. Clients wait for it before timing
anything (:meth:`~ltl_instruct.nodes.client.GraphClient.wait_for_graph`).
"""
from __future__ import annotations

import os
import queue
import sys
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Optional

from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from std_msgs.msg import String

from ltl_instruct import conversions as conv
from ltl_instruct.core.automaton.english import describe_task
from ltl_instruct.core.errors import (
    ErrorCode, LimitExceededError, LtlInstructError, TranslationError,
)
from ltl_instruct.core.language.verification import reading_lines, warnings_of
from ltl_instruct.core.lifecycle import InstructionLedger, plain_instruction_id
from ltl_instruct.core.spec import avoided_referents_of, parse_formula, referents_of
from ltl_instruct.nodes.common import ParamSpec, declare_parameters, latched_qos, reliable_qos, run_node

PARAMS = (
    ParamSpec('backend', 'combined', 'translator backend: combined (rules and learned model, the default), '
              'offline (rules only), neural (learned model only), llm, learned (trajectory parser)',
              choices=('combined', 'offline', 'neural', 'llm', 'learned')),
    ParamSpec('model_path', '', 'model directory or file for the combined/neural/llm/learned backends '
              '("" = default)'),
    ParamSpec('require_confirmation', False,
              'wait for verification/reply before publishing the task spec'),
    ParamSpec('confirmation_timeout', 120.0, 'how long to wait for verification/reply [s]', 1.0, 3600.0),
    ParamSpec('max_instruction_chars', 2000, 'longest instruction accepted [characters]', 10, 100000),
)
# read at each instruction; the backend and its model are loaded once at start (read-only)
RUNTIME = frozenset({'require_confirmation', 'confirmation_timeout', 'max_instruction_chars'})


@dataclass(frozen=True)
class _Job:
    """An instruction message waiting for the worker, with the id it is served under."""

    iid: str
    fallback_id: str      # the id made for it, used when the message names none
    text: str
    received: float = field(default_factory=time.monotonic)

    @property
    def id_source(self) -> str:
        """``sender`` when the message named its id, ``assigned`` when it was made here."""
        return 'assigned' if self.iid == self.fallback_id else 'sender'


class LtlTranslatorNode(Node):
    """Instruction in, verification request and task spec out."""

    def __init__(self) -> None:
        super().__init__('ltl_translator')
        self.params = declare_parameters(self, PARAMS, RUNTIME)
        self._translator: Any = None
        self._translator_error: Optional[LtlInstructError] = None
        self._prefix = os.urandom(3).hex()
        self._count = 0
        self._jobs: queue.Queue = queue.Queue()
        self._replies: dict[str, bool] = {}
        self._reply_event = threading.Condition()
        self._closing = threading.Event()
        self._ledger = InstructionLedger()
        self._ledger_lock = threading.Lock()
        self.spec_pub = self.create_publisher(String, 'task_spec', latched_qos(), event_callbacks=(
            PublisherEventCallbacks(matched=self.on_spec_reader)))
        self.verify_pub = self.create_publisher(String, 'verification/request', latched_qos())
        self.status_pub = self.create_publisher(String, '~/status', latched_qos(1))
        self._publish_state('loading')
        self.create_subscription(String, 'instruction', self.on_instruction, reliable_qos())
        # a volatile publisher cannot match this one: DDS would warn about each, and it is expected
        self.create_subscription(String, 'instruction', self.on_instruction, latched_qos(), event_callbacks=(
            SubscriptionEventCallbacks(incompatible_qos=lambda event: None)))
        self.create_subscription(String, 'task_status', self.on_status, latched_qos())
        self.create_subscription(String, 'verification/reply', self.on_reply, reliable_qos())
        self._worker = threading.Thread(target=self._work, name='translate', daemon=True)
        self._worker.start()
        self.get_logger().info(f'ltl_translator: backend {self.params["backend"]}')

    # ------------------------------------------------------------------ callbacks
    def on_instruction(self, msg: String, info: dict[str, Any]) -> None:
        """Give the instruction its id and queue it for the worker, unless it was taken already."""
        fallback_id = plain_instruction_id(info.get('source_timestamp'),
                                           info.get('publication_sequence_number'), msg.data)
        if fallback_id is None:
            self._count += 1
            fallback_id = f'{self._prefix}-{self._count}'
        job = _Job(self._id_of(fallback_id, msg.data), fallback_id, msg.data)
        with self._ledger_lock:
            if not self._ledger.take(job.iid):
                return
        self._jobs.put(job)

    def on_status(self, msg: String) -> None:
        """Follow each instruction's phase on ``task_status``."""
        try:
            status = conv.parse_json_payload(msg.data, conv.TASK_STATUS)
        except LtlInstructError:
            return
        with self._ledger_lock:
            self._ledger.note_status(status)

    def on_spec_reader(self, info: Any) -> None:
        """Send every spec still in flight to a reader of ``task_spec`` that has (re)started."""
        if info.current_count_change <= 0:
            return
        with self._ledger_lock:
            specs = self._ledger.in_flight()
        if specs:
            self.get_logger().info(f'a task_spec reader came: {len(specs)} spec(s) in flight sent again')
        for spec in specs:
            self.spec_pub.publish(conv.json_msg(spec))

    def on_reply(self, msg: String) -> None:
        """Record a person's answer to a verification request."""
        try:
            reply = conv.parse_json_payload(msg.data, conv.VERIFICATION_REPLY)
        except LtlInstructError as e:
            self.get_logger().warning(f'verification reply rejected: {e.message}')
            return
        with self._reply_event:
            self._replies[reply['id']] = bool(reply.get('accept', False))
            self._reply_event.notify_all()

    # ------------------------------------------------------------------ work
    def close(self) -> None:
        """Stop the worker thread (one still translating or loading a model is left: the process ends)."""
        self._closing.set()
        self._jobs.put(None)
        self._worker.join(timeout=0.5)

    def _work(self) -> None:
        # build the translator before the first instruction comes (imports, tables, models),
        # so that its set-up does not count against that instruction
        self._load_translator()
        while not self._closing.is_set():
            job = self._jobs.get()
            if job is None:
                return
            try:
                self._serve(job)
            except Exception as e:  # noqa: BLE001 - a bug must not kill the worker or lose the instruction
                self.get_logger().error(f'internal error on {job.iid}: {e!r}')
                self._publish_spec(job, '', error=LtlInstructError(
                    f'internal error: {e!r}', ErrorCode.INTERNAL_ERROR))

    def _read_instruction(self, fallback_id: str, text: str) -> tuple[str, str, Optional[str]]:
        """``(id, text, formula or None)`` of an instruction message."""
        return conv.read_instruction(text, fallback_id, self.params['max_instruction_chars'])

    def _id_of(self, fallback_id: str, text: str) -> str:
        """Return the id an instruction message is served under (that of its failure, if it is invalid)."""
        try:
            return self._read_instruction(fallback_id, text)[0]
        except LtlInstructError as e:
            return str(e.details.get('id') or conv.salvage_id(text) or fallback_id)

    def _serve(self, job: _Job) -> None:
        with self._ledger_lock:   # ended meanwhile (the latched statuses tell a restarted translator so)
            if self._ledger.ended(job.iid):
                return
        try:
            iid, body, formula_text = self._read_instruction(job.fallback_id, job.text)
        except LtlInstructError as e:
            self._publish_spec(job, job.text[:200], error=e)
            return
        started = time.monotonic()
        try:
            if formula_text is not None:
                formula = parse_formula(formula_text)
                backend, notes, warnings = 'formula', (), ()
            else:
                translation = self._translate(body)
                formula, backend, notes = translation.formula, translation.backend, translation.notes
                warnings = warnings_of(translation)
            description = describe_task(formula)
        except LtlInstructError as e:
            self._publish_spec(job, body, error=e)
            return
        except RecursionError:
            self._publish_spec(job, body, error=LimitExceededError('instruction nests too deeply'))
            return
        elapsed = time.monotonic() - started
        spec = dict(formula=str(formula), referents=[str(d) for d in referents_of(formula)],
                    avoid=[str(d) for d in avoided_referents_of(formula)], backend=backend,
                    notes=list(notes), warnings=list(warnings), description=description.to_dict(),
                    # the translator's notes (words left out, typos corrected) are read before anything moves,
                    # the parts it could not read first
                    verification_text='\n'.join([description.text()] + reading_lines(notes, warnings)))
        needs_reply = self.params['require_confirmation']
        self.verify_pub.publish(conv.json_msg(conv.payload(
            conv.VERIFICATION_REQUEST, iid, instruction=body, requires_reply=needs_reply, **spec)))
        if needs_reply:
            accepted = self._wait_for_reply(iid)
            if accepted is None:
                self._publish_spec(job, body, error=LtlInstructError(
                    'no verification reply in time', ErrorCode.TIMEOUT))
                return
            if not accepted:
                self._publish_spec(job, body, error=LtlInstructError(
                    'the person rejected the formula', ErrorCode.VERIFICATION_FAILED))
                return
        self._publish_spec(job, body, spec=spec, translate_s=elapsed)

    def _load_translator(self) -> None:
        if self._translator is None and self._translator_error is None:
            try:
                from ltl_instruct.core.language import make_translator
                opts = {'model_path': self.params['model_path']} if self.params['model_path'] else {}
                self._translator = make_translator(self.params['backend'], **opts)
                if getattr(self._translator, 'model_error', ''):
                    self.get_logger().warning('the learned translator is not loaded, the rules alone read: '
                                              f'{self._translator.model_error}')
            except ImportError as e:
                self._translator_error = TranslationError(f'translator backend unavailable: {e}',
                                                          ErrorCode.MODEL_ERROR)
            except LtlInstructError as e:
                self._translator_error = e
            except Exception as e:  # noqa: BLE001 - a broken backend fails each instruction, never the worker
                self._translator_error = TranslationError(f'translator backend failed to start: {e!r}',
                                                          ErrorCode.MODEL_ERROR)
            if self._translator_error is not None:
                self.get_logger().error(f'translator: {self._translator_error.message}')
            self._publish_state('ready' if self._translator_error is None else 'failed')

    def _publish_state(self, state: str) -> None:
        """Say on ``~/status`` whether instructions are read yet (``loading``, ``ready``, ``failed``)."""
        if self._closing.is_set():   # the node is being destroyed
            return
        fields: dict[str, Any] = {'state': state, 'backend': self.params['backend']}
        if self._translator_error is not None:
            fields.update(code=self._translator_error.code.value, reason=self._translator_error.message)
        elif getattr(self._translator, 'model_error', ''):
            fields['model_error'] = self._translator.model_error
        status = conv.payload(conv.TRANSLATOR_STATUS, self.get_name(), **fields)
        self.status_pub.publish(conv.json_msg(status))

    def _translate(self, text: str) -> Any:
        self._load_translator()
        if self._translator_error is not None:
            raise self._translator_error
        return self._translator.translate(text)

    def _wait_for_reply(self, iid: str) -> Optional[bool]:
        deadline = time.monotonic() + self.params['confirmation_timeout']
        with self._reply_event:
            while iid not in self._replies:
                left = deadline - time.monotonic()
                if left <= 0 or self._closing.is_set():
                    return None
                self._reply_event.wait(min(left, 0.5))
            return self._replies.pop(iid)

    def _publish_spec(self, job: _Job, instruction: str, spec: Optional[dict[str, Any]] = None,
                      error: Optional[LtlInstructError] = None, translate_s: float = 0.0) -> None:
        """Publish the task spec (or the failure) of a job, and keep it to send again after a restart."""
        iid = job.iid
        fields: dict[str, Any] = dict(instruction=instruction, ok=error is None, id_source=job.id_source,
                                      timing={'translate_s': translate_s,
                                              'queue_s': time.monotonic() - job.received - translate_s})
        if error is not None:
            fields['error'] = error.to_dict()
            self.get_logger().warning(f'{iid}: [{error.code.value}] {error.message}')
        else:
            fields.update(spec or {})
            self.get_logger().info(f'{iid}: {fields["formula"]}')
        payload = conv.payload(conv.TASK_SPEC, iid, **fields)
        with self._ledger_lock:
            self._ledger.sent(iid, payload)
        self.spec_pub.publish(conv.json_msg(payload))


def main(args: Optional[list[str]] = None) -> int:
    """Entry point of the ``ltl_translator`` console script."""
    return run_node(LtlTranslatorNode, args)


if __name__ == '__main__':
    sys.exit(main())

"""JSON payloads of the topics, parsed without ROS: schema checks and the instruction message.

The nodes receive ``std_msgs/String`` messages; what their text means is decided
here, in the core, so that it is tested without ROS. ``ltl_instruct.conversions``
re-exports these names for the nodes.
"""
from __future__ import annotations

import json
import re
from typing import Any, Optional

from ltl_instruct.core.errors import InvalidInputError, LimitExceededError

SCHEMA_VERSION = 1
MAX_PAYLOAD_BYTES = 1_000_000
INSTRUCTION = 'ltl_instruct/instruction'


def parse_json_payload(text: str, schema: Optional[str] = None,
                       max_bytes: int = MAX_PAYLOAD_BYTES) -> dict[str, Any]:
    """Parse a JSON payload and check its schema name, version and ``id``.

    Raises
    ------
    LimitExceededError
        If the text is longer than ``max_bytes``.
    InvalidInputError
        On invalid JSON, a non-object, a wrong schema or version, or a missing ``id``.
    """
    data = _json_object(text, max_bytes)
    if schema is not None:
        _check_schema(data, schema)
    _check_id(data)
    return data


def _json_object(text: str, max_bytes: int = MAX_PAYLOAD_BYTES) -> dict[str, Any]:
    if len(text) > max_bytes:
        raise LimitExceededError(f'payload of {len(text)} bytes exceeds the limit of {max_bytes}')
    try:
        data = json.loads(text)
    except (ValueError, RecursionError) as e:
        raise InvalidInputError(f'not valid JSON: {str(e)[:200]}') from None
    if not isinstance(data, dict):
        raise InvalidInputError(f'expected a JSON object, got {type(data).__name__}')
    return data


def _check_schema(data: dict[str, Any], schema: str) -> None:
    if data.get('schema') != schema:
        raise InvalidInputError(f'expected schema {schema!r}, got {str(data.get("schema"))[:80]!r}',
                                details={'id': safe_id(data.get('id'))})
    if data.get('version') != SCHEMA_VERSION:
        raise InvalidInputError(f'unsupported {schema} version {data.get("version")!r} '
                                f'(expected {SCHEMA_VERSION})', details={'id': safe_id(data.get('id'))})


def _check_id(data: dict[str, Any]) -> None:
    if not isinstance(data.get('id'), str) or not data['id'] or len(data['id']) > 200:
        raise InvalidInputError('payload has no valid "id" (non-empty text up to 200 characters)')


def revision_of(data: dict[str, Any], default: int = 0) -> int:
    """Return a payload's ``revision`` (``default`` when it is missing or not a whole number)."""
    value = data.get('revision', default)
    return value if isinstance(value, int) and not isinstance(value, bool) else default


def timing_of(data: dict[str, Any]) -> dict[str, float]:
    """Return the stage times [s] a payload carries (its ``timing`` object; anything else is none)."""
    timing = data.get('timing')
    if not isinstance(timing, dict):
        return {}
    return {str(k): float(v) for k, v in timing.items()
            if isinstance(v, (int, float)) and not isinstance(v, bool)}


def safe_id(value: Any) -> str:
    """Return ``value`` cut to 200 characters if it is text, else ''."""
    return value[:200] if isinstance(value, str) else ''


_ID_PATTERN = re.compile(r'"id"\s*:\s*"([A-Za-z0-9_.:#/@+-]{1,200})"')


def salvage_id(text: str) -> str:
    """Return the ``id`` of a payload that failed validation, when one can be read, else ''."""
    try:
        data = json.loads(text[:MAX_PAYLOAD_BYTES])
    except (ValueError, RecursionError):
        # truncated or broken JSON: the id may still be readable
        m = _ID_PATTERN.search(text[:10000])
        return m.group(1) if m else ''
    return safe_id(data.get('id')) if isinstance(data, dict) else ''


# JSON values that are not text: null, true, false, numbers (NaN, Infinity too), arrays
_JSON_NON_TEXT = re.compile(r'(?:null|true|false|NaN|-?Infinity|[-+]?[0-9.][0-9.eE+-]*|\[.*)\Z', re.DOTALL)


def read_instruction(text: Any, fallback_id: str, limit: int = 2000) -> tuple[str, str, Optional[str]]:
    """Read an ``instruction`` message: ``(id, text, formula or None)``.

    The message is plain English, or a JSON object ``{"id": ..., "text": ...}`` (or
    ``"formula"`` instead of ``"text"``; ``"schema": "ltl_instruct/instruction"`` and
    ``"version": 1`` may be given, and are checked when they are). An instruction without an
    ``id`` gets ``fallback_id``. A JSON string (``"go to the hall"``) is read as its text.

    Raises
    ------
    InvalidInputError
        A message that is not text: JSON ``null``, ``true``, ``false``, a number or an
        array; an object with no text or formula, or with ones that are not strings; an
        empty message.
    LimitExceededError
        Text or formula longer than ``limit`` characters.
    """
    if not isinstance(text, str):
        raise InvalidInputError(f'an instruction must be text, not {type(text).__name__}')
    stripped = text.strip()
    if stripped.startswith('{'):
        data = _instruction_object(stripped, fallback_id)
        body, formula = data.get('text', ''), data.get('formula')
        if not isinstance(body, str) or (formula is not None and not isinstance(formula, str)):
            raise InvalidInputError('instruction "text" and "formula" must be strings',
                                    details={'id': data['id']})
        if not body.strip() and not formula:
            raise InvalidInputError('instruction has neither "text" nor "formula"',
                                    details={'id': data['id']})
        if len(body) > limit or (formula and len(formula) > limit):
            raise LimitExceededError(f'instruction longer than {limit} characters',
                                     details={'id': data['id']})
        return data['id'], body, formula
    if len(text) > limit:
        raise LimitExceededError(f'instruction of {len(text)} characters exceeds the limit of {limit}')
    if not stripped:
        raise InvalidInputError('empty instruction')
    if _JSON_NON_TEXT.match(stripped) or stripped.startswith('"'):
        try:
            value = json.loads(stripped)
        except (ValueError, RecursionError):
            value = stripped   # "[kitchen] then the hall", "3rd floor": English, not JSON
        if isinstance(value, str):
            if value is not stripped:   # a JSON string: its content is the instruction
                if not value.strip():
                    raise InvalidInputError('empty instruction')
                return fallback_id, value, None
        else:
            kind = 'null' if value is None else type(value).__name__
            raise InvalidInputError(f'an instruction must be English text or a JSON object, '
                                    f'not the JSON value {stripped[:40]!r} ({kind})')
    return fallback_id, text, None


def _instruction_object(text: str, fallback_id: str) -> dict[str, Any]:
    """Parse an instruction JSON object: schema and version checked when given, ``id`` defaulting."""
    data = _json_object(text)
    if 'schema' in data or 'version' in data:
        _check_schema(data, INSTRUCTION)
    data.setdefault('id', fallback_id)
    _check_id(data)
    return data


def read_cancel(text: Any) -> str:
    """Read a ``cancel`` message: the id to cancel, as plain text or a JSON object ``{"id": ...}``.

    Raises
    ------
    InvalidInputError
        Anything else: empty text, JSON that is not a string or an object with an ``id``
        (``null``, numbers, arrays), an id longer than 200 characters.
    """
    if not isinstance(text, str):
        raise InvalidInputError(f'a cancel must be text, not {type(text).__name__}')
    stripped = text.strip()
    value: Any = stripped
    if stripped.startswith(('{', '"')) or _JSON_NON_TEXT.match(stripped):
        try:
            value = json.loads(stripped[:MAX_PAYLOAD_BYTES])
        except (ValueError, RecursionError):
            raise InvalidInputError(f'cancel is not valid JSON: {stripped[:40]!r}') from None
    if isinstance(value, dict):
        value = value.get('id')
    if not isinstance(value, str) or not value.strip() or len(value) > 200:
        raise InvalidInputError('a cancel names the id of an instruction (text up to 200 characters, or '
                                f'{{"id": ...}}), not {stripped[:40]!r}')
    return value.strip()

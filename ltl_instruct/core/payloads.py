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
    if len(text) > max_bytes:
        raise LimitExceededError(f'payload of {len(text)} bytes exceeds the limit of {max_bytes}')
    try:
        data = json.loads(text)
    except (ValueError, RecursionError) as e:
        raise InvalidInputError(f'not valid JSON: {str(e)[:200]}') from None
    if not isinstance(data, dict):
        raise InvalidInputError(f'expected a JSON object, got {type(data).__name__}')
    if schema is not None and data.get('schema') != schema:
        raise InvalidInputError(f'expected schema {schema!r}, got {str(data.get("schema"))[:80]!r}',
                                details={'id': safe_id(data.get('id'))})
    if schema is not None and data.get('version') != SCHEMA_VERSION:
        raise InvalidInputError(f'unsupported {schema} version {data.get("version")!r} '
                                f'(expected {SCHEMA_VERSION})', details={'id': safe_id(data.get('id'))})
    if not isinstance(data.get('id'), str) or not data['id'] or len(data['id']) > 200:
        raise InvalidInputError('payload has no valid "id" (non-empty text up to 200 characters)')
    return data


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

    The message is plain English, or a JSON payload ``{"schema": "ltl_instruct/instruction",
    "version": 1, "id": ..., "text": ...}`` (or ``"formula"`` instead of ``"text"``). A JSON
    string (``"go to the hall"``) is read as its text.

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
        data = parse_json_payload(stripped, INSTRUCTION)
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

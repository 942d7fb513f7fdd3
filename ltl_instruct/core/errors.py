"""One root exception for the whole core, and a typed error code per failure.

Every stage raises a subclass of :class:`LtlInstructError`; its ``code`` is one of
:class:`ErrorCode` (as Nav2 does for planners), so that a node can put the code and
the human-readable message on ``task_status`` without knowing the stage.
"""
from __future__ import annotations

import enum
from typing import Any


class ErrorCode(str, enum.Enum):
    """Typed error codes, one per way a stage can fail."""

    PARSE_ERROR = 'PARSE_ERROR'              # malformed formula text
    LIMIT_EXCEEDED = 'LIMIT_EXCEEDED'        # input too long, too deep, too many atoms
    INVALID_INPUT = 'INVALID_INPUT'          # garbage JSON, NaN pose, wrong schema
    FRAME_MISMATCH = 'FRAME_MISMATCH'        # a pose or map in a frame this robot cannot place in its map
    TRANSLATION_ERROR = 'TRANSLATION_ERROR'  # instruction could not be translated
    UNSATISFIABLE = 'UNSATISFIABLE'          # no accepting automaton state reachable
    UNKNOWN_REFERENT = 'UNKNOWN_REFERENT'    # nothing of that name is known
    NO_MATCH = 'NO_MATCH'                    # detected, but no instance satisfies relations
    AMBIGUOUS_REFERENT = 'AMBIGUOUS_REFERENT'  # several instances where one is meant
    SCENE_ERROR = 'SCENE_ERROR'              # malformed scene file
    START_OCCUPIED = 'START_OCCUPIED'        # start pose in collision or in an avoid region
    GOAL_OCCUPIED = 'GOAL_OCCUPIED'          # every goal region is blocked
    NO_VALID_PATH = 'NO_VALID_PATH'          # the planner found no path
    VERIFICATION_FAILED = 'VERIFICATION_FAILED'  # a plan failed the independent check
    TIMEOUT = 'TIMEOUT'                      # a stage ran out of time
    SKILL_FAILED = 'SKILL_FAILED'            # pick or release did not succeed
    MODEL_ERROR = 'MODEL_ERROR'              # a model could not be loaded or answered badly
    INTERNAL_ERROR = 'INTERNAL_ERROR'        # a bug: reported, never swallowed


class LtlInstructError(Exception):
    """Root of every error the core raises.

    Parameters
    ----------
    message:
        Human-readable reason, shown to the person on ``task_status``.
    code:
        The typed error code; subclasses set a default.
    details:
        Optional JSON-serialisable facts (column, transition, referent...).
    """

    default_code: ErrorCode = ErrorCode.INTERNAL_ERROR

    def __init__(self, message: str, code: ErrorCode | None = None,
                 details: dict[str, Any] | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.code = code or self.default_code
        self.details = dict(details or {})

    def to_dict(self) -> dict[str, Any]:
        """Return ``{'code', 'message', 'details'}`` for JSON payloads."""
        return {'code': self.code.value, 'message': self.message, 'details': self.details}


class FormulaSyntaxError(LtlInstructError):
    """A formula text does not follow the grammar of spec/formula.md."""

    default_code = ErrorCode.PARSE_ERROR


class LimitExceededError(LtlInstructError):
    """An input is larger than a configured limit (length, depth, atoms)."""

    default_code = ErrorCode.LIMIT_EXCEEDED


class InvalidInputError(LtlInstructError):
    """An input is malformed (bad JSON, wrong schema, NaN...)."""

    default_code = ErrorCode.INVALID_INPUT


class FrameMismatchError(InvalidInputError):
    """A stamped input is in a frame that cannot be placed in the robot's map frame."""

    default_code = ErrorCode.FRAME_MISMATCH


class UnsatisfiableError(LtlInstructError):
    """A task cannot be satisfied (automaton-level or geometric)."""

    default_code = ErrorCode.UNSATISFIABLE


class TranslationError(LtlInstructError):
    """An instruction could not be translated into a formula."""

    default_code = ErrorCode.TRANSLATION_ERROR


class GroundingError(LtlInstructError):
    """A descriptor could not be resolved to instances."""

    default_code = ErrorCode.UNKNOWN_REFERENT


class SceneError(LtlInstructError):
    """A scene file is malformed."""

    default_code = ErrorCode.SCENE_ERROR


class PlanningError(LtlInstructError):
    """Motion or task planning failed."""

    default_code = ErrorCode.NO_VALID_PATH

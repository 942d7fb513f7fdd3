"""The referent semantic map (RSM): for every descriptor, the instances it denotes.

This is the contract between grounding (which fills it) and planning (which turns
``near[x]`` into regions). Positions are in the ``map`` frame [m].
"""
from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import Any, Mapping, Optional

import numpy as np

from ltl_instruct.core.world import near


class Outcome(str, enum.Enum):
    """How resolving one descriptor ended."""

    RESOLVED = 'RESOLVED'                  # exactly one instance (every instance, if only avoided)
    AMBIGUOUS = 'AMBIGUOUS'                # several instances satisfy it
    UNKNOWN_REFERENT = 'UNKNOWN_REFERENT'  # nothing of that name detected
    NO_MATCH = 'NO_MATCH'                  # detected, but none satisfies the relations


@dataclass(frozen=True)
class Instance:
    """One detected or known object.

    Attributes
    ----------
    id: unique id in the map (``red_sofa``, ``chair_2``, ``det_17``).
    label: class or free-text label (``red sofa``).
    center: representative point [m], shape (3,).
    size: axis-aligned extent [m], shape (3,); zeros for a point.
    confidence: detection confidence in [0, 1] (1 for known objects).
    observations: number of frames that saw it (0 for known objects).
    """

    id: str
    label: str
    center: tuple[float, float, float]
    size: tuple[float, float, float] = (0.0, 0.0, 0.0)
    confidence: float = 1.0
    observations: int = 0

    def distance(self, points: np.ndarray, dims: int = 3) -> np.ndarray:
        """Distance [m] from points (N, >=dims) to this instance's box (0 inside), shape (N,)."""
        return near.box_distance(points, np.asarray([self.center]), np.asarray([self.size]), dims)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'id': self.id, 'label': self.label, 'center': list(self.center),
                'size': list(self.size), 'confidence': self.confidence,
                'observations': self.observations}

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'Instance':
        """Inverse of :meth:`to_dict`."""
        return Instance(str(d['id']), str(d.get('label', d['id'])),
                        tuple(float(x) for x in d['center']),  # type: ignore[arg-type]
                        tuple(float(x) for x in d.get('size', (0.0, 0.0, 0.0))),  # type: ignore[arg-type]
                        float(d.get('confidence', 1.0)), int(d.get('observations', 0)))


@dataclass(frozen=True)
class Grounding:
    """What one descriptor resolved to, and why."""

    descriptor: str
    outcome: Outcome
    instances: tuple[Instance, ...] = ()
    explanation: tuple[str, ...] = ()
    # False when the descriptor only occurs under a negation (``G !near[door]``): finding
    # nothing is then harmless, and several instances are all meant (not ambiguous).
    required: bool = True

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'descriptor': self.descriptor, 'outcome': self.outcome.value,
                'instances': [i.to_dict() for i in self.instances],
                'explanation': list(self.explanation), 'required': self.required}

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'Grounding':
        """Inverse of :meth:`to_dict`."""
        return Grounding(str(d['descriptor']), Outcome(d['outcome']),
                         tuple(Instance.from_dict(i) for i in d.get('instances', [])),
                         tuple(str(e) for e in d.get('explanation', [])),
                         bool(d.get('required', True)))


@dataclass(frozen=True)
class ReferentMap:
    """Descriptor text (as printed, e.g. ``sofa::isbehind(pillar)``) -> grounding."""

    groundings: Mapping[str, Grounding] = field(default_factory=dict)
    frame_id: str = 'map'

    def instances(self, descriptor: str) -> tuple[Instance, ...]:
        """Instances a descriptor resolved to (empty if unknown)."""
        g = self.groundings.get(descriptor)
        return g.instances if g else ()

    def get(self, descriptor: str) -> Optional[Grounding]:
        """Return the grounding of a descriptor, or None."""
        return self.groundings.get(descriptor)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict."""
        return {'frame_id': self.frame_id,
                'groundings': {k: g.to_dict() for k, g in self.groundings.items()}}

    @staticmethod
    def from_dict(d: Mapping[str, Any]) -> 'ReferentMap':
        """Inverse of :meth:`to_dict`."""
        return ReferentMap({k: Grounding.from_dict(g) for k, g in d.get('groundings', {}).items()},
                           str(d.get('frame_id', 'map')))

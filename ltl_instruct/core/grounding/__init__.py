"""Spatial grounding: comparators, descriptor resolution, semantic maps, detectors.

Public entry points: :func:`ground_formula` (formula + instances -> referent map),
:func:`instances_from_scene` (a scene's known object list), :class:`GroundingParams`,
:func:`grounding_error`, and the voxel :class:`SemanticMap` built from RGB-D frames.
"""
from ltl_instruct.core.grounding.comparators import GroundingParams  # noqa: F401
from ltl_instruct.core.grounding.names import NameMatcher  # noqa: F401
from ltl_instruct.core.grounding.resolve import (  # noqa: F401
    Resolution, Resolver, ground_formula, grounding_error, instances_from_scene, required_referents,
)
from ltl_instruct.core.grounding.rsm import Grounding, Instance, Outcome, ReferentMap  # noqa: F401
from ltl_instruct.core.grounding.semantic_map import SemanticMap, SemanticMapParams  # noqa: F401

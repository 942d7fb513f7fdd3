"""Spatial grounding: comparators, descriptor resolution, semantic maps, detectors."""

"""Worlds: scene files, synthetic RGB-D camera, kinematic robot."""

"""Scenes of the search tests (core and node graph alike)."""
from __future__ import annotations


def wall(x0: float, y0: float, x1: float, y1: float) -> dict:
    """Return a 0.2 m thick, 2.5 m high wall from (x0, y0) to (x1, y1) [m] (axis-aligned)."""
    return {'center': [(x0 + x1) / 2, (y0 + y1) / 2, 1.25],
            'size': [max(abs(x1 - x0), 0.2), max(abs(y1 - y0), 0.2), 2.5]}


# two rooms (x 0..5 and 5..10) joined by a doorway at y 4.5..5.8 in the wall at x = 5; the vase
# stands in the second room, the crate in sight of the start (facing +x), and the piano is shut
# in a storeroom (a block no camera sees into)
SEARCH_ROOMS = {
    'name': 'search_rooms',
    'bounds': {'min': [0, 0, 0], 'max': [10, 6, 3]},
    'robot': {'kind': 'ground', 'start': [1.0, 1.0, 0.0], 'radius': 0.3},
    'obstacles': [wall(0, 0.1, 10, 0.1), wall(0, 5.9, 10, 5.9), wall(0.1, 0, 0.1, 6),
                  wall(9.9, 0, 9.9, 6), wall(5.0, 0, 5.0, 4.5),
                  {'center': [8.9, 4.9, 1.25], 'size': [1.6, 1.6, 2.5]}],
    'objects': [{'label': 'vase', 'center': [8.5, 1.0, 0.3], 'size': [0.4, 0.4, 0.6]},
                {'label': 'crate', 'center': [3.0, 1.8, 0.25], 'size': [0.6, 0.6, 0.5]},
                {'label': 'piano', 'center': [8.9, 4.9, 0.5], 'size': [0.8, 0.5, 1.0]}],
}

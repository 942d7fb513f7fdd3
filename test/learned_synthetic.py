"""A tiny synthetic city for the learned-parser tests: landmarks, trajectories, instructions.

Built in the test run (no shared datasets): six landmarks on a small grid near
Providence, trajectories simulated with k-th shortest paths, and instructions
from a few templates that name the start, the waypoints and the goal.
"""
from __future__ import annotations

import csv
import json
import os

import numpy as np

from ltl_instruct.core.language.learned.data import Demonstration
from ltl_instruct.core.world.landmarks import build_landmark_map, simulate_trajectory

NAMES = ('Blue Cafe', 'Old Library', 'City Hall', 'Rose Garden', 'Train Station', 'Art Museum')
LAT_LON = np.array([[41.8260, -71.4030], [41.8260, -71.4010], [41.8275, -71.4030],
                    [41.8275, -71.4010], [41.8290, -71.4030], [41.8290, -71.4010]])
TEMPLATES = ('start at {s} and go to {w} then {g}', 'from the {s} walk past {w} to the {g}',
             'begin at {s}, pass the {w} and stop at the {g}', 'go from {s} to {g}')


def synthetic_map():
    """Build the landmark graph of the synthetic city."""
    return build_landmark_map('testville', NAMES, LAT_LON)


def synthetic_demonstrations(n: int = 60, seed: int = 3) -> list[Demonstration]:
    """``n`` demonstrations on simulated trajectories with templated instructions."""
    lmap = synthetic_map()
    rng = np.random.default_rng(seed)
    graph = lmap.graph()
    demos = []
    while len(demos) < n:
        path = tuple(simulate_trajectory(lmap, rng, graph=graph))
        names = [NAMES[v].lower() for v in path]
        mid = ', '.join(names[1:-1]) if len(path) > 2 else names[0]
        template = TEMPLATES[int(rng.integers(len(TEMPLATES)))]
        demos.append(Demonstration(template.format(s=names[0], w=mid, g=names[-1]), path))
    return demos


def write_dataset(folder: str, city: str = 'testville', n: int = 60) -> None:
    """Write the synthetic city in the osm-trajectories layout (with two bad rows)."""
    os.makedirs(os.path.join(folder, 'instructions'), exist_ok=True)
    os.makedirs(os.path.join(folder, 'maps'), exist_ok=True)
    demos = synthetic_demonstrations(n)
    maps = {}
    with open(os.path.join(folder, 'instructions', f'{city}.tsv'), 'w', newline='') as f:
        w = csv.writer(f, delimiter='\t')
        w.writerow(['map_name', 'utterance', 'trajectory', 'path_names', 'path_idxs'])
        for i, d in enumerate(demos):
            fig = f'path_{i}.png'
            w.writerow([city, d.instruction, '|'.join(NAMES[v] for v in d.path),
                        '|'.join(str(v) for v in d.path), fig])
            maps[str(i)] = {'map_name': city, 'path': list(d.path), 'alt_path': list(d.path),
                            'landmark_centers': LAT_LON.tolist(), 'landmark_names': list(NAMES),
                            'fig_name': fig}
        w.writerow([city, 'NA', 'x|y', '0|1', 'path_0.png'])
        w.writerow([city, 'too few columns'])
    with open(os.path.join(folder, 'maps', f'{city}.json'), 'w') as f:
        json.dump(maps, f)

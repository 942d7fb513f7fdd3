"""The osm-trajectories data: instructions with demonstrated landmark trajectories, and the test split.

Layout of a data folder (``../shared/datasets/osm-trajectories``)::

    instructions/<city>.tsv   map_name, utterance, trajectory (names, '|'), path_names (ids, '|'), path_idxs
    maps/<city>.json          per path: landmark_centers (lat, lon), landmark_names, path, alt_path, fig_name

Rows with ``NA`` or an empty utterance, the wrong number of columns, node ids
that are not landmarks of the map, or a path of fewer than two landmarks are
skipped and counted. Each row's alternative path (``alt_path`` of the map entry
named by ``path_idxs``) is kept when it is known.

Test split: every distinct trajectory (its node-id path) is ranked by the
SHA-256 of ``"ltl_instruct-osm-test-v1|<city>|<ids joined by '-'>"``; the 100
lowest-ranked trajectories are the test set, and every instruction of them is a
test example, so no instruction of a test trajectory is ever trained on.
"""
from __future__ import annotations

import csv
import hashlib
import json
import os
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ltl_instruct.core.errors import InvalidInputError
from ltl_instruct.core.world.landmarks import LandmarkMap, build_landmark_map

SPLIT_SALT = 'ltl_instruct-osm-test-v1'
TEST_TRAJECTORIES = 100
MAX_UTTERANCE_CHARS = 2000


@dataclass(frozen=True)
class Demonstration:
    """One instruction and the landmark trajectory it was written for.

    Attributes
    ----------
    instruction: the text written by a person.
    path: landmark node ids visited, start first.
    alt_path: another path with the same start and end, if the map gives one.
    """

    instruction: str
    path: tuple[int, ...]
    alt_path: Optional[tuple[int, ...]] = None


@dataclass(frozen=True)
class CityData:
    """A city's landmark names and centres, demonstrations, and the number of rows skipped."""

    city: str
    names: tuple[str, ...]
    lat_lon_deg: np.ndarray  # (n, 2) [deg]
    demonstrations: tuple[Demonstration, ...]
    skipped_rows: int

    def landmark_map(self, demonstrations: tuple[Demonstration, ...] = ()) -> LandmarkMap:
        """Delaunay landmark graph plus the steps taken in ``demonstrations`` (give the training ones)."""
        steps = {(a, b) for d in demonstrations for a, b in zip(d.path, d.path[1:])}
        return build_landmark_map(self.city, self.names, self.lat_lon_deg, sorted(steps))


def _read_json(path: str) -> dict:
    try:
        with open(path, encoding='utf-8') as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise InvalidInputError(f'cannot read map file {path}: {e}') from e
    if not isinstance(data, dict) or not data:
        raise InvalidInputError(f'map file {path} holds no paths')
    return data


def load_city(data_dir: str, city: str) -> CityData:
    """Read one city of an osm-trajectories folder; raises ``InvalidInputError`` if unusable."""
    if not city or '/' in city or city.startswith('.'):
        raise InvalidInputError(f'bad city name {city!r}')
    maps = _read_json(os.path.join(data_dir, 'maps', f'{city}.json'))
    entries = [v for v in maps.values() if isinstance(v, dict)]
    try:
        first = entries[0]
        names = tuple(str(n) for n in first['landmark_names'])
        lat_lon = np.asarray(first['landmark_centers'], dtype=float)
    except (IndexError, KeyError, TypeError, ValueError) as e:
        raise InvalidInputError(f'map of {city!r} lacks landmark_names/landmark_centers: {e}') from e
    if lat_lon.shape != (len(names), 2) or len(names) < 2:
        raise InvalidInputError(f'map of {city!r}: {len(names)} names but centres of shape {lat_lon.shape}')
    n = len(names)
    alt_by_figure: dict[str, tuple[int, ...]] = {}
    for e in entries:
        alt = e.get('alt_path')
        if isinstance(e.get('fig_name'), str) and isinstance(alt, list) \
                and all(isinstance(v, int) and 0 <= v < n for v in alt) and len(alt) >= 2:
            alt_by_figure[e['fig_name']] = tuple(alt)
    tsv = os.path.join(data_dir, 'instructions', f'{city}.tsv')
    demos: list[Demonstration] = []
    skipped = 0
    try:
        with open(tsv, encoding='utf-8', newline='') as f:
            rows = list(csv.reader(f, delimiter='\t'))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise InvalidInputError(f'cannot read instructions {tsv}: {e}') from e
    for row in rows[1:]:
        demo = _parse_row(row, n, alt_by_figure)
        if demo is None:
            skipped += 1
        else:
            demos.append(demo)
    if not demos:
        raise InvalidInputError(f'no usable instructions for {city!r} in {tsv}')
    return CityData(city, names, lat_lon, tuple(demos), skipped)


def _parse_row(row: list[str], n: int, alt_by_figure: dict[str, tuple[int, ...]]) -> Optional[Demonstration]:
    if len(row) != 5:
        return None
    text = row[1].strip()
    if not text or text.upper() == 'NA' or len(text) > MAX_UTTERANCE_CHARS:
        return None
    try:
        path = tuple(int(v) for v in row[3].split('|'))
    except ValueError:
        return None
    if len(path) < 2 or any(not 0 <= v < n for v in path) or any(a == b for a, b in zip(path, path[1:])):
        return None
    alt = alt_by_figure.get(row[4].strip())
    if alt is not None and (alt[0] != path[0] or alt[-1] != path[-1] or alt == path):
        alt = None
    return Demonstration(text, path, alt)


def trajectory_rank(city: str, path: tuple[int, ...]) -> str:
    """Hash that orders trajectories for the test split (hex SHA-256)."""
    key = f'{SPLIT_SALT}|{city}|' + '-'.join(str(v) for v in path)
    return hashlib.sha256(key.encode('utf-8')).hexdigest()


def split_train_test(data: CityData, test_trajectories: int = TEST_TRAJECTORIES
                     ) -> tuple[tuple[Demonstration, ...], tuple[Demonstration, ...]]:
    """(train, test) demonstrations: all instructions of the lowest-hashed trajectories are test.

    With fewer than ``2 * test_trajectories`` distinct trajectories, a quarter of them are test.
    """
    paths = sorted({d.path for d in data.demonstrations}, key=lambda p: trajectory_rank(data.city, p))
    n_test = test_trajectories if len(paths) >= 2 * test_trajectories else max(1, len(paths) // 4)
    test_paths = set(paths[:n_test])
    train = tuple(d for d in data.demonstrations if d.path not in test_paths)
    test = tuple(d for d in data.demonstrations if d.path in test_paths)
    return train, test

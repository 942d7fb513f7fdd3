"""City maps as graphs of named landmarks, and simulated trajectories over them.

A city map lists landmarks by name with a (latitude, longitude) centre. This
module puts the centres into a local metric frame (x east, y north, metres, an
equirectangular projection about the mean latitude, accurate to well under a
metre over the few kilometres of a campus map), joins neighbouring landmarks by
the edges of a Delaunay triangulation (plus any extra edges the caller knows
of, e.g. from demonstrations), and weighs each edge by its length in metres.

For maps without demonstrations, :func:`simulate_trajectory` picks a start and
an end uniformly and returns the k-th shortest simple path between them, with k
drawn from a geometric distribution (p = 0.2), so that paths are not always the
shortest.
"""
from __future__ import annotations

import functools
import itertools
import math
import re
from dataclasses import dataclass
from typing import Iterable, Optional, Sequence

import networkx as nx
import numpy as np
from scipy.spatial import Delaunay, QhullError

from ltl_instruct.core.errors import InvalidInputError, PlanningError

# Mean Earth radius [m] (spherical model; the error is negligible at city scale).
EARTH_RADIUS_M = 6_371_008.8
# Names that the formula grammar reserves; a landmark called so gets a suffix.
_RESERVED = frozenset({'true', 'false', 'near', 'pick', 'release'})


def snake_case_name(name: str) -> str:
    """Make the proposition for a landmark name: lower-case snake_case, as the grammar wants.

    ``"Busch-Reisinger Museum"`` becomes ``busch_reisinger_museum``; a name that
    would start with a digit gets a leading ``l_``; reserved words get ``_place``.
    """
    ascii_name = name.encode('ascii', 'ignore').decode('ascii').lower()
    text = re.sub(r'[^a-z0-9]+', '_', ascii_name).strip('_')
    if not text:
        text = 'landmark'
    if not text[0].isalpha():
        text = 'l_' + text
    if text in _RESERVED:
        text += '_place'
    return text


def unique_snake_case_names(names: Sequence[str]) -> tuple[str, ...]:
    """:func:`snake_case_name` of each name, made unique by suffixes ``_2``, ``_3``..."""
    seen: dict[str, int] = {}
    out = []
    for n in names:
        base = snake_case_name(n)
        k = seen.get(base, 0) + 1
        seen[base] = k
        out.append(base if k == 1 else f'{base}_{k}')
    if len(set(out)) != len(out):  # a suffixed name collided with a real one
        out = [f'{o}_{i}' for i, o in enumerate(out)]
    return tuple(out)


def local_metric_frame(lat_lon_deg: np.ndarray) -> np.ndarray:
    """Project (lat, lon) [deg], shape (n, 2), to local (x east, y north) [m], shape (n, 2).

    The origin is the mean of the points. Raises ``InvalidInputError`` on NaN,
    infinite or out-of-range coordinates.
    """
    ll = np.asarray(lat_lon_deg, dtype=float)
    if ll.ndim != 2 or ll.shape[1] != 2 or len(ll) == 0:
        raise InvalidInputError(f'landmark centres must have shape (n, 2), got {ll.shape}')
    if not np.all(np.isfinite(ll)) or np.any(np.abs(ll[:, 0]) > 90) or np.any(np.abs(ll[:, 1]) > 180):
        raise InvalidInputError('landmark centres must be finite (lat, lon) in degrees')
    lat0 = math.radians(float(ll[:, 0].mean()))
    lon0 = float(ll[:, 1].mean())
    lat_c = float(ll[:, 0].mean())
    x = np.radians(ll[:, 1] - lon0) * math.cos(lat0) * EARTH_RADIUS_M
    y = np.radians(ll[:, 0] - lat_c) * EARTH_RADIUS_M
    return np.stack([x, y], axis=1)


def delaunay_edges(xy: np.ndarray) -> frozenset[tuple[int, int]]:
    """Undirected edges ``(i, j)``, i < j, of the Delaunay triangulation of points (n, 2) [m].

    With fewer than three points, or points all on one line, neighbours along
    the line (sorted by position) are joined instead.
    """
    n = len(xy)
    if n < 2:
        return frozenset()
    try:
        if n < 3:
            raise QhullError('too few points')
        tri = Delaunay(xy)
    except QhullError:
        # degenerate layout: chain the points along their principal direction
        centred = xy - xy.mean(axis=0)
        direction = np.linalg.svd(centred, full_matrices=False)[2][0]
        order = np.argsort(centred @ direction)
        return frozenset((min(int(a), int(b)), max(int(a), int(b))) for a, b in zip(order, order[1:]))
    edges = set()
    for simplex in tri.simplices:
        for a, b in itertools.combinations(simplex, 2):
            edges.add((min(int(a), int(b)), max(int(a), int(b))))
    return frozenset(edges)


@dataclass(frozen=True)
class LandmarkMap:
    """A city map as a weighted graph of named landmarks.

    Attributes
    ----------
    city: the map's name.
    names: landmark names as written in the map, index = node id.
    props: the landmarks' propositions (snake_case, unique), index = node id.
    xy: landmark centres in the local metric frame [m], shape (n, 2).
    edges: undirected edges ``(i, j)``, i < j.
    """

    city: str
    names: tuple[str, ...]
    props: tuple[str, ...]
    xy: np.ndarray
    edges: frozenset[tuple[int, int]]

    @property
    def num_landmarks(self) -> int:
        """Number of landmarks (nodes)."""
        return len(self.names)

    def edge_length(self, i: int, j: int) -> float:
        """Straight-line length of edge i-j [m]."""
        return float(np.linalg.norm(self.xy[i] - self.xy[j]))

    def graph(self) -> nx.Graph:
        """Build the map as a networkx graph, edge attribute ``weight`` [m]."""
        g = nx.Graph()
        g.add_nodes_from(range(self.num_landmarks))
        for i, j in sorted(self.edges):
            g.add_edge(i, j, weight=self.edge_length(i, j))
        return g

    @functools.cached_property
    def adjacency(self) -> tuple[tuple[tuple[int, float], ...], ...]:
        """Adjacency of the graph, built once per map: item i is ((j, length [m]), ...), sorted by j.

        The map is immutable, so every plan on it shares this one structure.
        """
        adj: list[list[tuple[int, float]]] = [[] for _ in range(self.num_landmarks)]
        for i, j in sorted(self.edges):
            d = self.edge_length(i, j)
            adj[i].append((j, d))
            adj[j].append((i, d))
        return tuple(tuple(sorted(a)) for a in adj)

    def neighbours(self) -> list[list[tuple[int, float]]]:
        """Adjacency lists, a fresh copy of :attr:`adjacency`: item i is [(j, length [m]), ...]."""
        return [list(a) for a in self.adjacency]

    def path_length(self, path: Sequence[int]) -> float:
        """Length of a node path [m] (straight segments between centres)."""
        return float(sum(self.edge_length(a, b) for a, b in zip(path, path[1:])))

    def to_dict(self) -> dict:
        """JSON-ready form (saved inside trained models)."""
        return {'city': self.city, 'names': list(self.names), 'props': list(self.props),
                'xy': self.xy.tolist(), 'edges': sorted([list(e) for e in self.edges])}

    @staticmethod
    def from_dict(d: dict) -> 'LandmarkMap':
        """Inverse of :meth:`to_dict`; raises ``InvalidInputError`` on a malformed dict."""
        try:
            xy = np.asarray(d['xy'], dtype=float).reshape(-1, 2)
            names = tuple(str(n) for n in d['names'])
            props = tuple(str(p) for p in d['props'])
            edges = frozenset((int(a), int(b)) for a, b in d['edges'])
            city = str(d['city'])
        except (KeyError, TypeError, ValueError) as e:
            raise InvalidInputError(f'malformed landmark map: {e}') from e
        n = len(names)
        if len(props) != n or len(xy) != n or any(not (0 <= a < b < n) for a, b in edges):
            raise InvalidInputError('malformed landmark map: sizes or edges do not agree')
        return LandmarkMap(city, names, props, xy, edges)


def build_landmark_map(city: str, names: Sequence[str], lat_lon_deg: np.ndarray,
                       extra_edges: Iterable[tuple[int, int]] = ()) -> LandmarkMap:
    """Landmark graph of a city map: Delaunay edges of the projected centres plus ``extra_edges``.

    Parameters
    ----------
    city: the map's name.
    names: landmark names, index = node id.
    lat_lon_deg: landmark centres (lat, lon) [deg], shape (n, 2).
    extra_edges: further undirected edges (node id pairs), e.g. steps of demonstrations.
    """
    xy = local_metric_frame(lat_lon_deg)
    if len(names) != len(xy):
        raise InvalidInputError(f'{len(names)} names for {len(xy)} landmark centres')
    edges = set(delaunay_edges(xy))
    n = len(names)
    for a, b in extra_edges:
        a, b = int(a), int(b)
        if not (0 <= a < n and 0 <= b < n):
            raise InvalidInputError(f'edge ({a}, {b}) names a landmark outside 0..{n - 1}')
        if a != b:
            edges.add((min(a, b), max(a, b)))
    return LandmarkMap(city, tuple(names), unique_snake_case_names(names), xy, frozenset(edges))


def shortest_path(lmap: LandmarkMap, start: int, goal: int) -> list[int]:
    """Shortest node path start -> goal by length; raises ``PlanningError`` if none."""
    try:
        return list(nx.shortest_path(lmap.graph(), start, goal, weight='weight'))
    except (nx.NetworkXNoPath, nx.NodeNotFound) as e:
        raise PlanningError(f'no path from landmark {start} to {goal}') from e


def kth_shortest_path(lmap: LandmarkMap, start: int, goal: int, k: int,
                      graph: Optional[nx.Graph] = None) -> list[int]:
    """Find the k-th (k >= 1) shortest simple path start -> goal; the longest found if fewer exist."""
    if k < 1:
        raise InvalidInputError(f'k must be at least 1, got {k}')
    g = graph if graph is not None else lmap.graph()
    last: Optional[list[int]] = None
    try:
        for path in itertools.islice(nx.shortest_simple_paths(g, start, goal, weight='weight'), k):
            last = list(path)
    except (nx.NetworkXNoPath, nx.NodeNotFound) as e:
        raise PlanningError(f'no path from landmark {start} to {goal}') from e
    if last is None:
        raise PlanningError(f'no path from landmark {start} to {goal}')
    return last


def simulate_trajectory(lmap: LandmarkMap, rng: np.random.Generator, p: float = 0.2,
                        graph: Optional[nx.Graph] = None) -> list[int]:
    """Simulate a trajectory: uniform start != end, the k-th shortest path, k ~ Geometric(p).

    ``rng`` is a numpy generator (seed it for repeatable trajectories).
    """
    n = lmap.num_landmarks
    if n < 2:
        raise InvalidInputError('a trajectory needs at least two landmarks')
    if not 0.0 < p <= 1.0:
        raise InvalidInputError(f'p must be in (0, 1], got {p}')
    start, goal = (int(v) for v in rng.choice(n, size=2, replace=False))
    k = int(rng.geometric(p))
    return kth_shortest_path(lmap, start, goal, k, graph)

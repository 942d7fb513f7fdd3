"""Scene files (``spec/scene.md``): bounds, static geometry, named objects, the robot.

Units are metres in the ``map`` frame (x forward, y left, z up). Unknown keys are
an error that names the file and the key; nothing is silently ignored.
"""
from __future__ import annotations

import json
import math
import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np
import yaml

from ltl_instruct.core.errors import ErrorCode, SceneError
from ltl_instruct.core.world import near

ROBOT_KINDS = ('ground', 'drone')

MAX_SCENE_BYTES = 5_000_000
"""Largest scene file read [bytes]."""
MAX_SCENE_EXTENT_M = 10_000.0
"""Largest extent of a scene's bounds along any axis [m], and the largest absolute coordinate."""
MAX_YAML_ALIASES = 100
"""Most YAML aliases (``*name``) a scene file may use."""
MAX_YAML_NODES = 200_000
"""Most YAML nodes (values, lists, mappings) a scene file may hold."""


@dataclass(frozen=True)
class Box:
    """Axis-aligned box: ``center`` and full ``size`` in metres, each shape (3,)."""

    center: tuple[float, float, float]
    size: tuple[float, float, float]

    @property
    def lo(self) -> np.ndarray:
        """Minimum corner [m], shape (3,)."""
        return np.asarray(self.center) - np.asarray(self.size) / 2.0

    @property
    def hi(self) -> np.ndarray:
        """Maximum corner [m], shape (3,)."""
        return np.asarray(self.center) + np.asarray(self.size) / 2.0

    def contains(self, points: np.ndarray, margin: float = 0.0, dims: int = 3) -> np.ndarray:
        """Whether points (shape (N, >=dims)) lie in the box grown by ``margin`` [m].

        Only the first ``dims`` coordinates are compared (2 for a ground robot).
        """
        p = np.atleast_2d(points)[:, :dims]
        lo = self.lo[:dims] - margin
        hi = self.hi[:dims] + margin
        return np.all((p >= lo) & (p <= hi), axis=1)

    def distance(self, points: np.ndarray, dims: int = 3) -> np.ndarray:
        """Euclidean distance [m] from points (N, >=dims) to the box (0 inside)."""
        return near.box_distance(points, np.asarray([self.center]), np.asarray([self.size]), dims)


@dataclass(frozen=True)
class SceneObject:
    """A thing an instruction may name.

    Attributes
    ----------
    id: unique snake_case id within the scene (``red_sofa``, ``chair_2``).
    label: free text as a person names it (``red sofa``).
    center: position [m], shape (3,).
    size: extent [m] or None for a point object.
    on: id or label of the object it rests on, if any.
    passable: a ground robot may drive through it (a rug, a doorway).
    """

    id: str
    label: str
    center: tuple[float, float, float]
    size: Optional[tuple[float, float, float]] = None
    on: Optional[str] = None
    passable: bool = False

    @property
    def box(self) -> Optional[Box]:
        """The object's box, or None for a point object."""
        return Box(self.center, self.size) if self.size is not None else None


@dataclass(frozen=True)
class Robot:
    """The robot: ``kind`` ground or drone, ``start`` [m] shape (3,), ``radius`` [m]."""

    kind: str = 'ground'
    start: tuple[float, float, float] = (0.0, 0.0, 0.0)
    radius: float = 0.3

    @property
    def dims(self) -> int:
        """Planning dimension: 2 for a ground robot, 3 for a drone."""
        return 3 if self.kind == 'drone' else 2


@dataclass(frozen=True)
class Scene:
    """A world shared by the planner, the simulator and the tests."""

    name: str
    bounds_min: tuple[float, float, float]
    bounds_max: tuple[float, float, float]
    robot: Robot = field(default_factory=Robot)
    obstacles: tuple[Box, ...] = ()
    objects: tuple[SceneObject, ...] = ()
    altitude: Optional[tuple[float, float]] = None
    source: str = '<memory>'

    def object_by_id(self, object_id: str) -> SceneObject:
        """Return the object with ``id`` (KeyError if absent)."""
        for o in self.objects:
            if o.id == object_id:
                return o
        raise KeyError(object_id)

    def blocking_boxes(self) -> tuple[Box, ...]:
        """Return the static geometry the robot must not enter (before inflation).

        For a ground robot: obstacles and every sized object that is not passable.
        For a drone: obstacles and sized objects whose top reaches the altitude band.
        """
        boxes = list(self.obstacles)
        for o in self.objects:
            if o.box is None or o.passable:
                continue
            if self.robot.kind == 'drone':
                floor = self.altitude[0] if self.altitude else 0.0
                if o.box.hi[2] < floor:
                    continue
            boxes.append(o.box)
        return tuple(boxes)

    def to_dict(self) -> dict[str, Any]:
        """Return a dict in the scene-file format (round-trips through :func:`scene_from_dict`)."""
        d: dict[str, Any] = {
            'name': self.name,
            'bounds': {'min': list(self.bounds_min), 'max': list(self.bounds_max)},
            'robot': {'kind': self.robot.kind, 'start': list(self.robot.start),
                      'radius': self.robot.radius},
            'obstacles': [{'center': list(b.center), 'size': list(b.size)} for b in self.obstacles],
            'objects': [],
        }
        if self.altitude is not None:
            d['altitude'] = {'min': self.altitude[0], 'max': self.altitude[1]}
        for o in self.objects:
            od: dict[str, Any] = {'label': o.label, 'center': list(o.center)}
            if o.size is not None:
                od['size'] = list(o.size)
            if o.on is not None:
                od['on'] = o.on
            if o.passable:
                od['passable'] = True
            d['objects'].append(od)
        return d


# --------------------------------------------------------------------------- loading

_TOP_KEYS = {'name', 'bounds', 'robot', 'obstacles', 'objects', 'altitude'}
_ROBOT_KEYS = {'kind', 'start', 'radius'}
_BOUNDS_KEYS = {'min', 'max'}
_ALT_KEYS = {'min', 'max'}
_OBSTACLE_KEYS = {'center', 'size'}
_OBJECT_KEYS = {'label', 'center', 'size', 'on', 'passable'}


def slug(label: str) -> str:
    """snake_case form of a free-text label: ``'Red Sofa'`` -> ``'red_sofa'``."""
    s = re.sub(r'[^a-z0-9]+', '_', label.lower()).strip('_')
    if not s or not s[0].isalpha():
        s = 'object_' + s
    return s


class _Ctx:
    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, where: str, message: str) -> SceneError:
        return SceneError(f'{self.source}: {where}: {message}',
                          details={'file': self.source, 'key': where})

    def keys(self, obj: Any, allowed: set[str], where: str, required: Sequence[str] = ()) -> dict:
        if not isinstance(obj, Mapping):
            raise self.fail(where, f'expected a mapping, got {type(obj).__name__}')
        for k in obj:
            if k not in allowed:
                raise self.fail(f'{where}.{k}' if where else str(k),
                                f'unknown key {k!r} (allowed: {", ".join(sorted(allowed))})')
        for k in required:
            if k not in obj:
                raise self.fail(f'{where}.{k}' if where else k, 'missing required key')
        return dict(obj)

    def vec(self, v: Any, where: str, n: int = 3, positive: bool = False) -> tuple[float, ...]:
        if not isinstance(v, (list, tuple)) or len(v) != n:
            raise self.fail(where, f'expected a list of {n} numbers, got {v!r}')
        out = []
        for x in v:
            f = self._finite(x)
            if f is None:
                raise self.fail(where, f'expected finite numbers, got {_short(v)}')
            if abs(f) > MAX_SCENE_EXTENT_M:
                raise self.fail(where, f'{_short(x)} m is beyond the largest scene coordinate '
                                       f'({MAX_SCENE_EXTENT_M:g} m)')
            if positive and f <= 0:
                raise self.fail(where, f'sizes must be positive, got {_short(v)}')
            out.append(f)
        return tuple(out)

    def num(self, v: Any, where: str, positive: bool = False) -> float:
        f = self._finite(v)
        if f is None:
            raise self.fail(where, f'expected a finite number, got {_short(v)}')
        if abs(f) > MAX_SCENE_EXTENT_M:
            raise self.fail(where, f'{_short(v)} is beyond the largest scene value ({MAX_SCENE_EXTENT_M:g})')
        if positive and f <= 0:
            raise self.fail(where, f'expected a positive number, got {_short(v)}')
        return f

    @staticmethod
    def _finite(x: Any) -> Optional[float]:
        """``x`` as a finite float, or None (not a number, a boolean, NaN, inf, or too big for a float)."""
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            return None
        try:
            f = float(x)
        except OverflowError:   # an integer with hundreds of digits
            return None
        return f if math.isfinite(f) else None

    def seq(self, v: Any, where: str) -> list:
        """``v`` as a list (None or absent: empty); anything else names the key."""
        if v is None:
            return []
        if not isinstance(v, list):
            raise self.fail(where, f'expected a list, got {type(v).__name__} {_short(v)}')
        return v


def _short(v: Any) -> str:
    text = repr(v)
    return text if len(text) <= 80 else text[:77] + '...'


def scene_from_dict(data: Any, source: str = '<memory>') -> Scene:
    """Validate a scene mapping and build a :class:`Scene`.

    Raises
    ------
    SceneError
        Naming the file (``source``) and the key, for unknown or missing keys and
        bad values.
    """
    c = _Ctx(source)
    d = c.keys(data, _TOP_KEYS, '', required=('bounds',))
    name = d.get('name', Path(source).stem if source != '<memory>' else 'scene')
    if not isinstance(name, str):
        raise c.fail('name', 'expected text')
    b = c.keys(d['bounds'], _BOUNDS_KEYS, 'bounds', required=('min', 'max'))
    bmin = c.vec(b['min'], 'bounds.min')
    bmax = c.vec(b['max'], 'bounds.max')
    if any(lo >= hi for lo, hi in zip(bmin, bmax)):
        raise c.fail('bounds', f'min {bmin} must be below max {bmax} on every axis')
    if any(hi - lo > MAX_SCENE_EXTENT_M for lo, hi in zip(bmin, bmax)):
        raise c.fail('bounds', f'the scene spans more than {MAX_SCENE_EXTENT_M:g} m along an axis '
                               f'(min {bmin}, max {bmax})')
    r = c.keys(d.get('robot', {}), _ROBOT_KEYS, 'robot')
    kind = r.get('kind', 'ground')
    if kind not in ROBOT_KINDS:
        raise c.fail('robot.kind', f'expected one of {ROBOT_KINDS}, got {kind!r}')
    start = c.vec(r.get('start', list(bmin)), 'robot.start')
    radius = c.num(r.get('radius', 0.3), 'robot.radius', positive=True)
    robot = Robot(kind, start, radius)
    altitude = None
    if 'altitude' in d:
        a = c.keys(d['altitude'], _ALT_KEYS, 'altitude', required=('min', 'max'))
        altitude = (c.num(a['min'], 'altitude.min'), c.num(a['max'], 'altitude.max'))
        if altitude[0] > altitude[1]:
            raise c.fail('altitude', 'min must not exceed max')
        if kind != 'drone':
            raise c.fail('altitude', 'only a drone has an altitude band')
    obstacles = []
    for i, ob in enumerate(c.seq(d.get('obstacles'), 'obstacles')):
        o = c.keys(ob, _OBSTACLE_KEYS, f'obstacles[{i}]', required=('center', 'size'))
        obstacles.append(Box(c.vec(o['center'], f'obstacles[{i}].center'),
                             c.vec(o['size'], f'obstacles[{i}].size', positive=True)))
    objects: list[SceneObject] = []
    raw_objects = c.seq(d.get('objects'), 'objects')
    slugs = [slug(str(ob.get('label', ''))) if isinstance(ob, Mapping) else '' for ob in raw_objects]
    counts: dict[str, int] = {}
    for s in slugs:
        counts[s] = counts.get(s, 0) + 1
    seen: dict[str, int] = {}
    for i, ob in enumerate(raw_objects):
        o = c.keys(ob, _OBJECT_KEYS, f'objects[{i}]', required=('label', 'center'))
        label = o['label']
        if not isinstance(label, str) or not label.strip():
            raise c.fail(f'objects[{i}].label', 'expected non-empty text')
        s = slugs[i]
        seen[s] = seen.get(s, 0) + 1
        oid = s if counts[s] == 1 else f'{s}_{seen[s]}'
        size = c.vec(o['size'], f'objects[{i}].size', positive=True) if 'size' in o else None
        on = o.get('on')
        if on is not None and not isinstance(on, str):
            raise c.fail(f'objects[{i}].on', 'expected the label of another object')
        passable = o.get('passable', False)
        if not isinstance(passable, bool):
            raise c.fail(f'objects[{i}].passable', 'expected true or false')
        objects.append(SceneObject(oid, label.strip(), c.vec(o['center'], f'objects[{i}].center'),
                                   size, on, passable))
    return Scene(name, bmin, bmax, robot, tuple(obstacles), tuple(objects), altitude, source)


class _SceneLoader(yaml.SafeLoader):
    """YAML 1.1 safe loader with YAML 1.2 booleans and bounded aliases and nodes.

    Only ``true``/``false`` (any case) are booleans: ``on``, ``off``, ``yes``, ``no``,
    ``y``, ``n`` stay text, so the spec's ``on: table`` is the key ``'on'``, not ``True``.
    """

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self._aliases = 0
        self._nodes = 0

    def compose_node(self, parent: Any, index: Any) -> Any:
        """Count nodes and aliases while composing (a "billion laughs" file stops early)."""
        if self.check_event(yaml.AliasEvent):
            self._aliases += 1
            if self._aliases > MAX_YAML_ALIASES:
                raise yaml.YAMLError(f'more than {MAX_YAML_ALIASES} aliases')
        self._nodes += 1
        if self._nodes > MAX_YAML_NODES:
            raise yaml.YAMLError(f'more than {MAX_YAML_NODES} values')
        return super().compose_node(parent, index)


_SceneLoader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != 'tag:yaml.org,2002:bool']
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}
_SceneLoader.add_implicit_resolver(
    'tag:yaml.org,2002:bool', re.compile(r'^(?:true|True|TRUE|false|False|FALSE)$'), list('tTfF'))


def parse_scene_yaml(text: str) -> Any:
    """Parse scene YAML: only ``true``/``false`` are booleans; aliases and size are bounded."""
    return yaml.load(text, Loader=_SceneLoader)  # noqa: S506 - a SafeLoader subclass


def _read_scene_text(p: Path) -> str:
    """Read a scene file: a regular file of at most :data:`MAX_SCENE_BYTES`, UTF-8."""
    try:
        # O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below
        fd = os.open(p, os.O_RDONLY | getattr(os, 'O_NONBLOCK', 0))
    except OSError as e:
        raise SceneError(f'{p}: cannot read scene file: {e.strerror or e}', details={'file': str(p)}) from e
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise SceneError(f'{p}: not a regular file (a scene must be a YAML or JSON file)',
                             details={'file': str(p)})
        if st.st_size > MAX_SCENE_BYTES:
            raise SceneError(f'{p}: scene file of {st.st_size} bytes exceeds the limit of {MAX_SCENE_BYTES}',
                             ErrorCode.LIMIT_EXCEEDED, details={'file': str(p), 'limit': MAX_SCENE_BYTES})
        with os.fdopen(fd, 'rb') as f:
            fd = -1
            raw = f.read(MAX_SCENE_BYTES + 1)
    except OSError as e:
        raise SceneError(f'{p}: cannot read scene file: {e.strerror or e}', details={'file': str(p)}) from e
    finally:
        if fd >= 0:
            os.close(fd)
    if len(raw) > MAX_SCENE_BYTES:
        raise SceneError(f'{p}: scene file exceeds the limit of {MAX_SCENE_BYTES} bytes',
                         ErrorCode.LIMIT_EXCEEDED, details={'file': str(p), 'limit': MAX_SCENE_BYTES})
    try:
        return raw.decode('utf-8')
    except UnicodeDecodeError as e:
        raise SceneError(f'{p}: not UTF-8 text: byte 0x{raw[e.start]:02x} at offset {e.start} '
                         f'cannot be decoded', details={'file': str(p), 'offset': e.start}) from None


def load_scene(path: Union[str, Path]) -> Scene:
    """Load a scene from a YAML or JSON file (see ``spec/scene.md``).

    Raises
    ------
    SceneError
        A file that is missing, not a regular file (a FIFO, a directory), larger than
        :data:`MAX_SCENE_BYTES` (code ``LIMIT_EXCEEDED``), not UTF-8 (the message names
        the byte offset), not valid YAML/JSON, or not a valid scene (the message names
        the key).
    """
    p = Path(path)
    text = _read_scene_text(p)
    try:
        data = json.loads(text) if p.suffix == '.json' else parse_scene_yaml(text)
    except (ValueError, yaml.YAMLError, RecursionError) as e:
        raise SceneError(f'{p}: not valid {"JSON" if p.suffix == ".json" else "YAML"}: '
                         f'{str(e)[:300] or type(e).__name__}', details={'file': str(p)}) from None
    return scene_from_dict(data, str(p))

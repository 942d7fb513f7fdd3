"""Built-in scenes shipped with the package (``ltl_instruct/data/scenes/*.yaml``).

``apartment`` is a four-room apartment for a ground robot with 36 objects, several
of which share a label (two sofas, two tables, three chairs) so that only a spatial
description tells them apart. ``city_block`` is a city block for a drone: buildings
as 3D obstacles and named landmarks.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Union

from ltl_instruct.core.errors import SceneError
from ltl_instruct.core.world.scene import Scene, load_scene

SCENE_DIR = Path(__file__).resolve().parent.parent.parent / 'data' / 'scenes'
DEFAULT_GROUND_SCENE = 'apartment'
DEFAULT_DRONE_SCENE = 'city_block'


def builtin_scene_names() -> tuple[str, ...]:
    """Names of the built-in scenes, sorted."""
    return tuple(sorted(p.stem for p in SCENE_DIR.glob('*.yaml')))


def builtin_scene_path(name: str) -> Path:
    """Return the file of a built-in scene.

    Raises
    ------
    SceneError
        If no built-in scene has that name (the message lists the known ones).
    """
    path = SCENE_DIR / f'{name}.yaml'
    if not name or '/' in name or not path.is_file():
        raise SceneError(f'no built-in scene {name!r} (known: {", ".join(builtin_scene_names())})',
                         details={'scene': name})
    return path


def resolve_scene(name_or_path: Union[str, Path]) -> Scene:
    """Load a built-in scene by name, or a scene file by path.

    Every command and node that takes a scene goes through here. A value that exists
    on disk, ends in ``.yaml``/``.yml``/``.json`` or holds a path separator is read as
    a file (a FIFO or folder is refused there); anything else is looked up among the
    built-in scenes.

    Raises
    ------
    SceneError
        An unknown built-in name (the message lists the known ones) or a bad file.
    """
    text = str(name_or_path)
    p = Path(text)
    if p.suffix in ('.yaml', '.yml', '.json') or os.sep in text or '/' in text or p.exists():
        return load_scene(p)
    return load_scene(builtin_scene_path(text))

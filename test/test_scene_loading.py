"""Issue 21: scene files that are not what spec/scene.md says get a SceneError naming file and key."""
import os

import pytest

from ltl_instruct.core.errors import ErrorCode, SceneError
from ltl_instruct.core.world import scene as scene_mod
from ltl_instruct.core.world.scene import MAX_SCENE_EXTENT_M, load_scene

BOUNDS = 'bounds: {min: [0, 0, 0], max: [20, 15, 3]}\n'


def _write(tmp_path, data, name='s.yaml'):
    p = tmp_path / name
    p.write_bytes(data if isinstance(data, bytes) else data.encode())
    return p


def test_latin1_byte_names_file_and_offset(tmp_path):
    p = _write(tmp_path, BOUNDS.encode() + b'name: caf\xe9\n')   # UnicodeDecodeError on main
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert str(p) in e.value.message and 'offset 52' in e.value.message and '0xe9' in e.value.message
    assert e.value.details['offset'] == 52


@pytest.mark.parametrize('key, text', [
    ('obstacles', 'obstacles: 7\n'),                 # TypeError on main
    ('objects', 'objects: {a: 1}\n'),
    ('obstacles', 'obstacles: "box"\n'),
])
def test_wrong_types_name_file_and_key(tmp_path, key, text):
    p = _write(tmp_path, BOUNDS + text)
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert str(p) in e.value.message and e.value.details['key'] == key


def test_huge_integers_are_scene_errors(tmp_path):
    p = _write(tmp_path, 'bounds: {min: [0, 0, 0], max: [1' + '0' * 400 + ', 15, 3]}\n')  # OverflowError
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.details['key'] == 'bounds.max'


def test_spec_example_on_key_is_text(tmp_path):
    p = _write(tmp_path, BOUNDS + 'objects:\n'
               '  - {label: table, center: [12.0, 4.0, 0.4], size: [1.0, 1.0, 0.8]}\n'
               '  - {label: green plush toy, center: [12.2, 4.1, 0.5], size: [0.3, 0.3, 0.3], on: table}\n'
               '  - {label: rug, center: [2, 2, 0], passable: true}\n'
               '  - {label: no, center: [3, 3, 0]}\n')
    s = load_scene(p)
    assert s.object_by_id('green_plush_toy').on == 'table'
    assert s.object_by_id('rug').passable is True
    assert s.object_by_id('no').label == 'no'


def test_fifo_is_refused_without_blocking(tmp_path):
    p = tmp_path / 'fifo.yaml'
    os.mkfifo(p)                                         # blocked forever on main
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert 'not a regular file' in e.value.message


def test_directory_and_missing_file(tmp_path):
    with pytest.raises(SceneError):
        load_scene(tmp_path)
    with pytest.raises(SceneError):
        load_scene(tmp_path / 'missing.yaml')


def test_file_size_is_bounded(tmp_path, monkeypatch):
    monkeypatch.setattr(scene_mod, 'MAX_SCENE_BYTES', 100)
    p = _write(tmp_path, BOUNDS + '#' * 200 + '\n')
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED


def test_aliases_are_bounded(tmp_path):
    lines = ['a0: &a0 [1, 1]'] + [f'a{i}: &a{i} [' + ', '.join([f'*a{i - 1}'] * 10) + ']'
                                  for i in range(1, 12)]
    p = _write(tmp_path, '\n'.join(lines) + '\n')
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert 'aliases' in e.value.message


def test_deep_nesting_is_a_scene_error(tmp_path):
    p = _write(tmp_path, '[' * 100000 + '\n')
    with pytest.raises(SceneError):
        load_scene(p)
    p = _write(tmp_path, '[' * 100000 + ']' * 100000, 's.json')
    with pytest.raises(SceneError):
        load_scene(p)


def test_drone_bounds_are_bounded(tmp_path):
    p = _write(tmp_path, 'bounds: {min: [0, 0, 0], max: [100000000, 100000000, 40]}\n'
               'robot: {kind: drone, start: [1, 1, 5]}\naltitude: {min: 2, max: 30}\n')
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert f'{MAX_SCENE_EXTENT_M:g}' in e.value.message
    p = _write(tmp_path, 'bounds: {min: [-9000, 0, 0], max: [9000, 10, 3]}\n')
    with pytest.raises(SceneError) as e:
        load_scene(p)
    assert e.value.details['key'] == 'bounds'


def test_builtin_scenes_still_load():
    from ltl_instruct.core.world.builtin import builtin_scene_names, resolve_scene
    for name in builtin_scene_names():
        assert resolve_scene(name).objects

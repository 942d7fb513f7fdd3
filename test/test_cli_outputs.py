"""Issue 21: every command takes built-in scene names; output paths are used exactly as given."""
import os

import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.errors import InvalidInputError, SceneError
from ltl_instruct.core.planning.plot import check_output_path
from ltl_instruct.core.world.builtin import resolve_scene


def test_plan_accepts_a_builtin_scene_name(capsys):
    # "plan --scene apartment" said the file did not exist on main
    rc = main(['plan', '--scene', 'apartment', '--formula', 'F near[fridge]', '--samples', '800', '--json'])
    assert rc in (0, 1)
    assert 'does not exist' not in capsys.readouterr().err


def test_unknown_scene_name_lists_the_builtin_ones(capsys):
    assert main(['plan', '--scene', 'no_such_scene', '--formula', 'F near[a]']) == 2
    err = capsys.readouterr().err
    assert '[SCENE_ERROR]' in err and 'apartment' in err


def test_resolver_reads_paths_as_files(tmp_path):
    fifo = tmp_path / 'fifo'
    os.mkfifo(fifo)
    with pytest.raises(SceneError) as e:
        resolve_scene(str(fifo))
    assert 'not a regular file' in e.value.message


def test_png_in_a_missing_folder_is_refused_before_planning(tmp_path, capsys):
    target = tmp_path / 'nonexistent' / 'x.png'
    assert main(['plan', '--scene', 'apartment', '--formula', 'F near[fridge]', '--png', str(target)]) == 2
    assert '[INVALID_INPUT]' in capsys.readouterr().err
    assert not target.parent.exists()    # main created the folder silently


@pytest.mark.skipif(not os.path.exists('/dev/full'), reason='needs /dev/full')
def test_failed_png_write_is_a_typed_error_and_no_suffix_is_added(capsys):
    rc = main(['plan', '--scene', 'apartment', '--formula', 'F near[fridge]', '--samples', '800',
               '--png', '/dev/full'])
    err = capsys.readouterr().err
    if rc == 1:           # no plan, nothing drawn
        return
    assert rc == 2 and '[INVALID_INPUT]' in err and '/dev/full' in err
    assert not os.path.exists('/dev/full.png')   # main wrote a file /dev/full.png


def test_png_path_is_used_as_given(tmp_path):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from ltl_instruct.core.planning.plot import save_png
    fig = plt.figure()
    out = save_png(fig, tmp_path / 'picture', dpi=20)
    assert out == tmp_path / 'picture' and out.read_bytes()[:4] == b'\x89PNG'
    assert not (tmp_path / 'picture.png').exists()


def test_check_output_path():
    with pytest.raises(InvalidInputError):
        check_output_path('/nonexistent/dir/x.png')
    with pytest.raises(InvalidInputError):
        check_output_path('/')


def test_translate_output_that_cannot_be_written(tmp_path, capsys):
    src = tmp_path / 'in.jsonl'
    src.write_text('{"instruction": "go to the kitchen"}\n')
    assert main(['translate', '--input', str(src), '--output', str(tmp_path / 'no' / 'out.jsonl')]) == 2
    assert '[INVALID_INPUT]' in capsys.readouterr().err
    if os.path.exists('/dev/full'):
        assert main(['translate', '--input', str(src), '--output', '/dev/full']) == 2
        assert 'cannot write /dev/full' in capsys.readouterr().err

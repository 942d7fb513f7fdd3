"""The ``ltl-instruct ground`` command: object list, camera views, JSON, exit codes."""
from __future__ import annotations

import json

import pytest

from ltl_instruct.cli import main
from ltl_instruct.core.grounding.rsm import ReferentMap

SCENE = """
name: room
bounds: {min: [0, 0, 0], max: [8, 8, 3]}
objects:
  - {label: pillar, center: [3.0, 4.0, 1.0], size: [0.4, 0.4, 2.0]}
  - {label: sofa, center: [5.5, 4.0, 0.4], size: [0.9, 1.8, 0.8]}
  - {label: sofa, center: [1.5, 4.0, 0.4], size: [0.9, 1.8, 0.8]}
  - {label: door, center: [4.0, 7.0, 1.0], size: [1.0, 0.2, 2.0]}
"""


@pytest.fixture()
def scene_file(tmp_path):
    p = tmp_path / 'room.yaml'
    p.write_text(SCENE)
    return str(p)


def test_json_from_the_object_list(scene_file, capsys):
    rc = main(['ground', '--scene', scene_file, '--formula',
               'F near[couch::isbehind(pillar)] & G !near[door]', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out['ok']
    rmap = ReferentMap.from_dict(out['referent_map'])
    assert [i.id for i in rmap.instances('couch::isbehind(pillar)')] == ['sofa_1']
    assert rmap.get('door').required is False


def test_views_build_the_map_from_the_camera(scene_file, capsys):
    rc = main(['ground', '--scene', scene_file, '--formula', 'F near[sofa::isbehind(pillar)]',
               '--views', '6', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and 'synthetic views' in out['source']
    (inst,) = ReferentMap.from_dict(out['referent_map']).instances('sofa::isbehind(pillar)')
    assert inst.id.startswith('det_')
    assert abs(inst.center[0] - 5.5) < 0.15 and abs(inst.center[1] - 4.0) < 0.15


def test_text_output_and_failure_exit(scene_file, capsys):
    rc = main(['ground', '--scene', scene_file, '--formula', 'F near[sofa::isabove(pillar)]'])
    text = capsys.readouterr().out
    assert rc == 1 and 'NO_MATCH' in text and 'fails' in text
    rc = main(['ground', '--scene', scene_file, '--formula', 'F near[fridge]'])
    assert rc == 1 and 'UNKNOWN_REFERENT' in capsys.readouterr().out


@pytest.mark.parametrize('extra', [['--formula', 'F near['], ['--formula', 'F near[sofa]', '--views', '-1'],
                                   ['--formula', 'F near[sofa]', '--viewpoint', '1,2'],
                                   ['--formula', 'F near[sofa]', '--viewpoint', 'a,b,c']])
def test_bad_input_exits_2(scene_file, extra, capsys):
    assert main(['ground', '--scene', scene_file] + extra) == 2


def test_missing_scene_exits_2(tmp_path, capsys):
    assert main(['ground', '--scene', str(tmp_path / 'nope.yaml'), '--formula', 'F near[a]']) == 2

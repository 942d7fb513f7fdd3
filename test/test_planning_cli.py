"""``ltl-instruct plan``: JSON and picture output, exit codes, bad input."""
from __future__ import annotations

import json

import pytest
import yaml

from ltl_instruct.cli import main
from ltl_instruct.commands.plan import label_referent_map
from ltl_instruct.core.errors import GroundingError
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.scene import scene_from_dict

SCENE = {
    'name': 'cli',
    'bounds': {'min': [0, 0, 0], 'max': [12, 8, 3]},
    'robot': {'kind': 'ground', 'start': [1, 1, 0], 'radius': 0.3},
    'obstacles': [{'center': [6, 2.5, 1], 'size': [0.2, 5, 2]}],
    'objects': [{'label': 'red sofa', 'center': [10, 2, 0.4], 'size': [1, 1, 0.8]},
                {'label': 'blue sofa', 'center': [10, 7, 0.4], 'size': [1, 0.6, 0.8]},
                {'label': 'door', 'center': [8, 4.5, 0.5], 'size': [0.3, 0.3, 1], 'passable': True},
                {'label': 'cup', 'center': [2, 6, 0.4], 'size': [0.1, 0.1, 0.1], 'passable': True}],
}


@pytest.fixture()
def scene_file(tmp_path):
    p = tmp_path / 'scene.yaml'
    p.write_text(yaml.safe_dump(SCENE))
    return p


def test_plan_json_and_png(scene_file, tmp_path, capsys):
    png = tmp_path / 'plan.png'
    rc = main(['plan', '--scene', str(scene_file), '--formula',
               'F (pick[cup] & F release[cup, red_sofa]) & G !near[door]', '--json', '--png', str(png),
               '--samples', '1500'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0
    assert out['status'] == 'planned' and out['verification']['ok']
    kinds = [s['kind'] for s in out['steps']]
    assert 'skill' in kinds and 'navigate' in kinds
    for s in out['steps']:
        assert {'state_before', 'state_after'} <= set(s)
    assert out['length'] > 0 and out['automaton_states'][-1] == out['verification']['final_state']
    assert png.exists() and png.read_bytes()[:8] == b'\x89PNG\r\n\x1a\n'


def test_plan_text_output_and_start_option(scene_file, capsys):
    rc = main(['plan', '--scene', str(scene_file), '--formula', 'F near[red_sofa]', '--start', '2,6',
               '--samples', '1500'])
    text = capsys.readouterr().out
    assert rc == 0 and 'verified: yes' in text


def test_no_plan_exits_1_with_a_typed_error(scene_file, capsys):
    rc = main(['plan', '--scene', str(scene_file), '--formula', 'F near[door] & G !near[door]', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 1 and out['status'] == 'failed' and out['error']['code'] == 'UNSATISFIABLE'
    rc = main(['plan', '--scene', str(scene_file), '--formula', 'F (near[red_sofa] & near[cup])', '--json'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 1 and out['error']['code'] == 'GOAL_OCCUPIED'


@pytest.mark.parametrize('args', [
    ['--formula', 'F near[[sofa'],
    ['--formula', 'F near[unicorn]'],
    ['--formula', 'F near[sofa]', '--start', 'nan,1'],
    ['--formula', 'F near[sofa]', '--start', '30,2.5'],   # far outside (one in the thin wall is moved out)
    ['--formula', 'F near[sofa]', '--start', '1,2,3,4'],
    ['--formula', 'F near[sofa]', '--near', '-1'],
    ['--formula', 'F ' * 6000 + 'near[sofa]'],
])
def test_bad_input_exits_2_or_reports(scene_file, args, capsys):
    rc = main(['plan', '--scene', str(scene_file)] + args)
    captured = capsys.readouterr()
    assert rc in (1, 2)
    assert 'Traceback' not in captured.err
    if rc == 2:
        assert 'error [' in captured.err


def test_spatial_descriptors_are_grounded(scene_file, capsys):
    rc = main(['plan', '--scene', str(scene_file), '--formula', 'F near[sofa::isleftof(door)]', '--json',
               '--samples', '1500'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out['verification']['ok']
    assert out['referents']['sofa::isleftof(door)'] == ['blue_sofa']
    assert main(['plan', '--scene', str(scene_file), '--formula', 'F near[sofa::isabove(door)]']) == 2


def test_bad_scene_exits_2(tmp_path, capsys):
    p = tmp_path / 'bad.yaml'
    p.write_text(yaml.safe_dump(dict(SCENE, colour='red')))
    assert main(['plan', '--scene', str(p), '--formula', 'F near[sofa]']) == 2
    assert 'colour' in capsys.readouterr().err
    assert main(['plan', '--scene', str(tmp_path / 'missing.yaml'), '--formula', 'F near[sofa]']) == 2


def test_label_lookup_matches_every_instance_of_a_bare_name():
    scene = scene_from_dict(SCENE)
    rmap = label_referent_map(parse_formula('F near[sofa] & F near[red_sofa] & G !near[window]'), scene)
    assert {i.id for i in rmap.instances('sofa')} == {'red_sofa', 'blue_sofa'}
    assert [i.id for i in rmap.instances('red_sofa')] == ['red_sofa']
    assert rmap.instances('window') == ()          # only avoided: absence is fine
    with pytest.raises(GroundingError):
        label_referent_map(parse_formula('F near[window]'), scene)


def test_drone_plan_picture_has_a_side_view(tmp_path, capsys):
    drone = {'name': 'drone', 'bounds': {'min': [0, 0, 0], 'max': [10, 8, 4]},
             'robot': {'kind': 'drone', 'start': [1, 1, 1.5], 'radius': 0.25},
             'altitude': {'min': 1.0, 'max': 3.0},
             'obstacles': [{'center': [5, 3, 2], 'size': [0.4, 6, 4]}],
             'objects': [{'label': 'tower', 'center': [8, 2, 1.5], 'size': [1, 1, 3]},
                         {'label': 'antenna', 'center': [7, 6, 2.0], 'size': [0.2, 0.2, 1],
                          'passable': True}]}
    p = tmp_path / 'drone.yaml'
    p.write_text(yaml.safe_dump(drone))
    png = tmp_path / 'drone.png'
    rc = main(['plan', '--scene', str(p), '--formula', 'F near[tower] & G !near[antenna]', '--json',
               '--png', str(png), '--samples', '1500', '--start', '1,1,1.5'])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out['dims'] == 3 and out['verification']['ok']
    assert all(len(w) == 3 for s in out['steps'] if s['kind'] == 'navigate' for w in s['waypoints'])
    assert png.exists() and png.stat().st_size > 10_000
    assert main(['plan', '--scene', str(p), '--formula', 'F near[tower]', '--start', '1,1']) == 2

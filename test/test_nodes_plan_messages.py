"""What task_progression publishes for a plan: the whole path and a skill request per skill step."""
from __future__ import annotations

import numpy as np

from ltl_instruct import conversions as conv
from ltl_instruct.core import grounding, planning
from ltl_instruct.core.automaton import compile_automaton
from ltl_instruct.core.spec import parse_formula
from ltl_instruct.core.world.builtin import resolve_scene
from ltl_instruct.nodes.task_progression import _path_and_skills


def test_skill_requests_point_at_the_path_index_where_the_robot_stands():
    scene = resolve_scene('apartment')
    formula = 'F (pick[green_plush_toy] & F release[green_plush_toy, basket])'
    rmap = grounding.ground_formula(formula, grounding.instances_from_scene(scene))
    world = planning.world_from_scene(scene)
    plan = planning.plan_task(compile_automaton(parse_formula(formula)), rmap, world, scene.robot.start)
    path, skills = _path_and_skills(plan, rmap)
    assert path.shape[1] == 3 and np.allclose(path[:, 2], 0.0)
    assert np.allclose(path[0, :2], scene.robot.start[:2])
    assert [s['skill'] for s in skills] == ['pick', 'release']
    assert skills[0]['args'] == ['green_plush_toy'] and skills[1]['args'] == ['green_plush_toy', 'basket']
    assert skills[0]['targets'][0]['id'] == 'green_plush_toy' and skills[1]['targets'][1]['id'] == 'basket'
    for s in skills:
        assert np.allclose(path[s['path_index'], :2], s['position'][:2])
    assert skills[0]['path_index'] <= skills[1]['path_index'] < len(path)
    # the published Path round-trips to the same points
    assert np.allclose(conv.path_points(conv.path_msg(path)), path)

"""Task and motion planning: occupancy, task progression maps, FMT*, progressive planner, verifier.

Typical use::

    world = world_from_scene(scene)
    plan = plan_task(compile_automaton(formula), referent_map, world, scene.robot.start)
    plan.to_dict()

The ``fmt_planner`` node answers one :class:`SegmentRequest` at a time with
:func:`solve_segment`; the ``task_progression`` node runs :func:`plan_task` with a
solver that sends those requests over DDS.
"""
from ltl_instruct.core.planning.fmt import FmtSettings, plan_motion  # noqa: F401
from ltl_instruct.core.planning.occupancy import (  # noqa: F401
    OccupancyLookup, PlanningWorld, world_from_occupancy, world_from_points, world_from_scene,
)
from ltl_instruct.core.planning.planner import (  # noqa: F401
    DEFAULT_NEAR_THRESHOLD, PlannerSettings, plan_task, referent_regions,
)
from ltl_instruct.core.planning.regions import (  # noqa: F401
    AVOID, GOAL, NEUTRAL, AtomRegion, RegionSet, TaskProgressionMap, navigation_guard, regions_for,
    skill_guard,
)
from ltl_instruct.core.planning.segment import (  # noqa: F401
    SegmentProblem, SegmentRequest, SegmentResult, SolveFn, path_length, resample, solve_segment,
)
from ltl_instruct.core.planning.taskplan import (  # noqa: F401
    NAVIGATE, SKILL, PlanStep, TaskPlan, Verification,
)
from ltl_instruct.core.planning.verify import verify_plan  # noqa: F401

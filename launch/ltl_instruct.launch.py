"""Launch the ltl_instruct node graph on a machine with a full ROS 2 install.

``ros2 launch ltl_instruct ltl_instruct.launch.py [sim:=true] [scene:=apartment]
[params_file:=/path/to.yaml]``. The scene (a built-in name or a scene file) sets each
node's robot parameters exactly as ``ltl-instruct bringup --scene`` does: the simulator
and the grounder load it; ``task_progression`` and ``fmt_planner`` get the robot's kind
and radius and, for a drone, its flight volume. Without ROS (no ``ros2``/``launch``
from PyPI), use ``ltl-instruct bringup [--sim]``, which starts the same processes.
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PACKAGE = 'ltl_instruct'
PIPELINE = ('ltl_translator', 'referent_grounder', 'task_progression', 'fmt_planner')
SIM = 'sim_world'


def _nodes(context, *args, **kwargs):
    """Return the nodes, with the scene's per-node parameters after the parameters file."""
    from ltl_instruct.commands.bringup import scene_overrides
    params_file = LaunchConfiguration('params_file').perform(context)
    overrides = scene_overrides(LaunchConfiguration('scene').perform(context))
    names = PIPELINE
    if LaunchConfiguration('sim').perform(context).strip().lower() in ('true', '1', 'yes'):
        names = PIPELINE + (SIM,)
    return [Node(package=PACKAGE, executable=name, name=name, output='screen',
                 parameters=[params_file, overrides.get(name, {})])
            for name in names]


def generate_launch_description() -> LaunchDescription:
    """Return the pipeline nodes, plus ``sim_world`` when ``sim:=true``."""
    default_params = os.path.join(get_package_share_directory(PACKAGE), 'config', 'ltl_instruct.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=default_params,
                              description='ROS parameters file for every node'),
        DeclareLaunchArgument('sim', default_value='false', description='also start sim_world'),
        DeclareLaunchArgument('scene', default_value='apartment',
                              description='built-in scene name or scene file (robot kind, radius, objects)'),
        OpaqueFunction(function=_nodes),
    ])

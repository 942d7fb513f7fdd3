"""Launch the ltl_instruct node graph on a machine with a full ROS 2 install.

``ros2 launch ltl_instruct ltl_instruct.launch.py [sim:=true] [scene:=apartment]
[params_file:=/path/to.yaml]``. Without ROS (no ``ros2``/``launch`` from PyPI), use
``ltl-instruct bringup [--sim]``, which starts the same processes.
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PACKAGE = 'ltl_instruct'
PIPELINE = ('ltl_translator', 'referent_grounder', 'task_progression', 'fmt_planner')


def generate_launch_description() -> LaunchDescription:
    """Return the pipeline nodes, plus ``sim_world`` when ``sim:=true``."""
    default_params = os.path.join(get_package_share_directory(PACKAGE), 'config', 'ltl_instruct.yaml')
    params_file = LaunchConfiguration('params_file')
    scene = LaunchConfiguration('scene')
    actions = [
        DeclareLaunchArgument('params_file', default_value=default_params,
                              description='ROS parameters file for every node'),
        DeclareLaunchArgument('sim', default_value='false', description='also start sim_world'),
        DeclareLaunchArgument('scene', default_value='apartment',
                              description='built-in scene name or scene file (simulator and grounder)'),
    ]
    for name in PIPELINE:
        extra = [{'scene': scene}] if name == 'referent_grounder' else []
        actions.append(Node(package=PACKAGE, executable=name, name=name, output='screen',
                            parameters=[params_file] + extra))
    actions.append(Node(package=PACKAGE, executable='sim_world', name='sim_world', output='screen',
                        parameters=[params_file, {'scene': scene}],
                        condition=IfCondition(LaunchConfiguration('sim'))))
    return LaunchDescription(actions)

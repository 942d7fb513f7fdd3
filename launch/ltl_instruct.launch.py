"""Launch the ltl_instruct node graph on a machine with a full ROS 2 install.

``ros2 launch ltl_instruct ltl_instruct.launch.py [sim:=true] [scene:=apartment]
[params_file:=/path/to.yaml] [respawn:=true|false] [respawn_delay:=1.0] [state_dir:=DIR]
[namespace:=r1] [frame_prefix:=r1/] [use_sim_time:=true] [log_level:=info]``.
The scene (a built-in name or a scene file) sets each node's robot parameters exactly as
``ltl-instruct bringup --scene`` does: the simulator and the grounder load it;
``task_progression`` and ``fmt_planner`` get the robot's kind and radius and, for a
drone, its flight volume. As with ``bringup``, a node that dies is restarted (``respawn``,
default true), and ``task_progression`` keeps its journal in ``state_dir`` (default: a
folder of this launch under the temporary directory) so that it survives the restart.
``namespace`` puts every node of one robot under it (the parameters file applies in any
namespace), ``frame_prefix`` prefixes its frame ids, ``use_sim_time`` runs the nodes on
the simulator's ``/clock`` (``sim_world`` then publishes it), as ``bringup`` does.
Without ROS (no ``ros2``/``launch`` from PyPI), use ``ltl-instruct bringup [--sim]``,
which starts the same processes.
"""
import os
import tempfile

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
    from ltl_instruct.commands.bringup import (
        merge_overrides, normalize_namespace, robot_overrides, scene_overrides,
    )
    params_file = LaunchConfiguration('params_file').perform(context)
    robot = robot_overrides(LaunchConfiguration('frame_prefix').perform(context),
                            _true(LaunchConfiguration('use_sim_time').perform(context)))
    overrides = merge_overrides(scene_overrides(LaunchConfiguration('scene').perform(context)), robot)
    namespace = normalize_namespace(LaunchConfiguration('namespace').perform(context))
    log_level = LaunchConfiguration('log_level').perform(context)
    names = PIPELINE
    if _true(LaunchConfiguration('sim').perform(context)):
        names = PIPELINE + (SIM,)
    respawn = _true(LaunchConfiguration('respawn').perform(context))
    if respawn:   # a restarted task_progression reads back what it had said
        state_dir = LaunchConfiguration('state_dir').perform(context) or \
            os.path.join(tempfile.gettempdir(), f'ltl_instruct-state-{os.getpid()}')
        overrides.setdefault('task_progression', {})['state_dir'] = state_dir
    delay = float(LaunchConfiguration('respawn_delay').perform(context))
    return [Node(package=PACKAGE, executable=name, name=name, namespace=namespace, output='screen',
                 parameters=[params_file, overrides.get(name, {})], respawn=respawn, respawn_delay=delay,
                 ros_arguments=['--log-level', log_level])
            for name in names]


def _true(text: str) -> bool:
    return text.strip().lower() in ('true', '1', 'yes')


def generate_launch_description() -> LaunchDescription:
    """Return the pipeline nodes, plus ``sim_world`` when ``sim:=true``."""
    default_params = os.path.join(get_package_share_directory(PACKAGE), 'config', 'ltl_instruct.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=default_params,
                              description='ROS parameters file for every node'),
        DeclareLaunchArgument('sim', default_value='false', description='also start sim_world'),
        DeclareLaunchArgument('scene', default_value='apartment',
                              description='built-in scene name or scene file (robot kind, radius, objects)'),
        DeclareLaunchArgument('respawn', default_value='true',
                              description='restart a node that dies (the graph recovers what it lost)'),
        DeclareLaunchArgument('respawn_delay', default_value='1.0', description='seconds before a restart'),
        DeclareLaunchArgument('state_dir', default_value='',
                              description='where task_progression keeps its statuses across a restart '
                                          '("" = a folder of this launch under the temporary directory)'),
        DeclareLaunchArgument('namespace', default_value='',
                              description='namespace of every node (one robot of several on a graph)'),
        DeclareLaunchArgument('frame_prefix', default_value='',
                              description='prefix of every frame id ("r1/": r1/map, r1/odom, r1/base_link)'),
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='run the nodes on /clock (sim_world publishes it when sim:=true)'),
        DeclareLaunchArgument('log_level', default_value='info',
                              description='log level of every node (debug, info, warn, error, fatal)'),
        OpaqueFunction(function=_nodes),
    ])

"""gazebo_ros's gazebo.launch.py for gazelle: the server is `gazelle sim`, the client is the browser
viewer (its URL is printed). Arguments as gazebo_ros's (those without meaning here are accepted and
said so)."""

import os

from ament_index_python.packages import get_package_share_directory

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

SERVER_ARGS = [
    "world",
    "verbose",
    "pause",
    "extra_gazebo_args",
    "params_file",
    "gui",
    "init",
    "factory",
    "force_system",
    "physics",
    "lockstep",
    "seed",
    "server_required",
    "gdb",
    "valgrind",
    "record",
]


def generate_launch_description():
    launch_dir = os.path.join(get_package_share_directory("gazebo_ros"), "launch")
    args = [
        DeclareLaunchArgument(name, default_value=default, description=description)
        for name, default, description in (
            ("gui", "true", 'Set to "false" to run headless.'),
            ("server", "true", 'Set to "false" not to run gzserver.'),
            ("world", "", "Specify world file name"),
            ("verbose", "false", 'Set "true" to increase messages written to terminal.'),
            ("pause", "false", 'Set "true" to start the server in a paused state.'),
            ("extra_gazebo_args", "", "Extra arguments to be passed to Gazebo"),
            ("params_file", "", "Path to ROS 2 yaml parameter file"),
            ("init", "true", 'Set "false" not to load "libgazebo_ros_init.so"'),
            ("factory", "true", 'Set "false" not to load "libgazebo_ros_factory.so"'),
            ("force_system", "true", 'Set "false" not to load "libgazebo_ros_force_system.so"'),
            ("server_required", "false", 'Set "true" to shut down launch script when server is terminated'),
            ("gui_required", "false", 'Set "true" to shut down launch script when GUI is terminated'),
        )
    ]
    server = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_dir, "gzserver.launch.py")),
        condition=IfCondition(LaunchConfiguration("server")),
    )
    client = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_dir, "gzclient.launch.py")),
        condition=IfCondition(LaunchConfiguration("gui")),
    )
    return LaunchDescription([*args, server, client])

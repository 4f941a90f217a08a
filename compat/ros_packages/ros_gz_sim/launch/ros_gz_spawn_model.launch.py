"""ros_gz_sim's ros_gz_spawn_model.launch.py for gazelle: `create` with the model's source and pose."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


def _create(context):
    cfg = context.launch_configurations
    args = []
    for key, flag in (("file", "-file"), ("model_string", "-string"), ("topic", "-topic"), ("entity_name", "-name")):
        if cfg.get(key):
            args += [flag, cfg[key]]
    for axis in ("x", "y", "z", "R", "P", "Y"):
        if cfg.get(axis):
            args += [f"-{axis}", cfg[axis]]
    return [Node(package="ros_gz_sim", executable="create", arguments=args, output="screen")]


def generate_launch_description():
    names = ("world", "file", "model_string", "topic", "entity_name", "x", "y", "z", "R", "P", "Y")
    declared = [DeclareLaunchArgument(n, default_value="", description=f"{n} of the model") for n in names]
    return LaunchDescription([*declared, OpaqueFunction(function=_create)])

"""move_group for the Panda as MoveIt's own demo launch files start it (before MoveItConfigsBuilder):
the URDF through xacro, the SRDF, kinematics.yaml, joint_limits.yaml and moveit_controllers.yaml of
moveit_resources_panda_moveit_config as parameters of `moveit_ros_move_group move_group`. Nothing in it
names gazelle; with gazelle, that executable is gazelle's move_group.

    ros2 launch examples/arms/panda_move_group.launch.py
"""

import os

import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import Command, FindExecutable
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def load_file(package, path):
    with open(os.path.join(get_package_share_directory(package), path)) as f:
        return f.read()


def load_yaml(package, path):
    with open(os.path.join(get_package_share_directory(package), path)) as f:
        return yaml.safe_load(f)


def generate_launch_description():
    config = "moveit_resources_panda_moveit_config"
    urdf = os.path.join(get_package_share_directory(config), "config", "panda.urdf.xacro")
    robot_description = {
        "robot_description": ParameterValue(Command([FindExecutable(name="xacro"), " ", urdf]), value_type=str)
    }
    robot_description_semantic = {"robot_description_semantic": load_file(config, "config/panda.srdf")}
    kinematics = {"robot_description_kinematics": load_yaml(config, "config/kinematics.yaml")}
    joint_limits = {"robot_description_planning": load_yaml(config, "config/joint_limits.yaml")}
    controllers = load_yaml(config, "config/moveit_controllers.yaml")
    move_group = Node(
        package="moveit_ros_move_group",
        executable="move_group",
        output="screen",
        parameters=[robot_description, robot_description_semantic, kinematics, joint_limits, controllers],
    )
    return LaunchDescription([move_group])

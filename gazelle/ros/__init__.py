"""The ROS 2 side: the only package that imports rclpy.

:class:`RosBridge` puts a running :class:`~gazelle.sim.Simulation` on the ROS graph: /clock, the
gazebo_ros and simulation_interfaces services, and every system's topics (mirrored from the bus).
``spawn_main`` is ``gazelle spawn`` (gazebo_ros's spawn_entity.py); ``choose_discovery_range``
keeps a server on this host unless asked otherwise. ``message_definition`` is an interface's text with
its dependencies (rosbag2's and Foxglove's ``ros2msg`` schemas); ``resolve_interface`` is the one way a type
name from a file, the graph or a command line becomes a class (checked against the ament index first).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_attributes

# Imported when first used: the bridge brings MuJoCo and the runtime (1.1 s), which a client such as ``gazelle
# arm``, ``gazelle spawn`` or ``gazelle spawner`` never needs.
if TYPE_CHECKING:
    from ._bridge import RosBridge
    from ._cdr import serialized_joint_states
    from ._controller_spawner import controller_file_params
    from ._controller_spawner import spawner_main as spawner_main
    from ._controller_spawner import unspawner_main as unspawner_main
    from ._dds import announce_often
    from ._definitions import definition_path as interface_file
    from ._definitions import full_text as message_definition
    from ._definitions import message_class
    from ._exposure import LAUNCH_ID_VAR, choose_discovery_range, launch_ended, new_launch_id
    from ._gui_stand_ins import gui_stand_in_main, image_bridge_main
    from ._interfaces import InterfaceError, resolve_interface, split_type_name
    from ._names import gz_topic_on_ros
    from ._planning_scene import pose as matrix_to_pose
    from ._signals import await_signal_shutdown, silence_half_made_objects
    from ._spawn_entity import main as spawn_main

__getattr__ = lazy_attributes(__name__, __file__)


def move_group_main(argv: list[str]) -> int:
    """``gazelle move_group`` (moveit_msgs and the planner load only when it runs)."""
    from ._move_group import move_group_main as main

    return main(argv)


def servo_main(argv: list[str]) -> int:
    """MoveIt Servo's ``servo_node`` (compat/ros_packages/moveit_servo): moveit_msgs and the planner load when
    it runs."""
    from ._servo_node import servo_main as main

    return main(argv)


def ekf_main(argv: list[str]) -> int:
    """robot_localization's ``ekf_node`` (compat/ros_packages/robot_localization), on gazelle.estimation."""
    from ._ekf_node import main

    return main(argv)


def twist_mux_main(argv: list[str]) -> int:
    """twist_mux's ``twist_mux`` (compat/ros_packages/twist_mux)."""
    from ._twist_mux import main

    return main(argv)


def arm_main(argv: list[str]) -> int:
    """``gazelle arm``: move an arm through a running move_group."""
    from ._arm_cli import arm_main as main

    return main(argv)


__all__ = [
    "InterfaceError",
    "announce_often",
    "arm_main",
    "twist_mux_main",
    "await_signal_shutdown",
    "silence_half_made_objects",
    "RosBridge",
    "serialized_joint_states",
    "message_class",
    "interface_file",
    "resolve_interface",
    "split_type_name",
    "message_definition",
    "choose_discovery_range",
    "LAUNCH_ID_VAR",
    "launch_ended",
    "new_launch_id",
    "gui_stand_in_main",
    "gz_topic_on_ros",
    "image_bridge_main",
    "matrix_to_pose",
    "spawn_main",
    "move_group_main",
    "servo_main",
    "ekf_main",
    "spawner_main",
    "unspawner_main",
    "controller_file_params",
]

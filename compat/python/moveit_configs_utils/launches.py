"""The launch descriptions MoveIt Setup Assistant's launch files return (moveit_configs_utils.launches, Jazzy).

Each ``generate_*_launch(moveit_config)`` builds what upstream's builds, from a :class:`MoveItConfigs`: the same
launch arguments, nodes and parameters. The nodes are found by package and executable as any launch file's are;
gazelle installs stand-ins for ``moveit_ros_move_group move_group`` (gazelle's move_group),
``robot_state_publisher``, ``rviz2`` (a line saying where gazelle's viewer is), ``controller_manager spawner``,
``tf2_ros static_transform_publisher`` and ``controller_manager ros2_control_node`` (the robot and its controller
manager in gazelle, in place of MoveIt's mock hardware). ``moveit_setup_assistant`` and ``warehouse_ros_mongo`` have
none: a description that starts them stops with the launch's line naming the executable it could not find.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

from .launch_utils import DeclareBooleanLaunchArg, add_debuggable_node


def generate_rsp_launch(moveit_config: Any) -> LaunchDescription:
    """robot_state_publisher with the URDF, its ``publish_frequency`` a launch argument (15 Hz)."""
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument("publish_frequency", default_value="15.0"))
    ld.add_action(
        Node(
            package="robot_state_publisher",
            executable="robot_state_publisher",
            respawn=True,
            output="screen",
            parameters=[
                moveit_config.robot_description,
                {"publish_frequency": LaunchConfiguration("publish_frequency")},
            ],
        )
    )
    return ld


def generate_moveit_rviz_launch(moveit_config: Any) -> LaunchDescription:
    """rviz2 with ``config/moveit.rviz`` (launch argument ``rviz_config``) and the pipelines, kinematics and joint
    limits MoveIt's RViz plugin reads; under gdb with ``debug:=true``."""
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    ld.add_action(
        DeclareLaunchArgument("rviz_config", default_value=str(Path(moveit_config.package_path) / "config/moveit.rviz"))
    )
    add_debuggable_node(
        ld,
        package="rviz2",
        executable="rviz2",
        output="log",
        respawn=False,
        arguments=["-d", LaunchConfiguration("rviz_config")],
        parameters=[
            moveit_config.planning_pipelines,
            moveit_config.robot_description_kinematics,
            moveit_config.joint_limits,
        ],
    )
    return ld


def generate_setup_assistant_launch(moveit_config: Any) -> LaunchDescription:
    """MoveIt Setup Assistant on the config package (not part of gazelle: its launch names what is missing)."""
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    add_debuggable_node(
        ld,
        package="moveit_setup_assistant",
        executable="moveit_setup_assistant",
        arguments=[["--config_pkg=", str(moveit_config.package_path)]],
    )
    return ld


def _virtual_joints(srdf: Any) -> list[tuple[str, str]]:
    """(parent frame, child link) of each ``<virtual_joint>`` of an SRDF given as text (one given as a launch-time
    substitution is read when the launch runs, so it has none here)."""
    if not isinstance(srdf, str):
        return []
    from gazelle.description import load_string

    semantics = load_string(srdf, format="srdf").value
    return [(vj.parent_frame, vj.child_link) for vj in getattr(semantics, "virtual_joints", ())]


def generate_static_virtual_joint_tfs_launch(moveit_config: Any) -> LaunchDescription:
    """One tf2_ros static_transform_publisher per SRDF virtual joint (parent frame to the robot's root link)."""
    ld = LaunchDescription()
    count = 0
    for srdf in moveit_config.robot_description_semantic.values():
        for parent, child in _virtual_joints(srdf):
            ld.add_action(
                Node(
                    package="tf2_ros",
                    executable="static_transform_publisher",
                    name=f"static_transform_publisher{count}",
                    output="log",
                    arguments=["--frame-id", parent, "--child-frame-id", child],
                )
            )
            count += 1
    return ld


def generate_spawn_controllers_launch(moveit_config: Any) -> LaunchDescription:
    """A controller_manager spawner for each controller moveit_controllers.yaml names, and the
    joint_state_broadcaster."""
    names = moveit_config.trajectory_execution.get("moveit_simple_controller_manager", {}).get("controller_names", [])
    ld = LaunchDescription()
    for controller in [*names, "joint_state_broadcaster"]:
        ld.add_action(Node(package="controller_manager", executable="spawner", arguments=[controller], output="screen"))
    return ld


def generate_warehouse_db_launch(moveit_config: Any) -> LaunchDescription:
    """MoveIt's warehouse database (warehouse_ros_mongo; not part of gazelle)."""
    ld = LaunchDescription()
    ld.add_action(
        DeclareLaunchArgument(
            "moveit_warehouse_database_path",
            default_value=str(Path(moveit_config.package_path) / "default_warehouse_mongo_db"),
        )
    )
    ld.add_action(DeclareBooleanLaunchArg("reset", default_value=False))
    ld.add_action(DeclareLaunchArgument("moveit_warehouse_port", default_value="33829"))
    ld.add_action(DeclareLaunchArgument("moveit_warehouse_host", default_value="localhost"))
    database = {
        "overwrite": False,
        "database_path": LaunchConfiguration("moveit_warehouse_database_path"),
        "warehouse_port": LaunchConfiguration("moveit_warehouse_port"),
        "warehouse_host": LaunchConfiguration("moveit_warehouse_host"),
        "warehouse_exec": "mongod",
        "warehouse_plugin": "warehouse_ros_mongo::MongoDatabaseConnection",
    }
    ld.add_action(Node(package="warehouse_ros_mongo", executable="mongo_wrapper_ros.py", parameters=[database]))
    ld.add_action(
        Node(
            package="moveit_ros_warehouse",
            executable="moveit_init_demo_warehouse",
            output="screen",
            condition=IfCondition(LaunchConfiguration("reset")),
        )
    )
    return ld


def generate_move_group_launch(moveit_config: Any) -> LaunchDescription:
    """move_group with every parameter of the config (:meth:`MoveItConfigs.to_dict`) and the launch arguments
    upstream's declares (``allow_trajectory_execution``, ``publish_monitored_planning_scene``, ``capabilities``,
    ``disable_capabilities``, ``monitor_dynamics``, ``debug``)."""
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    ld.add_action(DeclareBooleanLaunchArg("allow_trajectory_execution", default_value=True))
    ld.add_action(DeclareBooleanLaunchArg("publish_monitored_planning_scene", default_value=True))
    capabilities = moveit_config.move_group_capabilities
    ld.add_action(DeclareLaunchArgument("capabilities", default_value=capabilities["capabilities"]))
    ld.add_action(DeclareLaunchArgument("disable_capabilities", default_value=capabilities["disable_capabilities"]))
    ld.add_action(DeclareBooleanLaunchArg("monitor_dynamics", default_value=False))
    publish = LaunchConfiguration("publish_monitored_planning_scene")
    own = {
        "publish_robot_description_semantic": True,
        "allow_trajectory_execution": LaunchConfiguration("allow_trajectory_execution"),
        # kept text, so that an empty value stays a string parameter
        "capabilities": ParameterValue(LaunchConfiguration("capabilities"), value_type=str),
        "disable_capabilities": ParameterValue(LaunchConfiguration("disable_capabilities"), value_type=str),
        "publish_planning_scene": publish,
        "publish_geometry_updates": publish,
        "publish_state_updates": publish,
        "publish_transforms_updates": publish,
        "monitor_dynamics": False,
    }
    add_debuggable_node(
        ld,
        package="moveit_ros_move_group",
        executable="move_group",
        commands_file=str(Path(moveit_config.package_path) / "launch" / "gdb_settings.gdb"),
        output="screen",
        parameters=[moveit_config.to_dict(), own],
        extra_debug_args=["--debug"],
        additional_env={"DISPLAY": os.environ.get("DISPLAY", "")},
    )
    return ld


def _include(path: Path, **kwargs: Any) -> IncludeLaunchDescription:
    return IncludeLaunchDescription(PythonLaunchDescriptionSource(str(path)), **kwargs)


def generate_demo_launch(moveit_config: Any, launch_package_path: Any = None) -> LaunchDescription:
    """The self-contained demo: the config package's static_virtual_joint_tfs (when it has one), rsp, move_group,
    moveit_rviz (``use_rviz``), warehouse_db (``db``) and spawn_controllers launch files, and
    controller_manager's ros2_control_node with ``config/ros2_controllers.yaml``. ``launch_package_path``: where
    those launch files are, when not in the config package."""
    base = Path(moveit_config.package_path if launch_package_path is None else launch_package_path)
    ld = LaunchDescription()
    ld.add_action(
        DeclareBooleanLaunchArg(
            "db", default_value=False, description="By default, we do not start a database (it can be large)"
        )
    )
    ld.add_action(
        DeclareBooleanLaunchArg("debug", default_value=False, description="By default, we are not in debug mode")
    )
    ld.add_action(DeclareBooleanLaunchArg("use_rviz", default_value=True))
    if (base / "launch/static_virtual_joint_tfs.launch.py").exists():
        ld.add_action(_include(base / "launch/static_virtual_joint_tfs.launch.py"))
    ld.add_action(_include(base / "launch/rsp.launch.py"))
    ld.add_action(_include(base / "launch/move_group.launch.py"))
    ld.add_action(
        _include(base / "launch/moveit_rviz.launch.py", condition=IfCondition(LaunchConfiguration("use_rviz")))
    )
    ld.add_action(_include(base / "launch/warehouse_db.launch.py", condition=IfCondition(LaunchConfiguration("db"))))
    ld.add_action(
        Node(
            package="controller_manager",
            executable="ros2_control_node",
            parameters=[str(Path(moveit_config.package_path) / "config/ros2_controllers.yaml")],
            remappings=[("/controller_manager/robot_description", "/robot_description")],
        )
    )
    ld.add_action(_include(base / "launch/spawn_controllers.launch.py"))
    return ld

"""moveit_configs_utils (issue 51 item 2), in-process: MoveItConfigsBuilder on a MoveIt Setup Assistant–style Panda
package gives the parameters MoveIt Jazzy's gives, and the ``generate_*_launch`` functions the nodes its launch
files start. The ROS test (tests/integration/test_moveit_config_package.py) launches the package."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
import yaml
from _msa_package import PACKAGE, install_panda_config


@pytest.fixture
def config(tmp_path, monkeypatch) -> Path:
    share = install_panda_config(tmp_path / "install")
    monkeypatch.setenv("AMENT_PREFIX_PATH", f"{tmp_path / 'install'}{os.pathsep}{sys.prefix}")
    return share


def test_the_builder_reads_a_setup_assistant_package_as_moveits_does(config):
    from moveit_configs_utils import MoveItConfigsBuilder

    moveit_config = MoveItConfigsBuilder("panda", package_name=PACKAGE).to_moveit_configs()
    params = moveit_config.to_dict()
    assert set(params) == {
        "robot_description",
        "robot_description_semantic",
        "robot_description_kinematics",
        "robot_description_planning",
        "planning_pipelines",
        "default_planning_pipeline",
        "ompl",
        "chomp",
        "pilz_industrial_motion_planner",
        "stomp",
        "moveit_manage_controllers",
        "trajectory_execution",
        "moveit_controller_manager",
        "moveit_simple_controller_manager",
        "publish_planning_scene",
        "publish_geometry_updates",
        "publish_state_updates",
        "publish_transforms_updates",
        "publish_robot_description",
        "publish_robot_description_semantic",
    }
    # config/panda.urdf.xacro (Setup Assistant's, with ros2_control) wins over .setup_assistant's urdf/panda.urdf
    assert '<ros2_control name="PandaFakeSystem"' in params["robot_description"]
    assert '<group name="panda_arm">' in params["robot_description_semantic"]
    config_dir = config / "config"
    assert params["robot_description_kinematics"] == yaml.safe_load((config_dir / "kinematics.yaml").read_text())
    # the config's chomp and ompl pipelines, then moveit_configs_utils' own pilz and stomp; ompl the default
    assert params["planning_pipelines"] == ["chomp", "ompl", "pilz_industrial_motion_planner", "stomp"]
    assert params["default_planning_pipeline"] == "ompl"
    assert params["ompl"] == yaml.safe_load((config_dir / "ompl_planning.yaml").read_text())
    assert params["pilz_industrial_motion_planner"]["planning_plugins"] == [
        "pilz_industrial_motion_planner/CommandPlanner"
    ]
    # joint_limits.yaml with pilz_cartesian_limits.yaml added (the Pilz pipeline is loaded)
    planning = params["robot_description_planning"]
    assert planning["joint_limits"]["panda_joint1"]["max_velocity"] == 2.175
    assert planning["cartesian_limits"]["max_trans_vel"] == 1.0
    # of moveit_controllers.yaml and ros2_controllers.yaml, moveit's
    assert params["moveit_simple_controller_manager"]["controller_names"] == ["panda_arm_controller"]
    assert params["trajectory_execution"]["allowed_start_tolerance"] == 0.01
    assert params["moveit_manage_controllers"] is True
    assert params["publish_planning_scene"] is True and params["publish_robot_description"] is False


def test_the_builders_choices_and_refusals_are_moveits(config):
    from moveit_configs_utils import MoveItConfigsBuilder

    (config / "config" / "ompl_planning.yaml").write_text("planning_plugins:\n  - ompl_interface/OMPLPlanner\n")
    built = (
        MoveItConfigsBuilder("panda", package_name=PACKAGE)
        .planning_pipelines(
            pipelines=["ompl", "pilz_industrial_motion_planner"],
            default_planning_pipeline="pilz_industrial_motion_planner",
        )
        .trajectory_execution(moveit_manage_controllers=False)
        .to_moveit_configs()
    )
    pipelines = built.planning_pipelines
    assert pipelines["default_planning_pipeline"] == "pilz_industrial_motion_planner"
    assert (
        "RRTConnect" in pipelines["ompl"]["planner_configs"]
    )  # an ompl file without planner_configs gets the defaults
    assert built.trajectory_execution["moveit_manage_controllers"] is False
    with pytest.raises(RuntimeError, match="doesn't name any of the input pipelines"):
        MoveItConfigsBuilder("panda", package_name=PACKAGE).planning_pipelines(default_planning_pipeline="nope")
    (config / "config" / "moveit_controllers.yaml").rename(config / "config" / "arm_controllers.yaml")
    with pytest.raises(RuntimeError, match="Unable to guess which parameter file to load"):
        MoveItConfigsBuilder("panda", package_name=PACKAGE).trajectory_execution()


def test_the_launch_functions_start_gazelles_move_group_with_the_configs_parameters(config):
    from moveit_configs_utils import MoveItConfigsBuilder
    from moveit_configs_utils.launches import generate_move_group_launch, generate_spawn_controllers_launch

    from launch import LaunchContext
    from launch.actions import DeclareLaunchArgument
    from launch_ros.actions import Node

    moveit_config = MoveItConfigsBuilder("panda", package_name=PACKAGE).to_moveit_configs()
    ld = generate_move_group_launch(moveit_config)
    nodes = [e for e in ld.entities if isinstance(e, Node)]
    assert len(nodes) == 2  # as upstream's: the node, and the same under gdb when debug:=true
    context = LaunchContext()
    for declared in (e for e in ld.entities if isinstance(e, DeclareLaunchArgument)):
        declared.visit(context)  # the launch arguments' defaults, as the launch sets them
    assert context.launch_configurations["allow_trajectory_execution"] == "True"
    command = nodes[0]._command(context)
    assert command[0] == str(Path(sys.prefix) / "lib" / "moveit_ros_move_group" / "move_group")
    assert (
        nodes[0].parameters[0]["robot_description_semantic"]
        == moveit_config.robot_description_semantic["robot_description_semantic"]
    )
    spawners = [e for e in generate_spawn_controllers_launch(moveit_config).entities if isinstance(e, Node)]
    assert [s.arguments for s in spawners] == [["panda_arm_controller"], ["joint_state_broadcaster"]]

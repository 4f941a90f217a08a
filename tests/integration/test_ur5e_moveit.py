"""A UR5e with MoveIt from Universal Robots' own packages, launched as their documentation launches it (issue 51):
``ros2 launch ur_simulation_gz ur_sim_moveit.launch.py ur_type:=ur5e`` (Jazzy's package is ur_simulation_gz; the issue
writes its Humble name, ur_simulation_gazebo). The launch files, ur_moveit_config's MoveIt configuration and SRDF and
ur_robot_driver's ``wait_for_robot_description`` are UR's, byte for byte (tests/data/ur, SOURCES.md).

ur_moveit_config's moveit_controllers.yaml makes ``scaled_joint_trajectory_controller`` MoveIt's default controller,
while ur_sim_control.launch.py starts ``joint_trajectory_controller`` unless told otherwise: with upstream MoveIt too
an execution then fails with the scaled controller's action not connected (UniversalRobots/
Universal_Robots_ROS2_Gazebo_Simulation issues 8 and 14: "works fine if the default controller is switched"). One
test runs the command unchanged: the execution fails as MoveIt's does, and the message says which controller to
start; the other switches it as UR's maintainers say, on the command line (``initial_joint_controller:=...``, an
argument ur_sim_control.launch.py declares; ros2 launch passes it down as a launch configuration).

Before, the launch stopped at "launch configuration 'warehouse_sqlite_path' does not exist": gazelle scoped an included
file's launch configurations, and ur_moveit.launch.py starts move_group from an event handler after its include ended.

About 10 s alone (xacro twice, the spawn, the launch's eight processes, move_group's model).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np
import pytest
from _harness import Proc, RosClient, start, wait_for
from _ur import install_ur
from gazebo_msgs.srv import GetEntityState
from geometry_msgs.msg import Pose
from moveit_msgs.action import MoveGroup
from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint, PositionConstraint
from moveit_msgs.srv import GetPositionFK
from rclpy.action.client import ActionClient
from shape_msgs.msg import SolidPrimitive

pytestmark = pytest.mark.slow

JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
TARGET = [0.5, -1.2, 1.0, -1.4, -0.5, 0.3]  # the pose goal is tool0 at these joint values


def pose_goal(link: str, frame: str, pose: Pose) -> MoveGroup.Goal:
    """MoveIt's pose goal as moveit_commander/MoveGroupInterface send it: a 1 mm sphere and 0.01 rad about each axis."""
    goal = MoveGroup.Goal()
    req = goal.request
    req.group_name = "ur_manipulator"
    req.num_planning_attempts = 1
    req.allowed_planning_time = 5.0
    req.max_velocity_scaling_factor = 0.5
    req.max_acceleration_scaling_factor = 0.5
    position = PositionConstraint(link_name=link, weight=1.0)
    position.header.frame_id = frame
    position.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001])]
    at = Pose()
    at.position = pose.position
    at.orientation.w = 1.0
    position.constraint_region.primitive_poses = [at]
    orientation = OrientationConstraint(link_name=link, orientation=pose.orientation, weight=1.0)
    orientation.header.frame_id = frame
    orientation.absolute_x_axis_tolerance = orientation.absolute_y_axis_tolerance = 0.01
    orientation.absolute_z_axis_tolerance = 0.01
    req.goal_constraints = [Constraints(position_constraints=[position], orientation_constraints=[orientation])]
    return goal


def _launch(tmp_path: Path, *args: str) -> Proc:
    """``ros2 launch ur_simulation_gz ur_sim_moveit.launch.py ur_type:=ur5e gazebo_gui:=false`` and ``args``, with UR's
    packages installed under ``tmp_path``, once move_group says it can plan."""
    prefix = install_ur(tmp_path / "install")
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    launch = start(
        [str(Path(sys.prefix) / "bin" / "ros2"), "launch", "ur_simulation_gz", "ur_sim_moveit.launch.py"]
        + ["ur_type:=ur5e", "gazebo_gui:=false", *args],
        "ros2 launch",
        env=env,
    )
    try:
        launch.wait_line("Configured and activated ", timeout=120)
        launch.wait_line("You can start planning now!", timeout=60)
    except BaseException:
        launch.interrupt(30)
        raise
    return launch


def _move_to_target(ros: RosClient, launch: Proc) -> tuple[Pose, MoveGroup.Result]:
    """tool0's pose at :data:`TARGET` (move_group's FK), and the result of a MoveGroup pose goal to it."""
    fk = GetPositionFK.Request(fk_link_names=["tool0"])
    fk.header.frame_id = "base_link"
    fk.robot_state.joint_state.name, fk.robot_state.joint_state.position = JOINTS, TARGET
    answer = ros.call(GetPositionFK, "/compute_fk", fk)
    assert answer.error_code.val == MoveItErrorCodes.SUCCESS, answer.error_code.message
    target = answer.pose_stamped[0].pose
    client = ActionClient(ros.node, MoveGroup, "/move_action")
    assert client.wait_for_server(timeout_sec=30), "/move_action is not served"
    accepted, result = ros.send_goal(
        client, pose_goal("tool0", "base_link", target), 90, said=lambda: "\n".join(launch.lines[-40:])
    )
    assert accepted and result is not None, "\n".join(launch.lines[-40:])
    return target, result.result


def test_the_unchanged_command_fails_as_with_moveit_and_says_which_controller_to_start(ros_env, tmp_path):
    """UR's command as its README gives it: MoveIt sends to its default controller, scaled_joint_trajectory_controller,
    which ur_sim_control.launch.py did not start (it started joint_trajectory_controller): CONTROL_FAILED, as with
    MoveIt and Gazebo, and the message says what to change (issue 51 item 3: "or say in one line what to use
    instead"). Before, it said only that the scaled controller's action was not available. ~25 s: one launch."""
    launch = _launch(tmp_path)
    ros = RosClient("ur5e_moveit_unchanged")
    try:
        launch.wait_line("Configured and activated joint_trajectory_controller", timeout=60)
        _, result = _move_to_target(ros, launch)
        code = result.error_code
        assert code.val == MoveItErrorCodes.CONTROL_FAILED, code.message
        assert "joint_trajectory_controller, listed for the same joints, is running" in code.message, code.message
        assert "start scaled_joint_trajectory_controller in its place" in code.message, code.message
    finally:
        ros.close()
        launch.interrupt(30)


def test_urs_own_moveit_launch_brings_up_the_ur5e_and_a_pose_goal_executes_within_a_millimetre(ros_env, tmp_path):
    launch = _launch(tmp_path, "initial_joint_controller:=scaled_joint_trajectory_controller")
    ros = RosClient("ur5e_moveit_test")
    try:
        launch.wait_line("Configured and activated scaled_joint_trajectory_controller", timeout=60)
        said = "\n".join(launch.lines)
        for line in ("Received message on /robot_description", "Successfully spawned entity [ur]"):
            assert line in said, said
        target, result = _move_to_target(ros, launch)
        code = result.error_code
        assert code.val == MoveItErrorCodes.SUCCESS, (code.message, "\n".join(launch.lines[-40:]))
        # the simulation's wrist: tool0 is fixed to wrist_3_link, so its pose is wrist_3_link's (the arm's base is at
        # the world's origin, as ur_gz.urdf.xacro mounts it); judged once the controller holds the last point
        goal = np.array([target.position.x, target.position.y, target.position.z])

        def error() -> float:
            # base_link is the world's origin here (ur_gz.urdf.xacro's world_joint is the identity); an idempotent
            # query, sent again if a first reply is lost (tests/_harness.py RosClient.call)
            req = GetEntityState.Request(name="ur::wrist_3_link")
            state = ros.call(GetEntityState, "/get_entity_state", req, timeout=30, resend_every=2)
            assert state.success, "no link wrist_3_link in the simulation"
            p = state.state.pose.position
            return float(np.linalg.norm(np.array([p.x, p.y, p.z]) - goal))

        wait_for(lambda: error() < 1e-3, 15, f"tool0 within 1 mm of {goal}")
    finally:
        ros.close()
        launch.interrupt(30)

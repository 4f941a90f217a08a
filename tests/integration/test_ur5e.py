"""A UR5e from Universal Robots' own packages, launched as their README launches it (issue 51 item 3):
``ros2 launch ur_simulation_gz ur_sim_control.launch.py ur_type:=ur5e`` with UR's scaled trajectory controller as the
initial one (``initial_joint_controller:=scaled_joint_trajectory_controller``, a declared argument of the launch
file). The files are UR's, unchanged (tests/data/ur, see SOURCES.md). Before, the launch file stopped at its import
of launch's ``IfElseSubstitution``, and the spawner at ``ur_controllers/ScaledJointTrajectoryController does not
exist``. A FollowJointTrajectory goal to the scaled controller then runs on gazelle's hardware, where speed scaling is
1.0 (gz_ros2_control's hardware has no speed scaling interface), and the arm ends within UR's goal tolerance and settles within 1 mrad of its last point.
Slow (about 40 s): xacro, the spawn of the arm's meshes and the launch's five processes."""

from __future__ import annotations

import os
import sys
import threading
from pathlib import Path

import pytest
from _harness import RosClient, start, wait_for
from _ur import install_ur
from control_msgs.action import FollowJointTrajectory
from rclpy.action.client import ActionClient
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectoryPoint

pytestmark = pytest.mark.slow

JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
ACTION = "/scaled_joint_trajectory_controller/follow_joint_trajectory"


def test_the_ur5e_of_urs_gazebo_simulation_follows_a_trajectory_through_the_scaled_controller(ros_env, tmp_path):
    prefix = install_ur(tmp_path / "install")
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    launch = start(
        [str(Path(sys.prefix) / "bin" / "ros2"), "launch", "ur_simulation_gz", "ur_sim_control.launch.py"]
        + ["ur_type:=ur5e", "gazebo_gui:=false", "launch_rviz:=false"]
        + ["initial_joint_controller:=scaled_joint_trajectory_controller"],
        "ros2 launch",
        env=env,
    )
    ros = RosClient("ur5e_test")
    try:
        launch.wait_line("Configured and activated scaled_joint_trajectory_controller", timeout=120)
        said = "\n".join(launch.lines)
        assert "Successfully spawned entity [ur]" in said, said
        assert "the hardware has no state interface 'speed_scaling/speed_scaling_factor'" in said, said
        heard: list[JointState] = []
        lock = threading.Lock()

        def keep(msg: JointState) -> None:
            with lock:
                heard.append(msg)

        ros.node.create_subscription(JointState, "/joint_states", keep, 10)
        client = ActionClient(ros.node, FollowJointTrajectory, ACTION)
        assert client.wait_for_server(timeout_sec=30), f"{ACTION} is not served"
        goal = FollowJointTrajectory.Goal()
        goal.trajectory.joint_names = JOINTS
        final = [0.5, -1.2, 1.0, -1.4, -0.5, 0.3]
        middle = [0.25, -1.4, 0.5, -1.5, -0.25, 0.15]
        points = []
        for t, q in ((1.5, middle), (3.0, final)):
            point = JointTrajectoryPoint(positions=q)
            point.time_from_start.sec, point.time_from_start.nanosec = int(t), int((t % 1) * 1e9)
            points.append(point)
        goal.trajectory.points = points
        accepted, result = ros.send_goal(client, goal, 60, said=lambda: "\n".join(launch.lines[-30:]))
        assert accepted
        assert result.result.error_code == FollowJointTrajectory.Result.SUCCESSFUL, result.result.error_string
        # the goal succeeds within UR's goal tolerance (0.1 rad, ur_controllers.yaml); the arm then settles on the
        # last point, which the controller holds

        def error() -> float:
            with lock:
                last = heard[-1]
            q = [last.position[list(last.name).index(j)] for j in JOINTS]
            return max(abs(a - b) for a, b in zip(q, final, strict=True))

        assert error() < 0.1
        wait_for(lambda: error() < 1e-3, 5, "the arm within 1 mrad of the trajectory's last point")
    finally:
        ros.close()
        launch.interrupt(30)

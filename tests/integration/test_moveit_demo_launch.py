"""MoveIt's demo.launch.py of a Setup Assistant config package, as its users launch it (issue 51):
``ros2 launch panda_moveit_config demo.launch.py`` (``generate_demo_launch(MoveItConfigsBuilder("panda", ...))``, the
Panda config of moveit_resources in ../shared/fixtures/real). It starts tf2_ros' static_transform_publisher for the
SRDF's virtual joint and controller_manager's ros2_control_node with ros2_controllers.yaml, which gazelle had neither
of: the launch stopped at the first. Now ros2_control_node runs the robot in gazelle (a server it starts, none running),
fixed at its base as MoveIt's mock hardware keeps it, and the demo's spawners bring up its controllers: move_group
plans, and a trajectory sent to panda_arm_controller moves the arm there. Slow (about 40 s): xacro of the Panda, the
server started by the launch, move_group."""

from __future__ import annotations

import os
import sys
import threading
from pathlib import Path

import pytest
from _harness import RosClient, start, wait_for
from _msa_package import PACKAGE, install_panda_config
from control_msgs.action import FollowJointTrajectory
from rclpy.action.client import ActionClient
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
from trajectory_msgs.msg import JointTrajectoryPoint

pytestmark = pytest.mark.slow

JOINTS = [f"panda_joint{i}" for i in range(1, 8)]
TARGET = [0.3, -0.5, 0.2, -2.0, 0.1, 1.8, 0.6]


def test_the_panda_configs_demo_launch_brings_up_move_group_the_robot_and_its_controllers(ros_env, tmp_path):
    prefix = tmp_path / "install"
    install_panda_config(prefix)
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    launch = start(
        [str(Path(sys.prefix) / "bin" / "ros2"), "launch", PACKAGE, "demo.launch.py", "use_rviz:=false"],
        "ros2 launch",
        env=env,
    )
    ros = RosClient("moveit_demo_test")
    try:
        launch.wait_line("You can start planning now!", 120)
        launch.wait_line("Configured and activated panda_arm_controller", 120)
        said = "\n".join(launch.lines)
        assert "no gazelle server is running: starting one" in said, said
        assert "controller manager '/controller_manager' at 100 Hz" in said, said  # ros2_controllers.yaml's rate

        static: list[TFMessage] = []
        # depth 100 as tf2's listener has for /tf_static: robot_state_publisher and the static_transform_publisher
        # both send their latched transforms at once, and a depth-1 reader kept only the one taken last
        latched = QoSProfile(
            depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        ros.node.create_subscription(TFMessage, "/tf_static", static.append, latched)
        wait_for(
            lambda: any(
                t.child_frame_id == "panda_link0" and t.header.frame_id == "world" for m in static for t in m.transforms
            ),
            20,
            "the virtual joint's static transform world -> panda_link0",
        )

        heard: list[JointState] = []
        lock = threading.Lock()

        def keep(msg: JointState) -> None:
            with lock:
                heard.append(msg)

        ros.node.create_subscription(JointState, "/joint_states", keep, 10)
        client = ActionClient(ros.node, FollowJointTrajectory, "/panda_arm_controller/follow_joint_trajectory")
        assert client.wait_for_server(timeout_sec=30)
        goal = FollowJointTrajectory.Goal()
        goal.trajectory.joint_names = JOINTS
        point = JointTrajectoryPoint(positions=TARGET)
        point.time_from_start.sec = 2
        goal.trajectory.points = [point]
        accepted, result = ros.send_goal(client, goal, 60, said=lambda: "\n".join(launch.lines[-30:]))
        assert accepted
        assert result.result.error_code == FollowJointTrajectory.Result.SUCCESSFUL, result.result.error_string

        def error() -> float:
            with lock:
                last = heard[-1]
            q = [last.position[list(last.name).index(j)] for j in JOINTS]
            return max(abs(a - b) for a, b in zip(q, TARGET, strict=True))

        wait_for(lambda: heard and error() < 2e-3, 10, "the arm at the trajectory's point (its base fixed)")
    finally:
        ros.close()
        rc = launch.interrupt(40)
    assert rc == 0, launch.output
    assert "gazelle: shutting down" in launch.output  # the server ros2_control_node started went with it

"""ros-controls/gz_ros2_control (jazzy) gz_ros2_control_demos unchanged, as its README says (issue 49): `colcon
build --symlink-install`, then `ros2 launch gz_ros2_control_demos diff_drive_example.launch.py`. Of its seven C++
example nodes, six need only rclcpp and the wheels' messages and are compiled for real (issue 54: the C++ tier);
example_position includes control_msgs' C++ headers, which gazelle's control_msgs does not have: one line, and a
placeholder that says so when run. The controllers come up, the robot drives 1 m on
/diff_drive_base_controller/cmd_vel (TwistStamped) with its odometry and ground truth within 2 %, then the
README's `ros2 run gz_ros2_control_demos example_diff_drive` (the real C++ node) drives it in a circle.
Longer than 30 s: the six nodes compile against rclcpp (about 30 s on 2 cores) before the launch."""

from __future__ import annotations

import os
import signal

import pytest
from _harness import wait_for
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace
from .test_blog_workspace import shell

pytestmark = pytest.mark.slow


def test_gz_ros2_control_diff_drive_demo_builds_spawns_controllers_and_drives(tmp_path, ros_client, cpp_tier):
    ws = workspace(tmp_path, "gz_ros2_control", ["gz_ros2_control_demos"])
    out = colcon_build(ws)
    lines = [line for line in out.splitlines() if line.startswith("gazelle: gz_ros2_control_demos: ")]
    assert len(lines) == 1 and "example_position is not built (it needs control_msgs, " in lines[0], out
    run = shell(f"cd {ws} && source install/setup.bash && ros2 run gz_ros2_control_demos example_position", "run")
    assert run.wait(60) == 1, run.output
    assert "example_position is a compiled program gazelle did not build: it needs control_msgs" in run.output
    odom = Topic.subscribe(ros_client, Odometry, "/diff_drive_base_controller/odom")
    proc = launch(ws, "ros2 launch gz_ros2_control_demos diff_drive_example.launch.py")
    try:
        proc.wait_line("Configured and activated diff_drive_base_controller", 120)
        cmd = ros_client.node.create_publisher(TwistStamped, "/diff_drive_base_controller/cmd_vel", 10)

        def send(speed: float) -> None:
            msg = TwistStamped()
            msg.twist.linear.x = speed
            cmd.publish(msg)

        drive_a_metre(ros_client, "diff_drive", send, odom, speed=0.5)
        # the README's C++ example: 0.1 m/s and 0.1 rad/s, every 50 ms, until stopped
        example = shell(
            f"cd {ws} && source install/setup.bash && ros2 run gz_ros2_control_demos example_diff_drive", "cpp"
        )
        try:

            def circling() -> bool:
                twist = odom.latest().twist.twist
                return abs(twist.linear.x - 0.1) < 0.01 and abs(twist.angular.z - 0.1) < 0.01

            wait_for(circling, 60, "odometry of example_diff_drive's 0.1 m/s, 0.1 rad/s")
        finally:
            os.killpg(example.popen.pid, signal.SIGKILL)  # its loop never ends (upstream's while (1))
            example.wait(10)
    finally:
        stop(proc)

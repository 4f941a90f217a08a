"""ros-controls/gz_ros2_control (jazzy) gz_ros2_control_demos unchanged, as its README says (issue 49): `colcon
build --symlink-install` (its seven C++ example nodes need rclcpp: each is one line and installs a placeholder that
says so when run; launch files, configs and URDFs install), then `ros2 launch gz_ros2_control_demos
diff_drive_example.launch.py`. The controllers come up and the robot drives 1 m on
/diff_drive_base_controller/cmd_vel (TwistStamped) with its odometry and ground truth within 2 %."""

from __future__ import annotations

import pytest
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace
from .test_blog_workspace import shell

pytestmark = pytest.mark.slow


def test_gz_ros2_control_diff_drive_demo_builds_spawns_controllers_and_drives(tmp_path, ros_client):
    ws = workspace(tmp_path, "gz_ros2_control", ["gz_ros2_control_demos"])
    out = colcon_build(ws)
    lines = [line for line in out.splitlines() if line.startswith("gazelle: gz_ros2_control_demos: ")]
    assert len(lines) == 7 and all("(it needs rclcpp" in line for line in lines), out
    run = shell(f"cd {ws} && source install/setup.bash && ros2 run gz_ros2_control_demos example_diff_drive", "run")
    assert run.wait(60) == 1, run.output
    assert "example_diff_drive is a compiled program gazelle did not build: it needs rclcpp" in run.output
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
    finally:
        stop(proc)

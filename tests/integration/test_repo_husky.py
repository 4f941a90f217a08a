"""husky/husky (humble-devel) unchanged, as a user runs it (issue 49): `colcon build --symlink-install` of
husky_description, husky_control, husky_gazebo and husky_base (whose hardware driver needs hardware_interface,
pluginlib, rclcpp and husky_msgs: one line, the rest installs), then `ros2 launch husky_gazebo
husky_playpen.launch.py`. The launch starts Classic's gzserver and gzclient, spawn_entity.py, two controller
spawners, robot_localization's ekf_node, interactive_marker_twist_server's marker_server and twist_mux; a missing
package aborted it. The Husky's IMU and GPS publish, and it drives 1 m on /cmd_vel through twist_mux (its
`external` input) into husky_velocity_controller with odometry and ground truth within 2 %. The playpen's models
from Gazebo Classic's online model database are read from ~/.gazebo/models as Classic reads them (a stand-in
jersey_barrier there); each one that is not there is one error-level line saying how to get it."""

from __future__ import annotations

import pytest
from _harness import wait_for
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu, NavSatFix

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace

pytestmark = pytest.mark.slow

PACKAGES = ["husky_base", "husky_control", "husky_description", "husky_gazebo"]


def test_husky_playpen_builds_launches_and_drives_through_twist_mux(tmp_path, ros_client):
    ws = workspace(tmp_path, "husky", PACKAGES)
    out = colcon_build(ws)
    assert "gazelle: husky_base: husky_hardware is not built (it needs hardware_interface, pluginlib, rclcpp" in out
    imu = Topic.subscribe(ros_client, Imu, "/imu/data_raw")  # /imu/data is imu_filter_madgwick's, off by default
    gps = Topic.subscribe(ros_client, NavSatFix, "/gps/data")
    odom = Topic.subscribe(ros_client, Odometry, "/husky_velocity_controller/odom")
    barrier = tmp_path / "home" / ".gazebo" / "models" / "jersey_barrier"
    barrier.mkdir(parents=True)
    (barrier / "model.config").write_text("<model><name>Jersey Barrier</name><sdf>model.sdf</sdf></model>")
    (barrier / "model.sdf").write_text(
        '<sdf version="1.4"><model name="jersey_barrier"><static>true</static><link name="link"><collision name="c">'
        "<pose>0 0 0.5 0 0 0</pose><geometry><box><size>4 0.4 1</size></box></geometry></collision></link></model></sdf>"
    )
    proc = launch(ws, f"export HOME={tmp_path / 'home'} && ros2 launch husky_gazebo husky_playpen.launch.py")
    try:
        proc.wait_line("Configured and activated husky_velocity_controller", 120)
        missing = [line for line in proc.output.splitlines() if "is not on the model paths nor in" in line]
        assert missing, proc.output
        assert all("error: [URI_UNRESOLVED]" in line and "osrf/gazebo_models" in line for line in missing), missing
        assert any("model 'dumpster'" in line for line in missing), proc.output
        assert not any("model 'jersey_barrier'" in line for line in missing), proc.output
        proc.wait_line("Topic handler 'topics.external' subscribed to topic 'cmd_vel'", 30)
        wait_for(lambda: imu.count() > 10 and gps.count() > 2, 60, "/imu/data_raw and /gps/data")
        cmd = ros_client.node.create_publisher(Twist, "/cmd_vel", 10)

        def send(speed: float) -> None:
            msg = Twist()
            msg.linear.x = speed
            cmd.publish(msg)

        drive_a_metre(ros_client, "husky", send, odom, speed=0.5)
    finally:
        stop(proc)

"""gazebosim/ros_gz_project_template unchanged, as its README says (issue 49): `colcon build --symlink-install`
of the four packages (ros_gz_example_gazebo compiles two gz-sim systems: each is one line, the worlds and hooks
install), then `ros2 launch ros_gz_example_bringup diff_drive.launch.py rviz:=false`. Its world starts paused (no
`-r` in gz_args, as gz sim does); once played, the robot's lidar publishes on the bridged /diff_drive/scan and it
drives 1 m on /diff_drive/cmd_vel with /diff_drive/odometry and ground truth within 2 %."""

from __future__ import annotations

import pytest
from _harness import wait_for
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace

pytestmark = pytest.mark.slow

PACKAGES = [
    "ros_gz_example_application",
    "ros_gz_example_bringup",
    "ros_gz_example_description",
    "ros_gz_example_gazebo",
]


def test_template_diff_drive_builds_plays_and_drives(tmp_path, ros_client):
    ws = workspace(tmp_path, "ros_gz_project_template", PACKAGES)
    out = colcon_build(ws)
    assert "gazelle: ros_gz_example_gazebo: BasicSystem is not built (it needs gz-sim" in out, out
    scan = Topic.subscribe(ros_client, LaserScan, "/diff_drive/scan")
    odom = Topic.subscribe(ros_client, Odometry, "/diff_drive/odometry")
    proc = launch(ws, "ros2 launch ros_gz_example_bringup diff_drive.launch.py rviz:=false")
    try:
        proc.wait_line("PAUSED", 120)
        proc.wait_line("Creating relay [/diff_drive/cmd_vel] -> [/model/diff_drive/cmd_vel]", 60)
        ros_client.call(Empty, "/unpause_physics", Empty.Request())
        wait_for(lambda: scan.count() > 2, 60, "/diff_drive/scan")
        assert len(scan.latest().ranges) == 640
        cmd = ros_client.node.create_publisher(Twist, "/diff_drive/cmd_vel", 10)

        def send(speed: float) -> None:
            msg = Twist()
            msg.linear.x = speed
            cmd.publish(msg)

        drive_a_metre(ros_client, "diff_drive", send, odom, speed=0.5)
    finally:
        stop(proc)

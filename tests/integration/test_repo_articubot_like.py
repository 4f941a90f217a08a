"""articubot_one (joshnewans/articubot_one, the Articulated Robotics tutorial robot) as its tutorial runs it (issue
49): `colcon build --symlink-install`, then `ros2 launch <pkg> launch_sim.launch.py world:=.../obstacles.world`,
with ros2_control (twist_mux -> /diff_cont/cmd_vel_unstamped, diff_drive_controller) and without it (Classic's
gazebo_ros_diff_drive on /cmd_vel). The repository has no licence, so tests/data/articubot_like is a stand-in
written with its structure (its README says what it mirrors): the lidar's `<argument>~/out:=scan</argument>`
publishes /scan, which sees the world's wall ahead and box to the left, and the robot drives 1 m with odometry
and ground truth within 2 %."""

from __future__ import annotations

import math
from typing import Any

import pytest
from _harness import wait_for
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Image, LaserScan

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace

pytestmark = pytest.mark.slow

LIDAR_X = -0.22 + 0.12
"""The lidar's x in base_link (chassis at -0.22, lidar 0.12 ahead of it): the robot spawns at the origin."""


def _ray(scan: LaserScan, angle: float) -> float:
    i = round((angle - scan.angle_min) / scan.angle_increment)
    return scan.ranges[i]


def _settled_x(ros: Any) -> float:
    """The robot's x once it has stopped moving (two looks 0.3 s apart within 1 mm)."""
    box: dict[str, float] = {"x": math.nan}

    def still() -> bool:
        x = ros.entity_state("my_bot").state.pose.position.x
        settled = abs(x - box["x"]) < 0.001
        box["x"] = x
        return settled

    wait_for(still, 20, "the robot at rest", interval=0.3)
    return box["x"]


@pytest.mark.parametrize("ros2_control", [True, False])
def test_articubot_like_builds_launches_sees_and_drives(tmp_path, ros_client, ros2_control):
    """One launch each way (~25 s each on this 2-core machine: a colcon build, the server and 1 m at 0.3 m/s)."""
    ws = workspace(tmp_path, "articubot_like", ["articubot_like"])
    colcon_build(ws)
    scans = Topic.subscribe(ros_client, LaserScan, "/scan")
    images = Topic.subscribe(ros_client, Image, "/camera/image_raw")
    odom_topic = "/diff_cont/odom" if ros2_control else "/odom"
    odom = Topic.subscribe(ros_client, Odometry, odom_topic)
    world = ws / "src" / "articubot_like" / "worlds" / "obstacles.world"
    args = f"world:={world}" + ("" if ros2_control else " use_ros2_control:=false")
    proc = launch(ws, f"ros2 launch articubot_like launch_sim.launch.py {args}")
    try:
        if ros2_control:
            proc.wait_line("Configured and activated diff_cont", 120)
            proc.wait_line("Configured and activated joint_broad", 60)
        else:
            proc.wait_line("Successfully spawned entity [my_bot]", 120)
        # the robot settles on its wheels and caster after the spawn (it rolls a few centimetres back): then its
        # scan sees the wall ahead
        x = _settled_x(ros_client)
        wait_for(lambda: scans.latest() and _ray(scans.latest(), 0.0) < 12, 30, "the wall on /scan", interval=0.05)
        scan = scans.latest()
        assert scan.header.frame_id == "laser_frame"
        assert _ray(scan, 0.0) == pytest.approx(3.0 - (x + LIDAR_X), abs=0.03), "the wall ahead"
        assert _ray(scan, math.pi / 2) == pytest.approx(1.5, abs=0.05), "the box to the left"
        wait_for(images.latest, 30, "an image from the camera", interval=0.05)
        assert images.latest().header.frame_id == "camera_link_optical"
        pub = ros_client.node.create_publisher(Twist, "/cmd_vel", 10)

        def send(speed: float) -> None:
            msg = Twist()
            msg.linear.x = speed
            pub.publish(msg)

        drive_a_metre(ros_client, "my_bot", send, odom, speed=0.3)
        wait_for(lambda: scans.latest().header.stamp != scan.header.stamp, 10, "a new scan", interval=0.05)
        x = _settled_x(ros_client)
        assert _ray(scans.latest(), 0.0) == pytest.approx(3.0 - (x + LIDAR_X), abs=0.03), "1 m nearer the wall"
    finally:
        stop(proc)

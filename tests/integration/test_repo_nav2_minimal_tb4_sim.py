"""ros-navigation/nav2_minimal_turtlebot_simulation (jazzy), its TurtleBot4 in the depot world, as a user runs it
(issue 49): `colcon build --symlink-install`, then `ros2 launch nav2_minimal_tb4_sim simulation.launch.py` with no
arguments (rviz2 and the gz client included). The packages are a faithful stand-in with the repository's structure
(tests/data/nav2_tb4_like/SOURCES.md says why and what differs), and Fuel's OpenRobotics/Depot, which the world
includes by URL, is a stand-in put in a test Fuel cache where gz-fuel-tools keeps its downloads (GZ_FUEL_CACHE_PATH;
no network at test time). The robot stands on the Depot's floor, its lidar sees the Depot's walls at the distances
the geometry gives, and it drives 1 m on /cmd_vel with /odom and ground truth within 2 %. Without the model in the
cache the launch says so in one error-level line naming how to get it, and the rest of the world still runs.
Each test starts a whole launch (gz sim, the bridges, robot_state_publisher, xacro): over 30 s."""

from __future__ import annotations

import math

import pytest
from _fuel_depot import DEPOT_URI, fuel_depot
from _harness import wait_for
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu, LaserScan

from ._real_repos import Topic, colcon_build, drive_a_metre, launch, stop, workspace

pytestmark = pytest.mark.slow

PACKAGES = ["nav2_minimal_tb4_description", "nav2_minimal_tb4_sim"]
ROBOT = "nav2_turtlebot4"
HALL = (20.0, 12.0)
"""The stand-in Depot's size: walls' inner faces at x = +-9.9 m and y = +-5.9 m, the floor's top at z = 0."""
LIDAR = (-8.0 - 0.04, -0.5)
"""Where the lidar is: the launch's spawn pose (-8, -0.5) and the lidar 4 cm behind the base (turned 90 degrees)."""


def _range_towards(scan: LaserScan, world_yaw: float) -> float:
    """The range of the ray that points along ``world_yaw`` (the robot faces +x, the lidar is mounted at +90 deg)."""
    angle = (world_yaw - math.pi / 2) % (2 * math.pi)
    i = round((angle - scan.angle_min) / scan.angle_increment)
    return scan.ranges[i % len(scan.ranges)]


def test_tb4_in_the_depot_builds_stands_sees_the_walls_and_drives(tmp_path, ros_client):
    ws = workspace(tmp_path, "nav2_tb4_like", PACKAGES)
    colcon_build(ws)
    fuel_depot(tmp_path / "fuel", size=HALL)
    scan = Topic.subscribe(ros_client, LaserScan, "/scan")
    imu = Topic.subscribe(ros_client, Imu, "/imu")
    odom = Topic.subscribe(ros_client, Odometry, "/odom")
    proc = launch(
        ws, f"export GZ_FUEL_CACHE_PATH={tmp_path / 'fuel'} && ros2 launch nav2_minimal_tb4_sim simulation.launch.py"
    )
    try:
        wait_for(lambda: scan.count() > 2 and imu.count() > 10, 120, "/scan and /imu from the TurtleBot4")
        assert "Fuel model" not in proc.output and "MESH_NOT_FOUND" not in proc.output, proc.output
        z = ros_client.entity_state(ROBOT).state.pose.position.z
        assert abs(z) < 0.01, f"the base stands on the Depot's floor (z = 0), not at {z:.3f}"
        ranges = scan.latest().ranges
        assert all(math.isfinite(r) for r in ranges), "every ray meets a wall of the hall within 20 m"
        hx, hy = HALL[0] / 2 - 0.1, HALL[1] / 2 - 0.1
        for yaw, expected in ((math.pi, LIDAR[0] + hx), (math.pi / 2, hy - LIDAR[1]), (-math.pi / 2, hy + LIDAR[1])):
            assert _range_towards(scan.latest(), yaw) == pytest.approx(expected, abs=0.03), (yaw, expected)
        cmd = ros_client.node.create_publisher(Twist, "/cmd_vel", 10)

        def send(speed: float) -> None:
            msg = Twist()
            msg.linear.x = speed
            cmd.publish(msg)

        drive_a_metre(ros_client, ROBOT, send, odom, speed=0.3)
    finally:
        stop(proc)


def test_without_the_depot_in_a_fuel_cache_the_launch_says_how_to_get_it_in_one_error_line(tmp_path, ros_client):
    ws = workspace(tmp_path, "nav2_tb4_like", PACKAGES)
    colcon_build(ws)
    (tmp_path / "fuel").mkdir()
    imu = Topic.subscribe(ros_client, Imu, "/imu")
    proc = launch(
        ws,
        f"export HOME={tmp_path} GZ_FUEL_CACHE_PATH={tmp_path / 'fuel'} && "
        "ros2 launch nav2_minimal_tb4_sim simulation.launch.py headless:=True use_rviz:=False",
    )
    try:
        wait_for(lambda: imu.count() > 10, 120, "/imu: the world runs without the Depot")
        lines = [line for line in proc.output.splitlines() if "Fuel model 'OpenRobotics/Depot'" in line]
        assert len(lines) == 1, proc.output
        assert "error: [URI_UNRESOLVED]" in lines[0] and f'gz fuel download -u "{DEPOT_URI}"' in lines[0], lines[0]
    finally:
        stop(proc)

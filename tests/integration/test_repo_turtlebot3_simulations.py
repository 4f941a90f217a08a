"""ROBOTIS-GIT/turtlebot3_simulations unchanged, as its README says (issue 49): `colcon build --symlink-install` of
its turtlebot3_gazebo, then `TURTLEBOT3_MODEL=burger ros2 launch turtlebot3_gazebo turtlebot3_world.launch.py`;
the jazzy branch (gz-sim, ros_gz_bridge) and the humble one (Gazebo Classic, gazebo_ros). Each CMakeLists compiles
turtlebot3_drive against rclcpp and obstacle plugins against gz-sim or Gazebo: each is one line, the rest installs.
The burger sees the arena's walls and pillars on /scan, its IMU publishes, and it drives 1 m on /cmd_vel
(jazzy: a TwistStamped through the package's bridge YAML) with odometry and ground truth within 2 %."""

from __future__ import annotations

import math
import shutil

import pytest
from _harness import wait_for
from geometry_msgs.msg import Twist, TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu, LaserScan

from ._real_repos import DATA, Topic, colcon_build, drive_a_metre, launch, stop, workspace
from .test_turtlebot3 import TB3

pytestmark = pytest.mark.slow

MESHES = ("bases/burger_base.stl", "sensors/lds.stl", "wheels/left_tire.stl", "wheels/right_tire.stl")


def _run(tmp_path, ros_client, repo: str, skipped: dict[str, str], stamped: bool) -> None:
    assert (DATA / repo / "LICENSE").is_file()
    ws = workspace(tmp_path, repo, ["turtlebot3_gazebo"])
    meshes = ws / "src" / "turtlebot3_gazebo" / "models" / "turtlebot3_common" / "meshes"
    for mesh in MESHES:  # the STL meshes, from the shared fixture (tests/data/<repo>/SOURCES.md)
        (meshes / mesh).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(TB3 / "turtlebot3_gazebo" / "models" / "turtlebot3_common" / "meshes" / mesh, meshes / mesh)
    out = colcon_build(ws)
    for target, needs in skipped.items():
        assert f"gazelle: turtlebot3_gazebo: {target} is not built (it needs {needs}," in out, out
    scan = Topic.subscribe(ros_client, LaserScan, "/scan")
    imu = Topic.subscribe(ros_client, Imu, "/imu")
    odom = Topic.subscribe(ros_client, Odometry, "/odom")
    proc = launch(ws, "export TURTLEBOT3_MODEL=burger && ros2 launch turtlebot3_gazebo turtlebot3_world.launch.py")
    try:
        proc.wait_line("Successfully spawned entity [burger]", 120)
        wait_for(lambda: scan.count() > 2 and imu.count() > 10, 60, "/scan and /imu from the burger")
        # from (-2, -0.5) inside the hexagonal arena every ray meets a wall or a pillar within 3.5 m
        hits = sum(1 for r in scan.latest().ranges if math.isfinite(r))
        assert hits > 300, f"{hits} of 360 rays hit"
        assert "MESH_NOT_FOUND" not in proc.output, proc.output
        if stamped:
            proc.wait_line("Converting [/cmd_vel] geometry_msgs/TwistStamped -> geometry_msgs/Twist", 30)
        cmd = ros_client.node.create_publisher(TwistStamped if stamped else Twist, "/cmd_vel", 10)

        def send(speed: float) -> None:
            twist = Twist()
            twist.linear.x = speed
            if stamped:
                cmd.publish(TwistStamped(twist=twist))
            else:
                cmd.publish(twist)

        drive_a_metre(ros_client, "burger", send, odom, speed=0.2)
    finally:
        stop(proc)


def test_turtlebot3_jazzy_world_builds_sees_the_arena_and_drives(tmp_path, ros_client):
    skipped = {"turtlebot3_drive": "rclcpp, tf2", "obstacles": "gz-sim, gz-math"}
    _run(tmp_path, ros_client, "turtlebot3_simulations", skipped, stamped=True)


def test_turtlebot3_humble_classic_world_builds_sees_the_arena_and_drives(tmp_path, ros_client):
    skipped = {"turtlebot3_drive": "rclcpp, tf2", "traffic_light_plugin": "gazebo", "obstacles": "gazebo"}
    _run(tmp_path, ros_client, "turtlebot3_simulations_humble", skipped, stamped=False)

"""The `ros2` introspection verbs against a running simulation, as a user types them (gazelle's ros2
command: no ROS installation)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from rosgraph_msgs.msg import Clock

from .conftest import GAZELLE, SEED_XACRO, start, wait_for

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")


def ros2(*args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    return subprocess.run([ROS2, *args], capture_output=True, text=True, timeout=timeout)


@pytest.mark.slow
def test_topic_service_node_and_interface_verbs_on_a_running_simulation(sim_factory, ros_client):
    sim_factory("--no-viewer")
    spawn = start([*GAZELLE, "spawn", "-entity", "bot", "-file", str(SEED_XACRO)], "spawn")
    assert spawn.wait(60) == 0, spawn.output

    listed = ros2("topic", "list", "-t")
    assert "/odom [nav_msgs/msg/Odometry]" in listed.stdout and "/clock [rosgraph_msgs/msg/Clock]" in listed.stdout
    assert "/_gazelle/servers" not in listed.stdout  # hidden unless asked

    echo = ros2("topic", "echo", "/odom", "--once")
    assert echo.returncode == 0, echo.stderr
    first = yaml.safe_load(echo.stdout.split("---")[0])
    assert first["header"]["frame_id"] == "odom" and first["child_frame_id"] == "base_link"
    assert len(first["pose"]["covariance"]) == 36
    best_effort = ros2("topic", "echo", "/odom", "--once", "--qos-profile", "sensor_data", "--field", "child_frame_id")
    assert best_effort.stdout.split("---")[0].strip() == "base_link", best_effort.stdout + best_effort.stderr

    assert "average rate:" in ros2("topic", "hz", "/clock", "--count", "1").stdout
    info = ros2("topic", "info", "/cmd_vel", "-v").stdout
    assert "Subscription count: 1" in info and "Node name: differential_drive" in info

    pub = start(
        [ROS2, "topic", "pub", "-r", "10", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {x: 0.3}}"], "ros2 pub"
    )
    try:
        wait_for(lambda: ros_client.entity_state("bot").state.pose.position.x > 0.2, 30, "the robot to drive")
    finally:
        pub.interrupt()

    call = ros2("service", "call", "/get_model_list", "gazebo_msgs/srv/GetModelList")
    assert call.returncode == 0, call.stderr
    assert "model_names:" in call.stdout and "- bot" in call.stdout and "success: true" in call.stdout
    services = ros2("service", "list", "-t").stdout
    assert "/spawn_entity [gazebo_msgs/srv/SpawnEntity]" in services
    assert "/gazelle" in ros2("node", "list").stdout.split()
    node = ros2("node", "info", "/gazelle").stdout
    assert "/clock: rosgraph_msgs/msg/Clock" in node and "/spawn_entity: gazebo_msgs/srv/SpawnEntity" in node
    assert "/cmd_vel" not in node  # the diff drive's own node subscribes to it (below)
    shown = ros2("interface", "show", "gazebo_msgs/srv/SpawnEntity").stdout
    assert "string xml" in shown and "---" in shown
    odom_def = ros2("interface", "show", "nav_msgs/msg/Odometry").stdout
    assert "string child_frame_id" in odom_def and "geometry_msgs/PoseWithCovariance pose" in odom_def

    # the diff drive plugin is its own node, named as in Gazebo, its configuration its parameters
    assert {"/gazelle", "/differential_drive"} <= set(ros2("node", "list").stdout.split())
    drive_info = ros2("node", "info", "/differential_drive").stdout
    assert "/cmd_vel: geometry_msgs/msg/Twist" in drive_info and "/odom: nav_msgs/msg/Odometry" in drive_info
    assert "Node name: differential_drive" in ros2("topic", "info", "-v", "/odom").stdout
    got = ros2("param", "get", "/differential_drive", "wheel_separation")
    assert got.stdout.strip() == "Double value is: 0.34", got.stdout + got.stderr
    refused = ros2("param", "set", "/differential_drive", "wheel_separation", "0.5")
    assert refused.returncode == 1
    assert refused.stderr.strip() == "Setting parameter failed: Trying to set a read-only parameter: wheel_separation."
    dumped = yaml.safe_load(ros2("param", "dump", "/differential_drive").stdout)
    assert dumped["/differential_drive"]["ros__parameters"]["odometry_frame"] == "odom"
    assert "Read only: true" in ros2("param", "describe", "/differential_drive", "wheel_diameter").stdout
    assert ros2("param", "get", "/nope", "x").stderr.strip() == "Node not found"

    assert ros2("topic", "find", "nav_msgs/msg/Odometry").stdout.split() == ["/odom"]
    bw = ros2("topic", "bw", "/odom", "--count", "1").stdout
    assert re.search(r"[\d.]+ K?B/s from \d+ messages\n\tMessage size mean: 724.00 B min: 724.00 B", bw), bw
    delay = ros2("topic", "delay", "/odom", "--count", "1", "--use-sim-time").stdout
    assert re.search(r"average delay: -?[\d.]+\n\tmin: ", delay), delay
    proto = ros2("interface", "proto", "geometry_msgs/msg/Twist").stdout
    assert yaml.safe_load(proto.strip().strip('"')) == {
        "linear": {"x": 0.0, "y": 0.0, "z": 0.0},
        "angular": {"x": 0.0, "y": 0.0, "z": 0.0},
    }

    # /odom at 100 Hz (the plugin's update rate, at real time)
    hz = ros2("topic", "hz", "/odom", "--count", "3").stdout
    rates = [float(line.split(":")[1]) for line in hz.splitlines() if line.strip().startswith("average rate:")]
    assert rates and rates[-1] == pytest.approx(100.0, rel=0.05), hz

    # pausing from the command line stops /clock
    clocks: list = []
    ros_client.node.create_subscription(Clock, "/clock", clocks.append, 10)
    wait_for(lambda: clocks, 10, "/clock")
    paused = ros2("service", "call", "/pause_physics", "std_srvs/srv/Empty")
    assert paused.returncode == 0 and "response:" in paused.stdout, paused.stderr
    ros_client.entity_state("bot")  # a round trip: a /clock sent before the pause has arrived by now
    at_pause = clocks[-1].clock
    ros2("topic", "echo", "/clock", "--once", "--timeout", "2")  # 2 s of /clock, seen by a second node too
    assert clocks[-1].clock == at_pause, "/clock still advances while paused"
    ros2("service", "call", "/unpause_physics", "std_srvs/srv/Empty")

    bad_type = ros2("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twst", "{}")
    assert bad_type.returncode == 1 and "The passed msg type 'geometry_msgs/msg/Twst' is invalid" in bad_type.stderr
    bad_field = ros2("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {w: 1}}")
    assert bad_field.returncode == 1 and "has no field 'linear.w'" in bad_field.stderr
    assert "Traceback" not in bad_type.stderr + bad_field.stderr

"""The `ros2` introspection verbs against a running simulation, as a user types them (gazelle's ros2
command: no ROS installation)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

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

    assert "average rate:" in ros2("topic", "hz", "/clock", "--count", "1").stdout
    info = ros2("topic", "info", "/cmd_vel", "-v").stdout
    assert "Subscription count: 1" in info and "Node name: gazelle" in info

    pub = start(
        [ROS2, "topic", "pub", "-r", "20", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {x: 0.3}}"], "ros2 pub"
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
    assert "/cmd_vel: geometry_msgs/msg/Twist" in node and "Service Servers:" in node
    shown = ros2("interface", "show", "gazebo_msgs/srv/SpawnEntity").stdout
    assert "string xml" in shown and "---" in shown

    bad_type = ros2("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twst", "{}")
    assert bad_type.returncode == 1 and "The passed msg type 'geometry_msgs/msg/Twst' is invalid" in bad_type.stderr
    bad_field = ros2("topic", "pub", "--once", "/cmd_vel", "geometry_msgs/msg/Twist", "{linear: {w: 1}}")
    assert bad_field.returncode == 1 and "has no field 'linear.w'" in bad_field.stderr
    assert "Traceback" not in bad_type.stderr + bad_field.stderr

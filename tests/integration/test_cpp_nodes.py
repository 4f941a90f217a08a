"""A team's C++ nodes in the pip workspace (issue 54): `colcon build --symlink-install` of ament_cmake packages
that find rclcpp, rclcpp_lifecycle and rclcpp_components (tests/data/cpp_ws), `ros2 run` of their nodes beside
`gazelle sim`,
talking to an rclpy node and following gazelle's /clock under use_sim_time.

The workspace's first `find_package(rclcpp)` installs the C++ tier (scripts/build_cpp.sh: from the cache in
seconds, or built in about two minutes on 2 cores when no clone on this machine has built it yet); the
build takes up to ~40 s of compiling on top, which is why these tests take longer than 30 s.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from _harness import GAZELLE, REPO, SEED_XACRO, Proc, start, wait_for, xacro_to_urdf, yaw_of
from lifecycle_msgs.msg import Transition
from lifecycle_msgs.srv import ChangeState, GetState
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String
from std_srvs.srv import SetBool

WORKSPACE = REPO / "tests" / "data" / "cpp_ws"
ACTIVATE = Path(sys.prefix) / "bin" / "activate"
# what a shell that only activated the venv has (no sourced ROS, no other workspace)
CLEAN_ENV = {k: v for k, v in os.environ.items() if k not in ("AMENT_PREFIX_PATH", "PYTHONPATH", "COLCON_PREFIX_PATH")}
BUILD_TIMEOUT = 600  # the C++ tier built cold (~2 min on 2 shared cores) and the package (~40 s)


def build_workspace(tmp: Path, package: str) -> Path:
    """tests/data/cpp_ws copied to ``tmp`` and ``package`` built there with `colcon build --symlink-install`."""
    ws = tmp / "cpp_ws"
    shutil.copytree(WORKSPACE, ws)
    build = subprocess.run(
        ["bash", "-c", f"source {ACTIVATE} && colcon build --symlink-install --packages-select {package}"],
        cwd=ws,
        env=CLEAN_ENV,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        timeout=BUILD_TIMEOUT,
    )
    log = ws / "log" / "latest_build" / package / "stdout_stderr.log"
    assert build.returncode == 0, build.stdout + (log.read_text() if log.exists() else "")
    assert "Summary: 1 package finished" in build.stdout
    return ws


def ros2_run(ws: Path, package: str, executable: str, *ros_args: str) -> Proc:
    """`ros2 run PACKAGE EXECUTABLE --ros-args ...` in a shell that activated the venv and sourced the workspace."""
    args = " ".join(["--ros-args", *ros_args]) if ros_args else ""
    script = f"source {ACTIVATE} && source {ws}/install/setup.bash && exec ros2 run {package} {executable} {args}"
    env = {**CLEAN_ENV, "ROS_DOMAIN_ID": os.environ["ROS_DOMAIN_ID"]}
    return start(["bash", "-c", script], f"{package}/{executable}", env)


COMPONENT_LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='cpp_nodes', executable='component_talker_node', output='screen',
             parameters=[{'use_sim_time': True}]),
    ])
"""


def ros2_launch(ws: Path, launch_file: Path) -> Proc:
    """`ros2 launch LAUNCH_FILE` in a shell that activated the venv and sourced the workspace."""
    script = f"source {ACTIVATE} && source {ws}/install/setup.bash && exec ros2 launch {launch_file}"
    env = {**CLEAN_ENV, "ROS_DOMAIN_ID": os.environ["ROS_DOMAIN_ID"]}
    return start(["bash", "-c", script], "ros2 launch", env)


def sim_seconds(text: str) -> float:
    """The node's clock reading ("... at <nanoseconds>") in a message the C++ nodes wrote."""
    m = re.search(r" at (\d+)", text)
    assert m, text
    return int(m.group(1)) * 1e-9


@pytest.mark.slow
def test_cpp_talker_server_lifecycle_node_and_component_talk_to_rclpy_on_sim_time(
    tmp_path, sim_factory, ros_client, cpp_tier
):
    ws = build_workspace(tmp_path, "cpp_nodes")
    sim_factory("--no-viewer", "--rtf", "2")
    node = ros_client.node
    lock = threading.Lock()
    clocks: list[float] = []
    chatter: list[str] = []
    lifecycle: list[str] = []
    component: list[str] = []

    def on_clock(msg: Clock) -> None:
        with lock:
            clocks.append(msg.clock.sec + msg.clock.nanosec * 1e-9)

    node.create_subscription(Clock, "/clock", on_clock, QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
    node.create_subscription(String, "/chatter", lambda m: chatter.append(m.data), 10)
    node.create_subscription(String, "/lifecycle_chatter", lambda m: lifecycle.append(m.data), 10)
    node.create_subscription(String, "/component_chatter", lambda m: component.append(m.data), 10)
    reply = node.create_publisher(String, "/reply", 10)
    wait_for(lambda: clocks, 15, "gazelle's /clock")

    def near_sim_time(text: str) -> bool:
        """The node's stamp is simulation time: within a second of the /clock this process saw (the wall
        clock reads some 1.7e9 s)."""
        t = sim_seconds(text)
        with lock:
            return any(abs(t - c) < 1.0 for c in clocks[-100:])

    # a talker: its timer and stamps on the node's clock, and it hears what rclpy says
    talker = ros2_run(ws, "cpp_nodes", "talker", "-p", "use_sim_time:=true")
    wait_for(lambda: chatter, 30, f"/chatter from the C++ talker:\n{talker.output}")

    def heard() -> bool:
        reply.publish(String(data="from rclpy"))
        return any(m.endswith("heard from rclpy") for m in chatter)

    wait_for(heard, 15, f"the C++ talker to hear rclpy:\n{talker.output}")
    assert "heard: 'from rclpy'" in talker.output
    assert near_sim_time(chatter[-1]), (chatter[-1], clocks[-1])
    stamps = [sim_seconds(m) for m in list(chatter)]
    assert all(b >= a for a, b in zip(stamps, stamps[1:])), stamps

    # a service server answering rclpy's requests
    server = ros2_run(ws, "cpp_nodes", "bool_server", "-p", "use_sim_time:=true")
    request = SetBool.Request(data=True)
    response = ros_client.call(SetBool, "/set_flag", request, timeout=30)
    assert response.success is True, server.output
    assert response.message.startswith("request 1 at "), response.message
    wait_for(lambda: near_sim_time(response.message), 5, f"a sim-time answer: {response.message}")
    assert ros_client.call(SetBool, "/set_flag", SetBool.Request(data=False)).success is False

    # a lifecycle node: silent until configured and activated through its lifecycle services
    managed = ros2_run(ws, "cpp_nodes", "lifecycle_talker", "-p", "use_sim_time:=true")
    state = ros_client.call(GetState, "/lifecycle_talker/get_state", GetState.Request(), timeout=30)
    assert state.current_state.label == "unconfigured", managed.output
    for transition in (Transition.TRANSITION_CONFIGURE, Transition.TRANSITION_ACTIVATE):
        change = ChangeState.Request(transition=Transition(id=transition))
        assert ros_client.call(ChangeState, "/lifecycle_talker/change_state", change).success, managed.output
    assert ros_client.call(GetState, "/lifecycle_talker/get_state", GetState.Request()).current_state.label == "active"
    wait_for(lambda: lifecycle, 15, f"/lifecycle_chatter once active:\n{managed.output}")
    assert near_sim_time(lifecycle[-1]), (lifecycle[-1], clocks[-1])
    assert "configured" in managed.output and "activated" in managed.output

    # a component, loaded from its library by the executable rclcpp_components_register_node() made, started
    # by `ros2 launch` with its parameters from the launch file
    launch_file = ws / "component.launch.py"
    launch_file.write_text(COMPONENT_LAUNCH)
    loaded = ros2_launch(ws, launch_file)
    wait_for(lambda: component, 30, f"/component_chatter from the component:\n{loaded.output}")
    assert near_sim_time(component[-1]), (component[-1], clocks[-1])

    for proc in (talker, server, managed):
        assert proc.interrupt() == 0, proc.output
    assert loaded.interrupt() in (0, -signal.SIGINT, 130), loaded.output  # as ros2 launch ends on Ctrl-C
    assert "component_talker_node-1]: process has finished cleanly" in loaded.output, loaded.output


def _spawn_seed_robot(ros_client, sim: Proc) -> None:
    """The seed robot spawned from robot_description (as test_square does), at rest on its wheels."""
    qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    ros_client.node.create_publisher(String, "robot_description", qos).publish(String(data=xacro_to_urdf(SEED_XACRO)))
    spawn = start(
        [*GAZELLE, "spawn", "-entity", "simple_robot", "-topic", "robot_description", "-timeout", "30"], "spawn"
    )
    assert spawn.wait(60) == 0, spawn.output
    assert "Subscribed to [/cmd_vel]" in sim.wait_line("Subscribed to", 10)
    wait_for(lambda: abs(ros_client.entity_state("simple_robot").state.twist.linear.z) < 1e-3, 10, "the robot at rest")


@pytest.mark.slow
@pytest.mark.serial  # real time: the square is driven on a 10 Hz timer
def test_cpp_square_movement_drives_the_seed_robot_like_the_python_one(tmp_path, sim_factory, ros_client, cpp_tier):
    """The seed's square_movement ported to rclcpp drives one side and turn within test_square's tolerance
    (1.00 m +- 0.03, 90 deg +- 3), on sim time at twice the wall clock's speed."""
    ws = build_workspace(tmp_path, "cpp_square")
    sim = sim_factory("--no-viewer", "--rtf", "2")
    _spawn_seed_robot(ros_client, sim)
    start_state = ros_client.entity_state("simple_robot").state
    driver = ros2_run(ws, "cpp_square", "square_movement", "-p", "max_sides:=1", "-p", "use_sim_time:=true")
    assert driver.wait(120) == 0, driver.output
    assert "Side 1 done" in driver.output
    wait_for(
        lambda: abs(ros_client.entity_state("simple_robot").state.twist.angular.z) < 1e-3,
        30,
        "the robot to stop turning",
    )
    end_state = ros_client.entity_state("simple_robot").state
    p0, p1 = start_state.pose.position, end_state.pose.position
    distance = math.hypot(p1.x - p0.x, p1.y - p0.y)
    turn = math.degrees(
        math.remainder(yaw_of(end_state.pose.orientation) - yaw_of(start_state.pose.orientation), math.tau)
    )
    print(f"[rclcpp] side: {distance:.4f} m, turn: {turn:.2f} deg")
    assert distance == pytest.approx(1.00, abs=0.03), driver.output
    assert turn == pytest.approx(90.0, abs=3.0), driver.output

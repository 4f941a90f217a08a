"""Gazebo-style launch files run unchanged with `ros2 launch`: a gz-sim one in the style of TurtleBot3's
(ros_gz_sim's gz_sim.launch.py, create, ros_gz_bridge's parameter_bridge with the robot's YAML), the ROS 1
spawn_model command line, and joint_state_publisher."""

from __future__ import annotations

import os
import signal
import sys
import textwrap
import threading
from pathlib import Path

import pytest
from _harness import GAZELLE as GAZELLE_CMD
from _harness import REPO, SEED_XACRO, start, wait_for, xacro_to_urdf
from gazebo_msgs.srv import GetModelState
from sensor_msgs.msg import JointState, LaserScan

from .test_turtlebot3 import TB3

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")

GZ_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

TB3 = {tb3!r}


def generate_launch_description():
    x_pose = LaunchConfiguration("x_pose", default="-2.0")
    y_pose = LaunchConfiguration("y_pose", default="-0.5")
    gzserver = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            os.path.join(get_package_share_directory("ros_gz_sim"), "launch", "gz_sim.launch.py")
        ),
        launch_arguments={{"gz_args": ["-r -s -v2 ", "empty.sdf"], "on_exit_shutdown": "true"}}.items(),
    )
    spawn = Node(
        package="ros_gz_sim",
        executable="create",
        arguments=["-name", "burger", "-file", os.path.join(TB3, "turtlebot3_gazebo/models/turtlebot3_burger/model.sdf"),
                   "-x", x_pose, "-y", y_pose, "-z", "0.01"],
        output="screen",
    )
    bridge = Node(
        package="ros_gz_bridge",
        executable="parameter_bridge",
        arguments=["--ros-args", "-p",
                   "config_file:=" + os.path.join(TB3, "turtlebot3_gazebo/params/turtlebot3_burger_bridge.yaml")],
        output="screen",
    )
    return LaunchDescription([
        DeclareLaunchArgument("x_pose", default_value="-2.0", description="x"),
        DeclareLaunchArgument("y_pose", default_value="-0.5", description="y"),
        gzserver, spawn, bridge,
    ])
"""


@pytest.mark.slow
def test_a_gz_sim_launch_file_runs_turtlebot3_with_its_bridge_yaml(tmp_path, ros_client, monkeypatch):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", f"{TB3}:{TB3 / 'turtlebot3_gazebo/models'}")
    launch_file = tmp_path / "tb3_gz.launch.py"
    launch_file.write_text(textwrap.dedent(GZ_LAUNCH.format(tb3=str(TB3))))
    scans: list[LaserScan] = []
    ros_client.node.create_subscription(LaserScan, "/scan", scans.append, 10)
    proc = start([ROS2, "launch", str(launch_file), "x_pose:=-1.0"], "ros2 launch")
    try:
        proc.wait_line("Successfully spawned entity [burger]", 90)
        wait_for(lambda: scans, 30, "/scan from the burger's lidar")
        proc.wait_line("scan: gazelle has it on ROS directly; nothing to bridge", 30)
        assert "[gazebo-1]" in proc.output
        st = ros_client.entity_state("burger")
        assert st.state.pose.position.x == pytest.approx(-1.0, abs=0.05)  # the launch argument reached create
    finally:
        os.kill(proc.popen.pid, signal.SIGINT)
        rc = proc.wait(20)
    assert rc == 0, proc.output


def test_ros1_spawn_model_command_line_and_joint_state_publisher(sim_factory, ros_client, tmp_path):
    sim_factory("--no-viewer")
    board = REPO / "examples" / "chessboard" / "chess_board.sdf"
    spawn = start(
        [ROS2, "run", "gazebo_ros", "spawn_model", "-file", str(board), "-sdf", "-model", "box"], "spawn_model"
    )
    assert spawn.wait(60) == 0, spawn.output
    res = ros_client.call(GetModelState, "/gazebo/get_model_state", GetModelState.Request(model_name="box"))
    assert res.success, res.status_message

    urdf = xacro_to_urdf(SEED_XACRO)
    got: list[JointState] = []
    lock = threading.Lock()

    def keep(m: JointState) -> None:
        with lock:
            got.append(m)

    ros_client.node.create_subscription(JointState, "/jsp_test/joint_states", keep, 10)
    import yaml

    params = tmp_path / "jsp.yaml"  # as a launch file passes robot_description: in a parameters file
    params.write_text(yaml.safe_dump({"/**": {"ros__parameters": {"robot_description": urdf}}}))
    jsp = start(
        [ROS2, "run", "joint_state_publisher", "joint_state_publisher", "--ros-args", "-r", "__ns:=/jsp_test"]
        + ["--params-file", str(params)],
        "joint_state_publisher",
    )
    try:
        wait_for(lambda: got, 20, "/jsp_test/joint_states")
        with lock:
            msg = got[-1]
        assert set(msg.name) == {"base_left_wheel_joint", "base_right_wheel_joint"}
        assert list(msg.position) == [0.0, 0.0]
    finally:
        jsp.interrupt()


def test_parameter_bridge_relays_a_renamed_topic_in_its_direction(sim_factory, ros_client, tmp_path):
    """A bridge YAML that renames: gz's `model/diff/odometry` becomes ROS `odom_renamed`, and ROS
    `cmd_vel_renamed` feeds gz's `cmd_vel`; gazelle publishes the gz names, the bridge relays."""
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry

    sim_factory("--no-viewer")
    spawn = start([*GAZELLE_CMD, "spawn", "-entity", "bot", "-file", str(SEED_XACRO)], "spawn")
    assert spawn.wait(60) == 0, spawn.output
    config = tmp_path / "bridge.yaml"
    config.write_text(
        textwrap.dedent(
            """
            - ros_topic_name: "odom_renamed"
              gz_topic_name: "odom"
              ros_type_name: "nav_msgs/msg/Odometry"
              gz_type_name: "gz.msgs.Odometry"
              direction: GZ_TO_ROS
            - ros_topic_name: "cmd_vel_renamed"
              gz_topic_name: "cmd_vel"
              ros_type_name: "geometry_msgs/msg/Twist"
              gz_type_name: "gz.msgs.Twist"
              direction: ROS_TO_GZ
            """
        )
    )
    bridge = start(
        [ROS2, "run", "ros_gz_bridge", "parameter_bridge", "--ros-args", "-p", f"config_file:={config}"], "bridge"
    )
    try:
        bridge.wait_line("Creating relay [cmd_vel_renamed] -> [cmd_vel]", 20)
        odom: list[Odometry] = []
        ros_client.node.create_subscription(Odometry, "/odom_renamed", odom.append, 10)
        wait_for(lambda: odom, 20, "/odom_renamed relayed from gazelle's /odom")
        pub = ros_client.node.create_publisher(Twist, "/cmd_vel_renamed", 10)
        cmd = Twist()
        cmd.linear.x = 0.3

        def moved() -> bool:
            pub.publish(cmd)
            return odom[-1].pose.pose.position.x > 0.1

        wait_for(moved, 30, "the robot to drive on /cmd_vel_renamed", interval=0.1)
    finally:
        bridge.interrupt()


BRIDGE_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="ros_gz_bridge", executable="parameter_bridge", name="{name}",
             parameters=[{{"config_file": {config!r}, "expand_gz_topic_names": True}}], output="screen"),
    ])
"""


@pytest.mark.parametrize("how", ["launch dict", "params-file node section"])
def test_parameter_bridge_takes_config_file_in_every_parameter_form(how, tmp_path):
    """ros_gz_bridge declares `config_file` on its node and rcl applies the parameters however they come: a launch
    file's `parameters=[{...}]` (a `/**` params file, as ros_gz_project_template gives it) or a params file whose
    section names the node. gazelle's stand-in read only `-p config_file:=` and said "nothing to bridge".
    Its entry is relayed, so the bridge says it creates the relay; with `expand_gz_topic_names` the YAML's
    relative gz name is put in the node's namespace, as RosGzBridge::spin does."""
    config = tmp_path / "bridge.yaml"
    config.write_text(
        '- {ros_topic_name: "odom_renamed", gz_topic_name: "odom", '
        'ros_type_name: "nav_msgs/msg/Odometry", direction: GZ_TO_ROS}\n'
    )
    if how == "launch dict":
        launch_file = tmp_path / "bridge.launch.py"
        launch_file.write_text(BRIDGE_LAUNCH.format(name="my_bridge", config=str(config)))
        cmd = [ROS2, "launch", str(launch_file)]
        relay = "Creating relay [/odom] -> [odom_renamed]"
    else:
        params = tmp_path / "params.yaml"
        params.write_text(f"ros_gz_bridge:\n  ros__parameters:\n    config_file: {config}\n")
        cmd = [ROS2, "run", "ros_gz_bridge", "parameter_bridge", "--ros-args", "--params-file", str(params)]
        relay = "Creating relay [odom] -> [odom_renamed]"
    bridge = start(cmd, "bridge")
    try:
        bridge.wait_line(relay, 30)
        assert "nothing to bridge" not in bridge.output
    finally:
        bridge.interrupt()


SERVER_AND_GUI_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource

GZ_SIM = os.path.join(get_package_share_directory("ros_gz_sim"), "launch", "gz_sim.launch.py")


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(GZ_SIM), launch_arguments={"gz_args": "-r -s empty.sdf"}.items()),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(GZ_SIM), launch_arguments={"gz_args": "-g"}.items()),
    ])
"""


WAREHOUSE_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import AppendEnvironmentVariable, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    gz = os.path.join(get_package_share_directory("ros_gz_sim"), "launch", "gz_sim.launch.py")
    return LaunchDescription([
        AppendEnvironmentVariable("GZ_SIM_RESOURCE_PATH", {worlds!r}),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(gz),
                                 launch_arguments={{"gz_args": "-r -s warehouse.sdf"}}.items()),
    ])
"""


def test_gz_sim_server_and_gui_from_two_includes_show_the_servers_viewer(tmp_path):
    """TurtleBot3's jazzy launch includes gz_sim.launch.py twice, `-r -s WORLD` and `-g`. gazelle's `-s` served no
    viewer, so there was none at all; the server now serves it (its GUI is the browser) and `-g` prints its real
    address."""
    launch_file = tmp_path / "server_and_gui.launch.py"
    launch_file.write_text(SERVER_AND_GUI_LAUNCH)
    launch = start([ROS2, "launch", str(launch_file)], "ros2 launch")
    try:
        launch.wait_line("gazelle: viewer at ", 60)
        url = launch.output.split("gazelle: viewer at ", 1)[1].split()[0]
        launch.wait_line(f"open {url}", 30)
    finally:
        launch.interrupt()


def test_parameter_bridge_names_a_bad_config_file_in_one_line(tmp_path):
    """A config_file that is not YAML, or a 5,000-digit number in it, is one line naming the file (it went through
    plain yaml.safe_load: a traceback for the number)."""
    for name, text in (
        ("broken.yaml", "- {ros_topic_name: [unclosed\n"),
        ("huge.yaml", f"- {{depth: {'9' * 5000}}}\n"),
    ):
        config = tmp_path / name
        config.write_text(text)
        bridge = start(
            [ROS2, "run", "ros_gz_bridge", "parameter_bridge", "--ros-args", "-p", f"config_file:={config}"], "bridge"
        )
        assert bridge.popen.wait(30) == 1, bridge.output
        bridge.wait_line(f"config_file {config}", 5)
        assert "Traceback" not in bridge.output


def test_a_bare_world_name_in_gz_args_is_found_on_the_resource_path_the_launch_sets(tmp_path, monkeypatch):
    """A bring-up's `gz_args: -r -s warehouse.sdf` with its worlds folder appended to GZ_SIM_RESOURCE_PATH
    (AppendEnvironmentVariable), launched from another folder: gz sim finds the world there, so gazelle must."""
    worlds = tmp_path / "share" / "my_bringup" / "worlds"
    worlds.mkdir(parents=True)
    (worlds / "warehouse.sdf").write_text(
        '<?xml version="1.0"?><sdf version="1.9"><world name="warehouse"><model name="ground_plane">'
        "<static>true</static><link name='link'><collision name='c'><geometry><plane><normal>0 0 1</normal>"
        "</plane></geometry></collision></link></model></world></sdf>"
    )
    launch_file = tmp_path / "bringup.launch.py"
    launch_file.write_text(textwrap.dedent(WAREHOUSE_LAUNCH.format(worlds=str(worlds))))
    monkeypatch.delenv("GZ_SIM_RESOURCE_PATH", raising=False)
    monkeypatch.chdir(tmp_path)
    proc = start([ROS2, "launch", str(launch_file)], "ros2 launch")
    try:
        proc.wait_line("gazelle: ready: world 'warehouse'", 60)
    finally:
        if proc.popen.poll() is None:
            os.kill(proc.popen.pid, signal.SIGINT)
        rc = proc.wait(20)
    assert rc == 0, proc.output
    assert "FILE_NOT_FOUND" not in proc.output

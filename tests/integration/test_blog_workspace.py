"""The seed blog's workflow, unchanged: a colcon workspace, `ros2 launch` of its Gazebo launch file,
`ros2 run` of its node, in a shell that only activated the venv (no ROS installation).

The workspace is written from the blog: its layout, its launch file (the blog shows it in pieces:
xacro.process_file, the gazebo_ros include, robot_state_publisher with robot_description,
spawn_entity.py -entity simple_robot -topic robot_description), the example robot and its node.
"""

from __future__ import annotations

import math
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from _harness import REPO, Proc, wait_for
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

VENV_ACTIVATE = Path(sys.prefix) / "bin" / "activate"

BLOG_LAUNCH = """\
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node
import xacro


def generate_launch_description():
    pkg_dir = get_package_share_directory('simple_robot')
    xacro_file = os.path.join(pkg_dir, 'robot.urdf.xacro')
    robot_description_config = xacro.process_file(xacro_file)
    robot_description = {'robot_description': robot_description_config.toxml()}

    gazebo_launch = IncludeLaunchDescription(
        PythonLaunchDescriptionSource([os.path.join(
            get_package_share_directory('gazebo_ros'), 'launch', 'gazebo.launch.py')]),
    )

    robot_state_publisher = Node(
        package='robot_state_publisher',
        executable='robot_state_publisher',
        output='screen',
        parameters=[robot_description]
    )

    spawn_entity = Node(
        package='gazebo_ros',
        executable='spawn_entity.py',
        arguments=['-entity', 'simple_robot',
                  '-topic', 'robot_description'],
        output='screen'
    )

    return LaunchDescription([
        gazebo_launch,
        robot_state_publisher,
        spawn_entity,
    ])
"""

SETUP_PY = """\
from setuptools import setup

package_name = 'simple_robot'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml', 'simple_robot/robot.urdf.xacro',
                                   'simple_robot/launch/robot_gazebo.launch.py']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='user',
    maintainer_email='user@example.com',
    description='A simple differential drive robot',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'square_movement = simple_robot.square_movement:main',
        ],
    },
)
"""


def write_blog_workspace(root: Path) -> Path:
    """``simple_robot_ws/src/simple_robot`` laid out as the blog shows it; returns the workspace."""
    ws = root / "simple_robot_ws"
    pkg = ws / "src" / "simple_robot"
    (pkg / "simple_robot" / "launch").mkdir(parents=True)
    (pkg / "resource").mkdir()
    (pkg / "resource" / "simple_robot").write_text("")
    shutil.copy(REPO / "examples" / "simple_robot" / "package.xml", pkg / "package.xml")
    (pkg / "setup.py").write_text(SETUP_PY)
    (pkg / "simple_robot" / "__init__.py").write_text("")
    for name in ("robot.urdf.xacro", "square_movement.py"):
        shutil.copy(REPO / "examples" / "simple_robot" / "simple_robot" / name, pkg / "simple_robot" / name)
    (pkg / "simple_robot" / "launch" / "robot_gazebo.launch.py").write_text(BLOG_LAUNCH)
    return ws


def shell(commands: str, name: str) -> Proc:
    """``bash -c`` after activating the venv (the README's set-up), output collected, in its own group."""
    script = f"source {VENV_ACTIVATE} && {commands}"
    env = {k: v for k, v in os.environ.items() if k not in ("AMENT_PREFIX_PATH", "PYTHONPATH", "COLCON_PREFIX_PATH")}
    popen = subprocess.Popen(
        ["bash", "-c", script],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        env=env,
        start_new_session=True,
    )
    proc = Proc(popen, name)
    proc.start_reader()
    return proc


def _group_alive(pgid: int) -> bool:
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return False
    return True


@pytest.mark.slow
def test_the_blog_commands_build_launch_and_drive_the_robot(tmp_path, ros_client):
    ws = write_blog_workspace(tmp_path)
    build = shell(f"cd {ws} && colcon build --symlink-install", "colcon")
    assert build.wait(180) == 0, build.output
    assert "Summary: 1 package finished" in build.output

    launch = shell(f"cd {ws} && source install/setup.bash && ros2 launch simple_robot robot_gazebo.launch.py", "launch")
    try:
        launch.wait_line("Successfully spawned entity [simple_robot]", 60)
        assert "[robot_state_publisher-2]" in launch.output and "[gzserver-1]" in launch.output
        res = ros_client.entity_state("simple_robot")
        assert res.success

        odom: list[Odometry] = []
        frames: set[tuple[str, str]] = set()
        lock = threading.Lock()

        def on_tf(msg: TFMessage) -> None:
            with lock:
                frames.update((t.header.frame_id, t.child_frame_id) for t in msg.transforms)

        ros_client.node.create_subscription(Odometry, "/odom", lambda m: odom.append(m), 10)
        ros_client.node.create_subscription(TFMessage, "/tf", on_tf, 10)
        tf_pubs = wait_for(
            lambda: (
                [
                    p
                    for p in ros_client.node.get_publishers_info_by_topic("/tf")
                    if p.node_name == "robot_state_publisher"
                ]
                and ros_client.node.get_publishers_info_by_topic("/tf")
            ),
            15,
            "robot_state_publisher among the /tf publishers",
        )
        wait_for(lambda: odom, 15, "/odom")
        x0 = odom[-1].pose.pose.position.x

        run = shell(f"cd {ws} && source install/setup.bash && ros2 run simple_robot square_movement", "square")
        try:
            wait_for(
                lambda: math.hypot(odom[-1].pose.pose.position.x - x0, odom[-1].pose.pose.position.y) > 0.3,
                30,
                "/odom to move",
            )
        finally:
            os.killpg(run.popen.pid, signal.SIGINT)
            run.wait(15)
        with lock:
            got = set(frames)
        assert ("odom", "base_link") in got
        # the wheel frames come from the user's robot_state_publisher (gazelle's built-in one is off)
        assert {("base_link", "left_wheel"), ("base_link", "right_wheel")} <= got
        assert "robot_state_publisher" in {p.node_name for p in tf_pubs}
        assert "gazelle's built-in one is off" in launch.output
    finally:
        t0 = time.monotonic()
        os.killpg(launch.popen.pid, signal.SIGINT)
        rc = launch.wait(20)
        elapsed = time.monotonic() - t0
    assert "user interrupted with ctrl-c (SIGINT)" in launch.output, launch.output
    assert elapsed < 6.0, f"Ctrl-C took {elapsed:.1f} s"
    assert rc in (0, -signal.SIGINT, 130), launch.output
    wait_for(lambda: not _group_alive(launch.popen.pid), 5, "every launched process to exit")


INTERFACE_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>my_msgs</name>
  <version>0.0.1</version>
  <description>A user's interface package</description>
  <maintainer email="user@example.com">user</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <depend>std_msgs</depend>
  <exec_depend>rosidl_default_runtime</exec_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

INTERFACE_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(my_msgs)
find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)
find_package(std_msgs REQUIRED)
rosidl_generate_interfaces(${PROJECT_NAME} "msg/Num.msg" DEPENDENCIES std_msgs)
ament_package()
"""

ROUND_TRIP = (
    "import rclpy; from my_msgs.msg import Num; rclpy.init(); n = rclpy.create_node('rt'); got = []; "
    "n.create_subscription(Num, 'num', got.append, 10); p = n.create_publisher(Num, 'num', 10); "
    "[(p.publish(Num(num=42)), rclpy.spin_once(n, timeout_sec=0.1)) for _ in range(50) if not got]; "
    "print('GOT', got[0].num if got else None)"
)


@pytest.mark.slow
def test_colcon_builds_an_ament_cmake_interface_package_and_rclpy_uses_it(tmp_path):
    pkg = tmp_path / "ws" / "src" / "my_msgs"
    (pkg / "msg").mkdir(parents=True)
    (pkg / "package.xml").write_text(INTERFACE_PACKAGE_XML)
    (pkg / "CMakeLists.txt").write_text(INTERFACE_CMAKE)
    (pkg / "msg" / "Num.msg").write_text("int64 num\nstd_msgs/Header header\n")
    ws = tmp_path / "ws"
    build = shell(f"cd {ws} && colcon build", "colcon")
    assert build.wait(300) == 0, build.output
    run = shell(f'cd {ws} && source install/setup.bash && python -c "{ROUND_TRIP}"', "round trip")
    assert run.wait(60) == 0, run.output
    assert "GOT 42" in run.output, run.output

"""TurtleBot3 as its README says users run it (issue 26's end-to-end test): `colcon build` of a turtlebot3_gazebo
package, then `TURTLEBOT3_MODEL=burger ros2 launch turtlebot3_gazebo turtlebot3_world.launch.py`.

The package is a stand-in of ROBOTIS-GIT/turtlebot3_simulations' jazzy turtlebot3_gazebo: its package.xml,
models, worlds, urdf and bridge YAML are the fixture's files, and its three launch files are written here
with the upstream ones' structure (ros_gz_sim's gz_sim.launch.py with the world, robot_state_publisher with
the URDF, ros_gz_sim's create with model.sdf, ros_gz_bridge's parameter_bridge with the YAML,
GZ_SIM_RESOURCE_PATH appended with the package's models). Its CMakeLists finds ros_gz_sim and installs
the folders; the upstream one also compiles C++ (turtlebot3_drive and three gz-sim obstacle plugins),
which gazelle does not build. The robot must see the world's pillars on /scan, publish each transform once,
and drive 1 m on /cmd_vel (a TwistStamped, as the bridge YAML says: gazelle's DiffDrive takes a Twist, and
the bridge converts)."""

from __future__ import annotations

import math
import os
import shutil
import signal
import threading
from pathlib import Path

import pytest
from _harness import wait_for
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

from .test_blog_workspace import shell
from .test_turtlebot3 import TB3

pytestmark = pytest.mark.slow

CMAKELISTS = """cmake_minimum_required(VERSION 3.8)
project(turtlebot3_gazebo)
find_package(ament_cmake REQUIRED)
find_package(ros_gz_sim REQUIRED)
install(DIRECTORY launch models params urdf worlds DESTINATION share/${PROJECT_NAME}/)
ament_package()
"""

WORLD_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import AppendEnvironmentVariable, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    launch_file_dir = os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'launch')
    ros_gz_sim = get_package_share_directory('ros_gz_sim')
    use_sim_time = LaunchConfiguration('use_sim_time', default='true')
    x_pose = LaunchConfiguration('x_pose', default='-2.0')
    y_pose = LaunchConfiguration('y_pose', default='-0.5')
    world = os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'worlds', 'turtlebot3_world.world')
    gzserver_cmd = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(ros_gz_sim, 'launch', 'gz_sim.launch.py')),
        launch_arguments={'gz_args': ['-r -s -v2 ', world], 'on_exit_shutdown': 'true'}.items())
    gzclient_cmd = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(ros_gz_sim, 'launch', 'gz_sim.launch.py')),
        launch_arguments={'gz_args': '-g -v2 ', 'on_exit_shutdown': 'true'}.items())
    robot_state_publisher_cmd = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_file_dir, 'robot_state_publisher.launch.py')),
        launch_arguments={'use_sim_time': use_sim_time}.items())
    spawn_turtlebot_cmd = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_file_dir, 'spawn_turtlebot3.launch.py')),
        launch_arguments={'x_pose': x_pose, 'y_pose': y_pose}.items())
    set_env_vars_resources = AppendEnvironmentVariable(
        'GZ_SIM_RESOURCE_PATH', os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'models'))
    ld = LaunchDescription()
    ld.add_action(gzserver_cmd)
    ld.add_action(gzclient_cmd)
    ld.add_action(spawn_turtlebot_cmd)
    ld.add_action(robot_state_publisher_cmd)
    ld.add_action(set_env_vars_resources)
    return ld
"""

RSP_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    TURTLEBOT3_MODEL = os.environ['TURTLEBOT3_MODEL']
    use_sim_time = LaunchConfiguration('use_sim_time', default='true')
    urdf_file_name = 'turtlebot3_' + TURTLEBOT3_MODEL + '.urdf'
    frame_prefix = LaunchConfiguration('frame_prefix', default='')
    urdf_path = os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'urdf', urdf_file_name)
    with open(urdf_path, 'r') as infp:
        robot_desc = infp.read()
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false', description='Use simulation clock'),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='robot_state_publisher',
             output='screen',
             parameters=[{'use_sim_time': use_sim_time, 'robot_description': robot_desc,
                          'frame_prefix': PythonExpression(["'", frame_prefix, "/'"])}]),
    ])
"""

SPAWN_LAUNCH = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    TURTLEBOT3_MODEL = os.environ['TURTLEBOT3_MODEL']
    model_folder = 'turtlebot3_' + TURTLEBOT3_MODEL
    urdf_path = os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'models', model_folder, 'model.sdf')
    x_pose = LaunchConfiguration('x_pose', default='0.0')
    y_pose = LaunchConfiguration('y_pose', default='0.0')
    bridge_params = os.path.join(get_package_share_directory('turtlebot3_gazebo'), 'params',
                                 model_folder + '_bridge.yaml')
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('x_pose', default_value='0.0', description='x'))
    ld.add_action(DeclareLaunchArgument('y_pose', default_value='0.0', description='y'))
    ld.add_action(Node(package='ros_gz_sim', executable='create',
                       arguments=['-name', TURTLEBOT3_MODEL, '-file', urdf_path, '-x', x_pose, '-y', y_pose,
                                  '-z', '0.01'],
                       output='screen'))
    ld.add_action(Node(package='ros_gz_bridge', executable='parameter_bridge',
                       arguments=['--ros-args', '-p', f'config_file:={bridge_params}'], output='screen'))
    return ld
"""


def _workspace(root: Path) -> Path:
    pkg = root / "ws" / "src" / "turtlebot3_gazebo"
    source = TB3 / "turtlebot3_gazebo"
    pkg.mkdir(parents=True)
    shutil.copy(source / "package.xml", pkg / "package.xml")
    for folder in ("models", "params", "urdf", "worlds"):
        shutil.copytree(source / folder, pkg / folder)
    (pkg / "launch").mkdir()
    for name, text in (
        ("turtlebot3_world.launch.py", WORLD_LAUNCH),
        ("robot_state_publisher.launch.py", RSP_LAUNCH),
        ("spawn_turtlebot3.launch.py", SPAWN_LAUNCH),
    ):
        (pkg / "launch" / name).write_text(text)
    (pkg / "CMakeLists.txt").write_text(CMAKELISTS)
    return root / "ws"


def test_turtlebot3_world_launch_builds_sees_the_pillars_and_drives_a_metre(tmp_path, ros_client):
    ws = _workspace(tmp_path)
    build = shell(f"cd {ws} && colcon build", "colcon")
    assert build.wait(240) == 0, build.output
    node = ros_client.node
    scans: list[LaserScan] = []
    odom: list[Odometry] = []
    lock = threading.Lock()
    node.create_subscription(LaserScan, "/scan", lambda m: (lock.acquire(), scans.append(m), lock.release()), 10)
    node.create_subscription(Odometry, "/odom", lambda m: (lock.acquire(), odom.append(m), lock.release()), 10)
    launch = shell(
        f"cd {ws} && source install/setup.bash && export TURTLEBOT3_MODEL=burger && "
        "ros2 launch turtlebot3_gazebo turtlebot3_world.launch.py",
        "ros2 launch",
    )
    try:
        launch.wait_line("Successfully spawned entity [burger]", 120)
        launch.wait_line("Converting [/cmd_vel] geometry_msgs/TwistStamped -> geometry_msgs/Twist", 30)
        wait_for(lambda: len(scans) > 2 and odom, 60, "/scan and /odom from the burger")
        # the world's pillars (a 3 x 3 grid 1.1 m apart, model turtlebot3_world): from (-2, -0.5), facing +x,
        # the nearest two are at (-1.1, 0) and (-1.1, -1.1)
        with lock:
            scan = scans[-1]
        for px, py in ((-1.1, 0.0), (-1.1, -1.1)):
            bearing = math.atan2(py + 0.5, px + 2.0)
            centre = math.hypot(py + 0.5, px + 2.0)
            i = round((bearing - scan.angle_min) / scan.angle_increment) % len(scan.ranges)
            near = [scan.ranges[(i + k) % len(scan.ranges)] for k in range(-3, 4)]
            seen = min(r for r in near if math.isfinite(r))
            assert centre - 0.25 < seen < centre, (
                f"pillar at ({px}, {py}): {seen:.3f} m at {math.degrees(bearing):.0f}°"
            )
        # each transform once: the launch starts the user's robot_state_publisher and the spawn together (the
        # spawn first); whichever the server's graph saw first, gazelle's own publisher ends up off
        wait_for(
            lambda: {p.node_name for p in node.get_publishers_info_by_topic("/tf_static")} == {"robot_state_publisher"},
            15,
            "/tf_static from the user's robot_state_publisher alone",
        )
        # drive 1 m on /cmd_vel (TwistStamped, as the bridge YAML says), by odometry, at 0.2 m/s
        cmd = node.create_publisher(TwistStamped, "/cmd_vel", 10)
        with lock:
            x0 = odom[-1].pose.pose.position.x
        go = TwistStamped()
        go.twist.linear.x = 0.2

        def moved() -> float:
            with lock:
                return odom[-1].pose.pose.position.x - x0

        def drive() -> bool:
            cmd.publish(go)
            return moved() >= 1.0

        wait_for(drive, 60, "1 m of driving", interval=0.05)
        cmd.publish(TwistStamped())
        truth = ros_client.entity_state("burger").state.pose.position
        assert truth.x == pytest.approx(-1.0, abs=0.08) and truth.y == pytest.approx(-0.5, abs=0.08)
    finally:
        os.killpg(launch.popen.pid, signal.SIGINT)
        rc = launch.wait(30)
    assert rc in (0, -signal.SIGINT, 130), launch.output

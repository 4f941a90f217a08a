"""robot_localization's ekf_node as gazelle serves it, over real DDS: `ros2 run robot_localization ekf_node
--ros-args --params-file ekf.yaml` with a vendor's common 2-D configuration (wheel odometry's vx and vyaw,
the IMU's yaw and vyaw; the IMU mounted turned on the body, its mount on /tf_static), fed by this test's node
on its own /clock, publishes odometry/filtered and the odom -> base_link transform that follow the robot's
circle; and a launch file's `remappings=[('odometry/filtered', 'odom')]` puts the output on /odom.

Time is the test's: it publishes /clock and stamps the readings with it, 20 ms a tick, and waits for the
filter's output to catch up every few ticks, so the result does not depend on the machine's speed."""

from __future__ import annotations

import math
import sys
import textwrap
from pathlib import Path
from typing import Any

import pytest
import yaml
from _harness import Proc, RosClient, start, wait_for, yaw_of

rclpy = pytest.importorskip("rclpy")

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
V, W = 0.5, 0.4
"""The robot's circle: 0.5 m/s forward, turning at 0.4 rad/s."""
IMU_MOUNT_YAW = math.pi / 2
EKF_PARAMS = {  # a vendor's 2-D ekf.yaml (as the Nav2 and Clearpath guides write them), the values ekf_node reads
    "frequency": 30.0,
    "sensor_timeout": 0.1,
    "two_d_mode": True,
    "transform_time_offset": 0.0,
    "transform_timeout": 0.0,
    "print_diagnostics": True,
    "debug": False,
    "publish_acceleration": False,
    "publish_tf": True,
    "map_frame": "map",
    "odom_frame": "odom",
    "base_link_frame": "base_link",
    "world_frame": "odom",
    "odom0": "wheel/odom",
    "odom0_config": [False] * 6 + [True, False, False, False, False, True] + [False] * 3,
    "odom0_queue_size": 2,
    "odom0_differential": False,
    "odom0_relative": False,
    "imu0": "imu/data",
    "imu0_config": [False] * 5 + [True] + [False] * 5 + [True] + [False] * 3,
    "imu0_differential": False,
    "imu0_relative": False,
    "imu0_queue_size": 5,
    "imu0_remove_gravitational_acceleration": True,
    "use_control": False,
    "process_noise_covariance": [0.05, 0.05, 0.06, 0.03, 0.03, 0.06, 0.025, 0.025, 0.04, 0.01, 0.01, 0.02]
    + [0.01, 0.01, 0.015],
    "initial_estimate_covariance": [1e-9] * 15,
    "use_sim_time": True,
}


def _params_file(tmp_path: Path) -> Path:
    path = tmp_path / "ekf.yaml"
    path.write_text(yaml.safe_dump({"ekf_filter_node": {"ros__parameters": EKF_PARAMS}}))
    return path


class Robot:
    """This test's side: /clock, the wheel odometry, the IMU and its mount; what the filter publishes."""

    def __init__(self, ros: RosClient, output_topic: str) -> None:
        from nav_msgs.msg import Odometry
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import Imu
        from tf2_msgs.msg import TFMessage

        node = ros.node
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self.clock = node.create_publisher(Clock, "/clock", 10)
        self.odom = node.create_publisher(Odometry, "/wheel/odom", 10)
        self.imu = node.create_publisher(Imu, "/imu/data", 10)
        self.static = node.create_publisher(TFMessage, "/tf_static", latched)
        self.start: int | None = None
        """The tick the robot set off at (None: at rest)."""
        self.outputs: list[Any] = []
        self.transforms: list[Any] = []
        self.output = node.create_subscription(Odometry, output_topic, self.outputs.append, 100)
        node.create_subscription(TFMessage, "/tf", self._on_tf, 100)
        self._publish_mount()

    def _on_tf(self, msg: Any) -> None:
        self.transforms.extend(msg.transforms)

    def _publish_mount(self) -> None:
        from geometry_msgs.msg import TransformStamped
        from tf2_msgs.msg import TFMessage

        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = "base_link", "imu_link"
        t.transform.translation.x, t.transform.translation.z = 0.1, 0.2
        t.transform.rotation.z, t.transform.rotation.w = math.sin(IMU_MOUNT_YAW / 2), math.cos(IMU_MOUNT_YAW / 2)
        self.static.publish(TFMessage(transforms=[t]))

    def tick(self, k: int) -> None:
        """Time k * 20 ms: the clock, then the wheels' and the IMU's readings at that time: at rest before
        :attr:`start` (the tick the robot set off at), then on the circle."""
        from nav_msgs.msg import Odometry
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import Imu

        ns = k * 20_000_000
        stamp = Clock().clock
        stamp.sec, stamp.nanosec = ns // 1_000_000_000, ns % 1_000_000_000
        self.clock.publish(Clock(clock=stamp))
        moving = self.start is not None and k >= self.start
        odom = Odometry()
        odom.header.stamp, odom.header.frame_id, odom.child_frame_id = stamp, "odom", "base_link"
        odom.twist.twist.linear.x, odom.twist.twist.angular.z = (V, W) if moving else (0.0, 0.0)
        odom.twist.covariance = [1e-4 if i % 7 == 0 else 0.0 for i in range(36)]
        self.odom.publish(odom)
        imu = Imu()
        imu.header.stamp, imu.header.frame_id = stamp, "imu_link"
        heading = W * self.moved(ns * 1e-9) + IMU_MOUNT_YAW  # the sensor faces 90 degrees to the left of the body
        imu.orientation.z, imu.orientation.w = math.sin(heading / 2), math.cos(heading / 2)
        imu.orientation_covariance = [1e-4 if i % 4 == 0 else 0.0 for i in range(9)]
        imu.angular_velocity.z = W if moving else 0.0
        imu.angular_velocity_covariance = list(imu.orientation_covariance)
        imu.linear_acceleration.z = 9.80665
        imu.linear_acceleration_covariance = [-1.0] + [0.0] * 8
        self.imu.publish(imu)

    def moved(self, t: float) -> float:
        """Seconds the robot has been driving at time ``t``."""
        return 0.0 if self.start is None else max(0.0, t - self.start * 0.02)

    def drive(self, seconds: float, proc: Proc) -> None:
        """At rest until the filter's first output (readings sent before the node's readers matched are
        lost, and its first cycle may come before any reading), then the circle for ``seconds`` of the test's
        clock; every 5 ticks, the filter's output catches up."""
        for pub in (self.clock, self.odom, self.imu):
            wait_for(
                lambda pub=pub: _running(proc) and pub.get_subscription_count() >= 1,
                30,
                f"ekf_node's subscription to {pub.topic}",
            )
        ticks = iter(range(1, 1_000_000))

        def at_rest() -> bool:
            self.tick(next(ticks))
            return bool(self.outputs)

        wait_for(at_rest, 30, "the filter's first output")
        self.start = next(ticks)
        for k in range(self.start, self.start + round(seconds * 50)):
            self.tick(k)
            if k % 5 == 0:
                self._catch_up(k, due=(k - 5) * 0.02)

    def _catch_up(self, k: int, due: float) -> None:
        """Wait for an output stamped ``due`` or later, sending tick ``k`` again now and then (a reading or
        clock message lost on the way would leave the filter waiting)."""
        polls = iter(range(1_000_000))

        def caught_up() -> bool:
            if self.outputs and _t(self.outputs[-1]) >= due:
                return True
            if next(polls) % 10 == 9:
                self.tick(k)
            return False

        wait_for(caught_up, 20, f"the filter's output stamped {due:g} s")


def _running(proc: Proc) -> bool:
    if proc.popen.poll() is not None:
        pytest.fail(f"{proc.name} exited ({proc.popen.returncode}):\n{proc.output}")
    return True


def _t(msg: Any) -> float:
    return msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9


def _check_follows_the_circle(robot: Robot) -> None:
    last = robot.outputs[-1]
    t = robot.moved(_t(last))
    r = V / W
    x, y = r * math.sin(W * t), r * (1 - math.cos(W * t))
    pose = last.pose.pose
    assert (last.header.frame_id, last.child_frame_id) == ("odom", "base_link")
    assert math.hypot(pose.position.x - x, pose.position.y - y) < 0.1, (t, pose.position, (x, y))
    assert abs(math.remainder(yaw_of(pose.orientation) - W * t, 2 * math.pi)) < 0.05
    assert last.twist.twist.linear.x == pytest.approx(V, abs=0.02)
    assert last.twist.twist.angular.z == pytest.approx(W, abs=0.02)
    assert pose.position.z == 0.0 and last.pose.covariance[0] > 0.0  # 2-D mode; a covariance is published


@pytest.fixture
def ros_client():
    client = RosClient("ekf_node_test")
    yield client
    client.close()


def test_ros2_run_ekf_node_with_a_vendors_2d_config_follows_the_robot_and_broadcasts_odom_to_base_link(
    ros_client, tmp_path
):
    proc = start(
        [ROS2, "run", "robot_localization", "ekf_node", "--ros-args", "--params-file", str(_params_file(tmp_path))],
        "ekf_node",
    )
    try:
        robot = Robot(ros_client, "/odometry/filtered")
        robot.drive(6.0, proc)
        _check_follows_the_circle(robot)
        wait_for(lambda: any(t.child_frame_id == "base_link" for t in robot.transforms), 10, "odom -> base_link on /tf")
        tf = [t for t in robot.transforms if t.child_frame_id == "base_link"][-1]
        assert tf.header.frame_id == "odom"
        match = [m for m in robot.outputs if m.header.stamp == tf.header.stamp]
        assert match and tf.transform.translation.x == pytest.approx(match[0].pose.pose.position.x)
    finally:
        rc = proc.interrupt()
    assert rc == 0, proc.output
    assert "not read by gazelle's ekf_node" not in proc.output, proc.output  # a vendor's config is read whole


LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package="robot_localization",
            executable="ekf_node",
            name="ekf_filter_node",
            output="screen",
            parameters=[{params!r}, {{"use_sim_time": True}}],
            remappings=[("odometry/filtered", "odom")],
        ),
    ])
"""


def test_a_launch_files_remapping_puts_the_filtered_odometry_on_odom(ros_client, tmp_path):
    from nav_msgs.msg import Odometry

    launch_file = tmp_path / "ekf.launch.py"
    launch_file.write_text(textwrap.dedent(LAUNCH.format(params=str(_params_file(tmp_path)))))
    unmapped: list[Any] = []
    ros_client.node.create_subscription(Odometry, "/odometry/filtered", unmapped.append, 10)
    proc = start([ROS2, "launch", str(launch_file)], "ros2 launch")
    try:
        robot = Robot(ros_client, "/odom")
        robot.drive(3.0, proc)
        _check_follows_the_circle(robot)
        assert not unmapped
    finally:
        rc = proc.interrupt(20)
    assert rc == 0, proc.output


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (["-p", "frequency:=0.0"], "parameter 'frequency' must be a positive number of Hz, not 0.0"),
        (
            ["-p", "odom0:=odom", "-p", "odom0_config:=[true, false]"],
            "parameter 'odom0_config' must have 15 booleans, not 2",
        ),
    ],
)
def test_a_parameter_it_cannot_use_is_one_line_naming_it(args, said):
    proc = start([ROS2, "run", "robot_localization", "ekf_node", "--ros-args", *args], "ekf_node")
    assert proc.wait(30) == 1
    assert [line for line in proc.lines if line.strip()] == [f"[ERROR] [ekf_filter_node]: {said}"], proc.output

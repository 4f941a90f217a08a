"""robot_localization's ``ekf_node`` (the real one is C++ and not on PyPI), served by
:class:`gazelle.estimation.StateEstimator`: ``ros2 run robot_localization ekf_node --ros-args --params-file
ekf.yaml``, or a launch file's ``Node(package='robot_localization', executable='ekf_node',
name='ekf_filter_node', parameters=[...], remappings=[('odometry/filtered', 'odom')])``.

A plain rclpy node named ``ekf_filter_node``. As robot_localization's (ros2 branch, ``src/ros_filter.cpp``):

* its inputs are the ``odom<N>`` (nav_msgs/Odometry), ``pose<N>`` (PoseWithCovarianceStamped), ``twist<N>``
  (TwistWithCovarianceStamped) and ``imu<N>`` (sensor_msgs/Imu) topics, each kind numbered from 0 to its first
  gap, subscribed best-effort with ``<name>_queue_size`` (10) and configured by ``<name>_config`` (15 booleans),
  ``_differential``, ``_relative``, the rejection thresholds and ``imu<N>_remove_gravitational_acceleration``;
  ``cmd_vel`` (geometry_msgs/Twist) with ``use_control``;
* every ``1 / frequency`` s of its clock (sim time with ``use_sim_time``) it fuses what arrived and publishes
  ``odometry/filtered`` (nav_msgs/Odometry in ``world_frame``), with ``publish_tf`` the ``odom_frame`` ->
  ``base_link_frame`` transform on /tf (``map_frame`` -> ``odom_frame`` when ``world_frame`` is the map), and
  with ``publish_acceleration`` ``accel/filtered``;
* the ``set_pose`` topic (PoseWithCovarianceStamped) sets the state; the ``reset`` and ``enable``
  services (std_srvs/Empty) reset it and start a filter ``disabled_at_startup``;
* sensors' frames are related to the body and world frames by what it hears on /tf and /tf_static.

Where gazelle differs, said at start: parameters it does not act on are named in one warning. It has no
``set_pose`` or ``toggle`` service (robot_localization's srv package is not installed) and publishes no
/diagnostics (diagnostic_msgs is not installed): with ``print_diagnostics`` the configuration checks and
the data's problems are logged instead, each once. Transforms are the latest heard, not interpolated at the
reading's stamp (robot_localization falls back to the latest too).
"""

from __future__ import annotations

import array
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np
import rclpy
from builtin_interfaces.msg import Time
from geometry_msgs.msg import (
    AccelWithCovarianceStamped,
    Point,
    PoseWithCovariance,
    PoseWithCovarianceStamped,
    Quaternion,
    TransformStamped,
    Twist,
    TwistWithCovariance,
    TwistWithCovarianceStamped,
    Vector3,
)
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import Imu
from std_msgs.msg import Header
from std_srvs.srv import Empty
from tf2_msgs.msg import TFMessage

from ..estimation import (
    MAX_FRAMES,
    ConfigError,
    FilterOutput,
    FrameTree,
    ImuReading,
    PoseReading,
    Rigid,
    SensorConfig,
    StateEstimator,
    TwistReading,
    quaternion_from_rotation,
    quaternion_from_rpy,
    read_config,
)

NODE_NAME = "ekf_filter_node"
INPUT_TYPES = {"odom": Odometry, "pose": PoseWithCovarianceStamped, "twist": TwistWithCovarianceStamped, "imu": Imu}


def _ns(stamp: Time) -> int:
    return int(stamp.sec) * 1_000_000_000 + int(stamp.nanosec)


def _stamp(ns: int) -> Time:
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def _xyz(v: Vector3 | Point) -> tuple[float, float, float]:
    return (float(v.x), float(v.y), float(v.z))


def _xyzw(q: Quaternion) -> tuple[float, float, float, float]:
    return (float(q.x), float(q.y), float(q.z), float(q.w))


def _matrix(values: Sequence[float] | np.ndarray, n: int) -> np.ndarray:
    return np.asarray(values, dtype=float).reshape(n, n)


def pose_reading(header: Header, p: PoseWithCovariance) -> PoseReading:
    """A geometry_msgs/PoseWithCovariance with its header as plain values."""
    position, orientation = _xyz(p.pose.position), _xyzw(p.pose.orientation)
    return PoseReading(_ns(header.stamp), header.frame_id, position, orientation, _matrix(p.covariance, 6))


def twist_reading(stamp: Time, frame: str, t: TwistWithCovariance) -> TwistReading:
    """A geometry_msgs/TwistWithCovariance as plain values."""
    return TwistReading(_ns(stamp), frame, _xyz(t.twist.linear), _xyz(t.twist.angular), _matrix(t.covariance, 6))


def imu_reading(m: Imu) -> ImuReading:
    """A sensor_msgs/Imu as plain values."""
    return ImuReading(
        _ns(m.header.stamp),
        m.header.frame_id,
        _xyzw(m.orientation),
        _matrix(m.orientation_covariance, 3),
        _xyz(m.angular_velocity),
        _matrix(m.angular_velocity_covariance, 3),
        _xyz(m.linear_acceleration),
        _matrix(m.linear_acceleration_covariance, 3),
    )


class EkfNode(Node):
    """ekf_node (see the module docstring)."""

    def __init__(self, **node_kwargs: Any) -> None:
        """``node_kwargs`` go to rclpy's Node (a context, parameter overrides: for a node made in-process).

        Raises:
            ConfigError: a parameter of the wrong type or size (the message names it).
        """
        super().__init__(NODE_NAME, automatically_declare_parameters_from_overrides=True, **node_kwargs)
        self.cfg = read_config(self._parameter_values())
        self._said: set[str] = set()
        self._say_configuration()
        self.frames = FrameTree()
        self.estimator = StateEstimator(self.cfg, self.frames, self._now(), clock=self._now)
        self._odom = self.create_publisher(Odometry, "odometry/filtered", 10)
        self._accel = (
            self.create_publisher(AccelWithCovarianceStamped, "accel/filtered", 10)
            if self.cfg.publish_acceleration
            else None
        )
        self._tf = self.create_publisher(TFMessage, "/tf", 100)
        self._listen_to_transforms()
        for sensor in self.cfg.sensors:
            if sensor.updates_anything():
                self._subscribe(sensor)
        if self.cfg.control is not None:
            self.create_subscription(Twist, "cmd_vel", self._on_command, 1)
        self.create_subscription(PoseWithCovarianceStamped, "set_pose", self._on_set_pose, 1)
        self.create_service(Empty, "reset", self._on_reset)
        self.create_service(Empty, "enable", self._on_enable)
        self.create_timer(1.0 / self.cfg.frequency, self._cycle)

    # ------------------------------------------------------------------ set-up
    def _parameter_values(self) -> dict[str, object]:
        """Every parameter set (a params file, ``-p``, a launch file's dict) -> its value, arrays as lists."""
        names = self.list_parameters([], 0).names
        out: dict[str, object] = {}
        for name in names:
            value = self.get_parameter(name).value
            out[name] = list(value) if isinstance(value, array.array | tuple) else value
        return out

    def _say_configuration(self) -> None:
        """Upstream's load-time complaints; what gazelle does not act on, in one warning."""
        for note in self.cfg.notes:
            self.get_logger().warning(note)
        if self.cfg.unread:
            self.get_logger().warning(f"not read by gazelle's ekf_node: {', '.join(self.cfg.unread)}")
        if self.cfg.print_diagnostics:
            self.get_logger().info(
                "print_diagnostics: gazelle's ekf_node logs the diagnostics (each once) instead of publishing "
                "/diagnostics (diagnostic_msgs is not installed)"
            )

    def _listen_to_transforms(self) -> None:
        static = QoSProfile(
            depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self.create_subscription(TFMessage, "/tf", self._on_tf, 100)
        self.create_subscription(TFMessage, "/tf_static", self._on_tf, static)

    def _subscribe(self, sensor: SensorConfig) -> None:
        qos = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=sensor.queue_size,
            reliability=ReliabilityPolicy.BEST_EFFORT,
            durability=DurabilityPolicy.VOLATILE,
        )
        handler = {
            "odom": self._on_odometry,
            "pose": self._on_pose,
            "twist": self._on_twist,
            "imu": self._on_imu,
        }[sensor.kind]
        self.create_subscription(INPUT_TYPES[sensor.kind], sensor.topic, lambda m, s=sensor: handler(s, m), qos)

    # ------------------------------------------------------------------ inputs
    def _now(self) -> int:
        return self.get_clock().now().nanoseconds

    def _on_tf(self, msg: TFMessage) -> None:
        refused = self.frames.refused
        for t in msg.transforms:
            pose = Rigid.from_pose(_xyz(t.transform.translation), _xyzw(t.transform.rotation))
            self.frames.set(t.header.frame_id, t.child_frame_id, pose)
        if self.frames.refused > refused:
            self._say_once("frames_full", f"{MAX_FRAMES} frames heard on /tf: transforms of new frames are not kept")

    def _on_odometry(self, sensor: SensorConfig, m: Odometry) -> None:
        self.estimator.odometry(
            sensor, pose_reading(m.header, m.pose), twist_reading(m.header.stamp, m.child_frame_id, m.twist)
        )

    def _on_pose(self, sensor: SensorConfig, m: PoseWithCovarianceStamped) -> None:
        self.estimator.pose(sensor, pose_reading(m.header, m.pose))

    def _on_twist(self, sensor: SensorConfig, m: TwistWithCovarianceStamped) -> None:
        self.estimator.twist(sensor, twist_reading(m.header.stamp, m.header.frame_id, m.twist))

    def _on_imu(self, sensor: SensorConfig, m: Imu) -> None:
        self.estimator.imu(sensor, imu_reading(m))

    def _on_command(self, m: Twist) -> None:
        self.estimator.command((*_xyz(m.linear), *_xyz(m.angular)), self._now())

    def _on_set_pose(self, m: PoseWithCovarianceStamped) -> None:
        self.get_logger().info(f"Received set_pose request with value {m.pose.pose}")
        self.estimator.set_pose(pose_reading(m.header, m.pose), self._now())

    def _on_reset(self, _request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info("Received a request to reset filter.")
        self.estimator.reset()
        return response

    def _on_enable(self, _request: Empty.Request, response: Empty.Response) -> Empty.Response:
        if self.estimator.enabled:
            self.get_logger().warning(
                f"[{self.get_name()}:] Asking for enabling filter service, but the filter was already enabled! "
                "Use param disabled_at_startup."
            )
        else:
            self.get_logger().info(f"[{self.get_name()}:] Enabling filter...")
            self.estimator.enabled = True
        return response

    # ------------------------------------------------------------------ the cycle
    def _cycle(self) -> None:
        if not self.estimator.enabled:
            self._say_once("disabled", "Filter is disabled. To enable it call the enable service", info=True)
            return
        out = self.estimator.cycle(self._now())
        self._say_notes()
        if out is None:
            return
        if out.transform is not None:
            self._tf.publish(TFMessage(transforms=[self._transform(out)]))
        self._odom.publish(self._odometry(out))
        if self._accel is not None and out.acceleration is not None:
            self._accel.publish(self._acceleration(out))

    def _odometry(self, out: FilterOutput) -> Odometry:
        msg = Odometry()
        msg.header.stamp = _stamp(out.stamp_ns)
        msg.header.frame_id = out.frame
        msg.child_frame_id = out.child
        s = out.state
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        p.x, p.y, p.z = (float(v) for v in s[0:3])
        q.x, q.y, q.z, q.w = quaternion_from_rpy(float(s[3]), float(s[4]), float(s[5]))
        lin, ang = msg.twist.twist.linear, msg.twist.twist.angular
        lin.x, lin.y, lin.z = (float(v) for v in s[6:9])
        ang.x, ang.y, ang.z = (float(v) for v in s[9:12])
        msg.pose.covariance = [float(v) for v in out.covariance[0:6, 0:6].ravel()]
        msg.twist.covariance = [float(v) for v in out.covariance[6:12, 6:12].ravel()]
        return msg

    def _transform(self, out: FilterOutput) -> TransformStamped:
        assert out.transform is not None
        parent, child, pose = out.transform
        t = TransformStamped()
        t.header.stamp = _stamp(out.stamp_ns + self.cfg.transform_time_offset_ns)
        t.header.frame_id, t.child_frame_id = parent, child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = (
            float(v) for v in pose.translation
        )
        r = t.transform.rotation
        r.x, r.y, r.z, r.w = quaternion_from_rotation(pose.rotation)
        return t

    def _acceleration(self, out: FilterOutput) -> AccelWithCovarianceStamped:
        assert out.acceleration is not None
        values, cov = out.acceleration
        msg = AccelWithCovarianceStamped()
        msg.header.stamp = _stamp(out.stamp_ns)
        msg.header.frame_id = out.child
        a = msg.accel.accel
        a.linear.x, a.linear.y, a.linear.z = (float(v) for v in values[0:3])
        a.angular.x, a.angular.y, a.angular.z = (float(v) for v in values[3:6])
        msg.accel.covariance = [float(v) for v in cov.ravel()]
        return msg

    # ------------------------------------------------------------------ what it says
    def _say_once(self, key: str, text: str, info: bool = False) -> None:
        if key in self._said:
            return
        self._said.add(key)
        (self.get_logger().info if info else self.get_logger().warning)(text)

    def _say_notes(self) -> None:
        """The estimator's diagnostics, each kind once: a frame that cannot be related always (the commonest
        misconfiguration), the others with ``print_diagnostics``, as robot_localization reports them only then."""
        for key, text in list(self.estimator.notes.items()):
            always = key.endswith(("_transform", "_future")) or key in ("nan", "queue", "map_odom", "world_frame")
            if always or self.cfg.print_diagnostics:
                self._say_once(key, text)
        self.estimator.notes.clear()


def main(argv: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; returns the exit status (1, with one line, for a parameter it cannot use)."""
    from rclpy.utilities import try_shutdown

    from ._dds import announce_often
    from ._rsp_node import spin_until_interrupted

    announce_often()
    rclpy.init(args=sys.argv if argv is None else argv)
    try:
        node = EkfNode()
    except ConfigError as err:
        print(f"[ERROR] [{NODE_NAME}]: {err}", file=sys.stderr)
        try_shutdown()
        return 1
    spin_until_interrupted(node)
    return 0

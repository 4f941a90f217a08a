"""gz-sim's OdometryPublisher system: a model's ground-truth odometry, as a robot's bring-up bridges it to ROS.

Read against gz-sim 8's ``src/systems/odometry_publisher/OdometryPublisher.cc`` (Harmonic, what Jazzy pairs with):

* the pose is the model frame's world pose times ``<xyz_offset>``/``<rpy_offset>`` (applied in the body frame);
  with ``<dimensions>`` 2 (the default) its z stays 0, while the orientation is the whole rotation, as upstream
  sets it;
* published at ``<odom_publish_frequency>`` (50 Hz) of sim time on ``<odom_topic>`` (``/model/<model>/odometry``)
  as nav_msgs/Odometry without covariance, on ``<odom_covariance_topic>``
  (``/model/<model>/odometry_with_covariance``) with ``<gaussian_noise>``² on both diagonals (what ros_gz_bridge
  makes of gz.msgs.OdometryWithCovariance), and as one transform ``<odom_frame>`` (``<model>/odom``) ->
  ``<robot_base_frame>`` (``<model>/base_footprint``) on ``<tf_topic>`` (``/model/<model>/pose``, a gz Pose_V
  that a bridge YAML usually carries to ``/tf``). As every gz topic in gazelle, these are ROS topics of the
  same names, so the bridge's entries relay them where the YAML says;
* the twist is in the body frame: with 2 dimensions the linear x and y in the frame turned by the yaw and the
  angular z, the other three only noise; with 3 all six; ``<gaussian_noise>`` is the standard deviation of
  Gaussian noise on each of the six, none on the pose.

One difference, kept: upstream differentiates the pose over each step and publishes the mean of the last 10
steps' velocities; gazelle reads the model frame's velocity from MuJoCo when it publishes (the same for steady
motion, without the 10-step lag of the mean), so the world steps in blocks between publications instead of
Python running every step.
"""

from __future__ import annotations

import logging
import math
import random
from dataclasses import dataclass

from ..description import Pose, quat_conj, quat_from_rpy, quat_rotate
from ..physics import PhysicsWorld
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, resolve_topic
from ._payloads import Odometry, Transform, TransformBatch, Twist
from ._plugin_config import child_text, parse_float
from ._registration import add_plugin

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class OdometryPublisherConfig:
    """Parameters of gz-sim's OdometryPublisher (gz-sim 8's names and defaults)."""

    odom_frame: str = ""
    """``<odom_frame>``: the odometry's frame_id; default ``<model>/odom``."""
    robot_base_frame: str = ""
    """``<robot_base_frame>``: the child_frame_id; default ``<model>/base_footprint``."""
    odom_publish_frequency: float = 50.0
    """``<odom_publish_frequency>``, Hz of sim time."""
    odom_topic: str = ""
    """``<odom_topic>``; default ``/model/<model>/odometry``."""
    odom_covariance_topic: str = ""
    """``<odom_covariance_topic>``; default ``/model/<model>/odometry_with_covariance``."""
    tf_topic: str = ""
    """``<tf_topic>``: the odom -> base transform; default ``/model/<model>/pose``."""
    dimensions: int = 2
    """``<dimensions>``: 2 (planar: z, roll and pitch rates left out) or 3."""
    xyz_offset: Vec3 = (0.0, 0.0, 0.0)
    """``<xyz_offset>``, metres in the body frame."""
    rpy_offset: Vec3 = (0.0, 0.0, 0.0)
    """``<rpy_offset>``, radians in the body frame."""
    gaussian_noise: float = 0.0
    """``<gaussian_noise>``: standard deviation on each of the six velocities."""


def _vec3(text: str | None, tag: str, log: logging.Logger) -> Vec3:
    """``<tag>`` as three numbers; 0 0 0 when absent, and with a warning naming the text when it is not three."""
    if not text:
        return (0.0, 0.0, 0.0)
    try:
        values = [float(v) for v in text.split()]
    except ValueError:
        values = []
    if len(values) != 3:
        log.warning(f"<{tag}> must be three numbers, got {text!r}; using 0 0 0")
        return (0.0, 0.0, 0.0)
    return (values[0], values[1], values[2])


def parse_config(ctx: SystemContext, log: logging.Logger) -> OdometryPublisherConfig:
    """The plugin's parameters; a ``<dimensions>`` other than 2 or 3 is refused as upstream refuses it."""
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    dims_text = child_text(cfg, "dimensions")
    dimensions = 2
    if dims_text:
        try:
            dimensions = int(dims_text)
        except ValueError:
            dimensions = 0
    return OdometryPublisherConfig(
        odom_frame=child_text(cfg, "odom_frame") or "",
        robot_base_frame=child_text(cfg, "robot_base_frame") or "",
        odom_publish_frequency=parse_float(cfg, "odom_publish_frequency", 50.0, log),
        odom_topic=child_text(cfg, "odom_topic") or "",
        odom_covariance_topic=child_text(cfg, "odom_covariance_topic") or "",
        tf_topic=child_text(cfg, "tf_topic") or "",
        dimensions=dimensions,
        xyz_offset=_vec3(child_text(cfg, "xyz_offset"), "xyz_offset", log),
        rpy_offset=_vec3(child_text(cfg, "rpy_offset"), "rpy_offset", log),
        gaussian_noise=parse_float(cfg, "gaussian_noise", 0.0, log),
    )


class OdometryPublisher(System):
    """gz-sim's OdometryPublisher: the model frame's odometry and its transform (see the module docstring)."""

    gz_plugin = "OdometryPublisher"

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured OdometryPublisher (see :meth:`configure`); ``seed`` seeds its Gaussian noise."""
        self.config = OdometryPublisherConfig()
        self._entity = ""
        self._link = ""
        self._X_LM = Pose((0.0, 0.0, 0.0))
        self._offset = Pose((0.0, 0.0, 0.0))
        self.frame_id = ""
        self.child_frame_id = ""
        self._odom: Endpoint | None = None
        self._odom_cov: Endpoint | None = None
        self._tf: Endpoint | None = None
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._rng = random.Random(seed)

    def seed_noise(self, seed: int) -> None:
        self._rng = random.Random(seed)

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block and advertise the three topics; ``<dimensions>`` other than 2 or 3 leaves the
        system off with upstream's error."""
        log = ctx.logger
        self.config = c = parse_config(ctx, log)
        if c.dimensions not in (2, 3):
            log.error(
                f"OdometryPublisher system plugin <dimensions> must be 2D or 3D not {c.dimensions}D. "
                "Failed to initialize."
            )
            return
        entity = ctx.entity
        name = self._entity = entity.name
        model = entity.model
        self._link = model.root_link
        root = next((link for link in model.links if link.name == self._link), None)
        # the model frame rides on the root link: X_WM = X_WL * X_LM, X_LM the inverse of the link's model pose
        self._X_LM = (root.pose if root is not None and root.pose is not None else self._X_LM).inverse()
        self._offset = Pose(c.xyz_offset, quat_from_rpy(*c.rpy_offset))
        self.frame_id = c.odom_frame or f"{name}/odom"
        self.child_frame_id = c.robot_base_frame or f"{name}/base_footprint"
        ns = entity.namespace
        odom_topic = resolve_topic(c.odom_topic or f"/model/{name}/odometry", ns)
        cov_topic = resolve_topic(c.odom_covariance_topic or f"/model/{name}/odometry_with_covariance", ns)
        tf_topic = resolve_topic(c.tf_topic or f"/model/{name}/pose", ns)
        self._odom = ctx.bus.advertise(name, odom_topic, MsgType.ODOMETRY, depth=10)
        self._odom_cov = ctx.bus.advertise(name, cov_topic, MsgType.ODOMETRY, depth=10)
        self._tf = ctx.bus.advertise(name, tf_topic, MsgType.TF, depth=100)
        log.info(f"OdometryPublisher publishing odometry on [{odom_topic}], with covariance on [{cov_topic}]")
        log.info(f"OdometryPublisher publishing Pose_V (TF) on [{tf_topic}]")

    def next_update(self, sim_time_sec: float) -> float:
        return self._gate.next if self._odom is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        self._gate.reset()

    def measure(self, world: PhysicsWorld) -> tuple[Pose, Twist]:
        """The noise-free pose (world frame, offsets applied; z 0 in 2-D) and body-frame twist (2-D: x and y in the
        yaw frame and the z rate; 3-D: all six in the body's axes)."""
        state = world.entity_state(self._entity, self._link)
        X_WL = state.pose
        X_WB = X_WL * self._X_LM * self._offset
        omega = state.angular_velocity
        # the velocity of the body origin, which sits r = p_B - p_L from the link's
        r = _sub(X_WB.position, X_WL.position)
        v = _add(state.linear_velocity, _cross(omega, r))
        if self.config.dimensions == 2:
            yaw = X_WB.rpy[2]
            cy, sy = math.cos(yaw), math.sin(yaw)
            linear = (cy * v[0] + sy * v[1], cy * v[1] - sy * v[0], 0.0)
            body_omega = quat_rotate(quat_conj(X_WB.orientation), omega)
            return Pose((X_WB.position[0], X_WB.position[1], 0.0), X_WB.orientation), Twist(
                linear, (0.0, 0.0, body_omega[2])
            )
        qi = quat_conj(X_WB.orientation)
        return X_WB, Twist(quat_rotate(qi, v), quat_rotate(qi, omega))

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At ``<odom_publish_frequency>``, while anyone listens: the odometry, its covariance twin and the
        transform."""
        if (
            self._odom is None
            or info.paused
            or not self._gate.due(info.sim_time_sec, self.config.odom_publish_frequency)
        ):
            return
        pubs = [p for p in (self._odom, self._odom_cov, self._tf) if p is not None and p.wanted]
        if not pubs:
            return  # nobody listens: nothing to build
        pose, twist = self.measure(world)
        gn = self.config.gaussian_noise
        if gn > 0:
            g = self._rng.gauss
            twist = Twist(
                (twist.linear[0] + g(0, gn), twist.linear[1] + g(0, gn), twist.linear[2] + g(0, gn)),
                (twist.angular[0] + g(0, gn), twist.angular[1] + g(0, gn), twist.angular[2] + g(0, gn)),
            )
        stamp = info.sim_time_sec
        if self._odom is not None and self._odom.wanted:
            self._odom.publish(Odometry(stamp, self.frame_id, self.child_frame_id, pose, twist))
        if self._odom_cov is not None and self._odom_cov.wanted:
            cov = tuple(gn * gn if i % 7 == 0 else 0.0 for i in range(36))
            self._odom_cov.publish(Odometry(stamp, self.frame_id, self.child_frame_id, pose, twist, cov, cov))
        if self._tf is not None and self._tf.wanted:
            self._tf.publish(TransformBatch((Transform(stamp, self.frame_id, self.child_frame_id, pose),)))


def _add(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _sub(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a: Vec3, b: Vec3) -> Vec3:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


add_plugin(OdometryPublisher)

"""Force-torque: the wrench through a joint (geometry_msgs/WrenchStamped), gz-sim's sensor and gazebo_ros's
model plugin."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...description import (
    Pose,
    rotation_matrix,
)
from ...physics import BodyHandle, PhysicsWorld
from .._base import RateGate, System, SystemContext, UpdateInfo
from .._bus import Endpoint, MsgType, resolve_topic
from .._frames import entity_frame_prefix
from .._payloads import WrenchStamped
from .._plugin_config import child_text, parse_float, ros_block
from .._registration import add_plugin
from ._common import (
    SENSOR_DEPTH,
    Noise,
    checked_rate,
    xyz_noise,
)


# --------------------------------------------------------------------------- force-torque
@dataclass(frozen=True)
class ForceTorqueConfig:
    """Parameters of ``libgazebo_ros_ft_sensor.so`` (a model plugin), and of a gz-sim
    ``<sensor type="force_torque">`` in a ``<joint>``."""

    joint_name: str = ""
    """``<joint_name>`` (ROS 1: ``<jointName>``); for a gz-sim sensor, the joint it is in."""
    frame: str = "child"
    """gz-sim ``<force_torque><frame>``: child, parent or sensor. The plugin reports in the child frame."""
    measure_direction: str = "child_to_parent"
    """gz-sim ``<measure_direction>``: child_to_parent or parent_to_child (the plugin's)."""
    update_rate: float = 0.0
    """``<update_rate>`` (ROS 1: ``<updateRate>``), Hz of sim time; 0 = every step."""
    gaussian_noise: float = 0.0
    """``<gaussian_noise>`` (ROS 1: ``<gaussianNoise>``): standard deviation on every component."""
    topic: str = "wrench"
    """The plugin's topic (ROS 1: ``<topicName>``); gz-sim: ``<topic>``."""
    noise: tuple[Noise, ...] = ()
    """gz-sim: ``<force>`` and ``<torque>`` ``<x|y|z><noise>``, force x, y, z then torque x, y, z (N, N·m)."""


class ForceTorqueSensor(System):
    """The wrench through a joint (geometry_msgs/WrenchStamped), at the joint's origin.

    * gz-sim (``<sensor type="force_torque">`` in a ``<joint>``, with the world's
      ``gz-sim-forcetorque-system``): ``<force_torque><frame>`` child (default), parent or sensor, and
      ``<measure_direction>`` child_to_parent (default: what the child exerts on the parent) or
      parent_to_child; on ``<topic>``, else ``/world/<w>/model/<m>/joint/<j>/sensor/<s>/forcetorque``.
    * gazebo_ros (``libgazebo_ros_ft_sensor.so``, a model plugin): ``<joint_name>`` (ROS 1:
      ``<jointName>``), ``<update_rate>``, ``<gaussian_noise>``; the wrench on the child link in its
      frame, on ``wrench`` (ROS 1: ``<topicName>``) under ``<ros><namespace>``.
    """

    sdf_types = frozenset({"force_torque"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = "ForceTorque"
    gz_file = ""
    plugin_files = ("gazebo_ros_ft_sensor",)  # a model plugin naming a <joint_name>

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured sensor (see :meth:`configure`); ``seed`` seeds its noise, so that a run with the same
        seed reads the same noisy wrenches."""
        self.config = ForceTorqueConfig()
        self.offset = Pose()
        """The sensor frame in the joint frame (frame "sensor")."""
        self.frame_id = ""
        self._X_CJ = Pose()
        """The joint frame in the child link frame."""
        self._child: BodyHandle | None = None
        self._parent: BodyHandle | None = None
        self._pub: Endpoint | None = None
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._rng = np.random.default_rng(seed)
        self._bias = np.zeros(6)
        """The six channels' biases (force x, y, z, torque x, y, z), drawn once (gz-sim's noise)."""

    def seed_noise(self, seed: int) -> None:
        self._rng = np.random.default_rng(seed)

    @property
    def topic(self) -> str:
        """Where the wrench goes."""
        return self.config.topic

    def _parse(self, ctx: SystemContext) -> tuple[ForceTorqueConfig, str]:
        """The parameters from the gz ``<sensor>`` or the gazebo_ros plugin, and a file:line prefix."""
        log, sensor, plugin = ctx.logger, ctx.sensor, ctx.plugin
        if sensor is not None:
            block = sensor.config.find("force_torque") if sensor.config is not None else None
            where = f"{sensor.location}: " if sensor.location else ""
            frame = (child_text(block, "frame") or "child").strip().lower()
            if frame not in ("child", "parent", "sensor"):
                log.warning(f"{where}<frame> '{frame}' is not child, parent or sensor; using child")
                frame = "child"
            direction = (child_text(block, "measure_direction") or "child_to_parent").strip().lower()
            scoped = f"/world/{ctx.world_name}/model/{ctx.entity.name}/joint/{sensor.joint}"
            topic = resolve_topic(sensor.topic or f"{scoped}/sensor/{sensor.name}/forcetorque", ctx.entity.namespace)
            what = f"force-torque sensor '{sensor.name}'"
            noise = (
                *xyz_noise(block.find("force") if block else None, log, f"{what} force"),
                *xyz_noise(block.find("torque") if block else None, log, f"{what} torque"),
            )
            return ForceTorqueConfig(sensor.joint, frame, direction, sensor.update_rate_hz, 0.0, topic, noise), where
        cfg = plugin.config if plugin is not None else None
        ns, remaps = ros_block(cfg)
        ns = ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace
        # gazebo_ros_ft_sensor reports the wrench on the child link (the parent's action on it), in the child's
        # frame; its ROS 1 spellings are read too
        return ForceTorqueConfig(
            joint_name=child_text(cfg, "joint_name") or child_text(cfg, "jointName") or "",
            measure_direction="parent_to_child",
            update_rate=parse_float(cfg, "update_rate", parse_float(cfg, "updateRate", 0.0, log), log),
            gaussian_noise=parse_float(cfg, "gaussian_noise", parse_float(cfg, "gaussianNoise", 0.0, log), log),
            topic=resolve_topic(child_text(cfg, "topicName") or "wrench", ns, remaps),
        ), (f"{plugin.location}: " if plugin is not None and plugin.location else "")

    def configure(self, ctx: SystemContext) -> None:
        """Find the joint; read the frame, direction, rate and topic."""
        log = ctx.logger
        c, where = self._parse(ctx)
        c = dataclasses.replace(
            c, update_rate=checked_rate(c.update_rate, ctx.world.timestep, where, "force-torque sensor", log)
        )
        self.config = c
        joint = next((j for j in ctx.entity.model.joints if j.name == c.joint_name), None)
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        if not c.joint_name and child_text(cfg, "body_name") is not None:
            # gazebo_ros_ft_sensor's link mode reports Link::WorldForce/WorldTorque, the force other plugins
            # applied to the link this step, in world axes: not simulated here, and said instead of dropped
            log.error(
                f"{where}force-torque sensor: <body_name> (gazebo_ros_ft_sensor's link mode: the force applied to "
                "a link) is not simulated; name the joint it hangs on in <joint_name> instead. It does nothing"
            )
            return
        if joint is None:
            log.error(f"{where}force-torque sensor: '{ctx.entity.name}' has no joint '{c.joint_name}'; it does nothing")
            return
        self._X_CJ = joint.child_offset.inverse()
        self._child = ctx.world.body(ctx.entity.name, joint.child)
        self._parent = ctx.world.body(ctx.entity.name, joint.parent)

        prefix = entity_frame_prefix(ctx.entity, log)
        if ctx.sensor is not None:  # frame_id: the frame the wrench is in (gz-sim's scoped name for the sensor frame)
            self.offset = ctx.sensor.pose
            frame_link = {"child": joint.child, "parent": joint.parent}.get(c.frame)
            self.frame_id = (
                prefix + frame_link if frame_link else f"{ctx.entity.name}::{c.joint_name}::{ctx.sensor.name}"
            )
        else:
            self.frame_id = prefix + joint.child
        self._pub = ctx.bus.advertise(ctx.entity.name, c.topic, MsgType.WRENCH_STAMPED, depth=SENSOR_DEPTH)
        self._bias = np.array([n.bias(self._rng) for n in c.noise]) if c.noise else np.zeros(6)
        log.info(f"force-torque on joint [{c.joint_name}] at {c.update_rate:g} Hz on [{c.topic}] in [{self.frame_id}]")

    def next_update(self, sim_time_sec: float) -> float:
        """The next reading time (never, when not configured)."""
        return self._gate.next if self._pub is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Read again at the next step after a world reset."""
        self._gate.reset()

    def read(self, world: PhysicsWorld) -> tuple[np.ndarray, np.ndarray]:
        """(force, torque) at the joint origin, in the output frame and direction."""
        assert self._child is not None and self._parent is not None
        c = self.config
        X_WC = self._child.pose
        X_WJ = X_WC * self._X_CJ
        # what the parent exerts on the child through the joint, about the joint's origin, world frame (from
        # MuJoCo's constraint forces: what the physics really transmits, not a model of it)
        f, t = self._child.joint_wrench(np.asarray(X_WJ.position))
        if c.measure_direction != "parent_to_child":  # child_to_parent, gz-sim's default: Newton's third law
            f, t = -f, -t
        if c.frame == "parent":
            R = rotation_matrix(self._parent.pose.orientation)
        elif c.frame == "sensor":
            R = rotation_matrix((X_WJ * self.offset).orientation)
        else:
            R = rotation_matrix(X_WC.orientation)
        f, t = R.T @ f, R.T @ t  # world -> the output frame
        if c.gaussian_noise > 0:  # gazebo_ros_ft_sensor: one stddev on all six components
            f = f + self._rng.normal(0.0, c.gaussian_noise, 3)
            t = t + self._rng.normal(0.0, c.gaussian_noise, 3)
        if any(n.active for n in c.noise):
            # gz-sensors 8 ForceTorqueSensor::Update: each channel's own Gaussian model, in the output frame
            ft = np.concatenate([f, t])
            for k, n in enumerate(c.noise):
                if n.active:
                    jitter = self._rng.normal(0.0, n.stddev) if n.stddev > 0 else 0.0
                    ft[k] += self._bias[k] + n.mean + jitter
            f, t = ft[:3], ft[3:]
        return f, t

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the wrench stamped with this sim time.

        The wrench is read after the step, from the constraint forces MuJoCo solved in it, so it is what the
        joint carried during the step that ends at the stamp; nobody listening costs nothing (no read and no
        noise drawn)."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.update_rate):
            return
        if not self._pub.wanted:
            return
        f, t = self.read(world)
        self._pub.publish(
            WrenchStamped(
                info.sim_time_sec,
                self.frame_id,
                (float(f[0]), float(f[1]), float(f[2])),
                (float(t[0]), float(t[1]), float(t[2])),
            )
        )


add_plugin(ForceTorqueSensor)

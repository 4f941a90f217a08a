"""Ground-truth pose publisher, like ``libgazebo_ros_p3d.so``.

Publishes nav_msgs/Odometry of one link on ``odom`` (under ``<ros><namespace>``, remappable) at
``update_rate`` Hz of sim time (0 = every step): pose and twist of ``body_name`` in ``frame_name``
(``world`` by default, or a link of the same model), with constant ``xyz_offset`` / ``rpy_offset`` and
Gaussian noise of standard deviation ``gaussian_noise`` on the velocities (covariance diagonals = noise²).

Read against the ros2 branch's ``gazebo_plugins/src/gazebo_ros_p3d.cpp``:

- ``<xyz_offset>``/``<rpy_offset>`` are the names; the older ``<xyz_offsets>``/``<rpy_offsets>`` still work with
  upstream's deprecation warning, the singular winning when both are given.
- the noise is on the six velocities only (upstream draws it for the twist; the pose is exact), but both
  covariances carry its variance, as upstream fills them.
- The ROS 1 names (``bodyName``, ``frameName``, ``topicName``, ``updateRate``, ``xyzOffsets``/``xyzOffset``,
  ``rpyOffsets``/``rpyOffset``, ``gaussianNoise``, ``robotNamespace``), which the ROS 2 plugin does not read,
  are accepted too: a ROS 1-era description keeps its ground truth.
- Differs: a reference link's pose and velocities are removed exactly, the pose as ``X_WF⁻¹·X_WB`` and the twist
  as ``R_WF⁻¹·(v_B − v_F)``; upstream composes the orientation as ``q_B·q_F⁻¹`` and rotates the velocity
  differences by ``R_WF`` rather than its inverse, which agree with these only while the reference link is
  level and unturned.
"""

from __future__ import annotations

import logging
import math
import random
from collections.abc import Callable
from dataclasses import dataclass

from ..description import ConfigElement, Pose, alias_tags, quat_conj, quat_from_rpy, quat_mul, quat_rotate
from ..physics import WORLD_FRAMES, PhysicsWorld
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, resolve_topic
from ._frames import entity_frame_prefix
from ._payloads import Odometry, Twist
from ._plugin_config import child_text, parse_float, ros_block
from ._registration import add_plugin

ROS1_NAMES = {
    "bodyName": "body_name",
    "frameName": "frame_name",
    "topicName": "topic",
    "updateRate": "update_rate",
    "xyzOffsets": "xyz_offset",
    "xyzOffset": "xyz_offset",
    "rpyOffsets": "rpy_offset",
    "rpyOffset": "rpy_offset",
    "gaussianNoise": "gaussian_noise",
}


@dataclass(frozen=True)
class P3dConfig:
    """Parameters of ``libgazebo_ros_p3d.so`` (ROS 2 names; ROS 1 camelCase accepted)."""

    body_name: str = ""
    """``<body_name>``: the link to report. Required."""
    frame_name: str = "world"
    """``<frame_name>``: ``world`` or a link of the same model; the odometry's frame_id."""
    topic: str = "odom"
    """Topic (``odom`` in ROS 2, remappable; ``<topicName>`` in ROS 1); relative names go under the namespace."""
    update_rate: float = 0.0
    """``<update_rate>``, Hz of sim time; 0 = every step (the default)."""
    xyz_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    """``<xyz_offset>`` (deprecated ``<xyz_offsets>``), metres: added to the position."""
    rpy_offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    """``<rpy_offset>`` (deprecated ``<rpy_offsets>``), radians: pre-multiplied onto the orientation."""
    gaussian_noise: float = 0.0
    """``<gaussian_noise>``: standard deviation on each of the six velocities (m/s, rad/s)."""
    namespace: str = ""
    """``<ros><namespace>`` (ROS 1: ``<robotNamespace>``); default the entity's namespace."""
    remappings: tuple[tuple[str, str], ...] = ()


def _vec3(cfg: ConfigElement, tag: str, log: logging.Logger) -> tuple[float, float, float]:
    """``<tag>`` as three numbers (``<xyz_offsets>``, ``<rpy_offsets>``); 0 0 0 when absent, and with a warning
    naming the text when it is not three numbers."""
    raw = child_text(cfg, tag)
    if not raw:
        return (0.0, 0.0, 0.0)
    try:
        vals = [float(v) for v in raw.split()]
        if len(vals) == 3:
            return (vals[0], vals[1], vals[2])
    except ValueError:
        pass
    log.warning(f"<{tag}> must be three numbers, got {raw!r}; using 0 0 0")
    return (0.0, 0.0, 0.0)


def _offset(cfg: ConfigElement, tag: str, log: logging.Logger) -> tuple[float, float, float]:
    """``<xyz_offset>`` or ``<rpy_offset>``; the deprecated plural with gazebo_ros_p3d.cpp's warning, overridden
    by the singular when both are given (upstream reads the plural first, then the singular over it)."""
    old = tag + "s"
    if child_text(cfg, old) is not None:
        log.warning(f"<{old}> is deprecated, use <{tag}> instead.")
        if child_text(cfg, tag) is None:
            return _vec3(cfg, old, log)
    return _vec3(cfg, tag, log)


def parse_config(ctx: SystemContext, log: logging.Logger) -> P3dConfig:
    """The plugin's parameters, ROS 1 names mapped to ROS 2 ones first."""
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    if cfg is None:
        return P3dConfig(namespace=ctx.entity.namespace)
    alias_tags(ROS1_NAMES)  # a ROS 1 name counts as read when its ROS 2 name is
    kids = []
    for c in cfg.children:
        tag = ROS1_NAMES.get(c.tag, c.tag)
        kids.append(ConfigElement(tag, c.attributes, c.text, c.children, c.location))
    cfg = ConfigElement(cfg.tag, cfg.attributes, cfg.text, tuple(kids), cfg.location)
    ns, remaps = ros_block(cfg)
    return P3dConfig(
        body_name=child_text(cfg, "body_name") or "",
        frame_name=child_text(cfg, "frame_name") or "world",
        topic=child_text(cfg, "topic") or "odom",
        update_rate=parse_float(cfg, "update_rate", 0.0, log),
        xyz_offset=_offset(cfg, "xyz_offset", log),
        rpy_offset=_offset(cfg, "rpy_offset", log),
        gaussian_noise=parse_float(cfg, "gaussian_noise", 0.0, log),
        namespace=ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace,
        remappings=tuple(remaps.items()),
    )


class P3D(System):
    """Publishes a link's ground-truth pose and twist as nav_msgs/Odometry."""

    plugin_files = ("gazebo_ros_p3d",)

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured gazebo_ros_p3d (see :meth:`configure`); ``seed`` seeds its Gaussian noise."""
        self.config = P3dConfig()
        self._pub: Endpoint | None = None
        self._entity = ""
        self._frame_link: str | None = None
        self.frame_id = ""
        self.child_frame_id = ""
        self.topic = ""
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._rng = random.Random(seed)

    def seed_noise(self, seed: int) -> None:
        self._rng = random.Random(seed)

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block: ``<body_name>`` (required; a link of the model), ``<frame_name>`` (world, or
        another link the pose is expressed in; an unknown one falls back to world with a warning, as the plugin
        does), the offsets, the rate and the noise; advertise the Odometry topic."""
        log = ctx.logger
        self.config = c = parse_config(ctx, log)
        model = ctx.entity.model
        links = {lk.name for lk in model.links}
        if not c.body_name:
            log.error("Missing <body_name>, cannot proceed")
            return
        if c.body_name not in links:
            log.error(f"body_name: {c.body_name} does not exist")
            return

        prefix = entity_frame_prefix(ctx.entity, log)
        if c.frame_name in WORLD_FRAMES:
            self._frame_link = None
            self.frame_id = c.frame_name or "world"
        elif c.frame_name in links:
            self._frame_link = c.frame_name
            self.frame_id = prefix + c.frame_name
        else:
            log.warning(f"frame_name: {c.frame_name} does not exist, using world")
            self._frame_link = None
            self.frame_id = "world"
        self.child_frame_id = prefix + c.body_name
        self._entity = ctx.entity.name
        self.topic = resolve_topic(c.topic, c.namespace, dict(c.remappings))
        self._pub = ctx.bus.advertise(self._entity, self.topic, MsgType.ODOMETRY, depth=10)
        self._offset = Pose(c.xyz_offset, quat_from_rpy(*c.rpy_offset))
        log.info(f"p3d: ground truth of [{self.child_frame_id}] in [{self.frame_id}] on [{self.topic}]")

    def next_update(self, sim_time_sec: float) -> float:
        return self._gate.next if self._pub is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        self._gate.reset()

    def measure(self, world: PhysicsWorld) -> tuple[Pose, Twist]:
        """Noise-free pose and twist of the body in the frame, with the offsets applied.

        In the world frame the twist is the link's world velocity (linear and angular, world axes), as
        gazebo_ros_p3d reports ``WorldLinearVel``/``WorldAngularVel``; against a reference link both are
        taken relative to it and expressed in its axes (see the module docstring for how this differs)."""
        body = world.entity_state(self._entity, self.config.body_name)
        pose, lin, ang = body.pose, body.linear_velocity, body.angular_velocity
        if self._frame_link is not None:
            frame = world.entity_state(self._entity, self._frame_link)
            qi = quat_conj(frame.pose.orientation)
            pose = frame.pose.inverse() * pose
            lin = quat_rotate(qi, _sub(lin, frame.linear_velocity))
            ang = quat_rotate(qi, _sub(ang, frame.angular_velocity))
        o = self._offset
        pose = Pose(_add(pose.position, o.position), quat_mul(o.orientation, pose.orientation))
        return pose, Twist(lin, ang)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At ``<update_rate>``, while anyone listens: the body's ground-truth pose and twist (with the offsets, in
        the reference frame), Gaussian noise of ``<gaussian_noise>`` stddev on the velocities only (as
        gazebo_ros_p3d), and its variance on both covariance diagonals."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.update_rate):
            return
        if not self._pub.wanted:
            return  # nobody listens: nothing to build
        pose, twist = self.measure(world)
        gn = self.config.gaussian_noise
        if gn > 0:
            g = self._rng.gauss
            # drawn in gazebo_ros_p3d's order: linear x, y, z, then angular x, y, z
            twist = Twist(_noisy(twist.linear, g, gn), _noisy(twist.angular, g, gn))
        cov = [0.0] * 36
        for i in (0, 7, 14, 21, 28, 35):
            cov[i] = gn * gn
        self._pub.publish(
            Odometry(info.sim_time_sec, self.frame_id, self.child_frame_id, pose, twist, tuple(cov), tuple(cov))
        )


Vec3 = tuple[float, float, float]


def _add(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _sub(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _noisy(v: Vec3, gauss: Callable[[float, float], float], stddev: float) -> Vec3:
    """``v`` plus Gaussian noise on each component, drawn in the order x, y, z."""
    x = v[0] + gauss(0.0, stddev)
    y = v[1] + gauss(0.0, stddev)
    return (x, y, v[2] + gauss(0.0, stddev))


add_plugin(P3D)

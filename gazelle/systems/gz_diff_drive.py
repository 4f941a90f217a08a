"""Differential drive, configured like new Gazebo's ``gz-sim-diff-drive-system`` (``gz::sim::systems::DiffDrive``).

Differences from the classic plugin (:mod:`.diff_drive`), as in gz-sim 8:

* ``wheel_radius`` (not diameter), defaults ``wheel_separation`` 1.0 m and ``wheel_radius`` 0.2 m;
* velocity / acceleration / jerk limiters on the body twist (``math::SpeedLimiter``), applied every step;
* encoder odometry from the wheel joint *positions* (``math::DiffDriveOdometry``), published at
  ``odom_publish_frequency`` (default 50 Hz) with frames ``<model>/odom`` → ``<model>/<canonical link>``;
* topics ``/model/<model>/cmd_vel`` and ``/model/<model>/odometry`` by default. A relative ``<topic>``
  (TurtleBot3's ``cmd_vel``) resolves under the entity's namespace.

gz-sim publishes TF on the gz-transport topic ``/model/<model>/tf`` for ros_gz_bridge to carry to ROS.
Here, so that it works with no bridge, the odom → child transform always goes on ROS ``/tf``;
an explicit ``<tf_topic>`` other than ``/tf`` gets it as well.

The wheels use the same velocity servo as the classic drive (:func:`.diff_drive.add_wheel_servo`);
gz-sim's joint velocity command has no torque parameter, so the servo is limited by the joint's
``<limit><effort>`` when the file gives one.
"""

from __future__ import annotations

import logging
import math
from collections import deque
from dataclasses import dataclass

from ..description import ConfigElement, Pose, quat_from_rpy
from ..physics import PhysicsWorld
from ._actuation import VelocityServo, add_wheel_servo
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, resolve_topic
from ._frames import entity_frame_prefix
from ._payloads import Odometry, Transform, TransformBatch, Twist
from ._plugin_config import all_texts, child_text, parse_float
from ._registration import add_plugin
from .diff_drive import joints_listing, wheel_direction_hint

_INF = math.inf


@dataclass(frozen=True)
class SpeedLimits:
    """Bounds of one ``math::SpeedLimiter`` (unset = unbounded)."""

    min_velocity: float = -_INF
    max_velocity: float = _INF
    min_acceleration: float = -_INF
    max_acceleration: float = _INF
    min_jerk: float = -_INF
    max_jerk: float = _INF


class SpeedLimiter:
    """gz::math::SpeedLimiter: jerk, then acceleration, then velocity clamping."""

    def __init__(self, limits: SpeedLimits) -> None:
        self.limits = limits

    def limit(self, vel: float, prev: float, prev_prev: float, dt: float) -> float:
        """The limited velocity given the last two commands (``prev`` newest) and the step ``dt``."""
        lim = self.limits
        if dt <= 0:
            return min(max(vel, lim.min_velocity), lim.max_velocity)
        # jerk
        if math.isfinite(lim.min_jerk) or math.isfinite(lim.max_jerk):
            dv, dpv = vel - prev, prev - prev_prev
            da = min(max(dv - dpv, lim.min_jerk * dt * dt), lim.max_jerk * dt * dt)
            vel = prev + dpv + da
        # acceleration
        dv = min(max(vel - prev, lim.min_acceleration * dt), lim.max_acceleration * dt)
        vel = prev + dv
        # velocity
        return min(max(vel, lim.min_velocity), lim.max_velocity)


class DiffDriveOdometry:
    """gz::math::DiffDriveOdometry: pose from wheel angle increments, velocities as a rolling mean."""

    def __init__(self, separation: float, left_radius: float, right_radius: float, window: int = 10) -> None:
        """Odometry of a differential drive with wheels ``separation`` metres apart and these radii (metres); the
        published speeds are the means over the last ``window`` updates, as gz-math's DiffDriveOdometry."""
        self.separation = separation
        self.left_radius = left_radius
        self.right_radius = right_radius
        self._lin: deque[float] = deque(maxlen=window)
        self._ang: deque[float] = deque(maxlen=window)
        self.reset()

    def reset(self) -> None:
        """Back to the origin; the next update only records where the wheels are (gz-math's Init)."""
        self.x = self.y = self.heading = 0.0
        self.linear = self.angular = 0.0
        self._lin.clear()
        self._ang.clear()
        self._left_old: float | None = None
        self._right_old = 0.0
        self._time = 0.0

    def update(self, left_pos: float, right_pos: float, time_sec: float) -> None:
        """Integrate the wheels' travel since the last update (their angles in radians, at sim time ``time_sec``):
        the pose along the arc the travel describes (second-order Runge-Kutta when nearly straight), and the
        speeds as travel over time, averaged over the window. Updates closer than 0.1 ms are skipped (gz-math's
        guard against dividing by a vanishing dt)."""
        if self._left_old is None:  # Init(): remember where the wheels are
            self._left_old, self._right_old, self._time = left_pos, right_pos, time_sec
            return
        dt = time_sec - self._time
        if dt < 0.0001:
            return
        left = (left_pos - self._left_old) * self.left_radius
        right = (right_pos - self._right_old) * self.right_radius
        self._left_old, self._right_old, self._time = left_pos, right_pos, time_sec
        lin = (right + left) * 0.5
        ang = (right - left) / self.separation
        if abs(ang) < 1e-6:  # Runge-Kutta 2
            direction = self.heading + ang * 0.5
            self.x += lin * math.cos(direction)
            self.y += lin * math.sin(direction)
            self.heading += ang
        else:  # exact arc
            old = self.heading
            r = lin / ang
            self.heading += ang
            self.x += r * (math.sin(self.heading) - math.sin(old))
            self.y += -r * (math.cos(self.heading) - math.cos(old))
        self._lin.append(lin / dt)
        self._ang.append(ang / dt)
        self.linear = sum(self._lin) / len(self._lin)
        self.angular = sum(self._ang) / len(self._ang)


@dataclass(frozen=True)
class GzDiffDriveConfig:
    """Parameters of gz-sim's ``DiffDrive`` system (names and defaults as gz-sim 8)."""

    left_joints: tuple[str, ...] = ()
    """``<left_joint>`` (repeatable). Required; every listed joint gets the same command."""
    right_joints: tuple[str, ...] = ()
    """``<right_joint>`` (repeatable). Required."""
    wheel_separation: float = 1.0
    """``<wheel_separation>``, metres; default 1.0."""
    wheel_radius: float = 0.2
    """``<wheel_radius>``, metres; default 0.2."""
    odom_publish_frequency: float = 50.0
    """``<odom_publish_frequency>``, Hz of sim time; default 50."""
    topic: str = ""
    """``<topic>`` for geometry_msgs/Twist; default ``/model/<model>/cmd_vel``; relative ones go under the namespace."""
    odom_topic: str = ""
    """``<odom_topic>`` for nav_msgs/Odometry; default ``/model/<model>/odometry``."""
    tf_topic: str = ""
    """``<tf_topic>``; the transform always goes on ``/tf`` too (gz-sim: ``/model/<model>/tf`` for ros_gz_bridge)."""
    frame_id: str = ""
    """``<frame_id>``; default ``<model>/odom``. An explicit one gets the entity's frame prefix."""
    child_frame_id: str = ""
    """``<child_frame_id>``; default ``<model>/<canonical link>``. An explicit one gets the frame prefix."""
    linear: SpeedLimits = SpeedLimits()
    """``<min|max_velocity|acceleration|jerk>`` then ``<min|max_linear_…>``: limits of the forward speed."""
    angular: SpeedLimits = SpeedLimits()
    """``<min|max_velocity|acceleration|jerk>`` then ``<min|max_angular_…>``: limits of the turn rate."""
    namespace: str = ""
    """The entity's namespace (relative topics resolve under it)."""


def _limits(cfg: ConfigElement, which: str, log: logging.Logger) -> SpeedLimits:
    """The speed limits of one axis (``linear`` or ``angular``): gz-sim 8 reads ``<min_velocity>`` etc. for both
    axes, then ``<min_linear_velocity>``/``<min_angular_velocity>`` etc. override them per axis; unset limits are
    infinite."""
    vals: dict[str, float] = {}
    for m in ("min", "max"):
        for q in ("velocity", "acceleration", "jerk"):
            default = -_INF if m == "min" else _INF
            v = parse_float(cfg, f"{m}_{q}", default, log)
            vals[f"{m}_{q}"] = parse_float(cfg, f"{m}_{which}_{q}", v, log)
    return SpeedLimits(**vals)


def parse_config(ctx: SystemContext, log: logging.Logger) -> GzDiffDriveConfig:
    """Read the ``<plugin>`` block; unknown children are warned about by name and location.

    gz-sim 8's names and defaults (``DiffDrive.cc`` ``Configure``): one or more ``<left_joint>`` and
    ``<right_joint>``, ``wheel_separation`` 1.0 m, ``wheel_radius`` 0.2 m, odometry at 50 Hz; the topics and
    frames empty here mean gz-sim's model-scoped defaults, filled in by :meth:`GzDiffDrive.configure`."""
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    if cfg is None:
        return GzDiffDriveConfig(namespace=ctx.entity.namespace)
    return GzDiffDriveConfig(
        left_joints=all_texts(cfg, "left_joint"),
        right_joints=all_texts(cfg, "right_joint"),
        wheel_separation=parse_float(cfg, "wheel_separation", 1.0, log),
        wheel_radius=parse_float(cfg, "wheel_radius", 0.2, log),
        odom_publish_frequency=parse_float(cfg, "odom_publish_frequency", 50.0, log),
        topic=child_text(cfg, "topic") or "",
        odom_topic=child_text(cfg, "odom_topic") or "",
        tf_topic=child_text(cfg, "tf_topic") or "",
        frame_id=child_text(cfg, "frame_id") or "",
        child_frame_id=child_text(cfg, "child_frame_id") or "",
        linear=_limits(cfg, "linear", log),
        angular=_limits(cfg, "angular", log),
        namespace=ctx.entity.namespace,
    )


class GzDiffDrive(System):
    """gz-sim's DiffDrive: limiters every step, encoder odometry, ``/model/<model>/…`` topics."""

    gz_plugin = "DiffDrive"

    def __init__(self) -> None:
        """An unconfigured DiffDrive (see :meth:`configure`)."""
        self.config = GzDiffDriveConfig()
        self.log = logging.getLogger("DiffDrive")
        self._cmd = Twist()
        self._wheels: list[tuple[VelocityServo, int]] = []
        """(servo, side): +1 right, -1 left."""
        self._last0 = (0.0, 0.0)
        self._last1 = (0.0, 0.0)
        self._odom: DiffDriveOdometry | None = None
        self._odom_pub: Endpoint | None = None
        self._tf_pubs: list[Endpoint] = []
        self._odom_gate = RateGate()
        self._entity = ""
        self.frame_id = ""
        self.child_frame_id = ""
        self.cmd_topic = ""
        self._ok = False

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block (gz-sim 8's names and defaults), check the wheel joints (a missing one is an error
        naming the model's joints, and the plugin stays off, as gz-sim's does), put a velocity servo on each
        wheel joint (bounded by its ``<limit><effort>``), and declare the command, odometry and TF topics:
        ``/model/<model>/cmd_vel`` and ``/model/<model>/odometry`` unless given, and the odometry frames
        ``<model>/odom`` -> ``<model>/<canonical link>`` by default."""
        self.log = log = ctx.logger
        self.config = c = parse_config(ctx, log)
        entity = ctx.entity
        self._entity = model_name = entity.name

        prefix = entity_frame_prefix(entity, log)
        if not c.left_joints or not c.right_joints:
            log.error("DiffDrive plugin missing <left_joint> or <right_joint>; it will not work")
            return
        joints = {j.name: j for j in entity.model.joints}
        missing = [jn for jn in (*c.left_joints, *c.right_joints) if jn not in joints]
        if missing:
            for jn in missing:
                log.error(f"Joint [{jn}] not found, DiffDrive will not work. {joints_listing(entity.model)}")
            return
        hint = wheel_direction_hint(entity.model, tuple(c.left_joints), tuple(c.right_joints))
        if hint is not None:
            log.warning(hint)
        for side, names in ((1, c.right_joints), (-1, c.left_joints)):
            for jn in names:
                axis = joints[jn].axis
                limit = axis.limit.effort if axis is not None else None
                self._wheels.append(
                    (add_wheel_servo(ctx.world, entity, jn, limit if limit is not None else _INF), side)
                )
        self._odom = DiffDriveOdometry(c.wheel_separation, c.wheel_radius, c.wheel_radius)
        self._limit_lin = SpeedLimiter(c.linear)
        self._limit_ang = SpeedLimiter(c.angular)
        self.cmd_topic = resolve_topic(c.topic or f"/model/{model_name}/cmd_vel", c.namespace)
        ctx.bus.subscribe(model_name, self.cmd_topic, MsgType.TWIST, self._on_cmd, depth=1)
        log.info(f"DiffDrive subscribing to twist messages on [{self.cmd_topic}]")
        odom_topic = resolve_topic(c.odom_topic or f"/model/{model_name}/odometry", c.namespace)
        self._odom_pub = ctx.bus.advertise(model_name, odom_topic, MsgType.ODOMETRY, depth=1)
        tf_topics = ["/tf"]
        if c.tf_topic and resolve_topic(c.tf_topic, c.namespace) != "/tf":
            tf_topics.append(resolve_topic(c.tf_topic, c.namespace))
        self._tf_pubs = [ctx.bus.advertise(model_name, t, MsgType.TF, depth=100) for t in tf_topics]
        self.frame_id = prefix + c.frame_id if c.frame_id else f"{model_name}/odom"
        canonical = entity.model.root_link
        self.child_frame_id = prefix + c.child_frame_id if c.child_frame_id else f"{model_name}/{canonical}"
        log.info(
            f"DiffDrive publishing odometry on [{odom_topic}] and TF on {tf_topics} "
            f"between [{self.frame_id}] and [{self.child_frame_id}]"
        )
        self._ok = True

    def _on_cmd(self, twist: Twist) -> None:
        self._cmd = twist

    def command(self, linear_x: float, angular_z: float) -> None:
        """Set the commanded body velocity directly (as a ``cmd_vel`` message would)."""
        self._cmd = Twist((linear_x, 0.0, 0.0), (0.0, 0.0, angular_z))

    @property
    def limited_command(self) -> tuple[float, float]:
        """The (linear, angular) command after the limiters, as sent to the wheels this step."""
        return self._last0

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After a world reset: no command, limits' history cleared, servos and odometry back to their start."""
        self._cmd = Twist()
        self._last0 = self._last1 = (0.0, 0.0)
        for servo, _ in self._wheels:
            servo.reset()
        self._odom_gate.reset()
        if self._odom is not None:
            self._odom.reset()

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Before each step: the command, limited in velocity, acceleration and jerk, as wheel speeds: ``(v ± ω·s/2)
        / r`` (right +, left -)."""
        if not self._ok or info.paused:
            return
        c = self.config
        lin = self._limit_lin.limit(self._cmd.linear[0], self._last0[0], self._last1[0], info.dt_sec)
        ang = self._limit_ang.limit(self._cmd.angular[2], self._last0[1], self._last1[1], info.dt_sec)
        self._last1, self._last0 = self._last0, (lin, ang)
        for servo, side in self._wheels:
            servo.update((lin + side * ang * c.wheel_separation / 2.0) / c.wheel_radius, info.sim_time_sec)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After each step: the odometry integrates the wheels' angles; at ``<odom_publish_frequency>`` it is
        published with its transform, while anyone listens."""
        if not self._ok or info.paused or self._odom is None:
            return
        right = next(servo for servo, side in self._wheels if side == 1)
        left = next(servo for servo, side in self._wheels if side == -1)
        self._odom.update(left.actuator.joint.position, right.actuator.joint.position, info.sim_time_sec)
        if not self._odom_gate.due(info.sim_time_sec, self.config.odom_publish_frequency):
            return
        tf_pubs = [pub for pub in self._tf_pubs if pub.wanted]
        odom_pub = self._odom_pub if self._odom_pub is not None and self._odom_pub.wanted else None
        if odom_pub is None and not tf_pubs:
            return  # nobody listens: nothing to build
        o = self._odom
        pose = Pose((o.x, o.y, 0.0), quat_from_rpy(0.0, 0.0, o.heading))
        stamp = info.sim_time_sec
        if odom_pub is not None:
            odom_pub.publish(
                Odometry(
                    stamp, self.frame_id, self.child_frame_id, pose, Twist((o.linear, 0.0, 0.0), (0.0, 0.0, o.angular))
                )
            )
        batch = TransformBatch((Transform(stamp, self.frame_id, self.child_frame_id, pose),))
        for pub in tf_pubs:
            pub.publish(batch)


add_plugin(GzDiffDrive)

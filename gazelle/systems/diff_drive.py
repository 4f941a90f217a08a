"""Differential drive, configured like Gazebo Classic's ``libgazebo_ros_diff_drive.so``.

Subscribes ``cmd_vel`` (geometry_msgs/Twist) and drives each wheel joint with a
force-limited velocity servo (:class:`~gazelle.systems._actuation.VelocityServo`)
towards ``(v ∓ ω·separation/2) / radius`` along the joint's own axis, exactly as
the classic plugin sets the joint velocity. Publishes ``odom`` (nav_msgs/Odometry)
and the odom → base transform on ``/tf`` at ``update_rate``, stamped with sim time.

It runs at ``update_rate`` (100 Hz by default), as the classic plugin updates its
commands and odometry; between its updates the wheels' servos run inside MuJoCo.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

from ..description import ConfigElement, Model, Pose, alias_tags, quat_from_rpy, quat_rotate
from ..physics import BodyHandle, PhysicsWorld
from ._actuation import VelocityServo, add_wheel_servo
from ._base import System, SystemContext, UpdateInfo
from ._bus import Endpoint, MsgType, resolve_topic
from ._frames import entity_frame_prefix
from ._payloads import JointStates, Odometry, Transform, TransformBatch, Twist
from ._plugin_config import all_texts, child_text, parse_bool, parse_float, ros_block
from ._registration import add_plugin

ODOM_ENCODER = 0
ODOM_WORLD = 1


@dataclass(frozen=True)
class DiffDriveConfig:
    """Parameters of ``libgazebo_ros_diff_drive.so`` (names and defaults as the classic plugin)."""

    left_joints: tuple[str, ...] = ()
    """``<left_joint>`` (repeatable, one per wheel pair). Required."""
    right_joints: tuple[str, ...] = ()
    """``<right_joint>`` (repeatable). Required."""
    num_wheel_pairs: int = 1
    """``<num_wheel_pairs>``, default 1."""
    wheel_separation: tuple[float, ...] = (0.34,)
    """``<wheel_separation>`` per pair, metres; default 0.34."""
    wheel_diameter: tuple[float, ...] = (0.15,)
    """``<wheel_diameter>`` per pair, metres; default 0.15."""
    max_wheel_torque: float = 5.0
    """``<max_wheel_torque>``, N·m; the servo's force limit. Default 5."""
    max_wheel_acceleration: float = 0.0
    """``<max_wheel_acceleration>``, m/s² at the rim; 0 = unlimited (default)."""
    update_rate: float = 100.0
    """``<update_rate>``, Hz, for commands and odometry; ≤ 0 = every step. Default 100."""
    odometry_frame: str = "odom"
    """``<odometry_frame>``, default ``odom``."""
    robot_base_frame: str = "base_footprint"
    """``<robot_base_frame>``, default ``base_footprint``."""
    odometry_source: int = ODOM_WORLD
    """``<odometry_source>``: 1 = world (ground truth, default), 0 = encoder."""
    publish_odom: bool = False
    """``<publish_odom>``, default false."""
    publish_odom_tf: bool = False
    """``<publish_odom_tf>``, default false."""
    publish_wheel_tf: bool = False
    """``<publish_wheel_tf>``, default false."""
    covariance_x: float = 0.00001
    """``<covariance_x>``, m²: the odometry's x variance (pose and twist covariance diagonals)."""
    covariance_y: float = 0.00001
    """``<covariance_y>``, m²."""
    covariance_yaw: float = 0.001
    """``<covariance_yaw>``, rad²."""
    command_topic: str = "cmd_vel"
    """``<commandTopic>`` (ROS 1 name; the ROS 2 plugin fixes it to ``cmd_vel``, use a remapping)."""
    odometry_topic: str = "odom"
    """``<odometryTopic>`` (ROS 1 name; the ROS 2 plugin fixes it to ``odom``)."""
    publish_wheel_joint_state: bool = False
    """``<publishWheelJointState>`` (ROS 1): publish the wheel joints on ``joint_states``."""
    legacy_mode: bool = False
    """``<legacyMode>`` (ROS 1): true swaps the left and right wheel speeds, as ROS 1's default did."""
    namespace: str = ""
    """``<ros><namespace>``."""
    remappings: tuple[tuple[str, str], ...] = ()
    """``<ros><argument>from:=to`` and ``<ros><remapping>from:=to``, as gazebo_ros gives them to rcl."""


ROS1_NAMES = {
    "leftJoint": "left_joint",
    "rightJoint": "right_joint",
    "wheelSeparation": "wheel_separation",
    "wheelDiameter": "wheel_diameter",
    "wheelTorque": "max_wheel_torque",
    "wheelAcceleration": "max_wheel_acceleration",
    "updateRate": "update_rate",
    "commandTopic": "command_topic",
    "odometryTopic": "odometry_topic",
    "odometryFrame": "odometry_frame",
    "robotBaseFrame": "robot_base_frame",
    "publishWheelTF": "publish_wheel_tf",
    "publishOdomTF": "publish_odom_tf",
    "publishWheelJointState": "publish_wheel_joint_state",
    "odometrySource": "odometry_source",
    "legacyMode": "legacy_mode",
    "rosDebugLevel": "",  # accepted, no effect (ROS 1 console verbosity)
    "publishTf": "",  # ROS 1 master switch for all TF; handled below
    "robotNamespace": "",  # ROS 1 namespace; handled below
}
"""ROS 1 (``gazebo_ros_diff_drive`` for Gazebo 7-11) camelCase names -> the ROS 2 names used here."""


def _translate_ros1(cfg: ConfigElement, log: logging.Logger) -> tuple[ConfigElement, bool]:
    """Rename ROS 1 camelCase children to the ROS 2 names (each counts as read when its ROS 2 name is; a child
    nothing reads is named by the runtime, see ``description.config_reads``).

    Returns the (possibly rewritten) element and whether any ROS 1 name was used.
    """
    alias_tags(ROS1_NAMES)
    children: list[ConfigElement] = []
    ros1 = False
    for c in cfg.children:
        if c.tag in ROS1_NAMES:
            ros1 = True
            new = ROS1_NAMES[c.tag]
            if new == "odometry_source":  # ROS 1 takes "encoder" / "world" (or the number)
                text = {"encoder": str(ODOM_ENCODER), "world": str(ODOM_WORLD)}.get(c.text.strip().lower(), c.text)
                c = ConfigElement(c.tag, c.attributes, text, c.children, c.location)
            if new:
                children.append(ConfigElement(new, c.attributes, c.text, c.children, c.location))
            children.append(c)
        else:
            children.append(c)  # a child nothing reads is named by the runtime (``config_reads``)
    return ConfigElement(cfg.tag, cfg.attributes, cfg.text, tuple(children), cfg.location), ros1


def parse_config(ctx: SystemContext, log: logging.Logger) -> DiffDriveConfig:
    """Read a ``<plugin>`` block into :class:`DiffDriveConfig`, logging what is wrong.

    Also accepts the ROS 1 camelCase names (``leftJoint``, ``wheelDiameter``, ``commandTopic``...,
    see :data:`ROS1_NAMES`). A ROS 1 block keeps ROS 1's behaviour where it differs: odometry is
    always published and ``publishOdomTF`` defaults to true.
    """
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    if cfg is None:
        return DiffDriveConfig()
    cfg, ros1 = _translate_ros1(cfg, log)
    pairs = int(parse_float(cfg, "num_wheel_pairs", 1, log))
    if pairs < 1:
        log.warning("Drive requires at least one pair of wheels. Setting [num_wheel_pairs] to 1")
        pairs = 1

    def floats(tag: str, default: float) -> tuple[float, ...]:
        """Every ``<tag>`` (one per wheel pair), numbers only (a bad one is warned about with its file:line); as
        many as there are pairs, the rest ignored with the classic plugin's warning, missing ones ``default``."""
        vals: list[float] = []
        for el in cfg.findall(tag):
            try:
                vals.append(float(el.text.strip()))
            except ValueError:
                log.warning(f"{el.location}: <{tag}> must be a number, got {el.text.strip()!r}")
        if len(vals) > pairs:
            log.warning(f"Ignoring rest of specified <{tag}>")
            vals = vals[:pairs]
        while len(vals) < pairs:
            vals.append(default)
        return tuple(vals)

    ns, remaps = ros_block(cfg)
    ns = ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace
    source = int(parse_float(cfg, "odometry_source", ODOM_WORLD, log))
    publish_tf = parse_bool(cfg, "publishTf", True, log)
    legacy = False
    if ros1:
        if cfg.find("legacyMode") is None:
            log.warning(
                "missing <legacyMode>, defaults to true (as in ROS 1): left and right wheels are swapped; "
                "set <legacyMode>false</legacyMode>"
            )
            legacy = True
        else:
            legacy = parse_bool(cfg, "legacyMode", True, log)
    return DiffDriveConfig(
        left_joints=all_texts(cfg, "left_joint"),
        right_joints=all_texts(cfg, "right_joint"),
        num_wheel_pairs=pairs,
        wheel_separation=floats("wheel_separation", 0.34),
        wheel_diameter=floats("wheel_diameter", 0.15),
        max_wheel_torque=parse_float(cfg, "max_wheel_torque", 5.0, log),
        max_wheel_acceleration=parse_float(cfg, "max_wheel_acceleration", 0.0, log),
        update_rate=parse_float(cfg, "update_rate", 100.0, log),
        odometry_frame=child_text(cfg, "odometry_frame") or "odom",
        robot_base_frame=child_text(cfg, "robot_base_frame") or "base_footprint",
        odometry_source=source if source in (ODOM_ENCODER, ODOM_WORLD) else ODOM_WORLD,
        publish_odom=ros1 or parse_bool(cfg, "publish_odom", False, log),
        publish_odom_tf=publish_tf and parse_bool(cfg, "publish_odom_tf", ros1, log),
        publish_wheel_tf=publish_tf and parse_bool(cfg, "publish_wheel_tf", False, log),
        covariance_x=parse_float(cfg, "covariance_x", 0.00001, log),
        covariance_y=parse_float(cfg, "covariance_y", 0.00001, log),
        covariance_yaw=parse_float(cfg, "covariance_yaw", 0.001, log),
        command_topic=child_text(cfg, "command_topic") or "cmd_vel",
        odometry_topic=child_text(cfg, "odometry_topic") or "odom",
        publish_wheel_joint_state=parse_bool(cfg, "publish_wheel_joint_state", False, log),
        legacy_mode=legacy,
        namespace=ns,
        remappings=tuple(remaps.items()),
    )


@dataclass
class _Wheel:
    joint: str
    servo: VelocityServo
    radius: float
    side: int
    """+1 right, -1 left (sign of the ω term)."""
    separation: float
    instructed: float = 0.0
    """Current rim speed command after the acceleration limit, m/s."""


class DiffDrive(System):
    """The classic gazebo_ros differential drive."""

    plugin_files = ("gazebo_ros_diff_drive",)

    def __init__(self) -> None:
        """An unconfigured gazebo_ros diff drive (see :meth:`configure`). Its state: the last command (held
        until a new one, as the plugin holds it), the wheels and their servos, the encoder odometry's pose,
        twist and the wheel angles it last integrated from, and the links it publishes wheel TF between."""
        self.config = DiffDriveConfig()
        self.log = logging.getLogger("diff_drive")
        self._wheels: list[_Wheel] = []
        self._cmd = Twist()
        self._last_update = -math.inf
        self._odom_pub: Endpoint | None = None
        self._tf_pub: Endpoint | None = None
        self._js_pub: Endpoint | None = None
        self._cmd_sub: Endpoint | None = None
        self._entity = ""
        self.prefix = ""
        """Prepended to every frame (the namespace by default)."""
        self._enc_pose = (0.0, 0.0, 0.0)
        self._enc_twist = (0.0, 0.0)
        self._enc_last: tuple[float, float, float] | None = None
        """(sim time, right wheel angle, left wheel angle) at the last encoder update."""
        self._ok = False
        self._due = False
        self._root: BodyHandle | None = None
        self._wheel_links: list[tuple[BodyHandle, BodyHandle, str, str]] = []
        """(parent link, child link, parent frame, child frame) of each wheel joint, for the wheel TF."""

    # ------------------------------------------------------------------ configure
    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block (gazebo_ros2's names and defaults, and ROS 1's), check that every wheel joint
        exists and turns, put a velocity servo on each (bounded by ``<max_wheel_torque>``), and declare the
        command topic, odometry, wheel joint states and TF as the block asks. Frames get the entity's frame
        prefix, so robots in two namespaces publish ``r1/odom`` and ``r2/odom``."""
        self.log = ctx.logger
        self.config = c = parse_config(ctx, self.log)
        self._entity = ctx.entity.name

        self.prefix = entity_frame_prefix(ctx.entity, self.log)
        model = ctx.entity.model
        joint_names = {j.name for j in model.joints}
        if len(c.left_joints) != c.num_wheel_pairs or len(c.right_joints) != c.num_wheel_pairs:
            self.log.error("Inconsistent number of joints specified. Plugin will not work.")
            return
        ok = True
        for jn in (*c.left_joints, *c.right_joints):
            if jn not in joint_names:
                self.log.error(f"Joint [{jn}] not found, plugin will not work. {joints_listing(model)}")
                ok = False
            elif model.joint(jn).type.value == "fixed":
                self.log.error(
                    f"Joint [{jn}] is fixed: a wheel needs a continuous or revolute joint; plugin will not work."
                )
                ok = False
        if not ok:
            return
        hint = wheel_direction_hint(model, tuple(c.left_joints), tuple(c.right_joints))
        if hint is not None:
            self.log.warning(hint)
        for i in range(c.num_wheel_pairs):
            self.log.info(f"Wheel pair {i + 1} separation set to [{c.wheel_separation[i]:f}m]")
            self.log.info(f"Wheel pair {i + 1} diameter set to [{c.wheel_diameter[i]:f}m]")
        # joint order as the classic plugin: [right0, left0, right1, left1, ...]
        if c.legacy_mode:
            self.log.warning("<legacyMode> is true: the left and right wheel speeds are swapped, as in ROS 1")
        swap = -1 if c.legacy_mode else 1
        for i in range(c.num_wheel_pairs):
            for side, jn in ((1, c.right_joints[i]), (-1, c.left_joints[i])):
                servo = add_wheel_servo(ctx.world, ctx.entity, jn, c.max_wheel_torque)
                self._wheels.append(_Wheel(jn, servo, c.wheel_diameter[i] / 2.0, side * swap, c.wheel_separation[i]))
        self._root = ctx.world.body(self._entity)
        self._wheel_links = []
        for w in self._wheels:
            j = model.joint(w.joint)
            parent, child = ctx.world.body(self._entity, j.parent), ctx.world.body(self._entity, j.child)
            self._wheel_links.append((parent, child, self.prefix + j.parent, self.prefix + j.child))
        remaps = dict(c.remappings)
        cmd_topic = resolve_topic(c.command_topic, c.namespace, remaps)
        self._cmd_sub = ctx.bus.subscribe(self._entity, cmd_topic, MsgType.TWIST, self._on_cmd, depth=1)
        self.log.info(f"Subscribed to [{cmd_topic}]")
        if c.publish_odom:
            odom_topic = resolve_topic(c.odometry_topic, c.namespace, remaps)
            self._odom_pub = ctx.bus.advertise(self._entity, odom_topic, MsgType.ODOMETRY, depth=1)
            self.log.info(f"Advertise odometry on [{odom_topic}]")
        if c.publish_wheel_joint_state:
            js_topic = resolve_topic("joint_states", c.namespace, remaps)
            self._js_pub = ctx.bus.advertise(self._entity, js_topic, MsgType.JOINT_STATE, depth=1000)
        if c.publish_odom_tf or c.publish_wheel_tf:
            self._tf_pub = ctx.bus.advertise(self._entity, "/tf", MsgType.TF, depth=100)
        if c.publish_odom_tf:
            self.log.info(
                f"Publishing odom transforms between [{self.prefix}{c.odometry_frame}] and "
                f"[{self.prefix}{c.robot_base_frame}]"
            )
        if c.publish_wheel_tf:
            self.log.info(
                f"Publishing wheel transforms between [{c.robot_base_frame}], [{c.left_joints[0]}] and "
                f"[{c.right_joints[0]}]"
            )
        self._ok = True

    def _on_cmd(self, twist: Twist) -> None:
        self._cmd = twist  # one reference assignment: safe from the bridge thread

    def command(self, linear_x: float, angular_z: float) -> None:
        """Set the commanded body velocity directly (as a ``cmd_vel`` message would)."""
        self._cmd = Twist((linear_x, 0.0, 0.0), (0.0, 0.0, angular_z))

    # ------------------------------------------------------------------ stepping
    def next_update(self, sim_time_sec: float) -> float:
        """Commands and odometry at ``update_rate``; between them the wheel servos run inside MuJoCo."""
        period = 1.0 / self.config.update_rate if self.config.update_rate > 0 else 0.0
        return self._last_update + period if self._ok and math.isfinite(self._last_update) else sim_time_sec

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After a world reset: no command, the update timer and the encoder odometry back to their start, the
        servos' integrals cleared."""
        self._cmd = Twist()
        self._last_update = -math.inf
        self._due = False
        self._enc_pose = (0.0, 0.0, 0.0)
        self._enc_twist = (0.0, 0.0)
        self._enc_last = None
        for w in self._wheels:
            w.instructed = 0.0
            w.servo.reset()

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At ``<update_rate>``: each wheel's rim speed ``v ± ω·s/2`` (the pair's separation), ramped toward its
        target by ``<max_wheel_acceleration>`` when one is given (as the classic plugin, which skips ramps under
        0.01 m/s), then over the wheel's radius to the servo."""
        if not self._ok or info.paused:
            return
        c = self.config
        period = 1.0 / c.update_rate if c.update_rate > 0 else 0.0
        if info.sim_time_sec - self._last_update + 1e-12 < period:
            return
        dt = info.sim_time_sec - self._last_update if math.isfinite(self._last_update) else period
        self._last_update = info.sim_time_sec
        self._due = True
        v, wz = self._cmd.linear[0], self._cmd.angular[2]
        for w in self._wheels:
            target = v + w.side * wz * w.separation / 2.0
            if c.max_wheel_acceleration > 0 and abs(target - w.instructed) >= 0.01:
                step = c.max_wheel_acceleration * max(dt, info.dt_sec)
                delta = max(-step, min(step, target - w.instructed))
                w.instructed += delta
            else:
                w.instructed = target
            w.servo.update(w.instructed / w.radius, info.sim_time_sec)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After the steps that followed an update: the wheel joint states, then odometry and TF
        (``<odometry_source>`` 1, world: the base link's true pose; 0, encoder: integrated from the wheels),
        while anyone listens. The pose covariance is the classic plugin's: ``<covariance_x>``, ``_y``, ``_yaw``
        and 1e12 (unknown) for z, roll and pitch."""
        if not self._ok or info.paused or not self._due:
            return  # odometry goes out after the steps that followed a command update
        self._due = False
        c = self.config
        if c.odometry_source == ODOM_ENCODER:
            self._integrate_encoders(info.sim_time_sec)
        stamp = info.sim_time_sec
        if self._js_pub is not None and self._js_pub.wanted:
            joints = [w.servo.actuator.joint for w in self._wheels]
            self._js_pub.publish(
                JointStates(
                    stamp,
                    tuple(w.joint for w in self._wheels),
                    tuple(j.position for j in joints),
                    tuple(j.velocity for j in joints),
                )
            )
        odom_pub = self._odom_pub if self._odom_pub is not None and self._odom_pub.wanted else None
        tf_pub = self._tf_pub if self._tf_pub is not None and self._tf_pub.wanted else None
        if odom_pub is None and tf_pub is None:
            return  # nobody listens: nothing to build
        pose, twist = self._odometry(world)
        if odom_pub is not None:
            cov = [0.0] * 36
            cov[0], cov[7], cov[14], cov[21], cov[28], cov[35] = (
                c.covariance_x,
                c.covariance_y,
                1e12,
                1e12,
                1e12,
                c.covariance_yaw,
            )
            odom_pub.publish(
                Odometry(
                    stamp,
                    self.prefix + c.odometry_frame,
                    self.prefix + c.robot_base_frame,
                    pose,
                    twist,
                    tuple(cov),
                    tuple(cov),
                )
            )
        if tf_pub is not None:
            tfs: list[Transform] = []
            if c.publish_odom_tf:
                tfs.append(Transform(stamp, self.prefix + c.odometry_frame, self.prefix + c.robot_base_frame, pose))
            if c.publish_wheel_tf:
                tfs.extend(self._wheel_transforms(stamp, world))
            if tfs:
                tf_pub.publish(TransformBatch(tuple(tfs)))

    def _odometry(self, world: PhysicsWorld) -> tuple[Pose, Twist]:
        """The odometry's pose and twist: from the encoders, or the base link's world pose with its velocity turned
        into the base frame (forward and sideways speed, yaw rate)."""
        if self.config.odometry_source == ODOM_ENCODER:
            x, y, th = self._enc_pose
            return Pose((x, y, 0.0), quat_from_rpy(0.0, 0.0, th)), Twist(
                (self._enc_twist[0], 0.0, 0.0), (0.0, 0.0, self._enc_twist[1])
            )
        assert self._root is not None
        pose = self._root.pose
        (vx, vy, _), angular = self._root.velocity
        yaw = pose.rpy[2]
        cy, sy = math.cos(yaw), math.sin(yaw)
        twist = Twist((cy * vx + sy * vy, cy * vy - sy * vx, 0.0), (0.0, 0.0, angular[2]))
        return pose, twist

    def _integrate_encoders(self, sim_time_sec: float) -> None:
        """Siegwart 2011, as the classic plugin's encoder odometry (pair 0 only): the wheels' travel
        since the last update.

        gazebo_ros_diff_drive.cpp (ROS 2 branch, ``UpdateOdometryEncoder``) integrates every physics step,
        from each wheel's velocity times the step (pair 0's radius for both wheels); here it runs once per
        update, from each wheel's change of angle, which keeps Python out of the steps between. The
        distance travelled is then exact where the velocity sum approximates it; the heading's arc step
        (Siegwart's midpoint) is taken over the update instead of a step. Kept as upstream: the reported
        linear speed is the length of the step over its time, never negative, even driving backwards."""
        if len(self._wheels) < 2:
            return
        right, left = self._wheels[0], self._wheels[1]
        qr, ql = right.servo.actuator.joint.position, left.servo.actuator.joint.position
        last, self._enc_last = self._enc_last, (sim_time_sec, qr, ql)
        if last is None:
            return
        t0, qr0, ql0 = last
        dt = sim_time_sec - t0
        sr, sl = (qr - qr0) * right.radius, (ql - ql0) * left.radius
        b = right.separation
        x, y, th = self._enc_pose
        ssum, sdiff = sl + sr, sr - sl
        dx = ssum / 2.0 * math.cos(th + sdiff / (2.0 * b))
        dy = ssum / 2.0 * math.sin(th + sdiff / (2.0 * b))
        dth = sdiff / b
        self._enc_pose = (x + dx, y + dy, th + dth)
        self._enc_twist = (math.hypot(dx, dy) / dt if dt > 0 else 0.0, dth / dt if dt > 0 else 0.0)

    def _wheel_transforms(self, stamp: float, world: PhysicsWorld) -> list[Transform]:
        """The wheels' transforms (parent link -> wheel link) as ``<publish_wheel_tf>`` asks: the two links' true
        poses in the world, taken relative."""
        out: list[Transform] = []
        for parent, child, parent_frame, child_frame in self._wheel_links:
            out.append(Transform(stamp, parent_frame, child_frame, parent.pose.inverse() * child.pose))
        return out


def joint_axis_in_root(model: Model, joint_name: str) -> tuple[float, float, float]:
    """The axis of ``joint_name`` in the model's root link frame, with every joint at zero."""
    by_child = {j.child: j for j in model.joints}
    joint = model.joint(joint_name)
    axis = joint.axis.xyz if joint.axis is not None else (1.0, 0.0, 0.0)
    v = quat_rotate(joint.origin.orientation, axis)  # joint frame -> parent link frame
    link = joint.parent
    seen: set[str] = set()
    while link in by_child and link not in seen:  # up the tree to the root
        seen.add(link)
        up = by_child[link]
        X_PC = up.origin * up.child_offset
        v = quat_rotate(X_PC.orientation, v)
        link = up.parent
    return v


def wheel_direction_hint(model: Model, left: tuple[str, ...], right: tuple[str, ...]) -> str | None:
    """Why a positive ``cmd_vel`` would not drive this robot forward, or None when it does.

    Gazebo (and gazelle) turn each wheel joint at ``v/r`` about its own axis, so a wheel rolls the
    robot forward (+x of its root link) only when that axis points to the robot's left (+y). The
    seed blog's robot rotates its wheel joints by +pi/2 about x, so its axes point right and it
    drives backwards and turns clockwise.
    """
    try:
        lefts = [joint_axis_in_root(model, j)[1] for j in left]
        rights = [joint_axis_in_root(model, j)[1] for j in right]
    except KeyError:
        return None
    eps = 1e-6
    if any(abs(a) < eps for a in (*lefts, *rights)):
        return (
            "a wheel joint's axis has no left/right (y) component in the robot frame: that wheel cannot roll it forward"
        )
    back_l, back_r = all(a < 0 for a in lefts), all(a < 0 for a in rights)
    if back_l and back_r:
        return (
            "a positive cmd_vel drives this robot backwards and turns it clockwise: its wheel joint axes point to "
            'the robot\'s right (-y); Gazebo does the same. Flip them (axis xyz="0 0 -1", or turn the wheel '
            "joints by -pi/2 about x instead of +pi/2)"
        )
    if back_l != back_r:
        return (
            "the left and right wheel joint axes point opposite ways: a positive cmd_vel spins this robot in place "
            "instead of driving it; give both axes the robot's +y direction"
        )
    return None


def joints_listing(model: Model) -> str:
    """``The model's joints: a (continuous), b (fixed)`` for messages about a joint that is not there."""
    names = ", ".join(f"{j.name} ({j.type.value})" for j in model.joints) or "none"
    return f"The model's joints: {names}."


add_plugin(DiffDrive)

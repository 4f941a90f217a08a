"""Joint position and velocity controllers: gz-sim's JointPositionController and JointController,
and classic-style per-joint command topics (``gazelle_joint_commands``).

All take std_msgs/Float64 commands and drive the joint with a MuJoCo actuator, so the
stiff part of each loop is integrated implicitly:

* position (PID): a MuJoCo position servo with ``kp = p_gain``, ``kv = d_gain`` plus the
  integral term (``i_gain``, clamped to ``[i_min, i_max]``) added as a force offset; the
  force is clamped to ``[cmd_min, cmd_max]`` and to the joint's ``<limit><effort>``;
* velocity: the wheels' velocity servo (:mod:`._actuation`: ``kv = I/dt`` plus an integral
  term), as gz-sim's joint velocity command; with ``use_force_commands`` a PI velocity loop
  with ``kv = p_gain`` instead.

Commands arrive on a bridge thread and are applied at the next update (:data:`CONTROL_RATE_HZ`).
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

from ..description import ConfigElement, JointType
from ..physics import PhysicsWorld
from ._actuation import PidGains, PositionServo, VelocityServo, add_position_servo, add_velocity_servo
from ._base import RateGate, System, SystemContext, UpdateInfo
from ._bus import MsgType, resolve_topic
from ._payloads import Float64
from ._plugin_config import all_texts, child_text, parse_bool, parse_float, ros_block
from ._registration import add_plugin

_MOVABLE = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)

CONTROL_RATE_HZ = 100.0
"""How often (sim time) the controllers take new commands and update their servos' integral terms;
between updates the servos run inside MuJoCo. (``use_velocity_commands`` runs every step.)"""


def _check_joint(ctx: SystemContext, joint: str, log: logging.Logger) -> bool:
    """Whether ``joint`` exists and moves (revolute, continuous or prismatic); else an error naming it, and that
    joint is left out."""
    try:
        j = ctx.entity.model.joint(joint)
    except KeyError:
        log.error(f"Joint [{joint}] not found in model [{ctx.entity.name}]; the controller will not work")
        return False
    if j.type not in _MOVABLE:
        log.error(
            f"Joint [{joint}] is {j.type.name.lower()}; "
            "only revolute, continuous and prismatic joints can be controlled"
        )
        return False
    return True


class _Command:
    """One joint's command: a target set from any thread (one float assignment), applied by its servo."""

    every_step = False
    """Whether the control law needs Python every physics step."""

    def __init__(self, joint: str, servo: PositionServo | VelocityServo, target: float) -> None:
        """A joint's servo and its target, starting at ``target`` (restored on a world reset)."""
        self.joint = joint
        self.servo = servo
        self.target = target
        self.initial = target

    def command(self, value: float) -> None:
        """Set the target (rad, m, rad/s or m/s by the servo's kind); non-finite values are ignored."""
        if math.isfinite(value):
            self.target = value

    def on_msg(self, msg: Float64) -> None:
        """A std_msgs/Float64 on the command topic (any thread)."""
        self.command(msg.data)

    def update(self, sim_time_sec: float, dt_sec: float) -> None:
        """Apply the target to the servo at ``sim_time_sec`` (the simulation thread)."""
        self.servo.update(self.target, sim_time_sec)

    def reset(self) -> None:
        """Back to the initial target, integral forgotten."""
        self.target = self.initial
        self.servo.reset()


class _StepVelocityToPosition(_Command):
    """gz-sim ``use_velocity_commands``: a velocity servo commanded with (target − q)/dt, clamped, every step."""

    every_step = True

    def __init__(self, joint: str, servo: VelocityServo, target: float, max_speed: float) -> None:
        super().__init__(joint, servo, target)
        self.vel = servo
        self.max_speed = max_speed

    def update(self, sim_time_sec: float, dt_sec: float) -> None:
        """Apply the target to the servo at ``sim_time_sec`` (the simulation thread)."""
        v = (self.target - self.vel.actuator.joint.position) / dt_sec
        self.vel.update(max(-self.max_speed, min(self.max_speed, v)), sim_time_sec)


class _Controlled(System):
    """Joints following commands: they update at :data:`CONTROL_RATE_HZ` (every step if one needs it)."""

    def __init__(self) -> None:
        self._commands: list[_Command] = []
        self._gate = RateGate()

    def next_update(self, sim_time_sec: float) -> float:
        """The next :data:`CONTROL_RATE_HZ` period, or every step when a joint's law needs it."""
        if not self._commands:
            return math.inf
        if any(c.every_step for c in self._commands):
            return sim_time_sec
        return self._gate.next

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Back to the initial target, integral forgotten."""
        self._gate.reset()
        for c in self._commands:
            c.reset()

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Apply the latest commands to the servos, when due."""
        if info.paused or not self._commands:
            return
        every_step = any(c.every_step for c in self._commands)
        if not self._gate.due(info.sim_time_sec, 0.0 if every_step else CONTROL_RATE_HZ):
            return
        for c in self._commands:
            c.update(info.sim_time_sec, info.dt_sec)


# --------------------------------------------------------------------------- gz-sim
class _ServoGroup(_Controlled):
    """Systems whose joints all follow one Float64 command (position or velocity, by servo kind)."""

    def __init__(self) -> None:
        super().__init__()
        self.topic = ""

    @property
    def servos(self) -> list[_Command]:
        """The joints' commands, in ``<joint_name>`` order."""
        return self._commands

    @staticmethod
    def _joints(ctx: SystemContext, names: tuple[str, ...], system: str) -> list[str]:
        """The ``<joint_name>``s that exist and can be driven (gz-sim's errors for the others)."""
        if not names:
            ctx.logger.error(f"{system} found an empty jointName parameter. Failed to initialize.")
            return []
        return [jn for jn in names if _check_joint(ctx, jn, ctx.logger)]

    def _subscribe(self, ctx: SystemContext, system: str, topic: str, sub_topic: str, default: str) -> None:
        """Follow Float64 commands on ``topic``, else ``/model/<model>/<sub_topic>``, else on ``<default>`` there."""
        model = ctx.entity.name
        self.topic = resolve_topic(topic or f"/model/{model}/{sub_topic or default}", ctx.entity.namespace)
        ctx.bus.subscribe(model, self.topic, MsgType.FLOAT64, self._on_msg, depth=10)
        ctx.logger.info(f"{system} subscribing to Double messages on [{self.topic}]")

    def _on_msg(self, msg: Float64) -> None:
        for c in self._commands:
            c.command(msg.data)

    def command(self, value: float) -> None:
        """Set the target directly, as a message on the command topic would."""
        self._on_msg(Float64(value))


def _pid(cfg: ConfigElement | None, log: logging.Logger, defaults: PidGains) -> PidGains:
    """The PID gains a gz-sim joint controller reads (``<p_gain>``, ``<i_gain>``, ``<d_gain>``, ``<i_max>``,
    ``<i_min>``, ``<cmd_max>``, ``<cmd_min>``, ``<cmd_offset>``), each defaulting to the controller's own
    default when absent; a value that is not a number is warned about and the default used."""
    vals = {k: parse_float(cfg, k, getattr(defaults, k), log) for k in PidGains.__dataclass_fields__}
    return PidGains(**vals)


@dataclass(frozen=True)
class JointPositionControllerConfig:
    """gz-sim ``JointPositionController`` parameters (defaults as gz-sim 8)."""

    joint_names: tuple[str, ...] = ()
    """``<joint_name>`` (repeatable; all follow one command). Required."""
    joint_index: int = 0
    """``<joint_index>``: axis of a multi-axis joint (only 0 is supported)."""
    topic: str = ""
    """``<topic>`` (std_msgs/Float64); default ``/model/<model>/joint/<joint>/<index>/cmd_pos``.

    Relative names go under the namespace."""
    sub_topic: str = ""
    """``<sub_topic>``: ``/model/<model>/<sub_topic>`` instead of the default topic."""
    gains: PidGains = PidGains()
    """``<p_gain>`` ... ``<cmd_offset>``: the position servo's PID (gz-sim 8's defaults). ``p_gain`` is MuJoCo's
    kp (N·m/rad or N/m), ``d_gain`` its kv (integrated implicitly), ``cmd_max``/``cmd_min`` bound the force (and
    so does the joint's ``<limit><effort>``)."""
    use_velocity_commands: bool = False
    """``<use_velocity_commands>``: a velocity servo at (target − q)/dt, capped at ``<cmd_max>`` when written and
    at the joint's velocity limit."""
    initial_position: float = 0.0
    """``<initial_position>``: target before the first command."""


class JointPositionController(_ServoGroup):
    """gz-sim JointPositionController (``gz-sim-joint-position-controller-system``)."""

    gz_plugin = "JointPositionController"

    def __init__(self) -> None:
        super().__init__()
        self.config = JointPositionControllerConfig()

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block, check the joints, add a servo per joint and subscribe to the command topic.

        As gz-sim 8's JointPositionController.cc ``Configure``: every ``<joint_name>`` follows the one
        command; the topic is ``<topic>``, else ``/model/<model>/<sub_topic>``, else
        ``/model/<model>/joint/<first joint>/<joint_index>/cmd_pos``; the target starts at
        ``<initial_position>``. gz's PID computes a joint force each step from the position error; here
        the same gains drive MuJoCo's position servo (kp, kv integrated implicitly: stable at any gain), and
        ``<use_velocity_commands>`` sets the joint's velocity to reach the target in one step instead, as
        gz's velocity mode does (capped at ``<cmd_max>`` in rad/s or m/s when one is written, and at the
        joint's velocity limit). ``<use_actuator_msg>`` (gz's Actuators topic) is not read, and warned."""
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        names = all_texts(cfg, "joint_name")
        g = _pid(cfg, log, JointPositionControllerConfig.gains)
        self.config = c = JointPositionControllerConfig(
            joint_names=names,
            joint_index=int(parse_float(cfg, "joint_index", 0, log)),
            topic=child_text(cfg, "topic") or "",
            sub_topic=child_text(cfg, "sub_topic") or "",
            use_velocity_commands=parse_bool(cfg, "use_velocity_commands", False, log),
            initial_position=parse_float(cfg, "initial_position", 0.0, log),
            gains=g,
        )
        if names and c.joint_index != 0:
            log.warning(f"<joint_index> {c.joint_index}: only axis 0 is supported; using 0")
        joints = self._joints(ctx, names, "JointPositionController")
        if not joints:
            return
        # velocity mode's speed cap: gz's PreUpdate caps (target - q)/dt at |cmd_max| when <cmd_max> is written
        # (isMaxSet). The joint's <limit><velocity> caps it too: gz's physics engines keep a velocity command
        # within the joint's limits (DART's servo joints, not checked here in their source), and uncapped, a
        # force-limited servo commanded (target - q)/dt rings about the target (measured: -1.51 rad for -0.8)
        written_max = abs(g.cmd_max) if cfg is not None and cfg.find("cmd_max") is not None else math.inf
        for jn in joints:
            if c.use_velocity_commands:
                j = ctx.entity.model.joint(jn)
                limit = j.axis.limit.velocity if j.axis is not None and j.axis.limit.velocity else math.inf
                vmax = min(written_max, limit if limit > 0 else math.inf)
                vel = add_velocity_servo(ctx.world, ctx.entity, jn)
                self._commands.append(_StepVelocityToPosition(jn, vel, c.initial_position, vmax))
            else:
                self._commands.append(
                    _Command(jn, add_position_servo(ctx.world, ctx.entity, jn, g), c.initial_position)
                )
        self._subscribe(
            ctx, "JointPositionController", c.topic, c.sub_topic, f"joint/{joints[0]}/{c.joint_index}/cmd_pos"
        )


@dataclass(frozen=True)
class JointControllerConfig:
    """gz-sim ``JointController`` (velocity) parameters (defaults as gz-sim 8)."""

    joint_names: tuple[str, ...] = ()
    """``<joint_name>`` (repeatable). Required."""
    topic: str = ""
    """``<topic>`` (std_msgs/Float64, rad/s or m/s); default ``/model/<model>/joint/<joint>/cmd_vel``."""
    sub_topic: str = ""
    """``<sub_topic>``: ``/model/<model>/<sub_topic>`` instead."""
    initial_velocity: float = 0.0
    """``<initial_velocity>``."""
    use_force_commands: bool = False
    """``<use_force_commands>``: a PI velocity loop with the gains below instead of gz's velocity command."""
    gains: PidGains = PidGains(p_gain=1.0, i_gain=0.0, d_gain=0.0)
    """``<p_gain>`` ... ``<cmd_offset>``, read in force mode only: ``p_gain`` is the velocity servo's kv and
    ``cmd_max``/``cmd_min`` bound its force (so does ``<limit><effort>``); ``i_gain`` and ``d_gain`` are not used."""


class JointController(_ServoGroup):
    """gz-sim JointController (``gz-sim-joint-controller-system``): joint velocity from std_msgs/Float64."""

    gz_plugin = "JointController"

    def __init__(self) -> None:
        super().__init__()
        self.config = JointControllerConfig()

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block, check the joints, add a servo per joint and subscribe to the command topic.

        As gz-sim 8's JointController.cc: the command (rad/s or m/s) goes on ``<topic>``, else
        ``/model/<model>/<sub_topic>``, else ``/model/<model>/joint/<first joint>/cmd_vel``, starting at
        ``<initial_velocity>``. gz sets the joint's velocity command, which its physics meets exactly;
        here a stiff velocity servo does the same within the joint's effort limit. With
        ``<use_force_commands>`` gz runs a PID on the velocity error: here ``p_gain`` is the servo's kv and
        ``cmd_max``/``cmd_min`` bound its force (its ``i_gain`` and ``d_gain`` are not used)."""
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        names = all_texts(cfg, "joint_name")
        g = _pid(cfg, log, JointControllerConfig.gains)
        self.config = c = JointControllerConfig(
            joint_names=names,
            topic=child_text(cfg, "topic") or "",
            sub_topic=child_text(cfg, "sub_topic") or "",
            initial_velocity=parse_float(cfg, "initial_velocity", 0.0, log),
            use_force_commands=parse_bool(cfg, "use_force_commands", False, log),
            gains=g,
        )
        joints = self._joints(ctx, names, "JointController")
        if not joints:
            return
        for jn in joints:
            if c.use_force_commands:
                limit = max(abs(g.cmd_min), abs(g.cmd_max))
                servo = add_velocity_servo(ctx.world, ctx.entity, jn, kv=max(g.p_gain, 1e-9), force_limit=limit)
            else:
                servo = add_velocity_servo(ctx.world, ctx.entity, jn)
            self._commands.append(_Command(jn, servo, c.initial_velocity))
        self._subscribe(ctx, "JointController", c.topic, c.sub_topic, f"joint/{joints[0]}/cmd_vel")


# --------------------------------------------------------------------------- classic-style topics
JOINT_COMMANDS_PLUGIN = "gazelle_joint_commands"


@dataclass(frozen=True)
class JointCommandsConfig:
    """``<plugin filename="gazelle_joint_commands">``: per-joint command topics in the gazebo_ros style.

    Each ``<joint_name>`` gets ``<ns>/<joint>/cmd_pos`` (position mode) or ``<ns>/<joint>/cmd_vel``
    (velocity mode), std_msgs/Float64, with ``<ros><namespace>`` / ``<remapping>`` as gazebo_ros plugins.
    """

    joint_names: tuple[str, ...] = ()
    """``<joint_name>`` (repeatable). Default: every revolute, continuous and prismatic joint."""
    mode: str = "position"
    """``<mode>``: ``position`` or ``velocity``."""
    gains: PidGains = PidGains(p_gain=100.0, i_gain=0.0, d_gain=10.0, cmd_max=math.inf, cmd_min=-math.inf)
    """``<p_gain>``, ``<i_gain>``, ``<d_gain>``, ``<i_max>``, ``<i_min>`` (position mode): the position servo's kp
    (N·m/rad), integral and kv; the force is bounded by the joint's ``<limit><effort>`` alone."""
    namespace: str = ""
    """``<ros><namespace>``; default the entity's namespace."""
    remappings: tuple[tuple[str, str], ...] = ()


class JointCommands(_Controlled):
    """Classic-style position or velocity command topics, one per joint, effort-limited by ``<limit><effort>``."""

    plugin_files = ("gazelle_joint_commands",)

    def __init__(self) -> None:
        """An unconfigured JointCommands (see :meth:`configure`)."""
        super().__init__()
        self.config = JointCommandsConfig()
        self.servos: dict[str, _Command] = {}
        """Joint name -> its command."""
        self.topics: dict[str, str] = {}
        """Joint name -> its command topic."""

    def configure(self, ctx: SystemContext) -> None:
        """Read the plugin block, check the joints, add a servo per joint and subscribe to its command topic:
        ``<ns>/<joint>/cmd_pos`` or ``cmd_vel`` (std_msgs/Float64), every movable joint when no
        ``<joint_name>`` is given. gazelle's own plugin: gazebo_ros has none for bare joint commands in
        ROS 2."""
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        d = JointCommandsConfig()
        names = all_texts(cfg, "joint_name")
        if not names:
            names = tuple(j.name for j in ctx.entity.model.joints if j.type in _MOVABLE)
        ns, remaps = ros_block(cfg)
        mode = (child_text(cfg, "mode") or d.mode).lower()
        if mode not in ("position", "velocity"):
            log.warning(f"<mode> must be position or velocity, got {mode!r}; using position")
            mode = "position"
        g = _pid(cfg, log, d.gains)
        self.config = c = JointCommandsConfig(names, mode, g, ns or ctx.entity.namespace, tuple(remaps.items()))
        for jn in names:
            if not _check_joint(ctx, jn, log):
                continue
            servo: PositionServo | VelocityServo
            if mode == "position":
                servo, suffix = add_position_servo(ctx.world, ctx.entity, jn, g), "cmd_pos"
            else:
                servo, suffix = add_velocity_servo(ctx.world, ctx.entity, jn), "cmd_vel"
            cmd = _Command(jn, servo, 0.0)
            topic = resolve_topic(f"{jn}/{suffix}", c.namespace, dict(c.remappings))
            ctx.bus.subscribe(ctx.entity.name, topic, MsgType.FLOAT64, cmd.on_msg, depth=10)
            self._commands.append(cmd)
            self.servos[jn] = cmd
            self.topics[jn] = topic
            log.info(f"Joint [{jn}] {mode} commands on [{topic}]")

    def command(self, joint: str, value: float) -> None:
        """Set one joint's target directly, as a message on its topic would."""
        self.servos[joint].command(value)


add_plugin(JointPositionController)
add_plugin(JointController)
add_plugin(JointCommands)

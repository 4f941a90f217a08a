"""Joint position and velocity controllers: gz-sim's JointPositionController and JointController,
and classic-style per-joint command topics (``gazelle_joint_commands``).

All take std_msgs/Float64 commands and drive the joint with a MuJoCo actuator, so the
stiff part of each loop is integrated implicitly:

* position (PID): a MuJoCo position servo with ``kp = p_gain``, ``kv = d_gain`` plus the
  integral term (``i_gain``, clamped to ``[i_min, i_max]``) added as a force offset; the
  force is clamped to ``[cmd_min, cmd_max]`` and to the joint's ``<limit><effort>``;
* velocity: the wheel velocity servo of :mod:`.diff_drive` (``kv = I/dt`` plus an integral
  term), as gz-sim's joint velocity command; with ``use_force_commands`` a PI velocity loop
  with ``kv = p_gain`` instead.

Commands arrive on a bridge thread and are applied at the next step's ``pre_update``.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import mujoco

from ..description import ConfigElement, JointType
from ..physics._builder import scoped
from ._base import PerGeneration, all_texts, System, SystemContext, UpdateInfo, child_text, parse_bool, parse_float, ros_block
from ._bus import Float64, MsgType, resolve_topic
from .diff_drive import INTEGRAL_TIME_SEC, UNLIMITED_INTEGRAL, servo_gain, wheel_inertia_about_axis

if TYPE_CHECKING:  # pragma: no cover
    from ..physics._world import PhysicsWorld

_MOVABLE = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


def _effort_limit(ctx: SystemContext, joint: str) -> float:
    j = ctx.entity.model.joint(joint)
    eff = j.axis.limit.effort if j.axis is not None else None
    return eff if eff is not None and eff > 0 else math.inf


def _force_range(act: mujoco.MjsActuator, lo: float, hi: float) -> None:
    if math.isfinite(lo) or math.isfinite(hi):
        act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
        act.forcerange = [max(lo, -1e30), min(hi, 1e30)]


def _check_joint(ctx: SystemContext, joint: str, log: logging.Logger) -> bool:
    try:
        j = ctx.entity.model.joint(joint)
    except KeyError:
        log.error(f"Joint [{joint}] not found in model [{ctx.entity.name}]; the controller will not work")
        return False
    if j.type not in _MOVABLE:
        log.error(f"Joint [{joint}] is {j.type.name.lower()}; only revolute, continuous and prismatic joints can be controlled")
        return False
    return True


class _Servo:
    """One joint driven by one MuJoCo actuator; ``command`` is thread-safe (one float assignment)."""

    def __init__(self, entity: str, joint: str, actuator: str, target: float) -> None:
        self.entity, self.joint, self.actuator = entity, joint, actuator
        self.target = target
        self.initial = target
        self.integral = 0.0
        self._addr = PerGeneration(lambda w: (*w.joint_address(self.entity, self.joint), w.actuator_id(self.actuator)))

    def command(self, value: float) -> None:
        if math.isfinite(value):
            self.target = value

    def on_msg(self, msg: Float64) -> None:
        self.command(msg.data)

    def addresses(self, world: "PhysicsWorld") -> tuple[int, int, int]:
        """(qpos address, dof address, actuator id)."""
        return self._addr.get(world)

    def reset(self) -> None:
        self.target = self.initial
        self.integral = 0.0


class _PositionServo(_Servo):
    """PID on position: MuJoCo position actuator (kp, kv) plus the integral force."""

    def __init__(self, ctx: SystemContext, joint: str, gains: "PidGains", target: float) -> None:
        self.gains = g = gains
        name = scoped(ctx.entity.name, f"{joint}#pos")
        act = ctx.world.spec.add_actuator(name=name, target=scoped(ctx.entity.name, joint), trntype=mujoco.mjtTrn.mjTRN_JOINT)
        act.set_to_position(kp=max(g.p_gain, 1e-9), kv=max(g.d_gain, 0.0))
        eff = _effort_limit(ctx, joint)
        _force_range(act, max(g.cmd_min, -eff), min(g.cmd_max, eff))
        super().__init__(ctx.entity.name, joint, name, target)

    def step(self, world: "PhysicsWorld", dt: float) -> None:
        qadr, _, aid = self.addresses(world)
        g = self.gains
        err = self.target - float(world.data.qpos[qadr])
        self.integral = min(max(self.integral + g.i_gain * err * dt, g.i_min), g.i_max)
        # force = kp (ctrl - q) - kv qdot, so the integral force shifts ctrl by integral/kp
        kp = max(g.p_gain, 1e-9)
        world.data.ctrl[aid] = self.target + (g.cmd_offset + self.integral) / kp


class _VelocityServo(_Servo):
    """Velocity loop: servo kv (I/dt, or p_gain) plus an integral term as a velocity offset."""

    def __init__(self, ctx: SystemContext, joint: str, target: float, *, kv: float | None = None, force_limit: float = math.inf) -> None:
        model, world = ctx.entity.model, ctx.world
        arm = world.armature
        if kv is None:
            kv = servo_gain(wheel_inertia_about_axis(model, joint, arm), world.timestep)
        limit = min(force_limit, _effort_limit(ctx, joint))
        act = world.add_velocity_actuator(ctx.entity, joint, kv=kv, force_limit=limit if math.isfinite(limit) else None)
        self.integral_limit = limit / kv if math.isfinite(limit) else UNLIMITED_INTEGRAL
        super().__init__(ctx.entity.name, joint, act, target)

    def step(self, world: "PhysicsWorld", dt: float) -> None:
        _, dadr, aid = self.addresses(world)
        speed = float(world.data.qvel[dadr])
        self.integral += (self.target - speed) * dt / INTEGRAL_TIME_SEC
        self.integral = max(-self.integral_limit, min(self.integral_limit, self.integral))
        world.data.ctrl[aid] = self.target + self.integral


class _StepVelocityToPosition(_Servo):
    """gz-sim ``use_velocity_commands``: a velocity servo commanded with (target - q)/dt, clamped."""

    def __init__(self, ctx: SystemContext, joint: str, target: float, max_speed: float) -> None:
        self.vel = _VelocityServo(ctx, joint, 0.0)
        self.max_speed = max_speed
        super().__init__(ctx.entity.name, joint, self.vel.actuator, target)

    def step(self, world: "PhysicsWorld", dt: float) -> None:
        qadr, _, _ = self.addresses(world)
        v = (self.target - float(world.data.qpos[qadr])) / dt
        self.vel.target = max(-self.max_speed, min(self.max_speed, v))
        self.vel.step(world, dt)

    def reset(self) -> None:
        super().reset()
        self.vel.reset()


# --------------------------------------------------------------------------- gz-sim
class _ServoGroup(System):
    """Systems whose joints all follow one Float64 command (position or velocity, by servo kind)."""

    def __init__(self) -> None:
        self.servos: list[_Servo] = []
        self.topic = ""

    @staticmethod
    def _joints(ctx: SystemContext, names: tuple[str, ...], system: str) -> list[str]:
        """The ``<joint_name>``s that exist and can be driven (gz-sim's errors for the others)."""
        if not names:
            ctx.logger.error(f"{system} found an empty jointName parameter. Failed to initialize.")
            return []
        return [jn for jn in names if _check_joint(ctx, jn, ctx.logger)]

    def _subscribe(self, ctx: SystemContext, system: str, topic: str, sub_topic: str, default: str) -> None:
        """Follow Float64 commands on ``topic``, else ``/model/<model>/<sub_topic>``, else ``/model/<model>/<default>``."""
        model = ctx.entity.name
        self.topic = resolve_topic(topic or f"/model/{model}/{sub_topic or default}", ctx.entity.namespace)
        ctx.bus.subscribe(model, self.topic, MsgType.FLOAT64, self._on_msg, depth=10)
        ctx.logger.info(f"{system} subscribing to Double messages on [{self.topic}]")

    def _on_msg(self, msg: Float64) -> None:
        for s in self.servos:
            s.command(msg.data)

    def command(self, value: float) -> None:
        """Set the target directly, as a message on the command topic would."""
        self._on_msg(Float64(value))

    def reset(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        for s in self.servos:
            s.reset()

    def pre_update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        if info.paused:
            return
        for s in self.servos:
            s.step(world, info.dt_sec)


@dataclass(frozen=True)
class PidGains:
    p_gain: float = 1.0
    i_gain: float = 0.1
    d_gain: float = 0.01
    i_max: float = 1.0
    i_min: float = -1.0
    cmd_max: float = 1000.0
    cmd_min: float = -1000.0
    cmd_offset: float = 0.0


def _pid(cfg: ConfigElement | None, log: logging.Logger, defaults: PidGains) -> PidGains:
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
    """``<topic>`` (std_msgs/Float64); default ``/model/<model>/joint/<joint>/<index>/cmd_pos``; relative names go under the namespace."""
    sub_topic: str = ""
    """``<sub_topic>``: ``/model/<model>/<sub_topic>`` instead of the default topic."""
    p_gain: float = 1.0
    """``<p_gain>``, N·m/rad (N/m); the position servo's kp."""
    i_gain: float = 0.1
    """``<i_gain>``."""
    d_gain: float = 0.01
    """``<d_gain>``; the position servo's kv (integrated implicitly)."""
    i_max: float = 1.0
    """``<i_max>``: upper bound of the integral force."""
    i_min: float = -1.0
    """``<i_min>``."""
    cmd_max: float = 1000.0
    """``<cmd_max>``: force bound (also bounded by the joint's ``<limit><effort>``)."""
    cmd_min: float = -1000.0
    """``<cmd_min>``."""
    cmd_offset: float = 0.0
    """``<cmd_offset>``: constant force added."""
    use_velocity_commands: bool = False
    """``<use_velocity_commands>``: drive with a velocity servo at (target − q)/dt, clamped to the joint's velocity limit."""
    initial_position: float = 0.0
    """``<initial_position>``: target before the first command."""


class JointPositionController(_ServoGroup):
    """gz-sim JointPositionController (``gz-sim-joint-position-controller-system``)."""

    def __init__(self) -> None:
        super().__init__()
        self.config = JointPositionControllerConfig()

    def configure(self, ctx: SystemContext) -> None:
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        names = all_texts(cfg, "joint_name")
        g = _pid(cfg, log, PidGains())
        self.config = c = JointPositionControllerConfig(
            joint_names=names,
            joint_index=int(parse_float(cfg, "joint_index", 0, log)),
            topic=child_text(cfg, "topic") or "",
            sub_topic=child_text(cfg, "sub_topic") or "",
            use_velocity_commands=parse_bool(cfg, "use_velocity_commands", False, log),
            initial_position=parse_float(cfg, "initial_position", 0.0, log),
            **{k: getattr(g, k) for k in PidGains.__dataclass_fields__},
        )
        if names and c.joint_index != 0:
            log.warning(f"<joint_index> {c.joint_index}: only axis 0 is supported; using 0")
        joints = self._joints(ctx, names, "JointPositionController")
        if not joints:
            return
        for jn in joints:
            if c.use_velocity_commands:
                j = ctx.entity.model.joint(jn)
                vmax = j.axis.limit.velocity if j.axis is not None and j.axis.limit.velocity else math.inf
                self.servos.append(_StepVelocityToPosition(ctx, jn, c.initial_position, vmax if vmax > 0 else math.inf))
            else:
                self.servos.append(_PositionServo(ctx, jn, g, c.initial_position))
        self._subscribe(ctx, "JointPositionController", c.topic, c.sub_topic, f"joint/{joints[0]}/{c.joint_index}/cmd_pos")



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
    p_gain: float = 1.0
    """``<p_gain>`` (force mode): the velocity servo's kv."""
    i_gain: float = 0.0
    """``<i_gain>`` (force mode)."""
    d_gain: float = 0.0
    """``<d_gain>`` (force mode; not used)."""
    i_max: float = 1.0
    i_min: float = -1.0
    cmd_max: float = 1000.0
    """``<cmd_max>`` (force mode): force bound (also bounded by ``<limit><effort>``)."""
    cmd_min: float = -1000.0
    cmd_offset: float = 0.0


class JointController(_ServoGroup):
    """gz-sim JointController (``gz-sim-joint-controller-system``): joint velocity from std_msgs/Float64."""

    def __init__(self) -> None:
        super().__init__()
        self.config = JointControllerConfig()

    def configure(self, ctx: SystemContext) -> None:
        log = ctx.logger
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        names = all_texts(cfg, "joint_name")
        g = _pid(cfg, log, PidGains(p_gain=1.0, i_gain=0.0, d_gain=0.0))
        self.config = c = JointControllerConfig(
            joint_names=names,
            topic=child_text(cfg, "topic") or "",
            sub_topic=child_text(cfg, "sub_topic") or "",
            initial_velocity=parse_float(cfg, "initial_velocity", 0.0, log),
            use_force_commands=parse_bool(cfg, "use_force_commands", False, log),
            **{k: getattr(g, k) for k in PidGains.__dataclass_fields__},
        )
        joints = self._joints(ctx, names, "JointController")
        if not joints:
            return
        for jn in joints:
            if c.use_force_commands:
                servo = _VelocityServo(ctx, jn, c.initial_velocity, kv=max(c.p_gain, 1e-9), force_limit=max(abs(c.cmd_min), abs(c.cmd_max)))
            else:
                servo = _VelocityServo(ctx, jn, c.initial_velocity)
            self.servos.append(servo)
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
    p_gain: float = 100.0
    """``<p_gain>`` (position mode), N·m/rad: the position servo's kp."""
    i_gain: float = 0.0
    """``<i_gain>`` (position mode)."""
    d_gain: float = 10.0
    """``<d_gain>`` (position mode): the servo's kv."""
    i_max: float = 1.0
    i_min: float = -1.0
    namespace: str = ""
    """``<ros><namespace>``; default the entity's namespace."""
    remappings: tuple[tuple[str, str], ...] = ()


class JointCommands(System):
    """Classic-style position or velocity command topics, one per joint, effort-limited by ``<limit><effort>``."""

    def __init__(self) -> None:
        self.config = JointCommandsConfig()
        self.servos: dict[str, _Servo] = {}
        self.topics: dict[str, str] = {}

    def configure(self, ctx: SystemContext) -> None:
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
        g = _pid(cfg, log, PidGains(p_gain=d.p_gain, i_gain=d.i_gain, d_gain=d.d_gain, cmd_max=math.inf, cmd_min=-math.inf))
        self.config = c = JointCommandsConfig(
            names, mode, g.p_gain, g.i_gain, g.d_gain, g.i_max, g.i_min, ns or ctx.entity.namespace, tuple(remaps.items())
        )
        for jn in names:
            if not _check_joint(ctx, jn, log):
                continue
            if mode == "position":
                q0 = 0.0
                servo: _Servo = _PositionServo(ctx, jn, g, q0)
                suffix = "cmd_pos"
            else:
                servo = _VelocityServo(ctx, jn, 0.0)
                suffix = "cmd_vel"
            topic = resolve_topic(f"{jn}/{suffix}", c.namespace, dict(c.remappings))
            ctx.bus.subscribe(ctx.entity.name, topic, MsgType.FLOAT64, servo.on_msg, depth=10)
            self.servos[jn] = servo
            self.topics[jn] = topic
            log.info(f"Joint [{jn}] {mode} commands on [{topic}]")

    def command(self, joint: str, value: float) -> None:
        self.servos[joint].command(value)

    def reset(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        for s in self.servos.values():
            s.reset()

    def pre_update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        if info.paused:
            return
        for s in self.servos.values():
            s.step(world, info.dt_sec)

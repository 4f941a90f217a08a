"""Servos: the one place where joint commands become MuJoCo actuators and control laws.

Every plugin that drives a joint (the classic and gz-sim diff drives, the gz-sim joint
controllers, the classic-style command topics, and ros2_control's controllers next) uses
these, on the typed handles of :mod:`gazelle.physics`:

* :class:`VelocityServo`: a MuJoCo velocity actuator, ``kv = I/dt`` (see :func:`servo_gain`)
  and force-limited, plus an integral term. MuJoCo runs the proportional part every step,
  implicitly; the integral term is updated only when the owning system runs, from the joint's
  travel since the last update (∫(target − q̇)dt = target·Δt − Δq, exact whatever the interval),
  so Python is not needed between updates.
* :class:`PositionServo`: a MuJoCo position actuator (``kp``, ``kv``) plus the PID's integral
  force (``i_gain``), also updated when the system runs.

The gains, the wheel armature and the wheel-contact shape are here too, so every drive gets
the same behaviour.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..description import Cylinder, JointType, Model, Pose, Sphere, quat_rotate
from ..physics import ActuatorHandle, ActuatorKind, Entity, PhysicsWorld

WHEEL_ARMATURE = 1e-3
"""Reflected rotor inertia of a wheel's gear motor, kg·m² (a small DC motor through a ~30:1 gearbox).

It lets the speed servo be stiffer (kv grows with the wheel's inertia, see :func:`servo_gain`),
so the wheels follow cmd_vel changes within a few milliseconds as Gazebo's joint motors do."""

INTEGRAL_TIME_SEC = 0.05
"""Integral time of the wheel speed loop."""

UNLIMITED_INTEGRAL = 10.0
"""Anti-windup bound (rad/s) of the integral term of a velocity servo without a torque limit."""


def servo_gain(inertia_about_axis: float, dt_sec: float) -> float:
    """Velocity-servo gain kv (N·m·s/rad) for a wheel.

    ``implicitfast`` integrates an unsaturated velocity servo implicitly, so any kv
    is stable there; but a saturated servo (at ``max_wheel_torque``) is an explicit
    constant torque that changes the wheel speed by ``τ·dt/I`` in one step. If that
    jump is wider than the unsaturated band ``τ/kv`` the wheel chatters between
    ±τ and the robot hops (we measured it: kv=1000 turned 0° instead of 90°).
    ``kv = I/dt`` keeps the band at least one step wide, and since the wheel drags
    the robot's mass along, its effective inertia (and so its tracking) is higher.
    """
    return max(inertia_about_axis, 1e-6) / dt_sec


def wheel_inertia_about_axis(model: Model, joint_name: str, armature: float) -> float:
    """Moment of inertia of a joint's child link about the joint axis, plus the joint armature."""
    j = model.joint(joint_name)
    inertial = model.link(j.child).inertial
    if inertial is None or j.axis is None:
        return armature
    # axis in the child frame, then in the inertial (principal) frame
    X_CJ = j.child_offset.inverse()
    a_c = np.asarray(quat_rotate(X_CJ.orientation, j.axis.xyz))
    q_ci = inertial.pose.orientation
    R_ci = np.column_stack([quat_rotate(q_ci, e) for e in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))])
    a_i = R_ci.T @ a_c
    inertia = np.array(
        [
            [inertial.ixx, inertial.ixy, inertial.ixz],
            [inertial.ixy, inertial.iyy, inertial.iyz],
            [inertial.ixz, inertial.iyz, inertial.izz],
        ]
    )
    com = np.asarray(inertial.pose.position) - np.asarray(X_CJ.position)
    perp = com - a_c * float(com @ a_c)
    return float(a_i @ inertia @ a_i) + inertial.mass * float(perp @ perp) + armature


def joint_effort_limit(model: Model, joint: str) -> float:
    """The joint's ``<limit effort>`` when positive, else infinity."""
    j = model.joint(joint)
    eff = j.axis.limit.effort if j.axis is not None else None
    return eff if eff is not None and eff > 0 else math.inf


class VelocityServo:
    """A joint held at a target velocity: proportional in MuJoCo (every step), integral per update.

    The command is ``target + integral``: the actuator's force is ``kv·(target + integral − q̇)``,
    and the integral term (rad/s) removes the steady-state error under load (scrub, rolling
    resistance), as a constraint motor (Gazebo's "vel" + "fmax") has none. It is bounded by
    ``integral_limit`` (anti-windup: the torque limit over kv).
    """

    __slots__ = ("actuator", "integral_limit", "integral_time", "target", "integral", "_last")

    def __init__(
        self, actuator: ActuatorHandle, integral_limit: float, integral_time: float = INTEGRAL_TIME_SEC
    ) -> None:
        """A velocity servo on ``actuator``, its integral bounded by ``integral_limit`` (rad/s or m/s) and built up
        over ``integral_time``."""
        self.actuator = actuator
        self.integral_limit = integral_limit
        self.integral_time = integral_time
        self.target = 0.0
        """rad/s (m/s) in effect since the last update."""
        self.integral = 0.0
        self._last: tuple[float, float] | None = None
        """(sim time, joint position) at the last update."""

    def update(self, target: float, sim_time_sec: float) -> None:
        """Command ``target`` from now on, after folding the velocity error since the last update into the integral."""
        q = self.actuator.joint.position
        if self._last is not None:
            t0, q0 = self._last
            interval = sim_time_sec - t0
            travel_error = self.target * interval - (q - q0)  # ∫(target − q̇)dt over the interval
            # An update k·error with k = interval/Ti over 1 overshoots (k = 2 oscillates for good): a
            # controller manager at 10 Hz (Husky's) updates every 0.1 s against Ti = 0.05 s. The integral
            # time is at least two intervals, so each update removes at most half the error.
            integral = self.integral + travel_error / max(self.integral_time, 2.0 * interval)
            self.integral = max(-self.integral_limit, min(self.integral_limit, integral))
        self._last = (sim_time_sec, q)
        self.target = target
        self.actuator.command(target + self.integral)

    def reset(self) -> None:
        """Forget the integral and the last position (after a world reset: positions jumped)."""
        self.target = 0.0
        self.integral = 0.0
        self._last = None


@dataclass(frozen=True)
class PidGains:
    """A joint PID as gz-sim's controllers take it (``<p_gain>``, ``<i_gain>``, ... ``<cmd_offset>``)."""

    p_gain: float = 1.0
    """``<p_gain>``: force per unit of position error (N·m/rad or N/m); a position servo's MuJoCo kp."""
    i_gain: float = 0.1
    """``<i_gain>``: force per unit of integrated position error (N·m/(rad·s)); the integral force, bounded
    by ``i_min`` and ``i_max``, shifts the position servo's command (see :class:`PositionServo`)."""
    d_gain: float = 0.01
    """``<d_gain>``: force per unit of velocity (N·m·s/rad); MuJoCo's kv, integrated implicitly."""
    i_max: float = 1.0
    """``<i_max>``: upper bound of the integral force."""
    i_min: float = -1.0
    """``<i_min>``: lower bound of the integral force."""
    cmd_max: float = 1000.0
    """``<cmd_max>``: upper bound of the force (the joint's ``<limit><effort>`` bounds it too)."""
    cmd_min: float = -1000.0
    """``<cmd_min>``: lower bound of the force."""
    cmd_offset: float = 0.0
    """``<cmd_offset>``: a constant force added to the command."""


class PositionServo:
    """PID on position: a MuJoCo position actuator (``kp = p_gain``, ``kv = d_gain``) plus the integral force.

    The integral (``i_gain``·∫error, clamped to ``[i_min, i_max]``) and ``cmd_offset`` shift the
    actuator's command by ``force / kp``, since its force is ``kp·(command − q) − kv·q̇``.
    """

    __slots__ = ("actuator", "gains", "integral", "_last")

    def __init__(self, actuator: ActuatorHandle, gains: PidGains) -> None:
        """A position servo on ``actuator`` with ``gains``; no integral yet."""
        self.actuator = actuator
        self.gains = gains
        self.integral = 0.0
        self._last: float | None = None

    @property
    def needs_updates(self) -> bool:
        """Whether the integral term is on (else one command holds until the target changes)."""
        return self.gains.i_gain != 0.0

    def update(self, target: float, sim_time_sec: float, velocity: float = 0.0, measured: float | None = None) -> None:
        """Command ``target`` (moving at ``velocity``: the damping then acts on the velocity error,
        not on the velocity, so a moving target is followed without lag), integrating the position
        error over the time since the last update (``measured``: the joint's position, when the
        caller has just read it)."""
        self.actuator.command(self.control(target, sim_time_sec, velocity, measured))

    def control(
        self, target: float, sim_time_sec: float, velocity: float = 0.0, measured: float | None = None
    ) -> float:
        """What :meth:`update` commands, returned instead (to set several actuators in one write)."""
        g = self.gains
        if self._last is not None and g.i_gain:
            err = target - (self.actuator.joint.position if measured is None else measured)
            self.integral = min(max(self.integral + g.i_gain * err * (sim_time_sec - self._last), g.i_min), g.i_max)
        self._last = sim_time_sec
        kp = g.p_gain if g.p_gain > 1e-9 else 1e-9
        # kp·(c − q) − kv·q̇ with c = target + kv·velocity/kp is kp·(target − q) + kv·(velocity − q̇)
        return target + (g.cmd_offset + self.integral + g.d_gain * velocity) / kp

    def reset(self) -> None:
        self.integral = 0.0
        self._last = None


def add_position_servo(world: PhysicsWorld, entity: Entity, joint: str, gains: PidGains) -> PositionServo:
    """A :class:`PositionServo` on ``joint``, its force clamped to ``[cmd_min, cmd_max]`` and the joint's effort."""
    eff = joint_effort_limit(entity.model, joint)
    act = world.add_actuator(
        entity,
        joint,
        ActuatorKind.POSITION,
        kp=max(gains.p_gain, 1e-9),
        kv=max(gains.d_gain, 0.0),
        force_limit=(max(gains.cmd_min, -eff), min(gains.cmd_max, eff)),
    )
    return PositionServo(act, gains)


def add_velocity_servo(
    world: PhysicsWorld, entity: Entity, joint: str, *, kv: float | None = None, force_limit: float = math.inf
) -> VelocityServo:
    """A :class:`VelocityServo` on ``joint``: kv = I/dt unless given; limited by ``force_limit`` and its effort."""
    if kv is None:
        kv = servo_gain(wheel_inertia_about_axis(entity.model, joint, world.armature), world.timestep)
    limit = min(force_limit, joint_effort_limit(entity.model, joint))
    finite = 0 < limit < math.inf
    act = world.add_actuator(
        entity, joint, ActuatorKind.VELOCITY, kv=kv, force_limit=(-limit, limit) if finite else None
    )
    return VelocityServo(act, limit / kv if finite else UNLIMITED_INTEGRAL)


def add_wheel_servo(world: PhysicsWorld, entity: Entity, joint: str, torque_limit: float) -> VelocityServo:
    """Make ``joint`` a drive wheel (while the entity is staged): point contacts, the gear motor's
    armature and a velocity servo with kv = I/dt (see :func:`servo_gain`) limited to ``torque_limit``
    (≤ 0 or inf: none). The wheel's own ``<limit effort>`` is not applied: the drive's torque is."""
    model = entity.model
    world.make_wheel_contacts_pointlike(entity, model.joint(joint).child)
    world.set_joint_armature(entity, joint, WHEEL_ARMATURE)
    kv = servo_gain(wheel_inertia_about_axis(model, joint, WHEEL_ARMATURE), world.timestep)
    limited = 0 < torque_limit < math.inf
    act = world.add_actuator(
        entity, joint, ActuatorKind.VELOCITY, kv=kv, force_limit=(-torque_limit, torque_limit) if limited else None
    )
    return VelocityServo(act, torque_limit / kv if limited else UNLIMITED_INTEGRAL)


def ball_casters(model: Model, wheel_joints: list[str], tolerance: float = 0.005) -> list[str]:
    """Links that are ball casters of a robot driven by ``wheel_joints``: welded (fixed joints) under
    the wheels' parent link, with a sphere collision whose bottom is level with the wheels' bottom
    (within ``tolerance`` m) at spawn. A URDF ball caster is a fixed sphere; in Gazebo its author
    gives it ``mu 0`` or it drags (the ros2_control diffbot's two casters, with default friction,
    carry as much weight as its wheels and halved its speed)."""
    wheels = [model.joint(j) for j in wheel_joints]
    parents = {w.parent for w in wheels}
    if len(parents) != 1:
        return []
    base = parents.pop()
    bottoms = []
    for w in wheels:
        radius = max(
            (c.geometry.radius for c in model.link(w.child).collisions if isinstance(c.geometry, (Cylinder, Sphere))),
            default=None,
        )
        if radius is None:
            return []
        bottoms.append(w.origin.position[2] - radius)
    wheel_bottom = min(bottoms)
    out: list[str] = []
    # walk the fixed joints down from the base link, composing their poses
    frontier: list[tuple[str, Pose]] = [(base, Pose())]
    while frontier:
        link, X_BL = frontier.pop()
        for j in model.joints:
            if j.parent != link or j.type is not JointType.FIXED:
                continue
            X_BC = X_BL * j.origin * j.child_offset
            frontier.append((j.child, X_BC))
            for c in model.link(j.child).collisions:
                if isinstance(c.geometry, Sphere):
                    bottom = (X_BC * c.pose).position[2] - c.geometry.radius
                    if abs(bottom - wheel_bottom) <= tolerance:
                        out.append(j.child)
                        break
    return out

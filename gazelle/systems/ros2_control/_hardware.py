"""The simulated hardware behind a ``<ros2_control>`` block: its interfaces, over MuJoCo actuators.

What gazebo_ros2_control's ``GazeboSystem`` and gz_ros2_control's ``GazeboSimSystem`` do, on the
runtime's typed handles:

* every ``<joint>`` gets its state interfaces (``position``, ``velocity``, ``effort``) read from
  the joint each cycle, and one actuator per command interface:
  - ``position``: a stiff PD servo in MuJoCo (every step, implicit damping) plus an integral
    term updated each cycle, so a held arm does not sag under gravity;
  - ``velocity``: a velocity servo (``kv = I/dt``) with an integral term; a continuous joint
    is treated as a drive wheel (point contacts, gear-motor armature), as the diff drives are;
  - ``effort``: a motor, the torque as commanded;
* only the actuator of the joint's active command mode exerts force; a joint whose interfaces no
  active controller claims holds where it is (``hold_joints``, gz_ros2_control's default);
* ``<param name="min|max">`` of a command interface clamp the command only where the controller
  manager's ``enforce_command_limits`` is true, ros2_control Jazzy's default being false
  (controller_manager/src/controller_manager_parameters.yaml); gazebo_ros2_control
  (gazebo_system.cpp, ``write()``) and gz_ros2_control (gz_system.cpp, ``write()``: the velocity command
  goes to ``JointVelocityCmd`` as it is) pass commands on unclamped. Husky declares -1..1 rad/s on its
  wheels and drives at 1 m/s in Gazebo. ``<limit effort>`` clamps the force, as the physics does;
  ``initial_value`` of a state interface sets the joint at spawn; a
  ``<joint><mimic>`` joint follows its leader's position interface.

URDF ``<limit velocity>`` is not enforced on commands, as ros2_control Jazzy's resource manager
does not enforce it either (the ros2_control diffbot demo limits its wheels to 1 rad/s in the URDF
and drives them at 13 rad/s).
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..._errors import SimError
from ...description import ControlComponent, JointType, Pose, Ros2Control, rotation_matrix
from ...physics import ActuatorHandle, ActuatorKind, BodyHandle, Entity, JointHandle, PhysicsWorld, ServoPlan
from .._actuation import (
    PidGains,
    PositionServo,
    VelocityServo,
    add_velocity_servo,
    add_wheel_servo,
    ball_casters,
    joint_effort_limit,
    wheel_inertia_about_axis,
)

JOINT_INTERFACES = ("position", "velocity", "effort")
_UNLIMITED = (-math.inf, math.inf)
"""The joint interfaces simulated (ros2_control's hardware_interface::HW_IF_*)."""

POSITION_BANDWIDTH_HZ = 25.0
"""Natural frequency of a position interface's servo (critically damped), capped by the timestep."""

POSITION_INTEGRAL_SEC = 0.2
"""Integral time of a position interface's servo (removes the sag under gravity)."""

STEP_FACTOR = 2.0
"""A position target moving more than this times the joint's velocity limit is a step (see _drive_position)."""


class ControlError(SimError, ValueError):
    """A ``<ros2_control>`` block or request that cannot be honoured; the message names it."""


class UpdateFailed(ControlError):
    """A controller's ``update`` returned ros2_control's ``return_type::ERROR`` (it logged why): the manager
    deactivates it, as Jazzy's ``ControllerManager::update`` does, with its log line."""


@dataclass
class _Joint:
    """One ``<joint>`` of a ``<ros2_control>`` block: the simulated joint, the MuJoCo actuator behind each of
    its command interfaces, and the servo state that turns a position or velocity command into force.
    Units are the joint's: radians (revolute) or metres (prismatic), per second for velocities, N·m or N
    for efforts."""

    name: str
    handle: JointHandle
    commands: dict[str, ActuatorHandle] = field(default_factory=dict)
    """Command interface (``position``, ``velocity``, ``effort``) -> its actuator."""
    limits: dict[str, tuple[float, float]] = field(default_factory=dict)
    """Command interface -> (min, max) of its ``<param name="min|max">``, kept only when the manager's
    ``enforce_command_limits`` is true (then a command outside is clamped; see the module docstring)."""
    position: PositionServo | None = None
    """The PID that holds a position command (None: the joint has no position command interface)."""
    velocity: VelocityServo | None = None
    """The PID that tracks a velocity command (None: no velocity command interface)."""
    mode: str | None = None
    """The command interface in force (None: holding)."""
    hold: float = 0.0
    """Where the joint is held while no controller commands it."""
    mimic: tuple[str, float, float] | None = None
    """(leader, multiplier, offset) of a ``<mimic>`` joint."""
    enabled: str | None = None
    """The command interface whose actuator is switched on."""
    initial: float | None = None
    """``initial_value`` of the position state interface, applied by :meth:`SimHardware.start`."""
    initial_velocity: float = 0.0
    """``initial_value`` of the velocity state interface (0 without one), applied with :attr:`initial`."""
    last_target: tuple[float, float] | None = None
    """(position target, sim time) last sent in position mode."""
    keys: dict[str, str] = field(default_factory=dict)
    """Interface -> ``joint/interface`` (made once: the cycle runs at up to 1 kHz)."""
    slot: int = -1
    """Index of its position servo in :attr:`SimHardware._servo_values` (-1: none)."""
    max_speed: float = 0.0
    """URDF ``<limit velocity>`` (0: none): a position target that moves faster is a new set point."""


class SimHardware:
    """The interfaces of one ``<ros2_control>`` block and the actuators behind them.

    Build it while the entity is staged (it adds actuators); then each cycle :meth:`read`
    fills :attr:`states`, controllers read those and write :attr:`commands`, and :meth:`write`
    sends the commands of the joints' active modes to the actuators.
    """

    def __init__(
        self,
        rc: Ros2Control,
        world: PhysicsWorld,
        entity: Entity,
        log: logging.Logger,
        *,
        hold: bool = True,
        enforce_command_limits: bool = False,
    ) -> None:
        """The simulated hardware of one ``<ros2_control>`` block on ``entity``: for each ``<joint>``, an actuator
        per command interface (a position servo, a velocity servo or an effort motor, each bounded by the joint's
        effort limit) and its state interfaces; its sensors wired to the physics world's readings; its GPIOs
        warned about. ``hold``: joints no controller commands hold where they are (gz_ros2_control's
        ``hold_joints``, true by default), else they are left free. ``enforce_command_limits`` clamps commands to
        the interfaces' ``min``/``max``."""
        self.name = rc.name
        self.hold_joints = hold
        """Joints that no controller commands hold where they are (gz_ros2_control's ``hold_joints``);
        else their actuators are off and the joints are free."""
        self.type = rc.type
        self.plugin = rc.hardware_plugin
        self.state = "active"
        """Lifecycle state of the component (``set_hardware_component_state``)."""
        self.world = world
        self._log = log
        self.states: dict[str, float] = {}
        """``joint/interface`` -> value read this cycle."""
        self.commands: dict[str, float] = {}
        """``joint/interface`` -> value commanded (NaN until a controller writes one)."""
        self.joints: dict[str, _Joint] = {}
        self._velocity_servos: dict[str, VelocityServo] = {}
        self._velocity_servos_wheels: list[str] = []
        self._started = False
        self.entity = entity.name
        self.sensors: dict[str, tuple[str, ...]] = {}
        where = f"{rc.location}: " if rc.location else ""
        for comp in rc.joints:
            self._add_joint(rc, comp, world, entity, where, enforce_command_limits)
        names = tuple(self.joints)
        self._group = world.joint_group(entity.name, names)
        servos = [j for j in self.joints.values() if j.position is not None]
        for slot, j in enumerate(servos):
            j.slot = slot
        self._servos = world.actuator_group(tuple(j.commands["position"] for j in servos))
        """The position servos' actuators, set in one write each cycle."""
        self._servo_values: list[float] = [0.0] * len(servos)
        self._servo_joints = servos
        self._joint_index = {name: i for i, name in enumerate(names)}
        self._plan: ServoPlan | None = None
        """The planned block of cycles (see :meth:`plan_block`), made at the first."""
        self._plan_gains: tuple[PidGains, ...] = ()
        """The servos' gains the plan holds."""
        self._joint_list = list(self.joints.values())
        self._read_plan: list[tuple[str, list[int], list[str], bool]] = []
        """Per interface kind read: (kind, joint indices, state keys, whether every joint has it)."""
        for kind in JOINT_INTERFACES:
            idx = [i for i, n in enumerate(names) if f"{n}/{kind}" in self.states]
            if idx:
                self._read_plan.append((kind, idx, [f"{names[i]}/{kind}" for i in idx], len(idx) == len(names)))
        self._wheel_casters(rc, world, entity)
        self._sensor_readers: list[tuple[list[int], Callable[[], list[float]], list[str]]] = []
        """Per wired sensor component: (indices into its reading, the reading function, the state keys)."""
        self._wire_sensors(rc, world, entity, where)
        if rc.gpios:
            self._warn(
                f"{where}ros2_control '{rc.name}': gpio components ({', '.join(c.name for c in rc.gpios)}) "
                "are not simulated"
            )

    def _add_joint(
        self,
        rc: Ros2Control,
        comp: ControlComponent,
        world: PhysicsWorld,
        entity: Entity,
        where: str,
        enforce_command_limits: bool,
    ) -> None:
        """One ``<joint>`` of the ros2_control block: its command interfaces become actuators (a position
        one a :class:`PositionServo`), its state interfaces keys of :attr:`states`; what is not simulated
        is a warning naming it."""
        model = entity.model
        try:
            j = model.joint(comp.name)
        except KeyError:
            raise ControlError(
                f"{where}ros2_control '{rc.name}': joint '{comp.name}' is not in the robot description"
            ) from None
        if j.type in (JointType.FIXED, JointType.FLOATING, JointType.PLANAR, JointType.BALL):
            raise ControlError(
                f"{where}ros2_control '{rc.name}': joint '{comp.name}' is {j.type.value}; "
                "only revolute, continuous and prismatic joints have interfaces"
            )
        joint = _Joint(comp.name, world.joint(entity.name, comp.name))
        speed = j.axis.limit.velocity if j.axis is not None else None
        joint.max_speed = speed if speed and speed > 0 else 0.0
        joint.keys = {k: f"{comp.name}/{k}" for k in JOINT_INTERFACES}
        for ci in comp.command_interfaces:
            kind = ci.name
            if kind not in JOINT_INTERFACES:
                self._warn(
                    f"{where}ros2_control '{rc.name}': command interface '{kind}' of joint '{comp.name}' "
                    f"is not simulated (only {', '.join(JOINT_INTERFACES)}); no controller can claim it"
                )
                continue
            if enforce_command_limits:
                what = f"{where}ros2_control '{rc.name}': <param> of command interface '{kind}' of joint '{comp.name}'"
                joint.limits[kind] = (
                    self._number(ci.param("min"), -math.inf, f"{what} 'min'"),
                    self._number(ci.param("max"), math.inf, f"{what} 'max'"),
                )
            joint.commands[kind] = self._actuator(world, entity, comp.name, kind, j.type is JointType.CONTINUOUS)
            self.commands[f"{comp.name}/{kind}"] = math.nan
        for si in comp.state_interfaces:
            if si.name not in JOINT_INTERFACES:
                self._warn(
                    f"{where}ros2_control '{rc.name}': state interface '{si.name}' of joint '{comp.name}' "
                    f"is not simulated (only {', '.join(JOINT_INTERFACES)})"
                )
                continue
            self.states[f"{comp.name}/{si.name}"] = 0.0
            init = si.param("initial_value")
            if init is None:
                continue
            # gz_ros2_control's GazeboSimSystem::initSim (jazzy gz_system.cpp): a position initial_value resets
            # the joint there (JointPositionReset), a velocity one sets it moving (JointVelocityReset); an effort
            # one only seeds the reported effort and its command, which a simulated joint has no use for
            what = f"{where}ros2_control '{rc.name}': initial_value of joint '{comp.name}'"
            if si.name == "position":
                joint.initial = self._number(init, 0.0, what)
            elif si.name == "velocity":
                joint.initial_velocity = self._number(init, 0.0, f"{what} (velocity)")
            else:
                self._warn(f"{what} (effort) is not simulated: a joint's effort comes from its actuator")
        if j.mimic is not None:
            joint.mimic = (j.mimic.joint, j.mimic.multiplier, j.mimic.offset)
        joint.velocity = self._velocity_servos.get(comp.name)
        if "position" in joint.commands:
            act = joint.commands["position"]
            joint.position = PositionServo(act, self._position_gains(world, model, comp.name))
        self.joints[comp.name] = joint

    def _wheel_casters(self, rc: Ros2Control, world: PhysicsWorld, entity: Entity) -> None:
        """With two or more velocity-driven wheels, the spheres level with them roll as frictionless casters.

        A deliberate difference from Gazebo, said in the log: URDF has no ball joint for a caster, so robots
        weld a sphere under the base, and in Gazebo it drags unless its author gave it ``mu 0`` (the
        ros2_control diffbot's do drag: at default friction they carried as much weight as the wheels and
        halved its speed). See :func:`gazelle.systems._actuation.ball_casters` for what counts as one."""
        model, log = entity.model, self._log
        wheels = list(self._velocity_servos_wheels)
        if len(wheels) >= 2:
            casters = ball_casters(model, wheels)
            for link in casters:
                world.make_caster_frictionless(entity, link)
            if casters:
                log.info(
                    f"ros2_control '{rc.name}': {', '.join(casters)} roll as ball casters (frictionless spheres "
                    f"level with the wheels {', '.join(wheels)})"
                )

    def _wire_sensors(self, rc: Ros2Control, world: PhysicsWorld, entity: Entity, where: str) -> None:
        """The ``<sensor>`` components: their state interfaces read from the robot's sensor of the same
        name (imu, force_torque); one without such a sensor stays NaN, with a warning."""
        unwired = []
        for comp in rc.sensors:
            names = tuple(f"{comp.name}/{si.name}" for si in comp.state_interfaces)
            self.sensors[comp.name] = names
            for n in names:
                self.states[n] = math.nan  # sensor state interfaces: read by the sensor broadcasters
            reader = _sensor_reader(world, entity, comp.name)
            if reader is None:
                unwired.append(comp.name)
                continue
            order, read = reader
            wanted = [si.name for si in comp.state_interfaces if si.name in order]
            self._sensor_readers.append(([order.index(w) for w in wanted], read, [f"{comp.name}/{w}" for w in wanted]))
        if unwired:
            self._warn(
                f"{where}ros2_control '{rc.name}': sensor component(s) {', '.join(unwired)} have no <sensor> of "
                "the same name and type imu or force_torque in the robot: their state interfaces stay NaN"
            )

    def _warn(self, text: str) -> None:
        self._log.warning(text)

    def _number(self, text: str | None, default: float, what: str) -> float:
        """A ``<param>``'s number; ``default`` when absent or empty, and, with a warning naming ``what``, when
        it is not a number (the robot still loads)."""
        if text is None or not text.strip():
            return default
        try:
            return float(text)
        except ValueError:
            self._warn(f"{what} must be a number, got {text!r}; using {default:g}")
            return default

    def _actuator(self, world: PhysicsWorld, entity: Entity, joint: str, kind: str, wheel: bool) -> ActuatorHandle:
        """The actuator behind one command interface of ``joint``: ``position``, a MuJoCo position servo with the
        plugin's gains (``kp`` stiffness, ``kv`` damping, integrated implicitly); ``velocity``, a velocity servo
        (a wheel's has no position limit to respect); ``effort``, a motor whose force is the command. Each is
        bounded by the joint's ``<limit effort>``."""
        model = entity.model
        if kind == "position":
            gains = self._position_gains(world, model, joint)
            eff = joint_effort_limit(model, joint)
            act = world.add_actuator(
                entity,
                joint,
                ActuatorKind.POSITION,
                kp=gains.p_gain,
                kv=gains.d_gain,
                force_limit=(-eff, eff) if math.isfinite(eff) else None,
            )
        elif kind == "velocity":
            eff = joint_effort_limit(model, joint)
            servo = (
                add_wheel_servo(world, entity, joint, eff)
                if wheel
                else add_velocity_servo(world, entity, joint, force_limit=eff)
            )
            if wheel:
                self._velocity_servos_wheels.append(joint)
            act = servo.actuator
            self._velocity_servos[joint] = servo
        else:
            eff = joint_effort_limit(model, joint)
            act = world.add_actuator(
                entity, joint, ActuatorKind.EFFORT, force_limit=(-eff, eff) if math.isfinite(eff) else None
            )
        return act

    @staticmethod
    def _position_gains(world: PhysicsWorld, model, joint: str) -> PidGains:
        """Gains until the joint's inertia is known (:meth:`start`): from its child link alone."""
        eff = joint_effort_limit(model, joint)
        imax = eff if math.isfinite(eff) else 1e6
        base = PidGains(i_max=imax, i_min=-imax, cmd_max=imax, cmd_min=-imax)
        return _gains_for(wheel_inertia_about_axis(model, joint, world.armature), world.timestep, base)

    # ------------------------------------------------------------------ after the spawn
    def start(self) -> None:
        """Once the entity is in the world (idempotent): joints go to their ``initial_value`` (position, and
        velocity: a wheel given one starts turning), and those no controller commands hold there."""
        if self._started:
            return
        self._started = True
        for joint in self.joints.values():
            if joint.initial is not None or joint.initial_velocity != 0.0:
                self.world.set_joint_state(
                    self.entity, joint.name, position=joint.initial, velocity=joint.initial_velocity
                )
        for joint in self.joints.values():
            if joint.position is not None:
                # now the joint's real inertia is known (with all it carries): the servo's gains from it
                gains = _gains_for(joint.handle.inertia, self.world.timestep, joint.position.gains)
                joint.position.gains = gains
                joint.commands["position"].set_gains(gains.p_gain, gains.d_gain)
            if joint.mode is None:
                self._set_mode(joint, None)
        self._servo_values = [act.commanded for act in self._servos.actuators]

    def command_interfaces(self) -> list[str]:
        """Every ``joint/interface`` a controller may claim."""
        return list(self.commands)

    def state_interfaces(self) -> list[str]:
        """Every ``name/interface`` a controller may read."""
        return list(self.states)

    def read(self) -> None:
        """Fill :attr:`states` from the joints (one array read per interface kind) and the sensors.

        gz_ros2_control's ``read()`` copies the joints' position, velocity and effort out of the simulator
        each cycle; here each kind is one numpy gather over the robot's joints (the plan, made once, says
        which joints and keys), and each wired sensor (imu, force_torque) one reading."""
        states, group = self.states, self._group
        for kind, idx, keys, every in self._read_plan:
            arr = (
                group.positions()
                if kind == "position"
                else group.velocities()
                if kind == "velocity"
                else group.efforts()
            )
            values = arr.tolist() if every else arr[idx].tolist()
            states.update(zip(keys, values))
        for idx, reader, keys in self._sensor_readers:
            values = reader()
            states.update(zip(keys, (values[i] for i in idx)))

    def write(self, sim_time_sec: float) -> None:
        """Send each joint's command in its active mode (clamped to the interface's min/max where the manager
        enforces command limits); hold the others.

        The position servos' commands go to MuJoCo in one write (this runs every cycle, up to 1 kHz)."""
        if self.state != "active":
            return
        commands, joints, servo_values = self.commands, self.joints, self._servo_values
        for joint in self._joint_list:
            mode = joint.mode
            if mode is None:
                mimic = joint.mimic
                if mimic is not None and joint.slot >= 0 and mimic[0] in joints:
                    leader = joints[mimic[0]]
                    target = commands.get(leader.keys["position"], math.nan) if leader.mode == "position" else math.nan
                    if target == target and target not in (math.inf, -math.inf):
                        servo_values[joint.slot] = self._drive_position(
                            joint, mimic[1] * target + mimic[2], sim_time_sec
                        )
                        continue
                self._hold(joint, sim_time_sec)
                continue
            value = commands.get(joint.keys[mode], math.nan)
            if value != value or value in (math.inf, -math.inf):  # NaN or infinite: nothing commanded
                self._hold(joint, sim_time_sec)
                continue
            lo, hi = joint.limits.get(mode, _UNLIMITED)
            if value < lo:
                value = lo
            elif value > hi:
                value = hi
            if mode == "position":
                servo_values[joint.slot] = self._drive_position(joint, value, sim_time_sec)
            elif mode == "velocity":
                assert joint.velocity is not None
                joint.velocity.update(value, sim_time_sec)
            else:
                joint.commands["effort"].command(value)
        if servo_values:
            self._servos.command(servo_values)

    # ------------------------------------------------------------------ planned blocks of cycles
    def block_ready(self) -> bool:
        """Whether the next cycles can run as a planned block (:meth:`plan_block`): the component is active
        and every joint is a position servo, in position mode or held (``hold_joints``), and no mimic."""
        if self.state != "active" or not self._joint_list:
            return False
        for joint in self._joint_list:
            if joint.position is None or joint.mimic is not None or joint.mode not in (None, "position"):
                return False
            if joint.mode is None and not self.hold_joints:
                return False
        return True

    def plan_block(
        self,
        times: np.ndarray,
        targets: dict[str, np.ndarray],
        velocities: dict[str, np.ndarray],
        tolerances: dict[str, tuple[float, float, np.ndarray, np.ndarray]] | None = None,
    ) -> int:
        """Plan the cycles at ``times`` (see :meth:`block_ready`): each position-mode joint's commanded
        ``targets`` (and ``velocities`` where a controller writes the velocity interface too), the others
        held, as :meth:`write` would command them cycle after cycle (the same arithmetic, vectorised).
        ``tolerances``: per joint, the path tolerance (position, velocity) and the position and velocity the
        check compares with per cycle (a trajectory controller's reference at the cycle, where its target is
        the next cycle's). Returns how many cycles were planned: fewer than asked before a target that jumps
        (a new set point, which :meth:`_drive_position` handles in Python), 0 when none can be."""
        m = len(times)
        joints = self._servo_joints
        moving = [j for j in joints if j.mode == "position"]
        if any(j.name not in targets for j in moving):
            return 0
        target = np.empty((m, len(joints)))
        for j in joints:
            if j.mode is None:
                target[:, j.slot] = j.hold
        velref = np.zeros_like(target)
        if moving:
            planned = self._moving_targets(times, moving, targets, velocities)
            if planned is None:
                return 0
            value, refs, m = planned
            cols = [j.slot for j in moving]
            target[:, cols], velref[:, cols] = value, refs
        checked = tolerances is not None
        desp = desv = tol_p = tol_v = None
        if tolerances is not None:
            desp, desv = np.zeros_like(target), np.zeros_like(target)
            tol_p, tol_v = np.zeros(len(joints)), np.zeros(len(joints))
            for j in joints:
                if j.name in tolerances:
                    tol_p[j.slot], tol_v[j.slot], desp[:, j.slot], desv[:, j.slot] = tolerances[j.name]
        for j in joints:
            if j.enabled != "position":
                self._enable_only(j, "position")
        plan = self._block_plan()
        gains = tuple(j.position.gains for j in joints if j.position is not None)
        if gains != self._plan_gains:
            plan.kp[:] = [g.p_gain if g.p_gain > 1e-9 else 1e-9 for g in gains]
            plan.ki[:] = [g.i_gain for g in gains]
            plan.kd[:] = [g.d_gain for g in gains]
            plan.offset[:] = [g.cmd_offset for g in gains]
            plan.imin[:] = [g.i_min for g in gains]
            plan.imax[:] = [g.i_max for g in gains]
            self._plan_gains = gains
        for j in joints:
            servo = j.position
            assert servo is not None
            plan.integral[j.slot] = servo.integral
            plan.last[j.slot] = servo._last if servo._last is not None else math.nan
        plan.load(
            target[:m],
            velref[:m],
            desp=desp[:m] if desp is not None else None,
            desv=desv[:m] if desv is not None else None,
            tol_p=tol_p if checked else None,
            tol_v=tol_v if checked else None,
        )
        self.world.add_servo_plan(plan)
        return m

    def _moving_targets(
        self, times: np.ndarray, moving: list[_Joint], targets: dict[str, np.ndarray], velocities: dict[str, np.ndarray]
    ) -> tuple[np.ndarray, np.ndarray, int] | None:
        """The position-mode joints' targets (clamped as :meth:`write` clamps them) and velocity references
        per cycle (columns: ``moving``), and the cycles before the first target that jumps (see
        :meth:`_drive_position`); None when a target is not finite or the first one jumps."""
        value = np.column_stack([targets[j.name] for j in moving])
        if not np.isfinite(value).all():
            return None  # nothing commanded on some cycle: the Python cycle holds the joint
        lo = np.array([j.limits.get("position", _UNLIMITED)[0] for j in moving])
        hi = np.array([j.limits.get("position", _UNLIMITED)[1] for j in moving])
        value = np.where(value < lo, lo, np.where(value > hi, hi, value))
        m = len(times)
        # each cycle's last target is the cycle before's; the first's is the joint's last one
        step = times[1:] - times[:-1]
        diff = value[1:] - value[:-1]
        first = np.array([v - j.last_target[0] if j.last_target else math.nan for v, j in zip(value[0], moving)])
        first_dt = np.array([times[0] - j.last_target[1] if j.last_target else math.nan for j in moving])
        speed = np.array([j.max_speed for j in moving])
        if (speed > 0.0).any():
            dt = self.world.timestep
            limit = STEP_FACTOR * speed
            jumps = (np.abs(diff) > limit * np.maximum(step, dt)[:, None]) & (speed > 0.0)
            with np.errstate(invalid="ignore"):
                if ((np.abs(first) > limit * np.maximum(first_dt, dt)) & (speed > 0.0)).any():
                    return None
            rows = np.flatnonzero(jumps.any(axis=1))
            if len(rows):
                m = int(rows[0]) + 1  # the cycles before the jump
        with np.errstate(invalid="ignore", divide="ignore"):
            fd = np.empty_like(value)
            fd[1:] = diff / step[:, None]
            fd[0] = np.where(first_dt > 0.0, first / first_dt, 0.0)
        refs = np.empty_like(value)
        for k, j in enumerate(moving):
            given = velocities.get(j.name)
            stale = self.commands.get(j.keys["velocity"], math.nan)
            refs[:, k] = given if given is not None else (stale if stale == stale else fd[:, k])
        return value, refs, m

    def _block_plan(self) -> ServoPlan:
        """The servo plan of a planned block of cycles, made once: the position servos' actuators and the joints
        they read, with unit gains the plan scales (see ``physics/_servo_plan.py``)."""
        if self._plan is None:
            names = tuple(j.name for j in self._servo_joints)
            n = len(names)
            zeros = np.zeros(n)
            self._plan = ServoPlan(
                self._servos,
                self.world.joint_group(self.entity, names),
                self._group,
                {"kp": np.ones(n), "ki": zeros, "kd": zeros, "offset": zeros, "imin": zeros, "imax": zeros},
            )
        return self._plan

    @property
    def joint_names(self) -> tuple[str, ...]:
        """The joints, in the order a block's records hold them."""
        return self._group.names

    @property
    def joint_index(self) -> dict[str, int]:
        """Joint name -> its column in a block's records (the same dict every time)."""
        return self._joint_index

    @property
    def block(self) -> ServoPlan | None:
        """The planned block (its cycles taken so far: ``cursor``; records, times), if one was planned."""
        return self._plan

    def finish_block(self) -> int:
        """Take back the state of the cycles the world ran from the plan, as if :meth:`read` and
        :meth:`write` had run each: the servos' integrals and times, the joints' last targets, and the
        states of the last cycle. Returns the cycles taken (0: none since the last call)."""
        plan = self._plan
        if plan is None or plan.cursor == 0:
            return 0
        n = plan.cursor
        t_last = float(plan.times[n - 1])
        for joint in self._servo_joints:
            servo = joint.position
            assert servo is not None
            servo.integral = float(plan.integral[joint.slot])
            last = float(plan.last[joint.slot])
            servo._last = None if math.isnan(last) else last
            if joint.mode == "position":
                value = float(plan.target[n - 1, joint.slot])
                joint.last_target = (value, t_last)
                joint.hold = value
            else:
                joint.last_target = None
        self._servo_values = plan.commands.tolist()
        rows = plan.records[n - 1]
        kinds = {"position": 0, "velocity": 1, "effort": 2}
        for kind, idx, keys, _every in self._read_plan:
            self.states.update(zip(keys, rows[kinds[kind], idx].tolist()))
        plan.steps = plan.cursor = 0
        return n

    def drop_block(self) -> None:
        """Forget the plan (the entity goes, or the world was reset)."""
        if self._plan is not None:
            self.world.remove_servo_plan(self._plan)
            self._plan = None

    def _drive_position(self, joint: _Joint, target: float, sim_time_sec: float) -> float:
        """The position servo's command for ``target`` (its actuator switched on)."""
        servo = joint.position
        assert servo is not None
        if joint.enabled != "position":
            self._enable_only(joint, "position")
        # the target's own speed (the velocity interface when claimed too, else from the last target)
        # is the servo's velocity reference, as a real servo fed a trajectory has one
        velocity = self.commands.get(joint.keys["velocity"], math.nan) if joint.mode == "position" else math.nan
        last = joint.last_target
        step = (
            last is not None
            and joint.max_speed > 0.0
            and abs(target - last[0]) > STEP_FACTOR * joint.max_speed * max(sim_time_sec - last[1], self.world.timestep)
        )
        if step:
            # a step to a new set point (a gripper told to open), not a target moving: the integral built
            # up against the old one (a hand squeezing a piece, up to its effort limit) starts again, and
            # the step is no velocity to follow. Else the hand stayed shut until the integral unwound
            # (1.1 s on the Panda's fingers: a GripperCommand to open stalled), and the step's "speed"
            # (0.66 m/s) threw the finger 7 mm past its goal into the next chess piece.
            # gz_ros2_control's position servo has no integral to unwind (gz_system.cpp, write()).
            servo.integral = 0.0
            velocity = 0.0 if velocity != velocity else velocity
        if velocity != velocity:
            if last is not None and sim_time_sec > last[1]:
                velocity = (target - last[0]) / (sim_time_sec - last[1])
            else:
                velocity = 0.0
        joint.last_target = (target, sim_time_sec)
        joint.hold = target
        return servo.control(target, sim_time_sec, velocity, self.states.get(joint.keys["position"]))

    def _hold(self, joint: _Joint, sim_time_sec: float) -> None:
        """A joint no controller commands this cycle: with ``hold``, kept at the position it had when its last
        controller let go (a position servo, else a velocity servo at zero, else zero effort); without, its
        actuators are off and it moves freely."""
        joint.last_target = None
        if not self.hold_joints:
            if joint.enabled is not None:
                for act in joint.commands.values():
                    act.set_enabled(False)
                joint.enabled = None
            return
        if joint.position is not None:
            if joint.enabled != "position":
                self._enable_only(joint, "position")
            self._servo_values[joint.slot] = joint.position.control(
                joint.hold, sim_time_sec, 0.0, self.states.get(joint.keys["position"])
            )
        elif joint.velocity is not None:
            self._enable_only(joint, "velocity")
            joint.velocity.update(0.0, sim_time_sec)
        elif "effort" in joint.commands:
            self._enable_only(joint, "effort")
            joint.commands["effort"].command(0.0)

    def _enable_only(self, joint: _Joint, kind: str) -> None:
        """Turn on the actuator of one command interface of a joint and off its others (a joint has one actuator per
        command interface, and only the claimed one may act)."""
        if joint.enabled == kind:
            return
        for k, act in joint.commands.items():
            act.set_enabled(k == kind)
        joint.enabled = kind

    def _set_mode(self, joint: _Joint, mode: str | None) -> None:
        """A joint's command interface changed hands: on release it holds where it is now; on claim that interface's
        actuator acts; the servos' integrals restart either way."""
        joint.mode = mode
        if mode is None:
            joint.hold = joint.handle.position
        else:
            self._enable_only(joint, mode)
        if joint.position is not None:
            joint.position.reset()
        if joint.velocity is not None:
            joint.velocity.reset()

    def claim(self, interfaces: set[str]) -> None:
        """Set the joints' command modes from the interfaces claimed by active controllers (a joint
        with two claimed, as position and velocity, runs on position); the rest hold."""
        for name, joint in self.joints.items():
            claimed = [k for k in JOINT_INTERFACES if f"{name}/{k}" in interfaces]
            mode = claimed[0] if claimed else None
            if mode != joint.mode:
                self._set_mode(joint, mode)
                if mode is not None:
                    self.commands[f"{name}/{mode}"] = math.nan


IMU_INTERFACES = (
    "orientation.x",
    "orientation.y",
    "orientation.z",
    "orientation.w",
    "angular_velocity.x",
    "angular_velocity.y",
    "angular_velocity.z",
    "linear_acceleration.x",
    "linear_acceleration.y",
    "linear_acceleration.z",
)
"""An IMU sensor component's state interfaces (semantic_components::IMUSensor)."""

FT_INTERFACES = ("force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z")
"""A force-torque sensor component's state interfaces (semantic_components::ForceTorqueSensor)."""


def _sensor_reader(
    world: PhysicsWorld, entity: Entity, name: str
) -> tuple[tuple[str, ...], Callable[[], list[float]]] | None:
    """How to read the robot's ``<sensor name=name>`` (imu or force_torque) as gazebo_ros2_control's
    GazeboSystem does: the interfaces in order and a reading function; None when there is no such sensor."""
    for link in entity.model.links:
        for sensor in link.sensors:
            if sensor.name != name:
                continue
            if sensor.type == "imu":
                body, offset = world.body(entity.name, link.name), sensor.pose

                def read_imu(body: BodyHandle = body, offset: Pose = offset) -> list[float]:
                    r = body.imu_reading(offset)  # w, x, y, z, then angular velocity and acceleration
                    return [r[1], r[2], r[3], r[0], *r[4:]]

                return IMU_INTERFACES, read_imu
            if sensor.type in ("force_torque", "forcetorque") and sensor.joint:
                joint = entity.model.joint(sensor.joint)
                child = world.body(entity.name, joint.child)
                X_CJ = joint.child_offset.inverse()

                def read_ft(child: BodyHandle = child, X_CJ: Pose = X_CJ) -> list[float]:
                    X_WC = child.pose
                    f, t = child.joint_wrench(np.asarray((X_WC * X_CJ).position))
                    R = rotation_matrix(X_WC.orientation)
                    f, t = -(R.T @ f), -(R.T @ t)  # what the child exerts on the parent, in the child frame
                    return [*f.tolist(), *t.tolist()]

                return FT_INTERFACES, read_ft
    return None


def _gains_for(inertia: float, timestep: float, base: PidGains) -> PidGains:
    """A critically damped servo of :data:`POSITION_BANDWIDTH_HZ` (at most 0.2/dt rad/s) on ``inertia``,
    with the integral time :data:`POSITION_INTEGRAL_SEC`; force limits from ``base``."""
    inertia = max(inertia, 1e-6)
    omega = min(2.0 * math.pi * POSITION_BANDWIDTH_HZ, 0.2 / timestep)
    kp = inertia * omega * omega
    return dataclasses.replace(base, p_gain=kp, i_gain=kp / POSITION_INTEGRAL_SEC, d_gain=2.0 * math.sqrt(kp * inertia))

"""MoveIt Servo's computation of the next joint state (moveit_servo, Jazzy), on gazelle's planning model.

Core layer: no rclpy (``gazelle.ros._servo_node`` serves it with servo_node's ROS interface). Each cycle of
``publish_period`` seconds turns the latest command into a joint position delta of the move group's active
joints, as moveit_servo/src/servo.cpp ``getNextJointState`` and src/utils/command.cpp do:

* **joint jog**: velocities by joint name, × ``publish_period`` (× ``scale.joint`` when ``unitless``);
  a joint outside the group, or names and velocities of different lengths, is INVALID;
* **twist** (``TwistStamped``): expressed in its ``header.frame_id``, brought to the planning frame (the
  group's chain base, where MoveIt takes its IK solver's base frame) by the rotation of that frame
  (``apply_twist_commands_about_ee_frame``, the default) or the full adjoint; × ``publish_period``, then
  × ``scale.linear`` / ``scale.rotational`` (``unitless``) or capped at those speeds (``speed_units``);
* **pose** (``PoseStamped`` in the planning frame): the error to the tip's pose, capped at the same speeds;

then the Cartesian delta becomes joint deltas through the pseudo-inverse of the group's Jacobian (MoveIt's
path when no IK plugin is loaded; gazelle loads none), scaled near a singularity by the Jacobian's condition
number (``lower_singularity_threshold`` decelerates, ``hard_stop_singularity_threshold`` halts), capped at
the joints' velocity limits, and halted at a joint's position limit less its margin (JOINT_BOUND).

Not done, and said by the node: collision checking (``check_collisions``) and the smoothing plugin.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from ._robot_scene import PlanningError, RobotScene

INVALID, NO_WARNING = -1, 0
DECELERATE_FOR_APPROACHING_SINGULARITY, HALT_FOR_SINGULARITY, DECELERATE_FOR_LEAVING_SINGULARITY = 1, 2, 3
JOINT_BOUND = 6
STATUS_MESSAGES = {
    INVALID: "Invalid",
    NO_WARNING: "No warnings",
    DECELERATE_FOR_APPROACHING_SINGULARITY: "Moving closer to a singularity, decelerating",
    HALT_FOR_SINGULARITY: "Very close to a singularity, emergency stop",
    DECELERATE_FOR_LEAVING_SINGULARITY: "Moving away from a singularity, decelerating",
    4: "Close to a collision, decelerating",
    5: "Collision detected, emergency stop",
    JOINT_BOUND: "Close to a joint bound (position or velocity), halting",
}
"""moveit_servo's SERVO_STATUS_CODE_MAP (utils/datatypes.hpp): the ServoStatus codes and their messages."""
TOO_LARGE = "Invalid command: too large to compute a finite joint step."
UNITLESS_RANGE = "Invalid twist command: a component of a unitless command is outside [-1, 1]."
"""gazelle: what a command whose step overflows is told (MoveIt's arithmetic would pass on NaN positions), and
a unitless twist out of its range (Humble's rule)."""
JOINT_JOG, TWIST, POSE = 0, 1, 2
"""moveit_msgs/ServoCommandType's command types."""


@dataclass
class ServoSettings:
    """servo_parameters.yaml's parameters that the computation reads, with their defaults."""

    publish_period: float = 0.01
    command_in_type: str = "unitless"
    scale_linear: float = 0.4
    scale_rotational: float = 0.8
    scale_joint: float = 0.5
    apply_twist_commands_about_ee_frame: bool = True
    lower_singularity_threshold: float = 17.0
    hard_stop_singularity_threshold: float = 30.0
    leaving_singularity_threshold_multiplier: float = 2.0
    singularity_step_scale: float = 0.01
    joint_limit_margins: list[float] = field(default_factory=lambda: [0.1])
    halt_all_joints_in_joint_mode: bool = True
    halt_all_joints_in_cartesian_mode: bool = True
    override_velocity_scaling_factor: float = 0.0


@dataclass
class ServoStep:
    """One cycle's outcome: a ServoStatus code and the group's next joint positions and velocities."""

    status: int
    positions: np.ndarray
    velocities: np.ndarray
    warning: str = ""
    """What MoveIt logs for an INVALID command or a halt (the node logs it)."""


class ServoKinematics:
    """The move group's kinematics for servoing: frames, Jacobian and limits of its active joints."""

    def __init__(self, scene: RobotScene, group: str) -> None:
        """The kinematics MoveIt Servo uses for ``group``: its joints, the planning frame (the base of its chain,
        else the robot's root), the end-effector frame (the group's tip), and the joints' position and velocity
        limits."""
        self.scene = scene
        self.group = group
        self.joint_names = scene.group_joints(group)  # PlanningError for an unknown group
        g = next(g for g in scene.semantics.groups if g.name == group)
        self.planning_frame = g.chains[-1].base_link if g.chains else scene.root_link
        self.ee_frame = scene.tip_link(group)
        index = {n: i for i, n in enumerate(scene.joint_names)}
        self._index = [index[n] for n in self.joint_names]
        lo, hi = scene.scene.getPositionLimitVectors("")
        self.lower = np.asarray(lo, dtype=float)[self._index]
        self.upper = np.asarray(hi, dtype=float)[self._index]
        self.max_velocity = np.array([scene.velocity_limits.get(n, math.inf) for n in self.joint_names])
        self._analytic: bool | None = None

    def full(self, q: np.ndarray, others: Mapping[str, float] | None = None) -> np.ndarray:
        """A full configuration with the group's joints at ``q`` (the others as read)."""
        out = self.scene.state(others)
        out[self._index] = q
        return out

    def pose(self, q: np.ndarray, frame: str, others: Mapping[str, float] | None = None) -> np.ndarray:
        """``frame``'s pose in the planning frame (4x4); PlanningError for a frame the robot does not have."""
        qf = self.full(q, others)
        base = self.scene.fk(qf, self.planning_frame)
        return np.linalg.solve(base, self.scene.fk(qf, frame))

    def jacobian(self, q: np.ndarray, others: Mapping[str, float] | None = None) -> np.ndarray:
        """The tip's 6 x n Jacobian in the planning frame (linear, then angular): MoveIt's ``getJacobian`` of the
        group (at the tip's origin, in the base). pinocchio's world Jacobian through roboplan (7 µs), moved
        to the tip's origin and rotated into the base; checked once against :meth:`numeric_jacobian`, which
        stands in should a robot's joints not map one to one onto pinocchio's velocities."""
        if self._analytic is None:
            analytic, numeric = self._world_jacobian(q, others), self.numeric_jacobian(q, others)
            self._analytic = bool(np.allclose(analytic, numeric, atol=1e-5))
        return self._world_jacobian(q, others) if self._analytic else self.numeric_jacobian(q, others)

    def _world_jacobian(self, q: np.ndarray, others: Mapping[str, float] | None) -> np.ndarray:
        """The group's Jacobian at ``q`` as Servo uses it: rows are the tip's linear and angular velocity expressed
        in the planning frame, the linear part of the tip's origin (not of the world origin, as the frame
        Jacobian gives it)."""
        qf = self.full(q, others)
        world = np.asarray(self.scene.scene.computeFrameJacobian(qf, self.ee_frame, False))[:, self._index]
        tip = self.scene.fk(qf, self.ee_frame)[:3, 3]
        base = self.scene.fk(qf, self.planning_frame)[:3, :3]
        linear = world[:3] - _skew(tip) @ world[3:]  # the velocity of the tip's origin, not the world's
        return np.vstack([base.T @ linear, base.T @ world[3:]])

    def numeric_jacobian(self, q: np.ndarray, others: Mapping[str, float] | None = None) -> np.ndarray:
        """The same Jacobian by central differences of the forward kinematics."""
        h = 1e-6
        out = np.zeros((6, len(q)))
        for i in range(len(q)):
            dq = np.zeros(len(q))
            dq[i] = h
            plus, minus = self.pose(q + dq, self.ee_frame, others), self.pose(q - dq, self.ee_frame, others)
            out[:3, i] = (plus[:3, 3] - minus[:3, 3]) / (2 * h)
            out[3:, i] = _rotation_vector(plus[:3, :3] @ minus[:3, :3].T) / (2 * h)
        return out


def _rotation_vector(r: np.ndarray) -> np.ndarray:
    """The axis × angle of a rotation matrix."""
    angle = math.acos(max(-1.0, min(1.0, (np.trace(r) - 1.0) / 2.0)))
    if angle < 1e-12:
        return np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]) / 2.0
    axis = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]) / (2.0 * math.sin(angle))
    return axis * angle


def _capped(v: np.ndarray, cap: float) -> np.ndarray:
    """``v`` shrunk whole (its direction kept) to the length ``cap`` when longer (a cap <= 0 caps nothing);
    its length is taken without overflow, so a vector of 1e308s is capped, not zeroed by an infinite norm."""
    if cap <= 0.0:
        return v
    big = float(np.max(np.abs(v))) if len(v) else 0.0
    if big == 0.0:
        return v
    unit = v / big
    length = float(np.linalg.norm(unit))  # |v| / big, in [1, sqrt(len(v))]
    if length * (big / cap) <= 1.0:
        return v
    return unit * (cap / length)


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


class ServoCore:
    """getNextJointState for one move group (see the module docstring)."""

    def __init__(self, kinematics: ServoKinematics, settings: ServoSettings) -> None:
        """The servo loop's arithmetic (MoveIt Servo's, without ROS): the kinematics, the settings, the cycle period
        and each joint's limit margin (one margin for all joints when one is given)."""
        self.k = kinematics
        self.s = settings
        self.period = settings.publish_period
        """The time this cycle covers (s): ``publish_period``, unless the node's clock moved further since the
        last cycle (a simulation stepped in chunks longer than the period: see the node)."""
        n = len(kinematics.joint_names)
        margins = list(settings.joint_limit_margins) or [0.1]
        self.margins = np.array(margins * n if len(margins) == 1 else margins[:n], dtype=float)

    # ------------------------------------------------------------------ commands to joint deltas
    def joint_jog(self, names: Sequence[str], velocities: Sequence[float]) -> tuple[int, np.ndarray, str]:
        """A JointJog command as this cycle's joint step: velocities by joint name (names not in the group, a count
        mismatch or non-finite values are INVALID with MoveIt's messages) times the period, and times
        ``scale.joint`` for unitless commands."""
        n = len(self.k.joint_names)
        if len(names) != len(velocities):
            return (
                INVALID,
                np.zeros(n),
                (
                    "Invalid joint jog command. Each joint name must have one corresponding velocity command. "
                    f"Received {len(names)} joints with {len(velocities)} commands."
                ),
            )
        v = np.zeros(n)
        for name, value in zip(names, velocities):
            if name not in self.k.joint_names:
                return INVALID, np.zeros(n), f"Invalid joint name: {name} (not a joint of the move group)"
            v[self.k.joint_names.index(name)] = value
        if not np.all(np.isfinite(v)):
            return INVALID, np.zeros(n), "Invalid velocity values in joint jog command"
        delta = v * self.period
        if self.s.command_in_type == "unitless":
            delta *= self.s.scale_joint
        return NO_WARNING, delta, ""

    def out_of_range(self, twist: Sequence[float]) -> bool:
        """Whether an incoming twist (in its own frame) is out of the unitless range: servo_parameters.yaml says
        "unitless commands are in the range [-1:1]", and Humble's servo_calcs.cpp skipped one out of it (Jazzy
        scales it, and a twist of 1e308 then overflowed into NaN joint positions). Never for speed_units, whose
        speeds are capped."""
        return self.s.command_in_type == "unitless" and any(abs(v) > 1.0 for v in twist)

    def twist_in_planning_frame(
        self, q: np.ndarray, frame: str, twist: Sequence[float], others: Mapping[str, float] | None = None
    ) -> np.ndarray | None:
        """``twist`` (linear, angular) given in ``frame``, in the planning frame (servo.cpp toPlanningFrame);
        None when ``frame`` is not one of the robot's."""
        t = np.asarray(twist, dtype=float)
        if frame == self.k.planning_frame:
            return t
        try:
            tf = self.k.pose(q, frame, others)
        except PlanningError:
            return None
        r, p = tf[:3, :3], tf[:3, 3]
        with np.errstate(over="ignore", invalid="ignore"):  # a twist of 1e308s: inf, refused by twist()
            if self.s.apply_twist_commands_about_ee_frame:
                return np.concatenate([r @ t[:3], r @ t[3:]])
            adjoint = np.zeros((6, 6))  # [linear; angular] order: Modern Robotics eq. 3.83, reordered
            adjoint[:3, :3] = _skew(p) @ r
            adjoint[:3, 3:] = r
            adjoint[3:, :3] = r
            return adjoint @ t

    def twist(
        self, q: np.ndarray, twist: np.ndarray, others: Mapping[str, float] | None = None
    ) -> tuple[int, np.ndarray, str]:
        """command.cpp jointDeltaFromTwist for a twist already in the planning frame.

        Args:
            q: the group's positions (rad or m), the state the step starts from.
            twist: (vx, vy, vz, wx, wy, wz) in the planning frame. ``speed_units``: m/s and rad/s, each
                part capped at ``scale.linear``/``scale.rotational`` by shrinking it whole (its direction
                kept); ``unitless``: fractions of those scales, each component in [-1, 1].
            others: positions of joints outside the group that move its frames (a torso under an arm).

        Returns:
            (status, joint step for this cycle, message): the step is the twist times the period through the
            Jacobian's pseudo-inverse, scaled down approaching a singularity (status 1 or 2) and zero at the
            hard stop (3); an invalid twist is INVALID (-1) with MoveIt's message.
        """
        n = len(q)
        if not np.all(np.isfinite(twist)):
            return INVALID, np.zeros(n), "Invalid twist command."
        if not np.any(twist):
            return NO_WARNING, np.zeros(n), ""
        if self.s.command_in_type == "unitless":
            dx = twist * self.period
            dx[:3] *= self.s.scale_linear
            dx[3:] *= self.s.scale_rotational
        else:
            dx = np.concatenate([_capped(twist[:3], self.s.scale_linear), _capped(twist[3:], self.s.scale_rotational)])
            dx *= self.period
        return self._through_jacobian(q, dx, others)

    def pose(
        self, q: np.ndarray, target: np.ndarray, others: Mapping[str, float] | None = None
    ) -> tuple[int, np.ndarray, str]:
        """command.cpp jointDeltaFromPose: ``target`` (4x4, planning frame) approached at the capped speeds.

        The end effector's position error and its rotation's angle are each cut to what
        ``scale.linear`` (m/s) and ``scale.rotational`` (rad/s) allow in one period, so a far pose is
        approached along a straight line at those speeds and a near one reached in one cycle. Returns as
        :meth:`twist` does."""
        current = self.k.pose(q, self.k.ee_frame, others)
        error = target[:3, 3] - current[:3, 3]
        period = self.period
        error = _capped(error, self.s.scale_linear * period)
        rotation = target[:3, :3] @ current[:3, :3].T
        # a slerp by the cap's fraction: the same axis, a fraction of the angle
        rotvec = _capped(_rotation_vector(rotation), self.s.scale_rotational * period)
        return self._through_jacobian(q, np.concatenate([error, rotvec]), others)

    def _through_jacobian(
        self, q: np.ndarray, dx: np.ndarray, others: Mapping[str, float] | None
    ) -> tuple[int, np.ndarray, str]:
        """command.cpp jointDeltaFromIK without an IK plugin: the Jacobian's pseudo-inverse (from its SVD, which
        the singularity check below shares). A step too large to compute (a unitless twist of 1e308: the
        pseudo-inverse overflows) is INVALID, as is a Jacobian whose SVD does not converge."""
        n = len(q)
        try:
            u, sv, vt = np.linalg.svd(self.k.jacobian(q, others), full_matrices=False)
        except np.linalg.LinAlgError:
            return INVALID, np.zeros(n), "Invalid command: the Jacobian's SVD did not converge."
        with np.errstate(over="ignore", invalid="ignore"):
            delta = vt.T @ ((u.T @ dx) / sv)
        if not np.all(np.isfinite(delta)):
            return INVALID, np.zeros(n), TOO_LARGE
        scale, status = self._singularity_scale(q, u, sv, vt, dx, others)
        if status != NO_WARNING:
            return status, delta * scale, STATUS_MESSAGES[status]
        return NO_WARNING, delta, ""

    def _singularity_scale(
        self,
        q: np.ndarray,
        u: np.ndarray,
        sv: np.ndarray,
        vt: np.ndarray,
        dx: np.ndarray,
        others: Mapping[str, float] | None,
    ) -> tuple[float, int]:
        """common.cpp velocityScalingFactorForSingularity: the condition number now, and whether ``dx`` heads
        towards the singular direction (the last left singular vector, signed by a small test step)."""
        towards = u[:, len(dx) - 1].copy()
        condition = sv[0] / sv[-1] if sv[-1] > 0 else math.inf
        step = vt.T @ ((u.T @ (towards * self.s.singularity_step_scale)) / sv)
        next_sv = np.linalg.svd(self.k.jacobian(q + step, others), compute_uv=False)
        next_condition = next_sv[0] / next_sv[-1] if next_sv[-1] > 0 else math.inf
        if next_condition <= condition:
            towards *= -1
        with np.errstate(over="ignore", invalid="ignore"):
            approaching = float(towards @ dx) > 0
        lower, hard = self.s.lower_singularity_threshold, self.s.hard_stop_singularity_threshold
        upper = hard if approaching else lower + (hard - lower) * self.s.leaving_singularity_threshold_multiplier
        if lower < condition < hard:
            status = DECELERATE_FOR_APPROACHING_SINGULARITY if approaching else DECELERATE_FOR_LEAVING_SINGULARITY
            return 1.0 - (condition - lower) / (upper - lower), status
        if condition >= hard:
            return 0.0, HALT_FOR_SINGULARITY
        return 1.0, NO_WARNING

    # ------------------------------------------------------------------ the next state
    def next_state(self, q: np.ndarray, status: int, delta: np.ndarray, kind: int, warning: str = "") -> ServoStep:
        """servo.cpp getNextJointState after the delta: velocity limits, position limits less the margins.

        Args:
            q: the group's positions the step starts from.
            status: the status of the command's step (:meth:`twist`, :meth:`pose`, :meth:`joint_jog`).
            delta: the joint step for this period.
            kind: the command type (JOINT_JOG, TWIST or POSE): which ``halt_all_joints_in_*_mode`` applies.
            warning: the command's message, passed on.

        Returns:
            The next state: positions and velocities after scaling every joint by the one factor that keeps
            each within its velocity limit (so the motion keeps its direction), and, for a joint heading past
            its position limit less ``joint_limit_margins``, JOINT_BOUND with that joint (or all of them)
            held; INVALID (no motion) when the step is not finite.
        """
        period = self.period
        if status == INVALID:
            return ServoStep(INVALID, q.copy(), np.zeros(len(q)), warning)
        with np.errstate(over="ignore", invalid="ignore"):
            velocities = delta / period
            scale = self._velocity_limit_scale(velocities)
            positions = q + velocities * scale * period
            velocities = (positions - q) / period
        if not (np.all(np.isfinite(positions)) and np.all(np.isfinite(velocities))):
            # a step that overflowed (a command of 1e308): never a NaN position for the controller
            return ServoStep(INVALID, q.copy(), np.zeros(len(q)), TOO_LARGE)
        halt = [
            i
            for i in range(len(q))
            if (velocities[i] < 0 and positions[i] < self.k.lower[i] + self.margins[i])
            or (velocities[i] > 0 and positions[i] > self.k.upper[i] - self.margins[i])
        ]
        if halt:
            names = " ".join(self.k.joint_names[i] for i in halt)
            all_joints = (kind == JOINT_JOG and self.s.halt_all_joints_in_joint_mode) or (
                kind == TWIST and self.s.halt_all_joints_in_cartesian_mode
            )
            if all_joints:
                return ServoStep(
                    JOINT_BOUND, q.copy(), np.zeros(len(q)), f"Joint position limit reached on joints: {names}"
                )
            positions, velocities = positions.copy(), velocities.copy()
            positions[halt], velocities[halt] = q[halt], 0.0
            return ServoStep(JOINT_BOUND, positions, velocities, f"Joint position limit reached on joints: {names}")
        return ServoStep(status, positions, velocities, warning)

    def _velocity_limit_scale(self, velocities: np.ndarray) -> float:
        """common.cpp jointLimitVelocityScalingFactor (the override applies from 0.01 up)."""
        override = self.s.override_velocity_scaling_factor
        factor = override if override >= 0.01 else 1.0
        for v, cap in zip(velocities, self.k.max_velocity):
            if v != 0.0 and math.isfinite(cap):
                factor = min(factor, float(np.clip(v, -cap, cap)) / v)
        return factor

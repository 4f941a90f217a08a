"""``ackermann_steering_controller/AckermannSteeringController``, as ros2_controllers Jazzy's (branch ``jazzy`` at
ed360c9): ``steering_controllers_library/src/steering_controllers_library.cpp`` (parameters, topics, the
reference's timeout, the cycle) with ``ackermann_steering_controller/src/ackermann_steering_controller.cpp``
(its wheel parameters and odometry) and ``steering_kinematics.cpp`` (:mod:`._steering_kinematics`).

* Parameters (``steering_controllers_library.yaml``, ``ackermann_steering_controller.yaml``):
  ``traction_joints_names`` and ``steering_joints_names`` (two each, ordered right, left), or the deprecated
  ``rear_wheels_names`` / ``front_wheels_names`` placed by ``front_steering`` (each with its warning, as
  upstream); ``*_state_names``; ``wheelbase``, ``traction_track_width``, ``steering_track_width`` (else the
  traction one), ``traction_wheels_radius``, or the deprecated ``front_wheel_track`` / ``rear_wheel_track`` /
  ``front_wheels_radius`` / ``rear_wheels_radius``; ``reference_timeout`` (1 s), ``open_loop``,
  ``position_feedback`` (false: traction wheels' velocity states), ``reduce_wheel_speed_until_steering_reached``,
  ``velocity_rolling_window_size``, ``odom_frame_id``, ``base_frame_id``, ``enable_odom_tf`` (true), the
  covariance diagonals.
* Topics: ``~/reference`` (geometry_msgs/TwistStamped, best effort, depth 1), ``~/odometry``
  (nav_msgs/Odometry), ``~/tf_odometry`` (tf2_msgs/TFMessage: the library publishes odom -> base there, not
  on ``/tf``), ``~/controller_state`` (control_msgs/SteeringControllerStatus), each every cycle.
* The cycle: a reference newer than ``reference_timeout`` (0: used once) sets the wheels' speeds and the
  steering angles; a stale one stops the traction wheels (the steering holds). Odometry integrates the
  wheels' feedback (or the reference with ``open_loop``).

Departures: a reference stamped in another clock than the controller's (``node->now()`` of a node without
``use_sim_time``, as gz_ros2_control_demos' example_ackermann_drive.cpp stamps it, is wall time, far ahead
of sim time) never ages upstream, so the robot never stops when its sender does; here its age counts from
its arrival, as a zero stamp's does upstream. The chained-mode reference interfaces are not offered.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...description import Pose, quat_from_rpy
from .._bus import DeclaredMessage, MsgType, Qos
from .._payloads import Odometry, Transform, TransformBatch, Twist, TwistStamped
from ._controller import Controller
from ._hardware import ControlError
from ._steering_kinematics import ACKERMANN, SteeringKinematics

STEERING_CONTROLLER_STATUS = DeclaredMessage("STEERING_CONTROLLER_STATUS", "control_msgs/msg/SteeringControllerStatus")


@dataclass(frozen=True, slots=True)
class SteeringControllerStatus:
    """control_msgs/SteeringControllerStatus (its fields by name)."""

    stamp_sec: float
    frame_id: str
    traction_wheels_position: tuple[float, ...]
    traction_wheels_velocity: tuple[float, ...]
    linear_velocity_command: tuple[float, ...]
    steer_positions: tuple[float, ...]
    steering_angle_command: tuple[float, ...]


class AckermannSteeringController(Controller):
    """Two steered front wheels and two driven rear wheels from ``~/reference`` (see the module docstring)."""

    type_name = "ackermann_steering_controller/AckermannSteeringController"

    def _joint_lists(self) -> None:
        """The traction and steering joints (and the joints their states are read from), the deprecated front/rear
        names placed by ``front_steering`` as ``SteeringControllersLibrary::on_configure`` places them."""
        front = self.param("front_steering", True, bool)
        if not front:
            self.log.warning(
                "DEPRECATED parameter 'front_steering'. Instead, set 'traction_joints_names' or 'steering_joints_names'"
            )
        names = {k: self.string_list(f"{k}_joints_names") for k in ("traction", "steering")}
        states = {k: self.string_list(f"{k}_joints_state_names") for k in ("traction", "steering")}
        for old, table in (("wheels_names", names), ("wheels_state_names", states)):
            new = "joints_state_names" if "state" in old else "joints_names"
            for end, steered in (("front", front), ("rear", not front)):
                value = self.string_list(f"{end}_{old}")
                if value:
                    self.log.warning(
                        f"DEPRECATED parameter '{end}_{old}', set 'traction_{new}' or 'steering_{new}' instead"
                    )
                    table["steering" if steered else "traction"] = value
        for kind in ("traction", "steering"):
            if len(names[kind]) != 2:
                raise ControlError(
                    f"controller '{self.name}': Ackermann configuration requires exactly two {kind} joints, but "
                    f"{len(names[kind])} were provided"
                )
            if states[kind] and len(states[kind]) != 2:
                raise ControlError(
                    f"controller '{self.name}': Ackermann configuration requires exactly two {kind} joints, but "
                    f"{len(states[kind])} state interface names were provided"
                )
        self.traction, self.steering = names["traction"], names["steering"]
        self.traction_states = states["traction"] or self.traction
        self.steering_states = states["steering"] or self.steering

    def _wheel_params(self, front: bool) -> SteeringKinematics:
        """``AckermannSteeringController::configure_odometry``: the wheel parameters, the deprecated ones winning with
        their warnings; a traction radius that is not set fails the configure."""
        radius = self.param("traction_wheels_radius", 0.0, float)
        traction_track = self.param("traction_track_width", 0.0, float)
        steering_track = self.param("steering_track_width", 0.0, float)
        for end in ("front", "rear"):
            r = self.param(f"{end}_wheels_radius", 0.0, float)
            if r > 0.0:
                self.log.warning(f"DEPRECATED parameter '{end}_wheel_radius', set 'traction_wheels_radius' instead")
                radius = r
        for end, steered in (("front", front), ("rear", not front)):
            track = self.param(f"{end}_wheel_track", 0.0, float)
            if track > 0.0:
                self.log.warning(
                    f"DEPRECATED parameter '{end}_wheel_track', set 'traction_track_width' or 'steering_track_width' "
                    "instead"
                )
                if steered:
                    steering_track = track
                else:
                    traction_track = track
        if radius <= 0.0:
            raise ControlError(
                f"controller '{self.name}': parameter 'traction_wheels_radius' is not set, cannot configure odometry"
            )
        wheelbase = self.param("wheelbase", 0.0, float)
        if wheelbase <= 0.0:
            raise ControlError(f"controller '{self.name}': parameter 'wheelbase' must be greater than 0")
        if steering_track <= 0.0:
            steering_track = traction_track
        return SteeringKinematics(ACKERMANN, radius, wheelbase, steering_track, traction_track)

    def on_configure(self) -> None:
        """Read the parameters (upstream's names, defaults and checks), declare the topics."""
        self._joint_lists()
        self.kin = self._wheel_params(self.param("front_steering", True, bool))
        self.kin.set_window(self.param("velocity_rolling_window_size", 10, int))
        self.timeout = self.param("reference_timeout", 1.0, float)
        self.open_loop = self.param("open_loop", False, bool)
        self.position_feedback = self.param("position_feedback", False, bool)
        self.reduce = self.param("reduce_wheel_speed_until_steering_reached", False, bool)
        self.odom_frame = self.param("odom_frame_id", "odom", str)
        self.base_frame = self.param("base_frame_id", "base_link", str)
        self.enable_tf = self.param("enable_odom_tf", True, bool)
        default_cov = [0.0, 7.0, 14.0, 21.0, 28.0, 35.0]
        pose_cov = self.float_list("pose_covariance_diagonal", default_cov)
        twist_cov = self.float_list("twist_covariance_diagonal", default_cov)
        if len(pose_cov) != 6 or len(twist_cov) != 6:
            raise ControlError(f"controller '{self.name}': the covariance diagonals need 6 values")
        self._pose_cov = tuple(pose_cov[i // 7] if i % 7 == 0 else 0.0 for i in range(36))
        self._twist_cov = tuple(twist_cov[i // 7] if i % 7 == 0 else 0.0 for i in range(36))
        self._received: tuple[TwistStamped, float | None] | None = None
        self.subscribe("~/reference", MsgType.TWIST_STAMPED, self._on_reference, qos=Qos.SENSOR, depth=1)
        self._odom = self.advertise("~/odometry", MsgType.ODOMETRY)
        self._tf = self.advertise("~/tf_odometry", MsgType.TF)
        self._state = self.advertise("~/controller_state", STEERING_CONTROLLER_STATUS)
        self._ref: tuple[float, float, float] | None = None

    def _on_reference(self, msg: TwistStamped) -> None:
        """Keep the reference for the next cycle (its age is judged there, in the controller's clock)."""
        self._received = (msg, msg.stamp_sec if msg.stamp_sec > 0 else None)

    def command_interfaces(self) -> list[str]:
        return [f"{j}/velocity" for j in self.traction] + [f"{j}/position" for j in self.steering]

    def state_interfaces(self) -> list[str] | None:
        kind = "position" if self.position_feedback else "velocity"
        return [f"{j}/{kind}" for j in self.traction_states] + [f"{j}/position" for j in self.steering_states]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """No reference until one arrives (``reset_controller_reference_msg``); the odometry keeps its pose, as
        upstream's does across a deactivation."""
        self._received = None
        self._ref = None

    def _reference(self, t: float) -> tuple[float, float] | None:
        """``update_reference_from_subscribers``: the reference while it is fresh, else None."""
        if self._received is not None:
            msg, stamp = self._received
            self._received = None
            # a zero stamp, or one in another clock (ahead of this one), counts from its arrival
            start = stamp if stamp is not None and stamp <= t else t
            self._ref = (msg.twist.linear[0], msg.twist.angular[2], start)
        if self._ref is None:
            return None
        v, w, start = self._ref
        if self.timeout == 0.0:
            self._ref = None
            return (v, w) if math.isfinite(v) and math.isfinite(w) else None
        if t - start <= self.timeout and math.isfinite(v) and math.isfinite(w):
            return v, w
        self._ref = None
        return None

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle (``update_and_write_commands``): odometry from this cycle's states, then the commands for the
        reference (or the traction wheels stopped), then odometry, TF and the controller's state."""
        ref = self._reference(t)
        v, w = ref if ref is not None else (0.0, 0.0)
        self._odometry(states, v, w, period)
        if ref is not None:
            traction, steering = self.kin.commands(v, w, self.open_loop, self.reduce)
            for joint, value in zip(self.traction, traction, strict=True):
                commands[f"{joint}/velocity"] = value
            for joint, value in zip(self.steering, steering, strict=True):
                commands[f"{joint}/position"] = value
        else:
            for joint in self.traction:
                commands[f"{joint}/velocity"] = 0.0
        self._publish(t, states, commands)

    def _odometry(self, states: dict[str, float], v: float, w: float, dt: float) -> None:
        """``AckermannSteeringController::update_odometry``: open loop from the reference, else from the traction
        wheels' velocities (or positions) and the steering positions, skipped while any is not finite."""
        if self.open_loop:
            self.kin.update_open_loop(v, w, dt)
            return
        kind = "position" if self.position_feedback else "velocity"
        traction = [states.get(f"{j}/{kind}", math.nan) for j in self.traction_states]
        steering = [states.get(f"{j}/position", math.nan) for j in self.steering_states]
        if dt <= 0 or not all(math.isfinite(x) for x in (*traction, *steering)):
            return
        if self.position_feedback:
            self.kin.update_from_position(traction, steering, dt)
        else:
            self.kin.update_from_velocity(traction, steering, dt)

    def _publish(self, t: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """``~/odometry``, ``~/tf_odometry`` (with ``enable_odom_tf``) and ``~/controller_state``, each while wanted."""
        x, y, heading = self.kin.pose
        pose = Pose((x, y, 0.0), quat_from_rpy(0.0, 0.0, heading))
        if self._odom.wanted:
            twist = Twist((self.kin.linear, 0.0, 0.0), (0.0, 0.0, self.kin.angular))
            self._odom.publish(
                Odometry(t, self.odom_frame, self.base_frame, pose, twist, self._pose_cov, self._twist_cov)
            )
        if self.enable_tf and self._tf.wanted:
            self._tf.publish(TransformBatch((Transform(t, self.odom_frame, self.base_frame, pose),)))
        if self._state.wanted:
            kind = "position" if self.position_feedback else "velocity"
            wheels = tuple(states.get(f"{j}/{kind}", math.nan) for j in self.traction_states)
            self._state.publish(
                SteeringControllerStatus(
                    t,
                    self.odom_frame,
                    wheels if self.position_feedback else (),
                    () if self.position_feedback else wheels,
                    tuple(commands.get(f"{j}/velocity", math.nan) for j in self.traction),
                    tuple(states.get(f"{j}/position", math.nan) for j in self.steering_states),
                    tuple(commands.get(f"{j}/position", math.nan) for j in self.steering),
                )
            )

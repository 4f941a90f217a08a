"""``tricycle_controller/TricycleController``, as ros2_controllers Jazzy's (branch ``jazzy`` at ed360c9):
``tricycle_controller/src/tricycle_controller.cpp`` (parameters, topics, the cycle),
``tricycle_controller/src/odometry.cpp`` and the limiters (:mod:`._tricycle_limiters`).

* Parameters (``tricycle_controller_parameter.yaml``): ``traction_joint_name``, ``steering_joint_name``,
  ``wheelbase``, ``wheel_radius``, ``odom_frame_id``, ``base_frame_id``, the covariance diagonals,
  ``open_loop``, ``enable_odom_tf`` (false by default), ``odom_only_twist``, ``cmd_vel_timeout`` (integer
  milliseconds, 500), ``publish_ackermann_command``, ``velocity_rolling_window_size``, and the limits
  ``traction.{min,max}_{velocity,acceleration,deceleration,jerk}`` and
  ``steering.{min,max}_{position,velocity,acceleration}``.
* Topics: ``~/cmd_vel`` (geometry_msgs/TwistStamped), ``~/odom``, ``/tf`` with ``enable_odom_tf``.
* The cycle: the command while fresh (else zero) becomes a steering angle ``atan(w·L/v)`` and a traction speed
  ``v / (r·cos α)`` (a pure spin: ±90° and ``|w|·L/r``); the traction speed is scaled down while the steering is
  far from its target (1 within 30°, ``cos Δ`` up to 90°, 0.01 beyond), both go through the limiters and are
  written. Odometry integrates the traction wheel's measured speed and the measured steering angle
  (``v = ω·r·cos α``, ``w = ω·r·sin α / L``), or the command with ``open_loop``; ``~/odom`` and TF every cycle.

Departures: ``~/cmd_ackermann`` (ackermann_msgs/AckermannDrive, for ``publish_ackermann_command``) is not
published: gazelle has no ackermann_msgs, and says so once. A command stamped in another clock (ahead of the
controller's: wall time from a node without ``use_sim_time``) ages from its arrival, as a zero stamp does
upstream. ``~/reset_odometry`` is not served.
"""

from __future__ import annotations

import math
from collections import deque

from ...description import Pose, quat_from_rpy
from .._bus import MsgType
from .._payloads import Odometry, Transform, TransformBatch, Twist, TwistStamped
from ._controller import Controller
from ._hardware import ControlError
from ._steering_kinematics import integrate_exact
from ._tricycle_limiters import SteeringLimiter, TractionLimiter

_TRACTION_LIMITS = tuple(
    f"{m}_{k}" for k in ("velocity", "acceleration", "deceleration", "jerk") for m in ("min", "max")
)
_STEERING_LIMITS = tuple(f"{m}_{k}" for k in ("position", "velocity", "acceleration") for m in ("min", "max"))


class TricycleController(Controller):
    """One steered, driven wheel from ``~/cmd_vel`` (see the module docstring)."""

    type_name = "tricycle_controller/TricycleController"

    def on_configure(self) -> None:
        """Read the parameters (upstream's names, defaults and checks) and declare the topics."""
        self.traction = self.param("traction_joint_name", "", str)
        self.steering = self.param("steering_joint_name", "", str)
        if not self.traction or not self.steering:
            raise ControlError(f"controller '{self.name}': traction_joint_name and steering_joint_name must be set")
        self.wheelbase = self.param("wheelbase", 0.0, float)
        self.radius = self.param("wheel_radius", 0.0, float)
        if self.wheelbase <= 0 or self.radius <= 0:
            raise ControlError(
                f"controller '{self.name}': wheelbase ({self.wheelbase}) and wheel_radius ({self.radius}) must be "
                "positive"
            )
        self.odom_frame = self.param("odom_frame_id", "odom", str)
        self.base_frame = self.param("base_frame_id", "base_link", str)
        pose_cov = self.float_list("pose_covariance_diagonal", [0.0] * 6)
        twist_cov = self.float_list("twist_covariance_diagonal", [0.0] * 6)
        if len(pose_cov) != 6 or len(twist_cov) != 6:
            raise ControlError(f"controller '{self.name}': the covariance diagonals need 6 values")
        self._pose_cov = tuple(pose_cov[i // 7] if i % 7 == 0 else 0.0 for i in range(36))
        self._twist_cov = tuple(twist_cov[i // 7] if i % 7 == 0 else 0.0 for i in range(36))
        self.open_loop = self.param("open_loop", False, bool)
        self.enable_tf = self.param("enable_odom_tf", False, bool)
        self.only_twist = self.param("odom_only_twist", False, bool)
        self.timeout = self.param("cmd_vel_timeout", 500, int) / 1000.0
        self.window = max(1, self.param("velocity_rolling_window_size", 10, int))
        nan = math.nan
        self.traction_limiter = TractionLimiter(
            {k: self.param(f"traction.{k}", nan, float) for k in _TRACTION_LIMITS}, self.name
        )
        self.steering_limiter = SteeringLimiter(
            {k: self.param(f"steering.{k}", nan, float) for k in _STEERING_LIMITS}, self.name
        )
        if self.param("publish_ackermann_command", False, bool):
            self.log.warning(
                "publish_ackermann_command: ~/cmd_ackermann (ackermann_msgs/AckermannDrive) is not published: "
                "gazelle has no ackermann_msgs"
            )
        self._received: tuple[TwistStamped, float | None] | None = None
        self.subscribe("~/cmd_vel", MsgType.TWIST_STAMPED, self._on_cmd_vel)
        self._odom = self.advertise("~/odom", MsgType.ODOMETRY)
        self._tf = self.advertise("/tf", MsgType.TF, depth=100) if self.enable_tf else None
        self._reset()

    def _reset(self) -> None:
        """``reset()``: odometry at the origin, no command, the limiters' history zero."""
        self.pose = (0.0, 0.0, 0.0)
        self.linear = self.angular = 0.0
        self._v_acc: deque[float] = deque(maxlen=self.window)
        self._w_acc: deque[float] = deque(maxlen=self.window)
        self._last: tuple[float, float, float] = (0.0, 0.0, -math.inf)
        """The last command (v, w, when it counts from)."""
        self._previous = [(0.0, 0.0), (0.0, 0.0)]
        """The last two (traction speed, steering angle) written, the older first."""

    def _on_cmd_vel(self, msg: TwistStamped) -> None:
        self._received = (msg, msg.stamp_sec if msg.stamp_sec > 0 else None)

    def command_interfaces(self) -> list[str]:
        return [f"{self.traction}/velocity", f"{self.steering}/position"]

    def state_interfaces(self) -> list[str] | None:
        return [f"{self.traction}/velocity", f"{self.steering}/position"]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Going active needs both joints' interfaces (upstream's ``get_traction`` / ``get_steering``)."""
        missing = [s for s in self.state_interfaces() or [] if s not in states]
        if missing:
            raise ControlError(f"controller '{self.name}': Unable to obtain joint state handle for {missing[0]}")

    def on_deactivate(self) -> None:
        """``halt()`` is the hardware holding zero: the manager's next write after deactivation keeps the last
        command, so the old command is dropped here and the next activation starts still."""
        self._received = None
        self._last = (0.0, 0.0, -math.inf)

    def _command(self, t: float) -> tuple[float, float]:
        """The latest command while younger than ``cmd_vel_timeout``, else zero."""
        if self._received is not None:
            msg, stamp = self._received
            self._received = None
            start = stamp if stamp is not None and stamp <= t else t
            self._last = (msg.twist.linear[0], msg.twist.angular[2], start)
        v, w, start = self._last
        if t - start > self.timeout:
            return 0.0, 0.0
        return v, w

    def _twist_to_ackermann(self, v: float, w: float) -> tuple[float, float]:
        """(steering angle, traction speed in rad/s) for the twist (``twist_to_ackermann``)."""
        if v == 0 and w != 0:
            return (math.pi / 2 if w > 0 else -math.pi / 2), abs(w) * self.wheelbase / self.radius
        alpha = 0.0 if w == 0 or v == 0 else math.atan(w * self.wheelbase / v)
        return alpha, v / (self.radius * math.cos(alpha))

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle (see the module docstring)."""
        v, w = self._command(t)
        ws_read = states[f"{self.traction}/velocity"]
        alpha_read = states[f"{self.steering}/position"]
        if self.open_loop:
            self.linear, self.angular = v, w
            self.pose = integrate_exact(self.pose, v * period, w * period)
        elif math.isfinite(ws_read) and math.isfinite(alpha_read):
            speed = ws_read * self.radius
            vx, wz = speed * math.cos(alpha_read), speed * math.sin(alpha_read) / self.wheelbase
            self.pose = integrate_exact(self.pose, vx * period, wz * period)
            self._v_acc.append(vx)
            self._w_acc.append(wz)
            self.linear, self.angular = sum(self._v_acc) / len(self._v_acc), sum(self._w_acc) / len(self._w_acc)
        self._publish(t)
        alpha, ws = self._twist_to_ackermann(v, w)
        delta = abs(alpha - alpha_read)
        ws *= 1.0 if delta < math.pi / 6 else 0.01 if delta > math.pi / 2 else math.cos(delta)
        (ws1, alpha1), (ws0, alpha0) = self._previous
        ws = self.traction_limiter.limit(ws, ws0, ws1, period)
        alpha = self.steering_limiter.limit(alpha, alpha0, alpha1, period)
        self._previous = [(ws0, alpha0), (ws, alpha)]
        commands[f"{self.traction}/velocity"] = ws
        commands[f"{self.steering}/position"] = alpha

    def _publish(self, t: float) -> None:
        """``~/odom`` (only the twist with ``odom_only_twist``) and odom -> base on ``/tf``, each while wanted."""
        x, y, heading = self.pose
        pose = Pose((x, y, 0.0), quat_from_rpy(0.0, 0.0, heading))
        if self._odom.wanted:
            shown = Pose((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)) if self.only_twist else pose
            twist = Twist((self.linear, 0.0, 0.0), (0.0, 0.0, self.angular))
            self._odom.publish(
                Odometry(t, self.odom_frame, self.base_frame, shown, twist, self._pose_cov, self._twist_cov)
            )
        if self._tf is not None and self._tf.wanted:
            self._tf.publish(TransformBatch((Transform(t, self.odom_frame, self.base_frame, pose),)))

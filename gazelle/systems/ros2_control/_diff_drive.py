"""``diff_drive_controller/DiffDriveController`` with ros2_controllers Jazzy's parameters and topics.

Each control cycle (the controller manager's ``update_rate``, in sim time):

1. The latest ``~/cmd_vel`` (geometry_msgs/TwistStamped; ``~/cmd_vel_unstamped`` with Humble's
   ``use_stamped_vel: false``, kept with a warning: Jazzy has no such parameter) is the command until
   ``cmd_vel_timeout`` seconds after it arrived; then the robot is commanded to stop. Only ``linear.x``
   (m/s) and ``angular.z`` (rad/s) are read.
2. :class:`SpeedLimiter` bounds each by its ``linear.x.*`` / ``angular.z.*`` velocity, acceleration
   and jerk limits (a limit left out is not applied).
3. The wheels get ``(v ∓ ω·s/2) / r`` rad/s on their velocity command interfaces, with ``s`` the
   wheel separation and ``r`` each side's radius (times their multipliers): every wheel of a side
   gets the same command.
4. Odometry integrates the wheels' measured travel (their position interfaces, or velocity ones with
   ``position_feedback: false``; the commanded twist with ``open_loop``) along an arc, and publishes
   ``~/odom`` and, with ``enable_odom_tf``, odom -> base on ``/tf`` at ``publish_rate``.

Frames get the controller's ``tf_frame_prefix`` (its namespace by default, as in Jazzy), so two robots
in two namespaces publish ``robot1/odom`` and ``robot2/odom``.
"""

from __future__ import annotations

import math
from collections import deque

from ...description import Pose, quat_from_rpy
from .._bus import MsgType
from .._payloads import Odometry, Transform, TransformBatch, Twist, TwistStamped
from ._controller import Controller
from ._hardware import ControlError


class SpeedLimiter:
    """Velocity, acceleration and jerk limits of one axis (ros2_controllers' SpeedLimiter): a limit
    not given (NaN) is not applied; a ``min_*`` not given is ``-max_*``."""

    def __init__(self, prefix: str, controller: Controller) -> None:
        """The limits of one axis (``linear.x`` or ``angular.z``) from the controller's parameters:
        ``max_velocity``, ``max_acceleration``, ``max_jerk`` and their ``min_*`` (each group switched off by its
        ``has_*_limits``, true by default in Jazzy); a min above its max is a configure error."""

        def get(name: str) -> float:
            return controller.param(f"{prefix}.{name}", math.nan, float)

        def enabled(kind: str) -> bool:
            return controller.param(f"{prefix}.has_{kind}_limits", True, bool)

        nan = math.nan
        self.max_v, self.min_v = (get("max_velocity"), get("min_velocity")) if enabled("velocity") else (nan, nan)
        self.max_a, self.min_a = (
            (get("max_acceleration"), get("min_acceleration")) if enabled("acceleration") else (nan, nan)
        )
        self.max_j, self.min_j = (get("max_jerk"), get("min_jerk")) if enabled("jerk") else (nan, nan)
        for lo, hi in ((self.min_v, self.max_v), (self.min_a, self.max_a), (self.min_j, self.max_j)):
            if not math.isnan(lo) and not math.isnan(hi) and lo > hi:
                raise ControlError(f"controller '{controller.name}': {prefix} has a min limit above its max")
        self.min_v = -self.max_v if math.isnan(self.min_v) else self.min_v
        self.min_a = -self.max_a if math.isnan(self.min_a) else self.min_a
        self.min_j = -self.max_j if math.isnan(self.min_j) else self.min_j

    @staticmethod
    def _clamp(x: float, lo: float, hi: float) -> float:
        """``x`` within [lo, hi], a NaN bound not applied."""
        if not math.isnan(lo):
            x = max(x, lo)
        if not math.isnan(hi):
            x = min(x, hi)
        return x

    def limit(self, v: float, v0: float, v1: float, dt: float) -> float:
        """``v`` limited, given the last two outputs ``v0`` (previous) and ``v1`` (before it): first to the
        velocity bounds, then the change from ``v0`` to what the acceleration allows in ``dt``, then the
        change of that change to what the jerk allows (the order ros2_controllers' SpeedLimiter uses)."""
        v = self._clamp(v, self.min_v, self.max_v)
        if dt > 0:
            dv = self._clamp(v - v0, self.min_a * dt, self.max_a * dt)
            v = v0 + dv
            if not math.isnan(self.max_j) or not math.isnan(self.min_j):
                dv0 = v0 - v1
                ddv = self._clamp(dv - dv0, self.min_j * dt * dt, self.max_j * dt * dt)
                v = v0 + dv0 + ddv
        return v


class DiffDriveController(Controller):
    """Drives wheel velocity interfaces from ``~/cmd_vel`` and publishes ``~/odom`` and odom→base on ``/tf``."""

    type_name = "diff_drive_controller/DiffDriveController"

    def on_configure(self) -> None:
        """Read the parameters (Jazzy's names and defaults) and declare the topics; a missing wheel list, a
        non-positive separation or radius, or a covariance of the wrong length fails the configure with a
        message naming the parameter, as the controller manager reports it."""
        self.left = self.string_list("left_wheel_names")
        self.right = self.string_list("right_wheel_names")
        if not self.left or not self.right:
            raise ControlError(f"controller '{self.name}': left_wheel_names and right_wheel_names must not be empty")
        if len(self.left) != len(self.right):
            raise ControlError(f"controller '{self.name}': as many left wheels as right wheels are needed")
        self.separation = self.param("wheel_separation", 0.0, float)
        self.radius = self.param("wheel_radius", 0.0, float)
        if self.separation <= 0 or self.radius <= 0:
            raise ControlError(
                f"controller '{self.name}': wheel_separation ({self.separation}) and wheel_radius "
                f"({self.radius}) must be positive"
            )
        self.sep_mult = self.param("wheel_separation_multiplier", 1.0, float)
        self.left_mult = self.param("left_wheel_radius_multiplier", 1.0, float)
        self.right_mult = self.param("right_wheel_radius_multiplier", 1.0, float)
        self.open_loop = self.param("open_loop", False, bool)
        self.position_feedback = self.param("position_feedback", True, bool)
        self.enable_tf = self.param("enable_odom_tf", True, bool)
        self.timeout = self.param("cmd_vel_timeout", 0.5, float)
        self.publish_limited = self.param("publish_limited_velocity", False, bool)
        self.window = max(1, self.param("velocity_rolling_window_size", 10, int))
        self.publish_rate = self.param("publish_rate", 50.0, float)
        self.pose_cov = self.float_list("pose_covariance_diagonal", [0.0] * 6)
        self.twist_cov = self.float_list("twist_covariance_diagonal", [0.0] * 6)
        if len(self.pose_cov) != 6 or len(self.twist_cov) != 6:
            raise ControlError(f"controller '{self.name}': the covariance diagonals need 6 values")
        prefix = ""
        if self.param("tf_frame_prefix_enable", True, bool):
            prefix = self.param("tf_frame_prefix", "", str) or self.ctx.namespace.strip("/")
            prefix = f"{prefix.strip('/')}/" if prefix.strip("/") else ""
        self.odom_frame = prefix + self.param("odom_frame_id", "odom", str)
        self.base_frame = prefix + self.param("base_frame_id", "base_link", str)
        self.linear = SpeedLimiter("linear.x", self)
        self.angular = SpeedLimiter("angular.z", self)
        stamped = self.param("use_stamped_vel", True, bool)
        if not stamped:
            # ros2_controllers removed the parameter in 4.0.0, Jazzy's first release ("Remove non-stamped Twist
            # option", #812): on a real Jazzy robot this YAML's controller listens to ~/cmd_vel (TwistStamped)
            # only. gazelle keeps Humble's unstamped topic so the file runs unchanged, and says so once
            self.log.warning(
                "use_stamped_vel: false is Humble's: Jazzy's diff_drive_controller has no such parameter and "
                "takes geometry_msgs/TwistStamped on ~/cmd_vel only; gazelle listens on ~/cmd_vel_unstamped "
                "(geometry_msgs/Twist) as Humble did"
            )
        self._cmd: tuple[Twist, float | None] | None = None
        """(twist, header stamp or None) as received; its arrival time is taken at the next cycle."""
        if stamped:
            self.subscribe("~/cmd_vel", MsgType.TWIST_STAMPED, self._on_stamped)
        else:
            self.subscribe("~/cmd_vel_unstamped", MsgType.TWIST, self._on_twist)
        self._odom = self.advertise("~/odom", MsgType.ODOMETRY)
        self._tf = self.advertise("/tf", MsgType.TF, depth=100) if self.enable_tf else None
        self._limited = self.advertise("~/cmd_vel_out", MsgType.TWIST_STAMPED) if self.publish_limited else None
        self._reset_state()

    def _reset_state(self) -> None:
        """Odometry at the origin, no command, the limiter's history and the velocity windows empty, publishing due
        at once."""
        self.x = self.y = self.heading = 0.0
        self.v = self.w = 0.0
        self._last_cmd: tuple[Twist, float] | None = None
        self._prev = [(0.0, 0.0), (0.0, 0.0)]
        """The last two limited (linear, angular) outputs."""
        self._wheel_pos: tuple[float, float] | None = None
        self._v_hist: deque[float] = deque(maxlen=self.window)
        self._w_hist: deque[float] = deque(maxlen=self.window)
        self._next_publish = -math.inf

    def _on_stamped(self, msg: TwistStamped) -> None:
        self._cmd = (msg.twist, msg.stamp_sec if msg.stamp_sec > 0 else None)

    def _on_twist(self, msg: Twist) -> None:
        self._cmd = (msg, None)

    def command_interfaces(self) -> list[str]:
        return [f"{w}/velocity" for w in (*self.left, *self.right)]

    def state_interfaces(self) -> list[str] | None:
        kind = "position" if self.position_feedback else "velocity"
        return [f"{w}/{kind}" for w in (*self.left, *self.right)]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Going active needs every wheel's feedback state interface; the odometry starts again at the origin and no
        old command is kept."""
        missing = [s for s in self.state_interfaces() or [] if s not in states]
        if missing:
            raise ControlError(f"controller '{self.name}': the hardware has no state interface {', '.join(missing)}")
        self._reset_state()
        self._cmd = None

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle (see the module docstring): the command while it is fresh (else stop), limited, as wheel
        speeds; then odometry, the limited command on ``~/cmd_vel_out`` when asked, and ``~/odom`` and TF at
        their rate."""
        cmd = self._cmd
        if cmd is not None:
            self._cmd = None
            # the command's age counts from when it arrived (its header stamp may be in another clock)
            self._last_cmd = (cmd[0], t)
        twist = Twist()
        if self._last_cmd is not None and t - self._last_cmd[1] <= self.timeout:
            twist = self._last_cmd[0]
        # limits
        (v0, w0), (v1, w1) = self._prev
        lin = self.linear.limit(twist.linear[0], v0, v1, period)
        ang = self.angular.limit(twist.angular[2], w0, w1, period)
        self._prev = [(lin, ang), (v0, w0)]
        sep = self.separation * self.sep_mult
        r_l, r_r = self.radius * self.left_mult, self.radius * self.right_mult
        # each side's rim speed is v ∓ ω·s/2 (left slower when turning left, ω > 0); over its radius, rad/s
        vl, vr = (lin - ang * sep / 2.0) / r_l, (lin + ang * sep / 2.0) / r_r
        for w in self.left:
            commands[f"{w}/velocity"] = vl
        for w in self.right:
            commands[f"{w}/velocity"] = vr
        self._odometry(t, period, states, lin, ang, sep, r_l, r_r)
        if self._limited is not None and self._limited.wanted:
            self._limited.publish(TwistStamped(t, self.base_frame, Twist((lin, 0.0, 0.0), (0.0, 0.0, ang))))
        self._publish(t)

    def _odometry(
        self, t: float, dt: float, states: dict[str, float], lin: float, ang: float, sep: float, r_l: float, r_r: float
    ) -> None:
        """Integrate this cycle's motion into the pose: from the wheels' positions (the travel since the last
        cycle), their velocities, or the command itself (``open_loop``). The twist published is the mean over the
        rolling window; the pose integrates each cycle's own motion along its arc."""
        # As ros2_controllers' odometry.cpp (jazzy, Odometry::update/updateFromVelocity): the pose
        # integrates this cycle's displacement; only the published twist is the rolling mean of the
        # last `velocity_rolling_window_size` cycles (integrating the mean lagged the pose by half the
        # window: 0.5 s at Husky's 10 Hz, 0.165 m short after 2 m).
        if self.open_loop:
            v, w = lin, ang
            mean_v, mean_w = v, w
        else:
            if self.position_feedback:
                pl = sum(states[f"{n}/position"] for n in self.left) / len(self.left)
                pr = sum(states[f"{n}/position"] for n in self.right) / len(self.right)
                last = self._wheel_pos
                self._wheel_pos = (pl, pr)
                if last is None or dt <= 0:
                    return
                dl, dr = (pl - last[0]) * r_l, (pr - last[1]) * r_r
                v, w = (dl + dr) / 2.0 / dt, (dr - dl) / sep / dt
            else:
                ql = sum(states[f"{n}/velocity"] for n in self.left) / len(self.left) * r_l
                qr = sum(states[f"{n}/velocity"] for n in self.right) / len(self.right) * r_r
                v, w = (ql + qr) / 2.0, (qr - ql) / sep
            self._v_hist.append(v)
            self._w_hist.append(w)
            mean_v, mean_w = sum(self._v_hist) / len(self._v_hist), sum(self._w_hist) / len(self._w_hist)
        # exact integration along the arc (second-order Runge-Kutta when turning slowly)
        dth = w * dt
        if abs(dth) < 1e-6:
            mid = self.heading + dth / 2.0
            self.x += v * dt * math.cos(mid)
            self.y += v * dt * math.sin(mid)
        else:
            r = v / w
            self.x += r * (math.sin(self.heading + dth) - math.sin(self.heading))
            self.y -= r * (math.cos(self.heading + dth) - math.cos(self.heading))
        self.heading += dth
        self.v, self.w = mean_v, mean_w

    def _publish(self, t: float) -> None:
        """At ``publish_rate`` (every cycle when 0): ``~/odom`` with the covariance diagonals, and odom -> base on
        ``/tf``, each while it has a subscriber."""
        if self.publish_rate > 0:
            if t + 1e-9 < self._next_publish:
                return
            period = 1.0 / self.publish_rate
            self._next_publish = (math.floor(t / period + 1e-6) + 1) * period
        pose = Pose((self.x, self.y, 0.0), quat_from_rpy(0.0, 0.0, self.heading))  # planar: z, roll, pitch 0
        if self._odom.wanted:
            # the parameters give the diagonals of the 6x6 covariances; row-major, so element i·6 + i
            pc, tc = [0.0] * 36, [0.0] * 36
            for i in range(6):
                pc[7 * i], tc[7 * i] = self.pose_cov[i], self.twist_cov[i]
            self._odom.publish(
                Odometry(
                    t,
                    self.odom_frame,
                    self.base_frame,
                    pose,
                    Twist((self.v, 0.0, 0.0), (0.0, 0.0, self.w)),
                    tuple(pc),
                    tuple(tc),
                )
            )
        if self._tf is not None and self._tf.wanted:
            self._tf.publish(TransformBatch((Transform(t, self.odom_frame, self.base_frame, pose),)))

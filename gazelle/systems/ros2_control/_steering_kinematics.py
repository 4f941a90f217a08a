"""The steering controllers' kinematics and odometry, as ros2_controllers Jazzy's steering_controllers_library
computes them (``steering_controllers_library/src/steering_kinematics.cpp``, branch ``jazzy`` at ed360c9).

Odometry integrates the base's forward speed and yaw rate exactly along the arc (second-order Runge-Kutta
when the heading barely changes); the published twist is the rolling mean of the last
``velocity_rolling_window_size`` speeds. The inverse kinematics turn a (linear, angular) reference into
wheel speeds and steering angles for the bicycle, tricycle and Ackermann configurations. A pair of
traction or steering joints is ordered (right, left), as the library expects its joint lists.
"""

from __future__ import annotations

import math
from collections import deque

BICYCLE, TRICYCLE, ACKERMANN = "bicycle", "tricycle", "ackermann"
"""The kinematic configurations (steering_kinematics.hpp's BICYCLE_CONFIG, TRICYCLE_CONFIG, ACKERMANN_CONFIG)."""


def close_to_zero(value: float) -> bool:
    """steering_kinematics.hpp's ``is_close_to_zero``."""
    return abs(value) < 1e-6


def integrate_exact(pose: tuple[float, float, float], linear: float, angular: float) -> tuple[float, float, float]:
    """``pose`` (x, y, heading) moved by ``linear`` metres forward while turning ``angular`` radians: exactly along
    the arc, or by second-order Runge-Kutta when the turn is close to zero (``integrate_fk``; tricycle_controller's
    odometry.cpp ``integrateExact`` is the same)."""
    x, y, heading = pose
    if close_to_zero(angular):
        mid = heading + angular * 0.5
        return x + linear * math.cos(mid), y + linear * math.sin(mid), heading + angular
    r = linear / angular
    new_heading = heading + angular
    return (
        x + r * (math.sin(new_heading) - math.sin(heading)),
        y - r * (math.cos(new_heading) - math.cos(heading)),
        new_heading,
    )


class SteeringKinematics:
    """steering_kinematics.cpp's SteeringKinematics: odometry from the wheels (or the command) and the commands
    for a reference twist."""

    def __init__(self, config: str, radius: float, wheelbase: float, track_steering: float, track_traction: float):
        self.config = config
        self.radius = radius
        self.wheelbase = wheelbase
        self.track_steering = track_steering
        self.track_traction = track_traction
        self.window = 10
        self.reset()

    def reset(self) -> None:
        """Odometry at the origin, the velocity windows empty, the last wheel positions zero (``reset_odometry``)."""
        self.pose = (0.0, 0.0, 0.0)
        self.linear = self.angular = 0.0
        self.steer_pos = 0.0
        self._linear_acc: deque[float] = deque(maxlen=self.window)
        self._angular_acc: deque[float] = deque(maxlen=self.window)
        self._old_pos = (0.0, 0.0)

    def set_window(self, size: int) -> None:
        """``set_velocity_rolling_window_size``."""
        self.window = max(1, size)
        self._linear_acc = deque(maxlen=self.window)
        self._angular_acc = deque(maxlen=self.window)

    def _update(self, linear: float, angular: float, dt: float) -> None:
        """``update_odometry``: integrate; below 0.1 ms the speeds are not estimated."""
        self.pose = integrate_exact(self.pose, linear * dt, angular * dt)
        if dt < 0.0001:
            return
        self._linear_acc.append(linear)
        self._angular_acc.append(angular)
        self.linear = sum(self._linear_acc) / len(self._linear_acc)
        self.angular = sum(self._angular_acc) / len(self._angular_acc)

    def update_open_loop(self, linear: float, angular: float, dt: float) -> None:
        """``update_open_loop``: the command is the motion."""
        self.linear, self.angular = linear, angular
        self.pose = integrate_exact(self.pose, linear * dt, angular * dt)

    def _double_axle_linear(self, right_vel: float, left_vel: float, steer: float) -> float:
        """``get_linear_velocity_double_traction_axle``: each traction wheel's rim speed brought to the axle's middle
        by the turning radius, then averaged."""
        vr, vl = right_vel * self.radius, left_vel * self.radius
        tan = math.tan(steer)
        if tan == 0.0:
            return (vr + vl) * 0.5
        turning = self.wheelbase / tan
        half = self.track_traction * 0.5
        return (vr * turning / (turning + half) + vl * turning / (turning - half)) * 0.5

    def update_from_velocity(self, traction: list[float], steering: list[float], dt: float) -> None:
        """``update_from_velocity`` for the configuration: traction wheel speeds (rad/s) and steering positions (rad),
        each list (right, left) when there are two."""
        if len(steering) == 2:
            right, left = steering
            half = self.track_steering / 2
            wb = self.wheelbase
            right_est = math.atan(wb * math.tan(right) / (wb - half * math.tan(right)))
            left_est = math.atan(wb * math.tan(left) / (wb + half * math.tan(left)))
            self.steer_pos = (right_est + left_est) * 0.5
        else:
            self.steer_pos = steering[0]
        if len(traction) == 2:
            linear = self._double_axle_linear(traction[0], traction[1], self.steer_pos)
        else:
            linear = traction[0] * self.radius
        self._update(linear, math.tan(self.steer_pos) * linear / self.wheelbase, dt)

    def update_from_position(self, traction: list[float], steering: list[float], dt: float) -> None:
        """``update_from_position``: the traction wheels' travel since the last cycle, as speeds."""
        old = self._old_pos
        speeds = [(p - old[i]) / dt for i, p in enumerate(traction)]
        self._old_pos = (traction[0], traction[-1])
        self.update_from_velocity(speeds, steering, dt)

    def commands(
        self, v: float, w: float, open_loop: bool, reduce_until_steered: bool
    ) -> tuple[list[float], list[float]]:
        """``get_commands``: (traction wheel speeds in rad/s, steering angles in rad) for a reference of ``v`` m/s
        and ``w`` rad/s, the wheels' speeds split by the turning radius of the measured steering angle (the
        commanded one with ``open_loop``)."""
        phi = math.atan(w * self.wheelbase / v) if v != 0.0 else math.copysign(math.pi / 2, w) if w != 0.0 else 0.0
        if not math.isfinite(phi):
            phi = 0.0
        phi_ik = phi if open_loop else self.steer_pos
        ws = v / self.radius
        if not open_loop and reduce_until_steered:
            delta = abs(self.steer_pos - phi)
            low = math.pi / 6.0
            if delta >= low:
                ws *= math.cos(min(delta, 1.5608)) / math.cos(low)
        if self.config == BICYCLE:
            return [ws], [phi]
        if close_to_zero(phi_ik):
            traction = [ws, ws]
        else:
            turning = self.wheelbase / math.tan(phi_ik)
            half = self.track_traction * 0.5
            traction = [ws * (turning + half) / turning, ws * (turning - half) / turning]
        if self.config == TRICYCLE:
            return traction, [phi]
        if close_to_zero(phi_ik):
            return traction, [phi, phi]
        num = 2 * self.wheelbase * math.sin(phi)
        den, side = 2 * self.wheelbase * math.cos(phi), self.track_steering * math.sin(phi)
        return traction, [math.atan2(num, den + side), math.atan2(num, den - side)]

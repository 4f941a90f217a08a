"""tricycle_controller's rate limiters, as ros2_controllers Jazzy's (branch ``jazzy`` at ed360c9):
``tricycle_controller/src/traction_limiter.cpp`` and ``steering_limiter.cpp``.

Each limit is given as a positive pair (min, max) of magnitudes applied in both directions; a pair with one
side given gets the other from upstream's defaults (a missing max is 1000, a missing min 0, a missing
position bound the other's negative); a pair not given at all is not applied. A negative limit, or a min
above its max, is a configure error with upstream's words.
"""

from __future__ import annotations

import math

from ._hardware import ControlError

_BIG = 1000.0
"""Upstream's "arbitrarily big number" for a max not given beside a given min."""


def _pair(lo: float, hi: float, what: str, name: str, check_order: bool) -> tuple[float, float]:
    """A (min, max) magnitude pair completed as upstream completes it, and checked."""
    if not math.isnan(lo) and math.isnan(hi):
        hi = _BIG
    if not math.isnan(hi) and math.isnan(lo):
        lo = 0.0
    if lo < 0 or hi < 0:
        raise ControlError(
            f"controller '{name}': {what} cannot be negative. The positive limit will be applied to both directions."
        )
    if check_order and lo > hi:
        raise ControlError(f"controller '{name}': min {what.lower()} cannot be greater than max {what.lower()}")
    return lo, hi


def _clamp_magnitude(change: float, lo: float, hi: float) -> float:
    """``change`` with its magnitude clamped to [lo, hi], its sign kept (a zero change counts as positive)."""
    return min(max(abs(change), lo), hi) * (1.0 if change >= 0 else -1.0)


class TractionLimiter:
    """TractionLimiter: the traction wheel's speed (rad/s), its acceleration and deceleration, and its jerk."""

    def __init__(self, limits: dict[str, float], name: str) -> None:
        """``limits``: ``min_velocity`` ... ``max_jerk`` (NaN when not given)."""

        def pair(kind: str, what: str) -> tuple[float, float]:
            return _pair(limits[f"min_{kind}"], limits[f"max_{kind}"], what, name, True)

        self.velocity = pair("velocity", "Velocity")
        self.acceleration = pair("acceleration", "Acceleration")
        self.deceleration = pair("deceleration", "Deceleration")
        self.jerk = pair("jerk", "Jerk")

    def limit(self, v: float, v0: float, v1: float, dt: float) -> float:
        """``v`` limited given the last two outputs ``v0`` and ``v1``: jerk, then acceleration (deceleration when
        the speed's magnitude falls), then velocity, in upstream's order."""
        if not math.isnan(self.jerk[0]):
            dv0 = v0 - v1
            dt2 = 2.0 * dt * dt
            v = v0 + dv0 + _clamp_magnitude((v - v0) - dv0, self.jerk[0] * dt2, self.jerk[1] * dt2)
        lo, hi = self.acceleration if abs(v) >= abs(v0) else self.deceleration
        if not math.isnan(lo):
            v = v0 + _clamp_magnitude(v - v0, lo * dt, hi * dt)
        if not math.isnan(self.velocity[0]):
            v = _clamp_magnitude(v, *self.velocity)
        return v


class SteeringLimiter:
    """SteeringLimiter: the steering angle (rad), its rate and its acceleration."""

    def __init__(self, limits: dict[str, float], name: str) -> None:
        """``limits``: ``min_position`` ... ``max_acceleration`` (NaN when not given)."""
        lo, hi = limits["min_position"], limits["max_position"]
        if not math.isnan(lo) and math.isnan(hi):
            hi = -lo
        if not math.isnan(hi) and math.isnan(lo):
            lo = -hi
        self.position = (lo, hi)
        self.velocity = _pair(limits["min_velocity"], limits["max_velocity"], "Velocity", name, False)
        self.acceleration = _pair(limits["min_acceleration"], limits["max_acceleration"], "Acceleration", name, False)

    def limit(self, p: float, p0: float, p1: float, dt: float) -> float:
        """``p`` limited given the last two outputs: acceleration, then rate, then the position bounds."""
        if not math.isnan(self.acceleration[0]):
            dp0 = p0 - p1
            dt2 = 2.0 * dt * dt
            p = p0 + dp0 + _clamp_magnitude((p - p0) - dp0, self.acceleration[0] * dt2, self.acceleration[1] * dt2)
        if not math.isnan(self.velocity[0]):
            p = p0 + _clamp_magnitude(p - p0, self.velocity[0] * dt, self.velocity[1] * dt)
        if not math.isnan(self.position[0]):
            p = min(max(p, self.position[0]), self.position[1])
        return p

"""The control term of the prediction (robot_localization's ``use_control``): the last commanded body twist,
turned into an acceleration towards it, limited and scaled by its gains (``FilterBase::prepareControl`` and
``computeControlAcceleration``, read for their behaviour)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

TWIST_CONTROLS = 6
"""vx, vy, vz, vroll, vpitch, vyaw."""


def control_acceleration(
    state: float, command: float, limit: float, gain: float, brake_limit: float, brake_gain: float
) -> float:
    """The acceleration that brings a velocity ``state`` towards ``command``: ``gain * error`` clipped to
    ``+-limit``; when the velocity must shrink in magnitude (the robot slows, or the command reverses it),
    the deceleration limit and gain apply instead. A command whose sign differs from the velocity's by more
    than 0.01 aims at 0 first (upstream's ``same_sign`` test)."""
    error = command - state
    same_sign = abs(error) <= abs(command) + 0.01
    set_point = command if same_sign else 0.0
    if abs(set_point) < abs(state):
        limit, gain = brake_limit, brake_gain
    return min(max(gain * error, -limit), limit)


@dataclass
class ControlSettings:
    """``control_config`` (which of the six body velocities are commanded), ``control_timeout`` and the
    acceleration and deceleration limits and gains, six each."""

    update: tuple[bool, ...] = (False,) * TWIST_CONTROLS
    timeout_ns: int = 0
    acceleration_limits: tuple[float, ...] = (1.0,) * TWIST_CONTROLS
    acceleration_gains: tuple[float, ...] = (1.0,) * TWIST_CONTROLS
    deceleration_limits: tuple[float, ...] = (1.0,) * TWIST_CONTROLS
    deceleration_gains: tuple[float, ...] = (1.0,) * TWIST_CONTROLS
    latest: np.ndarray = field(default_factory=lambda: np.zeros(TWIST_CONTROLS))
    """The last command (body twist)."""
    latest_ns: int = 0
    """Its time on the node's clock."""

    def accelerations(self, velocities: np.ndarray, now_ns: int) -> np.ndarray:
        """The six control accelerations at ``now_ns`` for the body ``velocities``: 0 for an axis not
        controlled; a command older than the timeout counts as a command to stop."""
        timed_out = now_ns - self.latest_ns >= self.timeout_ns
        out = np.zeros(TWIST_CONTROLS)
        for i in range(TWIST_CONTROLS):
            if self.update[i]:
                out[i] = control_acceleration(
                    float(velocities[i]),
                    0.0 if timed_out else float(self.latest[i]),
                    self.acceleration_limits[i],
                    self.acceleration_gains[i],
                    self.deceleration_limits[i],
                    self.deceleration_gains[i],
                )
        return out

"""The filter's state layout and one measurement of it (robot_localization's ``filter_common.hpp`` and
``measurement.hpp``, read for their layout)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

STATE_SIZE = 15
"""x, y, z, roll, pitch, yaw, vx, vy, vz, vroll, vpitch, vyaw, ax, ay, az: a pose in the world frame, the twist
and the linear acceleration in the body frame (REP-103 units: m, rad, m/s, rad/s, m/s^2)."""
X, Y, Z, ROLL, PITCH, YAW, VX, VY, VZ, VROLL, VPITCH, VYAW, AX, AY, AZ = range(STATE_SIZE)
STATE_NAMES = tuple(
    "X Y Z ROLL PITCH YAW X_VELOCITY Y_VELOCITY Z_VELOCITY ROLL_VELOCITY PITCH_VELOCITY YAW_VELOCITY "
    "X_ACCELERATION Y_ACCELERATION Z_ACCELERATION".split()
)
"""robot_localization's names of the state variables, as its messages and ours name them."""
POSE = slice(0, 6)
TWIST = slice(6, 12)
ACCELERATION = slice(12, 15)
ANGLES = (ROLL, PITCH, YAW)
TWO_D_ZEROED = (Z, ROLL, PITCH, VZ, VROLL, VPITCH, AZ)
"""The variables ``two_d_mode`` measures as 0 with every measurement (``forceTwoD``)."""
TWO_D_VARIANCE = 1e-6
"""The variance those zero measurements carry."""
NO_THRESHOLD = math.inf
"""A rejection threshold that rejects nothing (robot_localization's default, ``numeric_limits::max()``)."""


@dataclass
class Measurement:
    """One sensor reading as the filter fuses it: full-size vectors, of which ``update`` selects the
    variables (the rest are ignored), stamped with the reading's time (ns of the node's clock)."""

    topic: str
    """The sensor part it came from (``odom0_twist``, ``imu0_pose``...)."""
    time_ns: int
    values: np.ndarray = field(default_factory=lambda: np.zeros(STATE_SIZE))
    covariance: np.ndarray = field(default_factory=lambda: np.zeros((STATE_SIZE, STATE_SIZE)))
    update: np.ndarray = field(default_factory=lambda: np.zeros(STATE_SIZE, dtype=bool))
    rejection_threshold: float = NO_THRESHOLD
    """In standard deviations (a Mahalanobis distance): a measurement further from the state is not fused."""

    def force_two_d(self) -> None:
        """``two_d_mode``: z, roll, pitch, their rates and az are measured as 0 with variance 1e-6 (the
        off-diagonal covariances are left as they are, as upstream leaves them)."""
        for i in TWO_D_ZEROED:
            self.values[i] = 0.0
            self.covariance[i, i] = TWO_D_VARIANCE
            self.update[i] = True

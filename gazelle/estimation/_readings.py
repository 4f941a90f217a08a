"""Sensor readings as plain values (what ``gazelle.ros`` takes out of nav_msgs/Odometry, sensor_msgs/Imu,
PoseWithCovarianceStamped and TwistWithCovarianceStamped): stamps in ns of the node's clock, vectors as
tuples, covariances as row-major matrices."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._rigid import Rigid

UNKNOWN_COVARIANCE = -1.0
"""sensor_msgs/Imu: a first covariance element of -1 says the field is not measured."""


@dataclass(frozen=True)
class PoseReading:
    """A pose with its 6x6 covariance (x, y, z, rotations about X, Y, Z), in ``frame``."""

    stamp_ns: int
    frame: str
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    orientation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    """(x, y, z, w)."""
    covariance: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))


@dataclass(frozen=True)
class TwistReading:
    """A twist with its 6x6 covariance (vx, vy, vz, rates about X, Y, Z), in ``frame``."""

    stamp_ns: int
    frame: str
    linear: tuple[float, float, float] = (0.0, 0.0, 0.0)
    angular: tuple[float, float, float] = (0.0, 0.0, 0.0)
    covariance: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))


@dataclass(frozen=True)
class ImuReading:
    """sensor_msgs/Imu: orientation (world-referenced, of the sensor), angular velocity and linear
    acceleration in the sensor's ``frame``, each with a 3x3 covariance whose [0, 0] is -1 when not measured."""

    stamp_ns: int
    frame: str
    orientation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    orientation_covariance: np.ndarray = field(default_factory=lambda: np.zeros((3, 3)))
    angular_velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    angular_velocity_covariance: np.ndarray = field(default_factory=lambda: np.zeros((3, 3)))
    linear_acceleration: tuple[float, float, float] = (0.0, 0.0, 0.0)
    linear_acceleration_covariance: np.ndarray = field(default_factory=lambda: np.zeros((3, 3)))

    def pose(self) -> PoseReading:
        """The orientation as a pose reading (its covariance in the rotation block)."""
        cov = np.zeros((6, 6))
        cov[3:6, 3:6] = self.orientation_covariance
        return PoseReading(self.stamp_ns, self.frame, orientation=self.orientation, covariance=cov)

    def twist(self) -> TwistReading:
        """The angular velocity as a twist reading."""
        cov = np.zeros((6, 6))
        cov[3:6, 3:6] = self.angular_velocity_covariance
        return TwistReading(self.stamp_ns, self.frame, angular=self.angular_velocity, covariance=cov)


def measured(covariance: np.ndarray) -> bool:
    """False for an Imu field whose covariance starts with -1 (REP-145: the sensor does not give it)."""
    return abs(float(covariance[0, 0]) - UNKNOWN_COVARIANCE) >= 1e-9


@dataclass(frozen=True)
class FilterOutput:
    """What one cycle of the node publishes: the state and covariance at ``stamp_ns`` (the filter's last
    measurement time) in ``frame`` with ``child`` the body, the transform to broadcast (parent, child, pose;
    None when there is none to send) and, with ``publish_acceleration``, the body acceleration (linear from
    the state, angular from the rates' change) with its 6x6 covariance."""

    stamp_ns: int
    frame: str
    child: str
    state: np.ndarray
    covariance: np.ndarray
    transform: tuple[str, str, Rigid] | None = None
    acceleration: tuple[np.ndarray, np.ndarray] | None = None
    """(ax, ay, az, angular x, y, z), 6x6 covariance."""

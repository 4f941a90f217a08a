"""One input of the filter as its parameters configure it (``odom0``, ``imu0``, ``pose0``, ``twist0``...), and
which state variables each part of its messages updates (``RosFilter::loadParams``, read for its behaviour)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._measurement import STATE_SIZE

KINDS = ("odom", "pose", "twist", "imu")
"""The input kinds, in the order robot_localization reads them: nav_msgs/Odometry,
geometry_msgs/PoseWithCovarianceStamped, geometry_msgs/TwistWithCovarianceStamped, sensor_msgs/Imu."""


def _only(config: tuple[bool, ...], keep: slice) -> np.ndarray:
    """``config`` with every variable outside ``keep`` switched off."""
    out = np.zeros(STATE_SIZE, dtype=bool)
    out[keep] = np.asarray(config, dtype=bool)[keep]
    return out


def _without(config: tuple[bool, ...], drop: slice) -> np.ndarray:
    """``config`` with the variables in ``drop`` switched off."""
    out = np.asarray(config, dtype=bool).copy()
    out[drop] = False
    return out


@dataclass(frozen=True)
class SensorConfig:
    """An input: its parameter name (``odom0``), kind, topic and ``<name>_*`` settings."""

    name: str
    kind: str
    topic: str
    config: tuple[bool, ...] = (False,) * STATE_SIZE
    """``<name>_config``: x, y, z, roll, pitch, yaw, vx, vy, vz, vroll, vpitch, vyaw, ax, ay, az."""
    differential: bool = False
    """``<name>_differential``: consecutive poses are fused as the velocity between them."""
    relative: bool = False
    """``<name>_relative``: poses are taken relative to the input's first."""
    queue_size: int = 10
    """``<name>_queue_size``: the depth of its subscription."""
    pose_threshold: float = math.inf
    """The pose part's rejection threshold, in standard deviations (inf: none)."""
    twist_threshold: float = math.inf
    """The twist part's rejection threshold."""
    acceleration_threshold: float = math.inf
    """An IMU's linear acceleration's rejection threshold."""
    remove_gravity: bool = False
    """``imu<N>_remove_gravitational_acceleration``."""

    def pose_update(self) -> np.ndarray:
        """The variables the pose part updates: an odometry's config without its twist (its accelerations are
        kept, as upstream keeps them: they are measured as 0); a pose's pose only; an IMU's orientation only."""
        if self.kind == "odom":
            return _without(self.config, slice(6, 12))
        if self.kind == "pose":
            return _only(self.config, slice(0, 6))
        if self.kind == "imu":
            return _only(self.config, slice(3, 6))
        return np.zeros(STATE_SIZE, dtype=bool)

    def twist_update(self) -> np.ndarray:
        """The variables the twist part updates: an odometry's or a twist's config without its pose (the
        accelerations kept, as upstream keeps them); an IMU's angular velocity only."""
        if self.kind in ("odom", "twist"):
            return _without(self.config, slice(0, 6))
        if self.kind == "imu":
            return _only(self.config, slice(9, 12))
        return np.zeros(STATE_SIZE, dtype=bool)

    def acceleration_update(self) -> np.ndarray:
        """The variables an IMU's linear acceleration updates (ax, ay, az)."""
        if self.kind == "imu":
            return _only(self.config, slice(12, 15))
        return np.zeros(STATE_SIZE, dtype=bool)

    def updates_anything(self) -> bool:
        """False when every part's update vector is empty (upstream then does not subscribe)."""
        return bool(self.pose_update().any() or self.twist_update().any() or self.acceleration_update().any())

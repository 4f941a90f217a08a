"""Rigid transforms and the angle conventions robot_localization uses (tf2's): roll, pitch and yaw are the
fixed-axis X, Y, Z rotations, ``R = Rz(yaw) Ry(pitch) Rx(roll)``; quaternions are (x, y, z, w) as ROS
messages carry them; angles are wrapped into [-pi, pi)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

Vector = np.ndarray
"""A float64 array of shape (3,)."""


def normalize_angle(angle: float) -> float:
    """``angle`` wrapped into [-pi, pi) (the angles package's ``normalize_angle``, which the filter applies to its
    roll, pitch and yaw and to every angular innovation)."""
    wrapped = math.fmod(angle + math.pi, 2.0 * math.pi)
    if wrapped < 0.0:  # fmod keeps the dividend's sign
        wrapped += 2.0 * math.pi
    return wrapped - math.pi


def rotation_x(a: float) -> np.ndarray:
    """The rotation about X by ``a`` radians."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rotation_y(a: float) -> np.ndarray:
    """The rotation about Y by ``a`` radians."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def rotation_z(a: float) -> np.ndarray:
    """The rotation about Z by ``a`` radians."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rotation_from_rpy(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """tf2's ``Matrix3x3::setRPY``: yaw about Z, then pitch about Y, then roll about X, all fixed axes."""
    return rotation_z(yaw) @ rotation_y(pitch) @ rotation_x(roll)


def rpy_from_rotation(r: np.ndarray) -> tuple[float, float, float]:
    """(roll, pitch, yaw) of a rotation matrix, pitch in [-pi/2, pi/2] (tf2's ``getRPY``). At gimbal lock
    (pitch = +-pi/2) the yaw is 0 and the whole rotation about the vertical is given as roll."""
    # the bottom row of Rz Ry Rx is (-sin p, cos p sin r, cos p cos r); the first column (cos y cos p,
    # sin y cos p, -sin p)
    sin_pitch = -float(r[2, 0])
    if abs(sin_pitch) >= 1.0 - 1e-12:
        # cos p = 0: roll and yaw turn about the same axis; the first row gives their combination
        sign = math.copysign(1.0, sin_pitch)
        return math.atan2(sign * float(r[0, 1]), sign * float(r[0, 2])), sign * math.pi / 2.0, 0.0
    pitch = math.asin(sin_pitch)
    roll = math.atan2(float(r[2, 1]), float(r[2, 2]))
    yaw = math.atan2(float(r[1, 0]), float(r[0, 0]))
    return roll, pitch, yaw


def rotation_from_quaternion(x: float, y: float, z: float, w: float) -> np.ndarray:
    """The rotation of a unit quaternion (x, y, z, w)."""
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """(x, y, z, w) of tf2's ``Quaternion::setRPY`` (the same rotation as :func:`rotation_from_rpy`)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def quaternion_from_rotation(r: np.ndarray) -> tuple[float, float, float, float]:
    """(x, y, z, w) of a rotation matrix, w >= 0."""
    return quaternion_from_rpy(*rpy_from_rotation(r))


@dataclass(frozen=True)
class Rigid:
    """A rigid transform: ``p_parent = rotation @ p_child + translation`` (tf2's ``Transform``)."""

    rotation: np.ndarray = field(default_factory=lambda: np.eye(3))
    translation: np.ndarray = field(default_factory=lambda: np.zeros(3))

    @staticmethod
    def from_pose(position: tuple[float, float, float], quaternion: tuple[float, float, float, float]) -> Rigid:
        """A transform from a message's position and (x, y, z, w) orientation."""
        return Rigid(rotation_from_quaternion(*quaternion), np.asarray(position, dtype=float))

    def __mul__(self, other: Rigid) -> Rigid:
        """The composition ``self * other`` (other's frame expressed in self's parent)."""
        return Rigid(self.rotation @ other.rotation, self.rotation @ other.translation + self.translation)

    def inverse(self) -> Rigid:
        """The transform the other way round."""
        rt = self.rotation.T
        return Rigid(rt, -(rt @ self.translation))

    def rpy(self) -> tuple[float, float, float]:
        """The rotation's (roll, pitch, yaw)."""
        return rpy_from_rotation(self.rotation)

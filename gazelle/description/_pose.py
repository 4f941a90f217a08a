"""Poses and rotations of the description model: SI units and radians; quaternions are ``wxyz``
(MuJoCo's order, not ROS messages' xyzw); ``X_AB`` is the pose of frame B expressed in frame A, and
``X_AB * X_BC = X_AC``."""

from __future__ import annotations

import math
from dataclasses import dataclass

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
RGBA = tuple[float, float, float, float]


def quat_from_rpy(roll: float, pitch: float, yaw: float) -> Quat:
    """Quaternion (wxyz) of fixed-axis roll/pitch/yaw, as URDF and SDF define it (R = Rz·Ry·Rx)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        cr * cp * cy + sr * sp * sy,
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
    )


def quat_mul(a: Quat, b: Quat) -> Quat:
    """Hamilton product a*b of two wxyz quaternions."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    )


def quat_rotate(q: Quat, v: Vec3) -> Vec3:
    """Rotate vector v by unit quaternion q (wxyz)."""
    w, x, y, z = q
    vx, vy, vz = v
    # t = 2 * cross(q.xyz, v)
    tx = 2 * (y * vz - z * vy)
    ty = 2 * (z * vx - x * vz)
    tz = 2 * (x * vy - y * vx)
    return (
        vx + w * tx + (y * tz - z * ty),
        vy + w * ty + (z * tx - x * tz),
        vz + w * tz + (x * ty - y * tx),
    )


def quat_conj(q: Quat) -> Quat:
    """Conjugate (inverse for unit quaternions)."""
    return (q[0], -q[1], -q[2], -q[3])


def quat_to_rpy(q: Quat) -> Vec3:
    """Roll, pitch, yaw of a wxyz quaternion (inverse of :func:`quat_from_rpy`)."""
    w, x, y, z = q
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    sinp = max(-1.0, min(1.0, 2 * (w * y - z * x)))
    pitch = math.asin(sinp)
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return (roll, pitch, yaw)


@dataclass(frozen=True, slots=True)
class Pose:
    """A rigid transform: position and orientation (wxyz)."""

    position: Vec3 = (0.0, 0.0, 0.0)
    """Translation in metres."""
    orientation: Quat = (1.0, 0.0, 0.0, 0.0)
    """Unit quaternion, wxyz."""

    @staticmethod
    def from_xyz_rpy(xyz: Vec3 = (0.0, 0.0, 0.0), rpy: Vec3 = (0.0, 0.0, 0.0)) -> Pose:
        """Pose from a translation and fixed-axis roll/pitch/yaw in radians."""
        return Pose((float(xyz[0]), float(xyz[1]), float(xyz[2])), quat_from_rpy(*rpy))

    def __mul__(self, other: Pose) -> Pose:
        """Compose: ``X_AB * X_BC = X_AC``."""
        p = quat_rotate(self.orientation, other.position)
        return Pose(
            (self.position[0] + p[0], self.position[1] + p[1], self.position[2] + p[2]),
            quat_mul(self.orientation, other.orientation),
        )

    def inverse(self) -> Pose:
        """``X_BA`` from ``X_AB``."""
        qi = quat_conj(self.orientation)
        p = quat_rotate(qi, self.position)
        return Pose((-p[0], -p[1], -p[2]), qi)

    @property
    def rpy(self) -> Vec3:
        """Roll, pitch, yaw in radians."""
        return quat_to_rpy(self.orientation)


IDENTITY = Pose()

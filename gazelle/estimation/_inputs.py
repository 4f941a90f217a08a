"""Readings turned into measurements of the state (robot_localization's ``preparePose``, ``prepareTwist`` and
``prepareAcceleration``, ros2 branch, read for their behaviour).

* A pose is taken into the world frame (an odometry's or a pose's) or, for an IMU's orientation, corrected for
  the sensor's mounting on the body: the mount's roll, pitch and yaw are subtracted and the result turned by
  the mount's yaw. The update vector goes through the same rotation, so a variable measured in the sensor's
  frame updates the state variables it maps to; the covariance is rotated with it.
* ``relative``: poses are taken relative to the input's first one. ``differential``: consecutive poses become a
  body-frame velocity (their difference over the stamps' interval), with the two covariances summed and
  scaled by the interval, as upstream does.
* A twist is taken into the body frame (the sensor's offset adds the velocity the body's rotation gives it).
* An IMU's linear acceleration is taken into the body frame (with the offset's tangential and centripetal
  terms) and, with ``remove_gravitational_acceleration``, gravity is taken out along the IMU's orientation
  (or the state's, when the IMU gives none).
* ``two_d_mode`` measures z, roll, pitch, their rates and az as 0 with every measurement.

A reading whose frame cannot be related to the target frame by what was heard on /tf and /tf_static is not
used (the caller is told which frames, once)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ._config import EkfConfig
from ._ekf import Ekf
from ._frames import FrameTree
from ._measurement import STATE_SIZE, Measurement
from ._readings import ImuReading, PoseReading, TwistReading, measured
from ._rigid import Rigid, normalize_angle, rotation_from_quaternion, rotation_from_rpy, rotation_z

MASK_EPSILON = 1e-6
"""A rotated update-mask row longer than this selects its variable."""
Note = Callable[[str, str], None]
"""(key, text): something the diagnostics would say."""


def rotated_mask(rotation: np.ndarray, flags: np.ndarray) -> np.ndarray:
    """Which of three variables a measurement of ``flags`` (three booleans) in a frame rotated by ``rotation``
    updates: every row of ``rotation @ diag(flags)`` of some length."""
    return np.linalg.norm(rotation @ np.diag(flags.astype(float)), axis=1) >= MASK_EPSILON


def _block(rotation: np.ndarray, size: int = 6) -> np.ndarray:
    """``rotation`` repeated along the diagonal of a size x size matrix (for a pose or twist covariance)."""
    out = np.eye(size)
    for k in range(0, size, 3):
        out[k : k + 3, k : k + 3] = rotation
    return out


class MeasurementBuilder:
    """Turns readings into :class:`Measurement` objects; remembers each input's first pose (``relative``) and
    last pose (``differential``)."""

    def __init__(self, cfg: EkfConfig, frames: FrameTree, ekf: Ekf, note: Note) -> None:
        self.cfg = cfg
        self.frames = frames
        self.ekf = ekf
        self.note = note
        self.previous: dict[str, tuple[Rigid, np.ndarray]] = {}
        self.initial: dict[str, Rigid] = {}
        self.angular_acceleration = np.zeros(3)
        """The body's angular acceleration, from the rates' change between the node's cycles."""

    def reset(self) -> None:
        """Forget the inputs' first and last poses."""
        self.previous.clear()
        self.initial.clear()

    def _lookup(self, topic: str, target: str, source: str) -> Rigid | None:
        """``source`` -> ``target`` from what was heard, or None (said under the input part's key: the frame
        names come from the wire, the parts from the configuration)."""
        found = self.frames.lookup(target, source)
        if found is None:
            self.note(
                f"{topic}_transform",
                f"Could not transform {topic} measurement from frame '{source}' into '{target}' (no such "
                "transform heard on /tf or /tf_static); it is ignored until there is one",
            )
        return found

    def _orientation(self, topic: str, q: tuple[float, float, float, float], uses_it: bool) -> np.ndarray:
        """The rotation of a message's quaternion: all zeros is the identity (said when the orientation is used),
        one that is not unit is normalized."""
        norm = float(np.linalg.norm(q))
        if norm == 0.0:
            if uses_it:
                self.note(
                    f"{topic}_orientation",
                    f"The {topic} message contains an invalid orientation quaternion, but its configuration is "
                    "such that orientation data is being used. Correcting...",
                )
            return np.eye(3)
        if abs(norm - 1.0) > 0.01:
            self.note("normalization", "An input was not normalized, this should NOT happen, but will normalize.")
        return rotation_from_quaternion(*(float(v) / norm for v in q))

    def pose(
        self,
        reading: PoseReading,
        topic: str,
        update: np.ndarray,
        threshold: float,
        *,
        target: str,
        differential: bool = False,
        relative: bool = False,
        imu: bool = False,
        last_ns: int = 0,
    ) -> Measurement | None:
        """A pose measurement in ``target`` (the world frame; the body frame for an IMU's orientation), or a
        velocity one with ``differential`` (None for its first reading); ``last_ns`` is the input's previous stamp.

        ``update`` is the part's update vector as configured, in the reading's frame; the measurement's is it
        rotated into ``target`` (a variable measured in a turned frame updates the variables it maps to).
        ``threshold`` is the part's rejection threshold. None when the reading's frame cannot be related to
        ``target``."""
        # an empty target frame takes the reading's own (upstream's guard against unfilled frame ids)
        target = target or reading.frame or self.cfg.world_frame
        # a differential pose is differenced in its own frame, then rotated: its frame need not be known
        data_frame = target if differential and not imu else reading.frame
        pose = Rigid(self._orientation(topic, reading.orientation, bool(update[3:6].any())), np.array(reading.position))
        to_target = self._lookup(topic, target, data_frame)
        if to_target is None:
            return None
        update = update.copy()
        # an IMU's orientation is in a world-referenced frame, not its mount's: only the mount's yaw decides
        # which body angle a sensor angle is (pitch for a sideways IMU is the body's roll)
        mount = rotation_z(to_target.rpy()[2]) if imu else to_target.rotation
        update[0:3] = rotated_mask(mount, update[0:3])
        update[3:6] = rotated_mask(mount, update[3:6])
        rot6 = _block(mount)
        covariance = np.asarray(reading.covariance, dtype=float)
        rotated = rot6 @ covariance @ rot6.T
        if imu:
            # the mounting offsets come off the angles, and the result is turned by the mount's yaw; from here
            # the reading is as if the IMU sat level and straight on the body (no NED -> ENU conversion)
            offsets, angles = to_target.rpy(), pose.rpy()
            rpy = rotation_z(offsets[2]) @ np.array([normalize_angle(a - o) for a, o in zip(angles, offsets)])
            pose = Rigid(rotation_from_rpy(*rpy), pose.translation)
            to_target = Rigid()
        if differential:
            return self._differential(reading, topic, update, threshold, pose, covariance, rot6, to_target, last_ns)
        if relative:  # the input's first pose is its zero
            pose = self.initial.setdefault(topic, pose).inverse() * pose
        pose = to_target * pose
        m = Measurement(topic, reading.stamp_ns, rejection_threshold=threshold, update=update)
        m.values[0:3] = pose.translation
        m.values[3:6] = pose.rpy()
        m.covariance[0:6, 0:6] = rotated
        if self.cfg.two_d_mode:
            m.force_two_d()
        return m

    def _differential(
        self,
        reading: PoseReading,
        topic: str,
        update: np.ndarray,
        threshold: float,
        pose: Rigid,
        covariance: np.ndarray,
        rot6: np.ndarray,
        to_target: Rigid,
        last_ns: int,
    ) -> Measurement | None:
        """The velocity between the input's previous pose and this one, in the body frame."""
        previous = self.previous.get(topic)
        self.previous[topic] = (pose, covariance)  # kept even when this one gives no measurement
        dt = (reading.stamp_ns - last_ns) * 1e-9
        if previous is None or dt <= 0.0:
            return None
        prev_pose, prev_covariance = previous
        # the motion since the previous pose, in the previous pose's frame (the body's, then), rotated into
        # the target frame
        delta = Rigid(to_target.rotation) * (prev_pose.inverse() * pose)
        # each measured pose variable measures its rate instead; the two poses' covariances add up, scaled by
        # the interval (upstream's formula; its units are not a rate's, but it is what robot_localization fuses)
        twist_update = np.zeros(STATE_SIZE, dtype=bool)
        twist_update[6:12] = update[0:6]
        twist_cov = (rot6 @ covariance @ rot6.T + rot6 @ prev_covariance @ rot6.T) * dt
        vx, vy, vz = (float(v) / dt for v in delta.translation)
        wx, wy, wz = (a / dt for a in delta.rpy())
        twist = TwistReading(reading.stamp_ns, self.cfg.base_link_frame, (vx, vy, vz), (wx, wy, wz), twist_cov)
        return self.twist(twist, topic, twist_update, threshold, target=self.cfg.base_link_frame)

    def twist(
        self, reading: TwistReading, topic: str, update: np.ndarray, threshold: float, *, target: str
    ) -> Measurement | None:
        """A velocity measurement in the body frame ``target``: linear and angular velocity rotated into it, the
        linear one with the offset's share of the body's rotation added, the update vector and covariance
        rotated likewise. None when the reading's frame cannot be related to ``target``."""
        to_target = self._lookup(topic, target, reading.frame or target)
        if to_target is None:
            return None
        rot = to_target.rotation
        # a sensor off the body's origin moves with the body's rotation too: offset x (the state's rates)
        rates = self.ekf.state[9:12]
        update = update.copy()
        update[6:9] = rotated_mask(rot, update[6:9])
        update[9:12] = rotated_mask(rot, update[9:12])
        rot6 = _block(rot)
        m = Measurement(topic, reading.stamp_ns, rejection_threshold=threshold, update=update)
        m.values[6:9] = rot @ np.asarray(reading.linear, dtype=float) + np.cross(to_target.translation, rates)
        m.values[9:12] = rot @ np.asarray(reading.angular, dtype=float)
        m.covariance[6:12, 6:12] = rot6 @ np.asarray(reading.covariance, dtype=float) @ rot6.T
        if self.cfg.two_d_mode:
            m.force_two_d()
        return m

    def acceleration(
        self, reading: ImuReading, topic: str, update: np.ndarray, threshold: float, *, relative: bool, gravity: bool
    ) -> Measurement | None:
        """A linear acceleration measurement in the body frame (gravity removed with ``gravity``; ``relative``:
        the IMU's orientation is relative to its first, so gravity is taken along the mount too). None when
        the reading's frame cannot be related to the body's."""
        base = self.cfg.base_link_frame
        to_target = self._lookup(topic, base, reading.frame or base)
        if to_target is None:
            return None
        rot, offset = to_target.rotation, to_target.translation
        state = self.ekf.state
        rates = state[9:12]
        acc = rot @ np.asarray(reading.linear_acceleration, dtype=float)
        # an IMU off the body's origin feels the rotation's tangential and centripetal accelerations
        acc = acc + np.cross(offset, self.angular_acceleration) - np.cross(np.cross(offset, rates), rates)
        if gravity:
            # an accelerometer at rest reads +g upwards: taken off along the sensor's attitude (its own
            # reading, relative to its first one with ``relative``; the state's, when it gives none)
            g = np.array([0.0, 0.0, self.cfg.gravity])
            if not measured(reading.orientation_covariance):
                attitude = rotation_from_rpy(float(state[3]), float(state[4]), float(state[5])) @ rot
                acc = acc - attitude.T @ g
            else:
                attitude = self._orientation(topic, reading.orientation, True)
                acc = acc - (rot.T @ attitude.T @ g if relative else attitude.T @ g)
        update = update.copy()
        update[12:15] = rotated_mask(rot, update[12:15])
        m = Measurement(topic, reading.stamp_ns, rejection_threshold=threshold, update=update)
        m.values[12:15] = acc
        m.covariance[12:15, 12:15] = rot @ np.asarray(reading.linear_acceleration_covariance, dtype=float) @ rot.T
        if self.cfg.two_d_mode:
            m.force_two_d()
        return m

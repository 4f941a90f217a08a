"""Messages of a fixed layout serialized from a template, without building message objects.

Building a sensor_msgs/JointState in rclpy costs about 27 µs (each field set through its checked
setter) and publishing it 17 µs more; publishing the same message as serialized bytes costs about
6 µs (rclpy's ``Publisher.publish`` takes ``bytes``). An Odometry built and published costs 41 µs
with nobody listening, 3.8 µs as bytes from a template (80 against 12 µs of wall time with a listener
process on the other core): the publisher thread shares the GIL with the simulation, so this is time
the physics waits too.

A message's layout is fixed once its strings are (frame names, joint names, array lengths): only the
stamp and some runs of float64 change. A template serializes one prototype with rclpy's own
serializer, with sentinel values in the fields that change (so the layout is the real one, never
written by hand here: alignment, string lengths, encapsulation header), finds the sentinels in its
bytes, and fills a copy per message: :class:`JointStateTemplate` a block of ``n`` joint states with
numpy in one vectorised write, :class:`Template` one message with ``struct.pack_into`` per run.

:func:`raw_serializer` gives the bridge's publisher lanes such a writer for Odometry, TF, Imu and
JointState; a payload a template cannot take (a stamp beyond builtin_interfaces/Time's 32-bit seconds,
a NaN stamp) gets None, and the lane builds the message as before. tests/ros/test_cdr.py checks that every
writer's bytes deserialize to the message the converter builds, for random payloads.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import Any

import numpy as np
from builtin_interfaces.msg import Time
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry as OdometryMsg
from rclpy.serialization import serialize_message
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu as ImuMsg
from sensor_msgs.msg import JointState as JointStateMsg
from tf2_msgs.msg import TFMessage

from ..systems import Imu, JointStates, JointStatesBlock, MsgType, Odometry, TransformBatch
from ._convert import split_seconds

_SEC, _NSEC = 0x2B3C4D5E, 0x1A2B3C4D
"""Sentinel stamp of the prototype (found again in its bytes)."""
_MAX_SEC = 2**31 - 1
"""builtin_interfaces/Time's seconds are an int32: a stamp from here on has no template."""


def _find(raw: bytes, pattern: bytes) -> int:
    """Where ``pattern`` (a sentinel) is in a prototype's bytes; ValueError unless exactly once."""
    at = raw.find(pattern)
    if at < 0 or raw.find(pattern, at + 1) >= 0:
        raise ValueError("a message prototype's layout is not as expected")
    return at


class JointStateTemplate:
    """sensor_msgs/JointState for one tuple of joint names, serialized from a template (see the module)."""

    def __init__(self, names: tuple[str, ...], frame_id: str = "") -> None:
        """A serialized sensor_msgs/JointState for these joint names with the stamp and the three arrays at known
        byte offsets: a message is built by writing numbers into a copy of the template, not by rclpy's per-field
        conversion. The offsets are found by serializing sentinel values (distinct doubles no real state takes)
        and searching for their bytes."""
        n = len(names)
        self.names = names
        proto = JointStateMsg()
        proto.header.stamp = Time(sec=_SEC, nanosec=_NSEC)
        proto.header.frame_id = frame_id
        proto.name = list(names)
        sentinels = [np.array([1.0e300 / (k + 2) / (j + 3) for j in range(n)]) for k in range(3)]
        proto.position, proto.velocity, proto.effort = (s.tolist() for s in sentinels)
        raw = serialize_message(proto)
        self.template = np.frombuffer(raw, dtype=np.uint8).copy()
        stamp = np.array([_SEC, _NSEC], dtype="<u4").tobytes()
        self._stamp = _find(raw, stamp)
        self._arrays = [_find(raw, s.astype("<f8").tobytes()) for s in sentinels] if n else [0, 0, 0]
        self.n = n

    def serialize(self, block: JointStatesBlock) -> list[bytes]:
        """The block's messages, serialized (as rclpy's serializer would write them, padding aside)."""
        m = len(block)
        out = np.repeat(self.template[None, :], m, axis=0)
        t = np.maximum(np.asarray(block.stamps, dtype=np.float64), 0.0)
        sec = np.floor(t)
        nsec = np.round((t - sec) * 1e9)
        carry = nsec >= 1e9
        sec, nsec = np.where(carry, sec + 1, sec), np.where(carry, nsec - 1e9, nsec)
        s = self._stamp
        out[:, s : s + 8].view("<u4")[:] = np.column_stack([sec, nsec]).astype(np.uint32)
        if self.n:
            for at, values in zip(self._arrays, (block.positions, block.velocities, block.efforts), strict=True):
                out[:, at : at + 8 * self.n].view("<f8")[:] = values
        return [row.tobytes() for row in out]


@lru_cache(maxsize=64)
def joint_state_template(names: tuple[str, ...], frame_id: str = "") -> JointStateTemplate:
    """The template for ``names`` and ``frame_id`` (made once)."""
    return JointStateTemplate(names, frame_id)


def serialized_joint_states(block: JointStatesBlock) -> list[bytes] | None:
    """The block's JointState messages serialized, or None where a template does not apply (arrays of
    another length than the names, a stamp beyond the 32-bit seconds of builtin_interfaces/Time)."""
    n = len(block.names)
    if any(getattr(a, "shape", (0, -1))[1:] != (n,) for a in (block.positions, block.velocities, block.efforts)):
        return None
    if block.stamps and not (0 <= block.stamps[0] and block.stamps[-1] < _MAX_SEC):  # (NaN fails too)
        return None
    return joint_state_template(block.names, block.frame_id).serialize(block)


# ----------------------------------------------------------------------------- one message at a time
def stamp_parts(sec: float) -> tuple[int, int] | None:
    """(sec, nanosec) of builtin_interfaces/Time for ``sec`` seconds, as ``_convert.to_time`` makes them;
    None where Time cannot hold it (NaN, past 2**31 - 1 seconds)."""
    return split_seconds(sec) if sec < _MAX_SEC else None  # (NaN fails the comparison)


def _sentinel_run(key: int, n: int) -> list[float]:
    """``n`` float64 values that occur nowhere else in a prototype: distinct for every (``key``, index)
    up to 10**6 values a run."""
    return [1.0e300 / (1 + key * 1_000_000 + j) for j in range(n)]


def _made(build: Callable[[], Template]) -> Template | None:
    """``build()``, or None if the prototype's bytes were not as expected (its messages are then built
    as objects, as before)."""
    try:
        return build()
    except ValueError:
        return None


class Template:
    """One message type with its strings fixed: a prototype's bytes, the offsets of its stamps and its
    runs of float64 (each found by its sentinels; see the module docstring)."""

    def __init__(self, raw: bytes, stamps: Sequence[tuple[int, int]], runs: Sequence[list[float]]) -> None:
        self.template = bytes(raw)
        self.stamps = [_find(raw, struct.pack("<II", s, ns)) for s, ns in stamps]
        self.runs = [(_find(raw, struct.pack(f"<{len(r)}d", *r)), struct.Struct(f"<{len(r)}d")) for r in runs]

    def fill(self, stamps: Sequence[tuple[int, int]], runs: Sequence[Sequence[float]]) -> bytes:
        """The message with these stamps and runs (in the order the template was made with)."""
        buf = bytearray(self.template)
        for at, (s, ns) in zip(self.stamps, stamps, strict=True):
            struct.pack_into("<II", buf, at, s, ns)
        for (at, packer), values in zip(self.runs, runs, strict=True):
            packer.pack_into(buf, at, *values)
        return bytes(buf)


_STAMP = (_SEC, _NSEC)


@lru_cache(maxsize=256)
def odometry_template(frame_id: str, child_frame_id: str) -> Template | None:
    """nav_msgs/Odometry: the pose and its covariance (43 float64), the twist and its covariance (42)."""
    msg = OdometryMsg()
    msg.header.stamp = Time(sec=_SEC, nanosec=_NSEC)
    msg.header.frame_id, msg.child_frame_id = frame_id, child_frame_id
    pose, twist = _sentinel_run(0, 43), _sentinel_run(1, 42)
    p = msg.pose.pose
    p.position.x, p.position.y, p.position.z = pose[0:3]
    p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w = pose[3:7]
    msg.pose.covariance = pose[7:]
    t = msg.twist.twist
    t.linear.x, t.linear.y, t.linear.z = twist[0:3]
    t.angular.x, t.angular.y, t.angular.z = twist[3:6]
    msg.twist.covariance = twist[6:]
    return _made(lambda: Template(serialize_message(msg), [_STAMP], [pose, twist]))


def serialize_odometry(o: Odometry) -> bytes | None:
    """nav_msgs/Odometry as CDR bytes from a template (None when it cannot be: a stamp out of range, a covariance of
    the wrong length, or a prototype whose bytes were not as expected; the message is then built as an object)."""
    stamp = stamp_parts(o.stamp_sec)
    if stamp is None or len(o.pose_covariance) != 36 or len(o.twist_covariance) != 36:
        return None
    template = odometry_template(o.frame_id, o.child_frame_id)
    if template is None:
        return None
    (px, py, pz), (qw, qx, qy, qz) = o.pose.position, o.pose.orientation
    return template.fill(
        [stamp],
        [
            (px, py, pz, qx, qy, qz, qw, *o.pose_covariance),
            (*o.twist.linear, *o.twist.angular, *o.twist_covariance),
        ],
    )


@lru_cache(maxsize=256)
def imu_template(frame_id: str) -> Template | None:
    """sensor_msgs/Imu: orientation, angular velocity, linear acceleration and their covariances, one run
    of 37 float64."""
    msg = ImuMsg()
    msg.header.stamp = Time(sec=_SEC, nanosec=_NSEC)
    msg.header.frame_id = frame_id
    run = _sentinel_run(2, 37)
    q = msg.orientation
    q.x, q.y, q.z, q.w = run[0:4]
    msg.orientation_covariance = run[4:13]
    av = msg.angular_velocity
    av.x, av.y, av.z = run[13:16]
    msg.angular_velocity_covariance = run[16:25]
    la = msg.linear_acceleration
    la.x, la.y, la.z = run[25:28]
    msg.linear_acceleration_covariance = run[28:37]
    return _made(lambda: Template(serialize_message(msg), [_STAMP], [run]))


def serialize_imu(i: Imu) -> bytes | None:
    """sensor_msgs/Imu as CDR bytes from a template (None when it cannot be), the orientation reordered from wxyz to
    the message's xyzw."""
    stamp = stamp_parts(i.stamp_sec)
    covs = (i.orientation_covariance, i.angular_velocity_covariance, i.linear_acceleration_covariance)
    if stamp is None or any(len(c) != 9 for c in covs):
        return None
    template = imu_template(i.frame_id)
    if template is None:
        return None
    w, x, y, z = i.orientation
    run = (x, y, z, w, *covs[0], *i.angular_velocity, *covs[1], *i.linear_acceleration, *covs[2])
    return template.fill([stamp], [run])


@lru_cache(maxsize=256)
def tf_template(frames: tuple[tuple[str, str], ...]) -> Template | None:
    """tf2_msgs/TFMessage of one transform per (parent, child), in order: a stamp and 7 float64 each."""
    stamps, runs, transforms = [], [], []
    for k, (parent, child) in enumerate(frames):
        t = TransformStamped()
        stamps.append((_SEC - k, _NSEC - k))
        t.header.stamp = Time(sec=stamps[-1][0], nanosec=stamps[-1][1])
        t.header.frame_id, t.child_frame_id = parent, child
        runs.append(_sentinel_run(3 + k, 7))
        tr, rot = t.transform.translation, t.transform.rotation
        tr.x, tr.y, tr.z = runs[-1][0:3]
        rot.x, rot.y, rot.z, rot.w = runs[-1][3:7]
        transforms.append(t)
    msg = TFMessage(transforms=transforms)
    return _made(lambda: Template(serialize_message(msg), stamps, runs))


def serialize_tf(batch: TransformBatch) -> bytes | None:
    """tf2_msgs/TFMessage as CDR bytes from a template for this list of (parent, child) frames (None when it cannot
    be)."""
    stamps = []
    for t in batch.transforms:
        stamp = stamp_parts(t.stamp_sec)
        if stamp is None:
            return None
        stamps.append(stamp)
    template = tf_template(tuple((t.parent, t.child) for t in batch.transforms))
    if template is None:
        return None
    runs = []
    for t in batch.transforms:
        (px, py, pz), (qw, qx, qy, qz) = t.pose.position, t.pose.orientation
        runs.append((px, py, pz, qx, qy, qz, qw))
    return template.fill(stamps, runs)


@lru_cache(maxsize=256)
def joint_states_template(names: tuple[str, ...], lengths: tuple[int, int, int], frame_id: str = "") -> Template | None:
    """sensor_msgs/JointState for these names, array lengths (position, velocity, effort) and frame."""
    msg = JointStateMsg()
    msg.header.stamp = Time(sec=_SEC, nanosec=_NSEC)
    msg.header.frame_id = frame_id
    msg.name = list(names)
    runs = [_sentinel_run(4000 + k, n) for k, n in enumerate(lengths)]
    msg.position, msg.velocity, msg.effort = runs
    return _made(lambda: Template(serialize_message(msg), [_STAMP], [r for r in runs if r]))


def serialize_joint_states(j: JointStates) -> bytes | None:
    """sensor_msgs/JointState as CDR bytes from the template of these names (an empty velocity or effort array is
    left empty; None when it cannot be)."""
    stamp = stamp_parts(j.stamp_sec)
    if stamp is None:
        return None
    arrays = (j.positions, j.velocities, j.efforts)
    template = joint_states_template(tuple(j.names), (len(arrays[0]), len(arrays[1]), len(arrays[2])), j.frame_id)
    return None if template is None else template.fill([stamp], [a for a in arrays if len(a)])


_RAW: dict[MsgType, Callable[[Any], bytes | None]] = {
    MsgType.ODOMETRY: serialize_odometry,
    MsgType.TF: serialize_tf,
    MsgType.IMU: serialize_imu,
    MsgType.JOINT_STATE: serialize_joint_states,
}


def raw_serializer(kind: object) -> Callable[[Any], bytes | None] | None:
    """The template writer for a bus message kind (None: that kind is built as a message object)."""
    return _RAW.get(kind) if isinstance(kind, MsgType) else None


@lru_cache(maxsize=1)
def _clock_template() -> Template | None:
    return _made(lambda: Template(serialize_message(Clock(clock=Time(sec=_SEC, nanosec=_NSEC))), [_STAMP], []))


def serialize_clock(sim_time: float) -> bytes | None:
    """rosgraph_msgs/Clock at ``sim_time`` (None where Time cannot hold it)."""
    stamp, template = stamp_parts(sim_time), _clock_template()
    return None if stamp is None or template is None else template.fill([stamp], [])

"""Messages serialized from templates (gazelle/ros/_cdr.py) are the bytes rclpy's own serializer writes
for the message the converter builds (gazelle/ros/_convert.py), for any payload; where a template cannot
hold a payload the writer says None and the message is built as before."""

from __future__ import annotations

import math
import struct
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("rclpy")

from rclpy.serialization import deserialize_message, serialize_message
from rosgraph_msgs.msg import Clock

from gazelle.description import Pose
from gazelle.ros._cdr import raw_serializer, serialize_clock
from gazelle.ros._convert import ros_type, to_ros, to_time
from gazelle.systems import Imu, JointStates, MsgType, Odometry, Transform, TransformBatch, Twist

floats = st.floats(allow_nan=True, allow_infinity=True, width=64)
finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
stamps = st.one_of(st.floats(min_value=-5.0, max_value=2.0**31 - 2), st.just(0.0), st.just(0.9999999999))
# ROS strings are UTF-8 C strings: no NUL, no lone surrogate (neither path can encode one)
names = st.text(st.characters(blacklist_characters="\x00", blacklist_categories=("Cs",)), min_size=0, max_size=12)
vec3 = st.tuples(floats, floats, floats)
quat = st.tuples(floats, floats, floats, floats)
poses = st.builds(Pose, vec3, quat)


def canon(value: Any) -> object:
    """A message as nested tuples, each float64 as its 8 bytes (so NaN equals NaN, and -0.0 is not 0.0)."""
    if hasattr(value, "get_fields_and_field_types"):
        return tuple((f, canon(getattr(value, f))) for f in value.get_fields_and_field_types())
    if isinstance(value, float):
        return struct.pack("<d", value)
    if hasattr(value, "tolist"):  # an array.array or numpy array field
        return tuple(canon(v) for v in value.tolist())
    if isinstance(value, (list, tuple)):
        return tuple(canon(v) for v in value)
    return value


def same_bytes(kind: MsgType, payload: object) -> bytes:
    """The template's bytes: as long as rclpy's serialization of the converter's message, and read back
    (by rclpy) as what a subscriber gets of that message, field by field and bit by bit. (The bytes
    themselves differ only in CDR's padding, which rclpy's serializer leaves as it finds its buffer.)"""
    writer = raw_serializer(kind)
    assert writer is not None
    raw = writer(payload)
    assert raw is not None
    expected = serialize_message(to_ros(kind)(payload))
    assert len(raw) == len(expected)
    assert canon(deserialize_message(raw, ros_type(kind))) == canon(deserialize_message(expected, ros_type(kind)))
    return raw


@settings(max_examples=150, deadline=None)
@given(
    stamp=stamps,
    frames=st.tuples(names, names),
    pose=poses,
    twist=st.builds(Twist, vec3, vec3),
    covs=st.tuples(st.lists(finite, min_size=36, max_size=36), st.lists(finite, min_size=36, max_size=36)),
)
def test_odometry_from_its_template_is_what_rclpy_serializes(stamp, frames, pose, twist, covs):
    o = Odometry(stamp, frames[0], frames[1], pose, twist, tuple(covs[0]), tuple(covs[1]))
    raw = same_bytes(MsgType.ODOMETRY, o)
    back = deserialize_message(raw, ros_type(MsgType.ODOMETRY))
    assert back.child_frame_id == frames[1] and back.header.stamp == to_time(stamp)


@settings(max_examples=150, deadline=None)
@given(stamp=stamps, frame=names, q=quat, av=vec3, la=vec3, cov=st.lists(finite, min_size=9, max_size=9))
def test_imu_from_its_template_is_what_rclpy_serializes(stamp, frame, q, av, la, cov):
    same_bytes(MsgType.IMU, Imu(stamp, frame, q, av, la, tuple(cov), tuple(reversed(cov)), tuple(cov)))


@settings(max_examples=100, deadline=None)
@given(transforms=st.lists(st.tuples(stamps, names, names, poses), min_size=0, max_size=12))
def test_a_tf_message_from_its_template_is_what_rclpy_serializes(transforms):
    batch = TransformBatch(tuple(Transform(s, parent, child, pose) for s, parent, child, pose in transforms))
    same_bytes(MsgType.TF, batch)


@settings(max_examples=100, deadline=None)
@given(
    stamp=stamps,
    joints=st.lists(names, min_size=0, max_size=8),
    data=st.data(),
)
def test_joint_states_from_their_template_are_what_rclpy_serializes(stamp, joints, data):
    n = len(joints)
    arrays = [
        tuple(data.draw(st.lists(floats, min_size=k, max_size=k))) for k in (n, n, data.draw(st.sampled_from([0, n])))
    ]
    frame = data.draw(st.sampled_from(["", "base_link", "r1/base_footprint"]))  # joint_state_broadcaster's frame_id
    same_bytes(MsgType.JOINT_STATE, JointStates(stamp, tuple(joints), arrays[0], arrays[1], arrays[2], frame))


def test_what_a_template_cannot_hold_is_built_as_a_message() -> None:
    """A stamp past builtin_interfaces/Time's 32-bit seconds or NaN, or a covariance of another length:
    the writer says None (the lane then converts as before, which fails or clips as it always did)."""
    pose, twist = Pose((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)), Twist()
    odom = raw_serializer(MsgType.ODOMETRY)
    assert odom is not None
    assert odom(Odometry(2.0**31, "odom", "base", pose, twist)) is None
    assert odom(Odometry(math.nan, "odom", "base", pose, twist)) is None
    assert odom(Odometry(1.0, "odom", "base", pose, twist, (0.0,) * 35)) is None
    tf = raw_serializer(MsgType.TF)
    assert tf is not None
    assert tf(TransformBatch((Transform(1.0, "a", "b", pose), Transform(math.inf, "a", "c", pose)))) is None
    assert raw_serializer(MsgType.LASER_SCAN) is None  # not templated: built as a message


def test_clock_from_its_template_is_what_rclpy_serializes() -> None:
    for t in (0.0, 0.001, 12.345678901, 1e6 + 0.5e-9, 2.0**31 - 1.5):
        assert serialize_clock(t) == serialize_message(Clock(clock=to_time(t)))  # no padding in a Clock
    assert serialize_clock(2.0**31) is None

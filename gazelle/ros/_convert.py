"""Conversions between gazelle's dataclasses and ROS messages."""

from __future__ import annotations

import math

from builtin_interfaces.msg import Time
from geometry_msgs.msg import Point, Quaternion, TransformStamped, Vector3
from geometry_msgs.msg import Pose as PoseMsg
from geometry_msgs.msg import Twist as TwistMsg
from nav_msgs.msg import Odometry as OdometryMsg
from sensor_msgs.msg import JointState as JointStateMsg
from std_msgs.msg import Float64 as Float64Msg
from std_msgs.msg import String as StringMsg
from tf2_msgs.msg import TFMessage

from ..description import Pose
from ..systems import Float64, JointStates, MsgType, Odometry, Transform, TransformBatch, Twist


def to_time(sec: float) -> Time:
    """builtin_interfaces/Time from seconds (non-negative)."""
    sec = max(sec, 0.0)
    s = int(math.floor(sec))
    ns = int(round((sec - s) * 1e9))
    if ns >= 1_000_000_000:
        s, ns = s + 1, ns - 1_000_000_000
    return Time(sec=s, nanosec=ns)


def from_time(t: Time) -> float:
    """builtin_interfaces/Time -> seconds."""
    return t.sec + t.nanosec * 1e-9


def to_pose_msg(p: Pose) -> PoseMsg:
    """A Pose -> geometry_msgs/Pose."""
    w, x, y, z = p.orientation
    return PoseMsg(
        position=Point(x=float(p.position[0]), y=float(p.position[1]), z=float(p.position[2])),
        orientation=Quaternion(x=float(x), y=float(y), z=float(z), w=float(w)),
    )


def from_pose_msg(m: PoseMsg) -> Pose:
    """Pose from a message; an all-zero quaternion (an unset field) means identity, as gazebo_ros does."""
    q = m.orientation
    quat = (q.w, q.x, q.y, q.z)
    if quat == (0.0, 0.0, 0.0, 0.0):
        quat = (1.0, 0.0, 0.0, 0.0)
    return Pose((m.position.x, m.position.y, m.position.z), quat)


def to_twist_msg(t: Twist) -> TwistMsg:
    """A bus Twist -> geometry_msgs/Twist."""
    return TwistMsg(
        linear=Vector3(x=t.linear[0], y=t.linear[1], z=t.linear[2]),
        angular=Vector3(x=t.angular[0], y=t.angular[1], z=t.angular[2]),
    )


def from_twist_msg(m: TwistMsg) -> Twist:
    """geometry_msgs/Twist -> a bus Twist."""
    return Twist((m.linear.x, m.linear.y, m.linear.z), (m.angular.x, m.angular.y, m.angular.z))


def to_transform_msg(t: Transform) -> TransformStamped:
    """A bus Transform -> geometry_msgs/TransformStamped."""
    msg = TransformStamped()
    msg.header.stamp = to_time(t.stamp_sec)
    msg.header.frame_id = t.parent
    msg.child_frame_id = t.child
    p, q = t.pose.position, t.pose.orientation
    msg.transform.translation = Vector3(x=float(p[0]), y=float(p[1]), z=float(p[2]))
    msg.transform.rotation = Quaternion(x=float(q[1]), y=float(q[2]), z=float(q[3]), w=float(q[0]))
    return msg


def to_odometry_msg(o: Odometry) -> OdometryMsg:
    """A bus Odometry -> nav_msgs/Odometry."""
    msg = OdometryMsg()
    msg.header.stamp = to_time(o.stamp_sec)
    msg.header.frame_id = o.frame_id
    msg.child_frame_id = o.child_frame_id
    msg.pose.pose = to_pose_msg(o.pose)
    msg.pose.covariance = [float(v) for v in o.pose_covariance]
    msg.twist.twist = to_twist_msg(o.twist)
    msg.twist.covariance = [float(v) for v in o.twist_covariance]
    return msg


def to_joint_state_msg(j: JointStates) -> JointStateMsg:
    """Bus JointStates -> sensor_msgs/JointState."""
    msg = JointStateMsg()
    msg.header.stamp = to_time(j.stamp_sec)
    msg.name = list(j.names)
    msg.position = [float(v) for v in j.positions]
    msg.velocity = [float(v) for v in j.velocities]
    msg.effort = [float(v) for v in j.efforts]
    return msg


def _to_tf(batch: TransformBatch) -> TFMessage:
    return TFMessage(transforms=[to_transform_msg(t) for t in batch.transforms])


ROS_TYPES = {
    MsgType.TWIST: TwistMsg,
    MsgType.ODOMETRY: OdometryMsg,
    MsgType.TF: TFMessage,
    MsgType.TF_STATIC: TFMessage,
    MsgType.JOINT_STATE: JointStateMsg,
    MsgType.STRING: StringMsg,
    MsgType.FLOAT64: Float64Msg,
}
"""The rclpy message class for each bus message type."""

TO_ROS = {
    MsgType.ODOMETRY: to_odometry_msg,
    MsgType.TF: _to_tf,
    MsgType.TF_STATIC: _to_tf,
    MsgType.STRING: lambda t: StringMsg(data=t.data),
    MsgType.JOINT_STATE: to_joint_state_msg,
    MsgType.TWIST: to_twist_msg,
    MsgType.FLOAT64: lambda f: Float64Msg(data=float(f.data)),
}
FROM_ROS = {
    MsgType.TWIST: from_twist_msg,
    MsgType.FLOAT64: lambda m: Float64(float(m.data)),
}

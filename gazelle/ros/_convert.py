"""Conversions between gazelle's payloads and ROS messages.

The systems publish plain frozen dataclasses on the bus (``gazelle.systems._payloads``; the payload of each
:class:`~gazelle.systems.MsgType` is in ``gazelle.systems.PAYLOADS``). One generic plan converts a payload
whose fields map onto its message (by name, by the header/time/vector/quaternion rules, or by the payload's
``ROS_FIELDS``), both ways: ``_layouts.py``. This module holds the tables of rclpy classes
(:data:`ROS_TYPES`, :data:`ARM_TYPES`) and the few conversions written by hand (:data:`TO_ROS`,
:data:`FROM_ROS`), each because its layout really differs from the message's (the reason is beside it;
tests/ros/test_message_layouts.py fails if the generic plan could do one of them). A message declared by its
own module (:class:`~gazelle.systems.DeclaredMessage`) takes the generic path too.

Conventions the conversions keep:

* Quaternions are ``wxyz`` in gazelle (MuJoCo's order) and ``xyzw`` in geometry_msgs: the fields are
  named, so only the unpacking order changes, never the rotation.
* Times are seconds of sim time as a float; a stamp is split into ``sec``/``nanosec`` with the nanoseconds
  rounded (:func:`split_seconds`), the same way the serialized-message path rounds them, so a message
  reads the same stamp whichever path published it.
* Array payloads (scans, images, clouds) travel as ``bytes``, which go into the message's array fields
  without a Python loop: the simulation thread hands bytes over and the publisher thread converts.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

from gazebo_msgs.msg import ContactsState, ContactState
from geometry_msgs.msg import Pose as PoseMsg
from geometry_msgs.msg import Twist as TwistMsg
from geometry_msgs.msg import TwistStamped as TwistStampedMsg
from geometry_msgs.msg import Vector3, Wrench
from geometry_msgs.msg import Vector3Stamped as Vector3StampedMsg
from geometry_msgs.msg import WrenchStamped as WrenchStampedMsg
from nav_msgs.msg import Odometry as OdometryMsg
from ros_gz_interfaces.msg import Altimeter as AltimeterMsg
from ros_gz_interfaces.msg import Contact as GzContact
from ros_gz_interfaces.msg import Contacts as GzContacts
from ros_gz_interfaces.msg import Entity as GzEntity
from ros_gz_interfaces.msg import JointWrench as GzJointWrench
from sensor_msgs.msg import CameraInfo as CameraInfoMsg
from sensor_msgs.msg import Image as ImageMsg
from sensor_msgs.msg import Imu as ImuMsg
from sensor_msgs.msg import JointState as JointStateMsg
from sensor_msgs.msg import LaserScan as LaserScanMsg
from sensor_msgs.msg import MagneticField as MagneticFieldMsg
from sensor_msgs.msg import NavSatFix as NavSatFixMsg
from sensor_msgs.msg import PointCloud2, PointField
from sensor_msgs.msg import Range as RangeMsg
from std_msgs.msg import Float64 as Float64Msg
from std_msgs.msg import Float64MultiArray
from std_msgs.msg import String as StringMsg
from tf2_msgs.msg import TFMessage
from trajectory_msgs.msg import JointTrajectory as JointTrajectoryMsg
from trajectory_msgs.msg import JointTrajectoryPoint

from .._errors import SimError
from ..description import Pose
from ..systems import (
    PAYLOADS,
    CloudLayout,
    Contacts,
    DeclaredMessage,
    DisplayTrajectory,
    JointStates,
    JointTrajectory,
    MsgType,
    PointCloud,
    TrajectoryPoint,
)
from ._interfaces import InterfaceError, resolve_interface
from ._layouts import from_duration as from_duration
from ._layouts import from_time as from_time
from ._layouts import msg_to_payload, payload_to_msg, to_time
from ._layouts import split_seconds as split_seconds
from ._layouts import to_duration as to_duration

if TYPE_CHECKING:
    from moveit_msgs.msg import DisplayTrajectory as DisplayTrajectoryMsg


def to_pose_msg(p: Pose) -> PoseMsg:
    """A Pose -> geometry_msgs/Pose (the generic plan: position -> Point, wxyz -> Quaternion)."""
    return payload_to_msg(Pose, PoseMsg)(p)


def from_pose_msg(m: PoseMsg) -> Pose:
    """Pose from a message; an all-zero quaternion (an unset field) means identity, as gazebo_ros does."""
    pose = msg_to_payload(PoseMsg, Pose)(m)
    if pose.orientation == (0.0, 0.0, 0.0, 0.0):
        return Pose(pose.position, (1.0, 0.0, 0.0, 0.0))
    return pose


def to_joint_state_msg(j: JointStates) -> JointStateMsg:
    """Bus JointStates -> sensor_msgs/JointState (the generic plan)."""
    return payload_to_msg(JointStates, JointStateMsg)(j)


def to_trajectory_point_msg(p: TrajectoryPoint) -> JointTrajectoryPoint:
    """Bus payload -> trajectory_msgs/JointTrajectoryPoint (the generic plan)."""
    return payload_to_msg(TrajectoryPoint, JointTrajectoryPoint)(p)


def from_joint_trajectory_msg(m: JointTrajectoryMsg) -> JointTrajectory:
    """trajectory_msgs/JointTrajectory -> bus payload (the generic plan)."""
    return msg_to_payload(JointTrajectoryMsg, JointTrajectory)(m)


# --------------------------------------------------------------------------- written by hand
@functools.cache
def _cloud_fields(layout: CloudLayout) -> list[PointField]:
    """The PointFields of a layout (float32 each), made once per layout."""
    return [PointField(name=n, offset=o, datatype=PointField.FLOAT32, count=1) for n, o in layout.fields]


def to_point_cloud_msg(c: PointCloud) -> PointCloud2:
    """sensor_msgs/PointCloud2 of the payload's float32 fields (x, y, z, intensity for rays; x, y, z, rgb for
    depth cameras, in each Gazebo's layout)."""
    msg = PointCloud2()
    msg.header.stamp = to_time(c.stamp_sec)
    msg.header.frame_id = c.frame_id
    msg.height, msg.width = c.height, c.width
    msg.fields = _cloud_fields(c.layout)
    msg.is_bigendian = False
    msg.point_step = c.layout.point_step
    msg.row_step = c.layout.point_step * c.width
    msg.data = c.data
    msg.is_dense = c.is_dense
    return msg


def _vec(v) -> Vector3:
    return Vector3(x=float(v[0]), y=float(v[1]), z=float(v[2]))


def to_contacts_msg(c: Contacts) -> ContactsState:
    """gazebo_msgs/ContactsState (one ContactState per pair of collisions in contact)."""
    msg = ContactsState()
    msg.header.stamp = to_time(c.stamp_sec)
    msg.header.frame_id = c.frame_id
    states = []
    for pair in c.states:
        st = ContactState()
        st.info = f"{len(pair.depths)} contact point(s) of {pair.collision1} with {pair.collision2}"
        st.collision1_name, st.collision2_name = pair.collision1, pair.collision2
        st.wrenches = [Wrench(force=_vec(f), torque=_vec(t)) for f, t in zip(pair.forces, pair.torques)]
        st.total_wrench = Wrench(
            force=_vec([sum(f[i] for f in pair.forces) for i in range(3)]),
            torque=_vec([sum(t[i] for t in pair.torques) for i in range(3)]),
        )
        st.contact_positions = [_vec(p) for p in pair.positions]
        st.contact_normals = [_vec(n) for n in pair.normals]
        st.depths = [float(d) for d in pair.depths]
        states.append(st)
    msg.states = states
    return msg


def to_gz_contacts_msg(c: Contacts) -> GzContacts:
    """ros_gz_interfaces/Contacts, as ros_gz_bridge (convert/sensor_msgs.cpp) makes it of gz-sim's contact
    sensor message (gz-sim8 Physics.cc fills it): one Contact per pair of collisions, named (gazelle has no
    entity numbers: ids 0, type unset as in gz's), each point's position, normal, depth and the wrench
    pair, force on collision1 and its opposite on collision2 (gz sends no torque: zero)."""
    msg = GzContacts()
    msg.header.stamp = to_time(c.stamp_sec)
    msg.header.frame_id = c.frame_id
    contacts = []
    for pair in c.states:
        contact = GzContact()
        contact.collision1 = GzEntity(name=pair.collision1)
        contact.collision2 = GzEntity(name=pair.collision2)
        contact.positions = [_vec(p) for p in pair.positions]
        contact.normals = [_vec(n) for n in pair.normals]
        contact.depths = [float(d) for d in pair.depths]
        wrenches = []
        for f in pair.forces:
            w = GzJointWrench()
            w.body_1_wrench.force = _vec(f)
            w.body_2_wrench.force = _vec([-v for v in f])
            wrenches.append(w)
        contact.wrenches = wrenches
        contacts.append(contact)
    msg.contacts = contacts
    return msg


def from_display_trajectory_msg(m: DisplayTrajectoryMsg) -> DisplayTrajectory:
    """moveit_msgs/DisplayTrajectory -> bus payload: each RobotTrajectory's joint part."""
    return DisplayTrajectory(
        str(m.model_id), tuple(from_joint_trajectory_msg(t.joint_trajectory) for t in m.trajectory)
    )


ROS_TYPES = {
    MsgType.TWIST: TwistMsg,
    MsgType.ODOMETRY: OdometryMsg,
    MsgType.TF: TFMessage,
    MsgType.TF_STATIC: TFMessage,
    MsgType.JOINT_STATE: JointStateMsg,
    MsgType.STRING: StringMsg,
    MsgType.FLOAT64: Float64Msg,
    MsgType.LASER_SCAN: LaserScanMsg,
    MsgType.POINT_CLOUD2: PointCloud2,
    MsgType.RANGE: RangeMsg,
    MsgType.IMU: ImuMsg,
    MsgType.IMAGE: ImageMsg,
    MsgType.CAMERA_INFO: CameraInfoMsg,
    MsgType.CONTACTS: ContactsState,
    MsgType.GZ_CONTACTS: GzContacts,
    MsgType.NAV_SAT_FIX: NavSatFixMsg,
    MsgType.VECTOR3_STAMPED: Vector3StampedMsg,
    MsgType.WRENCH_STAMPED: WrenchStampedMsg,
    MsgType.TWIST_STAMPED: TwistStampedMsg,
    MsgType.MAGNETIC_FIELD: MagneticFieldMsg,
    MsgType.ALTIMETER: AltimeterMsg,
    MsgType.FLOAT64_ARRAY: Float64MultiArray,
    MsgType.JOINT_TRAJECTORY: JointTrajectoryMsg,
}
"""The rclpy message class for each bus message type whose package is always there (on PyPI, or built by
the set-up's first tier: see ``ARM_TYPES``)."""

ARM_TYPES = {
    MsgType.TRAJECTORY_CONTROLLER_STATE: "control_msgs/msg/JointTrajectoryControllerState",
    MsgType.DYNAMIC_JOINT_STATE: "control_msgs/msg/DynamicJointState",
    MsgType.DISPLAY_TRAJECTORY: "moveit_msgs/msg/DisplayTrajectory",
}
"""Bus message types of ros2_control and MoveIt, imported when first used: their packages are the set-up's
second tier (``scripts/build_interfaces.sh``), which ``./demo.sh`` builds after the demo, so a world
without arms runs before they exist."""

TO_ROS: dict[MsgType, Callable[..., object]] = {
    # PointCloud's layout object expands into three message fields (fields, point_step, row_step)
    MsgType.POINT_CLOUD2: to_point_cloud_msg,
    # a pair's forces and torques become wrenches plus their sum and a made-up info line
    MsgType.CONTACTS: to_contacts_msg,
    # ros_gz_bridge's layout: entities by name, and each force's opposite on the other body
    MsgType.GZ_CONTACTS: to_gz_contacts_msg,
}
"""The payload-to-message conversions written by hand (the rest take the generic plan, see ``_layouts.py``)."""
FROM_ROS: dict[MsgType, Callable[..., object]] = {
    # each segment sits inside a RobotTrajectory (its multi-DOF part is dropped)
    MsgType.DISPLAY_TRAJECTORY: from_display_trajectory_msg,
}
"""The message-to-payload conversions written by hand."""


def ros_type(kind: MsgType | DeclaredMessage) -> Any:
    """The rclpy message class of an endpoint's kind: MsgType's from the tables above, a declared one's
    imported by its name (``sensor_msgs/msg/FluidPressure``)."""
    if isinstance(kind, MsgType):
        found = ROS_TYPES.get(kind)
        if found is not None:
            return found
        return interface_class(ARM_TYPES[kind])
    return interface_class(kind.value)


def interface_class(full_name: str) -> Any:
    """The rclpy class of ``pkg/msg/Name`` (or ``srv``, ``action``), imported now by the one checked resolver
    (:func:`~._interfaces.resolve_interface`); a package of the set-up's second tier that is not built yet is
    an :class:`InterfaceMissing` that says how to build it."""
    package, kind = full_name.split("/")[:2]
    try:
        return resolve_interface(full_name, kind)
    except InterfaceError:
        if package in ARM_PACKAGES:  # not listed in the ament index, or listed but not importable
            raise InterfaceMissing(package) from None
        raise


ARM_PACKAGES = frozenset(
    {"control_msgs", "controller_manager_msgs", "moveit_msgs", "octomap_msgs", "object_recognition_msgs"}
)
"""The set-up's second tier (``scripts/build_interfaces.sh``): the interfaces of ros2_control and MoveIt."""


@contextmanager
def second_tier() -> Iterator[None]:
    """Imports inside it of a second-tier package that is not built yet raise :class:`InterfaceMissing`
    (gazelle's modules that import control_msgs or moveit_msgs are loaded when a robot needs them)."""
    try:
        yield
    except ModuleNotFoundError as e:
        package = (e.name or "").split(".")[0]
        if package in ARM_PACKAGES:
            raise InterfaceMissing(package) from None
        raise


class InterfaceMissing(SimError, ImportError):
    """An interface package gazelle builds (control_msgs, moveit_msgs, ...) is not in this venv yet."""

    def __init__(self, package: str) -> None:
        super().__init__(
            f"{package} is not built in this venv yet (the set-up builds the ros2_control and MoveIt interfaces "
            "after the demo): run scripts/setup.sh",
            name=package,
        )
        self.package = package


def to_ros(kind: MsgType | DeclaredMessage) -> Callable[..., Any]:
    """The payload-to-message conversion of an endpoint's kind: a hand-written one of :data:`TO_ROS`, else the
    generic plan (``_layouts.py``) of its payload class (:data:`~gazelle.systems.PAYLOADS`; a declared
    message's: that of the first payload it converts, kept per class)."""
    if isinstance(kind, MsgType):
        found = TO_ROS.get(kind)
        if found is not None:
            return found
        return payload_to_msg(PAYLOADS[kind], ros_type(kind))
    cls = ros_type(kind)
    plans: dict[type, Callable[[object], object]] = {}

    def convert(payload: object) -> object:
        plan = plans.get(type(payload))
        if plan is None:
            plan = plans[type(payload)] = payload_to_msg(type(payload), cls)
        return plan(payload)

    return convert


def from_ros(kind: MsgType) -> Callable[..., object]:
    """The message-to-payload conversion of a subscription's kind: a hand-written one of :data:`FROM_ROS`,
    else the generic plan of its payload class."""
    found = FROM_ROS.get(kind)
    if found is not None:
        return found
    return msg_to_payload(ros_type(kind), PAYLOADS[kind])

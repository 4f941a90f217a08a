"""Conversions between gazelle's dataclasses and ROS messages.

The systems publish plain frozen dataclasses on the bus (``gazelle.systems._payloads``); this module is the only
place that knows their ROS message types. The tables at the end say, per bus message type, which rclpy
class carries it (:data:`ROS_TYPES`, :data:`ARM_TYPES`) and how to convert each way (:data:`TO_ROS`, and
the ``from_*`` functions for what the ROS side receives). A sensor declared by its own module
(:class:`~gazelle.systems.DeclaredMessage`) needs no entry here: its payload's fields are the message's.

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

import dataclasses
import functools
import math
from array import array
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

from builtin_interfaces.msg import Duration, Time
from gazebo_msgs.msg import ContactsState, ContactState
from geometry_msgs.msg import Point, Quaternion, TransformStamped, Vector3, Wrench
from geometry_msgs.msg import Pose as PoseMsg
from geometry_msgs.msg import Twist as TwistMsg
from geometry_msgs.msg import TwistStamped as TwistStampedMsg
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
from sensor_msgs.msg import NavSatStatus, PointCloud2, PointField
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
    Altimeter,
    CameraInfo,
    CloudLayout,
    Contacts,
    DeclaredMessage,
    DisplayTrajectory,
    DynamicJointState,
    Float64,
    Float64Array,
    Image,
    Imu,
    JointStates,
    JointTrajectory,
    LaserScan,
    MagneticField,
    MsgType,
    NavSatFix,
    Odometry,
    PointCloud,
    Range,
    TrajectoryControllerState,
    TrajectoryPoint,
    Transform,
    TransformBatch,
    Twist,
    TwistStamped,
    Vector3Stamped,
    WrenchStamped,
)
from ._interfaces import InterfaceError, resolve_interface

if TYPE_CHECKING:
    from control_msgs.msg import DynamicJointState as DynamicJointStateMsg
    from control_msgs.msg import JointTrajectoryControllerState as JointTrajectoryControllerStateMsg


def split_seconds(sec: float) -> tuple[int, int]:
    """(sec, nanosec) of builtin_interfaces/Time for ``sec`` seconds, nanoseconds rounded (a negative time
    is 0). ``ros/_cdr.py`` writes template stamps with it too, so both paths round alike."""
    sec = max(sec, 0.0)
    s = int(math.floor(sec))
    ns = int(round((sec - s) * 1e9))
    if ns >= 1_000_000_000:
        s, ns = s + 1, ns - 1_000_000_000
    return s, ns


def to_time(sec: float) -> Time:
    """builtin_interfaces/Time from seconds (non-negative)."""
    s, ns = split_seconds(sec)
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


def _stamped(msg: Any, payload: Any) -> Any:
    """``msg`` with its header from the payload's ``stamp_sec`` (sim time) and ``frame_id``."""
    msg.header.stamp = to_time(payload.stamp_sec)
    msg.header.frame_id = payload.frame_id
    return msg


def to_odometry_msg(o: Odometry) -> OdometryMsg:
    """A bus Odometry -> nav_msgs/Odometry."""
    msg = _stamped(OdometryMsg(), o)
    msg.child_frame_id = o.child_frame_id
    msg.pose.pose = to_pose_msg(o.pose)
    msg.pose.covariance = [float(v) for v in o.pose_covariance]
    msg.twist.twist = to_twist_msg(o.twist)
    msg.twist.covariance = [float(v) for v in o.twist_covariance]
    return msg


def to_joint_state_msg(j: JointStates) -> JointStateMsg:
    """Bus JointStates -> sensor_msgs/JointState."""
    msg = _stamped(JointStateMsg(), j)
    msg.name = list(j.names)
    msg.position = [float(v) for v in j.positions]
    msg.velocity = [float(v) for v in j.velocities]
    msg.effort = [float(v) for v in j.efforts]
    return msg


def to_laser_scan_msg(s: LaserScan) -> LaserScanMsg:
    """sensor_msgs/LaserScan (the float32 bytes go into the array fields without a Python loop)."""
    msg = _stamped(LaserScanMsg(), s)
    msg.angle_min, msg.angle_max, msg.angle_increment = s.angle_min, s.angle_max, s.angle_increment
    msg.time_increment, msg.scan_time = s.time_increment, s.scan_time
    msg.range_min, msg.range_max = s.range_min, s.range_max
    msg.ranges = array("f", s.ranges)
    msg.intensities = array("f", s.intensities)
    return msg


@functools.cache
def _cloud_fields(layout: CloudLayout) -> list[PointField]:
    """The PointFields of a layout (float32 each), made once per layout."""
    return [PointField(name=n, offset=o, datatype=PointField.FLOAT32, count=1) for n, o in layout.fields]


def to_point_cloud_msg(c: PointCloud) -> PointCloud2:
    """sensor_msgs/PointCloud2 of the payload's float32 fields (x, y, z, intensity for rays; x, y, z, rgb for
    depth cameras, in each Gazebo's layout)."""
    msg = _stamped(PointCloud2(), c)
    msg.height, msg.width = c.height, c.width
    msg.fields = _cloud_fields(c.layout)
    msg.is_bigendian = False
    msg.point_step = c.layout.point_step
    msg.row_step = c.layout.point_step * c.width
    msg.data = c.data
    msg.is_dense = c.is_dense
    return msg


def to_range_msg(r: Range) -> RangeMsg:
    """sensor_msgs/Range."""
    msg = _stamped(RangeMsg(), r)
    msg.radiation_type = r.radiation_type
    msg.field_of_view, msg.min_range, msg.max_range, msg.range = r.field_of_view, r.min_range, r.max_range, r.range
    return msg


def to_imu_msg(i: Imu) -> ImuMsg:
    """sensor_msgs/Imu."""
    msg = _stamped(ImuMsg(), i)
    q = msg.orientation
    q.w, q.x, q.y, q.z = (float(v) for v in i.orientation)
    av, la = msg.angular_velocity, msg.linear_acceleration
    av.x, av.y, av.z = (float(v) for v in i.angular_velocity)
    la.x, la.y, la.z = (float(v) for v in i.linear_acceleration)
    msg.orientation_covariance = array("d", i.orientation_covariance)
    msg.angular_velocity_covariance = array("d", i.angular_velocity_covariance)
    msg.linear_acceleration_covariance = array("d", i.linear_acceleration_covariance)
    return msg


def to_image_msg(i: Image) -> ImageMsg:
    """sensor_msgs/Image."""
    msg = _stamped(ImageMsg(), i)
    msg.height, msg.width, msg.encoding, msg.step = i.height, i.width, i.encoding, i.step
    msg.is_bigendian = 0
    msg.data = i.data
    return msg


def to_camera_info_msg(c: CameraInfo) -> CameraInfoMsg:
    """sensor_msgs/CameraInfo."""
    msg = _stamped(CameraInfoMsg(), c)
    msg.height, msg.width = c.height, c.width
    msg.distortion_model = c.distortion_model
    msg.d = array("d", c.d)
    msg.k = array("d", c.k)
    msg.r = array("d", c.r)
    msg.p = array("d", c.p)
    return msg


def _vec(v) -> Vector3:
    return Vector3(x=float(v[0]), y=float(v[1]), z=float(v[2]))


def to_contacts_msg(c: Contacts) -> ContactsState:
    """gazebo_msgs/ContactsState (one ContactState per pair of collisions in contact)."""
    msg = _stamped(ContactsState(), c)
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
    msg = _stamped(GzContacts(), c)
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


def to_nav_sat_fix_msg(f: NavSatFix) -> NavSatFixMsg:
    """sensor_msgs/NavSatFix with a fix from the GPS service."""
    msg = _stamped(NavSatFixMsg(), f)
    msg.status.status = NavSatStatus.STATUS_FIX
    msg.status.service = f.service
    msg.latitude, msg.longitude, msg.altitude = f.latitude, f.longitude, f.altitude
    msg.position_covariance = array("d", f.position_covariance)
    msg.position_covariance_type = f.covariance_type
    return msg


def to_vector3_stamped_msg(v: Vector3Stamped) -> Vector3StampedMsg:
    """geometry_msgs/Vector3Stamped."""
    msg = _stamped(Vector3StampedMsg(), v)
    msg.vector = _vec(v.vector)
    return msg


def to_wrench_stamped_msg(w: WrenchStamped) -> WrenchStampedMsg:
    """geometry_msgs/WrenchStamped."""
    msg = _stamped(WrenchStampedMsg(), w)
    msg.wrench = Wrench(force=_vec(w.force), torque=_vec(w.torque))
    return msg


def _to_tf(batch: TransformBatch) -> TFMessage:
    return TFMessage(transforms=[to_transform_msg(t) for t in batch.transforms])


def to_magnetic_field_msg(m: MagneticField) -> MagneticFieldMsg:
    """Bus payload -> sensor_msgs/MagneticField."""
    msg = MagneticFieldMsg(magnetic_field_covariance=list(m.covariance))
    msg.header.stamp = to_time(m.stamp_sec)
    msg.header.frame_id = m.frame_id
    msg.magnetic_field.x, msg.magnetic_field.y, msg.magnetic_field.z = m.field
    return msg


def to_altimeter_msg(a: Altimeter) -> AltimeterMsg:
    """Bus payload -> ros_gz_interfaces/Altimeter."""
    msg = AltimeterMsg(
        vertical_position=a.vertical_position,
        vertical_velocity=a.vertical_velocity,
        vertical_reference=a.vertical_reference,
    )
    msg.header.stamp = to_time(a.stamp_sec)
    msg.header.frame_id = a.frame_id
    return msg


def to_duration(sec: float) -> Duration:
    """builtin_interfaces/Duration from seconds (the nanoseconds always non-negative, as ROS keeps them)."""
    s = math.floor(sec)
    ns = int(round((sec - s) * 1e9))
    if ns >= 1_000_000_000:
        s, ns = s + 1, ns - 1_000_000_000
    return Duration(sec=int(s), nanosec=ns)


def from_duration(d: Duration) -> float:
    """Seconds of a builtin_interfaces/Duration."""
    return d.sec + d.nanosec * 1e-9


def from_twist_stamped_msg(m: TwistStampedMsg) -> TwistStamped:
    """geometry_msgs/TwistStamped -> bus payload."""
    return TwistStamped(from_time(m.header.stamp), m.header.frame_id, from_twist_msg(m.twist))


def to_twist_stamped_msg(t: TwistStamped) -> TwistStampedMsg:
    """Bus payload -> geometry_msgs/TwistStamped."""
    msg = _stamped(TwistStampedMsg(), t)
    msg.twist = to_twist_msg(t.twist)
    return msg


def to_trajectory_point_msg(p: TrajectoryPoint) -> JointTrajectoryPoint:
    """Bus payload -> trajectory_msgs/JointTrajectoryPoint."""
    return JointTrajectoryPoint(
        positions=list(p.positions),
        velocities=list(p.velocities),
        accelerations=list(p.accelerations),
        effort=list(p.effort),
        time_from_start=to_duration(p.time_from_start_sec),
    )


def from_trajectory_point_msg(m: JointTrajectoryPoint) -> TrajectoryPoint:
    """trajectory_msgs/JointTrajectoryPoint -> bus payload."""
    return TrajectoryPoint(
        from_duration(m.time_from_start),
        tuple(float(v) for v in m.positions),
        tuple(float(v) for v in m.velocities),
        tuple(float(v) for v in m.accelerations),
        tuple(float(v) for v in m.effort),
    )


def from_joint_trajectory_msg(m: JointTrajectoryMsg) -> JointTrajectory:
    """trajectory_msgs/JointTrajectory -> bus payload."""
    return JointTrajectory(
        from_time(m.header.stamp), tuple(m.joint_names), tuple(from_trajectory_point_msg(p) for p in m.points)
    )


def to_joint_trajectory_msg(t: JointTrajectory) -> JointTrajectoryMsg:
    """Bus payload -> trajectory_msgs/JointTrajectory."""
    msg = JointTrajectoryMsg(joint_names=list(t.joint_names), points=[to_trajectory_point_msg(p) for p in t.points])
    msg.header.stamp = to_time(t.stamp_sec)
    return msg


def to_jtc_state_msg(s: TrajectoryControllerState) -> JointTrajectoryControllerStateMsg:
    """Bus payload -> control_msgs/JointTrajectoryControllerState."""
    msg = ros_type(MsgType.TRAJECTORY_CONTROLLER_STATE)(
        joint_names=list(s.joint_names),
        reference=to_trajectory_point_msg(s.reference),
        feedback=to_trajectory_point_msg(s.feedback),
        error=to_trajectory_point_msg(s.error),
        output=to_trajectory_point_msg(s.output),
    )
    msg.header.stamp = to_time(s.stamp_sec)
    return msg


def to_dynamic_joint_state_msg(s: DynamicJointState) -> DynamicJointStateMsg:
    """Bus payload -> control_msgs/DynamicJointState."""
    interface_value = interface_class("control_msgs/msg/InterfaceValue")
    msg = ros_type(MsgType.DYNAMIC_JOINT_STATE)(
        joint_names=list(s.joint_names),
        interface_values=[
            interface_value(interface_names=list(names), values=[float(v) for v in values])
            for names, values in s.interface_values
        ],
    )
    return _stamped(msg, s)


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

TO_ROS = {
    MsgType.ODOMETRY: to_odometry_msg,
    MsgType.TF: _to_tf,
    MsgType.TF_STATIC: _to_tf,
    MsgType.STRING: lambda t: StringMsg(data=t.data),
    MsgType.JOINT_STATE: to_joint_state_msg,
    MsgType.TWIST: to_twist_msg,
    MsgType.FLOAT64: lambda f: Float64Msg(data=float(f.data)),
    MsgType.LASER_SCAN: to_laser_scan_msg,
    MsgType.POINT_CLOUD2: to_point_cloud_msg,
    MsgType.RANGE: to_range_msg,
    MsgType.IMU: to_imu_msg,
    MsgType.IMAGE: to_image_msg,
    MsgType.CAMERA_INFO: to_camera_info_msg,
    MsgType.CONTACTS: to_contacts_msg,
    MsgType.GZ_CONTACTS: to_gz_contacts_msg,
    MsgType.NAV_SAT_FIX: to_nav_sat_fix_msg,
    MsgType.VECTOR3_STAMPED: to_vector3_stamped_msg,
    MsgType.WRENCH_STAMPED: to_wrench_stamped_msg,
    MsgType.TWIST_STAMPED: to_twist_stamped_msg,
    MsgType.MAGNETIC_FIELD: to_magnetic_field_msg,
    MsgType.ALTIMETER: to_altimeter_msg,
    MsgType.FLOAT64_ARRAY: lambda a: Float64MultiArray(data=[float(v) for v in a.data]),
    MsgType.JOINT_TRAJECTORY: to_joint_trajectory_msg,
    MsgType.TRAJECTORY_CONTROLLER_STATE: to_jtc_state_msg,
    MsgType.DYNAMIC_JOINT_STATE: to_dynamic_joint_state_msg,
}
FROM_ROS = {
    MsgType.TWIST: from_twist_msg,
    MsgType.FLOAT64: lambda m: Float64(float(m.data)),
    MsgType.TWIST_STAMPED: from_twist_stamped_msg,
    MsgType.FLOAT64_ARRAY: lambda m: Float64Array(tuple(float(v) for v in m.data)),
    MsgType.JOINT_TRAJECTORY: from_joint_trajectory_msg,
    MsgType.DISPLAY_TRAJECTORY: lambda m: DisplayTrajectory(
        str(m.model_id), tuple(from_joint_trajectory_msg(t.joint_trajectory) for t in m.trajectory)
    ),
}


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


def to_ros(kind: MsgType | DeclaredMessage) -> Callable[[Any], Any]:
    """The payload-to-message conversion of an endpoint's kind: MsgType's from the table above; a declared
    one's generic: the payload dataclass's fields set by name, ``stamp_sec``/``frame_id`` as the header."""
    found = TO_ROS.get(kind) if isinstance(kind, MsgType) else None
    if found is not None:
        return found
    cls = ros_type(kind)

    def convert(payload: Any) -> Any:
        msg = cls()
        for f in dataclasses.fields(payload):
            value = getattr(payload, f.name)
            if f.name == "stamp_sec":
                msg.header.stamp = to_time(value)
            elif f.name == "frame_id":
                msg.header.frame_id = value
            else:
                setattr(msg, f.name, value)
        return msg

    return convert

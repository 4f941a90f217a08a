"""The payloads the bus carries: plain frozen dataclasses mirroring ROS messages, field for field where
it matters, converted to and from rclpy messages only in ``gazelle.ros`` (``_convert.py``). Stamps are
``stamp_sec``, sim time in seconds; frames are ``frame_id`` strings as the message's header has them;
arrays that are large (scans, images, clouds) are ``bytes``, cheap to hand to the publisher thread.

A payload whose fields are not its message's by name says where they go in ``ROS_FIELDS`` (payload field ->
dotted message path); ``gazelle.ros._layouts`` converts every payload with one generic plan by these names
(its docstring has the rules), and ``_convert.py`` writes by hand only the few whose layout differs."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any, ClassVar

from ..description import Pose

Vec3 = tuple[float, float, float]


# --------------------------------------------------------------------------- payloads
@dataclass(frozen=True, slots=True)
class Twist:
    """geometry_msgs/Twist."""

    linear: Vec3 = (0.0, 0.0, 0.0)
    """m/s along x, y, z of the frame the message names (a cmd_vel's: the robot's base)."""
    angular: Vec3 = (0.0, 0.0, 0.0)
    """rad/s about x, y, z."""


@dataclass(frozen=True, slots=True)
class Odometry:
    """nav_msgs/Odometry."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {
        "pose": "pose.pose",
        "twist": "twist.twist",
        "pose_covariance": "pose.covariance",
        "twist_covariance": "twist.covariance",
    }
    stamp_sec: float
    frame_id: str
    child_frame_id: str
    """The body frame the twist is expressed in (base_footprint, base_link)."""
    pose: Pose
    """X_frame_child: the body in the odometry frame, metres and a wxyz quaternion."""
    twist: Twist
    """The body's velocity, in child_frame_id (REP 105), not in the odometry frame."""
    pose_covariance: tuple[float, ...] = (0.0,) * 36
    """Row-major 6x6 over (x, y, z, roll, pitch, yaw), as nav_msgs/Odometry."""
    twist_covariance: tuple[float, ...] = (0.0,) * 36
    """Row-major 6x6 over (vx, vy, vz, wx, wy, wz)."""


@dataclass(frozen=True, slots=True)
class Transform:
    """geometry_msgs/TransformStamped: ``pose`` is the child frame in the parent frame."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {
        "parent": "header.frame_id",
        "child": "child_frame_id",
        "pose": "transform",
        "pose.position": "translation",
        "pose.orientation": "rotation",
    }
    stamp_sec: float
    parent: str
    """The frame the child is placed in (tf's header.frame_id)."""
    child: str
    """tf's child_frame_id."""
    pose: Pose
    """X_parent_child."""


@dataclass(frozen=True, slots=True)
class TransformBatch:
    """tf2_msgs/TFMessage."""

    transforms: tuple[Transform, ...]
    """One tf2_msgs/TFMessage's transforms, published together."""


@dataclass(frozen=True, slots=True)
class JointStates:
    """sensor_msgs/JointState."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {
        "names": "name",
        "positions": "position",
        "velocities": "velocity",
        "efforts": "effort",
    }
    stamp_sec: float
    names: tuple[str, ...]
    """Joint names, in the order of the values below."""
    positions: tuple[float, ...]
    """rad or m."""
    velocities: tuple[float, ...]
    """rad/s or m/s."""
    efforts: tuple[float, ...] = ()
    """N·m or N: the actuator force on each joint (empty: not measured)."""
    frame_id: str = ""
    """The header's frame (joint_state_broadcaster's ``frame_id``, ``base_link`` by default; "" elsewhere)."""


class PayloadBlock:
    """Consecutive payloads of one publisher handed over at once (one per cycle of a block of steps run
    inside MuJoCo, see ``gazelle.physics.ServoPlan``): a sequence of the bus's messages. Sinks that take
    blocks (the ROS bridge's publisher lanes) get it whole and build the messages off the simulation
    thread; the others get each message in order (:meth:`Endpoint.publish_block`)."""

    __slots__ = ()

    def __len__(self) -> int:
        raise NotImplementedError

    def __iter__(self) -> Iterator[Any]:
        raise NotImplementedError

    def last(self) -> Any:
        """The block's last payload."""
        raise NotImplementedError


class JointStatesBlock(PayloadBlock):
    """sensor_msgs/JointState of consecutive cycles, as arrays (rows: cycles; columns: ``names``)."""

    __slots__ = ("efforts", "frame_id", "names", "positions", "stamps", "velocities")

    def __init__(
        self,
        stamps: list[float],
        names: tuple[str, ...],
        positions: Any,
        velocities: Any,
        efforts: Any,
        frame_id: str = "",
    ) -> None:
        """The joint states of a block of cycles: one stamp per cycle and arrays of cycles x joints."""
        self.stamps = stamps
        self.names = names
        self.positions = positions
        self.velocities = velocities
        self.efforts = efforts
        self.frame_id = frame_id

    def __len__(self) -> int:
        return len(self.stamps)

    def __iter__(self) -> Iterator[JointStates]:
        """The block as one JointStates payload per cycle, in time order."""
        names = self.names
        for t, p, v, e in zip(
            self.stamps, self.positions.tolist(), self.velocities.tolist(), self.efforts.tolist(), strict=True
        ):
            yield JointStates(t, names, tuple(p), tuple(v), tuple(e), self.frame_id)

    def last(self) -> JointStates:
        """The last cycle's JointStates (what a latched reader or the viewer wants)."""
        return JointStates(
            self.stamps[-1],
            self.names,
            tuple(self.positions[-1].tolist()),
            tuple(self.velocities[-1].tolist()),
            tuple(self.efforts[-1].tolist()),
            self.frame_id,
        )


@dataclass(frozen=True, slots=True)
class Text:
    """std_msgs/String."""

    data: str


@dataclass(frozen=True, slots=True)
class Float64:
    """std_msgs/Float64 (joint position / velocity commands)."""

    data: float


@dataclass(frozen=True, slots=True)
class LaserScan:
    """sensor_msgs/LaserScan. ``ranges`` and ``intensities`` are float32 arrays' bytes (immutable,
    cheap to hand to the publisher thread); out-of-range readings are ±inf as REP 117 says."""

    stamp_sec: float
    frame_id: str
    angle_min: float
    """Angle of the first ray, radians about the sensor's z (0 is its x axis)."""
    angle_max: float
    """Angle of the last ray."""
    angle_increment: float
    """Radians between neighbouring rays."""
    range_min: float
    """Metres; nearer readings are -inf."""
    range_max: float
    """Metres; readings beyond it (and misses) are +inf."""
    ranges: bytes
    intensities: bytes
    time_increment: float = 0.0
    """Seconds between rays: 0, all rays of a scan are cast at one instant."""
    scan_time: float = 0.0
    """Seconds between scans (1 / the update rate)."""


@dataclass(frozen=True, slots=True)
class CloudLayout:
    """The float32 fields of a PointCloud2's points, by name and byte offset, and the bytes per point."""

    fields: tuple[tuple[str, int], ...]
    point_step: int


XYZI = CloudLayout((("x", 0), ("y", 4), ("z", 8), ("intensity", 12)), 16)
"""x, y, z, intensity in 16 bytes: gazebo_ros_ray_sensor's and gz-sim's lidar clouds."""
XYZ_RGB_PADDED = CloudLayout((("x", 0), ("y", 4), ("z", 8), ("rgb", 16)), 32)
"""x, y, z, then rgb at byte 16 of 32 (PCL's PointXYZRGB): gazebo_ros_camera's depth cloud."""
XYZ_RGB = CloudLayout((("x", 0), ("y", 4), ("z", 8), ("rgb", 12)), 16)
"""x, y, z, rgb packed in 16 bytes (gz-msgs InitPointCloudPacked, not memory-aligned): gz-sim's depth cloud."""


@dataclass(frozen=True, slots=True)
class PointCloud:
    """sensor_msgs/PointCloud2 of float32 fields (``layout``; unorganised when ``height`` is 1), ``data``
    little-endian bytes."""

    stamp_sec: float
    frame_id: str
    width: int
    """Points per row (all points when height is 1)."""
    height: int
    """Rows: 1 for an unorganised cloud, the image's height for a depth camera's organised one."""
    data: bytes
    layout: CloudLayout = XYZI
    is_dense: bool = False
    """True only when every point is finite (an organised cloud with ±inf points is not dense)."""


@dataclass(frozen=True, slots=True)
class Range:
    """sensor_msgs/Range (``radiation_type`` 0 ultrasound, 1 infrared)."""

    stamp_sec: float
    frame_id: str
    radiation_type: int
    field_of_view: float
    """The cone's full angle, radians."""
    min_range: float
    """Metres; a nearer reading is -inf."""
    max_range: float
    """Metres; nothing within it reads +inf."""
    range: float
    """The nearest hit within the cone, metres."""


@dataclass(frozen=True, slots=True)
class Imu:
    """sensor_msgs/Imu. A covariance whose first element is -1 says "not provided" (REP 145)."""

    stamp_sec: float
    frame_id: str
    orientation: tuple[float, float, float, float]
    """(w, x, y, z)."""
    angular_velocity: Vec3
    """rad/s about the sensor frame's axes."""
    linear_acceleration: Vec3
    """m/s², proper acceleration in the sensor frame: +9.8 up along z at rest on flat ground."""
    orientation_covariance: tuple[float, ...] = (0.0,) * 9
    """Row-major 3x3 about the x, y, z axes, rad²."""
    angular_velocity_covariance: tuple[float, ...] = (0.0,) * 9
    """Row-major 3x3, (rad/s)²: the noise's variance on the diagonal."""
    linear_acceleration_covariance: tuple[float, ...] = (0.0,) * 9
    """Row-major 3x3, (m/s²)²."""


@dataclass(frozen=True, slots=True)
class Image:
    """sensor_msgs/Image: ``data`` holds ``height`` rows of ``step`` bytes."""

    stamp_sec: float
    frame_id: str
    height: int
    """Rows, pixels."""
    width: int
    """Columns, pixels."""
    encoding: str
    """rgb8, bgr8, mono8 or 32FC1 (depth in metres)."""
    step: int
    """Bytes per row: width times the bytes per pixel."""
    data: bytes
    """The rows, top first, bytes as the encoding says (32FC1 little-endian)."""


@dataclass(frozen=True, slots=True)
class CameraInfo:
    """sensor_msgs/CameraInfo (row-major K 3x3, R 3x3, P 3x4; D as ``distortion_model`` orders it)."""

    stamp_sec: float
    frame_id: str
    height: int
    width: int
    distortion_model: str
    """plumb_bob: d holds k1, k2, p1, p2, k3."""
    d: tuple[float, ...]
    """Distortion coefficients (published, not applied to the image)."""
    k: tuple[float, ...]
    """Row-major 3x3 intrinsics: fx, 0, cx, 0, fy, cy, 0, 0, 1 (pixels)."""
    r: tuple[float, ...]
    """Row-major 3x3 rectification: the identity for a monocular camera."""
    p: tuple[float, ...]
    """Row-major 3x4 projection: K with a zero fourth column (no stereo baseline)."""


@dataclass(frozen=True, slots=True)
class ContactPair:
    """gazebo_msgs/ContactState: the contacts between two collisions, forces on ``collision1``."""

    collision1: str
    """Scoped collision name (model::link::collision) the forces act on."""
    collision2: str
    """The other collision's scoped name."""
    positions: tuple[Vec3, ...]
    """Contact points, world frame, metres."""
    normals: tuple[Vec3, ...]
    """Unit normals, world frame, pointing from collision2 into collision1."""
    forces: tuple[Vec3, ...]
    """Force on collision1 at each point, newtons, world frame."""
    torques: tuple[Vec3, ...]
    """Torque on collision1 at each point, N·m, world frame."""
    depths: tuple[float, ...]
    """Penetration at each point, metres (positive: overlapping)."""


@dataclass(frozen=True, slots=True)
class Contacts:
    """gazebo_msgs/ContactsState."""

    stamp_sec: float
    frame_id: str
    states: tuple[ContactPair, ...]
    """One entry per pair of collisions in contact."""


@dataclass(frozen=True, slots=True)
class NavSatFix:
    """sensor_msgs/NavSatFix, status FIX."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {
        "covariance_type": "position_covariance_type",
        "service": "status.service",
        "status": "status.status",
    }
    stamp_sec: float
    frame_id: str
    latitude: float
    """Degrees North (WGS84)."""
    longitude: float
    """Degrees East."""
    altitude: float
    """Metres above the WGS84 ellipsoid."""
    position_covariance: tuple[float, ...] = (0.0,) * 9
    """Row-major 3x3 in East, North, Up, m²."""
    covariance_type: int = 0
    """0 unknown, 1 approximated, 2 diagonal known, 3 known."""
    service: int = 1
    """NavSatStatus's service bits: 1 GPS (gazebo_ros_gps_sensor), 0 none (ros_gz_bridge leaves it unset)."""
    status: int = 0
    """NavSatStatus's status: 0 STATUS_FIX (the message's own default is -2, unknown)."""


@dataclass(frozen=True, slots=True)
class Vector3Stamped:
    """geometry_msgs/Vector3Stamped."""

    stamp_sec: float
    frame_id: str
    vector: Vec3
    """In frame_id; units as the topic says (a GPS velocity: m/s East, North, Up)."""


@dataclass(frozen=True, slots=True)
class WrenchStamped:
    """geometry_msgs/WrenchStamped."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {"force": "wrench.force", "torque": "wrench.torque"}
    stamp_sec: float
    frame_id: str
    force: Vec3
    """Newtons, in frame_id."""
    torque: Vec3
    """N·m, in frame_id."""


@dataclass(frozen=True, slots=True)
class MagneticField:
    """sensor_msgs/MagneticField (tesla, in the sensor's frame)."""

    ROS_FIELDS: ClassVar[dict[str, str]] = {"field": "magnetic_field", "covariance": "magnetic_field_covariance"}
    stamp_sec: float
    frame_id: str
    field: Vec3
    """Tesla along the sensor's x, y, z."""
    covariance: tuple[float, ...] = (0.0,) * 9
    """Row-major 3x3, tesla²."""


@dataclass(frozen=True, slots=True)
class Altimeter:
    """ros_gz_interfaces/Altimeter (what ros_gz_bridge makes of gz's): height above the reference (m),
    vertical velocity (m/s) and the reference (the sensor's height when it started)."""

    stamp_sec: float
    frame_id: str
    vertical_position: float
    """Metres above vertical_reference."""
    vertical_velocity: float
    """m/s, up positive."""
    vertical_reference: float
    """The world z (metres) the altitude is measured from: the sensor's at its start."""


@dataclass(frozen=True, slots=True)
class TwistStamped:
    """geometry_msgs/TwistStamped (diff_drive_controller's ``~/cmd_vel`` on Jazzy)."""

    stamp_sec: float
    frame_id: str
    twist: Twist
    """In frame_id (a controller's cmd_vel: the robot's base frame)."""


@dataclass(frozen=True, slots=True)
class Float64Array:
    """std_msgs/Float64MultiArray (forward command controllers' ``~/commands``); the layout is not used."""

    data: tuple[float, ...]
    """std_msgs/Float64MultiArray's data (no layout: a flat vector, one value per joint)."""


@dataclass(frozen=True, slots=True)
class TrajectoryPoint:
    """trajectory_msgs/JointTrajectoryPoint (empty tuples where the message has no values)."""

    time_from_start_sec: float
    """When the point is to be reached, seconds after the trajectory's start."""
    positions: tuple[float, ...] = ()
    """One per joint, rad or m (empty: not given)."""
    velocities: tuple[float, ...] = ()
    """rad/s or m/s (empty: not given)."""
    accelerations: tuple[float, ...] = ()
    """rad/s² or m/s² (empty: not given)."""
    effort: tuple[float, ...] = ()
    """N·m or N (empty: not given)."""


@dataclass(frozen=True, slots=True)
class JointTrajectory:
    """trajectory_msgs/JointTrajectory (``stamp_sec`` 0: start now)."""

    stamp_sec: float
    """When the trajectory starts, sim time; 0 means on arrival."""
    joint_names: tuple[str, ...]
    """The joints the points' values are for, in order."""
    points: tuple[TrajectoryPoint, ...]
    """Waypoints in time order."""


@dataclass(frozen=True, slots=True)
class DisplayTrajectory:
    """moveit_msgs/DisplayTrajectory: the joint trajectories a planner made for robot ``model_id``, one
    after the other (MoveIt's ``display_planned_path``)."""

    model_id: str
    """The robot's name (MoveIt's DisplayTrajectory.model_id)."""
    trajectories: tuple[JointTrajectory, ...]
    """The planned path, one segment per trajectory."""


@dataclass(frozen=True, slots=True)
class TrajectoryControllerState:
    """control_msgs/JointTrajectoryControllerState: reference, feedback and error of each joint."""

    stamp_sec: float
    joint_names: tuple[str, ...]
    """The controller's joints, in order."""
    reference: TrajectoryPoint
    """Where the trajectory says the joints should be now."""
    feedback: TrajectoryPoint
    """Where they are."""
    error: TrajectoryPoint
    """reference minus feedback."""
    output: TrajectoryPoint
    """What the controller commanded this cycle."""


@dataclass(frozen=True, slots=True)
class InterfaceValue:
    """control_msgs/InterfaceValue: one joint's interfaces and their values, in the same order."""

    interface_names: tuple[str, ...]
    """``position``, ``velocity``, ``effort``, ... as the hardware names them."""
    values: tuple[float, ...]
    """One per interface name."""


@dataclass(frozen=True, slots=True)
class DynamicJointState:
    """control_msgs/DynamicJointState: every interface of every joint (and sensor) by name."""

    stamp_sec: float
    joint_names: tuple[str, ...]
    """Joints (and sensors, gpios) of the hardware, in order."""
    interface_values: tuple[InterfaceValue, ...]
    """Per joint, in the order of ``joint_names``."""
    frame_id: str = ""
    """The header's frame (joint_state_broadcaster's ``frame_id``)."""

"""A small in-process message bus between systems and the outside world.

Systems publish and subscribe plain dataclass payloads (below) on ROS-style
topic names; the ROS bridge (``gazelle.ros``) listens for endpoints being added
and removed and mirrors them as rclpy publishers and subscriptions. The core
never imports rclpy: with no bridge attached, publishing costs a list lookup.
"""

from __future__ import annotations

import enum
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, Protocol

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

    stamp_sec: float
    names: tuple[str, ...]
    """Joint names, in the order of the values below."""
    positions: tuple[float, ...]
    """rad or m."""
    velocities: tuple[float, ...]
    """rad/s or m/s."""
    efforts: tuple[float, ...] = ()
    """N·m or N: the actuator force on each joint (empty: not measured)."""


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

    __slots__ = ("efforts", "names", "positions", "stamps", "velocities")

    def __init__(
        self, stamps: list[float], names: tuple[str, ...], positions: Any, velocities: Any, efforts: Any
    ) -> None:
        """The joint states of a block of cycles: one stamp per cycle and arrays of cycles x joints."""
        self.stamps = stamps
        self.names = names
        self.positions = positions
        self.velocities = velocities
        self.efforts = efforts

    def __len__(self) -> int:
        return len(self.stamps)

    def __iter__(self) -> Iterator[JointStates]:
        """The block as one JointStates payload per cycle, in time order."""
        names = self.names
        for t, p, v, e in zip(
            self.stamps, self.positions.tolist(), self.velocities.tolist(), self.efforts.tolist(), strict=True
        ):
            yield JointStates(t, names, tuple(p), tuple(v), tuple(e))

    def last(self) -> JointStates:
        """The last cycle's JointStates (what a latched reader or the viewer wants)."""
        return JointStates(
            self.stamps[-1],
            self.names,
            tuple(self.positions[-1].tolist()),
            tuple(self.velocities[-1].tolist()),
            tuple(self.efforts[-1].tolist()),
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
class PointCloud:
    """sensor_msgs/PointCloud2 with float32 fields x, y, z, intensity (16-byte points, unorganised
    when ``height`` is 1), ``data`` little-endian bytes."""

    stamp_sec: float
    frame_id: str
    width: int
    """Points per row (all points when height is 1)."""
    height: int
    """Rows: 1 for an unorganised cloud, the image's height for a depth camera's organised one."""
    data: bytes


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
    """sensor_msgs/NavSatFix (status FIX, service GPS)."""

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

    stamp_sec: float
    frame_id: str
    force: Vec3
    """Newtons, in frame_id."""
    torque: Vec3
    """N·m, in frame_id."""


@dataclass(frozen=True, slots=True)
class MagneticField:
    """sensor_msgs/MagneticField (tesla, in the sensor's frame)."""

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
class DynamicJointState:
    """control_msgs/DynamicJointState: every interface of every joint (and sensor) by name."""

    stamp_sec: float
    joint_names: tuple[str, ...]
    """Joints (and sensors, gpios) of the hardware, in order."""
    interface_values: tuple[tuple[tuple[str, ...], tuple[float, ...]], ...]
    """Per joint: (interface names, values)."""


class MsgType(enum.Enum):
    """The ROS message type each payload maps to."""

    TWIST = "geometry_msgs/msg/Twist"
    ODOMETRY = "nav_msgs/msg/Odometry"
    TF = "tf2_msgs/msg/TFMessage"
    TF_STATIC = "tf2_msgs/msg/TFMessage#static"
    """Like TF, but every publisher's transforms are kept and sent together, as tf2's static broadcaster does."""
    JOINT_STATE = "sensor_msgs/msg/JointState"
    STRING = "std_msgs/msg/String"
    FLOAT64 = "std_msgs/msg/Float64"
    LASER_SCAN = "sensor_msgs/msg/LaserScan"
    POINT_CLOUD2 = "sensor_msgs/msg/PointCloud2"
    RANGE = "sensor_msgs/msg/Range"
    IMU = "sensor_msgs/msg/Imu"
    IMAGE = "sensor_msgs/msg/Image"
    CAMERA_INFO = "sensor_msgs/msg/CameraInfo"
    CONTACTS = "gazebo_msgs/msg/ContactsState"
    NAV_SAT_FIX = "sensor_msgs/msg/NavSatFix"
    VECTOR3_STAMPED = "geometry_msgs/msg/Vector3Stamped"
    WRENCH_STAMPED = "geometry_msgs/msg/WrenchStamped"
    TWIST_STAMPED = "geometry_msgs/msg/TwistStamped"
    MAGNETIC_FIELD = "sensor_msgs/msg/MagneticField"
    ALTIMETER = "ros_gz_interfaces/msg/Altimeter"
    FLOAT64_ARRAY = "std_msgs/msg/Float64MultiArray"
    JOINT_TRAJECTORY = "trajectory_msgs/msg/JointTrajectory"
    TRAJECTORY_CONTROLLER_STATE = "control_msgs/msg/JointTrajectoryControllerState"
    DYNAMIC_JOINT_STATE = "control_msgs/msg/DynamicJointState"
    DISPLAY_TRAJECTORY = "moveit_msgs/msg/DisplayTrajectory"


class Qos(enum.Enum):
    """QoS profiles named after what ROS uses them for."""

    DEFAULT = "default"
    """reliable, volatile, keep last ``depth``."""
    SENSOR = "sensor"
    """best effort, keep last ``depth``."""
    LATCHED = "latched"
    """reliable, transient local (like /tf_static, /robot_description)."""


# --------------------------------------------------------------------------- endpoints
@dataclass(frozen=True)
class DeclaredMessage:
    """A message type declared by the system that publishes it, beside :class:`MsgType`'s (a new sensor
    kind's, in its own module). The ROS layer publishes it as ``value`` (``pkg/msg/Name``) by a generic
    conversion: the payload is a dataclass whose fields are the ROS message's own, ``stamp_sec`` and
    ``frame_id`` going into its ``header``."""

    name: str
    value: str
    """The ROS type, ``sensor_msgs/msg/FluidPressure``."""


MessageKind = MsgType | DeclaredMessage
"""What an endpoint carries: one of :class:`MsgType`'s, or a :class:`DeclaredMessage`."""


@dataclass(eq=False)
class Endpoint:
    """One publisher or subscription declared by a system."""

    owner: str
    """Entity name (endpoints are removed with their entity)."""
    topic: str
    """Fully resolved topic name, e.g. ``/cmd_vel`` or ``/r1/odom``."""
    msg_type: MessageKind
    is_publisher: bool
    qos: Qos = Qos.DEFAULT
    depth: int = 10
    callback: Callable[[Any], None] | None = None
    """Subscriptions: called (from a bridge thread, or by :meth:`Bus.inject`) with each payload."""
    sinks: tuple[Callable[[Any], None], ...] = field(default=(), repr=False)
    """Publishers: everything that receives each published payload (the ROS bridge, a recorder, an echo)."""
    last: Any = field(default=None, repr=False)
    """Publishers: the latest payload published (only published while :attr:`wanted`)."""
    _interest: tuple[Callable[[], bool] | None, ...] = field(default=(), repr=False)
    """Per sink: whether it wants payloads now (None: always)."""
    _takes_blocks: tuple[bool, ...] = field(default=(), repr=False)
    """Per sink: whether it takes a :class:`PayloadBlock` whole."""
    node: str = ""
    """The fully qualified ROS node it belongs to (``/differential_drive``): the gazebo_ros plugin that
    declared it (see :meth:`Bus.declaring`); "" for the simulation's own node."""

    def add_sink(
        self, sink: Callable[[Any], None], wanted: Callable[[], bool] | None = None, *, blocks: bool = False
    ) -> None:
        """Also send every published payload to ``sink`` (any number of them: the bus fans out).

        ``wanted`` says whether the sink wants payloads at the moment (the ROS bridge: whether
        anyone subscribes in ROS); without it, the sink always does. ``blocks``: the sink takes a
        :class:`PayloadBlock` whole (else it gets the block's payloads one by one).
        """
        # new tuples: publish() and wanted iterate without a lock
        self.sinks, self._interest = (*self.sinks, sink), (*self._interest, wanted)
        self._takes_blocks = (*self._takes_blocks, blocks)

    def remove_sink(self, sink: Callable[[Any], None]) -> None:
        """Stop sending payloads to ``sink``."""
        # == so that bound methods match
        keep = [x for x in zip(self.sinks, self._interest, self._takes_blocks, strict=True) if x[0] != sink]
        self.sinks, self._interest = tuple(x[0] for x in keep), tuple(x[1] for x in keep)
        self._takes_blocks = tuple(x[2] for x in keep)

    @property
    def wanted(self) -> bool:
        """Whether a payload published now reaches anyone. Systems build a message only when it is:
        with nobody listening (no ROS subscriber, no recorder, no viewer trail), publishing costs
        nothing, as in gz-transport."""
        for w in self._interest:
            if w is None or w():
                return True
        return False

    def publish(self, payload: Any) -> None:
        """Send a payload to every sink."""
        self.last = payload
        for sink in self.sinks:
            sink(payload)

    def publish_block(self, block: PayloadBlock) -> None:
        """Send consecutive payloads at once: whole to the sinks that take blocks, one by one (in order)
        to the others."""
        if not len(block):
            return
        self.last = block.last()
        for sink, whole in zip(self.sinks, self._takes_blocks, strict=True):
            if whole:
                sink(block)
            else:
                for payload in block:
                    sink(payload)


ParamValue = bool | int | float | str | list[bool] | list[int] | list[float] | list[str]


@dataclass(eq=False)
class PluginNode:
    """A gazebo_ros plugin's ROS node, announced with :meth:`Bus.add_component`: its name, and its
    configuration as parameters (read-only unless ``settable`` has a setter for the name; a setter runs
    on the simulation thread and returns None when applied, else why not)."""

    name: str
    namespace: str
    parameters: dict[str, ParamValue]
    settable: dict[str, Callable[[ParamValue], str | None]] = field(default_factory=dict)
    plugin: str = ""
    """The plugin's file name, as written."""

    @property
    def fully_qualified_name(self) -> str:
        """``/<namespace>/<name>``."""
        ns = self.namespace.strip("/")
        return f"/{ns}/{self.name}" if ns else f"/{self.name}"


class BusListener(Protocol):
    """What listens to the bus (the ROS bridge): told of every endpoint added and removed."""

    def endpoint_added(self, ep: Endpoint, /) -> None:
        """A system declared endpoint ``ep`` (called on the declaring thread)."""

    def endpoint_removed(self, ep: Endpoint, /) -> None:
        """Endpoint ``ep`` went away with its entity."""

    def component_added(self, owner: str, component: Any) -> None:
        """A system announced something the ROS layer serves for it (a controller manager's node, an
        action server of a controller); called on the announcing thread."""

    def component_removed(self, component: Any) -> None:
        """An announced component went away."""


class Bus:
    """Registry of endpoints with listeners (the ROS bridge)."""

    def __init__(self) -> None:
        """An empty bus: no endpoints, no listeners (the ROS bridge registers one when it attaches)."""
        self._lock = threading.Lock()
        self._endpoints: list[Endpoint] = []
        self._listeners: list[BusListener] = []
        self._components: list[tuple[str, Any]] = []
        self._declaring = threading.local()

    @contextmanager
    def declaring(self, node: str) -> Iterator[None]:
        """Endpoints declared on this thread inside the block belong to ROS node ``node`` (fully
        qualified; "" for the simulation's node): the runtime wraps a gazebo_ros plugin's configure in it,
        so its topics are its own node's, as in Gazebo."""
        before = getattr(self._declaring, "node", "")
        self._declaring.node = node
        try:
            yield
        finally:
            self._declaring.node = before

    def add_listener(self, listener: BusListener) -> None:
        """Attach a listener; it is told about every existing endpoint first."""
        with self._lock:
            self._listeners.append(listener)
            existing = list(self._endpoints)
        for ep in existing:
            listener.endpoint_added(ep)
        with self._lock:
            components = list(self._components)
        added = getattr(listener, "component_added", None)
        if added is not None:
            for owner, c in components:
                added(owner, c)

    def remove_listener(self, listener: BusListener) -> None:
        """Detach a listener (it is not told about removals any more)."""
        with self._lock:
            if listener in self._listeners:
                self._listeners.remove(listener)

    def advertise(
        self, owner: str, topic: str, msg_type: MessageKind, *, qos: Qos = Qos.DEFAULT, depth: int = 10
    ) -> Endpoint:
        """Declare a publisher."""
        return self._add(Endpoint(owner, topic, msg_type, True, qos, depth))

    def subscribe(
        self,
        owner: str,
        topic: str,
        msg_type: MsgType,
        callback: Callable[[Any], None],
        *,
        qos: Qos = Qos.DEFAULT,
        depth: int = 10,
    ) -> Endpoint:
        """Declare a subscription; ``callback`` may run on any thread."""
        return self._add(Endpoint(owner, topic, msg_type, False, qos, depth, callback))

    def _add(self, ep: Endpoint) -> Endpoint:
        """Add an endpoint (under the plugin node being declared, if any) and tell the listeners, outside the lock,
        so a listener may call back into the bus."""
        ep.node = getattr(self._declaring, "node", "")
        with self._lock:
            self._endpoints.append(ep)
            listeners = list(self._listeners)
        for listener in listeners:
            listener.endpoint_added(ep)
        return ep

    def remove_owner(self, owner: str) -> None:
        """Remove every endpoint of an entity."""
        with self._lock:
            gone = [ep for ep in self._endpoints if ep.owner == owner]
            self._endpoints = [ep for ep in self._endpoints if ep.owner != owner]
            listeners = list(self._listeners)
        for ep in gone:
            ep.sinks, ep._interest, ep._takes_blocks = (), (), ()
            for listener in listeners:
                listener.endpoint_removed(ep)
        with self._lock:
            dropped = [c for o, c in self._components if o == owner]
            self._components = [(o, c) for o, c in self._components if o != owner]
        for c in dropped:
            for listener in listeners:
                removed = getattr(listener, "component_removed", None)
                if removed is not None:
                    removed(c)

    def add_component(self, owner: str, component: Any) -> None:
        """Announce a component of entity ``owner`` to the listeners (see :meth:`BusListener.component_added`)."""
        with self._lock:
            self._components.append((owner, component))
            listeners = list(self._listeners)
        for listener in listeners:
            added = getattr(listener, "component_added", None)
            if added is not None:
                added(owner, component)

    def remove_component(self, component: Any) -> None:
        """Withdraw a component (its listeners are told)."""
        with self._lock:
            before = len(self._components)
            self._components = [(o, c) for o, c in self._components if c is not component]
            if len(self._components) == before:
                return
            listeners = list(self._listeners)
        for listener in listeners:
            removed = getattr(listener, "component_removed", None)
            if removed is not None:
                removed(component)

    def components(self) -> list[tuple[str, Any]]:
        """A snapshot of the announced components, with their owners."""
        with self._lock:
            return list(self._components)

    def remove(self, endpoint: Endpoint) -> None:
        """Remove one endpoint (a controller unloaded while its entity stays)."""
        with self._lock:
            if endpoint not in self._endpoints:
                return
            self._endpoints.remove(endpoint)
            listeners = list(self._listeners)
        endpoint.sinks, endpoint._interest, endpoint._takes_blocks = (), (), ()
        for listener in listeners:
            listener.endpoint_removed(endpoint)

    def endpoints(self) -> list[Endpoint]:
        """A snapshot of every endpoint."""
        with self._lock:
            return list(self._endpoints)

    def inject(self, topic: str, msg_type: MsgType, payload: Any) -> int:
        """Deliver ``payload`` to every subscription of ``topic`` as if it came from ROS.

        What the viewer's drive buttons, a command line tool or bag playback use to publish
        into the simulation the way the ROS bridge does. Returns how many subscriptions got it.
        """
        with self._lock:
            targets = [
                ep
                for ep in self._endpoints
                if not ep.is_publisher and ep.topic == topic and ep.msg_type == msg_type and ep.callback is not None
            ]
        for ep in targets:
            if ep.callback is not None:
                ep.callback(payload)
        return len(targets)


def resolve_topic(name: str, namespace: str = "", remaps: dict[str, str] | None = None, node: str = "") -> str:
    """Resolve a topic name the way rclcpp does for a node called ``node`` in ``namespace``.

    Remappings (``from:=to`` as in ``<ros><remapping>``) apply to the name as written, so
    ``~/out:=scan`` turns a sensor plugin's ``~/out`` into ``<ns>/scan``; an unmapped ``~/out``
    is ``<ns>/<node>/out``.
    """
    if remaps:
        for src, dst in remaps.items():
            if name.lstrip("/") == src.lstrip("/"):
                name = dst
                break
    if name.startswith("~"):
        # node-private (~/out): under the node's own name, as gazebo_ros plugins publish ~/out
        name = f"{node.strip('/')}/{name[1:].lstrip('/')}" if node else name[1:].lstrip("/")
    if name.startswith("/"):
        return name
    ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
    return f"{ns}/{name}"

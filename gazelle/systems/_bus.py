"""A small in-process message bus between systems and the outside world.

Systems publish and subscribe plain dataclass payloads (``_payloads.py``) on ROS-style
topic names; the ROS bridge (``gazelle.ros``) listens for endpoints being added
and removed and mirrors them as rclpy publishers and subscriptions. The core
never imports rclpy: with no bridge attached, publishing costs a list lookup.
"""

from __future__ import annotations

import enum
import re
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, Protocol

from . import _payloads as payloads
from ._payloads import PayloadBlock


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
    GZ_CONTACTS = "ros_gz_interfaces/msg/Contacts"
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


PAYLOADS: dict[MsgType, type] = {
    MsgType.TWIST: payloads.Twist,
    MsgType.ODOMETRY: payloads.Odometry,
    MsgType.TF: payloads.TransformBatch,
    MsgType.TF_STATIC: payloads.TransformBatch,
    MsgType.JOINT_STATE: payloads.JointStates,
    MsgType.STRING: payloads.Text,
    MsgType.FLOAT64: payloads.Float64,
    MsgType.LASER_SCAN: payloads.LaserScan,
    MsgType.POINT_CLOUD2: payloads.PointCloud,
    MsgType.RANGE: payloads.Range,
    MsgType.IMU: payloads.Imu,
    MsgType.IMAGE: payloads.Image,
    MsgType.CAMERA_INFO: payloads.CameraInfo,
    MsgType.CONTACTS: payloads.Contacts,
    MsgType.GZ_CONTACTS: payloads.Contacts,
    MsgType.NAV_SAT_FIX: payloads.NavSatFix,
    MsgType.VECTOR3_STAMPED: payloads.Vector3Stamped,
    MsgType.WRENCH_STAMPED: payloads.WrenchStamped,
    MsgType.TWIST_STAMPED: payloads.TwistStamped,
    MsgType.MAGNETIC_FIELD: payloads.MagneticField,
    MsgType.ALTIMETER: payloads.Altimeter,
    MsgType.FLOAT64_ARRAY: payloads.Float64Array,
    MsgType.JOINT_TRAJECTORY: payloads.JointTrajectory,
    MsgType.TRAJECTORY_CONTROLLER_STATE: payloads.TrajectoryControllerState,
    MsgType.DYNAMIC_JOINT_STATE: payloads.DynamicJointState,
    MsgType.DISPLAY_TRAJECTORY: payloads.DisplayTrajectory,
}
"""The payload dataclass each :class:`MsgType` carries on the bus: the ROS layer converts it to and from the
message by its fields (``ROS_FIELDS`` where their names differ; see ``_payloads.py``)."""


# --------------------------------------------------------------------------- endpoints
@dataclass(frozen=True)
class DeclaredMessage:
    """A message type declared by the system that publishes it, beside :class:`MsgType`'s (a new sensor
    kind's, in its own module). The ROS layer publishes it as ``value`` (``pkg/msg/Name``) by the generic
    conversion every payload takes (``gazelle/ros/_layouts.py``): the payload is a dataclass whose fields are
    the ROS message's own, ``stamp_sec`` and ``frame_id`` going into its ``header`` (a field named otherwise
    says where it goes in a ``ROS_FIELDS`` class attribute)."""

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
        """Attach a listener; it is told about every existing endpoint (and component) first, so one that
        attaches late (a ROS bridge started after the world was loaded) sees what an early one would have
        seen. The calls happen outside the lock: a listener may advertise or look up endpoints in them."""
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
        """Declare a publisher: the ROS bridge makes an rclpy publisher of it (under the plugin node being
        declared, if any) and converts each payload published to the ROS message of ``msg_type``.

        Args:
            owner: the entity the endpoint belongs to (its endpoints go when it is deleted).
            topic: the resolved topic name (see :func:`resolve_topic` for a plugin's namespace and
                ``<remapping>``s).
            msg_type: one of :class:`MsgType`'s, or a :class:`DeclaredMessage` of a new sensor kind's.
            qos: the ROS QoS it is published with (:class:`Qos`: sensor data, latched or the default).
            depth: the QoS history depth.

        Returns:
            The endpoint; publish with its ``publish`` (check ``wanted`` first to skip building a payload
            nobody listens to).
        """
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
        """Declare a subscription: the ROS bridge subscribes to ``topic`` and calls ``callback`` with each message
        converted to its payload (``inject`` does the same without ROS).

        ``callback`` may run on any thread (a ROS executor's, the viewer's, the test's): keep it to storing
        the payload (a single assignment, or under a lock) and act on it in the next ``pre_update``, as
        Gazebo's plugins take their commands under a mutex and apply them at the next update. Arguments
        as :meth:`advertise`'s.
        """
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
        """Remove every endpoint of an entity (it was deleted): each endpoint loses its sinks first, so a
        message a system is still handing over as it goes reaches no one, then the listeners (the ROS layer,
        the viewer) are told, outside the lock, so that one of them calling back into the bus cannot
        deadlock; the entity's components (its controller manager) are withdrawn the same way."""
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
        """Announce a component of entity ``owner`` to the listeners (see :meth:`BusListener.component_added`):
        something the ROS layer serves beyond topics, such as a trajectory controller's action server or a
        controller manager's services. The bus stays ROS-free: the component is an object of the systems
        layer, and the ROS layer picks the interfaces to serve for it by its type."""
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


NODE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
"""A node name as rmw validates it: letters, digits and ``_``, not starting with a digit."""
_TOPIC_NAME = re.compile(r"(/[A-Za-z_][A-Za-z0-9_]*)+")
"""A fully qualified topic name as rcl validates it: ``/``-separated tokens of letters, digits and ``_``,
none empty or starting with a digit."""


def remap_problem(src: str, dst: str, namespace: str, node: str) -> str | None:
    """The part of the rule ``src:=dst`` that rcl would refuse for ``node`` in ``namespace`` (an invalid node
    name before ``:`` in ``src``, or a side that is not a valid ROS name once expanded), or None."""
    target, name = rule_node(src)
    if target and NODE_NAME.fullmatch(target) is None:
        return target
    for side in (name, dst):
        if _TOPIC_NAME.fullmatch(resolve_topic(side, namespace, node=node)) is None:
            return side
    return None


def rule_node(src: str) -> tuple[str, str]:
    """A remapping rule's *from* side split into the node it is for ("" for every node) and the name:
    ``talker:chatter`` -> (``talker``, ``chatter``); ``~/out`` and ``/a/b`` name no node."""
    target, sep, rest = src.partition(":")
    if not sep or "/" in target or "~" in target:
        return "", src
    return target, rest


def remap_name(name: str, namespace: str, node: str, rules: tuple[tuple[str, str], ...]) -> str:
    """A node's topic (or action, or service) name as rcl resolves it with remapping ``rules``: the name and
    each rule's *from* are expanded for the node (``~`` is the node's own name, a relative name goes under
    its namespace) and compared whole; the first rule that matches gives its *to*, expanded the same way.
    So ``diffdrive_controller/odom:=odom`` in namespace ``r1`` turns the controller's ``~/odom`` into
    ``/r1/odom``. A rule ``node:from:=to`` applies to that node only."""
    resolved = resolve_topic(name, namespace, node=node)
    for src, dst in rules:
        target, rest = rule_node(src)
        if target and target != node:
            continue
        if resolve_topic(rest, namespace, node=node) == resolved:
            return resolve_topic(dst, namespace, node=node)
    return resolved


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

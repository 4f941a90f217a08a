"""The ROS 2 side of a running simulation: /clock, services, and every system's topics.

The node is called ``gazelle``. The classic gazebo_ros services live at the root
(``/spawn_entity``, ``/delete_entity``, ...) as gazebo_ros had them (``_gazebo_services.py``, a part the
node owns, with spawning from XML); simulation_interfaces' under ``~/`` (``_simulation_interfaces.py``, another).
Service callbacks run on a multi-threaded executor and hand the world work to
the simulation thread (:meth:`Simulation.call`), so a request never races a
physics step and a slow request never blocks the others.
"""

from __future__ import annotations

import functools
import logging
import math
import threading
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import rclpy
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Twist
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.context import Context
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.exceptions import InvalidTopicNameException
from rclpy.executors import Executor, MultiThreadedExecutor
from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.validate_full_topic_name import validate_full_topic_name
from rosgraph_msgs.msg import Clock

from ..physics import EntityState, WorldError
from ..sim import Simulation
from ..systems import (
    Endpoint,
    JointStatesBlock,
    MsgType,
    PayloadBlock,
    PluginNode,
    Qos,
    Transform,
    TransformBatch,
    UpdateInfo,
)
from ._acked_writer import ACK_WINDOW, AckedWriter
from ._cdr import raw_serializer, serialize_clock, serialized_joint_states
from ._convert import InterfaceMissing, from_ros, ros_type, second_tier, to_pose_msg, to_ros, to_time
from ._exposure import ServerRegistry
from ._gazebo_services import GazeboServices
from ._inbound import InboundGroup
from ._names import gz_topic_on_ros
from ._outbox import Lane, Outbox
from ._plugin_nodes import PluginNodes
from ._signals import spin_until_stopped
from ._simulation_interfaces import SimulationInterfaces
from ._subscribed import Subscribed

if TYPE_CHECKING:
    from rclpy.subscription import Subscription

    from ._control import ControllerManagerNode
    from ._controller_node import ControllerNode
    from ._scene_publisher import ScenePublisher


def qos_profile(qos: Qos, depth: int) -> QoSProfile:
    """rclpy QoS for a bus QoS name."""
    if qos is Qos.SENSOR:
        return QoSProfile(depth=depth, reliability=ReliabilityPolicy.BEST_EFFORT)
    if qos is Qos.LATCHED:
        return QoSProfile(
            depth=depth, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
    return QoSProfile(depth=depth, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)


MIN_CLOCK_WALL_PERIOD_SEC = 1.0 / 1000.0
"""/clock goes out at most 1000 times per wall-clock second (see ``_on_step``)."""

CLOCK_QOS = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE)
"""/clock is keep-last 1 like rclcpp's ClockQoS, but reliable: a reliable writer matches both
rclpy's best-effort TimeSource and a plain default (reliable) subscription, which a best-effort
writer (gazebo_ros) silently never reaches. Keep-last 1 never blocks the simulation."""

MODEL_STATES_RATE_HZ = 100.0
"""/model_states goes out every 10 ms of sim time, gazebo_ros_state's 100 Hz, and at most
MODEL_STATES_RATE_HZ times per wall-clock second (faster than real time, sim-time periods are
skipped rather than the simulation held back). Nothing is built while nobody subscribes."""

MODEL_STATES_QOS = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE)
"""Keep-last 1, reliable: a subscriber always gets the newest states and never stalls the sim."""


def model_states_msg(states: list[tuple[str, EntityState]]) -> ModelStates:
    """gazebo_msgs/ModelStates of entity names and world states (see ``SimulationNode.entity_states``)."""
    msg = ModelStates()
    twists = []
    for _name, st in states:
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.linear.z = st.linear_velocity
        twist.angular.x, twist.angular.y, twist.angular.z = st.angular_velocity
        twists.append(twist)
    msg.name = [name for name, _st in states]
    msg.pose = [to_pose_msg(st.pose) for _name, st in states]
    msg.twist = twists
    return msg


class _RosLogHandler(logging.Handler):
    """Send Python log records (systems, physics) to rclpy loggers named after the record's logger."""

    _LEVELS = {
        logging.DEBUG: "debug",
        logging.INFO: "info",
        logging.WARNING: "warning",
        logging.ERROR: "error",
        logging.CRITICAL: "fatal",
    }

    def emit(self, record: logging.LogRecord) -> None:
        """Forward one Python log record to the rclpy logger of the same name."""
        try:
            logger = get_logger(record.name)
            level = self._LEVELS.get(record.levelno, "info")
            text = record.getMessage()
            if record.exc_info:
                text += "\n" + "".join(traceback.format_exception(*record.exc_info)).rstrip()
            getattr(logger, level)(text)
        except Exception:
            self.handleError(record)


# Publishers and subscriptions of systems come and go with their entities. rclpy (Jazzy) gives
# each one a QoS event handler (a waitable) by default, and destroying it while the executor
# builds its wait set raises InvalidHandle inside ``add_to_wait_set``, which ends ``spin()``: an
# attacker killed the executor thread by deleting a diff-drive robot. So the bridge's endpoints
# get no event handlers, and its spin loop also survives an InvalidHandle of an entity destroyed
# mid-build (see RosBridge._spin).


def _no_pub_events() -> PublisherEventCallbacks:
    return PublisherEventCallbacks(use_default_callbacks=False)


def _no_sub_events() -> SubscriptionEventCallbacks:
    return SubscriptionEventCallbacks(use_default_callbacks=False)


@dataclass
class _RosEndpoint:
    """One rclpy publisher, shared by every bus endpoint of one node with the same topic."""

    handle: Publisher
    node: Node
    """The node it was made on (this one, or a plugin's)."""
    writer: AckedWriter
    """Publishes through ``handle`` without overwriting what a reliable reader has not acknowledged."""
    users: int = 0
    lane: Lane | None = None
    """/tf_static: the one lane of the union of every robot's static transforms."""


class SimulationNode(Node):
    """The simulation's ROS 2 node: it mirrors the bus and publishes /clock itself, and owns the parts that serve
    on it (:attr:`gazebo`, :attr:`simulation_interfaces`), each registering its own services."""

    def __init__(
        self,
        sim: Simulation,
        *,
        node_name: str = "gazelle",
        clock_rate_hz: float = 100.0,
        context: Context | None = None,
        drop_when_behind: bool = False,
    ):
        """The ``/gazelle`` node that puts ``sim`` on the ROS graph: /clock at ``clock_rate_hz`` of sim time, the
        gazebo_ros and simulation_interfaces services, a publisher or subscription for every bus endpoint (added
        as systems declare them), the plugin nodes and controller managers, and the world's geometry for
        move_group. Publishing goes through the outbox's thread; with ``drop_when_behind`` a full queue drops its
        oldest message (counted on /gazelle/dropped_messages) instead of pacing the simulation."""
        super().__init__(node_name, context=context)
        self.sim = sim
        self._cb = ReentrantCallbackGroup()
        self._inbound = InboundGroup()
        """The bus's subscriptions: taken before each requested step (:meth:`take_inbound`)."""
        self._lock = threading.Lock()
        self._pubs: dict[tuple[str, str, str], _RosEndpoint] = {}
        self._subs: dict[int, tuple[Subscription, Node]] = {}
        """id(subscriber endpoint) -> its rclpy subscription and the node it is on."""
        self._sinks: dict[int, Callable[[object], None]] = {}
        """id(publisher endpoint) -> the sink this bridge added to it (other sinks stay)."""
        self._static: dict[int, tuple[Transform, ...]] = {}
        self.outbox = Outbox(lossless=not drop_when_behind)
        """The publisher thread: the simulation thread only queues payloads (see ``_outbox``)."""
        if drop_when_behind:  # the opt-in loss is counted where anyone can see it
            self._count_dropped()
        self._lanes: dict[int, Lane] = {}
        """id(publisher endpoint) -> its lane in the outbox."""
        self._managers: dict[str, ControllerManagerNode] = {}
        """Entity -> the node of its controller manager (see ``_control``)."""
        self._controller_nodes: dict[int, ControllerNode] = {}
        """Each loaded controller's own node (``_controller_node.py``), by its parameters component's id."""
        self._executor: Executor | None = None
        self._pending_nodes: list[Node] = []
        """Manager and plugin nodes made before the executor was attached."""
        self.plugin_nodes = PluginNodes(sim, self.context, self._add_node, self._remove_node)
        """gazebo_ros plugins' own nodes (``/differential_drive``)."""
        self._clock_pub = self.create_publisher(Clock, "/clock", CLOCK_QOS)
        clock_pub = self._clock_pub
        self._clock_heard = Subscribed(clock_pub)
        self._last_clock_wall = -math.inf
        self.gazebo = GazeboServices(self, sim, self._cb)
        """gazebo_ros's services at the root (``/spawn_entity``, ...) and spawning from XML."""
        self.simulation_interfaces = SimulationInterfaces(self, sim, self.publish_clock, self.take_inbound)
        """simulation_interfaces' services and action under ``~/`` (``/gazelle/spawn_entity``, ...)."""
        # /clock at its rate (held back while listened to: see _on_step); the runtime steps inside
        # MuJoCo between two clock periods
        sim.add_step_listener(self._on_step, clock_rate_hz)
        self._publish_model_states()
        self._scene_publisher: ScenePublisher | None = None
        try:  # the world's collision geometry for move_group (moveit_msgs is built by the set-up)
            from ._scene_publisher import ScenePublisher

            self._scene_publisher = ScenePublisher(self, sim, self.outbox)
        except ImportError as err:
            self.get_logger().debug(f"no /gazelle/planning_scene_world: {err}")
        sim.bus.add_listener(self)
        self.publish_clock(sim.world.time)

    def _count_dropped(self) -> None:
        """``--drop-when-behind``: what the outbox dropped, on ``~/dropped_messages`` (latched, each second
        it changed)."""
        from std_msgs.msg import UInt64

        self._dropped_pub = self.create_publisher(
            UInt64, "~/dropped_messages", QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        )
        self._dropped_reported = -1

        def report_dropped() -> None:
            if self.outbox.dropped != self._dropped_reported:
                self._dropped_reported = self.outbox.dropped
                self._dropped_pub.publish(UInt64(data=self._dropped_reported))

        report_dropped()
        self.create_timer(1.0, report_dropped, callback_group=self._cb)

    def _publish_model_states(self) -> None:
        """/model_states (gazebo_ros's), at MODEL_STATES_RATE_HZ of sim time, through a keep-last lane."""
        self._model_states_pub = self.create_publisher(ModelStates, "/model_states", MODEL_STATES_QOS)
        states_pub = self._model_states_pub
        self._model_states_heard = Subscribed(states_pub)
        self._model_states_lane: Lane[list[tuple[str, EntityState]]] = self.outbox.lane(
            lambda states: states_pub.publish(model_states_msg(states)), 1, "/model_states", keep_last=True
        )
        self._model_states_period = 1.0 / MODEL_STATES_RATE_HZ
        self._last_model_states_wall = -math.inf
        self.sim.add_step_listener(self._on_step_model_states, MODEL_STATES_RATE_HZ)

    # ------------------------------------------------------------------ clock

    @property
    def clock_publisher(self) -> Publisher:
        """The rclpy publisher of ``/clock`` (benches and tools count its subscribers)."""
        return self._clock_pub

    def ros_publishers(self, topic: str) -> list[Publisher]:
        """The rclpy publishers this bridge has on ``topic`` (one per message type and QoS)."""
        with self._lock:
            return [entry.handle for key, entry in self._pubs.items() if key[1] == topic]  # (node, topic, type)

    def publish_clock(self, sim_time: float) -> None:
        """Publish ``sim_time`` on /clock, at once, from the calling thread.

        /clock is the one topic that does not go through the publisher thread: it paces every
        ``use_sim_time`` node, and the simulation holds itself back by when it sent it (see
        :meth:`_on_step`). Queued behind /odom and /tf, it reached a node late and the seed's
        square node turned 131° instead of 90° (a fresh-clone run, 10× real time, 2 cores).
        """
        data = serialize_clock(sim_time)  # 12 bytes from a template: this runs on the simulation thread
        self._clock_pub.publish(data if data is not None else Clock(clock=to_time(sim_time)))

    def _on_step(self, info: UpdateInfo) -> None:
        """A /clock period of sim time went by (the runtime calls this at the clock rate, and after a reset)."""
        t = info.sim_time_sec
        # Faster than real time, a sim-time rate becomes a flood in wall time: use_sim_time
        # nodes fall behind, their 10 Hz timers fire late, and a command lands a latency x RTF
        # too late (we measured a 5 s side driven for 5.2 s at 30x). While anyone listens to
        # /clock, keep its resolution and hold the simulation back instead: at most one clock
        # period of sim time per MIN_CLOCK_WALL_PERIOD_SEC of wall time (10x at 100 Hz).
        # Nobody listening: nothing to send and nothing to hold back for (a late subscriber gets
        # the next period's message).
        if not self._clock_heard():
            return
        wall = time.monotonic()
        wait = self._last_clock_wall + MIN_CLOCK_WALL_PERIOD_SEC - wall
        if wait > 0:
            time.sleep(wait)
            wall = time.monotonic()
        self._last_clock_wall = wall
        self.publish_clock(t)

    # ------------------------------------------------------------------ /model_states
    def _on_step_model_states(self, info: UpdateInfo) -> None:
        """Publish every entity's world pose and twist (gazebo_msgs/ModelStates) from the sim thread
        (the runtime calls this every 10 ms of sim time)."""
        if not self._model_states_heard():
            return  # nothing is built for nobody
        wall = time.monotonic()
        # at most about MODEL_STATES_RATE_HZ per wall second; the slack keeps the sim-time rate at real
        # time, where the blocks of steps that end on a 10 ms period arrive with a little jitter
        if wall - self._last_model_states_wall < 0.75 * self._model_states_period:
            return
        self._last_model_states_wall = wall
        self._model_states_lane.put(self.entity_states())

    def entity_states(self) -> list[tuple[str, EntityState]]:
        """Every entity's name and world state, now (call on the sim thread; see :func:`model_states_msg`)."""
        out = []
        world = self.sim.world
        for name in list(world.entities):
            try:
                out.append((name, world.entity_state(name)))
            except WorldError:  # an entity without a body: nothing to report
                continue
        return out

    # ------------------------------------------------------------------ bus mirroring
    def endpoint_added(self, ep: Endpoint) -> None:
        """Mirror a bus endpoint in ROS; a topic name ROS refuses is an error that names it (the entity
        still spawns, without that topic on ROS)."""
        topic = gz_topic_on_ros(ep.topic)
        try:
            validate_full_topic_name(topic)
        except InvalidTopicNameException as err:
            reason = str(err).splitlines()[0].rstrip(": ")
            logging.getLogger("gazelle.ros").error(
                f"'{ep.owner}': topic '{ep.topic}' is not a valid ROS name ({reason}); it is not on ROS"
            )
            return
        self._mirror(ep, topic)

    def _mirror(self, ep: Endpoint, topic: str) -> None:
        """A shared rclpy publisher (a sink on the endpoint) or a subscription for ``ep``, on ROS ``topic``."""
        try:
            msg_class = ros_type(ep.msg_type)
        except InterfaceMissing as missing:  # a tier the set-up has not built yet: that topic is not on ROS
            # a warning for a topic of the user's; gazelle's own (the viewer's planned path) is only told
            level = logging.INFO if ep.owner.startswith("_") else logging.WARNING
            logging.getLogger("gazelle.ros").log(level, f"'{ep.owner}': {ep.topic} is not on ROS: {missing}")
            return
        # a gazebo_ros plugin's topics are its own node's (see _plugin_nodes); the rest are this node's
        owner: Node = self.plugin_nodes.acquire(ep.node) if ep.node else self
        if ep.is_publisher:
            key = (ep.node, topic, ep.msg_type.value)
            with self._lock:
                entry = self._pubs.get(key)
                if entry is None:
                    entry = self._ros_endpoint(owner, msg_class, topic, ep)
                    self._pubs[key] = entry
                entry.users += 1
            convert = to_ros(ep.msg_type)
            handle = entry.handle
            writer = entry.writer
            if ep.msg_type is MsgType.TF_STATIC:
                with self._lock:
                    if entry.lane is None:
                        entry.lane = self.outbox.lane(
                            lambda payload: handle.publish(convert(payload)), 1, ep.topic, keep_last=True
                        )
                static_lane = entry.lane
                sink = lambda payload: self._publish_static(static_lane, ep, payload)
            else:
                publish = functools.partial(_publish_converted, writer, convert, raw_serializer(ep.msg_type))
                lane = self.outbox.lane(publish, ep.depth, ep.topic)
                sink = lane.put
                with self._lock:
                    self._lanes[id(ep)] = lane
            with self._lock:
                self._sinks[id(ep)] = sink
            # latched topics always publish (late joiners get the last one); the others only while
            # someone in ROS subscribes, so nothing is built for nobody
            wanted = None if ep.qos is Qos.LATCHED else Subscribed(handle)
            # a block of payloads (a planned block's joint states) goes to the lane whole: its messages
            # are built on the publisher thread
            ep.add_sink(sink, wanted, blocks=ep.msg_type is not MsgType.TF_STATIC)
        else:
            if not isinstance(ep.msg_type, MsgType):  # a declared message is something a system publishes
                logging.getLogger("gazelle.ros").error(
                    f"'{ep.owner}': {ep.topic} ({ep.msg_type.value}) is not one gazelle subscribes to; not on ROS"
                )
                return
            convert_in = from_ros(ep.msg_type)
            callback = ep.callback
            assert callback is not None
            deliver = self.sim.deliver  # at the sim time the message came, also while catching up
            sub = owner.create_subscription(
                msg_class,
                topic,
                lambda msg: deliver(callback, convert_in(msg)),
                qos_profile(ep.qos, ep.depth),
                callback_group=self._inbound,
                event_callbacks=_no_sub_events(),
            )
            with self._lock:
                self._subs[id(ep)] = (sub, owner)

    def _ros_endpoint(self, owner: Node, msg_class: Any, topic: str, ep: Endpoint) -> _RosEndpoint:
        """A new rclpy publisher for ``ep`` and its :class:`AckedWriter`. A reliable volatile topic's DDS history
        is ``ACK_WINDOW`` deep (at least its QoS depth), and the writer waits for its reliable readers'
        acknowledgements before that history would overflow, unless the outbox drops when behind
        (``--drop-when-behind``: the declared depth, never a wait). Latched topics are state, published once."""
        waits = ep.qos is Qos.DEFAULT and self.outbox.lossless
        depth = max(ep.depth, ACK_WINDOW) if waits else ep.depth
        handle = owner.create_publisher(msg_class, topic, qos_profile(ep.qos, depth), event_callbacks=_no_pub_events())
        outbox = self.outbox
        writer = AckedWriter(
            handle,
            depth if waits else 0,
            waiting=lambda: outbox.lossless,
            stall_timeout=outbox.stall_timeout,
            name=topic,
        )
        return _RosEndpoint(handle, owner, writer)

    def published_on(self, topic: str) -> int:
        """Messages this bridge's writers on ``topic`` have written (benches compare it with what a reader got)."""
        with self._lock:
            return sum(entry.writer.published for key, entry in self._pubs.items() if key[1] == topic)

    def take_inbound(self) -> int:
        """Hand the simulation every message its subscriptions' readers hold now, on this thread (the step
        services call it before stepping: see :class:`InboundGroup`); returns how many there were."""
        return self._inbound.drain()

    def _publish_static(self, lane: Lane, ep: Endpoint, batch: TransformBatch) -> None:
        """/tf_static keeps one latched message: it must hold every robot's static transforms."""
        with self._lock:
            self._static[id(ep)] = batch.transforms
            union = TransformBatch(tuple(t for ts in self._static.values() for t in ts))
        lane.put(union)

    # ------------------------------------------------------------------ ros2_control
    def attach_executor(self, executor: Executor) -> None:
        """Give the node the executor that spins it: controller managers' nodes are added to it."""
        with self._lock:
            self._executor = executor
            pending, self._pending_nodes = self._pending_nodes, []
        for node in pending:
            executor.add_node(node)

    def _add_node(self, node: Node) -> None:
        """Spin another node of this bridge (now, or once the executor is attached)."""
        with self._lock:
            executor = self._executor
            if executor is None:
                self._pending_nodes.append(node)
        if executor is not None:
            executor.add_node(node)

    def _remove_node(self, node: Node) -> None:
        """Take a plugin or manager node off the executor (its entity was deleted)."""
        with self._lock:
            executor = self._executor
            if node in self._pending_nodes:
                self._pending_nodes.remove(node)
        if executor is not None:
            executor.remove_node(node)

    def component_added(self, owner: str, component: object) -> None:
        """A gazebo_ros plugin gets its node; a controller manager its node; a trajectory controller its
        action server."""
        from ..systems.ros2_control import Controller, ControllerManager, ControllerParameters

        if isinstance(component, PluginNode):
            self.plugin_nodes.declare(component)
        elif isinstance(component, ControllerParameters):  # a loaded controller's own node
            with second_tier():
                from ._controller_node import ControllerNode
            cnode = ControllerNode(self.sim, component, self.context)
            with self._lock:
                self._controller_nodes[id(component)] = cnode
            self._add_node(cnode)
        elif isinstance(component, ControllerManager):
            with second_tier():
                from ._control import ControllerManagerNode
            node = ControllerManagerNode(self.sim, component, self.context)
            with self._lock:
                self._managers[owner] = node
            self._add_node(node)
        elif isinstance(component, Controller) and component.action_type:  # one serving an action (JTC, gripper)
            with self._lock:
                node = self._managers.get(owner)
            if node is not None:
                node.add_controller_action(component)

    def manager_nodes(self) -> list[ControllerManagerNode]:
        """The controller managers' nodes."""
        with self._lock:
            return list(self._managers.values())

    def controller_nodes(self) -> list[ControllerNode]:
        """The loaded controllers' own nodes."""
        with self._lock:
            return list(self._controller_nodes.values())

    def component_removed(self, component: object) -> None:
        """Undo :meth:`component_added`."""
        from ..systems.ros2_control import Controller, ControllerManager, ControllerParameters

        if isinstance(component, PluginNode):
            self.plugin_nodes.undeclare(component)
        elif isinstance(component, ControllerParameters):
            with self._lock:
                cnode = self._controller_nodes.pop(id(component), None)
            if cnode is not None:
                self._remove_node(cnode)
                cnode.destroy_node()
        elif isinstance(component, ControllerManager):
            with self._lock:
                owner = next((o for o, n in self._managers.items() if n.manager is component), None)
                node = self._managers.pop(owner, None) if owner is not None else None
            if node is not None:
                self._remove_node(node)
                node.destroy_node()
        elif isinstance(component, Controller) and component.action_type:
            with self._lock:
                nodes = list(self._managers.values())
            for node in nodes:
                node.remove_controller_action(component)

    def endpoint_removed(self, ep: Endpoint) -> None:
        """Undo :meth:`endpoint_added` (the rclpy publisher goes when its last user goes)."""
        if ep.msg_type is MsgType.TF_STATIC:
            with self._lock:
                self._static.pop(id(ep), None)
                entry = self._pubs.get((ep.node, gz_topic_on_ros(ep.topic), ep.msg_type.value))
                union = TransformBatch(tuple(t for ts in self._static.values() for t in ts))
            if entry is not None and entry.lane is not None and entry.users > 1:
                entry.lane.put(union)  # the latched message without what was taken back
        with self._lock:
            sink = self._sinks.pop(id(ep), None)
            lane = self._lanes.pop(id(ep), None)
        if sink is not None:
            ep.remove_sink(sink)
        if lane is not None:
            lane.close()  # nothing of it is published once its publisher may be gone
        if not ep.is_publisher:
            with self._lock:
                sub = self._subs.pop(id(ep), None)
            if sub is not None:
                sub[1].destroy_subscription(sub[0])
                if ep.node:
                    self.plugin_nodes.release(ep.node)
            return
        with self._lock:
            key = (ep.node, gz_topic_on_ros(ep.topic), ep.msg_type.value)
            entry = self._pubs.get(key)
            if entry is None:
                return
            entry.users -= 1
            last = entry.users <= 0
            if last:
                del self._pubs[key]
        if last:
            entry.writer.cancelled = True
            if entry.lane is not None:
                entry.lane.close()
            entry.node.destroy_publisher(entry.handle)
        if ep.node:
            self.plugin_nodes.release(ep.node)

    def destroy_node(self) -> None:
        """Detach from the simulation (listeners, sinks), then destroy the node."""
        self.sim.remove_step_listener(self._on_step)
        self.sim.remove_step_listener(self._on_step_model_states)
        if self._scene_publisher is not None:
            self._scene_publisher.close()
        self.sim.bus.remove_listener(self)
        for ep in self.sim.bus.endpoints():
            sink = self._sinks.pop(id(ep), None)
            if sink is not None:
                ep.remove_sink(sink)
        # the simulate_steps action server holds the node's handle: left alive, a half-destroyed /gazelle
        # (its action, /rosout and type description only) stayed in the graph as long as the process
        # lived, and `ros2 node info /gazelle` described it instead of a running server's node
        self.simulation_interfaces.destroy()
        super().destroy_node()


class RosBridge:
    """Owns rclpy's context, the node and an executor thread for a simulation."""

    def __init__(
        self,
        sim: Simulation,
        *,
        clock_rate_hz: float = 100.0,
        args: list[str] | None = None,
        announce: bool = False,
        drop_when_behind: bool = False,
    ):
        """
        Args:
            sim: the simulation to serve.
            clock_rate_hz: /clock rate in sim time.
            args: ROS arguments for rclpy.
            announce: take part in the one-server-per-domain check (``gazelle sim`` does).
            drop_when_behind: when publishing falls behind, drop the oldest messages (counted in
                ``node.outbox.dropped``) instead of making the simulation wait (see ``_outbox``).
        """
        self.context = Context()
        rclpy.init(args=args, context=self.context)
        self._handler = _RosLogHandler()
        root = logging.getLogger()
        root.addHandler(self._handler)
        if root.level > logging.INFO or root.level == logging.NOTSET:
            root.setLevel(logging.INFO)
        self.node = SimulationNode(
            sim, clock_rate_hz=clock_rate_hz, context=self.context, drop_when_behind=drop_when_behind
        )
        self.registry = ServerRegistry(self.node) if announce else None
        """Notices another server on the same ROS domain (``registry.conflict``)."""
        self.executor = MultiThreadedExecutor(num_threads=4, context=self.context)
        self.executor.add_node(self.node)
        self.node.attach_executor(self.executor)
        self._failure: BaseException | None = None
        self._stopping = threading.Event()
        self._thread = threading.Thread(target=self._spin, name="gazelle-ros", daemon=True)
        self._thread.start()

    @property
    def alive(self) -> bool:
        """Whether the executor threads are serving: the bridge's own and StepSimulation's (False after a
        crash of either, or shutdown)."""
        return self._thread.is_alive() and self.node.simulation_interfaces.stepping.alive

    @property
    def failure(self) -> BaseException | None:
        """What ended an executor thread, if one died (the server then exits non-zero)."""
        return self._failure or self.node.simulation_interfaces.stepping.failure

    def _spin(self) -> None:
        """Serve callbacks until shutdown (:func:`spin_until_stopped`); a crash is logged with its traceback
        and kept in :attr:`failure`, and the server's main loop then stops the process with a non-zero status."""
        err = spin_until_stopped(self.executor, self.context, self._stopping)
        if err is not None:
            self._failure = err
            logging.getLogger("gazelle.ros").critical("ROS executor thread crashed; the server stops", exc_info=err)

    def shutdown(self) -> None:
        """Stop spinning, destroy the node and the bridge's own rclpy context."""
        self._stopping.set()
        logging.getLogger().removeHandler(self._handler)
        self.node.outbox.close()  # what the simulation queued goes out before the node goes
        self.executor.shutdown(timeout_sec=2.0)
        for manager_node in self.node.manager_nodes():
            manager_node.destroy_node()
        for controller_node in self.node.controller_nodes():
            controller_node.destroy_node()
        self.node.plugin_nodes.destroy_all()
        self.node.destroy_node()
        if self.context.ok():
            rclpy.shutdown(context=self.context)
        self._thread.join(timeout=2.0)


def _publish_converted(
    handle: AckedWriter, convert: Callable[[Any], Any], raw: Callable[[Any], bytes | None] | None, payload: object
) -> None:
    """Publish one payload, or each of a :class:`PayloadBlock`'s in order (on the publisher thread): as
    bytes serialized from a template where its kind has one (:mod:`._cdr`: a block of joint states,
    Odometry, TF, Imu, JointState), the others as messages built by ``convert``."""
    if isinstance(payload, JointStatesBlock):
        block = serialized_joint_states(payload)
        if block is not None:
            for one in block:
                handle.publish(one)
            return
    for one in payload if isinstance(payload, PayloadBlock) else (payload,):
        data = raw(one) if raw is not None else None
        handle.publish(data if data is not None else convert(one))

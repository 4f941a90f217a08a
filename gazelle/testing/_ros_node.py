"""The test's own rclpy node, on the simulation's private domain, spun on a thread of its own.

It has its own rclpy context, so a test (or the code it tests) may use rclpy's default context as it
likes; helpers wait for conditions with timeouts and never sleep a fixed time.

Two clocks are in play, and each wait says which it counts: **wall-clock** timeouts (``wait``,
``wait_for_message``, ``call``, ``wait_until``) only bound how long a test may hang on a machine that is
slow or a graph that never answers; **sim time** (``sim_time``, the newest ``/clock`` heard) is what a
test's assertions should be about, and what ``gazelle_sim.run_for``/``run_until`` move. A typical test::

    def test_the_robot_drives(gazelle_sim, ros):
        odom = ros.subscribe("/odom", Odometry)
        cmd = ros.publisher("/cmd_vel", TwistStamped)
        ros.wait_for_subscribers(cmd)       # the robot's subscription, matched
        cmd.publish(forward)                # acts from the first step of the next run_for
        gazelle_sim.run_for(2.0)            # sim seconds, in lockstep with the nodes started
        assert odom.last.pose.pose.position.x > 0.5
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rosgraph_msgs.msg import Clock

from .._errors import SimError
from ._dds_profile import writer_profile
from ._domain import environ_applied

__all__ = ["MessageLog", "RosTestNode", "TestTimeout"]


class TestTimeout(SimError, AssertionError):
    """A wait ran out of time: the message names what was waited for (an AssertionError, so pytest
    reports it as the test's failure, not as an error in the harness)."""

    __test__ = False  # not a test class for pytest's collector


def poll_until(predicate: Callable[[], Any], timeout: float, what: str, pause: Callable[[], object]) -> Any:
    """``predicate()``'s first truthy value, calling ``pause()`` between tries (a sleep, or a wait on a
    condition that new data wakes); :class:`TestTimeout` naming ``what`` once ``timeout`` wall-clock seconds
    have passed with no such value."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise TestTimeout(f"{what} within {timeout:g} s")
        pause()


class MessageLog:
    """The messages one subscription received, in order, with the sim time (from /clock) at which each
    arrived at the test.

    ``messages`` and ``sim_times`` are parallel lists, appended on the node's thread; ``len(log)``, ``last``
    and :meth:`wait` take the log's lock, so they are safe to call while messages keep coming. The arrival
    time is when the test heard the message, not its header stamp: a message published at sim time t
    arrives at t or one /clock tick (10 ms) later."""

    def __init__(self, topic: str) -> None:
        """Every message heard on ``topic`` since the subscription began, with the sim time at which it was heard."""
        self.topic = topic
        self.messages: list[Any] = []
        self.sim_times: list[float] = []
        self._cond = threading.Condition()

    def _add(self, msg: Any, sim_time: float) -> None:
        """Keep a message (on the node's thread) and wake whoever waits for one."""
        with self._cond:
            self.messages.append(msg)
            self.sim_times.append(sim_time)
            self._cond.notify_all()

    def __len__(self) -> int:
        with self._cond:
            return len(self.messages)

    @property
    def last(self) -> Any:
        """The newest message (None before the first)."""
        with self._cond:
            return self.messages[-1] if self.messages else None

    def wait(self, count: int = 1, timeout: float = 10.0) -> Any:
        """Wait until ``count`` messages in all have arrived (counted since the subscription began, not since
        this call).

        Args:
            count: how many messages the log must hold.
            timeout: wall-clock seconds; sim time does not move while this waits, so a message the
                simulation has still to produce must be stepped for first (``run_until(lambda: len(log) >=
                n, ...)`` does both).

        Returns:
            The newest message.

        Raises:
            TestTimeout: fewer than ``count`` within ``timeout``, naming the topic and how many came.
        """
        deadline = time.monotonic() + timeout
        with self._cond:
            while len(self.messages) < count:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TestTimeout(f"{self.topic}: {len(self.messages)} of {count} message(s) within {timeout:g} s")
                self._cond.wait(left)
            return self.messages[-1]


def qos_for(reliable: bool = True, latched: bool = False, depth: int = 1000) -> QoSProfile:
    """A QoS profile: reliable or best effort, latched (transient local) or volatile, of ``depth`` (deep by default:
    a test's log must not drop messages while the test is busy)."""
    return QoSProfile(
        depth=depth,
        reliability=ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE,
    )


class RosTestNode:
    """A plain rclpy node for the test (``ros`` fixture): subscribe, wait, call, all with timeouts.

    ``node`` is the rclpy Node itself, for anything the helpers do not cover.
    """

    def __init__(self, domain_id: int, name: str = "gazelle_test") -> None:
        """A node of the test's own on ``domain_id``, in an rclpy context of its own (not the default one a user's
        code may also init), spun on a thread, following /clock for the simulation's time.

        Args:
            domain_id: the ROS domain of the test's simulation (each test run has one of its own).
            name: the node's name in the graph (what ``ros2 node list`` shows).
        """
        self.context = Context()
        with environ_applied(writer_profile()):  # read by Fast DDS at the process's first participant
            rclpy.init(context=self.context, domain_id=domain_id)
            self.node = rclpy.create_node(name, context=self.context, start_parameter_services=False)
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.node)
        self._sim_time = 0.0
        self._clock_cond = threading.Condition()
        self.recorder: tuple[str, frozenset[str]] | None = None
        """(node name, topics) of the simulation's bag recorder: :meth:`publisher` waits until it hears a
        publisher of one of those topics (the harness sets it; None: nothing is recorded)."""
        # reliable, unlike rclpy's TimeSource: a paused server sends no tick after the last one of a step, and
        # the test waits for that one. Best effort lost it beside CPU hogs (1 run in 8 to 12 of
        # test_lossless's stopped-listener test: /clock heard up to 3.13 s while /odom, reliable, came up to
        # 10 s); a reliable reader gets the writer's newest sample again after a loss.
        self.node.create_subscription(Clock, "/clock", self._on_clock, qos_for(reliable=True, depth=10))
        self._thread = threading.Thread(target=self._spin, name="gazelle-test-node", daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        """The node's thread: spin until the context ends (an exception raised because close() shut the context is
        the end, not an error)."""
        try:
            while self.context.ok():
                self._executor.spin_once(timeout_sec=0.05)
        except Exception:  # the context was shut down under the spin: close() is under way
            if self.context.ok():
                raise

    def _on_clock(self, msg: Clock) -> None:
        with self._clock_cond:
            self._sim_time = msg.clock.sec + msg.clock.nanosec * 1e-9
            self._clock_cond.notify_all()

    # ------------------------------------------------------------------ time
    @property
    def sim_time(self) -> float:
        """The newest /clock the test has heard, in seconds."""
        with self._clock_cond:
            return self._sim_time

    def restart_clock(self) -> None:
        """The simulation was reset to time 0: forget the newest /clock heard."""
        with self._clock_cond:
            self._sim_time = 0.0

    def wait_for_sim_time(self, at_least: float, timeout: float = 30.0) -> float:
        """Wait until the /clock the test hears has reached ``at_least`` (it does not step the world: use
        ``gazelle_sim.run_for`` for that; this waits for a running server, or for the last tick of a step).

        Args:
            at_least: sim seconds.
            timeout: wall-clock seconds.

        Returns:
            The sim time heard.

        Raises:
            TestTimeout: /clock did not get there in time (the message says where it was).
        """
        deadline = time.monotonic() + timeout
        with self._clock_cond:
            while self._sim_time < at_least - 1e-9:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TestTimeout(
                        f"/clock at {self._sim_time:.3f} s, waited for {at_least:.3f} s for {timeout:g} s"
                    )
                self._clock_cond.wait(left)
            return self._sim_time

    # ------------------------------------------------------------------ topics
    def subscribe(self, topic: str, msg_type: Any, *, reliable: bool = True, latched: bool = False) -> MessageLog:
        """Keep every message of ``topic`` from now on.

        Args:
            topic: the topic's full name (the test node is in the root namespace).
            msg_type: the message class, e.g. ``nav_msgs.msg.Odometry``.
            reliable: a reliable reader matches only reliable writers, a best-effort one every writer (DDS's
                request-offered rule): pass False for a best-effort publisher (ros2_control's
                imu_sensor_broadcaster, many drivers' sensor data); gazelle's own sensors publish reliably.
            latched: transient local, to get what a latched publisher (``/robot_description``, a map) sent
                before the test subscribed.

        Returns:
            A :class:`MessageLog` of depth 1000: a busy test does not lose messages while it is not looking.
        """
        log = MessageLog(topic)
        self.node.create_subscription(msg_type, topic, lambda m: log._add(m, self.sim_time), qos_for(reliable, latched))
        return log

    def wait_for_message(self, topic: str, msg_type: Any, timeout: float = 10.0, **qos: bool) -> Any:
        """The first message on ``topic`` published from now on (or the last one latched, with
        ``latched=True``), within wall-clock ``timeout``; ``qos`` as :meth:`subscribe`'s. It waits without
        stepping: for a message the simulation still has to produce, subscribe and ``run_until`` instead.

        Raises:
            TestTimeout: none came in time.
        """
        return self.subscribe(topic, msg_type, **qos).wait(1, timeout)

    def publisher(self, topic: str, msg_type: Any, *, latched: bool = False, timeout: float = 10.0) -> Any:
        """An rclpy publisher on ``topic``: reliable, depth 10, transient local with ``latched`` (what the
        simulation's subscriptions accept, like ``ros2 topic pub``'s default).

        What it publishes before ``run_for``/``run_until`` acts from their first step: they wait until every
        subscriber has acknowledged it, and the server takes what it received before it steps. A topic the
        failure bag records is returned once the recorder has subscribed to it (at most ``timeout`` wall
        seconds), so the bag holds the test's first message too. Wait for the receiver before publishing
        (:meth:`wait_for_subscribers`): a message sent before a subscriber matched is not sent to it."""
        pub = self.node.create_publisher(msg_type, topic, qos_for(True, latched, depth=10))
        recorder = self.recorder
        if recorder is not None and pub.topic_name in recorder[1]:
            try:
                self.wait_until(lambda: self._heard_by(pub, {recorder[0]}), timeout, f"the bag recorder on {topic}")
            except TestTimeout as err:
                import warnings

                warnings.warn(f"gazelle: {err}: the bag may miss what the test publishes there", stacklevel=2)
        return pub

    def _heard_by(self, pub: Any, nodes: set[str] | None = None, others: int = 0) -> bool:
        """Whether ``pub`` has matched every subscription on its topic the graph shows that its QoS can
        match, among them one of each node in ``nodes`` and ``others`` more of nodes not the harness's own
        (this node, the recorder)."""
        reliable = pub.qos_profile.reliability == ReliabilityPolicy.RELIABLE
        latched = pub.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL
        infos = [
            i
            for i in self.node.get_subscriptions_info_by_topic(pub.topic_name)
            if (reliable or i.qos_profile.reliability != ReliabilityPolicy.RELIABLE)
            and (latched or i.qos_profile.durability != DurabilityPolicy.TRANSIENT_LOCAL)
        ]
        names = {i.node_name for i in infos}
        own = {self.node.get_name(), *([self.recorder[0]] if self.recorder else [])}
        if not (nodes or set()) <= names or sum(i.node_name not in own for i in infos) < others:
            return False
        return pub.get_subscription_count() >= len(infos)

    def wait_for_subscribers(self, pub: Any, count: int = 1, timeout: float = 10.0) -> None:
        """Wait (wall clock) until ``count`` subscribers besides the harness's own (this node, the bag
        recorder) are on ``pub``'s topic and ``pub`` has matched every one it can: what it publishes from
        then on reaches them (a reliable publisher sends nothing to a subscriber it has not yet matched).

        Raises:
            TestTimeout: not within ``timeout``.
        """
        what = f"{count} subscriber(s) of {pub.topic_name}"
        self.wait_until(lambda: self._heard_by(pub, others=count), timeout, what)

    def wait_for_acks(self, timeout: float) -> list[str]:
        """Wait until every message this node's reliable publishers sent has been acknowledged by each
        subscriber they matched (in its reader's history: taken or not); returns the topics that were not
        within ``timeout`` wall seconds in all (a subscriber that died, before DDS noticed)."""
        deadline = time.monotonic() + timeout
        late = []
        for pub in list(self.node.publishers):
            if pub.qos_profile.reliability != ReliabilityPolicy.RELIABLE:
                continue
            left = max(0.0, deadline - time.monotonic())
            if not pub.wait_for_all_acked(Duration(nanoseconds=int(left * 1e9))):
                late.append(pub.topic_name)
        return late

    # ------------------------------------------------------------------ services
    def wait_for_service(self, name: str, srv_type: Any, timeout: float = 10.0) -> Any:
        """A client of ``name`` once a server of it has been discovered.

        Raises:
            TestTimeout: no server within wall-clock ``timeout`` (a node that never started, or a name
                spelled another way: ``ros2 service list`` in the failure's log shows what there was).
        """
        client = self.node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=timeout):
            raise TestTimeout(f"service {name} did not appear within {timeout:g} s")
        return client

    def call(self, name: str, srv_type: Any, request: Any = None, timeout: float = 30.0) -> Any:
        """Call a service and return its response.

        Args:
            name: the service's full name.
            srv_type: the service class, e.g. ``std_srvs.srv.SetBool``.
            request: the request (None: a default-constructed one).
            timeout: wall-clock seconds for the server to appear, and again for its reply. A server that
                answers only as sim time passes (a paused world's node waiting on its clock) never replies
                while the test waits here: call it with ``call_async`` on :attr:`node` and step meanwhile.

        Raises:
            TestTimeout: no server, or no reply, in time.
        """
        client = self.wait_for_service(name, srv_type, timeout)
        future = client.call_async(request if request is not None else srv_type.Request())
        done = threading.Event()
        future.add_done_callback(lambda _f: done.set())
        if not done.wait(timeout):
            raise TestTimeout(f"{name} did not reply within {timeout:g} s")
        result = future.result()
        self.node.destroy_client(client)
        return result

    def wait_until(self, predicate: Callable[[], Any], timeout: float = 10.0, what: str = "the condition") -> Any:
        """Wait (wall clock) until ``predicate()`` is truthy, without stepping the world: for things that
        happen in wall time (discovery, a process starting). For what happens in sim time use
        ``gazelle_sim.run_until``, which steps while it waits.

        Returns:
            The predicate's first truthy value.

        Raises:
            TestTimeout: still false after ``timeout`` wall seconds, naming ``what``.
        """

        def pause() -> None:
            with self._clock_cond:  # a /clock message wakes it early: new data may have come with it
                self._clock_cond.wait(0.02)

        return poll_until(predicate, timeout, what, pause)

    def close(self) -> None:
        """Stop spinning, destroy the node and end its context."""
        if self.context.ok():
            self._executor.shutdown(timeout_sec=1.0)
            self.node.destroy_node()
            self.context.try_shutdown()
        self._thread.join(2.0)

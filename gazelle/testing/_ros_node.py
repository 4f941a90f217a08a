"""The test's own rclpy node, on the simulation's private domain, spun on a thread of its own.

It has its own rclpy context, so a test (or the code it tests) may use rclpy's default context as it
likes; helpers wait for conditions with timeouts and never sleep a fixed time.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rosgraph_msgs.msg import Clock

__all__ = ["MessageLog", "RosTestNode", "TestTimeout"]


class TestTimeout(AssertionError):
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
    arrived at the test."""

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
        """Wait (wall-clock ``timeout``) until ``count`` messages have arrived; returns the newest."""
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
        code may also init), spun on a thread, following /clock for the simulation's time."""
        self.context = Context()
        rclpy.init(context=self.context, domain_id=domain_id)
        self.node = rclpy.create_node(name, context=self.context, start_parameter_services=False)
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.node)
        self._sim_time = 0.0
        self._clock_cond = threading.Condition()
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
        """Wait until /clock has reached ``at_least`` (wall-clock ``timeout``); returns it."""
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
        """Keep every message of ``topic`` from now on (depth 1000; best effort matches any publisher,
        reliable only reliable ones: pass ``reliable=False`` for sensor data published best effort)."""
        log = MessageLog(topic)
        self.node.create_subscription(msg_type, topic, lambda m: log._add(m, self.sim_time), qos_for(reliable, latched))
        return log

    def wait_for_message(self, topic: str, msg_type: Any, timeout: float = 10.0, **qos: bool) -> Any:
        """The first message on ``topic`` (from now), within wall-clock ``timeout``."""
        return self.subscribe(topic, msg_type, **qos).wait(1, timeout)

    def publisher(self, topic: str, msg_type: Any, *, latched: bool = False) -> Any:
        return self.node.create_publisher(msg_type, topic, qos_for(True, latched, depth=10))

    # ------------------------------------------------------------------ services
    def wait_for_service(self, name: str, srv_type: Any, timeout: float = 10.0) -> Any:
        """A client of ``name`` once the service is there (wall-clock ``timeout``)."""
        client = self.node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=timeout):
            raise TestTimeout(f"service {name} did not appear within {timeout:g} s")
        return client

    def call(self, name: str, srv_type: Any, request: Any = None, timeout: float = 30.0) -> Any:
        """Call a service and return its response (wall-clock ``timeout`` for the service and the reply)."""
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
        """Wait (wall clock) until ``predicate()`` is truthy; for sim-time waits use ``Sim.run_until``."""

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

"""A short-lived rclpy node for the ros2 verbs (as ros2cli's --no-daemon mode: it discovers the graph
for ``spin_time`` seconds before answering), or the graph daemon's view for a listing (:func:`graph_view`)."""

from __future__ import annotations

import argparse
import os
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

from ..._errors import SimError

if TYPE_CHECKING:
    from rclpy.node import Node

    from ._daemon_graph import DaemonGraph

DEFAULT_SPIN_TIME = 1.5
"""Seconds to discover the graph before listing without the daemon (``--no-daemon``, or the first verb)."""


def add_discovery_options(*verbs: argparse.ArgumentParser) -> None:
    """ros2cli's ``NodeStrategy`` options (ros2cli/node/strategy.py, ``add_arguments``) on each listing verb:
    ``--spin-time`` (how long :func:`discover` waits without the daemon) and ``--no-daemon``."""
    for verb in verbs:
        verb.add_argument(
            "--spin-time",
            type=float,
            default=DEFAULT_SPIN_TIME,
            help="Spin time in seconds to wait for discovery (only applies when not using an already running daemon)",
        )
        verb.add_argument("--no-daemon", action="store_true", help="Do not spawn nor use an already running daemon")


class ShutDown(SimError):
    """The verb's context was shut down under it (rclpy's own SIGINT/SIGTERM handler does that): whatever
    rcl call was running then fails (a wait set, a node, a subscription), and the verb ends in order."""


_EXECUTORS: dict[int, Any] = {}
"""id(node) -> the executor that spins it (rclpy.spin_once(node) adds and removes the node each call:
a few milliseconds, too slow for `ros2 topic echo` at 1 kHz)."""


@contextmanager
def cli_node(name: str = "ros2cli", *, node_name: str | None = None, use_sim_time: bool = False) -> Iterator[Any]:
    """An initialised rclpy context with a hidden node and its executor (see :func:`spin_once`), shut
    down on exit. ``node_name`` names the node exactly (``ros2 topic pub -n``); ``use_sim_time`` (ros2cli's
    ``-s``) makes its clock follow /clock."""
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.parameter import Parameter
    from rclpy.utilities import get_default_context, try_shutdown

    rclpy.init(args=[])
    context = get_default_context()
    try:
        node = rclpy.create_node(
            node_name or f"_{name}_{os.getpid()}",
            start_parameter_services=False,
            parameter_overrides=[Parameter("use_sim_time", value=True)] if use_sim_time else [],
        )
        executor = SingleThreadedExecutor()
        executor.add_node(node)
    except Exception as err:
        if not context.ok():
            # rclpy's signal handler shut the context down while the node or the executor was being made
            # (CI: a SIGTERM inside SingleThreadedExecutor()): the verb ends in order and says nothing more
            from ...ros import silence_half_made_objects

            silence_half_made_objects()
            raise ShutDown from err
        raise
    _EXECUTORS[id(node)] = executor
    try:
        yield node
    except KeyboardInterrupt:
        from ...ros import await_signal_shutdown

        await_signal_shutdown(context)  # rclpy's signal thread triggers the executor's guard condition first
        raise
    except Exception as err:
        if not context.ok():  # checked before our own shutdown below: the signal came first
            raise ShutDown from err
        raise
    finally:
        _EXECUTORS.pop(id(node), None)

        def teardown() -> None:
            executor.shutdown(timeout_sec=0.5)
            node.destroy_node()
            try_shutdown()

        # at most a few seconds: once, `ros2 param dump` printed its answer and then never returned from
        # here (CI killed it at 60 s); the process ends right after anyway (see console_main)
        done = threading.Thread(target=teardown, name="ros2cli-teardown", daemon=True)
        done.start()
        done.join(5.0)


def spin_once(node: Any, timeout_sec: float) -> None:
    """Take one ready callback of ``node`` (waiting at most ``timeout_sec``)."""
    executor = _EXECUTORS.get(id(node))
    if executor is None:  # a node not made by cli_node: rclpy's global executor
        import rclpy

        rclpy.spin_once(node, timeout_sec=timeout_sec)
    else:
        executor.spin_once(timeout_sec=timeout_sec)


QUIET_SEC = 2.0
"""Discovery is taken as done when the graph has not changed for this long (after the spin time)."""
MAX_DISCOVERY_SEC = 8.0
SETTLE_SEC = 1.0
"""Quiet time after a named node or topic has appeared: its other endpoints come in the same exchange."""


def discover(
    node: Any, seconds: float = DEFAULT_SPIN_TIME, quiet: float = QUIET_SEC, watch: Callable[[], Any] | None = None
) -> None:
    """Let discovery run for at least ``seconds``, until another node is seen and what is watched (by
    default the graph's nodes, topics and services; ``watch()`` when given) has been still for ``quiet``
    seconds; at most :data:`MAX_DISCOVERY_SEC` (spinning so graph events are taken). A listing waits the
    full :data:`QUIET_SEC`; a verb about one name that has already appeared waits :data:`SETTLE_SEC` for
    the rest of its endpoints."""

    def snapshot() -> tuple:
        return (
            tuple(sorted(node.get_node_names_and_namespaces())),
            tuple(sorted(n for n, _ in node.get_topic_names_and_types())) if watch is None else watch(),
            tuple(sorted(n for n, _ in node.get_service_names_and_types())) if watch is None else (),
        )

    start = time.monotonic()
    last, changed = snapshot(), start
    while True:
        spin_once(node, timeout_sec=0.05)
        now = time.monotonic()
        current = snapshot()
        if current != last:
            last, changed = current, now
        others = any(not n.startswith("_") for n, _ in current[0])  # someone besides this tool
        if now - start >= max(seconds, MAX_DISCOVERY_SEC):
            return
        if now - start >= seconds and others and now - changed >= quiet:
            return


@contextmanager
def graph_view(
    name: str, no_daemon: bool = False, spin_time: float = DEFAULT_SPIN_TIME
) -> Iterator[Node | DaemonGraph]:
    """The graph a listing verb reads (``get_node_names_and_namespaces`` and the other getters): a warm graph
    daemon's, in milliseconds (ros2cli's ``NodeStrategy``: the daemon when it runs, else a direct node, and
    the daemon started for the next verb); this verb's own node after :func:`discover` with ``no_daemon``
    or when no daemon runs yet."""
    from ._daemon_graph import daemon_graph

    graph = None if no_daemon else daemon_graph()
    if graph is not None:
        yield graph
        return
    with cli_node(name) as node:
        discover(node, spin_time)
        yield node


def absolute(name: str) -> str:
    """A name as the command line takes it (``odom``), made absolute (``/odom``)."""
    return name if name.startswith("/") else f"/{name}"


def is_hidden(name: str) -> bool:
    """ROS's hidden names: a path part starting with an underscore."""
    return any(part.startswith("_") for part in name.split("/") if part)


def wait_until(node: Any, found: Any, timeout: float = MAX_DISCOVERY_SEC) -> Any:
    """Spin until ``found()`` returns something truthy (a name appeared in the graph) or ``timeout``."""

    deadline = time.monotonic() + timeout
    while True:
        value = found()
        if value or time.monotonic() > deadline:
            return value
        spin_once(node, timeout_sec=0.05)


def offers(node: Any, topic: str) -> tuple[int, int, int]:
    """(publishers, how many offer reliable, how many offer transient local) of ``topic`` as discovered:
    what ros2topic's echo, rosbag2's recorder and :func:`matching_qos` adapt a reader to."""
    from rclpy.qos import DurabilityPolicy, ReliabilityPolicy

    infos = node.get_publishers_info_by_topic(topic)
    reliable = sum(i.qos_profile.reliability == ReliabilityPolicy.RELIABLE for i in infos)
    latched = sum(i.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL for i in infos)
    return len(infos), reliable, latched


def matching_qos(node: Any, topic: str) -> Any:
    """A subscription QoS that matches every publisher: reliable only when all are, transient local only
    when all are (a transient local reader does not match a volatile writer). rosbag2's recorder adapts
    its request to the offers by the same rule (rosbag2_transport qos.cpp, ``adapt_request_to_offers``),
    as ros2topic's echo does (verb/echo.py ``choose_qos``); gazelle asked for transient local when any
    publisher offered it, and so missed the volatile ones."""
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    count, reliable, latched = offers(node, topic)
    return QoSProfile(
        depth=10,
        reliability=ReliabilityPolicy.RELIABLE if count and reliable == count else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if count and latched == count else DurabilityPolicy.VOLATILE,
    )

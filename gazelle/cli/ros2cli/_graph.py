"""A short-lived rclpy node for the ros2 verbs (as ros2cli's --no-daemon mode: it discovers the graph
for ``spin_time`` seconds before answering)."""

from __future__ import annotations

import os
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

DEFAULT_SPIN_TIME = 1.5
"""Seconds to discover the graph before listing (ros2cli's daemon remembers it; we have no daemon)."""


@contextmanager
def cli_node(name: str = "ros2cli") -> Iterator[Any]:
    """An initialised rclpy context with a hidden node, shut down on exit."""
    import rclpy

    rclpy.init(args=[])
    node = rclpy.create_node(f"_{name}_{os.getpid()}", start_parameter_services=False)
    try:
        yield node
    finally:
        node.destroy_node()
        rclpy.try_shutdown()  # pyright: ignore[reportPrivateImportUsage]


QUIET_SEC = 2.0
"""Discovery is taken as done when the graph has not changed for this long (after the spin time)."""
MAX_DISCOVERY_SEC = 8.0


def discover(node: Any, seconds: float = DEFAULT_SPIN_TIME) -> None:
    """Let discovery run for at least ``seconds``, until another node is seen and the graph (nodes,
    topics, services) has been still for :data:`QUIET_SEC`; at most :data:`MAX_DISCOVERY_SEC` (spinning
    so graph events are taken)."""
    import rclpy

    def snapshot() -> tuple:
        return (
            tuple(sorted(node.get_node_names_and_namespaces())),
            tuple(sorted(n for n, _ in node.get_topic_names_and_types())),
            tuple(sorted(n for n, _ in node.get_service_names_and_types())),
        )

    start = time.monotonic()
    last, changed = snapshot(), start
    while True:
        rclpy.spin_once(node, timeout_sec=0.05)
        now = time.monotonic()
        current = snapshot()
        if current != last:
            last, changed = current, now
        others = any(not n.startswith("_") for n, _ in current[0])  # someone besides this tool
        if now - start >= max(seconds, MAX_DISCOVERY_SEC):
            return
        if now - start >= seconds and others and now - changed >= QUIET_SEC:
            return


def is_hidden(name: str) -> bool:
    """ROS's hidden names: a path part starting with an underscore."""
    return any(part.startswith("_") for part in name.split("/") if part)


def wait_until(node: Any, found: Any, timeout: float = MAX_DISCOVERY_SEC) -> Any:
    """Spin until ``found()`` returns something truthy (a name appeared in the graph) or ``timeout``."""
    import rclpy

    deadline = time.monotonic() + timeout
    while True:
        value = found()
        if value or time.monotonic() > deadline:
            return value
        rclpy.spin_once(node, timeout_sec=0.05)

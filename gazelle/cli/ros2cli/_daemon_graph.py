"""The graph as gazelle's graph daemon knows it, answering the queries a listing verb makes of an rclpy node
(ros2cli's ``DaemonNode`` proxies the same getters over XML-RPC)."""

from __future__ import annotations

import time

from ._daemon_link import WARM_SEC, names_and_types, request, start_daemon

START_WAIT_SEC = 5.0
"""How long a verb waits for the daemon it started to answer (it imports rclpy and makes its node: ~0.5 s)."""
SECTIONS = ("subscribers", "publishers", "service_servers", "service_clients", "action_servers", "action_clients")
"""One node's endpoints as ``ros2 node info`` lists them, in its order."""


class DaemonGraph:
    """A snapshot of the daemon's graph: node, topic and service names with their types, and one node's
    endpoints on request. Every name is a string checked on arrival; none is evaluated."""

    def __init__(self, reply: dict[str, object]) -> None:
        """The daemon's ``graph`` answer (already known to be an ``ok`` reply)."""
        nodes = reply.get("nodes")
        self._nodes = [
            (n[0], n[1])
            for n in (nodes if isinstance(nodes, list) else [])
            if isinstance(n, list) and len(n) == 2 and all(isinstance(x, str) for x in n)
        ]
        self._topics = names_and_types(reply.get("topics"))
        self._services = names_and_types(reply.get("services"))
        self._endpoints: dict[tuple[str, str], dict[str, list[tuple[str, list[str]]]]] = {}

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """(name, namespace) of each node, as rclpy's ``Node.get_node_names_and_namespaces``."""
        return list(self._nodes)

    def get_topic_names_and_types(self) -> list[tuple[str, list[str]]]:
        """(topic, types), as rclpy's ``Node.get_topic_names_and_types``."""
        return list(self._topics)

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        """(service, types), as rclpy's ``Node.get_service_names_and_types``."""
        return list(self._services)

    def endpoints(self, name: str, namespace: str) -> dict[str, list[tuple[str, list[str]]]]:
        """One node's endpoints by :data:`SECTIONS` (asked of the daemon once; empty when it is gone)."""
        key = (name, namespace)
        if key not in self._endpoints:
            reply = request({"op": "node", "name": name, "namespace": namespace}) or {}
            self._endpoints[key] = {s: names_and_types(reply.get(s)) for s in SECTIONS}
        return self._endpoints[key]


def daemon_graph(start: bool = True) -> DaemonGraph | None:
    """The graph as a warm daemon knows it; None when no daemon answers (with ``start``, one is started
    first, as ros2cli's verbs do, and waited for: at most :data:`START_WAIT_SEC` to answer). A daemon younger
    than :data:`WARM_SEC` is waited for until it is warm: it has then heard every participant (ros2cli's
    first verb lists what its own node found in 0.5 s; here the first is slower, and complete)."""
    reply = request({"op": "graph"})
    if reply is None and start and start_daemon():
        deadline = time.monotonic() + START_WAIT_SEC
        while reply is None and time.monotonic() < deadline:
            time.sleep(0.05)
            reply = request({"op": "status"})
    age = reply.get("age") if reply is not None else None
    if reply is None or not isinstance(age, (int, float)):
        return None
    if age < WARM_SEC or "nodes" not in reply:
        time.sleep(max(0.0, WARM_SEC - age))
        reply = request({"op": "graph"})
    return None if reply is None else DaemonGraph(reply)

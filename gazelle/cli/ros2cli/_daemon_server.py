"""gazelle's graph daemon: one long-lived hidden rclpy node per environment that answers the ``ros2`` verbs'
graph queries over a Unix socket (ros2cli's ``_ros2_daemon``, ros2cli/daemon/__init__.py: the same getters,
the same 2 h idle timeout; ros2cli serves XML-RPC on a localhost TCP port any local user may call, this
socket only its own user). Run by the verbs as ``python -m gazelle.cli.ros2cli._daemon_server SOCKET TIMEOUT``.

Requests are one JSON line of at most 4 KiB: ``{"op": "status" | "graph" | "stop"}`` or ``{"op": "node",
"name": ..., "namespace": ...}``; anything else gets ``{"ok": false}``. A peer of another user is closed at
once; a peer that sends nothing is dropped after 2 s.
"""

from __future__ import annotations

import fcntl
import json
import os
import socket
import struct
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING

from ._daemon_graph import SECTIONS
from ._daemon_link import MAX_REQUEST

if TYPE_CHECKING:
    from rclpy.node import Node

PEER_TIMEOUT = 2.0


def _by_node(node: Node, name: str, namespace: str) -> dict[str, object]:
    """One node's endpoints, each section as ``[[name, [types]], ...]`` (empty when the node has gone)."""
    from rclpy.action import graph

    getters = (
        node.get_subscriber_names_and_types_by_node,
        node.get_publisher_names_and_types_by_node,
        node.get_service_names_and_types_by_node,
        node.get_client_names_and_types_by_node,
        lambda n, ns: graph.get_action_server_names_and_types_by_node(node, n, ns),
        lambda n, ns: graph.get_action_client_names_and_types_by_node(node, n, ns),
    )
    out: dict[str, object] = {"ok": True}
    for section, get in zip(SECTIONS, getters, strict=True):
        try:
            out[section] = [[n, list(t)] for n, t in get(name, namespace)]
        except Exception:  # the node left the graph between the two queries: it has no endpoints now
            out[section] = []
    return out


def answer(node: Node, started: float, message: object) -> dict[str, object]:
    """The reply to one request (its fields are data: only ``op`` chooses, the names are passed to rcl)."""
    fields: dict[object, object] = message if isinstance(message, dict) else {}
    op = fields.get("op")
    base: dict[str, object] = {"ok": True, "age": time.monotonic() - started, "pid": os.getpid()}
    if op in ("status", "stop"):
        return base
    if op == "graph":
        base["nodes"] = [[n, ns] for n, ns in node.get_node_names_and_namespaces()]
        base["topics"] = [[n, list(t)] for n, t in node.get_topic_names_and_types()]
        base["services"] = [[n, list(t)] for n, t in node.get_service_names_and_types()]
        return base
    name, namespace = (fields.get(k) for k in ("name", "namespace")) if op == "node" else (None, None)
    if isinstance(name, str) and isinstance(namespace, str) and name and namespace.startswith("/"):
        return _by_node(node, name, namespace)
    return {"ok": False}


def _serve_one(conn: socket.socket, node: Node, started: float) -> bool:
    """Answer one connection; True when it asked the daemon to stop."""
    with conn:
        _pid, uid, _gid = struct.unpack("3i", conn.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, 12))
        if uid != os.getuid():
            return False
        conn.settimeout(PEER_TIMEOUT)
        data = b""
        try:
            while b"\n" not in data and len(data) <= MAX_REQUEST:
                chunk = conn.recv(MAX_REQUEST)
                if not chunk:
                    break
                data += chunk
            if len(data) > MAX_REQUEST:  # not a verb's request: dropped unanswered
                return False
            message = json.loads(data.split(b"\n", 1)[0])
        except (OSError, ValueError):
            return False
        reply = answer(node, started, message)
        try:
            conn.sendall(json.dumps(reply).encode())
        except OSError:
            pass
        return isinstance(message, dict) and message.get("op") == "stop"


def serve(path: Path, idle_timeout: float) -> int:
    """Hold the socket's lock (one daemon per socket: a second one ends at once), make the node, and answer
    until asked to stop or idle for ``idle_timeout`` seconds."""
    lock = os.open(f"{path}.lock", os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o600)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return 0
    from ...ros import announce_often

    announce_often()  # a node that starts learns of the daemon within 0.1 s, not at its 3 s announcement
    import rclpy
    from rclpy.utilities import ok, try_shutdown

    rclpy.init(args=[])
    domain = os.environ.get("ROS_DOMAIN_ID", "0")
    node = rclpy.create_node(f"_ros2cli_daemon_{domain}_{os.getpid()}", start_parameter_services=False)
    started = time.monotonic()
    server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    path.unlink(missing_ok=True)  # a daemon that died left its socket: the lock says none holds it
    old_mask = os.umask(0o177)
    try:
        server.bind(str(path))
    finally:
        os.umask(old_mask)
    server.listen(16)
    server.settimeout(1.0)
    last = time.monotonic()
    try:
        while time.monotonic() - last < idle_timeout and ok():  # a SIGTERM shuts the context down
            try:
                conn, _ = server.accept()
            except TimeoutError:
                continue
            last = time.monotonic()
            if _serve_one(conn, node, started):
                break
    finally:
        server.close()
        path.unlink(missing_ok=True)
        node.destroy_node()
        try_shutdown()
    return 0


def main(argv: list[str]) -> int:
    """``SOCKET TIMEOUT``: serve on SOCKET, ending after TIMEOUT idle seconds."""
    return serve(Path(argv[0]), float(argv[1]))


if __name__ == "__main__":
    sys.stdout.flush()
    os._exit(main(sys.argv[1:]))

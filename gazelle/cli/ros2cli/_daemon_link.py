"""A ``ros2`` verb's side of gazelle's graph daemon (ros2cli's daemon: ros2cli/node/daemon.py, daemon/__init__.py).

A verb's own DDS participant finds a running process when that process next announces itself: gazelle's own
processes every 0.1 s, any other (a user's rclpy node) every 3 s, Fast DDS's default. A listing that waits
for the graph to be still therefore took ~2.5 s and could still miss a user's node. The daemon is a
participant that stays: once it has been up longer than one announcement period (:data:`WARM_SEC`) it has
heard every participant in the domain, and a verb asks it for the graph in milliseconds, without importing
rclpy. As ros2cli, the first verb starts the daemon and discovers the graph itself meanwhile.

The link is a Unix socket in a folder only this user may enter (0700, owned by the user, and no other user may
replace it or a folder above it: ``gazelle._files.checked_folder``; else the daemon is not used and a warning
says why); the daemon answers only its own user (SO_PEERCRED). What comes back is JSON, each field checked for
its shape: names are data, printed and never evaluated.
Nothing here imports rclpy; ``_daemon_graph.DaemonGraph`` answers the graph queries a verb makes of a node.
"""

from __future__ import annotations

import hashlib
import json
import os
import socket
import subprocess
import sys
from pathlib import Path

from ..._files import checked_folder

DIR_VARIABLE = "GAZELLE_ROS2_DAEMON_DIR"
"""The daemons' folder (default ``$XDG_RUNTIME_DIR/gazelle-ros2-daemon``, else ``/tmp/gazelle-ros2-daemon-UID``)."""
TIMEOUT_VARIABLE = "GAZELLE_ROS2_DAEMON_TIMEOUT"
"""Seconds without a request after which a daemon a verb starts ends (ros2cli's ``--timeout``: 2 h)."""
DEFAULT_TIMEOUT = 2 * 60 * 60
WARM_SEC = 4.0
"""A daemon up this long has heard every participant of the domain: Fast DDS announces every 3 s, and the
exchange of endpoints that follows an announcement gets a second on a loaded machine."""
MAX_REQUEST = 4096
MAX_REPLY = 32 * 1024 * 1024
REPLY_TIMEOUT = 5.0
KEY_VARIABLES = (
    "ROS_DOMAIN_ID",
    "RMW_IMPLEMENTATION",
    "ROS_LOCALHOST_ONLY",
    "ROS_AUTOMATIC_DISCOVERY_RANGE",
    "ROS_STATIC_PEERS",
    "ROS_DISCOVERY_SERVER",
    "FASTRTPS_DEFAULT_PROFILES_FILE",
    "FASTDDS_DEFAULT_PROFILES_FILE",
)
"""What decides which graph a participant sees: one daemon for each combination."""


_WARNED: set[Path] = set()


def daemon_dir() -> Path:
    """The folder of this user's daemons' sockets."""
    given = os.environ.get(DIR_VARIABLE)
    if given:
        return Path(given)
    runtime = os.environ.get("XDG_RUNTIME_DIR")
    return Path(runtime) / "gazelle-ros2-daemon" if runtime else Path(f"/tmp/gazelle-ros2-daemon-{os.getuid()}")


def private_dir(create: bool) -> Path | None:
    """The daemons' folder (its real path), made 0700 when ``create``; None (with one warning line) when it is not
    a folder of this user that no one else may enter or replace (gazelle._files.checked_folder, owner-only), or
    when it does not exist and ``create`` is false."""
    folder = daemon_dir()
    try:
        real, why = checked_folder(folder, create=create, owner_only=True)
    except OSError as err:
        print(f"ros2: not using the graph daemon: cannot make {folder}: {err.strerror or err}", file=sys.stderr)
        return None
    if why is not None and folder not in _WARNED:  # once a process
        _WARNED.add(folder)
        print(f"ros2: not using the graph daemon: {why}", file=sys.stderr)
    return real


def socket_name() -> str:
    """The socket's file name: the domain, and a digest of the other settings that decide the graph."""
    key = "\0".join(f"{v}={os.environ.get(v, '')}" for v in KEY_VARIABLES)
    domain = os.environ.get("ROS_DOMAIN_ID", "0").strip() or "0"
    domain = domain if domain.isdigit() else "x"
    return f"domain{domain}-{hashlib.sha256(key.encode()).hexdigest()[:12]}.sock"


def request(message: dict[str, object], create: bool = False) -> dict[str, object] | None:
    """Send one request to this environment's daemon and return its answer; None when no daemon answers."""
    folder = private_dir(create)
    if folder is None:
        return None
    conn = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    conn.settimeout(REPLY_TIMEOUT)
    try:
        conn.connect(str(folder / socket_name()))
        conn.sendall(json.dumps(message).encode()[:MAX_REQUEST] + b"\n")
        conn.shutdown(socket.SHUT_WR)
        chunks, size = [], 0
        while size <= MAX_REPLY:
            chunk = conn.recv(1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        reply = json.loads(b"".join(chunks)) if size <= MAX_REPLY else None
    except (OSError, ValueError):
        return None
    finally:
        conn.close()
    return reply if isinstance(reply, dict) and reply.get("ok") is True else None


def start_daemon() -> bool:
    """Start this environment's daemon (a process of its own session, which outlives the verb); False when
    its folder cannot be used."""
    folder = private_dir(create=True)
    if folder is None:
        return False
    try:
        timeout = float(os.environ.get(TIMEOUT_VARIABLE, DEFAULT_TIMEOUT))
    except ValueError:
        timeout = DEFAULT_TIMEOUT
    command = [sys.executable, "-m", "gazelle.cli.ros2cli._daemon_server", str(folder / socket_name()), f"{timeout:g}"]
    subprocess.Popen(
        command,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,  # a Ctrl-C of the verb does not reach it
        close_fds=True,
    )
    return True


def names_and_types(value: object) -> list[tuple[str, list[str]]]:
    """``[[name, [type, ...]], ...]`` from the wire, checked; anything else is an empty list."""
    if not isinstance(value, list):
        return []
    out = []
    for item in value:
        if (
            isinstance(item, list)
            and len(item) == 2
            and isinstance(item[0], str)
            and isinstance(item[1], list)
            and all(isinstance(t, str) for t in item[1])
        ):
            out.append((item[0], list(item[1])))
    return out

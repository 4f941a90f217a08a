"""Who can reach ``gazelle sim`` over ROS, and one server per ROS domain.

Discovery range. ROS 2 Jazzy discovers nodes on the whole subnet by default, so anyone on the
same network could call ``/spawn_entity`` and ``/delete_entity``. ``gazelle sim`` therefore
limits its own discovery to this machine (``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST``) unless
the user chose a range (that variable, ``ROS_LOCALHOST_ONLY`` or ``ROS_STATIC_PEERS``) or passed
``--ros-discovery subnet``. Plain rclpy nodes started in a fresh shell (subnet range, the
default) still reach it on the same machine: a localhost participant answers their discovery.

One server per domain. Two servers on one domain would both answer every ``/spawn_entity``
and spawn every robot twice. Each server announces itself on a hidden latched topic; a server
that hears of one started before it says so and stops (exit status 1), and the older keeps
serving. The newer one is told the older's host, process id and start time.

A server its ``ros2 launch`` left behind. gazelle's ``ros2 launch`` names itself to every process it starts
(:data:`LAUNCH_ID_VAR`: its process id and start time), and a server started by a launch announces that name.
A server whose launch has ended (Ctrl-C that did not reach it, a killed terminal, a launch killed with
SIGKILL) stops by itself within a second, saying why (:func:`launch_ended`): otherwise it would keep the domain
and the next launch's own server would yield to it, and that launch's robot would spawn into the old world.
"""

from __future__ import annotations

import json
import os
import socket
import threading
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

if TYPE_CHECKING:
    from rclpy.node import Node

DISCOVERY_VARIABLES = ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_LOCALHOST_ONLY", "ROS_STATIC_PEERS")
LAUNCH_ID_VAR = "GAZELLE_LAUNCH_ID"
"""Set by gazelle's ``ros2 launch`` for the processes it starts: ``<pid>:<start time in clock ticks>``."""
ANNOUNCE_TOPIC = "/_gazelle/servers"
"""Hidden (a leading underscore): ``ros2 topic list`` shows it only with ``--include-hidden-topics``."""


def choose_discovery_range(requested: str | None, environ: dict[str, str] | os._Environ[str] = os.environ) -> str:
    """Set the discovery range for this process (before rclpy starts) and return a description of it.

    ``requested`` is ``--ros-discovery`` (``localhost``, ``subnet``, ``off``) or None: keep what the
    environment says, else LOCALHOST.
    """
    if requested is not None:
        environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = requested.upper()
        return f"{requested.upper()} (--ros-discovery)"
    chosen = [v for v in DISCOVERY_VARIABLES if environ.get(v)]
    if chosen:
        return ", ".join(f"{v}={environ[v]}" for v in chosen) + " (from the environment)"
    environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    return "LOCALHOST (default of gazelle sim; --ros-discovery subnet opens it)"


def _start_ticks(pid: int) -> str | None:
    """The process's start time in clock ticks since boot (``/proc/<pid>/stat`` field 22), which tells a process
    from a later one given the same id; None when there is no such process (or no /proc)."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as f:
            stat = f.read()
    except OSError:
        return None
    # the command name (field 2) is in parentheses and may hold spaces: count fields after its last ")"
    fields = stat.rsplit(")", 1)[-1].split()
    return fields[19] if len(fields) > 19 else None


def new_launch_id(pid: int) -> str:
    """The name a launch gives its processes (:data:`LAUNCH_ID_VAR`)."""
    return f"{pid}:{_start_ticks(pid) or ''}"


def launch_ended(launch_id: str) -> bool:
    """Whether the launch named ``launch_id`` has ended: its process is gone, or the id is now another process's.
    False when it runs, or when this machine cannot tell (no /proc, an id that is not gazelle's form)."""
    pid_text, sep, ticks = launch_id.partition(":")
    if not sep or not pid_text.isdigit() or not ticks or not os.path.isdir("/proc/self"):
        return False
    return _start_ticks(int(pid_text)) != ticks


@dataclass(frozen=True, order=True)
class ServerId:
    """Identifies one running server; the smaller (earlier started) one wins a conflict."""

    started: float
    host: str
    pid: int

    def describe(self) -> str:
        """Who the other server is, for the "one server per domain" warning."""
        age = time.time() - self.started
        return f"pid {self.pid} on {self.host}, started {age:.0f} s ago"


class ServerRegistry:
    """Announces this server and notices others on the same domain (see the module docstring)."""

    def __init__(self, node: Node) -> None:
        """Announce this server on the domain (latched: start time, host, pid) and listen for others: two ``gazelle
        sim`` on one domain would both answer every spawn."""
        self.me = ServerId(time.time(), socket.gethostname(), os.getpid())
        self.conflict: str | None = None
        """Set when an older server serves this domain: why this one must stop."""
        self._warned: set[ServerId] = set()
        self._lock = threading.Lock()
        self._log = node.get_logger()
        qos = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
        self._pub = node.create_publisher(String, ANNOUNCE_TOPIC, qos)
        self._sub = node.create_subscription(String, ANNOUNCE_TOPIC, self._on_announce, qos)
        self._announce()

    def _announce(self, **extra: str) -> None:
        """Publish who this server is (latched), with ``extra`` facts such as its viewer's address."""
        me = {
            "started": self.me.started,
            "host": self.me.host,
            "pid": self.me.pid,
            "launch": os.environ.get(LAUNCH_ID_VAR, ""),
            **extra,
        }
        self._pub.publish(String(data=json.dumps(me)))

    def announce_viewer(self, url: str) -> None:
        """Announce again, with the address the viewer really took (8080, or the next free port): gzclient,
        ``gz sim -g`` and rviz2's stand-ins print it (:mod:`._gui_stand_ins`)."""
        self._announce(viewer=url)

    def _on_announce(self, msg: String) -> None:
        """Another server's announcement: the older one keeps the domain; this one, if it is the newer, records why
        it must stop (and says so); else it warns that the newer one was told to stop."""
        try:
            data = json.loads(msg.data)
            other = ServerId(float(data["started"]), str(data["host"]), int(data["pid"]))
        except (ValueError, KeyError, TypeError):
            return
        if other == self.me:
            return
        domain = os.environ.get("ROS_DOMAIN_ID", "0")
        with self._lock:
            if other in self._warned:
                return
            self._warned.add(other)
            if other < self.me:
                self.conflict = (
                    f"another gazelle sim already serves ROS_DOMAIN_ID={domain} ({other.describe()}); "
                    "two servers would both answer /spawn_entity. Stop it, or start this one with another ROS_DOMAIN_ID"
                )
                self._log.error(self.conflict)
            else:
                self._log.warning(
                    f"a second gazelle sim started on ROS_DOMAIN_ID={domain} ({other.describe()}); it is told to stop"
                )

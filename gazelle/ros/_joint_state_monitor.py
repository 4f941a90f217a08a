"""The latest position of every joint heard on a JointState topic, read without an executor.

MoveIt's CurrentStateMonitor merges every /joint_states message into the robot's current state, joint by
joint by name (moveit2 moveit_ros/planning/planning_scene_monitor/src/current_state_monitor.cpp,
``jointStateCallback``), and drops a message whose name and position counts differ with an error
logged at most once a second of steady time: so does this monitor, counting them in ``invalid``. Here each
message through rclpy's executor cost move_group more than the planning did: at 8x real time the
simulation's joint_state_broadcaster sends 800 messages a second, and rclpy's MultiThreadedExecutor
spent ~0.7 of a core building wait sets for them (py-spy: `_wait_for_ready_callbacks`, not the callback).
This monitor's subscription lives on a node of its own that no executor spins: its messages wait in the
DDS reader (keep-last ``depth``: 1,000 by default, over a second of an 800 Hz broadcaster) and are taken, in
order, when the state is read and every ``poll_sec`` by a thread, so a slow publisher's message (a hand's
broadcaster beside an arm's) is merged before faster ones push it out of the reader's history.
"""

from __future__ import annotations

import threading

from rclpy.clock import Clock
from rclpy.clock_type import ClockType
from rclpy.node import Node
from rclpy.qos import QoSProfile
from sensor_msgs.msg import JointState

from ._side_node import side_node


class JointStateMonitor:
    """Joint name -> position, merged from every message on ``topic`` (resolved as ``owner`` resolves it:
    its namespace and remappings)."""

    def __init__(self, owner: Node, topic: str = "joint_states", *, depth: int = 1000, poll_sec: float = 0.01):
        """Follow ``topic`` (``/joint_states``) on a side node of ``owner`` without an executor: a thread takes
        every waiting message at ``poll_sec`` intervals and merges them into the latest position per joint
        (robots publish their joints in several messages)."""
        resolved = owner.resolve_topic_name(topic)
        self._node = side_node(owner, "joint_state_monitor")
        self._sub = self._node.create_subscription(JointState, resolved, _never_called, QoSProfile(depth=depth))
        self.topic = resolved
        self._logger = owner.get_logger()
        self._lock = threading.Lock()
        self.invalid = 0
        """Messages dropped because their name and position counts differ."""
        self._positions: dict[str, float] = {}
        self._poll_sec = poll_sec
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._poll, name="joint state monitor", daemon=True)
        self._thread.start()

    def positions(self) -> dict[str, float]:
        """Every joint's latest position (empty until a message came); a new dict when something changed,
        so a caller may keep the one it got."""
        self._take_all()
        return self._positions

    def _take_all(self) -> None:
        """Take every message waiting on the subscription and merge their positions in; a message whose name and
        position counts differ is dropped and counted, as MoveIt's state monitor does."""
        with self._lock:
            if self._stop.is_set():
                return
            merged: dict[str, float] | None = None
            with self._sub.handle:
                while True:
                    taken = self._sub.handle.take_message(JointState, False)
                    if taken is None:
                        break
                    msg = taken[0]
                    if len(msg.name) != len(msg.position):
                        self._drop_invalid(len(msg.name), len(msg.position))
                    elif msg.name:
                        if merged is None:
                            merged = dict(self._positions)
                        merged.update(zip(msg.name, msg.position))
            if merged is not None:
                self._positions = merged

    def _drop_invalid(self, names: int, positions: int) -> None:
        """Count an invalid message and say so, at most once a second (MoveIt's words)."""
        self.invalid += 1
        self._logger.error(
            f"State monitor received an invalid joint state on {self.topic} ({names} joint names, "
            f"{positions} positions); dropped",
            throttle_duration_sec=1.0,
            throttle_time_source_type=_STEADY,
        )

    def _poll(self) -> None:
        """The monitor's thread: take what arrived, until stopped."""
        while not self._stop.wait(self._poll_sec):
            try:
                self._take_all()
            except Exception:
                if not self._node.context.ok():
                    return  # shut down (a signal) before destroy(): nothing more to take
                raise

    def destroy(self) -> None:
        """Stop the thread (it holds the subscription's handle while it takes), then the node."""
        self._stop.set()
        self._thread.join(timeout=2.0)
        with self._lock:
            self._node.destroy_node()


_STEADY = Clock(clock_type=ClockType.STEADY_TIME)


def _never_called(_msg: JointState) -> None:
    """The subscription's callback: no executor spins its node, messages are taken by the monitor."""

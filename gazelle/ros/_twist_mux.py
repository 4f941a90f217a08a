"""twist_mux's ``twist_mux`` node (ros-teleop/twist_mux, ``src/twist_mux.cpp`` and
``include/twist_mux/topic_handle.hpp``), which vendors' bring-ups start between their teleop sources and the base
controller (Husky: joystick, interactive markers and ``cmd_vel`` into ``husky_velocity_controller``).

As upstream: the node takes undeclared parameters; every prefix under ``topics`` (``topics.joy``) is a velocity
input with ``topic``, ``timeout`` (s; 0 never expires) and ``priority`` (clamped to 0..255), every prefix under
``locks`` a ``std_msgs/Bool`` lock with the same three. An input is masked while it has expired (no message within
its timeout; before its first message it has expired) or while its priority is below the highest priority of the
locks that are locked (a lock is locked while its last message said true, or while it has expired). A message on
an input is published on ``cmd_vel_out`` (``geometry_msgs/Twist``, keep-last 1) when that input is the
highest-priority unmasked one (the first listed among equals). Time is the node's clock. No diagnostics.
"""

from __future__ import annotations

import functools
import sys
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rclpy.node import Node

if TYPE_CHECKING:
    from geometry_msgs.msg import Twist
    from std_msgs.msg import Bool

PRIORITY_RANGE = (0, 255)
"""twist_mux clamps every priority to this range."""


@dataclass
class _Handle:
    """One input or lock (``TopicHandle_``): its name (the parameter prefix), timeout, priority and last message."""

    name: str
    topic: str
    timeout: float
    priority: int
    stamp: float = 0.0
    message: Twist | Bool | None = None
    """An input's last Twist, a lock's last Bool."""

    def expired(self, now: float) -> bool:
        return self.timeout > 0.0 and now - self.stamp > self.timeout


def _handles(node: Node, group: str) -> list[_Handle]:
    """The inputs or locks under parameter ``group`` (``topics`` or ``locks``), in the order the parameters
    list them (upstream's ``getTopicHandles``); one with no topic is an error naming it."""
    out: list[_Handle] = []
    for prefix in node.list_parameters([group], 10).prefixes:
        topic = node.get_parameter_or(f"{prefix}.topic", None)
        if topic is None or not isinstance(topic.value, str) or not topic.value:
            raise ValueError(f"twist_mux: parameter {prefix}.topic (a topic name) is not set")
        timeout = node.get_parameter_or(f"{prefix}.timeout", None)
        priority = node.get_parameter_or(f"{prefix}.priority", None)
        seconds = float(timeout.value) if timeout is not None and timeout.value is not None else 0.0
        level = int(priority.value) if priority is not None and priority.value is not None else 0
        out.append(_Handle(prefix, topic.value, seconds, min(max(level, PRIORITY_RANGE[0]), PRIORITY_RANGE[1])))
        shown = f"{seconds}s" if seconds > 0 else "None"
        node.get_logger().info(
            f"Topic handler '{prefix}' subscribed to topic '{topic.value}': timeout = {shown} , priority = {level}."
        )
    return out


def main(argv: list[str]) -> int:
    """``ros2 run twist_mux twist_mux`` (compat/ros_packages/twist_mux)."""
    import rclpy
    from geometry_msgs.msg import Twist
    from rclpy.qos import QoSProfile, qos_profile_system_default
    from std_msgs.msg import Bool

    from ._rsp_node import spin_until_interrupted

    rclpy.init(args=["twist_mux", *argv])
    node = rclpy.create_node(
        "twist_mux", allow_undeclared_parameters=True, automatically_declare_parameters_from_overrides=True
    )
    try:
        inputs = _handles(node, "topics")
        locks = _handles(node, "locks")
    except (ValueError, TypeError) as exc:
        print(str(exc), file=sys.stderr, flush=True)
        node.destroy_node()
        node.context.try_shutdown()
        return 1
    out = node.create_publisher(Twist, "cmd_vel_out", QoSProfile(depth=1))

    def now() -> float:
        return node.get_clock().now().nanoseconds * 1e-9

    def lock_priority(t: float) -> int:
        locked = [h.priority for h in locks if h.expired(t) or (isinstance(h.message, Bool) and h.message.data)]
        return max(locked, default=0)

    def on_velocity(handle: _Handle, msg: Twist) -> None:
        t = now()
        handle.stamp, handle.message = t, msg
        floor = lock_priority(t)
        best, name = 0, None
        for h in inputs:
            if not (h.expired(t) or h.priority < floor) and best < h.priority:
                best, name = h.priority, h.name
        if name == handle.name:
            out.publish(msg)

    def on_lock(handle: _Handle, msg: Bool) -> None:
        handle.stamp, handle.message = now(), msg

    for h in inputs:
        node.create_subscription(Twist, h.topic, functools.partial(on_velocity, h), qos_profile_system_default)
    for h in locks:
        node.create_subscription(Bool, h.topic, functools.partial(on_lock, h), qos_profile_system_default)
    spin_until_interrupted(node)
    return 0

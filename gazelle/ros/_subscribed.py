"""Whether anyone listens to a publisher, asked of rclpy sparingly (:class:`Subscribed`): the bridge's topics and
the planning scene's are built only while someone subscribes."""

from __future__ import annotations

import math
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rclpy.publisher import Publisher


class Subscribed:
    """Whether an rclpy publisher has subscribers, asked of rclpy at most every ``refresh_sec`` of wall
    time: the simulation asks before building each message (thousands of times a second faster than
    real time), and a subscriber that just matched waits at most that long (far less than discovery)."""

    __slots__ = ("_handle", "_refresh", "_until", "_value")

    def __init__(self, handle: Publisher, refresh_sec: float = 0.02):
        """Whether an rclpy publisher has subscribers, asked again at most every ``refresh_sec`` (the count is a
        graph query, too slow to ask every step)."""
        self._handle = handle
        self._refresh = refresh_sec
        self._until = -math.inf
        self._value = False

    def __call__(self) -> bool:
        """The publisher's subscriber count is above zero (as of the last refresh)."""
        now = time.monotonic()
        if now >= self._until:
            self._value = self._handle.get_subscription_count() > 0
            self._until = now + self._refresh
        return self._value

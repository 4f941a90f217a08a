"""launch.events: shutdown and process events."""

from __future__ import annotations

from typing import Any

from ..event import Event


class Shutdown(Event):
    name = "launch.events.Shutdown"

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        self.reason = reason
        self.due_to_sigint = due_to_sigint


class IncludeLaunchDescription(Event):
    name = "launch.events.IncludeLaunchDescription"

    def __init__(self, launch_description: Any) -> None:
        self.launch_description = launch_description


class TimerEvent(Event):
    name = "launch.events.TimerEvent"

    def __init__(self, *, timer_action: Any) -> None:
        self.timer_action = timer_action


from . import process  # noqa: E402

__all__ = ["IncludeLaunchDescription", "Shutdown", "TimerEvent", "process"]

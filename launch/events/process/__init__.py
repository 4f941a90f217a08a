"""launch.events.process: a process started, wrote output, exited."""

from __future__ import annotations

from typing import Any

from ...event import Event


class RunningProcessEvent(Event):
    def __init__(self, *, action: Any, name: str, cmd: list[str], cwd: str | None, env: Any, pid: int) -> None:
        self.action, self.name, self.cmd, self.cwd, self.env, self.pid = action, name, cmd, cwd, env, pid

    @property
    def execute_process_action(self) -> Any:
        return self.action


class ProcessStarted(RunningProcessEvent):
    name = "launch.events.process.ProcessStarted"


class ProcessExited(RunningProcessEvent):
    name = "launch.events.process.ProcessExited"

    def __init__(self, *, returncode: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.returncode = returncode


class ProcessIO(RunningProcessEvent):
    name = "launch.events.process.ProcessIO"

    def __init__(self, *, text: bytes, fd: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.text, self.fd = text, fd


class ShutdownProcess(Event):
    name = "launch.events.process.ShutdownProcess"

    def __init__(self, *, process_matcher: Any) -> None:
        self.process_matcher = process_matcher


def matches_action(action: Any) -> Any:
    return lambda proc_action: proc_action is action


__all__ = ["ProcessExited", "ProcessIO", "ProcessStarted", "RunningProcessEvent", "ShutdownProcess", "matches_action"]

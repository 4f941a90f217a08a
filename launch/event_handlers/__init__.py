"""launch.event_handlers: OnProcessExit, OnProcessStart, OnProcessIO, OnShutdown."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..event import Event, EventHandler
from ..events import Shutdown
from ..events.process import ProcessExited, ProcessIO, ProcessStarted


class _OnProcess(EventHandler):
    event_type: type = Event

    def __init__(
        self, *, target_action: Any = None, on_event: Any = None, handle_once: bool = False, **kw: Any
    ) -> None:
        key = next((k for k in ("on_exit", "on_start", "on_stdout", "on_stderr") if k in kw), None)
        self._on = kw.get(key) if key else on_event
        self.target_action = target_action

        def matcher(event: Event) -> bool:
            if not isinstance(event, self.event_type):
                return False
            if self.target_action is None:
                return True
            if callable(self.target_action) and not hasattr(self.target_action, "visit"):
                return bool(self.target_action(getattr(event, "action", None)))
            return getattr(event, "action", None) is self.target_action

        super().__init__(matcher=matcher, handle_once=handle_once)

    def handle(self, event: Event, context: Any) -> list[Any] | None:
        context.extend_locals({"event": event})
        on = self._on
        if on is None:
            return None
        if callable(on) and not hasattr(on, "visit"):
            result = on(event, context)
            if result is None:
                return None
            return list(result) if isinstance(result, (list, tuple)) else [result]
        return list(on) if isinstance(on, (list, tuple)) else [on]


class OnProcessExit(_OnProcess):
    event_type = ProcessExited

    def __init__(self, *, target_action: Any = None, on_exit: Any = None, handle_once: bool = False) -> None:
        super().__init__(target_action=target_action, on_exit=on_exit, handle_once=handle_once)


class OnProcessStart(_OnProcess):
    event_type = ProcessStarted

    def __init__(self, *, target_action: Any = None, on_start: Any = None, handle_once: bool = False) -> None:
        super().__init__(target_action=target_action, on_start=on_start, handle_once=handle_once)


class OnProcessIO(_OnProcess):
    event_type = ProcessIO

    def __init__(
        self, *, target_action: Any = None, on_stdout: Callable | None = None, on_stderr: Callable | None = None
    ) -> None:
        self._stdout, self._stderr = on_stdout, on_stderr
        super().__init__(target_action=target_action)

    def handle(self, event: Event, context: Any) -> list[Any] | None:
        fn = self._stdout if getattr(event, "fd", 1) == 1 else self._stderr
        if fn is None:
            return None
        result = fn(event)
        return None if result is None else (list(result) if isinstance(result, (list, tuple)) else [result])


class OnShutdown(EventHandler):
    def __init__(self, *, on_shutdown: Any, handle_once: bool = False) -> None:
        self._on = on_shutdown
        super().__init__(matcher=lambda e: isinstance(e, Shutdown), handle_once=handle_once)

    def handle(self, event: Event, context: Any) -> list[Any] | None:
        context.extend_locals({"event": event})
        on = self._on
        if callable(on) and not hasattr(on, "visit"):
            result = on(event, context)
            return None if result is None else (list(result) if isinstance(result, (list, tuple)) else [result])
        return list(on) if isinstance(on, (list, tuple)) else [on]


class OnExecutionComplete(EventHandler):
    def __init__(self, *, target_action: Any = None, on_completion: Any = None) -> None:
        raise NotImplementedError("OnExecutionComplete is not supported by gazelle's launch yet")


__all__ = ["OnExecutionComplete", "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown"]

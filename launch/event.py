"""Events and event handlers (launch.Event, launch.EventHandler)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class Event:
    name = "launch.Event"


class EventHandler:
    """Handles the events that ``matcher`` accepts with ``entities`` (actions to run) or a callable."""

    def __init__(self, *, matcher: Callable[[Event], bool], entities: Any = None, handle_once: bool = False) -> None:
        self.matcher = matcher
        self.entities = entities
        self.handle_once = handle_once

    def matches(self, event: Event) -> bool:
        return self.matcher(event)

    def handle(self, event: Event, context: Any) -> list[Any] | None:
        context.extend_locals({"event": event})
        ents = self.entities
        if ents is None:
            return None
        return list(ents) if isinstance(ents, (list, tuple)) else [ents]

    def describe(self) -> str:
        return type(self).__name__

"""LaunchDescription: the list of entities a launch file returns."""

from __future__ import annotations

from typing import Any

from .action import Action
from .launch_context import LaunchContext


class LaunchDescription(Action):
    """Entities (actions, nested descriptions) visited in order."""

    def __init__(self, initial_entities: Any = None, *, deprecated_reason: str | None = None) -> None:
        super().__init__()
        self.entities: list[Any] = list(initial_entities or [])

    def add_action(self, action: Any) -> None:
        self.entities.append(action)

    def add_entity(self, entity: Any) -> None:
        self.entities.append(entity)

    def describe_sub_entities(self) -> list[Any]:
        return list(self.entities)

    def get_sub_entities(self) -> list[Any]:
        return list(self.entities)

    def execute(self, context: Any) -> list[Any] | None:
        return list(self.entities)

    def get_launch_arguments(self, conditional_inclusion: bool = False, context: Any = None) -> list[Any]:
        """Every DeclareLaunchArgument here and in what it includes, in order (best effort: an include
        whose path needs values only known at run time is skipped). ``context`` gives the file's folder
        (ThisLaunchFileDir) and the configurations known so far. Each entity says what lies below it
        (:meth:`Action.launch_arguments_walk`)."""
        found: list[Any] = []
        seen: set[int] = set()

        def walk(entities: list[Any], ctx: LaunchContext) -> None:
            for e in entities:
                if id(e) in seen:
                    continue
                seen.add(id(e))
                if isinstance(e, Action):
                    below, inner = e.launch_arguments_walk(ctx, found)
                else:
                    try:
                        below, inner = list(e.get_sub_entities()), ctx
                    except Exception:
                        below, inner = [], ctx
                walk(below, inner)

        walk(self.entities, context if context is not None else LaunchContext())
        return found

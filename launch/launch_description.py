"""LaunchDescription: the list of entities a launch file returns."""

from __future__ import annotations

from typing import Any

from .action import Action


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
        (ThisLaunchFileDir) and the configurations known so far."""
        import copy
        import os

        from .actions import DeclareLaunchArgument, IncludeLaunchDescription
        from .launch_context import LaunchContext

        found: list[Any] = []
        seen: set[int] = set()

        def walk(entities: list[Any], ctx: LaunchContext) -> None:
            for e in entities:
                if id(e) in seen:
                    continue
                seen.add(id(e))
                if isinstance(e, DeclareLaunchArgument):
                    if all(d.name != e.name for d in found):
                        found.append(e)
                    default = e.default_text(ctx)
                    if default is not None:
                        ctx.launch_configurations.setdefault(e.name, default)
                    continue
                if isinstance(e, IncludeLaunchDescription):
                    try:
                        ld = e.launch_description_source.get_launch_description(ctx)
                    except Exception:
                        continue
                    inner = copy.copy(ctx)
                    inner.launch_configurations = dict(ctx.launch_configurations)
                    location = getattr(e.launch_description_source, "location", "")
                    inner.locals = copy.copy(ctx.locals)
                    if location and os.path.isfile(location):
                        inner.locals.__dict__.update(
                            current_launch_file_path=location,
                            current_launch_file_directory=os.path.dirname(os.path.abspath(location)),
                        )
                    walk(list(getattr(ld, "entities", [])), inner)
                    continue
                try:
                    subs = e.get_sub_entities()
                except Exception:
                    subs = []
                walk(subs, ctx)

        walk(self.entities, context if context is not None else LaunchContext())
        return found

"""launch.actions: the actions Gazebo-style launch files use."""

from __future__ import annotations

import copy
import os
from collections.abc import Callable, Iterable
from typing import Any

from ..action import Action
from ..conditions import evaluate_condition_expression
from ..events import Shutdown as ShutdownEvent
from ..launch_context import LaunchContext
from ..launch_description import LaunchDescription
from ..launch_description_sources import AnyLaunchDescriptionSource, LaunchDescriptionSource
from ..logging import log
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .execute_process import ExecuteProcess


class DeclareLaunchArgument(Action):
    """A launch argument with its default, description and choices."""

    def __init__(
        self,
        name: str,
        *,
        default_value: Any = None,
        description: str | None = None,
        choices: Iterable[str] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.name = name
        self.default_value = None if default_value is None else normalize_to_list_of_substitutions(default_value)
        self.description = description or "no description given"
        self.choices = list(choices) if choices is not None else None

    def default_text(self, context: LaunchContext | None = None) -> str | None:
        if self.default_value is None:
            return None
        try:
            return perform_substitutions(context or LaunchContext(), self.default_value)
        except Exception:
            return "".join(s.describe() for s in self.default_value)

    def execute(self, context: LaunchContext) -> None:
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                raise LaunchArgumentError(
                    f"Required launch argument '{self.name}' (description: '{self.description}') was not provided"
                )
            context.launch_configurations[self.name] = perform_substitutions(context, self.default_value)
        value = context.launch_configurations[self.name]
        if self.choices is not None and value not in self.choices:
            raise LaunchArgumentError(
                f"Argument '{self.name}' provided value '{value}' is not valid. Valid options are: {self.choices}"
            )
        return None

    def launch_arguments_walk(self, context: LaunchContext, found: list[Any]) -> tuple[list[Any], LaunchContext]:
        """Listed once (the first declaration of a name); its default counts for what comes after it."""
        if all(d.name != self.name for d in found):
            found.append(self)
        default = self.default_text(context)
        if default is not None:
            context.launch_configurations.setdefault(self.name, default)
        return [], context


class LaunchArgumentError(RuntimeError):
    """A launch argument missing or outside its choices."""


class SetLaunchConfiguration(Action):
    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform_substitutions(context, self.name)] = perform_substitutions(
            context, self.value
        )


class UnsetLaunchConfiguration(Action):
    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.pop(perform_substitutions(context, self.name), None)


class _PushScope(Action):
    def __init__(self, configs: bool = True, env: bool = False, locals_: bool = False) -> None:
        super().__init__()
        self.configs, self.env, self.locals_ = configs, env, locals_

    def execute(self, context: LaunchContext) -> None:
        if self.configs:
            context._push_launch_configurations()
        if self.env:
            context._push_environment()
        if self.locals_:
            context._push_locals()


class _PopScope(_PushScope):
    def execute(self, context: LaunchContext) -> None:
        if self.locals_:
            context._pop_locals()
        if self.env:
            context._pop_environment()
        if self.configs:
            context._pop_launch_configurations()


class _SetLocals(Action):
    def __init__(self, values: dict[str, Any]) -> None:
        super().__init__()
        self.values = values

    def execute(self, context: LaunchContext) -> None:
        context.extend_locals(self.values)


class IncludeLaunchDescription(Action):
    """Another launch file (or LaunchDescription) with ``launch_arguments``; the configurations it sets stay set
    after it, as in ROS 2's launch (a GroupAction scopes them)."""

    def __init__(self, launch_description_source: Any, *, launch_arguments: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if isinstance(launch_description_source, LaunchDescription):
            launch_description_source = LaunchDescriptionSource(launch_description_source)
        elif isinstance(launch_description_source, (str, list)) or hasattr(launch_description_source, "perform"):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.launch_description_source = launch_description_source
        items = launch_arguments.items() if isinstance(launch_arguments, dict) else (launch_arguments or [])
        self.launch_arguments = [
            (normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v)) for k, v in items
        ]

    def get_sub_entities(self) -> list[Any]:
        ld = self.launch_description_source.try_get_launch_description_without_context()
        return [ld] if ld is not None else []

    def launch_arguments_walk(self, context: LaunchContext, found: list[Any]) -> tuple[list[Any], LaunchContext]:
        """The included file's entities, read in a copy of the context (its configurations and the file's own
        path stay inside); nothing where the path needs values only known at run time."""
        try:
            ld = self.launch_description_source.get_launch_description(context)
        except Exception:
            return [], context
        inner = copy.copy(context)
        inner.launch_configurations = dict(context.launch_configurations)
        inner.locals = copy.copy(context.locals)
        location = getattr(self.launch_description_source, "location", "")
        if location and os.path.isfile(location):
            inner.locals.__dict__.update(
                current_launch_file_path=location,
                current_launch_file_directory=os.path.dirname(os.path.abspath(location)),
            )
        return list(getattr(ld, "entities", [])), inner

    def execute(self, context: LaunchContext) -> list[Any]:
        ld = self.launch_description_source.get_launch_description(context)
        location = getattr(self.launch_description_source, "location", "")
        args = [
            (perform_substitutions(context, k), perform_substitutions(context, v)) for k, v in self.launch_arguments
        ]
        local_values = {}
        if location and os.path.isfile(location):
            local_values = {
                "current_launch_file_path": location,
                "current_launch_file_directory": os.path.dirname(os.path.abspath(location)),
            }
        # Jazzy's IncludeLaunchDescription.execute returns the arguments' SetLaunchConfiguration actions and the
        # description with no push or pop of the configurations: what the included file sets stays set after it
        # (ur_moveit.launch.py's move_group, started by an event handler, reads them); only GroupAction scopes.
        # The file's own path (current_launch_file_path/_directory) stays inside it.
        return [
            *(SetLaunchConfiguration(k, v) for k, v in args),
            _PushScope(configs=False, locals_=True),
            _SetLocals(local_values),
            ld,
            _PopScope(configs=False, locals_=True),
        ]


class GroupAction(Action):
    """Actions in a scope: launch configurations (and ROS namespace, parameters, remaps) set inside
    stay inside when ``scoped`` (default); ``forwarding`` passes the outer ones in."""

    def __init__(
        self,
        actions: Iterable[Any],
        *,
        scoped: bool = True,
        forwarding: bool = True,
        launch_configurations: dict[Any, Any] | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped = scoped
        self.forwarding = forwarding
        self.launch_configurations = launch_configurations or {}

    def get_sub_entities(self) -> list[Any]:
        return list(self.actions)

    def execute(self, context: LaunchContext) -> list[Any]:
        sets = [SetLaunchConfiguration(k, v) for k, v in self.launch_configurations.items()]
        if not self.scoped:
            return [*sets, *self.actions]
        out: list[Any] = [_PushScope(configs=True, env=True, locals_=True)]
        if not self.forwarding:
            out.append(_ClearConfigurations())
        return [*out, *sets, *self.actions, _PopScope(configs=True, env=True, locals_=True)]


class _ClearConfigurations(Action):
    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.clear()


class OpaqueFunction(Action):
    """A Python function called with the context; the actions it returns run next."""

    def __init__(
        self, *, function: Callable[..., Any], args: Iterable[Any] | None = None, kwargs: Any = None, **kw: Any
    ) -> None:
        super().__init__(**kw)
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})

    def execute(self, context: LaunchContext) -> list[Any] | None:
        result = self.function(context, *self.args, **self.kwargs)
        if result is None:
            return None
        return list(result)


class SetEnvironmentVariable(Action):
    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.environment[perform_substitutions(context, self.name)] = perform_substitutions(context, self.value)


class AppendEnvironmentVariable(Action):
    def __init__(
        self, name: Any, value: Any, *, prepend: Any = False, separator: Any = os.pathsep, **kwargs: Any
    ) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)
        self.prepend = prepend
        self.separator = normalize_to_list_of_substitutions(separator)

    def execute(self, context: LaunchContext) -> None:
        name = perform_substitutions(context, self.name)
        value = perform_substitutions(context, self.value)
        sep = perform_substitutions(context, self.separator)
        prepend = self.prepend
        if not isinstance(prepend, bool):
            prepend = evaluate_condition_expression(context, normalize_to_list_of_substitutions(prepend))
        old = context.environment.get(name, "")
        context.environment[name] = value if not old else (f"{value}{sep}{old}" if prepend else f"{old}{sep}{value}")


class UnsetEnvironmentVariable(Action):
    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.environment.pop(perform_substitutions(context, self.name), None)


class LogInfo(Action):
    """``[INFO] [launch.user]: <msg>``."""

    def __init__(self, *, msg: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.msg = normalize_to_list_of_substitutions(msg)

    def execute(self, context: LaunchContext) -> None:
        log("INFO", "launch.user", perform_substitutions(context, self.msg))


class TimerAction(Action):
    """Its actions run ``period`` seconds (wall time) later."""

    def __init__(self, *, period: Any, actions: Iterable[Any], cancel_on_shutdown: bool = True, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.period = period if isinstance(period, (int, float)) else normalize_to_list_of_substitutions(period)
        self.actions = list(actions)
        self.cancel_on_shutdown = cancel_on_shutdown

    def get_sub_entities(self) -> list[Any]:
        return list(self.actions)

    def execute(self, context: LaunchContext) -> None:
        period = (
            self.period if isinstance(self.period, (int, float)) else float(perform_substitutions(context, self.period))
        )
        context.service.schedule(float(period), self.actions)


class RegisterEventHandler(Action):
    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def get_sub_entities(self) -> list[Any]:
        on = getattr(self.event_handler, "_on", None) or getattr(self.event_handler, "entities", None)
        if isinstance(on, (list, tuple)):
            return [e for e in on if hasattr(e, "visit")]
        return [on] if on is not None and hasattr(on, "visit") else []

    def execute(self, context: LaunchContext) -> None:
        context.service.register_event_handler(self.event_handler)


class UnregisterEventHandler(Action):
    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        context.service.unregister_event_handler(self.event_handler)


class EmitEvent(Action):
    def __init__(self, *, event: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        context.service.emit_event(self.event)


class Shutdown(EmitEvent):
    """Stop the whole launch (``reason`` is logged)."""

    def __init__(self, *, reason: str = "reason not given", **kwargs: Any) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)


ExecuteLocal = ExecuteProcess


def _unsupported(name: str) -> type:
    def init(self: Any, *args: Any, **kwargs: Any) -> None:
        raise NotImplementedError(f"launch.actions.{name} is not supported by gazelle's launch yet")

    return type(name, (Action,), {"__init__": init})


ResetLaunchConfigurations = _unsupported("ResetLaunchConfigurations")
ForEach = _unsupported("ForEach")
ResetEnvironment = _unsupported("ResetEnvironment")

__all__ = [
    "AppendEnvironmentVariable",
    "DeclareLaunchArgument",
    "EmitEvent",
    "ExecuteLocal",
    "ExecuteProcess",
    "ForEach",
    "GroupAction",
    "IncludeLaunchDescription",
    "LaunchArgumentError",
    "LogInfo",
    "OpaqueFunction",
    "RegisterEventHandler",
    "ResetEnvironment",
    "ResetLaunchConfigurations",
    "SetEnvironmentVariable",
    "SetLaunchConfiguration",
    "Shutdown",
    "TimerAction",
    "UnregisterEventHandler",
    "UnsetEnvironmentVariable",
    "UnsetLaunchConfiguration",
]

"""The context a launch description is visited in: launch configurations, environment, locals."""

from __future__ import annotations

import os
from typing import Any


class LaunchContext:
    """What substitutions and actions read and change while the launch runs (launch.LaunchContext)."""

    def __init__(self, argv: list[str] | None = None, noninteractive: bool = False) -> None:
        self.argv = list(argv or [])
        self.noninteractive = noninteractive
        self.launch_configurations: dict[str, str] = {}
        self._config_stack: list[dict[str, str]] = []
        self._env_stack: list[dict[str, str]] = []
        self.environment: dict[str, str] = dict(os.environ)
        self.locals = _Locals()
        self._locals_stack: list[dict[str, Any]] = []
        self.is_shutdown = False
        self.service: Any = None
        """The LaunchService running this context (processes, events, timers)."""

    # scopes (GroupAction with scoped=True, IncludeLaunchDescription)
    def _push_launch_configurations(self) -> None:
        self._config_stack.append(dict(self.launch_configurations))

    def _pop_launch_configurations(self) -> None:
        self.launch_configurations = self._config_stack.pop()

    def _push_environment(self) -> None:
        self._env_stack.append(dict(self.environment))

    def _pop_environment(self) -> None:
        self.environment = self._env_stack.pop()

    def _push_locals(self) -> None:
        self._locals_stack.append(dict(self.locals.__dict__))

    def _pop_locals(self) -> None:
        self.locals.__dict__.clear()
        self.locals.__dict__.update(self._locals_stack.pop())

    def extend_locals(self, values: dict[str, Any]) -> None:
        self.locals.__dict__.update(values)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self.locals.__dict__)

    def emit_event_sync(self, event: Any) -> None:
        if self.service is not None:
            self.service.emit_event(event)

    def emit_event(self, event: Any) -> None:
        self.emit_event_sync(event)

    def perform_substitution(self, substitution: Any) -> str:
        return substitution.perform(self)


class _Locals:
    """Attribute bag (``context.locals.launch_file_path``...)."""

    def __getattr__(self, name: str) -> Any:
        raise AttributeError(f"context.locals has no '{name}'")

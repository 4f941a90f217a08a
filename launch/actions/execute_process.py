"""ExecuteProcess: run a program, its output prefixed ``[name-N]`` as ros2 launch does."""

from __future__ import annotations

import os
import re
import shlex
from typing import Any

from ..action import Action
from ..conditions import evaluate_condition_expression
from ..launch_context import LaunchContext
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions


class ExecuteProcess(Action):
    """A process of the launch. ``on_exit`` actions run when it exits; ``respawn`` restarts it."""

    def __init__(
        self,
        *,
        cmd: Any,
        name: Any = None,
        cwd: Any = None,
        env: dict[Any, Any] | None = None,
        additional_env: dict[Any, Any] | None = None,
        shell: bool = False,
        sigterm_timeout: Any = 5,
        sigkill_timeout: Any = 5,
        emulate_tty: bool = False,
        prefix: Any = None,
        output: Any = "log",
        output_format: str = "[{this.process_description.final_name}] {line}",
        cached_output: bool = False,
        log_cmd: bool = False,
        on_exit: Any = None,
        respawn: Any = False,
        respawn_delay: float | None = None,
        respawn_max_retries: int = -1,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        if isinstance(cmd, str):
            cmd = [cmd]
        self.cmd = [normalize_to_list_of_substitutions(c) for c in cmd]
        self.name = None if name is None else normalize_to_list_of_substitutions(name)
        self.cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.env = env
        self.additional_env = additional_env or {}
        self.shell = shell
        self.prefix = None if prefix is None else normalize_to_list_of_substitutions(prefix)
        self.output = output
        self.log_cmd = log_cmd
        self.on_exit = on_exit
        self.respawn = respawn
        self.respawn_delay = respawn_delay or 0.0
        self.respawn_max_retries = respawn_max_retries
        self.final_name = ""
        self.final_cmd: list[str] = []

    def _env(self, context: LaunchContext) -> dict[str, str]:
        if self.env is not None:
            env = {
                perform_substitutions(context, normalize_to_list_of_substitutions(k)): perform_substitutions(
                    context, normalize_to_list_of_substitutions(v)
                )
                for k, v in self.env.items()
            }
        else:
            env = dict(context.environment)
        for k, v in self.additional_env.items():
            env[perform_substitutions(context, normalize_to_list_of_substitutions(k))] = perform_substitutions(
                context, normalize_to_list_of_substitutions(v)
            )
        return env

    def _prefixed(self, context: LaunchContext, cmd: list[str]) -> list[str]:
        """``cmd`` behind its prefix: the one given, else the ``launch-prefix`` launch configuration (what
        ``ros2 launch --launch-prefix`` sets) when ``launch-prefix-filter`` (a regex, empty by default)
        matches the executable's file name, as launch's ``Executable`` does (launch/descriptions/executable.py,
        Jazzy); a prefix given to the action applies whatever the filter."""
        if self.prefix is not None:
            return shlex.split(perform_substitutions(context, self.prefix)) + cmd
        configured = context.launch_configurations.get("launch-prefix", "")
        if not configured or not cmd:
            return cmd
        pattern = context.launch_configurations.get("launch-prefix-filter", "")
        if re.match(pattern, os.path.basename(cmd[0])) is None:
            return cmd
        return shlex.split(configured) + cmd

    def _command(self, context: LaunchContext) -> list[str]:
        """The command line (a Node builds its own)."""
        return [perform_substitutions(context, c) for c in self.cmd]

    def execute(self, context: LaunchContext) -> None:
        cmd = self._command(context)
        cmd = self._prefixed(context, cmd)
        if not cmd or not cmd[0]:
            raise RuntimeError("ExecuteProcess: the command is empty")
        base = perform_substitutions(context, self.name) if self.name is not None else os.path.basename(cmd[0])
        self.final_cmd = cmd
        cwd = perform_substitutions(context, self.cwd) if self.cwd is not None else None
        respawn = self.respawn
        if not isinstance(respawn, bool):
            respawn = evaluate_condition_expression(context, normalize_to_list_of_substitutions(respawn))
        context.service.start_process(self, base, cmd, cwd, self._env(context), respawn)
        return None

    def get_sub_entities(self) -> list[Any]:
        on = self.on_exit
        if isinstance(on, (list, tuple)):
            return [e for e in on if hasattr(e, "visit")]
        return []

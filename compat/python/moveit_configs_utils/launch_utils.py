"""Launch helpers of moveit_configs_utils: a boolean launch argument and a node that can be started under gdb."""

from __future__ import annotations

from typing import Any

from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

_BOOLEANS = ["true", "false", "True", "False"]


class DeclareBooleanLaunchArg(DeclareLaunchArgument):
    """A launch argument whose only values are true and false (either capitalisation)."""

    def __init__(self, name: str, *, default_value: bool = False, description: str | None = None, **kwargs: Any):
        super().__init__(name, default_value=str(default_value), description=description, choices=_BOOLEANS, **kwargs)


def add_debuggable_node(
    ld: Any,
    package: str,
    executable: str,
    condition_name: str = "debug",
    commands_file: str | None = None,
    extra_debug_args: list[str] | None = None,
    **kwargs: Any,
) -> None:
    """Add the node to ``ld`` twice: as it is, unless the launch argument ``condition_name`` is true, and under
    ``gdb`` (with ``commands_file`` and ``extra_debug_args``) when it is."""
    ld.add_action(
        Node(
            package=package,
            executable=executable,
            condition=UnlessCondition(LaunchConfiguration(condition_name)),
            **kwargs,
        )
    )
    commands = f"-x {commands_file} " if commands_file else ""
    arguments = kwargs.pop("arguments", None)
    if arguments is not None and extra_debug_args:
        arguments = [*arguments, *extra_debug_args]
    ld.add_action(
        Node(
            package=package,
            executable=executable,
            condition=IfCondition(LaunchConfiguration(condition_name)),
            prefix=[f"gdb {commands}--ex run --args"],
            arguments=arguments,
            **kwargs,
        )
    )

"""The keyword arguments of a :class:`~._robot_scene.RobotScene` (whose signature holds their defaults and says what
each means), as an :class:`~._planner.ArmPlanner` takes them and hands them on to the scene it owns: written once."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TypedDict


class RobotOptions(TypedDict, total=False):
    """How a robot's scene is made beyond its URDF and SRDF (see :class:`~._robot_scene.RobotScene`)."""

    srdf_source: str
    resolve_mesh: Callable[[str], str | None] | None
    joint_limits: Mapping[str, Mapping[str, float]] | None
    seed: int

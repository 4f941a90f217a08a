"""launch_ros.descriptions (Jazzy): where bring-ups import parameter descriptions from (nav2_bringup's
``from launch_ros.descriptions import ParameterFile``); the same classes as launch_ros.parameter_descriptions."""

from __future__ import annotations

from typing import Any

from ..parameter_descriptions import Parameter, ParameterFile, ParameterValue


class ComposableNode:
    """A node to load into a component container: not supported by gazelle's launch yet (nor are containers)."""

    def __init__(self, **kwargs: Any) -> None:
        raise NotImplementedError("launch_ros.descriptions.ComposableNode is not supported by gazelle's launch yet")


__all__ = ["ComposableNode", "Parameter", "ParameterFile", "ParameterValue"]

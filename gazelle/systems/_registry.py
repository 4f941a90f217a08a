"""Maps plugin file names and class names to system implementations."""

from __future__ import annotations

import logging
import re
from typing import Callable

from ..description import Plugin
from ._base import System

_log = logging.getLogger("gazelle.systems")


def _normalise(filename: str) -> str:
    """``libgazebo_ros_diff_drive.so`` -> ``gazebo_ros_diff_drive``; keeps gz names."""
    name = filename.strip()
    name = re.sub(r"^lib", "", name)
    name = re.sub(r"\.(so|dylib|dll)$", "", name)
    return name


def _diff_drive() -> System:
    from .diff_drive import DiffDrive

    return DiffDrive()


def _classic_joint_states() -> System:
    from .robot_state import JointStatePublisher

    return JointStatePublisher(all_by_default=False)


def _gz_joint_states() -> System:
    from .robot_state import JointStatePublisher

    return JointStatePublisher(all_by_default=True)


def _gz_diff_drive() -> System:
    from .gz_diff_drive import GzDiffDrive

    return GzDiffDrive()


def _gz_joint_position() -> System:
    from .joint_controllers import JointPositionController

    return JointPositionController()


def _gz_joint_velocity() -> System:
    from .joint_controllers import JointController

    return JointController()


def _joint_commands() -> System:
    from .joint_controllers import JointCommands

    return JointCommands()


def _p3d() -> System:
    from .pose_publisher import P3D

    return P3D()


_REGISTRY: dict[str, Callable[[], System]] = {
    "gazebo_ros_diff_drive": _diff_drive,
    "gazebo_ros_joint_state_publisher": _classic_joint_states,
    "gz-sim-joint-state-publisher-system": _gz_joint_states,
    "gz::sim::systems::JointStatePublisher": _gz_joint_states,
    "ignition-gazebo-joint-state-publisher-system": _gz_joint_states,
    "ignition::gazebo::systems::JointStatePublisher": _gz_joint_states,
    "gz-sim-diff-drive-system": _gz_diff_drive,
    "gz::sim::systems::DiffDrive": _gz_diff_drive,
    "ignition-gazebo-diff-drive-system": _gz_diff_drive,
    "ignition::gazebo::systems::DiffDrive": _gz_diff_drive,
    "gz-sim-joint-position-controller-system": _gz_joint_position,
    "gz::sim::systems::JointPositionController": _gz_joint_position,
    "ignition-gazebo-joint-position-controller-system": _gz_joint_position,
    "ignition::gazebo::systems::JointPositionController": _gz_joint_position,
    "gz-sim-joint-controller-system": _gz_joint_velocity,
    "gz::sim::systems::JointController": _gz_joint_velocity,
    "ignition-gazebo-joint-controller-system": _gz_joint_velocity,
    "ignition::gazebo::systems::JointController": _gz_joint_velocity,
    "gazelle_joint_commands": _joint_commands,
    "gazebo_ros_p3d": _p3d,
}


def supported_plugins() -> list[str]:
    """Plugin file names (normalised) with an implementation."""
    return sorted(_REGISTRY)


def create_system(plugin: Plugin) -> System | None:
    """A new system for ``plugin``, or None (with a warning naming it) if unsupported."""
    factory = _REGISTRY.get(_normalise(plugin.filename)) or _REGISTRY.get(_normalise(plugin.name))
    if factory is None:
        where = f"{plugin.location}: " if plugin.location else ""
        _log.warning(f"{where}plugin '{plugin.name}' ({plugin.filename}) is not supported; it is ignored")
        return None
    return factory()

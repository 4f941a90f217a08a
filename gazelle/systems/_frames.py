"""The frame names an entity's systems publish under: the built-in robot_state_publisher's settings (its
``<frame_prefix>``, its namespace) and the prefix they give every TF frame of the entity (``r1/base_link``).

A ground-floor module of ``gazelle.systems``: the drives, the pose publishers and the sensors name their frames
with :func:`entity_frame_prefix` and import it from here, beside the robot_state_publisher, not from it."""

from __future__ import annotations

import logging
from dataclasses import dataclass

from ..description import Plugin
from ..physics import Entity
from ._plugin_config import child_text, parse_bool, parse_float, ros_block
from ._plugin_names import RSP_PLUGIN


def default_frame_prefix(namespace: str) -> str:
    """``r1/`` for namespace ``/r1`` (so two robots never publish the same frame); '' without one."""
    ns = namespace.strip("/")
    return f"{ns}/" if ns else ""


@dataclass(frozen=True)
class RobotStateConfig:
    """Parameters of the built-in robot_state_publisher (``<plugin filename="gazelle_robot_state_publisher">``)."""

    enabled: bool = True
    """``<enabled>``: false when you run your own robot_state_publisher (nothing is published twice)."""
    publish_frequency: float = 50.0
    """``<publish_frequency>``, Hz of sim time, for /tf of the moving joints. Default 50."""
    frame_prefix: str | None = None
    """``<frame_prefix>``: prepended to every frame; default: the namespace plus '/', or nothing."""
    namespace: str = ""
    """``<ros><namespace>``; default: the entity's namespace."""


def robot_state_config(entity: Entity, log: logging.Logger) -> tuple[RobotStateConfig, Plugin | None]:
    """The configuration from the model's own ``gazelle_robot_state_publisher`` plugin block, if any.

    Gazebo runs no robot_state_publisher: a ROS user starts one from a launch file. gazelle runs one per
    spawned robot so that a bare ``gazelle sim robot.urdf`` has /tf and /robot_description; this plugin
    block is the way a model file turns it off (``<enabled>false</enabled>``, when the user's launch file
    starts its own) or sets its rate and frame prefix. Without it: on, 50 Hz, the namespace as the prefix."""
    plugin = next((p for p in entity.model.plugins if p.filename == RSP_PLUGIN), None)
    if plugin is None:
        return RobotStateConfig(namespace=entity.namespace), None
    cfg = plugin.config
    ns, _ = ros_block(cfg)
    prefix = child_text(cfg, "frame_prefix")
    return (
        RobotStateConfig(
            enabled=parse_bool(cfg, "enabled", True, log),
            publish_frequency=parse_float(cfg, "publish_frequency", 50.0, log),
            frame_prefix=prefix,
            namespace=ns or entity.namespace,
        ),
        plugin,
    )


def entity_frame_prefix(entity: Entity, log: logging.Logger) -> str:
    """The prefix of every TF frame of an entity: its RSP ``frame_prefix``, else ``<namespace>/``."""
    config, _ = robot_state_config(entity, log)
    return config.frame_prefix if config.frame_prefix is not None else default_frame_prefix(config.namespace)

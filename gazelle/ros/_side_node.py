"""A node beside another, for entities that must not wait in the other node's executor."""

from __future__ import annotations

import rclpy
from rclpy.node import Node


def side_node(owner: Node, suffix: str) -> Node:
    """``<owner's name>_<suffix>`` in the owner's namespace and context, without parameter services and
    without the context's global arguments (a ``-r __node:=name`` given to the process would otherwise
    name it as the owner). Names for its entities come from ``owner.resolve_*_name`` (its remappings)."""
    return rclpy.create_node(
        f"{owner.get_name()}_{suffix}",
        namespace=owner.get_namespace(),
        context=owner.context,
        use_global_arguments=False,
        start_parameter_services=False,
    )

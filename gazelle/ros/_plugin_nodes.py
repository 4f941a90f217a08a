"""gazebo_ros plugins as ROS nodes of their own, as in Gazebo Classic (``/differential_drive``).

A node exists while anything of its plugin does: the topics the plugin declared (their publishers and
subscriptions are the node's, so ``ros2 topic info -v`` and ``ros2 node info`` name it) and its
:class:`~gazelle.systems.PluginNode` announcement, whose configuration becomes the node's parameters.
Parameters are read-only (rclpy then refuses a set with "Trying to set a read-only parameter") except
those the plugin's system has a setter for; a setter runs on the simulation thread.

The nodes have no ``/rosout`` publisher and keep ``use_sim_time`` false (each would otherwise take
every /clock message), and no ``~/get_type_description`` service (see :data:`NO_TYPE_DESCRIPTION_SERVICE`); they
are added to the bridge's executor.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.context import Context
from rclpy.node import Node
from rclpy.parameter import Parameter

from ..sim import Simulation
from ..systems import PluginNode

NO_TYPE_DESCRIPTION_SERVICE = (Parameter("start_type_description_service", value=False),)
"""A plugin node is made without rclpy's ``~/get_type_description`` service (Jazzy's rclpy starts one in every
node unless this parameter says no): ~100 KiB of native memory stay for each node made with it after the node is
destroyed, while another node (the server's) lives in the context (measured: 100.8 KiB a node over 800 nodes,
linear, not given back by ``malloc_trim``; 0.6 KiB without the service; tests/ros/test_plugin_node_memory.py),
so a robot with a gazebo_ros plugin spawned and deleted 100 times grew the server by 10.5 MiB. The service
describes message types a client does not have; a plugin node's topics are standard messages (the ``gazelle``
node keeps its service)."""


class PluginNodes:
    """The plugin nodes of one bridge, reference-counted by fully qualified name."""

    def __init__(self, sim: Simulation, context: Context, add: Callable[[Node], None], remove: Callable[[Node], None]):
        """The ROS nodes of gazebo_ros plugins (``/differential_drive``, a camera's node), made and removed as the
        bus declares them; ``add``/``remove`` put them on and take them off the bridge's executor."""
        self.sim = sim
        self.context = context
        self._add, self._remove = add, remove
        self._lock = threading.Lock()
        self._nodes: dict[str, tuple[Node, int]] = {}

    def acquire(self, fqn: str) -> Node:
        """The node named ``fqn`` (made on first use); pair with :meth:`release`."""
        with self._lock:
            entry = self._nodes.get(fqn)
            if entry is not None:
                self._nodes[fqn] = (entry[0], entry[1] + 1)
                return entry[0]
            namespace, _, name = fqn.rpartition("/")
            node = Node(
                name,
                namespace=namespace or "/",
                context=self.context,
                enable_rosout=False,
                parameter_overrides=list(NO_TYPE_DESCRIPTION_SERVICE),
            )
            self._nodes[fqn] = (node, 1)
        self._add(node)
        return node

    def release(self, fqn: str) -> None:
        """One user fewer; the node goes with its last."""
        with self._lock:
            entry = self._nodes.get(fqn)
            if entry is None:
                return
            node, users = entry
            if users > 1:
                self._nodes[fqn] = (node, users - 1)
                return
            del self._nodes[fqn]
        self._remove(node)
        node.destroy_node()

    def declare(self, plugin: PluginNode) -> None:
        """Give the plugin's node its parameters (read-only unless settable)."""
        node = self.acquire(plugin.fully_qualified_name)
        for name, value in plugin.parameters.items():
            if node.has_parameter(name) or (isinstance(value, list) and not value):
                continue
            read_only = name not in plugin.settable
            node.declare_parameter(
                name,
                value,
                ParameterDescriptor(
                    name=name,
                    read_only=read_only,
                    description=f"<{name}> of {plugin.plugin}"
                    + (" (read-only: set from the plugin's SDF at load time)" if read_only else ""),
                ),
            )
        if plugin.settable:
            node.add_on_set_parameters_callback(lambda params: self._set(plugin, params))

    def _set(self, plugin: PluginNode, params: list[Any]) -> SetParametersResult:
        """``ros2 param set`` on a plugin node: each settable parameter is applied on the simulation thread by the
        system's setter; the first refusal (its reason) fails the whole request, as rclpy's callbacks do."""
        for p in params:
            setter = plugin.settable.get(p.name)
            if setter is None:
                continue  # read-only ones never get here; use_sim_time and the like: rclpy's own
            value = p.value
            try:
                why = self.sim.call(lambda setter=setter, value=value: setter(value))
            except Exception as err:  # the simulation is stopping, or the setter raised
                why = f"{type(err).__name__}: {err}"
            if why:
                return SetParametersResult(successful=False, reason=f"{p.name}: {why}")
        return SetParametersResult(successful=True)

    def undeclare(self, plugin: PluginNode) -> None:
        """The plugin went (its entity was deleted)."""
        self.release(plugin.fully_qualified_name)

    def destroy_all(self) -> None:
        """At shutdown."""
        with self._lock:
            nodes = [n for n, _ in self._nodes.values()]
            self._nodes.clear()
        for node in nodes:
            node.destroy_node()

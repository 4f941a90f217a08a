"""What every part of simulation_interfaces uses (:class:`InterfacesContext`), as MoveIt's ``MoveGroupContext`` is
for move_group's capabilities: the node the services are registered on, the simulation they serve, the resolver of
``model://`` and ``package://`` URIs, the callback group, and the two things of the bridge's node a part needs
(/clock published at once, the subscriptions' messages handed to the simulation before a requested step). Made by
:class:`~._simulation_interfaces.SimulationInterfaces` and handed to each part, which registers its own services
with :meth:`InterfacesContext.serve` and names nothing that builds it."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node

from ..description import ResourceResolver
from ..sim import Simulation
from ._replies import Req, Res, ServiceCallback, ServiceType, guarded_service, serve

if TYPE_CHECKING:
    from rclpy.impl.rcutils_logger import RcutilsLogger
    from rclpy.service import Service


class InterfacesContext:
    """The shared state of the simulation_interfaces parts (see the module docstring)."""

    def __init__(
        self,
        node: Node,
        sim: Simulation,
        resolver: ResourceResolver,
        publish_clock: Callable[[float], None],
        take_inbound: Callable[[], int],
    ) -> None:
        self.node = node
        """The ``gazelle`` node: every service is its ``~/<name>``; its logger is the parts' logger."""
        self.sim = sim
        self.resolver = resolver
        """How a spawn's or a load's ``uri`` is found (and what it may read)."""
        self.cb = ReentrantCallbackGroup()
        """Every service and the action are in it: requests are served side by side."""
        self.services: list[Service] = []
        """Every service the parts registered (:meth:`destroy` removes them)."""
        self.publish_clock = publish_clock
        """/clock, at once (a load or a reset starts the clock again: nodes on sim time hear it now)."""
        self.take_inbound = take_inbound
        """Hand the simulation the messages its subscriptions hold now (before a requested step)."""

    def serve(self, srv_type: ServiceType[Req, Res], name: str, fn: ServiceCallback[Req, Res]) -> None:
        """Register ``fn`` as the node's ``~/<name>`` service, guarded (bad input gets a result code and a message,
        never a dead server), in the shared callback group."""
        self.services.append(serve(self.node, srv_type, f"~/{name}", guarded_service(name, fn), self.cb))

    @property
    def logger(self) -> RcutilsLogger:
        return self.node.get_logger()

    def destroy(self) -> None:
        """Remove every registered service (the node is being destroyed)."""
        for service in self.services:
            self.node.destroy_service(service)
        self.services.clear()

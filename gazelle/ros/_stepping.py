"""StepSimulation's own node and executor (see :class:`SteppingService`)."""

from __future__ import annotations

import logging
import threading
from collections.abc import Callable
from typing import Any

from rclpy.exceptions import InvalidHandle
from rclpy.executors import ExternalShutdownException, ShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from simulation_interfaces.srv import StepSimulation

from ._replies import serve
from ._side_node import side_node


class SteppingService:
    """StepSimulation on a node and a single-threaded executor of its own, under the simulation node's name
    (``~/step_simulation``).

    A test in lockstep (gazelle.testing) steps 10 ms of sim time a call. On the simulation node, whose
    MultiThreadedExecutor builds its wait set in Python from every service, subscription and plugin node
    of the server each time it wakes, a call took ~7 ms; rclpy measured alone: 1.2 ms a call to a node
    with one service, 5.4 ms with 50 services and 50 subscriptions beside it."""

    def __init__(self, node: Node, handler: Callable[[Any, Any], Any]) -> None:
        self.name = node.resolve_service_name("~/step_simulation")
        self.node = side_node(node, "stepping")
        self.service = serve(self.node, StepSimulation, self.name, handler, None)
        self.executor = SingleThreadedExecutor(context=node.context)
        self.executor.add_node(self.node)
        self._stopping = threading.Event()
        self._thread = threading.Thread(target=self._spin, name="step_simulation", daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        log = logging.getLogger("gazelle.ros")
        while not self._stopping.is_set() and self.node.context.ok():
            try:
                self.executor.spin_once(timeout_sec=0.1)
            except InvalidHandle:
                continue  # destroyed while waited on: the next wait set is built without it
            except (ShutdownException, ExternalShutdownException):
                return
            except Exception:  # the handler's own errors are replies (guarded_service): this is rclpy's
                if self._stopping.is_set() or not self.node.context.ok():
                    return
                log.exception("the step_simulation executor failed; it goes on serving")

    def destroy(self) -> None:
        """Stop the executor, wait for its thread (it may hold the service in its wait set), then the node."""
        self._stopping.set()
        self.executor.shutdown(timeout_sec=2.0)
        self._thread.join(timeout=2.0)
        self.node.destroy_service(self.service)
        self.node.destroy_node()

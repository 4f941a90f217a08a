"""The ROS node of one loaded ros2_control controller: named as the controller in its manager's namespace, holding
the controller's parameters (see ``systems/ros2_control/_controller_parameters.py`` for which and what setting one
does). ``ros2 param get /diff_drive_controller wheel_separation`` reads it; ``ros2 param set`` sets it where
ros2_control allows it, and a refusal is the reply's one-line reason.

Like ros2_control's (controller_interface_base.cpp: the LifecycleNode is made with its lifecycle services disabled),
it serves parameters only: the manager drives the controller's lifecycle (``ros2 control``, the spawner). It serves
nothing of the controller's topics or actions, which the bridge's and the manager's nodes carry.
"""

from __future__ import annotations

import logging
import threading
from typing import TYPE_CHECKING, Any

from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from ..sim import Simulation
from ..systems.ros2_control import ControlError
from ..systems.ros2_control import ControllerParameters as Parameters

if TYPE_CHECKING:
    from rclpy.context import Context

_log = logging.getLogger(__name__)


class ControllerNode(Node):
    """See the module docstring."""

    def __init__(self, sim: Simulation, params: Parameters, context: Context | None) -> None:
        """The node, its parameters declared with the values they have now (call on the thread that loaded the
        controller: the simulation's, between two steps)."""
        super().__init__(params.name, namespace=params.namespace or "/", context=context)
        self.sim = sim
        self.params = params
        self._local = threading.local()
        self._lock = threading.Lock()
        self.declare_current()
        self.add_on_set_parameters_callback(self._on_set)
        params.listener = self.declare_current

    def declare_current(self) -> None:
        """Declare the controller's parameters the node does not have yet (at its creation, and after each configure,
        when the controller has read the ones it reads; the simulation thread). A value no ROS parameter can hold
        (an array of mixed types) is left out."""
        values, read_only = self.params.values(), self.params.read_only()
        with self._lock:
            self._local.declaring = True
            try:
                for name, value in values.items():
                    if self.has_parameter(name):
                        continue
                    descriptor = ParameterDescriptor(dynamic_typing=True, read_only=name in read_only)
                    try:
                        self.declare_parameter(name, value, descriptor)
                    except Exception as err:  # a value rclpy cannot type: not a parameter of this node
                        _log.debug(f"{self.get_name()}: parameter '{name}' left out: {err}")
            finally:
                self._local.declaring = False

    def _on_set(self, params: list[Parameter]) -> SetParametersResult:
        """A set from outside (``ros2 param set``): checked and applied on the simulation thread, all or none; the
        reason of a refusal is the reply's. The node's own declarations pass."""
        if getattr(self._local, "declaring", False):
            return SetParametersResult(successful=True)
        values: dict[str, Any] = {p.name: p.value for p in params}
        try:
            self.sim.call(lambda: self.params.set(values))
        except ControlError as err:
            return SetParametersResult(successful=False, reason=str(err))
        except TimeoutError:
            return SetParametersResult(successful=False, reason="the simulation did not answer in time")
        return SetParametersResult(successful=True)

    def destroy_node(self) -> None:
        """Stop hearing of the controller's parameters, then go."""
        self.params.listener = None
        super().destroy_node()

"""A loaded controller's parameters as its ROS node holds them (issue 50 item 5).

In ros2_control every controller is a lifecycle node named as the controller, in the manager's namespace
(controller_interface_base.cpp ``init``: ``rclcpp_lifecycle::LifecycleNode(controller_name, node_namespace, ...,
false)``, the lifecycle services disabled). Its parameters are those ``init`` declares (``update_rate``, the
manager's rate by default; ``is_async``, false; ``thread_priority``, -100), ``use_sim_time`` (the manager sets it
true under simulation, controller_manager.cpp ``determine_controller_node_options``) and the controller's own,
which ``on_init`` declares with their defaults (generate_parameter_library), each given its value from the
parameter files. Users read and set them there: ``ros2 param get /diff_drive_controller wheel_separation``.

The manager announces one :class:`ControllerParameters` per loaded controller on the bus; the ROS layer makes the
node. Its parameters: the base ones above, every parameter the controller read at its last configure with the
default it read it with (gazelle's controllers read theirs in ``configure``, so an unconfigured one shows what its
files give), and every value the files give. A value set on the node is refused for a parameter upstream declares
``read_only`` (the controller's :attr:`~._controller.Controller.read_only_parameters`), or of another type than the
parameter's; otherwise it is the controller's from then on, read at its next configure as upstream's controllers
read theirs in ``on_configure`` (the JTC reads its tolerances and gains again at once, as its ``update()`` does).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, Protocol

from ._controller import MANAGER_READ_PARAMETERS
from ._hardware import ControlError
from ._params import Params, ParamValue


class _Manager(Protocol):
    """What a controller's parameters read of its manager (``_manager.py``'s ControllerManager)."""

    @property
    def namespace(self) -> str: ...
    @property
    def update_rate(self) -> float: ...
    @property
    def controllers(self) -> Mapping[str, Any]: ...
    @property
    def node_params(self) -> dict[str, Params]: ...
    def controller_params(self, name: str) -> Params: ...


_NOT_THE_NODES = MANAGER_READ_PARAMETERS - {"use_sim_time", "is_async"} | {"node_options_args"}
"""Keys of a controller's section that are the manager's, not parameters of the controller's node."""


class ControllerParameters:
    """See the module docstring. Everything here runs on the simulation thread (the ROS layer calls it through
    ``Simulation.call``), except :attr:`name` and :attr:`namespace`."""

    def __init__(self, manager: _Manager, name: str) -> None:
        self.manager = manager
        self.name = name
        self.namespace = manager.namespace
        self.listener: Callable[[], None] | None = None
        """Called (on the simulation thread) when the controller's parameters were read again: its node declares
        the ones it did not have."""

    def _controller(self) -> Any:
        loaded = self.manager.controllers.get(self.name)
        if loaded is None:
            raise ControlError(f"controller '{self.name}' is not loaded")
        return loaded.controller

    def values(self) -> dict[str, ParamValue]:
        """The node's parameters and their values now."""
        c = self._controller()
        out: dict[str, ParamValue] = dict(c.defaults)
        out.update(update_rate=c.update_rate or self.manager.update_rate, is_async=False, thread_priority=-100)
        out.update({k: v for k, v in self.manager.controller_params(self.name).items() if k not in _NOT_THE_NODES})
        out["use_sim_time"] = True
        return out

    def read_only(self) -> frozenset[str]:
        """The parameters its node refuses to set."""
        return self._controller().read_only_parameters

    def set(self, values: Params) -> None:
        """Set parameters on the node: all or none.

        Raises:
            ControlError: a read-only parameter, one the node does not have, or a value of another type, named.
        """
        c = self._controller()
        have = self.values()
        for key, value in values.items():
            if key == "use_sim_time":
                if value is not True:
                    raise ControlError(f"{self.name}: use_sim_time: a controller runs on the simulation's clock")
                continue
            if key in c.read_only_parameters:
                raise ControlError(f"{self.name}: parameter '{key}' cannot be set: it is read-only")
            if key not in have:
                raise ControlError(f"{self.name}: parameter '{key}' is not declared")
            ref = c.defaults.get(key, have[key])
            if not _same_kind(ref, value):
                raise ControlError(f"{self.name}: parameter '{key}' is {_kind(ref)}; {_kind(value)} cannot be set")
        mine = self.manager.node_params.setdefault(self.name, {})
        for key, value in values.items():
            if key != "use_sim_time":
                ref = c.defaults.get(key, have[key])
                mine[key] = float(value) if isinstance(ref, float) and isinstance(value, int) else value
        c.params = self.manager.controller_params(self.name)
        c.on_parameters_changed()

    def changed(self) -> None:
        """Tell the node that the controller read its parameters again (it was configured)."""
        if self.listener is not None:
            self.listener()


def _kind(value: object) -> str:
    if isinstance(value, bool):
        return "a bool"
    if isinstance(value, int):
        return "an integer"
    if isinstance(value, float):
        return "a double"
    if isinstance(value, str):
        return "a string"
    return "an array" if isinstance(value, list) else type(value).__name__


def _same_kind(have: object, value: object) -> bool:
    """Whether ``value`` may replace ``have``: the same type, or an integer for a double (taken as the double: rclcpp
    refuses ``ros2 param set ... 1`` on a double parameter, which surprises more than it protects), any array for an
    array."""
    if isinstance(have, float) and isinstance(value, int) and not isinstance(value, bool):
        return True
    if isinstance(have, list):
        return isinstance(value, list)
    return type(have) is type(value)

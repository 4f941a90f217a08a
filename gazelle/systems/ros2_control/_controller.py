"""What every ros2_control controller shares: its lifecycle, parameters, interfaces and topics.

The lifecycle is ros2_control Jazzy's, driven by the controller manager (``_manager.py``) as
``ros2 control`` and the spawner ask:

* **load**: the controller is made with its parameters (the YAML's ``<name>.ros__parameters``); state
  ``unconfigured``.
* **configure** (:meth:`Controller.configure`): parameters are read and checked, topics declared; a bad
  parameter raises :class:`~._hardware.ControlError` naming the controller and the parameter, and the
  controller stays unconfigured, as a failed ``on_configure`` leaves it in ros2_control. State
  ``inactive``.
* **activate** (:meth:`Controller.on_activate`): the manager gives it the command interfaces it claims
  (:meth:`Controller.command_interfaces`), which no other active controller may hold, and it takes the
  hardware's current values (a trajectory controller holds where the joints are). State ``active``.
* **update** (:meth:`Controller.update`) every cycle while active, on the simulation thread, at the
  manager's ``update_rate`` (with a lower ``update_rate`` of its own: every ``round(manager's / own)``
  cycles): read ``states``, write the claimed entries of ``commands``. Cycles run in sim time:
  ``period`` is the sim seconds since the controller's last one.
* **deactivate** releases the interfaces (the hardware holds its last command); **cleanup** drops the
  topics and goes back to unconfigured.

A controller never touches MuJoCo or rclpy: it reads and writes interface values by name
(``joint/interface``), and talks through the bus (``~/`` topics are its node's).
"""

from __future__ import annotations

import enum
import functools
import logging
import math
import operator
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any, ClassVar, TypeVar

from ...description import Joint, JointType
from .._bus import Bus, Endpoint, MessageKind, MsgType, Qos, remap_name
from ._hardware import ControlError
from ._params import Params

T = TypeVar("T")

UNCONFIGURED, INACTIVE, ACTIVE, FINALIZED = "unconfigured", "inactive", "active", "finalized"


class GoalState(enum.StrEnum):
    """Where an action goal that a controller runs stands. The controller moves it from PENDING to
    EXECUTING when the goal starts to act, and ends it in one of the other three; the ROS layer answers
    the action client with the matching action_msgs/GoalStatus (succeed, abort or canceled). A string
    enum: it reads as its name in logs and in a checkpoint."""

    PENDING = "pending"
    EXECUTING = "executing"
    SUCCEEDED = "succeeded"
    ABORTED = "aborted"
    CANCELED = "canceled"


"""Lifecycle states, as ros2_control names them in ``list_controllers``."""


def _ignore(_component: Any) -> None:
    """The default of a controller context's component hooks: nobody serves it."""


@dataclass
class ControllerContext:
    """What a controller may use: the bus and where its node is."""

    bus: Bus
    owner: str
    """The entity (its endpoints go with it)."""
    namespace: str
    """The controller manager's namespace; the controller's node is ``<namespace>/<name>``."""
    logger: logging.Logger
    state_names: tuple[str, ...]
    """Every state interface of the hardware (``joint/position``...)."""
    command_names: tuple[str, ...]
    """Every command interface of the hardware."""
    joint_names: tuple[str, ...]
    """The hardware's joints, in the ``<ros2_control>`` block's order."""
    add_component: Callable[[Any], None] = _ignore
    """Announce an interface the ROS layer serves for this controller (an action server)."""
    remove_component: Callable[[Any], None] = _ignore
    description_joints: tuple[str, ...] | None = None
    """The moving (non-fixed) joints of the robot's URDF, the ``robot_description`` a controller gets; None when
    the robot came from SDF (no URDF to parse, as a controller whose description fails to load)."""
    manager_rate: int = 100
    """The controller manager's ``update_rate`` (Hz): a controller without an ``update_rate`` of its own
    updates at it (ros2_control's ``get_update_rate()``)."""
    remaps: tuple[tuple[str, str], ...] = ()
    """Remapping rules of the controller's node (``from``, ``to``), first match wins: the manager's own
    (``<ros><remapping>``), then the spawner's ``--controller-ros-args``, as ros2_control Jazzy gives them."""
    position_limits: dict[str, tuple[float, float]] = field(default_factory=dict)
    """Joint -> its description's position range (URDF ``<limit lower upper>``) for the revolute and prismatic
    joints that have one (:func:`position_limits`): what a trajectory controller clamps its position commands
    to."""


class Controller:
    """Base class of the controllers. The manager drives the lifecycle; each cycle it calls
    :meth:`update` with the hardware's state values and the command values to write."""

    type_name: ClassVar[str] = ""
    """``package/Class`` as in the controller YAML."""
    read_only_parameters: ClassVar[frozenset[str]] = frozenset()
    """Parameters its node refuses to set at run time (``read_only: true`` in the upstream controller's
    generate_parameter_library YAML)."""
    action_type: ClassVar[str] = ""
    """The action the controller serves on ``action_name`` (``control_msgs/action/FollowJointTrajectory``),
    announced with ``ctx.add_component``; the ROS layer serves it by this type. "" for none."""

    def __init__(self, name: str, params: Params, ctx: ControllerContext) -> None:
        """A controller named ``name`` (its node's name: topics go under ``/<name>/``), with its parameters
        from the YAML (``<name>: ros__parameters:`` flattened to dotted keys) and what the manager lends it.
        It starts UNCONFIGURED, as ros2_control's lifecycle does: nothing is read or advertised until
        ``configure``."""
        self.name = name
        self.params = params
        self.ctx = ctx
        self.log = ctx.logger
        self.state = UNCONFIGURED
        self.update_rate = 0
        """Hz; 0: every cycle of the manager."""
        self._endpoints: list[Endpoint] = []
        self._read: set[str] = set()
        """The parameters :meth:`param` was asked for since the last configure (the rest are reported)."""
        self.defaults: dict[str, Any] = {}
        """Each parameter :meth:`param` was asked for, with its default: what the controller's node declares beside
        the values it was given (upstream's nodes declare every parameter of the controller, with its default)."""

    # ------------------------------------------------------------------ parameters
    def param(self, key: str, default: T, kind: type | tuple[type, ...] | None = None) -> T:
        """A parameter, checked against the type of ``default`` (ints accepted for floats).

        Raises:
            ControlError: a value of the wrong type, naming the controller and the parameter.
        """
        self._read.add(key)
        self.defaults.setdefault(key, default)
        if key not in self.params:
            return default
        value = self.params[key]
        want = kind or type(default)
        ok = {
            float: isinstance(value, (int, float)) and not isinstance(value, bool),
            int: isinstance(value, int) and not isinstance(value, bool),
            bool: isinstance(value, bool),
            str: isinstance(value, str),
            list: isinstance(value, list),
        }.get(want, isinstance(value, want))
        if not ok:
            raise ControlError(f"controller '{self.name}': parameter '{key}' is {value!r}, expected {_type_name(want)}")
        return float(value) if want is float else value  # type: ignore[return-value] - the value was checked against the default's type just above

    def float_list(self, key: str, default: list[float]) -> list[float]:
        """A list of numbers."""
        value = self.param(key, default, list)
        if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
            raise ControlError(f"controller '{self.name}': parameter '{key}' must be a list of numbers, got {value!r}")
        return [float(v) for v in value]

    def string_list(self, key: str, default: list[str] | None = None) -> list[str]:
        """A list of strings."""
        value = self.param(key, default if default is not None else [], list)
        if not all(isinstance(v, str) for v in value):
            raise ControlError(f"controller '{self.name}': parameter '{key}' must be a list of strings, got {value!r}")
        return list(value)

    # ------------------------------------------------------------------ topics
    def topic(self, name: str) -> str:
        """A topic or action name resolved for the controller's node (``~/cmd_vel`` is ``<ns>/<name>/cmd_vel``),
        after the node's remapping rules (:func:`~gazelle.systems._bus.remap_name`)."""
        return remap_name(name, self.ctx.namespace, self.name, self.ctx.remaps)

    def advertise(self, name: str, msg_type: MessageKind, qos: Qos = Qos.DEFAULT, depth: int = 10) -> Endpoint:
        """A publisher of the controller's, removed at cleanup."""
        ep = self.ctx.bus.advertise(self.ctx.owner, self.topic(name), msg_type, qos=qos, depth=depth)
        self._endpoints.append(ep)
        return ep

    def subscribe(
        self, name: str, msg_type: MsgType, callback: Callable[[Any], None], depth: int = 10, qos: Qos = Qos.DEFAULT
    ) -> Endpoint:
        """A subscription of the controller's, removed at cleanup."""
        ep = self.ctx.bus.subscribe(self.ctx.owner, self.topic(name), msg_type, callback, qos=qos, depth=depth)
        self._endpoints.append(ep)
        return ep

    def drop_endpoints(self) -> None:
        """Remove every topic of this controller."""
        for ep in self._endpoints:
            self.ctx.bus.remove(ep)
        self._endpoints.clear()

    # ------------------------------------------------------------------ the lifecycle
    def configure(self) -> None:
        """Read the parameters and declare topics (raises :class:`ControlError` on bad ones). A parameter the
        controller did not read is named in one warning: it has no effect here, and the user should know."""
        self._read.clear()
        rate = self.param("update_rate", 0, int)
        if rate < 0:
            raise ControlError(f"controller '{self.name}': update_rate must not be negative")
        self.update_rate = rate
        self.on_configure()
        unread = sorted(k for k in self.params if k not in self._read and k not in MANAGER_READ_PARAMETERS)
        if unread:
            self.log.warning(
                f"controller '{self.name}': parameter(s) {', '.join(unread)} are not read by gazelle's "
                f"{self.type_name or type(self).__name__}: they have no effect"
            )

    def on_configure(self) -> None:
        """Subclasses: read parameters, declare topics."""

    def on_parameters_changed(self) -> None:
        """A parameter was set on the controller's node (``params`` holds the new values; the simulation thread).
        Upstream's controllers read their parameters in ``on_configure``, so by default a new value takes effect at
        the next configure; a controller that reads some again while it runs (the JTC) overrides this."""

    def command_interfaces(self) -> list[str]:
        """The command interfaces this controller claims while active."""
        return []

    def state_interfaces(self) -> list[str] | None:
        """The state interfaces it reads (None: every one)."""
        return []

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Going active (on the simulation thread, between two cycles)."""

    def on_deactivate(self) -> None:
        """Going inactive."""

    def on_cleanup(self) -> None:
        """Back to unconfigured: drop topics and state."""
        self.drop_endpoints()

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle: read ``states``, write the claimed entries of ``commands``."""


MANAGER_READ_PARAMETERS = frozenset({"type", "params_file", "use_sim_time", "fallback_controllers", "is_async"})
"""A controller's parameters that are not the controller's to read: its type and parameter files (the
controller manager's), ``use_sim_time`` (every node's: the simulation's clock is the one it runs on), and
ros2_control's scheduling options (gazelle runs every controller in the simulation's step, in order)."""


def missing_interfaces(c: Controller, commands: Iterable[str], states: Iterable[str]) -> str:
    """Why the hardware cannot run controller ``c``: the command or state interfaces it needs and the hardware does
    not offer, named with what the hardware has ("" when none is missing; ros2_control refuses it at activation
    the same way)."""
    have_c, have_s = set(commands), set(states)
    missing_c = [i for i in c.command_interfaces() if i not in have_c]
    missing_s = [i for i in (c.state_interfaces() or []) if i not in have_s]
    if not missing_c and not missing_s:
        return ""
    parts = []
    if missing_c:
        parts.append(f"command interface(s) {', '.join(missing_c)}")
    if missing_s:
        parts.append(f"state interface(s) {', '.join(missing_s)}")
    return (
        f"controller '{c.name}' needs {' and '.join(parts)}, which the hardware does not offer "
        f"(it has command interfaces {sorted(have_c)})"
    )


def _type_name(t: type | tuple[type, ...]) -> str:
    if isinstance(t, tuple):
        return " or ".join(_type_name(x) for x in t)
    return {bool: "a bool", int: "an integer", float: "a number", str: "a string", list: "a list"}.get(t, t.__name__)


def finite(values: list[float]) -> bool:
    """Whether every value is finite."""
    return all(math.isfinite(v) for v in values)


def position_limits(joints: Iterable[Joint]) -> dict[str, tuple[float, float]]:
    """The position range (lower, upper) of each revolute or prismatic joint of ``joints`` whose description
    gives both bounds (a continuous joint has none); what ros2_control's joint limits read from the URDF as
    ``min_position`` / ``max_position``."""
    out: dict[str, tuple[float, float]] = {}
    for j in joints:
        if j.type in (JointType.REVOLUTE, JointType.PRISMATIC) and j.axis is not None:
            lo, hi = j.axis.limit.lower, j.axis.limit.upper
            if lo is not None and hi is not None and lo <= hi:
                out[j.name] = (lo, hi)
    return out


def values_getter(keys: list[str]) -> Callable[[dict[str, float]], tuple[float, ...]]:
    """A function giving the values of ``keys`` in a state or command dict as a tuple (NaN for a ""
    key): one C-level ``itemgetter`` call when it can, since controllers run at up to 1 kHz. Module
    functions and partials, never closures, so that a checkpoint can save a controller."""
    if not keys:
        return _no_values
    if all(keys):
        get = operator.itemgetter(*keys)
        return get if len(keys) > 1 else functools.partial(_one_value, get)
    return functools.partial(_values_or_nan, tuple(keys))


def _no_values(_values: dict[str, float]) -> tuple[float, ...]:
    return ()


def _one_value(get: Callable[[dict[str, float]], float], values: dict[str, float]) -> tuple[float, ...]:
    return (get(values),)


def _values_or_nan(keys: tuple[str, ...], values: dict[str, float]) -> tuple[float, ...]:
    return tuple(values[k] if k else math.nan for k in keys)


def values_or_zero(keys: tuple[str, ...], values: dict[str, float]) -> tuple[float, ...]:
    """The values of ``keys``, 0.0 for a key missing from ``values`` (bind ``keys`` with a partial)."""
    return tuple(values.get(k, 0.0) for k in keys)

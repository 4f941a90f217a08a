"""joint_state_broadcaster and the forward_command_controller family."""

from __future__ import annotations

import math

from .._bus import DynamicJointState, Float64Array, JointStates, MsgType
from ._controller import Controller
from ._hardware import ControlError

_JOINT_STATE_FIELDS = ("position", "velocity", "effort")


class JointStateBroadcaster(Controller):
    """``joint_state_broadcaster/JointStateBroadcaster``: ``joint_states`` (sensor_msgs/JointState) of every
    joint with a position, velocity or effort state interface, and ``dynamic_joint_states`` with every
    interface. Parameters: ``joints`` and ``interfaces`` (empty: all), ``use_local_topics``,
    ``map_interface_to_joint_state.{position,velocity,effort}``, ``extra_joints``."""

    type_name = "joint_state_broadcaster/JointStateBroadcaster"

    def on_configure(self) -> None:
        self._joints = self.string_list("joints")
        self._interfaces = self.string_list("interfaces")
        if bool(self._joints) != bool(self._interfaces):
            # the real one refuses half a selection too
            raise ControlError(
                f"controller '{self.name}': 'joints' and 'interfaces' must be given together (or neither, for all)"
            )
        self._map = {f: self.param(f"map_interface_to_joint_state.{f}", f, str) for f in _JOINT_STATE_FIELDS}
        self._extra = self.string_list("extra_joints")
        local = self.param("use_local_topics", False, bool)
        prefix = "~/" if local else ""
        self._js = self.advertise(f"{prefix}joint_states", MsgType.JOINT_STATE)
        self._djs = self.advertise(f"{prefix}dynamic_joint_states", MsgType.DYNAMIC_JOINT_STATE)

    def state_interfaces(self) -> list[str] | None:
        if not self._joints:
            return None
        return [f"{j}/{i}" for j in self._joints for i in self._interfaces]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        wanted = set(self.state_interfaces() or states)
        names: list[str] = []
        groups: dict[str, list[str]] = {}
        for full in states:
            if full not in wanted:
                continue
            prefix, _, iface = full.rpartition("/")
            if prefix not in groups:
                groups[prefix] = []
                names.append(prefix)
            groups[prefix].append(iface)
        self._groups = [(n, tuple(groups[n])) for n in names]
        mapped = {v: k for k, v in self._map.items()}
        self._js_joints = tuple(n for n, ifaces in self._groups if any(i in mapped for i in ifaces))
        have = dict(self._groups)
        # per JointState field: the state keys in joint order ("" where a joint lacks that interface)
        self._columns = [
            [f"{n}/{self._map[f]}" if self._map[f] in have[n] else "" for n in self._js_joints]
            for f in _JOINT_STATE_FIELDS
        ]
        self._djs_keys = [[f"{n}/{i}" for i in ifaces] for n, ifaces in self._groups]

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        if self._js.wanted:
            nan = math.nan
            pos, vel, eff = (tuple(states[k] if k else nan for k in col) for col in self._columns)
            if self._extra:
                zeros = (0.0,) * len(self._extra)
                pos, vel, eff = pos + zeros, vel + zeros, eff + zeros
            self._js.publish(JointStates(t, self._js_joints + tuple(self._extra), pos, vel, eff))
        if self._djs.wanted:
            self._djs.publish(
                DynamicJointState(
                    t,
                    tuple(n for n, _ in self._groups),
                    tuple(
                        (ifaces, tuple(states[k] for k in keys))
                        for (_, ifaces), keys in zip(self._groups, self._djs_keys, strict=True)
                    ),
                )
            )


class ForwardCommandController(Controller):
    """``forward_command_controller/ForwardCommandController``: ``~/commands`` (Float64MultiArray), one value
    per joint in ``joints`` order, written to each joint's ``interface_name``."""

    type_name = "forward_command_controller/ForwardCommandController"
    fixed_interface = ""

    def on_configure(self) -> None:
        self._joints = self.string_list("joints")
        if not self._joints:
            raise ControlError(f"controller '{self.name}': 'joints' is empty")
        self._interface = self.fixed_interface or self.param("interface_name", "", str)
        if not self._interface:
            raise ControlError(f"controller '{self.name}': 'interface_name' is not set")
        self._latest: tuple[float, ...] | None = None
        self._fresh = False
        self.subscribe("~/commands", MsgType.FLOAT64_ARRAY, self._on_commands)

    def _on_commands(self, msg: Float64Array) -> None:
        if len(msg.data) != len(self._joints):
            self.log.error(
                f"{self.name}: command size ({len(msg.data)}) does not match the number of joints "
                f"({len(self._joints)}); ignored"
            )
            return
        self._latest, self._fresh = msg.data, True

    def command_interfaces(self) -> list[str]:
        return [f"{j}/{self._interface}" for j in self._joints]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        self._latest, self._fresh = None, False  # commands from before activation are not replayed

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        if self._fresh and self._latest is not None:
            for key, value in zip(self.command_interfaces(), self._latest, strict=True):
                commands[key] = value
            self._fresh = False


class JointGroupPositionController(ForwardCommandController):
    """``position_controllers/JointGroupPositionController``."""

    type_name = "position_controllers/JointGroupPositionController"
    fixed_interface = "position"


class JointGroupVelocityController(ForwardCommandController):
    """``velocity_controllers/JointGroupVelocityController``."""

    type_name = "velocity_controllers/JointGroupVelocityController"
    fixed_interface = "velocity"


class JointGroupEffortController(ForwardCommandController):
    """``effort_controllers/JointGroupEffortController``."""

    type_name = "effort_controllers/JointGroupEffortController"
    fixed_interface = "effort"

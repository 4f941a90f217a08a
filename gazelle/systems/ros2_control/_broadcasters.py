"""joint_state_broadcaster, the sensor broadcasters and the forward_command_controller family."""

from __future__ import annotations

import math

import numpy as np

from .._bus import MsgType, Qos
from .._payloads import (
    DynamicJointState,
    Float64Array,
    Imu,
    InterfaceValue,
    JointStates,
    JointStatesBlock,
    WrenchStamped,
)
from ._controller import Controller, values_getter
from ._hardware import FT_INTERFACES, IMU_INTERFACES, ControlError, UpdateFailed

_JOINT_STATE_FIELDS = ("position", "velocity", "effort")


class JointStateBroadcaster(Controller):
    """``joint_state_broadcaster/JointStateBroadcaster``: ``joint_states`` (sensor_msgs/JointState) of every
    joint with a position, velocity or effort state interface, and ``dynamic_joint_states`` with every
    interface. Parameters: ``joints`` and ``interfaces`` (empty: all), ``use_local_topics``,
    ``map_interface_to_joint_state.{position,velocity,effort}``, ``extra_joints``, ``frame_id``,
    ``use_urdf_to_filter``, ``publish_dynamic_joint_states``.

    As ros2_controllers Jazzy's (``joint_state_broadcaster.cpp``): both messages carry ``frame_id``
    (``base_link`` by default; empty is warned "Frame ID is not set."); with ``use_urdf_to_filter`` (true)
    and no ``joints`` list, ``joint_states`` holds the URDF's moving joints that have a state interface, in
    the order of the URDF model's joint map, which is by name; a value a joint has no interface for is NaN."""

    read_only_parameters = frozenset(
        {
            "use_local_topics",
            "joints",
            "extra_joints",
            "interfaces",
            "map_interface_to_joint_state.position",
            "map_interface_to_joint_state.velocity",
            "map_interface_to_joint_state.effort",
            "use_urdf_to_filter",
            "frame_id",
            "publish_dynamic_joint_states",
        }
    )
    """joint_state_broadcaster_parameters.yaml's ``read_only`` parameters (ros2_controllers jazzy)."""

    type_name = "joint_state_broadcaster/JointStateBroadcaster"

    def on_configure(self) -> None:
        """Read ``joints``/``interfaces`` (both or neither, as the real one insists),
        ``map_interface_to_joint_state`` (which interface fills JointState's position, velocity, effort),
        ``extra_joints`` (published at zero) and ``use_local_topics`` (``~/joint_states`` instead of
        ``/joint_states``); declare both topics."""
        self._joints = self.string_list("joints")
        self._interfaces = self.string_list("interfaces")
        if bool(self._joints) != bool(self._interfaces):
            # the real one refuses half a selection too
            raise ControlError(
                f"controller '{self.name}': 'joints' and 'interfaces' must be given together (or neither, for all)"
            )
        self._map = {f: self.param(f"map_interface_to_joint_state.{f}", f, str) for f in _JOINT_STATE_FIELDS}
        self._extra_param = self.string_list("extra_joints")
        self._extra: list[str] = []
        """The extra joints published at 0: ``extra_joints`` less those the hardware has (set when activated)."""
        self._frame_id = self.param("frame_id", "base_link", str)
        if not self._frame_id:
            self.log.warning("Frame ID is not set.")
        self._urdf_filter = self.param("use_urdf_to_filter", True, bool)
        local = self.param("use_local_topics", False, bool)
        prefix = "~/" if local else ""
        self._js = self.advertise(f"{prefix}joint_states", MsgType.JOINT_STATE)
        self._djs = (
            self.advertise(f"{prefix}dynamic_joint_states", MsgType.DYNAMIC_JOINT_STATE)
            if self.param("publish_dynamic_joint_states", True, bool)
            else None
        )

    def state_interfaces(self) -> list[str] | None:
        if not self._joints:
            return None
        return [f"{j}/{i}" for j in self._joints for i in self._interfaces]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Lay out the messages once: the joints in the hardware's order, grouped by name prefix; per JointState
        field, the state key of each joint (a joint without that interface gets no value there); per joint, its
        interfaces for DynamicJointState. The cycle then reads the values with one lookup per field."""
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
        # init_joint_data: each of extra_joints not already a name (nor listed before) joins both messages with
        # position, velocity and effort 0 (Jazzy joint_state_broadcaster.cpp; a hardware joint keeps its values)
        self._extra = [e for e in dict.fromkeys(self._extra_param) if e not in groups]
        mapped = {v: k for k, v in self._map.items()}
        self._js_joints = tuple(n for n, ifaces in self._groups if any(i in mapped for i in ifaces))
        urdf = self.ctx.description_joints
        if self._urdf_filter and not self._joints and urdf is not None:
            # init_joint_data: the URDF model's moving joints (urdf::Model::joints_, a std::map: by name)
            # that have a joint_states interface; a hardware "joint" the URDF lacks is left out
            in_urdf = set(urdf)
            self._js_joints = tuple(sorted(n for n in self._js_joints if n in in_urdf))
        have = dict(self._groups)
        # per JointState field: the state keys in joint order ("" where a joint lacks that interface)
        self._columns = [
            [f"{n}/{self._map[f]}" if self._map[f] in have[n] else "" for n in self._js_joints]
            for f in _JOINT_STATE_FIELDS
        ]
        self._djs_keys = [[f"{n}/{i}" for i in ifaces] for n, ifaces in self._groups]
        # per JointState field: one C-level lookup of its values (the cycle runs at up to 1 kHz)
        self._getters = [values_getter(col) for col in self._columns]
        self._block_columns: tuple[dict[str, int], list[list[tuple[int, int] | str]]] | None = None
        """For a planned block: per JointState field, each column's (kind, joint index) in the records, or its
        state key (made once per record layout)."""

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """Publish JointState and DynamicJointState for this cycle, each only while it has a subscriber.

        Every cycle of the manager, as upstream's ``update()`` (no rate of its own): the values are this
        cycle's reads, stamped with the cycle's sim time, NaN where a joint lacks the interface; the extra
        joints follow at 0. Building the message costs one C-level lookup per field (see ``on_activate``),
        which matters at a 1 kHz manager."""
        if self._js.wanted:
            pos, vel, eff = (get(states) for get in self._getters)
            if self._extra:
                zeros = (0.0,) * len(self._extra)
                pos, vel, eff = pos + zeros, vel + zeros, eff + zeros
            self._js.publish(JointStates(t, self._js_joints + tuple(self._extra), pos, vel, eff, self._frame_id))
        if self._djs is not None and self._djs.wanted:
            extra = [InterfaceValue(_JOINT_STATE_FIELDS, (0.0, 0.0, 0.0))] * len(self._extra)
            self._djs.publish(
                DynamicJointState(
                    t,
                    tuple(n for n, _ in self._groups) + tuple(self._extra),
                    tuple(
                        InterfaceValue(ifaces, tuple(states[k] for k in keys))
                        for (_, ifaces), keys in zip(self._groups, self._djs_keys, strict=True)
                    )
                    + tuple(extra),
                    self._frame_id,
                )
            )

    def block_ready(self) -> bool:
        """Whether its cycles can be part of a planned block (see ``ControllerManager._plan_block``): no
        ``dynamic_joint_states`` listener (its sensor interfaces are not recorded per cycle)."""
        return self._djs is None or not self._djs.wanted

    def publish_block(
        self, times: np.ndarray, records: np.ndarray, column: dict[str, int], states: dict[str, float]
    ) -> None:
        """Publish the ``joint_states`` of the cycles at ``times`` of a planned block, one message per cycle as
        :meth:`update` would, handed over as one :class:`JointStatesBlock`: ``records`` holds each cycle's
        joint positions, velocities and efforts (rows: cycles; ``column``: a joint's index), other
        interfaces are as in ``states``."""
        if not self._js.wanted:
            return
        if self._block_columns is None or self._block_columns[0] is not column:
            kinds = {"position": 0, "velocity": 1, "effort": 2}
            plan: list[list[tuple[int, int] | str]] = []
            for keys in self._columns:
                cols: list[tuple[int, int] | str] = []
                for key in keys:
                    joint, _, iface = key.rpartition("/")
                    cols.append((kinds[iface], column[joint]) if key and iface in kinds and joint in column else key)
                plan.append(cols)
            self._block_columns = (column, plan)
        n, extra = len(times), len(self._extra)
        fields = []
        for cols in self._block_columns[1]:
            recorded = [c for c in cols if isinstance(c, tuple)]
            if len(recorded) == len(cols) and len({c[0] for c in recorded}) <= 1 and not extra:
                kind = recorded[0][0] if recorded else 0
                values = records[:, kind, [c[1] for c in recorded]]  # one gather: every column recorded
            else:
                values = np.zeros((n, len(cols) + extra))
                for i, c in enumerate(cols):
                    if isinstance(c, tuple):
                        values[:, i] = records[:, c[0], c[1]]
                    else:
                        values[:, i] = states[c] if c else math.nan
            fields.append(values)
        pos, vel, eff = fields
        names = self._js_joints + tuple(self._extra)
        self._js.publish_block(JointStatesBlock(times.tolist(), names, pos, vel, eff, self._frame_id))


class ForwardCommandController(Controller):
    """``forward_command_controller/ForwardCommandController``: ``~/commands`` (Float64MultiArray), one value
    per joint in ``joints`` order, written to each joint's ``interface_name``."""

    type_name = "forward_command_controller/ForwardCommandController"
    fixed_interface = ""

    def on_configure(self) -> None:
        """Read ``joints`` and ``interface_name`` (fixed by the class for the JointGroup* controllers) and subscribe
        to ``~/commands`` (std_msgs/Float64MultiArray, one value per joint)."""
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
        """Keep the latest command for the next cycle, as Jazzy's forward_controllers_base.cpp does: a command
        with a value that is not finite is dropped with its warning (the previous one stays); its size is
        checked by the cycle that writes it."""
        if not all(math.isfinite(v) for v in msg.data):
            self.log.warning("Non-finite value received. Dropping message")
            return
        self._latest, self._fresh = msg.data, True

    def command_interfaces(self) -> list[str]:
        return [f"{j}/{self._interface}" for j in self._joints]

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        self._latest, self._fresh = None, False  # commands from before activation are not replayed

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """Write the command that arrived since the last cycle; between commands the hardware holds the last one.

        A command whose size is not the number of joints fails the cycle, as Jazzy's ``update`` returns
        ERROR with its log line: the manager then deactivates the controller (the hardware keeps the last
        command it had)."""
        if self._fresh and self._latest is not None:
            if len(self._latest) != len(self._joints):
                self.log.error(
                    f"command size ({len(self._latest)}) does not match number of interfaces ({len(self._joints)})"
                )
                raise UpdateFailed(f"controller '{self.name}': command size does not match its joints")
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


class ImuSensorBroadcaster(Controller):
    """``imu_sensor_broadcaster/IMUSensorBroadcaster``: the ``sensor_name`` component's 10 interfaces as
    sensor_msgs/Imu on ``~/imu`` in ``frame_id``, with the ``static_covariance_*`` parameters."""

    type_name = "imu_sensor_broadcaster/IMUSensorBroadcaster"

    def on_configure(self) -> None:
        """Read ``sensor_name``, ``frame_id`` and the three ``static_covariance_*`` (9 values each) and declare
        ``~/imu`` with the sensor QoS."""
        self.sensor = self.param("sensor_name", "", str)
        self.frame_id = self.param("frame_id", "", str)
        if not self.sensor or not self.frame_id:
            raise ControlError(f"controller '{self.name}': 'sensor_name' and 'frame_id' must be set")
        covs = []
        for key in ("orientation", "angular_velocity", "linear_acceleration"):
            values = self.float_list(f"static_covariance_{key}", [0.0] * 9)
            if len(values) != 9:
                raise ControlError(f"controller '{self.name}': static_covariance_{key} needs 9 values")
            covs.append(tuple(values))
        self._cov = covs
        self._keys = [f"{self.sensor}/{i}" for i in IMU_INTERFACES]
        self._pub = self.advertise("~/imu", MsgType.IMU, Qos.SENSOR)

    def state_interfaces(self) -> list[str] | None:
        return list(self._keys)

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """Publish the IMU's ten state interfaces (orientation x, y, z, w; angular velocity; linear acceleration) as
        sensor_msgs/Imu in ``frame_id``."""
        if not self._pub.wanted:
            return
        v = [states[k] for k in self._keys]
        self._pub.publish(
            Imu(
                t,
                self.frame_id,
                (v[3], v[0], v[1], v[2]),
                (v[4], v[5], v[6]),
                (v[7], v[8], v[9]),
                self._cov[0],
                self._cov[1],
                self._cov[2],
            )
        )


class ForceTorqueSensorBroadcaster(Controller):
    """``force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster``: geometry_msgs/WrenchStamped on
    ``~/wrench`` in ``frame_id``, from ``sensor_name``'s force.x..torque.z or the ``interface_names.*`` given."""

    type_name = "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster"

    def on_configure(self) -> None:
        """Read ``sensor_name`` (its six ``force.x`` ... ``torque.z`` interfaces) or ``interface_names.*`` one by
        one, and ``frame_id``; declare ``~/wrench``."""
        self.sensor = self.param("sensor_name", "", str)
        self.frame_id = self.param("frame_id", "", str)
        names = [self.param(f"interface_names.{i}", "", str) for i in FT_INTERFACES]
        if not self.sensor and not any(names):
            raise ControlError(f"controller '{self.name}': 'sensor_name' or 'interface_names' must be set")
        if not self.frame_id:
            raise ControlError(f"controller '{self.name}': 'frame_id' must be set")
        self._keys = [
            n if n else (f"{self.sensor}/{i}" if self.sensor else "") for n, i in zip(names, FT_INTERFACES, strict=True)
        ]
        self._pub = self.advertise("~/wrench", MsgType.WRENCH_STAMPED)

    def state_interfaces(self) -> list[str] | None:
        return [k for k in self._keys if k]

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """Publish the wrench (an interface not given reads NaN) in ``frame_id``."""
        if not self._pub.wanted:
            return
        v = [states[k] if k else math.nan for k in self._keys]
        self._pub.publish(WrenchStamped(t, self.frame_id, (v[0], v[1], v[2]), (v[3], v[4], v[5])))

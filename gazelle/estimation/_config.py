"""ekf_node's parameters (robot_localization's ``RosFilter::loadParams``, ros2 branch, read for the names,
defaults and checks), read from a plain mapping of name -> value as rclpy gives them.

What a parameter file sets that this reads not, or whose setting gazelle does not do, is listed in
``EkfConfig.unread`` (the node names them in one warning at start). A value of the wrong type or size is a
:class:`ConfigError` naming the parameter. Upstream's load-time complaints (frames that are not unique, an
input with every variable off...) are kept as ``notes``, to be logged."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._errors import SimError
from ._control import TWIST_CONTROLS, ControlSettings
from ._measurement import STATE_NAMES, STATE_SIZE
from ._sensor_config import KINDS, SensorConfig

BUILT_IN = frozenset({"use_sim_time", "start_type_description_service"})
"""Parameters every rclpy node has, not the filter's."""
NO_EFFECT = frozenset({"tf_prefix", "reset_on_time_jump", "debug_out_file", "stamped_control"})
"""Parameters that have no effect upstream either: ``tf_prefix`` (declared, then a prefix of "" is appended),
``reset_on_time_jump`` (declared and never used), ``debug_out_file`` (without ``debug``) and
``stamped_control`` (in params/ekf.yaml, never declared: ``cmd_vel`` is a geometry_msgs/Twist)."""


class ConfigError(SimError, ValueError):
    """A parameter ekf_node cannot use; the message names it."""


@dataclass
class EkfConfig:
    """Everything ekf_node reads from its parameters."""

    frequency: float = 30.0
    """``frequency``: the node's cycles per second of its clock (each fuses what arrived and publishes)."""
    sensor_timeout_ns: int = 0
    """``sensor_timeout`` (default 1 / frequency): with no reading for this long, a cycle predicts to now."""
    two_d_mode: bool = False
    """``two_d_mode``: z, roll, pitch, their rates and az are measured as 0 with every measurement."""
    publish_tf: bool = True
    """``publish_tf``: broadcast the world frame's transform each time the state is published."""
    publish_acceleration: bool = False
    """``publish_acceleration``: also publish ``accel/filtered``."""
    permit_corrected_publication: bool = False
    """``permit_corrected_publication``: publish a cycle's state even when its time did not move on."""
    predict_to_current_time: bool = False
    """``predict_to_current_time``: every cycle predicts the state to now, not only after a sensor timeout."""
    transform_time_offset_ns: int = 0
    """``transform_time_offset``: added to the broadcast transform's stamp (future-dating it)."""
    map_frame: str = "map"
    """``map_frame``: the world frame of global inputs (GPS, a localizer)."""
    odom_frame: str = "odom"
    """``odom_frame``: the continuous world frame of odometry."""
    base_link_frame: str = "base_link"
    """``base_link_frame``: the body; twists and IMU readings are taken into it."""
    base_link_output_frame: str = "base_link"
    """``base_link_frame_output`` (default ``base_link_frame``): the child frame of what is published."""
    world_frame: str = "odom"
    """``world_frame`` (default ``odom_frame``): the frame of the state's pose; poses are taken into it."""
    gravity: float = 9.80665
    """``gravitational_acceleration`` (m/s^2), removed from IMUs with ``remove_gravitational_acceleration``."""
    print_diagnostics: bool = False
    """``print_diagnostics``: check the configuration's coverage and report the data's problems."""
    disabled_at_startup: bool = False
    """``disabled_at_startup``: the filter waits for the ``enable`` service."""
    dynamic_process_noise: bool = False
    """``dynamic_process_noise_covariance``: the pose's process noise scales with the squared speed."""
    initial_state: np.ndarray | None = None
    """``initial_state`` (15 values): the state before the first measurement (None: at rest at the origin)."""
    process_noise: np.ndarray | None = None
    """``process_noise_covariance`` (15x15; None: robot_localization's defaults)."""
    initial_covariance: np.ndarray | None = None
    """``initial_estimate_covariance`` (15x15; None: 1e-9 on the diagonal)."""
    control: ControlSettings | None = None
    """``use_control`` and its settings (None: no control term)."""
    sensors: list[SensorConfig] = field(default_factory=list)
    """The inputs, in upstream's order: odom, pose, twist, imu, each numbered from 0."""
    notes: list[str] = field(default_factory=list)
    """Upstream's complaints about the configuration, to be logged as warnings."""
    unread: list[str] = field(default_factory=list)
    """Parameters set that gazelle does not act on (sorted)."""


class _Reader:
    """Typed reads of a parameter mapping that remember which names were read."""

    def __init__(self, params: Mapping[str, Any]) -> None:
        self.params = params
        """What the node was given: its parameter file's, ``-p``'s and a launch file's values together."""
        self.read: set[str] = set()
        """Names this configuration reads (set or not): what is set beyond them is named as not read."""
        self.unread: set[str] = set()
        """Names read whose setting gazelle does not do (``debug: true``...)."""

    def has(self, name: str) -> bool:
        """Whether ``name`` is set (a parameter declared without a value is not)."""
        return name in self.params and self.params[name] is not None

    def get(self, name: str, default: Any, kind: type) -> Any:
        """``name`` as ``kind`` (bool, int, float, str), ``default`` when not set; an int is taken as a float."""
        self.read.add(name)
        if not self.has(name):
            return default
        value = self.params[name]
        # rclcpp would refuse an integer for a double parameter (and end the node); a YAML "30" is meant as 30.0
        if kind is float and isinstance(value, int) and not isinstance(value, bool):
            return float(value)
        if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
            raise ConfigError(f"parameter {name!r} must be a {kind.__name__}, not {value!r}")
        return value

    def floats(self, name: str, sizes: tuple[int, ...] = ()) -> np.ndarray | None:
        """A list of numbers (of one of ``sizes`` lengths, when given), or None when not set."""
        self.read.add(name)
        if not self.has(name):
            return None
        value = self.params[name]
        if not isinstance(value, list | tuple) or not all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in value
        ):
            raise ConfigError(f"parameter {name!r} must be a list of numbers")
        if sizes and len(value) not in sizes:
            said = " or ".join(str(s) for s in sizes)
            raise ConfigError(f"parameter {name!r} must have {said} values, not {len(value)}")
        return np.asarray(value, dtype=float)

    def bools(self, name: str, size: int) -> tuple[bool, ...] | None:
        """A list of ``size`` booleans, or None when not set."""
        self.read.add(name)
        if not self.has(name):
            return None
        value = self.params[name]
        if not isinstance(value, list | tuple) or not all(isinstance(v, bool) for v in value):
            raise ConfigError(f"parameter {name!r} must be a list of {size} booleans (true/false), not {value!r}")
        if len(value) != size:
            raise ConfigError(f"parameter {name!r} must have {size} booleans, not {len(value)}")
        return tuple(value)

    def not_done_when(self, name: str, condition: bool) -> None:
        """``name`` is read, but gazelle does not do what it asks when ``condition`` holds."""
        self.read.add(name)
        if condition:
            self.unread.add(name)


def _covariance(reader: _Reader, name: str) -> np.ndarray | None:
    """A 15x15 matrix given whole (225 values, row-major) or as its diagonal (15)."""
    flat = reader.floats(name, (STATE_SIZE, STATE_SIZE * STATE_SIZE))
    if flat is None:
        return None
    return np.diag(flat) if flat.size == STATE_SIZE else flat.reshape(STATE_SIZE, STATE_SIZE)


def _frames(cfg: EkfConfig, r: _Reader) -> None:
    """The frames, which default to one another as upstream's do (``world_frame`` to ``odom_frame``, the output
    frame to ``base_link_frame``). Frames that are not unique are upstream's error message, and the node goes
    on, as upstream's does."""
    cfg.map_frame = r.get("map_frame", "map", str)
    cfg.odom_frame = r.get("odom_frame", "odom", str)
    cfg.base_link_frame = r.get("base_link_frame", "base_link", str)
    cfg.base_link_output_frame = r.get("base_link_frame_output", cfg.base_link_frame, str)
    cfg.world_frame = r.get("world_frame", cfg.odom_frame, str)
    frames = (cfg.map_frame, cfg.odom_frame, cfg.base_link_frame)
    if len(set(frames)) < 3 or cfg.base_link_output_frame in (cfg.map_frame, cfg.odom_frame):
        cfg.notes.append(
            "Invalid frame configuration! The values for map_frame, odom_frame, and base_link_frame must be "
            "unique. If using a base_link_frame_output values, it must not match the map_frame or odom_frame."
        )


def _globals(cfg: EkfConfig, r: _Reader) -> None:
    """The filter-wide settings, in upstream's order. ``debug`` (a file of every matrix),
    ``smooth_lagged_data`` with ``history_length`` (re-running the filter from a saved state for a reading
    that arrives late) and a ``transform_timeout`` (waiting for a transform) are not done: when asked for
    they are named as not read. The parameters that do nothing upstream either are taken as read."""
    cfg.print_diagnostics = r.get("print_diagnostics", False, bool)
    cfg.gravity = r.get("gravitational_acceleration", 9.80665, float)
    r.not_done_when("debug", r.get("debug", False, bool))
    cfg.publish_tf = r.get("publish_tf", True, bool)
    cfg.publish_acceleration = r.get("publish_acceleration", False, bool)
    cfg.permit_corrected_publication = r.get("permit_corrected_publication", False, bool)
    cfg.transform_time_offset_ns = round(r.get("transform_time_offset", 0.0, float) * 1e9)
    r.not_done_when("transform_timeout", r.get("transform_timeout", 0.0, float) != 0.0)
    cfg.frequency = r.get("frequency", 30.0, float)
    if not cfg.frequency > 0.0 or not math.isfinite(cfg.frequency):
        raise ConfigError(f"parameter 'frequency' must be a positive number of Hz, not {cfg.frequency!r}")
    cfg.predict_to_current_time = r.get("predict_to_current_time", False, bool)
    timeout = r.get("sensor_timeout", 1.0 / cfg.frequency, float)
    cfg.sensor_timeout_ns = round(timeout * 1e9)
    cfg.two_d_mode = r.get("two_d_mode", False, bool)
    smoothing = r.get("smooth_lagged_data", False, bool)
    r.not_done_when("smooth_lagged_data", smoothing)
    history = r.get("history_length", 0.0, float)
    r.not_done_when("history_length", smoothing and r.has("history_length"))
    if not smoothing and abs(history) > 0:
        cfg.notes.append(
            f"Filter history interval of {history:g} specified, but smooth_lagged_data is set to false. "
            "Lagged data will not be smoothed."
        )
    cfg.dynamic_process_noise = r.get("dynamic_process_noise_covariance", False, bool)
    initial = r.floats("initial_state")
    if initial is not None and initial.size != STATE_SIZE:
        cfg.notes.append(
            f"Initial state must be of size {STATE_SIZE}. Provided config was of size {initial.size}. "
            "The initial state will be ignored."
        )
        initial = None
    cfg.initial_state = initial
    cfg.disabled_at_startup = r.get("disabled_at_startup", False, bool)
    for name in NO_EFFECT:
        r.read.add(name)


def _control(cfg: EkfConfig, r: _Reader) -> None:
    """``use_control`` and its settings, with upstream's checks (a wrong size turns the control term off)."""
    use = r.get("use_control", False, bool)
    timeout = r.get("control_timeout", 0.0, float)
    names = ("control_config", "acceleration_limits", "acceleration_gains", "deceleration_limits", "deceleration_gains")
    if not use:
        r.read.update(names)  # upstream declares these only with use_control: without it they do nothing
        return
    config = r.bools("control_config", TWIST_CONTROLS)
    if config is None:
        cfg.notes.append("use_control is set to true, but control_config is missing. No control term will be used.")
        return
    values: dict[str, tuple[float, ...]] = {}
    # a limit of the wrong size turns the control term off; a gain of the wrong size makes every gain 1
    # (upstream's two answers, with its words)
    for name in names[1:]:
        given = r.floats(name)
        if given is not None and given.size != TWIST_CONTROLS:
            cfg.notes.append(f"{name} must be of size {TWIST_CONTROLS}. Provided config was of size {given.size}.")
            if name.endswith("limits"):
                return  # "No control term will be used."
            given = np.ones(TWIST_CONTROLS)  # "All gains will be assumed to be 1."
        if given is not None:
            values[name] = tuple(float(v) for v in given)
    # limits default to 1 (upstream says so), gains to 1; the deceleration ones to the acceleration ones
    accel_limits = values.get("acceleration_limits", (1.0,) * TWIST_CONTROLS)
    accel_gains = values.get("acceleration_gains", (1.0,) * TWIST_CONTROLS)
    cfg.control = ControlSettings(
        update=config,
        timeout_ns=round(timeout * 1e9),
        acceleration_limits=accel_limits,
        acceleration_gains=accel_gains,
        deceleration_limits=values.get("deceleration_limits", accel_limits),
        deceleration_gains=values.get("deceleration_gains", accel_gains),
    )


def _sensor(r: _Reader, kind: str, name: str, topic: str) -> tuple[SensorConfig, list[str]]:
    """``<name>_*`` of one input, and upstream's complaints about it. A twist input has no
    ``_differential`` or ``_relative`` (a velocity is neither); an IMU's apply to its orientation, and
    ``_relative`` to the gravity it removes too."""
    notes: list[str] = []
    differential = r.get(f"{name}_differential", False, bool) if kind != "twist" else False
    relative = r.get(f"{name}_relative", False, bool) if kind != "twist" else False
    if differential and relative:
        notes.append(f"Both {name}_differential and {name}_relative were set to true. Using differential mode.")
        relative = False
    if kind == "odom":
        # the pose of the message's child frame (a second odometry source mounted off the body) taken to the
        # body's: not done
        r.not_done_when(f"{name}_pose_use_child_frame", r.get(f"{name}_pose_use_child_frame", False, bool))
    # the thresholds are Mahalanobis distances (standard deviations); a pose or twist input has one, named
    # without its part, an odometry one per part and an IMU one more for its linear acceleration
    pose_t = twist_t = accel_t = math.inf
    if kind == "pose":
        pose_t = r.get(f"{name}_rejection_threshold", math.inf, float)
    elif kind == "twist":
        twist_t = r.get(f"{name}_rejection_threshold", math.inf, float)
    else:
        pose_t = r.get(f"{name}_pose_rejection_threshold", math.inf, float)
        twist_t = r.get(f"{name}_twist_rejection_threshold", math.inf, float)
    if kind == "imu":
        accel_t = r.get(f"{name}_linear_acceleration_rejection_threshold", math.inf, float)
    # the depth of the input's best-effort subscription (upstream's SensorDataQoS): readings beyond it,
    # arriving between two cycles, are dropped by DDS
    queue = r.get(f"{name}_queue_size", 10, int)
    if queue < 1:
        raise ConfigError(f"parameter '{name}_queue_size' must be at least 1, not {queue}")
    gravity = r.get(f"{name}_remove_gravitational_acceleration", False, bool) if kind == "imu" else False
    # without a config an input updates nothing: upstream's default is all false, and it says so below
    config = r.bools(f"{name}_config", STATE_SIZE) or (False,) * STATE_SIZE
    sensor = SensorConfig(
        name, kind, topic, config, differential, relative, queue, pose_t, twist_t, accel_t, remove_gravity=gravity
    )
    if kind == "imu":  # an Imu has no position and no linear velocity: upstream's warnings, word for word
        if any(config[0:3]):
            notes.append(
                f"Warning: Some position entries in parameter {name}_config are set to true, but the "
                "sensor_msgs/Imu message contains no positional data"
            )
        if any(config[6:9]):
            notes.append(
                f"Warning: Some position entries in parameter {name}_config are set to true, but the "
                "sensor_msgs/Imu message contains no linear velocity data"
            )
    if not sensor.updates_anything():
        notes.append(f"Warning: {topic} is listed as an input topic, but all its update variables are false")
    return sensor, notes


def _sensors(cfg: EkfConfig, r: _Reader) -> None:
    """``odom0``, ``odom1``... then ``pose<N>``, ``twist<N>``, ``imu<N>``: each kind up to its first gap."""
    for kind in KINDS:
        index = 0
        while r.has(f"{kind}{index}"):
            name = f"{kind}{index}"
            topic = r.get(name, "", str)
            sensor, notes = _sensor(r, kind, name, topic)
            cfg.notes.extend(notes)
            cfg.sensors.append(sensor)  # one updating nothing is kept: the node does not subscribe to it
            index += 1
        r.read.add(f"{kind}{index}")  # the gap: a later input of this kind is not read (upstream stops here)


def _imu_overrides_control(cfg: EkfConfig) -> None:
    """An axis whose acceleration an IMU measures is not controlled (upstream's rule, with its message)."""
    if cfg.control is None:
        return
    update = list(cfg.control.update)
    for sensor in cfg.sensors:
        measured = sensor.acceleration_update()
        for axis, label in enumerate("XYZ"):
            if update[axis] and measured[12 + axis]:
                cfg.notes.append(
                    f"{label} acceleration is being measured from IMU; {label} velocity control input is disabled"
                )
                update[axis] = False
    if not any(update):
        cfg.notes.append(
            "use_control is set to true, but control_config has only false values. No control term will be used."
        )
        cfg.control = None
        return
    cfg.control.update = tuple(update)


def _coverage_notes(cfg: EkfConfig) -> list[str]:
    """``print_diagnostics``' configuration checks: a pose variable measured absolutely by more than one input,
    or neither it nor its velocity measured at all (in 2-D mode, z, roll and pitch are not asked for)."""
    absolute = np.zeros(6, dtype=int)
    rates = np.zeros(6, dtype=int)
    for s in cfg.sensors:
        pose = s.pose_update()[0:6].astype(int)
        if s.differential:
            rates += pose
        else:
            absolute += pose
        rates += s.twist_update()[6:12].astype(int)
    notes = []
    for i in range(6):
        if absolute[i] > 1:
            notes.append(
                f"{absolute[i]} absolute pose inputs detected for {STATE_NAMES[i]}. This may result in "
                "oscillations. Please ensure that your variances for each measured variable are set appropriately."
            )
        elif absolute[i] == 0 and rates[i] == 0 and not (cfg.two_d_mode and i in (2, 3, 4)):
            notes.append(
                f"Neither {STATE_NAMES[i]} nor its velocity is being measured. This will result in unbounded "
                "error growth and erratic filter behavior."
            )
    return notes


def read_config(params: Mapping[str, Any]) -> EkfConfig:
    """The configuration in ``params`` (parameter name -> value).

    Raises:
        ConfigError: a parameter of the wrong type or size, or a frequency that is not positive.
    """
    r = _Reader(params)
    cfg = EkfConfig()
    _globals(cfg, r)
    _frames(cfg, r)
    _control(cfg, r)
    _sensors(cfg, r)
    _imu_overrides_control(cfg)
    if cfg.print_diagnostics:
        cfg.notes.extend(_coverage_notes(cfg))
    # the two matrices come last, as upstream reads them; a size other than 15 or 225 is upstream's fatal error
    cfg.process_noise = _covariance(r, "process_noise_covariance")
    cfg.initial_covariance = _covariance(r, "initial_estimate_covariance")
    # what was set and not read: a misspelt name, an input after a gap in the numbering, qos_overrides, and
    # the settings gazelle does not do
    cfg.unread = sorted((set(params) - r.read - BUILT_IN) | r.unread)
    return cfg

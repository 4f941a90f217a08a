"""Maps plugin file names and class names to system implementations."""

from __future__ import annotations

import functools
import logging
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..description import Diagnostic, ErrorCode, Model, Plugin, Sensor, Severity, World
from ._base import System
from .robot_state import RSP_PLUGIN

_log = logging.getLogger("gazelle.systems")


def _normalise(filename: str) -> str:
    """``libgazebo_ros_diff_drive.so`` -> ``gazebo_ros_diff_drive``; keeps gz names."""
    name = filename.strip()
    name = re.sub(r"^lib", "", name)
    name = re.sub(r"\.(so|dylib|dll)$", "", name)
    return name


def _diff_drive() -> System:
    from .diff_drive import DiffDrive

    return DiffDrive()


def _classic_joint_states() -> System:
    from .robot_state import JointStatePublisher

    return JointStatePublisher(all_by_default=False)


def _gz_joint_states() -> System:
    from .robot_state import JointStatePublisher

    return JointStatePublisher(all_by_default=True)


def _gz_diff_drive() -> System:
    from .gz_diff_drive import GzDiffDrive

    return GzDiffDrive()


def _gz_joint_position() -> System:
    from .joint_controllers import JointPositionController

    return JointPositionController()


def _gz_joint_velocity() -> System:
    from .joint_controllers import JointController

    return JointController()


def _joint_commands() -> System:
    from .joint_controllers import JointCommands

    return JointCommands()


def _imu() -> System:
    from .sensors import ImuSensor

    return ImuSensor()


def _force_torque() -> System:
    from .sensors import ForceTorqueSensor

    return ForceTorqueSensor()


def _controller_manager() -> System:
    from .ros2_control import ControllerManager

    return ControllerManager()


def _p3d() -> System:
    from .pose_publisher import P3D

    return P3D()


_REGISTRY: dict[str, Callable[[], System]] = {
    "gazebo_ros_diff_drive": _diff_drive,
    "gazebo_ros_joint_state_publisher": _classic_joint_states,
    "gz-sim-joint-state-publisher-system": _gz_joint_states,
    "gz::sim::systems::JointStatePublisher": _gz_joint_states,
    "ignition-gazebo-joint-state-publisher-system": _gz_joint_states,
    "ignition::gazebo::systems::JointStatePublisher": _gz_joint_states,
    "gz-sim-diff-drive-system": _gz_diff_drive,
    "gz::sim::systems::DiffDrive": _gz_diff_drive,
    "ignition-gazebo-diff-drive-system": _gz_diff_drive,
    "ignition::gazebo::systems::DiffDrive": _gz_diff_drive,
    "gz-sim-joint-position-controller-system": _gz_joint_position,
    "gz::sim::systems::JointPositionController": _gz_joint_position,
    "ignition-gazebo-joint-position-controller-system": _gz_joint_position,
    "ignition::gazebo::systems::JointPositionController": _gz_joint_position,
    "gz-sim-joint-controller-system": _gz_joint_velocity,
    "gz::sim::systems::JointController": _gz_joint_velocity,
    "ignition-gazebo-joint-controller-system": _gz_joint_velocity,
    "ignition::gazebo::systems::JointController": _gz_joint_velocity,
    "gazelle_joint_commands": _joint_commands,
    "gazebo_ros_p3d": _p3d,
    "gazebo_ros_ft_sensor": _force_torque,  # a model plugin naming a <joint_name>
    "gazebo_ros_imu": _imu,  # ROS 1's IMU model plugin (<bodyName>), as in TurtleBot3's noetic xacro
    # ros2_control's simulator plugins: the controller manager (a robot with <ros2_control> and no such
    # tag gets one too, see Simulation)
    "gazebo_ros2_control": _controller_manager,
    "gz_ros2_control-system": _controller_manager,
    "gz_ros2_control::GazeboSimROS2ControlPlugin": _controller_manager,
    "ign_ros2_control-system": _controller_manager,
    "ign_ros2_control::IgnitionROS2ControlPlugin": _controller_manager,
}


def _gz_spellings(name: str, file: str = "") -> tuple[str, ...]:
    """Every way a world names gz-sim's system ``name`` (``Imu``): gz and Ignition, file (``file``, else the
    lower-case name) and class."""
    kebab = file or name.lower()
    return (
        f"gz-sim-{kebab}-system",
        f"gz::sim::systems::{name}",
        f"ignition-gazebo-{kebab}-system",
        f"ignition::gazebo::systems::{name}",
    )


@functools.cache
def _sensor_tables() -> tuple[
    dict[str, tuple[Callable[[], System], frozenset[str]]], dict[str, dict[str, Callable[[], System]]]
]:
    """From every sensor class's declaration (``systems.sensors.SENSOR_SYSTEMS``): the gazebo_ros plugins
    that sit inside a ``<sensor>`` (the system and the sensor types each takes), and the gz-sim world
    systems that run the sensors of a type that have no gazebo_ros plugin (imported on first use)."""
    from .sensors import SENSOR_SYSTEMS

    plugins: dict[str, tuple[Callable[[], System], frozenset[str]]] = {}
    world: dict[str, dict[str, Callable[[], System]]] = {}
    for cls in SENSOR_SYSTEMS:
        for plugin, types in cls.classic_plugins.items():
            plugins[plugin] = (cls, types if types is not None else cls.sdf_types)
        for spelling in _gz_spellings(cls.gz_system, cls.gz_file) if cls.gz_system else ():
            world.setdefault(spelling, {}).update(dict.fromkeys(sorted(cls.sdf_types), cls))
    return plugins, world


SDF_SENSOR_TYPES = frozenset(
    {
        "air_pressure",
        "air_speed",
        "altimeter",
        "boundingbox_camera",
        "camera",
        "contact",
        "custom",
        "depth",
        "depth_camera",
        "force_torque",
        "gps",
        "gpu_lidar",
        "gpu_ray",
        "imu",
        "lidar",
        "logical_camera",
        "magnetometer",
        "multicamera",
        "navsat",
        "ray",
        "rfid",
        "rfidtag",
        "rgbd",
        "rgbd_camera",
        "segmentation",
        "segmentation_camera",
        "sonar",
        "thermal",
        "thermal_camera",
        "wide_angle_camera",
        "wireless_receiver",
        "wireless_transmitter",
    }
)
"""Every ``<sensor type>`` SDF knows (sdformat's sensor.sdf, 1.4 to 1.11)."""


def _sensor_type_problem(label: str, kind: str) -> str:
    """Why a sensor of ``kind`` does not run: not simulated yet, or not a sensor type at all."""
    if kind in SDF_SENSOR_TYPES:
        return f"{label} is not simulated yet"
    import difflib

    close = difflib.get_close_matches(kind, sorted(SDF_SENSOR_TYPES), n=1, cutoff=0.6)
    hint = f"; did you mean '{close[0]}'?" if close else ""
    return f"{label}: '{kind}' is not an SDF sensor type, so nothing runs it{hint}"


@dataclass(frozen=True)
class SensorPlan:
    """One sensor that will run: its link, the ``<sensor>``, the gazebo_ros plugin (None: gz-sim) and its system."""

    link: str
    sensor: Sensor
    plugin: Plugin | None
    make: Callable[[], System]


def _plugin_plans(
    link: str,
    sensor: Sensor,
    label: str,
    sensor_plugins: dict[str, tuple[Callable[[], System], frozenset[str]]],
    warn: Callable[[str, Any], None],
) -> list[SensorPlan]:
    """A sensor's plans through the gazebo_ros plugins inside it: one per plugin that publishes its type;
    a warning for each other plugin (unknown, or of another sensor type)."""
    plans = []
    for plugin in sensor.plugins:
        key = _normalise(plugin.filename) if _normalise(plugin.filename) in sensor_plugins else _normalise(plugin.name)
        entry = sensor_plugins.get(key)
        if entry is None:
            problem = plugin_problem(plugin)
            warn(f"{label}: {problem or f'plugin {plugin.filename} does not publish a sensor'}", plugin.location)
            continue
        make, types = entry
        if sensor.type not in types:
            if sensor.type not in SDF_SENSOR_TYPES:
                warn(_sensor_type_problem(label, sensor.type), sensor.location)
            else:
                warn(
                    f"{label}: plugin '{plugin.filename}' does not publish a {sensor.type} sensor; it is ignored",
                    plugin.location,
                )
            continue
        plans.append(SensorPlan(link, sensor, plugin, make))
    return plans


def plan_sensors(
    model: Model, world_plugins: tuple[Plugin, ...] | None = None
) -> tuple[list[SensorPlan], list[Diagnostic]]:
    """Which sensors of ``model`` run, and a warning naming each one that does not and why.

    A sensor runs through a gazebo_ros plugin inside it, or, without one and in a model that uses no
    gazebo_ros plugin (a gz-sim model), through the gz-sim world system for its type among
    ``world_plugins`` (None: not known, e.g. ``gazelle check`` of a model file; then no warning is
    given for that case).
    """
    sensor_plugins, gz_world_systems = _sensor_tables()
    gz_types: dict[str, Callable[[], System]] = {}
    for wp in world_plugins or ():
        for key in (_normalise(wp.filename), _normalise(wp.name)):
            gz_types.update(gz_world_systems.get(key, {}))
    plans: list[SensorPlan] = []
    out: list[Diagnostic] = []
    # a model with gazebo_ros plugins is a Gazebo Classic model: its sensors publish through their own
    # plugins only (gz-sim's world systems would add a second, gz-named topic Classic never had)
    classic = any(
        _normalise(p.filename).startswith("gazebo_ros")
        for p in (*model.plugins, *(q for lk in model.links for sn in lk.sensors for q in sn.plugins))
    )

    def warn(text: str, where: Any) -> None:
        out.append(Diagnostic(ErrorCode.ELEMENT_UNSUPPORTED, Severity.WARNING, text, where))

    for link in model.links:
        for sensor in link.sensors:
            label = f"sensor '{sensor.name}' ({sensor.type}) on link '{link.name}'"
            if sensor.plugins:  # through its own plugins; each one that does not publish it is warned about
                plans.extend(_plugin_plans(link.name, sensor, label, sensor_plugins, warn))
                continue
            make_gz = gz_types.get(sensor.type)
            if classic:
                warn(
                    f"{label} publishes nothing: it has no gazebo_ros plugin (as in Gazebo Classic, whose plugins "
                    "this model uses)",
                    sensor.location,
                )
            elif make_gz is not None:
                plans.append(SensorPlan(link.name, sensor, None, make_gz))
            elif any(sensor.type in types for types in gz_world_systems.values()):
                if world_plugins is not None:
                    system = next(
                        n for n, types in gz_world_systems.items() if sensor.type in types and n.startswith("gz-sim")
                    )
                    warn(
                        f"{label} publishes nothing: it has no gazebo_ros plugin and the world has no '{system}'",
                        sensor.location,
                    )
            else:
                warn(_sensor_type_problem(label, sensor.type), sensor.location)
    return plans, out


def supported_plugins() -> list[str]:
    """Plugin file names (normalised) with an implementation."""
    return sorted(_REGISTRY)


def plugin_factories() -> dict[str, Callable[[], System]]:
    """Every plugin name gazelle runs -> a factory of its system: the model and world plugins, then the
    gazebo_ros plugins that sit inside a ``<sensor>`` (the plugin reference, scripts/gen_plugin_docs.py)."""
    out = dict(_REGISTRY)
    out.update({name: factory for name, (factory, _types) in _sensor_tables()[0].items()})
    return out


def create_system(plugin: Plugin) -> System | None:
    """A new system for ``plugin``, or None if unsupported (:func:`audit_model` says why)."""
    factory = _REGISTRY.get(_normalise(plugin.filename)) or _REGISTRY.get(_normalise(plugin.name))
    return factory() if factory is not None else None


_CONTROL_PLUGINS = frozenset(
    {
        "gazebo_ros2_control",
        "gz_ros2_control-system",
        "gz_ros2_control::GazeboSimROS2ControlPlugin",
        "ign_ros2_control-system",
        "ign_ros2_control::IgnitionROS2ControlPlugin",
    }
)


# Plugins gazelle knows but does not simulate yet, and what to say about them.
_NOT_YET: dict[str, str] = {
    **{n: "sensors are not simulated yet" for n in ("gazebo_ros_range",)},
}

# gz-sim world systems whose work gazelle does itself: no warning.
BUILT_IN_WORLD_SYSTEMS = frozenset(
    {
        "gz-sim-physics-system",
        "gz::sim::systems::Physics",
        "ignition-gazebo-physics-system",
        "gz-sim-user-commands-system",
        "gz::sim::systems::UserCommands",
        "ignition-gazebo-user-commands-system",
        "gz-sim-scene-broadcaster-system",
        "gz::sim::systems::SceneBroadcaster",
        "ignition-gazebo-scene-broadcaster-system",
        "gazebo_ros_init",
        "gazebo_ros_factory",
        "gazebo_ros_state",
        "gazebo_ros_properties",
    }
)
"""Physics (MuJoCo), user commands and the factory (the spawn/delete/state services), the scene
broadcaster (the browser viewer), gazebo_ros's init/factory/state world plugins (/clock and the
classic services)."""


def _known_names() -> list[str]:
    sensor_plugins, gz_world_systems = _sensor_tables()
    return sorted({*_REGISTRY, *sensor_plugins, *gz_world_systems, *_NOT_YET, *BUILT_IN_WORLD_SYSTEMS})


_FAMILY_PARTS = ("gz::sim::systems::", "ignition::gazebo::systems::", "ignition-gazebo-", "gz-sim-", "gazebo_ros_")


def _core(name: str) -> str:
    """The part of a plugin name that tells plugins apart: ``gz-sim-lift-drag-system`` -> ``liftdrag``.
    Compared whole, every gz-sim system looks like every other (they share 15 of ~23 characters), and a
    LiftDrag was offered the DiffDrive (issue 26)."""
    from difflib import SequenceMatcher

    core = name.lower()
    for part in _FAMILY_PARTS:
        core = core.replace(part, "")
    core = core.removeprefix("lib").removesuffix(".so")
    head, dash, last = core.rpartition("-")
    if dash and SequenceMatcher(None, last, "system").ratio() >= 0.7:  # "-system", or a typo of it
        core = head
    return core.replace("-", "").replace("_", "").replace(":", "")


def _did_you_mean(plugin: Plugin) -> str:
    """A known name close to the plugin's, as a whole (cutoff 0.8) and in the part that tells plugins
    apart (0.7): a typo gets its plugin, another plugin of the same family does not."""
    from difflib import SequenceMatcher

    names = _known_names()
    for raw in (plugin.filename, plugin.name):
        key = _normalise(raw)
        scored = []
        for name in names:
            whole = SequenceMatcher(None, key, name).ratio()
            core = SequenceMatcher(None, _core(key), _core(name)).ratio()
            if whole >= 0.8 and core >= 0.7:
                scored.append((whole + core, name))
        if scored:
            return f"; did you mean '{_display(max(scored)[1])}'?"
    return ""


def _display(name: str) -> str:
    """A known name as users write it (``libgazebo_ros_diff_drive.so``)."""
    return f"lib{name}.so" if name.startswith("gazebo_ros") else name


def plugin_problem(plugin: Plugin, *, world: bool = False) -> str | None:
    """Why ``plugin`` will not run (unsupported, not yet, a likely typo), or None when it runs or is built in."""
    key_f, key_n = _normalise(plugin.filename), _normalise(plugin.name)
    if key_f in _REGISTRY or key_n in _REGISTRY or key_f == RSP_PLUGIN:
        return None  # (the built-in robot_state_publisher's options are read by the runtime)
    if key_f in BUILT_IN_WORLD_SYSTEMS or key_n in BUILT_IN_WORLD_SYSTEMS:
        return None
    label = f"{'world ' if world else ''}plugin '{plugin.name}' ({plugin.filename})"
    sensor_plugins, gz_world_systems = _sensor_tables()
    if world and {key_f, key_n} & set(gz_world_systems):
        return None
    if {key_f, key_n} & set(sensor_plugins):
        return f"{label} is ignored: a sensor plugin works only inside the <sensor> it publishes"
    why = _NOT_YET.get(key_f) or _NOT_YET.get(key_n)
    if why is not None:
        return f"{label} is ignored: {why}"
    return f"{label} is not supported; it is ignored{_did_you_mean(plugin)}"


def audit_model(model: Model, world_plugins: tuple[Plugin, ...] | None = None) -> list[Diagnostic]:
    """What of ``model`` will not be simulated: unsupported plugins (with a "did you mean") and sensors
    (see :func:`plan_sensors`; ``world_plugins`` are those of the world it goes into, if known)."""
    out: list[Diagnostic] = []
    for plugin in model.plugins:
        problem = plugin_problem(plugin)
        if problem is not None:
            out.append(Diagnostic(ErrorCode.PLUGIN_UNSUPPORTED, Severity.WARNING, problem, plugin.location))
    out.extend(plan_sensors(model, world_plugins)[1])
    if not model.ros2_control and any(
        _normalise(p.filename) in _CONTROL_PLUGINS or p.name in _CONTROL_PLUGINS for p in model.plugins
    ):
        plugin = next(
            p for p in model.plugins if _normalise(p.filename) in _CONTROL_PLUGINS or p.name in _CONTROL_PLUGINS
        )
        out.append(
            Diagnostic(
                ErrorCode.ELEMENT_UNSUPPORTED,
                Severity.WARNING,
                "the ros2_control plugin has no <ros2_control> block to control: no controller manager runs",
                plugin.location,
            )
        )
    return out


def audit_world(world: World) -> list[Diagnostic]:
    """:func:`audit_model` for every model of ``world``, and its world plugins."""
    out = [
        Diagnostic(ErrorCode.PLUGIN_UNSUPPORTED, Severity.WARNING, problem, p.location)
        for p in world.plugins
        if (problem := plugin_problem(p, world=True)) is not None
    ]
    for model in world.models:
        out.extend(audit_model(model, world.plugins))
    return out

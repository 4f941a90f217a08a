"""Which system runs a ``<plugin>`` or a ``<sensor>``, and a warning naming each one that does not run.

Nothing here is a table kept by hand: the plugin names come from the declarations of the systems that register
themselves in their own modules (``_registration.add_plugin``): ``plugin_files`` / ``gz_plugin``, and the sensor
classes' ``sdf_types`` / ``classic_plugins`` / ``gz_system``.
The rest is what to say about the others: not simulated yet, built in, or a likely typo of a known name."""

from __future__ import annotations

import functools
import logging
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, cast

from ..description import Diagnostic, ErrorCode, Model, Plugin, Sensor, Severity, World
from ._base import System
from ._plugin_names import RSP_PLUGIN
from ._registration import registered

if TYPE_CHECKING:
    from .sensors import SensorClass

_log = logging.getLogger("gazelle.systems")


def normalised(filename: str) -> str:
    """``libgazebo_ros_diff_drive.so`` -> ``gazebo_ros_diff_drive``; keeps gz names."""
    name = filename.strip()
    name = re.sub(r"^lib", "", name)
    name = re.sub(r"\.(so|dylib|dll)$", "", name)
    return name


def _kebab(name: str) -> str:
    """``JointPositionController`` -> ``joint-position-controller`` (gz-sim's file names)."""
    return re.sub(r"(?<!^)(?=[A-Z])", "-", name).lower()


def plugin_names(cls: type[System]) -> tuple[str, ...]:
    """Every plugin name that runs ``cls``: its :attr:`~System.plugin_files`, then the gz-sim and Ignition
    spellings of its :attr:`~System.gz_plugin`. Declared on the class itself: a subclass (gz-sim's joint
    state publisher of gazebo_ros's) answers to its own names, not its base's."""
    own = vars(cls)
    gz_plugin, gz_file = own.get("gz_plugin", ""), own.get("gz_plugin_file", "")
    gz = _gz_spellings(gz_plugin, gz_file or _kebab(gz_plugin)) if gz_plugin else ()
    return (*own.get("plugin_files", ()), *gz)


def is_sensor(cls: type[System]) -> bool:
    """Whether ``cls`` runs ``<sensor>`` elements: it declares the ``sdf_types`` it simulates."""
    return bool(getattr(cls, "sdf_types", None))


def plugin_table(classes: Iterable[type[System]] | None = None) -> dict[str, type[System]]:
    """Plugin name -> system class, from the declarations of ``classes`` (None: every registered system,
    :func:`~._registration.add_plugin`).

    Raises:
        ValueError: a class that declares neither a plugin name nor a sensor type, or two classes that declare
            the same name.
    """
    out: dict[str, type[System]] = {}
    for cls in registered() if classes is None else classes:
        names = plugin_names(cls)
        if not names and not is_sensor(cls):
            raise ValueError(
                f"{cls.__module__}.{cls.__qualname__} declares no plugin name (plugin_files or gz_plugin) "
                "and no sensor type (sdf_types)"
            )
        for name in names:
            if name in out:
                raise ValueError(f"plugin name '{name}' is declared by {out[name].__name__} and {cls.__name__}")
            out[name] = cls
    return out


@functools.cache
def _registry() -> dict[str, type[System]]:
    return plugin_table()


def _gz_spellings(name: str, file: str = "") -> tuple[str, ...]:
    """Every way a world names gz-sim's system ``name`` (``Imu``): gz and Ignition, file (``file``, else the
    lower-case name) and class.

    Worlds written for Fortress say ``ignition-gazebo-imu-system`` / ``ignition::gazebo::systems::Imu``,
    those for Garden on ``gz-sim-imu-system`` / ``gz::sim::systems::Imu``; gz-sim 8 still loads the
    Ignition names, so gazelle answers to all four."""
    kebab = file or name.lower()
    return (
        f"gz-sim-{kebab}-system",
        f"gz::sim::systems::{name}",
        f"ignition-gazebo-{kebab}-system",
        f"ignition::gazebo::systems::{name}",
    )


def sensor_classes() -> list[SensorClass]:
    """Every registered sensor kind (a class that declares ``sdf_types``), by module."""
    return [cast("SensorClass", cls) for cls in registered() if is_sensor(cls)]


@functools.cache
def _sensor_tables() -> tuple[
    dict[str, tuple[Callable[[], System], frozenset[str]]], dict[str, dict[str, Callable[[], System]]]
]:
    """From every sensor class's declaration (:func:`sensor_classes`): the gazebo_ros plugins that sit inside a
    ``<sensor>`` (the system and the sensor types each takes), and the gz-sim world systems that run the sensors
    of a type that have no gazebo_ros plugin."""
    plugins: dict[str, tuple[Callable[[], System], frozenset[str]]] = {}
    world: dict[str, dict[str, Callable[[], System]]] = {}
    for cls in sensor_classes():
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
    a warning for each other plugin (unknown, or of another sensor type).

    In Gazebo Classic a sensor publishes nothing by itself: each ``<plugin>`` inside it makes one ROS
    interface of it (a ray sensor with gazebo_ros_ray_sensor publishes LaserScan or PointCloud2 as its
    ``<output_type>`` says; two plugins, two topics). A plugin is found by its file name first, then by its
    ``name`` attribute. A plugin that exists but for another sensor type (a camera plugin in an IMU) is
    warned about rather than run on data it was not written for."""
    plans = []
    for plugin in sensor.plugins:
        key = normalised(plugin.filename) if normalised(plugin.filename) in sensor_plugins else normalised(plugin.name)
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
    gazebo_ros plugin (a gz-sim model), through the gz-sim system for its type among ``world_plugins``
    (None: not known, e.g. ``gazelle check`` of a model file; then no warning is given for that case)
    or among the model's own plugins. gz-sim loads a ``<plugin>`` of a model as it does one of the world
    (gz-sim8 ``SdfEntityCreator::LoadModelPlugins`` -> ``SimulationRunner::LoadPlugins`` ->
    ``SystemManager::LoadPlugin``, the model as its entity), and its sensor systems ignore that entity
    (``Sensors::Configure``, ``ImuPrivate::CreateSensors`` take every sensor of their type), so a robot that
    carries ``gz-sim-sensors-system`` runs its sensors in a world without one. (In gz-sim such a system
    runs the other models' sensors too; here it runs its own model's.)
    """
    sensor_plugins, gz_world_systems = _sensor_tables()
    gz_types: dict[str, Callable[[], System]] = {}
    for wp in (*(world_plugins or ()), *model.plugins):
        for key in (normalised(wp.filename), normalised(wp.name)):
            gz_types.update(gz_world_systems.get(key, {}))
    plans: list[SensorPlan] = []
    out: list[Diagnostic] = []
    # a model with gazebo_ros plugins is a Gazebo Classic model: its sensors publish through their own
    # plugins only (gz-sim's world systems would add a second, gz-named topic Classic never had)
    classic = any(
        normalised(p.filename).startswith("gazebo_ros")
        for p in (*model.plugins, *(q for lk in model.links for sn in lk.sensors for q in sn.plugins))
    )

    def warn(text: str, where: Any) -> None:
        out.append(Diagnostic(ErrorCode.ELEMENT_UNSUPPORTED, Severity.WARNING, text, where))

    # per sensor, the first rule that applies: its own plugins; a Classic model's sensor without one
    # publishes nothing (said); a gz-sim world system for its type; a known type whose world system the
    # world lacks (said, naming the system to add); a type gazelle does not simulate (said)
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
    return sorted(_registry())


def plugin_factories() -> dict[str, Callable[[], System]]:
    """Every plugin name gazelle runs -> a factory of its system: the model and world plugins, then the
    gazebo_ros plugins that sit inside a ``<sensor>`` (the plugin reference, scripts/gen_plugin_docs.py)."""
    out: dict[str, Callable[[], System]] = dict(_registry())
    out.update({name: factory for name, (factory, _types) in _sensor_tables()[0].items()})
    return out


def system_class(plugin: Plugin) -> type[System] | None:
    """The system class that runs a model or world ``<plugin>`` (by its file name, else its name), or None."""
    registry = _registry()
    return registry.get(normalised(plugin.filename)) or registry.get(normalised(plugin.name))


def create_system(plugin: Plugin) -> System | None:
    """A new system for ``plugin``, or None if unsupported (:func:`audit_model` says why)."""
    cls = system_class(plugin)
    return cls() if cls is not None else None


def _control_plugins() -> frozenset[str]:
    """The names of ros2_control's simulator plugins (the controller manager's declaration)."""
    from .ros2_control import ControllerManager

    return frozenset(plugin_names(ControllerManager))


# Plugins gazelle knows but does not simulate yet, and what to say about them.
_NOT_YET: dict[str, str] = {}

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
    return sorted({*_registry(), *sensor_plugins, *gz_world_systems, *_NOT_YET, *BUILT_IN_WORLD_SYSTEMS})


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
        key = normalised(raw)
        scored = []
        for name in names:
            if name == key:
                continue  # the name it already has: the reason it is refused is not a typo
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
    key_f, key_n = normalised(plugin.filename), normalised(plugin.name)
    registry = _registry()
    if key_f in registry or key_n in registry or key_f == RSP_PLUGIN:
        return None  # (the built-in robot_state_publisher's options are read by the runtime)
    if key_f in BUILT_IN_WORLD_SYSTEMS or key_n in BUILT_IN_WORLD_SYSTEMS:
        return None
    label = f"{'world ' if world else ''}plugin '{plugin.name}' ({plugin.filename})"
    sensor_plugins, gz_world_systems = _sensor_tables()
    if {key_f, key_n} & set(gz_world_systems):
        return None  # a world's or a model's (gz-sim loads both; :func:`plan_sensors` runs its sensors)
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
    control = _control_plugins()
    if not model.ros2_control and any(normalised(p.filename) in control or p.name in control for p in model.plugins):
        plugin = next(p for p in model.plugins if normalised(p.filename) in control or p.name in control)
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

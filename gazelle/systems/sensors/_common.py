"""What every sensor shares: noise, rates, the output's topic, frame and message (gazebo_ros and gz-sim
naming), the base class with its rate gate, and what a sensor kind declares (:class:`SensorClass`).

A sensor's life, whichever kind it is:

* **Chosen.** ``systems/_registry.py`` plans one system per ``<sensor>``: a gazebo_ros plugin inside it
  (``classic_plugins``) makes it publish as that plugin does; else a gz-sim world system that simulates
  the kind (``gz_system``: ``Sensors``, ``Imu``, ...) makes it publish on gz-sim's topic; else it is warned
  about and not simulated. The tables come from the classes' declarations (:class:`SensorClass`).
* **Configured** (:meth:`_SensorSystem._configure_common`): its link, its pose on the link, its rate
  (:func:`checked_rate`), where it publishes (:func:`sensor_output`: topic, frame_id, message type) and
  its noise (:func:`parse_noise`). A block that cannot be simulated raises :class:`SensorConfigError`,
  which the runtime reports with file:line and leaves the sensor out; the rest of the model runs.
* **Run** in ``post_update``, after the physics step, at its rate in sim time (a :class:`RateGate`, so
  sensors of one rate fall on the same steps and the world steps inside MuJoCo between them), only
  while its topic has a subscriber, and never while paused.

Noise follows gz-sensors' Gaussian model: a per-reading N(mean, stddev) plus a bias drawn once per
channel. Each sensor has its own random stream, seeded from the run's ``--seed``, its entity's name and
its own, so a run with a seed repeats bit for bit and a spawn does not change another sensor's noise.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar, Protocol, Self, TypeVar

import numpy as np

from ..._errors import SimError
from ...description import (
    ConfigElement,
    Plugin,
    Pose,
    Sensor,
)
from ...physics import BodyHandle, PhysicsWorld
from .._base import RateGate, System, SystemContext, UpdateInfo
from .._bus import (
    Endpoint,
    MessageKind,
    MsgType,
    ParamValue,
    resolve_topic,
)
from .._frames import entity_frame_prefix
from .._plugin_config import child_text, parse_float, ros_block

T = TypeVar("T")


class SensorClass(Protocol):
    """A sensor system's class, as it registers itself (``add_plugin(Lidar)`` at the bottom of its module). It
    declares, as class attributes:

    * ``sdf_types``: the ``<sensor type>`` values it simulates;
    * ``classic_plugins``: the gazebo_ros plugins (file names without ``lib``/``.so``) that publish it from
      inside its ``<sensor>``, each with the sensor types it takes (None: all of ``sdf_types``);
    * ``gz_system``: the gz-sim world system that runs it when a model has no gazebo_ros plugin, by its
      class name (``Sensors``, ``Imu``, ...): ``gz-sim-<name>-system``, ``gz::sim::systems::<Name>`` and
      the Ignition spellings all name it (``gz_file``: the file's part, where it is not the lower-case
      name: ``air-pressure``);
    * ``output_kind`` (the gz-sim topic's suffix) and, for a message of its own, ``output_message``.
    """

    sdf_types: frozenset[str]
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]]
    gz_system: str
    gz_file: str

    def __call__(self) -> System: ...


SENSOR_DEPTH = 5
"""Publisher history of every sensor topic: SensorDataQoS's depth 5, made reliable as gazebo_ros does."""

NOISE_ROWS = 256
"""An IMU draws its noise for this many readings at once (the same random stream as one draw a reading)."""


# --------------------------------------------------------------------------- noise
@dataclass(frozen=True)
class Noise:
    """``<noise>``: Gaussian with ``mean`` and ``stddev``, plus a bias drawn once from
    N(``bias_mean``, ``bias_stddev``). ``type`` none means exact readings."""

    type: str = "none"
    """``<noise type>``: none or gaussian (gaussian_quantized runs as gaussian; other types are warned about and
    their readings are exact)."""
    mean: float = 0.0
    """Added to every reading, in the reading's unit (m for a range, rad/s for a gyro, ...)."""
    stddev: float = 0.0
    """Standard deviation of each reading's N(0, stddev²) term, in the reading's unit."""
    bias_mean: float = 0.0
    """Mean magnitude of the constant bias (its sign is drawn; see :meth:`bias`)."""
    bias_stddev: float = 0.0
    """Spread of the bias drawn once per channel and run."""

    @property
    def active(self) -> bool:
        """Whether readings are changed at all."""
        return self.type != "none" and (self.mean, self.stddev, self.bias_mean, self.bias_stddev) != (0, 0, 0, 0)

    def bias(self, rng: np.random.Generator) -> float:
        """The constant bias of one sensor channel: |N(bias_mean, bias_stddev)| with a random sign."""
        if not self.active or (self.bias_mean == 0 and self.bias_stddev == 0):
            return 0.0
        b = rng.normal(self.bias_mean, self.bias_stddev) if self.bias_stddev > 0 else self.bias_mean
        return float(b if rng.random() < 0.5 else -b)


SIMULATED_NOISE = frozenset({"none", "gaussian"})


def parse_noise(el: ConfigElement | None, log: logging.Logger, what: str) -> Noise:
    """A ``<noise>`` element, its type as an attribute (IMU channels) or a ``<type>`` child (rays).

    As gz-sensors' GaussianNoiseModel: each reading gets ``mean`` plus N(0, ``stddev``²), and a bias drawn
    once per channel and run (see :meth:`Noise.bias`). What gazelle does not model is said once, naming the
    element: ``gaussian_quantized`` runs without its quantization, another type reads exactly, and
    ``<dynamic_bias_*>`` (a bias that wanders) and ``<precision>`` are not simulated. The draws come from
    the system's seeded stream, so a run with the same seed repeats its noise bit for bit."""
    if el is None:
        return Noise()
    kind = (el.attr("type") or child_text(el, "type") or "none").strip().lower()
    where = f"{el.location}: " if el.location else ""
    if kind == "gaussian_quantized":
        log.warning(f"{where}{what}: noise type 'gaussian_quantized' is simulated as 'gaussian' (no quantization)")
        kind = "gaussian"
    elif kind not in SIMULATED_NOISE:
        log.warning(f"{where}{what}: noise type '{kind}' is not simulated; readings are exact")
        return Noise()
    for tag in ("dynamic_bias_stddev", "dynamic_bias_correlation_time", "precision"):
        if el.find(tag) is not None:
            log.warning(f"{where}{what}: <{tag}> is not simulated")
    return Noise(
        kind,
        parse_float(el, "mean", 0.0, log),
        parse_float(el, "stddev", 0.0, log),
        parse_float(el, "bias_mean", 0.0, log),
        parse_float(el, "bias_stddev", 0.0, log),
    )


class SensorConfigError(SimError, ValueError):
    """A sensor's configuration that cannot be simulated (the message names the file:line)."""


class SensorLimitError(SensorConfigError):
    """A sensor past one of gazelle's bounds (rays, image size, rate): the spawn is refused with the reason,
    never accepted with the sensor quietly off."""


def faster_than_step(rate: float, step_sec: float) -> bool:
    """Whether ``rate`` (Hz) is faster than physics steps of ``step_sec`` can sample (0: no step known)."""
    return step_sec > 0 and rate > 1.0 / step_sec * (1 + 1e-9)


def checked_rate(rate: float, step_sec: float, where: str, what: str, log: logging.Logger) -> float:
    """A sensor's ``update_rate`` (Hz of sim time; 0 = every step, as SDF says) as it will run.

    A rate faster than the physics steps cannot be met: it is every step, and is bounded to the step
    rate with a warning naming it.

    Raises:
        SensorLimitError: a negative, NaN or infinite rate.
    """
    if not math.isfinite(rate) or rate < 0:
        raise SensorLimitError(f"{where}{what}: <update_rate> must be a number >= 0 Hz (0: every step), got {rate!r}")
    if faster_than_step(rate, step_sec):
        log.warning(
            f"{where}{what}: <update_rate> {rate:g} Hz is faster than the physics step ({1.0 / step_sec:g} Hz); "
            "it runs every step"
        )
        return 1.0 / step_sec
    return rate


# --------------------------------------------------------------------------- where a sensor publishes
@dataclass(frozen=True)
class Output:
    """Where and how a sensor publishes: the ROS topic, the frame_id and (rays) the message type."""

    topic: str
    frame_id: str
    msg_type: MessageKind
    radiation_type: int = 1
    min_intensity: float = -math.inf


def gz_scoped_topic(ctx: SystemContext, link: str, sensor: Sensor, suffix: str) -> str:
    """gz-sim's topic for a sensor without ``<topic>``."""
    return f"/world/{ctx.world_name}/model/{ctx.entity.name}/link/{link}/sensor/{sensor.name}/{suffix}"


# A kind whose plugin has settings of its own subclasses SensorPluginConfig in its own module and names the subclass
# in its class's ``plugin_config`` (the lidar's RayPluginConfig, the IMU's ImuPluginConfig, the camera's
# CameraPluginConfig), overriding ``settings`` to read them and, where its output differs, ``plugin_topic``,
# ``message_type`` or ``output``: nothing here knows a kind or a plugin's file name.
@dataclass(frozen=True)
class SensorPluginConfig:
    """What every gazebo_ros sensor plugin (inside a ``<sensor>``) is configured with: where it publishes and in
    which frame, ROS 2's names and ROS 1's. Without a plugin (a gz-sim model), the sensor's own ``<topic>`` and
    ``<frame_id>``/``<gz_frame_id>`` apply."""

    frame_name: str = ""
    """``<frame_name>`` (ROS 1: ``<frameName>``): the header's frame_id; default the sensor's link."""
    topic: str = "~/out"
    """``~/out`` in ROS 2 (rename it with ``<ros><remapping>~/out:=scan``, or Dashing's
    ``<argument>~/out:=scan``); ROS 1: ``<topicName>``."""
    namespace: str = ""
    """``<ros><namespace>`` (ROS 1: ``<robotNamespace>``); default the entity's namespace."""
    remappings: tuple[tuple[str, str], ...] = ()
    """``<ros><argument>from:=to`` and ``<ros><remapping>from:=to``, as gazebo_ros gives them to rcl."""
    body_name: str = ""
    """A ROS 1-era model plugin without a ``<sensor>`` (``<bodyName>``): the link it measures; read by the kinds
    whose plugin has that form (the IMU)."""
    update_rate: float = 0.0
    """A ROS 1 plugin's ``<updateRate>``, Hz of sim time (0: every step), which every ROS 1 sensor plugin has: the
    IMU's model plugin and the range plugin run at it; sensors use their ``<update_rate>``."""

    @classmethod
    def read(cls, ctx: SystemContext) -> Self:
        """The settings of the plugin ``ctx`` configures (defaults, in the entity's namespace, without one)."""
        if ctx.plugin is None or ctx.plugin.config is None:
            return cls(namespace=ctx.entity.namespace)
        return cls(**cls.settings(ctx.plugin, ctx.plugin.config, ctx))

    @classmethod
    def settings(cls, plugin: Plugin, cfg: ConfigElement, ctx: SystemContext) -> dict[str, Any]:
        """The fields read from the plugin's block ``cfg`` (a subclass adds its own to these)."""
        ns, remaps = ros_block(cfg)
        return {
            "frame_name": child_text(cfg, "frame_name") or child_text(cfg, "frameName") or "",
            "topic": child_text(cfg, "topicName") or "~/out",
            "namespace": ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace,
            "remappings": tuple(remaps.items()),
            "update_rate": parse_float(cfg, "updateRate", 0.0, ctx.logger),
        }

    def plugin_topic(self, ctx: SystemContext, sensor: Sensor | None) -> str:
        """The ROS topic it publishes on: its ``topic`` under its node's namespace and remappings."""
        node = ctx.plugin.name if ctx.plugin is not None else ""
        return resolve_topic(self.topic, self.namespace, dict(self.remappings), node=node)

    def message_type(self, ctx: SystemContext, default: MessageKind) -> MessageKind:
        """The message it publishes: the kind's own (a ray sensor's follows its ``<output_type>``)."""
        return default

    def output(self, topic: str, frame_id: str, msg_type: MessageKind) -> Output:
        """The :class:`Output` of these settings (a range sensor's adds its radiation type)."""
        return Output(topic, frame_id, msg_type)


OUTPUT_MESSAGES = {
    "scan": MsgType.LASER_SCAN,
    "imu": MsgType.IMU,
    "image": MsgType.IMAGE,
    "magnetometer": MsgType.MAGNETIC_FIELD,
    "altimeter": MsgType.ALTIMETER,
    "contact": MsgType.CONTACTS,
    "navsat": MsgType.NAV_SAT_FIX,
}
"""A sensor's ``output_kind`` (its gz-sim topic's suffix) -> the message it publishes by default."""


def sensor_output(
    ctx: SystemContext,
    link: str,
    sensor: Sensor | None,
    kind: str,
    c: SensorPluginConfig,
    message: MessageKind | None = None,
) -> Output:
    """Resolve the topic, frame and message type of a sensor (``kind``: ``scan``, ``imu`` or ``image``), from its
    gazebo_ros plugin's parameters ``c`` or, without a plugin, as gz-sim names it.

    gz-sim: the sensor's ``<topic>``, else its scoped name ``/world/<w>/model/<m>/link/<l>/sensor/<s>/<kind>``
    (``depth_image`` for a depth camera), in ``<frame_id>`` (``<gz_frame_id>`` in older files), else
    gz's scoped frame ``<model>::<link>::<sensor>``, which no TF tree has: a user who wants TF names one.
    gazebo_ros: the plugin's topic under its node's namespace and remappings, in ``<frame_name>``, else the
    link, as the kind's settings ``c`` (:class:`SensorPluginConfig` or its own subclass) say. Frames get the
    robot's frame prefix (its namespace) as the robot's TF does."""

    log = ctx.logger
    prefix = entity_frame_prefix(ctx.entity, log)
    default_type = message if message is not None else OUTPUT_MESSAGES[kind]
    if ctx.plugin is None:  # gz-sim: <topic> and <frame_id>
        assert sensor is not None
        cfg = sensor.config
        suffix = "depth_image" if kind == "image" and sensor.type in ("depth", "depth_camera") else kind
        topic = sensor.topic or gz_scoped_topic(ctx, link, sensor, suffix)
        frame = child_text(cfg, "frame_id") or child_text(cfg, "gz_frame_id")
        frame = prefix + frame if frame else f"{ctx.entity.name}::{link}::{sensor.name}"
        return Output(resolve_topic(topic, ctx.entity.namespace), frame, default_type)
    return c.output(c.plugin_topic(ctx, sensor), prefix + (c.frame_name or link), c.message_type(ctx, default_type))


# --------------------------------------------------------------------------- systems
class _SensorSystem(System):
    """What the lidar and the IMU share: the link, the pose on it, the rate gate and the publisher."""

    kind = ""
    """How log lines name it."""
    output_kind = "scan"
    """Its output as :func:`sensor_output` resolves it: the gz-sim topic's suffix and the default message."""
    sdf_types: frozenset[str] = frozenset()
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = ""
    gz_file = ""
    plugin_config: ClassVar[type[SensorPluginConfig]] = SensorPluginConfig
    """The settings its gazebo_ros plugins take: :class:`SensorPluginConfig`, or a subclass in the kind's module."""
    output_message: ClassVar[MessageKind | None] = None
    """The message it publishes, when not its ``output_kind``'s in :data:`OUTPUT_MESSAGES` (a
    :class:`DeclaredMessage` of its own module)."""

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured sensor: no link yet, a rate gate and its own random stream (``seed``)."""
        self.sensor: Sensor | None = None
        self.link = ""
        self.offset = Pose()
        """X_LS: the sensor in its link's frame."""
        self.rate_hz = 0.0
        self.output: Output | None = None
        self.config = self.plugin_config()
        self._pub: Endpoint | None = None
        self._body: BodyHandle | None = None
        self._gate = RateGate()
        self.phase_gate = self._gate  # post_update does nothing while the gate is not due
        self._rng = np.random.default_rng(seed)
        self._step_sec = 0.0

    def seed_noise(self, seed: int) -> None:
        self._rng = np.random.default_rng(seed)

    def node_parameters(self) -> dict[str, ParamValue]:
        """A gazebo_ros sensor plugin's node shows the sensor's rate as ``update_rate``."""
        return {"update_rate": float(self.rate_hz)}

    def parameter_setters(self) -> dict[str, Callable[[ParamValue], str | None]]:
        """``update_rate`` can be changed at run time (as gazebo_ros_camera allows; decided for every sensor)."""
        return {"update_rate": self._set_rate}

    def _set_rate(self, value: ParamValue) -> str | None:
        """``ros2 param set <plugin node> update_rate``: a number of Hz >= 0 no faster than the physics step,
        applied from the next step; the refusal's reason otherwise."""
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= 0 or not math.isfinite(value):
            return f"must be a number >= 0 (Hz; 0: every step), got {value!r}"
        step = self._step_sec
        if faster_than_step(float(value), step):
            return f"{value:g} Hz is faster than the physics step ({1.0 / step:g} Hz)"
        self.rate_hz = float(value)
        self._gate.reset()
        return None

    def _parse_sensor(
        self, ctx: SystemContext, sensor_type: str, parse: Callable[[Sensor, logging.Logger], T]
    ) -> T | None:
        """``parse(sensor, logger)`` of the ``<sensor>`` this plugin sits in; None, after an error that
        names why and where, when there is no sensor or its configuration cannot be simulated."""
        if ctx.sensor is None:
            where = f"{ctx.plugin.location}: " if ctx.plugin and ctx.plugin.location else ""
            ctx.logger.error(
                f"{where}a {self.kind} plugin must be inside a <sensor type='{sensor_type}'>; it does nothing"
            )
            return None
        try:
            return parse(ctx.sensor, ctx.logger)
        except SensorLimitError:
            raise  # past a bound: the spawn is refused with the reason
        except SensorConfigError as err:
            ctx.logger.error(f"{err}; the sensor does nothing")
            return None

    def _configure_common(self, ctx: SystemContext, *, advertise: bool = True) -> bool:
        """Read link, pose, rate and output (and declare the output topic unless ``advertise`` is False);
        False (after an error naming why) when it cannot run.

        A sensor is configured one of two ways. Inside a ``<sensor>`` (SDF, or URDF's ``<gazebo
        reference>``): the link is the sensor's, its pose the offset from it, its rate ``<update_rate>``.
        As a ROS 1-era model plugin without a ``<sensor>`` (gazebo_ros's IMU plugin with ``<bodyName>`` and
        ``<updateRate>``, as TurtleBot3's Noetic files have it): the link is ``<bodyName>``, no offset, the
        plugin's rate. Either way the topic and frame follow the plugin's or gz-sim's rules
        (:func:`sensor_output`), and a link the model lacks, or no link at all, leaves the sensor doing
        nothing with an error naming the file and line."""
        log = ctx.logger
        self.sensor, link = ctx.sensor, ctx.link
        self.config = c = self.plugin_config.read(ctx)
        if self.sensor is None:
            if not c.body_name:
                where = f"{ctx.plugin.location}: " if ctx.plugin and ctx.plugin.location else ""
                log.error(
                    f"{where}a {self.kind} plugin must be inside a <sensor> or name a <bodyName>; it does nothing"
                )
                return False
            link = c.body_name
            where = f"{ctx.plugin.location}: " if ctx.plugin and ctx.plugin.location else ""
            self.rate_hz = checked_rate(c.update_rate, ctx.world.timestep, where, f"{self.kind} plugin", log)
        else:
            self.offset = self.sensor.pose
            where = f"{self.sensor.location}: " if self.sensor.location else ""
            self.rate_hz = checked_rate(
                self.sensor.update_rate_hz, ctx.world.timestep, where, f"sensor '{self.sensor.name}'", log
            )
        self._step_sec = ctx.world.timestep
        if link not in {lk.name for lk in ctx.entity.model.links}:
            log.error(f"{self.kind} sensor: link '{link}' does not exist in '{ctx.entity.name}'; it does nothing")
            return False
        self.link = link or ""
        self.output = sensor_output(ctx, self.link, self.sensor, self.output_kind, c, self.output_message)
        self._body = ctx.world.body(ctx.entity.name, self.link)
        if advertise:
            self._pub = ctx.bus.advertise(ctx.entity.name, self.output.topic, self.output.msg_type, depth=SENSOR_DEPTH)
        return True

    def next_update(self, sim_time_sec: float) -> float:
        """The next scan time (never, when the sensor could not be configured)."""
        return self._gate.next if self._pub is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Measure again at the next step after a world reset."""
        self._gate.reset()

    def _due(self, info: UpdateInfo) -> bool:
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.rate_hz):
            return False
        return self._pub.wanted

    def sensor_pose(self) -> Pose:
        """X_WS: the sensor's world pose now."""
        assert self._body is not None
        return self._body.pose * self.offset


# --------------------------------------------------------------------------- GPS


def xyz_noise(el: ConfigElement | None, log: logging.Logger, what: str) -> tuple[Noise, Noise, Noise]:
    """``<x>``, ``<y>``, ``<z>`` each with a ``<noise type>`` (SDF 1.5+)."""
    out = []
    for ax in "xyz":
        a = el.find(ax) if el is not None else None
        out.append(parse_noise(a.find("noise") if a is not None else None, log, f"{what} {ax}"))
    return out[0], out[1], out[2]

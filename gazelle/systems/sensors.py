"""Sensors: lidars and rays, and IMUs, published as gazebo_ros's plugins and gz-sim's sensors publish them.

Each sensor is a :class:`System` made for one ``<sensor>`` of a link (or, for ROS 1's
``libgazebo_ros_imu.so``, for a model plugin naming a ``<bodyName>``):

* **gazebo_ros** (Gazebo Classic): a ``<plugin>`` inside the ``<sensor>`` publishes it on ``~/out``,
  which is ``/<ns>/<plugin name>/out`` unless ``<ros><remapping>~/out:=scan</remapping>`` renames it,
  in ``<frame_name>`` (else the sensor's link). ``libgazebo_ros_ray_sensor.so`` takes ``<output_type>``
  (``sensor_msgs/PointCloud2`` by default, ``LaserScan`` or ``Range``), ``<radiation_type>`` and
  ``<min_intensity>``; ``libgazebo_ros_imu_sensor.so`` takes ``<initial_orientation_as_reference>``.
  ROS 1's names (``libgazebo_ros_laser.so`` with ``<topicName>``/``<frameName>``, the
  ``libgazebo_ros_imu.so`` model plugin) are read too.
* **gz-sim**: with the world's ``gz-sim-sensors-system`` (lidars) or ``gz-sim-imu-system`` (IMUs), a
  sensor publishes on its ``<topic>`` (relative names under the entity's namespace), else on
  ``/world/<w>/model/<m>/link/<l>/sensor/<s>/scan|imu``, in ``<frame_id>``/``<gz_frame_id>``, else the
  scoped ``<model>::<link>::<sensor>``; the ROS topic has the gz topic's name, as ros_gz_bridge maps it.

Measurements are taken at the sim time they are stamped with, at the sensor's ``<update_rate>`` (0:
every step) through the runtime's rate gate, and only while someone listens. Rays are cast in one
``mj_multiRay`` call against collision geoms, excluding the sensor's own link; readings beyond the
maximum range are +inf and nearer than the minimum -inf (REP 117). The IMU reads its link's proper
acceleration (+g upwards at rest) and angular velocity in its own frame. Gaussian noise (``mean``,
``stddev``; ``bias_mean``/``bias_stddev`` drawn once, with a random sign, as gz-sensors does) is
applied as configured; any other noise type is warned about with its file:line and left out.
"""

from __future__ import annotations

import dataclasses
import logging
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import ClassVar, Protocol, TypeVar, cast

import numpy as np

from ..description import (
    ConfigElement,
    Pose,
    Sensor,
    SphericalCoordinates,
    quat_conj,
    quat_mul,
    rotation_matrix,
)
from ..physics import BodyHandle, OffscreenRenderer, PerGeneration, PhysicsWorld, RenderError
from ._base import RateGate, System, SystemContext, UpdateInfo, child_text, parse_bool, parse_float, ros_block
from ._bus import (
    Altimeter,
    CameraInfo,
    ContactPair,
    Contacts,
    Endpoint,
    Image,
    Imu,
    LaserScan,
    MagneticField,
    MsgType,
    NavSatFix,
    ParamValue,
    PointCloud,
    Range,
    Vec3,
    Vector3Stamped,
    WrenchStamped,
    resolve_topic,
)

T = TypeVar("T")

LIDAR_TYPES = frozenset({"ray", "gpu_ray", "lidar", "gpu_lidar"})
"""``<sensor type>`` values cast as rays (Gazebo's ``gpu_*`` variants see visuals; here all see collisions)."""
CAMERA_TYPES = frozenset({"camera", "depth", "depth_camera", "rgbd_camera", "rgbd"})
DEPTH_TYPES = frozenset({"depth", "depth_camera", "rgbd_camera", "rgbd"})


class SensorClass(Protocol):
    """A sensor system's class, as :func:`sensor_system` registers it."""

    sdf_types: frozenset[str]
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]]
    gz_system: str

    def __call__(self) -> System: ...


SENSOR_SYSTEMS: list[SensorClass] = []
"""Every sensor kind gazelle simulates, each declaring what runs it (see :func:`sensor_system`); the plugin
registry derives its tables from these declarations."""

S = TypeVar("S", bound=type)


def sensor_system(cls: S) -> S:
    """Register a sensor class. It declares, as class attributes:

    * ``sdf_types``: the ``<sensor type>`` values it simulates;
    * ``classic_plugins``: the gazebo_ros plugins (file names without ``lib``/``.so``) that publish it from
      inside its ``<sensor>``, each with the sensor types it takes (None: all of ``sdf_types``);
    * ``gz_system``: the gz-sim world system that runs it when a model has no gazebo_ros plugin, by its
      class name (``Sensors``, ``Imu``, ...): ``gz-sim-<name>-system``, ``gz::sim::systems::<Name>`` and
      the Ignition spellings all name it.
    """
    SENSOR_SYSTEMS.append(cast(SensorClass, cls))
    return cls


MAX_RAYS = 1_048_576
"""The most rays one lidar scan may cast: twice a 128 x 4096 automotive lidar (524,288). A scan of
2,000,000 rays ran the world at 0.035 of real time with 5 s between clocks."""
MAX_IMAGE_SIDE = 4096
"""The widest and tallest camera image (4K; 8192 x 8192 fills a 256 MB buffer a frame)."""

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
    mean: float = 0.0
    stddev: float = 0.0
    bias_mean: float = 0.0
    bias_stddev: float = 0.0

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
    """A ``<noise>`` element, its type as an attribute (IMU channels) or a ``<type>`` child (rays)."""
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


# --------------------------------------------------------------------------- lidar geometry
@dataclass(frozen=True)
class ScanAxis:
    """One axis of ``<scan>``: ``samples`` x ``resolution`` rays from ``min_angle`` to ``max_angle``."""

    samples: int = 1
    resolution: float = 1.0
    min_angle: float = 0.0
    max_angle: float = 0.0

    @property
    def count(self) -> int:
        """Readings on this axis (SDF: ``resolution`` multiplies ``samples``)."""
        return max(1, round(self.samples * self.resolution))

    def angles(self) -> np.ndarray:
        """The ray angles, both ends included."""
        if self.count == 1:
            return np.array([self.min_angle])
        return np.linspace(self.min_angle, self.max_angle, self.count)

    @property
    def increment(self) -> float:
        """The angle between neighbouring rays (0 for a single ray)."""
        return (self.max_angle - self.min_angle) / (self.count - 1) if self.count > 1 else 0.0


@dataclass(frozen=True)
class LidarSpec:
    """A lidar's ``<ray>``/``<lidar>`` block."""

    horizontal: ScanAxis = ScanAxis(640, 1.0, 0.0, 0.0)
    vertical: ScanAxis = ScanAxis()
    range_min: float = 0.0
    range_max: float = 10.0
    noise: Noise = Noise()

    def directions(self) -> np.ndarray:
        """Unit ray directions in the sensor frame, vertical-major (row v, column h): x forward, z up."""
        h = self.horizontal.angles()
        v = self.vertical.angles()
        cv, sv = np.cos(v)[:, None], np.sin(v)[:, None]
        d = np.stack([cv * np.cos(h)[None, :], cv * np.sin(h)[None, :], np.broadcast_to(sv, (len(v), len(h)))], axis=-1)
        return d.reshape(-1, 3)


def _axis(el: ConfigElement | None, log: logging.Logger, default: ScanAxis) -> ScanAxis:
    if el is None:
        return default
    return ScanAxis(
        int(parse_float(el, "samples", default.samples, log)),
        parse_float(el, "resolution", default.resolution, log),
        parse_float(el, "min_angle", default.min_angle, log),
        parse_float(el, "max_angle", default.max_angle, log),
    )


class SensorConfigError(ValueError):
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


def parse_lidar(sensor: Sensor, log: logging.Logger) -> LidarSpec:
    """The ``<ray>`` (Classic) or ``<lidar>`` (gz) block of a lidar sensor.

    Raises:
        SensorConfigError: zero samples, a range that is not 0 <= min < max, or angles out of order.
    """
    cfg = sensor.config
    block = None
    if cfg is not None:
        block = cfg.find("lidar") or cfg.find("ray")
    where = f"{sensor.location}: " if sensor.location else ""
    if block is None:
        log.warning(f"{where}sensor '{sensor.name}' ({sensor.type}) has no <ray>/<lidar> block; using SDF's defaults")
        return LidarSpec()
    scan = block.find("scan")
    h = _axis(scan.find("horizontal") if scan else None, log, LidarSpec.horizontal)
    v = _axis(scan.find("vertical") if scan else None, log, ScanAxis())
    rng = block.find("range")
    rmin = parse_float(rng, "min", 0.0, log)
    rmax = parse_float(rng, "max", 10.0, log)
    if h.samples < 1 or v.samples < 1 or h.count < 1:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <samples> must be at least 1")
    if h.count * v.count > MAX_RAYS:
        raise SensorLimitError(
            f"{where}sensor '{sensor.name}': {v.count} x {h.count} rays is more than the {MAX_RAYS:,} a scan may cast"
        )
    if not (0.0 <= rmin < rmax) or not math.isfinite(rmax):
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <range> needs 0 <= min < max, got {rmin} .. {rmax}")
    if h.max_angle < h.min_angle or v.max_angle < v.min_angle:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <max_angle> is below <min_angle>")
    return LidarSpec(h, v, rmin, rmax, parse_noise(block.find("noise"), log, f"sensor '{sensor.name}'"))


# --------------------------------------------------------------------------- where a sensor publishes
@dataclass(frozen=True)
class Output:
    """Where and how a sensor publishes: the ROS topic, the frame_id and (rays) the message type."""

    topic: str
    frame_id: str
    msg_type: MsgType
    radiation_type: int = 1
    min_intensity: float = -math.inf


_OUTPUT_TYPES = {
    "sensor_msgs/laserscan": MsgType.LASER_SCAN,
    "sensor_msgs/msg/laserscan": MsgType.LASER_SCAN,
    "sensor_msgs/pointcloud2": MsgType.POINT_CLOUD2,
    "sensor_msgs/msg/pointcloud2": MsgType.POINT_CLOUD2,
    "sensor_msgs/range": MsgType.RANGE,
    "sensor_msgs/msg/range": MsgType.RANGE,
}


def gz_scoped_topic(ctx: SystemContext, link: str, sensor: Sensor, suffix: str) -> str:
    """gz-sim's topic for a sensor without ``<topic>``."""
    return f"/world/{ctx.world_name}/model/{ctx.entity.name}/link/{link}/sensor/{sensor.name}/{suffix}"


@dataclass(frozen=True)
class SensorPluginConfig:
    """Parameters of ``libgazebo_ros_ray_sensor.so`` and ``libgazebo_ros_imu_sensor.so`` (inside a
    ``<sensor>``), and of ROS 1's ``libgazebo_ros_laser.so`` and ``libgazebo_ros_imu.so``. Without any
    of them (a gz-sim model), the sensor's own ``<topic>`` and ``<frame_id>``/``<gz_frame_id>`` apply."""

    output_type: str = ""
    """Ray sensors: ``sensor_msgs/PointCloud2`` (the default; ROS 1's laser plugin: LaserScan),
    ``sensor_msgs/LaserScan`` or ``sensor_msgs/Range``."""
    frame_name: str = ""
    """``<frame_name>`` (ROS 1: ``<frameName>``): the header's frame_id; default the sensor's link."""
    radiation_type: str = "infrared"
    """Range output: ``infrared`` or ``ultrasound``."""
    min_intensity: float = -math.inf
    """Intensities below it are raised to it (gazelle's rays have intensity 0: no laser_retro yet)."""
    initial_orientation_as_reference: bool = False
    """IMU: report orientation relative to the first reading instead of the world."""
    topic: str = "~/out"
    """``~/out`` in ROS 2 (rename it with ``<ros><remapping>~/out:=scan``); ROS 1: ``<topicName>``."""
    body_name: str = ""
    """ROS 1's IMU model plugin: ``<bodyName>``, the link it measures."""
    update_rate: float = 0.0
    """ROS 1's IMU model plugin: ``<updateRate>``, Hz of sim time (0: every step). Sensors use ``<update_rate>``."""
    gaussian_noise: float = 0.0
    """ROS 1's IMU model plugin: ``<gaussianNoise>``, standard deviation of every channel."""
    camera_name: str = ""
    """Cameras: ``<camera_name>``, the first part of their topics; default the sensor's name."""
    namespace: str = ""
    """``<ros><namespace>`` (ROS 1: ``<robotNamespace>``); default the entity's namespace."""
    remappings: tuple[tuple[str, str], ...] = ()
    """``<ros><remapping>from:=to``."""


def parse_plugin_config(ctx: SystemContext) -> SensorPluginConfig:
    """The plugin's parameters (ROS 2 and ROS 1 names); defaults without a plugin."""
    cfg = ctx.plugin.config if ctx.plugin is not None else None
    if cfg is None:
        return SensorPluginConfig(namespace=ctx.entity.namespace)
    log = ctx.logger
    ns, remaps = ros_block(cfg)
    raw_type = child_text(cfg, "output_type")
    if raw_type is None and "laser" in ctx.plugin.filename.lower():  # type: ignore[union-attr]
        raw_type = "sensor_msgs/LaserScan"  # ROS 1's gazebo_ros_laser publishes LaserScan
    return SensorPluginConfig(
        output_type=raw_type or "sensor_msgs/PointCloud2",
        frame_name=child_text(cfg, "frame_name") or child_text(cfg, "frameName") or "",
        radiation_type=(child_text(cfg, "radiation_type") or "infrared").strip().lower(),
        min_intensity=parse_float(cfg, "min_intensity", -math.inf, log),
        initial_orientation_as_reference=parse_bool(cfg, "initial_orientation_as_reference", False, log),
        topic=child_text(cfg, "topicName") or "~/out",
        body_name=child_text(cfg, "bodyName") or child_text(cfg, "body_name") or "",
        update_rate=parse_float(cfg, "updateRate", 0.0, log),
        gaussian_noise=parse_float(cfg, "gaussianNoise", 0.0, log),
        camera_name=child_text(cfg, "camera_name") or child_text(cfg, "cameraName") or "",
        namespace=ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace,
        remappings=tuple(remaps.items()),
    )


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


def sensor_output(ctx: SystemContext, link: str, sensor: Sensor | None, kind: str, c: SensorPluginConfig) -> Output:
    """Resolve the topic, frame and message type of a sensor (``kind``: ``scan``, ``imu`` or ``image``), from its
    gazebo_ros plugin's parameters ``c`` or, without a plugin, as gz-sim names it."""
    from .robot_state import entity_frame_prefix

    log = ctx.logger
    prefix = entity_frame_prefix(ctx.entity, log)
    default_type = OUTPUT_MESSAGES[kind]
    if ctx.plugin is None:  # gz-sim: <topic> and <frame_id>
        assert sensor is not None
        cfg = sensor.config
        suffix = "depth_image" if kind == "image" and sensor.type in ("depth", "depth_camera") else kind
        topic = sensor.topic or gz_scoped_topic(ctx, link, sensor, suffix)
        frame = child_text(cfg, "frame_id") or child_text(cfg, "gz_frame_id")
        frame = prefix + frame if frame else f"{ctx.entity.name}::{link}::{sensor.name}"
        return Output(resolve_topic(topic, ctx.entity.namespace), frame, default_type)
    if kind == "image":  # gazebo_ros_camera: <camera_name>/image_raw in the plugin's namespace
        name = c.camera_name or (sensor.name if sensor is not None else "camera")
        topic = resolve_topic(f"{name}/image_raw", c.namespace, dict(c.remappings))
    else:
        topic = resolve_topic(c.topic, c.namespace, dict(c.remappings), node=ctx.plugin.name)
    msg_type = default_type
    if kind == "scan":
        found = _OUTPUT_TYPES.get(c.output_type.strip().lower())
        if found is None:
            el = ctx.plugin.config.find("output_type")
            where = f"{el.location}: " if el is not None and el.location else ""
            log.warning(
                f"{where}<output_type> '{c.output_type}' is not one gazelle publishes (LaserScan, PointCloud2, "
                "Range); publishing sensor_msgs/PointCloud2"
            )
            found = MsgType.POINT_CLOUD2
        msg_type = found
    return Output(
        topic,
        prefix + (c.frame_name or link),
        msg_type,
        radiation_type=0 if c.radiation_type == "ultrasound" else 1,
        min_intensity=c.min_intensity,
    )


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

    def __init__(self, seed: int | None = None) -> None:
        self.sensor: Sensor | None = None
        self.link = ""
        self.offset = Pose()
        """X_LS: the sensor in its link's frame."""
        self.rate_hz = 0.0
        self.output: Output | None = None
        self.config = SensorPluginConfig()
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
        False (after an error naming why) when it cannot run."""
        log = ctx.logger
        self.sensor, link = ctx.sensor, ctx.link
        self.config = c = parse_plugin_config(ctx)
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
        self.output = sensor_output(ctx, self.link, self.sensor, self.output_kind, c)
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


@sensor_system
class Lidar(_SensorSystem):
    """A ray / lidar sensor: LaserScan, PointCloud2 or Range (see the module docstring)."""

    sdf_types = LIDAR_TYPES
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {
        "gazebo_ros_ray_sensor": None,
        "gazebo_ros_laser": None,
        "gazebo_ros_gpu_laser": None,
    }
    gz_system = "Sensors"
    output_kind = "scan"

    kind = "lidar"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.spec = LidarSpec()
        self._dirs = np.zeros((0, 3))
        self._intensity_cache: tuple[tuple[int, float], bytes] = ((0, 0.0), b"")

    def configure(self, ctx: SystemContext) -> None:
        """Parse the sensor's ``<ray>``/``<lidar>`` block and the plugin; declare the output topic."""
        spec = self._parse_sensor(ctx, "ray", parse_lidar)
        if spec is None or ctx.sensor is None:
            return
        self.spec = spec
        if not self._configure_common(ctx):
            return
        self._dirs = self.spec.directions()
        assert self.output is not None
        s = self.spec
        ctx.logger.info(
            f"{ctx.sensor.type} '{ctx.sensor.name}': {s.vertical.count}x{s.horizontal.count} rays, "
            f"{s.range_min:g}..{s.range_max:g} m at {self.rate_hz:g} Hz on [{self.output.topic}] "
            f"({self.output.msg_type.value.rsplit('/', 1)[-1]}) in frame [{self.output.frame_id}]"
        )

    def scan(self, world: PhysicsWorld, *, noise: bool = True) -> np.ndarray:
        """Ranges (vertical-major, v rows x h columns) with noise (unless ``noise`` is False: the viewer's
        overlay, which must not draw from the sensor's random stream) and REP 117's ±inf."""
        assert self._body is not None
        s = self.spec
        dist, _ = self._body.cast_rays_from(self.offset, self._dirs, s.range_max)
        hit = dist >= 0
        if noise and s.noise.active:
            dist += s.noise.mean + (self._rng.normal(0.0, s.noise.stddev, len(dist)) if s.noise.stddev > 0 else 0.0)
        ranges = np.where(hit, dist, np.inf)  # a miss is +inf; a hit nearer than range_min is -inf
        np.copyto(ranges, -np.inf, where=ranges < s.range_min)
        np.copyto(ranges, np.inf, where=ranges > s.range_max)
        return ranges.reshape(s.vertical.count, s.horizontal.count)

    def _intensities(self, n: int, value: float) -> bytes:
        """A scan's intensities (every ray the same), made once."""
        if self._intensity_cache[0] != (n, value):
            self._intensity_cache = ((n, value), np.full(n, value, np.float32).tobytes())
        return self._intensity_cache[1]

    def world_points(self, world: PhysicsWorld) -> np.ndarray:
        """The noise-free hit points of a scan now, in the world frame (N x 3, float32): the viewer's overlay."""
        ranges = self.scan(world, noise=False).reshape(-1)
        ok = np.isfinite(ranges)
        X = self.sensor_pose()
        pts = (self._dirs[ok] * ranges[ok, None]) @ rotation_matrix(X.orientation).T + np.asarray(X.position)
        return pts.astype(np.float32)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: scan and publish stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        ranges = self.scan(world)
        s, out, t = self.spec, self.output, info.sim_time_sec
        intensity = max(0.0, out.min_intensity)
        if out.msg_type is MsgType.LASER_SCAN:
            row = ranges[s.vertical.count // 2].astype(np.float32)
            self._pub.publish(
                LaserScan(
                    t,
                    out.frame_id,
                    s.horizontal.min_angle,
                    s.horizontal.max_angle,
                    s.horizontal.increment,
                    s.range_min,
                    s.range_max,
                    row.tobytes(),
                    self._intensities(len(row), intensity),
                    scan_time=1.0 / self.rate_hz if self.rate_hz > 0 else 0.0,
                )
            )
        elif out.msg_type is MsgType.RANGE:
            valid = ranges[np.isfinite(ranges)]
            r = float(valid.min()) if valid.size else (-math.inf if np.any(ranges < 0) else math.inf)
            fov = max(s.horizontal.max_angle - s.horizontal.min_angle, s.vertical.max_angle - s.vertical.min_angle)
            self._pub.publish(Range(t, out.frame_id, out.radiation_type, fov, s.range_min, s.range_max, r))
        else:
            flat = ranges.reshape(-1)
            ok = np.isfinite(flat)
            pts = self._dirs[ok] * flat[ok, None]
            cloud = np.empty((len(pts), 4), np.float32)
            cloud[:, :3] = pts
            cloud[:, 3] = intensity
            self._pub.publish(PointCloud(t, out.frame_id, len(pts), 1, cloud.astype("<f4").tobytes()))


@dataclass(frozen=True)
class ImuNoise:
    """Per-channel noise of an IMU: angular velocity x, y, z and linear acceleration x, y, z."""

    rate: tuple[Noise, Noise, Noise] = (Noise(), Noise(), Noise())
    accel: tuple[Noise, Noise, Noise] = (Noise(), Noise(), Noise())


def _imu_axes(el: ConfigElement | None, log: logging.Logger, what: str) -> tuple[Noise, Noise, Noise]:
    """``<x>``, ``<y>``, ``<z>`` each with a ``<noise type>`` (SDF 1.5+)."""
    out = []
    for ax in "xyz":
        a = el.find(ax) if el is not None else None
        out.append(parse_noise(a.find("noise") if a is not None else None, log, f"{what} {ax}"))
    return out[0], out[1], out[2]


def _imu_channel(old: ConfigElement, tag: str, log: logging.Logger) -> Noise:
    """``<rate>`` or ``<accel>`` of SDF 1.4's ``<imu><noise>``; its ``<type>`` is the parent's."""
    el = old.find(tag)
    if el is None:
        return Noise()
    kind = child_text(old, "type") or "none"
    return parse_noise(ConfigElement("noise", (("type", kind),), "", el.children, el.location), log, f"IMU {tag}")


def parse_imu_noise(sensor: Sensor | None, plugin_cfg: ConfigElement | None, log: logging.Logger) -> ImuNoise:
    """SDF 1.5+ per-axis ``<imu><angular_velocity><x><noise>``, or the older ``<imu><noise><rate>/<accel>``
    (SDF 1.4 and ROS 1's gazebo_ros_imu plugin), or ROS 1's ``<gaussianNoise>``."""
    blocks: list[ConfigElement] = []
    for holder in (sensor.config if sensor is not None else None, plugin_cfg):
        imu = holder.find("imu") if holder is not None else None
        if imu is not None:
            blocks.append(imu)
    for imu in blocks:
        av, la = imu.find("angular_velocity"), imu.find("linear_acceleration")
        if av is not None or la is not None:
            return ImuNoise(_imu_axes(av, log, "IMU angular velocity"), _imu_axes(la, log, "IMU linear acceleration"))
        old = imu.find("noise")
        if old is not None:
            r, a = _imu_channel(old, "rate", log), _imu_channel(old, "accel", log)
            return ImuNoise((r, r, r), (a, a, a))
    g = parse_float(plugin_cfg, "gaussianNoise", 0.0, log) if plugin_cfg is not None else 0.0
    if g > 0:  # ROS 1's model plugin
        n = Noise("gaussian", 0.0, g)
        return ImuNoise((n, n, n), (n, n, n))
    return ImuNoise()


@sensor_system
class ImuSensor(_SensorSystem):
    """An IMU: orientation, angular velocity and proper linear acceleration (sensor_msgs/Imu)."""

    sdf_types = frozenset({"imu"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_imu_sensor": None}
    gz_system = "Imu"
    output_kind = "imu"

    kind = "IMU"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.noise = ImuNoise()
        self.orientation_reference = False
        self._q0: tuple[float, float, float, float] | None = None
        self._bias = np.zeros(6)
        self._mean = np.zeros(6)
        self._std = np.zeros(6)
        self._perturbed = False
        self._rows: list[list[float]] = []
        """What the next readings add to the six channels (bias + mean + noise), drawn NOISE_ROWS at a time."""
        self._cov: tuple[tuple[float, ...], tuple[float, ...]] = ((0.0,) * 9, (0.0,) * 9)

    def configure(self, ctx: SystemContext) -> None:
        """Parse the noise and the plugin; declare the output topic."""
        if not self._configure_common(ctx):
            return
        cfg = ctx.plugin.config if ctx.plugin is not None else None
        self.noise = parse_imu_noise(ctx.sensor, cfg, ctx.logger)
        self.orientation_reference = self.config.initial_orientation_as_reference
        channels = (*self.noise.rate, *self.noise.accel)
        self._bias = np.array([n.bias(self._rng) for n in channels])
        self._mean = np.array([n.mean if n.active else 0.0 for n in channels])
        self._std = np.array([n.stddev if n.active else 0.0 for n in channels])
        self._perturbed = bool(self._bias.any() or self._mean.any() or self._std.any())
        self._rows = []

        def cov(ns: tuple[Noise, Noise, Noise]) -> tuple[float, ...]:
            c = [0.0] * 9
            for i, n in enumerate(ns):
                c[4 * i] = n.stddev**2 if n.active else 0.0
            return tuple(c)

        self._cov = (cov(self.noise.rate), cov(self.noise.accel))
        assert self.output is not None
        ctx.logger.info(
            f"IMU on [{self.link}] at {self.rate_hz:g} Hz on [{self.output.topic}] in frame [{self.output.frame_id}]"
        )

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Measure again at the next step; a reference orientation is taken again."""
        super().reset(info, world)
        self._q0 = None

    def read(self) -> tuple[tuple[float, float, float, float], Vec3, Vec3]:
        """(orientation, angular velocity, linear acceleration) with noise, as published."""
        assert self._body is not None
        r = self._body.imu_reading(self.offset)
        q = (r[0], r[1], r[2], r[3])
        if self.orientation_reference:
            if self._q0 is None:
                self._q0 = q
            q = quat_mul(quat_conj(self._q0), q)
        if not self._perturbed:
            return q, (r[4], r[5], r[6]), (r[7], r[8], r[9])
        if not self._rows:
            self._rows = self._perturbation_rows()
        n = self._rows.pop()
        return q, (r[4] + n[0], r[5] + n[1], r[6] + n[2]), (r[7] + n[3], r[8] + n[4], r[9] + n[5])

    def _perturbation_rows(self) -> list[list[float]]:
        """The next :data:`NOISE_ROWS` readings' additions (bias + mean + stddev x N(0, 1)), in the order
        :meth:`read` pops them: drawing them together costs what one draw per reading cost."""
        rows = np.broadcast_to(self._bias + self._mean, (NOISE_ROWS, 6))
        if self._std.any():
            rows = rows + self._std * self._rng.standard_normal((NOISE_ROWS, 6))
        return rows[::-1].tolist()

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: read and publish stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        q, w, a = self.read()
        self._pub.publish(
            Imu(
                info.sim_time_sec,
                self.output.frame_id,
                q,
                w,
                a,
                angular_velocity_covariance=self._cov[0],
                linear_acceleration_covariance=self._cov[1],
            )
        )


# --------------------------------------------------------------------------- magnetometer
@sensor_system
class Magnetometer(_SensorSystem):
    """gz-sim's magnetometer (``gz-sim-magnetometer-system``): the world's ``<magnetic_field>`` in the
    sensor's frame, with ``<magnetometer><x|y|z><noise>``, as sensor_msgs/MagneticField on ``<topic>``
    (else gz's ``.../sensor/<s>/magnetometer``), which ros_gz_bridge maps to ROS under the same name."""

    sdf_types = frozenset({"magnetometer"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = "Magnetometer"
    output_kind = "magnetometer"

    kind = "magnetometer"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.field_W = np.zeros(3)
        self._noise: tuple[Noise, Noise, Noise] = (Noise(), Noise(), Noise())
        self._bias = np.zeros(3)
        self._cov: tuple[float, ...] = (0.0,) * 9

    def configure(self, ctx: SystemContext) -> None:
        """The world's field and the noise; declare the output topic."""
        if not self._configure_common(ctx):
            return
        self.field_W = np.asarray(ctx.magnetic_field, dtype=float)
        block = self.sensor.config.find("magnetometer") if self.sensor and self.sensor.config is not None else None
        self._noise = _imu_axes(block, ctx.logger, "magnetometer")
        self._bias = np.array([n.bias(self._rng) for n in self._noise])
        cov = [0.0] * 9
        for i, n in enumerate(self._noise):
            cov[4 * i] = n.stddev**2 if n.active else 0.0
        self._cov = tuple(cov)
        assert self.output is not None
        ctx.logger.info(
            f"magnetometer on [{self.link}] at {self.rate_hz:g} Hz on [{self.output.topic}] "
            f"in frame [{self.output.frame_id}]"
        )

    def read(self) -> np.ndarray:
        """The field in the sensor's frame (tesla), with noise."""
        R_WS = rotation_matrix(self.sensor_pose().orientation)
        value = R_WS.T @ self.field_W + self._bias
        for i, n in enumerate(self._noise):
            if n.active:
                value[i] += n.mean + n.stddev * self._rng.standard_normal()
        return value

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        b = self.read().tolist()
        self._pub.publish(MagneticField(info.sim_time_sec, self.output.frame_id, (b[0], b[1], b[2]), self._cov))


# --------------------------------------------------------------------------- altimeter
@sensor_system
class AltimeterSensor(_SensorSystem):
    """gz-sim's altimeter (``gz-sim-altimeter-system``): the sensor's height above where it started
    (``vertical_reference``) and its vertical velocity, with ``<altimeter><vertical_position|
    vertical_velocity><noise>``, as ros_gz_interfaces/Altimeter on ``<topic>`` (else gz's
    ``.../sensor/<s>/altimeter``)."""

    sdf_types = frozenset({"altimeter"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = "Altimeter"
    output_kind = "altimeter"

    kind = "altimeter"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.phase_gate = None  # post_update takes the reference height at the first step, due or not
        self._noise = (Noise(), Noise())
        self._bias = (0.0, 0.0)
        self.reference: float | None = None

    def configure(self, ctx: SystemContext) -> None:
        """The noise; declare the output topic."""
        if not self._configure_common(ctx):
            return
        block = self.sensor.config.find("altimeter") if self.sensor and self.sensor.config is not None else None
        noises = []
        for tag in ("vertical_position", "vertical_velocity"):
            el = block.find(tag) if block is not None else None
            noises.append(parse_noise(el.find("noise") if el is not None else None, ctx.logger, f"altimeter {tag}"))
        self._noise = (noises[0], noises[1])
        self._bias = (noises[0].bias(self._rng), noises[1].bias(self._rng))
        assert self.output is not None
        ctx.logger.info(f"altimeter on [{self.link}] at {self.rate_hz:g} Hz on [{self.output.topic}]")

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """The reference is taken again."""
        super().reset(info, world)
        self.reference = None

    def read(self) -> tuple[float, float, float]:
        """(height above the reference, vertical velocity, reference), with noise."""
        assert self._body is not None
        z = self.sensor_pose().position[2]
        if self.reference is None:
            self.reference = z
        vz = self._body.velocity[0][2]
        out = [z - self.reference + self._bias[0], vz + self._bias[1]]
        for i, n in enumerate(self._noise):
            if n.active:
                out[i] += n.mean + n.stddev * self._rng.standard_normal()
        return out[0], out[1], self.reference

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish stamped with this sim time."""
        if self._pub is not None and self.reference is None and not info.paused:
            self.read()  # the reference is where it starts, whether or not anyone listens yet
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        h, v, ref = self.read()
        self._pub.publish(Altimeter(info.sim_time_sec, self.output.frame_id, h, v, ref))


# --------------------------------------------------------------------------- cameras
@dataclass(frozen=True)
class CameraSpec:
    """A ``<camera>`` block: image size and format, field of view, clip planes, distortion, noise."""

    width: int = 320
    height: int = 240
    format: str = "R8G8B8"
    horizontal_fov: float = 1.047
    near: float = 0.1
    far: float = 100.0
    distortion: tuple[float, float, float, float, float] = (0.0, 0.0, 0.0, 0.0, 0.0)
    """k1, k2, p1, p2, k3 (ROS's plumb_bob order); published in CameraInfo, not applied to the image."""
    noise: Noise = Noise()

    def k(self) -> tuple[float, ...]:
        """The intrinsic matrix: square pixels, f = (width / 2) / tan(hfov / 2), principal point at the
        image centre (pixel centres at half-integers, as the renderer draws them)."""
        f = (self.width / 2.0) / math.tan(self.horizontal_fov / 2.0)
        return (f, 0.0, self.width / 2.0, 0.0, f, self.height / 2.0, 0.0, 0.0, 1.0)


_ENCODINGS = {
    "R8G8B8": "rgb8",
    "RGB_INT8": "rgb8",
    "B8G8R8": "bgr8",
    "BGR_INT8": "bgr8",
    "L8": "mono8",
    "L_INT8": "mono8",
}


def parse_camera(sensor: Sensor, log: logging.Logger) -> CameraSpec:
    """The ``<camera>`` block of a camera sensor.

    Raises:
        SensorConfigError: an image of zero size, a field of view outside (0, pi), or clip planes out of order.
    """
    cam = sensor.config.find("camera") if sensor.config is not None else None
    where = f"{sensor.location}: " if sensor.location else ""
    if cam is None:
        log.warning(f"{where}sensor '{sensor.name}' ({sensor.type}) has no <camera> block; using SDF's defaults")
        return CameraSpec()
    image, clip, dist = cam.find("image"), cam.find("clip"), cam.find("distortion")
    width = int(parse_float(image, "width", 320, log))
    height = int(parse_float(image, "height", 240, log))
    fmt = (child_text(image, "format") or "R8G8B8").strip()
    hfov = parse_float(cam, "horizontal_fov", 1.047, log)
    near, far = parse_float(clip, "near", 0.1, log), parse_float(clip, "far", 100.0, log)
    if width < 1 or height < 1:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': a camera of {width}x{height} pixels cannot render")
    if width > MAX_IMAGE_SIDE or height > MAX_IMAGE_SIDE:
        raise SensorLimitError(
            f"{where}sensor '{sensor.name}': a camera of {width}x{height} pixels is larger than "
            f"{MAX_IMAGE_SIDE}x{MAX_IMAGE_SIDE}, the largest image gazelle renders"
        )
    if not 0.0 < hfov < math.pi:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <horizontal_fov> must be in (0, pi), got {hfov}")
    if not 0.0 < near < far:
        raise SensorConfigError(f"{where}sensor '{sensor.name}': <clip> needs 0 < near < far, got {near} .. {far}")
    if fmt not in _ENCODINGS:
        log.warning(f"{where}sensor '{sensor.name}': image format '{fmt}' is not rendered; publishing rgb8 (R8G8B8)")
        fmt = "R8G8B8"
    coeffs = tuple(parse_float(dist, t, 0.0, log) for t in ("k1", "k2", "p1", "p2", "k3"))
    if dist is not None and any(coeffs):
        log.warning(
            f"{where}sensor '{sensor.name}': <distortion> is published in CameraInfo but not applied to the image"
        )
    return CameraSpec(
        width,
        height,
        fmt,
        hfov,
        near,
        far,
        coeffs,  # type: ignore[arg-type]
        parse_noise(cam.find("noise"), log, f"sensor '{sensor.name}'"),
    )


@dataclass(frozen=True)
class CameraTopics:
    """Where a camera publishes (an empty name: not published)."""

    image: str
    info: str
    depth: str = ""
    depth_info: str = ""
    points: str = ""


OPTICAL = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]])
"""Rotation from a link frame (x forward, z up) to the optical frame (z forward, x right, y down)."""


@sensor_system
class Camera(_SensorSystem):
    """A camera or depth camera: Image, CameraInfo, depth Image (32FC1) and PointCloud2 (see the module
    docstring). It renders only while someone subscribes."""

    sdf_types = CAMERA_TYPES
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {
        "gazebo_ros_camera": None,
        "gazebo_ros_depth_camera": DEPTH_TYPES,
        "gazebo_ros_openni_kinect": DEPTH_TYPES,
    }
    gz_system = "Sensors"
    output_kind = "image"

    kind = "camera"

    checkpoint_skip = ("_renderer",)
    """Its offscreen renderer (a GL context) is made again where a checkpoint is loaded."""

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.spec = CameraSpec()
        self.topics = CameraTopics("", "")
        self.depth = False
        self._eps: dict[str, Endpoint] = {}
        self._renderer: OffscreenRenderer | None = None
        self._failed = False

    def configure(self, ctx: SystemContext) -> None:
        """Parse the ``<camera>`` block and the plugin; declare the image, info, depth and points topics."""
        spec = self._parse_sensor(ctx, "camera", parse_camera)
        if spec is None or ctx.sensor is None:
            return
        self.spec = spec
        if not self._configure_common(ctx):
            return
        assert self.output is not None and self._pub is not None
        self.depth = ctx.sensor.type in DEPTH_TYPES
        self.topics = self._topics(ctx)
        # _configure_common advertised the image topic (output.topic); the others go beside it
        self._eps = {"image": self._pub}
        for key, msg_type in (
            ("info", MsgType.CAMERA_INFO),
            ("depth", MsgType.IMAGE),
            ("depth_info", MsgType.CAMERA_INFO),
            ("points", MsgType.POINT_CLOUD2),
        ):
            topic = getattr(self.topics, key)
            if topic:
                self._eps[key] = ctx.bus.advertise(ctx.entity.name, topic, msg_type, depth=SENSOR_DEPTH)
        s = self.spec
        ctx.logger.info(
            f"{ctx.sensor.type} '{ctx.sensor.name}': {s.width}x{s.height} at {self.rate_hz:g} Hz on "
            f"[{self.topics.image}]"
            + (f" and [{self.topics.depth}]" if self.depth else "")
            + f" in frame [{self.output.frame_id}]"
        )

    def _topics(self, ctx: SystemContext) -> CameraTopics:
        assert self.output is not None and self.sensor is not None
        image = self.output.topic
        parent = image.rsplit("/", 1)[0]
        if ctx.plugin is not None:  # gazebo_ros: <camera_name>/image_raw etc. under the node's namespace
            return CameraTopics(
                image,
                f"{parent}/camera_info",
                f"{parent}/depth/image_raw" if self.depth else "",
                f"{parent}/depth/camera_info" if self.depth else "",
                f"{parent}/points" if self.depth else "",
            )
        if self.sensor.type in ("rgbd_camera", "rgbd"):  # gz: <topic>/image, /depth_image, /points, /camera_info
            base = resolve_topic(
                self.sensor.topic or gz_scoped_topic(ctx, self.link, self.sensor, ""), ctx.entity.namespace
            ).rstrip("/")
            return CameraTopics(
                f"{base}/image", f"{base}/camera_info", f"{base}/depth_image", f"{base}/camera_info", f"{base}/points"
            )
        if self.depth:  # gz depth_camera: <topic> is the depth image
            return CameraTopics("", f"{parent}/camera_info", image, f"{parent}/camera_info", f"{image}/points")
        return CameraTopics(image, f"{parent}/camera_info")

    def _wanted(self) -> dict[str, bool]:
        return {k: ep.wanted for k, ep in self._eps.items()}

    def info(self, stamp: float) -> CameraInfo:
        """CameraInfo of this camera (K and P from ``horizontal_fov`` and the image size)."""
        s = self.spec
        k = s.k()
        p = (k[0], 0.0, k[2], 0.0, 0.0, k[4], k[5], 0.0, 0.0, 0.0, 1.0, 0.0)
        assert self.output is not None
        return CameraInfo(
            stamp,
            self.output.frame_id,
            s.height,
            s.width,
            "plumb_bob",
            s.distortion,
            k,
            (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
            p,
        )

    def render(self, world: PhysicsWorld, depth: bool) -> tuple[np.ndarray, np.ndarray | None] | None:
        """Colour (H x W x 3 uint8) and depth (metres, -inf nearer than near, +inf where nothing is
        within far) as this camera sees the world now; None when no GL context could be made."""
        if self._failed:
            return None
        s = self.spec
        try:
            if self._renderer is None:
                self._renderer = world.offscreen_renderer(s.width, s.height)
            rgb, d = self._renderer.render(self.sensor_pose(), s.horizontal_fov, s.near, s.far, depth=depth)
        except RenderError as err:
            self._failed = True
            logging.getLogger("gazelle.sensors").error(f"camera '{self.sensor.name if self.sensor else ''}': {err}")
            return None
        if d is not None:
            d = d.copy()
            d[d >= s.far * (1 - 1e-4)] = np.inf
        return rgb.copy(), d

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the camera's rate, while anyone subscribes: render and publish stamped with this sim time."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.rate_hz):
            return
        want = self._wanted()
        if not any(want.values()):
            return
        t, s = info.sim_time_sec, self.spec
        assert self.output is not None
        frame = self.output.frame_id
        need_depth = self.depth and (want.get("depth", False) or want.get("points", False))
        need_image = want.get("image", False) and bool(self.topics.image)
        out = self.render(world, need_depth) if (need_image or need_depth) else None
        ci = self.info(t)
        for key in ("info", "depth_info"):
            if want.get(key):
                self._eps[key].publish(ci)
        if out is None:
            return
        rgb, d = out
        if need_image:
            img = rgb
            if s.noise.active:
                noisy = rgb.astype(np.float32) + 255.0 * self._rng.normal(s.noise.mean, s.noise.stddev, rgb.shape)
                img = np.clip(noisy, 0, 255).astype(np.uint8)
            enc = _ENCODINGS[s.format]
            if enc == "bgr8":
                img = img[..., ::-1]
            elif enc == "mono8":
                img = (img.astype(np.float32) @ np.array([0.299, 0.587, 0.114], np.float32)).astype(np.uint8)
            data = np.ascontiguousarray(img)
            channels = 1 if data.ndim == 2 else 3
            self._eps["image"].publish(Image(t, frame, s.height, s.width, enc, s.width * channels, data.tobytes()))
        if d is None:
            return
        if want.get("depth"):
            self._eps["depth"].publish(
                Image(t, frame, s.height, s.width, "32FC1", s.width * 4, d.astype("<f4").tobytes())
            )
        if want.get("points"):
            k = s.k()
            v, u = np.mgrid[0 : s.height, 0 : s.width]
            ok = np.isfinite(d)
            z = d[ok]
            x = (u[ok] + 0.5 - k[2]) / k[0] * z
            y = (v[ok] + 0.5 - k[5]) / k[4] * z
            cloud = np.empty((len(z), 4), np.float32)
            cloud[:, 0], cloud[:, 1], cloud[:, 2] = x, y, z
            cloud[:, 3] = rgb[ok] @ np.array([1.0 / 3, 1.0 / 3, 1.0 / 3]) / 255.0
            self._eps["points"].publish(PointCloud(t, frame, len(z), 1, cloud.astype("<f4").tobytes()))

    def shutdown(self) -> None:
        """Free the GL context (on the simulation thread, where it was made)."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None


# --------------------------------------------------------------------------- contact
@sensor_system
class ContactSensor(_SensorSystem):
    """A contact sensor (``<sensor type="contact">`` with ``<contact><collision>``): every contact of its
    collisions as gazebo_msgs/ContactsState, forces on the sensor's collision. gazebo_ros_bumper
    publishes ``bumper_states`` in ``<frame_name>`` (default ``world``); gz-sim's contact system on
    ``<contact><topic>``/``<topic>``, else ``/world/<w>/model/<m>/link/<l>/sensor/<s>/contact``."""

    sdf_types = frozenset({"contact"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_bumper": None}
    gz_system = "Contact"
    output_kind = "contact"

    kind = "contact"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.collisions: tuple[str, ...] = ()
        self._frame: BodyHandle | None = None
        """``<frame_name>``'s link, when the contacts are reported in a link's frame (None: the world)."""
        self._geoms: PerGeneration[frozenset[int]] | None = None

    def _find_geoms(self, world: PhysicsWorld) -> frozenset[int]:
        """The collision geoms of the sensor's ``<collision>`` elements in the world's current model."""
        return frozenset().union(*(world.collision_geoms(self._entity, self.link, n) for n in self._collisions))

    def configure(self, ctx: SystemContext) -> None:
        """Read the collisions it watches and the plugin; declare the output topic."""
        sensor = ctx.sensor
        if self._parse_sensor(ctx, "contact", lambda _s, _log: True) is None or sensor is None:
            return
        block = sensor.config.find("contact") if sensor.config is not None else None
        names = tuple(el.text.strip() for el in (block.findall("collision") if block is not None else ()))
        link = next((lk for lk in ctx.entity.model.links if lk.name == ctx.link), None)
        known = {c.name for c in link.collisions} if link is not None else set()
        where = f"{sensor.location}: " if sensor.location else ""
        # Gazebo names a URDF link's first unnamed <collision> '<link>_collision' (sdformat's URDF
        # conversion; the later ones '_1', '_2', ... as here): a contact sensor written for Gazebo names it so
        if link is not None and link.collisions:
            first = link.collisions[0].name
            alias = f"{ctx.link}_collision"
            if first == f"{alias}_0" and alias not in known:
                names = tuple(first if n == alias else n for n in names)
        missing = [n for n in names if n not in known]
        if not names or missing:
            what = f"its <collision> {', '.join(missing)} is not" if missing else "it names no <collision>"
            ctx.logger.error(
                f"{where}contact sensor '{sensor.name}': {what} a collision of link '{ctx.link}' "
                f"(it has {', '.join(sorted(known)) or 'none'}); it does nothing"
            )
            return
        if not self._configure_common(ctx, advertise=False):
            return
        self.collisions = names
        gz_topic = child_text(block, "topic")
        assert self.output is not None
        if ctx.plugin is None:
            topic = sensor.topic or gz_topic or gz_scoped_topic(ctx, self.link, sensor, "contact")
            self.output = dataclasses.replace(self.output, topic=resolve_topic(topic, ctx.entity.namespace))
        else:
            c = self.config
            self.output = dataclasses.replace(
                self.output,
                topic=resolve_topic("bumper_states", c.namespace, dict(c.remappings)),
                frame_id=c.frame_name or "world",
            )
            if c.frame_name and c.frame_name not in ("world", "map"):
                if c.frame_name in {lk.name for lk in ctx.entity.model.links}:
                    self._frame = ctx.world.body(ctx.entity.name, c.frame_name)
                else:
                    where = f"{ctx.plugin.location}: " if ctx.plugin.location else ""
                    ctx.logger.warning(
                        f"{where}<frame_name> '{c.frame_name}' is not a link of '{ctx.entity.name}'; "
                        "contacts are reported in the world frame"
                    )
                    self.output = dataclasses.replace(self.output, frame_id="world")
        self._pub = ctx.bus.advertise(ctx.entity.name, self.output.topic, MsgType.CONTACTS, depth=SENSOR_DEPTH)
        self._entity, self._collisions = ctx.entity.name, tuple(names)
        self._geoms = PerGeneration(self._find_geoms)
        ctx.logger.info(
            f"contact sensor '{sensor.name}' on [{', '.join(names)}] at {self.rate_hz:g} Hz on [{self.output.topic}]"
        )

    def read(self, world: PhysicsWorld) -> tuple[ContactPair, ...]:
        """The current contacts of the watched collisions, grouped by pair, in the output frame."""
        assert self._geoms is not None
        points = world.contacts_of(self._geoms.get(world))
        R = None
        origin = np.zeros(3)
        if self._frame is not None:
            X = self._frame.pose
            R, origin = rotation_matrix(X.orientation).T, np.asarray(X.position)
        pairs: dict[tuple[str, str], list] = {}
        for p in points:
            pos, n, f, t = (np.asarray(v) for v in (p.position, p.normal, p.force, p.torque))
            if R is not None:
                pos, n, f, t = R @ (pos - origin), R @ n, R @ f, R @ t
            pairs.setdefault((p.collision1, p.collision2), []).append((pos, n, f, t, p.depth))

        def vec(a: np.ndarray) -> tuple[float, float, float]:
            return (float(a[0]), float(a[1]), float(a[2]))

        return tuple(
            ContactPair(
                c1,
                c2,
                tuple(vec(x[0]) for x in items),
                tuple(vec(x[1]) for x in items),
                tuple(vec(x[2]) for x in items),
                tuple(vec(x[3]) for x in items),
                tuple(float(x[4]) for x in items),
            )
            for (c1, c2), items in pairs.items()
        )

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the contacts stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        self._pub.publish(Contacts(info.sim_time_sec, self.output.frame_id, self.read(world)))


# --------------------------------------------------------------------------- GPS
WGS84_A = 6378137.0
"""WGS84 equatorial radius (m)."""
WGS84_E2 = 6.69437999014e-3
"""WGS84 first eccentricity squared."""


def enu_to_geodetic(east: float, north: float, up: float, origin: SphericalCoordinates) -> tuple[float, float, float]:
    """(latitude deg, longitude deg, altitude m) of a point ``east``/``north``/``up`` metres from the
    origin, on the WGS84 ellipsoid's local radii of curvature (exact to centimetres over kilometres)."""
    lat0 = math.radians(origin.latitude_deg)
    s2 = math.sin(lat0) ** 2
    meridian = WGS84_A * (1 - WGS84_E2) / (1 - WGS84_E2 * s2) ** 1.5
    prime = WGS84_A / math.sqrt(1 - WGS84_E2 * s2)
    lat = origin.latitude_deg + math.degrees(north / (meridian + origin.elevation))
    lon = origin.longitude_deg + math.degrees(east / ((prime + origin.elevation) * math.cos(lat0)))
    return lat, lon, origin.elevation + up


def world_to_enu(v: tuple[float, float, float], heading_deg: float) -> tuple[float, float, float]:
    """A world-frame vector in East, North, Up: the world frame is ENU turned by ``heading`` about the
    downward vertical (North to East positive), as SDF's ``<heading_deg>`` says."""
    h = math.radians(heading_deg)
    x, y, z = v
    return (x * math.cos(h) + y * math.sin(h), -x * math.sin(h) + y * math.cos(h), z)


@dataclass(frozen=True)
class GpsNoise:
    """``<gps>``/``<navsat>`` noise: position horizontal and vertical, velocity horizontal and vertical."""

    position_horizontal: Noise = Noise()
    position_vertical: Noise = Noise()
    velocity_horizontal: Noise = Noise()
    velocity_vertical: Noise = Noise()


def parse_gps_noise(sensor: Sensor, log: logging.Logger) -> GpsNoise:
    """SDF's ``<gps>`` (or ``<navsat>``) ``<position_sensing>``/``<velocity_sensing>`` noise."""
    block = None
    if sensor.config is not None:
        block = sensor.config.find("navsat") or sensor.config.find("gps")
    if block is None:
        return GpsNoise()

    def one(kind: str, axis: str) -> Noise:
        el = block.find(kind)
        ax = el.find(axis) if el is not None else None
        return parse_noise(ax.find("noise") if ax is not None else None, log, f"GPS {kind} {axis}")

    return GpsNoise(
        one("position_sensing", "horizontal"),
        one("position_sensing", "vertical"),
        one("velocity_sensing", "horizontal"),
        one("velocity_sensing", "vertical"),
    )


@sensor_system
class GpsSensor(_SensorSystem):
    """A GPS (``gps``/``navsat``): NavSatFix from the world's ``<spherical_coordinates>`` and, with
    gazebo_ros_gps_sensor, the ENU velocity on ``~/vel``."""

    sdf_types = frozenset({"gps", "navsat"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_gps_sensor": None}
    gz_system = "NavSat"
    output_kind = "navsat"

    kind = "GPS"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.origin = SphericalCoordinates()
        self.noise = GpsNoise()
        self._vel: Endpoint | None = None

    def configure(self, ctx: SystemContext) -> None:
        """Read the world's spherical coordinates and the noise; declare ``~/out`` and ``~/vel``."""
        if self._parse_sensor(ctx, "gps", lambda _s, _log: True) is None or ctx.sensor is None:
            return
        if not self._configure_common(ctx, advertise=False):
            return
        assert self.output is not None
        if ctx.plugin is None:  # gz navsat: <topic> or .../navsat
            topic = ctx.sensor.topic or gz_scoped_topic(ctx, self.link, ctx.sensor, "navsat")
            self.output = dataclasses.replace(self.output, topic=resolve_topic(topic, ctx.entity.namespace))
        self._pub = ctx.bus.advertise(ctx.entity.name, self.output.topic, MsgType.NAV_SAT_FIX, depth=SENSOR_DEPTH)
        if ctx.plugin is not None:
            c = self.config
            vel = resolve_topic("~/vel", c.namespace, dict(c.remappings), node=ctx.plugin.name)
            self._vel = ctx.bus.advertise(ctx.entity.name, vel, MsgType.VECTOR3_STAMPED, depth=SENSOR_DEPTH)
        if ctx.spherical_coordinates is None:
            where = f"{ctx.sensor.location}: " if ctx.sensor.location else ""
            ctx.logger.warning(
                f"{where}GPS '{ctx.sensor.name}': the world has no <spherical_coordinates>; its origin is 0° N 0° E"
            )
        self.origin = ctx.spherical_coordinates or SphericalCoordinates()
        self.noise = parse_gps_noise(ctx.sensor, ctx.logger)
        ctx.logger.info(f"GPS '{ctx.sensor.name}' at {self.rate_hz:g} Hz on [{self.output.topic}]")

    def read(self, world: PhysicsWorld) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """((latitude, longitude, altitude), ENU velocity) of the sensor now, with noise."""
        assert self._body is not None
        X_WB = self._body.pose
        X = X_WB * self.offset
        h = self.origin.heading_deg
        e, n, u = world_to_enu(X.position, h)
        lin, ang = self._body.velocity
        r = np.asarray(X.position) - np.asarray(X_WB.position)
        v = np.asarray(lin) + np.cross(np.asarray(ang), r)  # the sensor point's velocity
        ve, vn, vu = world_to_enu((float(v[0]), float(v[1]), float(v[2])), h)
        nz = self.noise

        def noisy(value: float, noise: Noise) -> float:
            if not noise.active:
                return value
            return value + noise.mean + (float(self._rng.normal(0.0, noise.stddev)) if noise.stddev > 0 else 0.0)

        e, n = noisy(e, nz.position_horizontal), noisy(n, nz.position_horizontal)
        u = noisy(u, nz.position_vertical)
        ve, vn = noisy(ve, nz.velocity_horizontal), noisy(vn, nz.velocity_horizontal)
        vu = noisy(vu, nz.velocity_vertical)
        return enu_to_geodetic(e, n, u, self.origin), (ve, vn, vu)

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the fix (and the velocity) stamped with this sim time."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.rate_hz):
            return
        want_fix = self._pub.wanted
        want_vel = self._vel is not None and self._vel.wanted
        if not (want_fix or want_vel):
            return
        assert self.output is not None
        (lat, lon, alt), vel = self.read(world)
        t, frame = info.sim_time_sec, self.output.frame_id
        if want_fix:
            sh, sv = self.noise.position_horizontal.stddev, self.noise.position_vertical.stddev
            cov = (sh * sh, 0.0, 0.0, 0.0, sh * sh, 0.0, 0.0, 0.0, sv * sv)
            self._pub.publish(NavSatFix(t, frame, lat, lon, alt, cov, 2 if any(cov) else 0))
        if want_vel and self._vel is not None:
            self._vel.publish(Vector3Stamped(t, frame, vel))


# --------------------------------------------------------------------------- force-torque
@dataclass(frozen=True)
class ForceTorqueConfig:
    """Parameters of ``libgazebo_ros_ft_sensor.so`` (a model plugin), and of a gz-sim
    ``<sensor type="force_torque">`` in a ``<joint>``."""

    joint_name: str = ""
    """``<joint_name>`` (ROS 1: ``<jointName>``); for a gz-sim sensor, the joint it is in."""
    frame: str = "child"
    """gz-sim ``<force_torque><frame>``: child, parent or sensor. The plugin reports in the child frame."""
    measure_direction: str = "child_to_parent"
    """gz-sim ``<measure_direction>``: child_to_parent or parent_to_child (the plugin's)."""
    update_rate: float = 0.0
    """``<update_rate>`` (ROS 1: ``<updateRate>``), Hz of sim time; 0 = every step."""
    gaussian_noise: float = 0.0
    """``<gaussian_noise>`` (ROS 1: ``<gaussianNoise>``): standard deviation on every component."""
    topic: str = "wrench"
    """The plugin's topic (ROS 1: ``<topicName>``); gz-sim: ``<topic>``."""


@sensor_system
class ForceTorqueSensor(System):
    """The wrench through a joint (geometry_msgs/WrenchStamped), at the joint's origin.

    * gz-sim (``<sensor type="force_torque">`` in a ``<joint>``, with the world's
      ``gz-sim-forcetorque-system``): ``<force_torque><frame>`` child (default), parent or sensor, and
      ``<measure_direction>`` child_to_parent (default: what the child exerts on the parent) or
      parent_to_child; on ``<topic>``, else ``/world/<w>/model/<m>/joint/<j>/sensor/<s>/forcetorque``.
    * gazebo_ros (``libgazebo_ros_ft_sensor.so``, a model plugin): ``<joint_name>`` (ROS 1:
      ``<jointName>``), ``<update_rate>``, ``<gaussian_noise>``; the wrench on the child link in its
      frame, on ``wrench`` (ROS 1: ``<topicName>``) under ``<ros><namespace>``.
    """

    sdf_types = frozenset({"force_torque"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = "ForceTorque"

    def __init__(self, seed: int | None = None) -> None:
        self.config = ForceTorqueConfig()
        self.offset = Pose()
        """The sensor frame in the joint frame (frame "sensor")."""
        self.frame_id = ""
        self._X_CJ = Pose()
        """The joint frame in the child link frame."""
        self._child: BodyHandle | None = None
        self._parent: BodyHandle | None = None
        self._pub: Endpoint | None = None
        self._gate = RateGate()
        self.phase_gate = self._gate
        self._rng = np.random.default_rng(seed)

    def seed_noise(self, seed: int) -> None:
        self._rng = np.random.default_rng(seed)

    @property
    def topic(self) -> str:
        """Where the wrench goes."""
        return self.config.topic

    def _parse(self, ctx: SystemContext) -> tuple[ForceTorqueConfig, str]:
        """The parameters from the gz ``<sensor>`` or the gazebo_ros plugin, and a file:line prefix."""
        log, sensor, plugin = ctx.logger, ctx.sensor, ctx.plugin
        if sensor is not None:
            block = sensor.config.find("force_torque") if sensor.config is not None else None
            where = f"{sensor.location}: " if sensor.location else ""
            frame = (child_text(block, "frame") or "child").strip().lower()
            if frame not in ("child", "parent", "sensor"):
                log.warning(f"{where}<frame> '{frame}' is not child, parent or sensor; using child")
                frame = "child"
            direction = (child_text(block, "measure_direction") or "child_to_parent").strip().lower()
            scoped = f"/world/{ctx.world_name}/model/{ctx.entity.name}/joint/{sensor.joint}"
            topic = resolve_topic(sensor.topic or f"{scoped}/sensor/{sensor.name}/forcetorque", ctx.entity.namespace)
            return ForceTorqueConfig(sensor.joint, frame, direction, sensor.update_rate_hz, 0.0, topic), where
        cfg = plugin.config if plugin is not None else None
        ns, remaps = ros_block(cfg)
        ns = ns or child_text(cfg, "robotNamespace") or ctx.entity.namespace
        return ForceTorqueConfig(
            joint_name=child_text(cfg, "joint_name") or child_text(cfg, "jointName") or "",
            measure_direction="parent_to_child",
            update_rate=parse_float(cfg, "update_rate", parse_float(cfg, "updateRate", 0.0, log), log),
            gaussian_noise=parse_float(cfg, "gaussian_noise", parse_float(cfg, "gaussianNoise", 0.0, log), log),
            topic=resolve_topic(child_text(cfg, "topicName") or "wrench", ns, remaps),
        ), (f"{plugin.location}: " if plugin is not None and plugin.location else "")

    def configure(self, ctx: SystemContext) -> None:
        """Find the joint; read the frame, direction, rate and topic."""
        log = ctx.logger
        c, where = self._parse(ctx)
        c = dataclasses.replace(
            c, update_rate=checked_rate(c.update_rate, ctx.world.timestep, where, "force-torque sensor", log)
        )
        self.config = c
        joint = next((j for j in ctx.entity.model.joints if j.name == c.joint_name), None)
        if joint is None:
            log.error(f"{where}force-torque sensor: '{ctx.entity.name}' has no joint '{c.joint_name}'; it does nothing")
            return
        self._X_CJ = joint.child_offset.inverse()
        self._child = ctx.world.body(ctx.entity.name, joint.child)
        self._parent = ctx.world.body(ctx.entity.name, joint.parent)
        from .robot_state import entity_frame_prefix

        prefix = entity_frame_prefix(ctx.entity, log)
        if ctx.sensor is not None:
            self.offset = ctx.sensor.pose
            frame_link = {"child": joint.child, "parent": joint.parent}.get(c.frame)
            self.frame_id = (
                prefix + frame_link if frame_link else f"{ctx.entity.name}::{c.joint_name}::{ctx.sensor.name}"
            )
        else:
            self.frame_id = prefix + joint.child
        self._pub = ctx.bus.advertise(ctx.entity.name, c.topic, MsgType.WRENCH_STAMPED, depth=SENSOR_DEPTH)
        log.info(f"force-torque on joint [{c.joint_name}] at {c.update_rate:g} Hz on [{c.topic}] in [{self.frame_id}]")

    def next_update(self, sim_time_sec: float) -> float:
        """The next reading time (never, when not configured)."""
        return self._gate.next if self._pub is not None else math.inf

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Read again at the next step after a world reset."""
        self._gate.reset()

    def read(self, world: PhysicsWorld) -> tuple[np.ndarray, np.ndarray]:
        """(force, torque) at the joint origin, in the output frame and direction."""
        assert self._child is not None and self._parent is not None
        c = self.config
        X_WC = self._child.pose
        X_WJ = X_WC * self._X_CJ
        f, t = self._child.joint_wrench(np.asarray(X_WJ.position))
        if c.measure_direction != "parent_to_child":
            f, t = -f, -t
        if c.frame == "parent":
            R = rotation_matrix(self._parent.pose.orientation)
        elif c.frame == "sensor":
            R = rotation_matrix((X_WJ * self.offset).orientation)
        else:
            R = rotation_matrix(X_WC.orientation)
        f, t = R.T @ f, R.T @ t
        if c.gaussian_noise > 0:
            f = f + self._rng.normal(0.0, c.gaussian_noise, 3)
            t = t + self._rng.normal(0.0, c.gaussian_noise, 3)
        return f, t

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the wrench stamped with this sim time."""
        if self._pub is None or info.paused or not self._gate.due(info.sim_time_sec, self.config.update_rate):
            return
        if not self._pub.wanted:
            return
        f, t = self.read(world)
        self._pub.publish(
            WrenchStamped(
                info.sim_time_sec,
                self.frame_id,
                (float(f[0]), float(f[1]), float(f[2])),
                (float(t[0]), float(t[1]), float(t[2])),
            )
        )

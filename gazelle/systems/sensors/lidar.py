"""Lidars and rays (``ray``, ``gpu_ray``, ``lidar``, ``gpu_lidar``): LaserScan, PointCloud2 or Range, cast in one
``mj_multiRay`` call against collision geoms (excluding the sensor's own link); beyond the maximum range +inf,
nearer than the minimum -inf (REP 117).

What is matched, and where:

- the ±inf readings: gz-sensors 8's ``GpuLidarSensor.cc`` turns clamping off ("Mask ranges outside of min/max to
  +/- inf, as per REP 117"); noise (with its bias drawn once) is then added to the readings in range only and
  the result clamped into ``[range_min, range_max]`` (``Lidar::ApplyNoise``), so noise never makes a hit ±inf.
- the LaserScan of a multi-row lidar, its zero ``scan_time``/``time_increment``, the PointCloud2 of hits only and
  the Range as the least ray: gazebo_ros's ``conversions/sensor_msgs.hpp`` (ros_gz_bridge fills the LaserScan's
  two times with 0 too).
- Differs: Gazebo's ``gpu_*`` sensors render visuals, gazelle casts against collision geoms for every type (a
  model whose visuals and collisions differ reads differently); intensities are one value for every ray (the
  plugin's ``<min_intensity>``, at least 0), where Gazebo reads a retro-reflectivity per visual.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ...description import (
    ConfigElement,
    Plugin,
    Sensor,
    rotation_matrix,
)
from ...physics import PhysicsWorld
from .._base import RateGate, SystemContext, UpdateInfo
from .._bus import MessageKind, MsgType
from .._payloads import LaserScan, PointCloud, Range
from .._plugin_config import child_text, parse_float
from .._registration import add_plugin
from ._common import (
    Noise,
    Output,
    SensorConfigError,
    SensorLimitError,
    SensorPluginConfig,
    _SensorSystem,
    parse_noise,
)

LIDAR_TYPES = frozenset({"ray", "gpu_ray", "lidar", "gpu_lidar"})
"""``<sensor type>`` values cast as rays (Gazebo's ``gpu_*`` variants see visuals; here all see collisions)."""


MAX_RAYS = 1_048_576
"""The most rays one lidar scan may cast: twice a 128 x 4096 automotive lidar (524,288). A scan of
2,000,000 rays ran the world at 0.035 of real time with 5 s between clocks."""


# --------------------------------------------------------------------------- lidar geometry
@dataclass(frozen=True)
class ScanAxis:
    """One axis of ``<scan>``: ``samples`` x ``resolution`` rays from ``min_angle`` to ``max_angle``."""

    samples: int = 1
    """``<samples>``: rays on this axis before ``resolution``."""
    resolution: float = 1.0
    """``<resolution>``: multiplies ``samples`` (SDF's way of asking for more or fewer readings)."""
    min_angle: float = 0.0
    """``<min_angle>``, radians."""
    max_angle: float = 0.0
    """``<max_angle>``, radians (the last ray's angle: both ends are cast)."""

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
    """``<scan><horizontal>``: angles about the sensor's z axis, 0 straight ahead (x), positive to the left."""
    vertical: ScanAxis = ScanAxis()
    """``<scan><vertical>``: elevation angles, positive up; one row (a 2D scanner) by default."""
    range_min: float = 0.0
    """``<range><min>``, metres: a hit nearer reads -inf."""
    range_max: float = 10.0
    """``<range><max>``, metres: rays end there; nothing within it reads +inf."""
    noise: Noise = Noise()
    """``<noise>``: Gaussian on each range, metres (hits only: a miss stays +inf)."""

    def directions(self) -> np.ndarray:
        """Unit ray directions in the sensor frame, vertical-major (row v, column h): x forward, z up."""
        h = self.horizontal.angles()
        v = self.vertical.angles()
        cv, sv = np.cos(v)[:, None], np.sin(v)[:, None]
        d = np.stack([cv * np.cos(h)[None, :], cv * np.sin(h)[None, :], np.broadcast_to(sv, (len(v), len(h)))], axis=-1)
        return d.reshape(-1, 3)


def _axis(el: ConfigElement | None, log: logging.Logger, default: ScanAxis) -> ScanAxis:
    """One ``<scan>`` axis (``<horizontal>`` or ``<vertical>``), its values read with warnings, ``default`` where
    the block says nothing."""
    if el is None:
        return default
    return ScanAxis(
        int(parse_float(el, "samples", default.samples, log)),
        parse_float(el, "resolution", default.resolution, log),
        parse_float(el, "min_angle", default.min_angle, log),
        parse_float(el, "max_angle", default.max_angle, log),
    )


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


_OUTPUT_TYPES = {
    "sensor_msgs/laserscan": MsgType.LASER_SCAN,
    "sensor_msgs/msg/laserscan": MsgType.LASER_SCAN,
    "sensor_msgs/pointcloud2": MsgType.POINT_CLOUD2,
    "sensor_msgs/msg/pointcloud2": MsgType.POINT_CLOUD2,
    "sensor_msgs/range": MsgType.RANGE,
    "sensor_msgs/msg/range": MsgType.RANGE,
}
"""``<output_type>`` -> the message a ray sensor publishes."""


@dataclass(frozen=True)
class RayPluginConfig(SensorPluginConfig):
    """The ray plugins' settings: ``libgazebo_ros_ray_sensor.so`` (ROS 2), ROS 1's ``libgazebo_ros_laser.so`` /
    ``libgazebo_ros_gpu_laser.so`` (LaserScan) and ``libgazebo_ros_range.so`` (Range on ``/range``, ultrasound)."""

    output_type: str = "sensor_msgs/PointCloud2"
    """``sensor_msgs/PointCloud2`` (the default; ROS 1's laser plugins: LaserScan, its range plugin: Range),
    ``sensor_msgs/LaserScan`` or ``sensor_msgs/Range``."""
    radiation_type: str = "infrared"
    """Range output: ``infrared`` or ``ultrasound`` (``<radiation_type>``; ROS 1's gazebo_ros_range:
    ``<radiation>``, ultrasound by default)."""
    min_intensity: float = -math.inf
    """Intensities below it are raised to it (gazelle's rays have intensity 0: no laser_retro yet)."""
    gaussian_noise: float = 0.0
    """ROS 1's gazebo_ros_range: ``<gaussianNoise>``, the standard deviation added to a reading."""

    @classmethod
    def settings(cls, plugin: Plugin, cfg: ConfigElement, ctx: SystemContext) -> dict[str, Any]:
        """The common settings, the output type (each ROS 1 plugin's own default) and the range's radiation,
        and ROS 1's ``<gaussianNoise>`` (the range plugin adds it to its readings)."""
        out = super().settings(plugin, cfg, ctx)
        log, filename = ctx.logger, plugin.filename.lower()
        ros1_range = "gazebo_ros_range" in filename
        raw_type = child_text(cfg, "output_type")
        if raw_type is None and "laser" in filename:
            raw_type = "sensor_msgs/LaserScan"  # ROS 1's gazebo_ros_laser publishes LaserScan
        if raw_type is None and ros1_range:
            raw_type = "sensor_msgs/Range"  # ROS 1's gazebo_ros_range (<radiation>, default ultrasound)
        radiation = child_text(cfg, "radiation_type") or child_text(cfg, "radiation")
        if ros1_range:
            out["topic"] = child_text(cfg, "topicName") or "/range"
        return out | {
            "output_type": raw_type or "sensor_msgs/PointCloud2",
            "radiation_type": (radiation or ("ultrasound" if ros1_range else "infrared")).strip().lower(),
            "min_intensity": parse_float(cfg, "min_intensity", -math.inf, log),
            "gaussian_noise": parse_float(cfg, "gaussianNoise", 0.0, log),
        }

    def message_type(self, ctx: SystemContext, default: MessageKind) -> MessageKind:
        """``<output_type>``'s message; one gazelle does not publish is warned about, and PointCloud2 used."""
        found = _OUTPUT_TYPES.get(self.output_type.strip().lower())
        if found is None:
            el = ctx.plugin.config.find("output_type") if ctx.plugin is not None and ctx.plugin.config else None
            where = f"{el.location}: " if el is not None and el.location else ""
            ctx.logger.warning(
                f"{where}<output_type> '{self.output_type}' is not one gazelle publishes (LaserScan, PointCloud2, "
                "Range); publishing sensor_msgs/PointCloud2"
            )
            found = MsgType.POINT_CLOUD2
        return found

    def output(self, topic: str, frame_id: str, msg_type: MessageKind) -> Output:
        """With the range's radiation type (sensor_msgs/Range: 0 ultrasound, 1 infrared) and the intensity floor."""
        return Output(
            topic,
            frame_id,
            msg_type,
            radiation_type=0 if self.radiation_type == "ultrasound" else 1,
            min_intensity=self.min_intensity,
        )


class Lidar(_SensorSystem):
    """A ray / lidar sensor: LaserScan, PointCloud2 or Range (see the module docstring)."""

    sdf_types = LIDAR_TYPES
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {
        "gazebo_ros_ray_sensor": None,
        "gazebo_ros_laser": None,
        "gazebo_ros_gpu_laser": None,
        "gazebo_ros_range": None,
    }
    gz_system = "Sensors"
    output_kind = "scan"
    plugin_config = RayPluginConfig
    config: RayPluginConfig

    kind = "lidar"

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured lidar (see :meth:`configure`); ``seed`` seeds its range noise."""
        super().__init__(seed)
        self.spec = LidarSpec()
        self._dirs = np.zeros((0, 3))
        self._bias = 0.0
        self._intensity_cache: tuple[tuple[int, float], bytes] = ((0, 0.0), b"")
        self._ros1_range: tuple[float, float] | None = None
        """ROS 1's gazebo_ros_range: its (``<fov>``, ``<gaussianNoise>``); None for the other plugins."""
        self._ros1_gate = RateGate()

    def configure(self, ctx: SystemContext) -> None:
        """Parse the sensor's ``<ray>``/``<lidar>`` block and the plugin; declare the output topic."""
        spec = self._parse_sensor(ctx, "ray", parse_lidar)
        if spec is None or ctx.sensor is None:
            return
        self.spec = spec
        if not self._configure_common(ctx):
            return
        self._dirs = self.spec.directions()
        if ctx.plugin is not None and "gazebo_ros_range" in ctx.plugin.filename.lower():
            # <updateRate> and <gaussianNoise> are read with the other ROS 1 names (RayPluginConfig)
            fov = parse_float(ctx.plugin.config, "fov", 0.05, ctx.logger)  # gazebo_ros_range.cpp's default
            self._ros1_range = (fov, self.config.gaussian_noise)
        self._bias = self.spec.noise.bias(self._rng)  # one bias per sensor and run (GaussianNoiseModel::Load)
        assert self.output is not None
        s = self.spec
        ctx.logger.info(
            f"{ctx.sensor.type} '{ctx.sensor.name}': {s.vertical.count}x{s.horizontal.count} rays, "
            f"{s.range_min:g}..{s.range_max:g} m at {self.rate_hz:g} Hz on [{self.output.topic}] "
            f"({self.output.msg_type.value.rsplit('/', 1)[-1]}) in frame [{self.output.frame_id}]"
        )

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """A world reset: the sensor's rate gate and gazebo_ros_range's throttle start again."""
        super().reset(info, world)
        self._ros1_gate.reset()

    def scan(self, world: PhysicsWorld, *, noise: bool = True) -> np.ndarray:
        """Ranges (vertical-major, v rows x h columns) with noise (unless ``noise`` is False: the viewer's
        overlay, which must not draw from the sensor's random stream) and REP 117's ±inf."""
        assert self._body is not None
        s = self.spec
        dist, _ = self._body.cast_rays_from(self.offset, self._dirs, s.range_max)
        # REP 117 from the true distance first: a miss, or a hit past range_max (mj_multiRay's cutoff only
        # prunes by bounding box, so farther hits come back too), is +inf; a hit nearer than range_min -inf
        ranges = np.where(dist >= 0, dist, np.inf)
        np.copyto(ranges, np.inf, where=ranges > s.range_max)
        np.copyto(ranges, -np.inf, where=ranges < s.range_min)
        if noise and s.noise.active:
            # then noise on the readings in range, clamped back into [range_min, range_max]: gz-sensors 8's
            # Lidar::ApplyNoise (Lidar.cc: Apply, then Clamp, which leaves ±inf alone), so noise never turns a
            # hit into ±inf nor a miss into a hit
            ok = np.isfinite(ranges)
            jitter = self._rng.normal(0.0, s.noise.stddev, int(ok.sum())) if s.noise.stddev > 0 else 0.0
            ranges[ok] = np.clip(ranges[ok] + self._bias + s.noise.mean + jitter, s.range_min, s.range_max)
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
        # the message the plugin's <output_type> asks for (gazebo_ros_ray_sensor; gz-sim: LaserScan for a lidar)
        if out.msg_type is MsgType.LASER_SCAN:
            # a LaserScan is one plane: of a multi-row lidar, its middle row (row vertical_count // 2, as
            # gazebo_ros's conversions/sensor_msgs.hpp `Convert<LaserScan>` takes it). scan_time and
            # time_increment stay 0: both gazebo_ros (same file) and ros_gz_bridge (convert/sensor_msgs.cpp) send
            # 0: the scan is one instant of sim time (a time_increment of 0 tells laser_geometry's
            # transformLaserScanToPointCloud that every ray was taken at the stamp)
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
                )
            )
        elif out.msg_type is MsgType.RANGE and self._ros1_range is not None:
            self._publish_ros1_range(t, ranges)
        elif out.msg_type is MsgType.RANGE:
            # a Range (sonar, IR): the least of the cone's rays, as gazebo_ros's `Convert<Range>`
            # (conversions/sensor_msgs.hpp) takes it: a ray nearer than range_min (-inf) wins over hits in range.
            # Where every ray misses, upstream's loop leaves its start value, FLT_MAX; gazelle sends REP 117's
            # +inf (both read as out of range to a `range >= max_range` check)
            r = float(ranges.min())
            fov = max(s.horizontal.max_angle - s.horizontal.min_angle, s.vertical.max_angle - s.vertical.min_angle)
            self._pub.publish(Range(t, out.frame_id, out.radiation_type, fov, s.range_min, s.range_max, r))
        else:
            # a PointCloud2 of the hits only (an unorganised cloud), in the sensor frame: x forward, z up
            flat = ranges.reshape(-1)
            ok = np.isfinite(flat)
            pts = self._dirs[ok] * flat[ok, None]
            cloud = np.empty((len(pts), 4), np.float32)
            cloud[:, :3] = pts
            cloud[:, 3] = intensity
            self._pub.publish(PointCloud(t, out.frame_id, len(pts), 1, cloud.astype("<f4").tobytes()))

    def _publish_ros1_range(self, t: float, ranges: np.ndarray) -> None:
        """ROS 1's gazebo_ros_range (gazebo_plugins ``gazebo_ros_range.cpp`` ``PutRangeData``), throttled to its
        ``<updateRate>``: the least of the rays' raw ranges, where Classic's rays report ``range_max`` for a miss
        (so the message says ``range_max``, never +inf), then ``<gaussianNoise>`` added to a reading below
        ``range_max`` and capped there; ``field_of_view`` is the plugin's ``<fov>`` (0.05 by default), not the
        rays' spread. Classic's rays start at ``range_min``; a hit nearer than that reads ``range_min`` here."""
        if not self._ros1_gate.due(t, self.config.update_rate):
            return
        assert self._pub is not None and self.output is not None and self._ros1_range is not None
        s, out = self.spec, self.output
        fov, noise = self._ros1_range
        raw = np.where(np.isposinf(ranges), s.range_max, np.where(np.isneginf(ranges), s.range_min, ranges))
        r = float(raw.min())
        if r < s.range_max and noise > 0:
            r = min(r + float(self._rng.normal(0.0, noise)), s.range_max)
        self._pub.publish(Range(t, out.frame_id, out.radiation_type, fov, s.range_min, s.range_max, r))


add_plugin(Lidar)

"""IMUs: orientation, angular velocity in the sensor frame and proper linear acceleration (+g upwards at
rest), with Gaussian noise and biases as gz-sensors draws them (sensor_msgs/Imu).

The orientation is reported against a reference frame, which differs between the two Gazebos:

* **gz-sim** (no gazebo_ros plugin; gz-sim8 ``src/systems/imu/Imu.cc`` ``AddSensor`` with gz-sensors
  ``src/ImuSensor.cc``): the sensor's own world orientation when it was created (its spawn pose), so a
  robot spawned facing +y reads the identity. ``<imu><orientation_reference_frame>`` with
  ``<localization>`` ENU, NED or NWU makes it the world's ENU frame (turned by the world's
  ``<heading_deg>``) times that frame's rotation; CUSTOM with ``<custom_rpy parent_frame="world">`` the
  world's times ``custom_rpy``. ``<enable_orientation>false`` leaves the orientation unset (four zeros
  once bridged).
* **gazebo_ros_imu_sensor** (Classic, ros2 branch ``gazebo_plugins/src/gazebo_ros_imu_sensor.cpp``): the
  world (REP 145), unless ``<initial_orientation_as_reference>`` is true (ROS 1:
  ``<initialOrientationAsReference>``), which takes the spawn orientation as gz-sim does.
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
    Quat,
    Sensor,
    parse_floats,
    quat_conj,
    quat_from_rpy,
    quat_mul,
)
from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._payloads import Imu, Vec3
from .._plugin_config import child_text, parse_bool, parse_float
from .._registration import add_plugin
from ._common import (
    NOISE_ROWS,
    Noise,
    SensorPluginConfig,
    _SensorSystem,
    parse_noise,
    xyz_noise,
)


@dataclass(frozen=True)
class ImuNoise:
    """Per-channel noise of an IMU: angular velocity x, y, z and linear acceleration x, y, z."""

    rate: tuple[Noise, Noise, Noise] = (Noise(), Noise(), Noise())
    accel: tuple[Noise, Noise, Noise] = (Noise(), Noise(), Noise())


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
            return ImuNoise(xyz_noise(av, log, "IMU angular velocity"), xyz_noise(la, log, "IMU linear acceleration"))
        old = imu.find("noise")
        if old is not None:
            r, a = _imu_channel(old, "rate", log), _imu_channel(old, "accel", log)
            return ImuNoise((r, r, r), (a, a, a))
    g = parse_float(plugin_cfg, "gaussianNoise", 0.0, log) if plugin_cfg is not None else 0.0
    if g > 0:  # ROS 1's model plugin
        n = Noise("gaussian", 0.0, g)
        return ImuNoise((n, n, n), (n, n, n))
    return ImuNoise()


_NAMED_FRAMES: dict[str, Quat] = {
    "ENU": (1.0, 0.0, 0.0, 0.0),
    "NED": quat_from_rpy(math.pi, 0.0, math.pi / 2),
    "NWU": quat_from_rpy(0.0, 0.0, math.pi / 2),
}
"""gz-sensors ImuSensor.cc ``SetWorldFrameOrientation``: each named frame's rotation from the world's ENU
frame (gz-sim hands the world over as ENU)."""


@dataclass(frozen=True)
class OrientationReference:
    """What an IMU's orientation is reported against: a fixed frame in the world (``fixed``), or, when
    ``fixed`` is None, the sensor's own orientation at the first step it runs (its spawn pose)."""

    fixed: Quat | None = None
    """The reference's world orientation (wxyz); None: the spawn orientation."""
    enabled: bool = True
    """False: no orientation is reported (``<enable_orientation>false``: four zeros)."""


def gz_orientation_reference(sensor: Sensor | None, heading_deg: float, log: logging.Logger) -> OrientationReference:
    """gz-sim's reference for an IMU run by its Imu system (see the module's docstring); a reference
    gz-sensors does not apply either (CUSTOM on another parent, GRAV_UP, GRAV_DOWN, a misspelling) is named
    in a warning, and the spawn orientation stays the reference, as in gz-sim."""
    imu = _imu_block(sensor)
    enabled = parse_bool(imu, "enable_orientation", True, log)
    frame = imu.find("orientation_reference_frame") if imu is not None else None
    if frame is None:
        return OrientationReference(None, enabled)
    where = f"{frame.location}: " if frame.location else ""
    heading = quat_from_rpy(0.0, 0.0, math.radians(heading_deg))  # Imu.cc: the world's heading offset, about z
    localization = (child_text(frame, "localization") or "CUSTOM").strip()  # sdf/1.11/imu.sdf's default
    if localization in _NAMED_FRAMES:
        return OrientationReference(quat_mul(heading, _NAMED_FRAMES[localization]), enabled)
    if localization == "CUSTOM":
        rpy = frame.find("custom_rpy")
        parent = rpy.attr("parent_frame", "") if rpy is not None else ""
        if rpy is not None and parent == "world":
            values = parse_floats(rpy.text, 3) if rpy.text.strip() else (0.0, 0.0, 0.0)  # sdf: "0 0 0" by default
            if values is not None:
                return OrientationReference(quat_mul(heading, quat_from_rpy(*values)), enabled)
            log.warning(f"{where}IMU <custom_rpy> must be three numbers, got {rpy.text.strip()!r} (rpy is 0 0 0)")
            return OrientationReference(heading, enabled)
        log.warning(
            f"{where}IMU <orientation_reference_frame> CUSTOM with <custom_rpy parent_frame={parent!r}>: "
            "gz-sensors takes only parent_frame 'world'; the orientation is relative to the sensor's spawn pose"
        )
        return OrientationReference(None, enabled)
    log.warning(
        f"{where}IMU <orientation_reference_frame> <localization> {localization!r} is not one gz-sensors applies "
        "(ENU, NED, NWU, CUSTOM); the orientation is relative to the sensor's spawn pose"
    )
    return OrientationReference(None, enabled)


def _imu_block(sensor: Sensor | None) -> ConfigElement | None:
    """The ``<imu>`` element of a ``<sensor>``, if any."""
    config = sensor.config if sensor is not None else None
    return config.find("imu") if config is not None else None


@dataclass(frozen=True)
class ImuPluginConfig(SensorPluginConfig):
    """The IMU plugins' settings: ``libgazebo_ros_imu_sensor.so`` (inside a ``<sensor>``) and ROS 1's
    ``libgazebo_ros_imu.so`` model plugin (``<bodyName>``, ``<updateRate>``, ``<gaussianNoise>``)."""

    gaussian_noise: float = 0.0
    """ROS 1's ``<gaussianNoise>``: the standard deviation of every channel when no ``<imu><noise>`` says more
    (:func:`parse_imu_noise`)."""
    initial_orientation_as_reference: bool = False
    """``<initial_orientation_as_reference>`` (ROS 1: ``<initialOrientationAsReference>``): report the orientation
    relative to the sensor's spawn orientation instead of the world (REP 145's reference)."""

    @classmethod
    def settings(cls, plugin: Plugin, cfg: ConfigElement, ctx: SystemContext) -> dict[str, Any]:
        """The common settings, the orientation reference and ROS 1's model plugin's link and noise."""
        log = ctx.logger
        return super().settings(plugin, cfg, ctx) | {
            "initial_orientation_as_reference": parse_bool(
                cfg,
                "initial_orientation_as_reference"
                if cfg.find("initialOrientationAsReference") is None
                else "initialOrientationAsReference",  # ROS 1's gazebo_ros_imu_sensor spelling
                False,
                log,
            ),
            "body_name": child_text(cfg, "bodyName") or child_text(cfg, "body_name") or "",
            "gaussian_noise": parse_float(cfg, "gaussianNoise", 0.0, log),
        }


class ImuSensor(_SensorSystem):
    """An IMU: orientation, angular velocity and proper linear acceleration (sensor_msgs/Imu)."""

    sdf_types = frozenset({"imu"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_imu_sensor": None}
    gz_system = "Imu"
    plugin_files = ("gazebo_ros_imu",)  # ROS 1's IMU model plugin (<bodyName>), as in TurtleBot3's noetic xacro
    output_kind = "imu"
    plugin_config = ImuPluginConfig
    config: ImuPluginConfig

    kind = "IMU"

    def __init__(self, seed: int | None = None) -> None:
        """An unconfigured IMU (see :meth:`configure`) reporting against the world, gazebo_ros's default;
        ``seed`` seeds its noise and biases."""
        super().__init__(seed)
        self.noise = ImuNoise()
        self.reference = OrientationReference(fixed=(1.0, 0.0, 0.0, 0.0))
        """What the orientation is reported against (gazebo_ros's default: the world)."""
        self._q0: Quat | None = None
        """The reference's world orientation once known (the spawn orientation is taken at the first step)."""
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
        heading = ctx.spherical_coordinates.heading_deg if ctx.spherical_coordinates is not None else 0.0
        if ctx.plugin is None:  # run by gz-sim's Imu system
            self.reference = gz_orientation_reference(ctx.sensor, heading, ctx.logger)
        else:
            if self.config.initial_orientation_as_reference:
                self.reference = OrientationReference(None)
            imu = _imu_block(ctx.sensor)
            for tag in ("orientation_reference_frame", "enable_orientation"):
                el = imu.find(tag) if imu is not None else None
                if el is not None:  # gazebo_ros_imu_sensor sets the reference itself (the world, or the spawn pose)
                    ctx.logger.warning(
                        f"{f'{el.location}: ' if el.location else ''}IMU <{tag}> is not applied under "
                        f"{ctx.plugin.filename}: the orientation is against the world (REP 145), or the spawn "
                        "orientation with <initial_orientation_as_reference>"
                    )
        self._q0 = self.reference.fixed
        # six channels: angular velocity x, y, z (rad/s), then linear acceleration x, y, z (m/s²); each gets a
        # bias drawn once for the run, then N(mean, stddev) per reading (gz-sensors' Gaussian noise model)
        channels = (*self.noise.rate, *self.noise.accel)
        self._bias = np.array([n.bias(self._rng) for n in channels])
        self._mean = np.array([n.mean if n.active else 0.0 for n in channels])
        self._std = np.array([n.stddev if n.active else 0.0 for n in channels])
        self._perturbed = bool(self._bias.any() or self._mean.any() or self._std.any())
        self._rows = []

        def cov(ns: tuple[Noise, Noise, Noise]) -> tuple[float, ...]:
            """The message's 3x3 covariance, row-major: each axis's variance on the diagonal (0, 4, 8)."""
            c = [0.0] * 9
            for i, n in enumerate(ns):
                c[4 * i] = n.stddev**2 if n.active else 0.0
            return tuple(c)

        self._cov = (cov(self.noise.rate), cov(self.noise.accel))
        assert self.output is not None
        ctx.logger.info(
            f"IMU on [{self.link}] at {self.rate_hz:g} Hz on [{self.output.topic}] in frame [{self.output.frame_id}]"
        )

    def read(self) -> tuple[Quat, Vec3, Vec3]:
        """(orientation, angular velocity, linear acceleration) with noise, as published."""
        assert self._body is not None
        r = self._body.imu_reading(self.offset)  # ideal: orientation, then gyro and accelerometer in the sensor frame
        q = (r[0], r[1], r[2], r[3])
        if self._q0 is None:  # the first reading before the first step (a test's direct read)
            self._q0 = q
        if not self.reference.enabled:
            q = (0.0, 0.0, 0.0, 0.0)
        elif self._q0 != (1.0, 0.0, 0.0, 0.0):
            q = quat_mul(quat_conj(self._q0), q)  # gz-sensors: reference⁻¹ · the sensor's world orientation
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
        """At the sensor's rate, while listened to: read and publish stamped with this sim time. At its first
        step it takes its spawn orientation as the reference when that is the reference (listened to or
        not: gz-sim takes it when the sensor is created); a world reset keeps it (gz-sim's Imu system has no
        reset)."""
        if self._q0 is None and self._body is not None:
            r = self._body.imu_reading(self.offset)
            self._q0 = (r[0], r[1], r[2], r[3])
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


add_plugin(ImuSensor)

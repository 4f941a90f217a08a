"""IMUs: orientation, angular velocity in the sensor frame and proper linear acceleration (+g upwards at
rest), with Gaussian noise and biases as gz-sensors draws them (sensor_msgs/Imu)."""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...description import (
    ConfigElement,
    Sensor,
    quat_conj,
    quat_mul,
)
from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._payloads import Imu, Vec3
from .._plugin_config import child_text, parse_float
from ._common import (
    NOISE_ROWS,
    Noise,
    _SensorSystem,
    parse_noise,
    sensor_system,
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


@sensor_system
class ImuSensor(_SensorSystem):
    """An IMU: orientation, angular velocity and proper linear acceleration (sensor_msgs/Imu)."""

    sdf_types = frozenset({"imu"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {"gazebo_ros_imu_sensor": None}
    gz_system = "Imu"
    plugin_files = ("gazebo_ros_imu",)  # ROS 1's IMU model plugin (<bodyName>), as in TurtleBot3's noetic xacro
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

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Measure again at the next step; a reference orientation is taken again."""
        super().reset(info, world)
        self._q0 = None

    def read(self) -> tuple[tuple[float, float, float, float], Vec3, Vec3]:
        """(orientation, angular velocity, linear acceleration) with noise, as published."""
        assert self._body is not None
        r = self._body.imu_reading(self.offset)  # ideal: orientation, then gyro and accelerometer in the sensor frame
        q = (r[0], r[1], r[2], r[3])
        # <initial_orientation_as_reference>: the orientation relative to the first reading (so a robot that
        # starts turned reads identity), instead of relative to the world's axes
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

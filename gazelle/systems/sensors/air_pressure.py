"""Air pressure (SDF ``<sensor type="air_pressure">``), as gz-sensors computes it and ros_gz_bridge publishes it:
sensor_msgs/FluidPressure, in pascals.

gz-sensors (``src/AirPressureSensor.cc``, constants from RotorS) takes the sensor's height as
``<air_pressure><reference_altitude>`` plus its world z, turns it into geopotential height, and reads the
US standard atmosphere's troposphere: 101,325 Pa at sea level, 288.15 K, a lapse of 6.5 K/km. Gaussian
``<air_pressure><pressure><noise>`` is added (its bias drawn once); the message's ``variance`` is then
``sqrt(stddev)``, as gz-sensors writes it (not stddev squared), and 0 without noise. gz-sim's
``gz-sim-air-pressure-system`` runs it and names its topic ``.../sensor/<s>/air_pressure`` unless
``<topic>`` says otherwise; Gazebo Classic had no ROS plugin for it.

This module is the whole of the sensor kind: its message (declared here), its reading and its
registration; the package's ``__init__`` imports it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._bus import DeclaredMessage, MessageKind
from .._registration import add_plugin
from ._common import Noise, _SensorSystem, parse_noise

FLUID_PRESSURE = DeclaredMessage("FLUID_PRESSURE", "sensor_msgs/msg/FluidPressure")

# gz-sensors src/AirPressureSensor.cc (from RotorS' gazebo_pressure_plugin.h)
GAS_CONSTANT = 8314.32
"""N m / (kmol K)."""
MOLAR_MASS_AIR = 28.9644
"""kg / kmol."""
GRAVITY = 9.80665
EARTH_RADIUS_M = 6356766.0
SEA_LEVEL_PA = 101325.0
SEA_LEVEL_K = 288.15
LAPSE_K_PER_M = 0.0065
AIR_CONSTANT = GRAVITY * MOLAR_MASS_AIR / (GAS_CONSTANT * -LAPSE_K_PER_M)


def pressure_at(height_m: float) -> float:
    """The air pressure (Pa) at ``height_m`` above sea level, as gz-sensors computes it."""
    geopotential = EARTH_RADIUS_M * height_m / (EARTH_RADIUS_M + height_m)
    temperature = SEA_LEVEL_K - LAPSE_K_PER_M * geopotential
    return SEA_LEVEL_PA * math.exp(AIR_CONSTANT * math.log(SEA_LEVEL_K / temperature))


@dataclass(frozen=True, slots=True)
class FluidPressure:
    """sensor_msgs/FluidPressure (its fields by name: see :class:`DeclaredMessage`)."""

    stamp_sec: float
    frame_id: str
    fluid_pressure: float
    """Pa."""
    variance: float


class AirPressureSensor(_SensorSystem):
    """An air pressure sensor on a link (see the module docstring)."""

    sdf_types = frozenset({"air_pressure"})
    classic_plugins: ClassVar[dict[str, frozenset[str] | None]] = {}
    gz_system = "AirPressure"
    gz_file = "air-pressure"
    output_kind = "air_pressure"
    output_message: ClassVar[MessageKind | None] = FLUID_PRESSURE

    kind = "air pressure"

    def __init__(self, seed: int | None = None) -> None:
        super().__init__(seed)
        self.reference_altitude = 0.0
        self._noise = Noise()
        self._bias = 0.0

    def configure(self, ctx: SystemContext) -> None:
        """``<reference_altitude>`` (metres: the altitude the sensor's world z = 0 stands for, as gz-sensors'
        AirPressureSensor adds it before the US Standard Atmosphere gives a pressure) and the noise of
        ``<pressure>``, in pascals; declare the output topic. A reference that is not a number is warned
        about at its line and read as 0."""
        if not self._configure_common(ctx):
            return
        block = self.sensor.config.find("air_pressure") if self.sensor and self.sensor.config is not None else None
        ref = block.find("reference_altitude") if block is not None else None
        try:
            self.reference_altitude = float((ref.text or "0").strip()) if ref is not None else 0.0
        except ValueError:
            where = f"{ref.location}: " if ref is not None and ref.location else ""
            ctx.logger.warning(f"{where}<reference_altitude> '{ref.text if ref else ''}' is not a number; using 0")
        pressure = block.find("pressure") if block is not None else None
        noise_el = pressure.find("noise") if pressure is not None else None
        self._noise = parse_noise(noise_el, ctx.logger, "air pressure")
        self._bias = self._noise.bias(self._rng)
        assert self.output is not None
        ctx.logger.info(f"air pressure sensor on [{self.link}] at {self.rate_hz:g} Hz on [{self.output.topic}]")

    def read(self) -> tuple[float, float]:
        """(pressure in Pa with noise, the variance gz-sensors reports)."""
        height = self.reference_altitude + self.sensor_pose().position[2]
        pressure = pressure_at(height)
        variance = 0.0
        if self._noise.active:
            pressure += self._bias + self._noise.mean + self._noise.stddev * self._rng.standard_normal()
            variance = math.sqrt(self._noise.stddev)  # sic: gz-sensors' set_variance(sqrt(StdDev()))
        return pressure, variance

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish stamped with this sim time."""
        if not self._due(info):
            return
        assert self._pub is not None and self.output is not None
        pressure, variance = self.read()
        self._pub.publish(FluidPressure(info.sim_time_sec, self.output.frame_id, pressure, variance))


add_plugin(AirPressureSensor)

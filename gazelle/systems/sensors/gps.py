"""GPS / NavSat: the position as latitude, longitude and altitude from the world's spherical coordinates,
with noise (sensor_msgs/NavSatFix), and gazebo_ros's velocity (geometry_msgs/Vector3Stamped).

The two Gazebos add the same ``<noise>`` elements in different units, and gazelle follows the one the sensor is
written for:

- with ``libgazebo_ros_gps_sensor`` (Classic; ``GpsSensor::UpdateImpl`` in gazebo's ``GpsSensor.cc``), position
  noise is metres on the Gazebo frame's x, y and z *before* the point becomes latitude and longitude, one noise
  model (and bias) for each of the three;
- without it (gz-sim's ``NavSat`` system and gz-sensors' ``NavSatSensor::Update``), the horizontal noise is added
  to the latitude and the longitude *in degrees*, one model (so one bias) for both, and the vertical to the
  altitude in metres: a ``<stddev>`` of 1 there is a degree, about 111 km;
- velocity noise is m/s on East, North and Up after the conversion in both (only Classic's plugin publishes the
  velocity; ros_gz_bridge's NavSatFix has none).

Every noise model is gz-sensors' and Classic's Gaussian: ``mean`` + N(0, ``stddev``²) per reading plus a bias drawn
once (see :class:`~gazelle.systems.sensors._common.Noise`).
"""

from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...description import (
    Sensor,
    SphericalCoordinates,
)
from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._bus import Endpoint, MsgType, resolve_topic
from .._payloads import NavSatFix, Vector3Stamped
from .._registration import add_plugin
from ._common import (
    SENSOR_DEPTH,
    Noise,
    _SensorSystem,
    gz_scoped_topic,
    parse_noise,
)

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
    """Metres, on East and North each (one draw per axis)."""
    position_vertical: Noise = Noise()
    """Metres, on Up."""
    velocity_horizontal: Noise = Noise()
    """m/s, on the East and North velocity each."""
    velocity_vertical: Noise = Noise()
    """m/s, on the Up velocity."""


def parse_gps_noise(sensor: Sensor, log: logging.Logger) -> GpsNoise:
    """SDF's ``<gps>`` (or ``<navsat>``) ``<position_sensing>``/``<velocity_sensing>`` noise."""
    block = None
    if sensor.config is not None:
        block = sensor.config.find("navsat") or sensor.config.find("gps")  # gz-sim's name, then Classic's
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
        self._covariance: tuple[tuple[float, ...], int, int] = ((0.0,) * 9, 0, 0)
        """The fix's (position_covariance, covariance_type, service), as the Gazebo that runs it sends them."""
        self._classic = True
        """Whether Classic's gazebo_ros_gps_sensor runs it (position noise in metres) or gz-sim (in degrees)."""
        self._bias = (0.0,) * 6
        """The biases of the six noise channels (x or latitude, y or longitude, altitude, east, north, up)."""

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
        # without <spherical_coordinates>, gz-sim 8's NavSat warns at every update and publishes a fix that stays
        # at 0, 0, 0 however the sensor moves (NavSat.cc: Update skips it; its sensor publishes the unset values);
        # gazelle warns once and measures from an origin at 0° N 0° E
        if ctx.spherical_coordinates is None:
            where = f"{ctx.sensor.location}: " if ctx.sensor.location else ""
            ctx.logger.warning(
                f"{where}GPS '{ctx.sensor.name}': the world has no <spherical_coordinates>; its origin is 0° N 0° E"
            )
        self.origin = ctx.spherical_coordinates or SphericalCoordinates()
        self.noise = parse_gps_noise(ctx.sensor, ctx.logger)
        self._classic = ctx.plugin is not None
        nz, draw = self.noise, (lambda n: n.bias(self._rng))
        # Classic loads one noise model per axis from the same element; gz-sensors one for latitude and longitude
        lat_bias = draw(nz.position_horizontal)
        lon_bias = draw(nz.position_horizontal) if self._classic else lat_bias
        vel = (draw(nz.velocity_horizontal), draw(nz.velocity_horizontal), draw(nz.velocity_vertical))
        self._bias = (lat_bias, lon_bias, draw(nz.position_vertical), *vel)
        if ctx.plugin is not None:
            # gazebo_ros_gps_sensor.cpp: each noise's variance on the diagonal (East, North, Up; 0 without
            # noise: gazebo_ros NoiseVariance), always COVARIANCE_TYPE_DIAGONAL_KNOWN, service GPS
            sh, sv = (
                n.stddev**2 if n.active else 0.0 for n in (self.noise.position_horizontal, self.noise.position_vertical)
            )
            self._covariance = ((sh, 0.0, 0.0, 0.0, sh, 0.0, 0.0, 0.0, sv), 2, 1)
        else:
            # gz-sim's NavSat message has no covariance: ros_gz_bridge (convert/sensor_msgs.cpp) sends
            # COVARIANCE_TYPE_UNKNOWN with zeros, and sets no service
            self._covariance = ((0.0,) * 9, 0, 0)
        ctx.logger.info(f"GPS '{ctx.sensor.name}' at {self.rate_hz:g} Hz on [{self.output.topic}]")

    def read(self, world: PhysicsWorld) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """((latitude, longitude, altitude), ENU velocity) of the sensor now, with noise as the Gazebo that runs
        it adds it (see the module docstring)."""
        assert self._body is not None
        X_WB = self._body.pose
        X = X_WB * self.offset
        h, nz, b = self.origin.heading_deg, self.noise, self._bias
        x, y, z = X.position
        if self._classic:  # metres on the Gazebo frame, then to the sphere
            x = self._noisy(x, nz.position_horizontal, b[0])
            y = self._noisy(y, nz.position_horizontal, b[1])
            z = self._noisy(z, nz.position_vertical, b[2])
        lat, lon, alt = enu_to_geodetic(*world_to_enu((x, y, z), h), self.origin)
        if not self._classic:  # on the sphere: degrees, then metres of altitude
            lat = self._noisy(lat, nz.position_horizontal, b[0])
            lon = self._noisy(lon, nz.position_horizontal, b[1])
            alt = self._noisy(alt, nz.position_vertical, b[2])
        lin, ang = self._body.velocity
        r = np.asarray(X.position) - np.asarray(X_WB.position)
        v = np.asarray(lin) + np.cross(np.asarray(ang), r)  # the sensor point's velocity
        ve, vn, vu = world_to_enu((float(v[0]), float(v[1]), float(v[2])), h)
        ve = self._noisy(ve, nz.velocity_horizontal, b[3])
        vn = self._noisy(vn, nz.velocity_horizontal, b[4])
        vu = self._noisy(vu, nz.velocity_vertical, b[5])
        return (lat, lon, alt), (ve, vn, vu)

    def _noisy(self, value: float, noise: Noise, bias: float) -> float:
        """``value`` through one Gaussian noise model: its bias, mean and one N(0, stddev²) draw."""
        if not noise.active:
            return value
        jitter = float(self._rng.normal(0.0, noise.stddev)) if noise.stddev > 0 else 0.0
        return value + bias + noise.mean + jitter

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """At the sensor's rate, while listened to: publish the fix (and the velocity) stamped with this sim time.

        One reading serves both topics (the fix and the velocity of one instant); the fix always says
        STATUS_FIX, as gazebo_ros_gps_sensor and ros_gz_bridge both send it (neither models a loss of fix)."""
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
            self._pub.publish(NavSatFix(t, frame, lat, lon, alt, *self._covariance))
        if want_vel and self._vel is not None:
            self._vel.publish(Vector3Stamped(t, frame, vel))


add_plugin(GpsSensor)

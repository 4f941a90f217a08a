"""gz-sim's altimeter: height above the start and vertical velocity (ros_gz_interfaces/Altimeter)."""

from __future__ import annotations

from typing import ClassVar

from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._payloads import Altimeter
from .._registration import add_plugin
from ._common import (
    Noise,
    _SensorSystem,
    parse_noise,
)


# --------------------------------------------------------------------------- altimeter
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
        """The noise of ``<vertical_position>`` and ``<vertical_velocity>`` (each its own Gaussian model with a
        bias drawn once, as gz-sensors' AltimeterSensor); declare the output topic. The vertical reference is
        taken at the first reading, as gz-sim's Altimeter system takes the sensor's height when it is made."""
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


add_plugin(AltimeterSensor)

"""gz-sim's magnetometer: the world's magnetic field in the sensor frame (sensor_msgs/MagneticField)."""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from ...description import (
    rotation_matrix,
)
from ...physics import PhysicsWorld
from .._base import SystemContext, UpdateInfo
from .._payloads import MagneticField
from .._registration import add_plugin
from ._common import (
    Noise,
    _SensorSystem,
    xyz_noise,
)


# --------------------------------------------------------------------------- magnetometer
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

    def configure(self, ctx: SystemContext) -> None:
        """The world's field and the noise; declare the output topic."""
        if not self._configure_common(ctx):
            return
        self.field_W = np.asarray(ctx.magnetic_field, dtype=float)
        block = self.sensor.config.find("magnetometer") if self.sensor and self.sensor.config is not None else None
        self._noise = xyz_noise(block, ctx.logger, "magnetometer")
        self._bias = np.array([n.bias(self._rng) for n in self._noise])
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
        # no covariance (MagneticField's zeros) whatever the noise: gz-msgs' Magnetometer has none to carry, and
        # ros_gz_bridge (convert/sensor_msgs.cpp) says "magnetic_field_covariance is not supported"
        self._pub.publish(MagneticField(info.sim_time_sec, self.output.frame_id, (b[0], b[1], b[2])))


add_plugin(Magnetometer)

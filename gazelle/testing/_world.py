"""The ``gazelle_world`` fixture's object: a simulation inside the test's own process, no ROS, no DDS.

For tests of behaviour that needs no ROS graph (a plugin's physics, a controller's maths, a scenario's
outcome): the test steps the world itself, publishes on the simulation's bus the payloads a ROS node
would, and reads states directly. Nothing crosses a process or a network, so a run is bit-identical to
every other run with the same seed, on any machine with the same wheels.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from .._errors import SimError

__all__ = ["InProcessWorld", "WorldTimeout"]


class WorldTimeout(SimError, AssertionError):
    """``run_until``'s condition did not hold within its sim time."""


class TopicLog:
    """Every payload published on one topic of the bus since the log was made (``.messages``, ``.last``)."""

    def __init__(self) -> None:
        self.messages: list[Any] = []

    def __call__(self, payload: Any) -> None:
        self.messages.append(payload)

    @property
    def last(self) -> Any:
        return self.messages[-1] if self.messages else None

    def __len__(self) -> int:
        return len(self.messages)


class InProcessWorld:
    """A :class:`~gazelle.sim.Simulation` owned by a test, stepped by the test (never by a thread of its own).

    Args:
        world: a world file (``.sdf``/``.world``), or None for the embedded default world.
        seed: the seed of every sensor's and plugin's noise.
    """

    def __init__(self, world: str | os.PathLike[str] | None = None, *, seed: int = 0) -> None:
        """A world without ROS for a unit-level robot test: ``world`` (a file; None: the default world) in a
        Simulation that does not pace itself, its noise seeded with ``seed``."""
        from ..description import World, load
        from ..sim import Simulation
        from ..worlds import default_world

        description = load(world).value if world is not None else default_world()
        if not isinstance(description, World):
            raise ValueError(f"{world}: not a world (it describes a {type(description).__name__.lower()})")
        self.sim = Simulation(description, rtf=0, seed=seed)
        self.seed = seed

    # ------------------------------------------------------------------ building
    def spawn(
        self,
        file: str | os.PathLike[str],
        name: str,
        *,
        pose: Sequence[float] = (0.0, 0.0, 0.0),
        yaw: float = 0.0,
        namespace: str = "",
        args: Mapping[str, str] | None = None,
    ) -> Any:
        """Spawn a robot or model file as ``name``, its plugins and ros2_control running in the world as they
        would under ``gazelle sim`` (minus the ROS graph).

        Args:
            file: a URDF, xacro or SDF model file (package:// and model:// resolved from
                ``GAZELLE_RESOURCE_PATH`` and the file's package).
            name: the entity's name, unique in the world.
            pose: (x, y, z) of its root in the world, metres.
            yaw: rotation about z, radians.
            namespace: its topics' namespace, as a ROS spawn's ``-robot_namespace``.
            args: xacro arguments.

        Returns:
            The physics world's entity (its ``systems``: plugins, a controller manager).

        Raises:
            gazelle.description.ModelLoadError: the file is missing or bad; the message names file:line.
            ValueError: the file is a world, not a robot or model.
        """
        from ..description import Model, Pose, load

        model = load(Path(file), args=dict(args or {})).value
        if not isinstance(model, Model):
            raise ValueError(f"{file}: not a robot or model (it describes a {type(model).__name__.lower()})")
        x, y, z = (float(v) for v in pose)
        orientation = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))
        return self.sim.spawn(model, name=name, pose=Pose((x, y, z), orientation), namespace=namespace)

    # ------------------------------------------------------------------ topics
    def publish(self, topic: str, payload: Any) -> int:
        """Hand ``payload`` (a :mod:`gazelle.systems` message such as ``Twist``) to every subscription of
        ``topic`` in the simulation, as the ROS bridge would; returns how many took it (0: nobody listens
        to that topic with that type, which is an error a test wants to see, so it raises)."""
        from ..systems import MsgType

        kind = _msg_type(payload, MsgType)
        taken = self.sim.bus.inject(topic, kind, payload)
        if taken == 0:
            raise ValueError(f"nothing in the simulation subscribes to {topic} ({kind.value})")
        return taken

    def subscribe(self, topic: str) -> TopicLog:
        """A log of every payload the simulation publishes on ``topic`` from now on: the
        :mod:`gazelle.systems` payloads (``Odometry``, ``JointStates``...) the ROS bridge would convert,
        without a conversion.

        Raises:
            ValueError: nothing in the simulation publishes ``topic`` (a misspelt topic fails here, not as a
                log that stays empty).
        """
        endpoints = [ep for ep in self.sim.bus.endpoints() if ep.is_publisher and ep.topic == topic]
        if not endpoints:
            raise ValueError(f"nothing in the simulation publishes {topic}")
        log = TopicLog()
        for ep in endpoints:
            ep.add_sink(log)
        return log

    # ------------------------------------------------------------------ time
    @property
    def time(self) -> float:
        """Sim time, seconds."""
        return float(self.sim.world.time)

    def run_for(self, seconds: float) -> float:
        """Step ``seconds`` of sim time (whole physics steps, as fast as the machine allows) on the test's
        thread; returns the sim time. Nothing runs between the calls: the world is the test's alone."""
        if seconds < 0 or not math.isfinite(seconds):
            raise ValueError(f"run_for takes a finite time >= 0, got {seconds!r}")
        steps = round(seconds / self.sim.world.timestep)
        if steps:
            self.sim.step(steps)
        return self.time

    def run_until(
        self, predicate: Callable[[], Any], timeout: float, what: str = "the condition", step: float = 0.01
    ) -> Any:
        """Step until ``predicate()`` is truthy (checked every ``step`` s of sim time), at most ``timeout``
        seconds of sim time; returns its value or raises :class:`WorldTimeout` naming ``what``.

        The check's granularity is ``step``: the time at which a condition first held is known to within it
        (0.01 s by default; the physics steps at the world's ``max_step_size`` regardless)."""
        end = self.time + timeout
        while True:
            value = predicate()
            if value:
                return value
            if self.time >= end - 1e-9:
                raise WorldTimeout(f"{what}: not within {timeout:g} s of sim time")
            self.run_for(min(step, end - self.time))

    # ------------------------------------------------------------------ state
    def pose(self, name: str, link: str | None = None) -> tuple[float, float, float, float]:
        """(x, y, z, yaw) of an entity (its root link, or ``link``) in the world frame: metres, and radians
        about z (from the orientation's roll-pitch-yaw, so a tipped robot's yaw is its heading's projection)."""
        from ..description import quat_to_rpy

        p = self.sim.world.entity_state(name, link).pose
        x, y, z = p.position
        return (float(x), float(y), float(z), float(quat_to_rpy(p.orientation)[2]))

    def state_digest(self) -> str:
        """SHA-256 of the whole physics state (time, positions, velocities, actuator states, warm start):
        equal digests mean bit-identical worlds."""
        return self.sim.world.state_digest()

    def close(self) -> None:
        """Remove every entity (their systems shut down)."""
        for name in list(self.sim.world.entities):
            self.sim.delete(name)  # a failure here is the test's to see, not to swallow


def _msg_type(payload: Any, kinds: Any) -> Any:
    """The bus message type of a payload, from its class's name (Twist -> TWIST)."""
    import re

    name = re.sub(r"(?<!^)(?=[A-Z])", "_", type(payload).__name__).upper()
    try:
        return kinds[name]
    except KeyError:
        raise TypeError(f"{type(payload).__name__} is not a gazelle.systems message") from None

"""The runtime's small value types: what a spawn asks for, a listener of the steps, a measured real-time factor,
the loaded world and a load refused because the world is busy."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from .._errors import SimError
from ..description import Model, Pose, World
from ..systems import RateGate, UpdateInfo


@dataclass(frozen=True)
class RtfSample:
    """Real-time factor measured over the last window."""

    rtf: float
    steps_per_sec: float


@dataclass(frozen=True, slots=True)
class SpawnRequest:
    """One model to add with :meth:`Simulation.spawn_many`."""

    model: Model
    name: str = ""
    """The entity's name; empty means the model's own."""
    pose: Pose = Pose()
    """Where the model frame goes (composed with the file's own pose)."""
    namespace: str = ""
    allow_renaming: bool = False
    """A taken name becomes ``name_1``, ``name_2``, ... instead of failing."""


@dataclass(eq=False)
class StepListener:
    """A function called after the steps, at most ``rate_hz`` times per second of sim time (0: every step)."""

    fn: Callable[[UpdateInfo], None]
    rate_hz: float = 0.0
    gate: RateGate = field(default_factory=RateGate)


class WorldBusy(SimError):
    """A load or unload refused because another load is under way, or a client is stepping the world on
    request; or a step on request refused because a load is under way. The message says which."""


@dataclass(frozen=True)
class LoadedWorld:
    """The world the simulation runs: its name, the URI a LoadWorld names it by again (empty for a world that
    came as a string) and its description."""

    name: str
    uri: str
    description: World

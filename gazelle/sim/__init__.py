"""The runtime: a :class:`Simulation` (its thread, pacing, spawn and delete orchestration).

It sits above physics and systems: it stages an entity in the physics world, lets the
systems of its plugins configure (add actuators, declare topics), commits it, and then
runs the systems' phases around blocks of physics steps. ROS, the viewer and the command
line drive it through its thread-safe methods.
"""

from ._checkpoint import CheckpointError as CheckpointError
from ._replay import ReplayRecorder as ReplayRecorder
from ._runtime_types import LoadedWorld as LoadedWorld
from ._runtime_types import RtfSample as RtfSample
from ._runtime_types import SpawnRequest as SpawnRequest
from ._runtime_types import StepListener as StepListener
from ._runtime_types import WorldBusy as WorldBusy
from ._scene import SceneGeometry as SceneGeometry
from ._scene import SceneLink as SceneLink
from ._scene import SceneShape as SceneShape
from ._scene import moved as moved
from ._simulation import MAX_CATCH_UP_SEC as MAX_CATCH_UP_SEC
from ._simulation import Simulation as Simulation
from ._watchdog import start_signal_watchdog as start_signal_watchdog
from ._world_swap import MAX_WORLD_MODELS as MAX_WORLD_MODELS
from ._world_swap import WorldSwap as WorldSwap

__all__ = [
    "MAX_CATCH_UP_SEC",
    "MAX_WORLD_MODELS",
    "CheckpointError",
    "LoadedWorld",
    "RtfSample",
    "SceneGeometry",
    "SceneLink",
    "SceneShape",
    "Simulation",
    "SpawnRequest",
    "StepListener",
    "WorldBusy",
    "WorldSwap",
    "moved",
]

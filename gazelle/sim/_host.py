"""What the simulation's parts see of it: the :class:`SimulationHost` protocol.

:class:`~gazelle.sim.Simulation` owns two parts: its :class:`~._spawning.Spawner` (``sim.spawner``: how a model
becomes an entity, and how one goes) and its :class:`~._world_swap.WorldSwap` (``sim.worlds``: the world replaced
at run time). Each is given the simulation as this protocol, so a part names only what it uses and neither imports
the module that builds it (no import circle inside the package; gz-sim's systems see the server the same way,
through the ``EntityComponentManager`` they are handed, not the server's class).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol, TypeVar

if TYPE_CHECKING:
    from ..description import Plugin, SphericalCoordinates, Vec3, World
    from ..physics import PhysicsWorld
    from ..systems import Bus, System, SystemManager

T = TypeVar("T")


class SimulationHost(Protocol):
    """The simulation as its parts use it (see the module docstring). Everything here runs on the simulation
    thread, except :meth:`call`, which takes work there."""

    world: PhysicsWorld
    """The physics world; a load replaces it (read it again after any call, never keep it)."""
    bus: Bus
    systems: SystemManager
    robot_state_publisher: bool
    """Give every robot the built-in robot_state_publisher (a model file may still opt out)."""
    world_name: str
    world_plugins: tuple[Plugin, ...]
    spherical_coordinates: SphericalCoordinates | None
    magnetic_field: Vec3

    def call(self, fn: Callable[[], T], timeout: float | None = 10.0) -> T:
        """Run ``fn`` on the simulation thread between two steps and return its result."""
        ...

    def _seed_noise(self, system: System, entity: str, name: str) -> None:
        """Seed a new system's noise from the simulation's seed and its place (entity, name)."""
        ...

    def _forget_divergence(self, name: str) -> None:
        """Drop what the simulation remembers of a deleted entity's divergences."""
        ...

    def _install_world(self, world: World, rtf: float | None) -> None:
        """Every entity out the way a delete takes one, then ``world``'s physics in (no models yet), its clock at
        zero, paused; ``rtf`` the real-time factor asked for (None: the world's own)."""
        ...

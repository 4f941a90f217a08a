"""What every part a :class:`~gazelle.physics.PhysicsWorld` owns (its queries, its state) reads of the world, written
once: the part holds the world as a :class:`WorldView` (its compiled model and data, its entities) and reads them
through it, as a recompile replaces them. The parts import nothing of the module that builds the world."""

from __future__ import annotations

from typing import Generic, Protocol, TypeVar

import mujoco

from ._entities import Entity


class WorldView(Protocol):
    """What every part reads of the world (:class:`~gazelle.physics.PhysicsWorld` is one)."""

    @property
    def model(self) -> mujoco.MjModel: ...

    @property
    def data(self) -> mujoco.MjData: ...

    @property
    def entities(self) -> dict[str, Entity]: ...


W = TypeVar("W", bound=WorldView)


class WorldPart(Generic[W]):
    """A part of a world: the world it belongs to (as what the part uses of it) and the world's model, data and
    entities read through it."""

    def __init__(self, world: W) -> None:
        self._world = world

    @property
    def model(self) -> mujoco.MjModel:
        """The world's compiled model (a recompile replaces it)."""
        return self._world.model

    @property
    def data(self) -> mujoco.MjData:
        """The world's data (a recompile replaces it)."""
        return self._world.data

    @property
    def entities(self) -> dict[str, Entity]:
        """The world's entities by name."""
        return self._world.entities

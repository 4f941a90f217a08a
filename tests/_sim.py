"""One way for the in-process tests to build a :class:`~gazelle.sim.Simulation` (the ``make_sim`` fixture of
tests/conftest.py hands it out and stops what a failing test left running)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from gazelle.description import World
    from gazelle.sim import Simulation


def new_simulation(world: World | None = None, *, rtf: float | None = 0.0, **kwargs: Any) -> Simulation:
    """A simulation of ``world`` (the embedded default world when None) that the test steps itself
    (``rtf=0``: as fast as possible, unless given; None takes the world's real-time factor). Other keyword
    arguments go to :class:`~gazelle.sim.Simulation` (``seed``, ``visual_geoms``, ``bus``...)."""
    from gazelle.sim import Simulation
    from gazelle.worlds import default_world

    return Simulation(default_world() if world is None else world, rtf=rtf, **kwargs)

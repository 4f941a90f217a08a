"""Worlds at run time: the simulation's world replaced, or taken away, while the process, its clock and the
listeners of its bus (the ROS bridge: /clock, the services) stay (simulation_interfaces' LoadWorld,
UnloadWorld and GetCurrentWorld).

A :class:`WorldSwap` is a part of :class:`~gazelle.sim.Simulation` (``sim.worlds``), not a layer of it. A load
runs in two halves: the slow preparation of the new world's meshes in the caller's thread, then, in one call
on the simulation thread, every entity of the old world goes the way a deleted one goes (its systems shut
down, its topics withdrawn from the bus, so the ROS bridge destroys their publishers), a new physics world is
built from the description and the world file's models are added to it as at start-up. The clock starts
again at zero and the simulation is left paused with no step taken: simulation_interfaces' STOPPED state,
as LoadWorld.srv asks. ``gazelle sim WORLD``'s world is the first load (:attr:`WorldSwap.first`).

One load at a time, and never while a client steps the world on request (a SimulateSteps goal, a
StepSimulation call): such a load is refused with :class:`WorldBusy`, naming what holds the world, and a
request to step while a load runs is refused the same way.
"""

from __future__ import annotations

import contextlib
import ctypes
import functools
import logging
import threading
from collections.abc import Callable, Iterator

from ..description import World
from ..physics import ErrorKind, WorldError, prepare_meshes
from ..systems import audit_world
from ._host import SimulationHost
from ._runtime_types import LoadedWorld, WorldBusy
from ._spawning import Spawner

MAX_WORLD_MODELS = 4096
"""The most models a world loaded at run time may place (gz-sim's 3k_shapes.sdf has 3,000): a world of ten
thousand is refused before anything of the current world is touched."""
LOAD_TIMEOUT_SEC = 600.0
"""How long a load waits for the simulation thread to take it (the thread finishes a block of steps first)."""
_log = logging.getLogger("gazelle")


def release_freed_memory() -> None:
    """Hand the memory a replaced world freed back to the system (glibc's ``malloc_trim``; elsewhere nothing).

    A world's MuJoCo model and data are large blocks; once glibc has seen such blocks freed it serves the next
    ones from its heap (its dynamic mmap threshold), and the heap keeps what is freed. Measured in process on
    the seed robot: a load, a spawn and another load, 400 times, grew the RSS by 20 MiB, linearly; with this
    call after each load, 3.2 MiB over the first 100 and nothing after. Nothing leaked (one physics world alive,
    and ``malloc_trim`` at the end took the 20 MiB back): the memory was free but kept.
    """
    libc = _libc()
    if libc is not None:
        libc.malloc_trim(0)


@functools.cache
def _libc() -> ctypes.CDLL | None:
    """glibc, when this process runs on it (it has ``malloc_trim``)."""
    try:
        libc = ctypes.CDLL("libc.so.6")
        return libc if hasattr(libc, "malloc_trim") else None
    except OSError:
        return None


def empty_world(like: World) -> World:
    """What an unloaded simulation runs: no models, no lights, no plugins; ``like``'s physics settings, so the
    clock keeps its step."""
    return World(name="", gravity=like.gravity, physics=like.physics)


class WorldSwap:
    """The simulation's current world and the one way to replace it (see the module docstring)."""

    def __init__(self, sim: SimulationHost, spawner: Spawner, world: World, rtf: float | None):
        """``world`` is the one ``sim`` was built with, ``spawner`` the part that adds a world's models to it;
        ``rtf`` the real-time factor asked for (None: each world's own, taken again at every load)."""
        self._sim = sim
        self._spawner = spawner
        self._rtf = rtf
        self.first = LoadedWorld(world.name, world.source_file, world)
        """The world the process started with: ``gazelle sim WORLD``'s first load."""
        self.current: LoadedWorld | None = self.first
        """The loaded world; None after an unload (or a load whose world failed to build)."""
        self.installed: dict[str, Callable[[], World]] = {}
        """Worlds a load may name by a bare file name (``empty.sdf``): the ones installed with gazelle
        (``gazelle sim`` fills it; the runtime knows of none)."""
        self._lock = threading.Lock()
        self._loading: str | None = None
        self._holds: dict[str, int] = {}

    def name_first(self, uri: str) -> None:
        """How a LoadWorld names the world the simulation started with (``gazelle sim`` sets it: the file it
        read, or ``empty.sdf``); a load of ``uri`` then takes that world again, without reading anything."""
        self.first = LoadedWorld(self.first.name, uri, self.first.description)
        if self.current is not None and self.current.description is self.first.description:
            self.current = self.first

    # ------------------------------------------------------------------ who holds the world
    @property
    def loading(self) -> bool:
        """Whether a load or an unload is under way (simulation_interfaces' STATE_LOADING_WORLD)."""
        return self._loading is not None

    @contextlib.contextmanager
    def stepping(self, what: str) -> Iterator[None]:
        """Hold the world while ``what`` (``"a SimulateSteps goal"``) steps it on request: a load meanwhile is
        refused. Raises :class:`WorldBusy` if a load is under way."""
        with self._lock:
            if self._loading is not None:
                raise WorldBusy(f"{self._loading} is under way; step once it is done")
            self._holds[what] = self._holds.get(what, 0) + 1
        try:
            yield
        finally:
            with self._lock:
                self._holds[what] -= 1
                if not self._holds[what]:
                    del self._holds[what]

    @contextlib.contextmanager
    def _claim(self, doing: str) -> Iterator[None]:
        with self._lock:
            if self._loading is not None:
                raise WorldBusy(f"{self._loading} is under way; try again once it is done")
            if self._holds:
                held = ", ".join(sorted(self._holds))
                raise WorldBusy(f"{held} is stepping the world; cancel it or wait for it to end, then try again")
            self._loading = doing
        try:
            yield
        finally:
            with self._lock:
                self._loading = None

    # ------------------------------------------------------------------ load and unload
    def load(self, world: World, uri: str = "") -> LoadedWorld:
        """Replace the current world (and every entity in it) by ``world`` (thread-safe): the clock back to
        zero, the simulation paused with no step taken. ``uri`` is how a later load names it again.

        Raises:
            WorldBusy: another load is under way, or a client steps the world on request.
            WorldError: ``world`` places more than :data:`MAX_WORLD_MODELS` models (nothing changed), or one of
                its models failed to build: the old world is gone by then, and no world is loaded.
        """
        if len(world.models) > MAX_WORLD_MODELS:
            raise WorldError(
                ErrorKind.BUILD_FAILED,
                f"world '{world.name}' places {len(world.models)} models, more than the {MAX_WORLD_MODELS} "
                "a world may have; nothing was changed",
            )
        with self._claim(f"loading world '{world.name}'"):
            for model in world.models:
                prepare_meshes(model)  # slow work (convex decompositions) here, in the caller's thread
            try:
                return self._sim.call(lambda: self._swap(world, uri), timeout=LOAD_TIMEOUT_SEC)
            finally:
                release_freed_memory()

    def unload(self) -> None:
        """Remove the current world and every entity (thread-safe): an empty simulation, paused, its clock at
        zero, until the next load.

        Raises:
            WorldBusy: a load is under way, or a client steps the world on request.
            WorldError: (NOT_FOUND) no world is loaded.
        """
        with self._claim("unloading the world"):
            try:
                self._sim.call(self._unload, timeout=LOAD_TIMEOUT_SEC)
            finally:
                release_freed_memory()

    def _unload(self) -> None:
        if self.current is None:
            raise WorldError(ErrorKind.NOT_FOUND, "no world is loaded")
        self._sim._install_world(empty_world(self._sim.world.description), self._rtf)
        self.current = None

    def _swap(self, world: World, uri: str) -> LoadedWorld:
        """On the simulation thread: the old world out, ``world`` in (its models as at start-up)."""
        self.current = None
        self._sim._install_world(world, self._rtf)
        for problem in audit_world(World(name=world.name, plugins=world.plugins)):
            _log.warning(problem.format())
        try:
            self._spawner.add_world_models(list(world.models))
        except WorldError:
            self._sim._install_world(empty_world(world), self._rtf)  # what was added goes: no half world is left
            raise
        self.current = LoadedWorld(world.name, uri, world)
        return self.current

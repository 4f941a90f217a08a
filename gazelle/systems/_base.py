"""The plugin framework: systems opt into phases, run in an explicit priority order.

Phases per step, as in gz-sim:

1. ``pre_update`` (before physics): controllers write commands; takes effect this step.
2. ``update`` with priority < ``PHYSICS`` runs before the physics step, the rest after it.
3. ``post_update`` (after physics): read-only observers (odometry, joint states, TF).

``configure`` runs once when the entity is added (while it is staged, before the MuJoCo
model is recompiled, so a system can add actuators), ``reset`` on a world reset.

Between two updates the world steps inside MuJoCo: a system says when it next needs to run
(:meth:`System.next_update`), and the runtime takes all the steps until the earliest such time
in one MuJoCo call. A system that does not say runs every step.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import ClassVar, NamedTuple

from ..description import DEFAULT_MAGNETIC_FIELD, Plugin, Sensor, SphericalCoordinates
from ..physics import Entity, PhysicsWorld
from ._bus import Bus, ParamValue

_log = logging.getLogger("gazelle.systems")

PRE_PHYSICS = -128
PHYSICS = -64
DEFAULT_PRIORITY = 0


class UpdateInfo(NamedTuple):
    """What every system receives at each update (immutable; a named tuple, as it is made twice per block of steps)."""

    sim_time_sec: float
    """Simulation time at the start of this update's steps (pre/update) or after them (post)."""
    real_time_sec: float
    """Wall-clock seconds since the simulation started."""
    dt_sec: float
    """Simulation time this update covers: the steps taken between its pre_update and post_update
    (one physics step when a system runs every step)."""
    iterations: int
    """Steps taken so far."""
    paused: bool


@dataclass
class SystemContext:
    """Everything a system may touch while configuring."""

    world: PhysicsWorld
    """The world; while configuring, the entity is staged in it (add actuators, set joint properties)."""
    entity: Entity
    plugin: Plugin | None
    """The ``<plugin>`` this system was made from (None for built-in systems)."""
    bus: Bus
    logger: logging.Logger
    sensor: Sensor | None = None
    """The ``<sensor>`` a sensor plugin sits in (None for model plugins)."""
    link: str = ""
    """The link that ``sensor`` is on."""
    world_name: str = "default"
    """The world's name (gz-sim's default sensor topics contain it)."""
    spherical_coordinates: SphericalCoordinates | None = None
    """Where the world's origin is on the Earth (GPS sensors)."""
    magnetic_field: tuple[float, float, float] = DEFAULT_MAGNETIC_FIELD
    """The world's magnetic field (tesla, world frame): what magnetometers read."""


class System:
    """Base class; override only the phases you need (trivial ones are skipped)."""

    plugin_files: ClassVar[tuple[str, ...]] = ()
    """The ``<plugin filename>`` values of a model or world (without ``lib`` and ``.so``; a ``name`` matches
    too) that run this system, for plugins that are not gz-sim systems: gazebo_ros's, ros2_control's,
    gazelle's own. A class that declares a name and registers itself (``add_plugin(Cls)`` at the bottom of its
    module, ``_registration.py``) is run for it."""
    gz_plugin: ClassVar[str] = ""
    """The gz-sim system this one is, by its class name (``DiffDrive``): gz-sim's and Ignition's file and
    class spellings all select it (``gz-sim-diff-drive-system``, ``gz::sim::systems::DiffDrive``,
    ``ignition-gazebo-diff-drive-system``, ``ignition::gazebo::systems::DiffDrive``)."""
    gz_plugin_file: ClassVar[str] = ""
    """The file's part of :attr:`gz_plugin`'s names where it is not the class name in kebab case."""

    priority: int = DEFAULT_PRIORITY
    phase_gate: RateGate | None = None
    """A rate gate that each of this system's stepped phases checks first, doing nothing while it is not
    due: the runtime then does not call those phases until the gate is due (a lidar's post_update at
    5 Hz is not called on the 199 steps in between). None: every phase is called at every update."""

    checkpoint_skip: tuple[str, ...] = ()
    """Attributes a checkpoint leaves out: resources the system makes again or keeps (a renderer's GL
    context), never state that shapes what it does next."""

    def configure(self, ctx: SystemContext) -> None:
        """Read the configuration, check the entity, declare endpoints and actuators.

        Called once, on the simulation thread, while the entity is staged: its bodies and joints are in
        the world's spec but not yet compiled, so this is the one moment a system may add actuators or
        change joint properties. Read the ``<plugin>``'s children through ``ctx.plugin.config`` (each tag
        looked up is recorded; one never looked up is warned about with its file:line, so a user's
        parameter is never dropped silently). Raise ``ValueError`` (or a subclass) naming the parameter
        and the file for configuration that cannot work: the spawn is then refused with that message and
        the staged entity discarded, the world left bit-identical.
        """

    def seed_noise(self, seed: int) -> None:
        """Draw this system's noise from a stream seeded with ``seed`` (called before :meth:`configure`
        when the simulation has a seed: a run then repeats bit for bit). Systems without noise ignore it."""

    def next_update(self, sim_time_sec: float) -> float:
        """The sim time at which this system next needs a phase call (at or after ``sim_time_sec``).

        The world steps inside MuJoCo until the earliest such time over all systems, so a system
        that runs at a rate returns its next period (see :class:`RateGate`). The default, the
        current time, means every step; ``math.inf`` means only when something else runs.
        """
        return sim_time_sec

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Forget internal state after a world reset (gazebo_ros's ``/reset_world`` and
        ``/reset_simulation``, simulation_interfaces' ``ResetSimulation``): odometry back to zero, rate
        gates re-armed (``info.sim_time_sec`` may have gone back to 0), commands dropped. The world's
        state has been reset before this is called."""

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Before physics: write commands (actuator controls, joint velocities) for the steps that follow.

        ``info.sim_time_sec`` is the time at the start of the block of steps about to run; the commands
        hold for every step of it, so a system that must act between two steps says so with
        :meth:`next_update`. Runs on the simulation thread: hand anything slow to another thread and take
        the result at a later update."""

    def update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Around physics, by priority: before the steps when :attr:`priority` < ``PHYSICS`` (gz-sim's
        ``PreUpdate``-like systems that must follow others' commands), after them otherwise."""

    def post_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After physics: observe and publish; must not change the world (gz-sim's ``PostUpdate`` contract:
        every observer of a step sees the same state, whatever their order).

        ``info.sim_time_sec`` is the time after the block's steps and the state is the state then. Publish
        through the bus (an endpoint's ``publish``): the bus hands the payload to the ROS bridge's
        outbox, which converts and publishes it off the simulation thread, so this should cost no more
        than building the payload."""

    def shutdown(self) -> None:
        """The entity is being removed (deleted, or a failed spawn undone): release what :meth:`configure`
        took that the world does not own (threads, GL contexts, files). Endpoints and actuators go with
        the entity."""

    def node_parameters(self) -> dict[str, ParamValue]:
        """Values this system adds to its plugin node's parameters, beyond the ``<plugin>`` elements
        (a sensor's ``update_rate``); see :func:`~gazelle.systems._plugin_config.plugin_node`."""
        return {}

    def parameter_setters(self) -> dict[str, Callable[[ParamValue], str | None]]:
        """The parameters that can be set at run time (called on the simulation thread; a setter returns
        None once applied, else why not). The others are read-only."""
        return {}


_Call = tuple[System, str, Callable[[UpdateInfo, PhysicsWorld], None], "RateGate | None"]
"""A bound phase call: the system, the phase's name, the bound method and the system's phase gate."""


def _overrides(system: System, phase: str) -> bool:
    return getattr(type(system), phase) is not getattr(System, phase)


class SystemManager:
    """Keeps one sorted list per phase; equal priorities run in load order."""

    PHASES = ("reset", "pre_update", "update", "post_update")

    def __init__(self) -> None:
        """No systems yet; the phase lists are rebuilt whenever a system is added or removed."""
        self._systems: list[tuple[str, System]] = []
        self._phase: dict[str, list[System]] = {p: [] for p in self.PHASES}
        self._before_calls: list[_Call] = []
        self._after_calls: list[_Call] = []
        self._update_before: list[System] = []
        self._update_after: list[System] = []
        self._stepped: list[System] = []

    def add(self, owner: str, system: System) -> None:
        """Add a system owned by entity ``owner``; the phase lists are re-sorted by priority."""
        self._systems.append((owner, system))
        self._rebuild()

    def remove_owner(self, owner: str) -> list[System]:
        """Remove and shut down every system of entity ``owner``; returns them."""
        gone = [s for o, s in self._systems if o == owner]
        self._systems = [(o, s) for o, s in self._systems if o != owner]
        self._rebuild()
        for s in gone:
            s.shutdown()
        return gone

    def systems(self, owner: str | None = None) -> list[System]:
        """The systems of ``owner`` (all when None), in load order."""
        return [s for o, s in self._systems if owner is None or o == owner]

    def refresh(self) -> None:
        """Bind the phase calls again (after systems' attributes were replaced, as a checkpoint restores them)."""
        self._rebuild()

    def _rebuild(self) -> None:
        """The phase lists, in priority order (ties in the order added): which systems run before physics and which
        after, and the bound calls of each, made once so a block of steps does not look them up again."""
        ordered = [s for _, s in sorted(enumerate(self._systems), key=lambda it: (it[1][1].priority, it[0]))]
        systems = [s for _, s in ordered]
        for p in self.PHASES:
            self._phase[p] = [s for s in systems if _overrides(s, p)]
        self._update_before = [s for s in self._phase["update"] if s.priority < PHYSICS]
        self._update_after = [s for s in self._phase["update"] if s.priority >= PHYSICS]
        stepped = ("pre_update", "update", "post_update")
        self._stepped = [s for s in systems if any(_overrides(s, p) for p in stepped)]
        # the calls of each stepping phase, bound once (each block of steps makes them all)
        self._before_calls = [(s, "pre_update", s.pre_update, s.phase_gate) for s in self._phase["pre_update"]] + [
            (s, "update", s.update, s.phase_gate) for s in self._update_before
        ]
        self._after_calls = [(s, "update", s.update, s.phase_gate) for s in self._update_after] + [
            (s, "post_update", s.post_update, s.phase_gate) for s in self._phase["post_update"]
        ]

    def next_update(self, sim_time_sec: float) -> float:
        """The earliest :meth:`System.next_update` of the systems that have a per-step phase: the runtime
        steps MuJoCo without calling Python until then (a block of steps). A system whose ``next_update``
        raises is disabled with its error and the answer is "now", so a broken system costs one block, not
        the run; an answer at or before now ends the search early, since nothing can be sooner."""
        earliest = math.inf
        for s in self._stepped:
            try:
                t = s.next_update(sim_time_sec)
            except Exception as err:
                self._disable(s, "next_update", err)
                return sim_time_sec
            if t < earliest:
                earliest = t
                if t <= sim_time_sec:
                    break
        return earliest

    def _disable(self, system: System, phase: str, err: BaseException) -> None:
        """A system that raises is reported and taken out; the simulation keeps running."""
        owner = next((o for o, s in self._systems if s is system), "?")
        _log.error(
            f"system {type(system).__name__} of entity '{owner}' raised in {phase}: "
            f"{type(err).__name__}: {err}; it is disabled, the simulation goes on"
        )
        self._systems = [(o, s) for o, s in self._systems if s is not system]
        self._rebuild()

    def _run(self, systems: list[System], phase: str, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Run one phase on every system in ``systems``; a system that raises is reported and disabled, and the
        others run on."""
        for s in systems:
            try:
                getattr(s, phase)(info, world)
            except Exception as err:
                self._disable(s, phase, err)

    def reset(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Run every system's ``reset`` (a world reset)."""
        self._run(self._phase["reset"], "reset", info, world)

    def pre_update(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """Before the steps: every ``pre_update``, then the ``update`` s with priority below PHYSICS."""
        self._call(self._before_calls, info, world)

    def post_physics(self, info: UpdateInfo, world: PhysicsWorld) -> None:
        """After the steps: the other ``update`` s, then every ``post_update``."""
        self._call(self._after_calls, info, world)

    def _call(self, calls: list[_Call], info: UpdateInfo, world: PhysicsWorld) -> None:
        """Run the bound calls of a stepping phase, skipping a gated system that is not due (with a 200 Hz IMU and a
        system running every step, 199 calls in 200); a system that raises is reported and disabled, and the rest
        run on."""
        # a gated phase that is not due would return at once: not calling it saves the call (with a
        # 200 Hz IMU and a system running every step, 199 of 200 calls); the test is RateGate.due's
        t = info.sim_time_sec + RateGate.TOLERANCE
        for system, phase, fn, gate in calls:
            if gate is not None and t < gate._next:
                continue
            try:
                fn(info, world)
            except Exception as err:
                self._disable(system, phase, err)  # rebuilds the lists; this loop goes on over the old one


class RateGate:
    """A sim-time rate limit: :meth:`due` is true at most ``rate_hz`` times per second of sim time
    (every step when ``rate_hz`` is 0 or less), first at the first step. One implementation for every
    periodic publisher (robot_state_publisher, joint states, p3d, gz-sim odometry, sensors next);
    :attr:`next` is what the system's :meth:`System.next_update` returns."""

    __slots__ = ("_next",)

    TOLERANCE = 1e-9
    """A time within this of the next period is due (float sums of steps fall either side of it)."""

    def __init__(self) -> None:
        self._next = 0.0

    @property
    def next(self) -> float:
        """The sim time from which :meth:`due` is true again."""
        return self._next

    def due(self, sim_time_sec: float, rate_hz: float) -> bool:
        """Whether it is time to act at ``sim_time_sec``; if so, the next time is the next multiple of
        the period. Every gate of one rate (and of rates that divide each other: 100, 50, 20 Hz) then
        falls on the same times, so the world steps inside MuJoCo between them in long blocks."""
        if sim_time_sec + self.TOLERANCE < self._next:
            return False
        if rate_hz > 0:
            period = 1.0 / rate_hz
            self._next = (math.floor(sim_time_sec / period + 1e-6) + 1) * period
        else:
            self._next = sim_time_sec
        return True

    def reset(self) -> None:
        """Act at the next step (after a reset of sim time)."""
        self._next = 0.0

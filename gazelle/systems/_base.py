"""The plugin framework: systems opt into phases, run in an explicit priority order.

Phases per step, as in gz-sim:

1. ``pre_update`` (before physics): controllers write commands; takes effect this step.
2. ``update`` with priority < ``PHYSICS`` runs before the physics step, the rest after it.
3. ``post_update`` (after physics): read-only observers (odometry, joint states, TF).

``configure`` runs once when the entity is added (before the MuJoCo model is
recompiled, so a system can add actuators), ``reset`` on a world reset.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Generic, TypeVar

from ..description import ConfigElement, Plugin
from ._bus import Bus

if TYPE_CHECKING:  # pragma: no cover
    from ..physics._world import Entity, PhysicsWorld

_log = logging.getLogger("gazelle.systems")

PRE_PHYSICS = -128
PHYSICS = -64
DEFAULT_PRIORITY = 0
T = TypeVar("T")


class PerGeneration(Generic[T]):
    """A value derived from the compiled model (MuJoCo ids, qpos/qvel addresses): ``get(world)`` computes
    it once per ``world.generation``, since every recompile (a spawn, a delete) may renumber them."""

    __slots__ = ("_compute", "_generation", "_value")

    def __init__(self, compute: Callable[[PhysicsWorld], T]) -> None:
        self._compute = compute
        self._generation = -1
        self._value: T | None = None

    def get(self, world: PhysicsWorld) -> T:
        if self._generation != world.generation:
            self._value = self._compute(world)
            self._generation = world.generation
        return self._value  # type: ignore[return-value]


@dataclass(frozen=True, slots=True)
class UpdateInfo:
    """What every system receives each step."""

    sim_time_sec: float
    """Simulation time at the start of this step (pre/update) or after it (post)."""
    real_time_sec: float
    """Wall-clock seconds since the simulation started."""
    dt_sec: float
    """Physics step size."""
    iterations: int
    """Steps taken so far."""
    paused: bool


@dataclass
class SystemContext:
    """Everything a system may touch while configuring."""

    world: "PhysicsWorld"
    entity: "Entity"
    plugin: Plugin | None
    bus: Bus
    logger: logging.Logger


class System:
    """Base class; override only the phases you need (trivial ones are skipped)."""

    priority: int = DEFAULT_PRIORITY

    def configure(self, ctx: SystemContext) -> None:
        """Read the configuration, check the entity, declare endpoints and actuators."""

    def reset(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        """Forget internal state after a world reset."""

    def pre_update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        """Before physics: write commands."""

    def update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        """Around physics, by priority."""

    def post_update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        """After physics: observe; must not change the world."""

    def shutdown(self) -> None:
        """The entity is being removed."""


def _overrides(system: System, phase: str) -> bool:
    return getattr(type(system), phase) is not getattr(System, phase)


class SystemManager:
    """Keeps one sorted list per phase; equal priorities run in load order."""

    PHASES = ("reset", "pre_update", "update", "post_update")

    def __init__(self) -> None:
        self._systems: list[tuple[str, System]] = []
        self._phase: dict[str, list[System]] = {p: [] for p in self.PHASES}
        self._update_before: list[System] = []
        self._update_after: list[System] = []

    def add(self, owner: str, system: System) -> None:
        self._systems.append((owner, system))
        self._rebuild()

    def remove_owner(self, owner: str) -> list[System]:
        gone = [s for o, s in self._systems if o == owner]
        self._systems = [(o, s) for o, s in self._systems if o != owner]
        self._rebuild()
        for s in gone:
            s.shutdown()
        return gone

    def systems(self, owner: str | None = None) -> list[System]:
        return [s for o, s in self._systems if owner is None or o == owner]

    def _rebuild(self) -> None:
        ordered = [s for _, s in sorted(enumerate(self._systems), key=lambda it: (it[1][1].priority, it[0]))]
        systems = [s for _, s in ordered]
        for p in self.PHASES:
            self._phase[p] = [s for s in systems if _overrides(s, p)]
        self._update_before = [s for s in self._phase["update"] if s.priority < PHYSICS]
        self._update_after = [s for s in self._phase["update"] if s.priority >= PHYSICS]

    def _disable(self, system: System, phase: str, err: BaseException) -> None:
        """A system that raises is reported and taken out; the simulation keeps running."""
        owner = next((o for o, s in self._systems if s is system), "?")
        _log.error(
            f"system {type(system).__name__} of entity '{owner}' raised in {phase}: "
            f"{type(err).__name__}: {err}; it is disabled, the simulation goes on"
        )
        self._systems = [(o, s) for o, s in self._systems if s is not system]
        self._rebuild()

    def _run(self, systems: list[System], phase: str, info: UpdateInfo, world: "PhysicsWorld") -> None:
        for s in systems:
            try:
                getattr(s, phase)(info, world)
            except Exception as err:  # noqa: BLE001 - one broken plugin must not stop the world
                self._disable(s, phase, err)

    def reset(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        self._run(self._phase["reset"], "reset", info, world)

    def pre_update(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        self._run(self._phase["pre_update"], "pre_update", info, world)
        self._run(self._update_before, "update", info, world)

    def post_physics(self, info: UpdateInfo, world: "PhysicsWorld") -> None:
        self._run(self._update_after, "update", info, world)
        self._run(self._phase["post_update"], "post_update", info, world)


# --------------------------------------------------------------------------- config helpers
def child_text(cfg: ConfigElement | None, tag: str) -> str | None:
    """The stripped text of ``<tag>``; None when it (or the whole configuration) is absent."""
    el = cfg.find(tag) if cfg is not None else None
    return el.text.strip() if el is not None else None


def all_texts(cfg: ConfigElement | None, tag: str) -> tuple[str, ...]:
    """The stripped text of every direct child ``<tag>`` (repeatable elements such as ``<joint_name>``)."""
    return tuple(el.text.strip() for el in cfg.findall(tag)) if cfg is not None else ()


def parse_float(cfg: ConfigElement | None, tag: str, default: float, log: logging.Logger) -> float:
    raw = child_text(cfg, tag)
    if cfg is None or raw is None or raw == "":
        return default
    try:
        return float(raw)
    except ValueError:
        el = cfg.find(tag)
        where = f"{el.location}: " if el is not None and el.location else ""
        log.warning(f"{where}<{tag}> must be a number, got {raw!r}; using {default}")
        return default


def parse_bool(cfg: ConfigElement | None, tag: str, default: bool, log: logging.Logger) -> bool:
    raw = child_text(cfg, tag)
    if cfg is None or raw is None or raw == "":
        return default
    low = raw.lower()
    if low in ("1", "true"):
        return True
    if low in ("0", "false"):
        return False
    el = cfg.find(tag)
    where = f"{el.location}: " if el is not None and el.location else ""
    log.warning(f"{where}<{tag}> must be true/false, got {raw!r}; using {default}")
    return default


def ros_block(cfg: ConfigElement | None) -> tuple[str, dict[str, str]]:
    """The ``<ros><namespace>`` and ``<remapping>from:=to`` entries of a gazebo_ros plugin."""
    ros = cfg.find("ros") if cfg is not None else None
    if ros is None:
        return "", {}
    ns = child_text(ros, "namespace") or ""
    remaps: dict[str, str] = {}
    for r in ros.findall("remapping"):
        text = r.text.strip()
        if ":=" in text:
            src, dst = text.split(":=", 1)
            remaps[src.strip()] = dst.strip()
        elif "=" in text:
            src, dst = text.split("=", 1)
            remaps[src.strip()] = dst.strip()
    return ns, remaps


class RateGate:
    """A sim-time rate limit: :meth:`due` is true at most ``rate_hz`` times per second of sim time
    (every step when ``rate_hz`` is 0 or less), first at the first step. One implementation for every
    periodic publisher (robot_state_publisher, joint states, p3d, gz-sim odometry, sensors next)."""

    __slots__ = ("_next",)

    def __init__(self) -> None:
        self._next = 0.0

    def due(self, sim_time_sec: float, rate_hz: float) -> bool:
        """Whether it is time to act at ``sim_time_sec``; if so, the next time is one period later."""
        if sim_time_sec + 1e-9 < self._next:
            return False
        self._next = sim_time_sec + (1.0 / rate_hz if rate_hz > 0 else 0.0)
        return True

    def reset(self) -> None:
        """Act at the next step (after a reset of sim time)."""
        self._next = 0.0

"""The running simulation: a physics world, its systems, pacing to a real-time factor.

All access to the world goes through one thread. Other threads (ROS service
callbacks, the viewer) hand work to it with :meth:`Simulation.call`, which runs
a function between two physics steps and returns its result, so requests never
race the stepping and are applied at step boundaries (deterministically when
the simulation is stepped in lock-step).
"""

from __future__ import annotations

import logging
import math
import queue
import threading
import time
from concurrent.futures import Future
from concurrent.futures import TimeoutError as FutureTimeout
from dataclasses import dataclass
from typing import Any, Callable, TypeVar

import mujoco
import numpy as np

from ..description import Model, Pose, World
from ..systems._base import SystemContext, SystemManager, UpdateInfo
from ..systems._bus import Bus
from ..systems._registry import audit_model, audit_world, create_system
from ..systems.robot_state import RSP_PLUGIN, RobotStatePublisher, robot_state_config
from ._convex import prepare as prepare_meshes
from ._world import Entity, ErrorKind, PhysicsOverload, PhysicsWorld, WorldError

T = TypeVar("T")

DIVERGENCE_REPORT_SEC = 10.0
"""After the first report of an entity's divergence, repeats are summarised at most this often."""
MAX_CATCH_UP_SEC = 1.0
"""With a target RTF, a lag behind the wall clock up to this long is made up by running flat out."""
_log = logging.getLogger("gazelle")


def _shutdown_system(system: object) -> None:
    """Shut down a system whose entity never made it into the world (its spawn failed)."""
    try:
        system.shutdown()  # type: ignore[attr-defined]
    except Exception:  # noqa: BLE001 - the spawn already failed; say so and go on
        _log.exception(f"{type(system).__name__}.shutdown raised after a failed spawn")


@dataclass(frozen=True)
class RtfSample:
    """Real-time factor measured over the last window."""

    rtf: float
    steps_per_sec: float


class Simulation:
    """A world plus systems, stepped on its own thread (or by hand, in lock-step)."""

    def __init__(
        self, world: World, *, rtf: float | None = None, bus: Bus | None = None, robot_state_publisher: bool = True
    ):
        """
        Args:
            world: the world description.
            rtf: target real-time factor; None = the world's ``real_time_factor``; 0 = as fast as possible.
        """
        if rtf is not None and (not math.isfinite(rtf) or rtf < 0):
            raise ValueError(f"`rtf` must be >= 0, got {rtf!r}")
        self.world = PhysicsWorld(world)
        self.world.model.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_AUTORESET)
        self.world.spec.option.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_AUTORESET)
        self.systems = SystemManager()
        self.bus = bus or Bus()
        physics = world.physics
        if rtf is None:
            rtf = physics.real_time_factor
            if physics.real_time_update_rate_hz == 0:
                rtf = 0.0
        self.rtf = rtf
        self.paused = False
        self.iterations = 0
        self.step_listeners: list[Callable[[UpdateInfo], None]] = []
        """Called on the sim thread after every step (e.g. the /clock publisher)."""
        self.divergence_listeners: list[Callable[[str, str], None]] = []
        self._queue: queue.Queue[tuple[Callable[[], Any], Future]] = queue.Queue()
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._wall0 = time.monotonic()
        self._anchor = (time.monotonic(), 0.0)
        self._rtf_window: list[tuple[float, float, int]] = []
        self.robot_state_publisher = robot_state_publisher
        """Give every spawned robot the built-in robot_state_publisher (a model file may still opt out)."""
        self.diverged: dict[str, str] = {}
        """Entity name -> what went wrong, for entities that blew up."""
        self._divergence_log: dict[str, tuple[int, float]] = {}
        """Entity name -> (divergences not yet reported, wall time of the last report)."""
        self._state_views: tuple[Any, np.ndarray, np.ndarray] = (None, np.zeros(0), np.zeros(0))
        """(MjData, its qpos, its qvel): array views kept for the divergence check before every step."""
        for problem in audit_world(World(name=world.name, plugins=world.plugins)):
            _log.warning(problem.format())
        for m in world.models:
            self._add_entity(m, name=m.name, pose=Pose(), namespace="", spawned=False)

    # ------------------------------------------------------------------ threading
    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def start(self) -> None:
        """Start stepping on a background thread."""
        if self.running:
            return
        self._stop.clear()
        self._anchor = (time.monotonic(), self.world.time)
        self._thread = threading.Thread(target=self._loop, name="gazelle-sim", daemon=True)
        self._thread.start()

    def stop(self, timeout: float = 5.0) -> None:
        """Stop the stepping thread (pending calls are still answered)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout)
        self._thread = None
        self._drain()

    def call(self, fn: Callable[[], T], timeout: float | None = 10.0) -> T:
        """Run ``fn`` on the simulation thread between two steps and return its result.

        A call the sim thread has not started within ``timeout`` is cancelled, never applied
        later: the caller was told it failed, so it must not happen behind its back. One already
        running is waited for (its work is bounded), so its reply is the truth.

        Raises whatever ``fn`` raises; ``TimeoutError`` if the sim thread did not get to it in time.
        """
        if not self.running or threading.current_thread() is self._thread:
            return fn()
        fut: Future = Future()
        self._queue.put((fn, fut))
        try:
            return fut.result(timeout=timeout)
        except FutureTimeout:
            if fut.cancel():
                raise TimeoutError(f"the simulation thread did not take the request within {timeout:g} s") from None
            return fut.result()  # it started in the meantime: its outcome is the reply

    def _drain(self) -> None:
        while not self._queue.empty():  # cheap check first: this runs before every step
            try:
                fn, fut = self._queue.get_nowait()
            except queue.Empty:
                return
            self._run_item(fn, fut)

    @staticmethod
    def _run_item(fn: Callable[[], Any], fut: Future) -> None:
        if not fut.set_running_or_notify_cancel():
            return
        try:
            fut.set_result(fn())
        except BaseException as err:  # noqa: BLE001 - handed to the caller
            fut.set_exception(err)

    def _wait(self, seconds: float) -> None:
        """Sleep up to ``seconds`` but serve calls as they arrive."""
        deadline = time.monotonic() + seconds
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return
            try:
                fn, fut = self._queue.get(timeout=remaining)
            except queue.Empty:
                return
            self._run_item(fn, fut)

    def _loop(self) -> None:
        try:
            while not self._stop.is_set():
                self._drain()
                if self.paused:
                    self._wait(0.01)
                    self._anchor = (time.monotonic(), self.world.time)
                    continue
                self.step()
                if self.rtf > 0:
                    wall_anchor, sim_anchor = self._anchor
                    target = wall_anchor + (self.world.time - sim_anchor) / self.rtf
                    ahead = target - time.monotonic()
                    if ahead > 0:
                        self._wait(ahead)
                    elif ahead < -MAX_CATCH_UP_SEC:
                        # too far behind to catch up: accept the loss and pace from here
                        self._anchor = (time.monotonic(), self.world.time)
                    # a shorter stall (a busy CPU, a garbage collection) is made up by stepping
                    # without sleeping, so sim time keeps tracking wall time for wall-clock nodes
        except Exception:  # pragma: no cover - reported, never silent
            _log.exception("simulation thread crashed")
            raise

    # ------------------------------------------------------------------ stepping
    def _info(self, paused: bool = False) -> UpdateInfo:
        return UpdateInfo(
            sim_time_sec=self.world.time,
            real_time_sec=time.monotonic() - self._wall0,
            dt_sec=self.world.timestep,
            iterations=self.iterations,
            paused=paused,
        )

    def step(self, n: int = 1) -> None:
        """Take ``n`` physics steps with every system phase (call on the sim thread or when stopped)."""
        w = self.world
        for _ in range(n):
            self.systems.pre_update(self._info(), w)
            # checked right before every step: MuJoCo's solver spreads one body's NaN to every
            # body in one step, so a NaN set from outside (a service, a system) must be caught here
            self._check_divergence()
            try:
                w.step()
            except PhysicsOverload as err:
                # never a dead simulation thread: pause, say why once, and keep serving requests
                self.paused = True
                _log.error(f"simulation paused: {err}")
                for listener in self.divergence_listeners:
                    listener("<world>", str(err))
                return
            self.iterations += 1
            info = self._info()
            self.systems.post_physics(info, w)
            for listener in tuple(self.step_listeners):
                try:
                    listener(info)
                except Exception:  # noqa: BLE001 - an observer must not stop the world
                    _log.exception(f"step listener {listener!r} raised; it is removed")
                    self.step_listeners.remove(listener)
            self._record_rtf()

    def _record_rtf(self) -> None:
        now = time.monotonic()
        win = self._rtf_window
        win.append((now, self.world.time, self.iterations))
        while len(win) > 2 and now - win[0][0] > 2.0:
            win.pop(0)

    def measured_rtf(self) -> RtfSample:
        """RTF and steps/s over the last ~2 s of stepping."""
        win = self._rtf_window
        if len(win) < 2 or win[-1][0] <= win[0][0]:
            return RtfSample(0.0, 0.0)
        dw = win[-1][0] - win[0][0]
        return RtfSample((win[-1][1] - win[0][1]) / dw, (win[-1][2] - win[0][2]) / dw)

    def _check_divergence(self) -> None:
        d = self.world.data
        cache = self._state_views
        if cache[0] is not d:  # a recompile made a new MjData; `d.qpos` builds a new array object per access
            cache = self._state_views = (d, d.qpos, d.qvel)
        _, qpos, qvel = cache
        # fast path (~0.6 µs): a NaN/inf makes these dot products non-finite (NaN < x is False),
        # a |qvel| >= 1e4 makes the first >= 1e8
        if qvel.dot(qvel) < 1e8 and math.isfinite(qpos.dot(qpos)):
            return
        if np.all(np.isfinite(d.qpos)) and np.all(np.isfinite(d.qvel)) and np.all(np.abs(d.qvel) < 1e4):
            return
        for name in self.world.diverged_entities() or ["<world>"]:
            reason = f"simulation of '{name}' diverged at t={self.world.time:.3f}s (NaN or runaway velocity)"
            first = name not in self.diverged
            self.diverged[name] = reason
            self._report_divergence(name, reason, first)
            if first:
                for listener in self.divergence_listeners:
                    listener(name, reason)
            if name in self.world.entities:
                e = self.world.entities[name]
                bad = ~np.isfinite(d.qpos)
                d.qpos[bad] = 0.0
                d.qvel[~np.isfinite(d.qvel)] = 0.0
                if e.built.free_joint:
                    self.world.set_entity_state(name, self.world._spawn_root_pose(e))
        d.qacc[:] = 0.0
        d.qacc_warmstart[:] = 0.0
        d.qvel[~np.isfinite(d.qvel)] = 0.0
        mujoco.mj_forward(self.world.model, d)

    def _report_divergence(self, name: str, reason: str, first: bool) -> None:
        """Log a divergence once, then at most a summary every :data:`DIVERGENCE_REPORT_SEC` of wall time.

        An entity that keeps diverging (reset, diverge, reset...) logged 2,006 lines a second.
        """
        now = time.monotonic()
        count, last = self._divergence_log.get(name, (0, -math.inf))
        if first:
            _log.error(reason + "; its state is reset to its spawn pose (repeats are summarised)")
            self._divergence_log[name] = (0, now)
            return
        count += 1
        if now - last >= DIVERGENCE_REPORT_SEC:
            _log.error(
                f"simulation of '{name}' diverged {count} more time(s) in the last {now - last:.0f} s, "
                "each time reset to its spawn pose; delete it or fix its model (inertia, joint limits, start pose)"
            )
            count, last = 0, now
        self._divergence_log[name] = (count, last)

    # ------------------------------------------------------------------ entities
    def _configure_plugins(self, entity: Entity, into: list) -> None:
        """Create and configure a system for each supported plugin of ``entity`` (before the recompile),
        and the built-in robot_state_publisher for anything with joints or a URDF."""
        for problem in audit_model(entity.model):  # unsupported plugins and sensors: named, never dropped silently
            _log.warning(f"'{entity.name}': {problem.format()}")
        for plugin in entity.model.plugins:
            if plugin.filename == RSP_PLUGIN:
                continue  # configures the built-in one below
            system = create_system(plugin)
            if system is None:
                continue
            logger = logging.getLogger(plugin.name or plugin.filename)
            system.configure(SystemContext(self.world, entity, plugin, self.bus, logger))
            into.append(system)
        if self.robot_state_publisher and (entity.model.joints or entity.model.urdf):
            logger = logging.getLogger(f"{entity.name}.robot_state_publisher")
            config, plugin = robot_state_config(entity, logger)
            if config.enabled:
                rsp = RobotStatePublisher(config)
                rsp.configure(SystemContext(self.world, entity, plugin, self.bus, logger))
                into.append(rsp)

    def _add_entity(self, model: Model, *, name: str, pose: Pose, namespace: str, spawned: bool) -> Entity:
        pending: list = []

        def configure(entity: Entity) -> None:
            self._configure_plugins(entity, pending)

        try:
            entity = self.world.add_entity(
                model, name=name, X_WM=pose * model.pose, namespace=namespace, spawned=spawned, configure=configure
            )
        except WorldError as err:
            if err.kind == ErrorKind.BUILD_FAILED:  # only then did this attempt configure systems
                for system in pending:
                    _shutdown_system(system)
                self.bus.remove_owner(name)
            raise
        entity.systems.extend(pending)
        for s in pending:
            self.systems.add(name, s)
        return entity

    def spawn(self, model: Model, *, name: str | None = None, pose: Pose = Pose(), namespace: str = "") -> Entity:
        """Add a model (thread-safe). ``pose`` is where its model frame goes, composed with the file's own pose.

        Raises:
            WorldError: on a duplicate/invalid name, a bad pose or a model that cannot be built.
        """
        prepare_meshes(model)  # slow work (convex decompositions) here, in the caller's thread
        return self.call(
            lambda: self._add_entity(model, name=name or model.name, pose=pose, namespace=namespace, spawned=True)
        )

    def delete(self, name: str) -> None:
        """Remove an entity and its systems (thread-safe).

        Raises:
            WorldError: no such entity.
        """

        def do() -> None:
            if name not in self.world.entities:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{name}' does not exist")
            self.systems.remove_owner(name)
            self.bus.remove_owner(name)
            self.world.remove_entity(name)
            self.diverged.pop(name, None)
            self._divergence_log.pop(name, None)

        self.call(do)

    def reset(self, *, time_: bool = True, state: bool = True, spawned: bool = True) -> None:
        """Reset sim time, entity states and/or remove the spawned entities (thread-safe)."""

        def do() -> None:
            t = self.world.time
            if spawned:
                for e in [e for e in self.world.entities.values() if e.spawned]:
                    self.systems.remove_owner(e.name)
                    self.bus.remove_owner(e.name)
                    self.world.remove_entity(e.name)
            if state:
                self.world.reset_state()
                self.world.data.time = t
            if time_:
                self.world.reset_time()
                self.iterations = 0
            self._anchor = (time.monotonic(), self.world.time)
            self.systems.reset(self._info(self.paused), self.world)

        self.call(do)

    # ------------------------------------------------------------------ batch spawning (simulation_interfaces)
    def spawn_many(
        self, requests: list[tuple[Model, str, Pose, str, bool]], timeout: float | None = 60.0
    ) -> list[Entity | WorldError]:
        """Add several models in one sim-thread call with one recompile (thread-safe).

        Each request is ``(model, name, pose, namespace, allow_renaming)``; an empty
        name means the model's own. With ``allow_renaming`` a taken name becomes
        ``name_1``, ``name_2``, ... Returns, per request, the new entity or the
        :class:`WorldError` that refused it.
        """
        for request in requests:
            prepare_meshes(request[0])
        return self.call(lambda: self._spawn_many(requests), timeout=timeout)

    def _spawn_many(self, requests: list[tuple[Model, str, Pose, str, bool]]) -> list[Entity | WorldError]:
        taken = set(self.world.entities)
        names: list[str] = []
        for model, name, _pose, _ns, rename in requests:
            name = name or model.name
            if rename and name in taken:
                i = 1
                while f"{name}_{i}" in taken:
                    i += 1
                name = f"{name}_{i}"
            taken.add(name)
            names.append(name)
        pending: dict[str, list] = {}

        def make_configure(name: str) -> Callable[[Entity], None]:
            def configure(entity: Entity) -> None:
                self._configure_plugins(entity, pending.setdefault(name, []))

            return configure

        items = [
            (model, name, pose * model.pose, ns, True, make_configure(name))
            for (model, _n, pose, ns, _r), name in zip(requests, names)
        ]
        try:
            out = self.world.add_entities(items)
        except WorldError:
            # the combined build failed: undo every configure, then add one at a time
            for name, systems in pending.items():
                for system in systems:
                    _shutdown_system(system)
                self.bus.remove_owner(name)
            out = []
            for (model, _n, pose, ns, _r), name in zip(requests, names):
                if name in self.world.entities:  # never touch an existing entity's endpoints
                    out.append(WorldError(ErrorKind.NAME_NOT_UNIQUE, f"entity '{name}' already exists"))
                    continue
                try:
                    out.append(self._add_entity(model, name=name, pose=pose, namespace=ns, spawned=True))
                except WorldError as err:
                    out.append(err)
            return out
        for res, name in zip(out, names):
            if isinstance(res, Entity):
                res.systems.extend(pending.get(name, []))
                for s in pending.get(name, []):
                    self.systems.add(name, s)
            elif name in pending:  # configured, then its build failed
                for system in pending[name]:
                    _shutdown_system(system)
                self.bus.remove_owner(name)
        return out

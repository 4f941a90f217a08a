"""The running simulation: a physics world, its systems, pacing to a real-time factor.

This is the runtime layer: it owns the :class:`~gazelle.physics.PhysicsWorld`, creates the
systems of every entity's plugins and runs their phases around the physics steps.

Stepping: between two system updates the world steps inside MuJoCo. Before each block of
steps the runtime asks the systems (and the step listeners, such as /clock) when they next
need to run, and takes all the steps up to then in one ``mj_step(m, d, nstep)`` call. Python
runs only when something is due.

All access to the world goes through one thread. Other threads (ROS service
callbacks, the viewer) hand work to it with :meth:`Simulation.call`, which runs
a function between two physics steps and returns its result, so requests never
race the stepping and are applied at step boundaries (deterministically when
the simulation is stepped in lock-step).
"""

from __future__ import annotations

import hashlib
import logging
import math
import os
import queue
import threading
import time
import weakref
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from concurrent.futures import TimeoutError as FutureTimeout
from pathlib import Path
from typing import Any, TypeVar

from ..description import Model, Pose, World
from ..physics import (
    Entity,
    PhysicsOverload,
    PhysicsWorld,
    WorldError,
)
from ..systems import (
    Bus,
    System,
    SystemManager,
    UpdateInfo,
    audit_world,
)
from ._runtime_types import RtfSample, SpawnRequest, StepListener
from ._spawning import Spawner
from ._world_swap import WorldSwap

T = TypeVar("T")

DIVERGENCE_REPORT_SEC = 10.0
"""After the first report of an entity's divergence, repeats are summarised at most this often."""
MAX_CATCH_UP_SEC = 1.0
"""With a target RTF, a lag behind the wall clock up to this long is made up by running flat out."""
MAX_BLOCK_SEC = 0.01
"""The longest block of steps (sim time) taken without returning to Python, when nothing is due sooner."""
_log = logging.getLogger("gazelle")


class Simulation:
    """A world plus systems, stepped on its own thread (or by hand, in lock-step); its entities are added and
    removed by its :class:`~._spawning.Spawner` (``spawner``; ``spawn``, ``spawn_many`` and ``delete`` here hand
    their work on to it), and its world replaced at run time by its :class:`~._world_swap.WorldSwap` (``worlds``).
    Both parts see it as a :class:`~._host.SimulationHost`."""

    def __init__(
        self,
        world: World,
        *,
        rtf: float | None = None,
        bus: Bus | None = None,
        robot_state_publisher: bool = True,
        visual_geoms: bool = False,
        seed: int | None = None,
    ):
        """
        Args:
            world: the world description.
            rtf: target real-time factor; None = the world's ``real_time_factor``; 0 = as fast as possible.
            bus: the bus systems publish on (a new one by default); the ROS bridge listens to it.
            robot_state_publisher: give every robot the built-in robot_state_publisher.
            visual_geoms: put the visuals in the MuJoCo model (see :class:`~gazelle.physics.PhysicsWorld`),
                for offscreen cameras.
            seed: the seed of every system's noise (each system draws from its own stream, derived from
                this seed, its entity's name and its own, so a spawn never shifts another's noise); None,
                as Gazebo without ``--seed``: fresh entropy, runs with noise differ.
        """
        self.seed = seed
        asked_rtf = rtf
        self._noise_places: weakref.WeakKeyDictionary[System, tuple[str, str]] = weakref.WeakKeyDictionary()
        """Each noisy system's place (entity, name), from which its stream is seeded (see :meth:`reseed`)."""
        if rtf is not None and (not math.isfinite(rtf) or rtf < 0):
            raise ValueError(f"`rtf` must be >= 0, got {rtf!r}")
        self.world = PhysicsWorld(world, visual_geoms=visual_geoms)
        self.visual_geoms = visual_geoms
        """As asked (the world turns visuals on by itself once a camera is in it)."""
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
        self.step_listeners: list[StepListener] = []
        """Called on the sim thread after the steps (e.g. the /clock publisher); see :meth:`add_step_listener`."""
        self.divergence_listeners: list[Callable[[str, str], None]] = []
        self._queue: queue.Queue[tuple[Callable[[], Any], Future]] = queue.Queue()
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._wall0 = time.monotonic()
        self._anchor = (time.monotonic(), 0.0)
        self._inbox: deque[tuple[float, Callable[[Any], None], Any]] = deque()
        """Messages that arrived while the simulation was behind the wall clock: (sim time due, sink, payload)."""
        self._inbox_lock = threading.Lock()
        self._rtf_window: list[tuple[float, float, int]] = []
        self.robot_state_publisher = robot_state_publisher
        """Give every spawned robot the built-in robot_state_publisher (a model file may still opt out)."""
        self.max_block_steps = max(1, round(MAX_BLOCK_SEC / self.world.timestep))
        """The most steps taken in one MuJoCo call: calls from other threads wait at most this long."""
        self.diverged: dict[str, str] = {}
        """Entity name -> what went wrong, for entities that blew up."""
        self._divergence_log: dict[str, tuple[int, float]] = {}
        """Entity name -> (divergences not yet reported, wall time of the last report)."""
        self._lag_log: tuple[int, float, float] = (0, 0.0, -math.inf)
        """(lags not yet reported, their wall seconds lost, wall time of the last report)."""
        self.world_name = world.name
        self.named_poses = world.named_poses
        """Its named places, the world's ``<frame>``s attached to the world (see ``description.NamedPose``)."""
        self.world_plugins = world.plugins
        self.spherical_coordinates = world.spherical_coordinates
        self.magnetic_field = world.magnetic_field
        """The world's plugins: gz-sim's sensor systems among them run the sensors without a gazebo_ros plugin."""
        for problem in audit_world(World(name=world.name, plugins=world.plugins)):
            _log.warning(problem.format())
        self.spawner = Spawner(self, lambda: self.worlds.current is not None)
        """How models become entities and entities go (``spawn``, ``spawn_many``, ``delete`` hand their work to it)."""
        self.spawner.add_world_models(list(world.models))
        self.worlds = WorldSwap(self, self.spawner, world, asked_rtf)
        """The loaded world, and the one way to replace it at run time (``load``, ``unload``)."""

    def _seed_noise(self, system: System, entity: str, name: str) -> None:
        """Seed ``system``'s noise from the simulation's seed and its place (stable across processes and
        machines: a hash of the names, not Python's salted ``hash``)."""
        self._noise_places[system] = (entity, name)
        if self.seed is None:
            return
        digest = hashlib.sha256(f"{self.seed}\0{entity}\0{name}".encode()).digest()
        system.seed_noise(int.from_bytes(digest[:8], "little"))

    def reseed(self, seed: int) -> None:
        """Draw every system's noise from new streams seeded with ``seed`` (as if the run had started with
        it), from now on: a branch from a checkpoint with another draw of the sensors' noise."""

        def do() -> None:
            self.seed = seed
            for system, (entity, name) in list(self._noise_places.items()):
                self._seed_noise(system, entity, name)

        self.call(do)

    # ------------------------------------------------------------------ entities (the spawner's)
    def spawn(self, model: Model, *, name: str | None = None, pose: Pose = Pose(), namespace: str = "") -> Entity:
        """Add a model (thread-safe), as gazebo_ros's ``/spawn_entity`` and simulation_interfaces'
        ``SpawnEntity`` do: the model's plugins configured, its ros2_control started, its topics declared,
        all in the simulation thread's next gap between blocks.

        Args:
            model: a loaded robot or model (:func:`gazelle.description.load`).
            name: the entity's name (None: the model's own); it must not be taken.
            pose: where the model frame goes in the world, composed with the file's own ``<pose>`` (an SDF
                model's), as Gazebo places a spawned model: the request's pose times the model's.
            namespace: the ROS namespace of its topics and controller manager (``-robot_namespace``).

        Returns:
            The new entity.

        Raises:
            WorldError: on a duplicate/invalid name, a bad pose or a model that cannot be built; the world is
                then as it was (bit-identical: nothing of the model is left in it).
        """
        return self.spawner.spawn(model, name=name, pose=pose, namespace=namespace)

    def spawn_many(self, requests: list[SpawnRequest], timeout: float | None = 60.0) -> list[Entity | WorldError]:
        """Add several models in one sim-thread call with one recompile (thread-safe): simulation_interfaces'
        batch spawn, where a MuJoCo model rebuilt once for N models costs what one spawn does (a chessboard's
        32 pieces).

        Args:
            requests: the models with their names, poses and namespaces (:class:`SpawnRequest`).
            timeout: wall seconds to wait for the simulation thread (None: for ever).

        Returns:
            Per request, in order, the new entity or the :class:`WorldError` that refused it: one bad model
            never takes the others with it.
        """
        return self.spawner.spawn_many(requests, timeout)

    def add_entity_placed(
        self, model: Model, name: str, X_WM: Pose, namespace: str = "", *, spawned: bool = True
    ) -> Entity:
        """Add a model with its model frame at ``X_WM`` (the file's own pose already composed in), as a
        checkpoint recorded it (thread-safe).

        Args:
            model: the model as loaded.
            name: its entity's name.
            X_WM: the model frame in the world: :meth:`spawn`'s ``pose`` composed with the model's own.
            namespace: its ROS namespace.
            spawned: whether a reset with ``spawned`` removes it (spawned at run time) or keeps it (one of the
                world file's own models).
        """
        return self.spawner.add_entity_placed(model, name, X_WM, namespace, spawned=spawned)

    def delete(self, name: str) -> None:
        """Remove an entity and its systems (thread-safe).

        Raises:
            WorldError: no such entity.
        """
        self.spawner.delete(name)

    def _forget_divergence(self, name: str) -> None:
        """Drop what is remembered of a deleted entity's divergences (the spawner calls this)."""
        self.diverged.pop(name, None)
        self._divergence_log.pop(name, None)

    def _install_world(self, world: World, rtf: float | None) -> None:
        """The world swap's half on the simulation thread: every entity taken out the way a delete takes one,
        then ``world``'s physics started (no models yet), its clock at zero, paused; ``rtf`` the real-time factor
        asked for (None: the world's own)."""
        for name in list(self.world.entities):
            self.systems.remove_owner(name)
            self.bus.remove_owner(name)
        with self._inbox_lock:  # messages for the systems that just went
            self._inbox.clear()
        self.diverged.clear()
        self._divergence_log.clear()
        self._rtf_window.clear()
        generation = self.world.generation
        self.world = PhysicsWorld(world, visual_geoms=self.visual_geoms)
        # generations go on counting: what is cached against the old world's (the replay's body index, a
        # handle's indices) must not look current in the new one
        self.world.generation = generation + 1
        self.world_name = world.name
        self.world_plugins = world.plugins
        self.spherical_coordinates = world.spherical_coordinates
        self.magnetic_field = world.magnetic_field
        if rtf is None:
            physics = world.physics
            self.rtf = 0.0 if physics.real_time_update_rate_hz == 0 else physics.real_time_factor
        self.max_block_steps = max(1, round(MAX_BLOCK_SEC / self.world.timestep))
        self.paused = True
        self.iterations = 0
        for listener in self.step_listeners:
            listener.gate.reset()
        self._reanchor()

    # ------------------------------------------------------------------ threading
    @property
    def running(self) -> bool:
        """Whether the simulation thread is stepping (or paused but alive)."""
        return self._thread is not None and self._thread.is_alive()

    @property
    def thread_id(self) -> int | None:
        """The simulation thread's native (kernel) id while it runs, else None: what a profiler or a
        CPU meter (``/proc/self/task/<id>/stat``) reads."""
        thread = self._thread
        return thread.native_id if thread is not None and thread.is_alive() else None

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
        self._deliver_due(math.inf)

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

    def deliver(self, sink: Callable[[Any], None], payload: Any) -> None:
        """Hand ``payload``, a message that arrived just now from another thread, to ``sink`` so that it
        takes effect at the sim time of its arrival (thread-safe).

        Paced by the wall clock, the simulation is normally level with it and ``sink`` is called at
        once. After a stall (a busy CPU, a garbage collection) it is behind and catches up by stepping
        without sleeping; a message that arrived meanwhile waits until sim time reaches the moment it
        came. Called at once it would act on the steps that belong before it: a wall-clock node's
        0.2 m/s for 5 s drove 0.946 m when the turn command overtook the catching-up steps.
        """
        if self.rtf > 0 and not self.paused and self.running:
            wall_anchor, sim_anchor = self._anchor
            due = sim_anchor + (time.monotonic() - wall_anchor) * self.rtf
            with self._inbox_lock:
                # behind by more than a block (the normal jitter), or earlier messages still wait: in order
                if self._inbox or due > self.world.time + self.max_block_steps * self.world.timestep:
                    self._inbox.append((due, sink, payload))
                    return
        sink(payload)

    def _deliver_due(self, until: float) -> None:
        """Hand over the waiting messages due at or before sim time ``until`` (on the sim thread)."""
        while self._inbox:
            with self._inbox_lock:
                if not self._inbox or self._inbox[0][0] > until:
                    return
                _, sink, payload = self._inbox.popleft()
            try:
                sink(payload)
            except Exception:
                _log.exception(f"delivering a message to {sink!r} failed")

    def _reanchor(self) -> None:
        """Pace from here (start, pause, reset, a lag given up): waiting messages are due now."""
        self._anchor = (time.monotonic(), self.world.time)
        self._deliver_due(math.inf)

    def _drain(self) -> None:
        """Run every request queued by other threads (``call``), on this thread, before the next step: a request
        sees the world between two steps, never in the middle of one."""
        while not self._queue.empty():  # cheap check first: this runs before every step
            try:
                fn, fut = self._queue.get_nowait()
            except queue.Empty:
                return
            self._run_item(fn, fut)

    @staticmethod
    def _run_item(fn: Callable[[], Any], fut: Future) -> None:
        """Run one queued request and hand its result or exception to the caller's future (a cancelled future is
        skipped: its caller gave up waiting)."""
        if not fut.set_running_or_notify_cancel():
            return
        try:
            fut.set_result(fn())
        except BaseException as err:
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
        """The simulation thread: requests first, then a block of steps, then pacing. With a real-time factor, sim
        time is kept on a line anchored at the last (re)start: a thread ahead of it sleeps; one behind by less
        than :data:`MAX_CATCH_UP_SEC` steps without sleeping until it is back on the line; one further behind (a
        suspended laptop, a debugger) re-anchors and reports the lag, rather than racing for seconds. While
        paused it only serves requests."""
        try:
            while not self._stop.is_set():
                self._drain()
                if self.paused:
                    self._wait(0.01)
                    self._reanchor()
                    continue
                self._block(self.max_block_steps)
                if self.rtf > 0:
                    wall_anchor, sim_anchor = self._anchor
                    target = wall_anchor + (self.world.time - sim_anchor) / self.rtf
                    ahead = target - time.monotonic()
                    if ahead > 0:
                        self._wait(ahead)
                    elif ahead < -MAX_CATCH_UP_SEC:
                        # too far behind to catch up: accept the loss and pace from here
                        self._reanchor()
                        self._report_lag(-ahead)
                    # a shorter stall (a busy CPU, a garbage collection) is made up by stepping
                    # without sleeping, so sim time keeps tracking wall time for wall-clock nodes
        except Exception:  # pragma: no cover - reported, never silent
            _log.exception("simulation thread crashed")
            raise

    # ------------------------------------------------------------------ stepping
    def add_step_listener(self, fn: Callable[[UpdateInfo], None], rate_hz: float = 0.0) -> StepListener:
        """Call ``fn`` on the sim thread after the steps, at most ``rate_hz`` times per sim second
        (every step when 0). A listener that raises is logged and removed. Thread-safe.

        Args:
            fn: takes the block's :class:`UpdateInfo` (sim time, steps, paused). It runs on the simulation
                thread between blocks of steps, so it should hand data over and return (the ROS bridge
                publishes from here through its outbox): the world waits while it runs.
            rate_hz: the most calls per sim second; 0 calls it after every block. Listeners are due on
                sim time, so the rate is the same at any real-time factor.

        Returns:
            The listener (``remove_step_listener(fn)`` removes it).
        """
        listener = StepListener(fn, rate_hz)
        self.call(lambda: self.step_listeners.append(listener))
        return listener

    def remove_step_listener(self, fn: Callable[[UpdateInfo], None]) -> None:
        """Stop calling ``fn`` (thread-safe; unknown functions are ignored)."""

        def do() -> None:
            self.step_listeners[:] = [listener for listener in self.step_listeners if listener.fn != fn]

        self.call(do)

    def _info(self, paused: bool = False, dt: float | None = None) -> UpdateInfo:
        """The UpdateInfo the systems get for the step about to run: sim time, wall time since start, the step (or
        ``dt``), the iteration count and whether paused."""
        w = self.world
        return UpdateInfo(
            float(w.data.time),
            time.monotonic() - self._wall0,
            w.timestep if dt is None else dt,
            self.iterations,
            paused,
        )

    def _steps_until_due(self, limit: int) -> int:
        """How many physics steps (1..``limit``) can run before a system or listener is due."""
        t = float(self.world.data.time)
        due = self.systems.next_update(t)
        if self._inbox:
            due = min(due, self._inbox[0][0])
        for listener in self.step_listeners:
            due = min(due, listener.gate.next if listener.rate_hz > 0 else t)
        if due <= t:
            return 1
        dt = self.world.timestep
        steps = (due - t) / dt - 1e-6  # the gates accept a time within 1e-9 s of their period
        return max(1, min(limit, math.ceil(steps))) if math.isfinite(steps) else limit

    def step(self, n: int = 1) -> None:
        """Take ``n`` physics steps with every system phase (call on the sim thread or when stopped).

        The steps run in blocks: each block starts with the systems' ``pre_update`` and ends with
        their ``post_update`` and the step listeners, and is as long as nothing is due in between.
        """
        while n > 0:
            n -= self._block(n)

    def _block(self, limit: int) -> int:
        """One block of steps, at most ``limit``; returns how many steps were taken."""
        w = self.world
        if self._inbox:
            self._deliver_due(w.time + 0.5 * w.timestep)
        self.systems.pre_update(self._info(), w)
        # checked right before the steps: MuJoCo's solver spreads one body's NaN to every body in one
        # step, so a NaN set from outside (a service, a system) must be caught here
        self._check_divergence()
        k = self._steps_until_due(min(limit, self.max_block_steps))
        try:
            # fewer steps when a servo plan ends sooner (a JTC goal left its path tolerance: its
            # controller manager is due at once)
            k = w.step(k)
        except PhysicsOverload as err:
            # never a dead simulation thread: pause, say why once, and keep serving requests
            self.paused = True
            _log.error(f"simulation paused: {err}")
            for listener in self.divergence_listeners:
                listener("<world>", str(err))
            return limit
        self.iterations += k
        info = self._info(dt=k * w.timestep)
        self.systems.post_physics(info, w)
        t = info.sim_time_sec
        for listener in tuple(self.step_listeners) if self.step_listeners else ():
            if listener.rate_hz > 0 and not listener.gate.due(t, listener.rate_hz):
                continue
            try:
                listener.fn(info)
            except Exception:
                _log.exception(f"step listener {listener.fn!r} raised; it is removed")
                if listener in self.step_listeners:
                    self.step_listeners.remove(listener)
        self._record_rtf()
        return k

    def _record_rtf(self) -> None:
        """Add a sample to the 2 s window the real-time factor is measured over (at most one every 10 ms of wall
        time: a block of many steps adds one sample, not one per step)."""
        now = time.monotonic()
        win = self._rtf_window
        sample = (now, float(self.world.data.time), self.iterations)
        if len(win) > 2 and now - win[-2][0] < 0.01:
            win[-1] = sample  # one sample per 10 ms of wall time is plenty for a 2 s window
            return
        win.append(sample)
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
        """After a block: an entity whose state went NaN or ran away is put back at its spawn pose, at rest,
        by the physics world, and the rest of the world runs on. The first time an entity diverges the
        listeners hear of it (the ROS layer logs it on /rosout); GetEntityInfo reports it from then on."""
        diverged = self.world.recover_divergence()
        if diverged is None:
            return
        for name in diverged:
            reason = f"simulation of '{name}' diverged at t={self.world.time:.3f}s (NaN or runaway velocity)"
            first = name not in self.diverged
            self.diverged[name] = reason
            self._report_divergence(name, reason, first)
            if first:
                for listener in self.divergence_listeners:
                    listener(name, reason)

    def _report_lag(self, behind: float) -> None:
        """Say that sim time fell behind the wall clock for good (nodes timing with the wall clock see
        shorter motions): the first time at once, then a summary at most every
        :data:`DIVERGENCE_REPORT_SEC`."""
        now = time.monotonic()
        count, lost, last = self._lag_log
        count, lost = count + 1, lost + behind - MAX_CATCH_UP_SEC
        if now - last < DIVERGENCE_REPORT_SEC:
            self._lag_log = (count, lost, last)
            return
        _log.warning(
            f"the simulation fell {behind:.2f} s behind the wall clock (real-time factor {self.rtf:g}) and "
            f"dropped {lost:.2f} s of wall time in {count} stall(s) since the last report; nodes timing "
            "with the wall clock saw less sim time (a busy CPU? use_sim_time:=true avoids it)"
        )
        self._lag_log = (0, 0.0, now)

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

    # ------------------------------------------------------------------ checkpoints
    def checkpoint(self, path: str | os.PathLike[str], force: bool = False) -> Path:
        """Save everything this run needs to go on bit-identically to ``path`` (owner-only): the world and
        its entities, MuJoCo's whole data, every system's and controller's state, the noise streams (see
        :mod:`gazelle.sim._checkpoint`). :meth:`from_checkpoint` goes on from it, in any process. An earlier
        checkpoint at ``path`` is replaced; any other file only with ``force``.

        Raises:
            CheckpointError: something a system holds cannot be saved (the message names it), ``path`` holds
                something else than a checkpoint, or it cannot be written.
        """
        from . import _checkpoint

        return self.call(lambda: _checkpoint.save(self, path, force))

    @classmethod
    def from_checkpoint(cls, path: str | os.PathLike[str], world: World | None = None) -> Simulation:
        """A simulation that goes on from a checkpoint as the saved run did. ``world``, when given, must be
        the checkpoint's world.

        Raises:
            CheckpointError: not a checkpoint, made by another gazelle or MuJoCo version, of another world,
                or its models' files changed so that the world rebuilds differently.
        """
        from . import _checkpoint

        return _checkpoint.restore(_checkpoint.read(path), cls, world)

    def reset(self, *, time_: bool = True, state: bool = True, spawned: bool = True) -> None:
        """Reset sim time, entity states and/or remove the spawned entities (thread-safe).

        The three parts are Gazebo's three resets: gazebo_ros's ``/reset_world`` is ``state`` (models back
        to their start, the clock going on), ``/reset_simulation`` is ``state`` and ``time_``, and
        simulation_interfaces' ``ResetSimulation`` with SCOPE_ALL adds ``spawned`` (what was spawned since
        the start is removed; the world file's own models stay). Every system is told (a diff drive's
        odometry starts again at zero; a controller manager cycles at once, its controllers keeping their
        state).

        Args:
            time_: the clock back to 0 (nodes on sim time see /clock go back, as after Gazebo's reset).
            state: every entity's joints, poses and velocities back to their initial values.
            spawned: remove the entities spawned at run time.
        """

        def do() -> None:
            """On the simulation thread: spawned entities removed (``spawned``), the physics state back to the start
            with the clock kept (``state``), the clock back to zero (``time_``), and every system told to reset,
            as Gazebo's reset world / reset time / reset all."""
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
                for listener in self.step_listeners:
                    listener.gate.reset()
            self._reanchor()
            self.systems.reset(self._info(self.paused), self.world)

        self.call(do)

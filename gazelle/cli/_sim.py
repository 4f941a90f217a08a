"""``gazelle sim``: load a world, start physics and the ROS bridge, run until Ctrl-C."""

from __future__ import annotations

import dataclasses
import logging
import os
import signal
import subprocess
import sys
import threading
from pathlib import Path
from typing import TYPE_CHECKING

from ..description import Model, ModelLoadError, World, load
from ..sim import ReplayRecorder, start_signal_watchdog
from ..worlds import default_world
from ._world_file import INSTALLED_WORLDS, find_world_file

if TYPE_CHECKING:
    from ..ros import RosBridge
    from ..sim import Simulation
    from ..viewer import Viewer

GIL_SWITCH_INTERVAL_SEC = 0.0002
SHUTDOWN_DEADLINE_SEC = 4.5
"""SIGINT/SIGTERM end the process within this long, even if a thread is stuck (then with status 1).

An orderly shutdown takes 0.3 s idle and 0.6-0.9 s with three CPU hogs on two cores; a test run under
load once took over 3 s and the former 2.5 s deadline killed a healthy server. ``ros2 launch`` waits 5 s
after SIGINT before it sends SIGTERM (launch/actions/execute_local.py, ``sigterm_timeout`` default 5),
so a deadline under 5 s never makes launch escalate."""
FOXGLOVE_STOP_SEC = 0.5
"""How long a shutdown waits for the Foxglove process to stop by itself before killing it."""


def _force_exit() -> None:
    """The last resort of a shutdown that overran its deadline (a wedged rclpy or viewer thread): say so and
    end the process at once, status 1, so a launch or CI job never hangs on the server."""
    print(
        f"gazelle: shutdown did not finish within {SHUTDOWN_DEADLINE_SEC:g} s; exiting now", file=sys.stderr, flush=True
    )
    os._exit(1)


def load_world(path: Path | None, args: dict[str, str]) -> World:
    """The world to simulate: the embedded default, a world file (found where gz sim finds one:
    :func:`~._world_file.find_world_file`), or the default world plus one model.

    Raises:
        ModelLoadError: the file is nowhere gz sim would look, or has errors.
    """
    found = None if path is None else find_world_file(path)
    if found is None:
        return default_world()
    result = load(found, args=args)
    for d in result.diagnostics:
        print(d.format(), file=sys.stderr)
    value = result.value
    if isinstance(value, World):
        return value
    if isinstance(value, Model):
        base = default_world()
        return World(
            name=base.name, gravity=base.gravity, physics=base.physics, models=(*base.models, value), lights=base.lights
        )
    raise ModelLoadError(result.diagnostics)


def with_named_poses(world: World, files: tuple[Path, ...]) -> World:
    """``world`` with the named poses of each ``--named-poses`` file added after its own: the world ``<frame>``s
    of an SDF file that holds nothing else (see gazelle/ros/_named_poses.py).

    Raises:
        ModelLoadError: a file does not load.
        ValueError: a file is not a world, holds models, or names a named pose again (the line says where).
    """
    places = list(world.named_poses)
    for path in files:
        extra = load(path, expand_xacro=False).value
        if not isinstance(extra, World):
            raise ValueError(f"--named-poses {path}: not an SDF world (its <world> holds the <frame>s)")
        if extra.models:
            raise ValueError(f"--named-poses {path}: holds models; a named-poses file holds only world <frame>s")
        for place in extra.named_poses:
            first = next((p for p in places if p.name == place.name), None)
            if first is not None:
                where = f"{first.location.file}:{first.location.line}" if first.location else "the world"
                raise ValueError(f"--named-poses {path}: named pose '{place.name}' is already defined at {where}")
            places.append(place)
    return dataclasses.replace(world, named_poses=tuple(places))


def _name_worlds(sim: Simulation, path: Path | None) -> None:
    """The first LoadWorld is the world this server starts with: a LoadWorld of its URI (``file://`` and the
    file's real path, or ``empty.sdf`` for the embedded default) takes it again without reading anything, and
    the installed worlds are loadable by their bare names (as ``gazelle sim empty.sdf`` finds them)."""
    sim.worlds.installed = {name: default_world for name in INSTALLED_WORLDS}
    found = None if path is None else find_world_file(path)
    sim.worlds.name_first(INSTALLED_WORLDS[0] if found is None else f"file://{found.resolve()}")


PAUSED_NOTE = (
    "; PAUSED: time stands still until the viewer's play button, /unpause_physics or "
    "/gazelle/set_simulation_state runs it (gz sim starts paused without -r, gzserver with -u)"
)
"""Said on the ready line of a server started paused: a world that starts paused and says nothing looks broken."""


def run_sim(
    path: Path | None,
    *,
    rtf: float | None,
    clock_rate_hz: float,
    paused: bool,
    args: dict[str, str],
    viewer: bool = False,
    viewer_host: str = "127.0.0.1",
    viewer_port: int = 8080,
    viewer_allow_origins: tuple[str, ...] = (),
    ros_discovery: str | None = None,
    foxglove_port: int | None = None,
    seed: int | None = None,
    drop_when_behind: bool = False,
    replay: Path | None = None,
    replay_topics: tuple[str, ...] = (),
    replay_force: bool = False,
    named_poses: tuple[Path, ...] = (),
) -> int:
    """Run the server; returns the process exit code."""
    logging.basicConfig(level=logging.INFO, format="[%(levelname)s] [%(name)s]: %(message)s", stream=sys.stderr)
    if replay is not None and (why := ReplayRecorder.refusal(replay, replay_force)) is not None:
        print(f"gazelle: --replay {why}", file=sys.stderr)  # said now, not after a run whose replay it loses
        return 2
    stop, write_replay = _install_signal_handlers()
    start_signal_watchdog(
        SHUTDOWN_DEADLINE_SEC + 0.5
    )  # before any thread, and before the world's build, which may be long
    try:
        world = with_named_poses(load_world(path, args), named_poses)
    except (ModelLoadError, ValueError) as err:
        print(str(err), file=sys.stderr)
        return 1
    from ..ros import RosBridge, announce_often, choose_discovery_range
    from ..sim import Simulation

    # The sim thread holds the GIL while it steps; ROS callbacks (a cmd_vel arriving) wait
    # for the interpreter's switch interval, 5 ms by default: at 30x real time that is
    # 150 ms of sim time between a command and its effect. 0.2 ms keeps it to ~6 ms.
    sys.setswitchinterval(GIL_SWITCH_INTERVAL_SEC)
    discovery = choose_discovery_range(ros_discovery)
    sim = Simulation(world, rtf=rtf, seed=seed)  # its log lines (plugins, decompositions) go to stderr as they are
    sim.paused = paused
    _name_worlds(sim, path)
    # rclpy prints our records itself once the bridge is up
    for h in list(logging.getLogger().handlers):
        logging.getLogger().removeHandler(h)
    announce_often()  # before the first DDS participant: later processes find this one at once (see _dds)
    bridge = RosBridge(sim, clock_rate_hz=clock_rate_hz, announce=True, drop_when_behind=drop_when_behind)
    replays = (
        _Replays(ReplayRecorder(sim, topics=replay_topics), replay, world.name, replay_force)
        if replay is not None
        else None
    )
    sim.start()
    view = _start_viewer(sim, viewer_host, viewer_port, viewer_allow_origins) if viewer else None
    if view is not None and bridge.registry is not None:
        bridge.registry.announce_viewer(view.url)
    fox = _start_foxglove(viewer_host, foxglove_port, viewer_allow_origins) if foxglove_port is not None else None
    target = "as fast as possible" if sim.rtf == 0 else f"{sim.rtf:g}"
    print(
        f"gazelle: ready: world '{world.name}' ({len(sim.world.entities)} entities), "
        f"step {sim.world.timestep * 1000:g} ms, real-time factor {target}, "
        f"ROS_DOMAIN_ID={os.environ.get('ROS_DOMAIN_ID', '0')}, discovery {discovery}, publishing "
        + ("drops the oldest when behind (--drop-when-behind)" if drop_when_behind else "lossless")
        + (PAUSED_NOTE if paused else ""),
        flush=True,
    )
    rc = _serve(stop, write_replay, sim, bridge, replays)
    print("gazelle: shutting down", flush=True)
    _shut_down(sim, bridge, view, fox, replays)
    return rc


def _install_signal_handlers() -> tuple[threading.Event, threading.Event]:
    """SIGINT and SIGTERM set the first event (stop), SIGUSR1 the second (write the replay now and go
    on: a test that failed on a module's shared server wants it)."""
    stop, write_replay = threading.Event(), threading.Event()

    def on_signal(signum: int, _frame: object) -> None:
        """SIGINT or SIGTERM: the server loop ends in order (bridge, viewer, replay) from the main thread."""
        stop.set()

    signal.signal(signal.SIGINT, on_signal)
    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGUSR1, lambda _signum, _frame: write_replay.set())
    return stop, write_replay


class _Replays:
    """``--replay FILE``: the recorder and where (and as what) its replay is written."""

    def __init__(self, recorder: ReplayRecorder, path: Path, world_name: str, force: bool = False) -> None:
        self.recorder, self.path, self.world_name, self.force = recorder, path, world_name, force
        self.page = None
        if path.suffix.lower() in (".html", ".htm"):
            from ..viewer import replay_html  # now: the shutdown has 3 s for everything

            self.page = replay_html

    def save(self) -> None:
        """Write the replay (an HTML page when the path ends in .html, else the recorder's own file); a
        failure to write is said, never a traceback during shutdown."""
        try:
            if self.page is not None:
                data = self.page(self.recorder.data(), title=f"gazelle replay: {self.world_name}")
                self.recorder.write(self.path, data, force=self.force)
            else:
                self.recorder.write(self.path, force=self.force)
        except OSError as err:
            print(f"gazelle: the replay was not written: {err}", file=sys.stderr)


def _start_viewer(sim: Simulation, host: str, port: int, allow_origins: tuple[str, ...]) -> Viewer | None:
    """The browser viewer, started; None (said on stderr) if its port cannot be had."""
    from ..viewer import Viewer

    try:
        view = Viewer(sim, host=host, port=port, allow_origins=allow_origins)
    except OSError as err:
        print(f"gazelle: viewer not started: {err}", file=sys.stderr)
        return None
    view.start()
    print(f"gazelle: viewer at {view.url}", flush=True)
    return view


def _start_foxglove(host: str, port: int, allow_origins: tuple[str, ...]) -> subprocess.Popen[bytes]:
    """The Foxglove bridge in a process of its own: forwarding topics never competes with the simulation
    for the GIL."""
    cmd = [sys.executable, "-m", "gazelle.cli", "foxglove", "--host", host, "--port", str(port)]
    for origin in allow_origins:
        cmd += ["--allow-origin", origin]
    return subprocess.Popen(cmd, env={**os.environ, "GAZELLE_FOXGLOVE_PARENT": str(os.getpid())})


def _serve(
    stop: threading.Event, write_replay: threading.Event, sim: Simulation, bridge: RosBridge, replays: _Replays | None
) -> int:
    """Until a signal asks to stop (0) or a part of the server died (1, said on stderr): never a deaf
    server that looks alive."""
    from ..ros import LAUNCH_ID_VAR, launch_ended

    launch_id = os.environ.get(LAUNCH_ID_VAR, "")
    ticks = 0
    while not stop.wait(0.1):
        ticks += 1
        if launch_id and ticks % 10 == 0 and launch_ended(launch_id):
            domain = os.environ.get("ROS_DOMAIN_ID", "0")
            print(
                f"gazelle: the ros2 launch that started this server (pid {launch_id.split(':')[0]}) has ended without "
                f"stopping it; exiting, so that the next launch on ROS_DOMAIN_ID={domain} gets its own server",
                file=sys.stderr,
            )
            return 1
        if write_replay.is_set():
            write_replay.clear()
            if replays is not None:
                replays.save()
        if not sim.running:
            print("gazelle: simulation thread stopped unexpectedly (its traceback is above); exiting", file=sys.stderr)
            return 1
        if not bridge.alive:
            print(f"gazelle: ROS executor thread stopped ({bridge.failure!r}); exiting", file=sys.stderr)
            return 1
        if bridge.registry is not None and bridge.registry.conflict is not None:
            print(f"gazelle: {bridge.registry.conflict}; exiting", file=sys.stderr)
            return 1
    return 0


def _shut_down(
    sim: Simulation,
    bridge: RosBridge,
    view: Viewer | None,
    fox: subprocess.Popen[bytes] | None,
    replays: _Replays | None,
) -> None:
    """The user asked to stop: whatever a thread is in the middle of, the process ends within
    SHUTDOWN_DEADLINE_SEC (an orderly shutdown takes ~0.3 s)."""
    import time

    watchdog = threading.Timer(SHUTDOWN_DEADLINE_SEC, _force_exit)
    watchdog.daemon = True
    watchdog.start()
    t0 = time.monotonic()
    # the Foxglove process stops on its own meanwhile: asked first, waited for last, with what is left of
    # the deadline (a loaded run waited 3 s on it here and the watchdog killed the server)
    if fox is not None:
        fox.send_signal(signal.SIGINT)
    bridge.node.outbox.stop_waiting()  # the simulation thread's last block must not wait on publishing
    if view is not None:
        view.stop()
    sim.stop()
    if replays is not None:
        replays.save()
    bridge.shutdown()
    if fox is not None:
        # it stops in ~0.4 s; one that has not by the time the rest is done is killed: the interpreter's
        # own exit needs what is left of the deadline (a loaded run was killed by the watchdog at 3 s)
        try:
            fox.wait(max(0.1, min(FOXGLOVE_STOP_SEC, SHUTDOWN_DEADLINE_SEC - 1.0 - (time.monotonic() - t0))))
        except subprocess.TimeoutExpired:
            fox.kill()

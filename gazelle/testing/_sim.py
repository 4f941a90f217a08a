"""A `gazelle sim` server owned by a test: started paused on a private domain, stepped by the test in
sim time, with the robots it spawns, the launch files it runs and an optional MCAP recording, all torn
down with it."""

from __future__ import annotations

import contextlib
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from .._errors import SimError
from ._dds_profile import without_writer_profile
from ._domain import environ_applied
from ._ros_node import RosTestNode, TestTimeout
from ._settle import Settler
from ._warnings import GazelleWarning, client_warnings, server_warning, spawn_failure

__all__ = ["ChildProcess", "Sim", "SimError", "SimFailed"]

_READY = re.compile(r"gazelle: ready: .* step ([0-9.eE+-]+) ms")
STEP_CHUNK_SEC = 0.05
"""run_until checks its predicate every this much sim time (and the test node catches up in between)."""
ACK_TIMEOUT = 10.0
"""Wall seconds a step waits for the subscribers of the test's topics to acknowledge what it published."""


class SimFailed(SimError, RuntimeError):
    """The simulation could not do what the test asked (start, spawn, launch): the message says why,
    with the last lines the process printed. A :class:`SimError`, gazelle's one root (``except SimError``, as
    the docs say, catches it)."""


def collect_lines(popen: subprocess.Popen[str], lines: list[str], cond: threading.Condition) -> None:
    """Append each line ``popen`` prints to ``lines`` (under ``cond``, waking its waiters) until it ends.

    The process is reaped before the last wake-up, so a waiter woken by it sees the exit (``poll()`` was
    None for a moment after EOF, and a process that died at once cost a waiter its whole timeout)."""
    assert popen.stdout is not None
    for line in popen.stdout:
        with cond:
            lines.append(line.rstrip("\n"))
            cond.notify_all()
    with contextlib.suppress(subprocess.TimeoutExpired):
        popen.wait(5)
    with cond:
        cond.notify_all()


class ChildProcess:
    """A process the test started (the server, a spawn, a launch, a recorder), in a process group of its
    own so that stopping it stops everything it started; its output is kept line by line."""

    def __init__(self, name: str, argv: Sequence[str], env: Mapping[str, str], cwd: Path | None = None) -> None:
        """A process the test harness started, in a session of its own (stopped with its children), its output read
        on a thread and kept."""
        self.name = name
        self.argv = list(argv)
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self.popen = subprocess.Popen(
            self.argv,
            env=dict(env),
            cwd=cwd,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            errors="replace",
            start_new_session=True,
        )
        threading.Thread(target=self._read, name=f"gazelle-test-{name}", daemon=True).start()

    def _read(self) -> None:
        collect_lines(self.popen, self.lines, self._cond)

    @property
    def output(self) -> str:
        with self._cond:
            return "\n".join(self.lines)

    def lines_from(self, start: int) -> list[str]:
        """The output lines from the ``start``-th on (a copy)."""
        with self._cond:
            return self.lines[start:]

    def tail(self, n: int = 20) -> str:
        with self._cond:
            return "\n".join(self.lines[-n:])

    def wait_line(self, pattern: re.Pattern[str], timeout: float) -> re.Match[str]:
        """The first output line matching ``pattern``; SimError if the process ends or time runs out."""
        deadline = time.monotonic() + timeout
        seen = 0
        with self._cond:
            while True:
                for line in self.lines[seen:]:
                    if m := pattern.search(line):
                        return m
                seen = len(self.lines)
                if self.popen.poll() is not None:
                    raise SimFailed(f"{self.name} exited with {self.popen.returncode}:\n{self.tail()}")
                left = deadline - time.monotonic()
                if left <= 0:
                    raise SimFailed(
                        f"{self.name} did not print {pattern.pattern!r} within {timeout:g} s:\n{self.tail()}"
                    )
                self._cond.wait(min(left, 0.1))

    def wait(self, timeout: float) -> int:
        """Its exit code; a SimError with the end of its output when it has not ended within ``timeout``."""
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            raise SimFailed(f"{self.name} did not end within {timeout:g} s:\n{self.tail()}") from None

    def stop(self, timeout: float = 10.0) -> int | None:
        """SIGINT to its whole group (as Ctrl-C), SIGKILL after ``timeout``; returns the exit status."""
        if self.popen.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.popen.pid, signal.SIGINT)
            try:
                self.popen.wait(timeout)
            except subprocess.TimeoutExpired:
                pass
        # whatever it started and left behind goes too (the group outlives its leader)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self.popen.pid, signal.SIGKILL)
        with contextlib.suppress(subprocess.TimeoutExpired):
            self.popen.wait(5)
        return self.popen.returncode


def _sent_as_it_is(file: Path) -> bool:
    """Whether ``gazelle spawn -file`` sends the file's text as it is (its lines the file's): not xacro, which it
    expands (the expanded elements name their files and lines themselves)."""
    from ..description import xacro_markup

    try:
        return not file.name.endswith(".xacro") and xacro_markup(file.read_text(encoding="utf-8")) is None
    except (OSError, UnicodeDecodeError):
        return False


def gazelle_command(*args: str) -> list[str]:
    """The argv of a ``gazelle`` command run by this Python (the test's venv, whatever is on PATH)."""
    return [sys.executable, "-m", "gazelle.cli", *args]


def recorded_names(topics: Sequence[str]) -> list[str]:
    """The topics a test's bag records: those it names, then /tf, /tf_static and /clock."""
    return list(dict.fromkeys([*topics, "/tf", "/tf_static", "/clock"]))


def _server_args(
    world: str | os.PathLike[str] | None,
    seed: int,
    paused: bool,
    rtf: float | None,
    replay: tuple[str | os.PathLike[str], Sequence[str]] | None,
    extra: Sequence[str],
) -> list[str]:
    """``gazelle sim``'s arguments for a test's server (see :class:`Sim`): headless, seeded, and paused
    unless the test runs the world in real time."""
    args = ["sim", *([str(world)] if world is not None else []), "--no-viewer", "--seed", str(seed)]
    if paused:
        args.append("--paused")
    if rtf is not None:
        args += ["--rtf", f"{rtf:g}"]
    if replay is not None:
        args += ["--replay", str(replay[0]), *[a for t in replay[1] for a in ("--replay-topic", t)]]
    return args + list(extra)


class Sim:
    """The ``gazelle_sim`` fixture: a server started paused, and the test's ROS node (``ros``).

    Time is the test's: nothing moves until ``run_for``/``run_until`` steps the world (as fast as the
    machine allows, through simulation_interfaces' StepSimulation), and every timeout given in sim
    seconds means the same on a slow runner as on a fast one. Wall-clock limits only catch a hung
    server.

    Args:
        domain_id: the ROS domain of this simulation alone (the plugin reserves one per test).
        world: an SDF world file (None: the embedded default world: ground plane and sun).
        seed: the seed of every random draw in the server (sensor noise), so a failure can be run again
            bit for bit with ``--gazelle-seed``.
        paused: start paused, the test stepping the world (the plugin's default); False runs the world
            on its own at ``rtf``, and :meth:`run_for` then waits instead of stepping.
        rtf: real-time factor of a running server (None: the server's default, 1).
        env: the environment for the server and every process started (None: this process's); the
            domain, localhost-only discovery and Fast DDS are set over it.
        start_timeout: wall seconds for the server to say it is ready and its services to appear.
        record: (folder, topics) to record from the first step (see :meth:`record`); the recorder
            starts beside the server, so their start-ups overlap.
        server_args: more ``gazelle sim`` arguments.
        replay: (file, topics): the server keeps a replay page of the run since the last reset there
            (written at its end, or by :meth:`save_replay`).
        settle_timeout: after each chunk of stepped time, wait up to this many wall seconds until the
            processes the test started (:meth:`run`, :meth:`launch`) are idle (lockstep, see
            ``_settle``); 0 steps without waiting for them.
        strict: a warning of the server about a spawn (:meth:`spawn`) is a :class:`SimError`, not a
            :class:`GazelleWarning`.

    Raises:
        SimError: the server did not start (its output's end is in the message).
    """

    def __init__(
        self,
        *,
        domain_id: int,
        world: str | os.PathLike[str] | None = None,
        seed: int = 0,
        paused: bool = True,
        rtf: float | None = None,
        env: Mapping[str, str] | None = None,
        start_timeout: float = 60.0,
        record: tuple[str | os.PathLike[str], Sequence[str]] | None = None,
        server_args: Sequence[str] = (),
        replay: tuple[str | os.PathLike[str], Sequence[str]] | None = None,
        settle_timeout: float = 10.0,
        strict: bool = False,
    ) -> None:
        """Start a ``gazelle sim`` server (headless) on ``domain_id`` and the test's node, and return once the
        server's StepSimulation service is reachable (the arguments: see the class docstring)."""
        self.domain_id = domain_id
        self._settler = Settler(settle_timeout)
        self.seed = seed
        self.paused = paused
        self.strict = strict
        self.warnings: list[str] = []
        """The server's warnings about what the test spawned since the last reset ("spawning NAME from FILE: ...")."""
        self._warnings_from = 0
        self._sources: dict[str, str] = {}
        """The server's label of a spawn's XML -> the plain file it came from (see :meth:`_named`)."""
        """The server's first output line that :meth:`server_warnings` reads (its first, then each reset's)."""
        self.env = {
            **without_writer_profile(dict(env if env is not None else os.environ)),
            "ROS_DOMAIN_ID": str(domain_id),
            "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
            "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp",
        }
        self.env.pop("ROS_LOCALHOST_ONLY", None)
        self.env.pop("ROS_STATIC_PEERS", None)
        self.children: list[ChildProcess] = []
        self._kept = 0
        self._ros: RosTestNode | None = None
        self.replay_path = Path(replay[0]) if replay is not None else None
        self._recorder: ChildProcess | None = None
        self._record_topics: list[str] = list(record[1]) if record is not None else []
        self._unacked: set[str] = set()
        """Topics already warned about: a subscriber did not acknowledge what the test published."""
        args = _server_args(world, seed, paused, rtf, replay, server_args)
        self.server = self._child("gazelle sim", gazelle_command(*args))
        try:
            m = self.server.wait_line(_READY, start_timeout)
            self.step_sec = float(m.group(1)) / 1000.0
            # The test's node and the recorder join once the server's participant exists: a participant
            # that announces itself before the other is there is found only at Fast DDS's next periodic
            # announcement, 3 s later (measured: the step service found 1.0-3.6 s after "ready" with the
            # node made first, 0.1-0.3 s with it made after)
            if record is not None:
                self._recorder = self.record(*record)
            self._ros = RosTestNode(domain_id)
            self._tell_recorder()
            self._kept = len(self.children)
            """The server and its recorder: what a reset keeps running."""
            from simulation_interfaces.srv import StepSimulation

            self._step_srv = StepSimulation
            self._step_client = self.ros.wait_for_service(
                "/gazelle/step_simulation", StepSimulation, timeout=start_timeout
            )
            if record is not None:
                self.wait_for_recorder(start_timeout)
        except BaseException:
            self.close()
            raise

    @property
    def ros(self) -> RosTestNode:
        """The test's own ROS node on this simulation's domain (subscribe, publish, call, wait).

        Raises:
            SimError: the simulation is closed (or never started).
        """
        if self._ros is None:
            raise SimFailed("this simulation is closed: its ROS node is gone")
        return self._ros

    @property
    def is_open(self) -> bool:
        """Whether the simulation's ROS node is there (False once :meth:`close` ran)."""
        return self._ros is not None

    # ------------------------------------------------------------------ processes
    def _child(
        self, name: str, argv: Sequence[str], cwd: Path | None = None, env: Mapping[str, str] | None = None
    ) -> ChildProcess:
        """Start a process in the simulation's environment (its domain and the test's token), kept so that close()
        stops it."""
        child = ChildProcess(name, argv, {**self.env, **(env or {})}, cwd)
        self.children.append(child)
        return child

    def spawn(
        self,
        file: str | os.PathLike[str],
        name: str,
        *,
        namespace: str = "",
        pose: Sequence[float] = (0.0, 0.0, 0.0),
        yaw: float = 0.0,
        args: Mapping[str, str] | None = None,
        params_file: str | os.PathLike[str] | Sequence[str | os.PathLike[str]] | None = None,
        timeout: float = 60.0,
    ) -> list[str]:
        """Spawn a robot from a file as ``gazelle spawn -file`` (and gazebo_ros's ``spawn_entity.py``) does, and
        return once the server has it, with what the server warned about it.

        Args:
            file: a URDF, xacro or SDF file; meshes and ros2_control ``<parameters>`` are resolved from the
                file's package (``package://``, ``$(find ...)``) or its folder, as a launch file's would be.
            name: the entity's name, unique in the world.
            namespace: the robot's ROS namespace (its topics, its controller manager), as ``-robot_namespace``.
            pose: (x, y, z) in metres, in the world frame.
            yaw: rotation about z in radians.
            args: xacro arguments (``{"use_gazebo": "true"}`` is ``--arg use_gazebo:=true``).
            params_file: a controllers' parameters file (or several) for the robot's controller manager, as
                ``gazelle spawn ... --ros-args --params-file FILE``.
            timeout: wall seconds for the spawn to be done.

        Returns:
            The server's warnings about this spawn (a plugin it does not know, with its "did you mean", a
            mesh it cannot find, a parameter nothing reads), one line each; each is also a
            :class:`GazelleWarning` (pytest lists them), and with ``strict`` a :class:`SimError`.

        Raises:
            SimError: the spawn was refused or failed (one line: the server's reason, file:line for a bad
                description; the world is as it was), or the server warned about it and ``strict`` is on.
        """
        x, y, z = (list(pose) + [0.0, 0.0, 0.0])[:3]
        argv = ["spawn", "-file", str(file), "-entity", name, "-x", f"{x}", "-y", f"{y}", "-z", f"{z}", "-Y", f"{yaw}"]
        if namespace:
            argv += ["-robot_namespace", namespace]
        for k, v in (args or {}).items():
            argv += ["--arg", f"{k}:={v}"]
        files = [params_file] if isinstance(params_file, (str, os.PathLike)) else list(params_file or ())
        if files:
            argv += ["--ros-args", *[a for f in files for a in ("--params-file", str(f))]]
        if _sent_as_it_is(Path(file)):
            self._sources[f"<spawn_entity:{name}>"] = str(file)
        start = len(self.server.lines_from(0))
        child = self._child(f"gazelle spawn {name}", gazelle_command(*argv))
        if child.wait(timeout) != 0:
            raise SimFailed(f"spawning {name} from {file} was refused: {spawn_failure(child)}")
        found = self._spawn_warnings(name, start) + client_warnings(child)
        self.warnings.extend(f"spawning {name} from {file}: {w}" for w in found)
        if found and self.strict:
            raise SimFailed(f"spawning {name} from {file}: the server warned (strict): " + " | ".join(found))
        for w in found:
            warnings.warn(GazelleWarning(f"spawning {name} from {file}: {w}"), stacklevel=2)
        return found

    def _spawn_warnings(self, name: str, start: int, timeout: float = 5.0) -> list[str]:
        """The server's warnings between output line ``start`` and its line saying it spawned ``name`` (it logs its
        warnings about an entity before that line; the line is waited for, the output being read on a thread)."""
        done = re.compile(rf"Successfully spawned entity \[{re.escape(name)}\]")
        deadline = time.monotonic() + timeout
        while True:
            lines = self.server.lines_from(start)
            end = next((i for i, line in enumerate(lines) if done.search(line)), None)
            if end is not None or time.monotonic() > deadline:
                return [self._named(w) for line in lines[:end] if (w := server_warning(line)) is not None]
            time.sleep(0.02)  # another process's output, read by its thread: nothing to wait on here

    def server_warnings(self) -> list[str]:
        """Every warning and error the server printed since it started (loading the world) or was last reset, one
        line each."""
        lines = self.server.lines_from(self._warnings_from)
        return [self._named(w) for line in lines if (w := server_warning(line)) is not None]

    def _named(self, warning: str) -> str:
        """A server's warning with the file's name where it names the XML of a spawn from a plain file
        (``<spawn_entity:bot>:23`` is the user's ``robot.urdf:23``: the file went as it is, lines and all)."""
        for label, file in self._sources.items():
            warning = warning.replace(label, file)
        return warning

    def launch(
        self, package_or_path: str | os.PathLike[str], file: str | None = None, **arguments: Any
    ) -> ChildProcess:
        """Run a launch file as ``ros2 launch`` does (``launch("my_pkg", "sim.launch.py", use_sim_time="true")``
        or ``launch(path)``); its processes belong to the test and end with it.

        Args:
            package_or_path: a package on the workspace's ``AMENT_PREFIX_PATH`` (a colcon build sourced
                before pytest), or a launch file's path.
            file: the launch file's name in the package (None with a path).
            arguments: launch arguments, ``name:=value`` each.

        Returns:
            The ``ros2 launch`` process (its output: ``.tail()``; it is in lockstep with every step, and the
            nodes it starts are, as their process group's members).
        """
        argv = [str(Path(sys.prefix) / "bin" / "ros2"), "launch", str(package_or_path)]
        if file is not None:
            argv.append(file)
        argv += [f"{k}:={v}" for k, v in arguments.items()]
        return self._child(f"ros2 launch {package_or_path} {file or ''}".strip(), argv)

    def run(
        self,
        argv: Sequence[str],
        name: str | None = None,
        cwd: Path | None = None,
        env: Mapping[str, str] | None = None,
    ) -> ChildProcess:
        """Start any other process on the simulation's domain (a node of the user's); it ends with the test.

        Args:
            argv: the command, e.g. ``[sys.executable, "my_node.py"]`` or ``["ros2", "run", "pkg", "node"]``;
                a node should run with ``use_sim_time:=true`` to follow the world the test steps.
            name: how the harness names it in its messages (None: the program's name).
            cwd: its working directory (None: the test's).
            env: added to (or overriding) the simulation's environment, for this process only.

        Returns:
            The process, in a process group of its own: stopped (SIGINT, then SIGKILL) at the test's end
            with all it started, and waited for after every chunk of stepped time (lockstep).
        """
        return self._child(name or Path(argv[0]).name, argv, cwd, env)

    # ------------------------------------------------------------------ time
    @property
    def time(self) -> float:
        """Sim time as the test has heard it on /clock."""
        return self.ros.sim_time

    def _check_server(self) -> None:
        if self.server.popen.poll() is not None:
            raise SimFailed(f"the simulation server exited with {self.server.popen.returncode}:\n{self.server.tail()}")

    def _step(self, steps: int, wall_timeout: float) -> None:
        """Step the server by ``steps`` through StepSimulation, waiting at most ``wall_timeout`` seconds of wall
        time; a server that died, hung or refused (it was not paused) is a SimError saying which.

        What the test published before is in every subscriber's reader first (acknowledged), and the server
        takes what its readers hold before it steps: a command sent before ``run_for`` acts from its first
        step (without this, the start command of a 5 s drive acted up to 0.93 s of sim time late)."""
        self._check_server()
        for topic in self.ros.wait_for_acks(min(ACK_TIMEOUT, wall_timeout)):
            if topic not in self._unacked:
                self._unacked.add(topic)
                warnings.warn(
                    f"gazelle: what the test published on {topic} was not acknowledged by all its subscribers "
                    f"within {ACK_TIMEOUT:g} s of wall time; the world steps on",
                    stacklevel=3,
                )
        req = self._step_srv.Request()
        req.steps = steps
        done = threading.Event()
        future = self._step_client.call_async(req)
        future.add_done_callback(lambda _f: done.set())
        if not done.wait(wall_timeout):
            self._check_server()
            raise SimFailed(f"the simulation did not take {steps} steps within {wall_timeout:g} s of wall time (hung?)")
        result = future.result().result
        if result.result != 1:  # simulation_interfaces/Result RESULT_OK
            raise SimFailed(f"StepSimulation({steps}) refused: {result.error_message}")

    def run_for(self, seconds: float, wall_timeout: float = 300.0, step: float = STEP_CHUNK_SEC) -> float:
        """Advance sim time by ``seconds`` (paused server: stepped as fast as possible; running server:
        waited for), then wait until the test has heard /clock get there. Returns the sim time.

        With processes the test started and lockstep on (``settle_timeout`` > 0), a paused world moves a
        ``step`` of sim time at a time (50 ms by default) and waits for those processes after each, as
        :meth:`run_until` does: one long step would let the world run ahead of a node for its whole length
        (a servo node's last commands then reached the arm after the test had read where it stopped).

        Args:
            seconds: sim seconds, rounded to whole physics steps (the world's ``<max_step_size>``).
            wall_timeout: wall seconds each step call may take before the server counts as hung.
            step: sim seconds per lockstep chunk; a node that times its own commands on sim time wants
                0.01, at the cost of more service calls.

        Returns:
            The sim time heard on /clock at the end (to its 10 ms tick).

        Raises:
            SimError: the server died, hung or refused to step (its output's end is in the message).
            ValueError: ``seconds`` or ``step`` is negative or not finite.
        """
        if seconds < 0 or not math.isfinite(seconds):
            raise ValueError(f"run_for takes a finite time >= 0, got {seconds!r}")
        if not (step > 0 and math.isfinite(step)):
            raise ValueError(f"run_for's step must be a finite time > 0, got {step!r}")
        target = self.ros.sim_time + seconds
        if not self.paused:
            return self._heard(target, wall_timeout)
        steps = round(seconds / self.step_sec)
        # without anything to wait for, one call (at most 100,000 steps) is the fastest way there
        chunk = max(1, round(step / self.step_sec)) if self._lockstep_nodes() else 100_000
        now = self.ros.sim_time
        while steps > 0:
            n = min(steps, chunk)
            self._step(n, wall_timeout)
            steps -= n
            now = self._heard(target - steps * self.step_sec, wall_timeout)
            self._settle()
        return now

    def _heard(self, target: float, wall_timeout: float) -> float:
        """Wait until the test has heard /clock reach ``target`` (to the 10 ms tick at or before it: gazelle
        sim publishes /clock every 10 ms of sim time, its --clock-rate); returns the sim time heard."""
        return self.ros.wait_for_sim_time(math.floor(target * 100 + 1e-6) / 100, timeout=wall_timeout)

    def _lockstep_nodes(self) -> list[int]:
        """The pids of the running processes the test started since the last reset (each leads a process group
        holding all it started), when lockstep is on; else none."""
        if self._settler.timeout <= 0:
            return []
        children = self.children[self._kept :]
        return [c.popen.pid for c in children if c.popen.poll() is None and c.popen.pid not in self._settler.ignored]

    def _settle(self) -> None:
        """Lockstep: wait until the nodes the test started have taken the time just stepped (their timers
        run, their replies sent), so that a node the machine delays does not fall behind the world."""
        busy = self._settler.wait(self._lockstep_nodes())
        if busy:
            names = ", ".join(sorted({f"{name} (pid {pid})" for pid, name in busy}))
            warnings.warn(
                f"gazelle: {names} stayed busy for {self._settler.timeout:g} s of wall time after a step; "
                "the world steps on without waiting for that process from now on",
                stacklevel=3,
            )

    def run_until(
        self,
        predicate: Callable[[], Any],
        timeout: float,
        what: str = "the condition",
        wall_timeout: float = 600.0,
        step: float = STEP_CHUNK_SEC,
    ) -> Any:
        """Step the world until ``predicate()`` is truthy, at most ``timeout`` seconds of **sim** time
        (checked every ``step`` seconds of sim time, 50 ms by default); returns the predicate's value, or
        fails the test naming ``what`` and the sim time waited.

        The world is paused between two chunks until the processes the test started are idle (see
        ``settle_timeout``): a node timing its commands on sim time acts within the chunk its time falls
        in however busy the machine is, so a smaller ``step`` (0.01) suits a test of open-loop timing (the
        seed's square), at the cost of more service calls.

        Args:
            predicate: called before each chunk, on the test's thread; it reads what the test's node heard
                (``log.last``, ``len(log)``), never blocking.
            timeout: sim seconds: the same bound on any machine, which is what makes the test's verdict
                repeatable.
            what: what is waited for, for the failure's message ("the robot at the goal").
            wall_timeout: wall seconds before the simulation counts as hung (a different failure).
            step: sim seconds per chunk.

        Returns:
            The predicate's first truthy value.

        Raises:
            TestTimeout: ``timeout`` sim seconds passed with the predicate false (an AssertionError: the
                test fails, naming ``what``).
            SimError: ``wall_timeout`` passed, or the server died.
        """
        if not (step > 0 and math.isfinite(step)):
            raise ValueError(f"run_until's step must be a finite time > 0, got {step!r}")
        start, deadline = self.ros.sim_time, time.monotonic() + wall_timeout
        while True:
            value = predicate()
            if value:
                return value
            if self.ros.sim_time - start >= timeout - 1e-9:
                raise TestTimeout(f"{what}: not within {timeout:g} s of sim time")
            if time.monotonic() > deadline:
                raise SimFailed(f"{what}: {wall_timeout:g} s of wall time passed (the simulation is hung?)")
            self.run_for(min(step, timeout - (self.ros.sim_time - start)), step=step)

    def reset(self, wall_timeout: float = 30.0) -> None:
        """Back to the start: sim time 0, the world's own models at their initial state, every entity the
        tests spawned removed (simulation_interfaces' ResetSimulation, SCOPE_ALL), and the processes
        started since the last reset stopped (the server and its recorder go on: a reset is much cheaper
        than a new server: the plugin's ``gazelle_shared_sim`` shares one per module this way).

        Raises:
            SimError: the server refused the reset (its reason is in the message).
            TestTimeout: it did not answer within ``wall_timeout`` seconds.
        """
        from simulation_interfaces.srv import ResetSimulation

        for child in self.children[self._kept :]:
            child.stop()
        del self.children[self._kept :]
        self._warnings_from = len(self.server.lines_from(0))
        self.warnings.clear()
        req = ResetSimulation.Request()
        req.scope = ResetSimulation.Request.SCOPE_ALL
        reply = self.ros.call("/gazelle/reset_simulation", ResetSimulation, req, timeout=wall_timeout)
        if reply.result.result != 1:
            raise SimFailed(f"ResetSimulation refused: {reply.result.error_message}")
        self.ros.restart_clock()

    # ------------------------------------------------------------------ recording
    def record(self, folder: str | os.PathLike[str], topics: Sequence[str]) -> ChildProcess:
        """Record ``topics`` (and /tf, /tf_static, /clock) into a rosbag2 MCAP folder until the test ends, with
        ``ros2 bag record`` (gazelle's, writing what rosbag2's MCAP storage writes: ``ros2 bag play``,
        Foxglove and the ``rosbags`` library read it).

        Returns:
            The recorder's process; :meth:`wait_for_recorder` waits until it hears the graph.
        """
        argv = [str(Path(sys.prefix) / "bin" / "ros2"), "bag", "record", "-o", str(folder), *recorded_names(topics)]
        return self._child("ros2 bag record", argv)

    def restart_recording(self, folder: str | os.PathLike[str], timeout: float = 30.0) -> Path | None:
        """Finish the bag the simulation's recorder has written so far (its folder is returned, complete),
        and record the same topics on into ``folder``; None when nothing was being recorded."""
        old = self._recorder
        if old is None:
            return None
        old.stop()
        done = Path(old.argv[old.argv.index("-o") + 1])
        new = self.record(folder, self._record_topics)
        self.children.remove(new)
        self.children[self.children.index(old)] = new  # kept across resets, as the one before
        self._recorder = new
        self._tell_recorder()
        self.wait_for_recorder(timeout)
        return done

    def _tell_recorder(self) -> None:
        """Let the test's node know the recorder's node and topics (its ``publisher`` waits for it)."""
        rec = self._recorder
        if self._ros is not None and rec is not None:
            # gazelle's `ros2 bag record` names its node _ros2bag_<pid> (cli_node), and the console script is
            # the process the harness started
            names = frozenset("/" + n.lstrip("/") for n in recorded_names(self._record_topics))
            self._ros.recorder = (f"_ros2bag_{rec.popen.pid}", names)

    def save_replay(self, timeout: float = 10.0) -> Path | None:
        """Have the server write its replay (the run since the last reset) now, and return the file; None
        when the server keeps no replay."""
        path = self.replay_path
        if path is None:
            return None
        self._check_server()

        def written() -> int:
            try:
                return path.stat().st_mtime_ns
            except FileNotFoundError:
                return 0

        before = written()
        self.server.popen.send_signal(signal.SIGUSR1)
        deadline = time.monotonic() + timeout
        while written() == before:
            if time.monotonic() > deadline:
                raise SimFailed(f"the server did not write its replay to {path} within {timeout:g} s")
            time.sleep(0.02)  # another process writes it: nothing to wait on but the file
        return path

    def wait_for_recorder(self, timeout: float = 30.0) -> None:
        """Wait until the recorder has subscribed (it hears /clock beside the test's node), so that the
        first step the test takes is in the bag."""
        node = self.ros.node
        try:
            self.ros.wait_until(lambda: node.count_subscribers("/clock") >= 2, timeout, "the bag recorder on /clock")
        except AssertionError as err:
            raise SimFailed(f"{err}:\n{self.children[-1].tail()}") from None

    def process_groups(self) -> frozenset[int]:
        """The process groups of every process the harness started (each child leads one: it and what it
        started are stopped together)."""
        return frozenset(c.popen.pid for c in self.children)

    def close(self) -> list[str]:
        """Stop every process (the newest first: a launch before the server it talks to) and the test's
        node. Returns the names of processes that had to be killed."""
        killed = []
        running = [c for c in reversed(self.children) if c.popen.poll() is None]
        for child in running:  # all asked at once, then waited for: the stops overlap
            with contextlib.suppress(ProcessLookupError):
                os.killpg(child.popen.pid, signal.SIGINT)
        for child in running:
            child.stop()
            if child.popen.returncode not in (0, -signal.SIGINT, 130, signal.SIGINT):
                killed.append(child.name)
        if self._ros is not None:
            self._ros.close()
            self._ros = None
        return killed

    def env_applied(self) -> contextlib.AbstractContextManager[None]:
        """os.environ with this simulation's domain while the block runs (for code under test that
        creates its own rclpy context from the environment)."""
        keys = ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE", "RMW_IMPLEMENTATION")
        return environ_applied({k: self.env[k] for k in keys})

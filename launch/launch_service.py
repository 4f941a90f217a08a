"""LaunchService: visits a launch description, runs its processes and timers, handles events and
Ctrl-C (SIGINT to every process, then SIGTERM, then SIGKILL: the whole tree is down within 5 s)."""

from __future__ import annotations

import os
import queue
import signal
import subprocess
import sys
import threading
import time
import traceback
from dataclasses import dataclass, field
from typing import Any

from .launch_context import LaunchContext
from .logging import log, output

SIGINT_GRACE_SEC = 3.0
"""After Ctrl-C: how long processes get to exit on SIGINT before SIGTERM."""
SIGTERM_GRACE_SEC = 1.5
"""Then how long after SIGTERM before SIGKILL."""
STARTUP_FATAL = "Fatal Python error: init_import_site"
"""What CPython prints (then a traceback of importlib frames) when a signal's KeyboardInterrupt comes while it
imports its site module: a Python child the launch stopped before it had started."""


@dataclass
class _Running:
    action: Any
    name: str
    cmd: list[str]
    cwd: str | None
    env: dict[str, str]
    popen: subprocess.Popen
    respawn: bool
    readers: list[threading.Thread] = field(default_factory=list)
    stopped_while_starting: bool = False


class LaunchService:
    """Runs launch descriptions (launch.LaunchService)."""

    def __init__(self, *, argv: list[str] | None = None, noninteractive: bool = False, debug: bool = False) -> None:
        self.context = LaunchContext(argv=argv, noninteractive=noninteractive)
        self.context.service = self
        self.debug = debug
        self._queue: queue.Queue = queue.Queue()
        self._handlers: list[Any] = []
        self._running: dict[int, _Running] = {}
        self._counts: dict[str, int] = {}
        self._counter = 0
        self._timers: list[threading.Timer] = []
        self._lock = threading.Lock()
        self._shutting_down = False
        self._returncode = 0
        self._descriptions: list[Any] = []

    # ------------------------------------------------------------------ API
    def include_launch_description(self, launch_description: Any) -> None:
        self._descriptions.append(launch_description)

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Run until nothing is left (or Ctrl-C); returns the exit status."""
        previous = (
            signal.signal(signal.SIGINT, self._on_sigint)
            if threading.current_thread() is threading.main_thread()
            else None
        )
        previous_term = (
            signal.signal(signal.SIGTERM, self._on_sigterm)
            if threading.current_thread() is threading.main_thread()
            else None
        )
        try:
            for ld in self._descriptions:
                self._queue.put(("visit", [ld]))
            while True:
                try:
                    kind, payload = self._queue.get(timeout=0.1)
                except queue.Empty:
                    if self._idle() and shutdown_when_idle:
                        break
                    continue
                if kind == "visit":
                    if not self._shutting_down or payload and getattr(payload[0], "_during_shutdown", False):
                        self._visit_all(payload)
                elif kind == "event":
                    self._dispatch(payload)
                elif kind == "shutdown":
                    self._shutdown(*payload)
                elif kind == "stop":
                    break
            return self._returncode
        finally:
            self._kill_all()
            for t in self._timers:
                t.cancel()
            if previous is not None:
                signal.signal(signal.SIGINT, previous)
            if previous_term is not None:
                signal.signal(signal.SIGTERM, previous_term)

    # ------------------------------------------------------------------ visiting
    def _visit_all(self, entities: list[Any]) -> None:
        for e in entities:
            if self._shutting_down and not getattr(e, "_during_shutdown", False):
                return
            try:
                subs = e.visit(self.context)
            except Exception as err:
                self._fail(e, err)
                return
            if subs:
                self._visit_all(list(subs))

    def _fail(self, entity: Any, err: BaseException) -> None:
        where = getattr(entity, "_created_at", "")
        user_tb = _user_traceback(err)
        log("ERROR", "launch", f"Caught exception in launch (see debug for traceback): {err}")
        if where:
            log("ERROR", "launch", f"  in {type(entity).__name__} made at {where}")
        if user_tb:
            sys.stderr.write(user_tb)
        if self.debug:
            traceback.print_exception(err)
        self._returncode = 1
        self._queue.put(("shutdown", ("an exception was raised", False)))

    # ------------------------------------------------------------------ events
    def register_event_handler(self, handler: Any) -> None:
        with self._lock:
            self._handlers.append(handler)

    def unregister_event_handler(self, handler: Any) -> None:
        with self._lock:
            if handler in self._handlers:
                self._handlers.remove(handler)

    def emit_event(self, event: Any) -> None:
        self._queue.put(("event", event))

    def _dispatch(self, event: Any) -> None:
        from .events import Shutdown

        with self._lock:
            handlers = list(self._handlers)
        for h in handlers:
            try:
                if not h.matches(event):
                    continue
                if h.handle_once:
                    self.unregister_event_handler(h)
                entities = h.handle(event, self.context)
            except Exception as err:
                self._fail(h, err)
                continue
            if entities:
                for ent in entities:
                    if isinstance(event, Shutdown):
                        try:
                            ent._during_shutdown = True
                        except AttributeError:
                            pass
                self._visit_all(list(entities))
        if isinstance(event, Shutdown) and not self._shutting_down:
            self._shutdown(event.reason, event.due_to_sigint)

    def schedule(self, period: float, actions: list[Any]) -> None:
        t = threading.Timer(period, lambda: self._queue.put(("visit", list(actions))))
        t.daemon = True
        with self._lock:
            self._timers.append(t)
        t.start()

    # ------------------------------------------------------------------ processes
    def start_process(
        self, action: Any, base: str, cmd: list[str], cwd: str | None, env: dict[str, str], respawn: bool
    ) -> None:
        from .events.process import ProcessStarted

        with self._lock:
            self._counter += 1
            name = f"{base}-{self._counter}"
        try:
            popen = subprocess.Popen(
                cmd,
                cwd=cwd,
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                start_new_session=True,  # its own process group: Ctrl-C here reaches it once, through us
            )
        except OSError as err:
            log(
                "ERROR",
                "launch",
                f"Caught exception when trying to start process '{name}': {err} (cmd: {' '.join(cmd)})",
            )
            self._returncode = 1
            self._exited(action, name, cmd, cwd, env, -1, 1)
            return
        action.final_name = name
        run = _Running(action, name, cmd, cwd, env, popen, respawn)
        with self._lock:
            self._running[popen.pid] = run
        log("INFO", name, f"process started with pid [{popen.pid}]")
        for stream in (popen.stdout, popen.stderr):
            t = threading.Thread(target=self._pump, args=(run, stream), daemon=True)
            t.start()
            run.readers.append(t)
        threading.Thread(target=self._wait, args=(run,), daemon=True).start()
        self.emit_event(ProcessStarted(action=action, name=name, cmd=cmd, cwd=cwd, env=env, pid=popen.pid))

    def _pump(self, run: _Running, stream: Any) -> None:
        for raw in iter(stream.readline, b""):
            line = raw.decode("utf-8", "replace").rstrip("\n")
            if run.stopped_while_starting:
                continue  # the rest of CPython's start-up traceback
            if self._shutting_down and line.startswith(STARTUP_FATAL):
                run.stopped_while_starting = True
                output(run.name, "interrupted while Python was starting (the launch was shutting down)")
                continue
            output(run.name, line)
        stream.close()

    def _wait(self, run: _Running) -> None:
        rc = run.popen.wait()
        for t in run.readers:
            t.join(2.0)
        with self._lock:
            self._running.pop(run.popen.pid, None)
        self._exited(run.action, run.name, run.cmd, run.cwd, run.env, run.popen.pid, rc, run)

    def _exited(
        self, action: Any, name: str, cmd: list[str], cwd: Any, env: Any, pid: int, rc: int, run: Any = None
    ) -> None:
        from .events.process import ProcessExited

        if rc == 0 or (run is not None and run.stopped_while_starting):
            log("INFO", name, f"process has finished cleanly [pid {pid}]")
        elif self._shutting_down and rc in (-signal.SIGINT, -signal.SIGTERM, -signal.SIGKILL, 130, 143):
            log(
                "INFO",
                name,
                f"process has finished cleanly [pid {pid}]"
                if rc in (-signal.SIGINT, 130)
                else f"process has died [pid {pid}, exit code {rc}]",
            )
        else:
            log("ERROR", name, f"process has died [pid {pid}, exit code {rc}, cmd '{' '.join(cmd)}'].")
        self.emit_event(ProcessExited(action=action, name=name, cmd=cmd, cwd=cwd, env=env, pid=pid, returncode=rc))
        on_exit = getattr(action, "on_exit", None)
        if on_exit is not None:
            ents = on_exit if isinstance(on_exit, (list, tuple)) else [on_exit]
            if callable(on_exit) and not hasattr(on_exit, "visit"):
                self._queue.put(("visit", [_Call(on_exit)]))
            else:
                self._queue.put(("visit", list(ents)))
        if run is not None and run.respawn and not self._shutting_down:
            delay = getattr(action, "respawn_delay", 0.0) or 0.0
            self.schedule(delay, [_Respawn(run)])

    def _idle(self) -> bool:
        with self._lock:
            timers_alive = any(t.is_alive() for t in self._timers)
            return not self._running and not timers_alive and self._queue.empty()

    # ------------------------------------------------------------------ shutdown
    def _on_sigint(self, signum: int, frame: Any) -> None:
        if self._shutting_down:
            log("WARNING", "launch", "user interrupted with ctrl-c (SIGINT) again, ignoring...")
            return
        log("WARNING", "launch", "user interrupted with ctrl-c (SIGINT)")
        self._queue.put(("shutdown", ("ctrl-c (SIGINT)", True)))

    def _on_sigterm(self, signum: int, frame: Any) -> None:
        log("WARNING", "launch", "user interrupted with SIGTERM")
        self._queue.put(("shutdown", ("SIGTERM", True)))

    def _shutdown(self, reason: str, due_to_sigint: bool) -> None:
        from .events import Shutdown

        if self._shutting_down:
            return
        if not due_to_sigint and reason not in ("ctrl-c (SIGINT)",):
            log("INFO", "launch", f"Shutting down: {reason}") if self.debug else None
        # OnShutdown handlers run first
        with self._lock:
            handlers = list(self._handlers)
        event = Shutdown(reason=reason, due_to_sigint=due_to_sigint)
        for h in handlers:
            try:
                if h.matches(event):
                    ents = h.handle(event, self.context)
                    if ents:
                        for ent in ents:
                            try:
                                ent._during_shutdown = True
                            except AttributeError:
                                pass
                        self._visit_all(list(ents))
            except Exception as err:
                self._fail(h, err)
        self._shutting_down = True
        self.context.is_shutdown = True
        for t in self._timers:
            t.cancel()
        threading.Thread(target=self._stop_processes, daemon=True).start()

    def _stop_processes(self) -> None:
        with self._lock:
            running = list(self._running.values())
        for r in running:
            _signal(r.popen, signal.SIGINT)
        deadline = time.monotonic() + SIGINT_GRACE_SEC
        while time.monotonic() < deadline and any(r.popen.poll() is None for r in running):
            time.sleep(0.05)
        for r in running:
            if r.popen.poll() is None:
                log(
                    "WARNING",
                    "launch",
                    f"process[{r.name}] failed to terminate after {SIGINT_GRACE_SEC:g} seconds, escalating to SIGTERM",
                )
                _signal(r.popen, signal.SIGTERM)
        deadline = time.monotonic() + SIGTERM_GRACE_SEC
        while time.monotonic() < deadline and any(r.popen.poll() is None for r in running):
            time.sleep(0.05)
        for r in running:
            if r.popen.poll() is None:
                log("WARNING", "launch", f"process[{r.name}] failed to terminate after SIGTERM, escalating to SIGKILL")
                _signal(r.popen, signal.SIGKILL)

    def _kill_all(self) -> None:
        with self._lock:
            running = list(self._running.values())
        for r in running:
            if r.popen.poll() is None:
                _signal(r.popen, signal.SIGKILL)
                try:
                    r.popen.wait(2.0)
                except subprocess.TimeoutExpired:
                    pass

    def shutdown(self) -> None:
        self._queue.put(("shutdown", ("LaunchService.shutdown()", False)))


def _signal(popen: subprocess.Popen, sig: int) -> None:
    """Signal the process's group (the process and what it started)."""
    try:
        os.killpg(popen.pid, sig)
    except (ProcessLookupError, PermissionError):
        try:
            popen.send_signal(sig)
        except ProcessLookupError:
            pass


class _Call:
    def __init__(self, fn: Any) -> None:
        self.fn = fn

    def visit(self, context: Any) -> Any:
        return self.fn(context)


class _Respawn:
    def __init__(self, run: _Running) -> None:
        self.run = run

    def visit(self, context: Any) -> None:
        r = self.run
        base = r.name.rsplit("-", 1)[0]
        context.service.start_process(r.action, base, r.cmd, r.cwd, r.env, r.respawn)


def _user_traceback(err: BaseException) -> str:
    """The traceback frames from outside launch, launch_ros, gazelle and gazelle's stand-ins for ROS packages'
    Python modules (nav2_common, ros2run...: their errors are one line, as launch's own are): the user's launch
    file."""
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ours = (here, os.path.join(root, "launch_ros"), os.path.join(root, "gazelle"))
    frames = [
        f
        for f in traceback.extract_tb(err.__traceback__)
        if not os.path.abspath(f.filename).startswith(ours) and not _gazelle_compat_module(f.filename)
    ]
    if not frames:
        return ""
    return "Traceback (user code):\n" + "".join(traceback.format_list(frames)) + f"{type(err).__name__}: {err}\n"


COMPAT_MARKER = ".gazelle-compat"
"""The file scripts/install_ros_packages.py leaves in each Python package it installs for gazelle."""


def _gazelle_compat_module(filename: str) -> bool:
    """Whether ``filename`` belongs to a Python package gazelle installed as a ROS package's stand-in: some
    folder above it holds the marker that scripts/install_ros_packages.py writes."""
    folder = os.path.dirname(os.path.abspath(filename))
    while True:
        if os.path.isfile(os.path.join(folder, COMPAT_MARKER)):
            return True
        parent = os.path.dirname(folder)
        if parent == folder or os.path.basename(folder) in ("site-packages", "dist-packages"):
            return False
        folder = parent

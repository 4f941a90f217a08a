"""Run untrusted-but-local work (xacro expansion of a user's own file) with a time and memory bound.

xacro evaluates Python expressions. For a file the user named on their own command line that
is their right, but a typo or a hostile file must not freeze the process: ``${9**9**9}`` is one
C-level big-integer operation that no signal interrupts, and it grows without limit. So the work
runs in a forked helper process with an address-space limit (``RLIMIT_AS``) and a time budget per
request; the parent kills the helper when it is spent. The budget counts the helper's own CPU time
(``/proc/<pid>/stat``), so a stalled or busy machine does not use it up: a 0.1 s expansion once
ran into a 5 s wall-clock limit on a loaded CI machine. A helper that blocks without computing is
stopped after :data:`WALL_FACTOR` times the budget of wall time (at least :data:`MIN_WALL_SEC`). The helper inherits
every imported module, and :class:`BoundedWorker` keeps it for the next request, so a bounded call
costs a pipe round trip, not an interpreter start.

Limits (generous for real robots: TurtleBot3, Husky and Panda expand in well under a second):

- ``GAZELLE_XACRO_TIMEOUT`` seconds of the helper's CPU time, default :data:`DEFAULT_TIMEOUT_SEC`;
- ``GAZELLE_XACRO_MEMORY_MB`` MiB of memory on top of what the process already maps, default
  :data:`DEFAULT_MEMORY_MB`.
"""

from __future__ import annotations

import gc
import json
import os
import resource
import select
import signal
import threading
import time
from collections.abc import Callable
from typing import TypeVar

from .._errors import SimError

T = TypeVar("T")

DEFAULT_TIMEOUT_SEC = 5.0
DEFAULT_MEMORY_MB = 2048
WALL_FACTOR = 6.0
"""A helper gets at most this many times its CPU budget of wall time (at least :data:`MIN_WALL_SEC`)."""
MIN_WALL_SEC = 30.0
_TICK = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def _cpu_seconds(pid: int) -> float | None:
    """User + system CPU time of process ``pid`` (None where /proc does not say)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / _TICK  # utime, stime (fields 14 and 15)
    except (OSError, IndexError, ValueError):
        return None


class _Budget:
    """One request's allowance: ``cpu_sec`` of the helper's CPU time and a wall-clock cap."""

    def __init__(self, pid: int, cpu_sec: float) -> None:
        """Start the allowance of one request to helper ``pid``: its CPU time now is the zero, and the wall-clock
        cap is :data:`WALL_FACTOR` times the CPU budget (at least :data:`MIN_WALL_SEC`); without /proc to read
        the helper's CPU time, the budget is wall time."""
        self.pid = pid
        self.cpu_sec = cpu_sec
        start = time.monotonic()
        self.cpu0 = _cpu_seconds(pid)
        # without /proc, the budget is wall time, as before
        self.wall_end = start + (max(MIN_WALL_SEC, WALL_FACTOR * cpu_sec) if self.cpu0 is not None else cpu_sec)

    def next_wait(self) -> float:
        """Seconds to wait for the reply before looking again; raises :class:`_Timeout` when spent."""
        now = time.monotonic()
        if now >= self.wall_end:
            raise _Timeout("wall")
        if self.cpu0 is None:
            return self.wall_end - now
        used = (_cpu_seconds(self.pid) or self.cpu0) - self.cpu0
        if used >= self.cpu_sec:
            raise _Timeout("cpu")
        return min(0.05, self.wall_end - now)


class BoundExceeded(SimError):
    """The bounded work ran out of time or memory, or its child process died."""

    def __init__(self, message: str, *, timed_out: bool = False) -> None:
        super().__init__(message)
        self.timed_out = timed_out
        """Whether the time limit stopped it (not memory, an error or a death)."""


def _env_float(name: str, default: float) -> float:
    """A positive number from the environment variable ``name``, else ``default`` (unset, not a number, or not
    positive: a limit of 0 would refuse every file)."""
    try:
        value = float(os.environ.get(name, default))
    except ValueError:
        return default
    return value if value > 0 else default


def limits() -> tuple[float, int]:
    """(timeout in seconds, extra memory in bytes) from the environment or the defaults."""
    timeout = _env_float("GAZELLE_XACRO_TIMEOUT", DEFAULT_TIMEOUT_SEC)
    memory = int(_env_float("GAZELLE_XACRO_MEMORY_MB", DEFAULT_MEMORY_MB) * 1024 * 1024)
    return timeout, memory


def _mapped_bytes() -> int:
    """The process's current virtual size (the child's limit is set above it)."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("VmSize:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0


def run_bounded(
    fn: Callable[[], T],
    *,
    what: str,
    timeout_sec: float | None = None,
    memory_bytes: int | None = None,
    timeout_hint: str = "GAZELLE_XACRO_TIMEOUT",
) -> T:
    """Run ``fn`` once in a forked child limited in wall time and memory; return its result.

    The result travels back as JSON (plain data only: no pickle, so nothing the child sends can
    run code in the parent). An exception ``fn`` raises becomes a :class:`BoundExceeded` naming it.

    Raises:
        BoundExceeded: the time or memory limit was hit, or the child died.
    """
    worker = BoundedWorker(lambda _request: fn(), memory_bytes=memory_bytes)
    try:
        return worker.call({}, what=what, timeout_sec=timeout_sec, timeout_hint=timeout_hint)  # type: ignore[return-value] - the worker returns what fn returned, typed Any across the process boundary
    finally:
        worker.close()


class BoundedWorker:
    """A forked helper process that serves requests one at a time, each bounded in wall time.

    :func:`run_bounded` forks for every call; that costs ~10 ms in a process that has MuJoCo and
    numpy mapped, which doubled the time to load a xacro file. A worker is forked once and reused:
    a request costs a pipe round trip. It runs under the same memory limit; a request that overruns
    its time gets the worker killed (the next request forks a fresh one), and a worker that dies is
    replaced. Requests and replies are JSON, as with :func:`run_bounded`.
    """

    def __init__(self, handler: Callable[[dict], object], *, memory_bytes: int | None = None) -> None:
        """A helper process that runs ``handler`` on each request's JSON body, started at the first request;
        ``memory_bytes`` above what the parent maps (None: ``GAZELLE_XACRO_MEMORY_MB``)."""
        self._handler = handler
        self._memory = memory_bytes
        self._lock = threading.Lock()
        self._pid = 0
        self._to_child = -1
        self._from_child = -1
        self._started_memory = -1

    def _start(self) -> None:
        """Fork the helper: it gets the request and reply pipes, dies with the parent, ignores Ctrl-C (the parent's
        to handle), and runs under an address-space limit of the parent's size plus the allowance. A fork copies
        every module already imported, so the helper is ready at once."""
        memory = limits()[1] if self._memory is None else self._memory
        req_r, req_w = os.pipe()
        rep_r, rep_w = os.pipe()
        cap = _mapped_bytes() + memory
        # Everything the parent has is frozen out of the child's garbage collector: the child is a
        # copy of a process with threads (rclpy's, DDS's), and collecting their objects in a copy
        # where those threads do not exist crashed it ("Segmentation fault ... Garbage-collecting").
        prctl = _prctl()  # looked up before the fork: the child of a process with threads only calls it
        gc.freeze()
        parent = os.getpid()
        pid = -1
        try:
            pid = os.fork()
        finally:
            if pid != 0:
                gc.unfreeze()
        if pid == 0:
            code = 0
            try:
                os.close(req_w)
                os.close(rep_r)
                signal.signal(signal.SIGTERM, signal.SIG_DFL)
                signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
                _die_with(parent, prctl)
                if cap > memory:
                    resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
                self._serve(req_r, rep_w)
            except BaseException:
                code = 1
            finally:
                os._exit(code)
        os.close(req_r)
        os.close(rep_w)
        self._pid, self._to_child, self._from_child = pid, req_w, rep_r

    def _serve(self, req_r: int, rep_w: int) -> None:
        """The helper's loop: read a request (its CPU budget and body), set the kernel's CPU limit for it, run the
        handler, and answer ``ok`` with the result, ``memory`` when it ran out, or ``error`` with the exception's
        type and text. It ends when the parent closes the pipe."""
        while True:
            request = _read_message(req_r, None)
            if request is None:
                return  # the parent is gone
            try:
                budget, body = json.loads(request)
                _limit_cpu(float(budget))
                payload = ("ok", self._handler(body))
            except MemoryError:
                payload = ("memory", None)
            except (Exception, SystemExit) as err:
                payload = ("error", f"{type(err).__name__}: {err}")
            try:
                data = json.dumps(payload).encode()
            except (TypeError, ValueError) as err:
                data = json.dumps(("error", f"{type(err).__name__}: {err}")).encode()
            _write_message(rep_w, data)

    def _stop(self) -> str:
        """Kill and reap the helper; returns how it ended (for messages).

        SIGKILL, not a polite signal: the helper may be deep in a runaway expansion (a xacro macro that
        recurses, a document that inflates) and is there only to be expendable. It is reaped at once so no
        zombie outlives the request, and how it ended (a signal of its own, such as the kernel's OOM kill, or
        an exit status) goes into the message the user sees."""
        how = "ended"
        if self._pid:
            for fd in (self._to_child, self._from_child):
                try:
                    os.close(fd)
                except OSError:
                    pass
            try:
                os.kill(self._pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            try:
                _, status = os.waitpid(self._pid, 0)
                if os.WIFSIGNALED(status) and os.WTERMSIG(status) != signal.SIGKILL:
                    how = f"was killed by signal {os.WTERMSIG(status)}"
                elif os.WIFEXITED(status):
                    how = f"exited with status {os.WEXITSTATUS(status)}"
            except ChildProcessError:
                pass
        self._pid = 0
        return how

    def _alive(self) -> bool:
        """Whether the helper is still running (a helper killed for its budget, or by the kernel, is replaced at the
        next request)."""
        if not self._pid:
            return False
        try:
            return os.waitpid(self._pid, os.WNOHANG)[0] == 0
        except ChildProcessError:  # reaped elsewhere
            return False

    def close(self) -> None:
        """Stop the helper process (a later call starts a new one)."""
        with self._lock:
            self._stop()

    def call(
        self, request: dict, *, what: str, timeout_sec: float | None = None, timeout_hint: str = "GAZELLE_XACRO_TIMEOUT"
    ) -> object:
        """Send ``request`` to the worker and return its reply.

        Raises:
            BoundExceeded: the time limit was hit (the worker is killed), memory ran out, or the worker died.
        """
        timeout = limits()[0] if timeout_sec is None else timeout_sec
        memory = limits()[1] if self._memory is None else self._memory
        with self._lock:
            reply = None
            for attempt in (1, 2):  # a helper that died (not one that overran) is replaced once
                if self._pid and not self._alive():
                    self._pid = 0  # it died between calls
                if self._pid and self._started_memory != memory:
                    self._stop()  # the limit changed (GAZELLE_XACRO_MEMORY_MB): a helper under the new one
                if not self._pid:
                    self._start()
                    self._started_memory = memory
                try:
                    _write_message(self._to_child, json.dumps([timeout, request]).encode())
                    reply = _read_message(self._from_child, _Budget(self._pid, timeout))
                except _Timeout as spent:
                    self._stop()
                    how = "of computing" if str(spent) == "cpu" else "and gave no result in time"
                    raise BoundExceeded(
                        f"{what} took longer than {timeout:g} s {how}; it was stopped ({timeout_hint})",
                        timed_out=True,
                    ) from None
                except OSError:
                    reply = None
                if reply is not None:
                    break
                how = self._stop()
                if attempt == 2:
                    raise BoundExceeded(
                        f"{what}: its helper process {how} without a result "
                        f"(memory limit {memory >> 20} MiB, GAZELLE_XACRO_MEMORY_MB)"
                    )
        if reply is None:  # (each attempt that gets none raises above)
            raise BoundExceeded(f"{what}: its helper process sent no result")
        try:
            kind, value = json.loads(reply)
        except ValueError:
            raise BoundExceeded(f"{what} sent back a malformed result") from None
        if kind == "ok":
            return value
        if kind == "memory":
            raise BoundExceeded(f"{what} needed more than {memory >> 20} MiB and was stopped (GAZELLE_XACRO_MEMORY_MB)")
        raise BoundExceeded(f"{what} failed: {value}")


class _Timeout(SimError):
    pass


PR_SET_PDEATHSIG = 1


def _prctl() -> Callable[..., int] | None:
    """libc's ``prctl``, or None where there is none."""
    try:
        import ctypes

        return ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None


def _die_with(parent: int, prctl: Callable[..., int] | None) -> None:
    """In a helper: be killed when the process that forked it ends (Linux's ``PR_SET_PDEATHSIG``), so a
    server killed while its helper computes leaves no orphan burning CPU. The signal follows the forking
    *thread*; a helper it kills early is replaced at the next request."""
    if prctl is not None:
        prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    if os.getppid() != parent:  # the parent ended before the request above took effect
        os._exit(1)


def _limit_cpu(budget_sec: float) -> None:
    """In a helper, before a request: the kernel kills it (``RLIMIT_CPU``) a little after the request's CPU
    budget, even when the parent is not there to do it."""
    used = resource.getrusage(resource.RUSAGE_SELF)
    spent = used.ru_utime + used.ru_stime
    soft = int(spent + 2 * budget_sec) + 2
    try:
        _, hard = resource.getrlimit(resource.RLIMIT_CPU)
        if hard != resource.RLIM_INFINITY:
            soft = min(soft, hard)
        resource.setrlimit(resource.RLIMIT_CPU, (soft, hard))
    except (ValueError, OSError):
        pass


def _write_message(fd: int, data: bytes) -> None:
    """Write a length-prefixed message (8 bytes little-endian, then the data), all of it."""
    view = memoryview(len(data).to_bytes(8, "little") + data)
    while view:
        n = os.write(fd, view)
        view = view[n:]


def _read_exact(fd: int, n: int, budget: _Budget | None) -> bytes | None:
    """Read exactly ``n`` bytes, waiting at most as the budget allows between chunks (:class:`_Timeout` once it
    is spent); None when the other end closed."""
    chunks: list[bytes] = []
    while n > 0:
        if budget is not None:
            ready, _, _ = select.select([fd], [], [], budget.next_wait())
            if not ready:
                continue
        chunk = os.read(fd, min(n, 1 << 20))
        if not chunk:
            return None
        chunks.append(chunk)
        n -= len(chunk)
    return b"".join(chunks)


def _read_message(fd: int, budget: _Budget | None) -> bytes | None:
    """One length-prefixed message, or None at end of file; raises :class:`_Timeout` when ``budget`` is spent."""
    head = _read_exact(fd, 8, budget)
    if head is None:
        return None
    return _read_exact(fd, int.from_bytes(head, "little"), budget)

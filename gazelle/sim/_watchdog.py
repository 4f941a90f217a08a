"""A watchdog process that ends a server a set time after SIGINT or SIGTERM, whatever holds its interpreter.

Used by ``gazelle sim`` and ``gazelle move_group``: both run C code (MuJoCo's compiler, coal's collision
checks, a regular expression's compile) that can hold the GIL for seconds, while a Python signal handler,
and a ``threading.Timer``, run only when the main thread gets it.
"""

from __future__ import annotations

import os
import signal
import time


def start_signal_watchdog(deadline_sec: float) -> int:
    """Fork a watchdog process that ends this one ``deadline_sec`` after a SIGINT or SIGTERM,
    whatever holds the interpreter; returns its pid.

    Python runs a signal handler only when the main thread gets the GIL: a regular-expression compile or
    a model build in C held it for seconds, and ``threading.Timer`` needs it too. But CPython's C-level
    handler writes the signal's number to the wakeup fd (:func:`signal.set_wakeup_fd`) at once, GIL or
    not. The watchdog reads that pipe; it leaves when the pipe closes (this process exited), and dies
    with this process (``PR_SET_PDEATHSIG``). Call it from the main thread, before other threads start,
    after installing the Python handlers for SIGINT and SIGTERM."""
    try:
        import ctypes

        prctl = ctypes.CDLL(None).prctl  # looked up before the fork: the child only calls it
    except (OSError, AttributeError):
        prctl = None
    read_fd, write_fd = os.pipe()
    os.set_blocking(write_fd, False)
    os.set_inheritable(write_fd, False)
    server = os.getpid()
    pid = os.fork()
    if pid == 0:  # the watchdog: only os calls, no threads, no imports
        try:
            os.close(write_fd)
            signal.signal(signal.SIGINT, signal.SIG_IGN)
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            if prctl is not None:
                prctl(1, signal.SIGKILL, 0, 0, 0)  # PR_SET_PDEATHSIG
            if os.getppid() != server:
                os._exit(0)
            while True:
                data = os.read(read_fd, 64)
                if not data:
                    break  # the server exited
                if any(b in (signal.SIGINT, signal.SIGTERM) for b in data):
                    time.sleep(deadline_sec)
                    os.write(
                        2,
                        f"gazelle: shutdown did not finish within {deadline_sec:g} s (a thread held the "
                        "interpreter); killing the server\n".encode(),
                    )
                    os.kill(server, signal.SIGKILL)
                    break
        finally:
            os._exit(0)
    os.close(read_fd)
    signal.set_wakeup_fd(write_fd, warn_on_full_buffer=False)
    return pid

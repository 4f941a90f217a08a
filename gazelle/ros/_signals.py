"""Ending a node on Ctrl-C (or SIGTERM) without racing rclpy's own signal thread.

rclpy (Jazzy, ``src/rclpy/signal_handler.cpp``) handles SIGINT and SIGTERM on a thread of its own: it
triggers the SIGINT guard condition of every executor, walking their global list without a lock, and then
shuts every context down. Python's KeyboardInterrupt can reach the main thread first (in 23 of 30 Ctrl-Cs of
a node with a busy timer, the context was still up when it did). Shutting an executor down then frees its
guard condition while the signal thread may still be about to trigger it: a segmentation fault, in 2 to 5 of
100 Ctrl-Cs of such a node and once in CI's move_group. Once the context is down, that thread has triggered
every guard condition; so after a signal, wait for that before shutting executors down or destroying nodes.
"""

from __future__ import annotations

import logging
import sys
import threading
import time
from typing import TYPE_CHECKING, Protocol

from rclpy._rclpy_pybind11 import RCLError
from rclpy.context import Context
from rclpy.exceptions import InvalidHandle
from rclpy.executors import ExternalShutdownException, ShutdownException
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions, get_current_signal_handlers_options

if TYPE_CHECKING:
    from rclpy.executors import Executor

SIGNAL_SHUTDOWN_WAIT_SEC = 2.0
"""How long to wait for rclpy's signal thread after a signal (it takes microseconds on an idle machine;
the processes' own watchdogs end them 3 s after the signal whatever happens)."""
TAKE_RACE_SEC = 0.5
"""How long a RuntimeError out of a spin may wait for the signal thread to finish shutting the context down
before it counts as a real error."""


def await_signal_shutdown(context: Context, timeout: float = SIGNAL_SHUTDOWN_WAIT_SEC) -> bool:
    """After a SIGINT or SIGTERM, wait until rclpy's signal thread has shut ``context`` down; True once it
    has (or when rclpy handles no signal in this process: ``rclpy.init`` installs its handlers only for the
    default context), False after ``timeout`` seconds. Call it only when a signal came: otherwise nothing
    shuts the context down and it waits the whole timeout."""
    if get_current_signal_handlers_options() == SignalHandlerOptions.NO:
        return True  # no signal thread to race with
    deadline = time.monotonic() + timeout
    while context.ok():
        if time.monotonic() >= deadline:
            return False
        time.sleep(0.001)
    return True


def silence_half_made_objects() -> None:
    """The process ends after a signal that came while rclpy objects were being made (rclpy refused them on
    the shut context): their ``__del__`` would print tracebacks as they go. Say nothing more."""
    sys.unraisablehook = lambda _unraisable: None


class Spinning(Protocol):
    """What :func:`spin_until_shutdown` asks of an executor: to spin until it is stopped."""

    def spin(self) -> None: ...


def spin_until_shutdown(executor: Spinning, node: Node) -> None:
    """Spin until Ctrl-C (or SIGTERM) shuts the node's context down, however the shutdown lands: as an
    interrupt, as rclpy's ExternalShutdownException, or as the RCLError "the given context is not valid"
    when it came while the executor was making its next wait set (seen under load). Any other rcl error,
    with the context still up, is a real one and is raised. On return the context is down, so the caller
    may shut the executor down and destroy the node."""
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        await_signal_shutdown(node.context)
    except RCLError:
        if node.context.ok():
            raise
    except RuntimeError:
        # a take from a subscription whose context the signal thread is shutting down: pybind11 cannot convert
        # the invalid handle ("Unable to convert call argument '0' to Python object"; an image_bridge with
        # use_sim_time, its /clock subscription, died on Ctrl-C with that traceback). With the context still up
        # a moment later, it is a real error
        deadline = time.monotonic() + TAKE_RACE_SEC
        while node.context.ok() and time.monotonic() < deadline:
            time.sleep(0.001)
        if node.context.ok():
            raise


def spin_until_stopped(executor: Executor, context: Context, stopping: threading.Event) -> BaseException | None:
    """Serve ``executor``'s callbacks on this thread until ``stopping`` is set or ``context`` shuts down;
    the loop of the server's executor threads. An entity destroyed while the executor built its wait set
    (InvalidHandle) only costs that wait. Anything else raised with the context up and ``stopping`` unset
    ends the loop and is returned, with its traceback logged, for the owner to report (the server then
    stops: never a half-deaf server); ``None`` after a normal stop."""
    invalid = 0
    while not stopping.is_set() and context.ok():
        try:
            executor.spin_once(timeout_sec=0.1)
        except InvalidHandle:
            invalid += 1  # the next wait set is built without the destroyed entity
            if invalid == 1:
                logging.getLogger("gazelle.ros").debug(
                    "an entity was destroyed while the executor waited on it; retrying"
                )
        except (ShutdownException, ExternalShutdownException):
            return None
        except BaseException as err:
            if stopping.is_set() or not context.ok():
                return None
            return err
    return None

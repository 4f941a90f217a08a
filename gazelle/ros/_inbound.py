"""The callback group of the subscriptions that feed the simulation (see :class:`InboundGroup`)."""

from __future__ import annotations

import logging
import os
import threading
import time

from rclpy.callback_groups import CallbackGroup
from rclpy.client import Client
from rclpy.exceptions import InvalidHandle
from rclpy.service import Service
from rclpy.subscription import Subscription
from rclpy.timer import Timer
from rclpy.waitable import Waitable

_log = logging.getLogger("gazelle.ros")

DRAIN_WAIT_SEC = 1.0
"""At most this long a drain waits for the callbacks the executor is running to end (each only hands a
message to the simulation, so they take microseconds; a stuck one is not waited for longer)."""
TAKE_CAP = 1000
"""At most this many messages taken per subscription in one drain, for one whose depth is unbounded
(KEEP_ALL): a publisher flooding a topic delays a step by at most that, never for ever."""


Entity = Subscription | Timer | Client | Service | Waitable
"""What rclpy's executor asks a callback group about (the entities a node's callbacks belong to)."""


class InboundGroup(CallbackGroup):
    """Reentrant, like rclpy's ReentrantCallbackGroup, with one more thing: :meth:`drain`, which the step
    services call before they step, so that every message that had reached the server's DDS readers when
    a step request came takes effect from that request's first step.

    Why: StepSimulation is served on an executor of its own (``_stepping``), the topics on the bridge's
    multi-threaded executor, and the two are not ordered: a command already in the server's reader when a
    step request came was taken whenever the bridge's executor came to it, possibly steps into the request
    (beside a CPU hog, 1 in 300 commands acknowledged before the request acted a 10 ms update late; with the
    executor 0.2 s slow to begin a callback, every one). Reliable delivery is the publisher's to wait for
    (``wait_for_all_acked``: gazelle.testing does); taking what was delivered before stepping is the
    server's, and this does it.

    How: while a drain runs, the executor may not begin a callback of the group (``can_execute`` and
    ``beginning_execution`` refuse; rclpy's executor tries again once it is over); the drain waits until the
    callbacks already begun (each takes its message and hands it on, between ``beginning_execution`` and
    ``ending_execution``) have ended, then takes what each subscription's reader holds, on the caller's
    thread, and runs the subscription's own callback on it."""

    def __init__(self) -> None:
        """A group with no callback running and no drain under way."""
        super().__init__()
        self._cond = threading.Condition()
        self._running = 0
        """Callbacks of the group the executor has begun and not yet ended."""
        self._draining = 0
        self._drain_lock = threading.Lock()
        """One drain at a time (StepSimulation's thread and a SimulateSteps goal may both drain)."""
        self._test_delay = float(os.environ.get("GAZELLE_TEST_INBOUND_DELAY_SEC", "0") or 0)
        """A test hook: the executor made slow on purpose (seconds before it begins each callback)."""

    def can_execute(self, entity: Entity) -> bool:
        """Whether the executor may run the entity's callback now: not while a drain takes the messages."""
        with self._cond:
            return not self._draining

    def beginning_execution(self, entity: Entity) -> bool:
        """The executor is about to take a message and run its callback: counted, unless a drain is under way."""
        if self._test_delay:
            time.sleep(self._test_delay)
        with self._cond:
            if self._draining:
                return False
            self._running += 1
            return True

    def ending_execution(self, entity: Entity) -> None:
        """The callback begun last by :meth:`beginning_execution` has ended (a drain may be waiting for it)."""
        with self._cond:
            self._running -= 1
            self._cond.notify_all()

    def drain(self) -> int:
        """Take every message the group's subscriptions hold now and run their callbacks on this thread,
        once the callbacks the executor had begun have ended; returns how many messages were taken."""
        with self._drain_lock:
            with self._cond:
                self._draining += 1
                if not self._cond.wait_for(lambda: self._running == 0, DRAIN_WAIT_SEC):
                    _log.warning(f"a subscription callback ran for over {DRAIN_WAIT_SEC:g} s; stepping without it")
            try:
                taken = 0
                for ref in list(self.entities):
                    entity = ref()
                    if entity is None:  # a deleted robot's subscription, collected: forgotten here too
                        self.entities.discard(ref)
                    elif isinstance(entity, Subscription):
                        taken += _take_all(entity)
                return taken
            finally:
                with self._cond:
                    self._draining -= 1
                    self._cond.notify_all()


def _take_all(sub: Subscription) -> int:
    """Take what ``sub``'s reader holds (at most its depth, or :data:`TAKE_CAP`) and run its callback on each;
    a subscription destroyed meanwhile (its entity deleted) holds nothing. A callback that raises is logged,
    as the executor would, and the next message is taken."""
    cap = sub.qos_profile.depth or TAKE_CAP
    for n in range(min(cap, TAKE_CAP)):
        try:
            with sub.handle:
                got = sub.handle.take_message(sub.msg_type, sub.raw)
        except InvalidHandle:
            return n
        if got is None:
            return n
        try:
            sub.callback(got[0])
        except Exception:
            _log.exception("a message taken before a step could not be handed to the simulation")
    return min(cap, TAKE_CAP)

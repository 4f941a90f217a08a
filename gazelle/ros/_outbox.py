"""Publishing off the simulation thread.

The simulation thread hands each payload to a :class:`Lane` (one per ROS publisher the bridge
feeds) and goes back to stepping; one publisher thread converts the payloads to ROS messages and
publishes them, in the order they were handed over. MuJoCo releases the GIL while it steps, so the
conversion runs beside the physics on a second core instead of between its steps.

Nothing is dropped by default: when the publisher thread falls behind (faster than real time, a slow
machine) and a lane holds ``depth`` payloads, the simulation thread waits for room (backpressure), as
Gazebo's simulation does, whose publishers run inside its step: every message the simulation produces
is handed to DDS, in order, and what a listener receives no longer depends on the machine's load.
Downstream, a reliable writer never overwrites what a reliable reader has not acknowledged: before its
history would overflow it waits (``_acked_writer``), this thread with it, and so the simulation goes at the
slowest reliable reader's pace. A KEEP_LAST reader that takes slower than it receives still keeps only its
newest ``depth`` (its own QoS); best-effort readers are never waited for; a reader that acknowledges nothing
for ``stall_timeout`` (a stopped process) is then not waited for.

``Outbox(lossless=False)`` (``gazelle sim --drop-when-behind``) is the opt-in trade: a full lane drops its
oldest payload, as a DDS writer with KEEP_LAST history does, the simulation never waits, and
:attr:`Outbox.dropped` counts what was lost. Lanes of state rather than messages (``keep_last=True``:
/tf_static, /model_states) always keep only their newest. A publish stuck for ``stall_timeout`` seconds
(a dead publisher) never freezes the simulation: that lane then drops, with one warning naming it.

Payloads are plain Python values (the bus's types), so building them on the sim thread and reading
them here needs no lock on the world. A :class:`~gazelle.systems.PayloadBlock` (the joint states of a
block of cycles run inside MuJoCo) is one item of its lane and counts as the messages it holds; its
messages are built here, off the simulation thread.
"""

from __future__ import annotations

import logging
import os
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Generic, TypeVar

from ..systems import PayloadBlock

_log = logging.getLogger("gazelle.ros")

P = TypeVar("P")
"""What a lane carries: the bus's payload of its topic (an Odometry, a TransformBatch, a PayloadBlock of them)."""


class Lane(Generic[P]):
    """One publisher's queue in an :class:`Outbox` (keep-last ``depth``) of ``P`` payloads."""

    __slots__ = ("_box", "_publish", "closed", "depth", "items", "keep_last", "name")

    def __init__(self, box: Outbox, publish: Callable[[P], None], depth: int, name: str, keep_last: bool = False):
        """One topic's queue in the outbox: ``depth`` payloads wait for the publisher thread; ``publish`` hands one
        to rclpy."""
        self._box = box
        self._publish = publish
        self.depth = max(1, depth)
        self.items: deque[P] = deque()
        self.name = name
        self.keep_last = keep_last
        """A lane of state (the newest is all that matters): never waits, keeps its newest ``depth``."""
        self.closed = False

    def put(self, payload: P) -> None:
        """Queue ``payload`` for publishing. When the lane is full: waits for room (a lossless outbox),
        or drops the lane's oldest (a lossy outbox, or a keep-last lane)."""
        self._box._put(self, payload)

    def close(self, timeout: float = 2.0) -> None:
        """Drop what this lane still holds and wait until the publisher thread is not publishing from
        it (then its publisher may be destroyed). Later puts are ignored."""
        self._box._discard(self, timeout)


class Outbox:
    """A publisher thread fed by :class:`Lane` objects (see the module docstring)."""

    def __init__(self, name: str = "gazelle-publish", *, lossless: bool = True, stall_timeout: float = 5.0):
        """The publisher thread between the simulation and rclpy (see the module docstring): lossless by default, a
        put waits up to ``stall_timeout`` seconds for room before it drops and says so."""
        self.lossless = lossless
        """Wait for room instead of dropping (the default; see the module docstring)."""
        self.stall_timeout = stall_timeout
        self.waited = 0
        """Puts that had to wait for the publisher thread (lossless): how often it set the pace."""
        self._stalled: set[str] = set()
        """Topics already warned about (once each)."""
        self._stuck = False
        """The publisher thread let a wait run out: puts drop instead of waiting until it publishes again."""
        self._cv = threading.Condition()
        self._order: deque[Lane] = deque()
        """One entry per queued payload, naming its lane: the publishing order across lanes."""
        self._current: Lane | None = None
        """The lane whose payload the publisher thread is publishing now."""
        self._closed = False
        self.dropped = 0
        """Payloads dropped because their lane was full (the publisher thread was behind)."""
        self.published = 0
        """Payloads published."""
        self._failed: set[str] = set()
        self._test_delay = float(os.environ.get("GAZELLE_TEST_PUBLISH_DELAY_SEC", "0") or 0)
        """A test hook: publishing made slow on purpose (seconds added to every publish)."""
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    def lane(self, publish: Callable[[P], None], depth: int, name: str = "", keep_last: bool = False) -> Lane[P]:
        """A new lane whose payloads go to ``publish`` (called on the publisher thread)."""
        return Lane(self, publish, depth, name, keep_last)

    def _put(self, lane: Lane[P], payload: P) -> None:
        """Queue a payload on its lane. When the lane is full: lossless, wait for the publisher thread to make room
        (never on that thread itself, and not for a state lane, whose newest value is all that matters); lossy,
        or after a wait that ran out, drop the oldest payload and count it."""
        with self._cv:
            if self._closed or lane.closed:
                return
            full = len(lane.items) >= lane.depth
            if (
                full
                and self.lossless
                and not lane.keep_last
                and not self._stuck
                and threading.current_thread() is not self._thread
            ):
                self.waited += 1
                room = self._cv.wait_for(
                    lambda: len(lane.items) < lane.depth or self._closed or lane.closed or not self.lossless,
                    self.stall_timeout,
                )
                if self._closed or lane.closed:
                    return
                full = len(lane.items) >= lane.depth  # still full: timed out, or stop_waiting() let it go
                self._stuck = not room
                if not room and lane.name not in self._stalled:
                    self._stalled.add(lane.name)
                    _log.warning(
                        f"publishing on {lane.name or 'a topic'} has been stuck for {self.stall_timeout:g} s: "
                        "dropping its oldest messages so the simulation goes on"
                    )
            if full:
                gone = lane.items.popleft()  # its entry in _order now stands for the next payload
                self.dropped += len(gone) if isinstance(gone, PayloadBlock) else 1
            else:
                self._order.append(lane)
            lane.items.append(payload)
            self._cv.notify_all()

    def _run(self) -> None:
        """The publisher thread: payloads are published one at a time in the order they were put, across lanes. A
        publish that fails (a publisher destroyed with its entity, a context shut down) is warned about once per
        topic and the thread goes on."""
        while True:
            with self._cv:
                self._current = None
                self._cv.notify_all()  # for flush() and Lane.close()
                while not self._order and not self._closed:
                    self._cv.wait()
                if not self._order:
                    return  # closed and drained
                lane = self._order.popleft()
                if not lane.items:
                    continue  # a closed lane's left-over entry
                payload = lane.items.popleft()
                self._current = lane
                self._cv.notify_all()  # a lane that was full has room: a waiting put goes on
            try:
                lane._publish(payload)
                if self._test_delay:
                    time.sleep(self._test_delay)
                self.published += len(payload) if isinstance(payload, PayloadBlock) else 1
                self._stuck = False  # it moves again: back to waiting for it
                if not self.lossless:
                    # lossy: hand the GIL to the simulation thread if it waits for it, so that publishing
                    # never slows the physics. Lossless, the simulation waits for this thread anyway, and
                    # the hand-over cost more than it gave: /odom + /tf heard, bench_rtf, 1,600 messages
                    # per wall second with it, 4,500 without (the thread waited for the GIL back after
                    # each message, 72 % of its samples)
                    time.sleep(0)
            except Exception as err:  # a publisher destroyed with its entity, a context shut down
                if lane.name not in self._failed:
                    self._failed.add(lane.name)
                    _log.warning(f"publishing on {lane.name or 'a topic'} failed: {type(err).__name__}: {err}")

    def stop_waiting(self) -> None:
        """From now on a full lane drops instead of holding the queuer: the server is shutting down, and
        the simulation thread must not wait on a publisher that is about to go (a ``gazelle sim`` was
        once killed by its 3 s shutdown deadline; the stop waited on the simulation thread)."""
        with self._cv:
            self.lossless = False
            self._cv.notify_all()

    def flush(self, timeout: float = 5.0) -> bool:
        """Wait until everything queued so far is published; False on timeout."""
        with self._cv:
            return self._cv.wait_for(lambda: not self._order and self._current is None, timeout)

    def _discard(self, lane: Lane, timeout: float) -> None:
        with self._cv:
            lane.closed = True
            lane.items.clear()
            self._cv.notify_all()  # a put waiting for room in this lane goes on (and queues nothing)
            if threading.current_thread() is not self._thread:
                self._cv.wait_for(lambda: self._current is not lane, timeout)

    def close(self, timeout: float = 2.0) -> None:
        """Publish what is queued, then stop the thread (later puts are ignored)."""
        with self._cv:
            self._closed = True
            self._cv.notify_all()
        self._thread.join(timeout)

"""Publishing off the simulation thread.

The simulation thread hands each payload to a :class:`Lane` (one per ROS publisher the bridge
feeds) and goes back to stepping; one publisher thread converts the payloads to ROS messages and
publishes them, in the order they were handed over. MuJoCo releases the GIL while it steps, so the
conversion runs beside the physics on a second core instead of between its steps.

A lane keeps the last ``depth`` payloads, as a DDS writer with KEEP_LAST history does: when the
publisher thread falls behind (faster than real time, a slow machine), the oldest payload of that
lane is dropped, and the simulation never waits and never piles up memory. Payloads are plain
Python values (the bus's types), so building them on the sim thread and reading them here needs
no lock on the world.
"""

from __future__ import annotations

import logging
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Any

_log = logging.getLogger("gazelle.ros")


class Lane:
    """One publisher's queue in an :class:`Outbox` (keep-last ``depth``)."""

    __slots__ = ("_box", "_publish", "closed", "depth", "items", "name")

    def __init__(self, box: Outbox, publish: Callable[[Any], None], depth: int, name: str):
        self._box = box
        self._publish = publish
        self.depth = max(1, depth)
        self.items: deque[Any] = deque()
        self.name = name
        self.closed = False

    def put(self, payload: Any) -> None:
        """Queue ``payload`` for publishing (never blocks; drops this lane's oldest when it is full)."""
        self._box._put(self, payload)

    def close(self, timeout: float = 2.0) -> None:
        """Drop what this lane still holds and wait until the publisher thread is not publishing from
        it (then its publisher may be destroyed). Later puts are ignored."""
        self._box._discard(self, timeout)


class Outbox:
    """A publisher thread fed by :class:`Lane` objects (see the module docstring)."""

    def __init__(self, name: str = "gazelle-publish"):
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
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    def lane(self, publish: Callable[[Any], None], depth: int, name: str = "") -> Lane:
        """A new lane whose payloads go to ``publish`` (called on the publisher thread)."""
        return Lane(self, publish, depth, name)

    def _put(self, lane: Lane, payload: Any) -> None:
        with self._cv:
            if self._closed or lane.closed:
                return
            if len(lane.items) >= lane.depth:
                lane.items.popleft()  # its entry in _order now stands for the next payload
                self.dropped += 1
            else:
                self._order.append(lane)
            lane.items.append(payload)
            self._cv.notify()

    def _run(self) -> None:
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
            try:
                lane._publish(payload)
                self.published += 1
                time.sleep(0)  # hand the GIL to the simulation thread if it waits for it (see the module docstring)
            except Exception as err:  # a publisher destroyed with its entity, a context shut down
                if lane.name not in self._failed:
                    self._failed.add(lane.name)
                    _log.warning(f"publishing on {lane.name or 'a topic'} failed: {type(err).__name__}: {err}")

    def flush(self, timeout: float = 5.0) -> bool:
        """Wait until everything queued so far is published; False on timeout."""
        with self._cv:
            return self._cv.wait_for(lambda: not self._order and self._current is None, timeout)

    def _discard(self, lane: Lane, timeout: float) -> None:
        with self._cv:
            lane.closed = True
            lane.items.clear()
            if threading.current_thread() is not self._thread:
                self._cv.wait_for(lambda: self._current is not lane, timeout)

    def close(self, timeout: float = 2.0) -> None:
        """Publish what is queued, then stop the thread (later puts are ignored)."""
        with self._cv:
            self._closed = True
            self._cv.notify_all()
        self._thread.join(timeout)

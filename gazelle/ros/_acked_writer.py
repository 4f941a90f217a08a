"""A reliable writer that never overwrites what a reliable reader has not acknowledged.

A DDS writer with KEEP_LAST history of depth N keeps its last N samples for its reliable readers to
acknowledge; the (N+1)-th write drops the oldest whether it was acknowledged or not, and a reader that had
not received it never will (Fast DDS's ``DataWriterHistory`` removes the oldest change of a full KEEP_LAST
history). gazelle's backpressure (``_outbox``) stopped at its own queue, so at ``--rtf 0`` a reliable
KEEP_ALL reader on /odom got 8,131 of 20,000 messages (measured: one writer of depth 10, Fast DDS's
default 3 s heartbeat).

:class:`AckedWriter` counts what it wrote since every reliable reader last acknowledged everything, and
before a write would overflow the writer's history (``window`` unconfirmed writes) it waits until they
have (rclpy's ``Publisher.wait_for_all_acked``, which releases the GIL: the simulation steps meanwhile until
the outbox's lane is full, then it waits too, so the simulation goes at the slowest reliable reader's
pace). Best-effort readers are never waited for: Fast DDS counts a write as acknowledged by them once it is
sent (measured: waits of 15 µs with a best-effort reader). What a reader acknowledges is what entered its
own history: a KEEP_LAST reader that takes slower than it receives still keeps only its newest ``depth``
(that is its QoS); a KEEP_ALL reader rejects what does not fit, does not acknowledge it, and gazelle waits.

The bridge gives its reliable volatile writers a DDS history of ``window`` (1000) samples, deeper than the
QoS depth a system declares: a wait costs one acknowledgement round trip (~10 ms: the reader answers a
heartbeat after Fast DDS's 5 ms heartbeatResponseDelay), paid once per ``window`` writes instead of every
``depth``. At depth 10 that was 776 writes a second; at 1000, 15,400 (20,000 writes, a plain reliable reader
in another process; 21,050 without waiting). Volatile writers never replay their history, so the deeper
history changes nothing a reader sees, and Fast DDS drops a change from it once every reader acknowledged
it. A reader that stops acknowledging (a stopped process) holds gazelle up to ``stall_timeout`` seconds
once; the writer then warns, overwrites as DDS does, and waits again only once that reader caught up.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from rclpy.duration import Duration

if TYPE_CHECKING:
    from rclpy.publisher import Publisher

_log = logging.getLogger("gazelle.ros")

ACK_WINDOW = 1000
"""The DDS history depth of the bridge's reliable volatile writers: writes between two waits for
acknowledgements (see the module docstring)."""

_SLICE = Duration(nanoseconds=100_000_000)
"""A wait is made of 0.1 s waits, so that a shutdown or a closed topic never waits for a reader."""
_NOW = Duration(nanoseconds=0)


class AckedWriter:
    """Publishes through one rclpy publisher; waits for its reliable readers' acknowledgements before its
    DDS history would overflow (see the module docstring)."""

    def __init__(
        self,
        publisher: Publisher,
        window: int,
        *,
        waiting: Callable[[], bool] = lambda: True,
        stall_timeout: float = 5.0,
        name: str = "",
    ):
        """``publisher`` is an rclpy publisher whose DDS history holds ``window`` samples (0: it never waits: a
        best-effort writer, or one of state); ``waiting()`` says whether to wait at all now (False with
        ``--drop-when-behind`` and while the server shuts down)."""
        self.publisher = publisher
        self.window = window
        self._waiting = waiting
        self.stall_timeout = stall_timeout
        self.name = name
        self.published = 0
        """Messages written (each message of a block counts)."""
        self.waits = 0
        """Times the writer waited for acknowledgements."""
        self.waited_sec = 0.0
        self.cancelled = False
        """Set when the topic goes: a wait in progress ends (the lane's close() waits for the publisher thread)."""
        self._unconfirmed = 0
        self._stalled = False
        self._warned = False

    def publish(self, msg: Any) -> None:
        """Write ``msg`` (a message or its serialized bytes); first wait for acknowledgements if ``window``
        writes are unconfirmed."""
        if self.window and self._unconfirmed >= self.window:
            self._confirm()
        self.publisher.publish(msg)
        self._unconfirmed += 1
        self.published += 1

    def _confirm(self) -> None:
        """Wait until every reliable reader acknowledged every write (up to ``stall_timeout``)."""
        self._unconfirmed = 0
        if not self._waiting() or self.cancelled:
            return
        if self._stalled:  # a reader stopped acknowledging: look, do not wait, until it has caught up
            self._stalled = not self.publisher.wait_for_all_acked(_NOW)
            return
        start = time.monotonic()
        acked = self.publisher.wait_for_all_acked(_SLICE)
        while not acked and not self.cancelled and self._waiting():
            if time.monotonic() - start >= self.stall_timeout:
                self._stalled = True
                if not self._warned:
                    self._warned = True
                    _log.warning(
                        f"a reliable reader of {self.name or 'a topic'} has not acknowledged for "
                        f"{self.stall_timeout:g} s: it may lose messages; the simulation goes on"
                    )
                break
            acked = self.publisher.wait_for_all_acked(_SLICE)
        self.waits += 1
        self.waited_sec += time.monotonic() - start

"""The bridge's publisher thread: the simulation thread queues, one thread publishes, keep-last per lane."""

from __future__ import annotations

import threading
from collections.abc import Callable

from gazelle.ros._outbox import Outbox


def test_everything_is_published_in_the_order_it_was_queued_across_lanes():
    box = Outbox()
    got: list[tuple[str, int]] = []
    odom = box.lane(lambda p: got.append(("odom", p)), 10, "/odom")
    tf = box.lane(lambda p: got.append(("tf", p)), 10, "/tf")
    for i in range(5):
        odom.put(i)
        tf.put(i)
    assert box.flush(5)
    assert got == [(name, i) for i in range(5) for name in ("odom", "tf")]
    assert (box.published, box.dropped) == (10, 0)
    box.close()


def _stuck_publisher() -> tuple[Outbox, threading.Event, threading.Event, list[int], Callable[[int], None]]:
    """An outbox and a publish function that blocks until ``release`` is set (``publishing`` says it started)."""
    box = Outbox()
    release, publishing = threading.Event(), threading.Event()
    got: list[int] = []

    def slow(p: int) -> None:
        publishing.set()
        release.wait(10)
        got.append(p)

    return box, release, publishing, got, slow


def test_a_publisher_thread_that_falls_behind_drops_the_oldest_of_a_lane_and_never_blocks_the_queuer():
    box, release, publishing, got, slow = _stuck_publisher()
    lane = box.lane(slow, 3, "/joint_states")
    lane.put(0)
    assert publishing.wait(5)  # 0 is being published; the publisher thread is stuck in it
    queuer = threading.Thread(target=lambda: [lane.put(i) for i in range(1, 1001)])
    queuer.start()
    queuer.join(5)
    assert not queuer.is_alive(), "queuing blocked while the publisher thread was busy"
    release.set()
    assert box.flush(5)
    assert got == [0, 998, 999, 1000]  # keep-last 3, as a DDS writer's KEEP_LAST history
    assert box.dropped == 997
    box.close()


def test_a_closed_lane_publishes_nothing_more_and_close_waits_for_its_publish_in_progress():
    box, release, publishing, got, slow = _stuck_publisher()
    lane = box.lane(slow, 10, "/odom")
    other = box.lane(lambda p: got.append(100 + p), 10, "/tf")
    lane.put(0)
    assert publishing.wait(5)
    lane.put(1)
    other.put(1)
    closed = threading.Event()
    closer = threading.Thread(target=lambda: (lane.close(), closed.set()))
    closer.start()
    assert not closed.wait(0.2)  # still publishing 0: its publisher must not be destroyed yet
    release.set()
    closer.join(5)
    assert closed.is_set()
    lane.put(2)
    assert box.flush(5)
    assert got == [0, 101]
    box.close()


def test_a_failing_publish_is_reported_once_per_topic_and_the_thread_goes_on(caplog):
    box = Outbox()
    got: list[int] = []

    def broken(_p: int) -> None:
        raise RuntimeError("publisher's context is invalid")

    bad = box.lane(broken, 10, "/gone")
    good = box.lane(got.append, 10, "/odom")
    for i in range(3):
        bad.put(i)
        good.put(i)
    assert box.flush(5)
    assert got == [0, 1, 2]
    assert sum("publishing on /gone failed" in r.getMessage() for r in caplog.records) == 1
    box.close()

"""The bridge's publisher thread: the simulation thread queues, one thread publishes, keep-last per lane."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from gazelle.ros._outbox import Lane, Outbox


def test_everything_is_published_in_the_order_it_was_queued_across_lanes():
    box = Outbox()
    got: list[tuple[str, int]] = []
    odom: Lane[int] = box.lane(lambda p: got.append(("odom", p)), 10, "/odom")
    tf: Lane[int] = box.lane(lambda p: got.append(("tf", p)), 10, "/tf")
    for i in range(5):
        odom.put(i)
        tf.put(i)
    assert box.flush(5)
    assert got == [(name, i) for i in range(5) for name in ("odom", "tf")]
    assert (box.published, box.dropped) == (10, 0)
    box.close()


def _stuck_publisher(
    lossless: bool = True,
) -> tuple[Outbox, threading.Event, threading.Event, list[int], Callable[[int], None]]:
    """An outbox and a publish function that blocks until ``release`` is set (``publishing`` says it started)."""
    box = Outbox(lossless=lossless)
    release, publishing = threading.Event(), threading.Event()
    got: list[int] = []

    def slow(p: int) -> None:
        publishing.set()
        release.wait(10)
        got.append(p)

    return box, release, publishing, got, slow


def test_a_lossy_outbox_behind_drops_the_oldest_of_a_lane_and_never_blocks_the_queuer():
    """`gazelle sim --drop-when-behind`: the opt-in trade of messages for speed."""
    box, release, publishing, got, slow = _stuck_publisher(lossless=False)
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
    other: Lane[int] = box.lane(lambda p: got.append(100 + p), 10, "/tf")
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


def test_by_default_a_publisher_thread_behind_makes_the_queuer_wait_and_nothing_is_dropped():
    """Issue 29: every payload the simulation produces is published, in order; when publishing is slow
    (1 ms a message here, on purpose) the queuer (the simulation thread) goes at the publisher's pace."""
    got: list[int] = []

    def slow(p: int) -> None:
        time.sleep(0.001)
        got.append(p)

    box = Outbox()
    lane = box.lane(slow, 5, "/odom")
    t0 = time.perf_counter()
    for i in range(300):
        lane.put(i)
    queued_in = time.perf_counter() - t0
    assert box.flush(10)
    assert got == list(range(300)) and box.dropped == 0
    assert queued_in >= 0.25, f"300 puts at 1 ms a publish took {queued_in:.3f} s: the queuer did not wait"
    assert box.waited > 0
    box.close()

    lossy = Outbox(lossless=False)
    got.clear()
    lane = lossy.lane(slow, 5, "/odom")
    t0 = time.perf_counter()
    for i in range(300):
        lane.put(i)
    assert time.perf_counter() - t0 < 0.1
    assert lossy.flush(10)
    assert lossy.dropped > 0 and len(got) == 300 - lossy.dropped and got == sorted(got)
    lossy.close()


def test_state_lanes_keep_their_newest_and_a_stuck_publish_never_freezes_the_queuer(caplog):
    """/tf_static and /model_states are state: their lanes keep the newest and never wait. A publish that
    never returns (a dead publisher) holds the queuer for the stall timeout once, then that lane drops,
    with one warning naming it."""
    box, release, publishing, got, slow = _stuck_publisher()
    box.stall_timeout = 0.3
    state = box.lane(slow, 1, "/model_states", keep_last=True)
    state.put(0)
    assert publishing.wait(5)
    t0 = time.perf_counter()
    for i in range(1, 50):
        state.put(i)
    assert time.perf_counter() - t0 < 0.1
    messages = box.lane(slow, 2, "/odom")
    t0 = time.perf_counter()
    for i in range(100, 110):
        messages.put(i)
    held = time.perf_counter() - t0
    assert 0.25 <= held < 0.6, held  # one stall timeout (0.3 s), then dropping; never frozen
    assert sum("/odom" in r.message and "stuck" in r.message for r in caplog.records) == 1
    release.set()
    assert box.flush(5)
    assert got[:2] == [0, 49] and got[2:] == [108, 109]
    box.close()


def test_stop_waiting_releases_a_queuer_held_by_a_stuck_publisher_at_once():
    """Shutting down: a put held by a full lane goes on at once (dropping) instead of after the stall
    timeout, so a server's stop never waits on its publisher thread."""
    box, release, publishing, got, slow = _stuck_publisher()
    lane = box.lane(slow, 1, "/odom")
    lane.put(0)
    assert publishing.wait(5)
    lane.put(1)  # fills the lane
    queuer = threading.Thread(target=lambda: lane.put(2))
    queuer.start()
    queuer.join(0.3)
    assert queuer.is_alive()  # held: lossless
    t0 = time.perf_counter()
    box.stop_waiting()
    queuer.join(2)
    assert not queuer.is_alive() and time.perf_counter() - t0 < 1.0
    release.set()
    assert box.flush(5)
    box.close()

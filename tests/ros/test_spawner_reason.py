"""A refused spawner step prints the manager's own reason, which reaches the spawner on /rosout: the manager logs it
before it answers, but beside load the line can come after the answer. The spawner waited 1 s for it and then said
only where to look (the r6bot test's ``not_in_yaml`` refusal, once beside other tests); it now waits on the line,
up to ``REASON_WAIT_SEC`` (rcl's rosout lifespan, 10 s), and ends the wait as soon as it comes."""

from __future__ import annotations

import time
from collections.abc import Callable

import pytest

pytest.importorskip("rclpy")

from rcl_interfaces.msg import Log

from gazelle.ros import _controller_spawner
from gazelle.ros._controller_spawner import _Client

REFUSAL = "load_controller: the 'type' of controller 'not_in_yaml' is not set"


class _Node:
    """The spawner's node as the client uses it: its /rosout subscription."""

    def __init__(self) -> None:
        self.on_log: Callable[[Log], None] | None = None

    def create_subscription(self, msg_type, topic, callback, qos):
        assert (msg_type, topic) == (Log, "/rosout")
        self.on_log = callback


class _Executor:
    """Spinning delivers the manager's line on /rosout ``late`` seconds after the first spin (None: never)."""

    def __init__(self, node: _Node, late: float | None) -> None:
        self.node, self.late, self.start = node, late, None

    def spin_once(self, timeout_sec: float) -> None:
        self.start = self.start or time.monotonic()
        time.sleep(timeout_sec)
        if self.late is not None and time.monotonic() - self.start >= self.late and self.node.on_log:
            self.node.on_log(Log(name="controller_manager", level=Log.ERROR, msg=REFUSAL))
            self.late = None


def _client(late: float | None) -> _Client:
    node = _Node()
    return _Client(node, _Executor(node, late), "/controller_manager", 5.0)  # type: ignore[arg-type]


def test_a_reason_that_comes_late_is_still_the_one_printed() -> None:
    t0 = time.monotonic()
    assert _client(late=2.0).reason("not_in_yaml") == REFUSAL
    assert time.monotonic() - t0 < 4.0  # the wait ended when the line came


def test_a_reason_that_never_comes_ends_the_wait_at_its_bound(monkeypatch) -> None:
    monkeypatch.setattr(_controller_spawner, "REASON_WAIT_SEC", 0.3)
    t0 = time.monotonic()
    assert _client(late=None).reason("not_in_yaml") == "the reason is in /controller_manager's log"
    assert 0.3 <= time.monotonic() - t0 < 2.0


def test_other_loggers_and_levels_are_not_a_reason() -> None:
    client = _client(late=None)
    node = client.node
    assert isinstance(node, _Node) and node.on_log is not None
    node.on_log(Log(name="some_node", level=Log.ERROR, msg=REFUSAL))
    node.on_log(Log(name="controller_manager", level=Log.WARN, msg=REFUSAL))
    assert client.errors == []

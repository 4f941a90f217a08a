"""The integration tests' own helpers (tests/_harness.py): a hung child is reported with its stacks, and the
test client closes without its spin thread raising."""

from __future__ import annotations

import sys
import threading
from typing import Any

import pytest
from _harness import RosClient, run_or_dump


def test_a_command_that_hangs_fails_the_test_with_where_it_hung() -> None:
    hang = (
        "import time\ndef waiting_for_ever():\n    time.sleep(600)\nprint('started', flush=True)\nwaiting_for_ever()\n"
    )
    with pytest.raises(pytest.fail.Exception) as failed:
        run_or_dump([sys.executable, "-X", "faulthandler", "-c", hang], timeout=3)
    said = str(failed.value)
    assert "did not end within 3 s" in said and "started" in said
    assert "waiting_for_ever" in said, said  # the Python stack faulthandler printed on SIGABRT


def test_the_test_client_closes_under_a_busy_spin_without_a_thread_error(monkeypatch: pytest.MonkeyPatch) -> None:
    """close() used to shut the executor down under its spinning thread, which then met a destroyed guard
    condition or a dropped callback generator (CI: an unhandled exception in ``_spin``)."""
    from std_msgs.msg import String

    errors: list[Any] = []
    monkeypatch.setattr(threading, "excepthook", errors.append)
    for _ in range(40):
        client = RosClient("harness_close_test")
        pub = client.node.create_publisher(String, "harness_chatter", 10)
        client.node.create_subscription(String, "harness_chatter", lambda _m: None, 10)
        client.node.create_timer(0.001, lambda pub=pub: pub.publish(String(data="x")))
        client.close()
        assert not client._thread.is_alive()
    assert not errors, [f"{e.exc_type.__name__}: {e.exc_value}" for e in errors]

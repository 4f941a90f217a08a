"""A reply the middleware drops for want of a discovered client reader is offered again."""

from __future__ import annotations

import threading
import time
import warnings

import pytest

from gazelle.ros import _replies


class _Service:
    """Sends the way rclpy does: a dropped reply is only a RuntimeWarning from ``send_response``."""

    def __init__(self, drops: int) -> None:
        self.drops, self.tries, self.delivered = drops, 0, []
        self.done = threading.Event()

    def send_response(self, response, header) -> None:
        self.tries += 1
        if self.tries <= self.drops:
            warnings.warn(
                "failed to send response (timeout): client will not receive response, at ./src/rmw_response.cpp:154",
                RuntimeWarning,
                stacklevel=1,
            )
            return
        self.delivered.append((response, header))
        self.done.set()


@pytest.fixture
def fresh_hook(monkeypatch):
    monkeypatch.setattr(_replies, "_hooked", False)
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        yield shown


def test_a_dropped_reply_is_sent_again_until_the_client_reader_is_there(fresh_hook) -> None:
    service = _replies.resend_lost_replies(_Service(drops=3), "/get_entity_state")
    service.send_response("reply", "header")  # what the executor calls
    assert service.done.wait(5), f"not delivered after {service.tries} tries"
    assert service.delivered == [("reply", "header")] and service.tries == 4
    # the drops were handled, not printed; other warnings still are
    warnings.warn("something else", RuntimeWarning, stacklevel=2)
    # (a ResourceWarning another test's garbage raises meanwhile is not this test's business)
    assert [str(w.message) for w in fresh_hook if issubclass(w.category, RuntimeWarning)] == ["something else"]


def test_a_reply_delivered_at_once_is_sent_once(fresh_hook) -> None:
    service = _replies.resend_lost_replies(_Service(drops=0), "/spawn_entity")
    service.send_response("reply", "header")
    assert service.delivered == [("reply", "header")] and service.tries == 1


def test_a_reply_that_never_finds_its_reader_is_given_up_with_one_warning(fresh_hook, monkeypatch, caplog) -> None:
    monkeypatch.setattr(_replies, "RESEND_SEC", 0.3)
    service = _replies.resend_lost_replies(_Service(drops=10**9), "/delete_entity")
    service.send_response("reply", "header")
    deadline = time.monotonic() + 5
    while "was not delivered" not in caplog.text and time.monotonic() < deadline:
        time.sleep(0.01)
    assert [r.getMessage() for r in caplog.records if "was not delivered" in r.getMessage()] == [
        "/delete_entity: a reply was not delivered in 0.3 s: the client's reader was never discovered"
    ]
    assert service.delivered == [] and service.tries > 1

"""The bounded helper process that runs xacro (and convex decompositions): bounded, and never a dead end."""

from __future__ import annotations

import os
import signal
import time

import pytest

from gazelle.description._bounded import BoundedWorker, BoundExceeded, run_bounded


def _handler(request: dict) -> object:
    kind = request["kind"]
    if kind == "echo":
        return request["value"]
    if kind == "pid":
        return os.getpid()
    if kind == "spin":
        while True:
            pass
    if kind == "sleep":  # blocked, not computing: a stalled machine looks like this to the budget
        time.sleep(request["sec"])
        return "slept"
    if kind == "exit":
        raise SystemExit(3)
    if kind == "die-once" and not os.path.exists(request["marker"]):
        open(request["marker"], "w").close()
        os._exit(9)  # the helper dies in the middle of a request
    return "survived"


def test_the_helper_is_reused_and_answers_in_order() -> None:
    worker = BoundedWorker(_handler)
    try:
        pids = {worker.call({"kind": "pid"}, what="t") for _ in range(5)}
        assert len(pids) == 1 and os.getpid() not in pids
        assert worker.call({"kind": "echo", "value": [1, "a"]}, what="t") == [1, "a"]
    finally:
        worker.close()


def test_an_overrun_is_stopped_and_the_next_request_gets_a_new_helper() -> None:
    worker = BoundedWorker(_handler)
    try:
        first = worker.call({"kind": "pid"}, what="t")
        t0 = time.monotonic()
        with pytest.raises(BoundExceeded, match="took longer than 0.5 s"):
            worker.call({"kind": "spin"}, what="spin", timeout_sec=0.5)
        assert time.monotonic() - t0 < 3.0
        assert worker.call({"kind": "pid"}, what="t") != first
    finally:
        worker.close()


def test_time_the_helper_spends_not_computing_does_not_use_up_its_budget(monkeypatch) -> None:
    """The budget is the helper's CPU time: a 0.1 s expansion once hit a 5 s wall-clock limit on a
    stalled CI machine. A helper that blocks for good is still stopped, by the wall-clock cap."""
    from gazelle.description import _bounded

    worker = BoundedWorker(_handler)
    try:
        assert worker.call({"kind": "sleep", "sec": 1.0}, what="nap", timeout_sec=0.3) == "slept"
        monkeypatch.setattr(_bounded, "MIN_WALL_SEC", 1.0)
        t0 = time.monotonic()
        with pytest.raises(BoundExceeded, match="took longer than 0.1 s"):
            worker.call({"kind": "sleep", "sec": 30.0}, what="hang", timeout_sec=0.1)
        assert time.monotonic() - t0 < 5.0
    finally:
        worker.close()


def test_a_helper_that_dies_is_replaced_and_the_request_retried(tmp_path) -> None:
    worker = BoundedWorker(_handler)
    try:
        pid = worker.call({"kind": "pid"}, what="t")
        assert isinstance(pid, int)
        os.kill(pid, signal.SIGKILL)  # killed between two requests
        assert worker.call({"kind": "echo", "value": 1}, what="t") == 1
        assert worker.call({"kind": "die-once", "marker": str(tmp_path / "m")}, what="t") == "survived"
    finally:
        worker.close()


def test_sys_exit_in_the_work_is_an_error_not_a_dead_helper() -> None:
    worker = BoundedWorker(_handler)
    try:
        pid = worker.call({"kind": "pid"}, what="t")
        with pytest.raises(BoundExceeded, match="SystemExit: 3"):
            worker.call({"kind": "exit"}, what="t")
        assert worker.call({"kind": "pid"}, what="t") == pid
    finally:
        worker.close()


def test_run_bounded_returns_plain_data_only() -> None:
    assert run_bounded(lambda: {"a": [1, 2.5]}, what="t") == {"a": [1, 2.5]}
    with pytest.raises(BoundExceeded, match="failed: ValueError: nope"):
        run_bounded(lambda: (_ for _ in ()).throw(ValueError("nope")), what="t")


class _Finalised:
    """Garbage (a reference cycle) that says which process finalises it."""

    def __init__(self, path: str) -> None:
        self.path, self.me = path, self

    def __del__(self) -> None:
        with open(self.path, "a") as f:
            f.write(f"{os.getpid()}\n")


def _collect(_request: dict) -> object:
    import gc

    return gc.collect()


def test_the_helper_never_collects_the_parents_objects(tmp_path) -> None:
    import gc

    log = tmp_path / "finalised"
    log.write_text("")
    gc.disable()  # keep the parent's garbage alive until the helper is forked
    try:
        _Finalised(str(log))
        worker = BoundedWorker(_collect)
        try:
            worker.call({}, what="t")  # the helper runs a full collection
        finally:
            worker.close()
    finally:
        gc.enable()
    gc.collect()
    # finalised once, by the parent; before, the helper finalised its copy too: objects of the
    # parent's threads (rclpy, DDS) then crashed the helper with a segmentation fault
    assert log.read_text().split() == [str(os.getpid())]

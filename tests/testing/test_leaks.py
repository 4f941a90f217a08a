"""gazelle's pytest plugin names a process the test left running, but not one of its own harness's
processes that it has just SIGKILLed and the kernel is still tearing down (a large server on a loaded
machine: seen as a false "left 1 process running" beside two CPU hogs)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
import uuid

from gazelle.testing.plugin import TOKEN_VAR, _leaked


def _carrier(token: str, seconds: float) -> subprocess.Popen:
    """A process with ``token`` in its environment, in a process group of its own, that ends by itself."""
    return subprocess.Popen(
        [sys.executable, "-c", f"import time; time.sleep({seconds})"],
        env={**os.environ, TOKEN_VAR: token},
        start_new_session=True,
    )


def test_a_harness_process_still_ending_is_waited_for_and_a_test_s_own_is_named() -> None:
    token = uuid.uuid4().hex
    ending = _carrier(token, 1.0)  # the harness's: its group is spared, it ends within the wait
    left = _carrier(token, 60.0)  # the test's own: named
    try:
        assert {pid for pid, _ in _leaked(token)} == {ending.pid, left.pid}
        start = time.monotonic()
        found = _leaked(token, frozenset({ending.pid}))
        assert [pid for pid, _ in found] == [left.pid]
        assert time.monotonic() - start < 20  # it waited for the spared one only as long as it took to end
    finally:
        for p in (ending, left):
            p.kill()
            p.wait()

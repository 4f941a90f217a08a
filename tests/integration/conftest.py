"""Fixtures of the integration tests: real `gazelle sim` processes, real DDS, a unique domain per run.

Every test here talks to a separate server process over ROS 2 (Fast DDS on
localhost) exactly like a user's node would. Waits are conditions with
timeouts, never bare sleeps.
"""

from __future__ import annotations

import signal
import subprocess
from collections.abc import Callable, Iterator

import pytest
from _harness import _STARTED, GAZELLE, Proc, RosClient, ros_env, start  # noqa: F401 - ros_env: the fixture

rclpy = pytest.importorskip("rclpy")


@pytest.fixture(autouse=True, scope="module")
def _no_leftover_processes() -> Iterator[None]:
    """Whatever a test module started and left running is stopped after it (Ctrl-C, then kill)."""
    yield
    while _STARTED:
        proc = _STARTED.pop()
        if proc.popen.poll() is None:
            proc.popen.send_signal(signal.SIGINT)
            try:
                proc.popen.wait(10)
            except subprocess.TimeoutExpired:
                proc.popen.kill()
                proc.popen.wait()


@pytest.fixture
def sim_factory() -> Iterator[Callable[..., Proc]]:
    """Start `gazelle sim` servers; each is stopped with Ctrl-C (SIGINT) at teardown and must exit 0."""
    procs: list[Proc] = []

    def make(*args: str) -> Proc:
        proc = start([*GAZELLE, "sim", *args], "gazelle sim")
        procs.append(proc)
        proc.wait_line("gazelle: ready", timeout=60)
        return proc

    yield make
    for p in procs:
        rc = p.interrupt()
        assert rc == 0, f"gazelle sim exited with {rc} on Ctrl-C:\n{p.output}"


@pytest.fixture
def ros_client() -> Iterator[RosClient]:
    client = RosClient()
    yield client
    client.close()

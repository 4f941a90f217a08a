"""Fixtures of the integration tests: real `gazelle sim` processes, real DDS, a unique domain per run.

Every test here talks to a separate server process over ROS 2 (Fast DDS on
localhost) exactly like a user's node would. Waits are conditions with
timeouts, never bare sleeps.
"""

from __future__ import annotations

import os
import signal
import subprocess
from collections.abc import Callable, Iterator

import pytest
from _ros_domain import reserved_domain_id

from ._harness import _STARTED, GAZELLE, Proc, RosClient, start

rclpy = pytest.importorskip("rclpy")


@pytest.fixture(scope="session", autouse=True)
def ros_env() -> Iterator[dict[str, str]]:
    """A unique ROS_DOMAIN_ID for this test run, discovery limited to localhost."""
    saved = {k: os.environ.get(k) for k in ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE", "RMW_IMPLEMENTATION")}
    os.environ["ROS_DOMAIN_ID"] = str(reserved_domain_id())
    os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    os.environ["RMW_IMPLEMENTATION"] = "rmw_fastrtps_cpp"
    yield dict(os.environ)
    for k, v in saved.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


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

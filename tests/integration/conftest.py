"""Fixtures of the integration tests: real `gazelle sim` processes, real DDS, a unique domain per run.

Every test here talks to a separate server process over ROS 2 (Fast DDS on
localhost) exactly like a user's node would. Waits are conditions with
timeouts, never bare sleeps.
"""

from __future__ import annotations

import signal
import subprocess
import sys
from collections.abc import Callable, Iterator

import pytest
from _harness import _STARTED, GAZELLE, REPO, Proc, RosClient, ros_env, start  # noqa: F401 - ros_env: the fixture

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


CPP_TIER_TIMEOUT = 900  # built cold: ~90 s alone on 2 cores, a few minutes beside the other worker's tests


@pytest.fixture(scope="session")
def cpp_tier() -> None:
    """The C++ tier (rclcpp and its companions, scripts/build_cpp.sh) installed in this venv, for the tests whose
    workspace finds rclcpp: from the cache (under a second), or built once per machine when no clone has built
    it yet. A workspace's first ``find_package(rclcpp)`` would install it as well (the stub set-up writes); done
    here first so that a cold build is not counted in a test's own colcon timeout, and a failed one is said once,
    with its log. A second xdist worker waits on the tier's lock, then finds it up to date."""
    done = subprocess.run(
        [str(REPO / "scripts" / "build_cpp.sh"), sys.prefix, "build"],
        capture_output=True,
        text=True,
        timeout=CPP_TIER_TIMEOUT,
    )
    assert done.returncode == 0, f"scripts/build_cpp.sh {sys.prefix} build failed:\n{done.stdout}{done.stderr}"


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

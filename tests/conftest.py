"""Fixtures and options for the whole suite: ``--phase`` (the serial and parallel runs of ./test.sh),
``resource_path``, ``make_sim``, and the per-file time summary (the ROS fixtures are in tests/integration/)."""

from __future__ import annotations

import json
import os
import socket
import tempfile
import time
from collections import defaultdict
from collections.abc import Iterator
from pathlib import Path

import pytest
from _paths import REAL
from _sim import new_simulation


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--phase",
        choices=("all", "serial", "parallel"),
        default="all",
        help="serial: only the tests marked serial (load and real-time tests, which ./test.sh runs alone "
        "first); parallel: all the others (which ./test.sh then runs on two workers); all: both",
    )


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    phase = config.getoption("--phase")
    if phase == "all":
        return
    keep: list[pytest.Item] = []
    deselected: list[pytest.Item] = []
    for item in items:
        serial = item.get_closest_marker("serial") is not None
        (keep if serial == (phase == "serial") else deselected).append(item)
    if deselected:
        config.hook.pytest_deselected(items=deselected)
        items[:] = keep


@pytest.fixture(autouse=True, scope="session")
def _ros2_daemons_of_this_run() -> Iterator[Path]:
    """The ``ros2`` verbs a test runs start gazelle's graph daemon, as ros2cli's do: this run's daemons live in
    a folder of its own (0700), end after 10 idle minutes at most, and are stopped when the run ends."""
    folder = Path(tempfile.mkdtemp(prefix="gazelle-ros2-daemons-"))
    os.environ["GAZELLE_ROS2_DAEMON_DIR"] = str(folder)
    os.environ["GAZELLE_ROS2_DAEMON_TIMEOUT"] = "600"
    yield folder
    for path in folder.glob("*.sock"):
        stop_ros2_daemon(path)


def stop_ros2_daemon(path: Path, wait: float = 10.0) -> None:
    """Ask the daemon on socket ``path`` to stop and wait for its socket to go (it removes it as it ends)."""
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as conn:
        conn.settimeout(5.0)
        try:
            conn.connect(str(path))
            conn.sendall(json.dumps({"op": "stop"}).encode() + b"\n")
            conn.recv(4096)
        except OSError:
            return
    deadline = time.monotonic() + wait
    while path.exists() and time.monotonic() < deadline:
        time.sleep(0.05)


@pytest.fixture
def resource_path(monkeypatch: pytest.MonkeyPatch):
    """``resource_path("turtlebot3", ...)``: set GAZELLE_RESOURCE_PATH (folders relative to the real
    fixtures, or absolute) for one test, clearing the other search-path variables."""
    for var in ("GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH", "GAZEBO_MODEL_PATH", "ROS_PACKAGE_PATH"):
        monkeypatch.delenv(var, raising=False)

    def set_path(*folders: str | Path) -> str:
        value = os.pathsep.join(str(REAL / f) for f in folders)
        monkeypatch.setenv("GAZELLE_RESOURCE_PATH", value)
        return value

    return set_path


@pytest.fixture
def make_sim():
    """``make_sim(world=None, **kwargs)``: a Simulation of ``world`` (the embedded default world when None)
    stepped by the test (``rtf=0`` unless given); see ``tests/_sim.py``. One the test started and left
    running (it failed before its ``stop()``) is stopped at teardown, so its thread does not outlive it."""
    made = []

    def make(world=None, **kwargs):
        sim = new_simulation(world, **kwargs)
        made.append(sim)
        return sim

    yield make
    for sim in made:
        if sim.running:
            sim.stop()


_FILE_SECONDS: defaultdict[str, float] = defaultdict(float)


_RERUNS: list[tuple[str, str]] = []
"""(test, the end of its failure) of each try that failed and was run again (``@pytest.mark.flaky``)."""


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    """Adds each phase's time (set-up, call, teardown) to its file's total (also from xdist's workers), and
    keeps the failure of a try that is run again: pytest-rerunfailures shows only that there was one."""
    _FILE_SECONDS[report.nodeid.split("::", 1)[0]] += report.duration
    if report.outcome == "rerun":
        _RERUNS.append((report.nodeid, "\n".join(report.longreprtext.splitlines()[-6:])))


def pytest_terminal_summary(terminalreporter, exitstatus: int, config: pytest.Config) -> None:
    """The failures of tries that were run again, and the files that took longest in all: where the suite's
    minutes go, in every CI log."""
    if _RERUNS:
        terminalreporter.write_sep("=", f"{len(_RERUNS)} failed tr(ies) run again")
        for nodeid, text in _RERUNS:
            terminalreporter.write_line(f"{nodeid}:\n{text}")
    if not _FILE_SECONDS:
        return
    total = sum(_FILE_SECONDS.values())
    terminalreporter.write_sep("=", f"slowest 15 test files ({total:.0f} s of test time in all)")
    for path, seconds in sorted(_FILE_SECONDS.items(), key=lambda kv: -kv[1])[:15]:
        terminalreporter.write_line(f"{seconds:8.1f}s {100 * seconds / total:5.1f}%  {path}")

"""Shared fixtures for the non-ROS tests."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from _paths import REAL

"""Real public robot/world descriptions (test inputs, read in place; never copied into the repo)."""


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

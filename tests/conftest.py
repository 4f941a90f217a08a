"""Shared fixtures for the non-ROS tests."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from _paths import REAL

"""Real public robot/world descriptions (test inputs, read in place; never copied into the repo)."""


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

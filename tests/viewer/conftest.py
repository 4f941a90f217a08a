"""Fixtures for the viewer tests: a real `gazelle sim` with its viewer on a free port, and a
headless Debian chromium (Playwright) looking at it (test_browser.py skips without chromium)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from _harness import (
    GAZELLE,
    Proc,
    RosClient,
    ros_env,  # noqa: F401 - the fixture, for this folder's tests
    start,
)
from _paths import ARTIFACTS


@pytest.fixture(scope="module")
def viewer_sim(ros_env: dict[str, str]) -> Iterator[tuple[Proc, str]]:
    """A `gazelle sim` server (real time) with its viewer on any free port; yields (process, url)."""
    proc = start([*GAZELLE, "sim", "--viewer-port", "0", "--rtf", "1"], "gazelle sim")
    try:
        line = proc.wait_line("gazelle: viewer at ", timeout=60)
        proc.wait_line("gazelle: ready", timeout=60)
        yield proc, line.split("viewer at ", 1)[1].strip()
    finally:
        rc = proc.interrupt()
        assert rc == 0, f"gazelle sim exited with {rc} on Ctrl-C:\n{proc.output}"


@pytest.fixture(scope="module")
def page(viewer_sim: tuple[Proc, str]) -> Iterator[Any]:
    from gazelle.viewer._browser import open_viewer_page

    with open_viewer_page(viewer_sim[1]) as p:
        yield p


@pytest.fixture(scope="module")
def ros_client_mod(ros_env: dict[str, str]) -> Iterator[RosClient]:
    client = RosClient("viewer_test_client")
    yield client
    client.close()


@pytest.fixture(scope="module")
def artifacts(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Screenshots go to the pytest tmp dir and are copied to out/viewer/ for CI."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    return tmp_path_factory.mktemp("viewer")

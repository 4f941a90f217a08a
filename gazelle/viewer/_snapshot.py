"""``gazelle snapshot``: a PNG of the viewer, headless (an in-process sim, or --attach to a running one)."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ._browser import BrowserUnavailable, screenshot

if TYPE_CHECKING:
    from ..description import World


def snapshot_world(world: "World", out: Path, *, settle_sec: float = 1.0) -> Path:
    """Simulate ``world`` in this process for a moment, serve it, and write a PNG of the viewer."""
    from ..physics import Simulation
    from ._viewer import Viewer

    sim = Simulation(world, rtf=1.0)
    sim.start()
    viewer = Viewer(sim, port=0)
    viewer.start()
    try:
        return screenshot(viewer.url, out, settle_sec=settle_sec)
    finally:
        viewer.stop()
        sim.stop()


def run_snapshot(world: "World | None", out: Path, *, attach: str | None, settle_sec: float) -> int:
    """CLI body: returns the exit code."""
    try:
        if attach is not None:
            path = screenshot(attach, out, settle_sec=settle_sec)
        else:
            assert world is not None
            path = snapshot_world(world, out, settle_sec=settle_sec)
    except BrowserUnavailable as err:
        print(f"gazelle snapshot: {err}", file=sys.stderr)
        return 2
    except Exception as err:  # noqa: BLE001 - a timeout or an unreachable URL: say which
        print(f"gazelle snapshot: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    print(f"gazelle: snapshot written to {path}")
    return 0

"""``gazelle snapshot``: a PNG of the viewer, headless (an in-process sim, or --attach to a running one)."""

from __future__ import annotations

import sys
import threading
import time
from pathlib import Path
from typing import TYPE_CHECKING, Callable

from ._browser import BrowserUnavailable, screenshot

if TYPE_CHECKING:
    from ..description import World
    from ..physics import Simulation


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


# --------------------------------------------------------------------------- videos
VIDEO_WIDTH = 640
"""Frames are scaled down to this width: GIFs of a full 1280 x 800 viewport get large."""


def record_gif(
    url: str,
    out: Path,
    *,
    seconds: float,
    fps: float = 4.0,
    width: int = VIDEO_WIDTH,
    stop: "threading.Event | None" = None,
    settle_sec: float = 1.0,
    on_start: "Callable[[], object] | None" = None,
) -> tuple[Path, int]:
    """Screenshots of the viewer at ``url`` at ``fps`` for ``seconds`` (or until ``stop`` is set), as an animated GIF.

    Headless chromium renders WebGL in software, so a frame costs ~0.1-0.3 s of CPU: keep ``fps`` modest.
    ``on_start`` is called once the page shows the scene, just before the first frame.
    Returns (``out``, frame count).
    """
    import io as _io

    from PIL import Image

    from ._browser import open_viewer_page

    if out.suffix.lower() != ".gif":
        raise ValueError(f"only GIF is written (no video encoder is installed): {out}")
    out.parent.mkdir(parents=True, exist_ok=True)
    frames: list[Image.Image] = []
    stamps: list[float] = []
    period = 1.0 / max(fps, 0.1)
    with open_viewer_page(url) as page:
        page.wait_for_timeout(int(settle_sec * 1000))
        if on_start is not None:
            on_start()
        t_end = time.monotonic() + seconds
        next_t = time.monotonic()
        while time.monotonic() < t_end and not (stop is not None and stop.is_set()):
            stamps.append(time.monotonic())
            img = Image.open(_io.BytesIO(page.screenshot())).convert("RGB")
            h = int(round(img.height * width / img.width))
            frames.append(img.resize((width, h), Image.BILINEAR).quantize(colors=128, method=Image.Quantize.MEDIANCUT))
            next_t += period
            delay = next_t - time.monotonic()
            if delay > 0:
                page.wait_for_timeout(int(delay * 1000))
            else:
                next_t = time.monotonic()
    if not frames:
        raise RuntimeError("no frame was captured")
    # each frame lasts as long as it really did: screenshots can fall behind ``fps`` on a busy machine
    stamps.append(time.monotonic())
    durations = [max(20, int(1000 * (b - a))) for a, b in zip(stamps, stamps[1:])]
    frames[0].save(out, save_all=True, append_images=frames[1:], duration=durations, loop=0, optimize=True)
    return out, len(frames)


def drive_first_robot(sim: "Simulation", linear: float, angular: float) -> str | None:
    """Send one Twist to the first entity with a cmd_vel subscription (as the viewer's Drive buttons do)."""
    from ..systems._bus import MsgType, Twist

    eps = sorted(
        (ep for ep in sim.bus.endpoints() if not ep.is_publisher and ep.msg_type == MsgType.TWIST and ep.callback),
        key=lambda ep: ep.owner,
    )
    if not eps:
        return None
    owner = eps[0].owner
    for ep in eps:
        if ep.owner == owner:
            ep.callback(Twist((linear, 0.0, 0.0), (0.0, 0.0, angular)))
    return owner


def run_record(
    world: "World | None",
    out: Path,
    *,
    attach: str | None,
    seconds: float,
    fps: float,
    drive: tuple[float, float] | None,
) -> int:
    """CLI body of ``gazelle record-video``: returns the exit code."""
    from ..physics import Simulation
    from ._viewer import Viewer

    sim = viewer = None
    try:
        url = attach
        on_start = None
        if url is None:
            assert world is not None
            sim = Simulation(world, rtf=1.0)
            sim.start()
            viewer = Viewer(sim, port=0)
            viewer.start()
            url = viewer.url
            if drive is not None:
                the_sim = sim

                def on_start() -> None:  # drive once the browser shows the scene, so the video sees it start
                    who = drive_first_robot(the_sim, *drive)
                    print(f"gazelle: driving {who}" if who else "gazelle: no diff-drive robot to drive", flush=True)

        path, n = record_gif(url, out, seconds=seconds, fps=fps, on_start=on_start)
    except BrowserUnavailable as err:
        print(f"gazelle record-video: {err}", file=sys.stderr)
        return 2
    except Exception as err:  # noqa: BLE001 - a timeout, an unreachable URL, a bad suffix: say which
        print(f"gazelle record-video: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    finally:
        if viewer is not None:
            viewer.stop()
        if sim is not None:
            sim.stop()
    print(f"gazelle: video written to {path} ({n} frames at {fps:g} fps)")
    return 0

"""A headless browser on the viewer: Debian's chromium driven by Playwright (snapshots, tests, bench).

Never a downloaded browser: we launch the system ``chromium`` with the flags that keep it
off the network and out of the GPU.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import SimError

if TYPE_CHECKING:
    from playwright.sync_api import ViewportSize

CHROMIUM_CANDIDATES = ("/usr/bin/chromium", "/usr/bin/chromium-browser")
CHROMIUM_ARGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)
VIEWPORT: ViewportSize = {"width": 1280, "height": 800}
# runs before the page's own scripts (Playwright init script), so the render loop picks it up
_RAF_CAP_JS = """(() => { const fps = %s; if (!(fps > 0)) return;
  const raf = window.requestAnimationFrame.bind(window);
  let queue = new Map(), nextId = 1, timer = null, last = 0;
  const tick = (t) => { timer = null; last = performance.now(); const q = queue; queue = new Map();
    for (const cb of q.values()) { try { cb(t); } catch (e) { console.error(e); } } };
  window.requestAnimationFrame = (cb) => { const id = nextId++; queue.set(id, cb);
    if (timer === null) { timer = setTimeout(() => raf(tick), Math.max(0, last + 1000 / fps - performance.now())); }
    return id; };
  window.cancelAnimationFrame = (id) => { queue.delete(id); }; })()"""


class BrowserUnavailable(SimError, RuntimeError):
    """No system chromium, or no playwright package."""


def find_chromium() -> str | None:
    """The system chromium's path ($GAZELLE_CHROMIUM overrides), or None."""
    env = os.environ.get("GAZELLE_CHROMIUM")
    if env:
        return env if Path(env).exists() else None
    for c in CHROMIUM_CANDIDATES:
        if Path(c).exists():
            return c
    return shutil.which("chromium")


@contextlib.contextmanager
def open_viewer_page(url: str, *, timeout_sec: float = 30.0, max_fps: float = 0.0, panel: bool = True) -> Iterator[Any]:
    """A Playwright page showing the viewer at ``url`` with its scene loaded (sync API).

    ``panel=False`` minimizes the control panel (for pictures of the scene: it covers its right quarter).

    ``max_fps`` caps the page's rendering (0: uncapped, as a user's browser renders). viser's client
    renders on demand, but each scene update opens a 250 ms window of continuous frames, so while
    poses stream it renders as fast as it can: in software WebGL a 1280x800 frame costs ~100-140 ms
    of CPU on two SwiftShader threads (~40 ms at 320x200: fill-bound), ~10 fps on one core. The cap
    (a requestAnimationFrame that batches callbacks into at most ``max_fps`` frames per second,
    installed before viser's scripts run) lowers chromium's CPU (5 fps: ~0.7 core) but slows scene
    loading, as viser drains its message queue once per frame.

    Raises:
        BrowserUnavailable: no chromium or playwright.
        TimeoutError: the viewer did not render within ``timeout_sec``.
    """
    exe = find_chromium()
    if exe is None:
        raise BrowserUnavailable("no system chromium (apt-get install chromium; scripts/setup.sh does it)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError as err:  # pragma: no cover - pinned in requirements.txt
        raise BrowserUnavailable("the playwright package is not installed") from err
    with tempfile.TemporaryDirectory(prefix="gazelle-chromium-") as profile, sync_playwright() as pw:
        ctx = pw.chromium.launch_persistent_context(
            profile,
            executable_path=exe,
            headless=True,
            args=list(CHROMIUM_ARGS),
            viewport=VIEWPORT,
        )
        try:
            page = ctx.pages[0] if ctx.pages else ctx.new_page()
            if max_fps > 0:
                page.add_init_script(_RAF_CAP_JS % float(max_fps))
            page.goto(url, timeout=timeout_sec * 1000)
            wait_rendered(page, timeout_sec)
            if not panel:
                minimize_panel(page, timeout_sec)
            yield page
        finally:
            ctx.close()


def wait_rendered(page: Any, timeout_sec: float) -> None:
    """Wait until the 3D canvas and the control panel exist and the scene had a moment to draw."""
    page.wait_for_selector("canvas", timeout=timeout_sec * 1000)
    page.get_by_text("Sim time").first.wait_for(timeout=timeout_sec * 1000)
    # hide toasts (e.g. "Software WebGL rendering detected"): they would cover the scene in snapshots
    page.add_style_tag(content=".mantine-Notifications-root, .mantine-Notification-root { display: none !important; }")
    # the first frames after connecting stream the scene: wait for two animation frames
    page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")


def minimize_panel(page: Any, timeout_sec: float = 30.0) -> None:
    """Minimize viser's control panel, and move the pointer off it (its tooltip would show)."""
    page.get_by_label("Minimize panel").click(timeout=timeout_sec * 1000)
    page.get_by_label("Expand panel").first.wait_for(timeout=timeout_sec * 1000)
    page.mouse.move(2, VIEWPORT["height"] - 2)


def screenshot(url: str, out: Path, *, settle_sec: float = 1.0, timeout_sec: float = 30.0, panel: bool = True) -> Path:
    """Write a PNG of the viewer at ``url`` (``panel=False``: with the control panel minimized); returns ``out``."""
    out.parent.mkdir(parents=True, exist_ok=True)
    with open_viewer_page(url, timeout_sec=timeout_sec, panel=panel) as page:
        deadline = time.monotonic() + settle_sec
        while time.monotonic() < deadline:  # let meshes stream in and poses settle
            page.wait_for_timeout(100)
        page.screenshot(path=str(out))
    return out

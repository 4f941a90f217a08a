"""Pixel helpers for the browser tests: where a world point lands in the viewer, and colour masks."""

from __future__ import annotations

import io
import math
from typing import Any

import numpy as np

from gazelle.viewer._overlays import PLAN_RGB, TRAIL_RGB
from gazelle.viewer._viewer import CAMERA_FOV_RAD, CAMERA_LOOK_AT, CAMERA_POSITION


def project(
    point: tuple[float, float, float], width: int, height: int, eye: Any = CAMERA_POSITION, target: Any = CAMERA_LOOK_AT
) -> tuple[float, float]:
    """Pixel (x right, y down) of a world point for the viewer's fixed initial camera (z up)."""
    eye, target = np.asarray(eye, dtype=float), np.asarray(target, dtype=float)
    fwd = target - eye
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    d = np.asarray(point) - eye
    x, y, z = d @ right, d @ up, d @ fwd
    f = (height / 2) / math.tan(CAMERA_FOV_RAD / 2)
    return width / 2 + f * x / z, height / 2 - f * y / z


def rgb_of(png: bytes) -> np.ndarray:
    """H x W x 3 int array of a PNG."""
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def blue_mask(image: bytes | np.ndarray) -> np.ndarray:
    """Strongly blue pixels (the seed robot's box) of a PNG or an RGB array."""
    rgb = rgb_of(image) if isinstance(image, bytes) else image.astype(int)
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    return (b > 100) & (b > r + 60) & (b > g + 60)


def trail_mask(image: bytes | np.ndarray, tol: int = 40) -> np.ndarray:
    """Pixels of the path trail's magenta (``TRAIL_RGB``, lit evenly: it is a screen-space line)."""
    rgb = rgb_of(image) if isinstance(image, bytes) else image.astype(int)
    return np.abs(rgb - np.asarray(TRAIL_RGB)).max(axis=-1) <= tol


def plan_mask(image: bytes | np.ndarray, tol: int = 40) -> np.ndarray:
    """Pixels of the planned path's blue (``PLAN_RGB``, a screen-space line like the trail)."""
    rgb = rgb_of(image) if isinstance(image, bytes) else image.astype(int)
    return np.abs(rgb - np.asarray(PLAN_RGB)).max(axis=-1) <= tol


def hex_rgb(color: str) -> np.ndarray:
    """``#rrggbb`` as an RGB array."""
    return np.array([int(color[i : i + 2], 16) for i in (1, 3, 5)])


def share_near(png: bytes, at: Any, rgb: np.ndarray, half: int = 4, tol: int = 60) -> float:
    """The share of the pixels within ``half`` of ``at`` (x, y) that have colour ``rgb``."""
    image = rgb_of(png).astype(int)
    x, y = int(round(at[0])), int(round(at[1]))
    patch = image[max(y - half, 0) : y + half + 1, max(x - half, 0) : x + half + 1]
    return float((np.abs(patch - rgb).sum(axis=2) < tol).mean()) if patch.size else 0.0


class ReplayPage:
    """A replay page (gazelle.viewer.replay_html) opened from disk in headless chromium."""

    def __init__(self, page: Any) -> None:
        self.page = page

    def frames(self) -> int:
        return int(self.page.evaluate("() => window.gazelleReplay.frames"))

    def seek(self, i: int) -> None:
        self.page.evaluate(f"() => window.gazelleReplay.seek({int(i)})")

    def to_screen(self, x: float, y: float) -> tuple[float, float]:
        sx, sy = self.page.evaluate(f"() => window.gazelleReplay.toScreen({float(x)}, {float(y)})")
        return float(sx), float(sy)

    def color_of(self, entity: str) -> np.ndarray:
        return hex_rgb(self.page.evaluate(f"() => window.gazelleReplay.colorOf({entity!r})"))

    def canvas(self) -> bytes:
        return self.page.locator("#view").screenshot()


def open_replay(path: Any, timeout_ms: float = 30_000) -> Any:
    """A context manager: a :class:`ReplayPage` of the HTML file at ``path`` (file://, no server), once its
    script has run (failing after ``timeout_ms`` when it never does)."""
    import contextlib

    from playwright.sync_api import sync_playwright

    from gazelle.viewer._browser import CHROMIUM_ARGS, VIEWPORT, find_chromium

    @contextlib.contextmanager
    def opened() -> Any:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path=find_chromium(), headless=True, args=list(CHROMIUM_ARGS))
            try:
                page = browser.new_page(viewport=VIEWPORT)
                page.goto(path.as_uri())
                page.wait_for_function("() => window.gazelleReplay !== undefined", timeout=timeout_ms)
                yield ReplayPage(page)
            finally:
                browser.close()

    return opened()

"""Where the camera goes to show every entity ("Fit all" in the viewer's panel): plain geometry, no viser."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np

MARGIN_M = 0.5
"""Added to the points' radius: a link's origin is not its extent."""
MIN_RADIUS_M = 0.5
"""The smallest view: one small robot still fills a sensible part of the picture."""


def fit_view(
    points: Iterable[Sequence[float]], eye: Sequence[float], target: Sequence[float], fov_rad: float
) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """(camera position, look-at point) that shows a sphere around every point, seen from the direction of
    ``eye`` from ``target`` (the initial camera's), with a vertical field of view of ``fov_rad``. No points:
    the initial camera."""
    pts = np.asarray([p[:3] for p in points], dtype=float).reshape(-1, 3)
    pts = pts[np.isfinite(pts).all(axis=1)]
    if not len(pts):
        return (float(eye[0]), float(eye[1]), float(eye[2])), (float(target[0]), float(target[1]), float(target[2]))
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    center = (lo + hi) / 2.0
    radius = max(float(np.linalg.norm(hi - lo)) / 2.0, MIN_RADIUS_M) + MARGIN_M
    direction = np.asarray(eye, dtype=float) - np.asarray(target, dtype=float)
    direction /= np.linalg.norm(direction)
    position = center + direction * (radius / math.sin(fov_rad / 2.0))
    return (
        (float(position[0]), float(position[1]), float(position[2])),
        (float(center[0]), float(center[1]), float(center[2])),
    )

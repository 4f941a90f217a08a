"""The browser viewer (viser): a live 3D view and controls for a running simulation.

This layer may import physics, description and systems; it never imports rclpy,
and the core never imports it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_attributes

# Imported when first used: viser and the renderer cost ~0.3 s, which ``gazelle sim --no-viewer`` (checking
# its --viewer-allow-origin values) and a replay page never need.
if TYPE_CHECKING:
    from ._browser import open_viewer_page, screenshot
    from ._origin import OriginPolicy, allowed_origins
    from ._replay import replay_html
    from ._snapshot import record_video, run_record, run_snapshot, video_format
    from ._viewer import DEFAULT_HOST, DEFAULT_PORT, POSE_RATE_HZ, Viewer

__getattr__ = lazy_attributes(__name__, __file__)


__all__ = [
    "DEFAULT_HOST",
    "DEFAULT_PORT",
    "OriginPolicy",
    "POSE_RATE_HZ",
    "Viewer",
    "allowed_origins",
    "open_viewer_page",
    "record_video",
    "replay_html",
    "run_record",
    "run_snapshot",
    "screenshot",
    "video_format",
]

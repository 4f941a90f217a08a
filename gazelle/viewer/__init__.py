"""The browser viewer (viser): a live 3D view and controls for a running simulation.

This layer may import physics, description and systems; it never imports rclpy,
and the core never imports it.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ._browser import open_viewer_page, screenshot
    from ._origin import OriginPolicy, allowed_origins
    from ._replay import replay_html
    from ._snapshot import record_video, run_record, run_snapshot, video_format
    from ._viewer import DEFAULT_HOST, DEFAULT_PORT, POSE_RATE_HZ, Viewer

_LAZY = {
    "open_viewer_page": "._browser",
    "screenshot": "._browser",
    "OriginPolicy": "._origin",
    "allowed_origins": "._origin",
    "replay_html": "._replay",
    "record_video": "._snapshot",
    "run_record": "._snapshot",
    "run_snapshot": "._snapshot",
    "video_format": "._snapshot",
    "DEFAULT_HOST": "._viewer",
    "DEFAULT_PORT": "._viewer",
    "POSE_RATE_HZ": "._viewer",
    "Viewer": "._viewer",
}
"""Imported when first used: viser and the renderer cost ~0.3 s, which ``gazelle sim --no-viewer`` (checking
its --viewer-allow-origin values) and a replay page never need."""


def __getattr__(name: str) -> Any:
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name], __name__), name)
    globals()[name] = value
    return value


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

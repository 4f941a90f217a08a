"""The browser viewer (viser): a live 3D view and controls for a running simulation.

This layer may import physics, description and systems; it never imports rclpy,
and the core never imports it.
"""

from ._browser import screenshot
from ._origin import OriginPolicy, allowed_origins
from ._snapshot import record_video, run_record, run_snapshot, video_format
from ._viewer import DEFAULT_HOST, DEFAULT_PORT, Viewer

__all__ = [
    "DEFAULT_HOST",
    "DEFAULT_PORT",
    "OriginPolicy",
    "Viewer",
    "allowed_origins",
    "record_video",
    "run_record",
    "run_snapshot",
    "screenshot",
    "video_format",
]

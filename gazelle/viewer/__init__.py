"""The browser viewer (viser): a live 3D view and controls for a running simulation.

This layer may import physics, description and systems; it never imports rclpy,
and the core never imports it.
"""

from ._viewer import DEFAULT_HOST, DEFAULT_PORT, Viewer

__all__ = ["DEFAULT_HOST", "DEFAULT_PORT", "Viewer"]

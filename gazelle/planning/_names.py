"""How a planning error quotes a name a request gave (a group, a link, a frame): at most :data:`NAME_CHARS`
characters of it, control characters escaped, and its length when cut, so that a hostile name can neither
flood a reply and the log nor forge a log line (a 10 MB group name to ``get_urdf`` was echoed whole into both)."""

from __future__ import annotations

from ..description import excerpt

NAME_CHARS = 40
"""The most characters of a requested name an error quotes (as ros2_control's refusals of controller names)."""


def quoted(name: object) -> str:
    """``name`` quoted for an error message: ``'panda_arm'``, or its first :data:`NAME_CHARS` characters and
    its length."""
    return excerpt(name, NAME_CHARS)

"""Which of the four formats a description is: by its file name (:func:`format_for_path`) or by its text
(:func:`detect_format`, :func:`xacro_markup`). On this package's ground floor: the package's loaders and the
xacro expansion (which keeps source locations only in URDF output) both ask it, and it asks nothing of them."""

from __future__ import annotations

import os
import re
from pathlib import Path

FORMATS = ("urdf", "xacro", "sdf", "srdf")
_SUFFIXES = {
    ".urdf": "urdf",
    ".xacro": "xacro",
    ".sdf": "sdf",
    ".world": "sdf",
    ".srdf": "srdf",
}


def format_for_path(path: str | os.PathLike[str]) -> str | None:
    """The format implied by a file name, or None if the suffix is unknown."""
    name = Path(path).name.lower()
    for suffix, fmt in _SUFFIXES.items():
        if name.endswith(suffix):
            return fmt
    return None


_XACRO_MARKUP = re.compile(r"<\s*xacro:|\$\{|\$\(")
"""What only xacro gives meaning to: its elements, ``${expr}`` and ``$(subst ...)``. A bare
``xmlns:xacro`` declaration is not markup: xacro's own output keeps it."""

XACRO_REFUSED = (
    "this description contains xacro ({what}); expand it first (`xacro file.urdf.xacro > robot.urdf`) "
    "or spawn the file with `gazelle spawn -file FILE`: a description sent as a string is data, "
    "never expanded or evaluated"
)


def xacro_markup(text: str) -> str | None:
    """The first piece of xacro markup in ``text`` outside comments (shortened), or None."""
    body = re.sub(r"<!--.*?-->", "", text, flags=re.S)
    m = _XACRO_MARKUP.search(body)
    if m is None:
        return None
    return body[m.start() : m.start() + 24].split("\n")[0]


def detect_format(text: str) -> str | None:
    """Guess the format of XML text from its content (xacro markup, root element).

    Files arrive with misleading names (a ``.urdf`` that is xacro, a ``.xml`` that is SDF, a description
    on a topic with no name at all), so the text decides: any xacro markup makes it xacro; an ``<sdf>`` root
    is SDF; a ``<robot>`` root is SRDF when it holds SRDF's elements and no link with geometry, else URDF.
    None when it is none of these (the caller says what it expected)."""
    if xacro_markup(text) is not None:
        return "xacro"
    # skip comments and the declaration, find the first element name
    body = re.sub(r"<!--.*?-->", "", text, flags=re.S)
    m = re.search(r"<\s*([A-Za-z_][\w:.-]*)", re.sub(r"<\?.*?\?>", "", body, flags=re.S))
    if not m:
        return None
    root = m.group(1)
    if root == "sdf":
        return "sdf"
    if root == "robot":
        if re.search(r"<\s*(group|disable_collisions|virtual_joint|end_effector)\b", body) and not re.search(
            r"<\s*link\s+name=[^>]*>\s*<\s*(visual|collision|inertial)", body
        ):
            return "srdf"
        return "urdf"
    return None


__all__ = ["FORMATS", "XACRO_REFUSED", "detect_format", "format_for_path", "xacro_markup"]

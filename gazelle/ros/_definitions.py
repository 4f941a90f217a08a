"""Interface definitions as text, read from the installed packages' ``share/<pkg>/msg/*.msg``.

``full_text`` is a message definition with every message it uses appended, as rosbag2 stores it in an
MCAP schema (encoding ``ros2msg``): each dependency after a line of 80 ``=`` and ``MSG: pkg/Name``."""

from __future__ import annotations

import importlib
import os
import re
from typing import Any


class InterfaceError(ValueError):
    """A type name that does not name an installed interface; the message says which."""


PRIMITIVES = frozenset(
    "bool byte char float32 float64 int8 uint8 int16 uint16 int32 uint32 int64 uint64 string wstring".split()
)
SEPARATOR = "=" * 80


def definition_path(type_name: str) -> str:
    """The file of ``pkg/msg/Name`` (``pkg/Name``: a message).

    Raises:
        InterfaceError: no such package or interface.
    """
    from ament_index_python.packages import get_package_share_directory

    parts = type_name.strip("/").split("/")
    if len(parts) == 2:
        parts = [parts[0], "msg", parts[1]]
    if len(parts) != 3 or not all(parts):
        raise InterfaceError(f"Invalid name '{type_name}'. Expected pkg/msg|srv|action/Name")
    pkg, kind, name = parts
    try:
        share = get_package_share_directory(pkg)
    except (LookupError, ValueError, OSError):  # OSError: AMENT_PREFIX_PATH is not set
        raise InterfaceError(f"Unknown package '{pkg}'") from None
    path = os.path.join(share, kind, f"{name}.{kind}")
    if not os.path.isfile(path):
        raise InterfaceError(f"Could not find the interface '{type_name}'")
    return path


def definition_text(type_name: str) -> str:
    """The definition file's text as it is."""
    with open(definition_path(type_name), encoding="utf-8") as f:
        return f.read()


def _field_types(pkg: str, text: str) -> list[str]:
    """The message types (``pkg/Name``) that a definition's fields use, in order of first use."""
    out: list[str] = []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        token = line.split()[0]  # (constants are of primitive types: skipped below too)
        base = re.sub(r"\[.*?\]$", "", token)
        base = re.sub(r"<=\d+$", "", base)
        if base in PRIMITIVES:
            continue
        name = base.replace("/msg/", "/")
        if "/" not in name:
            name = f"{pkg}/{name}"
        if name not in out:
            out.append(name)
    return out


def full_text(type_name: str) -> str:
    """``pkg/msg/Name``'s definition followed by those of every message it uses (depth first, once each).

    Raises:
        InterfaceError: the type or one of the types it uses is not installed.
    """
    pkg = type_name.strip("/").split("/")[0]
    main = definition_text(type_name).rstrip("\n")
    seen: list[str] = []
    parts = [main]

    def visit(pkg: str, text: str) -> None:
        for dep in _field_types(pkg, text):
            if dep in seen:
                continue
            seen.append(dep)
            dep_text = definition_text(dep).rstrip("\n")
            parts.append(f"{SEPARATOR}\nMSG: {dep}\n{dep_text}")
            visit(dep.split("/")[0], dep_text)

    visit(pkg, main)
    return "\n".join(parts) + "\n"


def message_class(type_name: str) -> Any:
    """``pkg/msg/Name``'s Python class (from the installed interface packages).

    Raises:
        InterfaceError: no such message.
    """
    parts = type_name.strip("/").split("/")
    pkg, name = parts[0], parts[-1]
    try:
        cls = getattr(importlib.import_module(f"{pkg}.msg"), name, None)
    except ImportError:
        cls = None
    if cls is None:
        raise InterfaceError(f"The message type '{type_name}' is not installed")
    return cls

"""Interface definitions as text, read from the installed packages' ``share/<pkg>/msg/*.msg``.

``full_text`` is a message definition with every message it uses appended, as rosbag2 stores it in an
MCAP schema (encoding ``ros2msg``): each dependency after a line of 80 ``=`` and ``MSG: pkg/Name``."""

from __future__ import annotations

import re
from typing import Any

from ._interfaces import KINDS, InterfaceError, checked_type_name, interface_package, resolve_interface, shown

PRIMITIVES = frozenset(
    "bool byte char float32 float64 int8 uint8 int16 uint16 int32 uint32 int64 uint64 string wstring".split()
)
SEPARATOR = "=" * 80


def definition_path(type_name: str) -> str:
    """The file of ``pkg/msg/Name`` (``pkg/Name``: a message; ``srv`` and ``action`` too), found as
    :mod:`._interfaces` finds a type: a name by rosidl's rules, of an interface the ament index lists, in
    ``share/<pkg>/<kind>/`` of the prefix that lists it.

    Raises:
        InterfaceError: a bad name, no such package or interface.
    """
    parts = type_name.split("/") if isinstance(type_name, str) else []
    kind = parts[1] if len(parts) == 3 and parts[1] in KINDS else "msg"
    package, kind, name, suffix = checked_type_name(type_name, kind)
    if suffix:
        raise InterfaceError(f"{shown(type_name)} is derived by rosidl: it has no definition file of its own")
    prefix, _names = interface_package(package)
    path = prefix / "share" / package / kind / f"{name}.{kind}"
    if not path.is_file():
        raise InterfaceError(f"Could not find the interface {shown(type_name)}")
    return str(path)


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
    """``pkg/msg/Name``'s Python class (from the installed interface packages), by
    :func:`~._interfaces.resolve_interface`: a type name from the graph is checked before it is imported.

    Raises:
        InterfaceError: no such message.
    """
    return resolve_interface(type_name, "msg")

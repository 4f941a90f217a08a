"""The one way a type name from outside (a bag's metadata.yaml, the graph, a command line, a bridge's YAML)
becomes a Python class: checked before anything is imported.

A name is ``pkg/msg|srv|action/Name`` (``pkg/Name``: the kind the caller asks for) under rosidl's rules
(rosidl_adapter/parser.py: a package is lower case letters, digits and single underscores, starting with a
letter and not ending with one; an interface is ``[A-Z][A-Za-z0-9]*``, with the suffixes rosidl derives for
a service's and an action's parts). The package must be one that the ament index lists as an interface
package (resource type ``rosidl_interfaces``, under ``<prefix>/share/ament_index/resource_index`` of each
prefix of ``AMENT_PREFIX_PATH`` and of this venv, where the ROS 2 wheels and gazelle's interface build put
theirs), and the interface must be among those its resource lists (``msg/Clock.msg``, ``msg/Clock.idl``).
Only then is ``pkg.msg`` (or ``pkg.srv``, ``pkg.action``) imported, never ``pkg`` alone nor any other
submodule: ``venv/__main__/Clock`` in a bag used to run ``python -m venv`` on the bag's folder.
"""

from __future__ import annotations

import importlib
import os
import re
import sys
from pathlib import Path
from typing import Any

from .._errors import SimError

KINDS = ("msg", "srv", "action")
"""The interface kinds, and the only submodules of an interface package that are imported."""
PACKAGE_NAME = re.compile(r"[a-z](?:_?[a-z0-9])*")
"""rosidl's package rule: no double underscore and no trailing one (rosidl_adapter/parser.py)."""
INTERFACE_NAME = re.compile(r"[A-Z][A-Za-z0-9]*")
"""rosidl's message name rule (rosidl_adapter/parser.py ``VALID_MESSAGE_NAME_PATTERN``)."""
MAX_NAME_CHARS = 256
"""A longer type name is refused before it is looked at (and is shown cut short in the error)."""

_SERVICE_PARTS = ("_Request", "_Response", "_Event")
_ACTION_SERVICES = ("_SendGoal", "_GetResult")
DERIVED: dict[tuple[str, str], tuple[str, ...]] = {
    ("msg", "msg"): ("",),
    ("msg", "srv"): _SERVICE_PARTS,
    ("msg", "action"): (
        "_Goal",
        "_Result",
        "_Feedback",
        "_FeedbackMessage",
        *(s + p for s in _ACTION_SERVICES for p in _SERVICE_PARTS),
    ),
    ("srv", "srv"): ("",),
    ("srv", "action"): _ACTION_SERVICES,
    ("action", "action"): ("",),
}
"""(what the caller needs, the name's kind) -> the suffixes rosidl gives the types it derives there: a topic
may carry a service's ``_Event`` or an action's ``_FeedbackMessage``; a service may be an action's
``_SendGoal``."""
_NESTED = {
    "_Goal": ("Goal",),
    "_Result": ("Result",),
    "_Feedback": ("Feedback",),
    "_FeedbackMessage": ("Impl", "FeedbackMessage"),
    "_SendGoal": ("Impl", "SendGoalService"),
    "_GetResult": ("Impl", "GetResultService"),
}
"""An action's parts that rosidl_generator_py keeps on the action class rather than in the module."""


class InterfaceError(SimError, ValueError):
    """A type name that does not name an installed interface, or values that do not fit it; the message is
    the one line to print."""


def shown(type_name: object) -> str:
    """A type name quoted for a one-line message: control characters escaped, a long one cut."""
    text = repr(str(type_name))
    return text if len(text) <= MAX_NAME_CHARS + 2 else text[:MAX_NAME_CHARS] + "...'"


def split_type_name(type_name: object, kind: str = "msg") -> tuple[str, str, str, str]:
    """``(package, kind, base name, derived suffix)`` of a type name, by rosidl's rules alone (no lookup).

    ``kind`` is what the caller needs (``msg``, ``srv`` or ``action``): a two-part ``pkg/Name`` is of that
    kind, and a three-part name may be another kind only for the parts rosidl derives (:data:`DERIVED`).

    Raises:
        InterfaceError: the name breaks a rule; the message names it and the rule.
    """
    if kind not in KINDS:
        raise InterfaceError(f"{shown(kind)} is not an interface kind (msg, srv or action)")
    bad = f"The passed {kind} type {shown(type_name)} is invalid"
    if not isinstance(type_name, str) or len(type_name) > MAX_NAME_CHARS:
        raise InterfaceError(f"{bad}: expected a name pkg/{kind}/Name of at most {MAX_NAME_CHARS} characters")
    parts = type_name.split("/")
    if len(parts) == 2:
        parts = [parts[0], kind, parts[1]]
    if len(parts) != 3:
        raise InterfaceError(f"{bad}: expected pkg/msg|srv|action/Name")
    package, middle, name = parts
    if not PACKAGE_NAME.fullmatch(package):
        raise InterfaceError(f"{bad}: {shown(package)} is not a ROS package name")
    if middle not in KINDS:
        raise InterfaceError(f"{bad}: {shown(middle)} is not msg, srv or action")
    base, _, rest = name.partition("_")
    suffix = f"_{rest}" if rest else ("_" if name.endswith("_") else "")
    allowed = DERIVED.get((kind, middle), ())
    if not INTERFACE_NAME.fullmatch(base) or suffix not in allowed:
        what = f"{kind} type" if middle == kind else f"{kind} type derived from a {middle}"
        raise InterfaceError(f"{bad}: {shown(name)} is not the name of a {what}")
    return package, middle, base, suffix


def ament_prefixes() -> list[Path]:
    """The install prefixes whose ament index is read: ``AMENT_PREFIX_PATH``'s, then this venv's."""
    paths = [Path(p) for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    venv = Path(sys.prefix)
    return paths if venv in paths else [*paths, venv]


_LISTED: dict[tuple[str, str], tuple[Path, frozenset[str]]] = {}
"""(prefixes, package) -> (prefix, its interfaces): a package once found stays found."""


def interface_package(package: str) -> tuple[Path, frozenset[str]]:
    """``(prefix, interfaces)`` of an interface package the ament index lists, its interfaces as
    ``msg/Clock`` (the resource's lines without their ``.msg``/``.idl``); the first prefix that lists it wins,
    as in ament_index_python.

    Raises:
        InterfaceError: no prefix lists ``package`` (a name :func:`split_type_name` has accepted).
    """
    prefixes = ament_prefixes()
    key = (os.pathsep.join(map(str, prefixes)), package)
    found = _LISTED.get(key)
    if found is not None:
        return found
    for prefix in prefixes:
        resource = prefix / "share" / "ament_index" / "resource_index" / "rosidl_interfaces" / package
        try:
            text = resource.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            continue
        names = frozenset(line.strip().rsplit(".", 1)[0] for line in text.splitlines() if "." in line)
        _LISTED[key] = (prefix, names)
        return prefix, names
    raise InterfaceError(
        f"{shown(package)} is not an interface package in the ament index (resource type rosidl_interfaces "
        f"under {', '.join(str(p) for p in prefixes)})"
    )


def checked_type_name(type_name: object, kind: str = "msg") -> tuple[str, str, str, str]:
    """:func:`split_type_name`, and the package and interface listed in the ament index.

    Raises:
        InterfaceError: a bad name, a package that is not an interface package, or an interface it lacks.
    """
    package, middle, base, suffix = split_type_name(type_name, kind)
    try:
        _prefix, names = interface_package(package)
    except InterfaceError as err:
        raise InterfaceError(f"The passed {kind} type {shown(type_name)} is invalid: {err}") from None
    if f"{middle}/{base}" not in names:
        raise InterfaceError(f"The passed {kind} type {shown(type_name)} is invalid: {package} has no {middle} {base}")
    return package, middle, base, suffix


def resolve_interface(type_name: object, kind: str = "msg") -> Any:
    """The Python class of ``pkg/msg|srv|action/Name`` (``pkg/Name``: of ``kind``) for a caller that needs a
    ``kind`` (a message class, a service type, an action type), imported only after
    :func:`checked_type_name`, and only from ``pkg.msg``, ``pkg.srv`` or ``pkg.action``.

    Raises:
        InterfaceError: the name is not that of an installed interface of that kind (one line naming it).
    """
    package, middle, base, suffix = checked_type_name(type_name, kind)
    bad = f"The passed {kind} type {shown(type_name)} is invalid"
    try:
        module = importlib.import_module(f"{package}.{middle}")
    except ImportError as err:
        raise InterfaceError(f"{bad}: {package}.{middle} does not import ({err})") from None
    found: Any = getattr(module, base + suffix, None)
    if found is None and suffix in _NESTED:
        found = getattr(module, base, None)
        for attr in _NESTED[suffix]:
            found = getattr(found, attr, None)
    if not isinstance(found, type) or not found.__module__.startswith(f"{package}.{middle}."):
        raise InterfaceError(f"{bad}: {package}.{middle} has no {base + suffix}")
    if not _is_kind(found, kind):
        raise InterfaceError(f"{bad}: {package}/{middle}/{base + suffix} is not a {kind}")
    return found


def _is_kind(cls: type, kind: str) -> bool:
    """Whether a generated class is a message, a service or an action, as ``kind`` asks."""
    if kind == "action":
        return all(hasattr(cls, a) for a in ("Goal", "Result", "Feedback"))
    if kind == "srv":
        return hasattr(cls, "Request") and hasattr(cls, "Response") and not hasattr(cls, "Goal")
    return hasattr(cls, "get_fields_and_field_types")

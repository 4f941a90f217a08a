"""Messages by type name, and to and from YAML as ros2cli prints and reads them (rosidl_runtime_py's
conventions: fields in definition order, nested mappings, arrays as block lists, ``{}`` for defaults)."""

from __future__ import annotations

import array
import functools
from collections import OrderedDict
from collections.abc import Callable
from typing import Any

import yaml

from ...description import UntrustedInputError, safe_load_bounded
from ...ros import InterfaceError, resolve_interface


def get_interface(type_name: str, kind: str = "msg") -> Any:
    """``pkg/msg/Type`` (or ``pkg/Type``) -> its Python class (``kind`` msg, srv or action), by gazelle's one
    checked resolver (:func:`gazelle.ros.resolve_interface`): a type name from the command line, the graph or
    a bag's metadata.yaml is held to rosidl's rules and the ament index before anything is imported."""
    return resolve_interface(type_name, kind)


def type_name_of(cls: Any) -> str:
    """``pkg/msg/Type`` of a message class."""
    module = cls.__module__.split(".")
    return f"{module[0]}/{module[1]}/{cls.__name__}"


def to_ordered(msg: Any, *, truncate: int | None = 128, no_arr: bool = False, no_str: bool = False) -> Any:
    """A message as nested ordered dicts and lists (what ros2 topic echo dumps)."""
    if not hasattr(msg, "get_fields_and_field_types"):
        if isinstance(msg, (bytes, bytearray)):
            msg = list(msg)
        if isinstance(msg, (list, tuple, array.array)) or type(msg).__name__ == "ndarray":
            items = [to_ordered(v, truncate=truncate, no_arr=no_arr, no_str=no_str) for v in list(msg)]
            if no_arr:
                return f"<array type: {len(items)} items>"
            if truncate is not None and len(items) > truncate:
                return [*items[:truncate], "..."]
            return items
        if isinstance(msg, str):
            if no_str:
                return f"<string length: <{len(msg)}>>"
            if truncate is not None and len(msg) > truncate:
                return msg[:truncate] + "..."
            return msg
        if type(msg).__module__ == "numpy":
            return msg.item()
        return msg
    out: OrderedDict = OrderedDict()
    for field in msg.get_fields_and_field_types():
        out[field] = to_ordered(getattr(msg, field), truncate=truncate, no_arr=no_arr, no_str=no_str)
    return out


_BASE_DUMPER: Any = getattr(yaml, "CSafeDumper", yaml.SafeDumper)
"""libyaml's emitter when PyYAML has it: `ros2 topic echo` keeps up with 1 kHz."""


class _Dumper(_BASE_DUMPER):
    pass


_Dumper.add_representer(
    OrderedDict, lambda dumper, data: dumper.represent_mapping("tag:yaml.org,2002:map", data.items())
)


def to_yaml(msg: Any, **kwargs: Any) -> str:
    """A message as ros2cli prints it (block style)."""
    return yaml.dump(
        to_ordered(msg, **kwargs), Dumper=_Dumper, default_flow_style=False, allow_unicode=True, width=10**6
    )


def to_csv(msg: Any) -> str:
    """A message's leaf values comma-separated, in field order (``ros2 topic echo --csv``)."""
    values: list[str] = []

    def walk(v: Any) -> None:
        if isinstance(v, dict):
            for x in v.values():
                walk(x)
        elif isinstance(v, list):
            for x in v:
                walk(x)
        else:
            values.append(str(v))

    walk(to_ordered(msg, truncate=None))
    return ",".join(values)


StampSetter = Callable[[Any], None]
"""Sets one ``builtin_interfaces/Time`` field of a message being published to the time it is given."""


def set_fields(msg: Any, values: Any, where: str = "", stamps: list[StampSetter] | None = None) -> Any:
    """Fill ``msg`` from a mapping parsed from YAML (nested, lists; absent fields keep their defaults).

    ``stamps``: given (``ros2 topic pub`` gives it), a ``std_msgs/Header`` field whose value is ``auto``
    keeps its defaults and the setter of its ``stamp`` is appended, and so is the setter of a
    ``builtin_interfaces/Time`` field whose value is ``now``: the caller stamps every message it publishes
    with its clock's time, as rosidl_runtime_py's ``set_message_fields(..., expand_header_auto=True,
    expand_time_now=True)`` does for ros2cli (rosidl_runtime_py/set_message.py, Jazzy). Without
    ``stamps`` (``service call``, ``action send_goal``, as upstream) ``auto`` and ``now`` are values like
    any other, and do not fit.

    Raises:
        InterfaceError: a field the type does not have, or a value of the wrong kind (the field named).
    """
    if values is None:
        return msg
    if not isinstance(values, dict):
        raise InterfaceError(f"{where or type(msg).__name__}: expected a mapping of fields, got {values!r}")
    fields = msg.get_fields_and_field_types()
    for key, value in values.items():
        if key not in fields:
            raise InterfaceError(
                f"{type_name_of(type(msg))} has no field '{where + key}' (its fields: {', '.join(fields)})"
            )
        current = getattr(msg, key)
        path = f"{where}{key}."
        if stamps is not None and _expand_stamp(msg, key, current, value, stamps):
            continue
        try:
            if hasattr(current, "get_fields_and_field_types"):
                set_fields(current, value, path, stamps)
            elif isinstance(current, (list, tuple)) or type(current).__name__ in ("ndarray", "array"):
                ftype = fields[key]
                inner = ftype.split("<", 1)[1].rstrip(">") if "<" in ftype else ftype.split("[", 1)[0]
                if "/" in inner and isinstance(value, list):
                    cls = get_interface(inner)
                    setattr(msg, key, [set_fields(cls(), v, path, stamps) for v in value])
                else:
                    setattr(msg, key, value)
            elif isinstance(current, float) and isinstance(value, int) and not isinstance(value, bool):
                setattr(msg, key, float(value))
            else:
                setattr(msg, key, value)
        except (AssertionError, TypeError, ValueError) as err:
            raise InterfaceError(f"field '{where + key}': {value!r} does not fit ({err})") from None
    return msg


def _expand_stamp(msg: Any, key: str, current: Any, value: Any, stamps: list[StampSetter]) -> bool:
    """``header: auto`` or ``<time field>: now`` (see :func:`set_fields`): its setter appended; whether it was one."""
    kind = type_name_of(type(current)) if hasattr(current, "get_fields_and_field_types") else ""
    if kind == "std_msgs/msg/Header" and value == "auto":
        stamps.append(functools.partial(setattr, current, "stamp"))
        return True
    if kind == "builtin_interfaces/msg/Time" and value == "now":
        stamps.append(functools.partial(setattr, msg, key))
        return True
    return False


def parse_values(text: str) -> Any:
    """The YAML of a ``pub`` / ``call`` argument (``{linear: {x: 0.2}}``), bounded: its aliases may not
    expand it past :data:`~gazelle.description.MAX_YAML_NODES` values (30 KB of anchors made a
    9-million-float JointTrajectory), and a recursive alias is refused, not a traceback."""
    try:
        return safe_load_bounded(text, "the values") if text.strip() else {}
    except UntrustedInputError as err:
        raise InterfaceError(str(err)) from None

"""The one generic conversion between a bus payload (a frozen dataclass of ``gazelle.systems``) and its ROS
message, both ways, for every payload whose fields map onto the message's.

A payload field goes to the message field of its name, with four rules and one declaration:

* ``stamp_sec`` is ``header.stamp`` and ``frame_id`` is ``header.frame_id`` (when the message has a header
  and no ``frame_id`` of its own); any other ``<name>_sec`` is the message's ``<name>`` when that is a
  builtin_interfaces Time or Duration (``time_from_start_sec``).
* A nested dataclass (a payload, or the description's ``Pose``) is the nested message of the same name,
  converted by the same rules; a tuple of them is a sequence of such messages.
* A 3-tuple is a geometry_msgs Vector3 or Point (x, y, z); a 4-tuple is a geometry_msgs Quaternion, written
  ``wxyz`` in gazelle (MuJoCo's order): the fields are named, so only the unpacking order changes.
* ``bytes`` fill a float32/float64/uint8 array field without a Python loop (scans, images); a tuple of
  numbers or strings fills an array or sequence field.
* Otherwise the payload class declares where a field goes: ``ROS_FIELDS`` (a class attribute) maps a field
  to a dotted path in the message (``{"names": "name"}``, ``{"pose": "pose.pose"}``); a dotted key renames
  inside a nested payload for this message only (``"pose.position": "translation"``: a Pose inside a
  geometry_msgs/Transform).

Every payload field must find its place, of a type its value converts to, or the plan is refused with an
:class:`InterfaceError` naming the field: that is what "the generic path cannot convert it" means, and only
then is a conversion written by hand (``_convert.py``, with its reason). The plan is made once per pair of
classes (introspecting the rclpy class's ``get_fields_and_field_types``); converting a message then costs
one small function call per field, and the nested messages a new rclpy message already holds (its header,
a pose's point) are filled in place rather than made anew, which makes the nested ones (Odometry,
TwistStamped, a controller's state) faster than the hand-written conversions this replaced.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import operator
import typing
from array import array
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any, Protocol, SupportsFloat, TypeGuard, TypeVar, cast

from builtin_interfaces.msg import Duration, Time
from geometry_msgs.msg import Point, Quaternion, Vector3

from ._interfaces import InterfaceError, resolve_interface

Converter = Callable[[Any], object]
"""A field's value converted: its type is what the plan learnt at run time from the payload's hints and the
message's field types (the one ``Any`` of this module)."""
Step = Callable[[object, object], None]
"""One field's part of filling a message: ``step(msg, payload)``."""
P = TypeVar("P")
M = TypeVar("M")


class _RosidlClass(Protocol):
    """What the plan reads of a generated message class."""

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]: ...


def _message_fields(msg_cls: type) -> dict[str, str]:
    """A generated message class's fields: name -> rosidl type (``sequence<double>``, ``std_msgs/Header``)."""
    return cast(_RosidlClass, msg_cls).get_fields_and_field_types()


Renames = tuple[tuple[str, str], ...]
"""A nested payload's renames for one message, as sorted (field, path) pairs (hashable, for the plan cache)."""

_FLOAT_CODES = {"float": "f", "double": "d"}
"""array typecodes of the float array element types (rosidl's ``float`` is float32)."""
_INTEGERS = frozenset(
    {"int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64", "octet", "byte", "char"}
)
_BYTE_TYPES = frozenset({"uint8", "octet", "byte", "char"})
_VECTOR_TYPES = frozenset({"geometry_msgs/Vector3", "geometry_msgs/Point"})
_QUATERNION = "geometry_msgs/Quaternion"
_TIME, _DURATION = "builtin_interfaces/Time", "builtin_interfaces/Duration"


def split_seconds(sec: float) -> tuple[int, int]:
    """(sec, nanosec) of builtin_interfaces/Time for ``sec`` seconds, nanoseconds rounded (a negative time
    is 0). ``ros/_cdr.py`` writes template stamps with it too, so both paths round alike."""
    sec = max(sec, 0.0)
    s = int(math.floor(sec))
    ns = int(round((sec - s) * 1e9))
    if ns >= 1_000_000_000:
        s, ns = s + 1, ns - 1_000_000_000
    return s, ns


def to_time(sec: float) -> Time:
    """builtin_interfaces/Time from seconds (non-negative)."""
    s, ns = split_seconds(sec)
    return Time(sec=s, nanosec=ns)


def from_time(t: Time) -> float:
    """builtin_interfaces/Time -> seconds."""
    return t.sec + t.nanosec * 1e-9


def split_duration(sec: float) -> tuple[int, int]:
    """(sec, nanosec) of builtin_interfaces/Duration for ``sec`` seconds (the nanoseconds always
    non-negative, as ROS keeps them)."""
    s = math.floor(sec)
    ns = int(round((sec - s) * 1e9))
    if ns >= 1_000_000_000:
        s, ns = s + 1, ns - 1_000_000_000
    return int(s), ns


def to_duration(sec: float) -> Duration:
    """builtin_interfaces/Duration from seconds (the nanoseconds always non-negative, as ROS keeps them)."""
    s, ns = split_duration(sec)
    return Duration(sec=s, nanosec=ns)


def from_duration(d: Duration) -> float:
    """Seconds of a builtin_interfaces/Duration."""
    return d.sec + d.nanosec * 1e-9


# --------------------------------------------------------------------------- where each field goes
def _element(ftype: str) -> tuple[str, bool]:
    """A rosidl field type's element type and whether the field is an array or sequence:
    ``sequence<double, 9>`` -> (``double``, True); ``double[9]`` -> (``double``, True); ``string<8>``: a string."""
    if ftype.startswith("sequence<"):
        return ftype[len("sequence<") : -1].split(",")[0].strip(), True
    if ftype.endswith("]"):
        return ftype[: ftype.index("[")], True
    return ftype, False


def _message_class(ftype: str) -> type:
    """The rclpy class of a nested field type ``pkg/Name``."""
    package, name = ftype.split("/")
    return resolve_interface(f"{package}/msg/{name}", "msg")


def _fields(payload_cls: type) -> list[tuple[str, object]]:
    """A payload dataclass's fields with their resolved type hints, in order."""
    if not dataclasses.is_dataclass(payload_cls):
        raise InterfaceError(f"{payload_cls.__name__} is not a dataclass")
    hints = typing.get_type_hints(payload_cls)
    return [(f.name, hints[f.name]) for f in dataclasses.fields(payload_cls) if f.init]


def _renames(payload_cls: type, outer: Renames) -> dict[str, str]:
    """Where the payload's fields go when not by their name: its own ``ROS_FIELDS``, then the renames its
    container gave for this message."""
    declared: Mapping[str, str] = getattr(payload_cls, "ROS_FIELDS", {})
    return {**declared, **dict(outer)}


def _path(name: str, renames: dict[str, str], msg_fields: dict[str, str]) -> str | None:
    """The dotted message path of payload field ``name`` (None: it has none)."""
    if name in renames:
        return renames[name]
    if name in msg_fields:
        return name
    if "header" in msg_fields and name in ("stamp_sec", "frame_id"):
        return "header.stamp" if name == "stamp_sec" else "header.frame_id"
    if name.endswith("_sec") and msg_fields.get(name[:-4]) in (_TIME, _DURATION):
        return name[:-4]
    return None


def _walk(msg_cls: type, path: str, where: str) -> str:
    """The rosidl type of the field at dotted ``path`` of ``msg_cls`` (every step but the last a nested message)."""
    cls = msg_cls
    parts = path.split(".")
    for i, part in enumerate(parts):
        ftype = _message_fields(cls).get(part)
        if ftype is None:
            raise InterfaceError(f"{where}: {cls.__name__} has no field {'.'.join(parts[: i + 1])!r}")
        if i == len(parts) - 1:
            return ftype
        if "/" not in ftype or _element(ftype)[1]:
            raise InterfaceError(f"{where}: {'.'.join(parts[: i + 1])} of {cls.__name__} is not a message")
        cls = _message_class(ftype)
    raise AssertionError("unreachable")


def _nested(name: str, renames: dict[str, str]) -> Renames:
    """The renames given for inside payload field ``name`` (keys ``name.x``), as the nested plan's key."""
    prefix = name + "."
    return tuple(sorted((k[len(prefix) :], v) for k, v in renames.items() if k.startswith(prefix)))


def _layout(payload_cls: type, msg_cls: type, outer: Renames) -> list[tuple[str, object, str, str, Renames]]:
    """Per payload field: (name, type hint, message path, rosidl type, renames inside it); refused with an
    :class:`InterfaceError` when a field has no place in the message."""
    renames = _renames(payload_cls, outer)
    msg_fields = _message_fields(msg_cls)
    out = []
    for name, hint in _fields(payload_cls):
        where = f"{payload_cls.__name__}.{name} -> {msg_cls.__name__}"
        path = _path(name, renames, msg_fields)
        if path is None:
            raise InterfaceError(f"{where}: the message has no field {name!r} and ROS_FIELDS gives it none")
        out.append((name, hint, path, _walk(msg_cls, path, where), _nested(name, renames)))
    return out


def _tuple_of(hint: object) -> object:
    """X of a ``tuple[X, ...]`` hint, or None."""
    args = typing.get_args(hint)
    if typing.get_origin(hint) is tuple and len(args) == 2 and args[1] is Ellipsis:
        return args[0]
    return None


def _fixed_floats(hint: object) -> int:
    """n of a ``tuple[float, ...n times]`` hint, else 0."""
    args = typing.get_args(hint)
    if typing.get_origin(hint) is tuple and args and Ellipsis not in args and all(a is float for a in args):
        return len(args)
    return 0


def _is_dataclass_type(hint: object) -> TypeGuard[type]:
    return isinstance(hint, type) and dataclasses.is_dataclass(hint)


# --------------------------------------------------------------------------- payload -> message
def _step(hint: object, ftype: str, inner: Renames, where: str, path: str, get: Converter) -> Step:
    """The step that fills the message field at ``path`` (rosidl type ``ftype``) from the payload value
    ``get(payload)`` of type ``hint``. A nested message the message already holds is filled in place (its
    fields set, no new message made: the cheapest way through rclpy's setters); arrays and primitives are set."""
    elem, many = _element(ftype)
    at = operator.attrgetter(path)
    if not many and "/" in elem:
        fill = _filler(hint, elem, inner, where)
        return lambda msg, p: fill(at(msg), get(p))
    parent, _, last = path.rpartition(".")
    owner = operator.attrgetter(parent) if parent else None
    convert = _to_value(hint, elem, many, inner, where)
    if owner is None:
        if convert is None:
            return lambda msg, p: setattr(msg, last, get(p))
        return lambda msg, p: setattr(msg, last, convert(get(p)))
    if convert is None:
        return lambda msg, p: setattr(owner(msg), last, get(p))
    return lambda msg, p: setattr(owner(msg), last, convert(get(p)))


def _filler(hint: object, ftype: str, inner: Renames, where: str) -> Callable[..., None]:
    """How a nested message of type ``ftype`` is filled in place from a payload value of ``hint``."""
    if ftype in (_TIME, _DURATION) and hint is float:
        return _fill_time if ftype == _TIME else _fill_duration
    if _is_dataclass_type(hint):
        return _fill_plan(hint, _message_class(ftype), inner)
    if ftype in _VECTOR_TYPES and _fixed_floats(hint) == 3:
        return _fill_vector
    if ftype == _QUATERNION and _fixed_floats(hint) == 4:
        return _fill_quaternion
    raise InterfaceError(f"{where}: a {hint} does not convert to a {ftype}")


def _fill_time(t: Time, sec: float) -> None:
    t.sec, t.nanosec = split_seconds(sec)


def _fill_duration(d: Duration, sec: float) -> None:
    d.sec, d.nanosec = split_duration(sec)


def _fill_vector(m: Vector3 | Point, v: Sequence[float]) -> None:
    m.x, m.y, m.z = float(v[0]), float(v[1]), float(v[2])


def _fill_quaternion(m: Quaternion, q: Sequence[float]) -> None:
    m.w, m.x, m.y, m.z = float(q[0]), float(q[1]), float(q[2]), float(q[3])


def _to_value(hint: object, elem: str, many: bool, inner: Renames, where: str) -> Converter | None:
    """How a payload value of ``hint`` becomes the value of a field of element type ``elem`` that is an array
    (``many``) or a primitive (None: as it is)."""
    item = _tuple_of(hint)
    if many and "/" in elem:
        if not _is_dataclass_type(item):
            raise InterfaceError(f"{where}: a sequence of {elem} needs a tuple of dataclasses, not {hint}")
        sub = payload_to_msg(item, _message_class(elem), inner)
        return lambda v: [sub(x) for x in v]
    if many:
        if elem in _FLOAT_CODES and (hint is bytes or item is float or _fixed_floats(hint)):
            return functools.partial(array, _FLOAT_CODES[elem])
        if elem in _BYTE_TYPES and hint is bytes:
            return None
        if item is not None and (elem in _INTEGERS or elem == "boolean" or elem.startswith("string")):
            return list
    elif elem in _FLOAT_CODES and hint in (float, int):
        return float
    elif (elem in _INTEGERS and hint is int) or (elem == "boolean" and hint is bool):
        return None
    elif elem.startswith("string") and hint is str:
        return None
    raise InterfaceError(f"{where}: a {hint} does not fill a {elem}{'[]' if many else ''}")


@functools.cache
def _fill_plan(payload_cls: type, msg_cls: type, outer: Renames = ()) -> Step:
    """``fill(msg, payload)``: every field of a ``payload_cls`` payload set in a ``msg_cls`` message."""
    steps = []
    for name, hint, path, ftype, inner in _layout(payload_cls, msg_cls, outer):
        where = f"{payload_cls.__name__}.{name} -> {msg_cls.__name__}.{path}"
        steps.append(_step(hint, ftype, inner, where, path, operator.attrgetter(name)))
    run = tuple(steps)

    def fill(msg: object, payload: object) -> None:
        for step in run:
            step(msg, payload)

    return fill


def payload_to_msg(payload_cls: type[P], msg_cls: type[M], outer: Renames = ()) -> Callable[[P], M]:
    """The conversion of ``payload_cls`` payloads to ``msg_cls`` messages by the rules of the module
    docstring, made once per pair.

    Raises:
        InterfaceError: a field of the payload has no place in the message (one line naming it).
    """
    return cast("Callable[[P], M]", _writer(payload_cls, msg_cls, outer))


@functools.cache
def _writer(payload_cls: type, msg_cls: type, outer: Renames) -> Callable[[object], object]:
    """:func:`payload_to_msg`'s conversion, made once per pair."""
    fill = _fill_plan(payload_cls, msg_cls, outer)

    def convert(payload: object) -> object:
        msg = msg_cls()
        fill(msg, payload)
        return msg

    return convert


# --------------------------------------------------------------------------- message -> payload
def _floats(v: Iterable[SupportsFloat]) -> tuple[float, ...]:
    return tuple(map(float, v))


def _from_value(hint: object, ftype: str, inner: Renames, where: str) -> Converter | None:
    """How a message value of rosidl type ``ftype`` becomes a payload value of ``hint`` (None: as it is)."""
    elem, many = _element(ftype)
    if not many:
        return _from_single(hint, elem, inner, where)
    item = _tuple_of(hint)
    if "/" in elem:
        if not _is_dataclass_type(item):
            raise InterfaceError(f"{where}: {ftype} needs a tuple of dataclasses, not {hint}")
        sub = msg_to_payload(_message_class(elem), item, inner)
        return lambda v: tuple(sub(x) for x in v)
    if hint is bytes and (elem in _FLOAT_CODES or elem in _BYTE_TYPES):
        return bytes
    if elem in _FLOAT_CODES and (item is float or _fixed_floats(hint)):
        return _floats
    if item is int and elem in _INTEGERS:
        return lambda v: tuple(map(int, v))
    if item is bool and elem == "boolean":
        return lambda v: tuple(map(bool, v))
    if item is str and elem.startswith("string"):
        return tuple
    raise InterfaceError(f"{where}: a {ftype} does not fill a {hint}")


def _from_single(hint: object, ftype: str, inner: Renames, where: str) -> Converter | None:
    """:func:`_from_value` for a field that is not an array."""
    if ftype in (_TIME, _DURATION) and hint is float:
        return from_time if ftype == _TIME else from_duration
    if "/" in ftype:
        if _is_dataclass_type(hint):
            return msg_to_payload(_message_class(ftype), hint, inner)
        if ftype in _VECTOR_TYPES and _fixed_floats(hint) == 3:
            return lambda v: (v.x, v.y, v.z)
        if ftype == _QUATERNION and _fixed_floats(hint) == 4:
            return lambda v: (v.w, v.x, v.y, v.z)
        raise InterfaceError(f"{where}: a {ftype} does not convert to a {hint}")
    if ftype in _FLOAT_CODES and hint is float:
        return float
    if (ftype in _INTEGERS and hint is int) or (ftype == "boolean" and hint is bool):
        return None
    if ftype.startswith("string") and hint is str:
        return None
    raise InterfaceError(f"{where}: a {ftype} is not a {hint}")


def msg_to_payload(msg_cls: type[M], payload_cls: type[P], outer: Renames = ()) -> Callable[[M], P]:
    """The conversion of ``msg_cls`` messages to ``payload_cls`` payloads (the inverse of
    :func:`payload_to_msg`), made once per pair.

    Raises:
        InterfaceError: a field of the payload has no place in the message (one line naming it).
    """
    return cast("Callable[[M], P]", _reader(msg_cls, payload_cls, outer))


@functools.cache
def _reader(msg_cls: type, payload_cls: type, outer: Renames) -> Callable[[object], object]:
    """:func:`msg_to_payload`'s conversion, made once per pair."""
    getters = []
    for name, hint, path, ftype, inner in _layout(payload_cls, msg_cls, outer):
        where = f"{msg_cls.__name__}.{path} -> {payload_cls.__name__}.{name}"
        get = operator.attrgetter(path)
        convert = _from_value(hint, ftype, inner, where)
        getters.append(get if convert is None else _compose(convert, get))
    run = tuple(getters)

    def convert_back(msg: object) -> object:
        return payload_cls(*[get(msg) for get in run])

    return convert_back


def _compose(outer: Converter, inner: Converter) -> Converter:
    return lambda m: outer(inner(m))

"""What ``ros2 bag`` reads from files someone else may have written: a bag's ``metadata.yaml`` and a
``--qos-profile-overrides-path`` file, each read with bounds and checked field by field before any of it is
used, so that a wrong field is one line naming the file and the field (never a traceback), and a topic's
type is a name held to rosidl's rules, not a module to import (:func:`gazelle.ros.split_type_name`).

Bounds: metadata.yaml at most :data:`MAX_METADATA_BYTES`, an overrides file at most
:data:`MAX_OVERRIDES_BYTES`, both regular files (a FIFO or ``/dev/zero`` is refused) and YAML within
:func:`~gazelle.description.safe_load_bounded`'s bounds (aliases, integer literals); times and counts in
int64 (rosbag2's ``rcutils_time_point_value_t``), a QoS depth at most :data:`MAX_QOS_DEPTH`, a QoS duration
at most :data:`MAX_DURATION_NS`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, TextIO

from ..._errors import SimError
from ...description import UntrustedInputError, read_regular_file, safe_load_bounded
from ...ros import InterfaceError, split_type_name

MAX_METADATA_BYTES = 16 << 20
"""The largest metadata.yaml read (rosbag2's for a bag of a thousand topics is a few hundred KB)."""
MAX_OVERRIDES_BYTES = 1 << 20
"""The largest QoS overrides file read."""
INT64_MAX = 2**63 - 1
"""The largest time, duration or count in metadata.yaml (rosbag2 keeps them in int64)."""
MAX_QOS_DEPTH = 2**31 - 1
"""The deepest history rclpy takes (its ``rmw_qos_profile_t`` binding refuses 2**31 with a TypeError)."""
MAX_DURATION_NS = 2**63 - 1
"""The longest QoS duration rclpy takes (``Duration`` is int64 nanoseconds: 9223372036.854775807 s)."""
_DURATION_KEYS = ("deadline", "lifespan", "liveliness_lease_duration")


class BagError(SimError):
    """What makes a bag command fail; the message is the one line printed."""


def brief(value: object) -> str:
    """A value from a file as an error shows it: short, on one line, and never a huge integer's digits (their
    conversion to text is what Python's int-string-conversion limit refuses)."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 128:
        return f"an integer of {value.bit_length()} bits"
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."


def load_yaml(path: Path, max_bytes: int, what: str) -> object:
    """The YAML document of a regular file of at most ``max_bytes``, within the bounded loader's bounds.

    Raises:
        BagError: not a regular file, too big, not UTF-8 or not YAML (the file and line named).
    """
    try:
        return safe_load_bounded(read_regular_file(path, max_bytes, what), str(path))
    except UntrustedInputError as err:
        raise BagError(str(err)) from None


def _field(parent: Any, key: str | int, where: str, kind: type | tuple[type, ...], what: str) -> Any:
    """``parent[key]`` when it is of ``kind`` (a bool is never an integer).

    Raises:
        BagError: ``where.key`` missing or of another kind (``where`` starts with the file).
    """
    name = f"{where}[{key}]" if isinstance(key, int) else f"{where}.{key}"
    if isinstance(key, str) and key not in parent:
        raise BagError(f"{name} is missing")
    value = parent[key]
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        raise BagError(f"{name}: expected {what}, got {brief(value)}")
    return value


def _count(parent: dict[str, Any], key: str, where: str, low: int = 0) -> int:
    """An integer field within ``[low, INT64_MAX]``."""
    value = _field(parent, key, where, int, "an integer")
    if not low <= value <= INT64_MAX:
        raise BagError(f"{where}.{key}: {brief(value)} is out of range ({low} to {INT64_MAX})")
    return value


def read_metadata(bag: Path) -> dict[str, Any]:
    """The ``rosbag2_bagfile_information`` of a bag folder's metadata.yaml, every field that ``info`` and
    ``play`` read checked for its kind and range, each topic's type for rosidl's rules, and each topic's
    ``offered_qos_profiles`` (rosbag2 writes a YAML string) read into a list of mappings; only the mcap
    storage is supported.

    Raises:
        BagError: no such bag, not a bag folder, or a field missing or wrong (one line naming file and field).
    """
    if not bag.exists():
        raise BagError(f"bag '{bag}' does not exist")
    meta_path = bag / "metadata.yaml"
    if not meta_path.is_file():
        raise BagError(f"'{bag}' is not a bag folder: it has no metadata.yaml")
    doc = load_yaml(meta_path, MAX_METADATA_BYTES, "bag metadata")
    if not isinstance(doc, dict):
        raise BagError(f"{meta_path}: expected a mapping (rosbag2_bagfile_information: ...), got {brief(doc)}")
    where = f"{meta_path}: rosbag2_bagfile_information"
    meta = doc.get("rosbag2_bagfile_information")
    if not isinstance(meta, dict):
        raise BagError(f"{where} is missing" if meta is None else f"{where}: expected a mapping, got {brief(meta)}")
    storage = _field(meta, "storage_identifier", where, str, "a string")
    if storage != "mcap":
        raise BagError(f"{meta_path}: storage {brief(storage)} is not supported (only mcap)")
    files = _field(meta, "relative_file_paths", where, list, "a list of file names")
    if not files:
        raise BagError(f"{where}.relative_file_paths is empty: the bag names no file to read")
    for i in range(len(files)):
        _field(files, i, f"{where}.relative_file_paths", str, "a file name")
    _count(_field(meta, "duration", where, dict, "a mapping"), "nanoseconds", f"{where}.duration")
    start = _field(meta, "starting_time", where, dict, "a mapping")
    _count(start, "nanoseconds_since_epoch", f"{where}.starting_time")
    _count(meta, "message_count", where)
    if not isinstance(meta.get("ros_distro", ""), str):
        raise BagError(f"{where}.ros_distro: expected a string, got {brief(meta['ros_distro'])}")
    topics = _field(meta, "topics_with_message_count", where, list, "a list of topics")
    for i in range(len(topics)):
        _check_topic(topics, i, f"{where}.topics_with_message_count")
    return meta


def _check_topic(topics: list[object], i: int, where: str) -> None:
    """One entry of ``topics_with_message_count``: its count, name, type (rosidl's rules, nothing imported),
    serialization format and offered QoS profiles (parsed in place from rosbag2's YAML string)."""
    entry = _field(topics, i, where, dict, "a mapping")
    here = f"{where}[{i}]"
    _count(entry, "message_count", here)
    md = _field(entry, "topic_metadata", here, dict, "a mapping")
    here += ".topic_metadata"
    name = _field(md, "name", here, str, "a topic name")
    type_name = _field(md, "type", here, str, "a type name")
    try:
        split_type_name(type_name)
    except InterfaceError as err:
        raise BagError(f"{here}.type (topic {brief(name)}): {err}") from None
    _field(md, "serialization_format", here, str, "a string")
    md["offered_qos_profiles"] = _offered(md.get("offered_qos_profiles", ""), f"{here}.offered_qos_profiles")


def _offered(value: object, where: str) -> list[dict[str, Any]]:
    """The recorded ``offered_qos_profiles`` as a list of mappings (rosbag2 writes it as a YAML string in
    metadata.yaml, as a list in the MCAP channel); empty is none."""
    if isinstance(value, str):
        try:
            value = safe_load_bounded(value, where) if value.strip() else []
        except UntrustedInputError as err:
            raise BagError(str(err)) from None
    if value is None:
        return []
    if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
        raise BagError(f"{where}: expected a list of QoS profiles, got {brief(value)}")
    return value


def qos_overrides(source: str | Path | TextIO) -> dict[str, Any]:
    """``--qos-profile-overrides-path`` (a path, or an open text file): topic -> rclpy QoSProfile, read as
    ros2bag/api/__init__.py's ``convert_yaml_to_qos_profile`` does (policies by their short keys, durations
    as ``{sec, nsec}``, no negative value, no other key, rclpy's own rule that history or depth is given).
    What rosbag2 would stop on with a traceback (not a mapping, an unknown policy value, a depth or a
    duration past what rclpy takes, a 5,000-digit integer) is a :class:`BagError` naming the file, the
    topic and the field."""
    from rclpy.qos import InvalidQoSProfileException, QoSProfile

    if isinstance(source, str | Path):
        name = str(source)
        loaded = load_yaml(Path(source), MAX_OVERRIDES_BYTES, "QoS overrides file")
    else:
        name = getattr(source, "name", "the QoS overrides file")
        text = source.read(MAX_OVERRIDES_BYTES + 1)
        if len(text) > MAX_OVERRIDES_BYTES:
            raise BagError(f"{name}: the QoS overrides file has more than the {MAX_OVERRIDES_BYTES} bytes allowed")
        try:
            loaded = safe_load_bounded(text, name)
        except UntrustedInputError as err:
            raise BagError(str(err)) from None
    if loaded is None:
        return {}
    if not isinstance(loaded, dict) or not all(isinstance(v, dict) for v in loaded.values()):
        raise BagError(f"{name}: expected a mapping of topic names to QoS profiles")
    out = {}
    for topic, profile in loaded.items():
        try:
            out[str(topic)] = QoSProfile(**{key: _qos_field(key, value) for key, value in profile.items()})
        except (InvalidQoSProfileException, ValueError) as err:
            raise BagError(f"{name}: topic {brief(topic).strip(chr(39))}: {err}") from None
    return out


def _qos_field(key: Any, value: object) -> Any:
    """One policy of an override, as rclpy takes it.

    Raises:
        ValueError: an unknown key, or a value that does not fit (the key named).
    """
    from rclpy.duration import Duration
    from rclpy.qos import QoSDurabilityPolicy, QoSHistoryPolicy, QoSLivelinessPolicy, QoSReliabilityPolicy

    policies = {
        "history": QoSHistoryPolicy,
        "reliability": QoSReliabilityPolicy,
        "durability": QoSDurabilityPolicy,
        "liveliness": QoSLivelinessPolicy,
    }
    if key in _DURATION_KEYS:
        return Duration(nanoseconds=_duration_ns(key, value))
    if key in policies:
        try:
            return policies[key].get_from_short_key(str(value))
        except KeyError:
            keys = ", ".join(policies[key].short_keys())
            raise ValueError(f"`{brief(value).strip(chr(39))}` is not a {key} policy (one of {keys})") from None
    if key == "depth":
        if not isinstance(value, int) or isinstance(value, bool) or value < 0:
            raise ValueError(
                f"`{key}` may not be a negative value."
                if isinstance(value, int)
                else f"`depth` must be a whole number, got {brief(value)}"
            )
        if value > MAX_QOS_DEPTH:
            raise ValueError(f"`depth` {brief(value)} is more than {MAX_QOS_DEPTH}, the deepest history rclpy takes")
        return value
    if key == "avoid_ros_namespace_conventions":
        if not isinstance(value, bool):
            raise ValueError(f"`{key}` must be true or false, got {brief(value)}")
        return value
    raise ValueError(f"Unexpected key `{brief(key).strip(chr(39))}` for QoS profile.")


def _duration_ns(key: str, value: object) -> int:
    """A ``{sec, nsec}`` YAML duration in nanoseconds (ros2bag's ``dict_to_duration``: empty is 0), within
    what rclpy's Duration holds."""
    if not value:
        return 0
    if not isinstance(value, dict) or "sec" not in value or "nsec" not in value:
        raise ValueError("Time overrides must include both seconds (sec) and nanoseconds (nsec).")
    sec, nsec = value["sec"], value["nsec"]
    if not all(isinstance(v, int) and not isinstance(v, bool) for v in (sec, nsec)):
        raise ValueError(f"{key}: sec and nsec must be whole numbers, got {brief(sec)} and {brief(nsec)}")
    total = sec * 1_000_000_000 + nsec
    if total < 0:
        raise ValueError("Time duration may not be a negative value.")
    if total > MAX_DURATION_NS:
        raise ValueError(
            f"{key}: {{sec: {brief(sec)}, nsec: {brief(nsec)}}} is longer than {MAX_DURATION_NS} ns, the longest "
            "duration rclpy takes"
        )
    return total

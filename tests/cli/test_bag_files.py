"""gazelle's rosbag2 (``ros2 bag``) without a graph: the MCAP schemas it writes parse with two
independent readers, and bad bags are one-line errors."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from _planted import PAYLOADS, imported, plant

from gazelle.cli.ros2cli import ensure_ament_prefix

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")


def ros2(*args: str, timeout: float = 60) -> subprocess.CompletedProcess:
    return subprocess.run([ROS2, *args], capture_output=True, text=True, timeout=timeout)


@pytest.mark.parametrize("type_name", ["nav_msgs/msg/Odometry", "tf2_msgs/msg/TFMessage", "sensor_msgs/msg/JointState"])
def test_schema_text_has_every_dependency_once_and_parses_independently(type_name):
    from mcap_ros2._dynamic import generate_dynamic
    from rosbags.typesys import get_types_from_msg

    from gazelle.ros import message_definition as full_text

    ensure_ament_prefix()
    text = full_text(type_name)
    deps = [line[5:] for line in text.splitlines() if line.startswith("MSG: ")]
    assert len(deps) == len(set(deps)) and "builtin_interfaces/Time" in deps
    assert type_name in generate_dynamic(type_name, text)
    types = get_types_from_msg(text, type_name)
    assert type_name in types and "std_msgs/msg/Header" in types


def test_bag_errors_are_one_line(tmp_path):
    missing = ros2("bag", "info", str(tmp_path / "nope"))
    assert missing.returncode == 1 and "does not exist" in missing.stderr

    not_a_bag = tmp_path / "empty"
    not_a_bag.mkdir()
    assert "has no metadata.yaml" in ros2("bag", "play", str(not_a_bag)).stderr

    corrupt = tmp_path / "corrupt"
    corrupt.mkdir()
    (corrupt / "metadata.yaml").write_text(
        "rosbag2_bagfile_information:\n  version: 9\n  storage_identifier: mcap\n"
        "  relative_file_paths: [corrupt_0.mcap]\n  topics_with_message_count: []\n"
        "  duration: {nanoseconds: 0}\n  starting_time: {nanoseconds_since_epoch: 0}\n  message_count: 0\n"
    )
    (corrupt / "corrupt_0.mcap").write_bytes(b"\x89MCAP0\r\n" + b"\x01" * 200)
    for verb in ("info", "play"):
        out = ros2("bag", verb, str(corrupt))
        assert out.returncode == 1 and "not a valid MCAP file" in out.stderr, out.stderr

    exists = ros2("bag", "record", "-o", str(not_a_bag), "/odom")
    assert exists.returncode == 1 and "already exists" in exists.stderr
    for out in (missing, exists):
        assert "Traceback" not in out.stderr and len(out.stderr.strip().splitlines()) == 1


# --------------------------------------------------------------------------- crafted bags (issue 48)
def _bag(folder: Path, type_name: str, schema_name: str | None = None) -> Path:
    """A one-message bag as rosbag2 lays it out (``<folder>_0.mcap`` and metadata.yaml) whose topic /crafted
    has ``type_name`` in metadata.yaml and ``schema_name`` (default the same) as its MCAP schema's name."""
    import yaml
    from mcap.writer import Writer

    folder.mkdir(parents=True)
    with open(folder / f"{folder.name}_0.mcap", "wb") as f:
        writer = Writer(f)
        writer.start(profile="ros2", library="test")
        schema = writer.register_schema(name=schema_name or type_name, encoding="ros2msg", data=b"int32 data\n")
        channel = writer.register_channel(topic="/crafted", message_encoding="cdr", schema_id=schema)
        writer.add_message(channel_id=channel, log_time=1, publish_time=1, data=b"\x00\x01\x00\x00\x07\x00\x00\x00")
        writer.finish()
    meta = {
        "rosbag2_bagfile_information": {
            "version": 9,
            "storage_identifier": "mcap",
            "duration": {"nanoseconds": 0},
            "starting_time": {"nanoseconds_since_epoch": 1},
            "message_count": 1,
            "topics_with_message_count": [
                {
                    "topic_metadata": {
                        "name": "/crafted",
                        "type": type_name,
                        "serialization_format": "cdr",
                        "offered_qos_profiles": "",
                    },
                    "message_count": 1,
                }
            ],
            "relative_file_paths": [f"{folder.name}_0.mcap"],
            "ros_distro": "jazzy",
        }
    }
    (folder / "metadata.yaml").write_text(yaml.safe_dump(meta))
    return folder


def _env(python_path: Path | None = None) -> dict[str, str]:
    """This process's environment on its reserved ROS domain (localhost), with ``python_path`` first on
    PYTHONPATH."""
    from _ros_domain import reserved_domain_id

    env = dict(os.environ, ROS_DOMAIN_ID=str(reserved_domain_id()), ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST")
    if python_path is not None:
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(python_path), env.get("PYTHONPATH", "")) if p)
    return env


def _one_line(out: subprocess.CompletedProcess) -> str:
    """The single line a refused command printed (status 1, no traceback)."""
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 1 and len(lines) == 1 and "Traceback" not in out.stderr, (out.returncode, out.stderr)
    return lines[0]


@pytest.mark.parametrize("payload", PAYLOADS)
def test_a_crafted_type_in_a_bag_is_one_line_and_imports_nothing(tmp_path: Path, payload: str) -> None:
    """Issue 48: a topic type ``venv/__main__/Clock`` in metadata.yaml made ``ros2 bag play`` run ``python -m
    venv`` on the bag's folder (``unittest/__main__/Clock`` ran unittest): the type was imported unchecked.
    Now play answers with one line naming it (info too, for a name that breaks rosidl's rules; a well-formed
    one it describes, as rosbag2's does), and none of the planted packages (one for each name, shadowing the
    standard library's) is imported, with the payload in the MCAP schema's name too."""
    path, markers = plant(tmp_path / "planted")
    bag = _bag(tmp_path / "crafted", payload)
    env = _env(path)
    for verb in ("play", "info"):
        out = subprocess.run([ROS2, "bag", verb, str(bag)], capture_output=True, text=True, timeout=60, env=env)
        if verb == "info" and "/msg/" in payload:  # a well-formed name of no installed package: described, as rosbag2's
            assert out.returncode == 0 and f"Type: {payload} | Count: 1" in out.stdout, out.stdout + out.stderr
            continue
        line = _one_line(out)
        assert line.startswith(f"[ERROR] [ros2bag]: {bag / 'metadata.yaml'}: ") and repr(payload) in line, line
    assert imported(markers) == []
    assert not (bag / "pyvenv.cfg").exists()


def test_an_mcap_schema_name_is_never_imported(tmp_path: Path) -> None:
    """The type a bag plays with is metadata.yaml's, resolved by the checked resolver; the MCAP schema's name
    is never imported (the reader decodes nothing): a bag whose schema is named ``venv/__main__/Clock`` over
    a real std_msgs/msg/Int32 topic plays and is described, and imports nothing planted."""
    path, markers = plant(tmp_path / "planted")
    bag = _bag(tmp_path / "schema", "std_msgs/msg/Int32", schema_name="venv/__main__/Clock")
    env = _env(path)
    play = subprocess.run(
        [ROS2, "bag", "play", str(bag), "--wait", "0"], capture_output=True, text=True, timeout=60, env=env
    )
    assert play.returncode == 0, play.stderr
    info = subprocess.run([ROS2, "bag", "info", str(bag)], capture_output=True, text=True, timeout=60, env=env)
    assert "Type: std_msgs/msg/Int32 | Count: 1" in info.stdout, info.stdout + info.stderr
    assert imported(markers) == []


def _set(path: tuple[str | int, ...], value: object):
    def mutate(meta: dict) -> None:
        node: Any = meta["rosbag2_bagfile_information"]
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value

    return mutate


def _drop(key: str):
    return lambda meta: meta["rosbag2_bagfile_information"].pop(key)


TOPIC = ("topics_with_message_count", 0, "topic_metadata")
WRONG_METADATA = {
    "string for a number": (
        _set(("duration", "nanoseconds"), "abc"),
        "rosbag2_bagfile_information.duration.nanoseconds: expected an integer, got 'abc'",
    ),
    "list for a map": (_set(("duration",), [1, 2]), "rosbag2_bagfile_information.duration: expected a mapping"),
    "empty relative_file_paths": (
        _set(("relative_file_paths",), []),
        "rosbag2_bagfile_information.relative_file_paths is empty",
    ),
    "map for the file list": (
        _set(("relative_file_paths",), {"a": 1}),
        "relative_file_paths: expected a list of file names, got {'a': 1}",
    ),
    "string for topic_metadata": (
        _set(TOPIC, "x"),
        "topics_with_message_count[0].topic_metadata: expected a mapping, got 'x'",
    ),
    "number for a topic name": (_set((*TOPIC, "name"), 5), "topic_metadata.name: expected a topic name, got 5"),
    "list for a count": (
        _set(("topics_with_message_count", 0, "message_count"), []),
        "topics_with_message_count[0].message_count: expected an integer, got []",
    ),
    "start past int64": (
        _set(("starting_time", "nanoseconds_since_epoch"), 10**30),
        "starting_time.nanoseconds_since_epoch: 1000000000000000000000000000000 is out of range",
    ),
    "boolean for a count": (_set(("message_count",), True), "message_count: expected an integer, got True"),
    "no message_count": (_drop("message_count"), "rosbag2_bagfile_information.message_count is missing"),
    "offered QoS not profiles": (
        _set((*TOPIC, "offered_qos_profiles"), "- 5"),
        "offered_qos_profiles: expected a list of QoS profiles, got [5]",
    ),
    "not a mapping at all": (lambda meta: meta.clear(), "rosbag2_bagfile_information is missing"),
}


@pytest.mark.parametrize("case", list(WRONG_METADATA))
def test_metadata_fields_of_the_wrong_kind_are_one_line_naming_the_file_and_field(tmp_path: Path, case: str) -> None:
    """Issue 48: a metadata.yaml field of the wrong kind (a string where a number is, a list where a map is)
    or an empty ``relative_file_paths`` was a traceback from ``ros2 bag info`` or ``play``; now one line names
    the file and the field, status 1."""
    import yaml

    mutate, said = WRONG_METADATA[case]
    bag = _bag(tmp_path / "bag", "std_msgs/msg/Int32")
    meta = yaml.safe_load((bag / "metadata.yaml").read_text())
    mutate(meta)
    (bag / "metadata.yaml").write_text(yaml.safe_dump(meta))
    for verb in ("info", "play"):
        out = subprocess.run([ROS2, "bag", verb, str(bag)], capture_output=True, text=True, timeout=60, env=_env())
        line = _one_line(out)
        assert line.startswith(f"[ERROR] [ros2bag]: {bag / 'metadata.yaml'}: ") and said in line, line


def test_a_5000_digit_integer_in_metadata_names_its_line(tmp_path: Path) -> None:
    """PyYAML converts an integer with ``int()``, whose limit (4,300 digits, ``sys.get_int_max_str_digits()``)
    raised a bare ValueError: a traceback. The bounded loader refuses a literal of over 1,000 characters with
    its line."""
    bag = _bag(tmp_path / "bag", "std_msgs/msg/Int32")
    lines = (bag / "metadata.yaml").read_text().splitlines()
    at = lines.index("  message_count: 1")
    lines[at] = "  message_count: " + "7" * 5000
    (bag / "metadata.yaml").write_text("\n".join(lines) + "\n")
    out = subprocess.run([ROS2, "bag", "info", str(bag)], capture_output=True, text=True, timeout=60, env=_env())
    said = f"[ERROR] [ros2bag]: {bag / 'metadata.yaml'}:{at + 1}: an integer of 5000 characters (at most 1000)"
    assert _one_line(out) == said


OVERRIDES = {
    "/crafted: {depth: " + "9" * 5000 + "}": ":1: an integer of 5000 characters (at most 1000)",
    "/crafted: {depth: 4294967296}": ": topic /crafted: `depth` 4294967296 is more than 2147483647",
    "/crafted: {depth: 1, deadline: {sec: 1e20, nsec: 0}}": (
        ": topic /crafted: deadline: sec and nsec must be whole numbers, got '1e20' and 0"
    ),
    "/crafted: {depth: 1, lifespan: {sec: 100000000000000000000, nsec: 0}}": (
        ": topic /crafted: lifespan: {sec: 100000000000000000000, nsec: 0} is longer than 9223372036854775807 ns"
    ),
    "/crafted: {depth: 1, avoid_ros_namespace_conventions: 7}": (
        ": topic /crafted: `avoid_ros_namespace_conventions` must be true or false, got 7"
    ),
}


@pytest.mark.parametrize(
    "text", list(OVERRIDES), ids=["5000 digits", "depth 2**32", "sec 1e20", "sec 10**20", "bool 7"]
)
def test_qos_override_values_past_what_rclpy_takes_are_one_line(tmp_path: Path, text: str) -> None:
    """Issue 48: ``--qos-profile-overrides-path`` with a 5,000-digit integer (PyYAML's ValueError), ``depth:
    4294967296`` (rclpy's TypeError when the publisher was made), a duration past int64 nanoseconds
    (OverflowError) or a non-boolean ``avoid_ros_namespace_conventions`` (AssertionError) was a traceback
    from ``ros2 bag play`` and ``record``; now one line names the file, the topic and the field."""
    overrides = tmp_path / "qos.yaml"
    overrides.write_text(text + "\n")
    bag = _bag(tmp_path / "bag", "std_msgs/msg/Int32")
    for argv in (["play", str(bag), "--wait", "0"], ["record", "-o", str(tmp_path / "rec"), "/crafted"]):
        out = subprocess.run(
            [ROS2, "bag", *argv, "--qos-profile-overrides-path", str(overrides)],
            capture_output=True,
            text=True,
            timeout=60,
            env=_env(),
        )
        assert _one_line(out).startswith(f"[ERROR] [ros2bag]: {overrides}{OVERRIDES[text]}"), out.stderr
    assert not (tmp_path / "rec").exists()

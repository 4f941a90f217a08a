"""gazelle's rosbag2 (``ros2 bag``) without a graph: the MCAP schemas it writes parse with two
independent readers, and bad bags are one-line errors."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

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

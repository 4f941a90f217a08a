"""`ros2 bag record | info | play` round trip on a driving robot, checked by an independent reader
(rosbags) and by a plain rclpy subscriber in a graph without the simulator."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import GAZELLE, SEED_XACRO, start, wait_for

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
LISTENER = str(Path(__file__).with_name("odom_listener.py"))


def ros2(*args: str, timeout: float = 60, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([ROS2, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd)


@pytest.mark.slow
def test_record_info_and_play_round_trip(sim_factory, ros_client, tmp_path):
    from rosbags.highlevel import AnyReader

    sim = sim_factory("--no-viewer")
    spawn = start([*GAZELLE, "spawn", "-entity", "bot", "-file", str(SEED_XACRO)], "spawn")
    assert spawn.wait(60) == 0, spawn.output
    drive = start(
        [
            ROS2,
            "topic",
            "pub",
            "-r",
            "10",
            "/cmd_vel",
            "geometry_msgs/msg/Twist",
            "{linear: {x: 0.3}, angular: {z: 0.2}}",
        ],
        "ros2 pub",
    )
    try:
        wait_for(lambda: ros_client.entity_state("bot").state.pose.position.x > 0.05, 30, "the robot to drive")
        rec = ros2("bag", "record", "-o", "B", "/odom", "/tf", "/clock", "--max-duration", "10", cwd=tmp_path)
    finally:
        drive.interrupt()
    assert rec.returncode == 0, rec.stdout + rec.stderr
    bag = tmp_path / "B"
    assert (bag / "metadata.yaml").is_file() and (bag / "B_0.mcap").is_file()

    info = ros2("bag", "info", str(bag))
    assert info.returncode == 0, info.stderr
    counts = {
        m.group(1): int(m.group(2)) for m in re.finditer(r"Topic: (\S+) \| Type: \S+ \| Count: (\d+)", info.stdout)
    }
    assert set(counts) == {"/odom", "/tf", "/clock"}, info.stdout
    assert counts["/odom"] > 300 and counts["/clock"] > 300, info.stdout  # ~100 Hz each for most of 10 s
    total = int(re.search(r"Messages:\s+(\d+)", info.stdout).group(1))  # type: ignore[union-attr]
    assert total == sum(counts.values())

    # an independent reader sees the same counts and decodes the same messages
    with AnyReader([bag]) as reader:
        assert {c.topic: c.msgcount for c in reader.connections} == counts
        odom = [c for c in reader.connections if c.topic == "/odom"]
        recorded = [reader.deserialize(raw, c.msgtype) for c, _t, raw in reader.messages(connections=odom)]
    assert len(recorded) == counts["/odom"]
    first, last = recorded[0], recorded[-1]
    assert last.pose.pose.position.x > first.pose.pose.position.x  # it was driving

    def key(m) -> tuple[int, float, float]:
        s = m.header.stamp
        return (s.sec * 1_000_000_000 + s.nanosec, m.pose.pose.position.x, m.pose.pose.position.y)

    # play into a graph without the simulator: a plain rclpy subscriber gets every message, in order
    assert sim.interrupt() == 0
    listener = start([sys.executable, LISTENER, str(len(recorded)), "10"], "odom listener")
    listener.wait_line("ready", 30)
    play = ros2("bag", "play", str(bag), "-r", "4", timeout=90)
    assert play.returncode == 0, play.stdout + play.stderr
    assert listener.wait(30) == 0
    got = [json.loads(line) for line in listener.lines if line.startswith("{")]
    assert [(g["stamp"], g["x"], g["y"]) for g in got] == [key(m) for m in recorded]

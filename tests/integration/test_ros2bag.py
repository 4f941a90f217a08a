"""`ros2 bag record | info | play` round trip on a driving robot, checked by an independent reader
(rosbags) and by a plain rclpy subscriber in a graph without the simulator; meanwhile a Foxglove
client (`gazelle sim --foxglove`) watches the same robot."""

from __future__ import annotations

import json
import math
import re
import socket
import struct
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from _harness import GAZELLE, SEED_XACRO, run_or_dump, start, wait_for
from nav_msgs.msg import Odometry
from rclpy.serialization import deserialize_message
from websockets.exceptions import InvalidStatus
from websockets.sync.client import connect
from websockets.typing import Subprotocol

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
LISTENER = str(Path(__file__).with_name("odom_listener.py"))
PROTOCOL = "foxglove.sdk.v1"
MESSAGE_DATA = 0x01
"""Foxglove server binary opcode: uint8 op, uint32 subscription id, uint64 receive time (ns), the message."""


def ros2(*args: str, timeout: float = 60, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return run_or_dump([ROS2, *args], timeout, cwd)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.slow
def test_record_info_and_play_round_trip_with_a_foxglove_client_watching(sim_factory, ros_client, tmp_path):
    """One driving robot for both (a simulator started once): `gazelle sim --foxglove` serves a Foxglove
    client while `ros2 bag record` records."""
    from rosbags.highlevel import AnyReader

    port = _free_port()
    sim = sim_factory("--no-viewer", "--foxglove", str(port))
    sim.wait_line(f"Foxglove bridge at ws://127.0.0.1:{port}", 30)
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
        rec = subprocess.Popen(
            [ROS2, "bag", "record", "-o", "B", "/odom", "/tf", "/clock", "--max-duration", "5"],
            cwd=tmp_path,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        _foxglove_client_checks(port)  # while it records
        rec_out, _ = rec.communicate(timeout=60)
    finally:
        drive.interrupt()
    assert rec.returncode == 0, rec_out
    bag = tmp_path / "B"
    assert (bag / "metadata.yaml").is_file() and (bag / "B_0.mcap").is_file()

    info = ros2("bag", "info", str(bag))
    assert info.returncode == 0, info.stderr
    counts = {
        m.group(1): int(m.group(2)) for m in re.finditer(r"Topic: (\S+) \| Type: \S+ \| Count: (\d+)", info.stdout)
    }
    assert set(counts) == {"/odom", "/tf", "/clock"}, info.stdout
    assert counts["/odom"] > 150 and counts["/clock"] > 150, info.stdout  # ~100 Hz each for most of 5 s
    total = int(re.search(r"Messages:\s+(\d+)", info.stdout).group(1))  # type: ignore[union-attr]
    assert total == sum(counts.values())

    # an independent reader sees the same counts and decodes the same messages
    with AnyReader([bag]) as reader:
        assert {c.topic: c.msgcount for c in reader.connections} == counts
        odom = [c for c in reader.connections if c.topic == "/odom"]
        recorded: list[Any] = [reader.deserialize(raw, c.msgtype) for c, _t, raw in reader.messages(connections=odom)]
    assert len(recorded) == counts["/odom"]
    first, last = recorded[0], recorded[-1]
    # it was driving (on a circle of 1.5 m radius: x alone can shrink), and the stamps are sim time in order
    moved = math.hypot(
        last.pose.pose.position.x - first.pose.pose.position.x, last.pose.pose.position.y - first.pose.pose.position.y
    )
    assert moved > 0.05, f"the robot moved {moved:.3f} m while recorded"
    stamps = [m.header.stamp.sec * 1_000_000_000 + m.header.stamp.nanosec for m in recorded]
    assert stamps == sorted(stamps) and len(set(stamps)) == len(stamps)

    def key(m) -> tuple[int, float, float]:
        s = m.header.stamp
        return (s.sec * 1_000_000_000 + s.nanosec, m.pose.pose.position.x, m.pose.pose.position.y)

    # play into a graph without the simulator: a plain rclpy subscriber gets every message, in order
    assert sim.interrupt() == 0
    listener = start([sys.executable, LISTENER, str(len(recorded)), "10"], "odom listener")
    listener.wait_line("ready", 30)
    # --delay (rosbag2's own flag): the player starts 5 s after it looked for subscribers, so a loaded
    # machine's slow discovery does not lose the first messages (with none it once lost them all, with 2 s
    # the first 163: participant announcements come again only after some seconds)
    play = ros2("bag", "play", str(bag), "-r", "10", "--delay", "5", timeout=90)
    assert play.returncode == 0, play.stdout + play.stderr
    assert listener.wait(30) == 0
    got = [json.loads(line) for line in listener.lines if line.startswith("{")]
    assert [(g["stamp"], g["x"], g["y"]) for g in got] == [key(m) for m in recorded]


def _foxglove_client_checks(port: int) -> None:
    """A client speaking the Foxglove WebSocket protocol sees /odom advertised with its schema, subscribes
    and decodes the CDR it gets; a page from a foreign origin is refused, the Foxglove app's accepted."""
    url = f"ws://127.0.0.1:{port}"
    with connect(url, subprotocols=[Subprotocol(PROTOCOL)], max_size=None) as ws:
        assert ws.subprotocol == PROTOCOL
        channels: dict[str, dict] = {}
        deadline = time.monotonic() + 20
        while "/odom" not in channels:
            assert time.monotonic() < deadline, f"/odom never advertised (got {sorted(channels)})"
            frame = ws.recv(timeout=10)
            if isinstance(frame, str):
                op = json.loads(frame)
                if op["op"] == "advertise":
                    channels.update({c["topic"]: c for c in op["channels"]})
        odom = channels["/odom"]
        assert (odom["encoding"], odom["schemaEncoding"], odom["schemaName"]) == (
            "cdr",
            "ros2msg",
            "nav_msgs/msg/Odometry",
        )
        assert "MSG: geometry_msgs/PoseWithCovariance" in odom["schema"]
        ws.send(json.dumps({"op": "subscribe", "subscriptions": [{"id": 3, "channelId": odom["id"]}]}))
        decoded: list[Odometry] = []
        deadline = time.monotonic() + 20
        while len(decoded) < 5:
            assert time.monotonic() < deadline, "no /odom messages"
            frame = ws.recv(timeout=10)
            if isinstance(frame, bytes) and frame[0] == MESSAGE_DATA:
                subscription, _received_ns = struct.unpack_from("<IQ", frame, 1)
                assert subscription == 3
                decoded.append(deserialize_message(frame[13:], Odometry))
    assert all(m.header.frame_id == "odom" and m.child_frame_id == "base_link" for m in decoded)
    stamps = [m.header.stamp.sec + m.header.stamp.nanosec * 1e-9 for m in decoded]
    assert stamps == sorted(stamps) and stamps[-1] > stamps[0]

    # a web page elsewhere may not connect; the Foxglove web app may
    with pytest.raises(InvalidStatus) as refused:
        connect(url, subprotocols=[PROTOCOL], origin="http://evil.example")  # pyright: ignore[reportArgumentType]
    assert refused.value.response.status_code == 403
    with connect(url, subprotocols=[PROTOCOL], origin="https://app.foxglove.dev") as ws:  # pyright: ignore[reportArgumentType]
        assert json.loads(ws.recv(timeout=10))["op"] == "serverInfo"

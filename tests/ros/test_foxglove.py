"""`gazelle sim --foxglove`: a client speaking the Foxglove WebSocket protocol subscribes to /odom and
decodes the CDR it gets with the advertised schema; a page from a foreign origin is refused."""

from __future__ import annotations

import json
import socket
import struct
import time

import pytest
from nav_msgs.msg import Odometry
from rclpy.serialization import deserialize_message
from websockets.exceptions import InvalidStatus
from websockets.sync.client import connect

from .conftest import GAZELLE, SEED_XACRO, start

PROTOCOL = "foxglove.sdk.v1"
MESSAGE_DATA = 0x01
"""Server binary opcode: uint8 op, uint32 subscription id, uint64 receive time (ns), then the message."""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.slow
def test_a_foxglove_client_gets_odom_and_foreign_origins_are_refused(sim_factory):
    port = _free_port()
    sim = sim_factory("--no-viewer", "--foxglove", str(port))
    sim.wait_line(f"Foxglove bridge at ws://127.0.0.1:{port}", 30)
    spawn = start([*GAZELLE, "spawn", "-entity", "bot", "-file", str(SEED_XACRO)], "spawn")
    assert spawn.wait(60) == 0, spawn.output

    url = f"ws://127.0.0.1:{port}"
    with connect(url, subprotocols=[PROTOCOL], max_size=None) as ws:
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

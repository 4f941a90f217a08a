"""Issue 25's payloads sent as a ROS peer (or a web page) would, to a real `gazelle sim` / `gazelle foxglove`
process; each test checks the refusal and that the server still answers afterwards."""

from __future__ import annotations

import os
import re
import socket
import ssl
import time
from pathlib import Path

import pytest
from _harness import GAZELLE, start
from _paths import REAL
from gazebo_msgs.srv import GetModelList
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import SetParameters
from simulation_interfaces.msg import Result
from simulation_interfaces.srv import GetEntities
from websockets.exceptions import ConnectionClosed, InvalidMessage
from websockets.sync.client import connect

DIFFBOT_URDF = REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf"
PROTOCOL = "foxglove.sdk.v1"


def _string(name: str, value: str) -> Parameter:
    return Parameter(name=name, value=ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=value))


def _still_answers(ros_client) -> None:
    res = ros_client.call(GetModelList, "/get_model_list", GetModelList.Request(), timeout=10)
    assert res.success


@pytest.mark.slow
def test_a_peer_cannot_make_the_controller_manager_read_a_file(sim_factory, ros_client, tmp_path: Path) -> None:
    sim = sim_factory("--no-viewer")
    spawn = start([*GAZELLE, "spawn", "-entity", "diffbot", "-file", str(DIFFBOT_URDF), "-z", "0.05"], "spawn")
    assert spawn.wait(60) == 0, spawn.output
    sim.wait_line("controller manager '/controller_manager'", 10)
    secret = tmp_path / "shadow"
    secret.write_text("root:*:19000:0:99999:7:::\n")
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    for path in (str(secret), "/etc/passwd", str(fifo)):
        start_t = time.monotonic()
        res = ros_client.call(
            SetParameters,
            "/controller_manager/set_parameters",
            SetParameters.Request(parameters=[_string("evil.params_file", path)]),
            resend_every=2.0,
        )
        assert time.monotonic() - start_t < 7.0
        (result,) = res.results
        assert not result.successful
        assert "not in a package or model folder gazelle may read" in result.reason
        assert "root:" not in result.reason
    assert "root:*" not in sim.output and "root:x" not in sim.output
    _still_answers(ros_client)


@pytest.mark.slow
def test_a_regex_bomb_filter_is_refused_and_the_server_keeps_its_clock(sim_factory, ros_client) -> None:
    sim_factory("--no-viewer")
    for pattern in ("a{4294967294}", "(?:(?:a{100}){100}){100}"):
        req = GetEntities.Request()
        req.filters.filter = pattern
        start_t = time.monotonic()
        res = ros_client.call(GetEntities, "/gazelle/get_entities", req, timeout=30)
        assert time.monotonic() - start_t < 10.0
        if res.result.result != Result.RESULT_OK:
            assert "filters.filter" in res.result.error_message
    req = GetEntities.Request()
    req.filters.filter = "^ground"
    res = ros_client.call(GetEntities, "/gazelle/get_entities", req)
    assert res.result.result == Result.RESULT_OK and res.entities == ["ground_plane"]
    _still_answers(ros_client)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.slow
def test_foxglove_private_server_refuses_a_direct_connection_and_the_proxy_bounds_frames() -> None:
    port = _free_port()
    fox = start([*GAZELLE, "foxglove", "--port", str(port)], "gazelle foxglove")
    try:
        fox.wait_line(f"Foxglove bridge at ws://127.0.0.1:{port}", 30)
        upstream = int(re.search(r"Started server on 127\.0\.0\.1:(\d+)", fox.output).group(1))  # type: ignore[union-attr]
        # through the proxy: the server's greeting
        with connect(f"ws://127.0.0.1:{port}", subprotocols=[PROTOCOL], open_timeout=10) as ws:  # type: ignore[list-item]
            assert '"serverInfo"' in str(ws.recv(timeout=10))
        # around it, as a page that found the port would: no plain websocket, no trusted TLS
        with pytest.raises((OSError, InvalidMessage, TimeoutError)):  # no websocket handshake in plain text
            with connect(f"ws://127.0.0.1:{upstream}", subprotocols=[PROTOCOL], open_timeout=5) as ws:  # type: ignore[list-item]
                ws.recv(timeout=5)
        with pytest.raises(ssl.SSLError):
            with connect(f"wss://127.0.0.1:{upstream}", subprotocols=[PROTOCOL], open_timeout=5) as ws:  # type: ignore[list-item]
                ws.recv(timeout=5)
        # a frame over the bound closes that client; the next is served
        with connect(f"ws://127.0.0.1:{port}", subprotocols=[PROTOCOL], open_timeout=10, max_size=None) as ws:  # type: ignore[list-item]
            ws.recv(timeout=10)
            ws.send(b"\0" * (17 << 20))
            with pytest.raises(ConnectionClosed) as closed:
                deadline = time.monotonic() + 10
                while time.monotonic() < deadline:
                    ws.recv(timeout=10)  # advertisements, until the proxy closes
            assert closed.value.rcvd is not None and closed.value.rcvd.code == 1009  # message too big
        with connect(f"ws://127.0.0.1:{port}", subprotocols=[PROTOCOL], open_timeout=10) as ws:  # type: ignore[list-item]
            assert '"serverInfo"' in str(ws.recv(timeout=10))
    finally:
        assert fox.interrupt() == 0, fox.output

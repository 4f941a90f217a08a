"""Who reaches `gazelle sim` over ROS: this machine by default, and one server per ROS domain."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from _harness import GAZELLE, start

pytestmark = pytest.mark.ros

FRESH_CLIENT = """
import rclpy
from gazebo_msgs.srv import GetModelList
rclpy.init()
node = rclpy.create_node("fresh_shell_client")
client = node.create_client(GetModelList, "/get_model_list")
assert client.wait_for_service(timeout_sec=30), "no /get_model_list"
future = client.call_async(GetModelList.Request())
rclpy.spin_until_future_complete(node, future, timeout_sec=30)
print("MODELS", list(future.result().model_names))
"""


def _fresh_env() -> dict[str, str]:
    """A shell with no ROS variables but the run's domain (so parallel test runs stay apart)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("ROS_", "RMW_"))}
    env["ROS_DOMAIN_ID"] = os.environ["ROS_DOMAIN_ID"]
    return env


def test_the_server_limits_discovery_to_this_machine_yet_a_fresh_shells_node_reaches_it():
    proc = start([*GAZELLE, "sim", "--no-viewer"], "gazelle sim", env=_fresh_env())
    ready = proc.wait_line("gazelle: ready", timeout=60)
    assert "discovery LOCALHOST (default of gazelle sim" in ready
    out = subprocess.run(
        [sys.executable, "-c", FRESH_CLIENT], env=_fresh_env(), capture_output=True, text=True, timeout=90
    )
    assert "MODELS ['ground_plane']" in out.stdout, out.stdout + out.stderr
    assert proc.interrupt() == 0


def test_the_discovery_range_is_the_users_choice_when_set():
    env = dict(_fresh_env(), ROS_AUTOMATIC_DISCOVERY_RANGE="SUBNET")
    proc = start([*GAZELLE, "sim", "--no-viewer"], "gazelle sim", env=env)
    assert "ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET (from the environment)" in proc.wait_line("gazelle: ready", timeout=60)
    assert proc.interrupt() == 0


def test_a_second_server_on_the_same_domain_stops_and_says_why(ros_client):
    from gazebo_msgs.srv import GetModelList

    first = start([*GAZELLE, "sim", "--no-viewer"], "gazelle sim")
    first.wait_line("gazelle: ready", timeout=60)
    second = start([*GAZELLE, "sim", "--no-viewer"], "gazelle sim (second)")
    assert second.wait(60) == 1
    assert "another gazelle sim already serves ROS_DOMAIN_ID" in second.output, second.output
    assert f"pid {first.popen.pid}" in second.output
    # the first keeps serving, alone
    assert ros_client.call(GetModelList, "/get_model_list", GetModelList.Request()).success
    assert first.popen.poll() is None
    assert first.interrupt() == 0

"""Controllers are ROS nodes (issue 50 item 5): in ros2_control every controller is a lifecycle node named as the
controller, holding its parameters (controller_interface_base.cpp ``init``: ``update_rate``, ``is_async``,
``thread_priority``, then the controller's own). ``ros2 param get /diffbot_base_controller wheel_separation`` said
"Node not found" before; now it reads the value the controllers YAML gave, ``ros2 param set`` sets it, and a
read-only parameter (ros2_controllers' ``read_only: true``) or a value of the wrong type is refused with its reason.
The real diffbot of ros2_control_demos with its own YAML, through gazelle's spawner."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from _harness import run_or_dump, wait_for

from .test_ros2_control import _spawn_diffbot, _spawner

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")


def ros2(*args: str) -> subprocess.CompletedProcess:
    return run_or_dump([ROS2, *args], 60)


@pytest.mark.slow
def test_each_controller_is_a_node_whose_parameters_ros2_param_reads_and_sets(sim_factory):
    sim = sim_factory("--no-viewer")
    _spawn_diffbot(sim)
    rc, out = _spawner("joint_state_broadcaster", "diffbot_base_controller")
    assert rc == 0, out

    nodes = ros2("node", "list").stdout.split()
    assert {"/diffbot_base_controller", "/joint_state_broadcaster", "/controller_manager"} <= set(nodes), nodes

    got = ros2("param", "get", "/diffbot_base_controller", "wheel_separation")
    assert got.returncode == 0, got.stderr
    assert got.stdout.strip() == "Double value is: 0.1", got.stdout  # the YAML's 0.10
    # the parameters every controller's node has (controller_interface_base.cpp), and a default the YAML leaves out
    listed = ros2("param", "list", "/diffbot_base_controller").stdout.split()
    assert {"update_rate", "is_async", "thread_priority", "wheel_radius", "tf_frame_prefix_enable"} <= set(listed), (
        listed
    )
    assert ros2("param", "get", "/diffbot_base_controller", "is_async").stdout.strip() == "Boolean value is: False"

    done = ros2("param", "set", "/diffbot_base_controller", "wheel_separation", "0.2")
    assert done.returncode == 0 and done.stdout.strip() == "Set parameter successful", done.stdout + done.stderr
    got = ros2("param", "get", "/diffbot_base_controller", "wheel_separation")
    assert got.stdout.strip() == "Double value is: 0.2", got.stdout

    wrong = ros2("param", "set", "/diffbot_base_controller", "wheel_separation", "wide")
    assert "Setting parameter failed" in wrong.stdout + wrong.stderr, wrong.stdout + wrong.stderr
    assert "is a double; a string cannot be set" in wrong.stdout + wrong.stderr
    # joint_state_broadcaster's joints are read_only in its parameters YAML (ros2_controllers jazzy)
    ro = ros2("param", "set", "/joint_state_broadcaster", "joints", "[left_wheel_joint]")
    assert "Setting parameter failed" in ro.stdout + ro.stderr, ro.stdout + ro.stderr
    assert "read-only" in ro.stdout + ro.stderr

    # unloaded, its node goes
    rc, out = _spawner_unload("diffbot_base_controller")
    assert rc == 0, out
    wait_for(lambda: "/diffbot_base_controller" not in ros2("node", "list").stdout.split(), 20, "the node gone")


def _spawner_unload(name: str) -> tuple[int, str]:
    from _harness import GAZELLE, start

    proc = start([*GAZELLE, "unspawner", name], "unspawner")
    return proc.wait(60), proc.output

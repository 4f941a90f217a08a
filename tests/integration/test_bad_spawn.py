"""Bad input gets a one-line error naming file:line or the request field; the server stays up."""

from __future__ import annotations

import os
import time

import pytest
from _harness import GAZELLE, REPO, SEED_XACRO, start, wait_for, xacro_to_urdf
from _ros_domain import empty_domain_id
from gazebo_msgs.srv import DeleteEntity, GetModelList, SpawnEntity
from rosgraph_msgs.msg import Clock

MISSING_PARENT = """<?xml version="1.0"?>
<robot name="broken">
  <link name="base"/>
  <link name="arm"/>
  <joint name="j" type="fixed">
    <parent link="bse"/>
    <child link="arm"/>
  </joint>
</robot>
"""

MALFORMED = """<?xml version="1.0"?>
<robot name="broken">
  <link name="base">
    <visual>
  </link>
</robot>
"""


def _spawn(ros_client, name: str, xml: str, reference_frame: str = "") -> SpawnEntity.Response:
    req = SpawnEntity.Request(name=name, xml=xml, reference_frame=reference_frame)
    return ros_client.call(SpawnEntity, "/spawn_entity", req)


def _one_line(message: str) -> str:
    assert "\n" not in message.strip(), f"error is not one line: {message!r}"
    assert "Traceback" not in message
    return message


def test_bad_spawns_fail_clearly_and_the_server_keeps_running(sim_factory, ros_client, tmp_path):
    sim = sim_factory()

    res = _spawn(ros_client, "broken", MISSING_PARENT)
    assert not res.success
    msg = _one_line(res.status_message)
    assert "<spawn_entity:broken>:5: error: [JOINT_PARENT_INVALID]" in msg and "'bse'" in msg

    res = _spawn(ros_client, "broken", MALFORMED)
    assert not res.success
    msg = _one_line(res.status_message)
    assert "<spawn_entity:broken>:" in msg and "[XML_PARSE_ERROR]" in msg

    urdf = xacro_to_urdf(SEED_XACRO)
    res = _spawn(ros_client, "robot", urdf, reference_frame="no_such_frame")
    assert not res.success
    assert "reference_frame 'no_such_frame' not found" in _one_line(res.status_message)

    # the same mistakes through the CLI: exit 1 with the location, on one line
    bad = tmp_path / "bad_parent.urdf"
    bad.write_text(MISSING_PARENT)
    cli = start([*GAZELLE, "spawn", "-entity", "broken", "-file", str(bad), "-timeout", "20"], "gazelle spawn")
    assert cli.wait(60) == 1
    errors = [ln for ln in cli.lines if "[ERROR]" in ln]
    # the file's own name and line (the server got its text as it is): not <spawn_entity:broken>:5 (issue 50 item 3)
    assert len(errors) == 1 and f"{bad}:5: error: [JOINT_PARENT_INVALID]" in errors[0], cli.output
    assert "Traceback" not in cli.output

    missing = start([*GAZELLE, "spawn", "-entity", "x", "-file", str(tmp_path / "nope.urdf")], "gazelle spawn")
    assert missing.wait(30) == 1
    assert "does not exist" in missing.output and "Traceback" not in missing.output

    # the server is alive: /clock still advances, and the next valid spawn works
    seen: list[float] = []
    ros_client.node.create_subscription(
        Clock, "/clock", lambda m: seen.append(m.clock.sec + m.clock.nanosec * 1e-9), 10
    )
    wait_for(lambda: len(seen) > 5 and seen[-1] > seen[0], 10, "/clock to advance after the bad requests")
    res = _spawn(ros_client, "robot", urdf)
    assert res.success, res.status_message
    names = ros_client.call(GetModelList, "/get_model_list", GetModelList.Request()).model_names
    assert "robot" in names and "broken" not in names

    # a duplicate name is refused and leaves the first robot (and its topics) alone
    res = _spawn(ros_client, "robot", urdf)
    assert not res.success and "already exists" in _one_line(res.status_message)
    res = ros_client.call(DeleteEntity, "/delete_entity", DeleteEntity.Request(name="ghost"))
    assert not res.success and "ghost" in res.status_message
    assert sim.popen.poll() is None
    assert "Traceback" not in sim.output


def test_spawn_times_out_cleanly_without_a_server(tmp_path):
    # no `gazelle sim` in this domain: the CLI must not hang
    proc = start(
        [
            *GAZELLE,
            "spawn",
            "-entity",
            "r",
            "-file",
            str(REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"),
            "-timeout",
            "2",
        ],
        "gazelle spawn",
        env={**os.environ, "ROS_DOMAIN_ID": str(empty_domain_id())},
    )
    assert proc.wait(30) == 1
    assert "unavailable" in proc.output


@pytest.mark.parametrize("flag", ["-file", "-topic"])
def test_spawn_arguments_are_checked(flag):
    proc = start([*GAZELLE, "spawn", flag], "gazelle spawn")
    assert proc.wait(30) == 2
    assert "usage: gazelle spawn" in proc.output


RCE = (
    '<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="p" value="'
    "${python.vars(python.type(()).mro()[-1])['__getattribute__'](xacro.load_yaml, '__globals__')"
    "['os'].system('id > %s')}\"/><link name=\"a\"/></robot>"
)
POWER_BOMB = '<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="p" value="${9**9**9}"/><link name="b${p}"/></robot>'


def test_descriptions_from_the_wire_are_data_never_code(sim_factory, ros_client, tmp_path):
    """The RCE payload, a file read and the power bomb, through every way a string reaches the server."""
    from simulation_interfaces.srv import SpawnEntity as SiSpawnEntity

    sim_factory()
    marker = tmp_path / "pwned"
    payloads = [RCE % marker, POWER_BOMB, '<robot name="x"><link name="${xacro.load_yaml(\'/etc/passwd\')}"/></robot>']
    for xml in payloads:
        t0 = time.monotonic()
        res = _spawn(ros_client, "x", xml)
        assert time.monotonic() - t0 < 5.0
        assert not res.success and "[XACRO_NOT_ALLOWED]" in res.status_message, res.status_message
        assert "expand it first" in res.status_message and "root:" not in res.status_message
        req = SiSpawnEntity.Request(name="x", resource_string=xml)
        si = ros_client.call(SiSpawnEntity, "/gazelle/spawn_entity", req)
        assert si.result.result == SiSpawnEntity.Response.RESOURCE_PARSE_ERROR, si.result.error_message
        assert "[XACRO_NOT_ALLOWED]" in si.result.error_message
    # gazelle spawn -string / -stdin send the string as it is: the server refuses it the same way
    cli = start([*GAZELLE, "spawn", "-entity", "x", "-string", RCE % marker, "-timeout", "20"], "gazelle spawn")
    assert cli.wait(60) == 1 and "XACRO_NOT_ALLOWED" in cli.output, cli.output
    assert not marker.exists()
    names = ros_client.call(GetModelList, "/get_model_list", GetModelList.Request()).model_names
    assert "x" not in names
    # and the server answers at once: a real spawn right after works
    assert _spawn(ros_client, "robot", xacro_to_urdf(SEED_XACRO)).success


def test_spawn_from_a_silent_topic_says_who_publishes_it(ros_client):
    from rclpy.qos import QoSProfile
    from std_msgs.msg import String

    proc = start([*GAZELLE, "spawn", "-entity", "r", "-topic", "robot_description", "-timeout", "2"], "gazelle spawn")
    assert proc.wait(30) == 1
    assert "no node publishes /robot_description" in proc.output and "-file" in proc.output, proc.output
    # a volatile publisher (a common mistake): named, and told to latch
    pub = ros_client.node.create_publisher(String, "/robot_description", QoSProfile(depth=1))
    assert pub is not None
    proc = start([*GAZELLE, "spawn", "-entity", "r", "-topic", "robot_description", "-timeout", "3"], "gazelle spawn")
    assert proc.wait(30) == 1
    assert "/test_client publishes /robot_description but not latched" in proc.output, proc.output

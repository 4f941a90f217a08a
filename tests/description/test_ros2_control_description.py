"""<ros2_control> blocks in URDF (issue 13, description part): read into typed dataclasses, each
unknown joint named with its file:line, and spawn/check saying the block is not simulated yet."""

from __future__ import annotations

import logging
import math

from _paths import REAL

from gazelle.description import ErrorCode, load, load_string
from gazelle.systems import audit_model

DIFFBOT = REAL / "ros2_control_diffbot" / "_xacro_expanded" / "diffbot.urdf"
R6BOT = REAL / "ros2_control_r6bot" / "ros2_control_demo_example_7" / "urdf" / "r6bot.urdf.xacro"
PANDA = REAL / "moveit_panda" / "_xacro_expanded" / "panda_moveit_config.urdf"


def test_the_diffbot_block_keeps_its_hardware_and_interfaces():
    model = load(DIFFBOT).model
    (rc,) = model.ros2_control
    assert (rc.name, rc.type, rc.hardware_plugin) == (
        "DiffBot",
        "system",
        "ros2_control_demo_example_2/DiffBotSystemHardware",
    )
    assert not rc.simulated  # a real robot's driver: the simulator stands in for it
    assert dict(rc.hardware_params) == {
        "example_param_hw_start_duration_sec": "0",
        "example_param_hw_stop_duration_sec": "3.0",
    }
    assert [j.name for j in rc.joints] == ["left_wheel_joint", "right_wheel_joint"]
    for j in rc.joints:
        assert [c.name for c in j.command_interfaces] == ["velocity"]
        assert [s.name for s in j.state_interfaces] == ["position", "velocity"]
    assert rc.location is not None and rc.location.line == 164


def test_r6bot_limits_and_initial_values_come_through_xacro(resource_path):
    resource_path("ros2_control_r6bot")
    (rc,) = load(R6BOT).model.ros2_control
    assert [j.name for j in rc.joints] == [f"joint_{i}" for i in range(1, 7)]
    j1 = rc.joints[0]
    pos, vel = j1.command_interfaces
    assert (pos.name, pos.param("min"), pos.param("max")) == ("position", str(-2 * math.pi), str(2 * math.pi))
    assert (vel.name, vel.param("min"), vel.param("max")) == ("velocity", "-3.15", "3.15")
    assert j1.state_interfaces[0].param("initial_value") == "0.0"
    assert j1.state_interfaces[1].param("initial_value") is None


def test_pandas_mock_hardware_is_a_simulated_system():
    blocks = load(PANDA).model.ros2_control
    assert [(rc.name, rc.hardware_plugin, rc.simulated) for rc in blocks] == [
        ("PandaFakeSystem", "mock_components/GenericSystem", True),
        ("PandaHandFakeSystem", "mock_components/GenericSystem", True),
    ]
    assert [j.name for j in blocks[0].joints] == [f"panda_joint{i}" for i in range(1, 8)]


BAD = """<?xml version="1.0"?>
<robot name="r">
  <link name="a"/><link name="b"/>
  <joint name="j" type="continuous"><parent link="a"/><child link="b"/></joint>
  <ros2_control name="hw" type="system">
    <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
    <joint name="j"><command_interface name="effort"/><state_interface name="position"/></joint>
    <joint name="nope"><command_interface name="velocity"/></joint>
  </ros2_control>
</robot>"""


def test_a_joint_the_robot_lacks_is_named_with_its_line_and_left_out():
    result = load_string(BAD)
    bad = [d for d in result.diagnostics if d.code is ErrorCode.CONTROL_JOINT_INVALID]
    assert len(bad) == 1 and bad[0].location is not None and bad[0].location.line == 8
    assert "joint 'nope' is not a joint of the robot (it has j)" in bad[0].message
    (rc,) = result.model.ros2_control
    assert rc.simulated and [j.name for j in rc.joints] == ["j"]


def test_spawn_runs_a_controller_manager_and_names_the_real_driver_it_stands_in_for(caplog, make_sim):
    from gazelle.systems.ros2_control import ControllerManager

    model = load(DIFFBOT).model
    assert not [p for p in audit_model(model) if "ros2_control" in p.format()]  # simulated: nothing to warn of
    sim = make_sim()
    with caplog.at_level(logging.INFO):
        entity = sim.spawn(model, name="diffbot")
    (manager,) = [s for s in entity.systems if isinstance(s, ControllerManager)]
    assert manager.node_name == "/controller_manager"
    assert sorted(manager.all_command_interfaces()) == ["left_wheel_joint/velocity", "right_wheel_joint/velocity"]
    messages = [r.getMessage() for r in caplog.records]
    assert any("'ros2_control_demo_example_2/DiffBotSystemHardware' is a real robot's driver" in m for m in messages)


def test_an_unknown_block_type_is_a_warning():
    result = load_string(BAD.replace('type="system"', 'type="robot"'))
    assert any("has type 'robot' (system, actuator or sensor)" in d.message for d in result.diagnostics)

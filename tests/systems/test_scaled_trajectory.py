"""Universal Robots' ``ur_controllers/ScaledJointTrajectoryController`` (issue 51 item 3), in-process on ros2_control
demos' r6bot: its trajectory time runs at the speed scaling factor it reads from the hardware
(ur_controllers jazzy, scaled_joint_trajectory_controller.cpp ``update()``: ``traj_time_ += period *
scaling_factor_``), and without such an interface (gz_ros2_control's hardware, which UR's Gazebo simulation runs) it is
joint_trajectory_controller, cycle for cycle. gazelle did not have the type: "does not exist"."""

from __future__ import annotations

import logging

import pytest
from _paths import REAL
from _sim import new_simulation

from gazelle.description import load_string
from gazelle.systems import JointTrajectory, TrajectoryPoint
from gazelle.systems.ros2_control import ControllerManager, JointTrajectoryController, TrajectoryGoal, parse_params

R6BOT = REAL / "ros2_control_r6bot"
URDF = R6BOT / "_xacro_expanded" / "r6bot.urdf"
JOINTS = tuple(f"joint_{i}" for i in range(1, 7))
SCALING = "speed_scaling/speed_scaling_factor"
YAML = """
controller_manager:
  ros__parameters:
    update_rate: 100
arm:
  ros__parameters:
    type: {type}
    joints: [joint_1, joint_2, joint_3, joint_4, joint_5, joint_6]
    command_interfaces: [position]
    state_interfaces: [position, velocity]
"""
# UR's driver's ros2_control block names its scaling interface so (ur_robot_driver's ur.ros2_control.xacro: a
# speed_scaling component with state interface speed_scaling_factor)
SENSOR = '<sensor name="speed_scaling"><state_interface name="speed_scaling_factor"/></sensor></ros2_control>'


def _arm(monkeypatch, kind: str, scaling_interface: bool):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(R6BOT))
    text = URDF.read_text()
    if scaling_interface:
        text = text.replace("</ros2_control>", SENSOR, 1)
    sim = new_simulation()
    entity = sim.spawn(load_string(text, source=str(URDF)).model, name="r6bot")
    cm = next(s for s in entity.systems if isinstance(s, ControllerManager))
    cm.files.append(parse_params(YAML.format(type=kind)))
    cm.update_rate = 100
    cm.load_controller("arm")
    cm.configure_controller("arm")
    cm.switch_controller(["arm"], [])
    ctrl = cm.controllers["arm"].controller
    assert isinstance(ctrl, JointTrajectoryController)
    return sim, cm, ctrl


def _goal(cm: ControllerManager) -> TrajectoryGoal:
    q0 = [cm.hardware[0].joints[j].handle.position for j in JOINTS]
    target = tuple(q + 0.4 for q in q0)
    return TrajectoryGoal(JointTrajectory(0.0, JOINTS, (TrajectoryPoint(1.0, target),)))


def _run(sim, goal: TrajectoryGoal, limit: float) -> float:
    """Step until the goal ends; the sim time it took from now."""
    t0 = sim.world.time
    while not goal.done.is_set() and sim.world.time - t0 < limit:
        sim.step(10)
    return sim.world.time - t0


def test_a_speed_scaling_of_one_half_makes_the_trajectory_take_twice_as_long(monkeypatch, caplog):
    """The hardware's speed_scaling/speed_scaling_factor at 0.5 (what UR's driver reports when the robot is slowed to
    half speed): a 1 s trajectory takes 2 s of sim time; its reference at 1 s of sim time is the trajectory's at
    0.5 s. The scaling interface is among the state interfaces the controller reads, as upstream's
    state_interface_configuration adds it."""
    caplog.set_level(logging.INFO)
    sim, cm, ctrl = _arm(monkeypatch, "ur_controllers/ScaledJointTrajectoryController", scaling_interface=True)
    assert SCALING in (ctrl.state_interfaces() or [])
    assert f"Using scaling state from the hardware from interface {SCALING}." in caplog.text
    cm.hardware[0].states[SCALING] = 0.5
    sim.step(100)
    goal = _goal(cm)
    ctrl.submit(goal)
    sim.step(1000)
    mid = ctrl.last_state
    assert mid is not None
    start = [p - 0.4 for p in goal.trajectory.points[-1].positions]
    # cubic-free (positions only): linear from the start to the point, half way at trajectory time 0.5 s
    assert list(mid.reference.positions) == pytest.approx([s + 0.2 for s in start], abs=5e-3)
    took = 1.0 + _run(sim, goal, 5.0)
    assert goal.status == "succeeded", goal.error_string
    assert took == pytest.approx(2.0, abs=0.03)


def test_a_speed_scaling_of_zero_holds_the_trajectory_until_it_is_raised(monkeypatch):
    """Factor 0 (UR's protective stop, or the pendant's speed slider at 0): the trajectory's time stands still and
    the arm holds; back at 1.0 it runs on from where it stood."""
    sim, cm, ctrl = _arm(monkeypatch, "ur_controllers/ScaledJointTrajectoryController", scaling_interface=True)
    hw = cm.hardware[0]
    sim.step(100)
    goal = _goal(cm)
    ctrl.submit(goal)
    sim.step(300)
    hw.states[SCALING] = 0.0
    sim.step(20)
    assert ctrl.last_state is not None
    held = ctrl.last_state.reference.positions
    sim.step(2000)
    assert ctrl.last_state.reference.positions == pytest.approx(held, abs=1e-9)  # the trajectory's time stood still
    # the arm at the command, which upstream samples one update period ahead of the reference (at 0.4 rad/s, 4 mrad)
    assert [hw.joints[j].handle.position for j in JOINTS] == pytest.approx(ctrl.last_state.output.positions, abs=1e-3)
    assert not goal.done.is_set()
    hw.states[SCALING] = 1.0
    assert _run(sim, goal, 3.0) == pytest.approx(0.7, abs=0.05)
    assert goal.status == "succeeded", goal.error_string


def test_without_a_scaling_interface_it_runs_as_joint_trajectory_controller_with_one_warning(monkeypatch, caplog):
    """No speed_scaling state interface (gz_ros2_control's GazeboSimSystem, UR's Gazebo simulation): the factor stays
    1.0, said once, and every joint of every cycle is what joint_trajectory_controller commands."""
    caplog.set_level(logging.WARNING)
    runs = {}
    for kind in (
        "ur_controllers/ScaledJointTrajectoryController",
        "joint_trajectory_controller/JointTrajectoryController",
    ):
        sim, cm, ctrl = _arm(monkeypatch, kind, scaling_interface=False)
        sim.step(100)
        goal = _goal(cm)
        ctrl.submit(goal)
        trace = []
        for _ in range(150):
            sim.step(10)
            trace.append(tuple(cm.hardware[0].joints[j].handle.position for j in JOINTS))
        assert goal.status == "succeeded", goal.error_string
        runs[kind] = trace
    scaled, plain = runs.values()
    assert scaled == plain
    assert caplog.text.count(f"the hardware has no state interface '{SCALING}'") == 1

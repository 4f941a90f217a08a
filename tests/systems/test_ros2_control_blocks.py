"""ros2_control's planned blocks: a 1 kHz controller manager whose cycles the world's steps run in compiled
code (issue 29) must give what its Python cycle gives, cycle for cycle.

r6bot (ros2_control_demos example 7) under joint_trajectory_controller and joint_state_broadcaster at
1 kHz, run twice from the same start: once with every cycle in Python (``blocks_allowed = False``, the
reference), once in blocks. Every /joint_states message (one per cycle) must agree within 1e-6 rad (they
are bit-identical today), goals must end the same way, and a path tolerance must abort at the same cycle
with the same message.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from _r6bot import JOINTS, R6BOT, URDF, arm


@pytest.fixture(autouse=True)
def _r6bot_resources(monkeypatch):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(R6BOT))


def _arm(blocks: bool):
    sim, cm = arm(blocks=blocks)
    heard: list = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/joint_states":
            ep.add_sink(heard.append)
    return sim, cm, cm.controllers["jtc"].controller, heard


def _points(kind: str):
    from gazelle.systems import TrajectoryPoint

    if kind == "jumps":
        # a segment faster than twice the joints' velocity limit (2.5 rad/s): each of its targets is a new
        # set point, which the hardware handles in Python (the blocks end before it), then slow ones again
        return (
            TrajectoryPoint(0.05, (0.4,) * 6),
            TrajectoryPoint(0.3, (0.3,) * 6),
            TrajectoryPoint(0.31, (-0.2,) * 6),
            TrajectoryPoint(0.9, (0.0,) * 6),
        )
    out = []
    for k in range(1, 9):
        t = 0.15 * k
        pos = tuple(0.4 * math.sin(t * (1 + 0.2 * i)) for i in range(6))
        vel = tuple(0.4 * (1 + 0.2 * i) * math.cos(t * (1 + 0.2 * i)) for i in range(6)) if kind != "linear" else ()
        acc = (
            tuple(-0.4 * (1 + 0.2 * i) ** 2 * math.sin(t * (1 + 0.2 * i)) for i in range(6))
            if kind == "quintic"
            else ()
        )
        out.append(TrajectoryPoint(t, pos, vel, acc))
    return tuple(out)


def _run(blocks: bool, kind: str, path_tolerance: float = 0.0, steps: int = 1600):
    from gazelle.systems import JointTrajectory
    from gazelle.systems.ros2_control import Tolerance, TrajectoryGoal

    sim, cm, jtc, heard = _arm(blocks)
    sim.step(137)  # the goal arrives at an odd time, inside what would be a block
    cm.settle()  # (what a service call or an action goal's arrival on the simulation thread does)
    goal = TrajectoryGoal(JointTrajectory(0.0, JOINTS, _points(kind)))
    if path_tolerance:
        goal.path_tolerance = {j: Tolerance(path_tolerance) for j in JOINTS}
    jtc.submit(goal)
    sim.step(steps)
    cm.settle()
    return heard, goal, cm


@pytest.mark.parametrize("kind", ["linear", "cubic", "quintic", "jumps"])
def test_blocks_track_a_goal_as_the_python_cycle_does_cycle_for_cycle(kind):
    ref, ref_goal, ref_cm = _run(False, kind)
    got, goal, cm = _run(True, kind)
    assert ref_cm.block_cycles == 0
    assert cm.block_cycles > 1000, "the blocks were not used"  # (not while the goal waits to stand still)
    assert len(got) == len(ref) == 1737  # one /joint_states per 1 ms cycle
    assert [m.stamp_sec for m in got] == [m.stamp_sec for m in ref]
    pos = np.array([m.positions for m in got])
    pos_ref = np.array([m.positions for m in ref])
    assert float(np.abs(pos - pos_ref).max()) <= 1e-6
    vel = np.array([m.velocities for m in got])
    assert float(np.abs(vel - np.array([m.velocities for m in ref])).max()) <= 1e-6
    # the arm really moved along the path, and both runs ended their goals alike
    assert float(np.ptp(pos_ref[:, 0])) > 0.3
    assert (goal.status, goal.error_code) == (ref_goal.status, ref_goal.error_code) == ("succeeded", 0)


def test_a_path_tolerance_aborts_at_the_same_cycle_with_the_same_message():
    from gazelle.systems.ros2_control import TrajectoryResult

    ref, ref_goal, _ = _run(False, "cubic", path_tolerance=2e-4, steps=600)
    got, goal, cm = _run(True, "cubic", path_tolerance=2e-4, steps=600)
    assert ref_goal.error_code == TrajectoryResult.PATH_TOLERANCE_VIOLATED
    assert (goal.status, goal.error_code, goal.error_string) == (
        ref_goal.status,
        ref_goal.error_code,
        ref_goal.error_string,
    )
    assert cm.block_cycles > 0
    # the same states before and after the abort (the arm holds where it was, in both)
    pos = np.array([m.positions for m in got])
    assert float(np.abs(pos - np.array([m.positions for m in ref])).max()) <= 1e-6


def test_the_vectorised_sample_is_the_scalar_sample_bit_for_bit():
    from gazelle.systems.ros2_control._segments import _Segmented

    rng = np.random.default_rng(3)
    times = [0.0, 0.3, 0.7, 1.2]
    pos = rng.normal(size=(4, 3)).tolist()
    vel = rng.normal(size=(4, 3)).tolist()
    acc = rng.normal(size=(4, 3)).tolist()
    t = np.concatenate([[-0.1, 0.0], np.add.accumulate(np.full(1300, 0.001)), [1.2, 5.0]])
    for seg in (
        _Segmented(times, pos, None, None, None),
        _Segmented(times, pos, vel, None, None),
        _Segmented(times, pos, vel, acc, None),
    ):
        many = seg.sample_many(t)
        for row, ti in enumerate(t.tolist()):
            one = seg.sample(ti)
            for got, want in zip(many, one, strict=True):
                assert got[row].tolist() == want, (ti, got[row].tolist(), want)


def test_blocks_clamp_a_goal_past_the_joints_limits_as_the_python_cycle_does():
    """A goal that takes joint_1 to 3.4 rad, past its upper limit (pi in the URDF): the blocks' planned commands
    are clamped to it as the Python cycle's are (issue 51 item 1), and both runs give the same joint states,
    joint_1 stopping at the limit. Without the clamp in ``plan_block`` the blocks commanded 3.4 rad."""
    from gazelle.systems import JointTrajectory, TrajectoryPoint
    from gazelle.systems.ros2_control import TrajectoryGoal

    runs = []
    for blocks in (False, True):
        sim, cm, jtc, heard = _arm(blocks)
        sim.step(100)
        points = (TrajectoryPoint(0.0, (0.0,) * 6), TrajectoryPoint(2.0, (3.4, 0.0, 0.0, 0.0, 0.0, 0.0)))
        jtc.submit(TrajectoryGoal(JointTrajectory(0.0, JOINTS, points)))
        highest = -10.0
        for _ in range(30):
            sim.step(100)
            cm.settle()
            highest = max(highest, cm.hardware[0].commands["joint_1/position"])
        runs.append((np.array([m.positions for m in heard]), highest, cm.block_cycles))
    (ref, ref_high, ref_blocks), (got, high, used) = runs
    assert ref_blocks == 0 and used > 1000, "the blocks were not used"
    assert ref_high == high == math.pi
    assert float(np.abs(got - ref).max()) <= 1e-6
    assert got[-1][0] == pytest.approx(math.pi, abs=1e-3)


def test_a_controller_state_listener_keeps_the_python_cycle():
    """~/controller_state is published every cycle from the cycle's own reference and error: with a
    listener, the cycles stay in Python (and give the same joint states)."""
    ref, _, _ = _run(False, "linear", steps=300)
    sim, cm, jtc, heard = _arm(True)
    states: list = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/jtc/controller_state":
            ep.add_sink(states.append)
    from gazelle.systems import JointTrajectory
    from gazelle.systems.ros2_control import TrajectoryGoal

    sim.step(137)
    jtc.submit(TrajectoryGoal(JointTrajectory(0.0, JOINTS, _points("linear"))))
    sim.step(300)
    assert cm.block_cycles == 0
    assert len(states) >= 300
    assert [m.positions for m in heard] == [m.positions for m in ref]


def test_blocks_drop_nothing_at_a_checkpoint_and_go_on_bit_identically(tmp_path):
    """A checkpoint taken while a block runs takes back the cycles so far; the branch goes on as the
    original does."""
    from gazelle.sim import Simulation
    from gazelle.systems import JointTrajectory
    from gazelle.systems.ros2_control import ControllerManager, TrajectoryGoal

    sim, cm, jtc, heard = _arm(True)
    jtc.submit(TrajectoryGoal(JointTrajectory(0.0, JOINTS, _points("cubic"))))
    sim.step(333)
    path = sim.checkpoint(tmp_path / "arm.ckpt")
    branch = Simulation.from_checkpoint(path)
    sim.step(400)
    branch.step(400)
    cm_b = next(s for s in branch.systems.systems() if isinstance(s, ControllerManager))
    cm_b.settle()
    cm.settle()
    assert branch.world.state_digest() == sim.world.state_digest()
    assert cm_b.block_cycles > 0


def test_models_without_ros2_control_are_untouched(make_sim):
    """The limp arm (no <ros2_control>) steps as before: no plan, nothing recorded."""
    from gazelle.description import load

    model = dataclasses.replace(load(URDF).model, ros2_control=())
    sim = make_sim()
    sim.spawn(model, name="r6bot")
    sim.step(50)
    assert sim.world.time == pytest.approx(0.05)


def test_joint_states_serialized_from_a_template_read_back_as_the_converted_messages():
    """The bridge publishes a block of joint states as bytes filled into a template: rclpy reads each back
    as the message the per-message conversion builds (stamps, names, the three arrays)."""
    from rclpy.serialization import deserialize_message
    from sensor_msgs.msg import JointState

    from gazelle.ros._cdr import serialized_joint_states
    from gazelle.ros._convert import to_joint_state_msg
    from gazelle.systems import JointStatesBlock

    rng = np.random.default_rng(7)
    for names in (JOINTS, ("a",), ("left_wheel_joint", "right_wheel_joint", "a_much_longer_joint_name_x")):
        n = len(names)
        stamps = [0.0, 0.001, 1.9999999999, 12.345, 86400.5]
        pos, vel, eff = (rng.normal(size=(len(stamps), n)) for _ in range(3))
        block = JointStatesBlock(stamps, names, pos, vel, eff, "base_link")
        block.efforts[1, 0] = math.nan
        raw = serialized_joint_states(block)
        assert raw is not None and len(raw) == len(stamps)
        for one, js in zip(raw, block, strict=True):
            got, want = deserialize_message(one, JointState), to_joint_state_msg(js)
            assert (got.header.stamp.sec, got.header.stamp.nanosec) == (
                want.header.stamp.sec,
                want.header.stamp.nanosec,
            )
            assert list(got.name) == list(want.name) and got.header.frame_id == want.header.frame_id == "base_link"
            for field in ("position", "velocity", "effort"):
                np.testing.assert_array_equal(np.array(getattr(got, field)), np.array(getattr(want, field)))
    # arrays that do not match the names are not templated: the messages are built one by one
    odd = JointStatesBlock([0.0], ("a", "b"), np.zeros((1, 2)), np.zeros((1, 2)), np.zeros((1, 0)))
    assert serialized_joint_states(odd) is None


def test_an_endpoint_removed_with_block_sinks_can_still_lose_its_sinks():
    """The bridge removes its sinks after the bus cleared a removed endpoint's (a deleted entity): the
    per-sink block flags are cleared with them (a delete_entity once failed with "zip() argument 3 is
    longer than arguments 1-2")."""
    from gazelle.systems import Bus, JointStatesBlock, MsgType

    bus = Bus()
    ep = bus.advertise("r1", "/r1/joint_states", MsgType.JOINT_STATE)
    got: list = []
    ep.add_sink(got.append, blocks=True)
    ep.add_sink(got.append)
    ep.publish_block(JointStatesBlock([0.0, 0.001], ("a",), np.zeros((2, 1)), np.ones((2, 1)), np.zeros((2, 1))))
    assert len(got) == 3 and isinstance(got[0], JointStatesBlock) and got[2].velocities == (1.0,)
    bus.remove_owner("r1")
    ep.remove_sink(got.append)
    ep2 = bus.advertise("r2", "/r2/joint_states", MsgType.JOINT_STATE)
    ep2.add_sink(got.append, blocks=True)
    bus.remove(ep2)
    ep2.remove_sink(got.append)
    assert ep.sinks == () and ep2.sinks == ()

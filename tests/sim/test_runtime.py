"""The runtime seam (issue 11): blocks of steps inside MuJoCo between system updates, typed handles,
one servo module, listeners on the bus, visuals in the MuJoCo model."""

from __future__ import annotations

import dataclasses
import logging
import math
import threading
import time

import mujoco
import numpy as np
import pytest
from _paths import SEED_XACRO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.physics import ActuatorKind, JointHandle
from gazelle.sim import MAX_CATCH_UP_SEC, Simulation
from gazelle.systems import MsgType, RateGate, System, Twist, UpdateInfo
from gazelle.systems.diff_drive import DiffDrive


def _seed_sim(**kw) -> tuple[Simulation, DiffDrive]:
    sim = new_simulation(**kw)
    entity = sim.spawn(load(SEED_XACRO).model, name="robot", pose=Pose((0.0, 0.0, 0.07)))
    return sim, next(s for s in entity.systems if isinstance(s, DiffDrive))


def test_the_world_steps_inside_mujoco_between_system_updates(monkeypatch) -> None:
    """With only the diff drive (100 Hz) and robot_state_publisher (50 Hz on the same grid) due, 1 s of sim
    time is 100 blocks of 10 steps, each one MuJoCo call, not 1000 Python round trips."""
    sim, drive = _seed_sim()
    drive.command(0.2, 0.3)
    sim.step(10)  # past the spawn's first blocks
    calls: list[int] = []
    real = mujoco.mj_step

    def counting(m, d, nstep=1):
        calls.append(nstep)
        real(m, d, nstep=nstep)

    monkeypatch.setattr(mujoco, "mj_step", counting)
    sim._rtf_window.clear()
    sim.world._overlap_steps = 0  # the 5 s watch after the spawn is over in a real run; here it would split blocks
    sim.step(1000)
    assert sum(calls) == 1000
    assert len(calls) <= 101, f"{len(calls)} MuJoCo calls for 1000 steps: {calls[:20]}"
    assert max(calls) == 10


class _EveryStep(System):
    def __init__(self) -> None:
        self.times: list[float] = []

    def pre_update(self, info: UpdateInfo, world) -> None:
        self.times.append(info.sim_time_sec)


class _TenHz(System):
    def __init__(self) -> None:
        self.times: list[float] = []
        self._next = 0.0

    def next_update(self, sim_time_sec: float) -> float:
        return self._next

    def post_update(self, info: UpdateInfo, world) -> None:
        if info.sim_time_sec + 1e-9 >= self._next:
            self.times.append(round(info.sim_time_sec, 6))
            self._next = info.sim_time_sec + 0.1


def _500_steps_beside_an_every_step_system(system: System) -> Simulation:
    """A world where ``system`` runs beside one that runs every step, after 500 steps (each one a block)."""
    sim = new_simulation()
    fast = _EveryStep()
    sim.systems.add("x", fast)
    sim.systems.add("x", system)
    sim.step(500)
    assert len(fast.times) == 500
    return sim


def test_a_system_that_declares_no_rate_runs_every_step_and_one_with_a_rate_at_its_times() -> None:
    slow = _TenHz()
    sim = _500_steps_beside_an_every_step_system(slow)
    assert slow.times[:5] == [0.001, 0.101, 0.201, 0.301, 0.401]
    sim.systems.remove_owner("x")
    slow2 = _TenHz()
    sim.systems.add("y", slow2)
    sim.world._overlap_steps = 0
    before = sim.iterations
    sim.step(1000)
    assert sim.iterations - before == 1000
    assert len(slow2.times) == 10


class _GatedTwentyHz(System):
    """A system whose post_update starts with its RateGate (a sensor's shape), counting every call."""

    def __init__(self) -> None:
        self.calls = 0
        self.published: list[float] = []
        self._gate = RateGate()
        self.phase_gate = self._gate

    def next_update(self, sim_time_sec: float) -> float:
        return self._gate.next

    def post_update(self, info: UpdateInfo, world) -> None:
        self.calls += 1
        if self._gate.due(info.sim_time_sec, 20.0):
            self.published.append(round(info.sim_time_sec, 6))


def test_a_gated_phase_is_called_only_when_its_gate_is_due_even_beside_an_every_step_system() -> None:
    """A 20 Hz sensor next to a system that runs every step (gz-sim's diff drive): its post_update is not
    called on the 49 steps out of 50 where it would return at once, and it still acts at its times."""
    gated = _GatedTwentyHz()
    _500_steps_beside_an_every_step_system(gated)
    assert gated.published[:4] == [0.001, 0.05, 0.1, 0.15]
    assert len(gated.published) == 11  # 0.001, then every 50 ms up to 0.5 s
    assert gated.calls == len(gated.published)  # never called while not due


def test_blocks_do_not_change_the_trajectory() -> None:
    """The same robot stepped in one call per step and in blocks ends bit-identical."""
    a, da = _seed_sim()
    b, db = _seed_sim()
    for d in (da, db):
        d.command(0.3, 0.5)
    for _ in range(2000):
        a.step(1)
    b.step(2000)
    assert np.array_equal(a.world.data.qpos, b.world.data.qpos)
    assert np.array_equal(a.world.data.qvel, b.world.data.qvel)


def test_joint_and_actuator_handles_read_and_command_through_recompiles() -> None:
    sim, drive = _seed_sim()
    wheel = drive._wheels[0].servo.actuator
    assert wheel.kind is ActuatorKind.VELOCITY
    assert isinstance(wheel.joint, JointHandle)
    drive.command(0.4, 0.0)
    sim.step(300)
    v = wheel.joint.velocity
    assert v == pytest.approx(0.4 / drive._wheels[0].radius, rel=0.02)
    # a spawn renumbers MuJoCo's arrays: the handle still reads this wheel
    sim.spawn(load_string(VISUAL).model, name="other", pose=Pose((5.0, 0.0, 0.5)))
    sim.step(1)
    qadr, dadr = sim.world.joint_address("robot", wheel.joint.name)
    assert wheel.joint.position == sim.world.data.qpos[qadr]
    assert wheel.joint.velocity == sim.world.data.qvel[dadr]
    assert wheel.force == sim.world.data.actuator_force[sim.world.actuator_id(wheel.name)]


def test_the_wheel_servo_holds_its_speed_under_load_by_its_integral_term() -> None:
    """The integral term, updated only at the drive's 100 Hz from the wheel's travel, removes the
    proportional servo's steady-state error: driving straight, the robot's speed is v within 0.5 %."""
    sim, drive = _seed_sim()
    drive.command(0.3, 0.0)
    sim.step(3000)
    vx = sim.world.entity_state("robot").linear_velocity
    assert math.hypot(vx[0], vx[1]) == pytest.approx(0.3, rel=0.005)
    assert any(abs(w.servo.integral) > 0 for w in drive._wheels)


def test_nothing_is_built_for_nobody_and_every_listener_gets_each_message() -> None:
    sim, drive = _seed_sim()
    drive.command(0.2, 0.0)
    odom = next(ep for ep in sim.bus.endpoints() if ep.is_publisher and ep.msg_type == MsgType.ODOMETRY)
    sim.step(100)
    assert odom.last is None and not odom.wanted  # nobody listens: no message was built
    first, second = [], []
    odom.add_sink(first.append)
    odom.add_sink(second.append, wanted=lambda: False)
    sim.step(100)
    assert len(first) == 10 and second == first  # the bus fans out: both get all ten (100 Hz)
    odom.remove_sink(first.append)
    n = len(second)
    sim.step(100)
    assert len(second) == n  # the one left does not want any: nothing is built


VISUAL = """<robot name="lamp">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><sphere radius="0.3"/></geometry><material name="red"><color rgba="1 0 0 1"/></material></visual>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
</robot>"""


def test_visuals_go_into_the_mujoco_model_as_massless_non_colliding_geoms(make_sim) -> None:
    runs = {}
    for visuals in (False, True):
        sim = make_sim(visual_geoms=visuals)
        sim.spawn(load_string(VISUAL).model, name="lamp", pose=Pose((0.0, 0.0, 0.5)))
        sim.step(2000)
        m = sim.world.model
        groups = [int(g) for g in m.geom_group]
        runs[visuals] = (groups, m, sim.world.data.qpos.copy())
    groups, m, qpos = runs[True]
    vis = [i for i, g in enumerate(groups) if g == 1]
    assert len(vis) == 1 and 1 not in runs[False][0]
    g = vis[0]
    assert int(m.geom_type[g]) == int(mujoco.mjtGeom.mjGEOM_SPHERE) and m.geom_size[g][0] == pytest.approx(0.3)
    assert int(m.geom_contype[g]) == 0 and int(m.geom_conaffinity[g]) == 0
    assert list(m.geom_rgba[g]) == pytest.approx([1.0, 0.0, 0.0, 1.0])
    # the 0.3 m sphere neither collides nor weighs: the box lands on its 5 cm half-height as without it
    assert np.array_equal(qpos, runs[False][2])
    assert qpos[2] == pytest.approx(0.05, abs=3e-3)


def test_a_handle_on_a_joint_that_is_not_there_is_refused_by_name() -> None:
    from gazelle.physics import WorldError

    sim, drive = _seed_sim()
    assert sim.world.joint("robot", drive._wheels[0].joint).position == drive._wheels[0].servo.actuator.joint.position
    with pytest.raises(WorldError, match="entity 'robot' has no joint 'QQQ'"):
        sim.world.joint("robot", "QQQ")
    with pytest.raises(WorldError, match="entity 'ghost' has no joint"):
        sim.world.joint("ghost", drive._wheels[0].joint)


def test_a_stall_longer_than_the_catch_up_is_reported_once_and_pacing_goes_on(caplog, make_sim) -> None:
    sim = make_sim(rtf=1.0)
    stalled = threading.Event()

    def stall(_info) -> None:
        if not stalled.is_set():
            stalled.set()
            time.sleep(MAX_CATCH_UP_SEC + 0.3)  # the stall under test (a busy CPU), not a wait for a condition

    sim.add_step_listener(stall, rate_hz=10)
    with caplog.at_level(logging.WARNING, logger="gazelle"):
        sim.start()
        try:
            assert stalled.wait(5)
            deadline = time.monotonic() + 10
            while "behind the wall clock" not in caplog.text and time.monotonic() < deadline:
                time.sleep(0.01)
            t0, w0 = sim.world.time, time.monotonic()
            while time.monotonic() - w0 < 0.5:
                time.sleep(0.01)
            rate = (sim.world.time - t0) / (time.monotonic() - w0)
        finally:
            sim.stop()
    lines = [r.getMessage() for r in caplog.records if "behind the wall clock" in r.getMessage()]
    assert len(lines) == 1, lines
    assert "dropped 0." in lines[0] and "real-time factor 1" in lines[0]
    assert 0.7 < rate < 1.3  # paced at real time again from the new anchor, not racing to make up the loss


@pytest.mark.serial  # a wall-clock stall: 0.12 s late once while the other worker ran (run alone)
def test_a_message_that_arrives_while_the_simulation_catches_up_acts_at_the_sim_time_it_came() -> None:
    sim, drive = _seed_sim()
    sim.rtf = 1.0
    stalled, stall_at = threading.Event(), []

    def stall(info: UpdateInfo) -> None:
        if info.sim_time_sec >= 0.3 and not stalled.is_set():
            stall_at.append((time.monotonic(), info.sim_time_sec))
            stalled.set()
            time.sleep(0.4)  # the stall under test (a busy CPU), not a wait for a condition

    applied: list[tuple[float, str]] = []

    def sink(twist: Twist) -> None:
        applied.append((sim.world.time, threading.current_thread().name))
        drive._on_cmd(twist)

    sim.add_step_listener(stall, rate_hz=10)
    sim.start()
    try:
        assert stalled.wait(10)
        time.sleep(0.2)  # the message comes half-way through the stall
        came = time.monotonic()
        sim.deliver(sink, Twist((0.2, 0.0, 0.0), (0.0, 0.0, 0.0)))
        deadline = time.monotonic() + 5
        while not applied and time.monotonic() < deadline:
            time.sleep(0.005)
        assert applied, "the message was never handed over"
        # level with the wall clock again: the next message is handed over at once, on this thread (on a
        # loaded machine the simulation can fall a block behind again just then: that one is queued, and
        # the test tries again)
        deadline = time.monotonic() + 5
        direct = False
        while not direct:
            assert time.monotonic() < deadline, f"no message was handed over at once: {applied}"
            if sim.world.time < stall_at[0][1] + (time.monotonic() - stall_at[0][0]) - 0.05:
                time.sleep(0.005)
                continue
            count = len(applied)
            sim.deliver(sink, Twist())
            direct = len(applied) == count + 1 and applied[-1][1] == threading.current_thread().name
            if not direct:
                while len(applied) == count and time.monotonic() < deadline:  # it went through the queue
                    time.sleep(0.005)
    finally:
        sim.stop()
    wall_stall, sim_stall = stall_at[0]
    due = sim_stall + (came - wall_stall)
    # before: handed over at once, it acted at the stalled sim time, 0.2 s of driving too early
    assert applied[0][0] == pytest.approx(due, abs=0.03)
    assert applied[0][1] == "gazelle-sim"


def test_a_worlds_models_are_compiled_into_mujoco_once_and_step_as_one_at_a_time_would(make_sim):
    """Issue 26 item 13: each of a world file's models was compiled into MuJoCo on its own, so loading was
    quadratic: gz-sim's 3k_shapes.sdf (3,000 models) took over 5 minutes to load (3.6 s now). The world's
    models are staged, then compiled once; the result is the same world as adding them one by one."""
    import numpy as np

    from gazelle.description import load_string

    boxes = "".join(
        f"<model name='b{i}'><pose>{i * 0.5} 0 {0.3 + 0.01 * i} 0 0 {0.1 * i}</pose><link name='l'>"
        "<inertial><mass>1</mass></inertial><collision name='c'><geometry><box><size>0.2 0.2 0.2</size>"
        "</box></geometry></collision></link></model>"
        for i in range(40)
    )
    world = load_string(f"<sdf version='1.9'><world name='w'>{boxes}</world></sdf>").world
    batch = make_sim(world)
    assert batch.world.generation == 1 and len(batch.world.entities) == 40
    one_by_one = make_sim(dataclasses.replace(world, models=()))
    for m in world.models:
        one_by_one.world.add_entity(m, name=m.name, X_WM=m.pose, spawned=False)
    batch.step(300)
    one_by_one.step(300)
    for name in ("b0", "b17", "b39"):
        a, b = batch.world.entity_state(name).pose, one_by_one.world.entity_state(name).pose
        assert np.allclose(a.position, b.position, atol=1e-9) and np.allclose(a.orientation, b.orientation, atol=1e-9)


def test_the_in_process_world_names_a_file_of_the_wrong_kind(tmp_path) -> None:
    """gazelle_world(world=...) given a robot file, or spawn() given a world file, says so by file instead of
    failing inside the runtime (an AttributeError on the model, before)."""
    from gazelle.testing import InProcessWorld

    robot = tmp_path / "bot.urdf"
    robot.write_text(
        '<robot name="bot"><link name="base"><inertial><mass value="1"/>'
        '<inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>'
    )
    world_file = tmp_path / "empty.sdf"
    world_file.write_text('<sdf version="1.9"><world name="w"></world></sdf>')
    with pytest.raises(ValueError, match=r"bot\.urdf: not a world \(it describes a model\)"):
        InProcessWorld(robot)
    world = InProcessWorld(world_file)
    with pytest.raises(ValueError, match=r"empty\.sdf: not a robot or model \(it describes a world\)"):
        world.spawn(world_file, "w2")
    assert world.spawn(robot, "bot").name == "bot"

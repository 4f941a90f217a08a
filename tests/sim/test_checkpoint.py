"""Issue 31: checkpoints. ``sim.checkpoint(path)`` saves everything a run needs to go on bit-identically;
``Simulation.from_checkpoint(path)`` goes on from it in another process: MuJoCo's whole state and warm
start, a ros2_control JTC goal in the middle of its trajectory, a diff drive's command and odometry, and
the noise streams of sensors someone listens to."""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import re
import subprocess
import sys
from pathlib import Path

import pytest
from _paths import REAL, REPO
from _sim import new_simulation

from gazelle.description import load
from gazelle.sim import CheckpointError, Simulation
from gazelle.worlds import default_world

SCRIPT = r"""
import hashlib, json, math, os, sys
import mujoco, numpy as np
from gazelle.description import Pose, load
from gazelle.sim import Simulation
from gazelle.systems import JointTrajectory, TrajectoryPoint, Twist, MsgType
from gazelle.systems.ros2_control import ControllerManager, TrajectoryGoal, load_params
from gazelle.worlds import default_world

REAL, REPO, CKPT, MODE = sys.argv[1:5]
R6 = f"{REAL}/ros2_control_r6bot/_xacro_expanded/r6bot.urdf"
JOINTS = tuple(f"joint_{i}" for i in range(1, 7))


def digest(sim):
    w, spec = sim.world, mujoco.mjtState.mjSTATE_INTEGRATION
    state = np.empty(mujoco.mj_stateSize(w.model, spec))
    mujoco.mj_getState(w.model, w.data, state, spec)
    return hashlib.sha256(state.tobytes()).hexdigest()


def listen(sim, heard):
    # someone listens to every sensor of the sensor robot and to the seed robot's odometry: the noisy
    # sensors then draw their noise, and what they publish is compared
    for ep in sim.bus.endpoints():
        if ep.is_publisher and ep.owner in ("bot", "seed") and ep.msg_type is not MsgType.IMAGE:
            ep.add_sink(lambda payload, topic=ep.topic: heard.update(repr((topic, payload)).encode()))


if MODE == "first":
    sim = Simulation(default_world(), rtf=0, seed=11)
    r6 = sim.spawn(load(R6).value, name="r6bot")
    cm = next(s for s in r6.systems if isinstance(s, ControllerManager))
    cm.files.append(load_params(f"{REPO}/tests/data/ros2_control/r6bot_jtc.yaml"))
    for n in ("joint_state_broadcaster", "joint_trajectory_controller"):
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(["joint_state_broadcaster", "joint_trajectory_controller"], [])
    sim.spawn(load(f"{REPO}/examples/sensor_bot/sensor_bot.urdf").value, name="bot", pose=Pose((2.0, 0.0, 0.1)))
    seed = sim.spawn(load(f"{REPO}/examples/simple_robot/simple_robot/robot.urdf.xacro").value, name="seed",
                     pose=Pose((0.0, 2.0, 0.07)))
    heard = hashlib.sha256()
    listen(sim, heard)
    sim.step(500)
    jtc = cm.controllers["joint_trajectory_controller"].controller
    goal = TrajectoryGoal(JointTrajectory(0.0, JOINTS, (
        TrajectoryPoint(4.0, (0.6, -0.8, 1.0, 0.4, -0.6, 0.8)),
        TrajectoryPoint(8.0, (0.2, -0.2, 0.3, 0.1, 0.2, -0.3)))))
    jtc.submit(goal)
    sim.bus.inject("/cmd_vel", MsgType.TWIST, Twist(linear=(0.2, 0.0, 0.0), angular=(0.0, 0.0, 0.3)))
    sim.step(4500)  # 5 s
    assert goal.status == "executing", goal.status
    sim.checkpoint(CKPT)
    at = digest(sim)
    heard = hashlib.sha256()
    listen(sim, heard)  # a second listener: from here on, only what comes after the checkpoint
    sim.step(5000)  # 5 s more: the goal ends in them
    print(json.dumps({"at": at, "end": digest(sim), "heard": heard.hexdigest(), "goal": goal.status,
                      "time": sim.world.time}))
else:
    sim = Simulation.from_checkpoint(CKPT)
    at = digest(sim)
    heard = hashlib.sha256()
    listen(sim, heard)
    sim.step(5000)
    jtc = next(s for s in sim.world.entities["r6bot"].systems
               if isinstance(s, ControllerManager)).controllers["joint_trajectory_controller"].controller
    print(json.dumps({"at": at, "end": digest(sim), "heard": heard.hexdigest(), "goal": "n/a",
                      "time": sim.world.time, "active": jtc.state}))
"""


def _run(tmp_path: Path, mode: str) -> dict:
    script = tmp_path / "run.py"
    script.write_text(SCRIPT)
    env = {**os.environ, "GAZELLE_RESOURCE_PATH": str(REAL / "ros2_control_r6bot")}
    out = subprocess.run(
        [sys.executable, str(script), str(REAL), str(REPO), str(tmp_path / "run.ckpt"), mode],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )
    assert out.returncode == 0, out.stderr[-3000:]
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_a_run_loaded_from_its_checkpoint_in_a_fresh_process_goes_on_bit_identically(tmp_path: Path) -> None:
    first = _run(tmp_path, "first")
    assert first["goal"] == "succeeded"  # the goal was mid-trajectory at the checkpoint, and ended after it
    assert oct((tmp_path / "run.ckpt").stat().st_mode & 0o777) == "0o600"
    again = _run(tmp_path, "again")
    assert again["at"] == first["at"]
    assert again["end"] == first["end"], "the continued run's state differs from the first run's"
    assert again["heard"] == first["heard"], "the sensors published other values (noise) after the checkpoint"
    assert again["time"] == first["time"]


@pytest.fixture
def seed_robot_sim() -> Simulation:
    sim = new_simulation(seed=3)
    sim.spawn(load(REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro").model, name="robot")
    sim.step(100)
    return sim


def test_a_checkpoint_of_another_world_version_or_no_checkpoint_at_all_is_one_clear_error(
    tmp_path: Path, seed_robot_sim: Simulation
) -> None:
    path = seed_robot_sim.checkpoint(tmp_path / "a.ckpt")
    other = load(REAL / "turtlebot3" / "turtlebot3_gazebo" / "worlds" / "empty_world.world").world
    with pytest.raises(CheckpointError, match="not of the one given"):
        Simulation.from_checkpoint(path, world=other)
    # the same world, given: fine
    assert Simulation.from_checkpoint(path, world=default_world()).world.time == seed_robot_sim.world.time
    # another gazelle or MuJoCo version
    payload = pickle.loads(path.read_bytes())
    payload["versions"]["mujoco"] = "0.0.1"
    (tmp_path / "old.ckpt").write_bytes(pickle.dumps(payload))
    with pytest.raises(CheckpointError, match=r"made by another version: mujoco 0\.0\.1"):
        Simulation.from_checkpoint(tmp_path / "old.ckpt")
    # truncated, foreign, missing
    (tmp_path / "cut.ckpt").write_bytes(path.read_bytes()[:1000])
    with pytest.raises(CheckpointError, match="not a gazelle checkpoint"):
        Simulation.from_checkpoint(tmp_path / "cut.ckpt")
    (tmp_path / "foreign.ckpt").write_bytes(pickle.dumps({"a": 1}))
    with pytest.raises(CheckpointError, match="not a gazelle checkpoint"):
        Simulation.from_checkpoint(tmp_path / "foreign.ckpt")
    with pytest.raises(CheckpointError, match="No such file"):
        Simulation.from_checkpoint(tmp_path / "none.ckpt")


class _Runs:
    """What a forged pickle holds: loading it calls ``os.makedirs(path)`` (any call would do)."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def __reduce__(self) -> tuple:
        return (os.makedirs, (str(self.path),))


def test_a_forged_checkpoint_is_refused_before_any_of_it_runs(tmp_path: Path) -> None:
    """A pickle that is not a checkpoint, or one of another format, runs nothing: the header is read from the
    pickle's opcodes first (before: the file was unpickled, running what it named, and only then refused)."""
    ran = tmp_path / "ran"
    forged = {
        "plain.ckpt": pickle.dumps(_Runs(ran)),
        "first.ckpt": pickle.dumps({"code": _Runs(ran), "magic": "gazelle-checkpoint", "format": 1}),
        "format.ckpt": pickle.dumps({"magic": "gazelle-checkpoint", "format": 99, "code": _Runs(ran)}),
    }
    for name, blob in forged.items():
        (tmp_path / name).write_bytes(blob)
        with pytest.raises(CheckpointError, match="not a gazelle checkpoint|checkpoint format 99") as err:
            Simulation.from_checkpoint(tmp_path / name)
        assert str(tmp_path / name) in str(err.value)
        assert not ran.exists(), f"{name}: loading it ran its code"
    (tmp_path / "text.ckpt").write_text("not a pickle at all\n")
    with pytest.raises(CheckpointError, match="not a gazelle checkpoint"):
        Simulation.from_checkpoint(tmp_path / "text.ckpt")


def _loads_checkpoints(folder: Path) -> list[str]:
    """The lines under ``folder`` that load a checkpoint or any pickle."""
    pattern = re.compile(r"from_checkpoint|_checkpoint\.read|pickle\.loads?\b|Unpickler")
    return [
        f"{path.name}:{n}: {line.strip()}"
        for path in sorted(folder.rglob("*.py"))
        for n, line in enumerate(path.read_text().splitlines(), 1)
        if pattern.search(line)
    ]


def test_nothing_on_the_ros_graph_loads_a_checkpoint(tmp_path: Path) -> None:
    """A request's path is data: no service, topic or action of gazelle's ROS side loads a checkpoint (a pickle
    runs code), so none can be made to load one. The check finds a planted loader."""
    assert _loads_checkpoints(REPO / "gazelle" / "ros") == []
    (tmp_path / "service.py").write_text("def on_load(req):\n    return Simulation.from_checkpoint(req.path)\n")
    assert _loads_checkpoints(tmp_path) == ["service.py:2: return Simulation.from_checkpoint(req.path)"]


def test_a_checkpoint_whose_models_changed_since_is_refused(tmp_path: Path, seed_robot_sim: Simulation) -> None:
    path = seed_robot_sim.checkpoint(tmp_path / "a.ckpt")
    payload = pickle.loads(path.read_bytes())
    # the robot's file changed since: one more link
    text = (REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro").read_text()
    from gazelle.description import load_string

    grown = load_string(_with_extra_link(text), format="urdf").value
    payload["entities"][-1]["model"] = grown
    (tmp_path / "b.ckpt").write_bytes(pickle.dumps(payload))
    with pytest.raises(CheckpointError, match="not the one saved"):
        Simulation.from_checkpoint(tmp_path / "b.ckpt")


def _with_extra_link(xacro_text: str) -> str:
    """The seed robot's URDF (expanded) with one more link fixed to its base."""
    from gazelle.description import DiagnosticSink, ResourceResolver, expand_xacro_bounded

    robot = REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
    urdf = expand_xacro_bounded(
        xacro_text, source=str(robot), sink=DiagnosticSink(), resolver=ResourceResolver().trusting(robot.parent)
    )
    assert urdf is not None
    extra = (
        '<link name="extra"><inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" '
        'iyz="0"/></inertial><collision><geometry><box size="0.05 0.05 0.05"/></geometry></collision></link>'
        '<joint name="extra_joint" type="fixed"><parent link="base_link"/><child link="extra"/>'
        '<origin xyz="0 0 0.2"/></joint></robot>'
    )
    return urdf.replace("</robot>", extra)


def test_what_cannot_be_saved_is_named(tmp_path: Path, seed_robot_sim: Simulation) -> None:
    system = seed_robot_sim.world.entities["robot"].systems[0]
    system.unsaveable = lambda: None  # a closure a system keeps: not state a file can hold
    with pytest.raises(CheckpointError, match=rf"{type(system).__name__}\.unsaveable"):
        seed_robot_sim.checkpoint(tmp_path / "c.ckpt")
    assert not (tmp_path / "c.ckpt").exists()


def test_sweep_runs_branch_from_a_checkpoint(tmp_path: Path, seed_robot_sim: Simulation) -> None:
    """``gazelle sweep --from CHECKPOINT``: every run starts where the checkpoint was, not at time 0."""
    ckpt = seed_robot_sim.checkpoint(tmp_path / "s.ckpt")
    scenario = tmp_path / "branch.py"
    scenario.write_text(
        "def drive(sim, params, seed):\n"
        "    t0 = sim.world.time\n"
        "    x0 = sim.world.entity_state('robot').pose.position[0]\n"
        "    from gazelle.systems import MsgType, Twist\n"
        "    sim.bus.inject('/cmd_vel', MsgType.TWIST, Twist(linear=(float(params['v']), 0.0, 0.0)))\n"
        "    sim.step(1000)\n"
        "    x1 = sim.world.entity_state('robot').pose.position[0]\n"
        "    return {'t0': t0, 'dx': x1 - x0, 'passed': True}\n"
    )
    out = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{scenario}::drive", "--param", "v=0.1,0.2"]
        + ["--seeds", "0:2", "-j", "1", "--from", str(ckpt), "--out", str(tmp_path / "out")],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    rows = [json.loads(line) for line in (tmp_path / "out" / "runs.jsonl").read_text().splitlines()]
    assert len(rows) == 4
    for row in rows:
        assert row["metric.t0"] == pytest.approx(seed_robot_sim.world.time)
        assert row["metric.dx"] == pytest.approx(float(row["param.v"]), rel=0.1)
    digest = {hashlib.sha256(json.dumps(r["metric.dx"]).encode()).hexdigest() for r in rows if r["param.v"] == 0.1}
    assert len(digest) == 1  # the seed changes nothing here: the same branch, the same result
    # a checkpoint that is not there: one line, exit 2, nothing run
    bad = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{scenario}::drive", "--param", "v=0.1"]
        + ["--from", str(tmp_path / "none.ckpt"), "--out", str(tmp_path / "bad")],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert bad.returncode == 2 and "Traceback" not in bad.stderr, bad.stderr
    assert bad.stderr.strip().count("\n") == 0 and "--from" in bad.stderr and "none.ckpt" in bad.stderr


@pytest.mark.slow
def test_branches_on_ray_start_from_the_checkpoint_shipped_to_the_workers(
    tmp_path: Path, seed_robot_sim: Simulation
) -> None:
    """On Ray the checkpoint goes to the workers as bytes (a cluster's nodes do not share this disk):
    the same rows as the process pool's."""
    from gazelle.sweep import sweep

    ckpt = seed_robot_sim.checkpoint(tmp_path / "r.ckpt")
    scenario = tmp_path / "branch.py"
    scenario.write_text(
        "def drive(sim, params, seed):\n"
        "    from gazelle.systems import MsgType, Twist\n"
        "    sim.bus.inject('/cmd_vel', MsgType.TWIST, Twist(linear=(0.2, 0.0, 0.0)))\n"
        "    sim.step(500)\n"
        "    return {'t': sim.world.time, 'state': sim.world.state_digest()}\n"
    )
    pool = sweep(f"{scenario}::drive", [], [0, 1], out=tmp_path / "pool", jobs=2, start=ckpt, report=False)
    ray = sweep(f"{scenario}::drive", [], [0, 1], out=tmp_path / "ray", jobs=2, ray="local", start=ckpt, report=False)
    assert {r["key"]: r["metric.state"] for r in ray.rows} == {r["key"]: r["metric.state"] for r in pool.rows}
    assert all(r["metric.t"] == pytest.approx(seed_robot_sim.world.time + 0.5) for r in ray.rows)

"""Spawn and delete while running: every other entity keeps its state (pose, velocity, joint positions).

In-process and in lock-step: the seed robot drives a circle (wheels spinning under their
velocity servos), a box slides along the ground, a ball falls and a pendulum swings, while
other entities (boxes, a pendulum, a second seed robot with its own actuators and
systems) are spawned and deleted. Across every spawn/delete each of them keeps its qpos,
qvel and actuator ctrl bit for bit, and its whole trajectory is bit-identical to a run in
which nothing was spawned or deleted.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from _paths import BOX, REAL, SEED_XACRO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.sim import Simulation, SpawnRequest
from gazelle.systems.diff_drive import DiffDrive

ICE_BOX = BOX.replace(
    "<box><size>0.2 0.2 0.2</size></box></geometry>",
    "<box><size>0.2 0.2 0.2</size></box></geometry><surface><friction><ode><mu>0.05</mu></ode></friction></surface>",
)
BALL = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="ball"><link name="l"><inertial><mass>1</mass>'
    "<inertia><ixx>0.004</ixx><iyy>0.004</iyy><izz>0.004</izz></inertia></inertial>"
    '<collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link></model></sdf>'
)
PENDULUM = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="pendulum"><link name="bob">'
    "<inertial><pose>0 0 -0.5 0 0 0</pose><mass>1</mass><inertia><ixx>1e-4</ixx><iyy>1e-4</iyy><izz>1e-4</izz></inertia></inertial>"
    '</link><joint name="hinge" type="revolute"><parent>world</parent><child>bob</child>'
    "<axis><xyz>0 1 0</xyz></axis></joint></model></sdf>"
)
WATCHED = ("robot", "slider", "faller", "pendulum")
CHUNK = 100  # steps between events
EVENTS = [
    ("spawn", "crate", "box", Pose((5.0, 5.0, 0.3))),
    ("spawn", "robot2", "robot", Pose((-5.0, 4.0, 0.05))),
    ("spawn", "pendulum2", "pendulum", Pose((8.0, -3.0, 2.0))),
    ("delete", "crate", None, None),
    ("spawn", "dropped", "box", Pose((-4.0, -4.0, 1.0), (0.92, 0.2, 0.3, 0.1))),
    ("delete", "robot2", None, None),  # removes actuators that sit between the robot's and others' in ctrl
    ("delete", "pendulum2", None, None),
    ("spawn", "robot3", "robot", Pose((6.0, -6.0, 0.05))),
    ("delete", "dropped", None, None),
    ("delete", "robot3", None, None),
]


def entity_state(sim: Simulation, name: str) -> dict[str, np.ndarray]:
    """qpos, qvel of every joint and ctrl of every actuator of an entity, by MuJoCo name (indices move on recompile)."""
    w = sim.world
    m, d = w.model, w.data
    built = w.entities[name].built
    out: dict[str, np.ndarray] = {}
    joints = [mj for names in built.joints.values() for mj in names] + ([built.free_joint] if built.free_joint else [])
    nq = {int(mujoco.mjtJoint.mjJNT_FREE): (7, 6), int(mujoco.mjtJoint.mjJNT_BALL): (4, 3)}
    for mj in joints:
        jid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, mj)
        a, v = int(m.jnt_qposadr[jid]), int(m.jnt_dofadr[jid])
        na, nv = nq.get(int(m.jnt_type[jid]), (1, 1))
        out[f"qpos {mj}"] = d.qpos[a : a + na].copy()
        out[f"qvel {mj}"] = d.qvel[v : v + nv].copy()
    for i in range(m.nu):
        act = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_ACTUATOR, i)
        if act.startswith(name + "::"):
            out[f"ctrl {act}"] = d.ctrl[i : i + 1].copy()
    return out


def snapshot(sim: Simulation) -> dict[str, dict[str, np.ndarray]]:
    return {n: entity_state(sim, n) for n in WATCHED}


def assert_same(a: dict[str, dict[str, np.ndarray]], b: dict[str, dict[str, np.ndarray]], when: str) -> None:
    for entity in WATCHED:
        assert a[entity].keys() == b[entity].keys(), f"{when}: '{entity}' has different joints/actuators"
        for key, x in a[entity].items():
            y = b[entity][key]
            # bitwise, so even -0.0 vs 0.0 would count
            assert np.array_equal(x.view(np.uint64), y.view(np.uint64)), (
                f"{when}: '{entity}' {key} changed: {x.tolist()} vs {y.tolist()} (diff {(y - x).tolist()})"
            )


def busy_world() -> tuple[Simulation, dict]:
    """A world in motion: the seed robot driving, a box sliding, a ball falling, a pendulum swinging."""
    models = {"robot": load(SEED_XACRO).model, "box": load_string(BOX).model, "pendulum": load_string(PENDULUM).model}
    sim = new_simulation()
    robot = sim.spawn(models["robot"], name="robot", pose=Pose((0.0, 0.0, 0.05)))
    next(s for s in robot.systems if isinstance(s, DiffDrive)).command(0.3, 0.5)
    sim.spawn(load_string(ICE_BOX).model, name="slider", pose=Pose((2.0, -2.0, 0.1)))
    sim.world.set_entity_state("slider", Pose((2.0, -2.0, 0.1)), linear=(1.5, 0.5, 0.0))  # slides for ~3 s (μ = 0.05)
    sim.spawn(load_string(BALL).model, name="faller", pose=Pose((-3.0, 0.0, 500.0)))  # free fall all along
    sim.spawn(models["pendulum"], name="pendulum", pose=Pose((0.0, 3.0, 2.0)))
    sim.world.set_joint_state("pendulum", "hinge", position=0.8)
    sim.step(200)  # the robot is on its wheels and driving
    return sim, models


def run(with_events: bool) -> tuple[list[dict], list[tuple[str, dict, dict]]]:
    """Snapshots of the watched entities after every chunk; with events, also (event, before, after) around each one."""
    sim, models = busy_world()
    trace = [snapshot(sim)]
    around: list[tuple[str, dict, dict]] = []
    for kind, name, model, pose in EVENTS:
        sim.step(CHUNK)
        trace.append(snapshot(sim))
        if with_events:
            before = snapshot(sim)
            if kind == "spawn":
                e = sim.spawn(models[model], name=name, pose=pose)
                if model == "robot":  # drive it too: its actuators are live, not idle
                    next(s for s in e.systems if isinstance(s, DiffDrive)).command(-0.2, 1.0)
            else:
                sim.delete(name)
            around.append((f"{kind} {name}", before, snapshot(sim)))
    sim.step(10 * CHUNK)  # and the motion goes on unchanged afterwards
    trace.append(snapshot(sim))
    return trace, around


def test_spawn_and_delete_leave_every_other_entity_bit_identical() -> None:
    plain, _ = run(with_events=False)
    busy, around = run(with_events=True)
    assert len(around) == len(EVENTS)
    for what, before, after in around:  # exactly continuous across each spawn/delete
        assert_same(before, after, f"across '{what}'")
    for k, (a, b) in enumerate(zip(plain, busy)):  # and the same trajectory as with nothing spawned
        assert_same(a, b, f"after {200 + k * CHUNK} steps")
    # the watched entities really are moving: wheels spin, the box slid, the ball falls, the pendulum swings
    first, last = plain[0], plain[-1]
    wheel_vels = [v for k, v in last["robot"].items() if k.startswith("qvel") and "wheel" in k]
    assert wheel_vels and all(abs(float(v[0])) > 1.0 for v in wheel_vels), wheel_vels
    assert any(k.startswith("ctrl") for k in last["robot"])
    slid = last["slider"]["qpos slider::link#free"][:2] - first["slider"]["qpos slider::link#free"][:2]
    assert np.linalg.norm(slid) > 0.05
    assert last["faller"]["qvel faller::l#free"][2] < -10.0
    assert first["pendulum"]["qpos pendulum::hinge"][0] != last["pendulum"]["qpos pendulum::hinge"][0]


@pytest.mark.parametrize("batch", [False, True])
def test_batch_spawn_keeps_the_others(batch: bool) -> None:
    """SpawnEntities (one recompile for several models, actuators included) keeps the others too."""
    sim, models = busy_world()
    ref, _ = busy_world()
    before = snapshot(sim)
    if batch:
        sim.spawn_many(
            [
                SpawnRequest(models["box"], "b1", Pose((5.0, 5.0, 0.3))),
                SpawnRequest(models["robot"], "r2", Pose((-5.0, 5.0, 0.05))),
            ]
        )
    else:
        sim.spawn(models["box"], name="b1", pose=Pose((5.0, 5.0, 0.3)))
    assert_same(before, snapshot(sim), "across the spawn")
    sim.step(CHUNK)
    ref.step(CHUNK)
    assert_same(snapshot(ref), snapshot(sim), "after the spawn")


def test_robots_with_the_same_meshes_share_one_copy_which_goes_with_the_last_of_them(monkeypatch, make_sim) -> None:
    """Issue 29: every arm copied its 88,755 mesh vertices (20 r6bot arms: 140 meshes, 762 MiB); a mesh is
    now in the model once however many robots use it, and leaves it with the last one."""
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(REAL / "ros2_control_r6bot"))
    model = load(REAL / "ros2_control_r6bot" / "_xacro_expanded" / "r6bot.urdf").model
    sim = make_sim()
    base = sim.world.model.nmesh
    sim.spawn(model, name="a0")
    one = sim.world.model.nmesh - base
    assert one > 0
    for i in (1, 2):
        sim.spawn(model, name=f"a{i}", pose=Pose((1.5 * i, 0.0, 0.0)))
    assert sim.world.model.nmesh - base == one  # not 3 copies
    sim.step(100)
    sim.delete("a0")
    sim.delete("a1")
    assert sim.world.model.nmesh - base == one  # a2 still uses them
    sim.step(10)
    sim.delete("a2")
    assert sim.world.model.nmesh == base  # gone with the last arm
    sim.spawn(model, name="again")
    assert sim.world.model.nmesh - base == one

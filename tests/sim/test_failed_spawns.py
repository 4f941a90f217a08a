"""A failed spawn, whatever failed, leaves the world bit-identical, the name free, and says why.

Found by an attacker (issue 10): a 985-link chain raised RecursionError in the builder and left
~989 orphan bodies; a plugin whose configuration failed left `repeated name 'dd::a'` debris;
"entity 'dd' has no joint 'r'" when the joint existed but was fixed.
"""

from __future__ import annotations

import logging

import numpy as np
import pytest
from _paths import BOX, SEED_XACRO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.physics import ActuatorKind, WorldError
from gazelle.sim import Simulation, SpawnRequest


def chain(n: int, joint_type: str) -> str:
    parts = ['<robot name="chain">']
    inertial = (
        '<inertial><mass value="0.1"/><inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial>'
    )
    for i in range(n):
        parts.append(f'<link name="l{i}">{inertial}</link>')
        if i:
            parts.append(
                f'<joint name="j{i}" type="{joint_type}"><parent link="l{i - 1}"/><child link="l{i}"/>'
                '<origin xyz="0 0 0.01"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
            )
    parts.append("</robot>")
    return "".join(parts)


def fingerprint(sim: Simulation) -> tuple:
    """Everything a failed spawn must not change: the compiled model's sizes, the state, the names."""
    m, d = sim.world.model, sim.world.data
    return (
        m.nbody,
        m.njnt,
        m.ngeom,
        m.nu,
        m.nmesh,
        m.neq,
        d.qpos.tobytes(),
        d.qvel.tobytes(),
        d.ctrl.tobytes(),
        float(d.time),
        tuple(sim.world.entities),
        len(sim.world.spec.bodies),
        len(sim.systems.systems()),
        tuple(sorted(ep.topic for ep in sim.bus.endpoints())),
    )


@pytest.fixture
def busy_sim() -> Simulation:
    """A world with a driving robot and a falling box, stepped a little."""
    sim = new_simulation()
    sim.spawn(load(SEED_XACRO).model, name="robot", pose=Pose((0.0, 0.0, 0.05)))
    sim.spawn(load_string(BOX).model, name="box", pose=Pose((2.0, 0.0, 1.0)))
    sim.step(50)
    return sim


def assert_next_spawn_works(sim: Simulation, name: str) -> None:
    before = fingerprint(sim)
    sim.step(20)
    again = fingerprint(sim)
    assert before[:6] == again[:6]
    e = sim.spawn(load_string(BOX).model, name=name, pose=Pose((-2.0, 0.0, 0.5)))
    assert e.name == name
    sim.step(5)


@pytest.mark.parametrize("joint_type", ["fixed", "revolute"])
@pytest.mark.parametrize("n", [985, 5000])
def test_long_chains_fail_clearly_or_spawn_and_the_world_is_untouched(busy_sim: Simulation, n: int, joint_type: str):
    model = load_string(chain(n, joint_type)).model
    before = fingerprint(busy_sim)
    if n <= 1000:
        busy_sim.spawn(model, name="c")
        busy_sim.delete("c")
    else:
        with pytest.raises(WorldError) as info:
            busy_sim.spawn(model, name="c")
        # the bound on links (issue 25) is met before the depth's: both name the model and the limit
        assert f"has {n} links, more than the 1000 a model may have" in str(info.value), str(info.value)
        assert fingerprint(busy_sim) == before
    assert_next_spawn_works(busy_sim, "c")


def test_a_plugin_that_raises_in_configure_leaves_no_debris(busy_sim: Simulation, monkeypatch) -> None:
    from gazelle.systems.diff_drive import DiffDrive

    def broken(self, ctx):  # a bug in a plugin, of any exception type
        ctx.world.add_actuator(ctx.entity, "base_left_wheel_joint", ActuatorKind.VELOCITY, kv=1.0)
        raise KeyError("surprise")

    robot = load(SEED_XACRO).model
    before = fingerprint(busy_sim)
    monkeypatch.setattr(DiffDrive, "configure", broken)
    with pytest.raises(WorldError) as info:
        busy_sim.spawn(robot, name="dd")
    assert "cannot build 'dd': KeyError: 'surprise'" in str(info.value)
    assert fingerprint(busy_sim) == before
    monkeypatch.undo()
    busy_sim.spawn(robot, name="dd", pose=Pose((0.0, 3.0, 0.05)))  # the same name, no "repeated name" debris
    assert "dd" in busy_sim.world.entities


def test_a_wheel_on_a_fixed_joint_is_named_as_fixed(busy_sim: Simulation, caplog) -> None:
    from xml.dom.minidom import Document

    import xacro

    from gazelle.description import SourceLocation  # noqa: F401 - the model is real xacro output

    document = xacro.process_file(str(SEED_XACRO))
    assert isinstance(document, Document)  # (xacro's annotation says a file)
    urdf = document.toxml().replace(
        'name="base_right_wheel_joint" type="continuous"', 'name="base_right_wheel_joint" type="fixed"'
    )
    assert 'type="fixed"' in urdf
    with caplog.at_level(logging.ERROR):
        busy_sim.spawn(load_string(urdf).model, name="dd", pose=Pose((0.0, 3.0, 0.05)))
    text = "\n".join(r.getMessage() for r in caplog.records)
    assert "Joint [base_right_wheel_joint] is fixed" in text, text
    from gazelle.physics._entities import no_joint_message as _no_joint_message

    assert "is fixed" in _no_joint_message(busy_sim.world.entities["dd"], "base_right_wheel_joint")
    assert "movable joints: base_left_wheel_joint" in _no_joint_message(busy_sim.world.entities["dd"], "r")


def test_a_failed_batch_member_leaves_the_others_and_the_world_intact(busy_sim: Simulation) -> None:
    deep = load_string(chain(1200, "fixed")).model
    box = load_string(BOX).model
    before_names = tuple(busy_sim.world.entities)
    out = busy_sim.spawn_many([SpawnRequest(box, "b1", Pose((3.0, 3.0, 0.5))), SpawnRequest(deep, "deep", Pose())])
    assert not isinstance(out[0], WorldError) and isinstance(out[1], WorldError)
    assert tuple(busy_sim.world.entities) == (*before_names, "b1")
    assert np.all(np.isfinite(busy_sim.world.data.qpos))


@pytest.mark.parametrize(
    ("pose", "field"), [(Pose((0.0, 0.0, -1e12)), "position.z"), (Pose((1e308, 0.0, 0.0)), "position.x")]
)
def test_absurd_poses_are_refused_with_the_field_named(busy_sim: Simulation, pose: Pose, field: str) -> None:
    before = fingerprint(busy_sim)
    with pytest.raises(WorldError) as info:
        busy_sim.spawn(load_string(BOX).model, name="far", pose=pose)
    assert field in str(info.value) and "out of range" in str(info.value)
    with pytest.raises(WorldError) as info:
        busy_sim.world.set_entity_state("box", pose)
    assert field in str(info.value)
    assert fingerprint(busy_sim) == before


def test_a_diverging_entity_is_reported_once_then_summarised(busy_sim: Simulation, caplog) -> None:
    """Poisoned every step for 2,000 steps (a reset loop): one ERROR line, not 2,000."""
    d = busy_sim.world.data
    with caplog.at_level(logging.ERROR, logger="gazelle"):
        for _ in range(2000):
            d.qvel[-1] = float("nan")  # the box's last dof
            busy_sim.step()
    errors = [r.getMessage() for r in caplog.records if r.levelno >= logging.ERROR]
    assert 1 <= len(errors) <= 2, errors
    assert "simulation of 'box' diverged" in errors[0]
    assert np.all(np.isfinite(d.qpos))


def test_unsimulated_contact_parameters_are_reported_once_per_model_file(caplog, make_sim) -> None:
    from _paths import REPO

    sim = make_sim()
    piece = load(REPO / "examples" / "chessboard" / "chess_piece.sdf").model
    with caplog.at_level(logging.WARNING, logger="gazelle.physics"):
        for i in range(32):
            sim.spawn(piece, name=f"p{i}", pose=Pose((0.1 * i, 0.0, 0.1)))
    lines = [r.getMessage() for r in caplog.records if "not simulated" in r.getMessage()]
    assert len(lines) == 1, lines
    assert "<max_vel>" in lines[0] and "<min_depth>" in lines[0] and "chess_piece.sdf" in lines[0]


def test_a_body_spawned_into_the_ground_rises_gently_and_rests(make_sim) -> None:
    """gazebo_ros's skid-steer demo: sphere wheels (r 0.5) start 0.2 m inside the ground. It shot up to
    29 m and landed upside down; now it rises at a bounded speed and settles on its wheels."""
    inertial = "<inertial><mass>{m}</mass><inertia><ixx>{i}</ixx><iyy>{i}</iyy><izz>{i}</izz></inertia></inertial>"
    wheels = joints = ""
    for n, (x, y) in {"fl": (0.5, 0.6), "fr": (0.5, -0.6), "rl": (-0.5, 0.6), "rr": (-0.5, -0.6)}.items():
        wheels += (
            f"<link name='{n}'><pose>{x} {y} 0 -1.5707 0 0</pose>{inertial.format(m=1, i=0.1)}"
            "<collision name='c'><geometry><sphere><radius>0.5</radius></sphere></geometry></collision></link>"
        )
        joints += f"<joint name='{n}_j' type='revolute'><parent>chassis</parent><child>{n}</child><axis><xyz>0 0 1</xyz></axis></joint>"
    vehicle = (
        f"<sdf version='1.6'><model name='v'><link name='chassis'>{inertial.format(m=10, i=1)}<collision name='c'>"
        f"<geometry><box><size>1.5 1 0.3</size></box></geometry></collision></link>{wheels}{joints}</model></sdf>"
    )
    sim = make_sim()
    sim.spawn(load_string(vehicle).model, name="v", pose=Pose((0.0, 0.0, 0.3)))  # wheel bottoms at -0.2
    top = fastest = 0.0
    st = sim.world.entity_state("v")
    for _ in range(4000):
        sim.step()
        st = sim.world.entity_state("v")
        top, fastest = max(top, st.pose.position[2]), max(fastest, st.linear_velocity[2])
    assert fastest <= 0.5 + 1e-6, fastest
    assert top < 0.5 + 0.05  # at rest the chassis centre is 0.5 up (the wheel radius); never 5 cm above it
    assert st.pose.position[2] == pytest.approx(0.5, abs=0.01)
    q = st.pose.orientation
    assert 1 - 2 * (q[1] ** 2 + q[2] ** 2) > 0.999  # upright


def test_when_contacts_outgrow_mujocos_arena_it_grows_and_the_world_keeps_stepping(caplog, make_sim) -> None:
    """8 clients spawning boxes at one spot ran MuJoCo out of arena memory, and its FatalError killed
    the simulation thread. Here the arena starts tiny so a pile of 40 overlapping boxes overflows it."""
    sim = make_sim()
    sim.world.spec.memory = 1 << 20  # 1 MiB
    sim.world._recompile()
    box = load_string(BOX).model
    with caplog.at_level(logging.WARNING, logger="gazelle.physics"):
        for i in range(40):
            sim.spawn(box, name=f"b{i}", pose=Pose((0.0, 0.0, 0.1)))
        sim.step(200)
    assert any("arena ran out" in r.getMessage() for r in caplog.records)
    assert sim.world.model.narena > 1 << 20 and not sim.paused
    assert np.all(np.isfinite(sim.world.data.qpos))


def test_past_the_arena_cap_the_simulation_pauses_and_says_why(monkeypatch, caplog, make_sim) -> None:
    from gazelle.physics import _world

    monkeypatch.setattr(_world, "MAX_ARENA_BYTES", 1 << 20)
    sim = make_sim()
    sim.world.spec.memory = 1 << 20
    sim.world._recompile()
    box = load_string(BOX).model
    refused = 0
    for i in range(40):
        try:
            sim.spawn(box, name=f"b{i}", pose=Pose((0.0, 0.0, 0.1)))
        except WorldError as err:
            refused += 1
            assert "arena" in str(err) and f"b{i}" not in sim.world.entities  # refused, and left out
    with caplog.at_level(logging.ERROR, logger="gazelle"):
        sim.step(50)
    if refused == 0:  # the pile overflowed while stepping instead: paused, said once
        assert sim.paused and sum("simulation paused" in r.getMessage() for r in caplog.records) == 1
    sim.delete("b0")  # and requests are still served

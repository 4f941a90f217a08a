"""Conformance of the classic gazebo_ros services at the root names, against a real `gazelle sim`."""

from __future__ import annotations

import math
import threading

import pytest
from _harness import wait_for
from gazebo_msgs.msg import EntityState
from gazebo_msgs.srv import DeleteEntity, GetEntityState, GetModelList, SetEntityState, SpawnEntity
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty

BOX = """<sdf version="1.9"><model name="box"><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
  <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
</link></model></sdf>"""


@pytest.fixture
def world(sim_factory, ros_client):
    sim_factory()
    clock: list[float] = []
    lock = threading.Lock()

    def on_clock(m: Clock) -> None:
        with lock:
            clock.append(m.clock.sec + m.clock.nanosec * 1e-9)

    ros_client.node.create_subscription(Clock, "/clock", on_clock, 10)

    def latest() -> float | None:
        with lock:
            return clock[-1] if clock else None

    wait_for(latest, 15, "/clock")
    return ros_client, latest


def spawn(client, name: str, *, z: float = 0.1, x: float = 0.0, frame: str = "") -> SpawnEntity.Response:
    req = SpawnEntity.Request(name=name, xml=BOX, reference_frame=frame)
    req.initial_pose.position.x, req.initial_pose.position.z = x, z
    return client.call(SpawnEntity, "/spawn_entity", req)


def test_spawn_and_delete(world):
    client, _ = world
    res = spawn(client, "b1")
    assert res.success and res.status_message == "SpawnEntity: Successfully spawned entity [b1]"
    dup = spawn(client, "b1")
    assert not dup.success and "already exists" in dup.status_message
    res = client.call(DeleteEntity, "/delete_entity", DeleteEntity.Request(name="b1"))
    assert res.success and "b1" in res.status_message
    res = client.call(DeleteEntity, "/delete_entity", DeleteEntity.Request(name="b1"))
    assert not res.success and "does not exist" in res.status_message


def test_get_model_list(world):
    client, _ = world
    assert spawn(client, "listed").success
    res = client.call(GetModelList, "/get_model_list", GetModelList.Request())
    assert res.success and set(res.model_names) == {"ground_plane", "listed"}
    assert res.header.stamp.sec + res.header.stamp.nanosec > 0


def test_get_entity_state_in_world_and_relative_frames(world):
    client, _ = world
    assert spawn(client, "a", x=1.0, z=0.1).success
    assert spawn(client, "b", x=3.0, z=0.1).success
    wait_for(lambda: abs(client.entity_state("b").state.twist.linear.z) < 1e-4, 10, "b at rest")
    res = client.entity_state("b")
    assert res.header.frame_id == "" and res.state.pose.position.x == pytest.approx(3.0, abs=1e-3)
    rel = client.call(GetEntityState, "/get_entity_state", GetEntityState.Request(name="b", reference_frame="a"))
    assert rel.success and rel.header.frame_id == "a"
    assert rel.state.pose.position.x == pytest.approx(2.0, abs=1e-3)
    link = client.call(GetEntityState, "/get_entity_state", GetEntityState.Request(name="b::body"))
    assert link.success and link.state.pose.position.x == pytest.approx(3.0, abs=1e-3)
    for req in (GetEntityState.Request(name="nope"), GetEntityState.Request(name="b", reference_frame="nope")):
        assert not client.call(GetEntityState, "/get_entity_state", req).success
    # every world-frame spelling means the world, in every service (one frame resolver for all)
    for world_name in ("world", "/world", "map", "/map"):
        res = client.call(
            GetEntityState, "/get_entity_state", GetEntityState.Request(name="b", reference_frame=world_name)
        )
        assert res.success and res.state.pose.position.x == pytest.approx(3.0, abs=1e-3), world_name
    assert spawn(client, "c", x=5.0, frame="/world").success
    assert client.entity_state("c").state.pose.position.x == pytest.approx(5.0, abs=1e-3)


def test_set_entity_state(world):
    client, _ = world
    assert spawn(client, "mover").success
    state = EntityState(name="mover")
    state.pose.position.x, state.pose.position.y, state.pose.position.z = 2.0, -1.0, 0.5
    state.pose.orientation.w = 1.0
    assert client.call(SetEntityState, "/set_entity_state", SetEntityState.Request(state=state)).success
    p = client.entity_state("mover").state.pose.position
    assert math.dist((p.x, p.y), (2.0, -1.0)) < 1e-3 and p.z <= 0.5
    state.name = "ghost"
    assert not client.call(SetEntityState, "/set_entity_state", SetEntityState.Request(state=state)).success
    state.name = "mover"
    state.pose.position.x = math.nan
    assert not client.call(SetEntityState, "/set_entity_state", SetEntityState.Request(state=state)).success


def test_pause_unpause_and_resets(world):
    client, latest = world
    client.call(Empty, "/pause_physics", Empty.Request())
    stopped = latest()
    t0 = client.call(GetModelList, "/get_model_list", GetModelList.Request()).header.stamp
    # paused: sim time in two replies 0.3 s of wall time apart is the same
    threading.Event().wait(0.3)
    t1 = client.call(GetModelList, "/get_model_list", GetModelList.Request()).header.stamp
    assert (t0.sec, t0.nanosec) == (t1.sec, t1.nanosec)
    assert stopped is not None and latest() - stopped < 0.05
    client.call(Empty, "/unpause_physics", Empty.Request())
    wait_for(lambda: latest() > stopped + 0.5, 10, "/clock to advance after unpause")

    assert spawn(client, "faller", z=2.0).success
    wait_for(lambda: client.entity_state("faller").state.pose.position.z < 1.0, 10, "the box to fall")
    before = latest()
    client.call(Empty, "/reset_world", Empty.Request())  # state only: time goes on, the box is back up
    assert client.entity_state("faller").state.pose.position.z > 1.5
    assert latest() >= before
    client.call(Empty, "/reset_simulation", Empty.Request())  # time too
    wait_for(lambda: latest() < before, 10, "/clock to restart from zero")
    names = client.call(GetModelList, "/get_model_list", GetModelList.Request()).model_names
    assert "faller" in names  # spawned entities stay, as in gazebo_ros


@pytest.mark.parametrize("sig", ["SIGINT", "SIGTERM"])
def test_a_bonded_spawn_deletes_its_entity_when_interrupted(world, sig):
    """gazebo_ros's spawn_entity.py ``-b``: it stays, and deletes the entity when interrupted (gazelle's
    refused the flag); ``-package_to_model`` is taken too (the XML parsed and written again)."""
    import signal

    from _harness import GAZELLE, start

    client, _ = world

    def names() -> list[str]:
        return list(client.call(GetModelList, "/get_model_list", GetModelList.Request()).model_names)

    proc = start([*GAZELLE, "spawn", "-entity", "bonded", "-string", BOX, "-b", "-package_to_model"], "spawn -b")
    proc.wait_line("Waiting for shutdown to delete entity [bonded]", 60)
    assert "bonded" in names()
    proc.popen.send_signal(getattr(signal, sig))
    assert proc.wait(30) == 0, proc.output
    assert "bonded" not in names() and "Deleting status:" in proc.output, proc.output
    assert "Traceback" not in proc.output, proc.output


def test_package_to_model_rewrites_package_mesh_uris_only():
    """spawn_entity.py's -package_to_model: ``package://`` mesh filenames become ``model://``; others stay."""
    from gazelle.ros._spawn_entity import _package_to_model

    urdf = (
        '<robot name="r"><link name="a"><visual><geometry><mesh filename="package://arm/meshes/a.dae"/>'
        '</geometry></visual><collision><geometry><mesh filename="file:///m/b.stl"/></geometry></collision>'
        "</link></robot>"
    )
    out = _package_to_model(urdf)
    assert out is not None and 'filename="model://arm/meshes/a.dae"' in out and 'filename="file:///m/b.stl"' in out
    assert _package_to_model("<robot") is None

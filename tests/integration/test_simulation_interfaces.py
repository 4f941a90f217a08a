"""simulation_interfaces (Jazzy 1.5.1) conformance over real DDS: every service and the SimulateSteps action.

One `gazelle sim` server (started paused) serves the whole module; each test
spawns entities with its own names and puts the simulation in the state it needs.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from _harness import GAZELLE, SEED_XACRO, Proc, RosClient, start, wait_for, xacro_to_urdf
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from rclpy.action.client import ActionClient
from simulation_interfaces import srv
from simulation_interfaces.action import SimulateSteps
from simulation_interfaces.msg import EntityCategory, Result, SimulationState, SimulatorFeatures
from simulation_interfaces.msg import SpawnEntity as SpawnEntityMsg

pytestmark = pytest.mark.ros

OK = Result.RESULT_OK
NS = "/gazelle/"


def box_sdf(name: str = "box", size: float = 0.2, static: bool = False) -> str:
    return (
        f'<?xml version="1.0"?>\n<sdf version="1.9">\n  <model name="{name}">\n'
        f"    <static>{'true' if static else 'false'}</static>\n"
        '    <link name="link">\n      <inertial><mass>1.0</mass></inertial>\n'
        f'      <collision name="c"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>\n'
        "    </link>\n  </model>\n</sdf>\n"
    )


BROKEN_SDF = (
    '<?xml version="1.0"?>\n<sdf version="1.9">\n  <model name="broken">\n    <link name="l">\n  </model>\n</sdf>\n'
)


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory, ros_env: dict[str, str]) -> Iterator[Proc]:
    res = tmp_path_factory.mktemp("resources")
    (res / "crate").mkdir()
    (res / "crate" / "model.sdf").write_text(box_sdf("crate", 0.3))
    (res / "notes.txt").write_text("not a model")
    secret = tmp_path_factory.mktemp("private") / "secret.sdf"
    secret.write_text(box_sdf("SECRET_MODEL"))
    (res / "evil").mkdir()
    (res / "evil" / "model.sdf").symlink_to(secret)  # a link out of the resource paths is never followed
    env = dict(ros_env, GAZELLE_RESOURCE_PATH=str(res))
    proc = start([*GAZELLE, "sim", "--paused"], "gazelle sim", env=env)
    proc.wait_line("gazelle: ready", timeout=60)
    proc.resources = res  # type: ignore[attr-defined]
    yield proc
    rc = proc.interrupt()
    assert rc == 0, f"gazelle sim exited with {rc} on Ctrl-C:\n{proc.output}"


@pytest.fixture(scope="module")
def ros(server: Proc) -> Iterator[RosClient]:
    client = RosClient("si_test_client")
    yield client
    client.close()


def call(ros: RosClient, kind: Any, service: str, **fields: Any) -> Any:
    return ros.call(kind, NS + service, kind.Request(**fields))


def set_state(ros: RosClient, state: int) -> int:
    res = call(ros, srv.SetSimulationState, "set_simulation_state", state=SimulationState(state=state))
    return res.result.result


def pause(ros: RosClient) -> None:
    assert set_state(ros, SimulationState.STATE_PAUSED) in (OK, srv.SetSimulationState.Response.ALREADY_IN_TARGET_STATE)


def spawn(
    ros: RosClient, name: str = "", *, uri: str = "", xml: str = "", frame: str = "", z: float = 0.0, **kw: Any
) -> Any:
    pose = PoseStamped()
    pose.header.frame_id = frame
    pose.pose.position.z = z
    return call(ros, srv.SpawnEntity, "spawn_entity", name=name, uri=uri, resource_string=xml, initial_pose=pose, **kw)


def entity_state(ros: RosClient, name: str) -> Any:
    res = call(ros, srv.GetEntityState, "get_entity_state", entity=name)
    assert res.result.result == OK, res.result.error_message
    return res.state


def stamp(state: Any) -> float:
    return state.header.stamp.sec + state.header.stamp.nanosec * 1e-9


# ---------------------------------------------------------------------- features and simulation state
def test_get_simulator_features(ros: RosClient) -> None:
    f = ros.call(srv.GetSimulatorFeatures, NS + "get_simulator_features", srv.GetSimulatorFeatures.Request()).features
    feats = set(f.features)
    for want in (
        SimulatorFeatures.SPAWNING,
        SimulatorFeatures.DELETING,
        SimulatorFeatures.SPAWNING_RESOURCE_STRING,
        SimulatorFeatures.SPAWNING_ENTITIES,
        SimulatorFeatures.ENTITY_CATEGORIES,
        SimulatorFeatures.ENTITY_STATE_GETTING,
        SimulatorFeatures.ENTITY_STATE_SETTING,
        SimulatorFeatures.ENTITY_INFO_GETTING,
        SimulatorFeatures.SIMULATION_RESET,
        SimulatorFeatures.SIMULATION_RESET_SPAWNED,
        SimulatorFeatures.SIMULATION_STATE_PAUSE,
        SimulatorFeatures.STEP_SIMULATION_SINGLE,
        SimulatorFeatures.STEP_SIMULATION_MULTIPLE,
        SimulatorFeatures.STEP_SIMULATION_ACTION,
    ):
        assert want in feats
    # truthful: nothing we do not implement
    for absent in (
        SimulatorFeatures.ENTITY_TAGS,
        SimulatorFeatures.ENTITY_BOUNDS,
        SimulatorFeatures.NAMED_POSES,
        SimulatorFeatures.ENTITY_INFO_SETTING,
        SimulatorFeatures.SPAWNABLES,
    ):
        assert absent not in feats
    assert list(f.spawn_formats) == ["urdf", "sdf"]
    assert "xacro" in f.custom_info


def test_simulation_state_transitions(ros: RosClient) -> None:
    A = srv.SetSimulationState.Response
    assert set_state(ros, SimulationState.STATE_PLAYING) == OK
    assert set_state(ros, SimulationState.STATE_PLAYING) == A.ALREADY_IN_TARGET_STATE
    got = call(ros, srv.GetSimulationState, "get_simulation_state")
    assert got.result.result == OK and got.state.state == SimulationState.STATE_PLAYING
    assert spawn(ros, "state_box", xml=box_sdf(), z=1.0).result.result == OK
    wait_for(lambda: stamp(entity_state(ros, "state_box")) > 0.05, 10, "sim time to advance while playing")
    assert set_state(ros, SimulationState.STATE_PAUSED) == OK
    assert call(ros, srv.GetSimulationState, "get_simulation_state").state.state == SimulationState.STATE_PAUSED
    res = call(
        ros, srv.SetSimulationState, "set_simulation_state", state=SimulationState(state=SimulationState.STATE_QUITTING)
    )
    assert res.result.result == A.INCORRECT_TRANSITION
    assert "Ctrl-C" in res.result.error_message
    # STOPPED = pause + reset everything: time to 0, spawned entities removed
    assert set_state(ros, SimulationState.STATE_STOPPED) == OK
    assert call(ros, srv.GetSimulationState, "get_simulation_state").state.state == SimulationState.STATE_STOPPED
    assert set_state(ros, SimulationState.STATE_STOPPED) == A.ALREADY_IN_TARGET_STATE
    assert stamp(entity_state(ros, "ground_plane")) == 0.0
    gone = call(ros, srv.GetEntityState, "get_entity_state", entity="state_box")
    assert gone.result.result == Result.RESULT_NOT_FOUND
    bad = call(ros, srv.SetSimulationState, "set_simulation_state", state=SimulationState(state=42))
    assert bad.result.result == Result.RESULT_OPERATION_FAILED


def test_reset_simulation_scopes(ros: RosClient) -> None:
    R = srv.ResetSimulation.Request
    pause(ros)
    assert spawn(ros, "reset_box", xml=box_sdf(), z=2.0).result.result == OK
    assert call(ros, srv.StepSimulation, "step_simulation", steps=400).result.result == OK
    fallen = entity_state(ros, "reset_box")
    assert fallen.pose.position.z < 1.5
    t = stamp(fallen)
    assert call(ros, srv.ResetSimulation, "reset_simulation", scope=R.SCOPE_STATE).result.result == OK
    back = entity_state(ros, "reset_box")
    assert back.pose.position.z == pytest.approx(2.0, abs=1e-6)
    assert stamp(back) == pytest.approx(t, abs=1e-6)  # time kept
    assert call(ros, srv.ResetSimulation, "reset_simulation", scope=R.SCOPE_TIME).result.result == OK
    assert stamp(entity_state(ros, "reset_box")) == 0.0
    assert call(ros, srv.ResetSimulation, "reset_simulation", scope=R.SCOPE_SPAWNED).result.result == OK
    assert (
        call(ros, srv.GetEntityState, "get_entity_state", entity="reset_box").result.result == Result.RESULT_NOT_FOUND
    )
    assert call(ros, srv.GetEntityState, "get_entity_state", entity="ground_plane").result.result == OK
    bad = call(ros, srv.ResetSimulation, "reset_simulation", scope=8)
    assert bad.result.result == Result.RESULT_FEATURE_UNSUPPORTED and "scope" in bad.result.error_message
    assert call(ros, srv.ResetSimulation, "reset_simulation", scope=R.SCOPE_DEFAULT).result.result == OK


# ---------------------------------------------------------------------- stepping
def test_step_simulation(ros: RosClient) -> None:
    assert set_state(ros, SimulationState.STATE_PLAYING) in (
        OK,
        srv.SetSimulationState.Response.ALREADY_IN_TARGET_STATE,
    )
    res = call(ros, srv.StepSimulation, "step_simulation", steps=10)
    assert res.result.result == Result.RESULT_INCORRECT_STATE and "paused" in res.result.error_message
    pause(ros)
    t0 = stamp(entity_state(ros, "ground_plane"))
    assert call(ros, srv.StepSimulation, "step_simulation").result.result == OK  # default steps = 1
    assert call(ros, srv.StepSimulation, "step_simulation", steps=250).result.result == OK
    assert stamp(entity_state(ros, "ground_plane")) == pytest.approx(t0 + 0.251, abs=1e-6)
    zero = call(ros, srv.StepSimulation, "step_simulation", steps=0)
    assert zero.result.result == Result.RESULT_OPERATION_FAILED and "steps" in zero.result.error_message


def test_step_simulation_is_served_beside_the_simulation_node_not_by_it(ros: RosClient) -> None:
    """A lockstep test calls srv.StepSimulation every 10 ms of sim time: served by /gazelle, whose executor
    builds its wait set from every service and plugin node of the server, a call took ~7 ms; from a node
    and an executor of its own, 3.5-5.5 ms (the same name: ``/gazelle/step_simulation``)."""
    node = ros.node

    def services(name: str) -> list[str]:
        return [s for s, _ in node.get_service_names_and_types_by_node(name, "/")]

    wait_for(lambda: NS + "step_simulation" in services("gazelle_stepping"), 10, "the stepping node's service")
    assert NS + "step_simulation" not in services("gazelle")
    assert NS + "spawn_entity" in services("gazelle")


def _send_goal(client: ActionClient, steps: int, feedback: list) -> Any:
    fut = client.send_goal_async(
        SimulateSteps.Goal(steps=steps), feedback_callback=lambda m: feedback.append(m.feedback)
    )
    return wait_for(lambda: fut.done() and fut.result(), 10, "goal response")


def test_simulate_steps_action(ros: RosClient) -> None:
    client = ActionClient(ros.node, SimulateSteps, NS + "simulate_steps")
    try:
        assert client.wait_for_server(timeout_sec=15)
        # not paused: aborted with INCORRECT_STATE
        set_state(ros, SimulationState.STATE_PLAYING)
        handle = _send_goal(client, 10, [])
        rf = handle.get_result_async()
        res = wait_for(lambda: rf.done() and rf.result(), 10, "result")
        assert res.status == GoalStatus.STATUS_ABORTED
        assert res.result.result.result == Result.RESULT_INCORRECT_STATE
        # paused: runs to completion with feedback
        pause(ros)
        t0 = stamp(entity_state(ros, "ground_plane"))
        feedback: list = []
        handle = _send_goal(client, 3000, feedback)
        assert handle.accepted
        rf = handle.get_result_async()
        res = wait_for(lambda: rf.done() and rf.result(), 30, "result")
        assert res.status == GoalStatus.STATUS_SUCCEEDED and res.result.result.result == OK
        assert feedback and all(f.completed_steps + f.remaining_steps == 3000 for f in feedback)
        assert feedback[-1].completed_steps == 3000 and feedback[-1].remaining_steps == 0
        assert stamp(entity_state(ros, "ground_plane")) == pytest.approx(t0 + 3.0, abs=1e-6)
        # cancellable, and other requests are served while it runs
        feedback = []
        handle = _send_goal(client, 10**9, feedback)
        wait_for(lambda: feedback, 10, "first feedback")
        assert call(ros, srv.GetSimulationState, "get_simulation_state").result.result == OK
        cf = handle.cancel_goal_async()
        wait_for(lambda: cf.done(), 10, "cancel response")
        rf = handle.get_result_async()
        res = wait_for(lambda: rf.done() and rf.result(), 20, "cancelled result")
        assert res.status == GoalStatus.STATUS_CANCELED
        assert "cancelled after" in res.result.result.error_message
        # too many steps: refused
        handle = _send_goal(client, 2**40, [])
        rf = handle.get_result_async()
        res = wait_for(lambda: rf.done() and rf.result(), 10, "result")
        assert res.status == GoalStatus.STATUS_ABORTED and res.result.result.result == Result.RESULT_OPERATION_FAILED
    finally:
        client.destroy()


# ---------------------------------------------------------------------- spawning and deleting
def test_spawn_entity_uri_and_renaming(ros: RosClient, server: Proc) -> None:
    pause(ros)
    # the server never runs xacro, not even on a file found by URI: the reply says what to do
    refused = spawn(ros, uri=str(SEED_XACRO), z=0.1)
    assert refused.result.result == srv.SpawnEntity.Response.RESOURCE_PARSE_ERROR
    assert (
        "[XACRO_NOT_ALLOWED]" in refused.result.error_message and "gazelle spawn -file" in refused.result.error_message
    )
    urdf = server.resources / "simple_robot.urdf"  # type: ignore[attr-defined]
    urdf.write_text(xacro_to_urdf(SEED_XACRO))
    SEED_URDF = str(urdf)
    res = spawn(ros, uri=SEED_URDF, z=0.1)
    assert res.result.result == OK, res.result.error_message
    assert res.entity_name == "simple_robot"  # empty name: the file's model name
    again = spawn(ros, uri=SEED_URDF, allow_renaming=True)
    assert again.result.result == OK and again.entity_name == "simple_robot_1"
    dup = spawn(ros, uri=SEED_URDF)
    assert dup.result.result == srv.SpawnEntity.Response.NAME_NOT_UNIQUE and "simple_robot" in dup.result.error_message
    # the refused duplicate did not disturb the existing robot
    assert entity_state(ros, "simple_robot").pose.position.z == pytest.approx(0.1, abs=0.05)
    ns = spawn(ros, "ns_robot", uri="file://" + SEED_URDF, entity_namespace="robot1", frame="simple_robot", z=1.0)
    assert ns.result.result == OK, ns.result.error_message
    info = call(ros, srv.GetEntityInfo, "get_entity_info", entity="ns_robot")
    assert "/robot1" in info.info.description
    # frame_id is an entity: pose composed with its pose
    assert entity_state(ros, "ns_robot").pose.position.z == pytest.approx(
        entity_state(ros, "simple_robot").pose.position.z + 1.0, abs=1e-6
    )
    crate = spawn(ros, uri="model://crate", z=0.5)
    assert crate.result.result == OK and crate.entity_name == "crate"
    evil = spawn(ros, "x", uri="model://evil")
    assert (
        evil.result.result == srv.SpawnEntity.Response.NO_RESOURCE and "SECRET_MODEL" not in evil.result.error_message
    )
    assert "outside" in evil.result.error_message, evil.result.error_message
    for uri in (
        "model://no_such_model",
        "model://crate/../../../etc/passwd",
        "package://nope/x.urdf",
        "http://x/y.sdf",
    ):
        r = spawn(ros, "x", uri=uri)
        assert r.result.result == srv.SpawnEntity.Response.NO_RESOURCE, uri
        assert uri in r.result.error_message
    txt = spawn(ros, "x", uri=str(server.resources / "notes.txt"))  # type: ignore[attr-defined]
    assert txt.result.result == srv.SpawnEntity.Response.UNSUPPORTED_FORMAT
    assert spawn(ros, "x").result.result == srv.SpawnEntity.Response.NO_RESOURCE


def test_spawn_entity_failures(ros: RosClient, tmp_path: Path) -> None:
    R = srv.SpawnEntity.Response
    ok = spawn(ros, "str_box", xml=box_sdf("whatever"), z=0.5)
    assert ok.result.result == OK and ok.entity_name == "str_box"
    parse = spawn(ros, "broken", xml=BROKEN_SDF)
    assert parse.result.result == R.RESOURCE_PARSE_ERROR
    assert re.search(r":\d+", parse.result.error_message), parse.result.error_message  # file:line
    assert spawn(ros, "bad::name", xml=box_sdf()).result.result == R.NAME_INVALID
    assert spawn(ros, " padded", xml=box_sdf()).result.result == R.NAME_INVALID
    spaced = spawn(ros, "Construction Cone", xml=box_sdf(), z=3.0)  # Gazebo GUI-saved worlds are full of these
    assert spaced.result.result == OK and spaced.entity_name == "Construction Cone"
    assert spawn(ros, "x", xml="<robot name='r'>", z=0.0).result.result == R.RESOURCE_PARSE_ERROR
    assert spawn(ros, "ns_bad", xml=box_sdf(), entity_namespace="1bad ns").result.result == R.NAMESPACE_INVALID
    nan = spawn(ros, "nan_box", xml=box_sdf(), z=math.nan)
    assert nan.result.result == R.INVALID_POSE
    frame = spawn(ros, "frame_box", xml=box_sdf(), frame="no_such_frame")
    assert frame.result.result == Result.RESULT_OPERATION_FAILED
    assert (
        "initial_pose.header.frame_id" in frame.result.error_message and "no_such_frame" in frame.result.error_message
    )
    # a real model file outside the resource paths is not read, by path or by file://
    outside = tmp_path / "secret_robot.sdf"
    outside.write_text(box_sdf("secret"))
    for uri in (str(outside), f"file://{outside}"):
        res = spawn(ros, "secret", uri=uri)
        assert res.result.result == R.NO_RESOURCE and "outside the resource paths" in res.result.error_message


def test_spawn_entities_batch(ros: RosClient) -> None:
    def item(name: str, xml: str, z: float = 0.5, rename: bool = False) -> SpawnEntityMsg:
        m = SpawnEntityMsg(name=name, allow_renaming=rename)
        m.entity_resource.resource_string = xml
        m.initial_pose.pose.position.z = z
        return m

    reqs = [item(f"batch_{i}", box_sdf(), z=0.2 + 0.3 * i) for i in range(20)]
    t0 = time.monotonic()
    res = ros.call(srv.SpawnEntities, NS + "spawn_entities", srv.SpawnEntities.Request(spawn_requests=reqs))
    elapsed = time.monotonic() - t0
    assert res.result.result == OK, res.result.error_message
    assert [r.entity_name for r in res.results] == [f"batch_{i}" for i in range(20)]
    assert all(r.result.result == OK for r in res.results)
    assert elapsed < 5.0
    mixed = [
        item("batch_0", box_sdf(), rename=True),
        item("batch_0", box_sdf()),
        item("batch_bad", BROKEN_SDF),
        item("batch_nan", box_sdf(), z=math.nan),
        item("batch_new", box_sdf()),
    ]
    res = ros.call(srv.SpawnEntities, NS + "spawn_entities", srv.SpawnEntities.Request(spawn_requests=mixed))
    assert res.result.result == srv.SpawnEntities.Response.ENTITIES_SPAWN_FAILED
    codes = [r.result.result for r in res.results]
    assert codes == [
        OK,
        srv.SpawnEntity.Response.NAME_NOT_UNIQUE,
        srv.SpawnEntity.Response.RESOURCE_PARSE_ERROR,
        srv.SpawnEntity.Response.INVALID_POSE,
        OK,
    ]
    assert res.results[0].entity_name == "batch_0_1" and res.results[4].entity_name == "batch_new"
    names = call(ros, srv.GetEntities, "get_entities", filters=srv.GetEntities.Request().filters).entities
    assert {"batch_0_1", "batch_new", "batch_19"} <= set(names) and "batch_bad" not in names


def test_delete_entity(ros: RosClient) -> None:
    assert spawn(ros, "del_box", xml=box_sdf(), z=0.5).result.result == OK
    assert call(ros, srv.DeleteEntity, "delete_entity", entity="del_box").result.result == OK
    again = call(ros, srv.DeleteEntity, "delete_entity", entity="del_box")
    assert again.result.result == Result.RESULT_NOT_FOUND and "del_box" in again.result.error_message


# ---------------------------------------------------------------------- queries and state setting
def _filters(pattern: str = "", categories: tuple[int, ...] = ()) -> Any:
    f = srv.GetEntities.Request().filters
    f.filter = pattern
    f.categories = [EntityCategory(category=c) for c in categories]
    return f


def test_get_entities_filters(ros: RosClient) -> None:
    assert spawn(ros, "q_robot", xml=xacro_to_urdf(SEED_XACRO), allow_renaming=True).result.result == OK
    assert spawn(ros, "q_box", xml=box_sdf(), z=0.5).result.result == OK
    assert spawn(ros, "q_wall", xml=box_sdf("wall", static=True), z=0.5).result.result == OK
    res = call(ros, srv.GetEntities, "get_entities", filters=_filters("^q_"))
    assert res.result.result == OK and set(res.entities) == {"q_robot", "q_box", "q_wall"}
    C = EntityCategory
    cat = lambda c: set(call(ros, srv.GetEntities, "get_entities", filters=_filters("^q_", (c,))).entities)
    assert cat(C.CATEGORY_ROBOT) == {"q_robot"}
    assert cat(C.CATEGORY_DYNAMIC_OBJECT) == {"q_box"}
    assert cat(C.CATEGORY_STATIC_OBJECT) == {"q_wall"}
    assert (
        "ground_plane"
        in call(ros, srv.GetEntities, "get_entities", filters=_filters("", (C.CATEGORY_STATIC_OBJECT,))).entities
    )
    bad = call(ros, srv.GetEntities, "get_entities", filters=_filters("q_(["))
    assert bad.result.result == Result.RESULT_OPERATION_FAILED and "regular expression" in bad.result.error_message
    tags = _filters()
    tags.tags.tags = ["furniture"]
    assert call(ros, srv.GetEntities, "get_entities", filters=tags).result.result == Result.RESULT_FEATURE_UNSUPPORTED
    # a backtracking bomb against a long name is refused within its time limit, for both services
    assert spawn(ros, "a" * 60 + "!", xml=box_sdf(), z=5.0).result.result == OK
    for kind, name in ((srv.GetEntities, "get_entities"), (srv.GetEntitiesStates, "get_entities_states")):
        t0 = time.monotonic()
        bomb = call(ros, kind, name, filters=_filters("(a|aa)+$"))  # exponential backtracking
        assert time.monotonic() - t0 < 3.0
        assert bomb.result.result == Result.RESULT_OPERATION_FAILED and "took longer than" in bomb.result.error_message


def test_entity_states(ros: RosClient) -> None:
    pause(ros)
    assert spawn(ros, "st_box", xml=box_sdf(), z=3.0).result.result == OK
    st = entity_state(ros, "st_box")
    assert st.header.frame_id == "world"
    assert st.pose.position.z == pytest.approx(3.0, abs=1e-6)
    missing = call(ros, srv.GetEntityState, "get_entity_state", entity="no_such_entity")
    assert missing.result.result == Result.RESULT_NOT_FOUND and "no_such_entity" in missing.result.error_message
    many = call(ros, srv.GetEntitiesStates, "get_entities_states", filters=_filters("^(st_box|ground_plane)$"))
    assert many.result.result == OK and sorted(many.entities) == ["ground_plane", "st_box"]
    assert all(s.header.frame_id == "world" for s in many.states)
    by_name = dict(zip(many.entities, many.states))
    assert by_name["st_box"].pose.position.z == pytest.approx(3.0, abs=1e-6)
    bad = call(ros, srv.GetEntitiesStates, "get_entities_states", filters=_filters("(("))
    assert bad.result.result == Result.RESULT_OPERATION_FAILED


def test_set_entity_state(ros: RosClient) -> None:
    pause(ros)
    assert spawn(ros, "set_box", xml=box_sdf(), z=0.5).result.result == OK
    req = srv.SetEntityState.Request(entity="set_box")
    req.state.header.frame_id = "world"
    req.state.pose.position.x, req.state.pose.position.z = 2.0, 4.0
    req.state.pose.orientation.w = 1.0
    req.state.twist.linear.x = 1.5
    assert ros.call(srv.SetEntityState, NS + "set_entity_state", req).result.result == OK
    st = entity_state(ros, "set_box")
    assert st.pose.position.x == pytest.approx(2.0, abs=1e-6) and st.pose.position.z == pytest.approx(4.0, abs=1e-6)
    assert st.twist.linear.x == pytest.approx(1.5, abs=1e-6)
    req.state.pose.position.y = math.nan
    nan = ros.call(srv.SetEntityState, NS + "set_entity_state", req)
    assert nan.result.result == srv.SetEntityState.Response.INVALID_POSE
    static = srv.SetEntityState.Request(entity="ground_plane")
    static.state.pose.orientation.w = 1.0
    static.state.twist.angular.z = 1.0
    res = ros.call(srv.SetEntityState, NS + "set_entity_state", static)
    assert res.result.result == Result.RESULT_OPERATION_FAILED and "static" in res.result.error_message
    missing = srv.SetEntityState.Request(entity="no_such_entity")
    assert ros.call(srv.SetEntityState, NS + "set_entity_state", missing).result.result == Result.RESULT_NOT_FOUND


def test_get_entity_info(ros: RosClient) -> None:
    assert spawn(ros, "info_robot", xml=xacro_to_urdf(SEED_XACRO)).result.result == OK
    res = call(ros, srv.GetEntityInfo, "get_entity_info", entity="info_robot")
    assert res.result.result == OK
    assert res.info.category.category == EntityCategory.CATEGORY_ROBOT
    assert "robot" in res.info.description and "simple_robot" in res.info.description
    ground = call(ros, srv.GetEntityInfo, "get_entity_info", entity="ground_plane")
    assert ground.info.category.category == EntityCategory.CATEGORY_STATIC_OBJECT
    missing = call(ros, srv.GetEntityInfo, "get_entity_info", entity="nobody")
    assert missing.result.result == Result.RESULT_NOT_FOUND and "nobody" in missing.result.error_message

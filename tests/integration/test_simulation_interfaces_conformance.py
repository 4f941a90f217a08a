"""simulation_interfaces conformance (issue 52): each of the standard's 22 services and the SimulateSteps action,
called through rclpy against a real `gazelle sim`, with the result codes each .srv names for bad input.

One server (started paused) serves the module: a world with named poses (its ``<frame>``s, one more from
``--named-poses``), and a resource folder with model folders for GetSpawnables. Tests run in file order; the
world services come last, since UnloadWorld empties the simulation. GetSimulatorFeatures is checked both ways:
every feature listed is served, and every service advertised has its feature listed.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import pytest
from _harness import GAZELLE, Proc, RosClient, start, wait_for
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped, Vector3
from rclpy.action.client import ActionClient
from simulation_interfaces import srv
from simulation_interfaces.action import SimulateSteps
from simulation_interfaces.msg import (
    Bounds,
    EntityCategory,
    EntityFilters,
    EntityInfo,
    Result,
    SimulationState,
    SimulatorFeatures,
    TagsFilter,
)
from simulation_interfaces.msg import SpawnEntity as SpawnEntityMsg

pytestmark = pytest.mark.ros

OK = Result.RESULT_OK
NS = "/gazelle/"
F = SimulatorFeatures

SERVICES = {
    "get_simulator_features": srv.GetSimulatorFeatures,
    "get_simulation_state": srv.GetSimulationState,
    "set_simulation_state": srv.SetSimulationState,
    "reset_simulation": srv.ResetSimulation,
    "step_simulation": srv.StepSimulation,
    "spawn_entity": srv.SpawnEntity,
    "spawn_entities": srv.SpawnEntities,
    "delete_entity": srv.DeleteEntity,
    "get_entities": srv.GetEntities,
    "get_entity_state": srv.GetEntityState,
    "get_entities_states": srv.GetEntitiesStates,
    "set_entity_state": srv.SetEntityState,
    "get_entity_info": srv.GetEntityInfo,
    "set_entity_info": srv.SetEntityInfo,
    "get_entity_bounds": srv.GetEntityBounds,
    "get_named_poses": srv.GetNamedPoses,
    "get_named_pose_bounds": srv.GetNamedPoseBounds,
    "get_spawnables": srv.GetSpawnables,
}
"""The 18 services of the standard gazelle serves in this branch."""
WORLD_SERVICES = {
    "get_available_worlds": srv.GetAvailableWorlds,
    "load_world": srv.LoadWorld,
    "unload_world": srv.UnloadWorld,
    "get_current_world": srv.GetCurrentWorld,
}
"""The other 4 (with the 18: the standard's 22)."""

SERVICE_FEATURES = {
    F.SPAWNING: "spawn_entity",
    F.DELETING: "delete_entity",
    F.NAMED_POSES: "get_named_poses",
    F.POSE_BOUNDS: "get_named_pose_bounds",
    F.ENTITY_BOUNDS: "get_entity_bounds",
    F.ENTITY_STATE_GETTING: "get_entity_state",
    F.ENTITY_STATE_SETTING: "set_entity_state",
    F.ENTITY_INFO_GETTING: "get_entity_info",
    F.ENTITY_INFO_SETTING: "set_entity_info",
    F.SPAWNABLES: "get_spawnables",
    F.SIMULATION_RESET: "reset_simulation",
    F.SIMULATION_STATE_GETTING: "get_simulation_state",
    F.SIMULATION_STATE_SETTING: "set_simulation_state",
    F.STEP_SIMULATION_SINGLE: "step_simulation",
    F.SPAWNING_ENTITIES: "spawn_entities",
    F.WORLD_LOADING: "load_world",
    F.WORLD_UNLOADING: "unload_world",
    F.WORLD_INFO_GETTING: "get_current_world",
    F.AVAILABLE_WORLDS: "get_available_worlds",
}
"""Features that are a service: listed if and only if the service is advertised."""
BEHAVIOUR_FEATURES = {
    F.ENTITY_TAGS,
    F.ENTITY_BOUNDS_BOX,
    F.ENTITY_CATEGORIES,
    F.SPAWNING_RESOURCE_STRING,
    F.SIMULATION_RESET_TIME,
    F.SIMULATION_RESET_STATE,
    F.SIMULATION_RESET_SPAWNED,
    F.SIMULATION_STATE_PAUSE,
    F.STEP_SIMULATION_MULTIPLE,
    F.STEP_SIMULATION_ACTION,
}
"""Features of a field or a mode, each exercised below."""
WORLD_BEHAVIOUR_FEATURES = {F.WORLD_RESOURCE_STRING, F.WORLD_TAGS}
"""Listed once LoadWorld (resource_string) and GetAvailableWorlds (tags) are served."""


def sdf_model(name: str, body: str, static: bool = False) -> str:
    return (
        f'<?xml version="1.0"?>\n<sdf version="1.9">\n  <model name="{name}">\n'
        f"    <static>{'true' if static else 'false'}</static>\n"
        f'    <link name="link">\n      <inertial><mass>1.0</mass></inertial>\n      {body}\n'
        "    </link>\n  </model>\n</sdf>\n"
    )


def box(size: float) -> str:
    return f'<collision name="c"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>'


WORLD = """<?xml version="1.0"?>
<sdf version="1.9" xmlns:gazelle="https://gazelle.dev/sdf">
  <world name="conformance">
    <model name="ground_plane"><static>true</static><link name="link">
      <collision name="c"><geometry><plane><normal>0 0 1</normal><size>20 20</size></plane></geometry></collision>
    </link></model>
    <model name="table"><static>true</static><pose>3 0 0.4 0 0 0</pose><link name="link">
      <collision name="c"><geometry><box><size>1 1 0.8</size></box></geometry></collision>
    </link></model>
    <frame name="dock">
      <pose>-2 1 0 0 0 1.5707963267948966</pose>
      <gazelle:description>in front of the charger</gazelle:description>
      <gazelle:tag>spawn</gazelle:tag>
      <gazelle:tag>dock</gazelle:tag>
      <gazelle:box>-0.5 -0.4 0 0.5 0.4 1</gazelle:box>
    </frame>
    <frame name="parking" attached_to="world">
      <pose>0 -3 0 0 0 0</pose>
      <gazelle:tag>spawn</gazelle:tag>
      <gazelle:tag>parking</gazelle:tag>
      <gazelle:sphere>0.75</gazelle:sphere>
    </frame>
    <frame name="above_table"><pose relative_to="table">0 0 0.6 0 0 0</pose></frame>
    <frame name="on_table" attached_to="table"><pose>0 0 0.4 0 0 0</pose></frame>
  </world>
</sdf>
"""
"""dock (box bounds), parking (sphere bounds), above_table (unbounded, relative to a model); on_table moves with
the table, so it is no named pose."""

EXTRA_POSES = """<sdf version="1.9"><world name="extra">
  <frame name="loading_bay"><pose>5 5 0 0 0 0</pose><gazelle:tag>parking</gazelle:tag></frame>
</world></sdf>
"""


def config(name: str, description: str, sdf: str = "model.sdf") -> str:
    return (
        f'<?xml version="1.0"?>\n<model><name>{name}</name><version>1.0</version>'
        f'<sdf version="1.9">{sdf}</sdf><description>{description}</description></model>\n'
    )


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory, ros_env: dict[str, str]) -> Iterator[Proc]:
    res = tmp_path_factory.mktemp("resources")
    for folder, files in {
        "crate": {"model.config": config("Crate", "a wooden crate"), "model.sdf": sdf_model("crate", box(0.3))},
        "lamp": {"model.config": config("Lamp", "a lamp", "lamp.sdf"), "lamp.sdf": sdf_model("lamp", box(0.1))},
        "broken": {"model.config": config("Broken", "unfinished"), "model.sdf": "<sdf version='1.9'><model>"},
        "more/bin": {"model.config": config("Bin", "a bin"), "model.sdf": sdf_model("bin", box(0.4), static=True)},
    }.items():
        (res / folder).mkdir(parents=True)
        for name, text in files.items():
            (res / folder / name).write_text(text)
    world = res / "conformance.sdf"
    world.write_text(WORLD)
    extra = tmp_path_factory.mktemp("poses") / "extra.sdf"
    extra.write_text(EXTRA_POSES)
    env = dict(ros_env, GAZELLE_RESOURCE_PATH=str(res))
    proc = start([*GAZELLE, "sim", str(world), "--paused", "--named-poses", str(extra)], "gazelle sim", env=env)
    proc.wait_line("gazelle: ready", timeout=60)
    proc.resources = res  # type: ignore[attr-defined]
    yield proc
    rc = proc.interrupt()
    assert rc == 0, f"gazelle sim exited with {rc} on Ctrl-C:\n{proc.output}"


@pytest.fixture(scope="module")
def ros(server: Proc) -> Iterator[RosClient]:
    client = RosClient("si_conformance")
    yield client
    client.close()


def call(ros: RosClient, service: str, **fields: Any) -> Any:
    kind = {**SERVICES, **WORLD_SERVICES}[service]
    return ros.call(kind, NS + service, kind.Request(**fields))


def code(reply: Any) -> int:
    return reply.result.result


def set_state(ros: RosClient, state: int) -> int:
    return code(call(ros, "set_simulation_state", state=SimulationState(state=state)))


def pause(ros: RosClient) -> None:
    assert set_state(ros, SimulationState.STATE_PAUSED) in (OK, srv.SetSimulationState.Response.ALREADY_IN_TARGET_STATE)


def spawn(ros: RosClient, name: str, *, uri: str = "", xml: str = "", x: float = 0.0, z: float = 0.0, **kw: Any) -> Any:
    pose = PoseStamped()
    pose.pose.position.x, pose.pose.position.z = x, z
    return call(ros, "spawn_entity", name=name, uri=uri, resource_string=xml, initial_pose=pose, **kw)


def filters(pattern: str = "", tags: tuple[str, ...] = (), mode: int = 0, bounds: Bounds | None = None) -> Any:
    f = EntityFilters(filter=pattern, tags=TagsFilter(tags=list(tags), filter_mode=mode))
    if bounds is not None:
        f.bounds = bounds
    return f


def points(*pts: tuple[float, float, float]) -> list[Vector3]:
    return [Vector3(x=float(x), y=float(y), z=float(z)) for x, y, z in pts]


def corners(bounds: Bounds) -> list[tuple[float, float, float]]:
    return [(round(p.x, 6), round(p.y, 6), round(p.z, 6)) for p in bounds.points]


# ---------------------------------------------------------------------- the services and the features
def test_every_service_of_the_standard_is_advertised(ros: RosClient) -> None:
    """The 18 of this branch (StepSimulation is served by a node of its own, under the same name)."""
    node = ros.node
    wanted = {NS + n for n in SERVICES}
    wait_for(lambda: wanted <= {n for n, _ in node.get_service_names_and_types()}, 15, "the services")
    types = dict(node.get_service_names_and_types())
    for name in SERVICES:
        assert types[NS + name][0].startswith("simulation_interfaces/srv/"), name
    assert ActionClient(node, SimulateSteps, NS + "simulate_steps").wait_for_server(timeout_sec=15)


def test_the_world_services_are_advertised(ros: RosClient) -> None:
    names = {NS + n for n in WORLD_SERVICES}
    wait_for(lambda: names <= {n for n, _ in ros.node.get_service_names_and_types()}, 15, "the world services")


def test_get_simulator_features_lists_what_is_served_and_only_that(ros: RosClient) -> None:
    f = call(ros, "get_simulator_features").features
    feats = set(f.features)
    assert len(feats) == len(f.features), "a feature is listed twice"
    advertised = {n.removeprefix(NS) for n, _ in ros.node.get_service_names_and_types() if n.startswith(NS)}
    for feature, service in SERVICE_FEATURES.items():
        assert (feature in feats) == (service in advertised), (feature, service)
    expected = {f for f, s in SERVICE_FEATURES.items() if s in advertised} | BEHAVIOUR_FEATURES
    if "load_world" in advertised:
        expected |= WORLD_BEHAVIOUR_FEATURES
    assert feats == expected
    assert F.ENTITY_BOUNDS_CONVEX not in feats  # TYPE_CONVEX_HULL filters are refused (below)
    assert list(f.spawn_formats) == ["urdf", "sdf"]


def test_spawn_formats_are_what_spawn_entity_takes(ros: RosClient) -> None:
    urdf = (
        '<robot name="u"><link name="l"><inertial><mass value="1"/>'
        '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>'
    )
    assert code(spawn(ros, "fmt_urdf", xml=urdf, z=1.0)) == OK
    assert code(spawn(ros, "fmt_sdf", xml=sdf_model("s", box(0.1)), x=1.0, z=1.0)) == OK
    mjcf = spawn(ros, "fmt_mjcf", xml="<mujoco><worldbody><body/></worldbody></mujoco>")
    assert code(mjcf) == srv.SpawnEntity.Response.UNSUPPORTED_FORMAT and mjcf.result.error_message
    for name in ("fmt_urdf", "fmt_sdf"):
        assert code(call(ros, "delete_entity", entity=name)) == OK


# ---------------------------------------------------------------------- simulation state and stepping
def test_simulation_state_codes(ros: RosClient) -> None:
    R = srv.SetSimulationState.Response
    pause(ros)
    assert code(call(ros, "step_simulation", steps=1)) == OK  # paused with a step taken: PAUSED, not STOPPED
    state = call(ros, "get_simulation_state")
    assert code(state) == OK and state.state.state == SimulationState.STATE_PAUSED
    assert set_state(ros, SimulationState.STATE_PAUSED) == R.ALREADY_IN_TARGET_STATE
    assert set_state(ros, SimulationState.STATE_QUITTING) == R.INCORRECT_TRANSITION
    assert set_state(ros, 99) == Result.RESULT_OPERATION_FAILED


def test_reset_simulation_codes(ros: RosClient) -> None:
    R = srv.ResetSimulation.Request
    assert code(spawn(ros, "reset_me", xml=sdf_model("r", box(0.1)), z=2.0)) == OK
    bad = call(ros, "reset_simulation", scope=8)
    assert code(bad) == Result.RESULT_FEATURE_UNSUPPORTED and "scope" in bad.result.error_message
    assert code(call(ros, "reset_simulation", scope=R.SCOPE_SPAWNED)) == OK
    assert code(call(ros, "get_entity_state", entity="reset_me")) == Result.RESULT_NOT_FOUND
    assert code(call(ros, "get_entity_state", entity="table")) == OK  # the world's own stay


def test_step_simulation_codes(ros: RosClient) -> None:
    """StepSimulation.srv: not paused -> RESULT_OPERATION_FAILED."""
    assert set_state(ros, SimulationState.STATE_PLAYING) == OK
    running = call(ros, "step_simulation", steps=5)
    assert code(running) == Result.RESULT_OPERATION_FAILED and "paused" in running.result.error_message
    pause(ros)
    assert code(call(ros, "step_simulation", steps=0)) == Result.RESULT_OPERATION_FAILED
    assert code(call(ros, "step_simulation", steps=3)) == OK


def test_simulate_steps_action_codes(ros: RosClient) -> None:
    """SimulateSteps.action: unpaused -> RESULT_OPERATION_FAILED (aborted); paused: done, with feedback."""
    client = ActionClient(ros.node, SimulateSteps, NS + "simulate_steps")
    try:
        assert client.wait_for_server(timeout_sec=15)
        assert set_state(ros, SimulationState.STATE_PLAYING) == OK
        accepted, res = ros.send_goal(client, SimulateSteps.Goal(steps=5))
        assert accepted and res.status == GoalStatus.STATUS_ABORTED
        assert res.result.result.result == Result.RESULT_OPERATION_FAILED
        pause(ros)
        accepted, res = ros.send_goal(client, SimulateSteps.Goal(steps=0))
        assert res.status == GoalStatus.STATUS_ABORTED and res.result.result.result == Result.RESULT_OPERATION_FAILED
        accepted, res = ros.send_goal(client, SimulateSteps.Goal(steps=20))
        assert accepted and res.status == GoalStatus.STATUS_SUCCEEDED and res.result.result.result == OK
    finally:
        client.destroy()


# ---------------------------------------------------------------------- spawning and deleting
def test_spawn_entity_codes(ros: RosClient) -> None:
    R = srv.SpawnEntity.Response
    pause(ros)
    assert code(spawn(ros, "sp_one", xml=sdf_model("a", box(0.1)), z=1.0)) == OK
    assert code(spawn(ros, "sp_one", xml=sdf_model("a", box(0.1)))) == R.NAME_NOT_UNIQUE
    assert code(spawn(ros, "bad::name", xml=sdf_model("a", box(0.1)))) == R.NAME_INVALID
    assert code(spawn(ros, "sp_none", uri="model://no_such_model")) == R.NO_RESOURCE
    assert code(spawn(ros, "sp_none", uri="", xml="")) == R.NO_RESOURCE
    assert code(spawn(ros, "sp_parse", xml="<sdf version='1.9'><model name='x'><link>")) == R.RESOURCE_PARSE_ERROR
    assert code(spawn(ros, "sp_ns", xml=sdf_model("a", box(0.1)), entity_namespace="bad ns")) == R.NAMESPACE_INVALID
    assert code(spawn(ros, "sp_pose", xml=sdf_model("a", box(0.1)), z=math.nan)) == R.INVALID_POSE
    assert code(call(ros, "delete_entity", entity="sp_one")) == OK


def test_spawn_entities_codes(ros: RosClient) -> None:
    good = SpawnEntityMsg(name="batch_ok", allow_renaming=False)
    good.entity_resource.resource_string = sdf_model("b", box(0.1))
    good.initial_pose.pose.position.z = 1.0
    bad = SpawnEntityMsg(name="batch_bad")
    bad.entity_resource.uri = "model://no_such_model"
    res = call(ros, "spawn_entities", spawn_requests=[good, bad])
    assert code(res) == srv.SpawnEntities.Response.ENTITIES_SPAWN_FAILED
    assert [r.result.result for r in res.results] == [OK, srv.SpawnEntity.Response.NO_RESOURCE]
    assert code(call(ros, "delete_entity", entity="batch_ok")) == OK


def test_delete_entity_codes(ros: RosClient) -> None:
    missing = call(ros, "delete_entity", entity="nobody_here")
    assert code(missing) == Result.RESULT_NOT_FOUND and "nobody_here" in missing.result.error_message


# ---------------------------------------------------------------------- entity queries and info
def test_entity_state_codes(ros: RosClient) -> None:
    assert code(call(ros, "get_entity_state", entity="nobody_here")) == Result.RESULT_NOT_FOUND
    req = srv.SetEntityState.Request(entity="nobody_here")
    req.state.pose.orientation.w = 1.0
    assert code(ros.call(srv.SetEntityState, NS + "set_entity_state", req)) == Result.RESULT_NOT_FOUND
    req = srv.SetEntityState.Request(entity="table")
    req.state.pose.position.x = math.inf
    assert code(ros.call(srv.SetEntityState, NS + "set_entity_state", req)) == srv.SetEntityState.Response.INVALID_POSE
    states = call(ros, "get_entities_states", filters=filters("^table$"))
    assert code(states) == OK and list(states.entities) == ["table"] and len(states.states) == 1


def test_set_entity_info_and_tag_filters(ros: RosClient) -> None:
    pause(ros)
    for name, x in (("tag_a", 10.0), ("tag_b", 12.0), ("tag_c", 14.0)):
        assert code(spawn(ros, name, xml=sdf_model(name, box(0.2)), x=x, z=1.0)) == OK
    C = EntityCategory
    for name, tags in (("tag_a", ["red", "heavy"]), ("tag_b", ["red"]), ("tag_c", [])):
        info = EntityInfo(category=C(category=C.CATEGORY_OBJECT), description=f"{name} described", tags=tags)
        assert code(call(ros, "set_entity_info", entity=name, info=info)) == OK
    got = call(ros, "get_entity_info", entity="tag_a")
    assert code(got) == OK and list(got.info.tags) == ["red", "heavy"]
    assert got.info.description == "tag_a described" and got.info.category.category == C.CATEGORY_OBJECT

    def names(f: Any) -> set[str]:
        res = call(ros, "get_entities", filters=f)
        assert code(res) == OK, res.result.error_message
        return set(res.entities)

    assert names(filters("^tag_", ("red", "heavy"), TagsFilter.FILTER_MODE_ANY)) == {"tag_a", "tag_b"}
    assert names(filters("^tag_", ("red", "heavy"), TagsFilter.FILTER_MODE_ALL)) == {"tag_a"}
    assert names(filters("^tag_", ())) == {"tag_a", "tag_b", "tag_c"}
    by_cat = EntityFilters(filter="^tag_", categories=[C(category=C.CATEGORY_OBJECT)])
    assert names(by_cat) == {"tag_a", "tag_b", "tag_c"}  # the category a client set is the one filters see
    states = call(ros, "get_entities_states", filters=filters("", ("heavy",)))
    assert code(states) == OK and list(states.entities) == ["tag_a"]
    bad_mode = call(ros, "get_entities", filters=filters("", ("red",), mode=7))
    assert code(bad_mode) == Result.RESULT_OPERATION_FAILED and "filter_mode" in bad_mode.result.error_message
    bad_cat = EntityInfo(category=C(category=3))
    reply = call(ros, "set_entity_info", entity="tag_a", info=bad_cat)
    assert code(reply) == Result.RESULT_OPERATION_FAILED and "category" in reply.result.error_message
    assert code(call(ros, "set_entity_info", entity="nobody_here", info=EntityInfo())) == Result.RESULT_NOT_FOUND
    assert code(call(ros, "get_entity_info", entity="nobody_here")) == Result.RESULT_NOT_FOUND
    too_many = EntityInfo(tags=[f"t{i}" for i in range(101)])
    assert code(call(ros, "set_entity_info", entity="tag_a", info=too_many)) == Result.RESULT_OPERATION_FAILED
    for name in ("tag_a", "tag_b", "tag_c"):
        assert code(call(ros, "delete_entity", entity=name)) == OK


def test_get_entity_bounds_is_the_collision_box_in_the_world_frame(ros: RosClient) -> None:
    res = call(ros, "get_entity_bounds", entity="table")
    assert code(res) == OK and res.bounds.type == Bounds.TYPE_BOX
    assert corners(res.bounds) == [(2.5, -0.5, 0.0), (3.5, 0.5, 0.8)]
    pause(ros)
    assert code(spawn(ros, "bounds_box", xml=sdf_model("bb", box(0.5)), x=-5.0, z=2.0)) == OK
    moved = srv.SetEntityState.Request(entity="bounds_box")
    moved.state.pose.position.x, moved.state.pose.position.z, moved.state.pose.orientation.w = -6.0, 3.0, 1.0
    assert code(ros.call(srv.SetEntityState, NS + "set_entity_state", moved)) == OK
    after = call(ros, "get_entity_bounds", entity="bounds_box")
    assert corners(after.bounds) == [(-6.25, -0.25, 2.75), (-5.75, 0.25, 3.25)]  # it follows the entity
    missing = call(ros, "get_entity_bounds", entity="nobody_here")
    assert code(missing) == Result.RESULT_NOT_FOUND and "nobody_here" in missing.result.error_message
    assert code(call(ros, "delete_entity", entity="bounds_box")) == OK


def test_bounds_filters(ros: RosClient) -> None:
    def names(b: Bounds) -> Any:
        return call(ros, "get_entities", filters=filters("^(table|ground_plane)$", bounds=b))

    over_table = Bounds(type=Bounds.TYPE_BOX, points=points((3.2, -0.2, 0.5), (4.0, 0.2, 2.0)))
    assert list(names(over_table).entities) == ["table"]  # above the ground: the plane has no thickness
    near_table = Bounds(type=Bounds.TYPE_SPHERE, points=points((3.0, 0.0, 1.2), (0.45, 0, 0)))
    assert list(names(near_table).entities) == ["table"]
    short = Bounds(type=Bounds.TYPE_SPHERE, points=points((3.0, 0.0, 1.2), (0.35, 0, 0)))
    assert list(names(short).entities) == []
    on_floor = Bounds(type=Bounds.TYPE_SPHERE, points=points((-1.0, -1.0, 0.0), (0.1, 0, 0)))
    assert list(names(on_floor).entities) == ["ground_plane"]
    convex = Bounds(type=Bounds.TYPE_CONVEX_HULL, points=points((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)))
    assert code(names(convex)) == Result.RESULT_FEATURE_UNSUPPORTED
    one_point = Bounds(type=Bounds.TYPE_BOX, points=points((0, 0, 0)))
    reply = names(one_point)
    assert code(reply) == Result.RESULT_OPERATION_FAILED and "filters.bounds.points" in reply.result.error_message
    negative = Bounds(type=Bounds.TYPE_SPHERE, points=points((0, 0, 0), (-1, 0, 0)))
    assert code(names(negative)) == Result.RESULT_OPERATION_FAILED
    states = call(ros, "get_entities_states", filters=filters("", bounds=over_table))
    assert code(states) == OK and list(states.entities) == ["table"]


# ---------------------------------------------------------------------- named poses
def test_get_named_poses_and_tags(ros: RosClient) -> None:
    res = call(ros, "get_named_poses")
    assert code(res) == OK
    poses = {p.name: p for p in res.poses}
    assert list(poses) == ["dock", "parking", "above_table", "loading_bay"]  # on_table moves with the table
    dock = poses["dock"]
    assert dock.description == "in front of the charger" and list(dock.tags) == ["spawn", "dock"]
    assert (dock.pose.position.x, dock.pose.position.y) == (-2.0, 1.0)
    assert dock.pose.orientation.z == pytest.approx(math.sqrt(0.5), abs=1e-6)
    assert poses["above_table"].pose.position.z == pytest.approx(1.0)  # relative to the table, in the world

    def named(tags: tuple[str, ...], mode: int) -> list[str]:
        reply = call(ros, "get_named_poses", tags=TagsFilter(tags=list(tags), filter_mode=mode))
        assert code(reply) == OK
        return [p.name for p in reply.poses]

    assert named(("spawn",), TagsFilter.FILTER_MODE_ANY) == ["dock", "parking"]
    assert named(("dock", "parking"), TagsFilter.FILTER_MODE_ANY) == ["dock", "parking", "loading_bay"]
    assert named(("spawn", "parking"), TagsFilter.FILTER_MODE_ALL) == ["parking"]
    bad = call(ros, "get_named_poses", tags=TagsFilter(tags=["spawn"], filter_mode=5))
    assert code(bad) == Result.RESULT_OPERATION_FAILED


def test_get_named_pose_bounds(ros: RosClient) -> None:
    dock = call(ros, "get_named_pose_bounds", name="dock")
    assert code(dock) == OK and dock.bounds.type == Bounds.TYPE_BOX
    assert corners(dock.bounds) == [(-0.5, -0.4, 0.0), (0.5, 0.4, 1.0)]
    parking = call(ros, "get_named_pose_bounds", name="parking")
    assert parking.bounds.type == Bounds.TYPE_SPHERE and corners(parking.bounds) == [(0, 0, 0), (0.75, 0, 0)]
    free = call(ros, "get_named_pose_bounds", name="above_table")
    assert code(free) == OK and free.bounds.type == Bounds.TYPE_EMPTY and list(free.bounds.points) == []
    missing = call(ros, "get_named_pose_bounds", name="nowhere")
    assert code(missing) == Result.RESULT_NOT_FOUND and "dock" in missing.result.error_message


# ---------------------------------------------------------------------- spawnables
def test_get_spawnables(ros: RosClient, server: Proc) -> None:
    res = call(ros, "get_spawnables")
    assert code(res) == OK
    found = {s.uri: s for s in res.spawnables}
    assert set(found) == {"model://crate", "model://lamp/lamp.sdf"}
    crate = found["model://crate"]
    assert crate.description == "Crate: a wooden crate"
    assert crate.spawn_bounds.type == Bounds.TYPE_BOX
    assert corners(crate.spawn_bounds) == [(-0.15, -0.15, -0.15), (0.15, 0.15, 0.15)]
    assert "1 model folder(s) left out" in res.result.error_message and "broken" in res.result.error_message
    more = server.resources / "more"  # type: ignore[attr-defined]
    extra = call(ros, "get_spawnables", sources=[str(more), "/etc", "model://no_such_thing"])
    assert code(extra) == OK  # unrecognised sources are named, the reply still succeeds (GetSpawnables.srv)
    uris = [s.uri for s in extra.spawnables]
    bin_uri = (more / "bin" / "model.sdf").resolve().as_uri()
    assert bin_uri in uris
    assert "sources[1] '/etc'" in extra.result.error_message and "sources[2]" in extra.result.error_message
    pause(ros)
    for i, uri in enumerate(["model://crate", "model://lamp/lamp.sdf", bin_uri]):  # each is what SpawnEntity takes
        assert code(spawn(ros, f"spawnable_{i}", uri=uri, x=20.0 + i, z=1.0)) == OK, uri
        assert code(call(ros, "delete_entity", entity=f"spawnable_{i}")) == OK


# ---------------------------------------------------------------------- worlds (last: UnloadWorld empties the simulation)
def test_get_available_worlds(ros: RosClient, server: Proc) -> None:
    res = call(ros, "get_available_worlds")
    assert code(res) == OK
    assert any(w.world_resource.uri.endswith("conformance.sdf") for w in res.worlds)


def test_get_current_world(ros: RosClient) -> None:
    res = call(ros, "get_current_world")
    assert code(res) == OK and res.world.name == "conformance"


def test_load_world_codes(ros: RosClient, server: Proc) -> None:
    R = srv.LoadWorld.Response
    unparsable = call(ros, "load_world", resource_string="<sdf version='1.9'><world name='w'><model>")
    assert code(unparsable) == R.RESOURCE_PARSE_ERROR and unparsable.result.error_message
    assert call(ros, "get_current_world").world.name == "conformance"  # a failed load leaves the world as it was
    missing_asset = (
        "<sdf version='1.9'><world name='with_missing'><include><uri>model://no_such_model</uri></include>"
        "</world></sdf>"
    )
    refused = call(ros, "load_world", resource_string=missing_asset)
    assert code(refused) == R.MISSING_ASSETS and "no_such_model" in refused.result.error_message
    loaded = call(ros, "load_world", resource_string=missing_asset, ignore_missing_or_unsupported_assets=True)
    assert code(loaded) == OK
    assert call(ros, "get_current_world").world.name == "with_missing"
    outside = call(ros, "load_world", uri="file:///etc/passwd")
    assert code(outside) == R.NO_RESOURCE
    uri = (server.resources / "conformance.sdf").as_uri()  # type: ignore[attr-defined]
    assert code(call(ros, "load_world", uri=uri)) == OK


def test_unload_world_codes(ros: RosClient, server: Proc) -> None:
    assert code(call(ros, "unload_world")) == OK
    assert code(call(ros, "get_current_world")) == srv.GetCurrentWorld.Response.NO_WORLD_LOADED
    assert code(call(ros, "unload_world")) == srv.UnloadWorld.Response.NO_WORLD_LOADED
    state = call(ros, "get_simulation_state")
    assert state.state.state == SimulationState.STATE_NO_WORLD
    uri = (server.resources / "conformance.sdf").as_uri()  # type: ignore[attr-defined]
    assert code(call(ros, "load_world", uri=uri)) == OK
    assert code(call(ros, "get_current_world")) == OK

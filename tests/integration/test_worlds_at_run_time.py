"""simulation_interfaces' worlds at run time over real DDS: GetAvailableWorlds, LoadWorld, UnloadWorld and
GetCurrentWorld on a real `gazelle sim` (issue 52), with every bad input the issue names.

One server (started paused on the embedded default world) serves the module; each test leaves the default
world loaded (``empty.sdf``) for the next.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from _harness import GAZELLE, Proc, RosClient, start, wait_for
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from rclpy.action.client import ActionClient
from simulation_interfaces import srv
from simulation_interfaces.action import SimulateSteps
from simulation_interfaces.msg import Result, SimulationState, SimulatorFeatures, TagsFilter

pytestmark = pytest.mark.ros

OK = Result.RESULT_OK
NS = "/gazelle/"
L = srv.LoadWorld.Response


def world_sdf(name: str, *models: str, extra: str = "") -> str:
    body = "".join(models)
    return f'<?xml version="1.0"?>\n<sdf version="1.9">\n<world name="{name}">{extra}{body}\n</world>\n</sdf>\n'


def box(name: str, x: float = 0.0, mesh: str = "", static: bool = True) -> str:
    shape = f"<mesh><uri>{mesh}</uri></mesh>" if mesh else "<box><size>0.2 0.2 0.2</size></box>"
    return (
        f'\n<model name="{name}"><static>{str(static).lower()}</static><pose>{x} 0 0.1 0 0 0</pose>'
        '<link name="l"><inertial><mass>1</mass></inertial>'
        f'<collision name="c"><geometry>{shape}</geometry></collision></link></model>'
    )


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory, ros_env: dict[str, str]) -> Iterator[Proc]:
    res = tmp_path_factory.mktemp("resources")
    worlds = res / "warehouse_pkg" / "worlds"
    worlds.mkdir(parents=True)
    (worlds / "shelves.sdf").write_text(world_sdf("shelves", box("shelf_a", 1.0), box("shelf_b", 2.0)))
    (worlds / "meshy.world").write_text(world_sdf("meshy", box("ok", 1.0), box("odd", 2.0, mesh="missing.stl")))
    (worlds / "odd.sdf").write_text(world_sdf("odd", box("plain"), extra="<wobble_field>3</wobble_field>"))
    (res / "crate").mkdir()
    (res / "crate" / "model.sdf").write_text(
        '<sdf version="1.9"><model name="crate"><link name="l"/></model></sdf>'
    )  # not a world
    outside = tmp_path_factory.mktemp("private")
    (outside / "secret.sdf").write_text(world_sdf("SECRET_WORLD", box("s")))
    env = dict(ros_env, GAZELLE_RESOURCE_PATH=str(res))
    proc = start([*GAZELLE, "sim", "--paused"], "gazelle sim", env=env)
    proc.wait_line("gazelle: ready", timeout=60)
    proc.resources = res  # type: ignore[attr-defined] - where the test worlds are
    proc.outside = outside  # type: ignore[attr-defined] - a folder off the resource paths
    yield proc
    rc = proc.interrupt()
    assert rc == 0, f"gazelle sim exited with {rc} on Ctrl-C:\n{proc.output}"


@pytest.fixture(scope="module")
def ros(server: Proc) -> Iterator[RosClient]:
    client = RosClient("worlds_test_client")
    yield client
    client.close()


def call(ros: RosClient, kind: Any, service: str, timeout: float = 30.0, **fields: Any) -> Any:
    return ros.call(kind, NS + service, kind.Request(**fields), timeout=timeout)


def load(ros: RosClient, uri: str = "", text: str = "", **flags: Any) -> Any:
    return call(ros, srv.LoadWorld, "load_world", uri=uri, resource_string=text, **flags)


def entities(ros: RosClient) -> list[str]:
    res = call(ros, srv.GetEntities, "get_entities")
    assert res.result.result == OK, res.result.error_message
    return sorted(res.entities)


def state(ros: RosClient) -> int:
    return call(ros, srv.GetSimulationState, "get_simulation_state").state.state


def spawn(ros: RosClient, name: str, xml: str) -> Any:
    if not xml.lstrip().startswith(("<?xml", "<robot", "<sdf")):
        xml = f'<sdf version="1.9">{xml}</sdf>'
    pose = PoseStamped()
    pose.pose.position.z = 0.5
    return call(ros, srv.SpawnEntity, "spawn_entity", name=name, resource_string=xml, initial_pose=pose)


def one_line(res: Any) -> str:
    """A refusal's message: one clear line, never a traceback."""
    msg = res.result.error_message
    assert msg and "\n" not in msg and "Traceback" not in msg, msg
    return msg


def back_to_default(ros: RosClient) -> None:
    res = load(ros, "empty.sdf")
    assert res.result.result == OK, res.result.error_message


# ---------------------------------------------------------------------- features, current and available worlds
def test_features_say_the_world_services_are_served(ros: RosClient) -> None:
    feats = set(call(ros, srv.GetSimulatorFeatures, "get_simulator_features").features.features)
    for want in (
        SimulatorFeatures.WORLD_LOADING,
        SimulatorFeatures.WORLD_RESOURCE_STRING,
        SimulatorFeatures.WORLD_TAGS,
        SimulatorFeatures.WORLD_UNLOADING,
        SimulatorFeatures.WORLD_INFO_GETTING,
        SimulatorFeatures.AVAILABLE_WORLDS,
    ):
        assert want in feats


def test_the_world_the_server_started_with_is_the_first_load(ros: RosClient) -> None:
    cur = call(ros, srv.GetCurrentWorld, "get_current_world")
    assert cur.result.result == OK
    assert cur.world.name == "default" and cur.world.world_resource.uri == "empty.sdf"
    assert {"installed", "default"} <= set(cur.world.tags)
    assert state(ros) == SimulationState.STATE_STOPPED


def test_available_worlds_on_the_resource_paths_with_tags(ros: RosClient, server: Proc) -> None:
    res = call(ros, srv.GetAvailableWorlds, "get_available_worlds", offline_only=False)
    assert res.result.result == OK, res.result.error_message
    by_name = {w.name: w for w in res.worlds}
    assert {"shelves", "meshy", "odd", "default"} <= set(by_name)
    assert "crate" not in by_name and "SECRET_WORLD" not in by_name  # a model; a file off the paths
    shelves = by_name["shelves"]
    assert shelves.world_resource.uri.startswith("file://") and shelves.world_resource.uri.endswith("shelves.sdf")
    assert list(shelves.tags) == ["warehouse_pkg", "worlds"]
    # tag filters: any / all
    res = call(
        ros, srv.GetAvailableWorlds, "get_available_worlds", filter=TagsFilter(tags=["warehouse_pkg", "installed"])
    )
    assert {w.name for w in res.worlds} == {"shelves", "meshy", "odd", "default"}
    res = call(
        ros,
        srv.GetAvailableWorlds,
        "get_available_worlds",
        filter=TagsFilter(tags=["warehouse_pkg", "installed"], filter_mode=TagsFilter.FILTER_MODE_ALL),
    )
    assert res.result.result == OK and not res.worlds
    res = call(ros, srv.GetAvailableWorlds, "get_available_worlds", filter=TagsFilter(tags=["x"], filter_mode=7))
    assert res.result.result == Result.RESULT_OPERATION_FAILED and "filter.filter_mode 7" in one_line(res)
    # additional sources: a folder off the resource paths and a remote one are refused, and named
    outside = str(server.outside)  # type: ignore[attr-defined] - set by the fixture
    res = call(ros, srv.GetAvailableWorlds, "get_available_worlds", additional_sources=[outside, "https://x.org/w"])
    assert res.result.result == Result.RESULT_OPERATION_FAILED and "additional_sources[0]" in one_line(res)
    res = call(
        ros,
        srv.GetAvailableWorlds,
        "get_available_worlds",
        additional_sources=[outside, "https://x.org/w"],
        continue_on_error=True,
    )
    assert res.result.result == OK and "shelves" in {w.name for w in res.worlds}
    assert "SECRET_WORLD" not in {w.name for w in res.worlds} and "skipped 2 source(s)" in res.result.error_message
    # a source on the resource paths is searched
    pkg = str(server.resources / "warehouse_pkg")  # type: ignore[attr-defined] - set by the fixture
    res = call(ros, srv.GetAvailableWorlds, "get_available_worlds", additional_sources=[pkg])
    assert res.result.result == OK and "shelves" in {w.name for w in res.worlds}


# ---------------------------------------------------------------------- load, unload, current
def test_load_world_replaces_every_entity_and_keeps_the_services(ros: RosClient) -> None:
    assert spawn(ros, "visitor", box("visitor", static=False)).result.result == OK
    assert call(ros, srv.StepSimulation, "step_simulation", steps=100).result.result == OK
    listed = call(ros, srv.GetAvailableWorlds, "get_available_worlds").worlds
    uri = next(w.world_resource.uri for w in listed if w.name == "shelves")
    res = load(ros, uri)
    assert res.result.result == OK, res.result.error_message
    assert res.world.name == "shelves" and res.world.world_resource.uri == uri
    assert entities(ros) == ["shelf_a", "shelf_b"]  # the old world and the spawned entity are gone
    assert state(ros) == SimulationState.STATE_STOPPED  # LoadWorld.srv: left stopped
    cur = call(ros, srv.GetCurrentWorld, "get_current_world")
    assert cur.world.name == "shelves" and list(cur.world.tags) == ["warehouse_pkg", "worlds"]
    # ResetSimulation's scopes keep their meaning: spawned entities go, the loaded world's models stay
    assert spawn(ros, "late", box("late", static=False)).result.result == OK
    assert call(ros, srv.StepSimulation, "step_simulation", steps=50).result.result == OK
    R = srv.ResetSimulation.Request
    assert call(ros, srv.ResetSimulation, "reset_simulation", scope=R.SCOPE_ALL).result.result == OK
    assert entities(ros) == ["shelf_a", "shelf_b"] and state(ros) == SimulationState.STATE_STOPPED
    # as does gazebo_ros's /reset_simulation (time and state; the loaded world stays)
    from std_srvs.srv import Empty

    ros.call(Empty, "/reset_simulation", Empty.Request())
    assert entities(ros) == ["shelf_a", "shelf_b"]
    # a world as a string
    res = load(ros, text=world_sdf("inline", box("inline_box")))
    assert res.result.result == OK and entities(ros) == ["inline_box"]
    cur = call(ros, srv.GetCurrentWorld, "get_current_world")
    assert cur.world.name == "inline" and "inline_box" in cur.world.world_resource.resource_string
    back_to_default(ros)
    assert entities(ros) == ["ground_plane"]


def test_unload_leaves_no_world_until_the_next_load(ros: RosClient) -> None:
    assert call(ros, srv.UnloadWorld, "unload_world").result.result == OK
    assert entities(ros) == []
    cur = call(ros, srv.GetCurrentWorld, "get_current_world")
    assert cur.result.result == srv.GetCurrentWorld.Response.NO_WORLD_LOADED and one_line(cur)
    assert state(ros) == SimulationState.STATE_NO_WORLD
    again = call(ros, srv.UnloadWorld, "unload_world")
    assert again.result.result == srv.UnloadWorld.Response.NO_WORLD_LOADED and one_line(again)
    refused = spawn(ros, "nowhere", box("nowhere"))
    assert refused.result.result != OK and "no world is loaded" in one_line(refused)
    back_to_default(ros)
    assert state(ros) == SimulationState.STATE_STOPPED and entities(ros) == ["ground_plane"]


# ---------------------------------------------------------------------- bad input: one clear line, the server stays
@pytest.mark.parametrize(
    ("what", "text", "code", "said"),
    [
        (
            "xacro",
            '<sdf version="1.9"><world name="x"><xacro:include filename="/etc/passwd"/></world></sdf>',
            L.UNSUPPORTED_FORMAT,
            "xacro",
        ),
        (
            "entities",
            '<?xml version="1.0"?><!DOCTYPE sdf [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>'
            '<sdf version="1.9"><world name="&b;"/></sdf>',
            L.RESOURCE_PARSE_ERROR,
            "<!DOCTYPE> declarations are refused",
        ),
        ("broken XML", '<sdf version="1.9"><world name="x">', L.RESOURCE_PARSE_ERROR, "malformed"),
        ("a robot", '<robot name="r"><link name="l"/></robot>', L.UNSUPPORTED_FORMAT, "URDF"),
        (
            "a model",
            '<sdf version="1.9"><model name="m"><link name="l"/></model></sdf>',
            L.RESOURCE_PARSE_ERROR,
            "no <world>",
        ),
        (
            "10,000 models",
            world_sdf("huge", *(f'<model name="m{i}"><static>true</static></model>' for i in range(10_000))),
            Result.RESULT_OPERATION_FAILED,
            "more than the 4096",
        ),
        ("nothing", "", L.NO_RESOURCE, "either uri or resource_string"),
    ],
)
def test_a_bad_world_string_is_refused_and_the_world_stays(
    ros: RosClient, what: str, text: str, code: int, said: str
) -> None:
    res = load(ros, text=text)
    assert res.result.result == code, f"{what}: {res.result.error_message}"
    assert said in one_line(res), what
    assert call(ros, srv.GetCurrentWorld, "get_current_world").world.name == "default"  # nothing changed
    assert entities(ros) == ["ground_plane"]


def test_a_uri_outside_the_resource_paths_is_refused(ros: RosClient, server: Proc) -> None:
    secret = server.outside / "secret.sdf"  # type: ignore[attr-defined] - set by the fixture
    for uri in (str(secret), f"file://{secret}", "package://warehouse_pkg/../../etc/passwd", "https://x.org/w.sdf"):
        res = load(ros, uri)
        assert res.result.result == L.NO_RESOURCE, f"{uri}: {res.result.error_message}"
        assert "SECRET" not in one_line(res)
    res = load(ros, "model://crate/model.sdf")  # inside, but a model
    assert res.result.result == L.RESOURCE_PARSE_ERROR and "no <world>" in one_line(res)
    assert call(ros, srv.GetCurrentWorld, "get_current_world").world.name == "default"


def test_missing_assets_and_unsupported_elements_follow_the_flags(ros: RosClient) -> None:
    meshy = "package://warehouse_pkg/worlds/meshy.world"
    res = load(ros, meshy)
    assert res.result.result == L.MISSING_ASSETS and "missing.stl" in one_line(res)
    assert entities(ros) == ["ground_plane"]
    res = load(ros, meshy, ignore_missing_or_unsupported_assets=True)
    assert res.result.result == OK and "warning" in res.result.error_message
    assert entities(ros) == ["odd", "ok"]
    odd = "package://warehouse_pkg/worlds/odd.sdf"
    res = load(ros, odd, fail_on_unsupported_element=True)
    assert res.result.result == L.UNSUPPORTED_ELEMENTS and "wobble_field" in one_line(res)
    assert load(ros, odd).result.result == OK and entities(ros) == ["plain"]  # ignored by default
    back_to_default(ros)


def test_a_load_while_another_loads_is_refused(ros: RosClient) -> None:
    big = world_sdf("big", *(box(f"b{i}", x=0.3 * i, static=False) for i in range(3000)))
    first: dict[str, Any] = {}
    loader = threading.Thread(target=lambda: first.setdefault("res", load(ros, text=big)))
    loader.start()
    try:
        wait_for(lambda: state(ros) == SimulationState.STATE_LOADING_WORLD, 30, "the first load to be under way")
        res = load(ros, "empty.sdf")
        assert res.result.result == Result.RESULT_INCORRECT_STATE and "loading world 'big'" in one_line(res)
        unload = call(ros, srv.UnloadWorld, "unload_world")
        assert unload.result.result == Result.RESULT_INCORRECT_STATE
    finally:
        loader.join(60)
    assert first["res"].result.result == OK, first["res"].result.error_message
    assert call(ros, srv.GetCurrentWorld, "get_current_world").world.name == "big"
    back_to_default(ros)


def test_a_load_during_a_simulate_steps_goal_is_refused(ros: RosClient) -> None:
    client = ActionClient(ros.node, SimulateSteps, NS + "simulate_steps")
    try:
        assert client.wait_for_server(timeout_sec=15)
        feedback: list = []
        fut = client.send_goal_async(SimulateSteps.Goal(steps=10**9), feedback_callback=feedback.append)
        handle = wait_for(lambda: fut.done() and fut.result(), 10, "goal response")
        wait_for(lambda: feedback, 10, "the goal to step")
        res = load(ros, "empty.sdf")
        assert res.result.result == Result.RESULT_INCORRECT_STATE and "SimulateSteps goal" in one_line(res)
        cf = handle.cancel_goal_async()
        wait_for(lambda: cf.done(), 10, "cancel response")
        rf = handle.get_result_async()
        assert wait_for(lambda: rf.done() and rf.result(), 20, "cancelled").status == GoalStatus.STATUS_CANCELED
    finally:
        client.destroy()
    back_to_default(ros)  # the goal is over: loads again


# ---------------------------------------------------------------------- many worlds on one server
def _rss_kib(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise AssertionError("no VmRSS")


def _interfaces(ros: RosClient) -> tuple[int, int, int]:
    """The /gazelle node's publishers and services, and the nodes on the graph."""
    node = ros.node
    pubs = node.get_publisher_names_and_types_by_node("gazelle", "/")
    services = node.get_service_names_and_types_by_node("gazelle", "/")
    return len(pubs), len(services), len(node.get_node_names())


ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
    </inertial><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <link name="upper"><inertial><mass value="0.5"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
    </inertial><collision><geometry><cylinder radius="0.03" length="0.4"/></geometry></collision></link>
  <link name="tool"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <joint name="tool_mount" type="fixed"><parent link="upper"/><child link="tool"/><origin xyz="0 0 0.4"/></joint>
</robot>"""
"""A robot whose built-in robot_state_publisher gives the node publishers of its own (robot_description, /tf,
/tf_static, joint states): they come with each spawn and must go with each world."""


def test_a_hundred_worlds_in_a_row_leak_neither_memory_nor_ros_interfaces(ros: RosClient, server: Proc) -> None:
    """LoadWorld -> spawn a robot (its robot_state_publisher's topics on the node) -> step -> UnloadWorld ->
    LoadWorld of another world, 100 times on one server, with flat memory and the node's publishers and services
    as they were.

    The robot has no gazebo_ros plugin: such a plugin gets an rclpy node of its own, and creating and destroying
    an rclpy node costs about 100 KiB of native memory each time (measured with spawn and delete alone, no world
    load: 10.5 MiB over 100 rounds of the seed robot, before and after this change), which would hide what this
    test is about. Measured with this robot: the RSS moves by -0.3 to +6 MiB over 100 rounds (the allocator's
    noise; 300 rounds ended 0.2 MiB below where they started); before a load handed freed memory back, 100 rounds
    grew it by 20.6 MiB. About 10 s."""
    shelves = "package://warehouse_pkg/worlds/shelves.sdf"

    def round_trip(i: int) -> None:
        assert load(ros, shelves).result.result == OK
        res = spawn(ros, "", ARM)
        assert res.result.result == OK, res.result.error_message
        assert call(ros, srv.StepSimulation, "step_simulation", steps=20).result.result == OK
        assert call(ros, srv.UnloadWorld, "unload_world").result.result == OK
        assert load(ros, "empty.sdf").result.result == OK, f"round {i}"

    for i in range(20):  # warm-up: caches, the first robot's topics and their types, the allocator's arenas
        round_trip(i)
    wait_for(lambda: _interfaces(ros) == _interfaces(ros), 10, "a settled graph")
    before, rss0 = _interfaces(ros), _rss_kib(server.popen.pid)
    # the robot's publishers do come: the count below is of something
    assert load(ros, shelves).result.result == OK and spawn(ros, "", ARM).result.result == OK
    wait_for(lambda: _interfaces(ros)[0] > before[0], 10, f"the robot's publishers beside the node's {before[0]}")
    assert load(ros, "empty.sdf").result.result == OK
    for i in range(100):
        round_trip(i)
    rss1 = _rss_kib(server.popen.pid)
    assert entities(ros) == ["ground_plane"]
    # the graph settles over discovery: wait for the counts to come back, fail if they never do
    wait_for(lambda: _interfaces(ros) == before, 20, f"the node's interfaces {before} (now {_interfaces(ros)})")
    assert rss1 - rss0 < 10 * 1024, f"RSS grew {(rss1 - rss0) / 1024:.1f} MiB over 100 worlds ({rss0} -> {rss1} KiB)"

"""Checks for gazelle's own ROS 2 interface packages (interfaces/).

They are built into the venv by scripts/build_interfaces.sh. These tests import
every msg/srv/action defined under interfaces/, construct and (de)serialise it,
check constants, field order and type hashes against the real Jazzy packages,
and make one real service round trip.
"""

from __future__ import annotations

import importlib
import json
import os
import sys
from pathlib import Path

import pytest

# Keep DDS traffic of this test on this machine and away from other runs.
os.environ.setdefault("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
from _ros_domain import reserved_domain_id

DOMAIN_ID = reserved_domain_id()

import rclpy  # noqa: E402
import rclpy.context  # noqa: E402
from _paths import REPO  # noqa: E402
from rclpy.executors import SingleThreadedExecutor  # noqa: E402
from rclpy.serialization import deserialize_message, serialize_message  # noqa: E402

INTERFACES = REPO / "interfaces"
PACKAGES = ("tf2_msgs", "simulation_interfaces", "gazebo_msgs")


def _has_trajectory_msgs() -> bool:
    try:
        importlib.import_module("trajectory_msgs.msg")
    except ImportError:
        return False
    return True


def _interface_files():
    for pkg in PACKAGES:
        for kind, ext in (("msg", ".msg"), ("srv", ".srv"), ("action", ".action")):
            for f in sorted((INTERFACES / pkg / kind).glob("*" + ext)):
                yield pytest.param(pkg, kind, f.stem, id=f"{pkg}/{kind}/{f.stem}")


def _load(pkg: str, kind: str, name: str):
    if (pkg, kind, name) == ("gazebo_msgs", "srv", "SetJointTrajectory") and not _has_trajectory_msgs():
        pytest.skip("trajectory_msgs wheel not installed: SetJointTrajectory is not built")
    return getattr(importlib.import_module(f"{pkg}.{kind}"), name)


def _roundtrip(msg_cls):
    msg = msg_cls()
    data = serialize_message(msg)
    assert isinstance(data, bytes) and data
    assert deserialize_message(data, msg_cls) == msg


def test_every_package_has_interfaces():
    files = list(_interface_files())
    # tf2_msgs 4, simulation_interfaces 15 msg + 22 srv + 1 action, gazebo_msgs 13 msg + 30 srv
    assert len(files) == 4 + 38 + 43


@pytest.mark.parametrize(("pkg", "kind", "name"), list(_interface_files()))
def test_import_construct_serialize(pkg, kind, name):
    cls = _load(pkg, kind, name)
    type(cls).__import_type_support__()  # loads the C extension / type support
    if kind == "msg":
        parts = [cls]
    elif kind == "srv":
        parts = [cls.Request, cls.Response]
    else:
        parts = [cls.Goal, cls.Result, cls.Feedback]
    for part in parts:
        _roundtrip(part)


def test_simulation_interfaces_constants_and_layout():
    from simulation_interfaces.msg import (
        Bounds,
        EntityCategory,
        Result,
        SimulationState,
        SimulatorFeatures,
        Spawnable,
        SpawnResult,
    )
    from simulation_interfaces.msg import SpawnEntity as SpawnEntityMsg
    from simulation_interfaces.srv import (
        GetSimulationState,
        LoadWorld,
        ResetSimulation,
        SetEntityState,
        SpawnEntities,
        SpawnEntity,
        StepSimulation,
    )

    assert Result.RESULT_FEATURE_UNSUPPORTED == 0
    assert Result.RESULT_OK == 1
    assert Result.RESULT_OPERATION_FAILED == 4
    assert Result().result == Result.RESULT_FEATURE_UNSUPPORTED
    assert SimulatorFeatures.SPAWNING_ENTITIES == 50
    assert SimulatorFeatures.AVAILABLE_WORLDS == 45
    assert SimulatorFeatures.STEP_SIMULATION_ACTION == 33
    assert SimulatorFeatures.get_fields_and_field_types()["features"] == "sequence<uint16>"
    assert SimulationState.STATE_LOADING_WORLD == 5
    assert EntityCategory.CATEGORY_STATIC_OBJECT == 5
    assert Bounds.TYPE_SPHERE == 3
    assert SpawnResult.INVALID_POSE == 109
    assert SetEntityState.Response.INVALID_POSE == 101
    assert SpawnEntity.Response.NAME_NOT_UNIQUE == 101
    assert SpawnEntities.Response.ENTITIES_SPAWN_FAILED == 150
    assert LoadWorld.Response.UNSUPPORTED_ELEMENTS == 106
    assert ResetSimulation.Request.SCOPE_ALL == 255
    assert StepSimulation.Request().steps == 1

    # Jazzy 1.x layout, not the 2.x/Rolling one.
    assert list(SpawnEntity.Request.get_fields_and_field_types()) == [
        "name",
        "allow_renaming",
        "uri",
        "resource_string",
        "entity_namespace",
        "initial_pose",
    ]
    assert list(Spawnable.get_fields_and_field_types()) == ["uri", "description", "spawn_bounds"]
    assert list(SpawnEntityMsg.get_fields_and_field_types()) == [
        "name",
        "allow_renaming",
        "entity_resource",
        "entity_namespace",
        "initial_pose",
    ]
    assert list(SetEntityState.Request.get_fields_and_field_types()) == ["entity", "state"]
    assert list(LoadWorld.Request.get_fields_and_field_types())[:2] == ["uri", "resource_string"]
    assert list(GetSimulationState.Response.get_fields_and_field_types()) == ["state", "result"]


def test_simulate_steps_action():
    from simulation_interfaces.action import SimulateSteps

    goal = SimulateSteps.Goal(steps=10)
    assert goal.steps == 10
    fb = SimulateSteps.Feedback(completed_steps=3, remaining_steps=7)
    assert (fb.completed_steps, fb.remaining_steps) == (3, 7)
    assert hasattr(SimulateSteps.Result(), "result")


def test_tf2_and_gazebo_msgs():
    from gazebo_msgs.msg import ModelStates
    from gazebo_msgs.srv import GetJointProperties
    from gazebo_msgs.srv import SpawnEntity as GzSpawnEntity
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TF2Error, TFMessage

    msg = TFMessage(transforms=[TransformStamped(child_frame_id="base_link")])
    assert deserialize_message(serialize_message(msg), TFMessage) == msg
    assert TF2Error.TRANSFORM_ERROR == 6
    assert list(GzSpawnEntity.Request.get_fields_and_field_types()) == [
        "name",
        "xml",
        "robot_namespace",
        "initial_pose",
        "reference_frame",
    ]
    assert list(ModelStates.get_fields_and_field_types()) == ["name", "pose", "twist"]
    assert GetJointProperties.Response.UNIVERSAL == 5


# RIHS01 type hashes of the real packages (from rosidl-generated code of
# gazebo_msgs 3.8, simulation_interfaces and tf2_msgs builds). Equal hashes mean
# identical field names, types and order, i.e. wire compatibility.
REFERENCE_HASHES = {
    "tf2_msgs/msg/TFMessage": "e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087",
    "simulation_interfaces/msg/Result": "cf43a306adff3337a0a47143d8f5689933bc70a30478f13b077dc1fe3bc5ad17",
    "simulation_interfaces/msg/Resource": "2bb1939cf80f8d2f284afba53cbec60b5ff33759bd39b714128ea8867a34c51a",
    "gazebo_msgs/msg/ContactState": "e8435200741f6b7b6f2d156d4a1d5d97d6869f6237ade6fe540b2e7a8516c358",
    "gazebo_msgs/msg/ODEPhysics": "ac82f81db143d0eaae55db4c4445a1e02a768e473f2e7210a65ab5ba0a581714",
    "gazebo_msgs/msg/PerformanceMetrics": "78a23a97ca2832491a26a73da2397fe2a470892704574f1f930c8a4a8b2ce456",
    "gazebo_msgs/msg/SensorPerformanceMetric": "2fb085a53ec05154b793411cc83d0120da95292c8f3b22ee1e402aa44d9846b6",
    "gazebo_msgs/msg/WheelSlip": "71875111e6e10937ba5cd6a6509bbcb5e2f8bc9c53b9aee9adbd0e407c94963d",
    "gazebo_msgs/srv/GetModelList": "7b19089b52e4e5b9db3fd84042f59e90becb14aa2e7bcd3db378994bcea42257",
    "gazebo_msgs/srv/GetModelProperties": "49525097678f4c00f1d0b1f79649f4b212403225dce6e70b959ce52b7336a23f",
}


@pytest.mark.parametrize("type_name", sorted(REFERENCE_HASHES))
def test_type_hash_matches_upstream(type_name):
    pkg, kind, name = type_name.split("/")
    # The build installs into the venv prefix (AMENT_PREFIX_PATH is usually unset).
    prefixes = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    prefixes.append(sys.prefix)
    candidates = [Path(p) / "share" / pkg / kind / f"{name}.json" for p in prefixes]
    path = next((c for c in candidates if c.is_file()), None)
    assert path is not None, f"no type description for {type_name} in {prefixes}"
    hashes = {h["type_name"]: h["hash_string"] for h in json.loads(path.read_text())["type_hashes"]}
    assert hashes[type_name] == "RIHS01_" + REFERENCE_HASHES[type_name]


def test_spawn_entity_service_round_trip():
    from geometry_msgs.msg import PoseStamped
    from simulation_interfaces.msg import Result
    from simulation_interfaces.srv import SpawnEntity

    context = rclpy.context.Context()
    rclpy.init(context=context, domain_id=DOMAIN_ID)
    executor = SingleThreadedExecutor(context=context)
    node = None
    try:
        node = rclpy.create_node(f"gazelle_test_interfaces_{os.getpid()}", context=context)
        seen = []

        def handle(request, response):
            seen.append(request)
            response.result.result = Result.RESULT_OK
            response.entity_name = request.name + "_1"
            return response

        service_name = f"/gazelle_test_{os.getpid()}/spawn_entity"
        node.create_service(SpawnEntity, service_name, handle)
        client = node.create_client(SpawnEntity, service_name)
        executor.add_node(node)
        assert client.wait_for_service(timeout_sec=10.0), "service did not appear"

        pose = PoseStamped()
        pose.header.frame_id = "world"
        pose.pose.position.z = 0.5
        request = SpawnEntity.Request(
            name="box", allow_renaming=True, resource_string="<sdf version='1.11'/>", initial_pose=pose
        )
        future = client.call_async(request)
        executor.spin_until_future_complete(future, timeout_sec=10.0)
        assert future.done(), "no response within 10 s"
        response = future.result()
        assert response is not None
        assert response.result.result == Result.RESULT_OK
        assert response.entity_name == "box_1"
        assert len(seen) == 1
        assert seen[0].resource_string == "<sdf version='1.11'/>"
        assert seen[0].initial_pose.pose.position.z == 0.5
    finally:
        executor.shutdown()
        if node is not None:
            node.destroy_node()
        rclpy.shutdown(context=context)

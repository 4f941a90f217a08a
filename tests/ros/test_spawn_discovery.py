"""`gazelle spawn -topic robot_description` turns gazelle's built-in robot_state_publisher off when the user's
own publishes the description, even while the ROS graph has not yet named the publisher's node (a busy
machine: seen as both publishing the robot's TF in a loaded test run)."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from gazelle.ros import _spawn_entity as _spawn

UNKNOWN = "_NODE_NAME_UNKNOWN_"  # what rmw_dds_common's graph cache calls a node it has not heard of


class _Graph:
    """A node whose graph names the description's publishers only from the ``known_after``-th query on."""

    def __init__(self, name: str, known_after: int) -> None:
        self.name, self.known_after, self.queries = name, known_after, 0

    def get_publishers_info_by_topic(self, topic: str) -> list[SimpleNamespace]:
        assert topic == "/robot_description"
        self.queries += 1
        known = self.queries > self.known_after
        return [SimpleNamespace(node_name=self.name if known else UNKNOWN)]


@pytest.fixture
def bound(monkeypatch) -> None:
    monkeypatch.setattr(_spawn, "NODE_NAME_WAIT_SEC", 0.2, raising=False)


def test_a_publisher_the_graph_names_late_is_still_found_to_be_robot_state_publisher(monkeypatch) -> None:
    monkeypatch.setattr(_spawn, "NODE_NAME_WAIT_SEC", 5.0, raising=False)
    graph = _Graph("robot_state_publisher", known_after=3)
    assert _spawn._published_by_robot_state_publisher(graph, "robot_description")  # type: ignore[arg-type]
    assert graph.queries == 4


def test_another_node_is_answered_at_once() -> None:
    graph = _Graph("my_description_server", known_after=0)
    assert not _spawn._published_by_robot_state_publisher(graph, "/robot_description")  # type: ignore[arg-type]
    assert graph.queries == 1


def test_a_publisher_never_named_is_not_waited_for_past_the_bound(bound) -> None:
    graph = _Graph("robot_state_publisher", known_after=10**9)
    assert not _spawn._published_by_robot_state_publisher(graph, "robot_description")  # type: ignore[arg-type]
    assert 2 <= graph.queries < 100  # asked again while waiting, and not past 0.2 s


def test_a_ros2_control_robot_gets_no_second_joint_state_publisher() -> None:
    """Issue 26 item 9: articubot and Husky (spawned from robot_description beside their robot_state_publisher)
    got gazelle's joint state publisher beside their joint_state_broadcaster: two /joint_states publishers,
    one with NaN efforts. In Gazebo the broadcaster is the only one."""
    plain = "<robot name='r'><link name='a'/></robot>"
    assert "JointStatePublisher" in _spawn.with_joint_state_publisher(plain)
    for ros2_control in (
        "<robot name='r'><link name='a'/><ros2_control name='h' type='system'/></robot>",
        "<sdf version='1.9'><model name='r'><link name='a'/><plugin filename='gz_ros2_control-system' "
        "name='gz_ros2_control::GazeboSimROS2ControlPlugin'/></model></sdf>",
    ):
        assert _spawn.with_joint_state_publisher(ros2_control) == ros2_control


class _VolatileGraph(_Graph):
    """The same, for a volatile publisher (its namespace, too, unknown until named)."""

    def get_publishers_info_by_topic(self, topic: str) -> list[SimpleNamespace]:
        (named,) = super().get_publishers_info_by_topic(topic)
        known = named.node_name != UNKNOWN
        return [
            SimpleNamespace(
                node_name=named.node_name,
                node_namespace="/" if known else "_NODE_NAMESPACE_UNKNOWN_",
                qos_profile=SimpleNamespace(durability=None),  # not TRANSIENT_LOCAL
            )
        ]


def test_the_hint_for_a_silent_topic_names_a_publisher_the_graph_names_late(monkeypatch) -> None:
    """A hog run's spawn said ``_NODE_NAMESPACE_UNKNOWN_/_NODE_NAME_UNKNOWN_ publishes /robot_description``:
    the hint now waits for the graph to name the node."""
    monkeypatch.setattr(_spawn, "NODE_NAME_WAIT_SEC", 5.0)
    graph = _VolatileGraph("test_client", known_after=3)
    hint = _spawn._topic_hint(graph, "robot_description")  # type: ignore[arg-type]
    assert hint.startswith("/test_client publishes /robot_description but not latched"), hint
    assert graph.queries == 4


def test_the_hint_says_so_when_the_publisher_is_never_named(monkeypatch) -> None:
    monkeypatch.setattr(_spawn, "NODE_NAME_WAIT_SEC", 0.2)
    hint = _spawn._topic_hint(_VolatileGraph("test_client", known_after=10**6), "robot_description")  # type: ignore[arg-type]
    assert hint.startswith("a node not yet named publishes /robot_description but not latched"), hint
    assert "UNKNOWN" not in hint

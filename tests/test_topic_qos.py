"""`ros2 topic echo` and `pub` choose their QoS as ros2topic does on Jazzy (verb/echo.py ``choose_qos``,
api ``profile_configure_short_keys``), against real publishers on a real (in-process) ROS graph: echo
adapts its preset to the publishers only when no ``--qos-*`` override is given, and asks for transient
local only when every publisher offers it (a transient local reader does not match a volatile writer)."""

from __future__ import annotations

import copy

import pytest

pytest.importorskip("rclpy")

from _ros_domain import reserved_domain_id
from rclpy.qos import DurabilityPolicy, LivelinessPolicy, QoSPresetProfiles, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from gazelle.cli.ros2cli._graph import cli_node
from gazelle.cli.ros2cli._topic import _configured, _echo_qos, parser


@pytest.fixture
def node(monkeypatch: pytest.MonkeyPatch):
    """The verbs' own node (``cli_node``), on this process's reserved domain, localhost only."""
    monkeypatch.setenv("ROS_DOMAIN_ID", str(reserved_domain_id()))
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    with cli_node("ros2topic", node_name="topic_qos_test") as node:  # a node of its own name: discovery sees "someone"
        yield node


def _pub(node, topic: str, durability: DurabilityPolicy, reliability=ReliabilityPolicy.RELIABLE):
    return node.create_publisher(String, topic, QoSProfile(depth=10, durability=durability, reliability=reliability))


def test_echo_asks_for_transient_local_only_when_every_publisher_offers_it(node, capsys) -> None:
    _pub(node, "/mixed", DurabilityPolicy.TRANSIENT_LOCAL)
    _pub(node, "/mixed", DurabilityPolicy.VOLATILE, ReliabilityPolicy.BEST_EFFORT)
    qos = _echo_qos(node, "/mixed", parser().parse_args(["echo", "/mixed"]))
    assert qos.durability == DurabilityPolicy.VOLATILE  # gazelle asked for transient local: the volatile one was lost
    assert qos.reliability == ReliabilityPolicy.BEST_EFFORT
    assert qos.depth == 5  # sensor_data, echo's preset
    said = capsys.readouterr().out
    assert "Some, but not all, publishers are offering QoSDurabilityPolicy.TRANSIENT_LOCAL" in said
    assert "Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE" in said

    _pub(node, "/latched", DurabilityPolicy.TRANSIENT_LOCAL)
    _pub(node, "/latched", DurabilityPolicy.TRANSIENT_LOCAL)
    qos = _echo_qos(node, "/latched", parser().parse_args(["echo", "/latched"]))
    assert (qos.durability, qos.reliability) == (DurabilityPolicy.TRANSIENT_LOCAL, ReliabilityPolicy.RELIABLE)
    assert "Some, but not all" not in capsys.readouterr().out


def test_an_override_takes_the_preset_as_it_is_with_liveliness_and_the_depth_rules(node) -> None:
    _pub(node, "/reliable", DurabilityPolicy.VOLATILE)
    argv = ["echo", "/reliable", "--qos-depth", "0", "--qos-liveliness", "manual_by_topic"]
    argv += ["--qos-liveliness-lease-duration-seconds", "2.5"]
    qos = _echo_qos(node, "/reliable", parser().parse_args(argv))
    # sensor_data as it is (best effort, not adapted to the reliable publisher), its depth kept for 0
    assert (qos.reliability, qos.depth) == (ReliabilityPolicy.BEST_EFFORT, 5)
    assert qos.liveliness == LivelinessPolicy.MANUAL_BY_TOPIC
    assert qos.liveliness_lease_duration.nanoseconds == 2_500_000_000
    # pub: system_default's depth is 0, and transient local then gets 1
    args = parser().parse_args(["pub", "/x", "std_msgs/msg/String", "--qos-profile", "system_default"])
    args.qos_durability = "transient_local"
    qos = _configured(copy.copy(QoSPresetProfiles.get_from_short_key(args.qos_profile)), args)
    assert (qos.durability, qos.depth) == (DurabilityPolicy.TRANSIENT_LOCAL, 1)


def test_the_recorder_and_foxglove_match_every_publisher_of_a_mixed_topic(node) -> None:
    """``matching_qos`` (ros2 bag record, hz, the Foxglove bridge) by rosbag2's rule (rosbag2_transport
    qos.cpp, ``adapt_request_to_offers``): transient local only when every publisher offers it."""
    from gazelle.cli.ros2cli import matching_qos

    _pub(node, "/mixed_rec", DurabilityPolicy.TRANSIENT_LOCAL)
    _pub(node, "/mixed_rec", DurabilityPolicy.VOLATILE)
    qos = matching_qos(node, "/mixed_rec")
    assert (qos.durability, qos.reliability) == (DurabilityPolicy.VOLATILE, ReliabilityPolicy.RELIABLE)
    _pub(node, "/all_latched", DurabilityPolicy.TRANSIENT_LOCAL)
    assert matching_qos(node, "/all_latched").durability == DurabilityPolicy.TRANSIENT_LOCAL
    # ros2 bag record says so, as rosbag2 does
    from gazelle.cli.ros2cli._bag import _mixed_offers

    (said,) = _mixed_offers(node, "/mixed_rec")
    assert 'publishers on topic "/mixed_rec" are offering RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL' in said
    assert _mixed_offers(node, "/all_latched") == []

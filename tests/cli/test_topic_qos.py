"""`ros2 topic echo` and `pub` choose their QoS as ros2topic does on Jazzy (verb/echo.py ``choose_qos``,
api ``profile_configure_short_keys``), against real publishers on a real (in-process) ROS graph: echo
adapts its preset to the publishers only when no ``--qos-*`` override is given, and asks for transient
local only when every publisher offers it (a transient local reader does not match a volatile writer)."""

from __future__ import annotations

import copy
import os
import re
import sys

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


OVERRIDES = """
/tf_static:
  history: keep_last
  depth: 1
  reliability: reliable
  durability: transient_local
  deadline: {sec: 1, nsec: 5}
/scan:
  depth: 7
  reliability: best_effort
"""


def test_bag_qos_overrides_are_read_as_ros2bag_reads_them(tmp_path) -> None:
    """``--qos-profile-overrides-path`` (ros2bag/api ``convert_yaml_to_qos_profile``): short keys, ``{sec,
    nsec}`` durations, rclpy's QoSProfile rules; each mistake is one line naming the file and topic."""
    import io

    from rclpy.qos import HistoryPolicy

    from gazelle.cli.ros2cli._bag import BagError, qos_overrides

    got = qos_overrides(io.StringIO(OVERRIDES))
    tf = got["/tf_static"]
    assert (tf.history, tf.depth, tf.durability) == (HistoryPolicy.KEEP_LAST, 1, DurabilityPolicy.TRANSIENT_LOCAL)
    assert tf.deadline.nanoseconds == 1_000_000_005
    assert (got["/scan"].depth, got["/scan"].reliability) == (7, ReliabilityPolicy.BEST_EFFORT)
    assert qos_overrides(io.StringIO("")) == {}
    bad = {
        "/a: {depth: 1, speed: 3}": "Unexpected key `speed` for QoS profile.",
        "/a: {depth: -1}": "`depth` may not be a negative value.",
        "/a: {depth: 1, deadline: {sec: 1}}": "must include both seconds (sec) and nanoseconds (nsec)",
        "/a: {depth: 1, lifespan: {sec: one, nsec: 0}}": "sec and nsec must be whole numbers, got 'one' and 0",
        "/a: {reliability: reliable}": "History and/or depth settings are required",
        "/a: {depth: 1, durability: sometimes}": "`sometimes` is not a durability policy (one of",
        "- /a": "expected a mapping of topic names to QoS profiles",
    }
    for text, said in bad.items():
        f = io.StringIO(text)
        f.name = "qos.yaml"
        with pytest.raises(BagError, match=re.escape(said)) as err:
            qos_overrides(f)
        assert str(err.value).startswith("qos.yaml:") and "\n" not in str(err.value)


def test_the_recorder_and_the_player_take_an_override_as_it_is_and_say_so(node, tmp_path, capsys, monkeypatch) -> None:
    """rosbag2_transport: the recorder subscribes with the override instead of adapting to the offers (and
    does not warn of mixed offers then); the player publishes with it; without one, the player offers
    what all recorded publishers offered, or, when they differed, rosbag2's default (reliable, volatile),
    said once."""
    import io

    from gazelle.cli.ros2cli._bag import _qos_dicts, _qos_profile, _Recorder, qos_overrides

    prefix = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    monkeypatch.setenv("AMENT_PREFIX_PATH", os.pathsep.join([*prefix, sys.prefix]))  # as `ros2` puts it
    overrides = qos_overrides(io.StringIO("/mixed_bag: {depth: 3, durability: transient_local}\n"))
    _pub(node, "/mixed_bag", DurabilityPolicy.TRANSIENT_LOCAL)
    _pub(node, "/mixed_bag", DurabilityPolicy.VOLATILE)
    rec = _Recorder(node, tmp_path, False, overrides)
    try:
        rec.add("/mixed_bag", "std_msgs/msg/String")
        sub = rec._subs[-1].qos_profile
        assert (sub.depth, sub.durability) == (3, DurabilityPolicy.TRANSIENT_LOCAL)
        said = capsys.readouterr().out
        assert "Overriding subscription profile for /mixed_bag" in said and "Some, but not all" not in said
        rec.overrides = {}
        rec.add("/mixed_bag_2", "std_msgs/msg/String")  # no publisher: adapted, volatile
        assert rec._subs[-1].qos_profile.durability == DurabilityPolicy.VOLATILE
    finally:
        rec.finish()

    offered = _qos_dicts(node.get_publishers_info_by_topic("/mixed_bag"))
    assert _qos_profile("/mixed_bag", offered, overrides).durability == DurabilityPolicy.TRANSIENT_LOCAL
    assert "Overriding QoS profile for topic /mixed_bag" in capsys.readouterr().out
    mixed = _qos_profile("/mixed_bag", offered, {})
    assert (mixed.durability, mixed.reliability) == (DurabilityPolicy.VOLATILE, ReliabilityPolicy.RELIABLE)
    assert "Not all original publishers on topic /mixed_bag offered the same QoS profiles" in capsys.readouterr().out
    _pub(node, "/latched_bag", DurabilityPolicy.TRANSIENT_LOCAL)
    _pub(node, "/latched_bag", DurabilityPolicy.TRANSIENT_LOCAL)
    same = _qos_profile("/latched_bag", _qos_dicts(node.get_publishers_info_by_topic("/latched_bag")), {})
    assert same.durability == DurabilityPolicy.TRANSIENT_LOCAL
    assert "Not all" not in capsys.readouterr().out


def test_a_bad_overrides_file_is_one_line_and_status_1(tmp_path, capsys) -> None:
    from gazelle.cli.ros2cli._bag import main

    bad = tmp_path / "qos.yaml"
    bad.write_text("/odom: {depth: 1, colour: blue}\n")
    assert main(["play", str(tmp_path / "no_bag"), "--qos-profile-overrides-path", str(bad)]) == 1
    err = capsys.readouterr().err.strip()
    assert err == f"[ERROR] [ros2bag]: {bad}: topic /odom: Unexpected key `colour` for QoS profile.", err

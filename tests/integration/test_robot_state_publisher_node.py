"""gazelle's ``ros2 run robot_state_publisher`` node against robot_state_publisher 3.3.3 (Jazzy,
src/robot_state_publisher.cpp), in a real rclpy context: a ``world`` link's fixed joint is a static
transform, mimic joints follow their leaders, and a JointState is published by its stamp (whole
milliseconds of 1 / publish_frequency past the last publication), never by the wall clock; a state
stamped 0 is not due, and ``ignore_timestamp`` publishes every message with its own stamp."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any, cast

import pytest
from _harness import RosClient, wait_for

rclpy = pytest.importorskip("rclpy")

_ARM = """<robot name="arm">
  <link name="world"/><link name="base"/><link name="a"/><link name="b"/>
  <joint name="to_world" type="fixed"><parent link="world"/><child link="base"/><origin xyz="1 2 0"/></joint>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <mimic joint="j1" multiplier="2" offset="0.1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>"""


@contextlib.contextmanager
def _node(name: str, **params: Any) -> Iterator[tuple[list[Any], list[Any], Any]]:
    """robot_state_publisher with ``params`` in a test client's context: what the client hears on /tf and
    /tf_static, and a /joint_states publisher; all destroyed at the end."""
    ros = RosClient(name)
    try:
        rsp, tf, static, pub = _start(ros, **params)
        try:
            yield tf, static, pub
        finally:
            ros.executor.remove_node(rsp)
            rsp.destroy_node()
    finally:
        ros.close()


def _start(ros: RosClient, **params: Any) -> tuple[Any, list[Any], list[Any], Any]:
    """The node with ``params``, and what the test hears on /tf and /tf_static, and a /joint_states publisher."""
    from rclpy.parameter import Parameter
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from sensor_msgs.msg import JointState
    from tf2_msgs.msg import TFMessage

    from gazelle.ros._rsp_node import RobotStatePublisherNode

    params.setdefault("robot_description", _ARM)
    overrides = [Parameter(k, value=v) for k, v in params.items()]
    rsp = RobotStatePublisherNode(context=ros.context, parameter_overrides=overrides)
    ros.executor.add_node(rsp)
    tf: list[Any] = []
    static: list[Any] = []
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    sub = ros.node.create_subscription(TFMessage, "/tf", lambda m: tf.append(cast(TFMessage, m)), 100)
    ros.node.create_subscription(TFMessage, "/tf_static", lambda m: static.append(cast(TFMessage, m)), latched)
    pub = ros.node.create_publisher(JointState, "/joint_states", 10)
    wait_for(lambda: pub.get_subscription_count() == 1, 10, "robot_state_publisher's subscription")
    wait_for(lambda: sub.get_publisher_count() == 1, 10, "robot_state_publisher's /tf")
    return rsp, tf, static, pub


def _state(sec: float, q: float) -> Any:
    from sensor_msgs.msg import JointState

    msg = JointState(name=["j1"], position=[q])
    ns = round(sec * 1e9)
    msg.header.stamp.sec, msg.header.stamp.nanosec = ns // 1_000_000_000, ns % 1_000_000_000
    return msg


def _stamp(m: Any) -> float:
    s = m.transforms[0].header.stamp
    return round(s.sec + s.nanosec * 1e-9, 6)


def test_a_world_link_is_a_static_transform_and_mimic_joints_follow_their_leader() -> None:
    import math

    with _node("rsp_world_mimic_test") as (tf, static, pub):
        wait_for(lambda: static, 10, "/tf_static")
        fixed = {t.child_frame_id: t for t in static[-1].transforms}
        assert set(fixed) == {"base"} and fixed["base"].header.frame_id == "world"
        v = fixed["base"].transform.translation
        assert (v.x, v.y, v.z) == (1.0, 2.0, 0.0)
        pub.publish(_state(1.0, 0.3))
        wait_for(lambda: tf, 10, "/tf")
        moved = tf[0].transforms
        assert [t.child_frame_id for t in moved] == ["a", "b"]  # by joint name, j2 from its leader j1
        yaw = [2 * math.atan2(t.transform.rotation.z, t.transform.rotation.w) for t in moved]
        assert yaw == pytest.approx([0.3, 2 * 0.3 + 0.1])


def test_states_are_published_by_their_stamp_and_one_stamped_zero_is_never_due() -> None:
    with _node("rsp_stamp_test", publish_frequency=10.0) as (tf, _static, pub):  # every 100 ms of stamps
        # published in a burst of wall time: which go out depends on their stamps only
        for sec in (1.0, 1.05, 0.0, 1.1, 1.15, 1.3):
            pub.publish(_state(sec, 0.1))
        # the node takes the states in order and publishes in order: once the last one's transforms are
        # here, every earlier state has been published or dropped
        wait_for(lambda: tf and _stamp(tf[-1]) == 1.3, 10, "the transforms of the state stamped 1.3 s")
        assert [_stamp(m) for m in tf] == [1.0, 1.1, 1.3]


def test_ignore_timestamp_publishes_every_state_with_its_own_stamp() -> None:
    with _node("rsp_ignore_stamp_test", ignore_timestamp=True) as (tf, _static, pub):
        for sec in (2.0, 2.001, 0.0):
            pub.publish(_state(sec, 0.1))
        wait_for(lambda: len(tf) >= 3, 10, "three /tf messages")
        assert [_stamp(m) for m in tf] == [2.0, 2.001, 0.0]


_SDF_ARM = """<sdf version="1.9"><model name="arm">
  <link name="base"/><link name="a"><pose>0 0 0.5 0 0 0</pose></link><link name="tool"><pose>0 0 0.8 0 0 0</pose></link>
  <joint name="j1" type="revolute"><parent>base</parent><child>a</child><axis><xyz>0 0 1</xyz></axis></joint>
  <joint name="tool_joint" type="fixed"><parent>a</parent><child>tool</child></joint>
</model></sdf>"""


def test_an_sdf_robot_description_is_read_as_jazzy_reads_it_through_sdformat_urdf() -> None:
    """ros_gz_project_template's launch gives robot_state_publisher the model's SDF. Jazzy's robot_state_publisher
    parses it with the sdformat_urdf plugin (urdf::Model's parser plugins); gazelle's died with `root element is
    <sdf>`. The SDF's links are the frames, its fixed joint a static transform, its revolute joint moves."""
    with _node("rsp_sdf_test", robot_description=_SDF_ARM) as (tf, static, pub):
        wait_for(lambda: static, 10, "/tf_static")
        fixed = {t.child_frame_id: t for t in static[-1].transforms}
        assert set(fixed) == {"tool"} and fixed["tool"].header.frame_id == "a"
        assert fixed["tool"].transform.translation.z == pytest.approx(0.3)
        pub.publish(_state(1.0, 0.3))
        wait_for(lambda: tf, 10, "/tf")
        moved = tf[0].transforms[0]
        assert (moved.header.frame_id, moved.child_frame_id) == ("base", "a")
        assert moved.transform.translation.z == pytest.approx(0.5)

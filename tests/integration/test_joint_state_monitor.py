"""gazelle.ros's JointStateMonitor (move_group's current state) in a real rclpy context: messages of
several publishers, each naming some joints, are merged in order; none is lost to the reader's history
when a fast publisher follows a slow one. A JointState whose names and positions differ in count is
dropped there and by robot_state_publisher, as MoveIt and robot_state_publisher do."""

from __future__ import annotations

from typing import cast

import pytest
from _harness import RosClient, wait_for

rclpy = pytest.importorskip("rclpy")


def test_the_joints_of_two_publishers_are_merged_and_the_last_message_wins() -> None:
    from sensor_msgs.msg import JointState

    from gazelle.ros._joint_state_monitor import JointStateMonitor

    ros = RosClient("monitor_test")
    owner = rclpy.create_node("owner", namespace="/arm", context=ros.context)
    monitor = JointStateMonitor(owner, "joint_states")
    try:
        assert monitor.topic == "/arm/joint_states"  # resolved as its owner resolves it
        pub = ros.node.create_publisher(JointState, "/arm/joint_states", 1000)
        wait_for(lambda: pub.get_subscription_count() == 1, 10, "the monitor's reader")
        pub.publish(JointState(name=["hand"], position=[0.04]))
        # the arm's 300 messages after the hand's one, read only once they all went: the reader's history
        # (1,000) holds them all and the hand's position is merged with the arm's
        for k in range(300):
            pub.publish(JointState(name=["a1", "a2"], position=[k * 0.001, -k * 0.001]))
        wait_for(lambda: monitor.positions().get("a1") == pytest.approx(0.299), 10, "the arm's last message")
        assert monitor.positions() == pytest.approx({"hand": 0.04, "a1": 0.299, "a2": -0.299})
        kept = monitor.positions()
        pub.publish(JointState(name=["a1"], position=[1.0]))
        wait_for(lambda: monitor.positions().get("a1") == 1.0, 10, "the next message")
        assert kept["a1"] == pytest.approx(0.299)  # a dict once returned is never changed
    finally:
        monitor.destroy()
        owner.destroy_node()
        ros.close()


def test_a_message_whose_names_and_positions_differ_in_count_is_dropped_as_moveit_does() -> None:
    """MoveIt's CurrentStateMonitor drops such a message with an error; pairing them up would move a joint
    to another joint's position."""
    from sensor_msgs.msg import JointState

    from gazelle.ros._joint_state_monitor import JointStateMonitor

    ros = RosClient("monitor_invalid_test")
    owner = rclpy.create_node("owner", context=ros.context)
    monitor = JointStateMonitor(owner, "joint_states")
    try:
        pub = ros.node.create_publisher(JointState, "/joint_states", 1000)
        wait_for(lambda: pub.get_subscription_count() == 1, 10, "the monitor's reader")
        pub.publish(JointState(name=["a1"], position=[0.5]))
        pub.publish(JointState(name=["a1", "a2"], position=[9.0]))  # two names, one position
        pub.publish(JointState(name=["a2"], position=[]))  # effort-only style, no position
        pub.publish(JointState(name=["a3"], position=[0.25]))
        wait_for(lambda: "a3" in monitor.positions(), 10, "the message after the invalid ones")
        assert monitor.positions() == {"a1": 0.5, "a3": 0.25}
        assert monitor.invalid == 2
    finally:
        monitor.destroy()
        owner.destroy_node()
        ros.close()


_TWO_JOINTS = """<robot name="two">
  <link name="base"/><link name="l1"/><link name="l2"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/><axis xyz="0 0 1"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/></joint>
</robot>"""


def test_robot_state_publisher_ignores_a_message_whose_names_and_positions_differ_in_count() -> None:
    """As robot_state_publisher 3.3.3 does (callbackJointState): no transform from such a message."""
    from rclpy.parameter import Parameter
    from sensor_msgs.msg import JointState
    from tf2_msgs.msg import TFMessage

    from gazelle.ros._rsp_node import RobotStatePublisherNode

    ros = RosClient("rsp_invalid_test")
    rsp = RobotStatePublisherNode(
        context=ros.context,
        parameter_overrides=[
            Parameter("robot_description", value=_TWO_JOINTS),
            Parameter("publish_frequency", value=10000.0),
        ],
    )
    ros.executor.add_node(rsp)
    heard: list[list[str]] = []
    tf = ros.node.create_subscription(
        TFMessage, "/tf", lambda m: heard.append([t.child_frame_id for t in cast(TFMessage, m).transforms]), 10
    )
    try:
        pub = ros.node.create_publisher(JointState, "/joint_states", 10)
        wait_for(lambda: pub.get_subscription_count() == 1, 10, "robot_state_publisher's subscription")
        wait_for(lambda: tf.get_publisher_count() == 1, 10, "robot_state_publisher's /tf")
        pub.publish(JointState(name=["j1", "j2"], position=[9.0]))  # two names, one position
        pub.publish(JointState(name=["j2"], position=[]))  # no positions at all
        pub.publish(JointState(name=["j1", "j2"], position=[0.5, 0.25]))
        wait_for(lambda: heard, 10, "a /tf message")
        assert heard[0] == ["l1", "l2"]  # the valid message's, first
    finally:
        ros.executor.remove_node(rsp)
        rsp.destroy_node()
        ros.close()

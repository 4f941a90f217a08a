"""gazelle.ros's JointStateMonitor (move_group's current state) in a real rclpy context: messages of
several publishers, each naming some joints, are merged in order; none is lost to the reader's history
when a fast publisher follows a slow one."""

from __future__ import annotations

import pytest

from ._harness import RosClient, wait_for

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

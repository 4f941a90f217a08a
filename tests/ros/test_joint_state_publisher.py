"""gazelle's joint_state_publisher against joint_state_publisher's own (ROS 2 branch,
joint_state_publisher/joint_state_publisher.py): which joints it publishes and in what order, where each
starts (``zeros``, the middle of a range without 0, soft limits), mimic chains and ``dependent_joints``,
the arrays a message has, ``delta``'s back-and-forth, ``source_list`` and a description file; and the
node in a real rclpy context."""

from __future__ import annotations

import math
from typing import Any, cast

import pytest
from _harness import RosClient, wait_for

from gazelle.ros._joint_state_publisher import (
    DescriptionError,
    Follower,
    JointStatePublisherNode,
    read_robot,
    resolve,
    state_arrays,
    step,
)

_LIMIT = '<limit lower="{lo}" upper="{hi}" effort="1" velocity="1"/>'


def _joint(name: str, kind: str, parent: str, child: str, extra: str = "") -> str:
    return (
        f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
        f'<axis xyz="0 0 1"/>{extra}</joint>'
    )


ARM = (
    '<robot name="arm">'
    + "".join(f'<link name="l{i}"/>' for i in range(7))
    + _joint("fixed_one", "fixed", "l0", "l1")
    + _joint("lift", "prismatic", "l1", "l2", _LIMIT.format(lo=0.2, hi=0.6))  # 0 outside: starts mid-range
    + _joint(
        "finger_b",
        "revolute",
        "l2",
        "l3",
        _LIMIT.format(lo=-1, hi=1) + '<mimic joint="finger_a" multiplier="2" offset="0.1"/>',
    )
    + _joint(
        "finger_a",
        "revolute",
        "l3",
        "l4",
        _LIMIT.format(lo=-1, hi=1) + '<mimic joint="wrist" multiplier="-1" offset="0.3"/>',
    )
    + _joint("wrist", "continuous", "l4", "l5")
    + _joint(
        "elbow",
        "revolute",
        "l5",
        "l6",
        _LIMIT.format(lo=-2, hi=2) + '<safety_controller soft_lower_limit="-1.5" k_velocity="1"/>',
    )
    + "</robot>"
)


def test_the_joints_are_published_in_the_files_order_from_where_joint_state_publisher_starts_them() -> None:
    robot = read_robot(ARM, zeros={"wrist": 0.5}, dependent={})
    assert robot.order == ["lift", "finger_b", "finger_a", "wrist", "elbow"]  # the file's, fixed left out
    assert set(robot.free) == {"lift", "wrist", "elbow"}
    assert robot.free["lift"].position == pytest.approx(0.4)  # 0 is outside 0.2..0.6: the middle
    assert robot.free["wrist"].position == 0.5  # zeros.wrist
    assert (robot.free["wrist"].lower, robot.free["wrist"].upper) == (-math.pi, math.pi)  # continuous
    assert (robot.free["elbow"].lower, robot.free["elbow"].upper) == (-1.5, 2.0)  # the written soft limit only
    names, positions, velocities, efforts = state_arrays(robot)
    assert names == robot.order
    # finger_a = -wrist + 0.3; finger_b = 2 * finger_a + 0.1, through the chain
    assert positions == pytest.approx([0.4, 2 * (-0.5 + 0.3) + 0.1, -0.5 + 0.3, 0.5, 0.0])
    assert velocities == [] and efforts == []  # publish_default_velocities / _efforts are false
    assert resolve(robot, "finger_b") == ("wrist", -2.0, pytest.approx(2 * 0.3 + 0.1))


def test_mimic_tags_can_be_ignored_and_dependent_joints_and_defaults_are_taken() -> None:
    robot = read_robot(
        ARM, zeros={}, dependent={"elbow": Follower("lift", 3.0)}, use_mimic=False, defaults=(True, True, True)
    )
    assert set(robot.free) == {"lift", "finger_b", "finger_a", "wrist"}  # mimic joints are free joints now
    robot.free["lift"].velocity = 0.1
    names, positions, velocities, efforts = state_arrays(robot)
    assert positions[names.index("elbow")] == pytest.approx(1.2)  # 3 * 0.4
    assert velocities[names.index("elbow")] == pytest.approx(0.3)
    assert efforts == [0.0] * 5
    unlimited = read_robot(ARM, zeros={}, dependent={}, use_smallest_limits=False)
    assert unlimited.free["elbow"].lower == -2.0


def test_a_joint_without_limits_and_a_mimic_cycle_are_refused_with_upstreams_words() -> None:
    bare = '<robot name="r"><link name="a"/><link name="b"/>' + _joint("j", "revolute", "a", "b") + "</robot>"
    with pytest.raises(DescriptionError, match='Limits must be specified for joint "j" of type "revolute"'):
        read_robot(bare, zeros={}, dependent={})
    robot = read_robot(ARM, zeros={}, dependent={"wrist": Follower("finger_b")})
    with pytest.raises(DescriptionError, match="infinite recursive mimic chain"):
        state_arrays(robot)


def test_delta_moves_joints_back_and_forth_and_wraps_a_continuous_one() -> None:
    robot = read_robot(ARM, zeros={"wrist": 3.0, "elbow": 1.9}, dependent={})
    step(robot, 0.2)
    assert robot.free["elbow"].position == 2.0 and not robot.free["elbow"].forward  # turned at its limit
    assert robot.free["wrist"].position == -math.pi  # past pi: wrapped to -pi
    step(robot, 0.2)
    assert robot.free["elbow"].position == pytest.approx(1.8)


def test_the_node_takes_source_list_values_and_a_description_file(tmp_path) -> None:
    from rclpy.parameter import Parameter
    from sensor_msgs.msg import JointState

    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    ros = RosClient("jsp_node_test")
    node = JointStatePublisherNode(
        str(path),
        context=ros.context,
        parameter_overrides=[
            Parameter("source_list", value=["/gripper/joint_states"]),
            Parameter("rate", value=50),
            Parameter("zeros.elbow", value=0.25),
        ],
    )
    ros.executor.add_node(node)
    heard: list[Any] = []
    sub = ros.node.create_subscription(JointState, "/joint_states", lambda m: heard.append(cast(JointState, m)), 10)
    source = ros.node.create_publisher(JointState, "/gripper/joint_states", 10)
    try:
        wait_for(lambda: heard, 10, "/joint_states")
        first = heard[-1]
        assert list(first.name) == ["lift", "finger_b", "finger_a", "wrist", "elbow"]
        assert first.position[4] == pytest.approx(0.25)
        wait_for(lambda: source.get_subscription_count() == 1, 10, "the node's source_list subscription")
        source.publish(JointState(name=["wrist", "unknown"], position=[1.0, 9.0], velocity=[0.5, 0.0]))

        def wrist_moved() -> Any:
            last = heard[-1]
            return last if last.position[3] == pytest.approx(1.0) else None

        msg = wait_for(wrist_moved, 10, "the source's wrist position")
        assert msg.position[2] == pytest.approx(-1.0 + 0.3)  # finger_a follows
        assert list(msg.velocity) == pytest.approx([0.0, -1.0, -0.5, 0.5, 0.0])  # the source's, scaled down the chain
        assert msg.header.stamp.sec > 0
    finally:
        ros.node.destroy_subscription(sub)
        ros.executor.remove_node(node)
        node.destroy_node()
        ros.close()


def test_a_bad_description_on_the_topic_is_refused_and_the_node_goes_on(tmp_path) -> None:
    """robot_description arrives from any ROS peer: text that is not a robot (garbage, xacro, which is never
    expanded, a joint without limits) is refused with a warning and the node publishes the robot it had; the
    next good description, published after them on the same latched topic, is taken."""
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String

    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    ros = RosClient("jsp_bad_description_test")
    node = JointStatePublisherNode(str(path), context=ros.context)
    ros.executor.add_node(node)
    heard: list[Any] = []
    sub = ros.node.create_subscription(JointState, "/joint_states", lambda m: heard.append(cast(JointState, m)), 10)
    latched = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    desc = ros.node.create_publisher(String, "/robot_description", latched)
    xacro = (
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="x">'
        '<xacro:property name="p" value="${__import__(\'os\').getpid()}"/></robot>'
    )
    bare = '<robot name="r"><link name="a"/><link name="b"/>' + _joint("j", "revolute", "a", "b") + "</robot>"
    good = (
        '<robot name="g"><link name="a"/><link name="b"/>'
        + _joint("k", "revolute", "a", "b", _LIMIT.format(lo=-1, hi=1))
        + "</robot>"
    )
    taken: list[bool] = []  # per description the node read: whether it became the node's robot
    configure = node._configure

    def spy(text: str) -> None:
        before = node._robot
        configure(text)
        taken.append(node._robot is not before)

    node._configure = spy  # the subscription calls it by name
    try:
        wait_for(lambda: heard, 10, "/joint_states of the arm")
        wait_for(lambda: desc.get_subscription_count() == 1, 10, "the node's robot_description subscription")
        for i, text in enumerate(("<<<not xml", xacro, bare, good)):  # one at a time: the node reads depth 1
            desc.publish(String(data=text))
            wait_for(lambda i=i: len(taken) > i, 10, f"the node to read description {i}")
        wait_for(lambda: list(heard[-1].name) == ["k"], 10, "the good description's joints")
        assert taken == [False, False, False, True]  # the three refused, in order, then the good one
    finally:
        ros.node.destroy_subscription(sub)
        ros.executor.remove_node(node)
        node.destroy_node()
        ros.close()

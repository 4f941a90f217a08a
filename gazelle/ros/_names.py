"""gz topic names on ROS.

gz-transport allows names ROS does not: gz-sim's JointPositionController listens on
``/model/<model>/joint/<joint>/0/cmd_pos``, and a ROS name's tokens must not start with a digit. With
ros_gz_bridge such a topic reaches ROS only under the name the bridge YAML gives it; gazelle, which has
every gz topic on ROS under its own name, puts an ``n`` before each such token
(``/model/panda/joint/panda_joint1/n0/cmd_pos``), and its parameter_bridge maps a YAML's
``gz_topic_name`` the same way. Valid names are unchanged.
"""

from __future__ import annotations


def gz_topic_on_ros(topic: str) -> str:
    """The ROS name of gz topic ``topic``: every token that starts with a digit gets an ``n`` before it."""
    return "/".join(f"n{t}" if t[:1].isdigit() else t for t in topic.split("/"))

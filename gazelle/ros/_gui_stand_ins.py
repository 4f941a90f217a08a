"""Stand-ins for the GUIs and image bridges that launch files start beside a simulator: ``gzclient`` and
``gz sim -g`` (Gazebo's GUI), ``rviz2`` and ros_gz_image's ``image_bridge``.

A missing executable aborts the whole launch, so each of these runs, says in one line what it is in gazelle,
and stays up until it is stopped (a launch waits on it, and may shut down when it exits, as with the real GUI).

The GUIs point at the running server's browser viewer, by the address that server took: each ``gazelle sim``
announces itself on the hidden latched ``/_gazelle/servers`` topic (:mod:`._exposure`), and once its viewer is
up the announcement carries the viewer's URL. A stand-in started before the server, or beside a server with no
viewer, says what it waits for and prints the address when one comes.

``image_bridge`` (ros_gz_image's ``image_bridge.cpp``: each argument a gz image topic, published on ROS under
the same name, through the node's remapping rules) has nothing to bridge: gazelle publishes a camera's images on
ROS under the gz topic's name already. Where a remapping rule renames the topic, the images are relayed to the
remapped name, as the real bridge's publisher would be renamed.
"""

from __future__ import annotations

import json
import os
import sys
from typing import TYPE_CHECKING

from ._exposure import ANNOUNCE_TOPIC
from ._names import gz_topic_on_ros

if TYPE_CHECKING:
    from rclpy.publisher import Publisher
    from rclpy.subscription import Subscription

NO_SERVER_NOTICE_SEC = 5.0
"""How long a GUI stand-in waits for a server's viewer before saying what it waits for."""


def gui_stand_in_main(name: str, intro: str, argv: list[str]) -> int:
    """Run a GUI stand-in named ``name`` (its node's name, as the real GUI's): print ``intro`` and the running
    server's viewer address once known; stay up until SIGINT/SIGTERM."""
    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    from ._rsp_node import spin_until_interrupted

    rclpy.init(args=[name, *argv])
    node = rclpy.create_node(name)
    domain = os.environ.get("ROS_DOMAIN_ID", "0")
    told: set[str] = set()

    def on_announce(msg: String) -> None:
        try:
            url = json.loads(msg.data).get("viewer")
        except (ValueError, AttributeError):
            return
        if isinstance(url, str) and url.startswith("http") and url not in told:
            told.add(url)
            print(f"{name} (gazelle): {intro}: open {url}", flush=True)

    qos = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    node.create_subscription(String, ANNOUNCE_TOPIC, on_announce, qos)

    def notice() -> None:
        timer.cancel()
        if not told:
            print(
                f"{name} (gazelle): {intro}; no gazelle sim with a viewer on ROS_DOMAIN_ID={domain} yet "
                "(one started with --no-viewer has none): its address is printed here when one comes",
                flush=True,
            )

    timer = node.create_timer(NO_SERVER_NOTICE_SEC, notice)
    spin_until_interrupted(node)
    return 0


def image_bridge_main(argv: list[str]) -> int:
    """ros_gz_image's ``image_bridge TOPIC [TOPIC ...]``: say where each topic's images already are on ROS, relay
    those a remapping rule renames; stay up until stopped."""
    import rclpy
    from rclpy.qos import qos_profile_default, qos_profile_sensor_data, qos_profile_system_default
    from rclpy.utilities import remove_ros_args
    from sensor_msgs.msg import Image

    from ._rsp_node import spin_until_interrupted

    rclpy.init(args=["image_bridge", *argv])
    node = rclpy.create_node("image_bridge")
    # the publisher's QoS as image_bridge.cpp's Handler takes it from its `qos` parameter (jazzy); the gz side is
    # read best effort, which matches gazelle's camera publishers whatever they offer
    node.declare_parameter("qos", "default")
    wanted = str(node.get_parameter("qos").value)
    profiles = {"default": qos_profile_default, "system_default": qos_profile_system_default}
    publish_qos = profiles.get(wanted, qos_profile_sensor_data if wanted == "sensor_data" else qos_profile_default)
    if wanted not in (*profiles, "sensor_data"):
        node.get_logger().error(f"Invalid QoS profile {wanted} specified. Using default profile.")
    topics = [a for a in remove_ros_args(["image_bridge", *argv])[1:] if not a.startswith("-")]
    if not topics:
        print("image_bridge (gazelle): usage: image_bridge TOPIC [TOPIC ...] (nothing to bridge)", file=sys.stderr)
    # the gz-named side of a relay: a node that ignores the command line's remapping rules
    raw = rclpy.create_node("image_bridge_gz_side", use_global_arguments=False, start_parameter_services=False)
    keep: list[Publisher | Subscription] = []
    for topic in topics:
        gz_name = gz_topic_on_ros(topic)
        ros_name = node.resolve_topic_name(topic)
        if ros_name.strip("/") == gz_name.strip("/"):
            print(
                f"image_bridge (gazelle): {topic}: gazelle publishes the camera's images on ROS as {ros_name} "
                "already; nothing to bridge",
                flush=True,
            )
            continue
        pub = node.create_publisher(Image, topic, publish_qos)
        keep.append(pub)
        keep.append(raw.create_subscription(Image, gz_name, pub.publish, qos_profile_sensor_data))
        print(f"image_bridge (gazelle): relaying {gz_name} -> {ros_name} (remapped)", flush=True)
    spin_until_interrupted(node, raw)
    return 0

"""The executables of ros_gz_sim, ros_gz_bridge and joint_state_publisher that Gazebo launch files run.

* ``create`` (ros_gz_sim): ``-name -topic -file -string -param -x -y -z -R -P -Y -world``, spawned
  as ``gazelle spawn`` spawns.
* ``parameter_bridge`` (ros_gz_bridge): gazelle publishes ROS topics itself, under the gz topic's
  name (see the README's sensors section), so there is nothing to bridge. It reads the same
  arguments (``/topic@ros_type@gz_type`` with ``@``, ``[`` or ``]``, and ``config_file`` YAML) and
  logs one line per entry: nothing to do, or that a renamed topic keeps its gz name.
* ``joint_state_publisher``: ``joint_states`` with every movable joint of ``robot_description`` (the
  parameter, else the latched topic) at zero, or the middle of its limits when zero is outside them;
  mimic joints follow; ``rate`` (10 Hz).
"""

from __future__ import annotations

import sys
from typing import Any

BRIDGE_DIRECTIONS = ("@", "[", "]")


def create_main(argv: list[str]) -> int:
    """``create``: ros_gz_sim's arguments, run as ``gazelle spawn``."""
    import argparse

    from ._spawn import main as spawn_main

    p = argparse.ArgumentParser(prog="create", description="Spawn an entity (ros_gz_sim's create)")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("-file")
    src.add_argument("-string")
    src.add_argument("-topic")
    src.add_argument("-param")
    p.add_argument("-name", default="")
    p.add_argument("-world", default="")
    p.add_argument("-allow_renaming", default="false")
    for axis in ("x", "y", "z", "R", "P", "Y"):
        p.add_argument(f"-{axis}", default="0")
    args = p.parse_args(argv)
    out = ["-entity", args.name or "entity"]
    for key in ("file", "string", "topic", "param"):
        value = getattr(args, key)
        if value:
            out += [f"-{key}", value]
    for axis in ("x", "y", "z", "R", "P", "Y"):
        out += [f"-{axis}", str(getattr(args, axis))]
    return spawn_main(out)


def _bridge_entries(argv: list[str]) -> tuple[list[tuple[str, str]], list[str]]:
    """(ros name, gz name) pairs from the command line and the config file; and the problems."""
    entries: list[tuple[str, str]] = []
    problems: list[str] = []
    config = None
    args = list(argv)
    if "--ros-args" in args:
        ros = args[args.index("--ros-args") + 1 :]
        args = args[: args.index("--ros-args")]
        for i, a in enumerate(ros):
            if a == "-p" and i + 1 < len(ros) and ros[i + 1].startswith("config_file:="):
                config = ros[i + 1].split(":=", 1)[1]
    for a in args:
        if a.startswith("-"):
            continue
        topic = a
        for d in BRIDGE_DIRECTIONS:
            topic = topic.split(d, 1)[0]
        if not topic:
            problems.append(f"cannot read bridge argument '{a}'")
            continue
        entries.append((topic, topic))
    if config:
        import yaml

        try:
            with open(config, encoding="utf-8") as f:
                data = yaml.safe_load(f) or []
        except (OSError, yaml.YAMLError) as err:
            problems.append(f"config_file {config}: {err}")
            data = []
        for item in data if isinstance(data, list) else []:
            if isinstance(item, dict):
                ros_name = str(item.get("ros_topic_name") or item.get("topic_name") or "")
                gz_name = str(item.get("gz_topic_name") or item.get("topic_name") or ros_name)
                if ros_name:
                    entries.append((ros_name, gz_name))
    return entries, problems


def bridge_main(argv: list[str]) -> int:
    """``parameter_bridge``: one line per entry (gazelle publishes ROS topics itself)."""
    entries, problems = _bridge_entries(argv)
    for p in problems:
        print(f"[ERROR] [ros_gz_bridge]: {p}", file=sys.stderr)
    for ros_name, gz_name in entries:
        if ros_name.strip("/") == gz_name.strip("/"):
            print(
                f"[INFO] [ros_gz_bridge]: {ros_name}: gazelle has it on ROS directly; nothing to bridge",
                file=sys.stderr,
            )
        else:
            print(
                f"[WARN] [ros_gz_bridge]: gz topic {gz_name} would appear as ROS topic {ros_name}; gazelle publishes "
                f"it as {gz_name}: set the sensor's <topic> to {ros_name}, or remap {gz_name}:={ros_name} in its "
                "subscriber",
                file=sys.stderr,
            )
    if not entries and not problems:
        print("[INFO] [ros_gz_bridge]: nothing to bridge", file=sys.stderr)
    return 1 if problems else 0


def joint_state_publisher_main(argv: list[str] | None = None) -> int:
    """``joint_state_publisher``: defaults for the movable joints, until Ctrl-C."""
    import math

    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String

    from ..description import JointType, Model, ModelLoadError, load_string
    from ._rsp_node import spin_until_interrupted

    rclpy.init(args=sys.argv if argv is None else argv)
    node = rclpy.create_node("joint_state_publisher")
    rate = float(node.declare_parameter("rate", 10.0).value or 10.0)
    text = str(node.declare_parameter("robot_description", "").value or "")
    state: dict[str, Any] = {"names": [], "positions": []}

    def use(description: str) -> None:
        try:
            model = load_string(description, format="urdf", source="robot_description").value
        except ModelLoadError as err:
            node.get_logger().error(f"robot_description is not a URDF: {err}")
            return
        if not isinstance(model, Model):
            return
        values: dict[str, float] = {}
        for j in model.joints:
            if j.type in (JointType.FIXED, JointType.FLOATING, JointType.PLANAR) or j.mimic is not None:
                continue
            lim = j.axis.limit if j.axis is not None else None
            lo = lim.lower if lim is not None and lim.lower is not None else -math.inf
            hi = lim.upper if lim is not None and lim.upper is not None else math.inf
            values[j.name] = 0.0 if lo <= 0.0 <= hi or not (math.isfinite(lo) and math.isfinite(hi)) else (lo + hi) / 2
        for j in model.joints:
            if j.mimic is not None and j.mimic.joint in values:
                values[j.name] = j.mimic.multiplier * values[j.mimic.joint] + j.mimic.offset
        state["names"], state["positions"] = list(values), list(values.values())

    if text:
        use(text)
    else:
        qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
        node.create_subscription(String, "robot_description", lambda m: use(str(getattr(m, "data", ""))), qos)
    pub = node.create_publisher(JointState, "joint_states", 10)

    def tick() -> None:
        if not state["names"]:
            return
        msg = JointState(name=state["names"], position=state["positions"])
        msg.header.stamp = node.get_clock().now().to_msg()
        pub.publish(msg)

    node.create_timer(1.0 / max(rate, 1e-3), tick)
    spin_until_interrupted(node)
    return 0

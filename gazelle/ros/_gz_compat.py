"""The executables of ros_gz_sim, ros_gz_bridge and joint_state_publisher that Gazebo launch files run.

* ``create`` (ros_gz_sim): ``-name -topic -file -string -param -x -y -z -R -P -Y -world``, spawned
  as ``gazelle spawn`` spawns.
* ``parameter_bridge`` (ros_gz_bridge): gazelle publishes ROS topics itself, under the gz topic's
  name (see docs/sensors.md), so an entry with equal names has nothing to bridge (one
  line says so); an entry that renames (``gz_topic_name: lidar``, ``ros_topic_name: scan``) is
  relayed between the two names, in its direction. Arguments as the bridge's:
  ``/topic@ros_type@gz_type`` (``[`` gz to ROS, ``]`` ROS to gz) and the ``config_file`` YAML.
* ``joint_state_publisher``: joint_state_publisher's node (:mod:`gazelle.ros._joint_state_publisher`).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ._interfaces import resolve_interface
from ._names import gz_topic_on_ros

if TYPE_CHECKING:
    from rclpy.node import Node
    from rclpy.publisher import Publisher
    from rclpy.qos import QoSProfile
    from rclpy.subscription import Subscription

BRIDGE_DIRECTIONS = ("@", "[", "]")


def create_main(argv: list[str]) -> int:
    """``create``: ros_gz_sim's arguments, run as ``gazelle spawn``. A flag it does not know is passed over with
    one line, as ros_gz_sim's create (jazzy, src/create.cpp) does: it parses its gflags after
    ``gflags::AllowCommandLineReparsing()``, so gz_ros2_control_demos' XML launch files' ``-allow-renaming true``
    (its flag is ``-allow_renaming``) is ignored there, not an error."""
    import argparse

    from ._spawn_entity import main as spawn_main

    p = argparse.ArgumentParser(prog="create", description="Spawn an entity (ros_gz_sim's create)", allow_abbrev=False)
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
    args, unknown = p.parse_known_args(argv)
    if unknown:
        print(f"create: ignoring what it does not know: {' '.join(unknown)}", file=sys.stderr, flush=True)
    out = ["-entity", args.name or "entity"]
    for key in ("file", "string", "topic", "param"):
        value = getattr(args, key)
        if value:
            out += [f"-{key}", value]
    for axis in ("x", "y", "z", "R", "P", "Y"):
        out += [f"-{axis}", str(getattr(args, axis))]
    return spawn_main(out)


@dataclass(frozen=True)
class BridgeEntry:
    """One topic a ros_gz_bridge would bridge: its ROS and gz names, ROS type and direction."""

    ros_name: str
    gz_name: str
    ros_type: str = ""
    direction: str = "BIDIRECTIONAL"
    """GZ_TO_ROS, ROS_TO_GZ or BIDIRECTIONAL (the YAML's ``direction``; ``[``, ``]``, ``@`` on the command line)."""


def _bridge_entries(
    argv: list[str], config: str = "", expand: Callable[[str], str] | None = None
) -> tuple[list[BridgeEntry], list[str]]:
    """The entries of the command line (``/topic@ros_type[gz_type``, ROS arguments already removed) and of the
    ``config_file`` YAML; and the problems. ``expand`` turns a YAML's gz name into the node's namespace, as
    ``expand_gz_topic_names: true`` has ros_gz_bridge do (``RosGzBridge::spin`` in ros_gz_bridge.cpp, jazzy)."""
    entries: list[BridgeEntry] = []
    problems: list[str] = []
    for a in argv:
        if a.startswith("-"):
            continue
        cut = min((a.find(d) for d in BRIDGE_DIRECTIONS if d in a), default=-1)
        if cut <= 0:
            problems.append(f"cannot read bridge argument '{a}' (expected /topic@ros_type@gz_type, with [ or ])")
            continue
        topic, rest = a[:cut], a[cut + 1 :]
        second = min((rest.find(d) for d in BRIDGE_DIRECTIONS if d in rest), default=-1)
        ros_type = rest[:second] if second >= 0 else rest
        mark = rest[second] if second >= 0 else "@"
        direction = {"[": "GZ_TO_ROS", "]": "ROS_TO_GZ"}.get(mark, "BIDIRECTIONAL")
        entries.append(BridgeEntry(topic, topic, ros_type, direction))
    if config:
        from ..description import MAX_PARAMS_FILE_BYTES, UntrustedInputError, read_regular_file, safe_load_bounded

        try:  # the bounded loader: a bridge YAML is a file, and a bad one is one line, never a traceback
            data = safe_load_bounded(read_regular_file(config, MAX_PARAMS_FILE_BYTES, "config_file"), config) or []
        except (OSError, UntrustedInputError) as err:
            problems.append(f"config_file {config}: {err}")
            data = []
        for item in data if isinstance(data, list) else []:
            if isinstance(item, dict):
                ros_name = str(item.get("ros_topic_name") or item.get("topic_name") or "")
                gz_raw = str(item.get("gz_topic_name") or item.get("topic_name") or ros_name)
                gz_name = gz_topic_on_ros(expand(gz_raw) if expand else gz_raw)
                if ros_name:
                    entries.append(
                        BridgeEntry(
                            ros_name,
                            gz_name,
                            str(item.get("ros_type_name") or ""),
                            str(item.get("direction") or "BIDIRECTIONAL"),
                        )
                    )
    return entries, problems


def _bridge_node(argv: list[str]) -> tuple[Node, list[str], str, bool]:
    """The ``ros_gz_bridge`` node, made before anything is read, as ``RosGzBridge``'s constructor declares its
    parameters (ros_gz_bridge.cpp, jazzy): rcl then applies every form a user gives them, ``-p config_file:=F``,
    ``--params-file`` (what a launch file's ``parameters=[{...}]`` becomes) with its ``/**`` and node-name
    sections, and a renamed node (``__node:=``). Returns the node, the non-ROS arguments, ``config_file`` and
    ``expand_gz_topic_names``."""
    import rclpy
    from rclpy.utilities import remove_ros_args

    rclpy.init(args=["parameter_bridge", *argv])
    node = rclpy.create_node("ros_gz_bridge")
    node.declare_parameter("subscription_heartbeat", 1000)
    node.declare_parameter("config_file", "")
    node.declare_parameter("expand_gz_topic_names", False)
    node.declare_parameter("override_timestamps_with_wall_time", False)
    node.declare_parameter("lazy", False)  # parameter_bridge.cpp's own
    config = str(node.get_parameter("config_file").value or "")
    expand = bool(node.get_parameter("expand_gz_topic_names").value)
    return node, remove_ros_args(["parameter_bridge", *argv])[1:], config, expand


def _message_class(type_name: str) -> Any:
    """``pkg/msg/Type`` (or ``pkg/Type``) -> the rclpy message class, by the one checked resolver: a
    ``ros_type_name`` from the bridge's YAML or command line is data, imported only as an interface the
    ament index lists (:func:`~._interfaces.resolve_interface`)."""
    return resolve_interface(type_name, "msg")


def bridge_main(argv: list[str]) -> int:
    """``parameter_bridge``: gazelle has every topic on ROS under its gz name already; an entry whose
    ROS name differs is relayed between the two names in this process, as the bridge would; the rest
    get one line saying there is nothing to do."""
    from rclpy.expand_topic_name import expand_topic_name
    from rclpy.qos import QoSPresetProfiles
    from rclpy.utilities import try_shutdown

    node, args, config, expand_names = _bridge_node(argv)
    namespace, name = node.get_namespace(), node.get_name()
    expand = (lambda gz: expand_topic_name(gz, name, namespace)) if expand_names else None
    entries, problems = _bridge_entries(args, config, expand)
    for p in problems:
        print(f"[ERROR] [ros_gz_bridge]: {p}", file=sys.stderr)
    relays = [e for e in entries if e.ros_name.strip("/") != e.gz_name.strip("/")]
    typed = [e for e in entries if e not in relays and e.ros_type]
    for e in entries:
        if e not in relays:
            print(
                f"[INFO] [ros_gz_bridge]: {e.ros_name}: gazelle has it on ROS directly; nothing to bridge"
                + (" unless gazelle's type differs from its ros_type_name" if e.ros_type else ""),
                file=sys.stderr,
            )
    if not entries and not problems:
        print("[INFO] [ros_gz_bridge]: nothing to bridge", file=sys.stderr)
    if problems or (not relays and not typed):
        node.destroy_node()
        try_shutdown()
        return 1 if problems else 0
    qos = QoSPresetProfiles.SYSTEM_DEFAULT.value
    keep: list[Publisher | Subscription] = []
    if typed:
        _TypeRelays(node, typed, qos, keep)
    for e in relays:
        try:
            cls = _message_class(e.ros_type)
        except (ValueError, ImportError, AttributeError) as err:
            node.get_logger().error(f"{e.ros_name}: cannot bridge: {err}")
            continue
        pairs = []
        if e.direction in ("GZ_TO_ROS", "BIDIRECTIONAL"):
            pairs.append((e.gz_name, e.ros_name))
        if e.direction == "ROS_TO_GZ":
            pairs.append((e.ros_name, e.gz_name))
        for src, dst in pairs:
            pub = node.create_publisher(cls, dst, qos)
            keep.append(pub)
            keep.append(node.create_subscription(cls, src, lambda m, pub=pub: pub.publish(m), qos))
            node.get_logger().info(f"Creating relay [{src}] -> [{dst}] ({e.ros_type}): gazelle publishes the gz name")
    from ._rsp_node import spin_until_interrupted

    spin_until_interrupted(node)
    return 0


def _type_name(cls: type) -> str:
    """``geometry_msgs/Twist`` for the rclpy class (rosidl's field types name nested messages so)."""
    return f"{cls.__module__.split('.')[0]}/{cls.__name__}"


def converter(src: Any, dst: Any) -> Any:
    """A function from a message of class ``src`` to one of ``dst`` when one holds the other (a TwistStamped's
    ``twist`` is a Twist): unwrapped, or wrapped with a default header; None for unrelated types."""
    for field, kind in dst.get_fields_and_field_types().items():
        if kind == _type_name(src):
            return lambda msg, field=field: dst(**{field: msg})
    for field, kind in src.get_fields_and_field_types().items():
        if kind == _type_name(dst):
            return lambda msg, field=field: getattr(msg, field)
    return None


class _TypeRelays:
    """Entries whose ROS name is gazelle's own but whose ``ros_type_name`` is not gazelle's type: TurtleBot3's
    jazzy bridge YAML has ``cmd_vel`` as ``geometry_msgs/msg/TwistStamped`` (ros_gz_bridge converts it to
    gz.msgs.Twist), while gazelle's DiffDrive takes ``geometry_msgs/msg/Twist`` on ``/cmd_vel``, so a stamped
    command reached nothing and the robot never moved. Once the graph shows gazelle's endpoint (the robot
    may be spawned after the bridge starts), a relay on the same name converts between the two types, in
    the entry's direction, as the bridge would."""

    def __init__(
        self, node: Node, entries: list[BridgeEntry], qos: QoSProfile, keep: list[Publisher | Subscription]
    ) -> None:
        """Relays for ros_gz_bridge YAML entries whose ROS type differs from the one gazelle publishes (the YAML's
        ``ros_type_name`` is what the user's nodes expect); checked every 0.5 s until every topic has appeared."""
        self.node, self.pending, self.qos, self.keep = node, list(entries), qos, keep
        self._out: Node | None = None
        self.timer = node.create_timer(0.5, self.check)
        self.check()

    def out_node(self) -> Node:
        """A node in a context of its own for the converted side: one DDS participant refuses a topic name
        with two types ("create_subscription() called for existing topic name rt/cmd_vel with incompatible
        type"), so the two types of one name live in two participants. Publishing needs no spinning."""
        if self._out is None:
            import atexit

            import rclpy
            from rclpy.context import Context
            from rclpy.utilities import try_shutdown

            context = Context()
            rclpy.init(context=context)
            self._out = rclpy.create_node("ros_gz_bridge_converted", context=context)
            atexit.register(lambda: try_shutdown(context=context))
        return self._out

    def _native(self, name: str, wanted: str, gazelle_subscribes: bool) -> str | None:
        """The type of the other side's endpoint of ``name`` (another node's, not this bridge's): '' when it is
        ``wanted``, None while there is none."""
        infos = (
            self.node.get_subscriptions_info_by_topic(name)
            if gazelle_subscribes
            else self.node.get_publishers_info_by_topic(name)
        )
        mine = {self.node.get_name(), "ros_gz_bridge_converted"}
        kinds = {i.topic_type for i in infos if i.node_name not in mine}
        if wanted in kinds:
            return ""  # the same type: nothing to convert
        return sorted(kinds)[0] if kinds else None

    def check(self) -> None:
        """For each entry not yet settled: once gazelle's topic exists, nothing to do when its type is the YAML's;
        else a relay that converts field by field (between compatible types), or an error naming both types when
        they cannot be converted."""
        for e in list(self.pending):
            name = e.ros_name if e.ros_name.startswith("/") else f"/{e.ros_name}"
            wanted = e.ros_type if e.ros_type.count("/") == 2 else e.ros_type.replace("/", "/msg/", 1)
            to_gz = e.direction == "ROS_TO_GZ"
            native = self._native(name, wanted, to_gz)
            if native is None:
                continue
            self.pending.remove(e)
            if not native:
                continue
            try:
                ros_cls, gz_cls = _message_class(wanted), _message_class(native)
            except (ValueError, ImportError, AttributeError) as err:
                self.node.get_logger().error(f"{name}: cannot bridge: {err}")
                continue
            src, dst = (ros_cls, gz_cls) if to_gz else (gz_cls, ros_cls)
            convert = converter(src, dst)
            if convert is None:
                self.node.get_logger().error(
                    f"{name}: gazelle's {native} and the YAML's {wanted} are not convertible; not bridged"
                )
                continue
            pub = self.out_node().create_publisher(dst, name, self.qos)
            sub = self.node.create_subscription(src, name, lambda m, pub=pub, c=convert: pub.publish(c(m)), self.qos)
            self.keep += [pub, sub]
            self.node.get_logger().info(
                f"Converting [{name}] {_type_name(src)} -> {_type_name(dst)}: gazelle's type differs from the YAML's"
            )
        if not self.pending:
            self.timer.cancel()


def joint_state_publisher_main(argv: list[str] | None = None) -> int:
    """``joint_state_publisher`` (see :mod:`gazelle.ros._joint_state_publisher`)."""
    from ._joint_state_publisher import main

    return main(argv)

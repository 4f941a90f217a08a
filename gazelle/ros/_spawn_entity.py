"""``gazelle spawn``: the arguments and behaviour of gazebo_ros's ``spawn_entity.py``.

It reads the entity XML from a file, a latched topic (``robot_description``),
a string or stdin, waits for ``<gazebo_namespace>/spawn_entity``, calls it, and
exits 0 on success or 1 with a one-line reason. Unlike the original it never
hangs: every wait has a timeout.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
import time
from pathlib import Path
from xml.sax.saxutils import escape

import rclpy
from gazebo_msgs.srv import SpawnEntity
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from std_srvs.srv import Empty

from ..description import quat_from_rpy
from ..systems import RSP_PLUGIN


def build_parser() -> argparse.ArgumentParser:
    """gazebo_ros's ``spawn_entity.py`` options (single-dash, as its users type them)."""
    p = argparse.ArgumentParser(
        prog="gazelle spawn",
        description="Spawn an entity in gazelle (the arguments of gazebo_ros's spawn_entity.py).",
    )
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("-file", dest="file", help="load entity XML (URDF, SDF or xacro) from a file")
    source.add_argument("-topic", dest="topic", help="load entity XML from a std_msgs/String topic (latched)")
    source.add_argument("-string", dest="string", help="entity XML given on the command line")
    source.add_argument("-database", dest="database", help="spawn model://NAME from the resource paths")
    source.add_argument("-stdin", dest="stdin", action="store_true", help="load entity XML from standard input")
    source.add_argument(
        "-param",
        dest="param",
        help="ROS 1 spawn_model: the description parameter; in ROS 2 read from the topic of that name "
        "(robot_state_publisher publishes it)",
    )
    p.add_argument("-entity", "-model", dest="entity", required=True, help="name of the entity to spawn")
    p.add_argument("-sdf", action="store_true", help="ROS 1 spawn_model: the XML is SDF (detected anyway)")
    p.add_argument("-urdf", action="store_true", help="ROS 1 spawn_model: the XML is URDF (detected anyway)")
    p.add_argument("-reference_frame", default="", help="frame of the pose ('' or world = world)")
    p.add_argument("-gazebo_namespace", default="", help="ROS namespace of the spawn service")
    p.add_argument("-robot_namespace", default="", help="namespace for the entity's topics")
    p.add_argument("-timeout", type=float, default=30.0, help="seconds to wait for the XML and the service")
    p.add_argument("-spawn_service_timeout", type=float, default=None, help="deprecated alias of -timeout")
    p.add_argument("-unpause", action="store_true", help="call unpause_physics after spawning")
    p.add_argument("-wait", dest="wait", default=None, help="wait for this entity in /get_model_list first")
    p.add_argument(
        "-no_robot_state_publisher",
        action="store_true",
        help="you run your own robot_state_publisher: gazelle publishes no /robot_description, /tf_static "
        "or joint /tf for this entity",
    )
    p.add_argument("-frame_prefix", default=None, help="prefix of the entity's TF frames (default: NAMESPACE/)")
    p.add_argument(
        "-package_to_model",
        action="store_true",
        help='convert urdf <mesh filename="package://..." to <mesh filename="model://..."',
    )
    p.add_argument(
        "-b",
        dest="bond",
        action="store_true",
        help="bond to the simulator and delete the entity when this program is interrupted",
    )
    for axis in ("x", "y", "z", "R", "P", "Y"):
        p.add_argument(f"-{axis}", type=float, default=0.0, help=f"initial {axis}")
    p.add_argument(
        "--arg",
        dest="xacro_args",
        action="append",
        default=[],
        metavar="NAME:=VALUE",
        help="a xacro argument for -file (repeatable), as `xacro FILE NAME:=VALUE` and `gazelle sim --arg`",
    )
    return p


def _fail(node: Node | None, message: str) -> int:
    """Say an error as spawn_entity.py does (on the node's logger, else on stderr) and return exit code 1."""
    if node is not None:
        node.get_logger().error(message)
    else:
        print(f"[ERROR] [spawn_entity]: {message}", file=sys.stderr)
    return 1


def _read_topic(node: Node, executor: SingleThreadedExecutor, topic: str, timeout: float) -> str | None:
    """The latched string on ``topic`` (a robot_description), or None when none arrives within ``timeout``."""
    got: list[str] = []
    qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)

    def keep(msg: String) -> None:
        got.append(msg.data)

    sub = node.create_subscription(String, topic, keep, qos)
    deadline = time.monotonic() + timeout
    while not got and time.monotonic() < deadline and executor.context.ok():
        executor.spin_once(timeout_sec=0.1)
    node.destroy_subscription(sub)
    return got[0] if got else None


UNKNOWN_NODE = "_NODE_NAME_UNKNOWN_"
"""The node name the ROS graph gives a publisher whose node it has not heard of yet."""

NODE_NAME_WAIT_SEC = 5.0
"""How long the spawner waits for the ROS graph to name the description's publishers."""


GRAPH_SETTLE_SEC = 2.0
"""How long the hint for a silent description topic waits for the graph to show its publishers."""


def _named_publishers(node: Node, topic: str, *, appear_within: float) -> list:
    """The publishers of ``topic`` as the graph lists them, once it has named their nodes.

    A publisher's endpoint and the name of its node come on different discovery messages: on a loaded
    machine the graph lists it as ``_NODE_NAME_UNKNOWN_`` for a while. This waits, at most
    :data:`NODE_NAME_WAIT_SEC`, until every publisher is named, and at most ``appear_within`` seconds for a
    first one to appear (0: answer at once when there is none). [] when the graph cannot be read."""
    start = time.monotonic()
    while True:
        try:
            pubs = node.get_publishers_info_by_topic(topic)
        except Exception:  # a graph that cannot be read has no publishers to name
            return []
        waited = time.monotonic() - start
        if pubs and (all(p.node_name != UNKNOWN_NODE for p in pubs) or waited >= NODE_NAME_WAIT_SEC):
            return pubs
        if not pubs and waited >= appear_within:
            return []
        time.sleep(0.05)  # the graph is kept by the middleware's own threads: no spinning needed


def _topic_hint(node: Node, topic: str) -> str:
    """What the graph says about a description topic that delivered nothing: who publishes it, or what to do
    (a loaded run's hint named ``_NODE_NAMESPACE_UNKNOWN_/_NODE_NAME_UNKNOWN_``: it now waits for the names)."""
    name = topic if topic.startswith("/") else f"/{topic}"
    # on a loaded machine discovery may lag behind the wait: give the graph a moment to show them
    pubs = _named_publishers(node, name, appear_within=GRAPH_SETTLE_SEC)
    if not pubs:
        return (
            f"no node publishes {name}. Start robot_state_publisher with your robot_description, or spawn the "
            "file directly: gazelle spawn -entity NAME -file robot.urdf.xacro"
        )
    who = ", ".join(
        sorted(
            {
                f"{p.node_namespace.rstrip('/')}/{p.node_name}"
                if p.node_name != UNKNOWN_NODE
                else "a node not yet named"
                for p in pubs
            }
        )
    )
    latched = any(p.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL for p in pubs)
    if not latched:
        return (
            f"{who} publishes {name} but not latched (durability volatile), so a late subscriber gets nothing; "
            "publish it with transient_local durability, as robot_state_publisher does, or use -file"
        )
    return f"{who} publishes {name} (latched) but sent nothing yet; is its description parameter empty?"


def _is_xacro(p: Path, text: str) -> bool:
    """Whether a file is xacro (by its suffix or its markup)."""
    from ..description import xacro_markup

    return p.name.endswith(".xacro") or xacro_markup(text) is not None


def _xml_from_file(path: str, xacro_args: dict[str, str] | None = None) -> str:
    """The entity XML of a file the user named: xacro (by suffix or markup) is expanded here, in the
    user's own process and bounded in time and memory, so the server only ever receives plain XML (the
    expanded elements carry their file and line); any other file is sent as it is."""
    from ..description import DiagnosticSink, ModelLoadError, ResourceResolver, expand_xacro_bounded

    p = Path(path)
    text = p.read_text(encoding="utf-8")
    if not _is_xacro(p, text):
        return text
    sink = DiagnosticSink()
    out = expand_xacro_bounded(text, source=str(p), args=xacro_args or {}, sink=sink, resolver=ResourceResolver())
    if out is None:
        raise ModelLoadError(sink.items)
    return out


def with_file_named(message: str, args: argparse.Namespace) -> str:
    """The server's reply with the file's name where it says ``<spawn_entity:NAME>`` (the label of XML it got as
    a string): for a plain file sent as it is, whose lines are the file's (a refused spawn said
    ``<spawn_entity:bot>:19`` where the user's file is ``robot.urdf:19``); xacro output names its files itself."""
    if not getattr(args, "plain_file", False) or args.package_to_model:
        return message
    return message.replace(f"<spawn_entity:{args.entity or 'entity'}>", str(args.file))


_PARAMETERS = re.compile(r"<parameters>\s*([^<]*?)\s*</parameters>")


def with_parameters_text(xml: str, folder: Path) -> str:
    """A robot file's ros2_control ``<parameters>`` that name a file beside it (or an absolute path): read here,
    with the user's own rights, and carried in the XML for the server, which cannot read the folder of a file it
    never saw (gazebo_ros2_control reads them next to the robot file, and so does ``gazelle sim FILE``). Each is
    added on the ``</parameters>`` line, its newlines as character references, so the file's line numbers hold.
    ``package://``/``$(find)`` paths are left to the server's resource roots; a file that cannot be read is left
    for the server to name."""
    from ..description import MAX_PARAMS_FILE_BYTES, PARAMETERS_TEXT_TAG, UntrustedInputError, read_regular_file

    def carry(match: re.Match[str]) -> str:
        raw = match.group(1)
        if not raw or "://" in raw or "$(" in raw:
            return match.group(0)
        path = Path(raw) if Path(raw).is_absolute() else folder / raw
        try:
            text = read_regular_file(path, MAX_PARAMS_FILE_BYTES, "parameters file")
        except (OSError, UntrustedInputError):
            return match.group(0)
        body = escape(text, {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"})
        name = escape(raw, {'"': "&quot;"})
        return f'{match.group(0)}<{PARAMETERS_TEXT_TAG} file="{name}">{body}</{PARAMETERS_TEXT_TAG}>'

    return _PARAMETERS.sub(carry, xml)


def with_robot_state_options(xml: str, *, enabled: bool, frame_prefix: str | None) -> str:
    """Add a ``gazelle_robot_state_publisher`` plugin block (see gazelle.systems.robot_state) to URDF or SDF text."""
    from xml.sax.saxutils import escape

    body = f"<enabled>{'true' if enabled else 'false'}</enabled>"
    if frame_prefix is not None:
        body += f"<frame_prefix>{escape(frame_prefix)}</frame_prefix>"
    plugin = f'<plugin name="robot_state_publisher" filename="{RSP_PLUGIN}">{body}</plugin>'
    if "</robot>" in xml:
        i = xml.rindex("</robot>")
        return xml[:i] + f"<gazebo>{plugin}</gazebo>" + xml[i:]
    if "</model>" in xml:
        i = xml.rindex("</model>")  # the outermost model closes last
        return xml[:i] + plugin + xml[i:]
    return xml


def _published_by_robot_state_publisher(node: Node, topic: str) -> bool:
    """Whether a node named robot_state_publisher publishes ``topic`` (the description just read).

    The description arrives as soon as its publisher is matched, but the name of the node behind it comes
    on another discovery message: on a busy machine the graph still lists the publisher as
    ``_NODE_NAME_UNKNOWN_`` then, and the user's robot_state_publisher was taken for someone else (both
    it and gazelle's built-in one published the robot's TF). So the answer waits, at most
    :data:`NODE_NAME_WAIT_SEC`, until every publisher of the topic is named."""
    name = topic if topic.startswith("/") else f"/{topic}"
    return any(p.node_name == "robot_state_publisher" for p in _named_publishers(node, name, appear_within=0.0))


def _has_ros2_control(xml: str) -> bool:
    """Whether a model asks for ros2_control (its joint_state_broadcaster publishes the joint states, as in Gazebo)."""
    return "<ros2_control" in xml or ("ros2_control" in xml and "<plugin" in xml)


def with_joint_state_publisher(xml: str) -> str:
    """Add gz-sim's JointStatePublisher (every joint, on ``joint_states`` under the robot's namespace)
    to a URDF or SDF that has no joint state publisher plugin, and no ros2_control (whose
    joint_state_broadcaster publishes them: two publishers of /joint_states disagree, one with NaN efforts)."""
    if "joint_state_publisher" in xml or "JointStatePublisher" in xml or "joint-state-publisher" in xml:
        return xml
    if _has_ros2_control(xml):
        return xml
    plugin = (
        '<plugin filename="gz-sim-joint-state-publisher-system" name="gz::sim::systems::JointStatePublisher">'
        "<topic>joint_states</topic></plugin>"
    )
    if "</robot>" in xml:
        i = xml.rindex("</robot>")
        return xml[:i] + f"<gazebo>{plugin}</gazebo>" + xml[i:]
    if "</model>" in xml:
        i = xml.rindex("</model>")
        return xml[:i] + plugin + xml[i:]
    return xml


def _split_ros_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """(the spawn's own arguments, what follows ``--ros-args`` up to ``--``)."""
    if "--ros-args" not in argv:
        return argv, []
    i = argv.index("--ros-args")
    rest = argv[i + 1 :]
    end = rest.index("--") if "--" in rest else len(rest)
    return argv[:i] + rest[end + 1 :], rest[:end]


def _params_files(ros_args: list[str]) -> list[str]:
    """The ``--params-file F`` of the ROS arguments (for the robot's controller manager); the other
    ROS arguments are named in a warning (this process is a client, they would not reach the robot)."""
    files, i = [], 0
    while i < len(ros_args):
        if ros_args[i] == "--params-file" and i + 1 < len(ros_args):
            files.append(ros_args[i + 1])
            i += 2
            continue
        print(f"[WARN] [spawn_entity]: ROS argument '{ros_args[i]}' is not used by gazelle spawn", file=sys.stderr)
        i += 1
    return files


def main(argv: list[str]) -> int:
    """Run ``gazelle spawn``; returns the exit code."""
    argv, ros_args = _split_ros_args(argv)
    args = build_parser().parse_args(argv)
    if args.param:  # ROS 1's parameter server is ROS 2's latched description topic
        args.topic = args.param
    args.params_files = _params_files(ros_args)
    bad = [a for a in args.xacro_args if ":=" not in a]
    if bad:
        return _fail(None, f"--arg takes NAME:=VALUE, got {bad[0]!r}")
    timeout = args.spawn_service_timeout if args.spawn_service_timeout is not None else args.timeout
    if not math.isfinite(timeout) or timeout < 0:
        return _fail(None, f"-timeout must be a non-negative number, got {timeout}")
    file_xml: str | None = None
    if args.file:  # before rclpy starts its threads: a xacro file is expanded in a forked child
        print(f"[INFO] [spawn_entity]: Loading entity XML from file {args.file}", file=sys.stderr)
        try:
            file_xml = _xml_from_file(args.file, dict(a.split(":=", 1) for a in args.xacro_args))
            args.plain_file = not _is_xacro(Path(args.file), Path(args.file).read_text(encoding="utf-8"))
            file_xml = with_parameters_text(file_xml, Path(args.file).resolve().parent)
        except FileNotFoundError:
            return _fail(None, f"Error: specified file {args.file} does not exist")
        except Exception as err:
            return _fail(None, f"Error: cannot read {args.file}: {err}")
    context = Context()
    rclpy.init(args=[], context=context)
    node = rclpy.create_node("spawn_entity", context=context)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    try:
        return _run(node, executor, args, timeout, file_xml)
    except KeyboardInterrupt:
        return _fail(node, "interrupted")
    finally:
        executor.shutdown()
        node.destroy_node()
        if context.ok():
            rclpy.shutdown(context=context)


def _entity_xml(node: Node, executor: SingleThreadedExecutor, args: argparse.Namespace, timeout: float) -> str | None:
    """The entity's XML from -topic, -string, -database or stdin (whichever was given); None after
    saying why (a topic that published nothing in time, with who publishes it)."""
    log = node.get_logger()
    if args.topic:
        log.info(f"Loading entity published on topic {args.topic}")
        log.info(f"Waiting for entity xml on {args.topic}")
        got = _read_topic(node, executor, args.topic, timeout)
        if got is None:
            _fail(
                node,
                f"Timed out after {timeout:g} s waiting for entity xml on topic {args.topic}: "
                + _topic_hint(node, args.topic),
            )
        return got
    if args.string is not None:
        return args.string
    if args.database:
        return (
            '<sdf version="1.6"><world name="default"><include>'
            f"<uri>model://{args.database}</uri></include></world></sdf>"
        )
    log.info("Loading entity XML from stdin")
    return sys.stdin.read()


def _give_params_files(node: Node, executor: SingleThreadedExecutor, args: argparse.Namespace, timeout: float) -> bool:
    """``--ros-args --params-file``: the files given to the robot's controller manager; True if that failed
    (said why)."""
    from ._controller_spawner import give_params_files

    robot_ns = args.robot_namespace.strip("/")
    manager = f"/{robot_ns}/controller_manager" if robot_ns else "/controller_manager"
    why = give_params_files(node, executor, manager, args.params_files, max(timeout, 1.0))
    if why is not None:
        _fail(node, f"--params-file: {why}")
        return True
    node.get_logger().info(f"Gave {', '.join(args.params_files)} to {manager}")
    return False


def _run(
    node: Node, executor: SingleThreadedExecutor, args: argparse.Namespace, timeout: float, file_xml: str | None
) -> int:
    """spawn_entity.py's work: the entity's XML (a file, a topic, a parameter, or stdin), adapted as asked
    (``-package_to_model``, gazelle's robot_state_publisher off when the user runs their own), sent to
    ``<gazebo_namespace>/spawn_entity`` with the requested pose; then the controllers' parameter files,
    ``-unpause`` and ``-bond`` as the original does. The exit code is the script's."""
    log = node.get_logger()
    log.info("Spawn Entity started")
    xml = file_xml if file_xml is not None else _entity_xml(node, executor, args, timeout)
    if xml is None:
        return 1
    if not xml.strip():
        return _fail(node, "Error: entity XML is empty")
    if args.package_to_model:
        xml = _package_to_model(xml)
        if xml is None:
            return _fail(node, "Invalid XML: the entity does not parse")

    if args.topic and not args.no_robot_state_publisher and _published_by_robot_state_publisher(node, args.topic):
        # one publisher per transform: the user's robot_state_publisher publishes this robot's TF, so
        # gazelle's built-in one is off, and the robot publishes joint_states for it (as Gazebo users add
        # a joint state publisher plugin for)
        log.info(
            f"{args.topic} comes from a running robot_state_publisher: gazelle's built-in one is off for this "
            "robot, which publishes joint_states for it"
        )
        args.no_robot_state_publisher = True
        xml = with_joint_state_publisher(xml)
    if args.no_robot_state_publisher or args.frame_prefix is not None:
        xml = with_robot_state_options(xml, enabled=not args.no_robot_state_publisher, frame_prefix=args.frame_prefix)
    ns = args.gazebo_namespace.rstrip("/")
    service = f"{ns}/spawn_entity"
    client = node.create_client(SpawnEntity, service)
    log.info(f"Waiting for service {service}, timeout = {timeout:.0f}")
    if not client.wait_for_service(timeout_sec=timeout):
        return _fail(node, f"Service {service} unavailable. Was gazelle sim started?")
    req = SpawnEntity.Request()
    req.name = args.entity
    req.xml = xml
    req.robot_namespace = args.robot_namespace
    req.reference_frame = args.reference_frame
    req.initial_pose.position.x, req.initial_pose.position.y, req.initial_pose.position.z = args.x, args.y, args.z
    w, x, y, z = quat_from_rpy(args.R, args.P, args.Y)
    o = req.initial_pose.orientation
    o.w, o.x, o.y, o.z = w, x, y, z
    log.info(f"Calling service {service}")
    future = client.call_async(req)
    executor.spin_until_future_complete(future, timeout_sec=max(timeout, 1.0))
    res = future.result() if future.done() else None
    if res is None:
        return _fail(node, f"Service {service} did not answer within {max(timeout, 1.0):g} s")
    if not res.success:
        return _fail(node, f"Spawn service failed: {with_file_named(res.status_message, args)}")
    log.info(f"Spawn status: {with_file_named(res.status_message, args)}")
    if args.params_files and _give_params_files(node, executor, args, timeout):
        return 1
    if args.unpause:
        unpause = node.create_client(Empty, f"{ns}/unpause_physics")
        if unpause.wait_for_service(timeout_sec=timeout):
            f2 = unpause.call_async(Empty.Request())
            executor.spin_until_future_complete(f2, timeout_sec=timeout)
    if args.bond:
        return _bond(node, executor, args, timeout)
    return 0


def _package_to_model(xml: str) -> str | None:
    """spawn_entity.py's ``-package_to_model``: every ``<mesh filename="package://...">`` made ``model://...``
    (the XML parsed and written again, as upstream does); None when the XML does not parse."""
    from urllib.parse import urlsplit
    from xml.etree import ElementTree

    try:
        root = ElementTree.fromstring(xml)
    except ElementTree.ParseError:
        return None
    for mesh in root.iterfind(".//mesh"):
        filename = mesh.get("filename")
        if filename is not None and urlsplit(filename).scheme == "package":
            mesh.set("filename", "model" + filename[len("package") :])
    return ElementTree.tostring(root, encoding="unicode")


def _bond(node: Node, executor: SingleThreadedExecutor, args: argparse.Namespace, timeout: float) -> int:
    """spawn_entity.py's ``-b``: stay until interrupted (Ctrl-C, SIGTERM), then delete the entity, through a
    context of its own (a signal may have shut the first down: upstream's own call fails there, its TODO
    on ros2/rclpy#244)."""
    import signal

    stop = []
    # Ctrl-C and a launch's SIGTERM end the wait between two spins, whenever they come (rclpy's own handler
    # left it racy: a SIGINT that landed inside a spin was seen neither as KeyboardInterrupt nor as a shut
    # down context, and the process hung)
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, lambda *_: stop.append(True))
    # said once the handlers are in: a signal sent when this line shows never meets the default action
    node.get_logger().info(f"Waiting for shutdown to delete entity [{args.entity}]")
    try:
        while node.context.ok() and not stop:
            executor.spin_once(timeout_sec=0.2)
    except KeyboardInterrupt:
        pass
    except Exception:
        if node.context.ok():
            raise
    print(f"[INFO] [spawn_entity]: Deleting entity [{args.entity}]", file=sys.stderr, flush=True)
    from gazebo_msgs.srv import DeleteEntity
    from rclpy.signals import SignalHandlerOptions

    context = Context()
    rclpy.init(args=[], context=context, signal_handler_options=SignalHandlerOptions.NO)
    deleter = rclpy.create_node("spawn_entity_bond", context=context)
    local = SingleThreadedExecutor(context=context)
    local.add_node(deleter)
    try:
        service = f"{args.gazebo_namespace.rstrip('/')}/delete_entity"
        client = deleter.create_client(DeleteEntity, service)
        if not client.wait_for_service(timeout_sec=max(timeout, 1.0)):
            return _fail(deleter, f"Service {service} unavailable. Was gazelle sim started?")
        future = client.call_async(DeleteEntity.Request(name=args.entity))
        local.spin_until_future_complete(future, timeout_sec=max(timeout, 1.0))
        res = future.result() if future.done() else None
        if res is None:
            return _fail(deleter, f"Service {service} did not answer within {max(timeout, 1.0):g} s")
        deleter.get_logger().info(f"Deleting status: {res.status_message}")
        return 0 if res.success else 1
    finally:
        local.shutdown()
        deleter.destroy_node()
        rclpy.shutdown(context=context)

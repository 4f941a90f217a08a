"""robot_state_publisher as a ROS node (the real one is C++ and not on PyPI): ``ros2 run
robot_state_publisher robot_state_publisher --ros-args -p robot_description:=...``.

Reads the ``robot_description`` parameter (URDF, or a one-model SDF as Jazzy's sdformat_urdf plugin reads it:
data, never xacro-expanded) and ``joint_states``;
publishes ``robot_description`` (latched), ``/tf_static`` for fixed joints and ``/tf`` for moving ones,
every frame prefixed with ``frame_prefix``. What it does is robot_state_publisher 3.3.3's (Jazzy;
``src/robot_state_publisher.cpp``), read from its source:

* the tree is every joint of the URDF, a ``world`` link's joints included (a fixed ``world`` ->
  ``base_link`` joint is a static transform, as KDL makes it); floating joints are skipped and planar
  ones are fixed (``addChildren``: KDL has no planar joint);
* mimic joints that a JointState does not name get ``multiplier * leader + offset`` from their leader
  (``callbackJointState``'s mimic map);
* a JointState is published when its stamp is at least ``1000 / publish_frequency`` whole milliseconds
  past the oldest last publication of its joints, on the message's stamp, not the wall clock: a joint
  state stamped 0 is never due unless ``ignore_timestamp``, which publishes every message; the transforms
  always carry the message's stamp;
* when the node's clock goes back (a bag played again, a simulation reset) the publication times are
  forgotten, with the same warning.

One difference: a position that is not finite is skipped (upstream would send a NaN transform, which
tf2 refuses with an error for every lookup of that frame).
"""

from __future__ import annotations

import math
import sys
from typing import Any

import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy._rclpy_pybind11 import RCLError
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.utilities import try_shutdown
from sensor_msgs.msg import JointState
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage

from ..description import Joint, JointType, Model, ModelLoadError, Pose, load_string
from ._dds import announce_often
from ._signals import await_signal_shutdown, silence_half_made_objects, spin_until_shutdown


def joint_motion(joint: Joint, q: float) -> Pose:
    """X_PC of a 1-dof joint at position ``q``: origin * motion(axis, q) * child_offset."""
    axis = joint.axis.xyz if joint.axis is not None else (1.0, 0.0, 0.0)
    n = math.sqrt(sum(a * a for a in axis)) or 1.0
    ax = tuple(a / n for a in axis)
    if joint.type is JointType.PRISMATIC:
        motion = Pose((ax[0] * q, ax[1] * q, ax[2] * q))
    else:
        s = math.sin(q / 2.0)
        motion = Pose(orientation=(math.cos(q / 2.0), ax[0] * s, ax[1] * s, ax[2] * s))
    return joint.origin * motion * joint.child_offset


def _format_of(text: str) -> str:
    """``sdf`` when the description's root element is ``<sdf>``, else ``urdf`` (xacro markup in either is refused as
    data, never expanded)."""
    head = text.lstrip()
    while head.startswith(("<?", "<!--")):
        end = head.find("?>" if head.startswith("<?") else "-->")
        head = head[end + (2 if head.startswith("<?") else 3) :].lstrip() if end >= 0 else ""
    return "sdf" if head.startswith("<sdf") else "urdf"


def _tf(stamp, parent: str, child: str, pose: Pose) -> TransformStamped:
    """A TransformStamped of ``child`` in ``parent`` at ``pose`` (wxyz reordered into the message's x, y, z, w)."""
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = pose.position
    o = pose.orientation
    t.transform.rotation.w, t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z = o
    return t


class RobotStatePublisherNode(Node):
    """robot_state_publisher (see the module docstring)."""

    def __init__(self, **node_kwargs: Any) -> None:
        """``node_kwargs`` go to rclpy's Node (a context, parameter overrides: for a node made in-process)."""
        super().__init__("robot_state_publisher", **node_kwargs)
        self.declare_parameter("robot_description", "")
        self.declare_parameter("publish_frequency", 20.0)
        self.declare_parameter("frame_prefix", "")
        self.declare_parameter("ignore_timestamp", False)
        text = self.get_parameter("robot_description").value
        if not text:
            raise RuntimeError("robot_description parameter must not be empty")
        try:
            # URDF, or SDF: Jazzy's robot_state_publisher parses through urdf::Model's parser plugins, and the
            # sdformat_urdf plugin reads a one-model SDF (ros_gz_project_template gives it the model's SDF);
            # the format is told from the root element
            loaded = load_string(str(text), format=_format_of(str(text)), source="robot_description").value
        except ModelLoadError as err:
            raise RuntimeError(f"robot_description is not a URDF or SDF robot_state_publisher can use: {err}") from None
        if not isinstance(loaded, Model):
            raise RuntimeError("robot_description is not a robot (a URDF <robot> or an SDF <model>)")
        model = loaded
        prefix = str(self.get_parameter("frame_prefix").value)
        frequency = float(self.get_parameter("publish_frequency").value or 20.0)
        # robot_state_publisher.cpp: std::chrono::milliseconds(static_cast<uint64_t>(1000.0 / publish_freq))
        self._interval_ns = int(1000.0 / max(frequency, 1e-6)) * 1_000_000
        self._ignore_stamp = bool(self.get_parameter("ignore_timestamp").value)
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self._desc = self.create_publisher(String, "robot_description", latched)
        self._desc.publish(String(data=str(text)))
        self._static = self.create_publisher(TFMessage, "/tf_static", latched)
        self._tf = self.create_publisher(TFMessage, "/tf", 100)
        for link in model.links:
            self.get_logger().info(f"got segment {link.name}")
        statics: list[TransformStamped] = []
        self._moving: dict[str, tuple[Joint, str, str]] = {}
        now = self.get_clock().now().to_msg()
        for j in model.joints:
            if j.type is JointType.FLOATING:
                continue  # "Floating joint is not supported; skipping segment"
            if j.type in (JointType.FIXED, JointType.PLANAR):
                statics.append(_tf(now, prefix + j.parent, prefix + j.child, j.origin * j.child_offset))
            else:
                self._moving[j.name] = (j, prefix + j.parent, prefix + j.child)
        self._mimic = {j.name: j.mimic for j in model.joints if j.mimic is not None and j.name in self._moving}
        if statics:
            self._static.publish(TFMessage(transforms=statics))
        self._last_published: dict[str, int] = {}  # joint -> stamp (ns) of its last publication
        self._last_callback_ns = 0
        self.create_subscription(JointState, "joint_states", self._on_joint_states, 10)

    def _on_joint_states(self, msg: JointState) -> None:
        """robot_state_publisher's ``callbackJointState`` (3.3.3): an invalid message is refused with its log
        line; the message is published when due by its stamp (see the module docstring), every moving joint's
        transform at its position, mimic joints from their leaders, stamped with the message's stamp."""
        if len(msg.name) != len(msg.position):
            if not msg.position:
                self.get_logger().warning(
                    f'Robot state publisher ignored a JointState message about joint(s) "{next(iter(msg.name))}"(,...) '
                    "whose position member was empty."
                )
            else:
                self.get_logger().error("Robot state publisher ignored an invalid JointState message")
            return
        now = self.get_clock().now().nanoseconds
        if self._last_callback_ns > now:
            self.get_logger().warning("Moved backwards in time, re-publishing joint transforms!")
            self._last_published.clear()
        self._last_callback_ns = now
        # the least recently published of the message's joints (0 for one never published)
        last = min([now, *(self._last_published.get(n, 0) for n in msg.name)])
        stamp_ns = msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec
        if not self._ignore_stamp and stamp_ns < last + self._interval_ns:
            return
        positions = dict(zip(msg.name, msg.position))
        for name, mimic in self._mimic.items():
            if mimic.joint in positions and name not in positions:  # std::map::insert keeps a given value
                positions[name] = positions[mimic.joint] * mimic.multiplier + mimic.offset
        out = []
        for name, q in sorted(positions.items()):  # publishTransforms walks a std::map: by joint name
            entry = self._moving.get(name)
            if entry is None or not math.isfinite(q):
                continue
            joint, parent, child = entry
            out.append(_tf(msg.header.stamp, parent, child, joint_motion(joint, float(q))))
        if out:
            self._tf.publish(TFMessage(transforms=out))
        for name in msg.name:
            self._last_published[name] = stamp_ns


def main(argv: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; returns the exit status."""
    announce_often()
    rclpy.init(args=sys.argv if argv is None else argv)
    try:
        node = RobotStatePublisherNode()
    except RuntimeError as err:
        print(f"[ERROR] [robot_state_publisher]: {err}", file=sys.stderr)
        try_shutdown()
        return 1
    spin_until_interrupted(node)
    return 0


def spin_until_interrupted(node: Node, *others: Node) -> None:
    """Spin ``node`` (and ``others``, of its context) until Ctrl-C (or an external shutdown), then destroy them and
    shut rclpy down. The signal
    may come at any point, even before the executor exists: rclpy's signal thread has then shut the context
    down, and rclpy refuses to make the executor (an RCLError, the end that was asked for)."""
    executor: SingleThreadedExecutor | None = None
    try:
        executor = SingleThreadedExecutor(context=node.context)
        for each in (node, *others):
            executor.add_node(each)
        spin_until_shutdown(executor, node)
    except KeyboardInterrupt:
        await_signal_shutdown(node.context)
    except RCLError:
        if node.context.ok():
            raise
        silence_half_made_objects()  # the executor rclpy refused
    finally:
        if executor is not None:
            executor.shutdown()
        for each in (*others, node):
            each.destroy_node()
        try_shutdown()

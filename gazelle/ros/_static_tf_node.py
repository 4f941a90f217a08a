"""tf2_ros's ``static_transform_publisher`` (the real one is C++ and not on PyPI), as tf2_ros Jazzy's
``static_transform_broadcaster_program.cpp`` parses its command line and ``static_transform_broadcaster_node.cpp``
publishes:

* new style: ``--x --y --z`` (metres), ``--qx --qy --qz --qw`` or ``--roll --pitch --yaw`` (radians, not both),
  ``--frame-id`` and ``--child-frame-id`` (required); no rotation or translation is the identity;
* old style (deprecated, with its warning): 9 positional arguments ``x y z qx qy qz qw frame child`` or 8,
  ``x y z yaw pitch roll frame child``; mixing the two styles, extra arguments, an empty frame or a number that
  does not parse is refused with upstream's text and the usage, exit status 1;
* the node is ``static_transform_publisher_`` and 16 random characters (unless remapped, as MoveIt's
  launch files name it), its parameters ``translation.{x,y,z}``, ``rotation.{x,y,z,w}``, ``frame_id``,
  ``child_frame_id`` read-only; it publishes the transform once, stamped now, on ``/tf_static`` (latched: depth
  1, transient local, reliable, as tf2's StaticTransformBroadcaster) and spins until Ctrl-C; a frame equal to its
  child is an error and the process ends.

The quaternion is published as given (tf2 does not normalise it either); Euler angles become one as tf2's
``Quaternion::setRPY``.
"""

from __future__ import annotations

import random
import re
import string
import sys
from collections.abc import Sequence

import rclpy
from geometry_msgs.msg import TransformStamped
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.utilities import remove_ros_args, try_shutdown
from tf2_msgs.msg import TFMessage

from .._errors import SimError
from ..estimation import quaternion_from_rpy
from ._dds import announce_often
from ._rsp_node import spin_until_interrupted

USAGE = (
    "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] [--qw QW] "
    "[--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID --child-frame-id CHILD_FRAME_ID\n\n"
    "A command line utility for manually sending a static transform.\n\nIf no translation or orientation is "
    "provided, the identity transform will be published.\n\nThe translation offsets are in meters.\n\nThe rotation "
    "may be provided with roll, pitch, yaw euler angles in radians, or as a quaternion.\n\n"
    "required arguments:\n  --frame-id FRAME_ID parent frame\n  --child-frame-id CHILD_FRAME_ID child frame id\n\n"
    "optional arguments:\n  --x X                 x component of translation\n"
    "  --y Y                 y component of translation\n  --z Z                 z component of translation\n"
    "  --qx QX               x component of quaternion rotation\n"
    "  --qy QY               y component of quaternion rotation\n"
    "  --qz QZ               z component of quaternion rotation\n"
    "  --qw QW               w component of quaternion rotation\n"
    "  --roll ROLL           roll component Euler rotation\n  --pitch PITCH         pitch component Euler rotation\n"
    "  --yaw YAW             yaw component Euler rotation"
)

_NUMBER = re.compile(r"\s*[+-]?(?:nan|inf(?:inity)?|(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)", re.IGNORECASE)
"""What ``std::stod`` takes: a number at the start of the text (the rest is ignored, as stod ignores it)."""

_TRANSLATION = {"--x": 0, "--y": 1, "--z": 2}
_QUATERNION = {"--qx": 0, "--qy": 1, "--qz": 2, "--qw": 3}
_EULER = {"--roll": 0, "--pitch": 1, "--yaw": 2}


class ArgumentError(SimError, ValueError):
    """A command line static_transform_publisher refuses; the message is upstream's."""


def _stod(name: str, text: str) -> float:
    m = _NUMBER.match(text)
    if m is None:
        raise ArgumentError(f"Failed to parse {name} argument as float")
    return float(m.group(0))


def parse_args(args: Sequence[str]) -> tuple[list[float], list[float], str, str] | None:
    """(translation, quaternion x y z w, frame, child) of a command line (``args[0]`` is the program), as
    ``parse_args`` of static_transform_broadcaster_program.cpp; None for ``--help``.

    Raises:
        ArgumentError: with upstream's text.
    """
    trans, quat, rpy = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0]
    frames = ["", ""]
    saw = {"frame": False, "quat": False, "rpy": False, "trans": False}
    help_asked, loose = False, []
    i = 1
    while i < len(args):
        opt = args[i]
        if opt in ("--help", "-h"):
            help_asked = True
        elif opt in (*_TRANSLATION, *_QUATERNION, *_EULER, "--frame-id", "--child-frame-id"):
            if i == len(args) - 1:
                raise ArgumentError(f"Not enough arguments for {opt}")
            i += 1
            if opt in ("--frame-id", "--child-frame-id"):
                frames[opt == "--child-frame-id"] = args[i]
                saw["frame"] = True
            elif opt in _TRANSLATION:
                trans[_TRANSLATION[opt]], saw["trans"] = _stod(opt, args[i]), True
            elif opt in _QUATERNION:
                quat[_QUATERNION[opt]], saw["quat"] = _stod(opt, args[i]), True
            else:
                rpy[_EULER[opt]], saw["rpy"] = _stod(opt, args[i]), True
        else:
            loose.append(opt)
        i += 1
    if help_asked:
        return None
    if saw["rpy"] and saw["quat"]:
        raise ArgumentError("Cannot specify both quaternion and Euler rotations")
    if saw["rpy"]:
        quat = list(quaternion_from_rpy(*rpy))
    if len(loose) in (8, 9):
        print("[WARN] Old-style arguments are deprecated; see --help for new-style arguments", file=sys.stderr)
        if saw["frame"] or saw["trans"] or saw["quat"]:
            raise ArgumentError("Cannot specify both new-style (flags) and old-style (arguments)")
        trans = [_stod(n, v) for n, v in zip(("x", "y", "z"), loose[:3], strict=True)]
        if len(loose) == 8:
            yaw, pitch, roll = (_stod(n, v) for n, v in zip(("yaw", "pitch", "roll"), loose[3:6], strict=True))
            quat = list(quaternion_from_rpy(roll, pitch, yaw))
        else:
            quat = [_stod(n, v) for n, v in zip(("qx", "qy", "qz", "qw"), loose[3:7], strict=True)]
        frames = loose[-2:]
    elif loose:
        raise ArgumentError("Extra unparsed arguments on command-line")
    if not frames[0]:
        raise ArgumentError("Frame id must not be empty")
    if not frames[1]:
        raise ArgumentError("Child frame id must not be empty")
    return trans, quat, frames[0], frames[1]


class StaticTransformPublisher(Node):
    """The node (see the module docstring): its read-only parameters, and the transform sent once, latched."""

    def __init__(self, trans: list[float], quat: list[float], frame: str, child: str) -> None:
        suffix = "".join(random.choice(string.digits + string.ascii_letters) for _ in range(16))
        super().__init__(f"static_transform_publisher_{suffix}")
        ro = ParameterDescriptor(read_only=True)
        values = {
            "translation.x": trans[0],
            "translation.y": trans[1],
            "translation.z": trans[2],
            "rotation.x": quat[0],
            "rotation.y": quat[1],
            "rotation.z": quat[2],
            "rotation.w": quat[3],
            "frame_id": frame,
            "child_frame_id": child,
        }
        for name, value in values.items():
            self.declare_parameter(name, value, ro)
        if frame == child:
            self.get_logger().error(f"cannot publish static transform from '{frame}' to '{child}', exiting")
            raise RuntimeError("child_frame_id cannot equal frame_id")
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self._pub = self.create_publisher(TFMessage, "/tf_static", latched)
        tf = TransformStamped()
        tf.header.stamp = self.get_clock().now().to_msg()
        tf.header.frame_id, tf.child_frame_id = frame, child
        t, r = tf.transform.translation, tf.transform.rotation
        t.x, t.y, t.z = trans
        r.x, r.y, r.z, r.w = quat
        self._pub.publish(TFMessage(transforms=[tf]))
        self.get_logger().info(
            "Spinning until stopped - publishing transform\n"
            f"translation: ('{trans[0]:f}', '{trans[1]:f}', '{trans[2]:f}')\n"
            f"rotation: ('{quat[0]:f}', '{quat[1]:f}', '{quat[2]:f}', '{quat[3]:f}')\nfrom '{frame}' to '{child}'"
        )


def main(argv: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; returns the exit status (1 for a command line it refuses)."""
    args = sys.argv if argv is None else argv
    try:
        parsed = parse_args(remove_ros_args(args))
    except ArgumentError as err:
        print(f"[ERROR] error parsing command line arguments: {err}", file=sys.stderr)
        print(USAGE)
        return 1
    if parsed is None:
        print(USAGE)
        return 0
    announce_often()
    rclpy.init(args=args)
    try:
        node = StaticTransformPublisher(*parsed)
    except RuntimeError:
        try_shutdown()
        return 1
    spin_until_interrupted(node)
    return 0

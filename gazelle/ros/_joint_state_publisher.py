"""joint_state_publisher as a ROS node (the real one is not on PyPI): ``ros2 run joint_state_publisher
joint_state_publisher [description_file]``.

What it does is joint_state_publisher's (ROS 2, ``joint_state_publisher/joint_state_publisher.py``, read
from its source; only the behaviour is matched):

* the robot comes from the ``description_file`` argument, else the latched ``robot_description`` topic
  (read again whenever a new description is published there); gazelle also takes a ``robot_description``
  parameter, which joint_state_publisher does not read, so a launch file that passes it the robot works
  here as it would with robot_state_publisher beside it. The text is data: URDF or SDF, never
  xacro-expanded;
* its joints, in the file's order, are every joint but fixed, floating and planar (URDF), or but fixed,
  ball, universal, screw, gearbox and revolute2 (SDF); a continuous joint ranges over [-pi, pi], another
  needs both limits (a joint without is named in a warning and the robot is not used, as upstream
  refuses it);
* with ``use_smallest_joint_limits`` (true) a written ``<safety_controller>`` soft limit narrows the range;
* each free joint starts at its ``zeros.<joint>`` parameter, else 0, else the middle of its range when 0
  is outside it; ``publish_default_positions`` (true), ``_velocities`` and ``_efforts`` (false) say which
  arrays the message has;
* a mimic joint (``use_mimic_tags``, true) or one of ``dependent_joints.<joint>.parent|factor|offset``
  follows its leader through any chain (position ``factor * leader + offset``, velocity scaled, effort
  copied); a cycle is an error naming the chain;
* ``source_list``: JointState topics whose positions, velocities and efforts of free joints are taken
  as they arrive;
* ``delta`` > 0 moves every free joint by that much each tick, back and forth between its limits
  (a continuous joint wraps round);
* at ``rate`` (10 Hz, on the node's clock) it publishes ``joint_states`` stamped now, unless empty.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rclpy.node import Node

from .._errors import SimError
from ..description import JointType, Model, ModelLoadError, load_string

if TYPE_CHECKING:
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String

URDF_SKIPPED = frozenset({JointType.FIXED, JointType.FLOATING, JointType.PLANAR})
"""URDF joint types that are never in the message (``init_urdf``)."""
SDF_SKIPPED = frozenset({JointType.FIXED, JointType.BALL, JointType.UNIVERSAL, JointType.SCREW})
"""SDF joint types that are never in the message (``init_sdf``: also gearbox and revolute2, which gazelle's
description has no type for and so never reach here)."""


class DescriptionError(SimError, ValueError):
    """A description joint_state_publisher cannot use; the message names the joint (upstream's wording)."""


@dataclass
class FreeJoint:
    """A joint the node moves: its range (rad or m) and the values it publishes."""

    lower: float
    upper: float
    position: float | None
    velocity: float | None
    effort: float | None
    continuous: bool = False
    forward: bool = True
    """The direction ``delta`` moves it in now."""


@dataclass
class Follower:
    """A joint that follows ``leader`` (a mimic tag, or ``dependent_joints``)."""

    leader: str
    factor: float = 1.0
    offset: float = 0.0


@dataclass
class Robot:
    """The joints of one description, as the node publishes them."""

    order: list[str] = field(default_factory=list)
    """Every published joint in the description's order (free and following ones)."""
    free: dict[str, FreeJoint] = field(default_factory=dict)
    following: dict[str, Follower] = field(default_factory=dict)


def read_robot(
    text: str,
    *,
    zeros: dict[str, float],
    dependent: dict[str, Follower],
    use_mimic: bool = True,
    use_smallest_limits: bool = True,
    defaults: tuple[bool, bool, bool] = (True, False, False),
) -> Robot:
    """The joints of the URDF or SDF ``text`` (see the module docstring); ``defaults`` says whether positions,
    velocities and efforts are published before a source sends any.

    Raises:
        DescriptionError: text that is not a robot, or a limited joint without both limits.
    """
    try:
        loaded = load_string(text, source="robot_description").value  # URDF or SDF, by its root
    except ModelLoadError as err:
        raise DescriptionError(f"robot_description cannot be read: {err}") from None
    if not isinstance(loaded, Model):
        raise DescriptionError("robot_description must describe one robot (a URDF <robot> or an SDF <model>)")
    skipped = URDF_SKIPPED if loaded.urdf else SDF_SKIPPED
    robot = Robot(following=dict(dependent))
    for joint in loaded.joints:
        if joint.type in skipped:
            continue
        name = joint.name
        if joint.type is JointType.CONTINUOUS:
            lower, upper = -math.pi, math.pi
        else:
            limit = joint.axis.limit if joint.axis is not None else None
            if limit is None or limit.lower is None or limit.upper is None:
                raise DescriptionError(f'Limits must be specified for joint "{name}" of type "{joint.type.value}"')
            lower, upper = limit.lower, limit.upper
        safety = joint.safety_controller
        if use_smallest_limits and safety is not None:
            if safety.soft_lower_limit is not None:
                lower = max(lower, safety.soft_lower_limit)
            if safety.soft_upper_limit is not None:
                upper = min(upper, safety.soft_upper_limit)
        robot.order.append(name)
        if use_mimic and joint.mimic is not None:
            robot.following[name] = Follower(joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset)
            continue
        if name in robot.following:
            continue
        start = zeros[name] if name in zeros else (lower + upper) / 2 if lower > 0 or upper < 0 else 0.0
        positions, velocities, efforts = defaults
        robot.free[name] = FreeJoint(
            lower,
            upper,
            start if positions else None,
            0.0 if velocities else None,
            0.0 if efforts else None,
            continuous=joint.type is JointType.CONTINUOUS,
        )
    return robot


def resolve(robot: Robot, name: str) -> tuple[str, float, float]:
    """(free joint, factor, offset) a following joint's values come from, through a chain of followers.

    Raises:
        DescriptionError: a chain that comes back to itself, or ends at a joint that is not free.
    """
    chain = [name]
    follower = robot.following[name]
    factor, offset, leader = follower.factor, follower.offset, follower.leader
    while leader in robot.following:
        if leader in chain:
            raise DescriptionError(f"Found an infinite recursive mimic chain: {chain + [leader]}")
        chain.append(leader)
        step = robot.following[leader]
        offset += factor * step.offset
        factor *= step.factor
        leader = step.leader
    if leader not in robot.free:
        raise DescriptionError(f"joint '{name}' follows '{leader}', which is not a moving joint of the robot")
    return leader, factor, offset


def state_arrays(robot: Robot) -> tuple[list[str], list[float], list[float], list[float]]:
    """(names, positions, velocities, efforts) of one message: an array is empty when no joint has values
    for it (positions are there whenever a joint follows another, as upstream sizes them)."""
    free = robot.free.values()
    has = (
        bool(robot.following) or any(j.position is not None for j in free),
        any(j.velocity is not None for j in free),
        any(j.effort is not None for j in free),
    )
    arrays: tuple[list[float], list[float], list[float]] = ([], [], [])
    names = []
    for name in robot.order:
        if name in robot.free:
            joint, factor, offset = robot.free[name], 1.0, 0.0
        elif name in robot.following:
            leader, factor, offset = resolve(robot, name)
            joint = robot.free[leader]
        else:
            continue
        names.append(name)
        values = (
            joint.position * factor + offset if joint.position is not None else 0.0,
            joint.velocity * factor if joint.velocity is not None else 0.0,
            joint.effort if joint.effort is not None else 0.0,
        )
        for wanted, out, value in zip(has, arrays, values):
            if wanted:
                out.append(float(value))
    return names, *arrays


def step(robot: Robot, delta: float) -> None:
    """Move every free joint by ``delta`` in its direction, turning at a limit (a continuous joint wraps from
    its upper limit to its lower one)."""
    for joint in robot.free.values():
        position = joint.position if joint.position is not None else 0.0
        if joint.forward:
            position += delta
            if position > joint.upper:
                if joint.continuous:
                    position = joint.lower
                else:
                    position, joint.forward = joint.upper, False
        else:
            position -= delta
            if position < joint.lower:
                position, joint.forward = joint.lower, True
        joint.position = position


class JointStatePublisherNode(Node):
    """joint_state_publisher (see the module docstring)."""

    def __init__(self, description_file: str | None = None, **node_kwargs: Any) -> None:
        """``description_file``: the robot's file (the command's argument); ``node_kwargs`` go to rclpy's Node."""
        from rcl_interfaces.msg import ParameterDescriptor, ParameterType
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        from sensor_msgs.msg import JointState
        from std_msgs.msg import String

        super().__init__("joint_state_publisher", automatically_declare_parameters_from_overrides=True, **node_kwargs)
        kinds = {bool: ParameterType.PARAMETER_BOOL, int: ParameterType.PARAMETER_INTEGER}
        for name, default in (
            ("publish_default_efforts", False),
            ("publish_default_positions", True),
            ("publish_default_velocities", False),
            ("rate", 10),
            ("use_mimic_tags", True),
            ("use_smallest_joint_limits", True),
        ):
            if not self.has_parameter(name):
                self.declare_parameter(name, default, ParameterDescriptor(type=kinds[type(default)]))
        for name, default, kind in (
            ("source_list", [], ParameterType.PARAMETER_STRING_ARRAY),
            ("delta", 0.0, ParameterType.PARAMETER_DOUBLE),
            ("robot_description", "", ParameterType.PARAMETER_STRING),
        ):
            if not self.has_parameter(name):
                self.declare_parameter(name, default, ParameterDescriptor(type=kind))
        self._JointState = JointState
        self._zeros = {k: float(v) for k, v in self._by_prefix("zeros").items()}
        self._dependent = self._dependent_joints()
        self._robot = Robot()
        self._delta = float(self.get_parameter("delta").value or 0.0)
        text = ""
        if description_file is not None:
            with open(description_file, encoding="utf-8") as f:  # the user's own command-line argument
                text = f.read()
        text = text or str(self.get_parameter("robot_description").value or "")
        if text:
            self._configure(text)
        else:
            self.get_logger().info("Waiting for robot_description to be published on the robot_description topic...")
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self.create_subscription(String, "robot_description", self._on_description, latched)
        for topic in self.get_parameter("source_list").value or []:
            self.create_subscription(JointState, str(topic), self._on_source, 10)
        self._pub = self.create_publisher(JointState, "joint_states", 10)
        rate = float(self.get_parameter("rate").value or 10)
        self.create_timer(1.0 / max(rate, 1e-3), self._tick)

    def _by_prefix(self, prefix: str) -> dict[str, Any]:
        """The values of the parameters ``<prefix>.<key>``, by key (maps arrive flattened: rclpy has none)."""
        return {key: self.get_parameter(f"{prefix}.{key}").value for key in self.get_parameters_by_prefix(prefix)}

    def _dependent_joints(self) -> dict[str, Follower]:
        """``dependent_joints.<joint>.parent|factor|offset`` parameters (a ``parent`` is required).

        Raises:
            DescriptionError: another key, or a joint without ``parent``.
        """
        found: dict[str, dict[str, Any]] = {}
        for key, value in self._by_prefix("dependent_joints").items():
            joint, _, what = key.partition(".")
            if what not in ("parent", "factor", "offset") or "." in what:
                raise DescriptionError(
                    f"Invalid dependent_joint name '{key}' (allowed values are 'parent', 'factor', 'offset')"
                )
            found.setdefault(joint, {})[what] = value
        out = {}
        for joint, values in found.items():
            if values.get("parent") is None:
                raise DescriptionError("All dependent_joints must at least have a parent")
            out[joint] = Follower(
                str(values["parent"]), float(values.get("factor", 1.0)), float(values.get("offset", 0.0))
            )
        return out

    def _on_description(self, msg: String) -> None:
        """A description published on ``robot_description`` (latched): the robot from now on."""
        self._configure(str(msg.data))

    def _configure(self, text: str) -> None:
        """Take a (new) description; one it cannot use is a warning, and the previous robot stays."""
        try:
            robot = read_robot(
                text,
                zeros=self._zeros,
                dependent=self._dependent,
                use_mimic=bool(self.get_parameter("use_mimic_tags").value),
                use_smallest_limits=bool(self.get_parameter("use_smallest_joint_limits").value),
                defaults=(
                    bool(self.get_parameter("publish_default_positions").value),
                    bool(self.get_parameter("publish_default_velocities").value),
                    bool(self.get_parameter("publish_default_efforts").value),
                ),
            )
            for name in robot.following:
                if name in robot.order:
                    resolve(robot, name)
        except DescriptionError as err:
            self.get_logger().warning(str(err))
            return
        self._robot = robot

    def _on_source(self, msg: JointState) -> None:
        """A source's values for the free joints it names (an array it leaves empty changes nothing)."""
        for i, name in enumerate(msg.name):
            joint = self._robot.free.get(name)
            if joint is None:
                continue
            if len(msg.position) > i:
                joint.position = float(msg.position[i])
            if len(msg.velocity) > i:
                joint.velocity = float(msg.velocity[i])
            if len(msg.effort) > i:
                joint.effort = float(msg.effort[i])

    def _tick(self) -> None:
        """Publish one message (see :func:`state_arrays`), after moving the joints by ``delta``."""
        if self._delta > 0:
            step(self._robot, self._delta)
        names, positions, velocities, efforts = state_arrays(self._robot)
        if not (names or positions or velocities or efforts):
            return
        msg = self._JointState(name=names, position=positions, velocity=velocities, effort=efforts)
        msg.header.stamp = self.get_clock().now().to_msg()
        self._pub.publish(msg)


def main(argv: list[str] | None = None) -> int:
    """``joint_state_publisher [description_file] [--ros-args ...]`` until Ctrl-C."""
    import argparse

    import rclpy
    from rclpy.utilities import remove_ros_args, try_shutdown

    from ._dds import announce_often
    from ._rsp_node import spin_until_interrupted

    args = sys.argv if argv is None else argv
    parser = argparse.ArgumentParser(prog="joint_state_publisher")
    parser.add_argument("description_file", nargs="?", default=None, help="Robot description file to use")
    parsed = parser.parse_args(remove_ros_args(args=args)[1:])
    announce_often()
    rclpy.init(args=args)
    try:
        node = JointStatePublisherNode(parsed.description_file)
    except (DescriptionError, OSError) as err:
        print(f"[ERROR] [joint_state_publisher]: {err}", file=sys.stderr)
        try_shutdown()
        return 1
    spin_until_interrupted(node)
    return 0

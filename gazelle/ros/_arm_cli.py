"""``gazelle arm``: move an arm from the command line through a running move_group.

    gazelle arm GROUP x y z roll pitch yaw [--frame F] [--link L]   a pose of the group's tip
    gazelle arm GROUP --named NAME                                   an SRDF group_state
    gazelle arm GROUP --joints V1 V2 ... | --joints J1=V1 J2=V2 ...  joint values

It is a MoveIt client like any other: it reads ``robot_description_semantic`` (and for bare
``--joints`` values ``robot_description``) from the ``move_group`` node's parameters, and sends one
MoveGroup action goal. Exit status 0 when the arm got there; 1 with MoveIt's error code and message
(or a bad group, state or joint name, with the names there are) otherwise.
"""

from __future__ import annotations

import argparse
import sys
import time
from typing import TYPE_CHECKING

from .._errors import SimError
from ..description import ModelLoadError, Semantics, load_string
from ..estimation import quaternion_from_rpy

if TYPE_CHECKING:
    from moveit_msgs.msg import Constraints
    from rclpy.client import Client
    from rclpy.node import Node

    from ..description import Group

TOLERANCE_M = 1e-4
TOLERANCE_RAD = 1e-3
"""MoveGroupCommander's default goal tolerances."""


class ArmError(SimError):
    """A request this command refuses before anything moves."""


def semantics(srdf: str) -> Semantics:
    """The SRDF move_group serves (its ``robot_description_semantic``), read as gazelle reads any SRDF; one that
    cannot be read is an ArmError with the loader's summary."""
    try:
        value = load_string(srdf, format="srdf", source="robot_description_semantic").value
    except ModelLoadError as err:
        raise ArmError(f"move_group's SRDF could not be read: {err.summary()}") from None
    if not isinstance(value, Semantics):
        raise ArmError("move_group's robot_description_semantic is not an SRDF")
    return value


def group_joints(sem: Semantics, urdf: str, group: str) -> list[str]:
    """The movable joints of an SRDF group, in chain order (chains are walked in the URDF)."""
    from lxml import etree

    g = _group(sem, group)
    joints: list[str] = list(g.joints)
    if g.chains:
        root = etree.fromstring(urdf.encode())
        # the robot's joints (not the <joint>s of <ros2_control> or <transmission>): child link -> (name,
        # type, parent link)
        by_child: dict[str, tuple[str, str, str]] = {}
        for j in root.findall("joint"):
            child, parent = j.find("child"), j.find("parent")
            child_link = child.get("link") if child is not None else None
            parent_link = parent.get("link") if parent is not None else None
            if child_link and parent_link:
                by_child[child_link] = (j.get("name") or "", j.get("type") or "", parent_link)
        for chain in g.chains:
            walk: list[str] = []
            link = chain.tip_link
            while link != chain.base_link and link in by_child:
                joint_name, joint_type, parent_link = by_child[link]
                if joint_type not in ("fixed", "floating", "planar") and joint_name:
                    walk.append(joint_name)
                link = parent_link
            joints += reversed(walk)
    for sub in g.subgroups:
        joints += group_joints(sem, urdf, sub)
    return list(dict.fromkeys(joints))


def _group(sem: Semantics, name: str) -> Group:
    """The SRDF's planning group ``name``; an ArmError listing the groups when there is none."""
    for g in sem.groups:
        if g.name == name:
            return g
    raise ArmError(f"no planning group '{name}' (the SRDF has: {', '.join(g.name for g in sem.groups) or 'none'})")


def tip_link(sem: Semantics, group: str) -> str:
    """The link a pose goal moves for ``group``, as MoveIt picks it: its last chain's tip, else its last subgroup's
    tip, else its last link ("" when it has none)."""
    g = _group(sem, group)
    if g.chains:
        return g.chains[-1].tip_link
    if g.subgroups:
        return tip_link(sem, g.subgroups[-1])
    if g.links:
        return g.links[-1]
    return ""


def named_state(sem: Semantics, group: str, name: str) -> dict[str, float]:
    """The joint values of the group's SRDF ``group_state`` ``name`` (MoveIt's set_named_target); an ArmError
    listing the group's states when there is none."""
    _group(sem, group)
    for state in sem.group_states:
        if state.group == group and state.name == name:
            return {joint: values[0] for joint, values in state.joint_values if values}
    known = sorted(s.name for s in sem.group_states if s.group == group)
    raise ArmError(f"group '{group}' has no named state '{name}' (it has: {', '.join(known) or 'none'})")


def joint_values(sem: Semantics, urdf: str, group: str, items: list[str]) -> dict[str, float]:
    """``--joints`` as NAME=VALUE pairs or as values in the group's joint order."""
    try:
        if all("=" in item for item in items):
            return {k: float(v) for k, v in (item.split("=", 1) for item in items)}
        values = [float(v) for v in items]
    except ValueError:
        raise ArmError(f"--joints takes numbers or NAME=VALUE pairs, not {' '.join(items)}") from None
    names = group_joints(sem, urdf, group)
    if len(values) != len(names):
        raise ArmError(f"group '{group}' has {len(names)} joints ({', '.join(names)}); --joints gave {len(values)}")
    return dict(zip(names, values))


def arm_main(argv: list[str]) -> int:
    """``gazelle arm GROUP (x y z roll pitch yaw | --named NAME | --joints ...)``: plan (and, unless
    ``--plan-only``, execute) one motion through move_group's MoveGroup action, as a MoveIt client would; an
    error is one line on stderr and exit code 1, never a traceback."""
    parser = argparse.ArgumentParser(
        prog="gazelle arm", description="Move an arm through move_group: a pose, a named state or joint values."
    )
    parser.add_argument("group")
    parser.add_argument("pose", nargs="*", type=float, help="x y z roll pitch yaw (m, rad)")
    parser.add_argument("--frame", default="", help="the pose's frame (default: the planning frame)")
    parser.add_argument("--link", default="", help="the link to move (default: the group's tip)")
    parser.add_argument("--named", help="an SRDF group_state of the group")
    parser.add_argument("--joints", nargs="+", help="values in the group's joint order, or NAME=VALUE pairs")
    parser.add_argument("--velocity", type=float, default=0.5, help="velocity and acceleration scaling (0, 1]")
    parser.add_argument("--plan-only", action="store_true")
    parser.add_argument("--timeout", type=float, default=30.0, help="s to wait for move_group")
    ros_args = argv[argv.index("--ros-args") :] if "--ros-args" in argv else []
    args = parser.parse_args(argv[: len(argv) - len(ros_args)] if ros_args else argv)
    wanted = sum((bool(args.pose), bool(args.named), bool(args.joints)))
    if wanted != 1 or (args.pose and len(args.pose) != 6):
        parser.error("give one of: x y z roll pitch yaw | --named NAME | --joints ...")

    import rclpy
    from rclpy.utilities import try_shutdown

    rclpy.init(args=["gazelle_arm", *ros_args])
    node = rclpy.create_node("gazelle_arm")
    try:
        return _run(node, args)
    except ArmError as err:
        print(f"gazelle arm: {err}", file=sys.stderr)
        return 1
    except Exception as err:  # said in one line, never a traceback
        print(f"gazelle arm: {type(err).__name__}: {err}", file=sys.stderr)
        return 1
    finally:
        node.destroy_node()
        try_shutdown()


def _served(client: Client, timeout: float) -> bool:
    """Whether ``client``'s service is found within ``timeout`` s, looked for every 10 ms (rclpy's
    ``wait_for_service`` looks every 0.25 s, a quarter of a second added to most answers)."""
    deadline = time.monotonic() + timeout
    while not client.service_is_ready():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)
    return True


def _parameters(node: Node, names: list[str], timeout: float) -> list[str]:
    """move_group's parameters ``names`` as strings (its URDF and SRDF); an ArmError when no move_group answers
    within ``timeout`` or it has no robot yet."""
    import rclpy
    from rcl_interfaces.srv import GetParameters

    client = node.create_client(GetParameters, "/move_group/get_parameters")
    if not _served(client, timeout):
        raise ArmError(f"no move_group is running (/move_group/get_parameters did not answer in {timeout:g} s)")
    future = client.call_async(GetParameters.Request(names=names))
    rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
    reply = future.result() if future.done() else None
    if reply is None:
        raise ArmError("move_group did not say its parameters")
    values = [v.string_value for v in reply.values]
    if len(values) != len(names):  # a move_group with no robot yet leaves them out
        raise ArmError(
            f"move_group has no robot yet (its parameters {', '.join(names)} are not set): give it the robot's "
            "URDF and SRDF (--urdf/--srdf, or robot_description and robot_description_semantic)"
        )
    return values


def _joint_goal(values: dict[str, float]) -> Constraints:
    """moveit_msgs/Constraints: each joint at its value, within TOLERANCE_RAD."""
    from moveit_msgs.msg import Constraints, JointConstraint

    constraints = Constraints()
    constraints.joint_constraints = [
        JointConstraint(
            joint_name=n, position=float(v), tolerance_above=TOLERANCE_RAD, tolerance_below=TOLERANCE_RAD, weight=1.0
        )
        for n, v in values.items()
    ]
    return constraints


def _pose_goal(link: str, frame: str, pose: tuple[float, float, float, float, float, float]) -> Constraints:
    """moveit_msgs/Constraints: ``link`` within TOLERANCE_M of (x, y, z) and TOLERANCE_RAD of (roll, pitch,
    yaw) in ``frame`` (a sphere region, absolute axis tolerances)."""
    from geometry_msgs.msg import Pose
    from moveit_msgs.msg import Constraints, OrientationConstraint, PositionConstraint
    from shape_msgs.msg import SolidPrimitive

    x, y, z, roll, pitch, yaw = pose
    position = PositionConstraint(link_name=link, weight=1.0)
    position.header.frame_id = frame
    position.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[TOLERANCE_M])]
    target = Pose()
    target.position.x, target.position.y, target.position.z = x, y, z
    target.orientation.w = 1.0
    position.constraint_region.primitive_poses = [target]
    orientation = OrientationConstraint(link_name=link, weight=1.0)
    orientation.header.frame_id = frame
    q = quaternion_from_rpy(roll, pitch, yaw)
    orientation.orientation.x, orientation.orientation.y, orientation.orientation.z, orientation.orientation.w = q
    orientation.absolute_x_axis_tolerance = TOLERANCE_RAD
    orientation.absolute_y_axis_tolerance = TOLERANCE_RAD
    orientation.absolute_z_axis_tolerance = TOLERANCE_RAD
    constraints = Constraints()
    constraints.position_constraints = [position]
    constraints.orientation_constraints = [orientation]
    return constraints


def _run(node: Node, args: argparse.Namespace) -> int:
    """Build the MoveGroup goal (joint constraints for a named state or joint values, position and orientation
    constraints for a pose), send it, and print the plan's duration and planning time, or MoveIt's error code and
    message."""
    import rclpy
    from moveit_msgs.action import MoveGroup
    from moveit_msgs.msg import MoveItErrorCodes
    from rclpy.action.client import ActionClient

    srdf, urdf = _parameters(node, ["robot_description_semantic", "robot_description"], args.timeout)
    if not srdf:
        raise ArmError("move_group has no robot_description_semantic parameter")
    sem = semantics(srdf)
    if args.named or args.joints:
        values = (
            named_state(sem, args.group, args.named) if args.named else joint_values(sem, urdf, args.group, args.joints)
        )
        constraints = _joint_goal(values)
    else:
        constraints = _pose_goal(args.link or tip_link(sem, args.group), args.frame, tuple(args.pose))
    goal = MoveGroup.Goal()
    goal.request.group_name = args.group
    goal.request.allowed_planning_time = 5.0
    goal.request.max_velocity_scaling_factor = args.velocity
    goal.request.max_acceleration_scaling_factor = args.velocity
    goal.request.goal_constraints = [constraints]
    goal.planning_options.plan_only = args.plan_only
    client = ActionClient(node, MoveGroup, "/move_action")
    if not client.wait_for_server(timeout_sec=args.timeout):
        raise ArmError(f"no move_group is running (/move_action did not answer in {args.timeout:g} s)")
    future = client.send_goal_async(goal)
    rclpy.spin_until_future_complete(node, future)
    handle = future.result()
    if handle is None or not handle.accepted:
        raise ArmError("move_group rejected the goal")
    result_future = handle.get_result_async()
    rclpy.spin_until_future_complete(node, result_future)
    result = result_future.result().result
    code = result.error_code
    if code.val != MoveItErrorCodes.SUCCESS:
        names = {
            v: k for k in dir(MoveItErrorCodes) if k.isupper() and isinstance(v := getattr(MoveItErrorCodes, k), int)
        }
        print(f"gazelle arm: {names.get(code.val, code.val)}: {code.message}", file=sys.stderr)
        return 1
    points = result.planned_trajectory.joint_trajectory.points
    duration = points[-1].time_from_start.sec + points[-1].time_from_start.nanosec * 1e-9 if points else 0.0
    verb = "planned" if args.plan_only else "moved"
    print(f"{args.group}: {verb} in {duration:.2f} s (planning {result.planning_time * 1e3:.0f} ms)")
    return 0

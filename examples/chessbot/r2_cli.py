#!/usr/bin/env python3
"""The seed's r2_cli.py for ROS 2: move one arm of the chess robot to a pose, as MoveIt plans it.

    r2_cli.py ARM x y z phi theta psi        (ARM: left or right; metres and radians, in ``world``)

The seed called MoveGroupCommander's ``set_pose_target`` and ``go``. moveit_commander is ROS 1;
this sends what ``go`` sends: a MoveGroup action goal with the pose as position and orientation
constraints at the group's tolerances (0.1 mm, 0.001 rad). A plain rclpy program that uses moveit_msgs
only (never gazelle), so it runs against MoveIt's move_group and gazelle's alike. Exits 0 when the
arm got there, 1 with MoveIt's error code and message otherwise.
"""

import math
import sys

import rclpy
from geometry_msgs.msg import Pose, Quaternion
from moveit_msgs.action import MoveGroup
from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint, PositionConstraint
from rclpy.action import ActionClient
from shape_msgs.msg import SolidPrimitive

GROUPS = {"left": "left_panda_arm", "right": "right_panda_arm"}
"""The arms' planning groups in dual_arm_panda_moveit_config's SRDF (the seed's were left_arm, right_arm)."""
TIPS = {"left": "left_panda_link8", "right": "right_panda_link8"}
FRAME = "world"


def quaternion_from_euler(phi: float, theta: float, psi: float) -> Quaternion:
    """tf's quaternion_from_euler(roll, pitch, yaw) (static x, y, z axes)."""
    cr, sr = math.cos(phi / 2), math.sin(phi / 2)
    cp, sp = math.cos(theta / 2), math.sin(theta / 2)
    cy, sy = math.cos(psi / 2), math.sin(psi / 2)
    return Quaternion(
        x=sr * cp * cy - cr * sp * sy,
        y=cr * sp * cy + sr * cp * sy,
        z=cr * cp * sy - sr * sp * cy,
        w=cr * cp * cy + sr * sp * sy,
    )


def pose_goal(arm: str, x: float, y: float, z: float, phi: float, theta: float, psi: float) -> MoveGroup.Goal:
    goal = MoveGroup.Goal()
    req = goal.request
    req.group_name = GROUPS[arm]
    req.num_planning_attempts = 1
    req.allowed_planning_time = 5.0
    req.max_velocity_scaling_factor = 1.0  # the joint limits' full speed
    req.max_acceleration_scaling_factor = 1.0
    position = PositionConstraint(link_name=TIPS[arm], weight=1.0)
    position.header.frame_id = FRAME
    position.constraint_region.primitives.append(SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[1e-4]))
    target = Pose()
    target.position.x, target.position.y, target.position.z = x, y, z
    target.orientation.w = 1.0
    position.constraint_region.primitive_poses.append(target)
    orientation = OrientationConstraint(link_name=TIPS[arm], weight=1.0)
    orientation.header.frame_id = FRAME
    orientation.orientation = quaternion_from_euler(phi, theta, psi)
    orientation.absolute_x_axis_tolerance = 1e-3
    orientation.absolute_y_axis_tolerance = 1e-3
    orientation.absolute_z_axis_tolerance = 1e-3
    req.goal_constraints.append(Constraints(position_constraints=[position], orientation_constraints=[orientation]))
    return goal


def main(argv: list[str]) -> int:
    if len(argv) != 8:
        print("usage: r2_cli.py arm x y z phi theta psi", file=sys.stderr)
        return 1
    arm = argv[1]
    if arm not in GROUPS:
        print(f"unknown arm: '{arm}' (left or right)", file=sys.stderr)
        return 1
    rclpy.init()
    node = rclpy.create_node("r2_cli")
    client = ActionClient(node, MoveGroup, "move_action")
    try:
        if not client.wait_for_server(timeout_sec=30.0):
            print("no move_group (/move_action) is running", file=sys.stderr)
            return 1
        future = client.send_goal_async(pose_goal(arm, *[float(v) for v in argv[2:]]))
        rclpy.spin_until_future_complete(node, future)
        handle = future.result()
        if not handle.accepted:
            print("move_group rejected the goal", file=sys.stderr)
            return 1
        result_future = handle.get_result_async()
        rclpy.spin_until_future_complete(node, result_future)
        code = result_future.result().result.error_code
        if code.val != MoveItErrorCodes.SUCCESS:
            print(f"{arm} arm: error {code.val}: {code.message}", file=sys.stderr)
            return 1
        return 0
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    sys.exit(main(sys.argv))

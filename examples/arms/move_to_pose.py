#!/usr/bin/env python3
"""Move an arm's end effector to a pose through MoveIt's MoveGroup action, as MoveIt's tutorials do.

A plain rclpy program: it uses moveit_msgs only (never gazelle), so it runs unchanged against
MoveIt's move_group or gazelle's.

    move_to_pose.py GROUP LINK FRAME x y z [qx qy qz qw] [--plan-only]

With a quaternion the goal is a pose (position within 1 mm, orientation within 0.01 rad); without
one, a position. Prints the MoveItErrorCodes value and message; exits 0 on SUCCESS.
"""

import sys

import rclpy
from geometry_msgs.msg import Pose
from moveit_msgs.action import MoveGroup
from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint, PositionConstraint
from rclpy.action import ActionClient
from shape_msgs.msg import SolidPrimitive


def pose_goal(group, link, frame, xyz, quat):
    goal = MoveGroup.Goal()
    req = goal.request
    req.group_name = group
    req.num_planning_attempts = 1
    req.allowed_planning_time = 5.0
    req.max_velocity_scaling_factor = 0.5
    req.max_acceleration_scaling_factor = 0.5
    constraints = Constraints()
    position = PositionConstraint()
    position.header.frame_id = frame
    position.link_name = link
    sphere = SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001])
    position.constraint_region.primitives.append(sphere)
    target = Pose()
    target.position.x, target.position.y, target.position.z = xyz
    target.orientation.w = 1.0
    position.constraint_region.primitive_poses.append(target)
    position.weight = 1.0
    constraints.position_constraints.append(position)
    if quat is not None:
        orientation = OrientationConstraint()
        orientation.header.frame_id = frame
        orientation.link_name = link
        orientation.orientation.x, orientation.orientation.y, orientation.orientation.z, orientation.orientation.w = (
            quat
        )
        orientation.absolute_x_axis_tolerance = 0.01
        orientation.absolute_y_axis_tolerance = 0.01
        orientation.absolute_z_axis_tolerance = 0.01
        orientation.weight = 1.0
        constraints.orientation_constraints.append(orientation)
    req.goal_constraints.append(constraints)
    goal.planning_options.plan_only = False
    return goal


def main():
    args = [a for a in sys.argv[1:] if a != "--plan-only"]
    if len(args) not in (6, 10):
        print(__doc__, file=sys.stderr)
        return 2
    group, link, frame = args[:3]
    xyz = [float(v) for v in args[3:6]]
    quat = [float(v) for v in args[6:10]] if len(args) == 10 else None
    rclpy.init()
    node = rclpy.create_node("move_to_pose")
    client = ActionClient(node, MoveGroup, "move_action")
    if not client.wait_for_server(timeout_sec=30.0):
        print("move_group is not running (no /move_action)", file=sys.stderr)
        return 1
    goal = pose_goal(group, link, frame, xyz, quat)
    goal.planning_options.plan_only = "--plan-only" in sys.argv
    future = client.send_goal_async(goal)
    rclpy.spin_until_future_complete(node, future)
    handle = future.result()
    if not handle.accepted:
        print("goal rejected", file=sys.stderr)
        return 1
    result_future = handle.get_result_async()
    rclpy.spin_until_future_complete(node, result_future)
    code = result_future.result().result.error_code
    print(f"error_code: {code.val} {code.message}")
    node.destroy_node()
    rclpy.shutdown()
    return 0 if code.val == MoveItErrorCodes.SUCCESS else 1


if __name__ == "__main__":
    sys.exit(main())

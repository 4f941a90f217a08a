#!/usr/bin/env python3
"""Pick a chess piece with one arm of the chess robot and place it on another square.

    pick_and_place.py [--arm left|right] [--from ROW,COL] [--to ROW,COL] [--piece NAME]

What a MoveIt user writes without MoveIt Task Constructor, against MoveIt's interfaces only (a plain
rclpy program; it never imports gazelle, so it runs against MoveIt's move_group and gazelle's alike):

1. open the hand (control_msgs/GripperCommand on ``/<arm>_hand_controller/gripper_cmd``, the
   controllers of ``hand_controllers.yaml``);
2. the flange over the piece (a MoveGroup action pose goal, as ``r2_cli.py`` sends it; the fingers
   close along the board's rows), then straight down until the finger pads are at the piece's sides
   (``/compute_cartesian_path``, then the ``/execute_trajectory`` action: MoveIt's approach);
3. close the hand on the piece, then attach the piece to the hand in the planning scene
   (``/apply_planning_scene``, an AttachedCollisionObject naming the simulation's object, touching the
   hand and fingers), so that MoveIt plans with the piece in the hand;
4. straight up (the retreat: a Cartesian path, whose start may touch, as the piece on the board does),
   over the other square, straight down, open, detach, and straight up again.

The squares are the board's, as ``examples/chessboard/spawn_chessboard.py`` lays them out (the
piece on square ROW,COL is ``piece_rROW_cCOL``). Prints each step's wall time; exits 0 when every
step succeeded, 1 with the step and its error otherwise.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import rclpy
from control_msgs.action import GripperCommand
from geometry_msgs.msg import Pose
from moveit_msgs.action import ExecuteTrajectory, MoveGroup
from moveit_msgs.msg import AttachedCollisionObject, CollisionObject, MoveItErrorCodes, PlanningScene
from moveit_msgs.srv import ApplyPlanningScene, GetCartesianPath
from rclpy.action import ActionClient

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "chessboard"))
from r2_cli import FRAME, GROUPS, TIPS, pose_goal, quaternion_from_euler  # noqa: E402  (this folder's)
from spawn_chessboard import BOARD_XYZ, piece_name, piece_pose  # noqa: E402  (the board's layout)

BOARD_TOP = BOARD_XYZ[2] + 0.01
"""The board is a 2 cm slab centred at BOARD_XYZ."""
FLANGE_TO_FINGERTIP = 0.0584 + 0.0538
"""panda_link8 to the fingertips' lowest point, hand pointing down: the finger joints' origin on the
hand (0.0584 m) plus the finger's collision mesh (0.0538 m deep)."""
GRASP_HEIGHT = 0.012
"""The fingertips this far above the board: the pads (their lowest 1.8 cm) hold the 4 cm piece's middle."""
CLEARANCE = 0.08
"""How far above the grasp height the hand travels between squares (over the other pieces)."""
OPEN = 0.016
"""Each finger's opening (m): 6 mm each side of a 2 cm piece, and clear of the pieces on the next
squares (5 cm apart) on the hand's outer sides."""
CLOSED = 0.0
DOWN = (3.14159265, 0.0, -0.785398)
"""The flange's roll, pitch, yaw: the hand pointing down, the fingers closing along the board's rows."""


class Robot:
    """The clients this program uses, on one node."""

    def __init__(self, node, arm: str) -> None:
        self.node, self.arm = node, arm
        self.move = ActionClient(node, MoveGroup, "move_action")
        self.hand = ActionClient(node, GripperCommand, f"/{arm}_hand_controller/gripper_cmd")
        self.scene = node.create_client(ApplyPlanningScene, "apply_planning_scene")
        self.cartesian = node.create_client(GetCartesianPath, "compute_cartesian_path")
        self.execute = ActionClient(node, ExecuteTrajectory, "execute_trajectory")

    def wait(self, timeout: float) -> str | None:
        """The first interface not served within ``timeout`` s, or None."""
        for name, ready in (
            ("/move_action", lambda t: self.move.wait_for_server(timeout_sec=t)),
            (self.hand._action_name, lambda t: self.hand.wait_for_server(timeout_sec=t)),
            ("/apply_planning_scene", lambda t: self.scene.wait_for_service(timeout_sec=t)),
            ("/compute_cartesian_path", lambda t: self.cartesian.wait_for_service(timeout_sec=t)),
            ("/execute_trajectory", lambda t: self.execute.wait_for_server(timeout_sec=t)),
        ):
            if not ready(timeout):
                return name
        return None

    def _result(self, client: ActionClient, goal, timeout: float):
        future = client.send_goal_async(goal)
        rclpy.spin_until_future_complete(self.node, future, timeout_sec=timeout)
        handle = future.result()
        if handle is None or not handle.accepted:
            raise RuntimeError("the goal was not accepted")
        result = handle.get_result_async()
        rclpy.spin_until_future_complete(self.node, result, timeout_sec=timeout)
        if not result.done():
            raise RuntimeError(f"no result within {timeout} s")
        return result.result().result

    def flange_to(self, x: float, y: float, z: float) -> None:
        code = self._result(self.move, pose_goal(self.arm, x, y, z, *DOWN), 60.0).error_code
        if code.val != MoveItErrorCodes.SUCCESS:
            raise RuntimeError(f"error {code.val}: {code.message}")

    def straight_to(self, x: float, y: float, z: float) -> None:
        """The flange along a straight line to (x, y, z), the hand pointing down."""
        req = GetCartesianPath.Request(group_name=GROUPS[self.arm], link_name=TIPS[self.arm])
        req.header.frame_id = FRAME
        req.start_state.is_diff = True  # from the current state
        target = Pose()
        target.position.x, target.position.y, target.position.z = x, y, z
        target.orientation = quaternion_from_euler(*DOWN)
        req.waypoints, req.max_step, req.avoid_collisions = [target], 0.005, True
        future = self.cartesian.call_async(req)
        rclpy.spin_until_future_complete(self.node, future, timeout_sec=30.0)
        res = future.result()
        if res is None:
            raise RuntimeError("/compute_cartesian_path did not answer")
        if res.fraction < 0.999:
            raise RuntimeError(f"only {res.fraction:.0%} of the straight path is possible")
        goal = ExecuteTrajectory.Goal(trajectory=res.solution)
        code = self._result(self.execute, goal, 60.0).error_code
        if code.val != MoveItErrorCodes.SUCCESS:
            raise RuntimeError(f"error {code.val}: {code.message}")

    def grip(self, position: float, max_effort: float = 20.0) -> None:
        goal = GripperCommand.Goal()
        goal.command.position, goal.command.max_effort = position, max_effort
        result = self._result(self.hand, goal, 30.0)
        if not (result.reached_goal or result.stalled):
            raise RuntimeError(f"the hand stopped at {result.position:.4f} m")

    def attach(self, object_id: str, attach: bool) -> None:
        aco = AttachedCollisionObject(link_name=f"{self.arm}_panda_hand")
        aco.touch_links = [f"{self.arm}_panda_{link}" for link in ("hand", "leftfinger", "rightfinger")]
        aco.object.id = object_id
        aco.object.operation = CollisionObject.ADD if attach else CollisionObject.REMOVE
        scene = PlanningScene(is_diff=True)
        scene.robot_state.is_diff = True
        scene.robot_state.attached_collision_objects.append(aco)
        future = self.scene.call_async(ApplyPlanningScene.Request(scene=scene))
        rclpy.spin_until_future_complete(self.node, future, timeout_sec=10.0)
        if future.result() is None or not future.result().success:
            raise RuntimeError("the planning scene was not changed")


def square(text: str) -> tuple[int, int]:
    row, col = (int(v) for v in text.split(","))
    if not (0 <= row < 8 and 0 <= col < 8):
        raise argparse.ArgumentTypeError(f"no square {text} on the board (rows and columns 0..7)")
    return row, col


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--arm", choices=("left", "right"), default="left")
    parser.add_argument("--from", dest="source", type=square, default=(1, 3), help="ROW,COL of the piece")
    parser.add_argument("--to", dest="target", type=square, default=(3, 3), help="ROW,COL to put it on")
    parser.add_argument("--piece", help="the piece's entity name (default: the one spawned on --from)")
    parser.add_argument("--timeout", type=float, default=30.0, help="for move_group and the hand to be served (s)")
    args = parser.parse_args(rclpy.utilities.remove_ros_args(argv)[1:])

    rclpy.init(args=argv)
    node = rclpy.create_node("pick_and_place")
    robot = Robot(node, args.arm)
    name = args.piece or piece_name(*args.source)
    piece = f"{name}::link"
    src, dst = piece_pose(*args.source).position, piece_pose(*args.target).position
    grasp_z = BOARD_TOP + GRASP_HEIGHT + FLANGE_TO_FINGERTIP
    steps = [
        ("open the hand", lambda: robot.grip(OPEN)),
        ("over the piece", lambda: robot.flange_to(src.x, src.y, grasp_z + CLEARANCE)),
        ("down to the piece", lambda: robot.straight_to(src.x, src.y, grasp_z)),
        ("close the hand", lambda: robot.grip(CLOSED)),
        ("attach the piece", lambda: robot.attach(piece, True)),
        ("lift", lambda: robot.straight_to(src.x, src.y, grasp_z + CLEARANCE)),
        ("over the square", lambda: robot.flange_to(dst.x, dst.y, grasp_z + CLEARANCE)),
        ("down to the square", lambda: robot.straight_to(dst.x, dst.y, grasp_z + 0.001)),
        ("open the hand", lambda: robot.grip(OPEN)),
        ("detach the piece", lambda: robot.attach(piece, False)),
        ("up", lambda: robot.straight_to(dst.x, dst.y, grasp_z + CLEARANCE)),
    ]
    try:
        missing = robot.wait(args.timeout)
        if missing:
            print(
                f"error: {missing} is not served (is the chess robot running, with its hand controllers?)",
                file=sys.stderr,
            )
            return 1
        t0 = time.monotonic()
        for k, (what, step) in enumerate(steps, 1):
            t = time.monotonic()
            try:
                step()
            except RuntimeError as err:
                print(f"error: step {k} ({what}): {err}", file=sys.stderr)
                return 1
            print(f"{k:2d}. {what:<20s} {time.monotonic() - t:6.2f} s", flush=True)
        print(f"{name} moved from {args.source} to {args.target} in {time.monotonic() - t0:.2f} s")
        return 0
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""The seed's spawn_chessboard.py, ported to ROS 2: one classic gazebo_msgs call per model.

A plain rclpy program (it never imports gazelle): deletes any old board and pieces
(an entity that is not there is fine), spawns the board at (0.25, 1.39, 0.90), then a
1 g piece on each square of rows 0, 1, 6 and 7 through ``/spawn_entity``, and prints
the wall time. Works against any server with gazebo_ros's factory services.

    python3 spawn_chessboard.py [--board chess_board.sdf] [--piece chess_piece.sdf] [--timeout 10]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import rclpy
from gazebo_msgs.srv import DeleteEntity, SpawnEntity
from geometry_msgs.msg import Pose

HERE = Path(__file__).resolve().parent
BOARD_XYZ = (0.25, 1.39, 0.90)
UNIT = 0.05
ROWS = (0, 1, 6, 7)
COLS = range(8)
BOARD_NAME = "chess_board"


def piece_name(row: int, col: int) -> str:
    return f"piece_r{row}_c{col}"


def piece_pose(row: int, col: int) -> Pose:
    """The seed's formula: cell centres 5 cm apart around the board centre, 2 cm above it."""
    bx, by, bz = BOARD_XYZ
    pose = Pose()
    pose.position.x = bx - 3.5 * UNIT + col * UNIT
    pose.position.y = by - 3.5 * UNIT + row * UNIT
    pose.position.z = bz + 0.02
    pose.orientation.w = 1.0
    return pose


def call(node, client, request, timeout: float):
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
    if not future.done():
        raise TimeoutError(f"{client.srv_name} did not answer within {timeout} s")
    return future.result()


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--board", default=str(HERE / "chess_board.sdf"))
    parser.add_argument("--piece", default=str(HERE / "chess_piece.sdf"))
    parser.add_argument("--timeout", type=float, default=10.0, help="per service call and for discovery (s)")
    args = parser.parse_args(rclpy.utilities.remove_ros_args(argv)[1:])
    board_xml = Path(args.board).read_text()
    piece_xml = Path(args.piece).read_text()

    rclpy.init(args=argv)
    node = rclpy.create_node("spawn_chessboard")
    try:
        spawn = node.create_client(SpawnEntity, "/spawn_entity")
        delete = node.create_client(DeleteEntity, "/delete_entity")
        for c in (spawn, delete):
            if not c.wait_for_service(timeout_sec=args.timeout):
                print(f"error: service {c.srv_name} not available within {args.timeout} s", file=sys.stderr)
                return 1
        t0 = time.monotonic()
        names = [BOARD_NAME] + [piece_name(r, c) for r in ROWS for c in COLS]
        deleted = 0
        for name in names:  # "does not exist" is fine: nothing to clean up
            deleted += bool(call(node, delete, DeleteEntity.Request(name=name), args.timeout).success)
        t1 = time.monotonic()

        board_pose = Pose()
        board_pose.position.x, board_pose.position.y, board_pose.position.z = BOARD_XYZ
        board_pose.orientation.w = 1.0
        requests = [(BOARD_NAME, board_xml, board_pose)]
        requests += [(piece_name(r, c), piece_xml, piece_pose(r, c)) for r in ROWS for c in COLS]
        for name, xml, pose in requests:
            req = SpawnEntity.Request(name=name, xml=xml, initial_pose=pose, reference_frame="world")
            res = call(node, spawn, req, args.timeout)
            if not res.success:
                print(f"error: spawning {name}: {res.status_message}", file=sys.stderr)
                return 1
        t2 = time.monotonic()
        print(f"deleted {deleted} old entities in {t1 - t0:.3f} s")
        print(f"spawned {len(requests)} entities with {len(requests)} /spawn_entity calls in {t2 - t1:.3f} s")
        print(f"total wall time: {t2 - t0:.3f} s")
        return 0
    except TimeoutError as err:
        print(f"error: {err}", file=sys.stderr)
        return 1
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main(sys.argv))

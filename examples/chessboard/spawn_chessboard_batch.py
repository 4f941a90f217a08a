#!/usr/bin/env python3
"""The seed's chessboard, spawned with one simulation_interfaces SpawnEntities call.

A plain rclpy program (it never imports gazelle): finds and deletes any old board and
pieces (``get_entities`` + ``delete_entity``), then spawns the board at (0.25, 1.39, 0.90)
and a 1 g piece on each square of rows 0, 1, 6 and 7 in a single ``spawn_entities``
request, and prints the wall time. The services live under the simulator's namespace
(``--ns``, gazelle's default ``/gazelle``).

    python3 spawn_chessboard_batch.py [--ns /gazelle] [--board ...] [--piece ...] [--timeout 10]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import rclpy
from geometry_msgs.msg import PoseStamped
from simulation_interfaces.msg import EntityFilters, Resource, Result
from simulation_interfaces.msg import SpawnEntity as SpawnRequest
from simulation_interfaces.srv import DeleteEntity, GetEntities, SpawnEntities

HERE = Path(__file__).resolve().parent
BOARD_XYZ = (0.25, 1.39, 0.90)
UNIT = 0.05
ROWS = (0, 1, 6, 7)
COLS = range(8)
BOARD_NAME = "chess_board"
OUR_ENTITIES = r"^(chess_board|piece_r[0-7]_c[0-7])$"


def stamped(x: float, y: float, z: float) -> PoseStamped:
    p = PoseStamped()
    p.header.frame_id = "world"
    p.pose.position.x, p.pose.position.y, p.pose.position.z = x, y, z
    p.pose.orientation.w = 1.0
    return p


def call(node, client, request, timeout: float):
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=timeout)
    if not future.done():
        raise TimeoutError(f"{client.srv_name} did not answer within {timeout} s")
    return future.result()


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ns", default="/gazelle", help="the simulator's simulation_interfaces namespace")
    parser.add_argument("--board", default=str(HERE / "chess_board.sdf"))
    parser.add_argument("--piece", default=str(HERE / "chess_piece.sdf"))
    parser.add_argument("--timeout", type=float, default=10.0, help="per service call and for discovery (s)")
    args = parser.parse_args(rclpy.utilities.remove_ros_args(argv)[1:])
    board_xml = Path(args.board).read_text()
    piece_xml = Path(args.piece).read_text()
    ns = args.ns.rstrip("/")

    rclpy.init(args=argv)
    node = rclpy.create_node("spawn_chessboard_batch")
    try:
        get_entities = node.create_client(GetEntities, f"{ns}/get_entities")
        delete = node.create_client(DeleteEntity, f"{ns}/delete_entity")
        spawn = node.create_client(SpawnEntities, f"{ns}/spawn_entities")
        for c in (get_entities, delete, spawn):
            if not c.wait_for_service(timeout_sec=args.timeout):
                print(f"error: service {c.srv_name} not available within {args.timeout} s", file=sys.stderr)
                return 1
        t0 = time.monotonic()
        old = call(node, get_entities, GetEntities.Request(filters=EntityFilters(filter=OUR_ENTITIES)), args.timeout)
        for name in old.entities:
            res = call(node, delete, DeleteEntity.Request(entity=name), args.timeout)
            if res.result.result not in (Result.RESULT_OK, Result.RESULT_NOT_FOUND):
                print(f"error: deleting {name}: {res.result.error_message}", file=sys.stderr)
                return 1
        t1 = time.monotonic()

        bx, by, bz = BOARD_XYZ
        board = Resource(resource_string=board_xml)
        piece = Resource(resource_string=piece_xml)
        requests = [SpawnRequest(name=BOARD_NAME, entity_resource=board, initial_pose=stamped(bx, by, bz))]
        for r in ROWS:
            for c in COLS:
                pose = stamped(bx - 3.5 * UNIT + c * UNIT, by - 3.5 * UNIT + r * UNIT, bz + 0.02)
                requests.append(SpawnRequest(name=f"piece_r{r}_c{c}", entity_resource=piece, initial_pose=pose))
        res = call(node, spawn, SpawnEntities.Request(spawn_requests=requests), args.timeout)
        t2 = time.monotonic()
        if res.result.result != Result.RESULT_OK:
            print(f"error: spawn_entities: {res.result.error_message}", file=sys.stderr)
            for req, r in zip(requests, res.results):
                if r.result.result != Result.RESULT_OK:
                    print(f"  {req.name}: {r.result.error_message}", file=sys.stderr)
            return 1
        print(f"deleted {len(old.entities)} old entities in {t1 - t0:.3f} s")
        print(f"spawned {len(requests)} entities with 1 spawn_entities call in {t2 - t1:.3f} s")
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

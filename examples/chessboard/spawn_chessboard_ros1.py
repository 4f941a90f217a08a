#!/usr/bin/env python3
"""The seed's ROS 1 spawn_chessboard.py, ported line by line to rclpy: the same ROS 1 service names
(gazebo/delete_model, gazebo/spawn_sdf_model), the same calls and the same layout. Only what rclpy
needs changed: a node and clients instead of rospy proxies, call_async instead of a call, range for
xrange, and the quaternion of euler (0, 0, 0) written out (tf.transformations is ROS 1).

Run it from examples/chessboard (it reads chess_board.sdf and chess_piece.sdf there), as the seed does.
"""

import os
import sys
from copy import deepcopy

import rclpy
from gazebo_msgs.srv import DeleteModel, SpawnModel
from geometry_msgs.msg import Point, Pose, Quaternion


def call(node, client, request):
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future, timeout_sec=30.0)
    return future.result()


if __name__ == "__main__":
    os.chdir(os.path.dirname(os.path.abspath(__file__)))
    rclpy.init()
    node = rclpy.create_node("spawn_chessboard")
    delete_model = node.create_client(DeleteModel, "gazebo/delete_model")
    s = node.create_client(SpawnModel, "gazebo/spawn_sdf_model")
    if not delete_model.wait_for_service(timeout_sec=30.0) or not s.wait_for_service(timeout_sec=30.0):
        print("gazebo/delete_model or gazebo/spawn_sdf_model is not available", file=sys.stderr)
        sys.exit(1)
    call(node, delete_model, DeleteModel.Request(model_name="chessboard"))
    orient = Quaternion(x=0.0, y=0.0, z=0.0, w=1.0)  # quaternion_from_euler(0, 0, 0)
    board_pose = Pose(position=Point(x=0.25, y=1.39, z=0.90), orientation=orient)
    unit = 0.05
    with open("chess_board.sdf") as f:
        board_xml = f.read()
    with open("chess_piece.sdf") as f:
        piece_xml = f.read()
    print(
        call(
            node,
            s,
            SpawnModel.Request(
                model_name="chessboard",
                model_xml=board_xml,
                robot_namespace="",
                initial_pose=board_pose,
                reference_frame="world",
            ),
        )
    )
    for row in [0, 1, 6, 7]:
        for col in range(0, 8):
            piece_name = "piece_%d_%d" % (row, col)  # noqa: UP031 - the seed's own line
            call(node, delete_model, DeleteModel.Request(model_name=piece_name))
            pose = deepcopy(board_pose)
            pose.position.x = board_pose.position.x - 3.5 * unit + col * unit
            pose.position.y = board_pose.position.y - 3.5 * unit + row * unit
            pose.position.z += 0.02
            call(
                node,
                s,
                SpawnModel.Request(
                    model_name=piece_name,
                    model_xml=piece_xml,
                    robot_namespace="",
                    initial_pose=pose,
                    reference_frame="world",
                ),
            )
    node.destroy_node()
    rclpy.shutdown()

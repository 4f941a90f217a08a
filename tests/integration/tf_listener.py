#!/usr/bin/env python3
"""A TF listener written with rclpy and tf2_msgs only (tf2_ros is not on PyPI).

Subscribes /tf and /tf_static, keeps the latest transform of every parent->child edge,
and, when asked on stdin with a line "ROOT TARGET [TARGET ...]", composes the chain of
transforms from ROOT to each TARGET itself and prints one JSON line:
{"TARGET": [x, y, z, qw, qx, qy, qz], ...} (null for a target it cannot reach).
"""

import json
import sys
import threading

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from tf2_msgs.msg import TFMessage


def mul(a, b):
    """Compose (p, q) poses: a * b, quaternions wxyz."""
    (pa, qa), (pb, qb) = a, b
    w1, x1, y1, z1 = qa
    w2, x2, y2, z2 = qb
    q = (
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    )
    # rotate pb by qa
    vx, vy, vz = pb
    tx, ty, tz = 2 * (y1 * vz - z1 * vy), 2 * (z1 * vx - x1 * vz), 2 * (x1 * vy - y1 * vx)
    r = (vx + w1 * tx + (y1 * tz - z1 * ty), vy + w1 * ty + (z1 * tx - x1 * tz), vz + w1 * tz + (x1 * ty - y1 * tx))
    return ((pa[0] + r[0], pa[1] + r[1], pa[2] + r[2]), q)


class Listener:
    def __init__(self, node):
        self.edges = {}  # child -> (parent, pose)
        self.lock = threading.Lock()
        node.create_subscription(TFMessage, "/tf", self.on_tf, QoSProfile(depth=100))
        static_qos = QoSProfile(
            depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        node.create_subscription(TFMessage, "/tf_static", self.on_tf, static_qos)

    def on_tf(self, msg):
        with self.lock:
            for t in msg.transforms:
                tr, ro = t.transform.translation, t.transform.rotation
                self.edges[t.child_frame_id] = (t.header.frame_id, ((tr.x, tr.y, tr.z), (ro.w, ro.x, ro.y, ro.z)))

    def lookup(self, root, target):
        """Pose of target in root, walking parents up from target (a tree)."""
        with self.lock:
            chain = []
            frame = target
            for _ in range(64):
                if frame == root:
                    pose = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
                    for p in reversed(chain):
                        pose = mul(pose, p)
                    return pose
                if frame not in self.edges:
                    return None
                parent, p = self.edges[frame]
                chain.append(p)
                frame = parent
        return None


def main():
    rclpy.init()
    node = rclpy.create_node("tf_listener")
    listener = Listener(node)

    def spin() -> None:
        try:
            rclpy.spin(node)
        except ExternalShutdownException:  # the context was shut down under it: the end of stdin
            return

    spinner = threading.Thread(target=spin, daemon=True)
    spinner.start()
    print("READY", flush=True)
    for line in sys.stdin:
        words = line.split()
        if not words:
            continue
        root, targets = words[0], words[1:]
        out = {}
        for t in targets:
            pose = listener.lookup(root, t)
            out[t] = None if pose is None else [*pose[0], *pose[1]]
        with listener.lock:
            out["__frames__"] = sorted(listener.edges)
        print(json.dumps(out), flush=True)
    rclpy.shutdown()  # the spinning thread returns first, then the node goes
    spinner.join(5.0)
    node.destroy_node()


if __name__ == "__main__":
    main()

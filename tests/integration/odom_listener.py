#!/usr/bin/env python3
"""A plain rclpy node (it never imports gazelle): prints ``ready`` once subscribed to /odom, then one
JSON line per Odometry received (stamp and position), and exits after ``count`` messages, or ``timeout``
seconds without one once they started (60 s for the first).

Usage: odom_listener.py COUNT TIMEOUT
"""

import json
import sys
import time

import rclpy
from nav_msgs.msg import Odometry


def main() -> int:
    count, timeout = int(sys.argv[1]), float(sys.argv[2])
    rclpy.init()
    node = rclpy.create_node("odom_listener")
    got: list[Odometry] = []
    node.create_subscription(Odometry, "/odom", got.append, 1000)
    print("ready", flush=True)
    printed, last = 0, time.monotonic()
    while printed < count and time.monotonic() - last < (timeout if printed else 60.0):
        rclpy.spin_once(node, timeout_sec=0.05)
        while printed < len(got):
            m = got[printed]
            p = m.pose.pose.position
            stamp = m.header.stamp.sec * 1_000_000_000 + m.header.stamp.nanosec
            print(json.dumps({"stamp": stamp, "x": p.x, "y": p.y}), flush=True)
            printed += 1
            last = time.monotonic()
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

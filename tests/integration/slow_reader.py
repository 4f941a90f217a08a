#!/usr/bin/env python3
"""A plain rclpy node (it never imports gazelle) that is slow on purpose: it sleeps ``SLEEP`` seconds in its
/odom callback. ``QOS`` is ``reliable`` (KEEP_ALL: it asks for every message) or ``best_effort`` (depth 10).
Prints ``ready`` once subscribed and ``first`` at its first message; then, when a line with an end stamp (ns)
comes on stdin, takes messages until one stamped at or after it arrived (or 20 s without one) and prints the
stamps (ns) it got as one JSON list.

Usage: slow_reader.py QOS SLEEP
"""

import json
import select
import sys
import time

import rclpy
from nav_msgs.msg import Odometry
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy


def main() -> int:
    qos_name, pause = sys.argv[1], float(sys.argv[2])
    qos = {
        "reliable": QoSProfile(depth=10, history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE),
        "best_effort": QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT),
    }[qos_name]
    rclpy.init()
    node = rclpy.create_node(f"slow_{qos_name}_reader")
    stamps: list[int] = []

    def slowly(m: Odometry) -> None:
        if not stamps:
            print("first", flush=True)
        stamps.append(m.header.stamp.sec * 1_000_000_000 + m.header.stamp.nanosec)
        time.sleep(pause)

    node.create_subscription(Odometry, "/odom", slowly, qos)
    print("ready", flush=True)
    end = None
    last = time.monotonic()
    while end is None or (stamps and stamps[-1] < end and time.monotonic() - last < 20.0):
        n = len(stamps)
        rclpy.spin_once(node, timeout_sec=0.05)
        if len(stamps) != n:
            last = time.monotonic()
        if end is None and select.select([sys.stdin], [], [], 0)[0]:
            end = int(sys.stdin.readline().strip() or 0)
            last = time.monotonic()
    print(json.dumps(stamps), flush=True)
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

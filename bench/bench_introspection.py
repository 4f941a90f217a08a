#!/usr/bin/env python3
"""``ros2 topic echo`` and ``ros2 bag record`` against a plain rclpy subscriber, on /tf at 1 kHz (issue 15).

One run: a plain rclpy publisher sends /tf (tf2_msgs/TFMessage, one transform, its sequence number in
the stamp) at 1 kHz for ``SECONDS``; at the same time a plain rclpy subscriber counts what it gets,
``ros2 topic echo /tf`` prints every message (counted by its ``---`` separators), and ``ros2 bag record
/tf`` records (counted by ``ros2 bag info`` and by reading the MCAP back). Printed: each count and the
ratios to the plain subscriber's, and whether the bag holds every message the plain subscriber got.
All processes share this machine's cores, as they would on a developer's laptop.
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
SECONDS = 10.0
RATE_HZ = 1000.0

PUBLISHER = textwrap.dedent(
    """
    import sys, time, rclpy
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage
    rclpy.init(); node = rclpy.create_node("tf_1khz")
    pub = node.create_publisher(TFMessage, "/tf", 100)
    seconds, rate = float(sys.argv[1]), float(sys.argv[2])
    deadline = time.monotonic() + 3.0
    while pub.get_subscription_count() < 3 and time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)
    time.sleep(1.0)  # the late joiners' discovery settles
    t = TransformStamped(); t.header.frame_id = "odom"; t.child_frame_id = "base_link"
    msg = TFMessage(transforms=[t])
    n, start, period = 0, time.monotonic(), 1.0 / rate
    while n < seconds * rate:
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(n, 1000)
        pub.publish(msg); n += 1
        delay = start + n * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    print(f"sent {n} in {time.monotonic() - start:.2f} s", flush=True)
    time.sleep(1.0)
    """
)

SUBSCRIBER = textwrap.dedent(
    """
    import json, sys, time, rclpy
    from tf2_msgs.msg import TFMessage
    rclpy.init(); node = rclpy.create_node("plain_listener")
    got = []
    node.create_subscription(TFMessage, "/tf", lambda m: got.append(m.transforms[0].header.stamp.sec * 1000
                             + m.transforms[0].header.stamp.nanosec), 1000)
    end = time.monotonic() + float(sys.argv[1])
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    print(json.dumps(got), flush=True)
    """
)


def main() -> int:
    global SECONDS, RATE_HZ
    if "--smoke" in sys.argv[1:]:  # ./test.sh: the same processes for 1 s at 100 Hz
        SECONDS, RATE_HZ = 1.0, 100.0
    env = dict(os.environ)
    from _domain import private_ros_domain

    env["ROS_DOMAIN_ID"] = str(private_ros_domain())
    env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    with tempfile.TemporaryDirectory() as tmp:
        bag = Path(tmp) / "tf_bag"
        listen_for = SECONDS + 8.0
        sub = subprocess.Popen(
            [sys.executable, "-c", SUBSCRIBER, str(listen_for)], env=env, stdout=subprocess.PIPE, text=True
        )
        echo_file = open(Path(tmp) / "echo.txt", "w")
        echo = subprocess.Popen(
            [ROS2, "topic", "echo", "/tf", "tf2_msgs/msg/TFMessage"],
            env=env,
            stdout=echo_file,
            stderr=subprocess.DEVNULL,
            text=True,
        )
        rec = subprocess.Popen(
            [ROS2, "bag", "record", "-o", str(bag), "/tf"],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        time.sleep(2.0)  # the tools start (python, rclpy) before the publisher does
        pub = subprocess.run(
            [sys.executable, "-c", PUBLISHER, str(SECONDS), str(RATE_HZ)],
            env=env,
            capture_output=True,
            text=True,
            timeout=120,
        )
        plain_out, _ = sub.communicate(timeout=60)
        for p in (echo, rec):
            p.send_signal(signal.SIGINT)
        echo.wait(timeout=30)
        echo_file.close()
        echo_out = (Path(tmp) / "echo.txt").read_text()
        rec.wait(timeout=30)
        info = subprocess.run([ROS2, "bag", "info", str(bag)], env=env, capture_output=True, text=True, timeout=60)
        recorded = int(re.search(r"Count: (\d+)", info.stdout).group(1)) if "Count:" in info.stdout else 0  # type: ignore[union-attr]
        from mcap.reader import make_reader
        from rclpy.serialization import deserialize_message
        from tf2_msgs.msg import TFMessage

        seqs = set()
        with open(next(bag.glob("*.mcap")), "rb") as f:
            for _s, _c, m in make_reader(f).iter_messages():
                s = deserialize_message(bytes(m.data), TFMessage).transforms[0].header.stamp
                seqs.add(s.sec * 1000 + s.nanosec)
    plain_seqs = json.loads(plain_out)
    plain = len(plain_seqs)
    echoed = echo_out.count("\n---")
    print(f"/tf at {RATE_HZ:g} Hz for {SECONDS:g} s: {pub.stdout.strip()}")
    print(f"{'plain rclpy subscriber':28s} {plain:7d} messages (ratio 1)")
    print(f"{'ros2 topic echo':28s} {echoed:7d} messages (ratio {echoed / plain:.3f})")
    print(
        f"{'ros2 bag record':28s} {recorded:7d} messages (ratio {recorded / plain:.3f}); "
        f"{len(seqs)} distinct in the MCAP"
    )
    missing = set(plain_seqs) - seqs
    print(f"messages the plain subscriber got that the bag lacks: {len(missing)}")
    if not plain:
        print("the plain subscriber got nothing: the bench measured nothing")
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

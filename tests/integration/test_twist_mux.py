"""twist_mux's node (Husky's and articubot_one's bring-ups start it between their teleop sources and the base
controller; a missing package aborted both launches): inputs by priority and timeout, locks, as
ros-teleop/twist_mux's topic_handle.hpp and twist_mux.cpp decide. Started with `ros2 run` and a params file."""

from __future__ import annotations

import sys
import threading
from pathlib import Path

import pytest
from _harness import start, wait_for
from geometry_msgs.msg import Twist
from std_msgs.msg import Bool

pytestmark = pytest.mark.slow

PARAMS = """twist_mux:
  ros__parameters:
    topics:
      navigation:
        topic   : nav_vel
        timeout : 0.5
        priority: 10
      joystick:
        topic   : joy_vel
        timeout : 0.5
        priority: 100
    locks:
      e_stop:
        topic   : e_stop
        timeout : 0.0
        priority: 255
"""


def test_twist_mux_forwards_the_highest_priority_fresh_input_unless_locked(tmp_path: Path, ros_client) -> None:
    params = tmp_path / "twist_mux.yaml"
    params.write_text(PARAMS)
    ros2 = str(Path(sys.prefix) / "bin" / "ros2")
    mux = start(
        [ros2, "run", "twist_mux", "twist_mux", "--ros-args", "--params-file", str(params), "-r", "cmd_vel_out:=out"],
        "twist_mux",
    )
    node = ros_client.node
    got: list[float] = []
    lock = threading.Lock()
    node.create_subscription(Twist, "/out", lambda m: (lock.acquire(), got.append(m.linear.x), lock.release()), 10)
    nav = node.create_publisher(Twist, "/nav_vel", 10)
    joy = node.create_publisher(Twist, "/joy_vel", 10)
    stop = node.create_publisher(Bool, "/e_stop", 10)

    def twist(x: float) -> Twist:
        msg = Twist()
        msg.linear.x = x
        return msg

    def forwards(pub, x: float) -> bool:
        pub.publish(twist(x))
        with lock:
            return bool(got) and got[-1] == x

    try:
        mux.wait_line("Topic handler 'locks.e_stop' subscribed to topic 'e_stop': timeout = None , priority = 255.", 60)
        wait_for(lambda: forwards(nav, 0.1), 30, "navigation forwarded", interval=0.05)
        # the joystick (100) takes over from navigation (10) while its messages are fresh
        wait_for(lambda: forwards(joy, 0.5), 10, "joystick forwarded", interval=0.05)
        with lock:
            got.clear()
        rounds = {"n": 0}

        def joystick_wins() -> bool:
            nav.publish(twist(0.1))
            joy.publish(twist(0.5))
            rounds["n"] += 1
            with lock:
                return rounds["n"] >= 20 and got.count(0.5) >= 3

        wait_for(joystick_wins, 10, "a second of both inputs", interval=0.05)
        with lock:
            assert 0.1 not in got, got
        # 0.5 s after the joystick's last message, navigation is forwarded again
        wait_for(lambda: forwards(nav, 0.2), 10, "navigation after the joystick timed out", interval=0.05)
        # the e-stop lock (255) masks every input while it says true: once it is taken, nothing more comes out
        silent = {"n": 0, "seen": 0}

        def masked() -> bool:
            stop.publish(Bool(data=True))
            joy.publish(twist(0.4))
            with lock:
                count = len(got)
            silent["n"] = silent["n"] + 1 if count == silent["seen"] else 0
            silent["seen"] = count
            return silent["n"] >= 20  # a second of commands with none forwarded

        wait_for(masked, 15, "the e-stop lock masking the joystick", interval=0.05)
        stop.publish(Bool(data=False))
        wait_for(lambda: forwards(joy, 0.6), 10, "joystick after the lock is released", interval=0.05)
    finally:
        mux.interrupt()

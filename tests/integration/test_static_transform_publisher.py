"""tf2_ros's ``static_transform_publisher`` (issue 51, MoveIt's demo.launch.py): MoveIt's launch files start it
(``generate_static_virtual_joint_tfs_launch``, the Panda's demo), and gazelle had no such executable, so the launch
stopped there. Its new-style flags and old-style positional arguments, as tf2_ros Jazzy's
static_transform_broadcaster_program.cpp parses them, each publish one latched transform on /tf_static that a reader
started afterwards gets; a command line it refuses exits 1 with upstream's reason and usage."""

from __future__ import annotations

import math
import sys
import threading
from pathlib import Path

import pytest
from _harness import run_or_dump, start, wait_for
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from tf2_msgs.msg import TFMessage

from gazelle.ros._static_tf_node import quaternion_from_rpy

ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
RUN = [ROS2, "run", "tf2_ros", "static_transform_publisher"]


def test_the_quaternion_of_roll_pitch_yaw_is_tf2s():
    x, y, z, w = quaternion_from_rpy(0.0, 0.0, math.pi / 2)  # a quarter turn about z
    assert (x, y, z, w) == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))
    x, y, z, w = quaternion_from_rpy(math.pi / 2, 0.0, 0.0)  # about x
    assert (x, y, z, w) == pytest.approx((math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)))


@pytest.mark.slow
def test_new_and_old_style_command_lines_publish_a_latched_static_transform(ros_client):
    procs = [
        start(
            RUN
            + ["--x", "1", "--y", "2", "--z", "3", "--yaw", str(math.pi / 2), "--frame-id", "world"]
            + ["--child-frame-id", "panda_link0", "--ros-args", "-r", "__node:=static_transform_publisher0"],
            "new style",
        ),
        start(RUN + ["0.5", "0", "0", "0", "0", "0.7071068", "0.7071068", "world", "old9"], "old style, quaternion"),
        start(RUN + ["0", "0", "1", "0", "0", "3.14159265", "world", "old8"], "old style, yaw pitch roll"),
    ]
    try:
        for proc in procs:
            proc.wait_line("Spinning until stopped - publishing transform", 30)
        assert "Old-style arguments are deprecated" in procs[1].output
        heard: dict[str, object] = {}
        lock = threading.Lock()

        def keep(msg: TFMessage) -> None:
            with lock:
                for tf in msg.transforms:
                    heard[tf.child_frame_id] = tf

        # depth 100 as tf2's listener has for /tf_static: three latched publishers answer at once, and a depth-1
        # reader kept only the one taken last (it failed twice beside other tests)
        latched = QoSProfile(
            depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        ros_client.node.create_subscription(TFMessage, "/tf_static", keep, latched)  # after they published
        wait_for(lambda: {"panda_link0", "old9", "old8"} <= set(heard), 20, "the three static transforms")
        new, old9, old8 = (heard[k] for k in ("panda_link0", "old9", "old8"))
        assert new.header.frame_id == "world"  # type: ignore[attr-defined]
        t, r = new.transform.translation, new.transform.rotation  # type: ignore[attr-defined]
        assert (t.x, t.y, t.z) == (1.0, 2.0, 3.0)
        assert (r.x, r.y, r.z, r.w) == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))
        r9 = old9.transform.rotation  # type: ignore[attr-defined]
        assert (r9.x, r9.y, r9.z, r9.w) == (0.0, 0.0, 0.7071068, 0.7071068)  # as given
        r8, t8 = old8.transform.rotation, old8.transform.translation  # type: ignore[attr-defined]
        assert t8.z == 1.0 and (r8.x, r8.y) == pytest.approx((1.0, 0.0), abs=1e-7)  # roll of pi: about x
        names = run_or_dump([ROS2, "node", "list"], 60).stdout.split()
        assert "/static_transform_publisher0" in names, names  # the launch file's name, as a remap
        got = run_or_dump([ROS2, "param", "get", "/static_transform_publisher0", "frame_id"], 60)
        assert got.stdout.strip() == "String value is: world", got.stdout + got.stderr
    finally:
        for proc in procs:
            proc.interrupt(15)


@pytest.mark.parametrize(
    ("args", "reason"),
    [
        (
            ["--frame-id", "a", "--child-frame-id", "b", "--qx", "0", "--roll", "1"],
            "Cannot specify both quaternion and Euler rotations",
        ),
        (
            ["--frame-id", "a", "--child-frame-id", "b", "0", "0", "0", "0", "0", "0", "a", "b"],
            "Cannot specify both new-style (flags) and old-style (arguments)",
        ),
        (["--frame-id", "a"], "Child frame id must not be empty"),
        (["--x", "abc", "--frame-id", "a", "--child-frame-id", "b"], "Failed to parse --x argument as float"),
        (["--frame-id", "a", "--child-frame-id", "b", "extra"], "Extra unparsed arguments on command-line"),
        (["--frame-id"], "Not enough arguments for --frame-id"),
    ],
)
def test_a_command_line_it_refuses_exits_1_with_upstreams_reason_and_usage(args, reason):
    out = run_or_dump(RUN + args, 60)
    assert out.returncode == 1, out.stdout + out.stderr
    assert f"error parsing command line arguments: {reason}" in out.stderr, out.stderr
    assert out.stdout.startswith("usage: static_transform_publisher [--x X]"), out.stdout

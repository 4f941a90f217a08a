"""Three namespaced seed robots in one world, each driven by its own plain rclpy process.

Their odometry and TF trees stay separate: a separate TF listener process (rclpy and
tf2_msgs only, no tf2_ros) composes the transforms itself and finds each robot's
base_link where ground truth says it is.
"""

from __future__ import annotations

import json
import math
import sys
import threading
from pathlib import Path
from types import SimpleNamespace

import pytest
from _harness import GAZELLE, SEED_XACRO, SQUARE_NODE, start, wait_for, yaw_of
from nav_msgs.msg import Odometry

LISTENER = Path(__file__).with_name("tf_listener.py")
ROBOTS = {"r1": 0.0, "r2": 1.2, "r3": 2.4}  # namespace -> spawn y


@pytest.mark.slow
def test_three_namespaced_robots_keep_separate_odometry_and_tf(sim_factory, ros_client):
    # twice real time, the drivers on sim time (as test_square's simtime case)
    sim = sim_factory("--rtf", "2")
    for ns, y in ROBOTS.items():
        spawn = start(
            [*GAZELLE, "spawn", "-entity", ns, "-robot_namespace", ns, "-file", str(SEED_XACRO), "-y", str(y)],
            f"spawn {ns}",
        )
        assert spawn.wait(60) == 0, spawn.output
        sim.wait_line(f"Subscribed to [/{ns}/cmd_vel]", 10)
        sim.wait_line(f"Advertise odometry on [/{ns}/odom]", 10)

    odom: dict[str, Odometry] = {}
    lock = threading.Lock()
    for ns in ROBOTS:

        def on_odom(msg: Odometry, ns: str = ns) -> None:
            with lock:
                odom[ns] = msg

        ros_client.node.create_subscription(Odometry, f"/{ns}/odom", on_odom, 10)

    listener = start([sys.executable, str(LISTENER)], "tf_listener", stdin=True)
    listener.wait_line("READY", 30)

    drivers = [
        start(
            [
                sys.executable,
                str(SQUARE_NODE),
                "--ros-args",
                "-r",
                f"/cmd_vel:=/{ns}/cmd_vel",
                "-r",
                f"__node:=square_{ns}",
                "-p",
                "max_sides:=1",
                "-p",
                "use_sim_time:=true",
            ],
            f"driver {ns}",
        )
        for ns in ROBOTS
    ]
    for d in drivers:
        assert d.wait(120) == 0, d.output
    for ns in ROBOTS:
        wait_for(lambda ns=ns: abs(ros_client.entity_state(ns).state.twist.angular.z) < 1e-3, 30, f"{ns} at rest")

    truth = {ns: ros_client.entity_state(ns).state.pose for ns in ROBOTS}
    # every robot moved (its own driver reached it) and they did not move together. Each drives 1 m
    # nominally, timed on sim time at twice real time; how far exactly is test_square's business (it runs
    # alone): with the other pytest worker busy, a driver's late commands left r2 at 0.88 m once
    for ns, y in ROBOTS.items():
        p = truth[ns].position
        assert math.hypot(p.x, p.y - y) > 0.5, f"{ns} did not drive: {p}"

    with lock:
        got = dict(odom)
    for ns in ROBOTS:
        msg = got[ns]
        assert msg.header.frame_id == f"{ns}/odom" and msg.child_frame_id == f"{ns}/base_link"
        p = msg.pose.pose.position
        assert math.hypot(p.x - truth[ns].position.x, p.y - truth[ns].position.y) < 1e-3

    # ask the listener, a separate process, to compose each robot's chain
    def ask(query: str) -> dict:
        assert listener.popen.stdin is not None
        n = len(listener.lines)
        listener.popen.stdin.write(query + "\n")
        listener.popen.stdin.flush()
        line = wait_for(
            lambda: next((ln for ln in listener.lines[n:] if ln.startswith("{")), None), 10, "listener answer"
        )
        return json.loads(line)

    frames: list[str] = []
    for ns in ROBOTS:
        ans = wait_for(
            lambda ns=ns: (
                (a := ask(f"{ns}/odom {ns}/base_link {ns}/left_wheel {ns}/right_wheel"))[f"{ns}/left_wheel"] and a
            ),
            20,
            f"{ns}'s TF tree",
        )
        x, y, z, qw, qx, qy, qz = ans[f"{ns}/base_link"]
        t = truth[ns]
        assert math.dist((x, y, z), (t.position.x, t.position.y, t.position.z)) < 1e-3, (ns, ans, t)

        q = SimpleNamespace(w=qw, x=qx, y=qy, z=qz)
        assert abs(math.remainder(yaw_of(q) - yaw_of(t.orientation), math.tau)) < 1e-3
        # wheels hang off this robot's own base_link, 0.17 m to each side of it
        lw, rw = ans[f"{ns}/left_wheel"], ans[f"{ns}/right_wheel"]
        assert abs(math.dist(lw[:2], rw[:2]) - 0.34) < 1e-3
        frames = ans["__frames__"]
    assert not {"base_link", "odom", "left_wheel"} & set(frames), f"unprefixed frames published: {frames}"
    for ns in ROBOTS:
        assert {f"{ns}/base_link", f"{ns}/left_wheel", f"{ns}/right_wheel"} <= set(frames)
    # end of its stdin ends the listener (rclpy's SIGINT handler keeps its stdin loop from seeing a Ctrl-C,
    # and the teardown then waited 10 s before killing it)
    assert listener.popen.stdin is not None
    listener.popen.stdin.close()
    assert listener.wait(10) == 0


def test_robot_state_publisher_is_built_in_and_can_be_turned_off(sim_factory, ros_client):
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String
    from tf2_msgs.msg import TFMessage

    sim_factory()
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
    descriptions: dict[str, str] = {}
    frames: set[tuple[str, str]] = set()
    lock = threading.Lock()
    for ns in ("own", "mine"):
        ros_client.node.create_subscription(
            String, f"/{ns}/robot_description", lambda m, ns=ns: descriptions.__setitem__(ns, m.data), latched
        )

    def on_tf(msg: TFMessage) -> None:
        with lock:
            frames.update((t.header.frame_id, t.child_frame_id) for t in msg.transforms)

    ros_client.node.create_subscription(TFMessage, "/tf", on_tf, 100)
    for ns, extra in (("own", ["-frame_prefix", "custom/"]), ("mine", ["-no_robot_state_publisher"])):
        spawn = start(
            [
                *GAZELLE,
                "spawn",
                "-entity",
                ns,
                "-robot_namespace",
                ns,
                "-file",
                str(SEED_XACRO),
                "-y",
                "2" if ns == "own" else "0",
                *extra,
            ],
            f"spawn {ns}",
        )
        assert spawn.wait(60) == 0, spawn.output
    # the built-in one: the URDF on /own/robot_description, joint frames with the chosen prefix
    wait_for(lambda: "own" in descriptions, 15, "/own/robot_description")
    assert '<robot name="simple_robot"' in descriptions["own"] and "gazelle_source" not in descriptions["own"]
    wait_for(lambda: ("custom/base_link", "custom/left_wheel") in frames, 15, "the built-in publisher's joint TF")
    # turned off: nothing on /mine/robot_description; the wheel TF comes from the diff drive's publish_wheel_tf only
    with lock:
        mine = {f for f in frames if f[0].startswith("mine/")}
    assert "mine" not in descriptions
    assert mine <= {
        ("mine/odom", "mine/base_link"),
        ("mine/base_link", "mine/left_wheel"),
        ("mine/base_link", "mine/right_wheel"),
    }

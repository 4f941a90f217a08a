"""Soak: 1,000 spawn/delete cycles of a small box through simulation_interfaces while the seed robot drives a circle.

Memory stays flat (the server's VmRSS before/after is printed), no call times out or
fails, and the robot's arc radius and speed stay v/ω and v within a few per cent.
"""

from __future__ import annotations

import math
import os
import threading
import time

import numpy as np
import pytest
from _harness import SEED_XACRO, wait_for, xacro_to_urdf
from geometry_msgs.msg import PoseStamped, Twist
from simulation_interfaces.msg import Result
from simulation_interfaces.srv import DeleteEntity, GetEntityState, SpawnEntity

pytestmark = [pytest.mark.ros, pytest.mark.serial]  # load tests: run alone (./test.sh)

NS = "/gazelle/"
V, W = 0.2, 0.4
CYCLES = 1000
WARMUP = 100
BOX = (
    '<?xml version="1.0"?><sdf version="1.9"><model name="box"><link name="link">'
    "<inertial><mass>0.5</mass><inertia><ixx>0.0008</ixx><iyy>0.0008</iyy><izz>0.0008</izz></inertia></inertial>"
    '<collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision></link></model></sdf>'
)


def rss_kb(pid: int) -> int:
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS")


def spawn_req(name: str, xml: str, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> SpawnEntity.Request:
    pose = PoseStamped()
    pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = x, y, z
    return SpawnEntity.Request(name=name, resource_string=xml, initial_pose=pose)


def circle_fit(xy: np.ndarray) -> float:
    A = np.c_[2 * xy, np.ones(len(xy))]
    b = (xy**2).sum(axis=1)
    cx, cy, c = np.linalg.lstsq(A, b, rcond=None)[0]
    return float(math.sqrt(c + cx * cx + cy * cy))


def servers(ros_client, service: str) -> str:
    """Who serves ``service`` on this domain: a second gazelle sharing the ROS_DOMAIN_ID answers our calls too
    (the first reply wins), which shows up as an entity that was just spawned 'does not exist'."""
    n = ros_client.node.count_services(service)
    nodes = sorted(f"{ns.rstrip('/')}/{name}" for name, ns in ros_client.node.get_node_names_and_namespaces())
    return f"{n} server(s) of {service} on ROS_DOMAIN_ID={os.environ.get('ROS_DOMAIN_ID')}; nodes: {nodes}"


@pytest.mark.slow
def test_soak_spawn_delete_while_driving(sim_factory, ros_client) -> None:
    sim = sim_factory()
    pid = sim.popen.pid
    ros_client.client(SpawnEntity, NS + "spawn_entity")
    assert ros_client.node.count_services(NS + "spawn_entity") == 1, "another server shares this domain: " + servers(
        ros_client, NS + "spawn_entity"
    )
    res = ros_client.call(
        SpawnEntity, NS + "spawn_entity", spawn_req("robot", xacro_to_urdf(SEED_XACRO), z=0.05), timeout=30
    )
    assert res.result.result == Result.RESULT_OK, res.result.error_message
    pub = ros_client.node.create_publisher(Twist, "/cmd_vel", 10)
    cmd = Twist()
    cmd.linear.x, cmd.angular.z = V, W

    samples: list[tuple[float, float, float]] = []  # (sim time, x, y)
    problems: list[str] = []  # the observer's failures (an exception in a thread would be lost)
    stop = threading.Event()

    def observe() -> None:
        while not stop.is_set():
            pub.publish(cmd)
            try:
                st = ros_client.call(
                    GetEntityState, NS + "get_entity_state", GetEntityState.Request(entity="robot"), timeout=10
                )
            except BaseException as err:
                problems.append(f"get_entity_state: {err}")
                return
            if st.result.result == Result.RESULT_OK:
                t = st.state.header.stamp.sec + st.state.header.stamp.nanosec * 1e-9
                samples.append((t, st.state.pose.position.x, st.state.pose.position.y))
            else:
                problems.append(f"get_entity_state(robot): {st.result.error_message}")
            stop.wait(0.1)

    observer = threading.Thread(target=observe, daemon=True)
    observer.start()
    # the robot reaches its steady circle: 3 s of sim time observed
    wait_for(lambda: problems or (samples and samples[-1][0] - samples[0][0] >= 3.0), 60, "3 s of driving")
    assert not problems, problems

    def cycle(i: int) -> None:
        name = f"soak_box_{i}"
        c0 = time.monotonic()
        r = ros_client.call(SpawnEntity, NS + "spawn_entity", spawn_req(name, BOX, x=3.0, y=3.0, z=0.05), timeout=10)
        assert r.result.result == Result.RESULT_OK, (
            f"spawn {i} failed after {time.monotonic() - c0:.3f} s: {r.result.error_message}; "
            + servers(ros_client, NS + "spawn_entity")
        )
        c1 = time.monotonic()
        r = ros_client.call(DeleteEntity, NS + "delete_entity", DeleteEntity.Request(entity=name), timeout=10)
        assert r.result.result == Result.RESULT_OK, (
            f"delete {i} failed after {time.monotonic() - c1:.3f} s: {r.result.error_message}; "
            + servers(ros_client, NS + "delete_entity")
            + f"; server alive: {sim.popen.poll() is None}; its last output:\n{sim.output}"
        )

    try:
        for i in range(WARMUP):
            cycle(i)
        rss0 = rss_kb(pid)
        n0 = len(samples)
        t0 = time.monotonic()
        latencies = []
        for i in range(WARMUP, WARMUP + CYCLES):
            c0 = time.monotonic()
            cycle(i)
            latencies.append(time.monotonic() - c0)
        wall = time.monotonic() - t0
        rss1 = rss_kb(pid)
    finally:
        stop.set()
        observer.join(5)
        pub.publish(Twist())

    assert not problems, f"the robot observer failed: {problems[:5]}"
    soak = np.array(samples[n0:])
    lat = np.array(latencies) * 1e3
    print(
        f"\nsoak: {CYCLES} spawn+delete cycles in {wall:.1f} s = {CYCLES / wall:.1f} cycles/s "
        f"(per cycle median {np.median(lat):.1f} ms, p99 {np.percentile(lat, 99):.1f} ms, max {lat.max():.1f} ms; "
        f"first 100 {np.median(lat[:100]):.1f} ms, last 100 {np.median(lat[-100:]):.1f} ms)"
    )
    print(f"soak: server VmRSS {rss0 / 1024:.1f} MB -> {rss1 / 1024:.1f} MB ({(rss1 - rss0) / 1024:+.1f} MB)")
    assert rss1 - rss0 < 30 * 1024, f"RSS grew by {(rss1 - rss0) / 1024:.1f} MB"

    assert len(soak) > 20, f"only {len(soak)} robot samples during the {wall:.1f} s soak"
    radius = circle_fit(soak[:, 1:])
    dist = float(np.sum(np.linalg.norm(np.diff(soak[:, 1:], axis=0), axis=1)))
    speed = dist / (soak[-1, 0] - soak[0, 0])
    turned = V / radius * (soak[-1, 0] - soak[0, 0])
    print(
        f"soak: robot over {soak[-1, 0] - soak[0, 0]:.1f} s sim ({math.degrees(turned):.0f}° of arc): "
        f"R = {radius:.4f} m vs v/ω = {V / W:.4f} ({(radius * W / V - 1) * 100:+.2f} %), "
        f"speed {speed:.4f} vs {V} ({(speed / V - 1) * 100:+.2f} %)"
    )
    assert radius == pytest.approx(V / W, rel=0.03), f"arc radius {radius:.4f} m, expected v/ω = {V / W:.4f} m"
    assert speed == pytest.approx(V, rel=0.03), f"speed {speed:.4f} m/s, expected {V} m/s"

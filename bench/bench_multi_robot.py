"""Real-time factor with 1, 10 and 100 namespaced seed robots, each with the ROS bridge on, beside raw MuJoCo.

Run: ``.venv/bin/python bench/bench_multi_robot.py [--seconds S] [--counts 1,10,100] [--no-rss]``.

Each robot is the seed robot (examples/simple_robot) spawned in namespace ``rN`` on ``default_world()``
with its classic diff drive at ``update_rate`` 50 Hz (odom + odom->base TF + wheel TF) and a
``gazebo_ros_joint_state_publisher`` block added (50 Hz), plus the built-in robot_state_publisher
(/tf of the moving joints at 50 Hz). All robots drive at v=0.2 m/s, w=0.3 rad/s. Per count it prints:

* raw MuJoCo: ``mj_step`` in a Python loop on a copy of the same compiled model, ctrl as the drives set it;
* gazelle ``sim.step(N)`` in-process with no ROS (systems on, nothing listening);
* gazelle + RosBridge (``RosBridge``, /clock at 100 Hz, every endpoint mirrored to rclpy) on the sim
  thread at rtf=0 for ``--seconds`` wall seconds, nobody subscribed.

Then the RSS of a fresh process holding a session (Simulation + RosBridge) idle, with 1 robot and with 100.

RTF = steps/s x timestep. Machine-dependent; nothing asserts timing. Takes about 2 minutes.
"""

from __future__ import annotations

import argparse
import copy
import logging
import os
import re
import sys
import time
from pathlib import Path

from _domain import private_ros_domain

private_ros_domain()
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"

REPO = Path(__file__).resolve().parent.parent
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, W = 0.2, 0.3
RATE_HZ = 50


def robot_urdf() -> str:
    """The seed URDF with the drive at 50 Hz and a 50 Hz joint state publisher block."""
    from gazelle.description import load

    urdf = load(ROBOT).model.urdf
    assert urdf
    urdf = urdf.replace("<publish_odom>", f"<update_rate>{RATE_HZ}</update_rate><publish_odom>", 1)
    joints = re.findall(r'<joint name="([^"]+)" type="continuous"', urdf)
    js = "".join(f"<joint_name>{j}</joint_name>" for j in joints)
    block = (
        f'<gazebo><plugin name="joint_states" filename="libgazebo_ros_joint_state_publisher.so">'
        f"<update_rate>{RATE_HZ}</update_rate>{js}</plugin></gazebo>"
    )
    return urdf.replace("</robot>", block + "</robot>")


def make_sim(n: int):
    from gazelle.description import Pose, load_string
    from gazelle.sim import Simulation
    from gazelle.systems.diff_drive import DiffDrive
    from gazelle.worlds import default_world

    model = load_string(robot_urdf()).model
    sim = Simulation(default_world(), rtf=0)
    side = max(1, int(n**0.5 + 0.999))
    for i in range(n):
        x, y = (i % side) * 3.0, (i // side) * 3.0
        e = sim.spawn(model, name=f"r{i}", namespace=f"r{i}", pose=Pose((x, y, 0.07)))
        next(s for s in e.systems if isinstance(s, DiffDrive)).command(V, W)
    sim.step(200)
    return sim


def measure(n: int, steps: int, seconds: float, bridge_cls) -> dict:
    import mujoco

    sim = make_sim(n)
    m = copy.copy(sim.world.model)
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:], d.ctrl[:] = sim.world.data.qpos, sim.world.data.qvel, sim.world.data.ctrl
    mujoco.mj_forward(m, d)
    raws, no_ross = [], []
    for _ in range(3):  # alternating, best of 3: the least disturbed run of each
        t0 = time.perf_counter()
        for _ in range(steps):
            mujoco.mj_step(m, d)
        raws.append(steps / (time.perf_counter() - t0))
        t0 = time.perf_counter()
        sim.step(steps)
        no_ross.append(steps / (time.perf_counter() - t0))
    raw, no_ros = max(raws), max(no_ross)
    bridge = bridge_cls(sim, clock_rate_hz=100.0)
    pubs = sum(1 for e in sim.bus.endpoints() if e.is_publisher)
    i0, w0 = sim.iterations, time.monotonic()
    sim.start()
    time.sleep(seconds)
    sim.stop()
    ros = (sim.iterations - i0) / (time.monotonic() - w0)
    bridge.shutdown()
    return dict(n=n, dt=sim.world.timestep, raw=raw, no_ros=no_ros, ros=ros, nv=m.nv, pubs=pubs)


def _rss_mib() -> float:
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    return float("nan")


def rss_child(n: int) -> int:
    """In a fresh process: RSS after the imports, then with a `gazelle sim` session (Simulation + RosBridge +
    viewer-less) holding ``n`` robots; prints ``imports idle_or_n`` in MiB."""
    import mujoco  # noqa: F401
    import rclpy  # noqa: F401

    from gazelle.ros import RosBridge
    from gazelle.sim import Simulation
    from gazelle.worlds import default_world

    imports = _rss_mib()
    if n:
        sim = make_sim(n)
    else:
        sim = Simulation(default_world(), rtf=0)
        sim.step(200)
    bridge = RosBridge(sim, clock_rate_hz=100.0)
    sim.step(100)
    print(f"{imports:.0f} {_rss_mib():.0f}", flush=True)
    bridge.shutdown()
    return 0


def rss_child_arms(n: int) -> int:
    """In a fresh process: RSS of a session (Simulation + RosBridge) holding ``n`` namespaced r6bot arms
    (ros2_control_demos' example 7), each with its joint_state_broadcaster and joint_trajectory_controller
    active; prints ``imports total`` in MiB."""
    import mujoco  # noqa: F401
    import rclpy  # noqa: F401

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    from _paths import REAL, REPO

    from gazelle.description import Pose, load
    from gazelle.ros import RosBridge
    from gazelle.sim import Simulation
    from gazelle.systems.ros2_control import ControllerManager, load_params
    from gazelle.worlds import default_world

    os.environ["GAZELLE_RESOURCE_PATH"] = str(REAL / "ros2_control_r6bot")
    imports = _rss_mib()
    sim = Simulation(default_world(), rtf=0)
    model = load(REAL / "ros2_control_r6bot" / "_xacro_expanded" / "r6bot.urdf").model
    params = load_params(REPO / "tests" / "data" / "ros2_control" / "r6bot_jtc.yaml")
    for i in range(n):
        entity = sim.spawn(model, name=f"arm{i}", namespace=f"arm{i}", pose=Pose((1.5 * i, 0.0, 0.0)))
        cm = next(s for s in entity.systems if isinstance(s, ControllerManager))
        cm.files.append(params)
        for c in ("joint_state_broadcaster", "joint_trajectory_controller"):
            cm.load_controller(c)
            cm.configure_controller(c)
        cm.switch_controller(["joint_state_broadcaster", "joint_trajectory_controller"], [])
    bridge = RosBridge(sim, clock_rate_hz=100.0)
    sim.step(100)
    print(f"{imports:.0f} {_rss_mib():.0f} {sim.world.model.nmesh}", flush=True)
    bridge.shutdown()
    return 0


def rss_table_arms(n: int) -> None:
    import subprocess

    out = subprocess.run(
        [sys.executable, __file__, "--rss-child-arms", str(n)], capture_output=True, text=True, check=True
    ).stdout.split()
    imports, total, meshes = float(out[0]), float(out[1]), int(out[2])
    print(
        f"  {n} r6bot arm{'s' if n > 1 else ''} (JTC + JSB each) {total:>6.0f} MiB  ({meshes} meshes in the model: "
        f"one copy of each however many arms; imports {imports:.0f} MiB)"
    )


def rss_table(counts: list[int]) -> None:
    """RSS of a gazelle session (in a fresh process per count) and what dominates it."""
    import subprocess
    import sys

    print("\nmemory (RSS of a fresh process: Simulation + RosBridge, no viewer):")
    for n in counts:
        out = subprocess.run(
            [sys.executable, __file__, "--rss-child", str(n)], capture_output=True, text=True, check=True
        ).stdout.split()
        imports, total = float(out[0]), float(out[1])
        label = "idle (default world)" if n == 0 else f"{n} robot{'s' if n > 1 else ''}"
        print(f"  {label:<22} {total:>6.0f} MiB  (imports of Python, numpy, MuJoCo, rclpy: {imports:.0f} MiB)")


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--counts", default="1,10,100", help="robot counts (default 1,10,100)")
    p.add_argument("--rss-child", type=int, default=-1, help=argparse.SUPPRESS)
    p.add_argument("--rss-child-arms", type=int, default=-1, help=argparse.SUPPRESS)
    p.add_argument("--arms", type=int, default=20, help="r6bot arms in the memory table (default 20; 0: none)")
    p.add_argument("--no-rss", action="store_true", help="skip the memory table")
    p.add_argument("--seconds", type=float, default=5.0, help="wall seconds of the ROS measurement (default 5)")
    p.add_argument("--steps", type=int, default=0, help="steps of the in-process measurements (default: ~3 s worth)")
    opts = p.parse_args()
    logging.disable(logging.CRITICAL)
    if opts.rss_child >= 0:
        return rss_child(opts.rss_child)
    if opts.rss_child_arms >= 0:
        return rss_child_arms(opts.rss_child_arms)
    t_all = time.perf_counter()
    from gazelle.ros import RosBridge

    rows = []
    for n in (int(c) for c in opts.counts.split(",")):
        steps = opts.steps or max(500, 6000 // n)
        rows.append(measure(n, steps, opts.seconds, RosBridge))
    dt = rows[0]["dt"]
    print(
        f"namespaced seed robots on default_world(), each driving v={V} w={W}: diff drive (odom + TF) at {RATE_HZ} Hz,"
    )
    print(
        f"joint states at {RATE_HZ} Hz, robot_state_publisher /tf at 50 Hz; dt = {dt * 1000:g} ms;"
        f" {os.cpu_count()} CPUs\n"
    )
    hdr = (
        f"{'robots':>6} {'nv':>5} {'ROS pubs':>8} | {'raw mj_step':>15} | {'gazelle no ROS':>15} {'x raw':>6}"
        f" | {'gazelle + ROS':>15} {'x raw':>6}"
    )
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        print(
            f"{r['n']:>6} {r['nv']:>5} {r['pubs']:>8} | {r['raw'] * dt:>8.2f}x RTF   | {r['no_ros'] * dt:>8.2f}x RTF   "
            f"{r['no_ros'] / r['raw']:>6.2f} | {r['ros'] * dt:>8.2f}x RTF   {r['ros'] / r['raw']:>6.2f}"
        )
    print("-" * len(hdr))
    print("RTF = steps/s x dt. 'gazelle + ROS' runs the sim thread at rtf=0 with RosBridge up (no subscribers).")
    if not opts.no_rss:
        rss_table([0, 1, 100])
    if opts.arms:
        print("\nmemory of arms (RSS of a fresh process: Simulation + RosBridge):")
        rss_table_arms(opts.arms)
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Real-time factor of the seed robot driving on the default world: raw MuJoCo vs gazelle, with and without ROS.

Run: ``.venv/bin/python bench/bench_rtf.py [-n STEPS] [--seconds S]``. One run prints, for the seed robot
(examples/simple_robot) spawned on ``default_world()`` and driving at v=0.2 m/s, w=0.3 rad/s:

* raw MuJoCo on a copy of the compiled world (``sim.world.model`` after the spawn): ``mj_step`` in a
  Python loop, and ``mj_step(m, d, nstep=N)`` (the loop in C), with the wheel ctrl held fixed;
* gazelle in-process without ROS: ``sim.step(N)`` (systems, listeners, divergence checks), and the
  same on the simulation thread (``sim.start()`` at rtf=0);
* gazelle with the ROS bridge (``RosBridge``: /clock at 100 Hz as ``gazelle sim`` by default, odom + tf
  at the diff drive's 100 Hz) on its thread at rtf=0, first with nobody on /clock (the bridge then
  runs free) and then with a plain rclpy process subscribed to /clock (the bridge then holds the sim
  back to keep /clock's resolution: at most one clock period per ms of wall time).

RTF = steps/s x timestep. Figures depend on the machine and its load; nothing here asserts timing.
"""

from __future__ import annotations

import argparse
import copy
import logging
import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

# a private ROS graph on this host only, before anything imports rclpy
os.environ["ROS_DOMAIN_ID"] = str(os.environ.get("GAZELLE_BENCH_DOMAIN_ID") or (os.getpid() % 100 + 1))
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"

REPO = Path(__file__).resolve().parent.parent
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, W = 0.2, 0.3
CLOCK_HZ = 100.0

SUBSCRIBER = textwrap.dedent(
    """
    import select, sys
    import rclpy
    from rclpy.qos import QoSProfile, ReliabilityPolicy
    from rosgraph_msgs.msg import Clock
    rclpy.init()
    node = rclpy.create_node("bench_clock_listener")
    n = [0]
    node.create_subscription(Clock, "/clock", lambda m: n.__setitem__(0, n[0] + 1),
                             QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))
    print("ready", flush=True)
    while not select.select([sys.stdin], [], [], 0)[0]:  # until the parent closes our stdin
        rclpy.spin_once(node, timeout_sec=0.05)
    print(n[0], flush=True)
    node.destroy_node()
    rclpy.shutdown()
    """
)


def make_sim():
    from gazelle.description import Pose, load
    from gazelle.sim import Simulation
    from gazelle.systems.diff_drive import DiffDrive
    from gazelle.worlds import default_world

    model = load(ROBOT).value
    sim = Simulation(default_world(), rtf=0)
    entity = sim.spawn(model, name="simple_robot", pose=Pose((0.0, 0.0, 0.07)))
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    drive.command(V, W)
    sim.step(500)  # settle and get up to speed
    return sim, drive


def run_threaded(sim, seconds: float) -> tuple[float, int, float]:
    """Run on the sim thread for ``seconds``; returns (sim seconds, steps, wall seconds)."""
    t0, i0, w0 = sim.world.time, sim.iterations, time.monotonic()
    sim.start()
    time.sleep(seconds)
    sim.stop()
    return sim.world.time - t0, sim.iterations - i0, time.monotonic() - w0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "-n", "--steps", type=int, default=20000, help="steps per in-process measurement (default 20000)"
    )
    parser.add_argument("--seconds", type=float, default=4.0, help="wall seconds per threaded measurement (default 4)")
    opts = parser.parse_args()
    logging.disable(logging.CRITICAL)
    t_all = time.perf_counter()
    import mujoco

    sim, drive = make_sim()
    dt = sim.world.timestep
    N = opts.steps
    rows: list[tuple[str, float, str]] = []  # (label, steps/s, note)

    # --- raw MuJoCo on a copy of the compiled world, wheel ctrl as the diff drive sets it
    m = copy.copy(sim.world.model)
    d = mujoco.MjData(m)
    d.qpos[:] = sim.world.data.qpos
    d.qvel[:] = sim.world.data.qvel
    d.ctrl[:] = sim.world.data.ctrl
    mujoco.mj_forward(m, d)
    step = mujoco.mj_step
    t0 = time.perf_counter()
    for _ in range(N):
        step(m, d)
    rows.append(("raw mj_step, Python loop", N / (time.perf_counter() - t0), f"{N} steps"))
    try:
        t0 = time.perf_counter()
        mujoco.mj_step(m, d, nstep=N)
        rows.append(("raw mj_step(nstep=N), C loop", N / (time.perf_counter() - t0), f"{N} steps"))
    except TypeError:
        rows.append(("raw mj_step(nstep=N), C loop", float("nan"), "nstep not supported"))
    raw = rows[0][1]

    # --- gazelle in-process, no ROS
    t0 = time.perf_counter()
    sim.step(N)
    rows.append(("gazelle sim.step(N), no ROS", N / (time.perf_counter() - t0), f"{N} steps, systems on"))
    no_ros = rows[-1][1]
    s, n, w = run_threaded(sim, opts.seconds)
    rows.append(("gazelle sim.start() rtf=0, no ROS", n / w, f"{s:.1f} sim s in {w:.1f} wall s"))

    # --- gazelle with the ROS bridge, nobody on /clock
    from gazelle.ros._bridge import RosBridge

    bridge = RosBridge(sim, clock_rate_hz=CLOCK_HZ)
    clock_pub = bridge.node._clock_pub
    subs_free = clock_pub.get_subscription_count()
    s, n, w = run_threaded(sim, opts.seconds)
    rows.append(
        ("gazelle + RosBridge, /clock unheard", n / w, f"{s:.1f} sim s in {w:.1f} wall s, {subs_free} /clock subs")
    )
    with_ros = rows[-1][1]

    # --- the same with a plain rclpy process subscribed to /clock
    proc = subprocess.Popen(
        [sys.executable, "-c", SUBSCRIBER],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        env=os.environ.copy(),
    )
    throttled = float("nan")
    try:
        assert proc.stdout is not None
        proc.stdout.readline()  # "ready"
        deadline = time.monotonic() + 8.0
        while clock_pub.get_subscription_count() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        subs = clock_pub.get_subscription_count()
        if subs:
            s, n, w = run_threaded(sim, opts.seconds)
            throttled = n / w
            note = f"{s:.1f} sim s in {w:.1f} wall s, {subs} /clock sub"
        else:
            note = "subscriber never matched (discovery?)"
        out, _ = proc.communicate(timeout=10)  # closes its stdin: it prints its count and exits
        received = out.strip().splitlines()[-1] if out.strip() else "?"
        rows.append(
            ("gazelle + RosBridge, /clock subscribed", throttled, note + f"; listener got {received} /clock msgs")
        )
    finally:
        if proc.poll() is None:
            proc.kill()
    bridge.shutdown()

    # --- table
    print(f"seed robot ({ROBOT.name}) on default_world(), driving v={V} m/s w={W} rad/s")
    print(
        f"timestep dt = {dt * 1000:g} ms, so RTF = steps/s x {dt:g} (1000 steps/s = 1.0x real time);"
        f" /clock at {CLOCK_HZ:g} Hz; {os.cpu_count()} CPUs; ROS_DOMAIN_ID={os.environ['ROS_DOMAIN_ID']}\n"
    )
    header = f"{'case':<40} {'steps/s':>9} {'RTF':>8} {'x raw':>7}  note"
    print(header)
    print("-" * (len(header) + 40))
    for label, sps, note in rows:
        print(f"{label:<40} {sps:>9.0f} {sps * dt:>7.1f}x {sps / raw:>7.3f}  {note}")
    print("-" * (len(header) + 40))
    print(
        f"ratios vs raw Python-loop mj_step: gazelle no-ROS {no_ros / raw:.3f},"
        f" gazelle + ROS (free) {with_ros / raw:.3f},"
        f" gazelle + ROS (/clock subscribed) {throttled / raw:.3f}"
    )
    cap = (1.0 / CLOCK_HZ) / 1e-3  # MIN_CLOCK_WALL_PERIOD_SEC = 1 ms: one clock period of sim time per ms of wall time
    print(f"(the /clock-subscribed case is capped by design at {cap:g}x real time = {cap / dt:.0f} steps/s)")
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

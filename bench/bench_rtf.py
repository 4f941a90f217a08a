"""Real-time factor of the seed robot driving on the default world: raw MuJoCo vs gazelle, with and without ROS.

Run: ``.venv/bin/python bench/bench_rtf.py [-n STEPS] [--seconds S]``. One run prints, for the seed robot
(examples/simple_robot) spawned on ``default_world()`` and driving at v=0.2 m/s, w=0.3 rad/s:

* raw MuJoCo on a copy of the compiled world (``sim.world.model`` after the spawn): ``mj_step`` in a
  Python loop, and ``mj_step(m, d, nstep=N)`` (the loop in C), with the wheel ctrl held fixed;
* gazelle in-process without ROS: ``sim.step(N)`` (systems, listeners, divergence checks), and the
  same on the simulation thread (``sim.start()`` at rtf=0);
* gazelle with the ROS bridge (``RosBridge``: /clock at 100 Hz as ``gazelle sim`` by default, odom + tf
  at the diff drive's 100 Hz) on its thread at rtf=0: with nobody subscribed (nothing is built for
  nobody), with a plain rclpy process on /odom and /tf (every message built, converted and sent): a reliable
  KEEP_ALL one, which gets every message written (printed: written and received; the simulation goes at
  its pace), then a best-effort one (DDS's semantics: it gets what it can take, and never slows the
  simulation), and with one on /clock (the bridge then holds the sim back to keep /clock's resolution: at most one
  clock period per ms of wall time).

The raw loop and ``sim.step(N)`` are measured three times, alternating; the best of each counts. The rows
with a listener process also print the CPU the bench's process and the listener's took while the sim ran
(in cores): on a 2-core machine they add up to about 2, the machine's ceiling for that row.

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
from _domain import private_ros_domain

private_ros_domain()
# the DDS settings of `gazelle sim` (its writers' 5 ms heartbeats), before the first participant
from gazelle.ros import announce_often  # noqa: E402

announce_often()

REPO = Path(__file__).resolve().parent.parent
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, W = 0.2, 0.3
CLOCK_HZ = 100.0

SUBSCRIBER = textwrap.dedent(
    """
    import select, sys, time
    import rclpy
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy
    from rosgraph_msgs.msg import Clock
    from nav_msgs.msg import Odometry
    from tf2_msgs.msg import TFMessage
    TYPES = {"/clock": Clock, "/odom": Odometry, "/tf": TFMessage}
    QOS = {
        "best_effort": QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
        "reliable": QoSProfile(depth=1, history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE),
    }
    rclpy.init()
    node = rclpy.create_node("bench_listener")
    n = [0]
    for topic in sys.argv[1].split(","):
        node.create_subscription(TYPES[topic], topic, lambda m: n.__setitem__(0, n[0] + 1), QOS[sys.argv[2]])
    print("ready", flush=True)
    while not select.select([sys.stdin], [], [], 0)[0]:  # until the parent closes our stdin
        rclpy.spin_once(node, timeout_sec=0.05)
    # the parent closed it once everything was acknowledged: take what the reader holds, until 0.5 s of quiet
    last = (n[0], time.monotonic())
    while time.monotonic() - last[1] < 0.5:
        rclpy.spin_once(node, timeout_sec=0.05)
        if n[0] != last[0]:
            last = (n[0], time.monotonic())
    print(n[0], flush=True)
    node.destroy_node()
    rclpy.shutdown()
    """
)


def cpu_seconds(pid: int) -> float:
    """User + system CPU seconds of process ``pid`` so far (all its threads), from /proc; 0 elsewhere."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii") as f:
            fields = f.read().rsplit(")", 1)[1].split()
    except OSError:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def with_listener(
    topics: str, pubs: list, sim, seconds: float, qos: str = "best_effort", outbox=None
) -> tuple[float, str, int]:
    """Run the sim thread for ``seconds`` while a plain rclpy process subscribes to ``topics`` with ``qos``
    (``best_effort``, or ``reliable``: KEEP_ALL), once every publisher in ``pubs`` has matched it (none given is
    an error: the runs would start before discovery, and a run then timed up to 3 s with nobody matched,
    publishing nothing). Returns the steps per wall second, a note, and how many messages the listener got
    (-1: unknown); before the listener counts, ``outbox`` is flushed and what was published acknowledged."""
    if not pubs:
        raise RuntimeError(f"no publishers on {topics} to wait for")
    proc = subprocess.Popen(
        [sys.executable, "-c", SUBSCRIBER, topics, qos],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        env=os.environ.copy(),
    )
    try:
        assert proc.stdout is not None
        proc.stdout.readline()  # "ready"
        deadline = time.monotonic() + 8.0
        while not all(p.get_subscription_count() for p in pubs) and time.monotonic() < deadline:
            time.sleep(0.05)
        if all(p.get_subscription_count() for p in pubs):
            mine, theirs = cpu_seconds(os.getpid()), cpu_seconds(proc.pid)
            s, n, w = run_threaded(sim, seconds)
            mine, theirs = cpu_seconds(os.getpid()) - mine, cpu_seconds(proc.pid) - theirs
            cpu = f"CPU: bench {mine / w:.2f}, listener {theirs / w:.2f} cores"
            rate, note = n / w, f"{s:.1f} sim s in {w:.1f} wall s; {cpu}"
        else:
            rate, note = float("nan"), "subscriber never matched (discovery?)"
        if outbox is not None:
            outbox.flush(10.0)
        from rclpy.duration import Duration

        for pub in pubs:
            pub.wait_for_all_acked(Duration(seconds=10))  # at once for a best-effort listener
        out, _ = proc.communicate(timeout=30)  # closes its stdin: it prints its count and exits
        received = out.strip().splitlines()[-1] if out.strip() else "?"
        got = int(received) if received.isdigit() else -1
        return rate, note + f"; listener got {received} msgs", got
    finally:
        if proc.poll() is None:
            proc.kill()


def make_sim():
    from gazelle.description import Pose, load
    from gazelle.sim import Simulation
    from gazelle.systems.diff_drive import DiffDrive
    from gazelle.worlds import default_world

    model = load(ROBOT).model
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


def best_threaded(sim, seconds: float, runs: int = 3) -> tuple[float, int, float]:
    """:func:`run_threaded` ``runs`` times; the run with the most steps per second (the least disturbed)."""
    return max((run_threaded(sim, seconds) for _ in range(runs)), key=lambda r: r[1] / r[2])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "-n", "--steps", type=int, default=20000, help="steps per in-process measurement (default 20000)"
    )
    parser.add_argument("--seconds", type=float, default=4.0, help="wall seconds per threaded measurement (default 4)")
    parser.add_argument(
        "--smoke",
        action="store_true",
        help="the same code path at tiny sizes (./test.sh runs it: the bench cannot rot)",
    )
    opts = parser.parse_args()
    if opts.smoke:
        opts.steps, opts.seconds = 300, 0.3
    logging.disable(logging.CRITICAL)
    t_all = time.perf_counter()
    import mujoco

    sim, drive = make_sim()
    dt = sim.world.timestep
    N = opts.steps
    rows: list[tuple[str, float, str]] = []  # (label, steps/s, note)

    # --- raw MuJoCo on a copy of the compiled world, wheel ctrl as the diff drive sets it; then gazelle in-process.
    # Each is measured 3 times, alternating, and the best run counts (the least disturbed by the machine).
    m = copy.copy(sim.world.model)
    d = mujoco.MjData(m)
    d.qpos[:] = sim.world.data.qpos
    d.qvel[:] = sim.world.data.qvel
    d.ctrl[:] = sim.world.data.ctrl
    mujoco.mj_forward(m, d)
    step = mujoco.mj_step
    raws, cloops, steps = [], [], []
    for _ in range(3):
        t0 = time.perf_counter()
        for _ in range(N):
            step(m, d)
        raws.append(N / (time.perf_counter() - t0))
        t0 = time.perf_counter()
        mujoco.mj_step(m, d, nstep=N)
        cloops.append(N / (time.perf_counter() - t0))
        t0 = time.perf_counter()
        sim.step(N)
        steps.append(N / (time.perf_counter() - t0))
    rows.append(("raw mj_step, Python loop", max(raws), f"{N} steps, best of 3"))
    rows.append(("raw mj_step(nstep=N), C loop", max(cloops), f"{N} steps, best of 3"))
    raw = rows[0][1]
    rows.append(("gazelle sim.step(N), no ROS", max(steps), f"{N} steps, systems on, best of 3"))
    no_ros = rows[-1][1]
    s, n, w = best_threaded(sim, opts.seconds)
    rows.append(("gazelle sim.start() rtf=0, no ROS", n / w, f"{s:.1f} sim s in {w:.1f} wall s, best of 3"))

    # --- gazelle with the ROS bridge, nobody subscribed
    from gazelle.ros import RosBridge

    bridge = RosBridge(sim, clock_rate_hz=CLOCK_HZ)
    node = bridge.node
    clock_pub = node.clock_publisher
    subs_free = clock_pub.get_subscription_count()
    s, n, w = best_threaded(sim, opts.seconds)
    rows.append(
        (
            "gazelle + RosBridge, nobody subscribed",
            n / w,
            f"{s:.1f} sim s in {w:.1f} wall s, {subs_free} subs, best of 3",
        )
    )
    with_ros = rows[-1][1]

    # --- a plain rclpy process on /odom and /tf (not /clock): every message is built and sent. A reliable
    # (KEEP_ALL) listener gets every message, and the simulation goes at its pace; a best-effort one keeps
    # DDS's semantics and never slows the simulation
    odom_tf = node.ros_publishers("/odom") + node.ros_publishers("/tf")
    box = node.outbox

    def heard(qos: str) -> tuple[float, str]:
        p0, d0 = box.published, box.dropped
        w0 = node.published_on("/odom") + node.published_on("/tf")
        rate, note, got = with_listener("/odom,/tf", odom_tf, sim, opts.seconds, qos, box)
        written = node.published_on("/odom") + node.published_on("/tf") - w0
        note += f"; bridge published {box.published - p0}, dropped {box.dropped - d0}" + (
            " (lossless)" if box.lossless else " (--drop-when-behind)"
        )
        verdict = "every one" if got == written else f"{written - got} missing"
        return rate, note + f"; /odom + /tf written {written}, the {qos} listener got {got} ({verdict})"

    rate, note = heard("reliable")
    rows.append(("gazelle + RosBridge, /odom + /tf heard", rate, note))
    heard_rate = rate
    rate, note = heard("best_effort")
    rows.append(("  ... heard best effort", rate, note))

    # --- the same on /clock: the bridge then holds the sim back to keep /clock's resolution
    throttled, note, _ = with_listener("/clock", [clock_pub], sim, opts.seconds)
    rows.append(("gazelle + RosBridge, /clock subscribed", throttled, note))
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
        f" gazelle + ROS (nobody subscribed) {with_ros / raw:.3f},"
        f" + ROS (/odom, /tf heard) {heard_rate / raw:.3f}, + ROS (/clock subscribed) {throttled / raw:.3f}"
    )
    cap = (1.0 / CLOCK_HZ) / 1e-3  # MIN_CLOCK_WALL_PERIOD_SEC = 1 ms: one clock period of sim time per ms of wall time
    print(f"(the /clock-subscribed case is capped by design at {cap:g}x real time = {cap / dt:.0f} steps/s)")
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""What the browser viewer costs the simulation: the seed scenario's RTF without and with a viewer.

Run: ``.venv/bin/python bench/bench_viewer.py [--seconds S] [--rounds N] [--scenario paced|flat|both]``.

The seed robot (examples/simple_robot) is spawned on ``default_world()`` and drives at v=0.2 m/s,
w=0.3 rad/s on the simulation thread (in process, no ROS). Two scenarios:

* ``paced``: real time (RTF 1), as the seed runs Gazebo and as ``gazelle sim`` runs by default. The
  RTF should stay 1.00; the cost shows as the simulation thread's CPU load (the share of a core
  it needs to keep real time): the headroom the viewer leaves.
* ``flat``: as fast as possible (``--rtf 0``): every bit of CPU the viewer takes shows in the RTF.

Each scenario runs three modes, interleaved over ``--rounds`` rounds so that a change of load on
the machine hits every mode alike:

* no viewer;
* the viewer serving, nobody connected (what ``gazelle sim`` costs by default);
* the viewer with a headless Debian chromium looking at it (Playwright, in a separate process as a
  user's browser is), rendering the live scene in software WebGL on the same CPUs.
  ``--max-fps F`` caps that chromium's frame rate (0, the default: uncapped, as a user's browser).

It prints each run, the medians and the drop against no viewer (target: < 10 %). Figures depend on
the machine and its load; nothing asserts timing.
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import os
import statistics
import subprocess
import sys
import textwrap
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, W = 0.2, 0.3
MODES = {
    "none": "no viewer",
    "idle": "viewer, no client",
    "browser": "viewer + headless chromium",
}
# the browser, in its own process (as a user's): opens the page, says "ready", holds it until stdin closes
BROWSER = textwrap.dedent(
    """
    import sys
    from gazelle.viewer import open_viewer_page
    with open_viewer_page(sys.argv[1], max_fps=float(sys.argv[2])) as page:
        page.wait_for_timeout(500)
        print("ready", flush=True)
        sys.stdin.read()
    """
)


def make_sim(rtf: float):
    from gazelle.description import load
    from gazelle.sim import Simulation
    from gazelle.systems import MsgType, Twist
    from gazelle.worlds import default_world

    sim = Simulation(default_world(), rtf=rtf)
    sim.spawn(load(ROBOT).model, name="simple_robot")
    for ep in sim.bus.endpoints():
        if (
            ep.owner == "simple_robot"
            and not ep.is_publisher
            and ep.callback is not None
            and ep.msg_type == MsgType.TWIST
        ):
            ep.callback(Twist((V, 0.0, 0.0), (0.0, 0.0, W)))
    return sim


def _stat_cpu(path: str) -> float:
    """utime + stime in seconds from a /proc .../stat file."""
    st = Path(path).read_text()
    f = st[st.rindex(")") + 2 :].split()
    return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")


def tree_cpu_sec(root: int) -> float:
    """CPU seconds used so far by ``root``'s descendants (not ``root`` itself), from /proc."""
    children: dict[int, list[tuple[int, float]]] = {}
    for p in os.listdir("/proc"):
        if not p.isdigit():
            continue
        try:
            st = Path(f"/proc/{p}/stat").read_text()
            cpu = _stat_cpu(f"/proc/{p}/stat")
        except (OSError, ValueError):
            continue
        ppid = int(st[st.rindex(")") + 2 :].split()[1])
        children.setdefault(ppid, []).append((int(p), cpu))
    total, stack = 0.0, [root]
    while stack:
        for pid, cpu in children.get(stack.pop(), []):
            total += cpu
            stack.append(pid)
    return total


@dataclass
class Run:
    rtf: float
    sim_load: float
    """CPU of the simulation thread, in cores (1.0: it needs a whole core)."""
    browser_cores: float = 0.0
    frames: int = 0


def measure(sim, seconds: float) -> Run:
    """RTF, the sim thread's CPU and the browser's CPU over ``seconds`` of wall time (after a 1 s warm-up)."""
    tid = sim.thread_id

    def sample() -> tuple[float, float, float, float]:
        return (
            sim.call(lambda: sim.world.time),
            time.monotonic(),
            _stat_cpu(f"/proc/self/task/{tid}/stat"),
            tree_cpu_sec(os.getpid()),
        )

    time.sleep(1.0)
    t0, w0, s0, b0 = sample()
    time.sleep(seconds)
    t1, w1, s1, b1 = sample()
    dt = w1 - w0
    return Run(rtf=(t1 - t0) / dt, sim_load=(s1 - s0) / dt, browser_cores=(b1 - b0) / dt)


@contextlib.contextmanager
def running(rtf: float, mode: str, max_fps: float) -> Iterator[tuple[object, object]]:
    sim = make_sim(rtf)
    sim.start()
    view = browser = None
    try:
        if mode != "none":
            from gazelle.viewer import Viewer

            view = Viewer(sim, port=0)
            view.start()
        if mode == "browser":
            browser = subprocess.Popen(
                [sys.executable, "-c", BROWSER, view.url, str(max_fps)],
                stdin=subprocess.PIPE,
                stdout=subprocess.PIPE,
                text=True,
                cwd=REPO,
            )
            line = browser.stdout.readline()
            if line.strip() != "ready":
                raise RuntimeError(f"the browser did not open the viewer (said {line!r})")
        yield sim, view
    finally:
        if browser is not None:
            browser.stdin.close()
            browser.wait(30)
        if view is not None:
            view.stop()
        sim.stop()


def scenario(name: str, rtf: float, a: argparse.Namespace) -> dict[str, float]:
    print(f"\n== {name}: target rtf {rtf:g} ({'real time, as the seed' if rtf else 'as fast as possible'})", flush=True)
    runs: dict[str, list[Run]] = {m: [] for m in MODES}
    for r in range(a.rounds):
        for mode in MODES:
            with running(rtf, mode, a.max_fps) as (sim, view):
                run = measure(sim, a.seconds)
                run.frames = getattr(view, "frames", 0)
            runs[mode].append(run)
            extra = f"  chromium {run.browser_cores:.2f} cores, {run.frames} frames pushed" if mode == "browser" else ""
            print(
                f"  round {r + 1}: {MODES[mode]:28s} RTF {run.rtf:7.3f}  sim thread {run.sim_load:.2f} cores{extra}",
                flush=True,
            )
    med_rtf = {m: statistics.median(x.rtf for x in v) for m, v in runs.items()}
    med_load = {m: statistics.median(x.sim_load for x in v) for m, v in runs.items()}
    print("  medians:")
    for m, label in MODES.items():
        ratio = med_rtf[m] / med_rtf["none"]
        print(
            f"    {label:28s} RTF {med_rtf[m]:7.3f}  ratio {ratio:.3f}  drop {100 * (1 - ratio):5.1f} % (target < 10 %)"
            f"   sim thread {med_load[m]:.2f} cores"
        )
    return med_rtf


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seconds", type=float, default=4.0, help="wall seconds measured per run (default 4)")
    ap.add_argument(
        "--rounds", type=int, default=3, help="interleaved rounds of the three modes (default 3; medians are printed)"
    )
    ap.add_argument("--scenario", choices=("paced", "flat", "both"), default="both")
    ap.add_argument("--max-fps", type=float, default=0.0, help="cap chromium's frame rate (default 0: uncapped)")
    a = ap.parse_args()
    t_all = time.perf_counter()
    logging.basicConfig(level=logging.WARNING)
    sys.setswitchinterval(0.0002)  # as `gazelle sim` does
    from gazelle.viewer import POSE_RATE_HZ

    print(
        f"seed robot driving; viewer poses at {POSE_RATE_HZ:g} Hz; {a.rounds} x {a.seconds:g} s per mode; "
        f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}; chromium "
        + (f"capped at {a.max_fps:g} fps" if a.max_fps > 0 else "uncapped")
    )
    if a.scenario in ("paced", "both"):
        scenario("seed scenario, paced", 1.0, a)
    if a.scenario in ("flat", "both"):
        scenario("flat out", 0.0, a)
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

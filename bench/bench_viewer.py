"""What the browser viewer costs the simulation: the seed scenario's RTF without and with a viewer.

Run: ``.venv/bin/python bench/bench_viewer.py [--seconds S] [--rtf R]``. The seed robot
(examples/simple_robot) is spawned on ``default_world()`` and drives at v=0.2 m/s, w=0.3 rad/s on
the simulation thread (in process, no ROS), as fast as possible by default (``--rtf 0``). Four runs:

* no viewer;
* the viewer serving, nobody connected (what ``gazelle sim`` costs by default);
* the viewer with a headless Debian chromium attached (Playwright), rendering the live scene;
* the same with chromium's frame rate capped (``--max-fps``, default 5): what our own headless
  client can cost at least (a user's browser is not capped).

The four runs are interleaved over ``--rounds`` rounds; it prints each run, the median RTF of each
mode and the drop against no viewer (target: < 10 %). Figures depend on the
machine and its load (chromium renders WebGL in software, on the same CPUs); nothing asserts timing.
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import os
import statistics
import sys
import time
from pathlib import Path
from typing import Iterator

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))
ROBOT = REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro"
V, W = 0.2, 0.3


def make_sim(rtf: float):
    from gazelle.description import load
    from gazelle.physics import Simulation
    from gazelle.worlds import default_world

    sim = Simulation(default_world(), rtf=rtf)
    model = load(ROBOT).value
    sim.spawn(model, name="simple_robot")
    for ep in sim.bus.endpoints():
        if ep.owner == "simple_robot" and not ep.is_publisher and ep.callback is not None:
            from gazelle.systems._bus import MsgType, Twist

            if ep.msg_type == MsgType.TWIST:
                ep.callback(Twist((V, 0.0, 0.0), (0.0, 0.0, W)))
    return sim


def child_cpu_sec() -> float:
    """CPU seconds used so far by this process's descendants (Playwright's driver and chromium), from /proc."""
    tick = os.sysconf("SC_CLK_TCK")
    children: dict[int, list[tuple[int, float]]] = {}
    for p in os.listdir("/proc"):
        if not p.isdigit():
            continue
        try:
            st = Path(f"/proc/{p}/stat").read_text()
        except OSError:
            continue
        f = st[st.rindex(")") + 2 :].split()
        children.setdefault(int(f[1]), []).append((int(p), (int(f[11]) + int(f[12])) / tick))
    total, stack = 0.0, [os.getpid()]
    while stack:
        for pid, cpu in children.get(stack.pop(), []):
            total += cpu
            stack.append(pid)
    return total


def measure(sim, seconds: float) -> tuple[float, float]:
    """(RTF, browser CPU in cores) over ``seconds`` of wall time on the running sim (after a 1 s warm-up)."""
    time.sleep(1.0)
    t0, w0, c0 = sim.call(lambda: sim.world.time), time.monotonic(), child_cpu_sec()
    time.sleep(seconds)
    t1, w1, c1 = sim.call(lambda: sim.world.time), time.monotonic(), child_cpu_sec()
    return (t1 - t0) / (w1 - w0), (c1 - c0) / (w1 - w0)


@contextlib.contextmanager
def running(rtf: float, viewer: str, rate_hz: float = 30.0, max_fps: float | None = None) -> Iterator[object]:
    sim = make_sim(rtf)
    sim.start()
    view = None
    try:
        if viewer != "none":
            from gazelle.viewer import Viewer

            view = Viewer(sim, port=0, rate_hz=rate_hz)
            view.start()
        if viewer in ("browser", "capped"):
            from gazelle.viewer._browser import open_viewer_page

            kw = {} if max_fps is None else {"max_fps": max_fps}
            with open_viewer_page(view.url, **kw) as page:
                page.wait_for_timeout(500)
                yield sim, view
        else:
            yield sim, view
    finally:
        if view is not None:
            view.stop()
        sim.stop()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seconds", type=float, default=4.0, help="wall seconds measured per run (default 4)")
    ap.add_argument("--rounds", type=int, default=3, help="interleaved rounds of the four runs (default 3; medians are printed)")
    ap.add_argument("--rtf", type=float, default=0.0, help="target real-time factor (default 0: as fast as possible)")
    ap.add_argument("--rate", type=float, default=None, help="viewer pose rate in Hz (default: the viewer's)")
    ap.add_argument(
        "--max-fps",
        type=float,
        default=None,
        help="render cap of the 'capped' chromium run (default: gazelle.viewer._browser.LOW_COST_MAX_FPS, 5)",
    )
    a = ap.parse_args()
    logging.basicConfig(level=logging.WARNING)
    sys.setswitchinterval(0.0002)  # as `gazelle sim` does
    from gazelle.viewer._browser import LOW_COST_MAX_FPS
    from gazelle.viewer._viewer import POSE_RATE_HZ

    rate = a.rate or POSE_RATE_HZ
    print(
        f"seed robot driving, target rtf {a.rtf:g} ({'flat out' if a.rtf == 0 else 'paced'}), viewer at {rate:g} Hz, "
        f"{a.rounds} x {a.seconds:g} s per mode, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}, "
        f"capped chromium at {a.max_fps or LOW_COST_MAX_FPS:g} fps"
    )
    labels = {
        "none": "no viewer",
        "idle": "viewer, no client",
        "browser": "viewer + headless chromium",
        "capped": "viewer + chromium, capped fps",
    }
    results: dict[str, list[float]] = {m: [] for m in labels}
    for r in range(a.rounds):
        for mode in labels:  # interleaved, so a load change on the machine hits every mode alike
            cap = 0.0 if mode == "browser" else (a.max_fps or LOW_COST_MAX_FPS)
            with running(a.rtf, mode, rate, cap) as (sim, view):
                rtf, browser_cores = measure(sim, a.seconds)
                frames, cpu = getattr(view, "frames", 0), getattr(view, "cpu_sec", 0.0)
            results[mode].append(rtf)
            extra = (
                f"  ({frames} frames pushed, viewer thread CPU {cpu:.2f} s, chromium {browser_cores:.2f} cores)"
                if mode in ("browser", "capped")
                else ""
            )
            print(f"  round {r + 1}: {labels[mode]:28s} RTF {rtf:8.2f}{extra}", flush=True)
    med = {m: statistics.median(v) for m, v in results.items()}
    print("medians:")
    for m, label in labels.items():
        print(f"  {label:28s} RTF {med[m]:8.2f}")
    for m in ("idle", "browser", "capped"):
        ratio = med[m] / med["none"] if med["none"] > 0 else float("nan")
        print(f"  {labels[m]:28s} vs no viewer: ratio {ratio:.3f}, drop {100 * (1 - ratio):5.1f} % (target < 10 %)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

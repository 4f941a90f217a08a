#!/usr/bin/env python3
"""What the pytest plugin's ``gazelle_sim`` costs a test: set-up (the server ready, its step service
found) and tear-down, with and without the failure bag's recorder (issue 30's goal: at most 1.5 s for
set-up and tear-down together), measured here as the fixture does it, in-process, N times.

Run: ``.venv/bin/python bench/bench_robot_ci.py [-n N] [--smoke]``.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

ROBOT = Path(__file__).resolve().parents[1] / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"


def one(record: bool, folder: Path) -> tuple[float, float]:
    from gazelle.testing import Sim, reserve_domain

    domain = reserve_domain()
    t0 = time.perf_counter()
    sim = Sim(domain_id=domain.domain_id, record=(folder, []) if record else None)
    ready = time.perf_counter() - t0
    sim.run_for(0.1)  # the test's part: 100 steps
    t1 = time.perf_counter()
    sim.close()
    domain.release()
    return ready, time.perf_counter() - t1


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", type=int, default=5, help="set-ups per mode (default 5)")
    ap.add_argument("--smoke", action="store_true", help="one of each (./test.sh)")
    a = ap.parse_args()
    n = 1 if a.smoke else a.n
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        for record in (False, True):
            runs = [one(record, Path(tmp) / f"bag{record}{i}") for i in range(n)]
            up = statistics.median(r[0] for r in runs)
            down = statistics.median(r[1] for r in runs)
            label = "with the failure bag's recorder" if record else "no recorder (--gazelle-artifacts=none)"
            print(
                f"{label:<42} set-up {up:.2f} s, tear-down {down:.2f} s, together {up + down:.2f} s "
                f"= {(up + down) / 1.5:.2f} of the 1.5 s goal (median of {n})"
            )
    # a module's shared server: reset (spawned entities removed, time 0) before each test
    from gazelle.testing import Sim, reserve_domain

    domain = reserve_domain()
    sim = Sim(domain_id=domain.domain_id)
    try:
        resets = []
        for _ in range(n * 2):
            sim.spawn(ROBOT, "robot", pose=(0.0, 0.0, 0.07))
            sim.run_for(0.05)
            t0 = time.perf_counter()
            sim.reset()
            resets.append(time.perf_counter() - t0)
    finally:
        sim.close()
        domain.release()
    reset = statistics.median(resets)
    print(f"{'shared server, reset between tests':<42} {reset:.3f} s a test = {reset / 0.2:.2f} of the 0.2 s goal")
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

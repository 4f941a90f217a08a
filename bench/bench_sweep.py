#!/usr/bin/env python3
"""Sweeps (issue 31), as ratios measured in one run:

* throughput of ``-j 2`` against ``-j 1`` on short ROS-less runs (goal >= 1.8x on 2 cores);
* per-run overhead (world reset, result row, the pool's hand-over) against a run of 5 s of sim time:
  the sweep's wall time per run beside the scenario's own time in the same rows (goal <= 5 %);
* the same sweep on a local Ray instance (``num_cpus=2``) against the process pool (goal >= 0.9).

Run: ``.venv/bin/python bench/bench_sweep.py [--runs N] [--smoke]``.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCENARIO = f"{HERE / 'sweep_scenarios.py'}::drive"


def timed(out: Path, runs: int, seconds: float, jobs: int, ray: str | None = None) -> tuple[float, list[dict]]:
    from gazelle.sweep import sweep

    t0 = time.perf_counter()
    result = sweep(SCENARIO, [("seconds", [seconds])], list(range(runs)), out=out, jobs=jobs, ray=ray, report=False)
    wall = time.perf_counter() - t0
    assert all(r["status"] == "passed" for r in result.rows), [r["error"] for r in result.rows if r["error"]][:1]
    return wall, result.rows


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", type=int, default=200, help="short runs per mode (default 200)")
    ap.add_argument("--smoke", action="store_true", help="a few runs of each (./test.sh)")
    ap.add_argument("--no-ray", action="store_true")
    a = ap.parse_args()
    runs = 4 if a.smoke else a.runs
    long_runs = 2 if a.smoke else 20
    t_all = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        one, _ = timed(base / "j1", runs, 0.5, 1)
        two, _ = timed(base / "j2", runs, 0.5, 2)
        print(
            f"{runs} runs of 0.5 s sim: -j 1 {one:.2f} s, -j 2 {two:.2f} s: -j 2 gives {one / two:.2f}x (goal >= 1.8)"
        )
        wall, rows = timed(base / "long", long_runs, 5.0, 1)
        inside = sum(r["wall_sec"] for r in rows)
        overhead = (wall - inside) / len(rows)
        per_run = statistics.median(r["wall_sec"] for r in rows)
        print(
            f"{long_runs} runs of 5 s sim on -j 1: {per_run:.2f} s a run inside the scenario, {overhead * 1000:.0f} ms "
            f"outside it = {overhead / per_run:.1%} overhead (goal <= 5 %)"
        )
        if not a.no_ray:
            import ray

            t0 = time.perf_counter()
            ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
            started = time.perf_counter() - t0
            try:
                on_ray, _ = timed(base / "ray", runs, 0.5, 2, ray="local")
                long_ray, _ = timed(base / "ray_long", long_runs, 5.0, 2, ray="local")
                long_pool, _ = timed(base / "pool_long", long_runs, 5.0, 2)
            finally:
                ray.shutdown()
            print(
                f"on a local Ray instance of 2 CPUs (started in {started:.1f} s): {runs} runs of 0.5 s sim in "
                f"{on_ray:.2f} s = {two / on_ray:.2f} of the pool's throughput; {long_runs} runs of 5 s sim "
                f"{long_ray:.2f} s against the pool's {long_pool:.2f} s = {long_pool / long_ray:.2f} (goal >= 0.9)"
            )
    print(f"bench took {time.perf_counter() - t_all:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

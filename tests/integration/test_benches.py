"""Benches cannot rot (issue 28): each bench that has a small mode runs here, the same code path at tiny
sizes, and must exit 0 with its closing line. bench_rtf.py crashed on main for a turn (it read a private
attribute whose keys changed) and nothing noticed."""

from __future__ import annotations

import subprocess
import sys

import pytest
from _paths import REPO

BENCHES = [
    (["bench_rtf.py", "--smoke"], "ratios vs raw Python-loop mj_step"),
    (["bench_control.py", "--smoke"], "ratio JTC + JSB / limp, cycles in blocks"),
    (
        ["bench_multi_robot.py", "--counts", "1", "--seconds", "0.5", "--steps", "200", "--no-rss", "--arms", "2"],
        "bench took",
    ),
    (["bench_spawn.py", "--reps", "1"], "spawn_many"),
    (["bench_planning.py", "--goals", "1", "--ik", "5", "--random-goals", "2", "--no-sim"], "bench took"),
    (["bench_load.py", "-n", "1"], "slowest load"),
    (["bench_caster.py", "--smoke"], "bench took"),
    (["bench_introspection.py", "--smoke"], "messages the plain subscriber got that the bag lacks"),
    (["bench_launch.py", "--smoke"], "best "),
    (["bench_sensors.py", "--smoke"], "bench took"),
    (["bench_robot_ci.py", "--smoke"], "bench took"),
    (["bench_robot_ci_agreement.py", "--smoke"], "bench took"),
    (["bench_sweep.py", "--smoke", "--no-ray"], "bench took"),
    (["bench_viewer.py", "--seconds", "0.5", "--rounds", "1", "--scenario", "flat"], "bench took"),
]


@pytest.mark.parametrize("args,closing", BENCHES, ids=[b[0][0] for b in BENCHES])
def test_the_bench_runs_in_its_small_mode(args: list[str], closing: str) -> None:
    out = subprocess.run(
        [sys.executable, str(REPO / "bench" / args[0]), *args[1:]],
        capture_output=True,
        text=True,
        timeout=180,
        cwd=REPO,
    )
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-3000:]
    assert closing in out.stdout, out.stdout[-2000:]

"""Load and compile times of real robot descriptions, against the 0.5 s load target.

Run: ``.venv/bin/python bench/bench_load.py [-n RUNS]``. For each description: the first load in
this process (cold: imports, mesh reads, caches empty) and the mean/min of the next RUNS loads;
then the same for compiling it into the physics world (a fresh ``Simulation(default_world())``
plus ``spawn``; the first compile reads the collision meshes, later ones hit the mesh cache).
Needs the shared real fixtures (/work/shared/fixtures/real or $GAZELLE_REAL_FIXTURES).
"""

from __future__ import annotations

import argparse
import logging
import os
import statistics
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from _paths import REAL  # noqa: E402

TARGET_SEC = 0.5

# (label, GAZELLE_RESOURCE_PATH, file); relative paths are under REAL, the seed robot is in the repo
CASES = [
    ("TurtleBot3 xacro", "turtlebot3", "turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro"),
    (
        "TurtleBot3 model.sdf",
        "turtlebot3/turtlebot3_gazebo/models",
        "turtlebot3/turtlebot3_gazebo/models/turtlebot3_burger/model.sdf",
    ),
    ("Panda URDF", "moveit_panda", "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf"),
    ("Panda xacro", "moveit_panda", "moveit_panda/moveit_resources_panda_description/urdf/panda.urdf.xacro"),
    ("Panda SRDF", "moveit_panda", "moveit_panda/moveit_resources_panda_moveit_config/config/panda.srdf"),
    ("seed robot xacro", "", str(REPO / "examples/simple_robot/simple_robot/robot.urdf.xacro")),
]


def timed(fn) -> tuple[float, object]:
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-n", "--runs", type=int, default=20, help="warm runs per measurement (default 20)")
    opts = parser.parse_args()
    if not REAL.is_dir():
        print(f"real fixtures not found at {REAL}", file=sys.stderr)
        return 1
    logging.disable(logging.CRITICAL)  # plugin notices from spawn (e.g. ROS 1 diff-drive params in TB3 noetic)

    t_import, _ = timed(lambda: __import__("gazelle.description"))
    from gazelle.description import Model, Pose, load
    from gazelle.sim import Simulation
    from gazelle.worlds import default_world

    print(f"import gazelle.description: {t_import * 1000:.0f} ms (not counted below)")
    print(f"{opts.runs} warm runs each; target {TARGET_SEC:.1f} s per load\n")
    header = (
        f"{'description':<22} {'load 1st':>9} {'mean':>8} {'min':>8} {'x target':>9}"
        f"  {'compile 1st':>11} {'mean':>8} {'min':>8}"
    )
    print(header)
    print("-" * len(header))
    worst = 0.0
    t_all = time.perf_counter()
    for label, res, rel in CASES:
        os.environ["GAZELLE_RESOURCE_PATH"] = str(REAL / res) if res else ""
        path = Path(rel) if os.path.isabs(rel) else REAL / rel
        first, result = timed(lambda path=path: load(path))
        warm = [timed(lambda path=path: load(path))[0] for _ in range(opts.runs)]
        value = result.value  # type: ignore[attr-defined]
        mean = statistics.fmean(warm)
        worst = max(worst, first, mean)
        row = (
            f"{label:<22} {first * 1000:>7.1f}ms {mean * 1000:>6.1f}ms {min(warm) * 1000:>6.1f}ms"
            f" {mean / TARGET_SEC:>9.3f}"
        )
        if isinstance(value, Model):

            def compile_once(value: Model = value) -> None:
                sim = Simulation(default_world(), rtf=0)
                sim.spawn(value, name="bench", pose=Pose((0.0, 0.0, 0.5)))

            c_first, _ = timed(compile_once)
            c_warm = [timed(compile_once)[0] for _ in range(opts.runs)]
            c_mean = statistics.fmean(c_warm)
            row += f"  {c_first * 1000:>9.1f}ms {c_mean * 1000:>6.1f}ms {min(c_warm) * 1000:>6.1f}ms"
        else:
            row += f"  {'n/a (' + type(value).__name__ + ')':>29}"
        print(row)
    print("-" * len(header))
    print(
        f"slowest load (first or mean): {worst * 1000:.1f} ms = {worst / TARGET_SEC:.3f} x the"
        f" {TARGET_SEC:.1f} s target"
        f" ({'OK' if worst <= TARGET_SEC else 'OVER TARGET'}); bench took {time.perf_counter() - t_all:.1f} s"
    )
    return 0 if worst <= TARGET_SEC else 1


if __name__ == "__main__":
    raise SystemExit(main())

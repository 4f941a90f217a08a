"""Issue 31: ROS scenarios in a sweep. A scenario whose first argument is ``gazelle_sim`` runs on the
robot-test fixtures' server (``gazelle sim`` on a ROS domain of its own, localhost discovery, paused and
stepped by the scenario), two at a time without hearing each other; a run that does not pass leaves its
replay, its bag and the server's log, linked from its row and the report."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from _paths import REPO

pytestmark = pytest.mark.slow

SCENARIO = """
from pathlib import Path
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

ROBOT = Path({robot!r})


def drive(gazelle_sim, params, seed):
    ros = gazelle_sim.ros
    gazelle_sim.spawn(ROBOT, "robot", pose=(0.0, 0.0, 0.07))
    odom = ros.subscribe("/odom", Odometry)
    gazelle_sim.run_for(0.2)
    cmd = ros.publisher("/cmd_vel", Twist)
    twist = Twist()
    twist.linear.x = float(params["v"])
    cmd.publish(twist)
    gazelle_sim.run_until(lambda: odom.last is not None and odom.last.twist.twist.linear.x > 0.5 * twist.linear.x,
                          timeout=5.0, what="moving")
    end = gazelle_sim.run_for(2.0)
    # the odometry of that moment (on a busy machine /odom can be heard after /clock)
    stamp = lambda m: m.header.stamp.sec + 1e-9 * m.header.stamp.nanosec
    ros.wait_until(lambda: stamp(odom.last) >= end - 0.011, 30, "/odom at the end")
    x = odom.last.pose.pose.position.x
    # every run drove alone: no other run's robot, no other run's command on this domain
    publishers = ros.node.count_publishers("/cmd_vel")
    return {{"x": x, "cmd_vel_publishers": publishers, "passed": x < float(params["limit"])}}


drive.record = ["/odom", "/cmd_vel"]
"""


def test_ros_scenarios_run_two_at_a_time_each_on_its_own_domain_and_failures_keep_their_artifacts(
    tmp_path: Path,
) -> None:
    robot = REPO / "examples" / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
    scenario = tmp_path / "ros_scenario.py"
    scenario.write_text(SCENARIO.format(robot=str(robot)))
    out = tmp_path / "out"
    run = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{scenario}::drive", "--param", "v=0.1,0.3"]
        + ["--param", "limit=0.5", "--seeds", "0", "-j", "2", "--out", str(out), "--timeout", "120"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 1, run.stdout[-3000:] + run.stderr[-3000:]  # the fast one fails on purpose
    rows = {r["param.v"]: r for r in map(json.loads, (out / "runs.jsonl").read_text().splitlines())}
    slow, fast = rows[0.1], rows[0.3]
    assert slow["status"] == "passed", slow
    assert fast["status"] == "failed", fast
    assert 0.15 < slow["metric.x"] < 0.3 and 0.5 < fast["metric.x"] < 0.8, rows
    assert slow["metric.cmd_vel_publishers"] == fast["metric.cmd_vel_publishers"] == 1
    assert slow["sim_sec"] > 2.0
    # the failing run's replay, bag and log, linked from its row (and from the report, which links rows)
    for kind in ("replay", "bag", "log"):
        assert (out / fast[f"artifact.{kind}"]).exists(), fast
    assert (out / fast["artifact.bag"] / "metadata.yaml").is_file()
    assert not any(k.startswith("artifact.") for k in slow)
    assert fast["artifact.replay"] in (out / "report.html").read_text()


def test_the_turtlebot3_example_sweep_runs_over_start_poses_and_lidar_noise(tmp_path: Path) -> None:
    """examples/sweeps/turtlebot3_goal.py, two of its runs: TurtleBot3 (its real files, in its own world)
    reaches the goal between the pillars; its lidar with noise reads nearer than without."""
    from _paths import REAL

    env = {**os.environ, "TURTLEBOT3_GAZEBO": str(REAL / "turtlebot3" / "turtlebot3_gazebo")}
    out = tmp_path / "tb3"
    run = subprocess.run(
        [sys.executable, "-m", "gazelle.cli", "sweep", f"{REPO}/examples/sweeps/turtlebot3_goal.py::reach_goal"]
        + ["--param", "start_y=-0.5", "--param", "lidar_noise=0,0.05", "--seeds", "0", "-j", "2", "--out", str(out)],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    rows = {r["param.lidar_noise"]: r for r in map(json.loads, (out / "runs.jsonl").read_text().splitlines())}
    assert all(r["metric.reached"] and r["metric.final_error_m"] < 0.1 for r in rows.values()), rows
    assert 0.25 < rows[0]["metric.nearest_range_m"] < 0.4  # the nearest pillar on its way, as in the robot test
    assert rows[0.05]["metric.nearest_range_m"] < rows[0]["metric.nearest_range_m"]

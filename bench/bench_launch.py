#!/usr/bin/env python3
"""Wall time from `ros2 launch simple_robot robot_gazebo.launch.py` (the seed blog's workspace, built
with colcon) to the robot's first /odom message, three runs. Goal: under 3 s (Gazebo Classic takes
several seconds to start)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))


def main() -> int:
    import rclpy
    from _domain import private_ros_domain
    from nav_msgs.msg import Odometry

    from tests.integration.test_blog_workspace import VENV_ACTIVATE, write_blog_workspace

    private_ros_domain()
    os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    env = {k: v for k, v in os.environ.items() if k not in ("AMENT_PREFIX_PATH", "PYTHONPATH")}
    with tempfile.TemporaryDirectory() as tmp:
        ws = write_blog_workspace(Path(tmp))
        subprocess.run(
            ["bash", "-c", f"source {VENV_ACTIVATE} && cd {ws} && colcon build --symlink-install"],
            check=True,
            capture_output=True,
            env=env,
        )
        rclpy.init()
        node = rclpy.create_node("bench_launch")
        times = []
        runs = 1 if "--smoke" in sys.argv[1:] else 3  # ./test.sh runs one
        for run in range(runs):
            got: list[float] = []
            sub = node.create_subscription(Odometry, "/odom", lambda _m, got=got: got.append(time.perf_counter()), 10)
            t0 = time.perf_counter()
            proc = subprocess.Popen(
                [
                    "bash",
                    "-c",
                    f"source {VENV_ACTIVATE} && cd {ws} && source install/setup.bash && "
                    "exec ros2 launch simple_robot robot_gazebo.launch.py",
                ],
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
                env=env,
                start_new_session=True,
            )
            deadline = t0 + 60
            while not got and time.perf_counter() < deadline:
                rclpy.spin_once(node, timeout_sec=0.01)
            if got:
                times.append(got[0] - t0)
                print(f"run {run + 1}: first /odom {got[0] - t0:.2f} s after ros2 launch")
            else:
                print(f"run {run + 1}: no /odom within 60 s")
            os.killpg(proc.pid, signal.SIGINT)
            proc.wait(15)
            node.destroy_subscription(sub)
            time.sleep(1.0)  # the previous server's DDS participants leave the graph
        node.destroy_node()
        rclpy.shutdown()
    if times:
        print(f"best {min(times):.2f} s, median {sorted(times)[len(times) // 2]:.2f} s (goal < 3 s)")
    return 0 if times else 1


if __name__ == "__main__":
    raise SystemExit(main())

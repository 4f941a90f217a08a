"""A ROS sweep scenario: TurtleBot3 (its real files, in its own world) reaches a goal between the pillars
under the robot-test package's P-controller node (a plain rclpy program), over start poses and lidar
noise.

    TURTLEBOT3_GAZEBO=/path/to/turtlebot3_simulations/turtlebot3_gazebo \\
    gazelle sweep examples/sweeps/turtlebot3_goal.py::reach_goal --param start_y=-0.7:-0.3:5 \\
        --param lidar_noise=0,0.01,0.03,0.05 --seeds 0:2 -j 2 --out out/sweep_tb3

A ROS scenario takes the robot-test fixtures' server as its first argument (``gazelle_sim``: ``gazelle
sim`` on a ROS domain of its own, discovery on localhost, paused, stepped by the scenario in sim time;
``spawn``, ``run``, ``launch``, ``run_until``, and ``gazelle_sim.ros``, the scenario's rclpy node). A run
that does not pass leaves its replay, a bag of ``record``'s topics and the server's log, linked from the
report.

Metrics: whether it got within 0.2 m of the goal in 60 s of sim time, when, its final distance once
stopped, and the nearest lidar range on the way (passed: reached, and never nearer than 0.15 m).
"""

import math
import os
import sys
import tempfile
from pathlib import Path

TURTLEBOT3 = Path(os.environ.get("TURTLEBOT3_GAZEBO", "turtlebot3_gazebo"))
os.environ.setdefault("GAZEBO_MODEL_PATH", str(TURTLEBOT3 / "models"))  # its model:// URIs, as its launch says
GO_TO_GOAL = Path(__file__).resolve().parents[1] / "robot_tests" / "robot_tests" / "go_to_goal.py"
GOAL = (-0.55, -0.55)
"""In the world: the middle of four pillars."""


def burger_with_lidar_noise(stddev: float) -> Path:
    """TurtleBot3 burger's model.sdf with Gaussian noise of ``stddev`` metres on its lidar's ranges."""
    text = (TURTLEBOT3 / "models" / "turtlebot3_burger" / "model.sdf").read_text()
    if stddev > 0:
        noise = f"<noise><type>gaussian</type><mean>0.0</mean><stddev>{stddev}</stddev></noise>"
        head, sep, tail = text.partition("</range>")
        text = head + sep + noise + tail
    folder = Path(tempfile.mkdtemp(prefix="tb3_noise_"))
    (folder / "model.sdf").write_text(text)
    return folder / "model.sdf"


def reach_goal(gazelle_sim, params, seed):
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import LaserScan

    ros = gazelle_sim.ros
    x0, y0 = float(params.get("start_x", -2.0)), float(params.get("start_y", -0.5))
    gazelle_sim.spawn(burger_with_lidar_noise(float(params.get("lidar_noise", 0.0))), "burger", pose=(x0, y0, 0.01))
    odom = ros.subscribe("/odom", Odometry)
    scans = ros.subscribe("/scan", LaserScan, reliable=False)
    gx, gy = GOAL[0] - x0, GOAL[1] - y0  # the goal in the odometry frame, which starts where the robot does
    gazelle_sim.run(
        [sys.executable, str(GO_TO_GOAL), "--ros-args", "-p", "use_sim_time:=true"]
        + ["-p", f"goal_x:={gx}", "-p", f"goal_y:={gy}"],
        name="go_to_goal",
    )
    ros.wait_until(lambda: ros.node.count_publishers("/cmd_vel") > 0, 30, "the go_to_goal node")

    def distance():
        if odom.last is None:
            return math.inf
        p = odom.last.pose.pose.position
        return math.hypot(p.x - gx, p.y - gy)

    t0 = gazelle_sim.time
    reached = True
    try:
        gazelle_sim.run_until(lambda: distance() < 0.2, timeout=60.0, what="within 0.2 m of the goal")
    except AssertionError:
        reached = False
    when = gazelle_sim.time - t0
    if reached:  # until the controller stops it, 10 ms at a time (turning in place towards the goal is not stopped)
        gazelle_sim.run_until(
            lambda: (
                len(odom.messages) > 10
                and all(
                    abs(m.twist.twist.linear.x) < 1e-3 and abs(m.twist.twist.angular.z) < 1e-3
                    for m in odom.messages[-10:]
                )
            ),
            timeout=20.0,
            what="the robot to stop",
            step=0.01,
        )
    ranges = [r for s in scans.messages for r in s.ranges if s.range_min <= r <= s.range_max]
    nearest = min(ranges, default=math.inf)
    return {
        "reached": reached,
        "time_to_goal_s": when if reached else math.nan,
        "final_error_m": distance(),
        "nearest_range_m": nearest,
        "passed": reached and nearest > 0.15,
    }


# the scenario's world, and the topics a run that does not pass keeps in its bag and replay
reach_goal.world = TURTLEBOT3 / "worlds" / "turtlebot3_world.world"
reach_goal.record = ["/odom", "/cmd_vel", "/scan"]

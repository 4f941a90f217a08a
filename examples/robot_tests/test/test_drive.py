"""Robot tests of this package, on gazelle's pytest fixtures: they never import gazelle.

`gazelle_sim` is a headless simulation on a private ROS domain, paused: time moves only when the test
says (`run_for`, `run_until`), as fast as the machine allows, and every timeout below is sim time, so
the tests mean the same on a slow CI runner. A failing test leaves a bag of /odom, /cmd_vel, /tf and
/clock, and the server's log, under gazelle-artifacts/ (the report names the folder and the seed).
"""

import math
import os
import sys
from pathlib import Path

import pytest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

HERE = Path(__file__).resolve().parent
GO_TO_GOAL = HERE.parent / "robot_tests" / "go_to_goal.py"
# the robot under test: the seed blog's robot, beside this package in gazelle's examples/
SEED_ROBOT = HERE.parents[1] / "simple_robot" / "simple_robot" / "robot.urdf.xacro"
# TurtleBot3 from its own repository (ROBOTIS-GIT/turtlebot3_simulations), where the user has it
TURTLEBOT3 = os.environ.get("TURTLEBOT3_GAZEBO", "")
TB3_WORLD = Path(TURTLEBOT3) / "worlds" / "turtlebot3_world.world" if TURTLEBOT3 else None
if TURTLEBOT3:  # where its world's model://turtlebot3_world is, as its launch files say to Gazebo
    os.environ.setdefault("GAZEBO_MODEL_PATH", str(Path(TURTLEBOT3) / "models"))


def distance(odom, x, y):
    if odom is None:
        return math.inf
    p = odom.pose.pose.position
    return math.hypot(p.x - x, p.y - y)


def start_go_to_goal(gazelle_sim, ros, x, y):
    gazelle_sim.run(
        [
            sys.executable,
            str(GO_TO_GOAL),
            "--ros-args",
            "-p",
            "use_sim_time:=true",
            "-p",
            f"goal_x:={x}",
            "-p",
            f"goal_y:={y}",
        ],
        name="go_to_goal",
    )
    # the node is up once it publishes /cmd_vel and listens to /odom
    ros.wait_until(lambda: ros.node.count_publishers("/cmd_vel") > 0, 30, "the go_to_goal node")


@pytest.mark.gazelle(record=["/odom", "/cmd_vel"])
def test_the_seed_robot_drives_to_a_goal(gazelle_sim, ros):
    gazelle_sim.spawn(SEED_ROBOT, "simple_robot", pose=(0.0, 0.0, 0.07))
    odom = ros.subscribe("/odom", Odometry)
    start_go_to_goal(gazelle_sim, ros, 1.0, 0.5)
    gazelle_sim.run_until(lambda: distance(odom.last, 1.0, 0.5) < 0.2, timeout=60.0, what="within 0.2 m of (1, 0.5)")


@pytest.mark.skipif(not TURTLEBOT3, reason="set TURTLEBOT3_GAZEBO to turtlebot3_simulations/turtlebot3_gazebo")
@pytest.mark.gazelle(world=TB3_WORLD, record=["/odom", "/cmd_vel", "/scan"])
def test_turtlebot3_reaches_a_goal_and_its_lidar_never_sees_anything_nearer_than_15_cm(gazelle_sim, ros):
    """In its own world, from where turtlebot3_world.launch.py puts it (-2, -0.5), between the pillars to
    (-0.55, -0.55), the middle of four pillars: (1.45, -0.05) in its odometry frame."""
    model = Path(TURTLEBOT3) / "models" / "turtlebot3_burger" / "model.sdf"
    gazelle_sim.spawn(model, "burger", pose=(-2.0, -0.5, 0.01))
    odom = ros.subscribe("/odom", Odometry)
    scans = ros.subscribe("/scan", LaserScan, reliable=False)
    start_go_to_goal(gazelle_sim, ros, 1.45, -0.05)
    gazelle_sim.run_until(lambda: distance(odom.last, 1.45, -0.05) < 0.2, timeout=60.0, what="within 0.2 m of the goal")
    assert len(scans) > 10
    nearest = min(
        min((r for r in s.ranges if s.range_min <= r <= s.range_max), default=math.inf) for s in scans.messages
    )
    assert nearest > 0.15, f"the lidar saw something {nearest:.3f} m away"

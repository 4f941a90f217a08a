"""Robot tests of this package, on gazelle's pytest fixtures: they never import gazelle.

`gazelle_sim` is a headless simulation on a private ROS domain, paused: time moves only when the test
says (`run_for`, `run_until`), as fast as the machine allows, and every timeout below is sim time, so
the tests mean the same on a slow CI runner. A failing test leaves a bag of /odom, /cmd_vel, /tf and
/clock, a replay page and the server's log, under gazelle-artifacts/ (the report names the folder and the
seed). Each test records its measured figures with pytest's ``record_property`` (in ``--junitxml``'s
report), so runs on different machines can be compared.
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
# the seed blog's own node: 5 s forward at 0.2 m/s, a quarter turn at 0.5 rad/s, again
SQUARE_NODE = SEED_ROBOT.parent / "square_movement.py"
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


def stopped(odom):
    """Whether the last ten odometry messages say the robot stands still."""
    last = odom.messages[-10:]
    return len(last) == 10 and all(
        abs(m.twist.twist.linear.x) < 1e-3 and abs(m.twist.twist.angular.z) < 1e-3 for m in last
    )


def settle_and_measure(gazelle_sim, odom, x, y):
    """After the robot came within 0.2 m: until the controller stopped it (stepping 10 ms at a time, so
    the node's last commands land within 10 ms of when it sent them); its final distance."""
    gazelle_sim.run_until(lambda: stopped(odom), timeout=20.0, what="the robot to stop at the goal", step=0.01)
    return distance(odom.last, x, y)


@pytest.mark.gazelle(record=["/odom", "/cmd_vel"])
def test_the_seed_robot_drives_to_a_goal(gazelle_sim, ros, record_property):
    gazelle_sim.spawn(SEED_ROBOT, "simple_robot", pose=(0.0, 0.0, 0.07))
    odom = ros.subscribe("/odom", Odometry)
    start_go_to_goal(gazelle_sim, ros, 1.0, 0.5)
    gazelle_sim.run_until(lambda: distance(odom.last, 1.0, 0.5) < 0.2, timeout=60.0, what="within 0.2 m of (1, 0.5)")
    record_property("final_error_m", round(settle_and_measure(gazelle_sim, odom, 1.0, 0.5), 4))


def corners(samples):
    """Where a square's robot turned: the mean position of each run of /odom samples turning in place."""
    found, run = [], []
    for msg in samples:
        turning = abs(msg.twist.twist.angular.z) > 0.25 and abs(msg.twist.twist.linear.x) < 0.02
        if turning:
            run.append((msg.pose.pose.position.x, msg.pose.pose.position.y))
        elif run:
            found.append(tuple(sum(c) / len(run) for c in zip(*run)))
            run = []
    if run:
        found.append(tuple(sum(c) / len(run) for c in zip(*run)))
    return found


@pytest.mark.gazelle(record=["/odom", "/cmd_vel"])
def test_the_seed_robot_drives_its_square_with_sides_within_3_cm(gazelle_sim, ros, record_property):
    """The seed blog's square_movement node, unchanged but for its max_sides parameter (one square): each
    side 1 m (5 s at 0.2 m/s), within 3 cm. The world steps 10 ms at a time, so the node's commands,
    timed on sim time, take effect at most 10 ms (2 mm of driving) late."""
    gazelle_sim.spawn(SEED_ROBOT, "simple_robot", pose=(0.0, 0.0, 0.07))
    odom = ros.subscribe("/odom", Odometry)
    gazelle_sim.run_for(0.2)
    start = (odom.last.pose.pose.position.x, odom.last.pose.pose.position.y)
    node = gazelle_sim.run(
        [sys.executable, str(SQUARE_NODE), "--ros-args", "-p", "use_sim_time:=true", "-p", "max_sides:=4"],
        name="square_movement",
    )
    ros.wait_until(lambda: ros.node.count_publishers("/cmd_vel") > 0, 30, "the square_movement node")
    # four sides of 5 s and four turns of 3.14 s: the node stops the robot and exits after the last
    gazelle_sim.run_until(
        lambda: node.popen.poll() is not None,
        timeout=45.0,
        what="one square",
        step=0.01,
    )
    assert node.popen.returncode == 0, node.tail()
    gazelle_sim.run_for(0.5)  # the last turn ends
    points = [start, *corners(odom.messages)]
    assert len(points) == 5, f"{len(points) - 1} corners found, not 4: {points}"
    sides = [math.dist(a, b) for a, b in zip(points, points[1:])]
    record_property("sides_m", ",".join(f"{s:.4f}" for s in sides))
    assert all(abs(s - 1.0) < 0.03 for s in sides), f"sides {sides} (1 m each)"


@pytest.mark.skipif(not TURTLEBOT3, reason="set TURTLEBOT3_GAZEBO to turtlebot3_simulations/turtlebot3_gazebo")
@pytest.mark.gazelle(world=TB3_WORLD, record=["/odom", "/cmd_vel", "/scan"])
def test_turtlebot3_reaches_a_goal_and_its_lidar_never_sees_anything_nearer_than_15_cm(
    gazelle_sim, ros, record_property
):
    """In its own world, from where turtlebot3_world.launch.py puts it (-2, -0.5), between the pillars to
    (-0.55, -0.55), the middle of four pillars: (1.45, -0.05) in its odometry frame."""
    model = Path(TURTLEBOT3) / "models" / "turtlebot3_burger" / "model.sdf"
    gazelle_sim.spawn(model, "burger", pose=(-2.0, -0.5, 0.01))
    odom = ros.subscribe("/odom", Odometry)
    scans = ros.subscribe("/scan", LaserScan, reliable=False)
    start_go_to_goal(gazelle_sim, ros, 1.45, -0.05)
    gazelle_sim.run_until(lambda: distance(odom.last, 1.45, -0.05) < 0.2, timeout=60.0, what="within 0.2 m of the goal")
    record_property("final_error_m", round(settle_and_measure(gazelle_sim, odom, 1.45, -0.05), 4))
    assert len(scans) > 10
    nearest = min(
        min((r for r in s.ranges if s.range_min <= r <= s.range_max), default=math.inf) for s in scans.messages
    )
    record_property("nearest_range_m", round(nearest, 4))
    assert nearest > 0.15, f"the lidar saw something {nearest:.3f} m away"

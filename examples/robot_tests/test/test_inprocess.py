"""A test of the in-process API: the seed robot's square with no ROS at all (no DDS between the test and
the simulation). ``gazelle_world`` is a simulation inside the test's process that the test steps itself;
commands go on the simulation's bus as the ROS bridge would put them there. With nothing crossing a
process, a run is bit-identical to every other run with the same seed: the test records the digest of
the world's final state, and of the states it passed through, for comparison across runs and machines.
"""

import hashlib
import math
from pathlib import Path

from gazelle.systems import Twist

SEED_ROBOT = Path(__file__).resolve().parents[2] / "simple_robot" / "simple_robot" / "robot.urdf.xacro"


def test_the_seed_robots_square_in_process_is_the_same_every_run(gazelle_world, record_property):
    gazelle_world.spawn(SEED_ROBOT, "simple_robot", pose=(0.0, 0.0, 0.07))
    odom = gazelle_world.subscribe("/odom")
    gazelle_world.run_for(0.5)
    trail = hashlib.sha256()
    start = gazelle_world.pose("simple_robot")
    corners = []
    for _ in range(4):  # the seed's square: 5 s at 0.2 m/s, a quarter turn at 0.5 rad/s
        gazelle_world.publish("/cmd_vel", Twist(linear=(0.2, 0.0, 0.0)))
        for _ in range(50):
            gazelle_world.run_for(0.1)
            trail.update(gazelle_world.state_digest().encode())
        gazelle_world.publish("/cmd_vel", Twist(angular=(0.0, 0.0, 0.5)))
        gazelle_world.run_for(math.pi)
        corners.append(gazelle_world.pose("simple_robot"))
    gazelle_world.publish("/cmd_vel", Twist())
    gazelle_world.run_for(0.5)
    record_property("states_sha256", trail.hexdigest())
    record_property("final_sha256", gazelle_world.state_digest())
    points = [start, *corners]
    sides = [math.dist(a[:2], b[:2]) for a, b in zip(points, points[1:])]
    record_property("sides_m", ",".join(f"{s:.4f}" for s in sides))
    assert all(abs(s - 1.0) < 0.03 for s in sides), f"sides {sides} (1 m each)"
    assert len(odom) > 100 and odom.last.pose.position[0] == odom.last.pose.position[0]  # odometry published

"""A ROS-less sweep scenario: the seed robot drives one side of its square (0.2 m/s for 5 s) and turns
(0.5 rad/s for pi seconds) with its wheels' friction and a slip of its caster-less base varied.

    gazelle sweep examples/sweeps/square.py::square --param wheel_mu=0.3,0.6,1.0 --param speed=0.1:0.3:5 \\
        --seeds 0:8 -j 2 --out out/sweep_square

Metrics: the side's length, the heading after the turn (degrees) and whether both are within 5 %.
"""

import math
from pathlib import Path

from gazelle import DiffDrive, Pose, ResourceResolver, Simulation, load_string, quat_to_rpy

ROBOT = Path(__file__).resolve().parents[1] / "simple_robot" / "simple_robot" / "robot.urdf.xacro"


def robot_with_wheel_friction(mu: float):
    """The seed robot with its wheels' <mu1>/<mu2> set to ``mu`` (a model to spawn)."""
    text = ROBOT.read_text().replace("<mu1>1.0</mu1>", f"<mu1>{mu}</mu1>").replace("<mu2>1.0</mu2>", f"<mu2>{mu}</mu2>")
    # xacro text read from our own file: expanded, reading only next to it
    resolver = ResourceResolver().trusting(ROBOT.parent)
    return load_string(text, format="urdf", source=str(ROBOT), expand_xacro=True, resolver=resolver).value


def square(sim: Simulation, params: dict, seed: int) -> dict:
    mu = float(params.get("wheel_mu", 1.0))
    speed = float(params.get("speed", 0.2))
    model = robot_with_wheel_friction(mu)
    # the seed varies where the robot starts, by up to 5 mm and 2 degrees
    jitter = ((seed * 7919) % 101 - 50) / 10_000
    yaw0 = math.radians(((seed * 104729) % 41 - 20) / 10)
    entity = sim.spawn(
        model, name="robot", pose=Pose((jitter, -jitter, 0.07), (math.cos(yaw0 / 2), 0.0, 0.0, math.sin(yaw0 / 2)))
    )
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    sim.step(500)
    p0 = sim.world.entity_state("robot").pose.position
    drive.command(speed, 0.0)
    sim.step(round(1.0 / speed / sim.world.timestep))  # commanded: 1 m
    p1 = sim.world.entity_state("robot").pose.position
    yaw1 = quat_to_rpy(sim.world.entity_state("robot").pose.orientation)[2]
    drive.command(0.0, 0.5)
    sim.step(round(math.pi / sim.world.timestep))  # commanded: 90 degrees
    drive.command(0.0, 0.0)
    sim.step(200)
    yaw2 = quat_to_rpy(sim.world.entity_state("robot").pose.orientation)[2]
    side = math.hypot(p1[0] - p0[0], p1[1] - p0[1])
    turn = math.degrees(math.remainder(yaw2 - yaw1, 2 * math.pi))
    return {"side_m": side, "turn_deg": turn, "passed": abs(side - 1.0) <= 0.05 and abs(turn - 90.0) <= 4.5}

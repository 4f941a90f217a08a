"""Determinism: the same inputs and command sequence under lock-step stepping give bit-identical trajectories."""

from __future__ import annotations

import numpy as np
from _paths import BOX, SEED_XACRO
from _sim import new_simulation

from gazelle.description import Pose, load, load_string
from gazelle.systems.diff_drive import DiffDrive


def run() -> list[np.ndarray]:
    """Spawn a robot, drive it through a command sequence, spawn and delete boxes on the way."""
    robot = load(SEED_XACRO).model
    box = load_string(BOX).model
    sim = new_simulation()
    entity = sim.spawn(robot, name="robot", pose=Pose((0.0, 0.0, 0.05)))
    drive = next(s for s in entity.systems if isinstance(s, DiffDrive))
    sim.spawn(box, name="crate", pose=Pose((1.0, 0.5, 0.3)))
    trace: list[np.ndarray] = []
    commands = [(0.2, 0.4), (0.5, -0.3), (0.0, 1.0), (-0.2, 0.0), (0.3, 0.3)]
    for i, (v, w) in enumerate(commands):
        drive.command(v, w)
        for _ in range(10):
            sim.step(50)
            trace.append(np.concatenate([sim.world.data.qpos, sim.world.data.qvel]).copy())
        if i == 1:
            sim.spawn(box, name="dropped", pose=Pose((-1.0, 0.0, 1.0), (0.92, 0.2, 0.3, 0.1)))
        if i == 3:
            sim.delete("dropped")
            sim.delete("crate")
    return trace


def test_two_runs_are_bit_identical() -> None:
    a, b = run(), run()
    assert len(a) == len(b) == 50
    for k, (x, y) in enumerate(zip(a, b)):
        assert x.shape == y.shape, k
        # bitwise: compare the raw float64 bits, so even -0.0/0.0 or NaN payloads would differ
        assert np.array_equal(x.view(np.uint64), y.view(np.uint64)), f"trajectories differ at sample {k}"
    # the robot really moved and the world really changed size in between
    assert not np.array_equal(a[0], a[-1])
    assert len({x.shape for x in a}) >= 2


def test_querying_state_does_not_change_the_trajectory(make_sim) -> None:
    """Reading poses (which refreshes derived kinematics) between steps leaves the trajectory bit-identical."""
    box = load_string(BOX).model

    def go(query: bool) -> np.ndarray:
        sim = make_sim()
        sim.spawn(box, name="b", pose=Pose((0.0, 0.0, 0.5), (0.9, 0.3, 0.2, 0.1)))
        for _ in range(200):
            sim.step(5)
            if query:
                sim.world.entity_state("b")
        return np.concatenate([sim.world.data.qpos, sim.world.data.qvel])

    assert np.array_equal(go(False).view(np.uint64), go(True).view(np.uint64))

#!/usr/bin/env python3
"""ros2_control's cost, as ratios measured in one run (issue 13's target).

r6bot (ros2_control_demos example 7) following a looping joint trajectory under
joint_trajectory_controller at a 1 kHz ``update_rate`` (with joint_state_broadcaster at 1 kHz,
listened to), against the same robot with no controllers:

* "no ros2_control": its ``<ros2_control>`` block taken out, so no manager runs and the joints hang
  limp (the issue's baseline);
* "manager, no controller": the manager running its 1 kHz cycle with nothing loaded (the joints held).

Two floors, the least any per-step Python cycle can cost: a bare loop (one ``ctrl`` write and one
``mj_step``, outside the runtime), and the manager's own share of a cycle done as barely as it can be
inside the runtime (a system at 1 kHz that reads the six positions and velocities in one array read
each, writes the six held targets in one write, and publishes one JointState to a listener; no
controller logic).

Goal: RTF under JTC at least 0.8 of the no-controller RTF. Every system runs in-process on
``sim.step`` (``rtf`` 0).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))

from _paths import REAL  # noqa: E402

R6BOT = REAL / "ros2_control_r6bot"
URDF = R6BOT / "_xacro_expanded" / "r6bot.urdf"
JOINTS = tuple(f"joint_{i}" for i in range(1, 7))
YAML = """
controller_manager:
  ros__parameters:
    update_rate: 1000
jsb:
  ros__parameters:
    type: joint_state_broadcaster/JointStateBroadcaster
jtc:
  ros__parameters:
    type: joint_trajectory_controller/JointTrajectoryController
    joints: [joint_1, joint_2, joint_3, joint_4, joint_5, joint_6]
    command_interfaces: [position]
    state_interfaces: [position, velocity]
"""


def make(kind: str):
    from gazelle.description import load
    from gazelle.sim import Simulation
    from gazelle.systems.ros2_control import ControllerManager, parse_params
    from gazelle.worlds import default_world

    model = load(URDF).value
    if kind == "none":
        model = dataclasses.replace(model, ros2_control=())
    sim = Simulation(default_world(), rtf=0)
    entity = sim.spawn(model, name="r6bot")
    if kind == "none":
        return sim, None
    cm = next(s for s in entity.systems if isinstance(s, ControllerManager))
    cm.files.append(parse_params(YAML))
    cm.update_rate = 1000
    if kind == "jtc":
        for name in ("jsb", "jtc"):
            cm.load_controller(name)
            cm.configure_controller(name)
        cm.switch_controller(["jsb", "jtc"], [])
        for ep in sim.bus.endpoints():
            if ep.topic == "/joint_states":
                ep.add_sink(lambda _m: None)  # listened to: every message is built
        return sim, cm.controllers["jtc"].controller
    return sim, None


def trajectory(start: float):
    from gazelle.systems import JointTrajectory, TrajectoryPoint

    points = tuple(
        TrajectoryPoint(0.1 * k, tuple(0.5 * math.sin(0.1 * k * (1 + 0.2 * i)) for i in range(6)))
        for k in range(1, 101)
    )
    return JointTrajectory(start, JOINTS, points)


def rtf_of(kind: str, seconds: float) -> float:
    sim, jtc = make(kind)
    sim.step(200)
    best = 0.0
    for _ in range(3):
        if jtc is not None:
            from gazelle.systems.ros2_control import TrajectoryGoal

            jtc.submit(TrajectoryGoal(trajectory(0.0)))
        n = round(seconds / sim.world.timestep)
        t0 = time.perf_counter()
        sim.step(n)
        best = max(best, seconds / (time.perf_counter() - t0))
    return best


def floor_rtf(seconds: float) -> float:
    """The fastest any per-step Python cycle can go: the same world stepped one ``mj_step`` at a time with
    one vector write of the six position targets between steps, and nothing else (no controller logic)."""
    import mujoco
    import numpy as np

    sim, _ = make("idle")
    m, d = sim.world.model, sim.world.data
    ctrl = np.array(d.ctrl[:6])
    n = round(seconds / sim.world.timestep)
    best = 0.0
    for _ in range(3):
        t0 = time.perf_counter()
        for _ in range(n):
            d.ctrl[:6] = ctrl
            mujoco.mj_step(m, d)
        best = max(best, seconds / (time.perf_counter() - t0))
    return best


def runtime_floor_rtf(seconds: float) -> float:
    """The second floor (see the module's docstring): the limp robot plus one bare 1 kHz system."""
    from gazelle.systems import JointStates, MsgType, RateGate, System

    sim, _ = make("none")
    world = sim.world
    group = world.joint_group("r6bot", JOINTS)
    ep = sim.bus.advertise("r6bot", "/floor/joint_states", MsgType.JOINT_STATE)
    ep.add_sink(lambda _m: None)
    # the limp robot has no actuators: the write goes to the six joints' applied forces (zeros, so the
    # dynamics are the limp robot's), one indexed write as the hardware's write of its servos is
    dofs, applied = group.dof_indices(), world.data.qfrc_applied
    zeros = (0.0,) * 6

    class Floor(System):
        def __init__(self) -> None:
            self.phase_gate = self.gate = RateGate()

        def pre_update(self, info, world) -> None:
            t = info.sim_time_sec
            if not self.gate.due(t, 1000.0):
                return
            pos, vel = group.positions().tolist(), group.velocities().tolist()
            applied[dofs] = zeros
            ep.publish(JointStates(t, JOINTS, tuple(pos), tuple(vel), zeros))

    sim.systems.add("r6bot", Floor())
    sim.step(200)
    n = round(seconds / sim.world.timestep)
    best = 0.0
    for _ in range(3):
        t0 = time.perf_counter()
        sim.step(n)
        best = max(best, seconds / (time.perf_counter() - t0))
    return best


def main() -> int:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--seconds", type=float, default=5.0, help="sim-seconds of each run (default 5)")
    parser.add_argument("--smoke", action="store_true", help="the same code path at tiny sizes (./test.sh runs it)")
    opts = parser.parse_args()
    logging.disable(logging.WARNING)
    os.environ["GAZELLE_RESOURCE_PATH"] = str(R6BOT)
    seconds = 0.05 if opts.smoke else opts.seconds
    none = rtf_of("none", seconds)
    idle = rtf_of("idle", seconds)
    jtc = rtf_of("jtc", seconds)
    floor = floor_rtf(seconds)
    runtime_floor = runtime_floor_rtf(seconds)
    print(f"r6bot, 1 ms physics steps, best of 3 runs of {seconds:g} sim-seconds each")
    print(f"{'case':58s} {'RTF':>8s}")
    print(f"{'no ros2_control (joints limp)':58s} {none:7.1f}x")
    print(f"{'controller manager at 1 kHz, no controller (joints held)':58s} {idle:7.1f}x")
    print(f"{'JTC + joint_state_broadcaster at 1 kHz, following a path':58s} {jtc:7.1f}x")
    print(f"{'floor: a bare Python loop, one ctrl write + mj_step per step':58s} {floor:7.1f}x")
    print(f"{'floor: no ros2_control + a bare 1 kHz read, write, JointState':58s} {runtime_floor:7.1f}x")
    print(f"ratio JTC / no ros2_control: {jtc / none:.2f} (goal >= 0.8)")
    print(
        f"ratio bare loop / no ros2_control: {floor / none:.2f} (no runtime and no cycle: the held arm's steps alone)"
    )
    print(
        f"ratio bare 1 kHz cycle in the runtime / no ros2_control: {runtime_floor / none:.2f} "
        "(the best a cycle the runtime calls every step, with joint states at 1 kHz, can do)"
    )
    print(f"ratio JTC / manager without controllers: {jtc / idle:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

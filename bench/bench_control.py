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

Goal: RTF under JTC at least 0.8 of the no-controller RTF. The in-process rows run every system on
``sim.step`` (``rtf`` 0), the JTC row's /joint_states to an in-process callback, which takes each message
built on the simulation thread. The ROS rows (the issue's goal) put the world on ROS (``RosBridge``) and
run the simulation thread at ``rtf`` 0: the limp arm with nobody subscribed, and the arm under JTC + JSB
with a plain rclpy process counting every /joint_states message (reliable, deep queue): its messages are
built on the bridge's publisher thread (the 1 kHz cycles run inside MuJoCo in blocks, issue 29), and the
listener must receive as many as the bridge published.
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

# a private ROS graph on this host only, before anything imports rclpy
from _domain import private_ros_domain  # noqa: E402
from _r6bot import JOINTS, R6BOT, URDF, manager_of  # noqa: E402

private_ros_domain()
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"

LISTENER = """
import select, sys, time
import rclpy
from rclpy.qos import QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import JointState
rclpy.init()
node = rclpy.create_node("bench_joint_states_listener")
n = [0]
sub = node.create_subscription(JointState, "/joint_states", lambda m: n.__setitem__(0, n[0] + 1),
                               QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE))
deadline = time.monotonic() + 30.0
while sub.get_publisher_count() < 1 and time.monotonic() < deadline:  # matched with the simulation's
    rclpy.spin_once(node, timeout_sec=0.05)
print("ready", flush=True)
while not select.select([sys.stdin], [], [], 0)[0]:  # until the parent closes our stdin
    rclpy.spin_once(node, timeout_sec=0.05)
for _ in range(100):  # what is still in flight
    rclpy.spin_once(node, timeout_sec=0.01)
print(n[0], flush=True)
"""


class MessageBuilder:
    """A consumer thread that makes every payload it is handed ready to publish, as the ROS bridge's
    publisher thread does: a block of joint states serialized from its template, a single payload built
    into a ROS sensor_msgs/JointState."""

    def __init__(self) -> None:
        import queue
        import threading

        self.queue: queue.SimpleQueue = queue.SimpleQueue()
        self.built = 0
        threading.Thread(target=self._run, daemon=True).start()

    def put(self, payload) -> None:
        self.queue.put(payload)

    def _run(self) -> None:
        from builtin_interfaces.msg import Time
        from sensor_msgs.msg import JointState

        from gazelle.ros import serialized_joint_states
        from gazelle.systems import JointStatesBlock

        while True:
            payload = self.queue.get()
            if isinstance(payload, JointStatesBlock):
                self.built += len(serialized_joint_states(payload) or ())
                continue
            js = payload
            sec = int(js.stamp_sec)
            msg = JointState()
            msg.header.stamp = Time(sec=sec, nanosec=int((js.stamp_sec - sec) * 1e9))
            msg.name = list(js.names)
            msg.position, msg.velocity, msg.effort = list(js.positions), list(js.velocities), list(js.efforts)
            self.built += 1


def make(kind: str, sink: str = "message", blocks: bool = True):
    """r6bot in a world: ``kind`` "none" (no ros2_control), "idle" (the manager, no controller) or "jtc";
    /joint_states to ``sink``: "message" (an in-process callback taking each message, built on the
    simulation thread), "thread" (a second thread that readies every message as the bridge does) or "none";
    ``blocks``: the manager may run its cycles in blocks (else every cycle in Python, as before issue 29)."""
    from gazelle.description import load
    from gazelle.sim import Simulation
    from gazelle.worlds import default_world

    model = load(URDF).value
    if kind == "none":
        model = dataclasses.replace(model, ros2_control=())
    sim = Simulation(default_world(), rtf=0)
    entity = sim.spawn(model, name="r6bot")
    if kind == "none":
        return sim, None
    cm = manager_of(entity, blocks=blocks, controllers=("jsb", "jtc") if kind == "jtc" else ())
    if kind == "jtc":
        for ep in sim.bus.endpoints():
            if ep.topic != "/joint_states":
                continue
            if sink == "message":
                ep.add_sink(lambda _m: None)
            elif sink == "thread":
                ep.add_sink(MessageBuilder().put, blocks=True)
        return sim, cm.controllers["jtc"].controller
    return sim, None


def trajectory(start: float):
    from gazelle.systems import JointTrajectory, TrajectoryPoint

    points = tuple(
        TrajectoryPoint(0.1 * k, tuple(0.5 * math.sin(0.1 * k * (1 + 0.2 * i)) for i in range(6)))
        for k in range(1, 101)
    )
    return JointTrajectory(start, JOINTS, points)


def rtf_of(kind: str, seconds: float, sink: str = "message", blocks: bool = True) -> float:
    sim, jtc = make(kind, sink, blocks)
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


def run_threaded(sim, seconds: float) -> tuple[float, float]:
    """Run on the simulation thread (``rtf`` 0) for ``seconds`` of wall time: (sim seconds, wall seconds)."""
    t0, w0 = sim.world.time, time.monotonic()
    sim.start()
    time.sleep(seconds)
    sim.stop()
    return sim.world.time - t0, time.monotonic() - w0


def ros_rtf(kind: str, seconds: float) -> tuple[float, str]:
    """The RTF with the world on ROS: the limp arm with nobody subscribed ("none"), or the arm under JTC +
    JSB with a plain rclpy process counting /joint_states ("jtc"); and a note of what was heard."""
    import subprocess

    from gazelle.ros import RosBridge
    from gazelle.systems.ros2_control import TrajectoryGoal

    sim, jtc = make(kind, sink="none")
    sim.step(200)
    bridge = RosBridge(sim, clock_rate_hz=100.0)
    try:
        if jtc is None:
            s, w = max((run_threaded(sim, seconds) for _ in range(3)), key=lambda r: r[0] / r[1])
            return s / w, f"{s:.1f} sim s in {w:.1f} wall s, best of 3"
        proc = subprocess.Popen(
            [sys.executable, "-c", LISTENER], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True
        )
        try:
            assert proc.stdout is not None
            proc.stdout.readline()  # "ready": it has matched the simulation's publisher
            box = bridge.node.outbox
            jtc.submit(TrajectoryGoal(trajectory(0.0)))
            p0 = box.published
            s, w = run_threaded(sim, seconds)
            box.flush(10.0)
            published = box.published - p0
            out, _ = proc.communicate(timeout=20)
            heard = int(out.strip().splitlines()[-1])
            cycles = round(s / sim.world.timestep)
            return s / w, (
                f"{s:.1f} sim s in {w:.1f} wall s; {cycles} cycles, bridge published {published} messages "
                f"(/clock included), dropped {box.dropped}; the listener heard {heard} /joint_states"
            )
        finally:
            if proc.poll() is None:
                proc.kill()
    finally:
        bridge.shutdown()


ARMS_LISTENER = """
import select, sys, time
import rclpy
from rclpy.qos import QoSProfile, ReliabilityPolicy
from sensor_msgs.msg import JointState
rclpy.init()
node = rclpy.create_node("bench_arms_listener")
n = [0]
subs = [node.create_subscription(JointState, f"/r{i}/joint_states", lambda m: n.__setitem__(0, n[0] + 1),
                                 QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE))
        for i in range(int(sys.argv[1]))]
deadline = time.monotonic() + 30.0
while min(s.get_publisher_count() for s in subs) < 1 and time.monotonic() < deadline:
    rclpy.spin_once(node, timeout_sec=0.05)
print("ready", sum(1 for s in subs if s.get_publisher_count()), flush=True)
while not select.select([sys.stdin], [], [], 0)[0]:
    rclpy.spin_once(node, timeout_sec=0.05)
for _ in range(100):
    rclpy.spin_once(node, timeout_sec=0.01)
print(n[0], flush=True)
"""


def arms_at_real_time(count: int, seconds: float, blocks: bool = True) -> tuple[float, str]:
    """``count`` namespaced r6bots (``/rN``), each under JTC + JSB at 1 kHz following a path, on ROS at
    ``--rtf 1`` for ``seconds`` of wall time, a plain rclpy process listening to every /rN/joint_states:
    the RTF held, the server's CPU, and how many joint states were published and heard."""
    import resource
    import subprocess

    from gazelle.description import Pose, load
    from gazelle.ros import RosBridge
    from gazelle.sim import Simulation
    from gazelle.systems.ros2_control import TrajectoryGoal
    from gazelle.worlds import default_world

    model = load(URDF).model
    sim = Simulation(default_world(), rtf=0)
    managers, controllers = [], []
    for i in range(count):
        entity = sim.spawn(model, name=f"r{i}", namespace=f"r{i}", pose=Pose((2.0 * i, 0.0, 0.0)))
        cm = manager_of(entity, blocks=blocks)
        managers.append(cm)
        controllers.append(cm.controllers["jtc"].controller)
    sim.step(200)
    sim.rtf = 1.0
    bridge = RosBridge(sim, clock_rate_hz=100.0)
    proc = subprocess.Popen(
        [sys.executable, "-c", ARMS_LISTENER, str(count)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True
    )
    try:
        assert proc.stdout is not None
        matched = int(proc.stdout.readline().split()[1])  # "ready N": N topics matched
        for jtc in controllers:
            jtc.submit(TrajectoryGoal(trajectory(0.0)))
        box = bridge.node.outbox
        s0 = sim.world.time
        c0 = sum(cm.block_cycles for cm in managers)
        ru0 = resource.getrusage(resource.RUSAGE_SELF)
        sim_s, wall_s = run_threaded(sim, seconds)
        ru1 = resource.getrusage(resource.RUSAGE_SELF)
        box.flush(20.0)
        cpu = (ru1.ru_utime + ru1.ru_stime - ru0.ru_utime - ru0.ru_stime) / wall_s
        out, _ = proc.communicate(timeout=60)
        heard = int(out.strip().splitlines()[-1])
        produced = round((sim.world.time - s0) / sim.world.timestep) * count  # one JointState per arm per cycle
        cycles = sum(cm.block_cycles for cm in managers) - c0
        return sim_s / wall_s, (
            f"RTF {sim_s / wall_s:.3f}; server {cpu * 100:.0f} % of a core; "
            f"{produced} joint states produced, {heard} heard by one rclpy "
            f"process ({matched}/{count} topics matched), none dropped: {box.dropped}; {cycles} cycles in blocks"
        )
    finally:
        if proc.poll() is None:
            proc.kill()
        bridge.shutdown()


def main() -> int:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--seconds", type=float, default=5.0, help="sim-seconds of each run (default 5)")
    parser.add_argument("--smoke", action="store_true", help="the same code path at tiny sizes (./test.sh runs it)")
    parser.add_argument("--arms", type=int, default=10, help="r6bots at --rtf 1 in the last row (default 10)")
    opts = parser.parse_args()
    logging.disable(logging.WARNING)
    os.environ["GAZELLE_RESOURCE_PATH"] = str(R6BOT)
    seconds = 0.05 if opts.smoke else opts.seconds
    none = rtf_of("none", seconds)
    idle = rtf_of("idle", seconds)
    before = rtf_of("jtc", seconds, blocks=False)
    jtc = rtf_of("jtc", seconds)
    threaded = rtf_of("jtc", seconds, sink="thread")
    floor = floor_rtf(seconds)
    runtime_floor = runtime_floor_rtf(seconds)
    wall = 0.3 if opts.smoke else 3.0
    ros_none, ros_none_note = ros_rtf("none", wall)
    ros_jtc, ros_jtc_note = ros_rtf("jtc", wall)
    arms = 2 if opts.smoke else opts.arms
    arms_rtf, arms_note = arms_at_real_time(arms, 0.5 if opts.smoke else 5.0)
    rows = [
        ("no ros2_control (joints limp)", none, ""),
        ("controller manager at 1 kHz, no controller (joints held)", idle, "cycles in blocks"),
        ("JTC + JSB at 1 kHz, a cycle in Python per step", before, "as before issue 29"),
        ("JTC + JSB at 1 kHz, cycles in blocks", jtc, "each message built on the sim thread"),
        ("JTC + JSB at 1 kHz, blocks, messages on a 2nd thread", threaded, "serialized as the bridge does"),
        ("floor: a bare Python loop, one ctrl write + mj_step", floor, ""),
        ("floor: limp + a bare 1 kHz Python read, write, JointState", runtime_floor, ""),
        ("over ROS: limp, nobody subscribed", ros_none, ros_none_note),
        ("over ROS: JTC + JSB, /joint_states heard", ros_jtc, ros_jtc_note),
        (f"over ROS at --rtf 1: {arms} arms, JTC + JSB, all heard", arms_rtf, arms_note),
    ]
    print(f"r6bot, 1 ms physics steps, best of 3 runs of {seconds:g} sim-seconds each (over ROS: {wall:g} wall s)")
    print(f"{'case':58s} {'RTF':>8s}  note")
    for label, rtf, note in rows:
        print(f"{label:58s} {rtf:7.1f}x  {note}")
    print(
        f"ratio JTC + JSB / limp, cycles in blocks: {jtc / none:.2f} "
        f"(goal >= 0.8; a Python cycle per step: {before / none:.2f})"
    )
    print(
        f"ratio JTC + JSB / limp, blocks, messages readied on a second thread: {threaded / none:.2f} "
        "(that thread's Python holds the GIL the simulation thread needs between blocks)"
    )
    print(f"ratio over ROS, JTC + JSB heard / limp nobody subscribed: {ros_jtc / ros_none:.2f}")
    print(f"ratio bare loop / limp: {floor / none:.2f} (no runtime and no cycle: the held arm's steps alone)")
    print(
        f"ratio bare 1 kHz Python cycle in the runtime / limp: {runtime_floor / none:.2f} "
        "(the best a per-step Python cycle with joint states at 1 kHz can do)"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

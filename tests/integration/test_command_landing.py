"""Issue 50, item 1: a command the test publishes before ``run_for`` acts from that ``run_for``'s first
step, and the failure bag holds it.

The test's node publishes ``/cmd_vel`` to the seed robot's diff drive (100 Hz: it reads its command at
every 10 ms of sim time, the first of them at the run's first step) right after the robot is spawned, 50
times, and right after a ``run_for``, 50 times. Each time the wheels' first joint states after it must
show the new command (a command one step late would act only at the drive's next update, 10 ms later,
and the wheels would still turn as before), and the bag must hold the command, received by the recorder
before the world stepped on (no /clock tick past the command's time before it). Before the fix, 24 and
32 of the 100 acted a step or more late (the issue's drive: 0.01-0.93 s of sim time late beside a CPU
hog), and the recorder logged a command after the next /clock tick, or lost what it had not yet taken
when it was stopped."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from _paths import SEED_XACRO
from geometry_msgs.msg import Twist
from rclpy.serialization import deserialize_message
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState
from simulation_interfaces.srv import DeleteEntity, SpawnEntity

from gazelle.ros._spawn_entity import _xml_from_file
from gazelle.testing import MessageLog, RosTestNode, Sim, reserve_domain

pytestmark = pytest.mark.slow
RUNS = 50
SPEED = 0.2
"""m/s: the seed robot's wheels (radius 0.05 m) then turn at 4 rad/s."""
WHEEL_RADIUS = 0.05


def seed_robot_with_wheel_states() -> tuple[str, str]:
    """The seed robot's URDF, its diff drive also publishing the wheels' joint states (at its 100 Hz), and
    an anchor: the same robot with wheel joints of other names, commanded on another topic. The anchor stays
    while the robot is spawned and deleted, and so does the /joint_states publisher the two share (the
    ``/differential_drive`` node's): the test hears the first joint states of each new robot."""

    def plugin_with(xml: str, extra: str) -> str:
        out, n = re.subn(r'(<plugin [^>]*name="differential_drive"[^>]*>)', r"\1" + extra, xml)
        assert n == 1, "the seed robot's diff drive plugin"
        return out

    urdf = plugin_with(_xml_from_file(str(SEED_XACRO)), "<publish_wheel_joint_state>true</publish_wheel_joint_state>")
    anchor = urdf.replace("base_left_wheel_joint", "anchor_left").replace("base_right_wheel_joint", "anchor_right")
    return urdf, plugin_with(anchor, "<ros><remapping>cmd_vel:=anchor_cmd_vel</remapping></ros>")


def spawn(ros: RosTestNode, name: str, urdf: str, y: float = 0.0) -> None:
    req = SpawnEntity.Request(name=name, resource_string=urdf)
    req.initial_pose.pose.position.y = y
    req.initial_pose.pose.position.z = 0.07
    reply = ros.call("/gazelle/spawn_entity", SpawnEntity, req)
    assert reply.result.result == 1, reply.result.error_message


def stamp(msg: JointState) -> float:
    return msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9


def robots(log: MessageLog) -> list[JointState]:
    """The robot's joint states (not the anchor's) the test has heard so far."""
    return [m for m in list(log.messages) if "base_left_wheel_joint" in m.name]


def wheel_speed(msg: JointState) -> float:
    return sum(abs(v) for v in msg.velocity) / len(msg.velocity)


def first_after(sim: Sim, states: MessageLog, t0: float) -> JointState:
    """The robot's first joint states stamped after ``t0``, once the test has them: those of the diff drive's
    update at ``t0`` (the run's first step), published after the steps that followed it."""
    return sim.ros.wait_until(
        lambda: next((m for m in robots(states) if stamp(m) > t0 + 1e-6), None),
        30,
        f"the wheels' joint states after {t0:.3f} s",
    )


def commanded(pub: Any, speed: float) -> Twist:
    msg = Twist()
    msg.linear.x = speed
    pub.publish(msg)
    return msg


def late(sim: Sim, states: MessageLog, t0: float, before: float, speed: float) -> str | None:
    """Why the command published at ``t0`` (wheels at ``before`` rad/s) did not act from the next step, or
    None: the wheels' first joint states after ``t0`` have gone a quarter of the way or more from ``before``
    to the command's speed (measured: half of it after one 1 ms step, 90 % after ten). A command that missed
    the update at ``t0`` acts only at the next, 10 ms later: these would still show ``before``."""
    target = speed / WHEEL_RADIUS
    first = first_after(sim, states, t0)
    after = wheel_speed(first)
    if abs(after - target) <= 0.75 * abs(before - target):
        return None
    return f"at {t0:.3f} s: {speed} m/s, the wheels at {after:.3f} rad/s at {stamp(first):.3f} s (from {before:.3f})"


def recorded(bag: Path) -> tuple[list[tuple[int, float]], list[tuple[int, float]]]:
    """(log time, linear x) of each /cmd_vel and (log time, sim time) of each /clock in the bag."""
    from mcap.reader import make_reader

    cmds, clocks = [], []
    (path,) = bag.glob("*.mcap")
    with open(path, "rb") as f:
        for _schema, channel, message in make_reader(f).iter_messages(log_time_order=True):
            if channel.topic == "/cmd_vel":
                cmds.append((message.log_time, deserialize_message(message.data, Twist).linear.x))
            elif channel.topic == "/clock":
                c = deserialize_message(message.data, Clock).clock
                clocks.append((message.log_time, c.sec + c.nanosec * 1e-9))
    return cmds, clocks


def after_run_for(sim: Sim, pub: Any, states: MessageLog, runs: int, sent: list[tuple[float, float]]) -> list[str]:
    """``runs`` commands, each right after a run_for (stop, go, stop, ...); why each acted late, if it did."""
    wrong = []
    for i in range(runs):
        speed = SPEED * (i % 2)
        t0 = sim.time
        held = sim.ros.wait_until(lambda t0=t0: [m for m in robots(states) if stamp(m) >= t0 - 1e-6], 30, "states")
        sent.append((t0, speed))
        commanded(pub, speed)
        sim.run_for(0.05)
        wrong.append(late(sim, states, t0, wheel_speed(held[-1]), speed) or "")
    return [w for w in wrong if w]


@pytest.fixture(params=["idle", "beside a CPU hog"])
def load(request: pytest.FixtureRequest) -> Iterator[str]:
    """The machine as the test finds it, or with a process spinning on a core for the whole test (the issue
    asks for both: before the fix the hog made commands land up to 0.93 s of sim time late)."""
    if request.param == "idle":
        yield request.param
        return
    hog = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        yield request.param
    finally:
        hog.kill()
        hog.wait()


def test_a_command_published_before_run_for_acts_from_its_first_step_and_is_in_the_bag(
    tmp_path: Path, load: str
) -> None:
    """50 commands right after a spawn (and its deletion), 50 right after a run_for; idle and beside a CPU
    hog."""
    urdf, anchor = seed_robot_with_wheel_states()
    domain = reserve_domain()
    sim = Sim(domain_id=domain.domain_id, record=(tmp_path / "bag", ["/cmd_vel"]))
    ros = sim.ros
    sent: list[tuple[float, float]] = []
    """(sim time, speed) of each command, in order"""
    wrong: list[str] = []
    try:
        states = ros.subscribe("/joint_states", JointState)
        spawn(ros, "anchor", anchor, y=3.0)
        sim.run_until(lambda: len(states) > 0, 5.0, "the anchor's joint states at the test")
        spawn(ros, "robot", urdf)  # as the test: the robot's /cmd_vel is there before the test's publisher
        pub = ros.publisher("/cmd_vel", Twist)
        ros.wait_until(lambda: pub.get_subscription_count() >= 2, 10, "the diff drive and the bag recorder")
        for i in range(RUNS):  # right after a spawn: the server's subscription is new
            if i:
                ros.call("/gazelle/delete_entity", DeleteEntity, DeleteEntity.Request(entity="robot"))
                # the deleted robot's subscription gone, so that the wait below is for the new one's
                ros.wait_until(lambda: pub.get_subscription_count() == 1, 10, "the old robot's subscription gone")
                spawn(ros, "robot", urdf)
                ros.wait_until(lambda: pub.get_subscription_count() == 2, 10, "the diff drive on /cmd_vel")
            t0 = sim.time
            sent.append((t0, SPEED))
            commanded(pub, SPEED)
            sim.run_for(0.02)
            wrong.append(late(sim, states, t0, 0.0, SPEED) or "")
        wrong = [w for w in wrong if w] + after_run_for(sim, pub, states, RUNS, sent)
    finally:
        sim.close()
        domain.release()
    assert not wrong, f"{len(wrong)} of {2 * RUNS} commands acted late:\n" + "\n".join(wrong[:10])
    cmds, clocks = recorded(tmp_path / "bag")
    assert [v for _t, v in cmds] == [v for _t, v in sent], f"the bag holds {len(cmds)} of {len(sent)} commands"
    early = []
    for (logged, _v), (t0, _speed) in zip(cmds, sent):
        ahead = [c for when, c in clocks if when < logged and c > t0 + 1e-6]  # sim time only goes on here
        if ahead:
            early.append(f"command of {t0:.3f} s recorded after /clock {ahead[-1]:.3f} s")
    assert not early, "\n".join(early[:10])


def test_a_command_acts_from_the_first_step_however_late_the_server_s_executor_takes_it() -> None:
    """The server's executor made slow on purpose (its test hook: 0.2 s before it begins each subscription
    callback): the step service takes the command itself before it steps. Without that, the executor and
    the step service are not ordered, and beside a CPU hog 1 command in 300 acted a step late."""
    urdf, _anchor = seed_robot_with_wheel_states()
    domain = reserve_domain()
    env = {**os.environ, "GAZELLE_TEST_INBOUND_DELAY_SEC": "0.2"}
    sim = Sim(domain_id=domain.domain_id, env=env)
    try:
        states = sim.ros.subscribe("/joint_states", JointState)
        spawn(sim.ros, "robot", urdf)
        sim.run_until(lambda: robots(states), 5.0, "the robot's joint states at the test")
        pub = sim.ros.publisher("/cmd_vel", Twist)
        sim.ros.wait_for_subscribers(pub)
        wrong = after_run_for(sim, pub, states, 10, [])
    finally:
        sim.close()
        domain.release()
    assert not wrong, f"{len(wrong)} of 10 commands acted late:\n" + "\n".join(wrong)


def test_the_recorder_writes_what_its_reader_holds_when_it_is_stopped(tmp_path: Path) -> None:
    """A recorder that fell behind and is stopped (here: SIGSTOP while the test published 10 messages, then
    Ctrl-C as it resumes) writes what its reader received before it ends. It took rclpy's signal handler's
    shutdown of its context as the end and wrote nothing more: a test's bag beside a CPU hog ended 1.8 s of
    sim time early, without the test's last command."""
    from std_msgs.msg import String

    from gazelle.testing._sim import ChildProcess

    domain = reserve_domain()
    node = RosTestNode(domain.domain_id)
    env = {**os.environ, "ROS_DOMAIN_ID": str(domain.domain_id), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
    rec = None
    try:
        pub = node.publisher("/chatter", String)
        argv = [str(Path(sys.prefix) / "bin" / "ros2"), "bag", "record", "-o", str(tmp_path / "bag"), "/chatter"]
        rec = ChildProcess("ros2 bag record", argv, env)
        node.wait_until(lambda: pub.get_subscription_count() >= 1, 30, "the recorder on /chatter")
        os.kill(rec.popen.pid, signal.SIGSTOP)
        for i in range(10):  # the publisher keeps 10 (its depth) to send again once the recorder answers
            pub.publish(String(data=str(i)))
        os.kill(rec.popen.pid, signal.SIGINT)
        os.kill(rec.popen.pid, signal.SIGCONT)
        assert rec.wait(30) == 0, rec.tail()
    finally:
        if rec is not None:
            rec.stop()
        node.close()
        domain.release()
    from mcap.reader import make_reader

    (path,) = (tmp_path / "bag").glob("*.mcap")
    with open(path, "rb") as f:
        got = [deserialize_message(m.data, String).data for _s, _c, m in make_reader(f).iter_messages()]
    assert got == [str(i) for i in range(10)], rec.tail() if rec is not None else ""

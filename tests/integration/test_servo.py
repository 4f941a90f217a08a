"""MoveIt Servo's servo_node (gazelle's, `ros2 run moveit_servo servo_node`) on MoveIt's Panda, with the
values of moveit_servo's own config/panda_simulated_config.yaml: a twist moves the flange at the commanded
speed along the commanded axis, a joint jog turns one joint, a command stops mattering once it is older
than incoming_command_timeout, a paused servo sends nothing, and a twist in a frame the robot does not
have is INVALID on ~/status. Time is the test's (gazelle_sim, lockstep): a command published before a
20 ms chunk acts in it, however busy the machine is."""

from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml
from _paths import REAL, REPO

pytest.importorskip("roboplan")
pytestmark = pytest.mark.slow  # a server, a spawn, the controllers and 3.6 s of sim time in 20 ms chunks: ~30 s

PANDA = REAL / "moveit_panda"
CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"
ON_TABLE = REPO / "examples" / "arms" / "panda_on_table.urdf.xacro"
ROS2 = str(Path(sys.prefix) / "bin" / "ros2")
SERVO = {  # moveit_servo/config/panda_simulated_config.yaml (Jazzy), the values servo_node reads
    "publish_period": 0.01,
    "max_expected_latency": 0.1,
    "command_in_type": "speed_units",
    "scale": {"linear": 0.2, "rotational": 0.8, "joint": 0.5},
    "command_out_type": "trajectory_msgs/JointTrajectory",
    "publish_joint_positions": True,
    "publish_joint_velocities": True,
    "publish_joint_accelerations": False,
    "use_smoothing": True,
    "smoothing_filter_plugin_name": "online_signal_smoothing::AccelerationLimitedPlugin",
    "move_group_name": "panda_arm",
    "lower_singularity_threshold": 10.0,
    "hard_stop_singularity_threshold": 30.0,
    "leaving_singularity_threshold_multiplier": 2.0,
    "joint_limit_margins": [0.12],
    "cartesian_command_in_topic": "~/delta_twist_cmds",
    "joint_command_in_topic": "~/delta_joint_cmds",
    "joint_topic": "/joint_states",
    "status_topic": "~/status",
    "command_out_topic": "/panda_arm_controller/joint_trajectory",
    "check_collisions": True,
}


@pytest.fixture
def panda_resources(monkeypatch):
    """Where package://moveit_resources_panda_description is, for the server (made after this) and xacro."""
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(PANDA))


@pytest.fixture
def servo(panda_resources, gazelle_sim, ros, tmp_path):
    """The Panda with its controllers and a servo_node, stepped by the test: (the arm's kinematics, the node)."""
    from gazelle.description import read_description_file
    from gazelle.planning import RobotScene, ServoKinematics

    gazelle_sim.spawn(ON_TABLE, "panda")
    spawner = gazelle_sim.run(
        [ROS2, "run", "controller_manager", "spawner", "joint_state_broadcaster", "panda_arm_controller"]
        + ["--param-file", str(CONFIG / "ros2_controllers.yaml")],
        name="spawner",
    )
    gazelle_sim.run_until(lambda: spawner.popen.poll() is not None, timeout=30.0, what="the spawner to finish")
    assert spawner.popen.returncode == 0, spawner.tail()
    params = tmp_path / "servo.yaml"
    params.write_text(yaml.safe_dump({"servo_node": {"ros__parameters": {"moveit_servo": SERVO}}}))
    node = gazelle_sim.run(
        [ROS2, "run", "moveit_servo", "servo_node", "--urdf", str(CONFIG / "panda.urdf.xacro")]
        + ["--srdf", str(CONFIG / "panda.srdf"), "--ros-args", "--params-file", str(params)]
        + ["-p", "use_sim_time:=true"],
        name="servo_node",
    )
    from moveit_msgs.srv import ServoCommandType

    ros.wait_for_service("/servo_node/switch_command_type", ServoCommandType, timeout=60)
    # the servo's trajectories go out on a volatile topic, and a drive is over in 1-2 s of wall time: one that
    # starts before the server's controller has discovered the servo's publisher loses its first commands
    # (the likeliest cause of one run's 15 mm rise for 50, not reproduced). The test's node sees both ends once
    # their announcements have gone round, which the server's take too
    out = SERVO["command_out_topic"]
    ros.wait_until(
        lambda: (
            any(i.node_name == "servo_node" for i in ros.node.get_publishers_info_by_topic(out))
            and ros.node.count_subscribers(out) >= 1
        ),
        timeout=30,
        what=f"the servo's publisher and the controller's subscriber on {out}",
    )
    scene = RobotScene(
        read_description_file(str(CONFIG / "panda.urdf.xacro")),
        (CONFIG / "panda.srdf").read_text(),
        resolve_mesh=lambda _u: None,
    )
    return ServoKinematics(scene, "panda_arm"), node


def _stamp(ros):
    from builtin_interfaces.msg import Time

    ns = int(round(ros.sim_time * 1e9))
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def _arm(joints, kinematics) -> np.ndarray:
    state = dict(zip(joints.last.name, joints.last.position))
    return np.array([state[n] for n in kinematics.joint_names])


def _switch(ros, kind: int) -> None:
    from moveit_msgs.srv import ServoCommandType

    assert ros.call(
        "/servo_node/switch_command_type", ServoCommandType, ServoCommandType.Request(command_type=kind)
    ).success


def _drive_report(sent, status, said: int, began: float) -> str:
    """What the servo published during a drive that began at sim time ``began``: how many trajectories the
    test heard and at which sim times (the largest gap between two), and the status codes it said."""
    times = [t - began for t in sent.sim_times]
    gaps = np.diff(times) if len(times) > 1 else np.array([0.0])
    codes = [s.code for s in status.messages[said:]]
    counts = {c: codes.count(c) for c in sorted(set(codes))}
    first = f"{times[0]:.3f}" if times else "-"
    last = f"{times[-1]:.3f}" if times else "-"
    return (
        f"{len(times)} trajectories heard (first at +{first} s, last at +{last} s, largest gap "
        f"{float(gaps.max()):.3f} s); status codes {counts}"
    )


def _drive(gazelle_sim, ros, pub, make, seconds: float) -> None:
    """Publish ``make()`` stamped now before each 20 ms chunk of sim time, for ``seconds``."""
    end = ros.sim_time + seconds
    while ros.sim_time < end - 1e-9:
        msg = make()
        msg.header.stamp = _stamp(ros)
        pub.publish(msg)
        gazelle_sim.run_for(0.02)


# Was flaky (first tries failed in 3 of 4 fresh clones of stop 49, the paused check reading 6-8 mrad of
# motion): `run_for(0.3)` was one step call, and the world ran its 0.3 s ahead of the servo node, whose last
# trajectories then reached the controller after the test had read the arm (measured: trajectories up to
# 0.51 s of sim time behind the world). run_for now steps in lockstep chunks as run_until does (at most
# 0.04 s behind, measured beside two CPU hogs). Twice, long ago and before the discovery wait, the flange
# rose 15.1 and 25.5 mm for 50 in idle runs; the drive report in the message would say why if it comes back.
def test_a_twist_moves_the_flange_along_it_a_jog_turns_a_joint_and_old_or_paused_commands_do_nothing(
    servo, gazelle_sim, ros
) -> None:
    from control_msgs.msg import JointJog
    from geometry_msgs.msg import TwistStamped
    from moveit_msgs.msg import ServoStatus
    from sensor_msgs.msg import JointState
    from std_srvs.srv import SetBool

    kinematics, node = servo
    joints = ros.subscribe("/joint_states", JointState)
    status = ros.subscribe("/servo_node/status", ServoStatus)
    gazelle_sim.run_until(
        lambda: joints.last is not None and len(status) > 0, timeout=10.0, what="joint states and servo status"
    )
    flange = lambda: kinematics.pose(_arm(joints, kinematics), "panda_link8")[:3, 3]
    twists = ros.publisher("/servo_node/delta_twist_cmds", TwistStamped)

    def up():
        msg = TwistStamped()
        msg.header.frame_id = "panda_link0"
        msg.twist.linear.z = 0.05  # m/s (speed_units), below scale.linear's 0.2
        return msg

    _switch(ros, 1)  # TWIST
    start = flange()
    # what the servo sent and said during the drive, to explain a failure (the flake above)
    from trajectory_msgs.msg import JointTrajectory

    sent = ros.subscribe(SERVO["command_out_topic"], JointTrajectory)
    said = len(status)
    began = ros.sim_time
    _drive(gazelle_sim, ros, twists, up, 1.0)
    gazelle_sim.run_for(0.3)  # the trajectory's last points (max_expected_latency ahead) play out
    moved = flange() - start
    # 1 s of commands, and the last one acts until it is older than incoming_command_timeout (0.1 s)
    # (and the trajectory the controller got a chunk late on a busy machine: up to 0.2 s more in all)
    assert 0.045 < moved[2] < 0.06, f"the flange rose {moved[2] * 1000:.1f} mm for 1 s at 50 mm/s; " + _drive_report(
        sent, status, said, began
    )
    assert math.hypot(moved[0], moved[1]) < 0.002, f"drifted {moved[:2] * 1000} mm sideways"

    # the same twist published once, then nothing: older than incoming_command_timeout (0.1 s), it halts
    rest = flange()
    _drive(gazelle_sim, ros, twists, up, 0.02)
    gazelle_sim.run_for(1.0)
    # 0.1-0.2 s of motion (5-10 mm; 8.4 mm measured beside a CPU hog), not the 1 s (50 mm) it would be
    assert np.linalg.norm(flange() - rest) < 0.015

    # joint jog: panda_joint1 at 0.2 rad/s for 0.5 s
    jogs = ros.publisher("/servo_node/delta_joint_cmds", JointJog)
    _switch(ros, 0)  # JOINT_JOG
    before = _arm(joints, kinematics)
    _drive(gazelle_sim, ros, jogs, lambda: JointJog(joint_names=["panda_joint1"], velocities=[0.2]), 0.5)
    gazelle_sim.run_for(0.3)
    turned = _arm(joints, kinematics) - before
    # 0.5 s of commands, and the last one acts until it is older than incoming_command_timeout (0.1 s)
    assert 0.09 < turned[0] < 0.135 and np.abs(turned[1:]).max() < 0.015, turned

    # paused: the commands are not acted on
    assert ros.call("/servo_node/pause_servo", SetBool, SetBool.Request(data=True)).success
    before = _arm(joints, kinematics)
    _drive(gazelle_sim, ros, jogs, lambda: JointJog(joint_names=["panda_joint1"], velocities=[0.2]), 0.3)
    assert np.abs(_arm(joints, kinematics) - before).max() < 1e-3
    assert ros.call("/servo_node/pause_servo", SetBool, SetBool.Request(data=False)).success

    # a twist in a frame the robot does not have: INVALID (-1) on ~/status, and nothing moves
    _switch(ros, 1)
    before = flange()

    def nowhere():
        msg = up()
        msg.header.frame_id = "no_such_frame"
        return msg

    status_count = len(status)
    _drive(gazelle_sim, ros, twists, nowhere, 0.1)
    gazelle_sim.run_for(0.1)
    assert any(s.code == -1 for s in status.messages[status_count:]), [s.code for s in status.messages[status_count:]]
    assert np.linalg.norm(flange() - before) < 1e-3
    output = node.output
    assert "does not check collisions" in output and "AccelerationLimitedPlugin is MoveIt's and is not loaded" in output
    assert "Could not transform twist command to planning frame." in output


def test_bad_parameters_are_one_line_and_status_1(panda_resources) -> None:
    import subprocess

    robot = ["--urdf", str(CONFIG / "panda.urdf.xacro"), "--srdf", str(CONFIG / "panda.srdf")]
    for extra, said in (
        ([], "moveit_servo.move_group_name is not set"),
        (["--ros-args", "-p", "moveit_servo.move_group_name:=legs"], "no planning group 'legs'"),
    ):
        out = subprocess.run(
            [ROS2, "run", "moveit_servo", "servo_node", *robot, *extra], capture_output=True, text=True, timeout=120
        )
        assert out.returncode == 1 and said in out.stderr and "Traceback" not in out.stderr, out.stderr
        assert out.stderr.strip().count("\n") == 0, out.stderr


def test_a_clock_that_goes_back_clears_the_window_and_starts_from_the_measured_state(panda_resources) -> None:
    """A simulation reset sends sim time back: the sliding window's states, stamped on the old time line,
    would otherwise stand for the robot's state for as long as that line was ahead (in-process: the node's
    clock set by hand, its output caught)."""
    import rclpy
    import rclpy.context
    from geometry_msgs.msg import TwistStamped
    from rclpy.clock import ROSClock
    from rclpy.parameter import Parameter
    from rclpy.time import Time
    from sensor_msgs.msg import JointState

    from gazelle.description import read_description_file
    from gazelle.ros._servo_node import ServoNode

    context = rclpy.context.Context()
    rclpy.init(context=context, domain_id=0)
    try:
        overrides = [
            Parameter("robot_description", value=read_description_file(str(CONFIG / "panda.urdf.xacro"))),
            Parameter("robot_description_semantic", value=(CONFIG / "panda.srdf").read_text()),
            Parameter("use_sim_time", value=True),
            Parameter("moveit_servo.move_group_name", value="panda_arm"),
            Parameter("moveit_servo.command_in_type", value="speed_units"),
        ]
        node = ServoNode(overrides, context=context)
        sent = []

        def caught(msg: Any) -> None:  # the trajectories, caught instead of published
            sent.append(msg)

        node._out.publish = caught
        ready = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]
        node._on_joints(JointState(name=[f"panda_joint{i}" for i in range(1, 8)], position=ready))
        node.command_type = 1
        clock = node.get_clock()
        assert isinstance(clock, ROSClock)  # use_sim_time: a clock whose time can be set

        def cycle_at(seconds: float) -> None:
            clock.set_ros_time_override(Time(seconds=seconds, clock_type=clock.clock_type))
            twist = TwistStamped()
            twist.header.frame_id = "panda_link0"
            twist.header.stamp = clock.now().to_msg()
            twist.twist.linear.z = 0.05
            node._on_command(1, twist)
            node._cycle()

        def commanded() -> float:  # how far the newest commanded state is from the measured one (rad)
            assert node._last_commanded is not None
            return float(abs(node._last_commanded.positions - ready).max())

        for k in range(20):
            cycle_at(100.0 + 0.01 * k)
        assert sent and commanded() > 0.02  # 20 cycles of commands integrated on the window's states
        for k in range(3):
            cycle_at(0.01 * k)  # reset: the clock is back at 0
        # integrated again from the measured (unchanged) state: three cycles' worth, not 23
        assert commanded() < 0.008, commanded()
        node.destroy_node()
    finally:
        rclpy.shutdown(context=context)

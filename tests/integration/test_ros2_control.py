"""ros2_control over ROS: the spawner against the simulated controller manager, real robots' files.

A `gazelle sim` server process, robots spawned with `gazelle spawn`, controllers started with
`gazelle spawner` (ros2_control's spawner command line), driven and watched by a plain rclpy node.
"""

from __future__ import annotations

import math
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from _harness import GAZELLE, run_or_dump, start, wait_for
from _paths import REAL as FIXTURES
from _paths import REPO
from control_msgs.action import FollowJointTrajectory
from controller_manager_msgs.srv import ListControllers, ListHardwareInterfaces, SwitchController
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.action.client import ActionClient
from sensor_msgs.msg import JointState
from simulation_interfaces.msg import SimulationState
from simulation_interfaces.srv import SetSimulationState, StepSimulation
from trajectory_msgs.msg import JointTrajectoryPoint

DIFFBOT = FIXTURES / "ros2_control_diffbot"
DIFFBOT_URDF = DIFFBOT / "_xacro_expanded" / "diffbot.urdf"
DIFFBOT_YAML = DIFFBOT / "ros2_control_demo_example_2" / "config" / "diffbot_controllers.yaml"
R6BOT = FIXTURES / "ros2_control_r6bot"
R6BOT_URDF = R6BOT / "_xacro_expanded" / "r6bot.urdf"
R6BOT_YAML = REPO / "tests" / "data" / "ros2_control" / "r6bot_jtc.yaml"


def _sim_time(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def _spawner(*args: str, timeout: float = 60) -> tuple[int, str]:
    proc = start([*GAZELLE, "spawner", *args], "spawner")
    rc = proc.wait(timeout)
    return rc, proc.output


def _spawn_diffbot(sim) -> None:
    """The real diffbot with its controllers YAML, the way launch files pass it (--ros-args --params-file
    on the spawn), its controller manager up."""
    spawn = start(
        [*GAZELLE, "spawn", "-entity", "diffbot", "-file", str(DIFFBOT_URDF), "-z", "0.05"]
        + ["--ros-args", "--params-file", str(DIFFBOT_YAML)],
        "spawn",
    )
    assert spawn.wait(60) == 0, spawn.output
    sim.wait_line("controller manager '/controller_manager'", 10)


@pytest.mark.slow
def test_diffbot_drives_with_its_own_controllers_yaml_and_the_spawner(sim_factory, ros_client):
    sim = sim_factory("--no-viewer")
    _spawn_diffbot(sim)  # the controllers YAML the way launch files pass it: --params-file on the spawn

    rc, out = _spawner("joint_state_broadcaster", "diffbot_base_controller")
    assert rc == 0, out
    assert "Configured and activated diffbot_base_controller" in out

    listed = ros_client.call(ListControllers, "/controller_manager/list_controllers", ListControllers.Request())
    states = {c.name: (c.state, c.type) for c in listed.controller}
    assert states == {
        "joint_state_broadcaster": ("active", "joint_state_broadcaster/JointStateBroadcaster"),
        "diffbot_base_controller": ("active", "diff_drive_controller/DiffDriveController"),
    }
    hw = ros_client.call(
        ListHardwareInterfaces, "/controller_manager/list_hardware_interfaces", ListHardwareInterfaces.Request()
    )
    claimed = {i.name for i in hw.command_interfaces if i.is_claimed}
    assert claimed == {"left_wheel_joint/velocity", "right_wheel_joint/velocity"}

    odom: list[Odometry] = []
    joints: list[JointState] = []
    lock = threading.Lock()

    def keep(store: list):
        def cb(msg) -> None:
            with lock:
                store.append(msg)

        return cb

    ros_client.node.create_subscription(Odometry, "/diffbot_base_controller/odom", keep(odom), 10)
    ros_client.node.create_subscription(JointState, "/joint_states", keep(joints), 10)
    wait_for(lambda: odom and joints, 15, "/diffbot_base_controller/odom and /joint_states")
    assert set(joints[-1].name) == {"left_wheel_joint", "right_wheel_joint"}
    assert joints[-1].header.frame_id == "base_link"  # joint_state_broadcaster's frame_id (Jazzy's default)

    pub = ros_client.node.create_publisher(TwistStamped, "/diffbot_base_controller/cmd_vel", 10)
    wait_for(lambda: pub.get_subscription_count() > 0, 15, "the controller on /diffbot_base_controller/cmd_vel")
    # Sim time driven by the test: the world paused, then stepped 50 ms at a time with a fresh command
    # before each step (the controller's cmd_vel_timeout is 0.5 s of sim time), so a busy machine cannot
    # starve the controller of commands as a wall-clock publisher did (0.95 m under a CPU hog).
    paused = ros_client.call(
        SetSimulationState,
        "/gazelle/set_simulation_state",
        SetSimulationState.Request(state=SimulationState(state=SimulationState.STATE_PAUSED)),
    )
    assert paused.result.result == 1, paused.result.error_message  # simulation_interfaces/Result RESULT_OK
    start_state = ros_client.entity_state("diffbot")
    t0 = _sim_time(start_state.header.stamp)
    with lock:
        odom_x0 = odom[-1].pose.pose.position.x
    cmd = TwistStamped()
    cmd.twist.linear.x = 0.2

    def sim_now() -> float:
        with lock:
            return _sim_time(odom[-1].header.stamp)

    def drive_for(seconds: float, twist: TwistStamped) -> None:
        for _ in range(round(seconds / 0.05)):
            pub.publish(twist)
            done = ros_client.call(StepSimulation, "/gazelle/step_simulation", StepSimulation.Request(steps=50))
            assert done.result.result == 1, done.result.error_message

    drive_for(5.0, cmd)  # 0.2 m/s for 5 s of sim time, then stop
    drive_for(1.5, TwistStamped())
    # the last odometry of the stepped time heard (published at 50 Hz)
    wait_for(lambda: sim_now() >= t0 + 6.5 - 0.021, 20, "the odometry of the robot stopped")
    end = ros_client.entity_state("diffbot")
    assert _sim_time(end.header.stamp) == pytest.approx(t0 + 6.5, abs=1e-6)  # 1 ms steps: 6.5 s stepped
    moved = math.hypot(
        end.state.pose.position.x - start_state.state.pose.position.x,
        end.state.pose.position.y - start_state.state.pose.position.y,
    )
    with lock:
        odom_moved = odom[-1].pose.pose.position.x - odom_x0
    assert moved == pytest.approx(1.0, abs=0.03), f"ground truth moved {moved:.4f} m"
    assert odom_moved == pytest.approx(moved, rel=0.02), f"odom {odom_moved:.4f} m vs ground truth {moved:.4f} m"


@pytest.mark.slow
def test_the_spawners_controller_ros_args_remap_the_controllers_topics(sim_factory, ros_client):
    """``spawner --controller-ros-args "-r ~/cmd_vel:=/cmd_vel"`` (ros2_control Jazzy): the controller's node
    takes the remapping, so it listens on /cmd_vel and publishes ~/odom where it was."""
    sim = sim_factory("--no-viewer")
    _spawn_diffbot(sim)
    rc, out = _spawner("diffbot_base_controller", "--controller-ros-args", "-r ~/cmd_vel:=/cmd_vel")
    assert rc == 0, out
    pub = ros_client.node.create_publisher(TwistStamped, "/cmd_vel", 10)
    wait_for(lambda: pub.get_subscription_count() > 0, 15, "the controller on /cmd_vel")
    assert ros_client.node.count_publishers("/diffbot_base_controller/odom") >= 1
    wait_for(lambda: ros_client.node.count_subscribers("/diffbot_base_controller/cmd_vel") == 0, 5, "no old name")
    # a switch timeout no Duration holds: one line before the manager is asked anything (before: the controller
    # loaded and configured, then a traceback building the switch request)
    rc, out = _spawner("joint_state_broadcaster", "--switch-timeout", "1e30")
    assert rc == 2 and "argument --switch-timeout: 1e30: expected seconds from 0 to" in out, out
    assert "Traceback" not in out and "Loaded" not in out, out


@pytest.mark.slow
def test_r6bot_follows_a_trajectory_holds_and_aborts_on_path_tolerance(sim_factory, ros_client, monkeypatch):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(R6BOT))  # the server finds the meshes' package
    # three times real time: the trajectory, the 10 s hold and the abort are all in sim time
    sim = sim_factory("--no-viewer", "--rtf", "3")
    spawn = start([*GAZELLE, "spawn", "-entity", "r6bot", "-file", str(R6BOT_URDF)], "spawn")
    assert spawn.wait(120) == 0, spawn.output
    sim.wait_line("controller manager '/controller_manager'", 10)
    # as launch files start it: `ros2 run controller_manager spawner ...`
    ros2 = start(
        [str(Path(sys.prefix) / "bin" / "ros2"), "run", "controller_manager", "spawner"]
        + ["joint_state_broadcaster", "joint_trajectory_controller", "-p", str(R6BOT_YAML)],
        "ros2 run spawner",
    )
    assert ros2.wait(60) == 0, ros2.output
    assert "Configured and activated joint_trajectory_controller" in ros2.output

    joints: list[JointState] = []
    ros_client.node.create_subscription(JointState, "/joint_states", joints.append, 10)
    wait_for(lambda: joints, 15, "/joint_states")
    names = [f"joint_{i}" for i in range(1, 7)]
    client = ActionClient(
        ros_client.node, FollowJointTrajectory, "/joint_trajectory_controller/follow_joint_trajectory"
    )
    assert client.wait_for_server(timeout_sec=15)

    def goal(points: list[tuple[float, list[float]]], path_tol: float = 0.0) -> FollowJointTrajectory.Goal:
        g = FollowJointTrajectory.Goal()
        g.trajectory.joint_names = names
        trajectory_points = []
        for t, q in points:
            p = JointTrajectoryPoint(positions=q)
            p.time_from_start.sec = int(t)
            p.time_from_start.nanosec = int((t - int(t)) * 1e9)
            trajectory_points.append(p)
        g.trajectory.points = trajectory_points
        if path_tol:
            from control_msgs.msg import JointTolerance

            g.path_tolerance = [JointTolerance(name=n, position=path_tol) for n in names]
        return g

    def run(g: FollowJointTrajectory.Goal, timeout: float = 30.0):
        accepted, result = ros_client.send_goal(client, g, timeout)
        return {"accepted": accepted, "result": result}

    final = [0.2, -0.2, 0.3, 0.1, 0.2, -0.3]
    box = run(goal([(1.0, [0.3, -0.4, 0.5, 0.2, -0.3, 0.4]), (2.0, [0.6, -0.8, 1.0, 0.4, -0.6, 0.8]), (3.0, final)]))
    assert box["accepted"]
    result = box["result"].result
    assert result.error_code == FollowJointTrajectory.Result.SUCCESSFUL, result.error_string

    def position() -> list[float]:
        msg = joints[-1]
        return [msg.position[list(msg.name).index(n)] for n in names]

    def position_after_the_goal() -> list[float]:
        """The joints once /joint_states is heard from after the goal ended: the server's sim time now
        (a service reply, answered after the result was sent) bounds when it ended. The last message
        heard when the result came can be older (1.24 mm short of the end once, on a busy machine)."""
        now = _sim_time(ros_client.entity_state("r6bot").header.stamp)
        wait_for(lambda: _sim_time(joints[-1].header.stamp) >= now, 15, "/joint_states after the goal's end")
        return position()

    q_end = position_after_the_goal()
    assert max(abs(a - b) for a, b in zip(q_end, final, strict=True)) < 1e-3
    t_end = _sim_time(joints[-1].header.stamp)
    # `ros2 action list` and `info` look while the arm holds (they only read the graph)
    ros2cli = [str(Path(sys.prefix) / "bin" / "ros2"), "action"]
    action = "/joint_trajectory_controller/follow_joint_trajectory"
    lister = subprocess.Popen([*ros2cli, "list", "-t"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    informer = subprocess.Popen([*ros2cli, "info", action], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wait_for(lambda: _sim_time(joints[-1].header.stamp) > t_end + 10.0, 40, "10 s of holding")
    drift = max(abs(a - b) for a, b in zip(position(), q_end, strict=True))
    assert drift < 1e-3, f"drifted {drift:.2e} rad in 10 s"

    # a fast move with a path tolerance it cannot keep: aborted with PATH_TOLERANCE_VIOLATED
    box = run(goal([(0.3, [1.5, -1.0, 1.5, 1.0, 1.0, 1.0])], path_tol=1e-4))
    assert box["accepted"]
    assert box["result"].result.error_code == FollowJointTrajectory.Result.PATH_TOLERANCE_VIOLATED

    # the same action from the command line, as a user types it (listed while the arm held, above)
    listed, _ = lister.communicate(timeout=60)
    info, _ = informer.communicate(timeout=60)
    assert f"{action} [control_msgs/action/FollowJointTrajectory]" in listed, listed
    assert "Action servers: 1" in info and "    /controller_manager" in info, info
    goal_yaml = (
        "{trajectory: {joint_names: [joint_1, joint_2, joint_3, joint_4, joint_5, joint_6], "
        "points: [{positions: [0.1, -0.1, 0.2, 0.0, 0.1, 0.0], time_from_start: {sec: 1}}]}}"
    )
    sent = subprocess.run(
        [*ros2cli, "send_goal", "-f", action, "control_msgs/action/FollowJointTrajectory", goal_yaml],
        capture_output=True,
        text=True,
        timeout=90,
    )
    assert "Goal accepted with ID:" in sent.stdout and "Feedback:" in sent.stdout, sent.stdout + sent.stderr
    assert "Goal finished with status: SUCCEEDED" in sent.stdout and sent.returncode == 0
    reached = position_after_the_goal()
    assert max(abs(a - b) for a, b in zip(reached, [0.1, -0.1, 0.2, 0.0, 0.1, 0.0], strict=True)) < 1e-3

    # a goal naming a joint the controller does not have is rejected
    bad = goal([(1.0, [0.0] * 6)])
    bad.trajectory.joint_names = [*names[:5], "elbow"]
    assert run(bad)["accepted"] is False

    # switching to a controller that is not loaded: refused, and the server still answers
    res = ros_client.call(
        SwitchController,
        "/controller_manager/switch_controller",
        SwitchController.Request(activate_controllers=["nope"], strictness=SwitchController.Request.STRICT),
    )
    assert res.ok is False
    sim.wait_line("controller 'nope' is not loaded", 10)
    rc, out = _spawner("not_in_yaml", "-p", str(R6BOT_YAML), "--controller-manager-timeout", "5")
    assert rc == 1 and "the 'type' of controller 'not_in_yaml' is not set" in out, out
    rc, out = _spawner("arm", "-t", "fancy_controllers/Fancy", "--controller-manager-timeout", "5")
    assert rc == 1 and "controller type 'fancy_controllers/Fancy' of 'arm' does not exist; the types are" in out, out
    assert ros_client.entity_state("r6bot").success


@pytest.mark.slow
def test_the_spawner_waits_for_a_manager_that_comes_late_as_jazzys_does(sim_factory):
    """Jazzy's spawner waits for ever by default (``--controller-manager-timeout`` 0; controller_manager_services.py
    ``service_caller`` says "Could not contact service" every 10 s): a launch file's spawner started before a slow
    simulation's manager gets its controllers. Before, gazelle's gave up after 10 s with "Controller manager not
    available". ~15 s: the spawner's first 10 s wait is the behaviour under test."""
    sim = sim_factory("--no-viewer")
    # the controllers' file given to the spawner, as Jazzy launch files do (the spawn's own --params-file reaches the
    # manager only after it is up: a spawner already waiting could load before the types were set)
    spawner = start(
        [*GAZELLE, "spawner", "joint_state_broadcaster", "diffbot_base_controller", "-p", str(DIFFBOT_YAML)], "spawner"
    )
    try:
        spawner.wait_line("Could not contact service /controller_manager/list_controllers", 30)
        assert spawner.popen.poll() is None, spawner.output
        _spawn_diffbot(sim)
        assert spawner.wait(60) == 0, spawner.output
        assert "Configured and activated diffbot_base_controller" in spawner.output
    finally:
        if spawner.popen.poll() is None:
            spawner.popen.kill()


def test_spawner_without_a_manager_says_so_and_exits_1():
    rc, out = _spawner("joint_state_broadcaster", "--controller-manager-timeout", "1", timeout=30)
    assert rc == 1
    assert "Controller manager not available" in out


@pytest.mark.parametrize(
    ("command", "flag", "value"),
    [
        ("spawner", "--controller-manager-timeout", "inf"),  # before: waited for ever
        ("spawner", "--service-call-timeout", "nan"),
        ("spawner", "--switch-timeout", "-1"),
        ("unspawner", "--switch-timeout", "1e10"),  # past a Duration's int32 seconds
    ],
)
def test_spawner_timeouts_that_are_not_seconds_are_one_line_each(command: str, flag: str, value: str) -> None:
    """Checked as the arguments are read: no manager is needed (one would be waited for 1 s)."""
    wait = ["--controller-manager-timeout", "1"] if command == "spawner" and "manager" not in flag else []
    proc = start([*GAZELLE, command, "joint_state_broadcaster", flag, value, *wait], command)
    assert proc.wait(30) == 2, proc.output
    assert f"argument {flag}: {value}: expected seconds from 0 to 2147483647" in proc.output, proc.output
    assert "Traceback" not in proc.output and "Controller manager not available" not in proc.output


@pytest.mark.slow
def test_a_namespaced_panda_closes_its_gripper_through_the_gripper_action(sim_factory, ros_client, monkeypatch):
    from control_msgs.action import GripperCommand

    panda = FIXTURES / "moveit_panda"
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(panda))
    sim = sim_factory("--no-viewer")
    xacro_file = panda / "moveit_resources_panda_moveit_config" / "config" / "panda.urdf.xacro"
    spawn = start(
        [*GAZELLE, "spawn", "-entity", "panda", "-robot_namespace", "panda", "-file", str(xacro_file)], "spawn"
    )
    assert spawn.wait(120) == 0, spawn.output
    sim.wait_line("controller manager '/panda/controller_manager'", 10)
    yaml = panda / "moveit_resources_panda_moveit_config" / "config" / "ros2_controllers.yaml"
    rc, out = _spawner("panda_hand_controller", "-c", "/panda/controller_manager", "-p", str(yaml))
    assert rc == 0, out
    client = ActionClient(ros_client.node, GripperCommand, "/panda/panda_hand_controller/gripper_cmd")
    assert client.wait_for_server(timeout_sec=15)
    goal = GripperCommand.Goal()
    goal.command.position = 0.03
    accepted, response = ros_client.send_goal(client, goal, 30.0)
    assert accepted
    result = response.result
    assert result.reached_goal and not result.stalled
    assert result.position == pytest.approx(0.03, abs=0.01)


def _ros2_control(*args: str) -> subprocess.CompletedProcess:
    ros2 = str(Path(sys.prefix) / "bin" / "ros2")
    return run_or_dump([ros2, "control", *args], 60)


@pytest.mark.slow
def test_ros2_control_verbs_list_switch_and_set_the_diffbots_controllers(sim_factory, tmp_path):
    """Issue 27: `ros2 control list_controllers|list_hardware_interfaces|switch_controllers|...` did not
    exist; users type them daily. Output as ros2controlcli Jazzy's (no colours when piped)."""
    sim = sim_factory("--no-viewer")
    _spawn_diffbot(sim)
    rc, out = _spawner("joint_state_broadcaster")
    assert rc == 0, out

    loaded = _ros2_control("load_controller", "diffbot_base_controller", "--set-state", "active")
    assert loaded.returncode == 0 and "Successfully loaded controller diffbot_base_controller into state active" in (
        loaded.stdout
    ), loaded.stdout + loaded.stderr
    listed = _ros2_control("list_controllers")
    assert listed.returncode == 0, listed.stderr
    rows = [line.split() for line in listed.stdout.splitlines()]
    assert ["joint_state_broadcaster", "joint_state_broadcaster/JointStateBroadcaster", "active"] in rows
    assert ["diffbot_base_controller", "diff_drive_controller/DiffDriveController", "active"] in rows
    assert "\033[" not in listed.stdout  # piped: no colour codes

    # ros2controlcli Jazzy's load_controller NAME PARAM_FILE (gazelle refused the file: its parameters go to
    # the manager as <name>.params_file and its type) and a controller already loaded (a warning, exit 0)
    params = tmp_path / "jsb2.yaml"
    params.write_text("jsb2:\n  ros__parameters:\n    type: joint_state_broadcaster/JointStateBroadcaster\n")
    with_file = _ros2_control("load_controller", "jsb2", str(params), "--set-state", "inactive")
    assert with_file.returncode == 0, with_file.stdout + with_file.stderr
    assert "Successfully loaded controller jsb2 into state inactive" in with_file.stdout
    assert ["jsb2", "joint_state_broadcaster/JointStateBroadcaster", "inactive"] in [
        line.split() for line in _ros2_control("list_controllers").stdout.splitlines()
    ]
    cleaned = _ros2_control("set_controller_state", "jsb2", "unconfigured")  # Jazzy's cleanup (refused before)
    assert cleaned.returncode == 0 and "successfully cleaned up jsb2" in cleaned.stdout, cleaned.stdout + cleaned.stderr
    assert ["jsb2", "joint_state_broadcaster/JointStateBroadcaster", "unconfigured"] in [
        line.split() for line in _ros2_control("list_controllers").stdout.splitlines()
    ]
    twice = _ros2_control("load_controller", "diffbot_base_controller")
    assert twice.returncode == 0, twice.stdout + twice.stderr
    assert "Controller : diffbot_base_controller already loaded, skipping load_controller!" in twice.stdout
    no_file = _ros2_control("load_controller", "jsb3", str(tmp_path / "missing.yaml"))
    assert no_file.returncode == 1 and "does not exist, Aborting!" in no_file.stderr, no_file.stdout + no_file.stderr

    hw = _ros2_control("list_hardware_interfaces")
    assert hw.returncode == 0 and hw.stdout.startswith("command interfaces\n"), hw.stdout + hw.stderr
    assert "\tleft_wheel_joint/velocity [available] [claimed]" in hw.stdout
    assert "state interfaces" in hw.stdout and "\tleft_wheel_joint/position" in hw.stdout

    switched = _ros2_control("switch_controllers", "--deactivate", "diffbot_base_controller")
    assert switched.returncode == 0 and "Successfully switched controllers" in switched.stdout, switched.stderr
    assert ["diffbot_base_controller", "diff_drive_controller/DiffDriveController", "inactive"] in [
        line.split() for line in _ros2_control("list_controllers").stdout.splitlines()
    ]
    assert "[available] [unclaimed]" in _ros2_control("list_hardware_interfaces").stdout
    again = _ros2_control("set_controller_state", "diffbot_base_controller", "active")
    assert again.returncode == 0, again.stdout + again.stderr
    assert ["diffbot_base_controller", "diff_drive_controller/DiffDriveController", "active"] in [
        line.split() for line in _ros2_control("list_controllers", "-c", "controller_manager").stdout.splitlines()
    ]
    # bad input: one line, exit 1, no traceback
    missing = _ros2_control("list_controllers", "-c", "/nobody_here", "--service-timeout", "1")
    assert missing.returncode == 1 and "Could not contact service /nobody_here/list_controllers" in missing.stderr
    unknown = _ros2_control("set_controller_state", "no_such_controller", "active")
    assert unknown.returncode == 1 and "does not seem to be loaded" in unknown.stderr
    assert "Traceback" not in missing.stderr + unknown.stderr


def test_parameters_next_to_the_robot_file_are_read_by_spawn_file(sim_factory, tmp_path):
    """Issue 50: `<parameters>diffbot_controllers.yaml</parameters>` beside the robot file was refused for
    `gazelle spawn -file` ("is not in a package or model folder gazelle may read"): the server only ever saw the
    XML. The client reads the file beside the robot file with the user's rights and carries its text, so the
    spawner finds the controllers' types with no -p, as with gazebo_ros2_control."""
    (tmp_path / "diffbot_controllers.yaml").write_text(DIFFBOT_YAML.read_text())
    plugin = (
        '<gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">'
        "<parameters>diffbot_controllers.yaml</parameters></plugin></gazebo>"
    )
    robot = tmp_path / "diffbot.urdf"
    robot.write_text(DIFFBOT_URDF.read_text().replace("</robot>", plugin + "</robot>"))
    sim = sim_factory("--no-viewer")
    spawn = start([*GAZELLE, "spawn", "-entity", "diffbot", "-file", str(robot), "-z", "0.05"], "spawn")
    assert spawn.wait(60) == 0, spawn.output
    sim.wait_line("controller manager '/controller_manager'", 10)
    rc, out = _spawner("joint_state_broadcaster", "diffbot_base_controller")
    assert rc == 0, out

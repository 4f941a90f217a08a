"""ros2_control in the simulator, without ROS: the controller manager, the hardware and the
controllers, on real robots' files (ros2_control_demos' diffbot and r6bot, MoveIt's Panda)."""

from __future__ import annotations

import dataclasses
import logging
import math

import numpy as np
import pytest
from _paths import REAL, REPO
from _sim import new_simulation

from gazelle.description import Joint, JointType, Pose, load, load_string
from gazelle.sim import Simulation
from gazelle.systems import Float64Array, InterfaceValue, JointTrajectory, MsgType, TrajectoryPoint, Twist, TwistStamped
from gazelle.systems.ros2_control import (
    ControlError,
    ControllerManager,
    GripperGoal,
    JointTrajectoryController,
    ParamsError,
    TrajectoryGoal,
    load_params,
    parse_params,
    segment_tolerances,
)
from gazelle.worlds import default_world

DIFFBOT = REAL / "ros2_control_diffbot"
DIFFBOT_URDF = DIFFBOT / "_xacro_expanded" / "diffbot.urdf"
DIFFBOT_YAML = DIFFBOT / "ros2_control_demo_example_2" / "config" / "diffbot_controllers.yaml"
R6BOT = REAL / "ros2_control_r6bot"
R6BOT_URDF = R6BOT / "_xacro_expanded" / "r6bot.urdf"
R6BOT_YAML = REPO / "tests" / "data" / "ros2_control" / "r6bot_jtc.yaml"
PANDA = REAL / "moveit_panda"
PANDA_XACRO = PANDA / "moveit_resources_panda_moveit_config" / "config" / "panda.urdf.xacro"
PANDA_YAML = PANDA / "moveit_resources_panda_moveit_config" / "config" / "ros2_controllers.yaml"
R6_JOINTS = tuple(f"joint_{i}" for i in range(1, 7))


def _manager(entity) -> ControllerManager:
    (cm,) = [s for s in entity.systems if isinstance(s, ControllerManager)]
    return cm


def _start(cm: ControllerManager, yaml_path, *names: str) -> None:
    """What the spawner does with ``-p yaml_path``: the params file (and type) set on the manager,
    then load, configure and activate."""
    pf = load_params(yaml_path)
    for n in names:
        cm.set_parameter(f"{n}.params_file", str(yaml_path))
        kind = pf.for_node(n).get("type") or pf.for_node("controller_manager").get(f"{n}.type")
        cm.set_parameter(f"{n}.type", kind)
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(list(names), [])


def _diffbot(sim: Simulation, name: str = "diffbot", namespace: str = "", y: float = 0.0):
    model = load(DIFFBOT_URDF).model
    return sim.spawn(model, name=name, pose=Pose((0.0, y, 0.05)), namespace=namespace)


# --------------------------------------------------------------------------- parameters
def test_parameter_files_flatten_nested_keys_and_match_wildcards_and_namespaces():
    pf = parse_params(
        """
/**:
  ros__parameters:
    use_sim_time: true
r1:
  diff:
    ros__parameters:
      linear: {x: {max_velocity: 2.0}}
      wheel_radius: 0.1
diff:
  ros__parameters:
    angular.z.max_velocity: 1.5
""",
        "f.yaml",
    )
    assert pf.for_node("diff", "/r1") == {
        "use_sim_time": True,
        "angular.z.max_velocity": 1.5,
        "linear.x.max_velocity": 2.0,
        "wheel_radius": 0.1,
    }
    assert pf.for_node("diff") == {"use_sim_time": True, "angular.z.max_velocity": 1.5}


def test_bad_yaml_names_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("controller_manager:\n  ros__parameters:\n    update_rate: [1, 2\n")
    with pytest.raises(ParamsError, match=r"bad\.yaml:\d+: not valid YAML"):
        load_params(bad)
    with pytest.raises(ParamsError, match="maps node names"):
        parse_params("- a\n- b\n", "list.yaml")


# --------------------------------------------------------------------------- diffbot
def test_the_diffbot_drives_one_metre_in_five_seconds_and_its_odometry_agrees(make_sim):
    sim = make_sim()
    entity = _diffbot(sim)
    cm = _manager(entity)
    assert cm.update_rate == 100  # ros2_control's default: its YAML has no controller_manager section
    _start(cm, DIFFBOT_YAML, "joint_state_broadcaster", "diffbot_base_controller")
    assert cm.claimed() == {
        "left_wheel_joint/velocity": "diffbot_base_controller",
        "right_wheel_joint/velocity": "diffbot_base_controller",
    }
    odom: list = []
    joint_states: list = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/diffbot_base_controller/odom":
            ep.add_sink(odom.append)
        if ep.topic == "/joint_states":
            ep.add_sink(joint_states.append)
    sim.step(500)
    x0 = sim.world.entity_state("diffbot").pose.position[0]
    t0 = sim.world.time
    go = TwistStamped(0.0, "", Twist((0.2, 0.0, 0.0)))
    while sim.world.time < t0 + 5.0 - 1e-9:
        assert sim.bus.inject("/diffbot_base_controller/cmd_vel", MsgType.TWIST_STAMPED, go) == 1
        sim.step(20)
    sim.bus.inject("/diffbot_base_controller/cmd_vel", MsgType.TWIST_STAMPED, TwistStamped(0.0, "", Twist()))
    sim.step(1500)
    moved = sim.world.entity_state("diffbot").pose.position[0] - x0
    assert moved == pytest.approx(1.0, abs=0.03)
    assert odom[-1].pose.position[0] == pytest.approx(moved, rel=0.02)
    assert odom[-1].frame_id == "odom" and odom[-1].child_frame_id == "base_link"
    assert joint_states[-1].names == ("left_wheel_joint", "right_wheel_joint")
    # both wheels turned the same way by distance / radius (0.015 m in its YAML)
    assert joint_states[-1].positions[0] == pytest.approx(moved / 0.015, rel=0.03)


def test_the_diffbot_holds_still_after_cmd_vel_timeout(make_sim):
    sim = make_sim()
    cm = _manager(_diffbot(sim))
    _start(cm, DIFFBOT_YAML, "diffbot_base_controller")
    sim.step(200)
    sim.bus.inject(
        "/diffbot_base_controller/cmd_vel", MsgType.TWIST_STAMPED, TwistStamped(0.0, "", Twist((0.2, 0.0, 0.0)))
    )
    sim.step(2000)  # one command, then 0.5 s cmd_vel_timeout: it stops by itself
    x1 = sim.world.entity_state("diffbot").pose.position[0]
    sim.step(1000)
    assert 0.05 < x1 < 0.2
    assert sim.world.entity_state("diffbot").pose.position[0] == pytest.approx(x1, abs=1e-3)


def test_two_namespaced_robots_each_have_their_own_manager_and_topics(make_sim):
    sim = make_sim()
    r1, r2 = _diffbot(sim, "r1", "r1", 0.0), _diffbot(sim, "r2", "r2", 1.0)
    m1, m2 = _manager(r1), _manager(r2)
    assert (m1.node_name, m2.node_name) == ("/r1/controller_manager", "/r2/controller_manager")
    _start(m1, DIFFBOT_YAML, "diffbot_base_controller")
    _start(m2, DIFFBOT_YAML, "diffbot_base_controller")
    topics = {ep.topic for ep in sim.bus.endpoints()}
    assert {"/r1/diffbot_base_controller/cmd_vel", "/r2/diffbot_base_controller/odom"} <= topics
    odom2 = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/r2/diffbot_base_controller/odom":
            ep.add_sink(odom2.append)
    for _ in range(50):
        sim.bus.inject(
            "/r1/diffbot_base_controller/cmd_vel", MsgType.TWIST_STAMPED, TwistStamped(0, "", Twist((0.2, 0.0, 0.0)))
        )
        sim.step(20)
    assert sim.world.entity_state("r1").pose.position[0] > 0.1
    assert abs(sim.world.entity_state("r2").pose.position[0]) < 1e-3
    assert odom2[-1].frame_id == "r2/odom"  # tf_frame_prefix defaults to the namespace


def _diffbot_with_wheels(make_sim) -> tuple[Simulation, ControllerManager]:
    """The diffbot with a configured (inactive) JointGroupVelocityController ``wheels`` on its two wheels."""
    sim = make_sim()
    cm = _manager(_diffbot(sim))
    cm.files.append(
        parse_params(
            "wheels:\n  ros__parameters:\n    type: velocity_controllers/JointGroupVelocityController\n"
            "    joints: [left_wheel_joint, right_wheel_joint]\n"
        )
    )
    cm.load_controller("wheels")
    cm.configure_controller("wheels")
    return sim, cm


def test_a_forward_command_controller_drives_the_wheels_and_switches_with_the_diff_drive(make_sim):
    sim, cm = _diffbot_with_wheels(make_sim)
    _start(cm, DIFFBOT_YAML, "diffbot_base_controller")
    with pytest.raises(ControlError, match="claimed by 'diffbot_base_controller'"):
        cm.switch_controller(["wheels"], [])
    cm.switch_controller(["wheels"], ["diffbot_base_controller"])
    sim.bus.inject("/wheels/commands", MsgType.FLOAT64_ARRAY, Float64Array((10.0, 10.0)))
    sim.step(1000)
    joint = sim.world.joint("diffbot", "left_wheel_joint")
    assert joint.velocity == pytest.approx(10.0, rel=0.02)


def test_a_forward_command_of_the_wrong_size_deactivates_the_controller_and_a_nan_is_dropped(make_sim, caplog):
    """Jazzy's forward_controllers_base.cpp: a command with a non-finite value is dropped with "Non-finite
    value received. Dropping message" (the last command stays); one of the wrong size makes update() return
    ERROR ("command size (3) does not match number of interfaces (2)"), and the controller manager
    deactivates the controller ("Deactivating controllers : [ wheels ] as their update resulted in an
    error!"). gazelle refused the wrong size in the callback and kept the controller active."""
    sim, cm = _diffbot_with_wheels(make_sim)
    cm.switch_controller(["wheels"], [])
    sim.bus.inject("/wheels/commands", MsgType.FLOAT64_ARRAY, Float64Array((5.0, 5.0)))
    sim.step(500)
    sim.bus.inject("/wheels/commands", MsgType.FLOAT64_ARRAY, Float64Array((math.nan, 1.0)))
    sim.step(500)
    joint = sim.world.joint("diffbot", "left_wheel_joint")
    assert joint.velocity == pytest.approx(5.0, rel=0.02)  # the NaN command was dropped
    assert "Non-finite value received. Dropping message" in caplog.text
    assert cm.controllers["wheels"].controller.state == "active"
    sim.bus.inject("/wheels/commands", MsgType.FLOAT64_ARRAY, Float64Array((1.0, 2.0, 3.0)))
    sim.step(20)
    assert "command size (3) does not match number of interfaces (2)" in caplog.text
    assert "Deactivating controllers : [ wheels ] as their update resulted in an error!" in caplog.text
    assert cm.controllers["wheels"].controller.state == "inactive"


# --------------------------------------------------------------------------- r6bot and JTC
def _r6bot(yaml_path) -> tuple[Simulation, ControllerManager]:
    sim = new_simulation()
    entity = sim.spawn(load(R6BOT_URDF).model, name="r6bot")
    cm = _manager(entity)
    cm.files.append(load_params(yaml_path))
    for n in ("joint_state_broadcaster", "joint_trajectory_controller"):
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(["joint_state_broadcaster", "joint_trajectory_controller"], [])
    return sim, cm


@pytest.fixture
def r6bot(monkeypatch):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(R6BOT))
    return _r6bot(R6BOT_YAML)


def _positions(cm: ControllerManager) -> list[float]:
    return [cm.hardware[0].joints[j].handle.position for j in R6_JOINTS]


def _run(sim: Simulation, goal: TrajectoryGoal, limit: float = 15.0) -> None:
    while not goal.done.is_set() and sim.world.time < limit:
        sim.step(10)


def test_r6bot_follows_three_waypoints_then_holds_under_gravity(r6bot):
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(300)
    final = (0.2, -0.2, 0.3, 0.1, 0.2, -0.3)
    points = (
        TrajectoryPoint(1.0, (0.3, -0.4, 0.5, 0.2, -0.3, 0.4)),
        TrajectoryPoint(2.0, (0.6, -0.8, 1.0, 0.4, -0.6, 0.8)),
        TrajectoryPoint(3.0, final),
    )
    goal = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, points))
    assert jtc.validate(goal.trajectory) is None
    jtc.submit(goal)
    worst = 0.0
    while not goal.done.is_set() and sim.world.time < 10:
        sim.step(10)
        if jtc.last_state is not None:
            worst = max(worst, *(abs(e) for e in jtc.last_state.error.positions))
    assert goal.status == "succeeded", goal.error_string
    assert goal.error_string == "Goal successfully reached!"  # Jazzy's
    assert sim.world.time < 0.3 + 3.0 + 1.0  # within its goal_time of 1 s
    q_end = _positions(cm)
    assert max(abs(a - b) for a, b in zip(q_end, final, strict=True)) < 1e-3
    assert worst < 0.05  # the YAML's path tolerance (it was checked every cycle)
    sim.step(10_000)  # 10 s under gravity
    assert max(abs(a - b) for a, b in zip(_positions(cm), q_end, strict=True)) < 1e-3


def test_the_trajectory_controller_commands_the_next_cycles_set_point_and_measures_errors_at_this_one(r6bot):
    """ros2_controllers 4.17+ (Jazzy's joint_trajectory_controller.cpp, ``update()``): the command is the
    trajectory sampled one update period ahead (``command_next_`` at ``traj_time_ + update_period_``), the
    reference and its errors are at the cycle's time (``state_desired_``). At the r6bot's 100 Hz a 0.5 rad/s
    segment's command leads its reference by 5 mrad (gazelle commanded the reference itself before)."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(100)
    target = tuple(q + 0.5 for q in _positions(cm))
    jtc.submit(TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(1.0, target),))))
    sim.step(500)  # mid-segment
    state = jtc.last_state
    assert state is not None
    lead = [o - r for o, r in zip(state.output.positions, state.reference.positions, strict=True)]
    assert all(abs(d - 0.5 * 0.01) < 1e-5 for d in lead), lead
    error = [r - f for r, f in zip(state.reference.positions, state.feedback.positions, strict=True)]
    assert error == pytest.approx(state.error.positions, abs=1e-12)


def test_a_position_only_trajectory_controller_has_no_velocity_errors_as_jazzys(r6bot):
    """Jazzy's compute_error_for_joint computes velocity errors only with a velocity or effort command
    interface: the r6bot's position-only controller reports them as 0, and a velocity path tolerance of
    1e-6 rad/s (which any motion leaves) never aborts its goal (gazelle aborted it at once before)."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(100)
    target = tuple(q + 0.3 for q in _positions(cm))
    goal = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(1.0, target),)))
    goal.path_tolerance = segment_tolerances(jtc, [(j, 0.0, 1e-6, 0.0) for j in R6_JOINTS], [], 0.0).path
    jtc.submit(goal)
    sim.step(500)
    state = jtc.last_state
    assert state is not None and state.error.velocities == (0.0,) * 6
    assert any(abs(v) > 0.1 for v in state.feedback.velocities)  # moving, at 0.3 rad/s
    _run(sim, goal)
    assert goal.status == "succeeded", goal.error_string


def test_a_trajectory_whose_first_point_is_past_is_sampled_between_its_own_points(r6bot):
    """Jazzy's Trajectory::sample: once the sample time is past the first point (a header stamp in the past,
    as MoveIt Servo's trajectories have), the reference is interpolated between the trajectory's own points;
    the measured state only starts a first segment while the first point is ahead. Stamped 0.5 s back with
    points at 0 s (+0.2 rad) and 1 s (+0.4 rad), the first cycle's reference is +0.3 rad (gazelle ran a
    segment from the measured state to the next point ahead, so the reference started where the arm was)."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(1000)  # (a stamp must be > 0: 0 means "now")
    q0 = _positions(cm)
    points = (TrajectoryPoint(0.0, tuple(q + 0.2 for q in q0)), TrajectoryPoint(1.0, tuple(q + 0.4 for q in q0)))
    jtc.submit(TrajectoryGoal(JointTrajectory(sim.world.time - 0.5, R6_JOINTS, points)))
    sim.step(10)  # one 100 Hz cycle
    state = jtc.last_state
    assert state is not None
    into = state.stamp_sec - (sim.world.time - 0.01 - 0.5)  # how far into the trajectory that cycle was
    want = [q + 0.2 + 0.2 * into for q in q0]
    assert state.reference.positions == pytest.approx(want, abs=1e-6)


def test_a_topic_trajectory_that_ended_before_it_arrived_is_refused(r6bot, caplog):
    """validate_trajectory_msg (Jazzy): a trajectory stamped so that it ended before the controller's now is
    refused with its line, and the arm holds. gazelle took it silently; now that a trajectory whose first
    point is past is sampled between its points, one wholly past would be a jump to its last point."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    assert isinstance(jtc, JointTrajectoryController)
    sim.step(2000)
    q0 = _positions(cm)
    points = (TrajectoryPoint(0.5, tuple(q + 0.1 for q in q0)), TrajectoryPoint(1.0, tuple(q + 0.3 for q in q0)))
    jtc._queue(JointTrajectory(sim.world.time - 1.5, R6_JOINTS, points), None)  # as ~/joint_trajectory does
    sim.step(200)
    assert "that ends in the past" in caplog.text
    assert max(abs(a - b) for a, b in zip(_positions(cm), q0, strict=True)) < 1e-3


@pytest.mark.parametrize("from_desired", [False, True])
def test_interpolate_from_desired_state_starts_a_new_trajectory_from_the_last_command(
    from_desired, tmp_path, monkeypatch
):
    """Jazzy's ``interpolate_from_desired_state`` (and the deprecated ``open_loop_control``): a new
    trajectory's first segment starts from the state last commanded instead of the measured one. Replacing
    a trajectory while the arm moves at 0.3 rad/s: the first cycle's reference is the measured position
    without it (error 0), and where the arm was commanded to be with it (ahead of it by the servo's lag,
    ~0.1 mrad); gazelle read the parameter and did nothing with it. The first trajectory starts with the
    arm's own position at 0 s, as MoveIt's do, so that the replacement comes after its first point (one
    replacing a trajectory still on its way to its first point starts from that segment's desired state)."""
    yaml_path = tmp_path / "r6bot.yaml"
    extra = "    interpolate_from_desired_state: true\n" if from_desired else ""
    yaml_path.write_text(R6BOT_YAML.read_text().replace("    joints: [joint_1", extra + "    joints: [joint_1", 1))
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(R6BOT))
    sim, cm = _r6bot(yaml_path)
    jtc = cm.controllers["joint_trajectory_controller"].controller
    assert isinstance(jtc, JointTrajectoryController) and jtc.from_desired is from_desired
    sim.step(100)
    q0 = _positions(cm)
    points = (TrajectoryPoint(0.0, tuple(q0)), TrajectoryPoint(1.0, tuple(q + 0.3 for q in q0)))
    jtc.submit(TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, points)))
    sim.step(500)
    q1 = _positions(cm)
    stop = TrajectoryPoint(1.0, tuple(q + 0.3 for q in q1), (0.0,) * 6)  # with velocities: a cubic
    jtc.submit(TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (stop,))))
    sim.step(10)  # the new trajectory's first cycle
    state = jtc.last_state
    assert state is not None
    if from_desired:
        assert min(state.error.positions) > 5e-5, state.error.positions  # ~0.1 mrad: the servo's lag
    else:
        assert max(abs(e) for e in state.error.positions) < 1e-12, state.error.positions
        # the segment starts at the measured velocity (about 0.3 rad/s), not at rest
        assert state.reference.velocities == pytest.approx(state.feedback.velocities, abs=1e-12)
        assert min(state.feedback.velocities) > 0.1  # (0.18-0.25 rad/s measured: the servo oscillates)


def test_r6bot_aborts_a_goal_that_leaves_its_path_tolerance(r6bot, caplog):
    """With Jazzy's result string and log lines (joint_trajectory_controller.cpp ``update()``, tolerances.hpp)."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(100)
    goal = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(0.3, (1.5, -1.0, 1.5, 1.0, 1.0, 1.0)),)))
    goal.path_tolerance = segment_tolerances(jtc, [(j, 1e-4, 0.0, 0.0) for j in R6_JOINTS], [], 0.0).path
    jtc.submit(goal)
    _run(sim, goal)
    assert goal.status == "aborted" and goal.error_code == -4  # PATH_TOLERANCE_VIOLATED
    assert goal.error_string == "Aborted due to path tolerance violation"
    assert "State tolerances failed for joint 0 (joint_1):" in caplog.text
    assert "Position Error: " in caplog.text and "Position Tolerance: 0.000100" in caplog.text
    assert "Aborted due to state tolerance violation" in caplog.text
    sim.step(1000)  # it was moving fast: it comes to rest and holds there
    q = _positions(cm)
    sim.step(1000)
    assert max(abs(a - b) for a, b in zip(_positions(cm), q, strict=True)) < 1e-3


def test_a_goals_tolerances_override_the_controllers_as_jazzys_trajectory_controller_resolves_them(r6bot, caplog):
    """tolerances.hpp get_segment_tolerances (ros2_controllers jazzy): per JointTolerance value, > 0 replaces
    the controller's, 0 keeps it, -1 erases it (not checked); goal_time_tolerance the same (-1: wait for ever).
    A joint the controller does not have, or another negative value, discards all of the goal's tolerances
    for the controller's own, with an error."""
    import logging

    _sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    j0, j1 = R6_JOINTS[0], R6_JOINTS[1]
    default = segment_tolerances(jtc, [], [], 0.0)
    assert default.path == jtc.path_tol and default.goal == jtc.goal_tol and default.goal_time == jtc.goal_time
    got = segment_tolerances(jtc, [(j0, 0.2, 0.0, 0.0), (j1, -1.0, 0.0, 0.0)], [(j0, 0.0, -1.0, 0.0)], -1.0)
    assert got.path[j0].position == 0.2 and got.path[j1].position == 0.0
    assert got.goal[j0].position == jtc.goal_tol[j0].position and got.goal[j0].velocity == 0.0
    assert got.goal_time == 0.0
    assert segment_tolerances(jtc, [], [], 2.5).goal_time == 2.5
    for path, goal, goal_time, said in (
        ([("no_such_joint", 0.1, 0.0, 0.0), (j0, 0.2, 0.0, 0.0)], [], 0.0, "goal.path_tolerance does not exist"),
        ([(j0, 0.2, 0.0, 0.0)], [(j1, -0.5, 0.0, 0.0)], 0.0, "invalid position tolerance"),
        ([(j0, 0.2, 0.0, 0.0)], [], -3.0, "illegal goal_time_tolerance"),
    ):
        caplog.clear()
        with caplog.at_level(logging.ERROR):
            assert segment_tolerances(jtc, path, goal, goal_time) == default
        assert any(said in r.getMessage() and "Using default tolerances" in r.getMessage() for r in caplog.records)


def test_a_goal_outside_its_goal_tolerance_after_goal_time_aborts_with_jazzys_string(r6bot, caplog):
    """A goal tolerance of 1e-9 rad no servo meets, and a goal_time_tolerance of 0.1 s: aborted
    GOAL_TOLERANCE_VIOLATED as Jazzy's update() words it, the seconds past the end in std::to_string's six
    decimals, each joint outside logged as check_state_tolerance_per_joint does."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(100)
    target = tuple(q + 0.2 for q in _positions(cm))
    goal = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(0.5, target),)))
    tolerances = segment_tolerances(jtc, [], [(j, 1e-9, 0.0, 0.0) for j in R6_JOINTS], 0.1)
    goal.goal_tolerance, goal.goal_time_tolerance = tolerances.goal, tolerances.goal_time
    jtc.submit(goal)
    _run(sim, goal)
    assert (goal.status, goal.error_code) == ("aborted", -5)  # GOAL_TOLERANCE_VIOLATED
    seconds = float(goal.error_string.removeprefix("Aborted due to goal_time_tolerance exceeding by ").split()[0])
    assert goal.error_string == f"Aborted due to goal_time_tolerance exceeding by {seconds:f} seconds"
    assert 0.1 <= seconds <= 0.11  # the first 10 ms cycle past 0.1 s (0.1 and a rounding)
    assert "Position Tolerance: 0.000000" in caplog.text  # %f of 1e-9, as upstream prints it


def _reconfigure(cm: ControllerManager, name: str, **params: float) -> None:
    """``params`` set in the controller's YAML, then configured and activated again (a user's edit and restart)."""
    cm.switch_controller([], [name])
    cm.files[0].nodes[name].update(params)
    cm.configure_controller(name)
    cm.switch_controller([name], [])


def test_cmd_timeout_holds_where_the_joints_are_and_ends_a_waiting_goal_as_jazzy_does(r6bot, caplog):
    """Jazzy's JTC: ``cmd_timeout`` seconds after the last point, "Aborted due to command timeout" and a hold
    at the measured positions; a goal still waiting for goal tolerances nobody meets (goal_time 0: for ever)
    then reports success, as upstream's next cycle does with its checks off while holding. A timeout not above
    constraints.goal_time is switched off with upstream's warning."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    with caplog.at_level(logging.WARNING):
        _reconfigure(cm, "joint_trajectory_controller", cmd_timeout=0.3, **{"constraints.goal_time": 0.5})
    assert (
        jtc.cmd_timeout == 0.0
        and "Command timeout must be higher than goal_time tolerance (0.300000 vs. 0.500000)" in caplog.text
    )
    _reconfigure(cm, "joint_trajectory_controller", cmd_timeout=0.2, **{"constraints.goal_time": 0.0})
    sim.step(100)
    target = tuple(q + 0.2 for q in _positions(cm))
    goal = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(0.5, target),)))
    goal.goal_tolerance = segment_tolerances(jtc, [], [(j, 1e-9, 0.0, 0.0) for j in R6_JOINTS], 0.0).goal
    start = sim.world.time
    caplog.clear()
    with caplog.at_level(logging.INFO):
        jtc.submit(goal)
        _run(sim, goal)
    assert (goal.status, goal.error_string) == ("succeeded", "Goal successfully reached!")
    assert sim.world.time - start == pytest.approx(0.5 + 0.2, abs=0.03)  # not before the timeout
    assert "Aborted due to command timeout" in caplog.text


def test_r6bot_refuses_goals_it_cannot_run(r6bot):
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    code, why = jtc.validate(JointTrajectory(0.0, (*R6_JOINTS[:5], "elbow"), (TrajectoryPoint(1.0, (0.0,) * 6),)))
    # INVALID_JOINTS, with validate_trajectory_msg's texts (jazzy joint_trajectory_controller.cpp)
    assert code == -2 and why.startswith("Incoming joint elbow doesn't match the controller's joints.")
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS[:3], (TrajectoryPoint(1.0, (0.0,) * 3),)))
    assert code == -2 and why.startswith("Joints on incoming trajectory don't match the controller joints.")
    assert "allow_partial_joints_goal" in why
    pts = (TrajectoryPoint(1.0, (0.0,) * 6), TrajectoryPoint(1.0, (0.1,) * 6))
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS, pts))
    assert (code, why) == (
        -1,
        "Time between points 0 and 1 is not strictly increasing, it is 1.000000 and 1.000000 respectively",
    )


def test_the_trajectory_controller_refuses_what_jazzys_validate_trajectory_msg_refuses(r6bot, caplog):
    """joint_trajectory_controller.cpp validate_trajectory_msg (jazzy): no points; a last point still moving
    (allow_nonzero_velocity_at_trajectory_end defaults to false); efforts for a controller without the effort
    command interface; points without positions unless allow_integration_in_goal_trajectories."""
    import logging

    _sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    assert jtc.validate(JointTrajectory(0.0, R6_JOINTS, ())) == (-1, "Empty trajectory received.")
    moving = (TrajectoryPoint(1.0, (0.1,) * 6, velocities=(0.0, 0.0, 0.5, 0.0, 0.0, 0.0)),)
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS, moving))
    assert code == -1 and why.startswith(f"Velocity of last trajectory point of joint {R6_JOINTS[2]} is not zero")
    efforts = (TrajectoryPoint(1.0, (0.1,) * 6, effort=(1.0,) * 6),)
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS, efforts))
    assert code == -1 and "effort fields are only supported" in why
    velocities_only = (TrajectoryPoint(1.0, (), velocities=(0.0,) * 6),)
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS, velocities_only))
    assert (code, why) == (-1, "Mismatch between joint_names size (6) and positions (0) at point #0.")
    # the parameters that allow them (set as a user's YAML would, then configured again)
    cm.switch_controller([], ["joint_trajectory_controller"])
    cm.files[0].nodes["joint_trajectory_controller"].update(
        {"allow_nonzero_velocity_at_trajectory_end": True, "allow_integration_in_goal_trajectories": True}
    )
    with caplog.at_level(logging.WARNING):
        cm.configure_controller("joint_trajectory_controller")
    cm.switch_controller(["joint_trajectory_controller"], [])
    assert jtc.validate(JointTrajectory(0.0, R6_JOINTS, moving)) is None
    code, why = jtc.validate(JointTrajectory(0.0, R6_JOINTS, velocities_only))  # a position controller
    assert code == -1 and "integrates positions only for velocity or effort" in why
    assert not [r for r in caplog.records if "not read" in r.getMessage()]


def test_a_new_goal_preempts_the_running_one_as_jazzys_preempt_active_goal_does(r6bot):
    """joint_trajectory_controller.cpp preempt_active_goal (jazzy): the running goal is aborted with
    INVALID_GOAL and "Current goal preempted by new incoming action."; the new one runs to its end."""
    sim, cm = r6bot
    jtc = cm.controllers["joint_trajectory_controller"].controller
    sim.step(100)
    first = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(2.0, (0.5,) * 6),)))
    jtc.submit(first)
    sim.step(300)
    second = TrajectoryGoal(JointTrajectory(0.0, R6_JOINTS, (TrajectoryPoint(1.0, (0.1,) * 6),)))
    jtc.submit(second)
    _run(sim, second)
    assert (first.status, first.error_code, first.error_string) == (
        "aborted",
        -1,
        "Current goal preempted by new incoming action.",
    )
    assert second.status == "succeeded", second.error_string


def test_a_controller_parameter_gazelle_does_not_read_is_named(r6bot, caplog):
    import logging

    _sim, cm = r6bot
    cm.switch_controller([], ["joint_trajectory_controller"])
    cm.files[0].nodes["joint_trajectory_controller"].update(
        {"action_monitor_rate": 10.0, "state_publish_rate": 50.0, "use_sim_time": True}
    )
    with caplog.at_level(logging.WARNING):
        cm.configure_controller("joint_trajectory_controller")
    said = [r.getMessage() for r in caplog.records if "not read" in r.getMessage()]
    assert said == [
        "controller 'joint_trajectory_controller': parameter(s) action_monitor_rate, state_publish_rate are not read by "
        "gazelle's joint_trajectory_controller/JointTrajectoryController: they have no effect"
    ]


# --------------------------------------------------------------------------- Panda
def test_panda_loads_with_its_moveit_controllers_yaml_and_its_arm_jtc_moves(monkeypatch, make_sim):
    monkeypatch.setenv("GAZELLE_RESOURCE_PATH", str(PANDA))
    sim = make_sim()
    model = load(PANDA_XACRO).model
    # bolted to the world as MoveIt's virtual_joint says (its URDF alone is a free-standing arm that
    # topples, as in Gazebo without a world joint)
    bolt = Joint("virtual_joint", JointType.FIXED, "world", "panda_link0")
    entity = sim.spawn(dataclasses.replace(model, joints=(bolt, *model.joints)), name="panda")
    cm = _manager(entity)
    cm.files.append(load_params(PANDA_YAML))
    assert [h.name for h in cm.hardware] == ["PandaFakeSystem", "PandaHandFakeSystem"]
    for n in ("joint_state_broadcaster", "panda_arm_controller"):
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(["joint_state_broadcaster", "panda_arm_controller"], [])
    sim.step(200)
    # initial_value from initial_positions.yaml: panda_joint4 starts at -2.356 (not 0)
    assert cm.hardware[0].joints["panda_joint4"].handle.position == pytest.approx(-2.356, abs=0.01)
    jtc = cm.controllers["panda_arm_controller"].controller
    assert isinstance(jtc, JointTrajectoryController)
    names = tuple(f"panda_joint{i}" for i in range(1, 8))
    target = (0.3, -0.6, 0.2, -2.2, 0.1, 1.7, 0.9)
    goal = TrajectoryGoal(JointTrajectory(0.0, names, (TrajectoryPoint(2.0, target),)))
    jtc.submit(goal)
    _run(sim, goal)
    assert goal.status == "succeeded", goal.error_string
    q = [cm.hardware[0].joints[n].handle.position for n in names]
    assert max(abs(a - b) for a, b in zip(q, target, strict=True)) < 0.01
    assert sim.world.entity_state("panda", "panda_hand").pose.position[2] > 0.3  # upright, off the floor
    # the hand: position_controllers/GripperActionController on panda_finger_joint1; finger 2 follows
    # it through its URDF <mimic> (it has state interfaces only)
    cm.load_controller("panda_hand_controller")
    cm.configure_controller("panda_hand_controller")
    cm.switch_controller(["panda_hand_controller"], [])
    hand = cm.controllers["panda_hand_controller"].controller
    grip = GripperGoal(0.03)
    hand.submit(grip)  # type: ignore[attr-defined]
    t0 = sim.world.time
    while not grip.done.is_set() and sim.world.time < t0 + 5:
        sim.step(10)
    assert grip.status == "succeeded" and grip.reached_goal and not grip.stalled  # within goal_tolerance 0.01
    sim.step(1000)  # and it settles at the goal
    fingers = [cm.hardware[1].joints[f"panda_finger_joint{i}"].handle.position for i in (1, 2)]
    assert fingers[0] == pytest.approx(0.03, abs=1e-3) and fingers[1] == pytest.approx(fingers[0], abs=1e-3)


# --------------------------------------------------------------------------- grasping (issue 27, item 11)
CHESSBOT = REPO / "examples" / "chessbot"
CHESSBOARD = REPO / "examples" / "chessboard"
DUAL = PANDA / "dual_arm_panda_moveit_config" / "config"


def test_the_chess_robots_hand_holds_a_1_g_piece_and_lets_it_go_where_it_was_carried(resource_path, make_sim):
    """The chess robot's left hand (examples/chessbot/hand_controllers.yaml: the Panda's
    position_controllers/GripperActionController) closes on a 1 g piece, lifts it 8 cm, carries it 10 cm
    and opens beside another piece. Before: the fingers, closing with their 20 N effort limit, went
    through the piece (MuJoCo's default contact is soft relative to a light body's mass) and it was
    squeezed out; the hand then stayed shut for 1.1 s after the command to open (the servo's integral
    unwinding; the action stalled), and the step to open threw the finger 7 mm past its goal into the
    next piece."""
    from gazelle.description import read_description_file
    from gazelle.planning import ArmPlanner

    resource_path("moveit_panda")
    urdf = read_description_file(str(CHESSBOT / "chessbot.urdf.xacro"))
    planner = ArmPlanner(urdf, (DUAL / "panda.srdf").read_text())
    sim = make_sim()
    sim.spawn(load(CHESSBOT / "table.sdf").model, name="table")
    robot = sim.spawn(load(CHESSBOT / "chessbot.urdf.xacro").model, name="chessbot")
    sim.spawn(load(CHESSBOARD / "chess_board.sdf").model, name="board", pose=Pose((0.25, 1.39, 0.90)))
    sim.step(1)  # the ros2_control initial values are applied
    arm = planner.group_joints("left_panda_arm")
    down = np.diag([1.0, -1.0, -1.0])  # the hand pointing down, its fingers closing along y
    c = math.cos(math.pi / 4)
    yaw = np.array([[c, c, 0.0], [-c, c, 0.0], [0.0, 0.0, 1.0]])  # -45° about z
    grasp_z = 0.91 + 0.012 + 0.0584 + 0.0538  # the fingertips 12 mm above the board
    ready = (0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785)  # the Panda's "ready": IK starts from it
    seed = planner.state({f"left_panda_joint{i + 1}": v for i, v in enumerate(ready)})

    def ik(x: float, y: float, z: float) -> dict[str, float]:
        # each pose from the last one's joints, with time to spare: under load a short budget ended the first
        # attempt and a random restart found another branch, and the arm swung the piece out of the hand
        nonlocal seed
        target = np.eye(4)
        target[:3, :3], target[:3, 3] = yaw @ down, (x, y, z)
        last = seed
        seed = planner.ik("left_panda_arm", "left_panda_link8", target, seed, timeout=10.0, avoid_collisions=False)
        assert float(np.max(np.abs(seed - last))) < 1.5, "IK jumped to another branch"
        return {n: float(seed[planner.joint_names.index(n)]) for n in arm}

    above, at = ik(0.225, 1.265, grasp_z + 0.08), ik(0.225, 1.265, grasp_z)
    over, put = ik(0.225, 1.365, grasp_z + 0.08), ik(0.225, 1.365, grasp_z + 0.001)
    for name, value in above.items():
        sim.world.set_joint_state("chessbot", name, position=value, velocity=0.0)
    piece = load(CHESSBOARD / "chess_piece.sdf").model
    for name, xy in (("piece", (0.225, 1.265)), ("behind", (0.225, 1.215)), ("next", (0.225, 1.315))):
        sim.spawn(piece, name=name, pose=Pose((*xy, 0.92)))
    cm = _manager(robot)
    _start(cm, DUAL / "ros2_controllers.yaml", "left_arm_controller")
    _start(cm, CHESSBOT / "hand_controllers.yaml", "left_hand_controller")
    jtc, hand = cm.controllers["left_arm_controller"].controller, cm.controllers["left_hand_controller"].controller
    finger = sim.world.joint("chessbot", "left_panda_finger_joint1")

    def move(goal: dict[str, float]) -> None:
        q0 = [sim.world.joint("chessbot", n).position for n in arm]
        points = tuple(
            TrajectoryPoint(
                2.0 * s, tuple(a + (goal[n] - a) * (3 * s**2 - 2 * s**3) for a, n in zip(q0, arm, strict=True))
            )
            for s in (k / 20 for k in range(21))
        )
        g = TrajectoryGoal(JointTrajectory(0.0, tuple(arm), points))
        jtc.submit(g)  # type: ignore[attr-defined]
        _run(sim, g)
        assert g.status == "succeeded", g.error_string

    def grip(position: float) -> GripperGoal:
        g = GripperGoal(position)
        hand.submit(g)  # type: ignore[attr-defined]
        t0 = sim.world.time
        while not g.done.is_set() and sim.world.time < t0 + 5.0:
            sim.step(10)
        return g

    def at_xyz(name: str) -> np.ndarray:
        return np.array(sim.world.entity_state(name).pose.position)

    assert grip(0.016).status == "succeeded"
    move(at)
    start = at_xyz("piece")
    closed = grip(0.0)
    assert closed.stalled and closed.status == "succeeded"  # allow_stalling: the piece stopped it
    assert finger.position > 0.0085  # the piece is 2 cm wide: each finger stops ~1 mm into it at most
    move(above)
    assert at_xyz("piece")[2] - start[2] == pytest.approx(0.08, abs=0.01)  # lifted with the hand
    move(over)
    move(put)
    t0, widest = sim.world.time, 0.0
    opened = GripperGoal(0.016)
    hand.submit(opened)  # type: ignore[attr-defined]
    while not opened.done.is_set() and sim.world.time < t0 + 2.0:
        sim.step(1)
        widest = max(widest, finger.position)
    assert opened.status == "succeeded" and not opened.stalled and sim.world.time - t0 < 0.3
    assert widest < 0.016 + 0.001  # no overshoot into the next piece
    sim.step(500)
    placed = at_xyz("piece")
    assert np.linalg.norm(placed[:2] - (0.225, 1.365)) < 0.005
    assert abs(placed[2] - start[2]) < 0.001  # standing on the board again (upright)
    for other, xy in (("behind", (0.225, 1.215)), ("next", (0.225, 1.315))):
        assert np.linalg.norm(at_xyz(other)[:2] - xy) < 0.001, other


@pytest.mark.parametrize("allow_stalling", [True, False])
def test_a_stalled_gripper_goal_ends_and_the_hand_goes_on_squeezing(allow_stalling: bool):
    """ros2_controllers' GripperActionController (jazzy, gripper_action_controller_impl.hpp): a stall ends
    the goal (succeeded with ``stalled`` when ``allow_stalling``, else aborted) and leaves the command at
    the goal's position. gazelle's aborted goal commanded where the finger had stopped: the hand let go."""
    import logging

    from gazelle.systems import Bus
    from gazelle.systems.ros2_control import GripperActionController
    from gazelle.systems.ros2_control._controller import ControllerContext

    ctx = ControllerContext(
        Bus(), "r", "", logging.getLogger("test"), ("f/position", "f/velocity"), ("f/position",), ("f",)
    )
    hand = GripperActionController("hand", {"joint": "f", "allow_stalling": allow_stalling, "stall_timeout": 0.5}, ctx)
    hand.on_configure()
    states, commands = {"f/position": 0.04, "f/velocity": 0.0}, {"f/position": math.nan}
    hand.on_activate(states, commands)
    goal = GripperGoal(0.0)
    hand.submit(goal)
    t = 0.0
    while not goal.done.is_set() and t < 2.0:
        hand.update(t, 0.01, {"f/position": 0.01, "f/velocity": 0.0}, commands)  # a piece stops it at 1 cm
        t += 0.01
    assert goal.stalled and goal.status == ("succeeded" if allow_stalling else "aborted")
    assert 0.5 < t < 0.6
    hand.update(t, 0.01, {"f/position": 0.01, "f/velocity": 0.0}, commands)
    assert commands["f/position"] == 0.0  # still closing on the piece


# --------------------------------------------------------------------------- bad input
def test_a_ros2_control_initial_value_that_is_not_a_number_is_a_warning_naming_it(make_sim, caplog):
    """Nothing a user gave is dropped silently: an ``initial_value`` that is not a number was read as 0."""
    text = DIFFBOT_URDF.read_text().replace(
        '<state_interface name="position"/>',
        '<state_interface name="position"><param name="initial_value">half</param></state_interface>',
        1,
    )
    sim = make_sim()
    with caplog.at_level("WARNING"):
        sim.spawn(load_string(text, format="urdf").model, name="diffbot", pose=Pose((0.0, 0.0, 0.05)))
    said = [r.getMessage() for r in caplog.records if "initial_value" in r.getMessage()]
    assert said and "initial_value of joint 'left_wheel_joint' must be a number, got 'half'; using 0" in said[0], said


def test_a_velocity_initial_value_sets_the_joint_moving_and_an_effort_one_is_named(make_sim, caplog):
    """gz_ros2_control (jazzy gz_system.cpp initSim): a velocity state interface's initial_value becomes the
    joint's starting velocity (JointVelocityReset); an effort one has nothing to act on in a simulated joint."""
    text = DIFFBOT_URDF.read_text().replace(
        '<state_interface name="velocity"/>',
        '<state_interface name="velocity"><param name="initial_value">2.5</param></state_interface>'
        '<state_interface name="effort"><param name="initial_value">1.0</param></state_interface>',
        1,
    )
    sim = make_sim()
    with caplog.at_level("WARNING"):
        entity = sim.spawn(load_string(text, format="urdf").model, name="diffbot", pose=Pose((0.0, 0.0, 0.05)))
    _manager(entity).hardware[0].start()  # what the manager's first cycle does
    _, dof = sim.world.joint_address("diffbot", "left_wheel_joint")
    assert float(sim.world.data.qvel[dof]) == 2.5
    assert "initial_value of joint 'left_wheel_joint' (effort) is not simulated" in caplog.text


def test_unknown_types_missing_interfaces_and_unloaded_controllers_are_clear_errors(make_sim):
    sim = make_sim()
    cm = _manager(_diffbot(sim))
    cm.files.append(
        parse_params(
            "x:\n  ros__parameters:\n    type: fancy_controllers/Fancy\n"
            "arm:\n  ros__parameters:\n    type: joint_trajectory_controller/JointTrajectoryController\n"
            "    joints: [left_wheel_joint]\n    command_interfaces: [effort]\n"
        )
    )
    with pytest.raises(ControlError, match=r"'fancy_controllers/Fancy' of 'x' does not exist; the types are: .*"
                       r"diff_drive_controller/DiffDriveController"):  # fmt: skip
        cm.load_controller("x")
    with pytest.raises(ControlError, match="type' of controller 'nothing' is not set"):
        cm.load_controller("nothing")
    cm.load_controller("arm")
    with pytest.raises(ControlError, match=r"needs command interface\(s\) left_wheel_joint/effort"):
        cm.configure_controller("arm")
    with pytest.raises(ControlError, match="controller 'ghost' is not loaded"):
        cm.switch_controller(["ghost"], [])
    with pytest.raises(ControlError, match="'arm' is unconfigured; configure it first"):
        cm.switch_controller(["arm"], [])
    # the world kept running through all of it
    sim.step(10)


def test_a_ros2_control_joint_missing_from_the_urdf_fails_the_spawn_and_the_world_goes_on(make_sim):
    urdf = """<robot name="r"><link name="a"><inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1"
      ixy="0" ixz="0" iyz="0"/></inertial></link>
      <ros2_control name="hw" type="system"><hardware><plugin>mock_components/GenericSystem</plugin></hardware>
      <joint name="ghost"><command_interface name="position"/><state_interface name="position"/></joint>
      </ros2_control></robot>"""
    model = load_string(urdf).model
    sim = make_sim()
    # the description already dropped the joint with a warning (file:line); the manager runs with none
    entity = sim.spawn(model, name="r")
    assert _manager(entity).all_command_interfaces() == []
    sim.step(10)


def test_bad_parameter_files_in_the_plugin_tag_fail_the_spawn_with_the_reason(tmp_path, make_sim):
    bad = tmp_path / "c.yaml"
    bad.write_text("controller_manager:\n  ros__parameters:\n    update_rate: {oops\n")
    urdf = DIFFBOT_URDF.read_text().replace(
        "</robot>",
        f'<gazebo><plugin filename="libgazebo_ros2_control.so" name="gazebo_ros2_control">'
        f"<parameters>{bad}</parameters></plugin></gazebo></robot>",
    )
    model = load_string(urdf, source=str(tmp_path / "robot.urdf")).model
    sim = make_sim()
    with pytest.raises(Exception, match=r"c\.yaml:\d+: not valid YAML"):
        sim.spawn(model, name="diffbot")
    assert "diffbot" not in sim.world.entities
    sim.step(10)


def test_the_plugin_tag_names_the_manager_and_its_parameters(tmp_path, make_sim):
    cfg = tmp_path / "c.yaml"
    cfg.write_text(
        "my_cm:\n  ros__parameters:\n    update_rate: 50\n"
        "    diffbot_base_controller:\n      type: diff_drive_controller/DiffDriveController\n"
        f"diffbot_base_controller:\n  ros__parameters:\n{_diffbot_controller_body()}"
    )
    urdf = DIFFBOT_URDF.read_text().replace(
        "</robot>",
        '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
        f"<parameters>{cfg}</parameters><controller_manager_name>my_cm</controller_manager_name>"
        "<ros><namespace>bot</namespace></ros></plugin></gazebo></robot>",
    )
    model = load_string(urdf, source=str(tmp_path / "robot.urdf")).model
    sim = make_sim()
    cm = _manager(sim.spawn(model, name="diffbot", pose=Pose((0, 0, 0.05))))
    assert (cm.node_name, cm.update_rate) == ("/bot/my_cm", 50)
    cm.load_controller("diffbot_base_controller")
    cm.configure_controller("diffbot_base_controller")
    cm.switch_controller(["diffbot_base_controller"], [])
    assert "/bot/diffbot_base_controller/cmd_vel" in {ep.topic for ep in sim.bus.endpoints()}
    assert math.isclose(cm.controllers["diffbot_base_controller"].controller.radius, 0.015)  # type: ignore[attr-defined]


def _diffbot_controller_body() -> str:
    body = DIFFBOT_YAML.read_text().split("ros__parameters:", 2)[2]  # diffbot_base_controller's section
    return body


def test_a_urdf_mimic_joint_follows_its_leader(make_sim):
    inertial = (
        '<inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>'
    )
    urdf = f"""<robot name="g"><link name="world"/><link name="base">{inertial}</link>
      <link name="a">{inertial}</link><link name="b">{inertial}</link>
      <joint name="fix" type="fixed"><parent link="world"/><child link="base"/></joint>
      <joint name="j1" type="prismatic"><parent link="base"/><child link="a"/><axis xyz="1 0 0"/>
        <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
      <joint name="j2" type="prismatic"><parent link="base"/><child link="b"/><axis xyz="1 0 0"/>
        <limit lower="-1" upper="1" effort="10" velocity="1"/><mimic joint="j1" multiplier="-2" offset="0.01"/></joint>
    </robot>"""
    sim = make_sim()
    sim.spawn(load_string(urdf).model, name="g")
    sim.world.set_joint_state("g", "j1", position=0.02)
    sim.step(300)
    j1, j2 = sim.world.joint("g", "j1").position, sim.world.joint("g", "j2").position
    assert j2 == pytest.approx(0.01 - 2 * j1, abs=1e-4)
    assert abs(j1) > 1e-3  # the pair moved together rather than the follower snapping alone


def test_humble_style_unstamped_cmd_vel_and_a_hardware_component_switched_off(make_sim, caplog):
    sim = make_sim()
    cm = _manager(_diffbot(sim))
    cm.files.append(parse_params("diffbot_base_controller:\n  ros__parameters:\n    use_stamped_vel: false\n"))
    with caplog.at_level(logging.WARNING):
        _start(cm, DIFFBOT_YAML, "diffbot_base_controller")  # the diffbot YAML, plus Humble's use_stamped_vel
    # gone from Jazzy's diff_drive_controller (ros2_controllers 4.0.0): a real Jazzy robot would not hear it
    assert "use_stamped_vel: false is Humble's: Jazzy's diff_drive_controller has no such parameter" in caplog.text
    topics = {ep.topic: ep.msg_type for ep in sim.bus.endpoints() if not ep.is_publisher}
    assert topics.get("/diffbot_base_controller/cmd_vel_unstamped") is MsgType.TWIST
    assert "/diffbot_base_controller/cmd_vel" not in topics
    for _ in range(50):
        sim.bus.inject("/diffbot_base_controller/cmd_vel_unstamped", MsgType.TWIST, Twist((0.2, 0.0, 0.0)))
        sim.step(20)
    assert sim.world.entity_state("diffbot").pose.position[0] > 0.1
    # the hardware component made inactive: its controller is deactivated and the wheels hold
    assert cm.set_hardware_component_state("DiffBot", "inactive") == "inactive"
    assert cm.controllers["diffbot_base_controller"].controller.state == "inactive"
    with pytest.raises(ControlError, match="no hardware component 'Nope'"):
        cm.set_hardware_component_state("Nope", "active")


SENSOR_BOT = """<robot name="s">
  <link name="world"/>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
  </inertial></link>
  <link name="tool"><inertial><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
  </inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0 0 1"/></joint>
  <joint name="wrist" type="revolute"><parent link="base"/><child link="tool"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="50" velocity="2"/></joint>
  <gazebo reference="base"><sensor name="imu" type="imu"><update_rate>100</update_rate></sensor></gazebo>
  <gazebo reference="wrist"><sensor name="ft" type="force_torque"><update_rate>100</update_rate></sensor></gazebo>
  <ros2_control name="hw" type="system">
    <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
    <joint name="wrist"><command_interface name="position"/><state_interface name="position"/>
      <state_interface name="velocity"/></joint>
    <sensor name="imu">
      <state_interface name="orientation.x"/><state_interface name="orientation.y"/>
      <state_interface name="orientation.z"/><state_interface name="orientation.w"/>
      <state_interface name="angular_velocity.x"/><state_interface name="angular_velocity.y"/>
      <state_interface name="angular_velocity.z"/><state_interface name="linear_acceleration.x"/>
      <state_interface name="linear_acceleration.y"/><state_interface name="linear_acceleration.z"/>
    </sensor>
    <sensor name="ft">
      <state_interface name="force.x"/><state_interface name="force.y"/><state_interface name="force.z"/>
      <state_interface name="torque.x"/><state_interface name="torque.y"/><state_interface name="torque.z"/>
    </sensor>
  </ros2_control>
</robot>"""


def test_imu_and_force_torque_sensor_components_are_read_from_the_simulated_sensors(make_sim):
    sim = make_sim()
    cm = _manager(sim.spawn(load_string(SENSOR_BOT).model, name="s"))
    cm.files.append(
        parse_params(
            "imu_broadcaster:\n  ros__parameters:\n    type: imu_sensor_broadcaster/IMUSensorBroadcaster\n"
            "    sensor_name: imu\n    frame_id: base\n"
            "ft_broadcaster:\n  ros__parameters:\n    type: force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster\n"
            "    sensor_name: ft\n    frame_id: tool\n"
        )
    )
    for n in ("imu_broadcaster", "ft_broadcaster"):
        cm.load_controller(n)
        cm.configure_controller(n)
    cm.switch_controller(["imu_broadcaster", "ft_broadcaster"], [])
    imu, wrench = [], []
    for ep in sim.bus.endpoints():
        if ep.topic == "/imu_broadcaster/imu":
            ep.add_sink(imu.append)
        if ep.topic == "/ft_broadcaster/wrench":
            ep.add_sink(wrench.append)
    sim.step(500)
    assert imu[-1].frame_id == "base" and imu[-1].linear_acceleration[2] == pytest.approx(9.81, abs=0.01)
    assert imu[-1].orientation == pytest.approx((1.0, 0.0, 0.0, 0.0), abs=1e-6)
    # the 2 kg tool hangs on the wrist joint: 19.6 N along z, as the simulated sensor reads it
    assert abs(wrench[-1].force[2]) == pytest.approx(2 * 9.81, rel=0.01)
    assert wrench[-1].frame_id == "tool"


# --------------------------------------------------------------------------- Husky: 10 Hz manager, coarse steps
HUSKY = REPO / "tests" / "data" / "husky_like"


@pytest.mark.parametrize("step_sec", [0.001, 0.004, 0.01])
def test_a_husky_with_its_10_hz_manager_drives_at_its_command_at_1_4_and_10_ms_steps(step_sec, make_sim):
    """Issue 26 item 4: Husky's own control.yaml runs its manager at 10 Hz, and its playpen world steps
    10 ms. The wheels' integral term was updated once per 0.1 s against a 0.05 s integral time, which
    overshoots every update: the body's speed swung 0.07-0.53 m/s for 0.3 at 10 ms. Its odometry
    integrated the rolling-mean velocity (ros2_controllers integrates each cycle's displacement), so it
    lagged 0.165 m behind the robot."""
    world = default_world()
    world = dataclasses.replace(world, physics=dataclasses.replace(world.physics, max_step_size_sec=step_sec))
    sim = make_sim(world)
    cm = _manager(sim.spawn(load(HUSKY / "husky.urdf").model, name="husky", pose=Pose((0.0, 0.0, 0.14))))
    _start(cm, HUSKY / "control.yaml", "joint_state_broadcaster", "husky_velocity_controller")
    odom: list = []
    for ep in sim.bus.endpoints():
        if ep.topic == "/husky_velocity_controller/odom":
            ep.add_sink(odom.append)
    steps = round(0.1 / step_sec)  # one manager cycle

    def x() -> float:
        return sim.world.entity_state("husky").pose.position[0]

    sim.step(10 * steps)
    x_start = x()
    xs = []
    for _ in range(60):  # 6 s at 0.3 m/s (Humble's unstamped topic: its YAML says use_stamped_vel: false)
        assert sim.bus.inject("/husky_velocity_controller/cmd_vel_unstamped", MsgType.TWIST, Twist((0.3, 0, 0))) == 1
        sim.step(steps)
        xs.append(x())
    speeds = [(b - a) / 0.1 for a, b in zip(xs[-21:], xs[-20:])]  # the last 2 s, cycle by cycle
    assert min(speeds) == pytest.approx(0.3, rel=0.03) and max(speeds) == pytest.approx(0.3, rel=0.03)
    # the odometry of the last cycle (read at its start, one cycle before the end) agrees with the
    # ground truth there
    assert odom[-1].pose.position[0] == pytest.approx(xs[-2] - x_start, abs=0.01)


def test_remapping_rules_resolve_as_rcl_resolves_them() -> None:
    from gazelle.systems._bus import remap_name
    from gazelle.systems._plugin_config import remap_arguments

    rules = (("diffbot_base_controller/odom", "odom"), ("/r1/diffbot_base_controller/cmd_vel", "/cmd_vel"))
    assert remap_name("~/odom", "r1", "diffbot_base_controller", rules) == "/r1/odom"  # both sides expanded
    assert remap_name("~/cmd_vel", "/r1", "diffbot_base_controller", rules) == "/cmd_vel"
    assert remap_name("~/odom", "r1", "other", rules) == "/r1/other/odom"  # another node's name: no match
    first = (("~/odom", "/a"), ("~/odom", "/b"), ("diffbot_base_controller:~/odom", "/c"))
    assert remap_name("~/odom", "", "diffbot_base_controller", first) == "/a"  # the first rule that matches
    assert remap_name("~/odom", "", "x", (("diffbot_base_controller:~/odom", "/c"),)) == "/x/odom"  # node-only
    assert remap_arguments(["--ros-args", "-r", "~/cmd_vel:=/cmd_vel", "--remap", "a:=b", "-p", "x:=1"]) == (
        (("~/cmd_vel", "/cmd_vel"), ("a", "b")),
        ["-p", "x:=1"],
    )


def test_the_plugins_remappings_and_the_spawners_controller_ros_args_reach_the_controllers_topics(
    tmp_path, make_sim, caplog
):
    """gz_ros2_control passes ``<ros><remapping>`` to the manager's node and ros2_control Jazzy hands the
    manager's arguments on to each controller (with a deprecation warning); ``spawner --controller-ros-args``
    sets ``<name>.node_options_args``, applied after them."""
    urdf = DIFFBOT_URDF.read_text().replace(
        "</robot>",
        '<gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">'
        "<ros><namespace>r1</namespace>"
        "<remapping>diffbot_base_controller/odom:=odom</remapping></ros></plugin></gazebo></robot>",
    )
    model = load_string(urdf, source=str(tmp_path / "robot.urdf")).model
    sim = make_sim()
    cm = _manager(sim.spawn(model, name="diffbot", pose=Pose((0, 0, 0.05))))
    cm.set_parameter("diffbot_base_controller.node_options_args", ["--ros-args", "-r", "~/cmd_vel:=/cmd_vel"])
    with caplog.at_level(logging.WARNING):
        _start(cm, DIFFBOT_YAML, "diffbot_base_controller")
    topics = {ep.topic for ep in sim.bus.endpoints()}
    assert {"/r1/odom", "/cmd_vel"} <= topics
    assert not {"/r1/diffbot_base_controller/odom", "/r1/diffbot_base_controller/cmd_vel"} & topics
    assert "remapping arguments to the controller_manager node is deprecated" in caplog.text
    for _ in range(25):
        sim.bus.inject("/cmd_vel", MsgType.TWIST_STAMPED, TwistStamped(0, "", Twist((0.2, 0.0, 0.0))))
        sim.step(20)
    assert sim.world.entity_state("diffbot").pose.position[0] > 0.05  # it drives from the remapped topic


_TWO_JOINT_ARM = """<robot name="arm">
  <link name="world"/><joint name="bolt" type="fixed"><parent link="world"/><child link="base"/></joint>
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l2"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="zeta" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/></joint>
  <joint name="alpha" type="revolute"><parent link="l1"/><child link="l2"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/></joint>
  <ros2_control name="arm" type="system"><hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="zeta"><command_interface name="position"/><state_interface name="position"/></joint>
    <joint name="alpha"><command_interface name="position"/><state_interface name="position"/>
      <state_interface name="velocity"/></joint>
  </ros2_control>
</robot>"""


def test_joint_state_broadcaster_frames_orders_and_filters_as_jazzys(tmp_path, make_sim, caplog):
    """ros2_controllers Jazzy's joint_state_broadcaster.cpp: header.frame_id is ``frame_id`` (``base_link``
    by default) on both messages; with ``use_urdf_to_filter`` the joints are the URDF's moving ones by name
    (its joint map), a missing interface is NaN; without it, the hardware's order; ``frame_id: ""`` is warned;
    ``publish_dynamic_joint_states: false`` advertises no dynamic_joint_states."""
    config = tmp_path / "c.yaml"
    config.write_text(
        "controller_manager:\n  ros__parameters:\n"
        "    jsb: {type: joint_state_broadcaster/JointStateBroadcaster}\n"
        "    raw: {type: joint_state_broadcaster/JointStateBroadcaster}\n"
        "raw:\n  ros__parameters:\n    use_urdf_to_filter: false\n    frame_id: ''\n"
        "    publish_dynamic_joint_states: false\n    use_local_topics: true\n"
    )
    sim = make_sim()
    cm = _manager(sim.spawn(load_string(_TWO_JOINT_ARM).model, name="arm", pose=Pose((0, 0, 0.1))))
    cm.files.append(load_params(config))
    with caplog.at_level(logging.WARNING):
        for name in ("jsb", "raw"):
            cm.load_controller(name)
            cm.configure_controller(name)
        cm.switch_controller(["jsb", "raw"], [])
    assert "Frame ID is not set." in caplog.text
    heard: dict[str, list] = {}
    for ep in sim.bus.endpoints():
        if ep.topic in ("/joint_states", "/raw/joint_states", "/dynamic_joint_states"):
            ep.add_sink(heard.setdefault(ep.topic, []).append)
    assert not [ep for ep in sim.bus.endpoints() if ep.topic == "/raw/dynamic_joint_states"]
    sim.step(50)
    js, raw, djs = heard["/joint_states"][-1], heard["/raw/joint_states"][-1], heard["/dynamic_joint_states"][-1]
    assert (js.names, js.frame_id, djs.frame_id) == (("alpha", "zeta"), "base_link", "base_link")
    assert math.isnan(js.velocities[1]) and not math.isnan(js.velocities[0])  # zeta has no velocity interface
    assert (raw.names, raw.frame_id) == (("zeta", "alpha"), "")


def test_an_effort_trajectory_controller_adds_the_trajectorys_efforts_as_feedforward(tmp_path, make_sim):
    """Jazzy's JTC with an effort command interface commands PID + ``command_next_.effort``: the trajectory's
    efforts, linear between its points (trajectory.cpp interpolate_between_points), sampled a cycle ahead;
    none on the segment from the state before the trajectory. With zero gains the command is the feedforward."""
    from gazelle.systems import JointTrajectory, TrajectoryPoint

    urdf = _TWO_JOINT_ARM.replace('<command_interface name="position"/>', '<command_interface name="effort"/>')
    both = '<state_interface name="position"/><state_interface name="velocity"/>'
    urdf = urdf.replace('<state_interface name="velocity"/>', "").replace('<state_interface name="position"/>', both)
    config = tmp_path / "c.yaml"
    gains = "{p: 0.0, i: 0.0, d: 0.0, ff_velocity_scale: 0.0}"
    config.write_text(
        "controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
        "    arm: {type: joint_trajectory_controller/JointTrajectoryController}\n"
        "arm:\n  ros__parameters:\n    joints: [zeta, alpha]\n    command_interfaces: [effort]\n"
        f"    state_interfaces: [position, velocity]\n    gains: {{zeta: {gains}, alpha: {gains}}}\n"
    )
    sim = make_sim()
    cm = _manager(sim.spawn(load_string(urdf).model, name="arm", pose=Pose((0, 0, 0.1))))
    _start(cm, config, "arm")
    points = (
        TrajectoryPoint(0.5, (0.0, 0.0), effort=(1.0, 2.0)),
        TrajectoryPoint(1.0, (0.0, 0.0), effort=(3.0, 6.0)),
    )
    assert (
        sim.bus.inject(
            "/arm/joint_trajectory", MsgType.JOINT_TRAJECTORY, JointTrajectory(0.0, ("zeta", "alpha"), points)
        )
        == 1
    )
    hw = cm.hardware[0]
    seen = []
    for _ in range(120):  # 100 Hz cycles over 1.2 s
        sim.step(10)
        seen.append((sim.world.time, hw.commands["zeta/effort"], hw.commands["alpha/effort"]))
    before = [z for t, z, _ in seen if t < 0.45]
    assert before and all(z == 0.0 for z in before)  # the segment from the state before the trajectory
    between = [(t, z, a) for t, z, a in seen if 0.55 < t < 0.95]
    # 1 -> 3 over 0.5 s, sampled a cycle (10 ms) ahead of a start within one cycle of 0
    assert all(z == pytest.approx(1.0 + 4.0 * (t - 0.5), abs=0.05) and a == 2 * z for t, z, a in between)
    assert seen[-1][1:] == (3.0, 6.0)  # past the end: the last point's efforts


def test_joint_state_broadcaster_extra_joints_join_both_messages_at_zero_once_each(tmp_path, make_sim):
    """Jazzy joint_state_broadcaster.cpp init_joint_data: an extra joint not already known is added with
    position, velocity and effort 0 to joint_states and dynamic_joint_states; a hardware joint named there
    keeps its own values, and a name listed twice is added once."""
    config = tmp_path / "c.yaml"
    config.write_text(
        "controller_manager:\n  ros__parameters:\n    jsb: {type: joint_state_broadcaster/JointStateBroadcaster}\n"
        "jsb:\n  ros__parameters:\n    extra_joints: [gripper, zeta, gripper]\n"
    )
    sim = make_sim()
    cm = _manager(sim.spawn(load_string(_TWO_JOINT_ARM).model, name="arm", pose=Pose((0, 0, 0.1))))
    _start(cm, config, "jsb")
    heard: dict[str, list] = {}
    for ep in sim.bus.endpoints():
        if ep.topic in ("/joint_states", "/dynamic_joint_states"):
            ep.add_sink(heard.setdefault(ep.topic, []).append)
    sim.step(50)
    js, djs = heard["/joint_states"][-1], heard["/dynamic_joint_states"][-1]
    assert js.names == ("alpha", "zeta", "gripper")
    assert (js.positions[2], js.velocities[2], js.efforts[2]) == (0.0, 0.0, 0.0)
    assert djs.joint_names[-1] == "gripper" and djs.joint_names.count("zeta") == 1
    assert djs.interface_values[-1] == InterfaceValue(("position", "velocity", "effort"), (0.0, 0.0, 0.0))


def test_remapping_rules_a_ros_peer_sets_that_rcl_would_refuse_refuse_the_load_and_the_manager_goes_on(make_sim):
    """``<name>.node_options_args`` is a parameter any ROS peer can set: a value that is not a list of strings,
    or a rule whose names are not ROS names (as rcl refuses them, and the node is not made), refuses that
    controller's load with the reason, quoted and bounded; the manager loads the next one as before."""
    from gazelle.description import ConfigElement
    from gazelle.systems._plugin_config import ros_remaps

    sim = make_sim()
    cm = _manager(_diffbot(sim))
    cm.files.append(load_params(DIFFBOT_YAML))
    cm.set_parameter("diffbot_base_controller.type", "diff_drive_controller/DiffDriveController")
    for args, why in (
        (5, "must be a list of strings"),
        (["-r", "~/cmd_vel:=/bad name!" + "x" * 500], "not a valid ROS name"),
        (["-r", "1node:~/cmd_vel:=/cmd_vel"], "not a valid ROS name"),
        (["-r", "~/odom:=/a//b"], "not a valid ROS name"),
    ):
        cm.set_parameter("diffbot_base_controller.node_options_args", args)
        with pytest.raises(ControlError, match=why) as err:
            cm.load_controller("diffbot_base_controller")
        assert len(str(err.value)) < 300 and "diffbot_base_controller" not in cm.controllers
    cm.set_parameter("diffbot_base_controller.node_options_args", ["-r", "~/cmd_vel:=/cmd_vel"])
    cm.load_controller("diffbot_base_controller")
    assert cm.controllers["diffbot_base_controller"].controller.topic("~/cmd_vel") == "/cmd_vel"
    # the ROS 1-era spelling of a plugin's rule, read as every gazebo_ros plugin reads it
    ros = ConfigElement("ros", children=(ConfigElement("remapping", text="a/odom=odom"),))
    assert ros_remaps(ConfigElement("plugin", children=(ros,))) == (("a/odom", "odom"),)

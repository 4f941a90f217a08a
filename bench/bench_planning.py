"""Arm planning: IK success rate and planning time in-process, then 20 Panda pose goals executed in a simulation.

Run: ``.venv/bin/python bench/bench_planning.py [--goals 20] [--ik 500] [--random-goals 50] [--seed 51] [--no-sim]``.

1. In-process (gazelle.planning.ArmPlanner on the Panda of moveit_resources_panda_moveit_config, its
   URDF, SRDF and joint_limits.yaml unchanged): ``--ik`` poses of panda_link8 at random joint values
   that are within limits and collision-free (so reachable by construction); IK from the ``ready``
   state with the default 0.5 s budget. Prints the success rate and IK time (median, p90). Then
   ``--goals`` pose goals from ``ready``: IK + RRT-Connect + shortcut + TOPP-RA, median and p90 of
   the whole plan.
2. ``--random-goals`` (issue 51) random reachable pose goals on the Panda and on UR's UR5e (ur_simulation_gz's URDF,
   ur_moveit_config's SRDF, tests/data/ur), planned as move_group plans them (tests/_pose_goals.py): how many were
   planned, the tip's error at each plan's last point, the time per goal.
3. With a simulation (unless ``--no-sim``): ``gazelle sim``, the Panda bolted to the world
   (examples/arms/panda_on_table.urdf.xacro), its ros2_controllers.yaml through the spawner, and
   ``gazelle move_group``, in a private ROS domain. ``--goals`` reachable poses (arm links clear of
   the floor) are sent one after another as MoveGroup action goals (1 mm / 0.01 rad constraints,
   scaling 1.0), each executed by panda_arm_controller. Afterwards the simulation's panda_link8
   pose (/get_entity_state) is compared with the goal: position error and orientation error,
   the planning_time move_group reports, and the wall time per goal.

Machine-dependent; nothing asserts timing. Takes about 2 minutes.
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

from _domain import private_ros_domain

private_ros_domain()
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO / "tests"))
from _paths import REAL  # noqa: E402 - the shared fixtures as the tests find them

PANDA = REAL / "moveit_panda"
os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"
ON_TABLE = REPO / "examples" / "arms" / "panda_on_table.urdf.xacro"
ARM = [f"panda_joint{i}" for i in range(1, 8)]
READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]
FLOOR_CLEARANCE = 0.15  # m: goals keep links 3, 5, 7 and 8 this far above the floor


def percentile(values: list[float], p: float) -> float:
    s = sorted(values)
    return s[min(len(s) - 1, int(round(p / 100 * (len(s) - 1))))]


def make_planner():
    import yaml

    from gazelle.description import read_description_file
    from gazelle.planning import ArmPlanner, moveit_joint_limits

    urdf = read_description_file(str(CONFIG / "panda.urdf.xacro"))
    srdf = (CONFIG / "panda.srdf").read_text()
    limits = moveit_joint_limits(yaml.safe_load((CONFIG / "joint_limits.yaml").read_text()))
    return ArmPlanner(urdf, srdf, joint_limits=limits, seed=1)


def sample_goals(planner, count: int, seed: int) -> list:
    """4x4 poses of panda_link8 at random valid joint values with the arm clear of the floor."""
    import numpy as np

    rng = np.random.default_rng(seed)
    lo, hi = planner.scene.getPositionLimitVectors("")
    out = []
    while len(out) < count:
        q = planner.state(None)
        idx = [planner.joint_names.index(j) for j in ARM]
        q[idx] = rng.uniform(np.array(lo)[idx], np.array(hi)[idx])
        if planner.in_collision(q):
            continue
        if min(planner.fk(q, link)[2, 3] for link in ("panda_link3", "panda_link5", "panda_link7", "panda_link8")) < (
            FLOOR_CLEARANCE
        ):
            continue
        out.append(planner.fk(q, "panda_link8"))
    return out


def in_process(goals: int, iks: int) -> list:
    from gazelle.planning import PlanningError

    t0 = time.perf_counter()
    planner = make_planner()
    print(f"ArmPlanner load (Panda URDF + SRDF, collision model): {time.perf_counter() - t0:.2f} s")
    ready = planner.state(dict(zip(ARM, READY)))
    targets = sample_goals(planner, iks, seed=3)
    ok, times = 0, []
    for target in targets:
        t = time.perf_counter()
        try:
            planner.ik("panda_arm", "panda_link8", target, ready, timeout=0.5)
            ok += 1
        except PlanningError:
            pass
        times.append((time.perf_counter() - t) * 1e3)
    print(
        f"IK, {iks} reachable collision-free poses: success {100 * ok / iks:.1f} %, "
        f"median {percentile(times, 50):.2f} ms, p90 {percentile(times, 90):.2f} ms"
    )
    plan_goals = sample_goals(planner, goals, seed=5)
    times, failures = [], 0
    for target in plan_goals:
        t = time.perf_counter()
        try:
            goal = planner.ik("panda_arm", "panda_link8", target, ready)
            planner.plan("panda_arm", goal, ready, velocity_scaling=1.0, acceleration_scaling=1.0)
        except PlanningError:
            failures += 1
        times.append((time.perf_counter() - t) * 1e3)
    print(
        f"plan (IK + RRT-Connect + shortcut + TOPP-RA), {goals} pose goals from 'ready': "
        f"median {percentile(times, 50):.2f} ms, p90 {percentile(times, 90):.2f} ms, failures {failures}"
    )
    return plan_goals


class Proc:
    def __init__(self, name: str, *args: str, cmd: list[str] | None = None, env: dict | None = None) -> None:
        self.name = name
        self.lines: list[str] = []
        self.p = subprocess.Popen(
            cmd or [sys.executable, "-m", "gazelle.cli", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,
            env=env,
        )
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        for line in self.p.stdout:
            self.lines.append(line.rstrip())

    def wait_line(self, needle: str, timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while not any(needle in ln for ln in self.lines):
            if time.monotonic() > deadline or self.p.poll() is not None:
                raise SystemExit(f"{self.name} did not print {needle!r}:\n" + "\n".join(self.lines[-30:]))
            time.sleep(0.05)

    def stop(self) -> None:
        if self.p.poll() is None:
            os.killpg(self.p.pid, signal.SIGINT)
            try:
                self.p.wait(30)
            except subprocess.TimeoutExpired:
                os.killpg(self.p.pid, signal.SIGKILL)


def panda_up(procs: list) -> tuple[str, str, str, str]:
    """``gazelle sim``, the Panda on the table, its controllers and ``gazelle move_group``; returns the group, the
    tip, the goals' frame and the simulation's link whose position is the tip's."""
    sim = Proc("sim", "sim", "--no-viewer")
    procs.append(sim)
    sim.wait_line("gazelle: ready", 60)
    spawn = Proc("spawn", "spawn", "-entity", "panda", "-file", str(ON_TABLE))
    spawn.p.wait(120)
    spawner = Proc(
        "spawner",
        "spawner",
        "joint_state_broadcaster",
        "panda_arm_controller",
        "-p",
        str(CONFIG / "ros2_controllers.yaml"),
    )
    if spawner.p.wait(60) != 0:
        raise SystemExit("spawner failed:\n" + "\n".join(spawner.lines))
    mg = Proc(
        "move_group", "move_group", "--urdf", str(CONFIG / "panda.urdf.xacro"), "--srdf", str(CONFIG / "panda.srdf"),
        "--config", str(CONFIG),
    )  # fmt: skip
    procs.append(mg)
    mg.wait_line("You can start planning now!", 60)
    return "panda_arm", "panda_link8", "panda_link0", "panda::panda_link8"


def ur5e_up(procs: list, prefix: Path) -> tuple[str, str, str, str]:
    """UR's ``ros2 launch ur_simulation_gz ur_sim_moveit.launch.py ur_type:=ur5e`` (its files unchanged, tests/data/ur)
    with the scaled controller started, as tests/integration/test_ur5e_moveit.py launches it. tool0 is fixed to
    wrist_3_link at its origin, the arm's base at the world's origin."""
    from _ur import install_ur

    install_ur(prefix)
    env = {
        **os.environ,
        "AMENT_PREFIX_PATH": f"{prefix}{os.pathsep}{sys.prefix}",
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
    }
    cmd = [str(Path(sys.prefix) / "bin" / "ros2"), "launch", "ur_simulation_gz", "ur_sim_moveit.launch.py"]
    cmd += ["ur_type:=ur5e", "gazebo_gui:=false", "initial_joint_controller:=scaled_joint_trajectory_controller"]
    launch = Proc("ros2 launch", cmd=cmd, env=env)
    procs.append(launch)
    launch.wait_line("Configured and activated scaled_joint_trajectory_controller", 180)
    launch.wait_line("You can start planning now!", 60)
    return "ur_manipulator", "tool0", "base_link", "ur::wrist_3_link"


def with_simulation(name: str, goals: list) -> None:
    """The goals (4x4 poses of the tip in the goals' frame) one after another as MoveGroup action goals (1 mm /
    0.01 rad constraints, scaling 1.0) on ``name``'s simulation, each then measured in the simulation."""
    import tempfile

    import rclpy
    import rclpy.action
    import rclpy.executors
    from gazebo_msgs.srv import GetEntityState
    from moveit_msgs.action import MoveGroup

    procs: list = []
    with tempfile.TemporaryDirectory() as tmp:
        try:
            robot = panda_up(procs) if name == "panda" else ur5e_up(procs, Path(tmp) / "install")
            rclpy.init()
            node = rclpy.create_node("bench_planning")
            executor = rclpy.executors.SingleThreadedExecutor()
            executor.add_node(node)
            threading.Thread(target=_spin, args=(executor,), daemon=True).start()
            client = rclpy.action.ActionClient(node, MoveGroup, "/move_action")
            state = node.create_client(GetEntityState, "/get_entity_state")
            client.wait_for_server(timeout_sec=30)
            state.wait_for_service(timeout_sec=30)
            print(f"simulation, {name}: " + send_goals(executor, client, state, robot, goals))
            rclpy.shutdown()
        finally:
            for proc in reversed(procs):
                proc.stop()


def _spin(executor) -> None:
    from rclpy.executors import ExternalShutdownException

    try:
        executor.spin()
    except ExternalShutdownException:
        pass  # rclpy.shutdown() at the robot's end


def _call(state, request, timeout: float = 30.0):
    """A /get_entity_state answer; the request sent again each 2 s without one (an idempotent query whose first
    reply can be lost while the server has not matched this client)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        f = state.call_async(request)
        until = time.monotonic() + 2.0
        while not f.done() and time.monotonic() < until:
            time.sleep(0.005)
        if f.done():
            return f.result()
        state.remove_pending_request(f)
    raise SystemExit("/get_entity_state did not answer")


def pose_goal(group: str, tip: str, frame: str, target):
    from geometry_msgs.msg import Pose
    from moveit_msgs.action import MoveGroup
    from moveit_msgs.msg import Constraints, OrientationConstraint, PositionConstraint
    from shape_msgs.msg import SolidPrimitive

    from gazelle.ros import matrix_to_pose as _pose

    p = _pose(target)
    goal = MoveGroup.Goal()
    req = goal.request
    req.group_name = group
    req.allowed_planning_time = 5.0
    req.max_velocity_scaling_factor = req.max_acceleration_scaling_factor = 1.0
    pc = PositionConstraint(link_name=tip, weight=1.0)
    pc.header.frame_id = frame
    pc.constraint_region.primitives.append(SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001]))
    pc.constraint_region.primitive_poses.append(Pose(position=p.position))
    oc = OrientationConstraint(link_name=tip, orientation=p.orientation, weight=1.0)
    oc.header.frame_id = frame
    oc.absolute_x_axis_tolerance = oc.absolute_y_axis_tolerance = oc.absolute_z_axis_tolerance = 0.01
    req.goal_constraints.append(Constraints(position_constraints=[pc], orientation_constraints=[oc]))
    return goal


def send_goals(executor, client, state, robot: tuple[str, str, str, str], goals: list) -> str:
    """Each goal through the MoveGroup action, then the simulation's link at rest compared with it (position only:
    the measured link's frame is not the tip's on every robot); returns the summary."""
    from gazebo_msgs.srv import GetEntityState
    from moveit_msgs.msg import MoveItErrorCodes

    group, tip, frame, measured = robot
    pos_err, plan_ms, wall, failures = [], [], [], []
    for k, target in enumerate(goals):
        box: dict = {}
        finished = threading.Event()

        def on_goal(f, box=box, finished=finished) -> None:
            f.result().get_result_async().add_done_callback(
                lambda r: (box.__setitem__("result", r.result()), finished.set())
            )

        t = time.perf_counter()
        # on the executor's thread: from another, a fast reply can be dropped (ros2/rclpy#1123)
        goal = pose_goal(group, tip, frame, target)
        executor.create_task(lambda g=goal, cb=on_goal: client.send_goal_async(g).add_done_callback(cb))
        if not finished.wait(120):
            failures.append(f"goal {k}: no result in 120 s")
            continue
        wall.append(time.perf_counter() - t)
        result = box["result"].result
        if result.error_code.val != MoveItErrorCodes.SUCCESS:
            failures.append(f"goal {k}: {result.error_code.val} {result.error_code.message}")
            continue
        plan_ms.append(result.planning_time * 1e3)
        time.sleep(0.3)  # settle: the measurement is of the arm at rest
        s = _call(state, GetEntityState.Request(name=measured)).state.pose
        pos_err.append(1e3 * math.dist((s.position.x, s.position.y, s.position.z), target[:3, 3]))
    n = len(goals)
    out = f"{n - len(failures)}/{n} pose goals executed"
    for line in failures:
        out += "\n  " + line
    if pos_err:
        out += (
            f"\n  {measured} in the simulation: position error median {percentile(pos_err, 50):.3f} mm, "
            f"max {max(pos_err):.3f} mm, within 1 mm {sum(1 for e in pos_err if e < 1)}/{n}"
            f"\n  move_group planning_time: median {percentile(plan_ms, 50):.1f} ms, p90 {percentile(plan_ms, 90):.1f}"
            f" ms; wall per goal (plan + execute): median {percentile(wall, 50):.2f} s"
        )
    return out


def random_goals(count: int, seed: int) -> None:
    """Issue 51: ``count`` random reachable pose goals on the Panda and on UR's UR5e, planned as move_group plans a
    pose goal (IK from the start state, then a plan within 5 s), each from where the last ended
    (tests/_pose_goals.py, as tests/planning/test_random_pose_goals.py runs them)."""
    import tempfile

    from _pose_goals import panda_arm, plan_goals, reachable_goals, ur5e_arm

    with tempfile.TemporaryDirectory() as tmp:
        for make in (panda_arm, lambda: ur5e_arm(Path(tmp) / "install")):
            arm = make()
            t = time.perf_counter()
            out = plan_goals(arm, reachable_goals(arm, count, seed))
            print(
                f"{arm.name}, {count} random reachable pose goals (seed {seed}): {out.summary(count)}; "
                f"{time.perf_counter() - t:.1f} s in all"
            )
            for line in out.failures:
                print("  " + line)


def random_goals_of(name: str, count: int, seed: int) -> list:
    """``count`` random reachable poses of ``name``'s tip (tests/_pose_goals.py), without planning them."""
    import tempfile

    from _pose_goals import panda_arm, reachable_goals, ur5e_arm

    with tempfile.TemporaryDirectory() as tmp:
        arm = panda_arm() if name == "panda" else ur5e_arm(Path(tmp) / "install")
        return reachable_goals(arm, count, seed)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--goals", type=int, default=20)
    parser.add_argument("--ik", type=int, default=500)
    parser.add_argument("--random-goals", type=int, default=50, help="issue 51's random pose goals per robot (0: none)")
    parser.add_argument("--seed", type=int, default=51, help="the random pose goals' seed")
    parser.add_argument("--no-sim", action="store_true")
    parser.add_argument("--sim-ur5e", action="store_true", help="also --goals random goals on UR's UR5e simulation")
    args = parser.parse_args()
    t0 = time.perf_counter()
    goals = in_process(args.goals, args.ik)
    if args.random_goals:
        random_goals(args.random_goals, args.seed)
    if not args.no_sim:
        with_simulation("panda", goals)
        if args.sim_ur5e:
            ur_goals = random_goals_of("ur5e", args.goals, args.seed)
            with_simulation("ur5e", ur_goals)
    print(f"bench took {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()

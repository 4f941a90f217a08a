"""Arm planning: IK success rate and planning time in-process, then 20 Panda pose goals executed in a simulation.

Run: ``.venv/bin/python bench/bench_planning.py [--goals 20] [--ik 500] [--no-sim]``.

1. In-process (gazelle.planning.ArmPlanner on the Panda of moveit_resources_panda_moveit_config, its
   URDF, SRDF and joint_limits.yaml unchanged): ``--ik`` poses of panda_link8 at random joint values
   that are within limits and collision-free (so reachable by construction); IK from the ``ready``
   state with the default 0.5 s budget. Prints the success rate and IK time (median, p90). Then
   ``--goals`` pose goals from ``ready``: IK + RRT-Connect + shortcut + TOPP-RA, median and p90 of
   the whole plan.
2. With a simulation (unless ``--no-sim``): ``gazelle sim``, the Panda bolted to the world
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
    def __init__(self, name: str, *args: str) -> None:
        self.name = name
        self.lines: list[str] = []
        self.p = subprocess.Popen(
            [sys.executable, "-m", "gazelle.cli", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,
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
                self.p.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(self.p.pid, signal.SIGKILL)


def with_simulation(goals: list) -> None:
    import numpy as np
    import rclpy
    from gazebo_msgs.srv import GetEntityState
    from geometry_msgs.msg import Pose
    from moveit_msgs.action import MoveGroup
    from moveit_msgs.msg import Constraints, MoveItErrorCodes, OrientationConstraint, PositionConstraint
    from rclpy.action import ActionClient
    from shape_msgs.msg import SolidPrimitive

    from gazelle.ros import matrix_to_pose as _pose

    procs = []
    try:
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
            "move_group",
            "move_group",
            "--urdf",
            str(CONFIG / "panda.urdf.xacro"),
            "--srdf",
            str(CONFIG / "panda.srdf"),
            "--config",
            str(CONFIG),
        )
        procs.append(mg)
        mg.wait_line("You can start planning now!", 60)
        rclpy.init()
        node = rclpy.create_node("bench_planning")
        executor = rclpy.executors.SingleThreadedExecutor()
        executor.add_node(node)
        threading.Thread(target=executor.spin, daemon=True).start()
        client = ActionClient(node, MoveGroup, "/move_action")
        state = node.create_client(GetEntityState, "/get_entity_state")
        client.wait_for_server(timeout_sec=30)
        state.wait_for_service(timeout_sec=30)

        def sim_time() -> float:
            f = state.call_async(GetEntityState.Request(name="panda::panda_link8"))
            while not f.done():
                time.sleep(0.005)
            stamp = f.result().header.stamp
            return stamp.sec + stamp.nanosec * 1e-9

        pos_err, ang_err, plan_ms, wall, failures, rtf = [], [], [], [], [], []
        for k, target in enumerate(goals):
            sim0, wall0 = sim_time(), time.perf_counter()
            p = _pose(target)
            goal = MoveGroup.Goal()
            req = goal.request
            req.group_name = "panda_arm"
            req.allowed_planning_time = 5.0
            req.max_velocity_scaling_factor = req.max_acceleration_scaling_factor = 1.0
            pc = PositionConstraint(link_name="panda_link8", weight=1.0)
            pc.header.frame_id = "panda_link0"
            pc.constraint_region.primitives.append(SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[0.001]))
            pc.constraint_region.primitive_poses.append(Pose(position=p.position))
            oc = OrientationConstraint(link_name="panda_link8", orientation=p.orientation, weight=1.0)
            oc.header.frame_id = "panda_link0"
            oc.absolute_x_axis_tolerance = oc.absolute_y_axis_tolerance = oc.absolute_z_axis_tolerance = 0.01
            req.goal_constraints.append(Constraints(position_constraints=[pc], orientation_constraints=[oc]))
            t = time.perf_counter()
            box: dict = {}
            finished = threading.Event()

            def on_goal(f, box=box, finished=finished) -> None:
                f.result().get_result_async().add_done_callback(
                    lambda r: (box.__setitem__("result", r.result()), finished.set())
                )

            # on the executor's thread: from another, a fast reply can be dropped (ros2/rclpy#1123)
            executor.create_task(lambda g=goal, cb=on_goal: client.send_goal_async(g).add_done_callback(cb))
            finished.wait(120)
            wall.append(time.perf_counter() - t)
            rtf.append((sim_time() - sim0) / (time.perf_counter() - wall0))
            result = box["result"].result
            if result.error_code.val != MoveItErrorCodes.SUCCESS:
                failures.append(f"goal {k}: {result.error_code.val} {result.error_code.message}")
                continue
            plan_ms.append(result.planning_time * 1e3)
            time.sleep(0.3)  # settle: the measurement is of the arm at rest
            f = state.call_async(GetEntityState.Request(name="panda::panda_link8"))
            while not f.done():
                time.sleep(0.005)
            s = f.result().state.pose
            pos_err.append(1e3 * math.dist((s.position.x, s.position.y, s.position.z), target[:3, 3]))
            q1 = np.array([s.orientation.x, s.orientation.y, s.orientation.z, s.orientation.w])
            q2 = np.array([p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w])
            ang_err.append(2 * math.acos(min(1.0, abs(float(q1 @ q2)))))
        n = len(goals)
        print(f"simulation: {n - len(failures)}/{n} pose goals executed")
        for line in failures:
            print("  " + line)
        if failures:
            for proc in procs:
                for line in proc.lines:
                    if "WARN" in line or "ERROR" in line or "fail" in line:
                        print(f"  [{proc.name}] {line}")
        if pos_err:
            print(
                f"  position error of panda_link8 in the simulation: median {percentile(pos_err, 50):.3f} mm, "
                f"max {max(pos_err):.3f} mm (goal < 1 mm); within 1 mm and 0.01 rad: "
                f"{sum(1 for a, b in zip(pos_err, ang_err) if a < 1 and b < 0.01)}/{n}"
            )
            print(f"  orientation error: median {percentile(ang_err, 50):.5f} rad, max {max(ang_err):.5f} rad")
            print(
                f"  move_group planning_time: median {percentile(plan_ms, 50):.1f} ms, "
                f"p90 {percentile(plan_ms, 90):.1f} ms; wall per goal (plan + execute): "
                f"median {percentile(wall, 50):.2f} s; simulation real-time factor meanwhile: "
                f"min {min(rtf):.2f}, median {percentile(rtf, 50):.2f}"
            )
        rclpy.shutdown()
    finally:
        for proc in reversed(procs):
            proc.stop()


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--goals", type=int, default=20)
    parser.add_argument("--ik", type=int, default=500)
    parser.add_argument("--no-sim", action="store_true")
    args = parser.parse_args()
    goals = in_process(args.goals, args.ik)
    if not args.no_sim:
        with_simulation(goals)


if __name__ == "__main__":
    main()

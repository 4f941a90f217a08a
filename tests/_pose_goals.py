"""Random reachable pose goals on the Panda and the UR5e, planned as move_group plans a MoveGroup pose goal (issue 51):
IK of the tip at the goal from the start state, then a plan to it within allowed_planning_time
(gazelle/ros/_move_group_pipeline.py ``PlanningPipeline.plan``: ``planner.ik`` then ``planner.plan``).

Reachable by construction: each goal is the tip's pose at random joint values within the limits that are collision
free and keep the arm's links clear of the floor the simulation has; the draws come from a fixed seed. Used by
tests/planning/test_random_pose_goals.py and bench/bench_planning.py.
"""

from __future__ import annotations

import os
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from _paths import REAL
from _ur import UR, install_ur

PANDA = REAL / "moveit_panda"
PANDA_CONFIG = PANDA / "moveit_resources_panda_moveit_config" / "config"


@dataclass(frozen=True)
class Arm:
    """A planner of one robot and what its goals are made of."""

    name: str
    planner: Any
    group: str
    tip: str
    start: str  # the SRDF named state the first goal starts from
    clear: tuple[str, ...]  # links kept at least FLOOR_CLEARANCE above the floor (z = 0) at every goal
    frame: str = ""  # the frame goals are given in (MoveIt's planning frame when empty)


FLOOR_CLEARANCE = 0.15
"""m: a goal keeps these links this far above the floor (the simulation's ground plane)."""


def panda_arm() -> Arm:
    """MoveIt's Panda config (URDF, SRDF, joint_limits.yaml), its meshes from the resource roots."""
    from gazelle.description import read_description_file
    from gazelle.planning import ArmPlanner, moveit_joint_limits

    saved = os.environ.get("GAZELLE_RESOURCE_PATH")
    os.environ["GAZELLE_RESOURCE_PATH"] = str(PANDA)
    try:
        urdf = read_description_file(str(PANDA_CONFIG / "panda.urdf.xacro"))
        limits = moveit_joint_limits(yaml.safe_load((PANDA_CONFIG / "joint_limits.yaml").read_text()))
        planner = ArmPlanner(urdf, (PANDA_CONFIG / "panda.srdf").read_text(), joint_limits=limits, seed=1)
    finally:
        _restore({"GAZELLE_RESOURCE_PATH": saved})
    return Arm("panda", planner, "panda_arm", "panda_link8", "ready", ("panda_link3", "panda_link5", "panda_link7"))


def ur5e_arm(prefix: Path) -> Arm:
    """The UR5e as ur_sim_moveit.launch.py gives it to move_group: ur_simulation_gz's URDF (``ur_type:=ur5e``),
    ur_moveit_config's SRDF and joint_limits.yaml, UR's files unchanged (tests/data/ur), installed under
    ``prefix`` for xacro's ``$(find ...)``."""
    from gazelle.planning import ArmPlanner, moveit_joint_limits

    install_ur(prefix)
    saved = {k: os.environ.get(k) for k in ("AMENT_PREFIX_PATH", "GAZELLE_RESOURCE_PATH")}
    os.environ["AMENT_PREFIX_PATH"] = os.pathsep.join(p for p in (str(prefix), saved["AMENT_PREFIX_PATH"]) if p)
    os.environ["GAZELLE_RESOURCE_PATH"] = str(UR)  # the collision meshes (file:// paths under tests/data/ur)
    try:
        urdf = _xacro(prefix / "share" / "ur_simulation_gz" / "urdf" / "ur_gz.urdf.xacro", name="ur", ur_type="ur5e")
        srdf = _xacro(prefix / "share" / "ur_moveit_config" / "srdf" / "ur.srdf.xacro", name="ur5e")
        moveit_limits = yaml.safe_load((UR / "ur_moveit_config" / "config" / "joint_limits.yaml").read_text())
        planner = ArmPlanner(urdf, srdf, joint_limits=moveit_joint_limits(moveit_limits), seed=1)
    finally:
        _restore(saved)
    return Arm(
        "ur5e", planner, "ur_manipulator", "tool0", "home", ("forearm_link", "wrist_1_link", "wrist_2_link", "tool0")
    )


def _restore(saved: dict[str, str | None]) -> None:
    """The environment variables as they were (bench_planning.py's simulation needs its resource path back)."""
    for key, value in saved.items():
        if value is None:
            os.environ.pop(key, None)
        else:
            os.environ[key] = value


def _xacro(path: Path, **args: str) -> str:
    """xacro's expansion of ``path`` with ``args`` (as ur_sim_control.launch.py and MoveItConfigsBuilder run it)."""
    from xml.dom.minidom import Document

    import xacro

    document = xacro.process_file(str(path), mappings=args)
    assert isinstance(document, Document)  # (xacro's annotation says a file)
    return document.toxml()


def reachable_goals(arm: Arm, count: int, seed: int) -> list[np.ndarray]:
    """``count`` 4x4 poses of the tip (root frame) at random valid joint values of the group, the arm clear of the
    floor, drawn from ``seed``."""
    planner = arm.planner
    rng = np.random.default_rng(seed)
    lo, hi = (np.array(v) for v in planner.scene.getPositionLimitVectors(""))
    idx = [planner.joint_names.index(j) for j in planner.group_joints(arm.group)]
    out: list[np.ndarray] = []
    while len(out) < count:
        q = planner.state(planner.named_state(arm.group, arm.start))
        q[idx] = rng.uniform(lo[idx], hi[idx])
        if planner.in_collision(q):
            continue
        if min(planner.fk(q, link)[2, 3] for link in (*arm.clear, arm.tip)) < FLOOR_CLEARANCE:
            continue
        out.append(planner.fk(q, arm.tip))
    return out


@dataclass
class Outcome:
    """What a run of goals gave: failures (index and MoveIt code: message), the tip's position error of each plan's
    last point (mm) and orientation error (rad), and the seconds each goal took (IK + plan)."""

    failures: list[str] = field(default_factory=list)
    position_mm: list[float] = field(default_factory=list)
    angle_rad: list[float] = field(default_factory=list)
    seconds: list[float] = field(default_factory=list)

    def summary(self, count: int) -> str:
        done = count - len(self.failures)
        if not self.position_mm:
            return f"{done}/{count} planned"
        return (
            f"{done}/{count} planned; the plan's last point: position error median "
            f"{statistics.median(self.position_mm):.4f} mm, max {max(self.position_mm):.4f} mm; orientation error "
            f"median {statistics.median(self.angle_rad):.5f} rad; per goal (IK + plan) median "
            f"{statistics.median(self.seconds) * 1e3:.0f} ms, max {max(self.seconds) * 1e3:.0f} ms"
        )


def plan_goals(arm: Arm, goals: list[np.ndarray], planning_time: float = 5.0) -> Outcome:
    """Each goal from where the last one ended (the first from the named start state), as one MoveGroup goal after
    another moves the arm: IK from the start state, then a plan within ``planning_time``."""
    from gazelle.planning import PlanningError

    planner = arm.planner
    start = planner.state(planner.named_state(arm.group, arm.start))
    out = Outcome()
    for k, target in enumerate(goals):
        t = time.perf_counter()
        try:
            goal = planner.ik(arm.group, arm.tip, target, start)
            traj = planner.plan(arm.group, goal, start, timeout=planning_time)
        except PlanningError as err:
            out.seconds.append(time.perf_counter() - t)
            out.failures.append(f"goal {k}: {err.code}: {err.message}")
            continue
        out.seconds.append(time.perf_counter() - t)
        end = planner.state({**planner.positions(start), **dict(zip(traj.joint_names, traj.positions[-1]))})
        at = planner.fk(end, arm.tip)
        out.position_mm.append(1e3 * float(np.linalg.norm(at[:3, 3] - target[:3, 3])))
        cos = (float(np.trace(at[:3, :3].T @ target[:3, :3])) - 1.0) / 2.0
        out.angle_rad.append(float(np.arccos(np.clip(cos, -1.0, 1.0))))
        start = end
    return out

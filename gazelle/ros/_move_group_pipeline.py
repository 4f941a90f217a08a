"""move_group's planning pipeline: a MotionPlanRequest's start state and goal turned into a timed trajectory
on gazelle's planner, as MoveIt's ``planning_pipeline::PlanningPipeline::generatePlan``
(moveit_ros/planning/planning_pipeline/src/planning_pipeline.cpp, jazzy) does for the ``plan_kinematic_path``
service and the ``move_action``; it also shows plans on ``/display_planned_path`` as that pipeline does."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import DisplayTrajectory
from shape_msgs.msg import SolidPrimitive

from ..planning import PLANNERS, PathConstraints, PlanningError, Trajectory, quoted
from ._move_group_common import PLANNING_TIME, _quat
from ._planning_scene import matrix as _matrix

if TYPE_CHECKING:
    from ._move_group_protocols import MoveGroupCore


class PlanningPipeline:
    """MotionPlanRequests planned on the context's primary planner (the caller holds it)."""

    def __init__(self, context: MoveGroupCore) -> None:
        self.context = context
        self._display = context.node.create_publisher(DisplayTrajectory, "display_planned_path", 10)

    def display(self, trajectory: DisplayTrajectory) -> None:
        """Show a plan on ``/display_planned_path`` (RViz's and Foxglove's trajectory displays)."""
        self._display.publish(trajectory)

    def plan(self, request: Any) -> tuple[np.ndarray, Trajectory]:
        """A MotionPlanRequest's start state and timed trajectory (raises PlanningError)."""
        planner = self.context.planner
        assert planner is not None
        group = request.group_name
        joints = planner.group_joints(group)
        start = self.context.start_state(request.start_state)
        self.check_start(group, joints, start)
        if not request.goal_constraints:
            raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the request has no goal_constraints")
        goal = self.goal(group, joints, request.goal_constraints[0], start)
        algorithm = self.algorithm(group, request.planner_id)
        self.note_unhonoured(request, algorithm)
        if request.planner_id and algorithm and f"planner {algorithm}" not in self.context.noted:
            self.context.noted.add(f"planner {algorithm}")  # once per planner: at most three
            self.context.logger.info(f"planner_id {quoted(request.planner_id)}: planned with {algorithm}")
        asked = request.allowed_planning_time
        timeout = asked if asked > 0.0 else PLANNING_TIME  # NaN too; the planner cuts a long one to its bound
        traj = planner.plan(
            group,
            goal,
            start,
            velocity_scaling=request.max_velocity_scaling_factor,
            acceleration_scaling=request.max_acceleration_scaling_factor,
            timeout=timeout,
            algorithm=algorithm or "RRTConnect",
            attempts=request.num_planning_attempts,
            constraints=self.path_constraints(request.path_constraints, start),
        )
        return start, traj

    def path_constraints(self, path: Any, start: np.ndarray) -> PathConstraints:
        """A request's ``path_constraints`` as the planner keeps them (MoveIt's kinematic_constraints.cpp gives
        their meaning): an orientation constraint bounds the link's roll, pitch and yaw from ``orientation``
        by its three axis tolerances; a position constraint keeps the link's origin in its region's first
        primitive (a box as it is; a sphere or a cylinder by the box inscribed in it, a little stricter); a
        joint constraint keeps the joint within ``position - tolerance_below`` and ``position +
        tolerance_above``. Tolerances under MoveIt's 1e-8 floor are taken at it (none would leave no path)."""
        inf = np.inf
        poses = []
        for oc in path.orientation_constraints:
            region = self.context.frame(oc.header.frame_id, start) @ _matrix(Pose(orientation=oc.orientation))
            tol = np.maximum(
                np.abs([oc.absolute_x_axis_tolerance, oc.absolute_y_axis_tolerance, oc.absolute_z_axis_tolerance]),
                1e-8,
            )
            poses.append((oc.link_name, region, np.array([-inf, -inf, -inf, *(-tol)]), np.array([inf, inf, inf, *tol])))
        for pc in path.position_constraints:
            region, half = self._region(pc, start)
            poses.append(
                (pc.link_name, region, np.array([*(-half), -inf, -inf, -inf]), np.array([*half, inf, inf, inf]))
            )
        joints = tuple(
            (jc.joint_name, jc.position - abs(jc.tolerance_below), jc.position + abs(jc.tolerance_above))
            for jc in path.joint_constraints
        )
        return PathConstraints(poses=tuple(poses), joints=joints)

    def _region(self, pc: Any, start: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A position constraint's region: its frame in the planning frame, and its box's half sizes (m)."""
        region = pc.constraint_region
        if not region.primitives or not region.primitive_poses:
            raise PlanningError("INVALID_MOTION_PLAN", "a position path constraint has no primitive and pose")
        shape, d = region.primitives[0], [abs(float(v)) for v in region.primitives[0].dimensions]
        if shape.type == SolidPrimitive.BOX and len(d) >= 3:
            half = np.array(d[:3]) / 2.0
        elif shape.type == SolidPrimitive.SPHERE and d:
            half = np.full(3, d[0] / math.sqrt(3.0))
        elif shape.type == SolidPrimitive.CYLINDER and len(d) >= 2:
            half = np.array([d[1] / math.sqrt(2.0), d[1] / math.sqrt(2.0), d[0] / 2.0])
        else:
            raise PlanningError(
                "INVALID_MOTION_PLAN", "a position path constraint's region is no box, sphere or cylinder"
            )
        return self.context.frame(pc.header.frame_id, start) @ _matrix(region.primitive_poses[0]), half

    def algorithm(self, group: str, planner_id: str) -> str | None:
        """The OMPL planner a request's ``planner_id`` names, as MoveIt's OMPL interface finds its configuration
        (moveit_planners/ompl/ompl_interface/src/planning_context_manager.cpp, getPlanningContext, and
        ompl_interface.cpp, loadPlannerConfigurations): a configuration of ompl_planning.yaml
        (``ompl.planner_configs.<id>.type``, e.g. ``geometric::RRTstar``; ``group[id]`` too), else the name
        itself; none: the group's ``default_planner_config``, else RRTConnect. One of
        :data:`gazelle.planning.PLANNERS` (RRTConnect, RRTstar, RRT), or None for another planner (planned with
        RRTConnect, and said)."""
        name = planner_id or self.context.param(f"ompl.{group}.default_planner_config")
        if not name:
            return "RRTConnect"
        if name.endswith("]") and "[" in name:
            name = name[name.index("[") + 1 : -1]
        kind = self.context.param(f"ompl.planner_configs.{name}.type") or name
        kind = kind.rpartition("::")[2].removesuffix("kConfigDefault")
        return kind if kind in PLANNERS else None

    def check_start(self, group: str, joints: list[str], start: np.ndarray) -> None:
        """MoveIt's default request adapters, run before the planner looks for the goal (moveit_configs_utils'
        default_configs/ompl_planning.yaml: ``CheckStartStateBounds``, then ``CheckStartStateCollision``;
        moveit_ros/planning/planning_request_adapter_plugins/src/check_start_state_bounds.cpp and
        check_start_state_collision.cpp, jazzy). A group joint outside its limits is START_STATE_INVALID "Start
        state out of bounds." with MoveIt's log line for each such joint: Jazzy's adapter does not clamp (its
        ``fix_start_state`` only normalises continuous, planar and floating joints), and a reading a hair
        past a limit was already moved onto it as the current state is (:meth:`MoveGroupContext.start_state`).
        A start state in collision is START_STATE_IN_COLLISION naming the contacts, at once: not after the
        goal's IK has spent its time."""
        planner = self.context.planner
        assert planner is not None
        lo, hi = planner.scene.getPositionLimitVectors("")
        index = {n: i for i, n in enumerate(planner.joint_names)}
        outside = False
        for joint in joints:
            i = index[joint]
            if not lo[i] - 1e-9 <= start[i] <= hi[i] + 1e-9:
                outside = True
                self.context.logger.error(
                    f"Joint '{joint}' from the starting state is outside bounds by: [{start[i]:g} ] should be in "
                    f"the range [{lo[i]:g} ], [{hi[i]:g} ]."
                )
        if outside:
            raise PlanningError("START_STATE_INVALID", "Start state out of bounds.")
        if planner.in_collision(start):
            pairs = planner.colliding_pairs(start)
            contacts = "".join(f"{a} - {b}, " for a, b in pairs)
            raise PlanningError("START_STATE_IN_COLLISION", f"{len(pairs)} contact(s) detected : {contacts}")

    def note_unhonoured(self, request: Any, algorithm: str | None) -> None:
        """Say what of a MotionPlanRequest gazelle's planner does not honour, once per kind (the request
        is planned all the same, as MoveIt plans with what it has)."""
        notes: list[tuple[str, str]] = []  # (kind, what is said the first time that kind comes)
        if request.pipeline_id and request.pipeline_id != "ompl":
            notes.append(("pipeline", f"pipeline_id {quoted(request.pipeline_id)} is not simulated"))
        if algorithm is None:
            notes.append(
                (
                    "planner",
                    f"planner_id {quoted(request.planner_id)} is not simulated (RRTConnect, RRTstar and RRT are)",
                )
            )
        path = request.path_constraints
        if any(
            any((pc.target_point_offset.x, pc.target_point_offset.y, pc.target_point_offset.z))
            for pc in path.position_constraints
        ):
            notes.append(
                (
                    "offset",
                    "a position path constraint's target_point_offset is not applied (the link's origin is kept)",
                )
            )
        if path.visibility_constraints or request.trajectory_constraints.constraints:
            notes.append(("trajectory", "visibility and trajectory constraints are not honoured"))
        if len(request.goal_constraints) > 1:
            notes.append(("goals", f"only the first of {len(request.goal_constraints)} goal_constraints is planned to"))
        for kind, note in notes:  # once per kind: what a client sends never grows this set or floods the log
            self.context.note_once(kind, f"motion plan request: {note}; gazelle plans with RRT-Connect")

    def goal(self, group: str, joints: list[str], constraints: Any, start: np.ndarray) -> np.ndarray:
        """The goal configuration of one Constraints message: joint constraints, or a pose goal."""
        planner = self.context.planner
        assert planner is not None
        if constraints.joint_constraints:
            values = {}
            for jc in constraints.joint_constraints:
                if jc.joint_name not in planner.joint_names:
                    raise PlanningError(
                        "INVALID_GOAL_CONSTRAINTS", f"unknown joint {quoted(jc.joint_name)} in the goal"
                    )
                values[jc.joint_name] = jc.position
            missing = [j for j in joints if j not in values]
            if missing and len(missing) == len(joints):
                raise PlanningError("INVALID_GOAL_CONSTRAINTS", f"the goal names none of group '{group}'s joints")
            return planner.state({**planner.positions(start), **values})
        if constraints.position_constraints:
            pc = constraints.position_constraints[0]
            link = pc.link_name or planner.tip_link(group)
            region = pc.constraint_region
            if not region.primitive_poses:
                raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the position constraint has no primitive pose")
            frame = self.context.frame(pc.header.frame_id, start)
            target = frame @ _matrix(region.primitive_poses[0])
            offset = pc.target_point_offset
            if constraints.orientation_constraints:
                oc = constraints.orientation_constraints[0]
                rotation = self.context.frame(oc.header.frame_id, start) @ _matrix(Pose(orientation=oc.orientation))
                target[:3, :3] = rotation[:3, :3]
                target[:3, 3] -= target[:3, :3] @ np.array([offset.x, offset.y, offset.z])
                return planner.ik(group, link, target, start)
            return self.position_only(group, link, target[:3, 3], start)
        if constraints.orientation_constraints:
            raise PlanningError(
                "INVALID_GOAL_CONSTRAINTS", "an orientation constraint alone is not a goal gazelle can plan to"
            )
        raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the goal has no joint, position or orientation constraint")

    def position_only(self, group: str, link: str, position: np.ndarray, start: np.ndarray) -> np.ndarray:
        """A position goal: the link's current orientation first, then others, until IK finds one."""
        planner = self.context.planner
        assert planner is not None
        current = planner.fk(start, link)
        rng = np.random.default_rng(0)
        rotations = [current[:3, :3]]
        for _ in range(20):
            q = rng.normal(size=4)
            q /= np.linalg.norm(q)
            rotations.append(_matrix(Pose(orientation=_quat(q)))[:3, :3])
        for rotation in rotations:
            target = np.eye(4)
            target[:3, :3], target[:3, 3] = rotation, position
            try:
                return planner.ik(group, link, target, start, timeout=0.1)
            except PlanningError:
                continue
        raise PlanningError("NO_IK_SOLUTION", f"no joint values of '{group}' put '{link}' at the goal position")

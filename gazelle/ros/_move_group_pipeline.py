"""move_group's planning pipeline: a MotionPlanRequest's start state and goal turned into a timed trajectory
on gazelle's planner, as MoveIt's ``planning_pipeline::PlanningPipeline::generatePlan``
(moveit_ros/planning/planning_pipeline/src/planning_pipeline.cpp, jazzy) does for the ``plan_kinematic_path``
service and the ``move_action``; it also shows plans on ``/display_planned_path`` as that pipeline does."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import DisplayTrajectory

from ..planning import PlanningError, Trajectory, quoted
from ._move_group_common import PLANNING_TIME, _quat
from ._planning_scene import matrix as _matrix

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class PlanningPipeline:
    """MotionPlanRequests planned on the context's primary planner (the caller holds it)."""

    def __init__(self, context: MoveGroupContext) -> None:
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
        if not request.goal_constraints:
            raise PlanningError("INVALID_GOAL_CONSTRAINTS", "the request has no goal_constraints")
        goal = self.goal(group, joints, request.goal_constraints[0], start)
        self.note_unhonoured(request)
        asked = request.allowed_planning_time
        timeout = asked if asked > 0.0 else PLANNING_TIME  # NaN too; the planner cuts a long one to its bound
        traj = planner.plan(
            group,
            goal,
            start,
            velocity_scaling=request.max_velocity_scaling_factor,
            acceleration_scaling=request.max_acceleration_scaling_factor,
            timeout=timeout,
        )
        return start, traj

    def note_unhonoured(self, request: Any) -> None:
        """Say what of a MotionPlanRequest gazelle's planner does not honour, once per kind (the request
        is planned all the same, as MoveIt plans with what it has)."""
        notes: list[tuple[str, str]] = []  # (kind, what is said the first time that kind comes)
        if request.pipeline_id and request.pipeline_id != "ompl":
            notes.append(("pipeline", f"pipeline_id {quoted(request.pipeline_id)} is not simulated"))
        if request.planner_id and "rrtconnect" not in request.planner_id.lower():
            notes.append(("planner", f"planner_id {quoted(request.planner_id)} is not simulated"))
        path = request.path_constraints
        if path.joint_constraints or path.position_constraints or path.orientation_constraints:
            notes.append(
                ("path", "path_constraints are not honoured: the path between the start and the goal ignores them")
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

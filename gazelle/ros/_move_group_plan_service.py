"""move_group's ``plan_kinematic_path``: MoveIt's ``MoveGroupPlanService`` capability
(moveit_ros/move_group/src/default_capabilities/plan_service_capability.cpp, jazzy)."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from moveit_msgs.srv import GetMotionPlan

from ..planning import PlanningError, quoted
from ._move_group_capability import serve_on_planner
from ._move_group_common import _code

if TYPE_CHECKING:
    from ..planning import ArmPlanner
    from ._move_group_context import MoveGroupContext


class PlanService:
    """``plan_kinematic_path`` through the context's planning pipeline, on the primary planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, GetMotionPlan, "plan_kinematic_path", self.plan_kinematic_path, "plan")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def plan_kinematic_path(
        self, req: GetMotionPlan.Request, res: GetMotionPlan.Response, _planner: ArmPlanner
    ) -> GetMotionPlan.Response:
        """Plan without executing (on the primary planner, held by the caller); a failure is the response's error
        code and message (MoveIt's MoveItErrorCodes), never an exception to the client."""
        t0 = time.monotonic()
        try:
            start, traj = self.context.pipeline.plan(req.motion_plan_request)
        except PlanningError as err:
            group = req.motion_plan_request.group_name
            self.context.warn(f"plan_kinematic_path for {quoted(group)} failed: {err.code}: {err.message}")
            res.motion_plan_response.error_code = _code(err.code)
            res.motion_plan_response.error_code.message = err.message
            return res
        mpr = res.motion_plan_response
        mpr.group_name = req.motion_plan_request.group_name
        mpr.trajectory_start = self.context.robot_state(start)
        mpr.trajectory = self.context.robot_trajectory(traj)
        mpr.planning_time = time.monotonic() - t0
        mpr.error_code = _code("SUCCESS")
        return res

"""move_group's ``move_action`` (moveit_msgs/MoveGroup): MoveIt's ``MoveGroupMoveAction`` capability
(moveit_ros/move_group/src/default_capabilities/move_action_capability.cpp, jazzy): plan, show, execute."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from moveit_msgs.action import MoveGroup
from moveit_msgs.msg import DisplayTrajectory

from ..planning import PlanningError, quoted
from ._move_group_capability import INTERNAL_ERROR, NO_ROBOT
from ._move_group_common import _code, _end_goal
from ._replies import serve_action

if TYPE_CHECKING:
    from rclpy.action.server import ActionServer, ServerGoalHandle

    from ._move_group_context import MoveGroupContext


class MoveAction:
    """The ``move_action`` server: the request planned through the context's pipeline, run by its execution
    manager."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context
        self._server: ActionServer | None = None

    def initialize(self) -> None:
        self._server = serve_action(
            self.context.node, MoveGroup, "move_action", self.execute, self.context.callback_group
        )

    def destroy(self) -> None:
        """Destroy the action server: one left alive holds its node's handle, and the node would stay in the graph
        with that action's endpoints alone."""
        if self._server is not None:
            self._server.destroy()

    def execute(self, handle: ServerGoalHandle) -> MoveGroup.Result:
        """The ``move_action`` goal (move_action_capability.cpp): plan the request (feedback PLANNING), show the
        plan on /display_planned_path, and unless ``plan_only`` execute it (feedback MONITOR); the result carries
        the start state, the planned trajectory and, on success, the executed one."""
        result = MoveGroup.Result()
        pool = self.context.pool
        if pool is None:
            result.error_code = _code("FAILURE")
            result.error_code.message = NO_ROBOT
            handle.abort()
            return result
        goal = handle.request
        t0 = time.monotonic()
        handle.publish_feedback(MoveGroup.Feedback(state="PLANNING"))
        try:
            with pool.using("plan"):
                start, traj = self.context.pipeline.plan(goal.request)
        except PlanningError as err:
            result.error_code = _code(err.code)
            result.error_code.message = err.message
            self.context.logger.warning(
                f"planning for {quoted(goal.request.group_name)} failed: {err.code}: {err.message}"
            )
            handle.abort()
            return result
        except Exception as err:
            self.context.logger.error(f"planning failed: {type(err).__name__}: {err}")
            result.error_code = _code("FAILURE")
            result.error_code.message = f"planning: {INTERNAL_ERROR}"
            handle.abort()
            return result
        result.planning_time = time.monotonic() - t0
        result.trajectory_start = self.context.robot_state(start)
        result.planned_trajectory = self.context.robot_trajectory(traj)
        # as MoveIt's move_group: every plan on /display_planned_path (RViz's and Foxglove's trajectory displays)
        self.context.pipeline.display(
            DisplayTrajectory(
                model_id=pool.primary.semantics.robot_name,
                trajectory=[result.planned_trajectory],
                trajectory_start=result.trajectory_start,
            )
        )
        if goal.planning_options.plan_only:
            result.error_code = _code("SUCCESS")
            handle.succeed()
            return result
        handle.publish_feedback(MoveGroup.Feedback(state="MONITOR"))
        code, message = self.context.execution.run(result.planned_trajectory.joint_trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        if code == "SUCCESS":
            result.executed_trajectory = result.planned_trajectory
        # move_action_capability.cpp: a preempted execution is a canceled goal (an aborted one when it was
        # stopped by the execution event, not cancelled: an executing goal cannot become canceled)
        _end_goal(handle, code, preempted="canceled" if handle.is_cancel_requested else "abort")
        return result

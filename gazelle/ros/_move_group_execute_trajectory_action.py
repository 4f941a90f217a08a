"""move_group's ``execute_trajectory`` (moveit_msgs/ExecuteTrajectory): MoveIt's
``MoveGroupExecuteTrajectoryAction`` capability
(moveit_ros/move_group/src/default_capabilities/execute_trajectory_action_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.action import ExecuteTrajectory
from trajectory_msgs.msg import JointTrajectory

from ..planning import START_BOUNDS_ERROR, ArmPlanner
from ._move_group_common import _code, _end_goal, _seconds
from ._replies import serve_action

if TYPE_CHECKING:
    from rclpy.action.server import ActionServer, ServerGoalHandle

    from ._move_group_context import MoveGroupContext


class ExecuteTrajectoryAction:
    """The ``execute_trajectory`` server: a trajectory checked against the limits, then run by the context's
    execution manager."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context
        self._server: ActionServer | None = None

    def initialize(self) -> None:
        self._server = serve_action(
            self.context.node, ExecuteTrajectory, "execute_trajectory", self.execute, self.context.callback_group
        )

    def destroy(self) -> None:
        """Destroy the action server (see MoveAction.destroy)."""
        if self._server is not None:
            self._server.destroy()

    def execute(self, handle: ServerGoalHandle) -> ExecuteTrajectory.Result:
        """The ``execute_trajectory`` goal (execute_trajectory_action_capability.cpp): a trajectory beyond the
        limits is refused (INVALID_MOTION_PLAN) before anything moves; otherwise it runs on its controllers and
        anything but success ends the goal aborted, as MoveIt ends it."""
        result = ExecuteTrajectory.Result()
        trajectory = handle.request.trajectory.joint_trajectory
        problem = self.check_trajectory(trajectory)
        if problem is not None:
            result.error_code = _code("INVALID_MOTION_PLAN")
            result.error_code.message = problem
            handle.abort()
            return result
        code, message = self.context.execution.run(trajectory, handle)
        result.error_code = _code(code)
        result.error_code.message = message
        # execute_trajectory_action_capability.cpp (Jazzy): anything but success is aborted, a cancelled or
        # stopped execution too (with PREEMPTED)
        _end_goal(handle, code, preempted="abort")
        return result

    def check_trajectory(self, trajectory: JointTrajectory) -> str | None:
        """Why a trajectory sent to execute_trajectory cannot run (positions or speeds beyond the limits).

        On the query planner, under its lock, as every use of roboplan's scene: the simulation's scene updates
        (a message for every millimetre anything moves, so a stream while an arm executes) add, move and
        rebuild its pinocchio/coal models on another executor thread. Read without the lock, the limits
        came from a model being replaced: pymoveit2's execute_trajectory on a YuMi died of "double free
        or corruption" 4 runs in 4, while the MoveGroup action (which plans under the lock) did not."""
        pool = self.context.pool
        if pool is None:
            return "move_group has no robot yet"
        with pool.using("query") as planner:
            return self.check_trajectory_locked(trajectory, planner)

    def check_trajectory_locked(self, trajectory: JointTrajectory, planner: ArmPlanner) -> str | None:
        """Why ``trajectory`` cannot be executed (None: it can): no points, a joint the robot lacks, a position
        outside its limits (the first point may be off by the start-state tolerance), or a speed between two
        points more than 1 % over the joint's velocity limit."""
        if not trajectory.points:
            return "the trajectory has no points"
        unknown = [j for j in trajectory.joint_names if j not in planner.joint_names]
        if unknown:
            return f"unknown joints {unknown}"
        lo, hi = planner.scene.getPositionLimitVectors("")
        speed = planner.velocity_limits  # not roboplan's getVelocityLimitVectors: see ArmPlanner.velocity_limits
        index = {n: i for i, n in enumerate(planner.joint_names)}
        prev = None
        for k, point in enumerate(trajectory.points):
            t = _seconds(point.time_from_start)
            for j, name in enumerate(trajectory.joint_names):
                i = index[name]
                p = point.positions[j]
                # the first point is where the arm is: a reading a little past a limit is allowed there,
                # as MoveIt allows a start state within start_state_max_bounds_error
                slack = START_BOUNDS_ERROR if k == 0 else 1e-4
                if not lo[i] - slack <= p <= hi[i] + slack:
                    return f"point {k}: {name} = {p:.4f} is outside its limits [{lo[i]:.4f}, {hi[i]:.4f}]"
                if prev is not None and t > prev[0]:
                    v = (p - prev[1][j]) / (t - prev[0])
                    if abs(v) > speed[name] * 1.01:
                        return f"point {k}: {name} moves at {v:.3f} rad/s, beyond its velocity limit {speed[name]:.3f}"
            prev = (t, list(point.positions))
        return None

"""move_group's ``compute_cartesian_path``: MoveIt's ``MoveGroupCartesianPathService`` capability
(moveit_ros/move_group/src/default_capabilities/cartesian_path_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.srv import GetCartesianPath

from ..planning import MAX_CARTESIAN_STEPS, ArmPlanner, PlanningError
from ._move_group_capability import serve_on_planner
from ._move_group_common import _code
from ._planning_scene import matrix as _matrix

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class CartesianPathService:
    """``compute_cartesian_path`` on the planning planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, GetCartesianPath, "compute_cartesian_path", self.compute_cartesian_path, "plan")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def compute_cartesian_path(
        self, req: GetCartesianPath.Request, res: GetCartesianPath.Response, planner: ArmPlanner
    ) -> GetCartesianPath.Response:
        """The link's straight-line path through the waypoints in ``max_step`` steps, cut where IK fails, a joint
        jumps (``jump_threshold``) or a collision begins; ``fraction`` says how much was achieved, and a partial
        path still answers SUCCESS, as MoveIt does. The planner's bounds refuse more than ``MAX_CARTESIAN_STEPS``
        poses (FAILURE, before any IK; so are more waypoints, before they are converted) and IK past
        ``CARTESIAN_TIMEOUT_SEC`` (TIMED_OUT)."""
        if len(req.waypoints) > MAX_CARTESIAN_STEPS:
            raise PlanningError(
                "FAILURE",
                f"{len(req.waypoints)} waypoints; a Cartesian path solves at most {MAX_CARTESIAN_STEPS} poses",
            )
        q = self.context.start_state(req.start_state, planner)
        link = req.link_name or planner.tip_link(req.group_name)
        frame = self.context.frame(req.header.frame_id, q, planner)
        traj, fraction = planner.cartesian_path(
            req.group_name,
            link,
            [frame @ _matrix(p) for p in req.waypoints],
            q,
            max_step=req.max_step,
            jump_threshold=req.jump_threshold,
            avoid_collisions=req.avoid_collisions,
            velocity_scaling=req.max_velocity_scaling_factor,
            acceleration_scaling=req.max_acceleration_scaling_factor,
        )
        res.start_state = self.context.robot_state(q)
        res.fraction = float(fraction)
        if traj is not None:
            res.solution = self.context.robot_trajectory(traj)
        res.error_code = _code("SUCCESS")  # as MoveIt: a partial path succeeds with its fraction
        return res

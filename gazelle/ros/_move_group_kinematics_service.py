"""move_group's ``compute_fk`` and ``compute_ik``: MoveIt's ``MoveGroupKinematicsService`` capability
(moveit_ros/move_group/src/default_capabilities/kinematics_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from geometry_msgs.msg import PoseStamped
from moveit_msgs.srv import GetPositionFK, GetPositionIK

from ..planning import ArmPlanner, PlanningError
from ._move_group_capability import serve_on_planner
from ._move_group_common import MAX_FK_LINKS, _code, _seconds
from ._planning_scene import matrix as _matrix
from ._planning_scene import pose as _pose

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class KinematicsService:
    """``compute_fk`` on the query planner, ``compute_ik`` on the IK planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        # each on the planner of its kind of work (gazelle.planning's PlannerPool): FK answers while a plan or
        # an IK runs, as MoveIt's services do
        serve_on_planner(self.context, GetPositionFK, "compute_fk", self.compute_fk, "query")
        serve_on_planner(self.context, GetPositionIK, "compute_ik", self.compute_ik, "ik")

    def destroy(self) -> None:
        pass  # its services go with the node

    def compute_fk(
        self, req: GetPositionFK.Request, res: GetPositionFK.Response, planner: ArmPlanner
    ) -> GetPositionFK.Response:
        """``compute_fk``: each named link's pose at the request's robot state (the current state where it gives
        none), in the request's frame, else the robot's root; at most :data:`MAX_FK_LINKS` links a request."""
        if len(req.fk_link_names) > MAX_FK_LINKS:
            raise PlanningError(
                "FAILURE", f"fk_link_names names {len(req.fk_link_names)} links; at most {MAX_FK_LINKS} a request"
            )
        q = self.context.start_state(req.robot_state, planner)
        base = np.linalg.inv(self.context.frame(req.header.frame_id, q, planner))
        poses = []
        for link in req.fk_link_names:
            ps = PoseStamped()
            ps.header.frame_id = req.header.frame_id or planner.root_link
            ps.pose = _pose(base @ planner.fk(q, link))
            poses.append(ps)
        res.pose_stamped = poses
        res.fk_link_names = list(req.fk_link_names)
        res.error_code = _code("SUCCESS")
        return res

    def compute_ik(
        self, req: GetPositionIK.Request, res: GetPositionIK.Response, planner: ArmPlanner
    ) -> GetPositionIK.Response:
        """``compute_ik``: a joint solution for ``ik_link_name`` (the group's tip by default) at the pose, seeded
        from the request's robot state, within its timeout (kinematics.yaml's ``kinematics_solver_timeout`` where
        it gives none, and at most the planner's ``MAX_IK_SEC``), collision-free when ``avoid_collisions``; the
        full robot state is returned, as MoveIt fills it."""
        ik = req.ik_request
        q = self.context.start_state(ik.robot_state, planner)
        link = ik.ik_link_name or planner.tip_link(ik.group_name)
        target = self.context.frame(ik.pose_stamped.header.frame_id, q, planner) @ _matrix(ik.pose_stamped.pose)
        timeout = _seconds(ik.timeout) or self.context.ik_timeout(ik.group_name)
        solution = planner.ik(ik.group_name, link, target, q, timeout=timeout, avoid_collisions=ik.avoid_collisions)
        res.solution.joint_state.name = list(planner.joint_names)
        res.solution.joint_state.position = [float(v) for v in solution]
        res.error_code = _code("SUCCESS")
        return res

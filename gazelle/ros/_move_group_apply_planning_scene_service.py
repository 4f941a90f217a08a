"""move_group's ``apply_planning_scene``: MoveIt's ``ApplyPlanningSceneService`` capability
(moveit_ros/move_group/src/default_capabilities/apply_planning_scene_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.srv import ApplyPlanningScene

from ._move_group_capability import serve_on_planner

if TYPE_CHECKING:
    from ..planning import ArmPlanner
    from ._move_group_context import MoveGroupContext


class ApplyPlanningSceneService:
    """``apply_planning_scene`` through the context's scene monitor, every planner's lock held."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, ApplyPlanningScene, "apply_planning_scene", self.apply_planning_scene, "write")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def apply_planning_scene(
        self, req: ApplyPlanningScene.Request, res: ApplyPlanningScene.Response, _planner: ArmPlanner
    ) -> ApplyPlanningScene.Response:
        """A diff or a whole scene, checked whole before any of it is applied (a bad one changes nothing and is
        refused with why); the caller holds the pool for writing."""
        self.context.scene.apply_scene(req.scene)
        res.success = True
        return res

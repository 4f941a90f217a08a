"""move_group's ``get_planning_scene``: MoveIt's ``MoveGroupGetPlanningSceneService`` capability
(moveit_ros/move_group/src/default_capabilities/get_planning_scene_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.srv import GetPlanningScene

from ..planning import ArmPlanner
from ._move_group_capability import serve_on_planner

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class GetPlanningSceneService:
    """``get_planning_scene`` on the query planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, GetPlanningScene, "get_planning_scene", self.get_planning_scene, "query")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def get_planning_scene(
        self, req: GetPlanningScene.Request, res: GetPlanningScene.Response, planner: ArmPlanner
    ) -> GetPlanningScene.Response:
        """The robot's current state with its attached objects and the world's collision objects (the
        simulation's own included), as a whole scene; gazelle fills every component whatever ``components`` asks
        (a superset of what MoveIt returns). Read from the query planner, a copy of the primary's scene, so it
        answers while a plan runs."""
        res.scene = self.context.scene.scene_message(planner)
        return res

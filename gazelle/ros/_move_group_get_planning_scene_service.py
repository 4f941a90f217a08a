"""move_group's ``get_planning_scene``: MoveIt's ``MoveGroupGetPlanningSceneService`` capability
(moveit_ros/move_group/src/default_capabilities/get_planning_scene_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from moveit_msgs.msg import AllowedCollisionEntry
from moveit_msgs.srv import GetPlanningScene

from ..planning import ArmPlanner
from ._move_group_capability import serve_on_planner
from ._planning_scene import attached_message, to_message

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
    ) -> Any:
        """The robot's current state with its attached objects and the world's collision objects (the
        simulation's own included), as a whole scene; gazelle fills every component whatever ``components`` asks
        (a superset of what MoveIt returns). Read from the query planner, a copy of the primary's scene, so it
        answers while a plan runs."""
        scene = res.scene
        scene.name = "gazelle"
        scene.robot_model_name = planner.semantics.robot_name
        scene.robot_state = self.context.robot_state(planner.state(self.context.latest_joints or None))
        objects = planner.objects()
        scene.robot_state.attached_collision_objects = [attached_message(o) for o in objects if o.link]
        scene.world.collision_objects = [to_message(o, planner.root_link) for o in objects if not o.link]
        acm = planner.acm
        scene.allowed_collision_matrix.entry_names = acm.message_names()
        scene.allowed_collision_matrix.entry_values = [AllowedCollisionEntry(enabled=row) for row in acm.rows()]
        scene.allowed_collision_matrix.default_entry_names = list(acm.defaults)
        scene.allowed_collision_matrix.default_entry_values = list(acm.defaults.values())
        scene.is_diff = False
        return res

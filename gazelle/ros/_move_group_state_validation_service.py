"""move_group's ``check_state_validity``: MoveIt's ``MoveGroupStateValidationService`` capability
(moveit_ros/move_group/src/default_capabilities/state_validation_service_capability.cpp, jazzy)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.msg import ContactInformation
from moveit_msgs.srv import GetStateValidity

from ..planning import ArmPlanner
from ._move_group_capability import serve_on_planner

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class StateValidationService:
    """``check_state_validity`` on the query planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, GetStateValidity, "check_state_validity", self.check_state_validity, "query")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def check_state_validity(
        self, req: GetStateValidity.Request, res: GetStateValidity.Response, planner: ArmPlanner
    ) -> GetStateValidity.Response:
        """Valid when within the joint limits and free of collisions; the colliding pairs as contacts (their
        bodies and kinds; gazelle has no contact points to give)."""
        q = self.context.start_state(req.robot_state, planner)
        colliding = planner.in_collision(q)
        res.valid = planner.within_limits(q) and not colliding
        if colliding:  # as MoveIt: the pairs in contact (gazelle knows the bodies, not the points)
            res.contacts = [_contact(a, b, planner) for a, b in planner.colliding_pairs(q)]
        return res


def _contact(a: str, b: str, planner: ArmPlanner) -> ContactInformation:
    """A ContactInformation for two colliding bodies, typed as MoveIt types them (a robot link, an object
    attached to the robot, a world object)."""
    attached = {o.name for o in planner.objects() if o.link}

    def kind(body: str) -> int:
        if planner.has_link(body):
            return ContactInformation.ROBOT_LINK
        return ContactInformation.ROBOT_ATTACHED if body in attached else ContactInformation.WORLD_OBJECT

    info = ContactInformation(contact_body_1=a, body_type_1=kind(a), contact_body_2=b, body_type_2=kind(b))
    info.header.frame_id = planner.root_link
    return info

"""move_group's ``get_urdf`` (moveit_msgs/GetGroupUrdf): MoveIt's ``GetUrdfService`` capability
(moveit_ros/move_group/src/default_capabilities/get_group_urdf_capability.cpp, jazzy; in move_group.cpp's
DEFAULT_CAPABILITIES). A planning group's URDF, built by :func:`gazelle.planning.group_urdf` as MoveIt builds
it; an unknown group or an invalid result is MoveIt's FAILURE with its message, ``source`` "GetUrdfService".

MoveIt's two file services (``save_geometry_to_file``, ``load_geometry_from_file``) are not served: they
write and read any path a ROS peer names, which gazelle's servers do not do."""

from __future__ import annotations

from typing import TYPE_CHECKING

from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetGroupUrdf

from ..planning import ArmPlanner, GroupUrdfError, group_urdf
from ._move_group_capability import serve_on_planner

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class GetUrdfService:
    """``get_urdf`` on the query planner."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve_on_planner(self.context, GetGroupUrdf, "get_urdf", self.get_urdf, "query")

    def destroy(self) -> None:
        pass  # its service goes with the node

    def get_urdf(
        self, req: GetGroupUrdf.Request, res: GetGroupUrdf.Response, planner: ArmPlanner
    ) -> GetGroupUrdf.Response:
        """The URDF of one planning group's links and joints, with the error code's source ``GetUrdfService`` as
        MoveIt sets it; an unknown group is FAILURE with why (the name quoted, at most ``NAME_CHARS`` characters
        of it)."""
        res.error_code.source = "GetUrdfService"
        try:
            res.urdf_string = group_urdf(self.context.urdf_text, planner.semantics, req.group_name)
        except GroupUrdfError as err:
            self.context.logger.error(str(err))
            res.error_code.val = MoveItErrorCodes.FAILURE
            res.error_code.message = str(err)
            return res
        res.error_code.val = MoveItErrorCodes.SUCCESS
        return res

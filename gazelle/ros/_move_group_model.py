"""move_group's ``get_urdf`` and ``clear_octomap``: two of MoveIt's default capabilities (Jazzy's
moveit_ros/move_group/src/move_group.cpp, DEFAULT_CAPABILITIES).

* ``get_urdf`` (moveit_msgs/GetGroupUrdf; get_group_urdf_capability.cpp): a planning group's URDF, built by
  :func:`gazelle.planning.group_urdf` as MoveIt builds it; an unknown group or an invalid result is
  MoveIt's FAILURE with its message, ``source`` "GetUrdfService".
* ``clear_octomap`` (std_srvs/Empty; clear_octomap_service_capability.cpp): RViz's "Clear octomap" button.
  gazelle's planning scene holds no octomap (no sensor plugin feeds one), so there is nothing to clear; it
  says MoveIt's two log lines all the same.

MoveIt's other two file services (``save_geometry_to_file``, ``load_geometry_from_file``) are not served:
they write and read any path a ROS peer names, which gazelle's servers do not do.
"""

from __future__ import annotations

from typing import Any

from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetGroupUrdf
from std_srvs.srv import Empty

from ..planning import ArmPlanner, GroupUrdfError, group_urdf
from ._move_group_base import _MoveGroupBase


class _ModelServices(_MoveGroupBase):
    """``get_urdf`` and ``clear_octomap`` (see the module docstring)."""

    _urdf_text: str = ""
    """The robot_description the planner was built from (MoveIt's RDFLoader URDF string)."""

    def _get_urdf(self, req: GetGroupUrdf.Request, res: GetGroupUrdf.Response, planner: ArmPlanner) -> Any:
        """``get_urdf`` (moveit_msgs/GetGroupUrdf): the URDF of one planning group's links and joints, with
        the error code's source ``GetUrdfService`` as MoveIt sets it; an unknown group is FAILURE with why (the
        name quoted, at most ``NAME_CHARS`` characters of it)."""
        res.error_code.source = "GetUrdfService"
        try:
            res.urdf_string = group_urdf(self._urdf_text, planner.semantics, req.group_name)
        except GroupUrdfError as err:
            self.get_logger().error(str(err))
            res.error_code.val = MoveItErrorCodes.FAILURE
            res.error_code.message = str(err)
            return res
        res.error_code.val = MoveItErrorCodes.SUCCESS
        return res

    def _clear_octomap(self, _req: Empty.Request, res: Empty.Response) -> Any:
        self.get_logger().info("Clearing octomap...")
        self.get_logger().info("Octomap cleared.")
        return res

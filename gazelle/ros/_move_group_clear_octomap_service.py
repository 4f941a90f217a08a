"""move_group's ``clear_octomap`` (std_srvs/Empty): MoveIt's ``ClearOctomapService`` capability
(moveit_ros/move_group/src/default_capabilities/clear_octomap_service_capability.cpp, jazzy), RViz's "Clear
octomap" button. gazelle's planning scene holds no octomap (no sensor plugin feeds one), so there is nothing
to clear; it says MoveIt's two log lines all the same."""

from __future__ import annotations

from typing import TYPE_CHECKING

from std_srvs.srv import Empty

from ._replies import serve

if TYPE_CHECKING:
    from ._move_group_context import MoveGroupContext


class ClearOctomapService:
    """``clear_octomap``: nothing to clear."""

    def __init__(self, context: MoveGroupContext) -> None:
        self.context = context

    def initialize(self) -> None:
        serve(self.context.node, Empty, "clear_octomap", self.clear_octomap, self.context.callback_group)

    def destroy(self) -> None:
        pass  # its service goes with the node

    def clear_octomap(self, _req: Empty.Request, res: Empty.Response) -> Empty.Response:
        self.context.logger.info("Clearing octomap...")
        self.context.logger.info("Octomap cleared.")
        return res

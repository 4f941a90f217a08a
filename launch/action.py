"""Actions: what a launch description does (launch.Action)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from .launch_context import LaunchContext


class Action:
    """Base class. :meth:`visit` checks the condition, then :meth:`execute`, which may return more
    actions (entities) to visit in order."""

    def __init__(self, *, condition: Any = None) -> None:
        self.__condition = condition
        import traceback

        # where the user's launch file made it (for errors naming its line)
        self._created_at = _user_frame(traceback.extract_stack()[:-1])

    @property
    def condition(self) -> Any:
        return self.__condition

    def describe(self) -> str:
        return type(self).__name__

    def visit(self, context: LaunchContext) -> list[Any] | None:
        if self.__condition is not None and not self.__condition.evaluate(context):
            return None
        return self.execute(context)

    def execute(self, context: LaunchContext) -> list[Any] | None:
        return None

    def get_sub_entities(self) -> list[Any]:
        return []

    def launch_arguments_walk(self, context: LaunchContext, found: list[Any]) -> tuple[list[Any], LaunchContext]:
        """One step of ``LaunchDescription.get_launch_arguments``: the entities below this one that the listing
        goes into, and the context it reads them in (here: the sub-entities, in the same context). A
        DeclareLaunchArgument adds itself to ``found``; an IncludeLaunchDescription gives its file's entities in
        a context of its own. Each action says this of itself, so the description knows no action class."""
        try:
            return self.get_sub_entities(), context
        except Exception:
            return [], context


def _user_frame(stack: Any) -> str:
    """``file:line`` of the innermost frame outside these packages (the launch file)."""
    import os

    here = os.path.dirname(os.path.abspath(__file__))
    ros_here = os.path.join(os.path.dirname(here), "launch_ros")
    for frame in reversed(stack):
        f = os.path.abspath(frame.filename)
        if not f.startswith(here) and not f.startswith(ros_here):
            return f"{frame.filename}:{frame.lineno}"
    return ""

"""How a move_group capability serves: MoveIt's ``MoveGroupCapability``
(moveit_ros/move_group/include/moveit/move_group/move_group_capability.hpp, jazzy) is a plugin given the
``MoveGroupContext`` that registers its own services and actions on the node in ``initialize()``. gazelle's
capabilities are plain classes of that shape, one a file (``_move_group_<capability>.py``): made with the
context, they register in ``initialize()`` and use nothing but the context. :func:`serve_on_planner` is the
service registration they share: every request answered, on the planner of its kind of work."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol, TypeVar

from ..description import reply_text
from ..planning import PlanningError
from ._move_group_common import _failed
from ._replies import ServiceType, serve

if TYPE_CHECKING:
    from rclpy.service import Service

    from ..planning import ArmPlanner
    from ._move_group_context import MoveGroupContext

Req = TypeVar("Req")
Res = TypeVar("Res")

NO_ROBOT = "move_group has no robot yet (robot_description and robot_description_semantic)"
"""What a request is answered while the robot is not known."""


class MoveGroupCapability(Protocol):
    """What the node asks of a capability (made with the context): register, and let go of what it made."""

    def initialize(self) -> None: ...

    def destroy(self) -> None: ...


INTERNAL_ERROR = "internal error in gazelle's planner (move_group's log has the details)"
"""What a reply says of an error that is not MoveIt's: the collision checker's own words (coal's assertions,
``pair_id < geom_model.collisionPairs.size()``) and exception names mean nothing to a client; the log keeps
them."""


def serve_on_planner(
    context: MoveGroupContext,
    srv_type: ServiceType[Req, Res],
    name: str,
    fn: Callable[[Req, Res, ArmPlanner], Res],
    role: str,
) -> Service:
    """Serve ``name`` with :func:`planner_callback` of ``fn``."""
    return serve(context.node, srv_type, name, planner_callback(context, name, fn, role), context.callback_group)


def planner_callback(
    context: MoveGroupContext, name: str, fn: Callable[[Req, Res, ArmPlanner], Res], role: str
) -> Callable[[Req, Res], Res]:
    """``fn(request, response, planner)`` as a service callback that answers every request: with no robot yet, a
    FAILURE saying what is missing; a PlanningError as its MoveIt error code and message (cut to a reply's
    length, its quoted values to excerpts); anything else as FAILURE with :data:`INTERNAL_ERROR`, the error
    itself in the log. ``fn`` runs on the pool's planner of ``role`` under that planner's lock, or, for
    ``write``, on the primary planner with every lock held (roboplan's scenes are not re-entrant)."""
    logger = context.logger

    def wrapper(request: Req, response: Res) -> Res:
        pool = context.pool
        if pool is None:
            return _failed(response, "FAILURE", NO_ROBOT)
        try:
            with pool.writing() if role == "write" else pool.using(role) as planner:
                return fn(request, response, planner)
        except PlanningError as err:
            message = reply_text(err.message)
            logger.warning(f"{name}: {err.code}: {message}")
            return _failed(response, err.code, message)
        except Exception as err:
            logger.error(f"{name}: {reply_text(f'{type(err).__name__}: {err}')}")
            return _failed(response, "FAILURE", f"{name}: {INTERNAL_ERROR}")

    return wrapper

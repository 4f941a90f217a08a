"""How a move_group capability answers (gazelle/ros/_move_group_capability.py): issue 51 item 7, an error of
the collision checker reached the client in coal's own words (``pair_id < geom_model.collisionPairs.size()``
after a mesh was added and removed and the allowed collisions changed). A reply says it was an internal error
and where the details are; the log keeps the error itself."""

from __future__ import annotations

from collections.abc import Callable
from contextlib import contextmanager
from types import SimpleNamespace
from typing import Any

from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import ApplyPlanningScene, GetMotionPlan

from gazelle.planning import PlanningError
from gazelle.ros._move_group_capability import planner_callback

COAL = "pair_id < geom_model.collisionPairs.size()"


def _context(said: list[str]) -> Any:
    """A stand-in MoveGroupContext: a pool whose planner is a string, and a logger into ``said``."""

    @contextmanager
    def held(*_role: str):
        yield "planner"

    logger = SimpleNamespace(warning=said.append, error=said.append)
    return SimpleNamespace(pool=SimpleNamespace(using=held, writing=held), logger=logger)


def _raises(err: Exception) -> Callable[[Any, Any, Any], Any]:
    def fn(_request: Any, _response: Any, _planner: Any) -> Any:
        raise err

    return fn


def test_an_internal_error_is_answered_without_the_collision_checkers_words_and_logged_whole() -> None:
    said: list[str] = []
    callback = planner_callback(_context(said), "apply_planning_scene", _raises(RuntimeError(COAL)), "write")
    reply = callback(ApplyPlanningScene.Request(), ApplyPlanningScene.Response())
    assert reply.success is False
    callback = planner_callback(_context(said), "plan_kinematic_path", _raises(RuntimeError(COAL)), "plan")
    code = callback(GetMotionPlan.Request(), GetMotionPlan.Response()).motion_plan_response.error_code
    assert code.val == MoveItErrorCodes.FAILURE
    assert "pair_id" not in code.message and "collisionPairs" not in code.message and "RuntimeError" not in code.message
    assert code.message == "plan_kinematic_path: internal error in gazelle's planner (move_group's log has the details)"
    assert any(COAL in line for line in said), said


def test_a_planning_error_is_answered_with_its_code_and_message() -> None:
    said: list[str] = []
    err = PlanningError("GOAL_IN_COLLISION", "the goal state is in collision")
    callback = planner_callback(_context(said), "plan_kinematic_path", _raises(err), "plan")
    code = callback(GetMotionPlan.Request(), GetMotionPlan.Response()).motion_plan_response.error_code
    assert (code.val, code.message) == (MoveItErrorCodes.GOAL_IN_COLLISION, "the goal state is in collision")

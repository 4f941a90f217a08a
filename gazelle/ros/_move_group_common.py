"""What the parts of ``move_group`` (see :mod:`._move_group`) share: constants, the error-code and
message helpers, and the controllers' description. The state they share is the
:class:`~._move_group_context.MoveGroupContext`."""

from __future__ import annotations

import logging
import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, TypeVar, runtime_checkable

import numpy as np
from action_msgs.msg import GoalStatus
from builtin_interfaces.msg import Duration as DurationMsg
from geometry_msgs.msg import Quaternion
from moveit_msgs.msg import MotionPlanResponse, MoveItErrorCodes
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

if TYPE_CHECKING:
    from rclpy.action.server import ServerGoalHandle

    from ..planning import Shape

_log = logging.getLogger("gazelle.move_group")
R = TypeVar("R")


@runtime_checkable
class _WithPlanResponse(Protocol):
    """A reply whose error code is in its motion plan response (GetMotionPlan)."""

    motion_plan_response: MotionPlanResponse


@runtime_checkable
class _WithErrorCode(Protocol):
    """A reply with a MoveIt error code of its own."""

    error_code: MoveItErrorCodes


@runtime_checkable
class _WithSuccess(Protocol):
    """A reply that says only whether it succeeded."""

    success: bool


OBJECT_PADDING_PARAMETER = "robot_description_planning.default_object_padding"
"""MoveIt's parameter (m) by which world objects are grown for collision checking; 0 by default, as MoveIt's
planning_scene_monitor.cpp (configureDefaultPadding). Here it grows the simulation's objects (what
``gazelle sim`` publishes); objects a client applies are kept as given, as ``get_planning_scene`` reports
them. The simulated robot collides with the convex hulls of its meshes, a little fatter than the meshes
the planner checks: a plan that grazes an object may touch it in the simulation (an arm planned 5 mm past
a pillar brushed it); 0.01 keeps a centimetre."""
TWIN_CHECK_SEC = 2.0
"""s after start when move_group looks for another of its name on the domain (discovery has run)."""
SHUTDOWN_DEADLINE_SEC = 3.0
"""s after SIGINT/SIGTERM by which move_group has ended, however busy (its watchdog process kills it)."""
CURRENT_STATE_WAIT = 5.0
"""s a request waits for the first /joint_states (MoveIt's planning-scene monitor waits 1 s)."""
CONTROLLER_WAIT = 5.0
"""s an execution waits for its controller's action server, or its joints' gz command topics, to be
discovered."""
_ENDED = (GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_CANCELED, GoalStatus.STATUS_ABORTED)
STREAM_RATE_HZ = 100.0
"""Set-points a second streamed to gz JointPositionController topics (wall time)."""
STREAM_GOAL_TOLERANCE = 0.01
"""rad (m): how near each joint must come to the trajectory's end for a streamed execution to succeed."""
GZ_CMD_POS = re.compile(r"/joint/(?P<joint>[^/]+)/n?\d+/cmd_pos$")
"""gz-sim JointPositionController's default command topic, ``/model/<model>/joint/<joint>/<index>/cmd_pos``
(on ROS ``.../n0/cmd_pos``: see ``gazelle.ros._names``)."""
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE)
MAX_FK_LINKS = 1_000
"""The most links one compute_fk request may name (a link may be named again): each is a pose in the reply."""
PLANNING_TIME = 5.0
"""s a plan searches when the request's ``allowed_planning_time`` is 0 or not a number (MoveIt's default)."""
MAX_SCENE_OBJECTS = 256
"""The most collision objects one planning-scene request may carry, and a scene may hold besides the
simulation's own. Adding one costs time in all the others (roboplan rebuilds its collision pairs): 200
take ~2 s; 3,000 in one request kept move_group deaf for over 15 minutes."""


def _code(name: str) -> MoveItErrorCodes:
    return MoveItErrorCodes(val=getattr(MoveItErrorCodes, name, MoveItErrorCodes.FAILURE))


def _same_shapes(a: tuple[Shape, ...], b: tuple[Shape, ...]) -> bool:
    return len(a) == len(b) and all(
        x.kind == y.kind and x.dimensions == y.dimensions and np.allclose(x.pose, y.pose) for x, y in zip(a, b)
    )


def _failed(response: R, code: str, message: str) -> R:
    """A service response that says why it failed: its error_code (GetMotionPlan's is in its
    motion_plan_response: an internal error there answered code 0 with no message), or ``success``."""
    if isinstance(response, _WithPlanResponse):
        response.motion_plan_response.error_code = _code(code)
        response.motion_plan_response.error_code.message = message
    elif isinstance(response, _WithErrorCode):
        response.error_code = _code(code)
        response.error_code.message = message
    elif isinstance(response, _WithSuccess):
        response.success = False
    return response


def _duration(t: float) -> DurationMsg:
    sec = math.floor(t)
    return DurationMsg(sec=int(sec), nanosec=int(round((t - sec) * 1e9)) % 1_000_000_000)


def _seconds(d: DurationMsg) -> float:
    return d.sec + d.nanosec * 1e-9


@dataclass(frozen=True)
class Controller:
    """A FollowJointTrajectory controller from moveit_controllers.yaml."""

    name: str
    action: str
    joints: tuple[str, ...]
    default: bool = False
    """moveit_simple_controller_manager's ``default``: preferred where several controllers have the joints."""


def _quat(q: np.ndarray) -> Quaternion:
    return Quaternion(x=float(q[0]), y=float(q[1]), z=float(q[2]), w=float(q[3]))


def _end_goal(handle: ServerGoalHandle, code: str, preempted: str) -> None:
    """End an action goal as its MoveItErrorCodes name says: succeeded, aborted, or for PREEMPTED as the
    action's capability ends it (``preempted``: "canceled" or "abort")."""
    if code == "SUCCESS":
        handle.succeed()
    elif code == "PREEMPTED" and preempted == "canceled":
        handle.canceled()
    else:
        handle.abort()

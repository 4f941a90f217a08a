"""What move_group's core parts (the planning scene monitor, the planning pipeline and the trajectory execution
manager) use of the :class:`~._move_group_context.MoveGroupContext` that holds them, as a protocol: the context
imports the parts it holds and no part imports the context (no circle of imports). MoveIt's parts take the same
few things from the node (moveit_ros/move_group/src/move_group_context.cpp builds them from the node, the robot
model and the scene monitor)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    import numpy as np
    from moveit_msgs.msg import RobotState
    from rclpy.callback_groups import CallbackGroup
    from rclpy.impl.rcutils_logger import RcutilsLogger
    from rclpy.node import Node

    from ..planning import ArmPlanner, PlannerPool


class MoveGroupCore(Protocol):
    """The node, the robot's planners, the current state, the parameters and the log, as a part uses them."""

    node: Node
    """The move_group node: where the part registers its topics and timers."""
    callback_group: CallbackGroup
    """The node's reentrant callback group, which every service, topic and action of move_group is in."""
    pool: PlannerPool | None
    """The robot's planners (None until the robot is known)."""
    noted: set[str]
    """The kinds of things said once."""

    @property
    def planner(self) -> ArmPlanner | None:
        """The pool's primary planner (None: no robot yet)."""
        ...

    @property
    def latest_joints(self) -> dict[str, float]:
        """Every joint's latest position heard on /joint_states."""
        ...

    @property
    def logger(self) -> RcutilsLogger: ...

    def warn(self, text: str) -> None: ...

    def note_once(self, kind: str, text: str) -> None:
        """Say ``text`` as a warning the first time ``kind`` comes."""
        ...

    def param(self, name: str) -> str:
        """A string parameter of the node, or "" when it is not set."""
        ...

    def parameter(self, name: str, default: object = None) -> object:
        """A parameter's value of any type, ``default`` when it is not set."""
        ...

    def start_state(self, state: RobotState, planner: ArmPlanner | None = None) -> np.ndarray:
        """The request's start state: the current one with what the request gives put in."""
        ...

    def frame(self, frame: str, q: np.ndarray, planner: ArmPlanner | None = None) -> np.ndarray:
        """The pose of ``frame`` in the planning frame at ``q``."""
        ...

    def robot_state(self, q: np.ndarray) -> RobotState:
        """moveit_msgs/RobotState of the planner's joints at ``q``."""
        ...

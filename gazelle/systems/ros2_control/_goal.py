"""One FollowJointTrajectory goal as the trajectory controller runs it, and control_msgs' result codes: what the
controller (``_trajectory.py``), its sampled segments (``_segments.py``) and the ROS layer's action share."""

from __future__ import annotations

import enum
import threading
from dataclasses import dataclass, field

from .._payloads import JointTrajectory, TrajectoryControllerState
from ._controller import GoalState
from ._tolerances import Tolerance


class TrajectoryResult(enum.IntEnum):
    """control_msgs/FollowJointTrajectory's result codes (``FollowJointTrajectory.Result``'s constants)."""

    SUCCESSFUL = 0
    INVALID_GOAL = -1
    INVALID_JOINTS = -2
    OLD_HEADER_TIMESTAMP = -3
    PATH_TOLERANCE_VIOLATED = -4
    GOAL_TOLERANCE_VIOLATED = -5


@dataclass
class TrajectoryGoal:
    """One FollowJointTrajectory goal as the controller runs it; the ROS layer reads its progress.

    Fields written on the simulation thread, read from the ROS thread (single assignments).
    """

    trajectory: JointTrajectory
    path_tolerance: dict[str, Tolerance] = field(default_factory=dict)
    goal_tolerance: dict[str, Tolerance] = field(default_factory=dict)
    goal_time_tolerance: float | None = None
    """Seconds after the end to meet the goal tolerances (0: no limit); None: the controller's ``goal_time``."""
    status: GoalState = GoalState.PENDING
    """Where the goal stands; set on the simulation thread, read by the ROS layer."""
    error_code: TrajectoryResult = TrajectoryResult.SUCCESSFUL
    error_string: str = ""
    feedback: TrajectoryControllerState | None = None
    done: threading.Event = field(default_factory=threading.Event)

    def finish(self, status: GoalState, code: TrajectoryResult, text: str) -> None:
        """End the goal (once)."""
        if self.done.is_set():
            return
        self.status, self.error_code, self.error_string = status, code, text
        self.done.set()

"""``position_controllers/GripperActionController`` and ``effort_controllers/GripperActionController``
(ros2_controllers Jazzy's gripper_controllers): the ``~/gripper_cmd`` action (control_msgs/GripperCommand)
on one ``joint``.

A goal's position is commanded (the position variant) or reached with a PID on the effort interface
(the effort variant, ``gains.<joint>``), its ``max_effort`` bounding the force. It succeeds when the
joint is within ``goal_tolerance``; a joint that stops short for ``stall_timeout`` s (slower than
``stall_velocity_threshold``) has stalled: success with ``stalled`` when ``allow_stalling``, else
aborted; either way the goal's position stays commanded (a grasp holds).
"""

from __future__ import annotations

import math
import threading
from dataclasses import dataclass, field

from ._controller import Controller, GoalState
from ._hardware import ControlError


@dataclass
class GripperGoal:
    """One GripperCommand goal; the ROS layer reads its progress (single assignments)."""

    position: float
    max_effort: float = 0.0
    status: GoalState = GoalState.PENDING
    """Where the goal stands; set on the simulation thread, read by the ROS layer."""
    stalled: bool = False
    reached_goal: bool = False
    feedback: tuple[float, float] = (math.nan, math.nan)
    """(position, effort) of the joint at the last cycle."""
    done: threading.Event = field(default_factory=threading.Event)

    def finish(self, status: GoalState) -> None:
        """End the goal (once)."""
        if not self.done.is_set():
            self.status = status
            self.done.set()


class GripperActionController(Controller):
    """See the module docstring."""

    type_name = "position_controllers/GripperActionController"
    action_type = "control_msgs/action/GripperCommand"
    interface = "position"

    def on_configure(self) -> None:
        """Read Jazzy's parameters (``joint``, ``goal_tolerance``, ``max_effort``, ``allow_stalling``,
        ``stall_velocity_threshold``, ``stall_timeout``, and ``gains.<joint>`` for the effort variant) and
        announce the ``~/gripper_cmd`` action."""
        self.joint = self.param("joint", "", str)
        if not self.joint:
            raise ControlError(f"controller '{self.name}': 'joint' is not set")
        self.goal_tolerance = self.param("goal_tolerance", 0.01, float)
        self.max_effort = self.param("max_effort", 0.0, float)
        self.allow_stalling = self.param("allow_stalling", False, bool)
        self.stall_velocity = self.param("stall_velocity_threshold", 0.001, float)
        self.stall_timeout = self.param("stall_timeout", 1.0, float)
        self.gains = tuple(self.param(f"gains.{self.joint}.{k}", 0.0, float) for k in ("p", "i", "d"))
        self._incoming: GripperGoal | None = None
        self._goal: GripperGoal | None = None
        self._target: float | None = None
        self._lock = threading.Lock()
        self.action_name = self.topic("~/gripper_cmd")
        self.ctx.add_component(self)

    def on_cleanup(self) -> None:
        self.ctx.remove_component(self)
        super().on_cleanup()

    def command_interfaces(self) -> list[str]:
        """The joint's ``position`` (position variant) or ``effort`` (effort variant) command interface."""
        return [f"{self.joint}/{self.interface}"]

    def state_interfaces(self) -> list[str] | None:
        """Position and velocity: the goal check and the stall clock read both (Jazzy claims the same two)."""
        return [f"{self.joint}/position", f"{self.joint}/velocity"]

    def submit(self, goal: GripperGoal) -> None:
        """Run ``goal`` from the next cycle (a goal running is preempted)."""
        with self._lock:
            old, self._incoming = self._incoming, goal
        if old is not None:
            old.finish(GoalState.ABORTED)

    def cancel(self, goal: GripperGoal) -> None:
        """Stop ``goal``: the gripper holds where it is."""
        goal.finish(GoalState.CANCELED)

    def on_activate(self, states: dict[str, float], commands: dict[str, float]) -> None:
        """Going active: hold the finger where it is, with no goal and a fresh integral."""
        self._target = states[f"{self.joint}/position"]
        self._goal = None
        self._integral = 0.0
        self._slow_since: float | None = None

    def on_deactivate(self) -> None:
        """Going inactive aborts the goal in progress (the action's client hears ABORTED); the last command
        stays on the interface, so the finger holds where it was told."""
        if self._goal is not None:
            self._goal.finish(GoalState.ABORTED)
        self._goal = None

    def update(self, t: float, period: float, states: dict[str, float], commands: dict[str, float]) -> None:
        """One cycle: take a new goal (aborting the one it replaces), command its position (or the PID's effort,
        bounded by the goal's ``max_effort``), feed back position and effort, and end the goal when the finger is
        within ``goal_tolerance`` or has stalled (see the module docstring).

        The end is Jazzy's ``check_for_success`` (gripper_action_controller_impl.hpp): within tolerance is
        success with ``reached_goal``; otherwise each cycle faster than ``stall_velocity_threshold`` restarts
        the stall clock, and ``stall_timeout`` seconds without movement end it with ``stalled`` (succeeded when
        ``allow_stalling``, aborted else). Either way the goal's position stays commanded: a finger closing on
        an object keeps squeezing it, which is how a grasp holds in Gazebo as on hardware."""
        q, v = states[f"{self.joint}/position"], states[f"{self.joint}/velocity"]
        with self._lock:
            incoming, self._incoming = self._incoming, None
        if incoming is not None:
            if self._goal is not None and self._goal is not incoming:
                self._goal.finish(GoalState.ABORTED)
            self._goal, self._target, self._slow_since = incoming, incoming.position, None
            incoming.status = GoalState.EXECUTING
        goal = self._goal
        if goal is not None and goal.done.is_set():
            self._goal, self._target, goal = None, q, None
        target = self._target if self._target is not None else q
        err = target - q
        if self.interface == "position":
            commands[f"{self.joint}/position"] = target
            effort = states.get(f"{self.joint}/effort", math.nan)
        else:
            p, i, d = self.gains
            self._integral += err * period
            u = p * err + i * self._integral - d * v
            limit = goal.max_effort if goal is not None and goal.max_effort > 0 else self.max_effort
            if limit > 0:
                u = max(-limit, min(limit, u))
            commands[f"{self.joint}/effort"] = u
            effort = u
        if goal is None:
            return
        goal.feedback = (q, effort)
        if abs(err) < self.goal_tolerance:
            goal.reached_goal = True
            self._goal = None
            goal.finish(GoalState.SUCCEEDED)
            return
        if abs(v) < self.stall_velocity:
            if self._slow_since is None:
                self._slow_since = t
            elif t - self._slow_since > self.stall_timeout:
                # the command stays the goal's position, stalled or not, allowed or not: a hand closed on
                # a piece goes on squeezing it (ros2_controllers jazzy, gripper_action_controller_impl.hpp:
                # check_for_success ends the goal and leaves the command as it is)
                goal.stalled = True
                self._goal = None
                goal.finish(GoalState.SUCCEEDED if self.allow_stalling else GoalState.ABORTED)
        else:
            self._slow_since = None


class EffortGripperActionController(GripperActionController):
    """``effort_controllers/GripperActionController``."""

    type_name = "effort_controllers/GripperActionController"
    interface = "effort"

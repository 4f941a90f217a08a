"""The trajectory controller's tolerances, as ros2_controllers Jazzy's ``tolerances.hpp`` defines them.

A joint's :class:`Tolerance` bounds its position and velocity error (0: not checked). The controller's own come
from its ``constraints`` parameters (``<joint>.trajectory`` for the path, ``<joint>.goal`` at the end,
``goal_time``); a FollowJointTrajectory goal may override each per joint with control_msgs/JointTolerance's
rules (> 0 replaces, 0 keeps, -1 erases), which :func:`segment_tolerances` applies.
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

FLOAT_EPSILON = 1.1920929e-07
"""std::numeric_limits<float>::epsilon(): the controller's "not zero" for a last point's velocity, and how near -1 a
tolerance must be to erase one."""


@dataclass(frozen=True)
class Tolerance:
    """Position, velocity and acceleration tolerance of one joint (0: not checked)."""

    position: float = 0.0
    velocity: float = 0.0
    acceleration: float = 0.0


def violates(tol: Tolerance, err_p: float, err_v: float) -> bool:
    """Whether an error breaks a tolerance (a tolerance of 0 is not checked)."""
    return (tol.position > 0 and abs(err_p) > tol.position) or (tol.velocity > 0 and abs(err_v) > tol.velocity)


@dataclass(frozen=True)
class SegmentTolerances:
    """What a goal is held to (tolerances.hpp ``SegmentTolerances``): per joint its path and goal tolerances,
    and the time after the trajectory's end within which the goal tolerances must be met (0: no limit)."""

    path: dict[str, Tolerance]
    goal: dict[str, Tolerance]
    goal_time: float
    """Seconds after the last point's time (0: wait for ever, as Jazzy does)."""


_ERASE = -1.0
"""control_msgs/JointTolerance: -1 erases a default (the joint moves without that check)."""


def resolve_tolerance(default: float, given: float) -> float:
    """One tolerance of a goal over the controller's (control_msgs/JointTolerance; tolerances.hpp
    ``resolve_tolerance_source``): > 0 replaces it, 0 keeps it, -1 erases it (0: not checked).

    Raises:
        ValueError: any other negative value.
    """
    if given > 0.0:
        return given
    if abs(given - _ERASE) < FLOAT_EPSILON:  # within a float's epsilon of -1, as upstream compares
        return 0.0
    if given < 0.0:
        raise ValueError(given)
    return default


class ToleranceDefaults(Protocol):
    """What a goal's tolerances fall back on: the trajectory controller's own ``constraints`` (and its logger)."""

    path_tol: dict[str, Tolerance]
    goal_tol: dict[str, Tolerance]
    goal_time: float
    log: logging.Logger


def segment_tolerances(
    controller: ToleranceDefaults,
    path: Sequence[tuple[str, float, float, float]],
    goal: Sequence[tuple[str, float, float, float]],
    goal_time: float,
) -> SegmentTolerances:
    """A FollowJointTrajectory goal's ``path_tolerance``, ``goal_tolerance`` ((joint, position, velocity,
    acceleration) each) and ``goal_time_tolerance`` over the controller's ``constraints``, as ros2_controllers
    jazzy's ``get_segment_tolerances`` resolves them: a joint the controller does not have, or an illegal
    value, discards all of the goal's tolerances for the controller's own, with upstream's error."""
    defaults = SegmentTolerances(dict(controller.path_tol), dict(controller.goal_tol), controller.goal_time)
    log = controller.log
    try:
        resolved_time = resolve_tolerance(defaults.goal_time, goal_time)
    except ValueError:
        log.error(f"Specified illegal goal_time_tolerance: {goal_time:f}. Using default tolerances")
        return defaults
    out = SegmentTolerances(dict(defaults.path), dict(defaults.goal), resolved_time)
    for which, given, table in (("path_tolerance", path, out.path), ("goal_tolerance", goal, out.goal)):
        for name, *values in given:
            if name not in table:
                log.error(f"joint '{name}' specified in goal.{which} does not exist. Using default tolerances.")
                return defaults
            before = table[name]
            resolved = []
            for interface, value, old in zip(
                ("position", "velocity", "acceleration"),
                values,
                (before.position, before.velocity, before.acceleration),
            ):
                try:
                    resolved.append(resolve_tolerance(old, value))
                except ValueError:
                    log.error(
                        f"joint '{name}' specified in goal.{which} has a invalid {interface} tolerance. "
                        "Using default tolerances."
                    )
                    return defaults
            table[name] = Tolerance(*resolved)
    return out

"""MoveIt's ``path_constraints`` as gazelle's planner keeps them along a path: a link's pose within a region
(MoveIt's position and orientation constraints) and joints within ranges (its joint constraints).

MoveIt's OMPL interface keeps them by sampling constrained states or projecting onto them
(moveit_planners/ompl/ompl_interface: constrained_sampler.cpp, and the constrained state space of
``enforce_constrained_state_space``); roboplan's RRT projects every new node onto its ``PoseConstraint`` s
(a frame's [x, y, z, roll, pitch, yaw] displacement from a region frame within bounds). Joint ranges are
checked along every path found; a path that leaves them is searched again."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PathConstraints:
    """What every state of a planned path keeps (an empty one keeps nothing)."""

    poses: tuple[tuple[str, np.ndarray, np.ndarray, np.ndarray], ...] = ()
    """(link, region, lower, upper): the link's displacement from ``region`` (4x4, in the planning frame) as
    [x, y, z, roll, pitch, yaw] (m, rad) within ``lower`` and ``upper`` (6 each; ±inf for a free axis)."""
    joints: tuple[tuple[str, float, float], ...] = ()
    """(joint, lowest, highest): a joint's position range (rad or m)."""

    def __bool__(self) -> bool:
        return bool(self.poses or self.joints)

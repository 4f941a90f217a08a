"""Collision-aware planning for an arm described by URDF + SRDF, on roboplan (pinocchio + coal).

roboplan does the numeric work: the kinematic model and its collision geometry, SRDF groups and
disabled collision pairs, collision-checked IK with restarts, RRT-Connect, path shortcutting and
TOPP-RA time parameterisation. This module turns MoveIt-shaped requests into calls on it and its
failures into MoveIt's error names, so the ROS layer only converts messages. The robot, its limits and
the objects in its scene are :class:`RobotScene` (``_robot_scene.py``); here the motions: IK, plans and
Cartesian paths.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any, Unpack

import numpy as np

from ..description import Semantics
from ._collision_matrix import CollisionMatrix
from ._path_constraints import PathConstraints
from ._robot_options import RobotOptions
from ._robot_scene import PlanningError, RobotScene, SceneObject, roboplan_modules

IK_DIAGNOSIS_SEC = 0.2
"""s a failed IK spends finding out why: the same IK with collisions ignored (out of reach, or in collision)."""

# The work one request may cost. MoveIt bounds none of these; gazelle's move_group serves a ROS domain, and
# one request once held it for 51 s and 1.4 GB (a 0.3 m line at max_step 1e-6, issue 48).
MAX_CARTESIAN_STEPS = 10_000
"""The most poses one Cartesian path interpolates, over all its waypoints (a 1 m line at 0.1 mm); a request
that needs more is refused (FAILURE, as MoveIt refuses a ``max_step`` it cannot use) before any IK."""
CARTESIAN_TIMEOUT_SEC = 30.0
"""s one Cartesian path's IK may take (10,000 poses take ~2 s on an idle core: room for a loaded machine, and a
bound on the IK's own 2 s guard a pose); past it the request is refused (TIMED_OUT)."""
MAX_PLANNING_SEC = 30.0
"""s the most one plan searches: a longer ``allowed_planning_time`` is cut to this (MoveIt's default is 5)."""
MAX_PLANNING_ATTEMPTS = 100
"""The most searches one plan makes for MoveIt's ``num_planning_attempts`` (they share its time)."""
TREE_NODES = 5_000
"""The most nodes one search's trees grow (roboplan's default is 1,000, which gave up on a UR5e pose goal 2
tries in 3): a search that fills them starts again from another seed while the plan's time lasts."""
SHORTCUT_WITHIN_SEC = 0.5
"""s the most a constrained path's shortcutting takes (a 65-point Panda path takes some 5 ms)."""
PLANNERS = {"RRTConnect": "rrt_connect", "RRTstar": "rrt_star", "RRT": "rrt"}
"""The OMPL planners gazelle plans with (roboplan's RRT in its three forms), by OMPL's name
(``geometric::RRTConnect``); every other planner_id is planned with RRT-Connect."""
MAX_IK_SEC = 5.0
"""s the most one IK searches: a longer ``timeout`` is cut to this."""
IK_RESTARTS = 1_000
"""The random restarts one IK makes after the attempt from its seed (roboplan's SimpleIk tries 100 iterations
from each): what bounds an IK's work, the same on any machine; its ``timeout`` is a guard."""
MAX_TRAJECTORY_POINTS = 20_000
"""The most points a timed trajectory has: 200 s at TOPP-RA's 10 ms; a longer one (a tiny velocity scaling,
a dense Cartesian path) is sampled more coarsely rather than grown without bound (a velocity scaling of 1e-6
made a 0.3 rad move 125,000 s long: 12.5 million points)."""
TRAJECTORY_DT = 0.01
"""s between the points of a timed trajectory, up to :data:`MAX_TRAJECTORY_POINTS` of them."""
MIN_MAX_STEP = 2.220446049250313e-16
"""MoveIt's smallest ``max_step`` (``std::numeric_limits<double>::epsilon()``; cartesian_path_service_capability.cpp
answers FAILURE below it)."""


@dataclass(frozen=True)
class Trajectory:
    """A timed joint trajectory of a group: one row per point, what MoveIt's ``RobotTrajectory`` carries
    into a ``FollowJointTrajectory`` goal (``time_from_start`` = ``times``)."""

    joint_names: tuple[str, ...]
    """The group's joints, in the order of the columns."""
    times: np.ndarray
    """(n,) seconds from the start, increasing; the first is 0."""
    positions: np.ndarray
    """(n, joints) rad or m."""
    velocities: np.ndarray
    """(n, joints) rad/s or m/s, within the joints' limits times the velocity scaling."""
    accelerations: np.ndarray
    """(n, joints) rad/s² or m/s², within the limits times the acceleration scaling."""

    @property
    def duration(self) -> float:
        """The time of the last point, seconds (0 for an empty trajectory)."""
        return float(self.times[-1]) if len(self.times) else 0.0


class ArmPlanner:
    """Plans for the groups of the :class:`RobotScene` it owns (:attr:`robot`): IK, joint-space plans (RRT-Connect,
    shortcut, TOPP-RA) and Cartesian paths, each checked against the scene's collisions and limits. The robot's
    own queries and its scene (FK, states, limits, objects) are the robot's, answered here as well so a caller
    holds one object.

    Not thread-safe: one request at a time (a ``PlannerPool`` gives each kind of work its own copy).
    """

    def __init__(self, urdf: str, srdf: str, **options: Unpack[RobotOptions]) -> None:
        """A planner for the robot of ``urdf`` and ``srdf`` (see :class:`RobotScene` for the keyword arguments and
        their defaults); its searches (RRT seeds) come from the scene's ``seed``: a plan repeats."""
        self.robot = RobotScene(urdf, srdf, **options)
        """The robot planned for: its model, limits, current state and the objects its plans keep clear of."""
        self._core, self._rrt, self._simple_ik, self._toppra = roboplan_modules()
        self._seed = self.robot.seed

    # ------------------------------------------------------------------ the robot's (see RobotScene)
    @property
    def scene(self) -> Any:
        """roboplan's scene of the robot (remade when an object is attached or detached) (:attr:`RobotScene.scene`)."""
        return self.robot.scene

    @property
    def joint_names(self) -> list[str]:
        """Every joint of the model, in the order of a full configuration (:attr:`RobotScene.joint_names`)."""
        return self.robot.joint_names

    @property
    def semantics(self) -> Semantics:
        """The SRDF as read (:attr:`RobotScene.semantics`)."""
        return self.robot.semantics

    @property
    def root_link(self) -> str:
        """The link plans and poses are expressed in (:attr:`RobotScene.root_link`)."""
        return self.robot.root_link

    @property
    def warnings(self) -> list[str]:
        """What was left out when the robot was loaded (groups, meshes), one line each (:attr:`RobotScene.warnings`)."""
        return self.robot.warnings

    @property
    def velocity_limits(self) -> dict[str, float]:
        """rad/s (m/s) each joint may move at (:attr:`RobotScene.velocity_limits`)."""
        return self.robot.velocity_limits

    @property
    def fixed_links(self) -> frozenset[str]:
        """Links that no plan moves (:attr:`RobotScene.fixed_links`)."""
        return self.robot.fixed_links

    @property
    def acm(self) -> CollisionMatrix:
        """The allowed collision matrix (:attr:`RobotScene.acm`)."""
        return self.robot.acm

    @property
    def groups(self) -> list[str]:
        """The SRDF's planning groups that could be built (:attr:`RobotScene.groups`)."""
        return self.robot.groups

    def group_joints(self, group: str) -> list[str]:
        """:meth:`RobotScene.group_joints` of :attr:`robot`."""
        return self.robot.group_joints(group)

    def tip_link(self, group: str) -> str:
        """:meth:`RobotScene.tip_link` of :attr:`robot`."""
        return self.robot.tip_link(group)

    def named_state(self, group: str, name: str) -> dict[str, float]:
        """:meth:`RobotScene.named_state` of :attr:`robot`."""
        return self.robot.named_state(group, name)

    def state(self, positions: Mapping[str, float] | None = None) -> np.ndarray:
        """:meth:`RobotScene.state` of :attr:`robot`."""
        return self.robot.state(positions)

    def set_current(self, positions: Mapping[str, float]) -> None:
        """:meth:`RobotScene.set_current` of :attr:`robot`."""
        self.robot.set_current(positions)

    def onto_limits(self, q: np.ndarray) -> np.ndarray:
        """:meth:`RobotScene.onto_limits` of :attr:`robot`."""
        return self.robot.onto_limits(q)

    def outside_limits(self, q: np.ndarray, joints: Sequence[str] | None = None) -> str | None:
        """:meth:`RobotScene.outside_limits` of :attr:`robot`."""
        return self.robot.outside_limits(q, joints)

    def positions(self, q: np.ndarray) -> dict[str, float]:
        """:meth:`RobotScene.positions` of :attr:`robot`."""
        return self.robot.positions(q)

    def fk(self, q: np.ndarray, link: str) -> np.ndarray:
        """:meth:`RobotScene.fk` of :attr:`robot`."""
        return self.robot.fk(q, link)

    def in_collision(self, q: np.ndarray) -> bool:
        """:meth:`RobotScene.in_collision` of :attr:`robot`."""
        return self.robot.in_collision(q)

    def named_pairs(self, q: np.ndarray, shown: int = 3) -> str:
        """:meth:`RobotScene.named_pairs` of :attr:`robot`."""
        return self.robot.named_pairs(q, shown)

    def colliding_pairs(self, q: np.ndarray, most: int = 50) -> list[tuple[str, str]]:
        """:meth:`RobotScene.colliding_pairs` of :attr:`robot`."""
        return self.robot.colliding_pairs(q, most)

    def within_limits(self, q: np.ndarray) -> bool:
        """:meth:`RobotScene.within_limits` of :attr:`robot`."""
        return self.robot.within_limits(q)

    def add_object(self, obj: SceneObject) -> None:
        """:meth:`RobotScene.add_object` of :attr:`robot`."""
        self.robot.add_object(obj)

    def set_allowed_collision_matrix(self, matrix: CollisionMatrix) -> None:
        """:meth:`RobotScene.set_allowed_collision_matrix` of :attr:`robot`."""
        self.robot.set_allowed_collision_matrix(matrix)

    def add_box(self, name: str, size: Sequence[float], pose: np.ndarray) -> None:
        """:meth:`RobotScene.add_box` of :attr:`robot`."""
        self.robot.add_box(name, size, pose)

    def remove_object(self, name: str) -> bool:
        """:meth:`RobotScene.remove_object` of :attr:`robot`."""
        return self.robot.remove_object(name)

    def move_object(self, name: str, pose: np.ndarray) -> None:
        """:meth:`RobotScene.move_object` of :attr:`robot`."""
        self.robot.move_object(name, pose)

    def has_link(self, link: str) -> bool:
        """:meth:`RobotScene.has_link` of :attr:`robot`."""
        return self.robot.has_link(link)

    def objects(self) -> list[SceneObject]:
        """:meth:`RobotScene.objects` of :attr:`robot`."""
        return self.robot.objects()

    # ------------------------------------------------------------------ queries
    def ik(
        self,
        group: str,
        link: str,
        target: np.ndarray,
        seed: np.ndarray | None = None,
        *,
        timeout: float = 0.5,
        avoid_collisions: bool = True,
    ) -> np.ndarray:
        """A full configuration putting ``link`` at ``target`` (4x4, root frame) within 1e-4 m and 1e-3
        rad, moving only ``group``'s joints, seeded from ``seed`` (else the current state), with restarts:
        what MoveIt's ``/compute_ik`` answers.

        Args:
            group: the SRDF planning group whose joints may move.
            link: the link to place (MoveIt's ``ik_link_name``; usually the group's tip).
            target: the link's pose as a 4x4 homogeneous matrix in the robot's root link frame, metres.
            seed: a full configuration to start from (None: the current state); restarts draw random
                configurations within the limits after it.
            timeout: wall seconds for the search (MoveIt's ``timeout``), at most :data:`MAX_IK_SEC`.
            avoid_collisions: refuse solutions in collision with the robot itself or the scene's objects.

        Returns:
            The full configuration (every joint of the model, in :attr:`joint_names` order), the other
            groups' joints as in ``seed``.

        Raises:
            PlanningError: ``NO_IK_SOLUTION``; with collisions avoided, the message says whether the pose is
                out of reach or reachable only in collision (naming the pairs), MoveIt's one code for both.
            PlanningError: ``INVALID_GROUP_NAME`` or ``INVALID_LINK_NAME`` for names the robot lacks.
        """
        joints = self.robot.group_joints(group)
        self.robot.fk(self.robot.state(), link)
        timeout = _budget(timeout, MAX_IK_SEC)
        start_full = self.robot.state() if seed is None else np.asarray(seed, dtype=float)
        goal = self._core.CartesianConfiguration(self.robot.root_link, link, np.asfortranarray(target, dtype=float))
        start = self._group_config(group, joints, start_full)
        try:
            return self._ik(group, joints, link, goal, start, start_full, float(timeout), avoid_collisions)
        except PlanningError as err:
            if not avoid_collisions or err.code != "NO_IK_SOLUTION":
                raise
            why = self._why_no_ik(group, joints, link, goal, start, start_full)
            raise PlanningError(err.code, f"{err.message}: {why}") from None

    def _why_no_ik(
        self, group: str, joints: list[str], link: str, goal: Any, start: Any, start_full: np.ndarray
    ) -> str:
        """Why a collision-free IK failed, said as a person would: the pose is out of reach, or it is reached
        only by joint values that collide (naming the pairs), e.g. a goal inside the table. The same code
        either way (MoveIt says NO_IK_SOLUTION for both); the message tells them apart."""
        try:
            q = self._ik(group, joints, link, goal, start, start_full, IK_DIAGNOSIS_SEC, False)
        except PlanningError:
            return "it is out of reach (no joint values reach it even with collisions ignored)"
        pairs = self.robot.named_pairs(q)
        return f"it is reachable, but in collision there{pairs}" if pairs else "no collision-free solution was found"

    def _ik(
        self,
        group: str,
        joints: list[str],
        link: str,
        goal: Any,
        start: Any,
        start_full: np.ndarray,
        timeout: float,
        avoid_collisions: bool,
    ) -> np.ndarray:
        """Joint values of ``group`` that put ``link`` at ``goal`` (roboplan's SimpleIk from ``start``, then from
        random configurations), the joints outside the group kept at ``start_full``. With ``avoid_collisions``, a
        solution in collision is not returned: the search goes on from the next restart. NO_IK_SOLUTION (MoveIt's
        code) after :data:`IK_RESTARTS` restarts or ``timeout`` s, whichever comes first.

        The restarts are drawn here, from the scene's generator restarted at the planner's seed, rather than by
        roboplan's own restarts (``max_restarts``), whose generator is seeded anew by every solver: the same
        request answers the same on any machine, whatever was asked before it. A CI run flipped on that: the
        UR5e's random goals (tests/planning/test_random_pose_goals.py) took other IK branches there than here,
        and two of them found no path in 5 s."""
        idx = self.robot.group_index(joints)
        deadline = time.monotonic() + timeout
        failed = PlanningError("NO_IK_SOLUTION", f"no joint values of '{group}' put '{link}' at the goal pose")
        self.robot.scene.setRngSeed(self._seed)
        lo, hi = self.robot.bounds
        revolute = self._revolute(joints)
        for restart in range(IK_RESTARTS + 1):
            remaining = deadline - time.monotonic()
            if remaining <= 0.0:
                break
            if restart:
                try:  # roboplan's restarts start from collision-free draws; so do these
                    drawn = np.asarray(self.robot.scene.randomCollisionFreePositions(), dtype=float)
                except RuntimeError as err:  # no collision-free configuration could be sampled
                    raise PlanningError("NO_IK_SOLUTION", f"{failed.message} ({err})") from None
                start = self._group_config(group, joints, drawn)
            opts = self._simple_ik.SimpleIkOptions()
            opts.group_name = group
            opts.check_collisions = avoid_collisions
            opts.max_time = remaining  # a guard: an attempt is at most max_iters (100) iterations
            opts.max_restarts = 0
            opts.max_linear_error_norm = 1e-4
            opts.max_angular_error_norm = 1e-3
            self.robot.scene.setJointPositions(start_full)  # the joints outside the group stay where they are
            solution = self._core.JointConfiguration()
            if not self._simple_ik.SimpleIk(self.robot.scene, opts).solveIk(goal, start, solution):
                continue
            q = self.robot.scene.toFullJointPositions(group, np.asarray(solution.positions, dtype=float))
            out = start_full.copy()  # the joints outside the group keep their values
            out[idx] = _turns_toward(q[idx], start_full[idx], lo[idx], hi[idx], revolute)
            if not avoid_collisions or not self.in_collision(out):
                return out
        raise failed

    def _revolute(self, joints: Sequence[str]) -> np.ndarray:
        """Which of ``joints`` are revolute (bounded; a continuous joint wraps by itself)."""
        revolute = self._core.JointType.REVOLUTE
        return np.array([self.scene.getJointInfo(j).type == revolute for j in joints], dtype=bool)

    def plan(
        self,
        group: str,
        goal: np.ndarray,
        start: np.ndarray | None = None,
        *,
        velocity_scaling: float = 1.0,
        acceleration_scaling: float = 1.0,
        timeout: float = 5.0,
        algorithm: str = "RRTConnect",
        attempts: int = 1,
        constraints: PathConstraints = PathConstraints(),
    ) -> Trajectory:
        """A collision-free, time-parameterised motion of ``group`` from ``start`` (full configuration; the
        current state when None) to the full configuration ``goal``: RRT-Connect in the group's joint space,
        shortcut, then timed by TOPP-RA (what MoveIt's default pipeline does with OMPL and its time
        parameterisation, with roboplan's implementations).

        Args:
            group: the SRDF planning group to move; the goal's other joints are ignored (they stay as they
                start).
            goal: a full configuration (:meth:`state` makes one from joint names).
            start: a full configuration (None: the current state); put onto the joint limits first, as
                MoveIt's FixStartStateBounds adapter does for a start a hair outside them.
            velocity_scaling: MoveIt's ``max_velocity_scaling_factor``: 0 (unset), a negative value or NaN
                means 1, a value above 1 is 1.
            acceleration_scaling: ``max_acceleration_scaling_factor``, the same way.
            timeout: wall seconds for the search (MoveIt's ``allowed_planning_time``), at most
                :data:`MAX_PLANNING_SEC`: searched until a path is found or the time is up, as OMPL does.
            algorithm: a key of :data:`PLANNERS` (OMPL's planner name).
            attempts: MoveIt's ``num_planning_attempts``: the searches made (within the one ``timeout``; at most
                :data:`MAX_PLANNING_ATTEMPTS`), the shortest path kept, as OMPL's parallel plan keeps it.
            constraints: MoveIt's ``path_constraints``, kept by every state of the path (see
                ``_path_constraints.py``); the start and the goal must keep them too
                (``START_STATE_VIOLATES_PATH_CONSTRAINTS``, ``GOAL_VIOLATES_PATH_CONSTRAINTS``).

        Raises:
            PlanningError: ``START_STATE_IN_COLLISION``, ``GOAL_IN_COLLISION``, ``GOAL_STATE_INVALID`` (outside
                the joint limits), or ``TIMED_OUT`` when no path was found in the time (OMPL's TIMEOUT status in
                moveit_planners/ompl/ompl_interface/src/model_based_planning_context.cpp, logPlannerStatus);
                collisions name the colliding pairs.
        """
        joints = self.robot.group_joints(group)
        q0 = self.robot.onto_limits(self.robot.state() if start is None else np.asarray(start, dtype=float))
        q1 = np.asarray(goal, dtype=float).copy()
        others = np.ones(len(q1), dtype=bool)
        others[self.robot.group_index(joints)] = False
        q1[others] = q0[others]  # the joints the group does not move stay as they start (onto their limits)
        outside = self.robot.outside_limits(q1, joints)
        if outside is not None:
            raise PlanningError("GOAL_STATE_INVALID", f"the goal lies outside the joints' limits: {outside}")
        if self.robot.in_collision(q1):
            raise PlanningError("GOAL_IN_COLLISION", f"the goal state is in collision{self.robot.named_pairs(q1)}")
        if self.robot.in_collision(q0):
            pairs = self.robot.named_pairs(q0)
            raise PlanningError("START_STATE_IN_COLLISION", f"the start state is in collision{pairs}")
        outside = self.robot.outside_limits(q0, joints)
        if outside is not None:  # roboplan refuses it on every search ("Invalid start configuration requested")
            raise PlanningError("START_STATE_INVALID", f"the start state lies outside the joints' limits: {outside}")
        keeps, poses = self._keeping(group, constraints)
        for q, who in ((q0, "START_STATE"), (q1, "GOAL")):
            if not keeps(q):
                raise PlanningError(
                    f"{who}_VIOLATES_PATH_CONSTRAINTS", f"the {who.lower()} breaks the path constraints"
                )
        asked, timeout = float(timeout), _budget(timeout, MAX_PLANNING_SEC)
        kept = (lambda path: self._kept(group, joints, q0, path, keeps)) if constraints else None
        path = self._search(group, joints, q0, q1, timeout, algorithm, attempts, poses, kept)
        if path is None:
            cut = f" (allowed_planning_time {asked:g} s is cut to {MAX_PLANNING_SEC:g})" if asked > timeout else ""
            raise PlanningError("TIMED_OUT", f"no collision-free path found in {timeout:g} s{cut}")
        sopts = self._core.PathShortcuttingOptions()
        sopts.group_name = group
        shortcut = self._core.PathShortcutter(self.robot.scene, sopts).shortcut(path)
        if not constraints or self._kept(group, joints, q0, shortcut, keeps):  # a shortcut may leave them
            path = shortcut
        else:
            path = self._shortcut_within(group, joints, q0, path, keeps)
        return self._timed(group, path, velocity_scaling, acceleration_scaling)

    def _keeping(self, group: str, constraints: PathConstraints) -> tuple[Any, list[Any]]:
        """A test of a full configuration against ``constraints`` (roboplan's own test for the poses, the
        ranges for the joints), and the roboplan pose constraints for its RRT."""
        poses = [
            self._rrt.PoseConstraint(
                self.robot.scene,
                group,
                link,
                np.asarray(lower, dtype=float),
                np.asarray(upper, dtype=float),
                np.asfortranarray(region, dtype=float),
                self.robot.root_link,
            )
            for link, region, lower, upper in constraints.poses
        ]
        index = {n: i for i, n in enumerate(self.robot.joint_names)}
        ranges = [(index[j], lo, hi) for j, lo, hi in constraints.joints if j in index]

        def keeps(q: np.ndarray) -> bool:
            if any(not lo - 1e-9 <= q[i] <= hi + 1e-9 for i, lo, hi in ranges):
                return False
            return all(c.satisfies(np.asarray(q, dtype=float)) for c in poses)

        return keeps, poses

    def _kept(self, group: str, joints: list[str], q0: np.ndarray, path: Any, keeps: Any, step: float = 0.02) -> bool:
        """Whether every state of ``path`` (the group's joints; the others as in ``q0``), and of the straight
        lines between them every ``step`` rad, keeps the constraints."""
        index = self.robot.group_index(joints)
        full = np.asarray(q0, dtype=float).copy()
        points = np.asarray(path.positions, dtype=float)
        for a, b in zip(points[:-1], points[1:]):
            for s in np.linspace(0.0, 1.0, max(2, int(np.max(np.abs(b - a)) / step) + 2)):
                full[index] = a + s * (b - a)
                if not keeps(full):
                    return False
        return True

    def _shortcut_within(self, group: str, joints: list[str], q0: np.ndarray, path: Any, keeps: Any) -> Any:
        """``path`` shortened by straight joint-space lines that keep the constraints and are collision free
        (both checked every 0.02 rad): from each point kept, the farthest later point such a line reaches. ompl's
        PathSimplifier, which MoveIt's OMPL runs on a constrained path, takes a shortcut only where the constrained
        state validity checker passes it, the same test. For at most :data:`SHORTCUT_WITHIN_SEC`; then the rest
        of the path as it is."""
        index = self.robot.group_index(joints)
        points = [np.asarray(p, dtype=float) for p in path.positions]
        a_full, b_full = np.asarray(q0, dtype=float).copy(), np.asarray(q0, dtype=float).copy()
        deadline = time.monotonic() + SHORTCUT_WITHIN_SEC

        def line_ok(a: np.ndarray, b: np.ndarray) -> bool:
            if time.monotonic() >= deadline:
                return False
            a_full[index], b_full[index] = a, b
            if self._core.hasCollisionsAlongPath(self.scene, a_full, b_full, 0.02):
                return False
            return self._kept(group, joints, q0, SimpleNamespace(positions=[a, b]), keeps)

        kept, i = [points[0]], 0
        while i < len(points) - 1:
            j = len(points) - 1
            while j > i + 1 and not line_ok(points[i], points[j]):
                j -= 1
            kept.append(points[j])
            i = j
        out = self._core.JointPath()
        out.joint_names, out.positions = path.joint_names, kept
        return out

    def _search(
        self,
        group: str,
        joints: list[str],
        q0: np.ndarray,
        q1: np.ndarray,
        timeout: float,
        algorithm: str,
        attempts: int,
        poses: list[Any],
        kept: Any,
    ) -> Any:
        """roboplan's RRT searches from ``q0`` to ``q1`` until ``attempts`` paths are found or ``timeout`` s are
        up, each from its own seed, each tree at most :data:`TREE_NODES` nodes (a full one is a failed
        search, not an error), its nodes projected onto ``poses`` (roboplan PoseConstraints); a path that
        ``kept`` (when given) refuses is searched again: the shortest path found, or None."""
        opts = self._rrt.RRTOptions()
        opts.group_name = group
        opts.rrt_connect = PLANNERS.get(algorithm, "rrt_connect") == "rrt_connect"
        opts.rrt_star = PLANNERS.get(algorithm) == "rrt_star"
        opts.fast_return = not opts.rrt_star  # RRT* improves its path while its time lasts, as OMPL's does
        opts.max_nodes = TREE_NODES
        opts.collision_check_step_size = 0.02
        deadline = time.monotonic() + timeout
        wanted = max(1, min(int(attempts), MAX_PLANNING_ATTEMPTS))
        start, goal = self._group_config(group, joints, q0), self._group_config(group, joints, q1)
        found: list[Any] = []
        search = 0
        while len(found) < wanted and (left := deadline - time.monotonic()) > 0.0:
            opts.max_planning_time = left
            planner = self._rrt.RRT(self.robot.scene, opts)
            planner.setRngSeed(self._seed + search)
            search += 1
            self.robot.scene.setJointPositions(q0)
            try:
                path = planner.plan(start, goal, poses)
            except RuntimeError:  # roboplan's trees are full ("Added maximum number of nodes"): search again
                continue
            if path is not None and len(path.positions) >= 2 and (kept is None or kept(path)):
                found.append(path)
        return min(found, key=_length, default=None)

    def _line_solver(self, group: str, avoid_collisions: bool) -> Any:
        """roboplan's SimpleIk for the poses of a Cartesian path: each solved from the last, within 1e-4 m and
        1e-3 rad, without restarts."""
        opts = self._simple_ik.SimpleIkOptions()
        opts.group_name = group
        opts.check_collisions = avoid_collisions
        # Each pose is solved from the last in at most max_iters iterations (roboplan's default, 100): the
        # same work and the same answer on any machine. The wall-clock budget is only a guard: at 50 ms a
        # loaded machine took it from the solver between two iterations, and the chess robot's lift
        # answered 0 % beside a CPU hog (tests/planning/test_planning.py stalls the planner's process to show it).
        opts.max_iters = 100
        opts.max_time = 2.0
        opts.max_restarts = 0  # continuity: each pose from the last one, never a jump to another branch
        opts.max_linear_error_norm = 1e-4
        opts.max_angular_error_norm = 1e-3
        return self._simple_ik.SimpleIk(self.robot.scene, opts)

    def _timed(self, group: str, path, velocity_scaling: float, acceleration_scaling: float) -> Trajectory:
        """TOPP-RA over a joint path of ``group``, within the limits times the scaling factors, a point every
        :data:`TRAJECTORY_DT` and at most :data:`MAX_TRAJECTORY_POINTS` points (then evenly spread)."""
        topts = self._toppra.TOPPRAOptions()
        topts.velocity_scale = _fraction(velocity_scaling)
        topts.acceleration_scale = _fraction(acceleration_scaling)
        parameterizer = self._toppra.PathParameterizerTOPPRA(self.robot.scene, group)
        # the duration first, sampled at its two ends (the solve is the cheap part: ~20 ms for 10,000 waypoints;
        # the samples are what grow), then the samples the duration allows
        topts.dt = 1e12
        duration = float(np.asarray(parameterizer.generate(path, topts).times, dtype=float)[-1])
        # (a hair wider than the even split, so that rounding never adds a point past the bound)
        topts.dt = max(TRAJECTORY_DT, duration / (MAX_TRAJECTORY_POINTS - 1) * (1.0 + 1e-9))
        traj = parameterizer.generate(path, topts)
        return Trajectory(
            tuple(traj.joint_names),
            np.asarray(traj.times, dtype=float),
            np.asarray(traj.positions, dtype=float),
            np.asarray(traj.velocities, dtype=float),
            np.asarray(traj.accelerations, dtype=float),
        )

    def cartesian_path(
        self,
        group: str,
        link: str,
        waypoints: Sequence[np.ndarray],
        start: np.ndarray | None = None,
        *,
        max_step: float = 0.01,
        jump_threshold: float = 0.0,
        avoid_collisions: bool = True,
        velocity_scaling: float = 1.0,
        acceleration_scaling: float = 1.0,
        timeout: float = CARTESIAN_TIMEOUT_SEC,
    ) -> tuple[Trajectory | None, float]:
        """``link`` along straight lines (orientation slerped) through ``waypoints`` (4x4, root frame)
        from where it is at ``start``, as MoveIt's compute_cartesian_path: poses every ``max_step`` m,
        each solved by IK seeded from the previous solution. Stops at the first pose with no solution,
        a collision on the way, or a joint jump (``jump_threshold`` times the mean step, when > 0). Each
        pose is made when it is solved, as MoveIt's cartesian_interpolator.cpp makes them: a path that
        stops early costs only the poses before it.

        Args:
            group: the SRDF planning group to move.
            link: the link that follows the lines.
            waypoints: poses (4x4, root link frame) the link passes through, in order.
            start: a full configuration (None: the current state).
            max_step: the largest Cartesian step between two solved poses, metres (MoveIt's ``max_step``).
            jump_threshold: MoveIt's ``jump_threshold``: 0 disables the joint-jump check.
            avoid_collisions: stop at the first pose in collision.
            velocity_scaling: as :meth:`plan`'s.
            acceleration_scaling: as :meth:`plan`'s.
            timeout: wall seconds the poses' IK may take, at most :data:`CARTESIAN_TIMEOUT_SEC`.

        Returns:
            The timed trajectory of what was achieved (None if nothing) and the fraction achieved, between 0
            and 1, as MoveIt's ``GetCartesianPath`` reply reports ``fraction``.

        Raises:
            PlanningError: ``FAILURE`` for a ``max_step`` below MoveIt's smallest (:data:`MIN_MAX_STEP`), a
                waypoint that is not a finite pose, or more than :data:`MAX_CARTESIAN_STEPS` poses to solve;
                ``TIMED_OUT`` past ``timeout``; the group and link names as :meth:`ik`'s.
        """
        joints = self.robot.group_joints(group)
        self.robot.fk(self.robot.state(), link)
        if not math.isfinite(max_step) or max_step < MIN_MAX_STEP:
            # cartesian_path_service_capability.cpp: "this value needs to be > 0", FAILURE
            raise PlanningError(
                "FAILURE", f"max_step must be a positive number of metres, at least {MIN_MAX_STEP:.3g} (got {max_step})"
            )
        q = self.robot.state() if start is None else np.asarray(start, dtype=float).copy()
        begin = self.robot.fk(q, link)
        steps = self._line_steps(begin, waypoints, max_step)
        total = sum(steps)
        poses = self._line_poses(begin, waypoints, steps)
        path = self._follow(group, link, q, poses, avoid_collisions, _budget(timeout, CARTESIAN_TIMEOUT_SEC), total)
        path = _cut_at_jump(path, jump_threshold)
        fraction = (len(path) - 1) / total if total else 1.0
        if len(path) < 2:
            return None, fraction
        joint_path = self._core.JointPath()
        joint_path.joint_names = list(joints)
        joint_path.positions = [np.asarray(p, dtype=float) for p in path]
        return self._timed(group, joint_path, velocity_scaling, acceleration_scaling), fraction

    def _follow(
        self, group: str, link: str, q: np.ndarray, poses: Any, avoid_collisions: bool, budget: float, total: int
    ) -> list[np.ndarray]:
        """The group's joint values along ``poses`` from the full configuration ``q``: each pose solved from the
        last, up to the first with no solution or (``avoid_collisions``) in collision.

        Raises:
            PlanningError: ``TIMED_OUT`` when the poses take more than ``budget`` seconds (``total`` poses).
        """
        joints = self.robot.group_joints(group)
        idx = self.robot.group_index(joints)
        solver = self._line_solver(group, avoid_collisions)
        self.robot.scene.setJointPositions(q)
        path = [q[idx].copy()]
        deadline = time.monotonic() + budget
        for pose in poses:
            if time.monotonic() > deadline:
                raise PlanningError(
                    "TIMED_OUT",
                    f"the Cartesian path's IK took more than {budget:g} s ({len(path) - 1} of {total} poses)",
                )
            goal = self._core.CartesianConfiguration(self.robot.root_link, link, np.asfortranarray(pose, dtype=float))
            solution = self._core.JointConfiguration()
            try:
                if not solver.solveIk(goal, self._group_config(group, joints, q), solution):
                    break
            except RuntimeError:
                break
            nxt = q.copy()
            nxt[idx] = self.robot.scene.toFullJointPositions(group, np.asarray(solution.positions, dtype=float))[idx]
            # each pose's state is checked, not the start nor the way between two poses: MoveIt's
            # compute_cartesian_path (moveit_ros/move_group cartesian_path_service_capability.cpp,
            # isStateValid on every IK solution). So a retreat starts from a state that touches, as a
            # grasped piece standing on the board does.
            if avoid_collisions and self.robot.in_collision(nxt):
                break
            path.append(nxt[idx].copy())
            q = nxt
        return path

    # ------------------------------------------------------------------ helpers
    @staticmethod
    def _line_steps(start: np.ndarray, waypoints: Sequence[np.ndarray], max_step: float) -> list[int]:
        """How many poses each line from ``start`` through ``waypoints`` is cut into: one every ``max_step`` m
        and every ``10 x max_step`` rad of rotation (at least 1 mrad), at least one a line. Counted before any
        is made.

        Raises:
            PlanningError: ``FAILURE`` for a waypoint that is not a finite pose, or more than
                :data:`MAX_CARTESIAN_STEPS` poses in all (naming ``max_step``).
        """
        steps: list[int] = []
        previous = np.asarray(start, dtype=float)
        total = 0
        for k, waypoint in enumerate(waypoints):
            target = np.asarray(waypoint, dtype=float)
            if target.shape != (4, 4) or not np.isfinite(target).all():
                raise PlanningError("FAILURE", f"waypoint {k} is not a finite pose")
            distance = float(np.linalg.norm(target[:3, 3] - previous[:3, 3]))
            cos = (np.trace(previous[:3, :3].T @ target[:3, :3]) - 1.0) / 2.0
            angle = math.acos(max(-1.0, min(1.0, cos)))
            need = max(1.0, distance / max_step, angle / max(max_step * 10.0, 1e-3))
            if total + need > MAX_CARTESIAN_STEPS:  # a float: inf and 1e300 compare before any rounding
                raise PlanningError(
                    "FAILURE",
                    f"max_step {max_step:g} m cuts the path into more than {MAX_CARTESIAN_STEPS} poses, the most one "
                    f"Cartesian path solves (the line to waypoint {k} alone needs {need:.0f}): use a larger max_step",
                )
            steps.append(math.ceil(need))
            total += steps[-1]
            previous = target
        return steps

    def _line_poses(self, start: np.ndarray, waypoints: Sequence[np.ndarray], steps: Sequence[int]):
        """The poses along straight lines from ``start`` through ``waypoints``, ``steps[k]`` on the ``k``-th
        line (:meth:`_line_steps`), orientations slerped, each waypoint the last pose of its line: made one at a
        time, as they are solved."""
        previous = np.asfortranarray(start, dtype=float)
        for waypoint, count in zip(waypoints, steps):
            target = np.asfortranarray(waypoint, dtype=float)
            for k in range(1, count + 1):
                yield np.asarray(self._core.interpolatePose(previous, target, k / count))
            previous = target

    def _group_config(self, group: str, joints: Sequence[str], q_full: np.ndarray):
        """A roboplan JointConfiguration of ``joints``, their values taken from a full-robot vector."""
        config = self._core.JointConfiguration()
        config.joint_names = list(joints)
        config.positions = np.asarray(q_full, dtype=float)[self.robot.group_index(joints)]
        return config


def _turns_toward(q: np.ndarray, seed: np.ndarray, lo: np.ndarray, hi: np.ndarray, revolute: np.ndarray) -> np.ndarray:
    """``q`` with each revolute joint moved by whole turns to the value nearest ``seed`` within [lo, hi]: the same
    pose and geometry. MoveIt's IK plugins search from the seed (KDL's Newton iterations; random restarts only when
    that fails), so a client gets the solution near it; roboplan's restarts from random values can converge a turn
    away on joints whose limits span two turns (UR's +-2 pi), and RRT-Connect then had to find a way round a whole
    turn (a UR5e's upper arm through its base: no path in 20 s)."""
    out = q.copy()
    turn = 2.0 * math.pi
    turns = np.round((seed - q) / turn)
    for fewer in (0.0, 1.0):  # the nearest value; if it leaves the limits, the one a turn less far
        moved = q + (turns - np.sign(turns) * fewer) * turn
        ok = revolute & (moved >= lo) & (moved <= hi) & (np.abs(moved - seed) < np.abs(out - seed))
        out[ok] = moved[ok]
    return out


def _cut_at_jump(path: list[np.ndarray], jump_threshold: float) -> list[np.ndarray]:
    """``path`` up to the first step in joint space longer than ``jump_threshold`` times the mean step: a flip
    to another IK branch (MoveIt's relative jump check, moveit_core cartesian_interpolator.cpp
    ``hasRelativeJointSpaceJump``); the whole path when the threshold is 0 or there are too few steps to
    judge. Differences kept: the step is the Euclidean norm of the joint change where MoveIt sums the joints'
    distances (``RobotState::distance``), and MoveIt checks from two states on (warning under ten)."""
    if jump_threshold <= 0.0 or len(path) <= 2:
        return path
    steps = np.linalg.norm(np.diff(np.asarray(path), axis=0), axis=1)
    limit = jump_threshold * float(np.mean(steps))
    for k, step in enumerate(steps):
        if step > limit:
            return path[: k + 1]
    return path


def _length(path: Any) -> float:
    """A joint path's length: the sum of its steps' norms (rad, m)."""
    q = np.asarray(path.positions, dtype=float)
    return float(np.linalg.norm(np.diff(q, axis=0), axis=1).sum())


def _budget(seconds: float, most: float) -> float:
    """A time budget a request gives, cut to ``most`` (not a number, or infinite: ``most``)."""
    seconds = float(seconds)
    return min(seconds, most) if math.isfinite(seconds) else most


def _fraction(value: float) -> float:
    """MoveIt's scaling factors: 0 (unset) means 1, and they are clamped to (0, 1]."""
    if not math.isfinite(value) or value <= 0.0:
        return 1.0
    return min(value, 1.0)

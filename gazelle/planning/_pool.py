"""The planners of one robot, one for each kind of work, so that a long plan does not hold up a query.

MoveIt's move_group answers its services concurrently: a plan reads the planning scene under a shared
lock, and so do FK, IK, state validity and ``get_planning_scene``; only a change of the scene waits for
them all (planning_scene_monitor's ``LockedPlanningSceneRO``/``RW``). A roboplan scene is not
thread-safe (FK, IK and collision checks write its pinocchio data), so gazelle gives each kind of work its
own copy of the robot's scene, under its own lock:

* ``plan``: joint-space plans and Cartesian paths (seconds, up to the planner's own bounds);
* ``ik``: IK requests (up to their timeout);
* ``query``: FK, state validity, the scene as a message, trajectory checks (milliseconds).

A change of the scene (objects, the allowed collision matrix) is made on the ``plan`` planner under every
lock, as MoveIt's write lock waits for every reader, and then copied to the others (:func:`copy_scene`).
A copy of the Panda costs ~2 MB and ~30 ms (its meshes are cached); a change costs its roboplan work once
per copy.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager

import numpy as np

from ._planner import ArmPlanner
from ._robot_scene import RobotScene, SceneObject

ROLES = ("plan", "ik", "query")
"""The kinds of work, each with its planner and lock; a change of the scene takes the locks in this order."""


class PlannerPool:
    """One :class:`ArmPlanner` per kind of work (:data:`ROLES`), each used under its own lock."""

    def __init__(self, make: Callable[[], ArmPlanner]) -> None:
        """``make()`` builds one planner of the robot (called once per role, the same way each time)."""
        self._planners = {role: make() for role in ROLES}
        self._locks = {role: threading.Lock() for role in ROLES}

    @property
    def primary(self) -> ArmPlanner:
        """The planner that plans and whose scene is changed (the others copy it)."""
        return self._planners["plan"]

    @contextmanager
    def using(self, role: str) -> Iterator[ArmPlanner]:
        """The planner of ``role``, held under its lock for the ``with`` block."""
        with self._locks[role]:
            yield self._planners[role]

    @contextmanager
    def writing(self) -> Iterator[ArmPlanner]:
        """The primary planner under every lock, to change its scene; the change is copied to the other
        planners when the block ends, whether or not it raised (a change half made is copied as made)."""
        with ExitStack() as held:
            for role in ROLES:
                held.enter_context(self._locks[role])
            try:
                yield self.primary
            finally:
                for role in ROLES[1:]:
                    copy_scene(self.primary.robot, self._planners[role].robot)


def copy_scene(source: RobotScene, target: RobotScene) -> None:
    """Make ``target``'s objects (in the same order) and allowed collision matrix ``source``'s: the objects
    ``source`` no longer has are removed, a world object whose shapes are unchanged is moved, any other change
    is added again; from the first object out of order on, all are added again in ``source``'s order. Both
    scenes are of the same robot."""
    theirs = source.objects()
    names = {obj.name for obj in theirs}
    for obj in target.objects():
        if obj.name not in names:
            target.remove_object(obj.name)
    mine = target.objects()
    cut = len(theirs)
    for k, obj in enumerate(theirs):
        have = mine[k] if k < len(mine) else None
        if have is None or have.name != obj.name:
            cut = k
            break
        if _same(have, obj, pose=True):
            continue
        if not obj.link and _same(have, obj, pose=False):
            target.move_object(obj.name, obj.pose)
            continue
        cut = k
        break
    for obj in theirs[cut:]:
        target.add_object(obj)
    if target.acm != source.acm:
        target.set_allowed_collision_matrix(source.acm)


def _same(a: SceneObject, b: SceneObject, *, pose: bool) -> bool:
    """Whether two objects have the same link, touch links and shapes (and pose, with ``pose``)."""
    if (a.name, a.link, a.touch_links) != (b.name, b.link, b.touch_links) or len(a.shapes) != len(b.shapes):
        return False
    for x, y in zip(a.shapes, b.shapes):
        if x.kind != y.kind or x.dimensions != y.dimensions or not np.array_equal(x.pose, y.pose):
            return False
    return not pose or np.array_equal(a.pose, b.pose)

"""The robot a planner plans for (:class:`RobotScene`, owned by :class:`~gazelle.planning.ArmPlanner`):
the URDF's kinematic and collision model with the SRDF's groups and disabled pairs loaded into roboplan, the
joint limits (URDF overridden by MoveIt's joint_limits.yaml), the current state, and the world and attached
objects the plans keep clear of. Names and codes are MoveIt's, so the ROS layer only converts messages."""

from __future__ import annotations

import dataclasses
import math
import os
import re
import tempfile
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from lxml import etree

from .._errors import SimError
from ..description import ModelLoadError, ResourceResolver, Semantics, Severity, load_string
from ._collision_matrix import CollisionMatrix
from ._names import quoted

DEFAULT_ACCELERATION = 1.0
"""rad/s² (m/s²) for a joint whose limits give no acceleration, as MoveIt's time parameterisation assumes."""

_COLLISION_LINE = re.compile(r"Collision detected between (\S+) and (\S+)")
"""roboplan's debug line for a colliding pair of geometries."""


def _body_of(geometry: str) -> str:
    """The body a roboplan geometry belongs to: a link's ``<link>_<n>``, an object's ``<name>#<n>``, an
    attached object's ``__attached_<k>_<n>``."""
    for sep in ("#", "_"):
        head, found, tail = geometry.rpartition(sep)
        if found and tail.isdigit() and head:
            return head
    return geometry


START_BOUNDS_ERROR = 0.05
"""How far past a joint limit a measured start state may read and still be planned from (moved onto it)."""


class PlanningError(SimError):
    """A request that cannot be met; ``code`` is the name of a MoveIt error code (``NO_IK_SOLUTION``)."""

    def __init__(self, code: str, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message


@dataclass(frozen=True)
class Shape:
    """A collision primitive of a scene object: ``box`` (x, y, z sizes), ``sphere`` (radius) or
    ``cylinder`` (height, radius: shape_msgs' order), at ``pose`` (4x4) in the object's frame."""

    kind: str
    dimensions: tuple[float, ...]
    pose: np.ndarray


@dataclass(frozen=True)
class SceneObject:
    """Geometry the planner keeps clear of: in the world (``link`` empty; ``pose`` in the root link's
    frame) or attached to a robot link (``pose`` in the link's frame), touching ``touch_links`` freely.

    An attached object becomes part of the robot model (a link fixed to ``link``), so that it is checked
    against world objects as well as the robot's other links: roboplan checks only pairs that involve the
    robot model."""

    name: str
    shapes: tuple[Shape, ...]
    pose: np.ndarray
    link: str = ""
    touch_links: tuple[str, ...] = ()


def roboplan_modules():  # roboplan's modules, imported on first use (they load pinocchio and coal)
    import importlib

    return tuple(importlib.import_module(f"roboplan.{m}") for m in ("core", "rrt", "simple_ik", "toppra"))


def _absolute_meshes(urdf: str, resolve: Callable[[str], str | None]) -> tuple[str, list[str]]:
    """The URDF with every mesh file name made an absolute path; the ones that could not be resolved."""
    root = etree.fromstring(urdf.encode(), etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False))
    missing = []
    for mesh in root.iter("mesh"):
        uri = mesh.get("filename", "")
        path = resolve(uri)
        if path is None:
            missing.append(uri)
            # a geometry that cannot be loaded is left out of the planner's model, said by the caller
            shape = mesh.getparent()
            holder = shape.getparent() if shape is not None else None
            owner = holder.getparent() if holder is not None else None
            if holder is not None and owner is not None:
                owner.remove(holder)
            continue
        mesh.set("filename", str(path))
    return etree.tostring(root, encoding="unicode"), missing


def moveit_joint_limits(config: Mapping) -> dict[str, dict[str, float]]:
    """The ``joint_limits:`` section of MoveIt's joint_limits.yaml: joint -> {max_velocity, max_acceleration}
    for the limits it switches on."""
    out: dict[str, dict[str, float]] = {}
    for joint, spec in (config.get("joint_limits") or {}).items():
        if not isinstance(spec, Mapping):
            continue
        limits = {}
        for key in ("velocity", "acceleration", "jerk"):
            if spec.get(f"has_{key}_limits") and f"max_{key}" in spec:
                limits[f"max_{key}"] = float(spec[f"max_{key}"])
        out[str(joint)] = limits
    return out


class RobotScene:
    """Planning for one robot: FK, IK, collision checks and timed paths for its SRDF groups.

    Not thread-safe: one request at a time (a ``PlannerPool`` gives each kind of work its own copy).
    """

    def __init__(
        self,
        urdf: str,
        srdf: str,
        *,
        srdf_source: str = "robot_description_semantic",
        resolve_mesh: Callable[[str], str | None] | None = None,
        joint_limits: Mapping[str, Mapping[str, float]] | None = None,
        seed: int = 0,
    ) -> None:
        """A planning scene for the robot of ``urdf`` and ``srdf`` in roboplan: the SRDF's groups, states and
        disabled collision pairs, the URDF's collision meshes (resolved through ``resolve_mesh``, else the
        resource roots; a mesh not found leaves its geometry out, with a warning), ``joint_limits`` (MoveIt's
        joint_limits.yaml, over the URDF's), and an allowed collision matrix as MoveIt keeps it. Random draws
        (RRT, IK restarts) come from ``seed``: a plan repeats."""
        core, rrt, simple_ik, toppra = roboplan_modules()
        self._core, self._rrt, self._simple_ik, self._toppra = core, rrt, simple_ik, toppra
        self.warnings: list[str] = []
        try:
            loaded = load_string(srdf, format="srdf", source=srdf_source)
        except ModelLoadError as err:
            raise PlanningError("FAILURE", f"the SRDF could not be read: {err.summary()}") from None
        semantics = loaded.value
        if not isinstance(semantics, Semantics):
            raise PlanningError("FAILURE", "the SRDF could not be read: no <robot>")
        self.warnings.extend(d.format() for d in loaded.diagnostics if d.severity is Severity.WARNING)
        self.semantics: Semantics = semantics
        resolver = ResourceResolver()

        def in_roots(uri: str) -> str | None:  # package://, model:// and files inside the resource roots
            path = resolver.resolve_uri(uri)
            return str(path) if path is not None and path.is_file() else None

        resolve = resolve_mesh or in_roots
        urdf, missing = _absolute_meshes(urdf, resolve)
        self.warnings.extend(
            f"mesh '{uri}' could not be resolved: its collision geometry is left out" for uri in missing
        )
        self._urdf, self._srdf, self.seed, self._joint_limits = urdf, srdf, seed, dict(joint_limits or {})
        # the scene's description is kept as long as the scene: roboplan's bindings do not say that a
        # Scene owns the description it was made from, so it is not left to the garbage collector
        self._description = core.loadUrdfSceneDescriptionFromXml(urdf, [])
        self.scene = core.Scene(semantics.robot_name or "robot", self._description)
        self.scene.setRngSeed(seed)
        robot = etree.fromstring(urdf.encode())
        self._known_groups = self._import_srdf(srdf, srdf_source, robot)
        self.joint_names: list[str] = list(self.scene.getJointNames())
        self._limits(self._joint_limits)
        self.velocity_limits: dict[str, float] = _velocity_limits(robot, self.joint_names, self._joint_limits)
        """rad/s (m/s) each joint may move at: the URDF's, overridden by joint_limits.yaml, as the plans' TOPP-RA
        takes them. Kept here because roboplan 0.7's ``Scene.getVelocityLimitVectors("")`` (the whole robot)
        writes past its vector on a robot with two mimic joints: YuMi's grippers corrupted the heap ("double
        free or corruption", "corrupted size vs. prev_size") and killed move_group on execute_trajectory."""
        tree = _tree(robot)
        self._tree = tree
        self.root_link = tree.root
        moved = tree.moved_by({j for g in self.groups for j in self.group_joints(g)})
        self.fixed_links = frozenset(tree.links) - moved
        """Links that no plan moves: the root, what is welded to it, and what only joints outside every
        group move (a mobile base's wheels). They may touch world objects (the ground they stand on)."""
        self._current = self.scene.getCurrentJointPositions().copy()
        self._objects: dict[str, tuple[SceneObject, tuple[str, ...]]] = {}  # name -> (object, geometry names)
        self._attached_links: list[str] = []
        """The links the attached objects are in the robot model (see :meth:`_rebuild`)."""
        collision_links = [str(link.get("name")) for link in robot.iter("link") if link.find("collision") is not None]
        self._collision_links = frozenset(collision_links)
        disabled = [(d.link1, d.link2) for d in semantics.disabled_collisions]
        self.acm = CollisionMatrix.initial(collision_links, disabled)
        """MoveIt's allowed collision matrix (see :mod:`._collision_matrix`); roboplan already holds the
        initial one (the SRDF's pairs), so it is applied only once a client has set one."""
        self._srdf_allowed = frozenset(self.acm.allowed)
        self._acm_set = False
        self._acm_applied: set[frozenset[str]] = set()
        """Pairs whose checking the matrix has changed in roboplan from the SRDF's (link pairs either way,
        object pairs allowed), to put back when a later matrix says otherwise."""

    # ------------------------------------------------------------------ model
    def _import_srdf(self, srdf: str, source: str, robot) -> set[str]:
        """Groups and disabled pairs into roboplan; a group naming links or joints the URDF lacks is a
        warning at the group's line in ``source``, naming them."""
        links = {str(link.get("name")) for link in robot.iter("link")}
        joints = {str(joint.get("name")) for joint in robot.iter("joint")}
        lines = _element_lines(srdf, "group")
        missing: dict[str, list[str]] = {}
        for group in self.semantics.groups:
            named_links = [*group.links, *(end for chain in group.chains for end in (chain.base_link, chain.tip_link))]
            gaps = [f"link '{n}'" for n in dict.fromkeys(named_links) if n not in links]
            gaps += [f"joint '{n}'" for n in group.joints if n not in joints]
            missing[group.name] = gaps
        subgroups = {g.name: g.subgroups for g in self.semantics.groups}

        def spread() -> None:  # a group of groups goes with any group it needs (in whatever order they come)
            changed = True
            while changed:
                changed = False
                for name, subs in subgroups.items():
                    gaps = [
                        f"group '{n}'" for n in subs if missing.get(n, ["?"]) and f"group '{n}'" not in missing[name]
                    ]
                    if gaps:
                        missing[name] += gaps
                        changed = True

        spread()
        # roboplan refuses the whole SRDF for one group naming an unknown link (a bad tip dropped every
        # group, the untouched hand too): it is given the SRDF without the groups already known to be bad
        bad = {name for name, gaps in missing.items() if gaps}
        try:
            self.scene.importSrdf(_without_groups(srdf, bad, links) if bad else srdf)
        except Exception as err:
            self.warnings.append(f"the SRDF's groups could not all be used: {err}")
        for group in self.semantics.groups:
            if missing[group.name]:
                continue
            try:
                self.scene.getJointGroupInfo(group.name)
            except Exception:
                missing[group.name] = ["links or joints the robot does not have"]
        spread()
        for name, gaps in missing.items():
            if gaps:
                where = f"{source}:{lines[name]}: " if name in lines else f"{source}: "
                self.warnings.append(f"{where}SRDF group '{name}' names {', '.join(gaps)}: the group is left out")
        known = {name for name, gaps in missing.items() if not gaps}
        ee_lines = _element_lines(srdf, "end_effector")
        for ee in self.semantics.end_effectors:
            if ee.group not in known:
                where = f"{source}:{ee_lines[ee.name]}: " if ee.name in ee_lines else f"{source}: "
                self.warnings.append(
                    f"{where}SRDF end effector '{ee.name}' names group '{ee.group}', which does not exist"
                )
        return known

    def _limits(self, limits: Mapping[str, Mapping[str, float]]) -> None:
        """Velocity and acceleration limits: the URDF's, overridden by joint_limits.yaml; an acceleration
        nobody gives is :data:`DEFAULT_ACCELERATION`."""
        lines = ["joint_limits:"]
        for joint in self.joint_names:
            spec = limits.get(joint, {})
            lines.append(f"  {joint}:")
            if "max_velocity" in spec:
                lines.append(f"    max_velocity: [{float(spec['max_velocity'])!r}]")
            lines.append(f"    max_acceleration: [{float(spec.get('max_acceleration', DEFAULT_ACCELERATION))!r}]")
            if "max_jerk" in spec:
                lines.append(f"    max_jerk: [{float(spec['max_jerk'])!r}]")
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:  # roboplan reads a file
            f.write("\n".join(lines) + "\n")
        try:
            self.scene.importJointLimitsFromConfig(self._core.loadJointLimitsConfig(f.name))
        finally:
            os.unlink(f.name)

    @property
    def groups(self) -> list[str]:
        """The SRDF's planning groups that roboplan could build, in the file's order (a group naming links
        or joints the URDF lacks was left out with a warning when the scene was made)."""
        return [g.name for g in self.semantics.groups if g.name in self._known_groups]

    def group_joints(self, group: str) -> list[str]:
        """The joints a planning group moves, in roboplan's order; INVALID_GROUP_NAME (MoveIt's code) listing the
        groups when there is no such group."""
        if group not in self._known_groups:
            known = ", ".join(self.groups) or "none"
            raise PlanningError("INVALID_GROUP_NAME", f"no planning group {quoted(group)} (the SRDF has: {known})")
        return list(self.scene.getJointGroupInfo(group).joint_names)

    def tip_link(self, group: str) -> str:
        """The link a pose goal without a link name moves: the tip of the group's last chain, else its last link."""
        self.group_joints(group)
        g = next(g for g in self.semantics.groups if g.name == group)
        if g.chains:
            return g.chains[-1].tip_link
        if g.subgroups:
            return self.tip_link(g.subgroups[-1])
        links = list(self.scene.getJointGroupInfo(group).link_names)
        if g.links:
            return g.links[-1]
        if not links:
            raise PlanningError("INVALID_LINK_NAME", f"group {quoted(group)} has no links to put a pose goal on")
        return links[-1]

    def named_state(self, group: str, name: str) -> dict[str, float]:
        """A ``<group_state>`` of the SRDF as joint values."""
        self.group_joints(group)
        for state in self.semantics.group_states:
            if state.group == group and state.name == name:
                return {joint: values[0] for joint, values in state.joint_values if values}
        names = sorted(s.name for s in self.semantics.group_states if s.group == group)
        raise PlanningError(
            "INVALID_GOAL_CONSTRAINTS",
            f"group {quoted(group)} has no named state {quoted(name)} (it has: {', '.join(names) or 'none'})",
        )

    # ------------------------------------------------------------------ state
    def state(self, positions: Mapping[str, float] | None = None) -> np.ndarray:
        """A full configuration: the current one with ``positions`` put in (names not in the model are ignored)."""
        q = self._current.copy()
        if positions:
            index = {n: i for i, n in enumerate(self.joint_names)}
            for name, value in positions.items():
                if name in index:
                    q[index[name]] = float(value)
        return q

    def set_current(self, positions: Mapping[str, float]) -> None:
        """What the robot's joints read now (from /joint_states).

        A reading a little past a limit (a simulated finger at -0.0001 m, its limit 0) is moved onto the
        limit, as MoveIt does within its ``start_state_max_bounds_error`` (0.05); further out stays as read.
        """
        self._current = self.onto_limits(self.state(positions))

    def onto_limits(self, q: np.ndarray) -> np.ndarray:
        """``q`` with every joint within :data:`START_BOUNDS_ERROR` past a limit moved onto it (a request's
        start state read from /joint_states: a finger at -6.6e-12 m against its limit 0)."""
        lo, hi = self.bounds
        q = np.asarray(q, dtype=float)
        near = (q >= lo - START_BOUNDS_ERROR) & (q <= hi + START_BOUNDS_ERROR)
        return np.where(near, np.clip(q, lo, hi), q)

    def outside_limits(self, q: np.ndarray, joints: Sequence[str] | None = None) -> str | None:
        """Which of ``joints`` (all when None) lies outside its limits in ``q``, said with its value and
        limits (for GOAL_STATE_INVALID), or None. MoveIt checks only the planned group's joints
        (moveit_ros/planning/planning_request_adapter_plugins/src/check_start_state_bounds.cpp takes the
        group's joint models), so a gripper finger a hair past its limit does not refuse an arm's plan."""
        lo, hi = self.bounds
        names = list(joints) if joints is not None else list(self.joint_names)
        for name, i in zip(names, self.group_index(names)):
            if not lo[i] - 1e-9 <= q[i] <= hi[i] + 1e-9:
                return f"joint '{name}' at {q[i]:.6g} is outside its limits [{lo[i]:.6g}, {hi[i]:.6g}]"
        return None

    def group_index(self, joints: Sequence[str]) -> list[int]:
        """The positions of ``joints`` in a full configuration (:attr:`joint_names` order)."""
        index = {n: i for i, n in enumerate(self.joint_names)}
        return [index[j] for j in joints]

    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Every joint's lower and upper position limits (rad or m), in the full configuration's order."""
        lo, hi = self.scene.getPositionLimitVectors("")
        return np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)

    def positions(self, q: np.ndarray) -> dict[str, float]:
        """A full configuration as {joint name: value} (rad or m), the inverse of :meth:`state`."""
        return {n: float(v) for n, v in zip(self.joint_names, q)}

    def fk(self, q: np.ndarray, link: str) -> np.ndarray:
        """The pose of ``link`` in the root link's frame, as a 4x4 matrix."""
        try:
            self.scene.getFrameId(link)
        except Exception:
            raise PlanningError("INVALID_LINK_NAME", f"the robot has no link {quoted(link)}") from None
        return np.array(self.scene.forwardKinematics(np.asarray(q, dtype=float), link))

    def in_collision(self, q: np.ndarray) -> bool:
        """Whether the robot at ``q`` touches itself (the pairs the SRDF's ``<disable_collisions>`` and the
        allowed collision matrix do not excuse) or an object of the scene."""
        return bool(self.scene.hasCollisions(np.asarray(q, dtype=float)))

    def named_pairs(self, q: np.ndarray, shown: int = 3) -> str:
        """``": a-b, c-d (and N more)"`` naming what collides at ``q``, for an error message."""
        pairs = self.colliding_pairs(q)
        if not pairs:
            return ""
        more = f" (and {len(pairs) - shown} more)" if len(pairs) > shown else ""
        return ": " + ", ".join(f"{a} with {b}" for a, b in pairs[:shown]) + more

    def colliding_pairs(self, q: np.ndarray, most: int = 50) -> list[tuple[str, str]]:
        """The pairs of bodies (links, world objects, attached objects) in collision at ``q``, at most
        ``most``: what MoveIt's check_state_validity reports as ``contacts`` and its errors name.

        roboplan says which geometries collide only in its debug print to the process's stdout, so the
        check runs once more with fd 1 sent to a temporary file (a file, not a pipe, which a long report
        would fill and block), read back and parsed. Call it under the planner's lock."""
        import ctypes

        libc = ctypes.CDLL(None)
        with tempfile.TemporaryFile() as out:
            libc.fflush(None)
            saved = os.dup(1)
            try:
                os.dup2(out.fileno(), 1)
                self.scene.hasCollisions(np.asarray(q, dtype=float), True)
                libc.fflush(None)
            finally:
                os.dup2(saved, 1)
                os.close(saved)
            out.seek(0)
            text = out.read(1 << 20).decode("utf-8", "replace")
        held = {
            link: obj.name for link, obj in zip(self._attached_links, (o for o, _ in self._objects.values() if o.link))
        }
        pairs: list[tuple[str, str]] = []
        for m in _COLLISION_LINE.finditer(text):
            a, b = _body_of(m.group(1)), _body_of(m.group(2))
            pair = (held.get(a, a), held.get(b, b))
            if pair not in pairs:
                pairs.append(pair)
            if len(pairs) >= most:
                break
        return pairs

    def within_limits(self, q: np.ndarray) -> bool:
        """Whether every joint of ``q`` is within the URDF's position limits (MoveIt's ``joint_limits.yaml``
        changes velocities and accelerations only, here as in gazelle's ``moveit_joint_limits``)."""
        return bool(self.scene.isValidConfiguration(np.asarray(q, dtype=float)))

    # ------------------------------------------------------------------ world
    def add_object(self, obj: SceneObject) -> None:
        """Put ``obj`` in the scene, replacing one of the same name (so an object moves, or is attached
        or detached, by adding it again)."""
        self.remove_object(obj.name)
        if obj.link:
            self.fk(self._current, obj.link)  # INVALID_LINK_NAME for a link the robot lacks
        for i, shape in enumerate(obj.shapes):
            if _urdf_geometry(shape) is None:
                raise PlanningError(
                    "INVALID_OBJECT_NAME",
                    f"object '{obj.name}': shape {i} ({shape.kind} {list(shape.dimensions)}) is not one gazelle "
                    "plans with",
                )
        if obj.link:
            self._objects[obj.name] = (obj, ())
            self._rebuild()
        else:
            self._objects[obj.name] = (obj, self._add_geometries(obj))
            self._apply_acm({obj.name})

    # ------------------------------------------------------------------ allowed collision matrix
    def set_allowed_collision_matrix(self, matrix: CollisionMatrix) -> None:
        """Replace the allowed collision matrix, as MoveIt's ``setPlanningSceneDiffMsg`` does: the pairs it
        allows are not checked from now on, the other pairs among its names are (the SRDF's too, when the
        matrix forbids them); an object it names that comes later gets its entries then."""
        self.acm = matrix
        self._acm_set = True
        self._apply_acm()

    def _apply_acm(self, only: set[str] | None = None) -> None:
        """Put the matrix's pairs into roboplan (those involving ``only``'s names, or all): link pairs as
        the matrix says; an object pair allowed, or checked again when an earlier matrix allowed it and
        gazelle does not allow it on its own (an attached object with its link and touch_links, a world
        object with the links no plan moves and with other world objects)."""
        if not self._acm_set:
            return
        allow: list[tuple[str, str]] = []
        check: list[tuple[str, str]] = []
        names = self.acm.names
        named = self.acm.named
        defaulted = set(self.acm.defaults)
        for key in [k for k in self._acm_applied if not k <= named and not k & defaulted]:
            # a pair an earlier matrix set that this one does not name: MoveIt's replaced matrix has no
            # entry for it (collision_matrix.cpp getAllowedCollision), so it is checked again; a pair of
            # links goes back to what the SRDF says
            a, b = sorted(key)
            if only is not None and a not in only and b not in only:
                continue
            self._acm_applied.discard(key)
            if a in self._collision_links and b in self._collision_links:
                (allow if key in self._srdf_allowed else check).append((a, b))
            elif not self._allowed_anyway(a, b):
                check += [(x, y) for x in self._bodies(a) for y in self._bodies(b)]
        for i, a in enumerate(names):
            for b in names[i + 1 :]:
                if only is None or a in only or b in only:
                    self._acm_pair(a, b, allow, check)
        defaults = self.acm.defaults
        if defaults:
            # a default entry decides its name's pairs with everything the entries do not name together
            universe = list(dict.fromkeys([*names, *defaults, *self._collision_links, *self._objects]))
            for i, a in enumerate(universe):
                for b in universe[i + 1 :]:
                    if (a in named and b in named) or (a not in defaults and b not in defaults):
                        continue
                    if only is None or a in only or b in only:
                        self._acm_pair(a, b, allow, check)
        for pairs, enabled in ((allow, False), (check, True)):
            if pairs:
                try:
                    self.scene.setCollisions(pairs, enabled)
                except Exception:  # see _add_geometries: the data is rebuilt below whatever happened
                    pass
        self.scene.setCollisions([], False)

    def _acm_pair(self, a: str, b: str, allow: list[tuple[str, str]], check: list[tuple[str, str]]) -> None:
        """Add the roboplan pairs of matrix names ``a`` and ``b`` to ``allow`` or ``check`` as the matrix says
        (see :meth:`_apply_acm`), keeping :attr:`_acm_applied` up to date."""
        key = frozenset((a, b))
        allowed = self.acm.is_allowed(a, b)
        if a in self._collision_links and b in self._collision_links:
            # only what differs from the SRDF's: roboplan never pairs links on one joint, and a pair set to
            # be checked would be added
            changed = allowed != (key in self._srdf_allowed)
            if changed or key in self._acm_applied:
                (allow if allowed else check).append((a, b))
                if changed:
                    self._acm_applied.add(key)
                else:
                    self._acm_applied.discard(key)
            return
        pairs = [(x, y) for x in self._bodies(a) for y in self._bodies(b)]
        if not pairs:
            return
        if allowed:
            allow += pairs
            self._acm_applied.add(key)
        elif key in self._acm_applied:
            self._acm_applied.discard(key)
            check += [(x, y) for x, y in pairs if not self._allowed_anyway(a, b)]

    def _bodies(self, name: str) -> list[str]:
        """roboplan's bodies of a matrix name: a link with collision geometry itself, an object its
        geometries; nothing for a name the scene does not have (yet)."""
        if name in self._collision_links:
            return [name]
        entry = self._objects.get(name)
        return list(entry[1]) if entry is not None else []

    def _allowed_anyway(self, a: str, b: str) -> bool:
        """Whether gazelle allows the pair whatever the matrix says (see :meth:`_add_geometries`)."""
        objects = {n: o for n, (o, _g) in self._objects.items()}
        for obj_name, other in ((a, b), (b, a)):
            obj = objects.get(obj_name)
            if obj is None:
                continue
            if obj.link:
                return other in {obj.link, *obj.touch_links}
            return other in self.fixed_links or (other in objects and not objects[other].link)
        return False

    def _add_geometries(self, obj: SceneObject) -> tuple[str, ...]:
        """Add ``obj``'s shapes as scene geometry: a world object's in the world, free to touch the links
        no plan moves and the other world objects; an attached object's on its link, free to touch that
        link and its ``touch_links`` (this copy is what the robot's own links are checked against: its
        copy in the robot model, see :meth:`_rebuild`, is what world objects are checked against)."""
        core = self._core
        frame = obj.link or "universe"
        # a geometry's placement is in its frame's *joint* frame (Pinocchio's convention): for a link
        # welded below its moving joint (panda_hand, 0.107 m below panda_link7's joint) the offset goes in
        # too, or a piece held in the hand sat at link7 and every plan with it collided there
        placed = self._in_joint_frame(obj.link) @ np.asarray(obj.pose, dtype=float) if obj.link else obj.pose
        names = []
        for i, shape in enumerate(obj.shapes):
            name = f"{obj.name}#{i}"
            tform = np.asfortranarray(np.asarray(placed, dtype=float) @ shape.pose, dtype=float)
            d = [float(v) for v in shape.dimensions]
            if shape.kind == "box":
                self.scene.addBoxGeometry(name, frame, core.Box(d[0], d[1], d[2]), tform, np.ones(4))
            elif shape.kind == "sphere":
                self.scene.addSphereGeometry(name, frame, core.Sphere(d[0]), tform, np.ones(4))
            else:
                self.scene.addCylinderGeometry(name, frame, core.Cylinder(d[1], d[0]), tform, np.ones(4))
            names.append(name)
        allowed = [(a, b) for k, a in enumerate(names) for b in names[k + 1 :]]
        if obj.link:
            # its own copy in the robot model (and the other held objects') overlap it by design
            allowed += [(n, link) for n in names for link in {obj.link, *obj.touch_links, *self._attached_links}]
        else:  # what the robot stands on touches links that no plan moves: not a collision to avoid
            allowed += [(n, link) for n in names for link in sorted(self.fixed_links)]
            # world objects may touch each other (the board on the table): not the robot's concern
            others = [g for other, geoms in self._objects.values() if not other.link for g in geoms]
            if others:
                self.scene.setCollisions([(a, b) for a in names for b in others], False)
        for a, b in allowed:
            try:
                self.scene.setCollisions(a, b, False)
            except Exception:  # a link with no collision geometry of its own: nothing to allow
                pass
        # roboplan's single-pair setCollisions may change the pairs and then raise before it rebuilds the
        # collision data (a link without geometry): coal then fails every check ("collisionPairs.size() ==
        # collisionResults.size()"), which made any attached object end every plan. The batch form
        # rebuilds the data once, whatever happened above.
        self.scene.setCollisions([], False)
        return tuple(names)

    def _in_joint_frame(self, link: str) -> np.ndarray:
        """Where ``link`` is in the frame of the joint that moves it: the frame of the nearest link up the
        tree (itself included) whose joint is not fixed, or of the root."""
        parent = {child: (up, kind) for up, kids in self._tree.children.items() for _, kind, child in kids}
        anchor = link
        while anchor in parent and parent[anchor][1] == "fixed":
            anchor = parent[anchor][0]
        if anchor == link:
            return np.eye(4)
        q = self._current
        return np.linalg.inv(self.fk(q, anchor)) @ self.fk(q, link)

    def add_box(self, name: str, size: Sequence[float], pose: np.ndarray) -> None:
        """A box of the world (``pose`` in the root link's frame) that plans keep clear of."""
        self.add_object(SceneObject(name, (Shape("box", tuple(size), np.eye(4)),), np.asarray(pose, dtype=float)))

    def remove_object(self, name: str) -> bool:
        """Take an object out of the scene; False when there is none of that name."""
        entry = self._objects.pop(name, None)
        if entry is None:
            return False
        if entry[0].link:
            self._rebuild()  # its geometry goes with the old scene
            return True
        for geometry in entry[1]:
            self.scene.removeGeometry(geometry)
        return True

    def _rebuild(self) -> None:
        """A new roboplan scene: the robot with its attached objects as links fixed to theirs (allowed to
        touch that link and their ``touch_links``), the SRDF, the limits, then the world objects again.
        Costs ~15 ms for the Panda (its meshes are cached)."""
        core = self._core
        attached = [obj for obj, _ in self._objects.values() if obj.link]
        links, disabled = [], []
        self._attached_links = [f"__attached_{k}" for k in range(len(attached))]
        for name, obj in zip(self._attached_links, attached):
            collisions = "".join(
                f"<collision>{_urdf_origin(np.asarray(obj.pose, dtype=float) @ shape.pose)}"
                f"<geometry>{_urdf_geometry(shape)}</geometry></collision>"
                for shape in obj.shapes
            )
            links.append(
                f'<link name="{name}">{collisions}</link><joint name="{name}_joint" type="fixed">'
                f'<parent link="{obj.link}"/><child link="{name}"/></joint>'
            )
            disabled += [
                f'<disable_collisions link1="{name}" link2="{link}" reason="Never"/>'
                for link in dict.fromkeys((obj.link, *obj.touch_links))
            ]
        urdf = self._urdf.replace("</robot>", "".join(links) + "</robot>") if links else self._urdf
        srdf = self._srdf.replace("</robot>", "".join(disabled) + "</robot>") if disabled else self._srdf
        description = core.loadUrdfSceneDescriptionFromXml(urdf, [])
        self.scene = core.Scene(self.semantics.robot_name or "robot", description)
        self._description = description  # see __init__
        self.scene.setRngSeed(self.seed)
        try:
            self.scene.importSrdf(srdf)
        except Exception:  # said once, when the planner was made
            pass
        self._limits(self._joint_limits)
        objects, self._objects = self._objects, {}
        for name, (obj, _) in objects.items():
            self._objects[name] = (obj, self._add_geometries(obj))
        self._acm_applied.clear()  # a new roboplan scene: the SRDF's pairs again, then the matrix
        self._apply_acm()

    def move_object(self, name: str, pose: np.ndarray) -> None:
        """Put an object (its shapes unchanged) at ``pose``: cheaper than adding it again."""
        obj, geometries = self._objects[name]
        if obj.link:
            self.add_object(dataclasses.replace(obj, pose=np.asarray(pose, dtype=float)))
            return
        pose = np.asarray(pose, dtype=float)
        for geometry, shape in zip(geometries, obj.shapes):
            tform = np.asfortranarray(pose @ shape.pose, dtype=float)
            self.scene.updateGeometryPlacement(geometry, obj.link or "universe", tform)
        self._objects[name] = (dataclasses.replace(obj, pose=pose), geometries)

    def has_link(self, link: str) -> bool:
        """Whether the robot model has a frame (link) of that name."""
        try:
            self.scene.getFrameId(link)
        except Exception:
            return False
        return True

    def objects(self) -> list[SceneObject]:
        """The scene's objects (world and attached), as added: what ``/get_planning_scene`` reports."""
        return [obj for obj, _ in self._objects.values()]


def _without_groups(srdf: str, groups: set[str], links: set[str]) -> str:
    """``srdf`` without the ``<group>`` elements named in ``groups`` and what refers to them (end effectors,
    group states, passive joints stay), nor ``<disable_collisions>`` naming links the robot lacks."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False)
    root = etree.fromstring(srdf.encode(), parser)
    for el in list(root):
        tag = el.tag if isinstance(el.tag, str) else ""
        if (
            (tag == "group" and el.get("name") in groups)
            or (tag == "group_state" and el.get("group") in groups)
            or (tag == "end_effector" and (el.get("group") in groups or el.get("parent_group") in groups))
            or (tag == "disable_collisions" and (el.get("link1") not in links or el.get("link2") not in links))
        ):
            root.remove(el)
    return etree.tostring(root, encoding="unicode")


def _urdf_geometry(shape: Shape) -> str | None:
    """A shape as a URDF ``<geometry>`` child (MoveIt's dimensions: a cylinder is height, radius)."""
    d = [float(v) for v in shape.dimensions]
    if shape.kind == "box" and len(d) >= 3:
        return f'<box size="{d[0]!r} {d[1]!r} {d[2]!r}"/>'
    if shape.kind == "sphere" and len(d) >= 1:
        return f'<sphere radius="{d[0]!r}"/>'
    if shape.kind == "cylinder" and len(d) >= 2:
        return f'<cylinder radius="{d[1]!r}" length="{d[0]!r}"/>'
    return None


def _urdf_origin(T: np.ndarray) -> str:
    """A 4x4 transform as a URDF ``<origin>`` (roll, pitch, yaw about fixed x, y, z)."""
    R = T[:3, :3]
    pitch = math.asin(max(-1.0, min(1.0, -R[2, 0])))
    if abs(R[2, 0]) < 1.0 - 1e-9:
        roll, yaw = math.atan2(R[2, 1], R[2, 2]), math.atan2(R[1, 0], R[0, 0])
    else:  # gimbal lock: all the rotation in yaw
        roll, yaw = 0.0, math.atan2(-R[0, 1], R[1, 1])
    x, y, z = (float(v) for v in T[:3, 3])
    return f'<origin xyz="{x!r} {y!r} {z!r}" rpy="{roll!r} {pitch!r} {yaw!r}"/>'


def _element_lines(srdf: str, tag: str) -> dict[str, int]:
    """The line of each top-level SRDF element ``<tag name=...>`` (``group``, ``end_effector``)."""
    try:
        root = etree.fromstring(srdf.encode())
    except etree.XMLSyntaxError:
        return {}
    return {str(g.get("name")): int(g.sourceline or 0) for g in root.findall(tag) if g.get("name")}


@dataclasses.dataclass(frozen=True)
class _Tree:
    """A URDF's kinematic tree, read once."""

    links: list[str]
    """Every link, in file order."""
    children: dict[str, list[tuple[str, str, str]]]
    """Link -> its (joint name, joint type, child link)s."""
    roots: list[str]
    """The links that are no joint's child."""

    @property
    def root(self) -> str:
        """The root link (the first, should there be several)."""
        return self.roots[0] if self.roots else (self.links[0] if self.links else "")

    def moved_by(self, joints: set[str]) -> set[str]:
        """The links that a motion of ``joints`` moves (a fixed joint moves nothing): their child links
        and everything below them."""
        moved: set[str] = set()
        todo = [(link, False) for link in self.roots]
        while todo:
            link, moving = todo.pop()
            if moving:
                moved.add(link)
            for name, kind, child in self.children.get(link, []):
                todo.append((child, moving or (name in joints and kind != "fixed")))
        return moved


def _tree(robot) -> _Tree:
    """The kinematic tree of a parsed URDF ``<robot>``."""
    links = [str(link.get("name")) for link in robot.iter("link")]
    children: dict[str, list[tuple[str, str, str]]] = {}
    child_links = set()
    for joint in robot.iter("joint"):
        parent, child = joint.find("parent"), joint.find("child")
        if parent is None or child is None:
            continue
        kids = children.setdefault(str(parent.get("link")), [])
        kids.append((str(joint.get("name")), str(joint.get("type")), str(child.get("link"))))
        child_links.add(str(child.get("link")))
    return _Tree(links, children, [link for link in links if link not in child_links])


def _velocity_limits(
    robot: etree._Element, joint_names: list[str], joint_limits: Mapping[str, Mapping[str, float]]
) -> dict[str, float]:
    """Each joint's speed limit (rad/s or m/s): joint_limits.yaml's ``max_velocity``, else the URDF's
    ``<limit velocity>``, else none (infinity)."""
    urdf_velocity = {
        str(j.get("name")): float(str(limit.get("velocity")))
        for j in robot.iter("joint")
        if (limit := j.find("limit")) is not None and limit.get("velocity") is not None
    }
    return {n: float(joint_limits.get(n, {}).get("max_velocity", urdf_velocity.get(n, math.inf))) for n in joint_names}

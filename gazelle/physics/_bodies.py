"""A model's links as MuJoCo bodies and its joints as dofs (:func:`add_model`), on the shapes of
``_builder.py``; names as ``_builder.py`` says (``<entity>::<link>``).

How description joints map to MuJoCo:

=============  ===============================================================
revolute       hinge, limited to [lower, upper]
continuous     hinge, unlimited
prismatic      slide, limited
fixed          no joint (welded body)
floating       free joint at the top level; three slides + ball when nested
planar         two slides + hinge about the plane normal
ball           ball
universal      two hinges
screw          hinge + slide, coupled by a joint equality (thread pitch)
=============  ===============================================================

Kinematic links (SDF ``<kinematic>true</kinematic>``; Gazebo: not moved by forces,
gravity or contacts, yet placed by joint positions and set-state calls):

* a kinematic *root* link gets no free joint: it stays where it is put
  (:meth:`PhysicsWorld.set_entity_state` moves it) and carries what lands on it;
* a kinematic link *below a joint* gets gravity compensation, and the dofs of the
  joint above it get a huge armature (:data:`KINEMATIC_ARMATURE`) so that the
  constraint solver sees an obstacle of practically infinite inertia; after every
  step :class:`PhysicsWorld` then puts those dofs back exactly where their own
  velocity takes them (``q += qdot·dt``, ``qdot`` unchanged), so no force moves
  them by even one bit. Their position and velocity change only through
  :meth:`PhysicsWorld.set_joint_state` (or a reset).

Limits: actuators on a kinematic joint (e.g. a ``JointPositionController``) have no
effect: command it with ``set_joint_state``; only hinge and slide dofs are held
exactly (the ball of a nested ``ball``/``floating`` joint above a kinematic link
only gets the armature, so it creeps under large loads); the dynamic links of the
same robot still feel the kinematic link's inertia but not its weight.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Sequence

import mujoco
import numpy as np

from ..description import (
    Joint,
    JointAxis,
    JointLimit,
    JointType,
    Link,
    Model,
    Pose,
    quat_rotate,
)
from ._builder import (
    COLLISION_GROUP,
    EQUAL_LIMITS_SLACK,
    JOINT_ARMATURE,
    KINEMATIC_ARMATURE,
    MAX_TREE_DEPTH,
    MIN_MASS,
    SHOWN_COLLISION_GROUP,
    BuildError,
    BuiltEntity,
    add_geom,
    add_visual_geom,
    scoped,
    unsimulated_surface_parameters,
)
from ._contact_pairs import add_contact_proxy

_log = logging.getLogger("gazelle.physics")


def _set_inertial(body: mujoco.MjsBody, link: Link) -> None:
    """A link's mass, centre of mass and full inertia tensor on its MuJoCo body, explicitly (MuJoCo does not derive
    them from the geoms); a mass below :data:`MIN_MASS` is raised to it, since MuJoCo refuses a massless moving
    body."""
    inertial = link.inertial
    if inertial is None:
        return
    body.explicitinertial = True
    body.mass = max(inertial.mass, MIN_MASS)
    body.ipos = np.array(inertial.pose.position, dtype=np.float64)
    body.iquat = np.array(inertial.pose.orientation, dtype=np.float64)
    # an isotropic 1e-6 of the trace absorbs the rounding the loader tolerates (A + B >= C within rtol 1e-6,
    # e.g. TurtleBot3's thin-disk wheels, A + B == C), which MuJoCo's exact check would reject
    eps = 1e-6 * (inertial.ixx + inertial.iyy + inertial.izz)
    body.fullinertia = np.array(
        [inertial.ixx + eps, inertial.iyy + eps, inertial.izz + eps, inertial.ixy, inertial.ixz, inertial.iyz]
    )


def _joint_frame_in_child(joint: Joint) -> Pose:
    return joint.child_offset.inverse()


def _set_range(j: mujoco.MjsJoint, limit: JointLimit | None, limited: bool) -> None:
    """A joint's position limits, if it has them (and both, in order)."""
    if not (
        limited
        and limit is not None
        and limit.lower is not None
        and limit.upper is not None
        and limit.upper >= limit.lower
    ):
        j.limited = mujoco.mjtLimited.mjLIMITED_FALSE
        return
    j.limited = mujoco.mjtLimited.mjLIMITED_TRUE
    lo, hi = limit.lower, limit.upper
    if hi - lo < 2 * EQUAL_LIMITS_SLACK:
        # lower == upper: a joint that cannot move, which Gazebo accepts (gz-sim's example worlds
        # nested_model_joint_positions and tracked_vehicle_simple have them); MuJoCo's compiler
        # refuses an empty range, so the range is opened by a micro-radian (micrometre) each way
        mid = (lo + hi) / 2
        lo, hi = mid - EQUAL_LIMITS_SLACK, mid + EQUAL_LIMITS_SLACK
    j.range = np.array([lo, hi], dtype=np.float64)


def _add_dof(
    body: mujoco.MjsBody,
    kind: mujoco.mjtJoint,
    jname: str,
    pos: list[float],
    jaxis: list[float],
    limited: bool,
    axis: JointAxis | None,
) -> mujoco.MjsJoint:
    """One MuJoCo joint of a description's joint: its limits, damping, friction, spring and effort limit.

    The mapping is what gz-sim's physics gives the same joint: ``<dynamics><damping>`` is viscous damping
    (MuJoCo integrates it implicitly, stable at any value), ``<friction>`` Coulomb friction
    (``frictionloss``), the SDF spring ``stiffness`` about ``springref``; ``<limit><effort>`` bounds the
    force actuators may apply to a hinge or slide (``actfrcrange``: what ros2_control and plugins command
    cannot exceed it, as Gazebo clamps a joint's force command to its effort limit), while a passive force
    (a spring, gravity through a contact) is not bounded by it, as in Gazebo."""
    limit = axis.limit if axis is not None else None
    dyn = axis.dynamics if axis is not None else None
    j = body.add_joint(name=jname, type=kind, pos=pos, axis=jaxis)
    _set_range(j, limit, limited)
    if dyn is not None:
        j.damping = np.array([dyn.damping, 0.0, 0.0])  # MuJoCo 4: polynomial coefficients
        j.frictionloss = dyn.friction
        if dyn.spring_stiffness:
            j.stiffness = np.array([dyn.spring_stiffness, 0.0, 0.0])
            j.springref = dyn.spring_reference
    one_dof = kind in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)
    if limit is not None and limit.effort is not None and limit.effort > 0 and one_dof:
        j.actfrclimited = mujoco.mjtLimited.mjLIMITED_TRUE
        j.actfrcrange = np.array([-limit.effort, limit.effort], dtype=np.float64)
    j.armature = JOINT_ARMATURE
    return j


def _plane_axes(normal: list[float]) -> tuple[list[float], list[float], list[float]]:
    """A planar joint's two directions in the plane and its normal (unit vectors, right-handed)."""
    n = np.asarray(normal, dtype=float)
    n = n / (np.linalg.norm(n) or 1.0)
    a = np.cross(n, [1.0, 0.0, 0.0])
    if np.linalg.norm(a) < 1e-6:
        a = np.cross(n, [0.0, 1.0, 0.0])
    a = a / np.linalg.norm(a)
    return list(a), list(np.cross(n, a)), list(n)


def _add_joint_dofs(spec: mujoco.MjSpec, body: mujoco.MjsBody, joint: Joint, name: str, built: BuiltEntity) -> None:
    """A joint's degrees of freedom on its child body, at the joint frame's origin: a hinge (revolute: limited,
    continuous: not), a slide, a ball, two hinges (universal), a hinge and a slide coupled by the thread pitch
    (screw), two slides and a hinge (planar), three slides and a ball (floating); nothing for fixed. Their MuJoCo
    names are recorded in ``built.joints`` under the joint's name."""
    X_CJ = _joint_frame_in_child(joint)
    pos = list(X_CJ.position)
    axis_j = joint.axis.xyz if joint.axis is not None else (1.0, 0.0, 0.0)
    axis = list(quat_rotate(X_CJ.orientation, axis_j))
    names: list[str] = []

    def add(kind: mujoco.mjtJoint, jname: str, jaxis: list[float], limited: bool) -> None:
        names.append(_add_dof(body, kind, jname, pos, jaxis, limited, joint.axis).name)

    t = joint.type
    if t in (JointType.REVOLUTE, JointType.CONTINUOUS):
        add(mujoco.mjtJoint.mjJNT_HINGE, name, axis, t is JointType.REVOLUTE)
    elif t is JointType.PRISMATIC:
        add(mujoco.mjtJoint.mjJNT_SLIDE, name, axis, True)
    elif t is JointType.BALL:
        j = body.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_BALL, pos=pos)
        names.append(j.name)
    elif t is JointType.UNIVERSAL:
        add(mujoco.mjtJoint.mjJNT_HINGE, name, axis, True)
        axis2 = joint.axis2.xyz if joint.axis2 is not None else (0.0, 1.0, 0.0)
        add(mujoco.mjtJoint.mjJNT_HINGE, name + "#2", list(quat_rotate(X_CJ.orientation, axis2)), False)
    elif t is JointType.SCREW:
        add(mujoco.mjtJoint.mjJNT_HINGE, name, axis, False)
        add(mujoco.mjtJoint.mjJNT_SLIDE, name + "#slide", axis, False)
        # SDF 1.10's <screw_thread_pitch>: metres along the axis per revolution (sdformat's joint.sdf; the
        # description converts the older <thread_pitch>, -2π/pitch rad/m), so the slide moves pitch/2π per
        # radian: a joint equality slide = pitch/2π · angle (MuJoCo's polynomial data, 12 numbers)
        pitch = joint.screw_thread_pitch if joint.screw_thread_pitch is not None else 1.0
        spec.add_equality(
            name=name + "#screw",
            type=mujoco.mjtEq.mjEQ_JOINT,
            name1=name + "#slide",
            name2=name,
            data=[0.0, pitch / (2 * math.pi), 0.0, 0.0, 0.0] + [0.0] * 7,
        )
        built.equalities.append(name + "#screw")
    elif t is JointType.PLANAR:
        # plane normal = axis; translate in two orthogonal directions, rotate about the normal
        a, b, n = _plane_axes(axis)
        add(mujoco.mjtJoint.mjJNT_SLIDE, name + "#x", a, False)
        add(mujoco.mjtJoint.mjJNT_SLIDE, name + "#y", b, False)
        add(mujoco.mjtJoint.mjJNT_HINGE, name, n, False)
    elif t is JointType.FLOATING:
        for i, ax in enumerate(([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])):
            add(mujoco.mjtJoint.mjJNT_SLIDE, f"{name}#t{i}", ax, False)
        j = body.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_BALL, pos=pos)
        names.append(j.name)
    elif t is JointType.FIXED:
        pass
    else:  # pragma: no cover
        raise BuildError(f"joint '{joint.name}': unsupported type {t.value}")
    built.joints[joint.name] = names


def add_visuals(spec: mujoco.MjSpec, model: Model, built: BuiltEntity) -> None:
    """Put the visual shapes of an entity built without them into ``spec`` (a camera came into the
    world: it should see everything as users do, textures included), and hide its collision shapes
    from cameras, as if it had been built with ``visuals``."""
    if built.visuals:
        return
    for link in model.links:
        body = spec.body(built.bodies.get(link.name, ""))
        if body is None:
            continue
        for geom in body.geoms:
            if geom.group == SHOWN_COLLISION_GROUP:
                geom.group = COLLISION_GROUP
        for i, vis in enumerate(link.visuals):
            add_visual_geom(spec, body, vis, scoped(built.name, f"{link.name}::{vis.name or 'visual'}#v{i}"))
    built.visuals = True


def add_model(spec: mujoco.MjSpec, model: Model, entity: str, X_WM: Pose, *, visuals: bool = False) -> BuiltEntity:
    """Add ``model`` to ``spec`` as entity ``entity`` placed at ``X_WM``; with ``visuals``, its visual
    shapes too, as geoms that neither collide nor weigh (group :data:`VISUAL_GROUP`), for cameras.

    Raises:
        BuildError: the model cannot be represented (e.g. an unresolved collision mesh).
    """
    if not model.links:
        raise BuildError(f"model '{model.name}' has no links")
    if len(model.links) > MAX_LINKS:
        raise BuildError(
            f"model '{model.name}' has {len(model.links)} links, more than the {MAX_LINKS} a model may have"
        )
    tree = _ModelTree(spec, model, entity, visuals)
    tree.add_roots(X_WM)
    tree.add_world_joints(X_WM)
    built = tree.built
    built.unsimulated = {param: tuple(where) for param, where in tree.ignored.items()}
    built.decomposed = tuple(tree.decomposed)
    _exclude_self_collisions(spec, model, entity, built)
    _couple_mimic_joints(spec, model, entity, built)
    return built


class _ModelTree:
    """One model's links added to a spec as a tree of bodies (see :func:`add_model`)."""

    def __init__(self, spec: mujoco.MjSpec, model: Model, entity: str, visuals: bool) -> None:
        """The pieces of one model's MuJoCo bodies: the joint tree by parent, its links by name, and what the build
        records (bodies, joints, the surface parameters it could not apply, the meshes it decomposed)."""
        self.spec, self.model, self.entity, self.visuals = spec, model, entity, visuals
        self.children: dict[str, list[Joint]] = {}
        self.child_joint: dict[str, Joint] = {}
        for j in model.joints:
            self.children.setdefault(j.parent, []).append(j)
            self.child_joint[j.child] = j
        self.links = {lk.name: lk for lk in model.links}
        self.built = BuiltEntity(name=entity, root_body="", free_joint=None, visuals=visuals)
        self.ignored: dict[str, list[str]] = {}
        """Surface parameters MuJoCo does not simulate -> the collisions that set them (warned about)."""
        self.decomposed: list[tuple[str, int, float, str]] = []
        self.total_mass = sum((lk.inertial.mass if lk.inertial else 0.0) for lk in model.links) or 1.0

    def add_roots(self, X_WM: Pose) -> None:
        """Each root link and its subtree; a root link of a non-static model gets a free joint (SDF: its
        link pose in the model frame). A link named "world" with joints from it is the world frame itself
        (r6bot, dual-arm Panda): not a body."""
        built, entity = self.built, self.entity
        roots = [
            lk.name
            for lk in self.model.links
            if lk.name not in self.child_joint and not (lk.name == "world" and "world" in self.children)
        ]
        for r in roots:
            link = self.links[r]
            X_MR = link.pose or Pose()
            self.add_subtree(self.spec.worldbody, r, X_WM * X_MR, None)
            body = self.spec.body(scoped(entity, r))
            if not built.root_body:
                built.root_body = body.name
            if not self.model.static and not link.kinematic:
                fj = body.add_freejoint(name=scoped(entity, f"{r}#free"))
                if built.free_joint is None:
                    built.free_joint = fj.name

    def add_world_joints(self, X_WM: Pose) -> None:
        """The subtrees hanging from the world by a joint (a fixed or moving base)."""
        for j in self.children.get("world", []):
            if self.links.get(j.child) is None:
                raise BuildError(f"joint '{j.name}': unknown child link '{j.child}'")
            # the SDF loader gives a joint to the world its origin in the world frame of the model's own
            # pose (``model.pose``): re-express it in the model frame, so it follows the spawn pose and the
            # model pose is not applied twice (URDF: ``model.pose`` is the identity, origin in the model frame)
            X_WJ = X_WM * self.model.pose.inverse() * j.origin
            self.add_subtree(self.spec.worldbody, j.child, X_WJ * j.child_offset, j)
            if not self.built.root_body:
                self.built.root_body = scoped(self.entity, j.child)

    def add_subtree(self, parent_body: mujoco.MjsBody, link_name: str, X_PC: Pose, joint: Joint | None) -> None:
        """Add the link ``link_name`` at ``X_PC`` in ``parent_body`` (through ``joint``), then every link below it,
        depth-first. Iterative, so a 5,000-link chain is no RecursionError; a tree deeper than
        :data:`MAX_TREE_DEPTH` is a BuildError naming the link."""
        # iterative (an explicit stack), so a 5,000-link chain is no RecursionError
        stack: list[tuple[mujoco.MjsBody, str, Pose, Joint | None, int]] = [(parent_body, link_name, X_PC, joint, 1)]
        while stack:
            parent, name, X, jnt, depth = stack.pop()
            if depth > MAX_TREE_DEPTH:
                raise BuildError(
                    f"model '{self.model.name}': the link tree is deeper than {MAX_TREE_DEPTH} links (at link "
                    f"'{name}'); MuJoCo nests bodies at most ~1,000 deep"
                )
            body = self._add_link_body(parent, self.links[name], X, jnt)
            stack.extend(
                (body, j.child, j.origin * j.child_offset, j, depth + 1) for j in reversed(self.children.get(name, []))
            )

    def _add_link_body(
        self, parent_body: mujoco.MjsBody, link: Link, X_PC: Pose, joint: Joint | None
    ) -> mujoco.MjsBody:
        """One link as a MuJoCo body: its pose in the parent, its inertia, the degrees of freedom of the joint above
        it, its collisions and (when visuals are built) its visuals. A kinematic link, or one without gravity, is
        gravity-compensated."""
        spec, entity, built = self.spec, self.entity, self.built
        link_name = link.name
        body = parent_body.add_body(
            name=scoped(entity, link_name), pos=list(X_PC.position), quat=list(X_PC.orientation)
        )
        if link.kinematic or not link.gravity:
            body.gravcomp = 1.0
        built.bodies[link_name] = body.name
        _set_inertial(body, link)
        if joint is not None:
            _add_joint_dofs(spec, body, joint, scoped(entity, joint.name), built)
            if link.kinematic:
                self._make_kinematic(built.joints[joint.name])
        self._add_collisions(body, link)
        for i, vis in enumerate(link.visuals if self.visuals else ()):
            add_visual_geom(spec, body, vis, scoped(entity, f"{link_name}::{vis.name or 'visual'}#v{i}"))
        return body

    def _make_kinematic(self, joint_names: Sequence[str]) -> None:
        """A kinematic link's joints: moved by commands only (a heavy armature, no damping, friction or
        spring)."""
        for jname in joint_names:
            mj = self.spec.joint(jname)
            mj.armature = KINEMATIC_ARMATURE
            mj.damping = np.zeros(3)
            mj.frictionloss = 0.0
            mj.stiffness = np.zeros(3)
            self.built.kinematic_joints.append(jname)

    def _add_collisions(self, body: mujoco.MjsBody, link: Link) -> None:
        """A link's collisions as geoms: in a group cameras do not draw when the model has visuals, or drawn in the
        link's first visual colour when it has none; every surface parameter MuJoCo cannot apply is collected for
        one warning."""
        visuals = self.visuals
        mass_hint = link.inertial.mass if link.inertial else self.total_mass
        colour = next(
            (v.material.diffuse for v in link.visuals if v.material is not None and v.material.diffuse is not None),
            None,
        )
        moving = not self.model.static
        for i, col in enumerate(link.collisions):
            name = scoped(self.entity, f"{link.name}::{col.name or 'collision'}#{i}")
            add_geom(
                self.spec,
                body,
                col,
                name,
                mass_hint,
                self.decomposed,
                group=COLLISION_GROUP if visuals else SHOWN_COLLISION_GROUP,
                rgba=None if visuals else colour,
                moving=moving,
            )
            proxy = add_contact_proxy(body, col, name, scoped(self.entity, "")) if moving else None
            if proxy is not None:
                self.built.contact_proxies.append(proxy)
            for param in unsimulated_surface_parameters(col, anisotropic=proxy is not None):
                self.ignored.setdefault(param, []).append(f"{link.name}/{col.name}")


MIMIC_TIME_CONSTANT_SEC = 0.005
"""How fast a mimic joint's coupling corrects an error (MuJoCo's default, 0.02 s, let a gripper's second
finger trail the first by 2 mm under gravity and made the pair oscillate; 5 ms stays above 2 steps)."""


def _couple_mimic_joints(spec: mujoco.MjSpec, model: Model, entity: str, built: BuiltEntity) -> None:
    """A URDF ``<mimic joint multiplier offset>`` joint follows its leader: a MuJoCo joint equality
    ``q = offset + multiplier * q_leader`` (a soft constraint, solved with the contacts), as gz-sim's
    mimic constraint and the grippers' real linkages do."""
    for j in model.joints:
        if j.mimic is None:
            continue
        follower, leader = built.joints.get(j.name), built.joints.get(j.mimic.joint)
        if not follower or not leader or len(follower) != 1 or len(leader) != 1:
            continue
        spec.add_equality(
            name=scoped(entity, f"{j.name}#mimic"),
            type=mujoco.mjtEq.mjEQ_JOINT,
            name1=follower[0],
            name2=leader[0],
            data=[j.mimic.offset, j.mimic.multiplier, 0.0, 0.0, 0.0] + [0.0] * 7,
            solref=[MIMIC_TIME_CONSTANT_SEC, 1.0],
        )


MAX_LINKS = 1000
"""The most links one model may have. Real robots have tens (a Panda 11, NASA's Robonaut 2 about 100); a
description of thousands is an attack or a mistake, and its build costs seconds and hundreds of MB."""
MAX_SELF_EXCLUDES = 500
"""The most body-pair excludes one model's self-collision filtering may add to the world. MuJoCo's spec
deletes an exclude in time proportional to all the world's excludes (500 of 7,140 took 13 s), so a
model past this uses collision bits instead (see :func:`_exclude_self_collisions`)."""
SELF_COLLISION_BITS = tuple(1 << b for b in range(16, 32))
"""contype bits above Gazebo's 16-bit collide_bitmask, one of which a large model's geoms take."""


def _weld_groups(model: Model, built: BuiltEntity) -> dict[str, str]:
    """Link -> the link its body is welded to (itself when it has a joint of its own), or ``""`` for a
    body welded to the world (a static model's, a kinematic root's, a link fixed to the world).

    MuJoCo never collides two bodies welded together, nor a body with its parent's weld group
    (``filterparent``), so those pairs need no exclude."""
    parent_of = {j.child: j for j in model.joints}
    out: dict[str, str] = {}
    for name in built.bodies:
        chain = []
        cur = name
        while True:
            if cur in out:
                root = out[cur]
                break
            chain.append(cur)
            j = parent_of.get(cur)
            if j is None:  # a root link: free unless the model is static or the link kinematic
                link = next((lk for lk in model.links if lk.name == cur), None)
                root = "" if model.static or (link is not None and link.kinematic) else cur
                break
            if j.type is not JointType.FIXED:
                root = cur
                break
            if j.parent in ("world", "") or j.parent not in built.bodies:
                root = ""
                break
            cur = j.parent
        for c in chain:
            out[c] = root
    return out


def _exclude_self_collisions(spec: mujoco.MjSpec, model: Model, entity: str, built: BuiltEntity) -> None:
    """Gazebo's links of one model do not collide with each other unless self_collide is on.

    Pairs of links welded together need nothing (MuJoCo never collides them); the others get one MuJoCo
    exclude each, up to :data:`MAX_SELF_EXCLUDES`. A model that would need more (hundreds of moving links)
    instead gives its collision geoms a contype bit of its own above Gazebo's 16 bits and every other
    high bit in conaffinity: its geoms then never collide with each other, collide with every other
    geom as their collide_bitmasks say, and with another such model unless the two drew the same bit
    (16 bits, chosen from the entity's name: documented in docs/security.md)."""
    if model.self_collide:
        return
    with_geoms = [
        lk.name for lk in model.links if lk.collisions and lk.self_collide is not True and lk.name in built.bodies
    ]
    weld = _weld_groups(model, built)
    groups: dict[str, list[str]] = {}
    for name in with_geoms:
        groups.setdefault(weld.get(name, name), []).append(name)
    members = list(groups.values())
    pairs = sum(len(a) * len(b) for i, a in enumerate(members) for b in members[i + 1 :])
    if pairs <= MAX_SELF_EXCLUDES:
        for i, group_a in enumerate(members):
            for group_b in members[i + 1 :]:
                for a in group_a:
                    for b in group_b:
                        spec.add_exclude(
                            name=scoped(entity, f"{a}|{b}#exclude"),
                            bodyname1=built.bodies[a],
                            bodyname2=built.bodies[b],
                        )
        return
    import zlib

    bit = SELF_COLLISION_BITS[zlib.crc32(entity.encode()) % len(SELF_COLLISION_BITS)]
    high = sum(SELF_COLLISION_BITS)
    for name in with_geoms:
        for geom in spec.body(built.bodies[name]).geoms:
            if geom.contype or geom.conaffinity:
                mask = int(geom.contype) & 0xFFFF
                geom.contype = _signed32(bit)
                geom.conaffinity = _signed32(mask | (high & ~bit))


def _signed32(value: int) -> int:
    """A 32-bit mask as MuJoCo's int field holds it."""
    value &= 0xFFFFFFFF
    return value - (1 << 32) if value >= 1 << 31 else value

"""Turn description objects into MuJoCo ``MjSpec`` bodies. Never sees XML.

Naming: every MuJoCo element of an entity is prefixed ``<entity>::``, e.g. the
link ``base_link`` of entity ``robot`` is the body ``robot::base_link`` and its
joint ``wheel`` the joint ``robot::wheel``. Links with a fixed joint become
separate welded bodies (never lumped), so every link frame stays addressable.

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

import hashlib
import logging
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from ..description import (
    Box,
    Capsule,
    Collision,
    Cone,
    Cylinder,
    Ellipsoid,
    Joint,
    JointAxis,
    JointLimit,
    JointType,
    Link,
    Mesh,
    MeshLook,
    MeshReadError,
    Model,
    Plane,
    Pose,
    Sphere,
    Visual,
    load_mesh,
    load_mesh_look,
    quat_rotate,
)
from ._convex import collision_parts

_log = logging.getLogger("gazelle.physics")

SEP = "::"
MIN_MASS = 1e-6
JOINT_ARMATURE = 1e-4
"""Rotor inertia added to every 1-dof joint (kg·m²): keeps light links well conditioned."""
MAX_TREE_DEPTH = 1000
"""Deepest link tree the builder accepts: MuJoCo's compiler refuses bodies nested deeper than ~1,020
("depth limit exceeded in signature computation"); we say so up front, naming the link."""
EQUAL_LIMITS_SLACK = 1e-6
"""rad (m) each way around a joint whose lower and upper limits are equal (see ``_add_joint_dofs``)."""
KINEMATIC_ARMATURE = 1e8
"""Armature of the dofs above a kinematic link (kg·m² or kg): contacts see an immovable obstacle."""


class BuildError(Exception):
    """A description cannot become a MuJoCo model; the message names the element."""


def scoped(entity: str, name: str) -> str:
    """The MuJoCo name of an element ``name`` of entity ``entity``."""
    return f"{entity}{SEP}{name}"


@dataclass
class BuiltEntity:
    """What the builder added to the spec for one entity (names only: indices change on recompile)."""

    name: str
    root_body: str
    free_joint: str | None
    bodies: dict[str, str] = field(default_factory=dict)
    """link name -> MuJoCo body name."""
    joints: dict[str, list[str]] = field(default_factory=dict)
    """description joint name -> MuJoCo joint names (several for planar/universal/...)."""
    equalities: list[str] = field(default_factory=list)
    kinematic_joints: list[str] = field(default_factory=list)
    """MuJoCo joints above kinematic links: moved only by set-state calls (see the module docstring)."""
    unsimulated: dict[str, tuple[str, ...]] = field(default_factory=dict)
    """Contact parameters MuJoCo cannot honour -> the ``link/collision`` places that set them."""
    decomposed: tuple[tuple[str, int, float, str], ...] = ()
    """Non-convex collision meshes split into convex parts: (file, parts, seconds, where from)."""
    visuals: bool = False
    """Whether its visual shapes are in the model (see :func:`add_visuals`)."""


def friction_priority(mu: float) -> int:
    """MuJoCo combines the friction of two geoms by taking the larger; ODE/Gazebo take the smaller.

    MuJoCo uses the parameters of the geom with the higher ``priority`` instead, so
    giving slippery geoms a higher priority reproduces ODE's min(mu1, mu2) rule.
    """
    mu = max(mu, 0.0)
    return int(max(0, min(100, round(40 - 20 * math.log10(mu + 1e-2)))))


def _surface_friction(col: Collision) -> list[float]:
    s = col.surface
    mu = s.mu if s.mu is not None else 1.0
    if s.mu2 is not None:
        mu = min(mu, s.mu2) if s.mu2 >= 0 else mu
    frictionless = mu == 0.0  # a frictionless caster resists neither sliding nor spinning
    torsional = s.torsional if s.torsional is not None else (0.0 if frictionless else 0.005)
    # Bullet's <rolling_friction> is not applied (see _NOT_SIMULATED): the rolling slot is MuJoCo's
    # default, used only by condim 6 geoms, which gazelle does not make
    rolling = 0.0 if frictionless else 0.0001
    return [max(mu, 0.0), max(torsional, 0.0), max(rolling, 0.0)]


DEFAULT_KP = 1e4
"""N/m: the contact stiffness, at the least, of a moving link whose collision gives no ``<kp>``."""
MUJOCO_DEFAULT_SOLREF = (0.02, 1.0)


def _solref_from_surface(
    col: Collision, mass_hint: float, timestep: float, *, moving: bool = True
) -> tuple[list[float], list[float]] | None:
    """Map ODE's contact stiffness kp (N/m) to a critically damped MuJoCo contact.

    ODE turns kp/kd into ERP/CFM, a heavily damped constraint; a raw spring of
    stiffness kp on a light link would ring faster than the step and launch it. So
    kp sets the time constant ``2·sqrt(m/kp)`` of a critically damped contact
    (never shorter than two steps, MuJoCo's stability limit); kd is ignored.

    Without a kp (SDFormat's default is 1e12, ``sdf/1.9/surface.sdf``: Gazebo's contacts are stiff),
    a moving link's contact is MuJoCo's default (0.02 s) unless that is softer than
    :data:`DEFAULT_KP`: MuJoCo's contact stiffness scales with the link's mass, and its default on a
    link lighter than 1 kg gives way to forces Gazebo's would not. The Panda's fingers, closing with
    their 20 N effort limit, went 1 cm into a 1 g chess piece and squeezed it out of the hand; with
    this the piece holds (1 mm into it). Heavier links and static ones keep MuJoCo's default, which
    the rest of gazelle's physics checks were measured with.
    """
    s = col.surface
    if s.kp is None and not moving:
        return None
    kp = DEFAULT_KP if s.kp is None else s.kp
    if kp <= 0:
        return None
    timeconst = 2.0 * math.sqrt(max(mass_hint, MIN_MASS) / kp)
    if s.kp is None and timeconst >= MUJOCO_DEFAULT_SOLREF[0]:
        return None  # MuJoCo's default is the stiffer
    return [max(2.0 * timestep, timeconst), 1.0], [0.9, 0.95, 0.001, 0.5, 2.0]


def _primitive(g: object) -> dict | None:
    """MuJoCo ``type`` and ``size`` of a box, cylinder, sphere, capsule or ellipsoid (half sizes); None for others."""
    if isinstance(g, Box):
        return {"type": mujoco.mjtGeom.mjGEOM_BOX, "size": [g.size[0] / 2, g.size[1] / 2, g.size[2] / 2]}
    if isinstance(g, Cylinder):
        return {"type": mujoco.mjtGeom.mjGEOM_CYLINDER, "size": [g.radius, g.length / 2, 0]}
    if isinstance(g, Sphere):
        return {"type": mujoco.mjtGeom.mjGEOM_SPHERE, "size": [g.radius, 0, 0]}
    if isinstance(g, Capsule):
        return {"type": mujoco.mjtGeom.mjGEOM_CAPSULE, "size": [g.radius, g.length / 2, 0]}
    if isinstance(g, Ellipsoid):
        return {"type": mujoco.mjtGeom.mjGEOM_ELLIPSOID, "size": list(g.radii)}
    return None


def _plane_quat(g: Plane, pose: Pose) -> list[float] | None:
    """A plane geom's orientation when its normal is not +z (MuJoCo's planes face +z): the collision's
    own rotation times the one taking +z to the normal; None for a +z (or zero) normal."""
    n = np.asarray(g.normal, dtype=float)
    if not (np.linalg.norm(n) > 0 and not np.allclose(n / np.linalg.norm(n), [0, 0, 1])):
        return None
    z = np.array([0.0, 0.0, 1.0])
    n = n / np.linalg.norm(n)
    axis = np.cross(z, n)
    ang = math.atan2(np.linalg.norm(axis), float(np.dot(z, n)))
    if np.linalg.norm(axis) <= 1e-12:
        return None
    axis = axis / np.linalg.norm(axis)
    q = [math.cos(ang / 2), *(axis * math.sin(ang / 2))]
    qq = np.zeros(4)
    mujoco.mju_mulQuat(qq, np.asarray(pose.orientation, dtype=float), np.asarray(q))
    return list(qq)


def _mesh_shape(
    spec: mujoco.MjSpec,
    col: Collision,
    g: Mesh,
    piece_names: list[str],
    decomposed: list[tuple[str, int, float, str]] | None,
) -> dict[str, Any] | None:
    """A collision mesh's geom fields: the mesh itself if convex, else its convex parts' meshes appended
    to ``piece_names`` (one geom each). None, with a warning naming it, for a mesh that cannot be found
    or read: gz-sim loads a world whose mesh fails to load without that geometry (gz-sim's MeshManager
    logs the failure and the collision has no shape); a missing construction barrel mesh must not kill a
    whole house world."""
    where = f"{col.location}: " if col.location is not None else ""
    if g.path is None:
        _log.warning(f"{where}collision '{col.name}': mesh '{g.uri}' could not be resolved; it is left out")
        return None
    try:
        parts = collision_parts(g.path, g.scale)
    except MeshReadError as err:
        _log.warning(f"{where}collision '{col.name}': {err}; it is left out")
        return None
    if parts is None:  # convex: the mesh itself
        vertices, faces = _load_mesh(g.path)
        mesh = _shared_mesh(spec, "collision", vertices * np.asarray(g.scale), faces)
        return {"type": mujoco.mjtGeom.mjGEOM_MESH, "meshname": mesh.name}
    for piece in parts.pieces:  # not convex: one geom per convex part (see _convex)
        piece_names.append(_shared_mesh(spec, "collision", np.asarray(piece, dtype=float)).name)
    if decomposed is not None:
        decomposed.append((g.path, len(piece_names), parts.seconds, parts.source))
    return {"type": mujoco.mjtGeom.mjGEOM_MESH}


def _contact_settings(col: Collision, mass_hint: float, timestep: float, moving: bool) -> dict[str, Any]:
    """A collision's contact fields: stiffness from its surface, torsional friction, collide bitmask."""
    settings: dict[str, Any] = {}
    solref = _solref_from_surface(col, mass_hint, timestep, moving=moving)
    if solref is not None:
        settings["solref"], settings["solimp"] = solref
    surface = col.surface
    # MuJoCo uses torsional friction from condim 4
    if surface.torsional:
        settings["condim"] = 4
    # Gazebo collides two shapes when (bitmask1 & bitmask2) != 0, default 0xffff; MuJoCo when
    # (contype1 & conaffinity2) | (contype2 & conaffinity1): both fields = the bitmask is the same rule.
    mask = surface.collide_bitmask if surface.collide_bitmask is not None else DEFAULT_COLLIDE_BITMASK
    settings["contype"] = settings["conaffinity"] = int(mask) & 0xFFFFFFFF
    return settings


def _add_geom(
    spec: mujoco.MjSpec,
    body: mujoco.MjsBody,
    col: Collision,
    name: str,
    mass_hint: float,
    decomposed: list[tuple[str, int, float, str]] | None = None,
    *,
    group: int = 3,
    rgba: tuple[float, float, float, float] | None = None,
    moving: bool = True,
) -> None:
    g = col.geometry
    piece_names: list[str] = []
    """MuJoCo meshes of a non-convex mesh's convex parts (one geom each); empty otherwise."""
    kwargs: dict = {
        "name": name,
        "pos": list(col.pose.position),
        "quat": list(col.pose.orientation),
        "friction": (friction := _surface_friction(col)),
        "priority": friction_priority(friction[0]),
        "group": group,
    }
    if rgba is not None:
        kwargs["rgba"] = list(rgba)
    primitive = _primitive(g)
    if primitive is not None:
        kwargs.update(primitive)
    elif isinstance(g, Plane):
        kwargs.update(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[g.size[0] / 2, g.size[1] / 2, 1.0])
        quat = _plane_quat(g, col.pose)
        if quat is not None:
            kwargs["quat"] = quat
    elif isinstance(g, Cone):
        mesh = _shared_mesh(spec, "collision", cone_vertices(g.radius, g.length))
        kwargs.update(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=mesh.name)
    elif isinstance(g, Mesh):
        shape = _mesh_shape(spec, col, g, piece_names, decomposed)
        if shape is None:
            return
        kwargs.update(shape)
    else:  # pragma: no cover - the union is closed
        raise BuildError(f"collision '{col.name}': unsupported geometry {type(g).__name__}")
    kwargs.update(_contact_settings(col, mass_hint, spec.option.timestep, moving))
    if piece_names:
        for i, mesh_name in enumerate(piece_names):
            body.add_geom(**{**kwargs, "name": f"{name}/{i}", "meshname": mesh_name})
        return
    body.add_geom(**kwargs)


VISUAL_GROUP = 1
"""MuJoCo geom group of visual geoms."""
COLLISION_GROUP = 3
"""Collision geoms of an entity whose visuals are in the model: cameras do not draw them."""
SHOWN_COLLISION_GROUP = 2
"""Collision geoms of an entity without visuals in the model: cameras draw them (in the colour of the
link's first visual), so props look as they should without the cost of their visual meshes."""


def _add_visual_geom(spec: mujoco.MjSpec, body: mujoco.MjsBody, vis: Visual, name: str) -> bool:
    """Add a link's visual as a geom that never collides and has no mass, so a camera renders what
    users see (collision shapes are often simpler). Returns False when its mesh cannot be read
    (the description already warned about a missing one)."""
    g = vis.geometry
    kwargs: dict = {
        "name": name,
        "pos": list(vis.pose.position),
        "quat": list(vis.pose.orientation),
        "group": VISUAL_GROUP,
        "contype": 0,
        "conaffinity": 0,
        "density": 0.0,
    }
    rgba = vis.material.diffuse if vis.material is not None and vis.material.diffuse is not None else None
    if rgba is not None:
        kwargs["rgba"] = list(rgba)
    primitive = _primitive(g)
    if primitive is not None:
        kwargs.update(primitive)
    elif isinstance(g, Plane):
        return False  # an infinite visual plane is the collision plane's look: nothing to add
    elif isinstance(g, (Cone, Mesh)):
        if isinstance(g, Cone):
            vertices, faces, scale = cone_vertices(g.radius, g.length), None, (1.0, 1.0, 1.0)
        else:
            if g.path is None:
                return False
            try:
                vertices, faces = _load_mesh(g.path)
            except (MeshReadError, BuildError) as err:
                _log.warning(f"visual '{vis.name}': {err}; it is not in the physics model (cameras will not see it)")
                return False
            scale = tuple(g.scale)
        look = load_mesh_look(g.path) if isinstance(g, Mesh) and g.path is not None and vis.material is None else None
        texcoord = None
        if look is not None and look.image is not None and look.uv is not None:
            texcoord = np.array(look.uv, dtype=float)
            texcoord[:, 1] = 1.0 - texcoord[:, 1]  # MuJoCo's images start at their top row, the file's v at the bottom
        mesh = _shared_mesh(spec, "visual", np.asarray(vertices, dtype=float) * np.asarray(scale), faces, texcoord)
        kwargs.update(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=mesh.name)
        if look is not None:
            _use_mesh_look(spec, look, name, kwargs)
    else:  # pragma: no cover - the union is closed
        return False
    body.add_geom(**kwargs)
    return True


SHARED_MESH = "mesh" + SEP
"""Meshes are named by their content, so every entity with the same mesh uses one copy (20 arms, one set
of arm meshes); a mesh leaves the model with the last geom that uses it (see PhysicsWorld)."""


def _shared_mesh(
    spec: mujoco.MjSpec,
    kind: str,
    vertices: np.ndarray,
    faces: np.ndarray | None = None,
    texcoord: np.ndarray | None = None,
) -> mujoco.MjsMesh:
    """The spec's mesh with these vertices (and faces, texture coordinates), added if it is not there yet.
    ``kind`` ("collision", "visual") keeps meshes MuJoCo processes differently apart."""
    verts = np.ascontiguousarray(vertices, dtype=float)
    digest = hashlib.sha256(kind.encode())
    digest.update(verts.tobytes())
    for extra in (faces, texcoord):
        digest.update(b"|" + (np.ascontiguousarray(extra).tobytes() if extra is not None else b""))
    name = f"{SHARED_MESH}{digest.hexdigest()[:24]}"
    mesh = spec.mesh(name)
    if mesh is None:
        mesh = spec.add_mesh(name=name)
        mesh.uservert = list(verts.ravel())
        if faces is not None:
            mesh.userface = list(np.asarray(faces).ravel())
        if texcoord is not None:
            mesh.usertexcoord = list(np.asarray(texcoord, dtype=float).ravel())
        if kind == "visual":
            mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL  # open visual meshes have no volume
    return mesh


def _use_mesh_look(spec: mujoco.MjSpec, look: MeshLook, name: str, kwargs: dict) -> None:
    """A visual mesh without an SDF/URDF ``<material>`` looks as its file says (``look``): its texture
    (COLLADA, OBJ; the mesh carries the texture coordinates), else its material's colour. With a
    ``<material>``, that one is used instead, as gz-sim does (``src/rendering/SceneManager.cc``: the
    visual's material is set on the geometry; a mesh without one keeps its own submeshes' materials)."""
    if look.image is not None and look.uv is not None:
        h, w = look.image.shape[:2]
        tex = spec.add_texture(name=f"{name}__tex", type=mujoco.mjtTexture.mjTEXTURE_2D, width=w, height=h, nchannel=3)
        tex.data = look.image.tobytes()
        material = spec.add_material(name=f"{name}__mat", rgba=[1.0, 1.0, 1.0, 1.0])
        material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = tex.name
        kwargs["material"] = material.name
        kwargs.pop("rgba", None)
    elif look.rgba is not None:
        kwargs["rgba"] = list(look.rgba)


CONE_SEGMENTS = 32


def cone_vertices(radius: float, length: float, segments: int = CONE_SEGMENTS) -> np.ndarray:
    """Vertices of a cone (base ring at z = -length/2, apex at +length/2); MuJoCo takes their hull."""
    a = np.linspace(0.0, 2.0 * math.pi, segments, endpoint=False)
    ring = np.column_stack([radius * np.cos(a), radius * np.sin(a), np.full(segments, -length / 2.0)])
    return np.vstack([ring, [[0.0, 0.0, length / 2.0]]])


DEFAULT_COLLIDE_BITMASK = 0xFFFF
"""Gazebo's default ``collide_bitmask``."""

_NOT_SIMULATED = {
    "fdir1": "fdir1",
    "slip1": "slip1",
    "slip2": "slip2",
    "kd": "kd",
    "min_depth": "min_depth",
    "max_vel": "max_vel",
    "soft_cfm": "soft_cfm",
    "soft_erp": "soft_erp",
    "restitution": "restitution",
    # Only the Bullet engines read <bullet><rolling_friction>: gz-physics' dartsim plugin (gz-sim's default
    # engine) warns "DART doesn't support rolling friction setting" and drops it
    # (dartsim/src/SimulationFeatures.cc), Classic's ODE reads only <ode>. gz-sim's diff_drive.sdf gives its
    # wheels 0.1, which applied here held vehicle_blue to 0.43 m/s for 0.5.
    "rolling": "rolling_friction",
}
"""Surface fields gazelle does not apply: field name -> the SDF element a warning names."""


def unsimulated_surface_parameters(col: Collision) -> list[str]:
    """The contact parameters a collision sets that gazelle does not honour (see docs/contact_parameters.md)."""
    return [element for field, element in _NOT_SIMULATED.items() if getattr(col.surface, field) is not None]


def _load_mesh(path: str) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (metres) and faces of a mesh file; MuJoCo collides with their convex hull."""
    try:
        verts, faces = load_mesh(path)
    except MeshReadError as err:
        raise BuildError(str(err)) from err
    if len(verts) < 4:
        raise BuildError(f"mesh '{path}' has fewer than 4 vertices")
    return verts, faces


def _set_inertial(body: mujoco.MjsBody, link: Link) -> None:
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
    """One MuJoCo joint of a description's joint: its limits, damping, friction, spring and effort limit."""
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
        pitch = joint.screw_thread_pitch or 1.0
        eq = spec.add_equality(
            name=name + "#screw",
            type=mujoco.mjtEq.mjEQ_JOINT,
            name1=name + "#slide",
            name2=name,
            data=[0, 1.0 / (2 * math.pi * pitch) if pitch else 0, 0, 0, 0] + [0] * 6,
        )
        del eq
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
            _add_visual_geom(spec, body, vis, scoped(built.name, f"{link.name}::{vis.name or 'visual'}#v{i}"))
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
            _add_visual_geom(spec, body, vis, scoped(entity, f"{link_name}::{vis.name or 'visual'}#v{i}"))
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
        visuals = self.visuals
        mass_hint = link.inertial.mass if link.inertial else self.total_mass
        colour = next(
            (v.material.diffuse for v in link.visuals if v.material is not None and v.material.diffuse is not None),
            None,
        )
        for i, col in enumerate(link.collisions):
            _add_geom(
                self.spec,
                body,
                col,
                scoped(self.entity, f"{link.name}::{col.name or 'collision'}#{i}"),
                mass_hint,
                self.decomposed,
                group=COLLISION_GROUP if visuals else SHOWN_COLLISION_GROUP,
                rgba=None if visuals else colour,
                moving=not self.model.static,
            )
            for param in unsimulated_surface_parameters(col):
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

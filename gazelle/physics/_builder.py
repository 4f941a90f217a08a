"""Turn description objects into MuJoCo ``MjSpec`` bodies. Never sees XML.

Naming: every MuJoCo element of an entity is prefixed ``<entity>::``, e.g. the
link ``base_link`` of entity ``robot`` is the body ``robot::base_link`` and its
joint ``wheel`` the joint ``robot::wheel``. Links with a fixed joint become
separate welded bodies (never lumped), so every link frame stays addressable.

A model's links become bodies and its joints dofs in ``_bodies.py`` (:func:`add_model`); here the
shapes: collision geoms with their contact parameters, meshes (convex parts, shared between entities) and visuals.
"""

from __future__ import annotations

import hashlib
import logging
import math
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from .. import description as desc
from .._errors import SimError
from ..description import (
    Collision,
    Cone,
    Geometry,
    Mesh,
    MeshLook,
    MeshReadError,
    Plane,
    Pose,
    Visual,
    load_mesh,
    load_mesh_look,
)
from ._contact_pairs import ContactProxy, anisotropic_friction
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
"""rad (m) each way around a joint whose lower and upper limits are equal (see ``_bodies._add_joint_dofs``)."""
KINEMATIC_ARMATURE = 1e8
"""Armature of the dofs above a kinematic link (kg·m² or kg): contacts see an immovable obstacle."""


class BuildError(SimError):
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
    contact_proxies: list[ContactProxy] = field(default_factory=list)
    """Its collisions with anisotropic friction on planes (see ``_contact_pairs``)."""


def friction_priority(mu: float) -> int:
    """MuJoCo combines the friction of two geoms by taking the larger; ODE/Gazebo take the smaller.

    MuJoCo uses the parameters of the geom with the higher ``priority`` instead, so
    giving slippery geoms a higher priority reproduces ODE's min(mu1, mu2) rule.
    """
    mu = max(mu, 0.0)
    return int(max(0, min(100, round(40 - 20 * math.log10(mu + 1e-2)))))


def _surface_friction(col: Collision) -> list[float]:
    """MuJoCo's friction triple (sliding, torsional, rolling) of a collision: sliding is ODE's ``<mu>`` (1 by
    default, as SDF's), or the smaller of ``<mu>`` and ``<mu2>`` when both are given, since a MuJoCo geom's sliding
    friction is isotropic (anisotropic contacts with planes are pairs: ``_contact_pairs``); torsional is
    ``<torsional><coefficient>`` (a small default keeps a wheel from spinning in place on a point contact); a
    frictionless surface gets none of the three."""
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


def _primitive(g: Geometry) -> dict | None:
    """MuJoCo ``type`` and ``size`` of a box, cylinder, sphere, capsule or ellipsoid; None for the shapes
    MuJoCo builds from a mesh (cone, mesh) or a plane. MuJoCo's sizes are half sizes: a box's half extents,
    a cylinder's and a capsule's half length (the capsule's without its caps, as SDF's ``<length>``)."""
    G = mujoco.mjtGeom
    match g:
        case desc.Box(size=size):
            return {"type": G.mjGEOM_BOX, "size": [size[0] / 2, size[1] / 2, size[2] / 2]}
        case desc.Cylinder(radius=r, length=length):
            return {"type": G.mjGEOM_CYLINDER, "size": [r, length / 2, 0]}
        case desc.Sphere(radius=r):
            return {"type": G.mjGEOM_SPHERE, "size": [r, 0, 0]}
        case desc.Capsule(radius=r, length=length):
            return {"type": G.mjGEOM_CAPSULE, "size": [r, length / 2, 0]}
        case desc.Ellipsoid(radii=radii):
            return {"type": G.mjGEOM_ELLIPSOID, "size": list(radii)}
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
    moving: bool = True,
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
        parts = collision_parts(g.path, g.scale, static=not moving)
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


def _placed_geom(name: str, pose: Pose, rgba: tuple[float, ...] | None, **fields: Any) -> dict[str, Any]:
    """The MuJoCo fields of a geom named ``name`` at ``pose`` in its body, in colour ``rgba`` (None: MuJoCo's
    default), with ``fields`` added (its group, contact settings, ...): the shape is the caller's to add."""
    kwargs: dict[str, Any] = {"name": name, "pos": list(pose.position), "quat": list(pose.orientation), **fields}
    if rgba is not None:
        kwargs["rgba"] = list(rgba)
    return kwargs


def add_geom(
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
    """Add a collision as geoms of ``body``: a primitive as itself, a plane rotated to its normal, a cone as a mesh,
    a mesh as its convex hull or, when it is far from convex, its convex parts (one geom each, decomposed or read
    from the cache); with its friction, contact stiffness (from ``<kp>`` and ``mass_hint``) and collide bitmask.
    A mesh that cannot be read adds nothing (the description warned)."""
    g = col.geometry
    piece_names: list[str] = []
    """MuJoCo meshes of a non-convex mesh's convex parts (one geom each); empty otherwise."""
    friction = _surface_friction(col)
    kwargs = _placed_geom(name, col.pose, rgba, friction=friction, priority=friction_priority(friction[0]), group=group)
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
        shape = _mesh_shape(spec, col, g, piece_names, decomposed, moving)
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


def add_visual_geom(spec: mujoco.MjSpec, body: mujoco.MjsBody, vis: Visual, name: str) -> bool:
    """Add a link's visual as a geom that never collides and has no mass, so a camera renders what
    users see (collision shapes are often simpler). Returns False when its mesh cannot be read
    (the description already warned about a missing one)."""
    g = vis.geometry
    rgba = vis.material.diffuse if vis.material is not None and vis.material.diffuse is not None else None
    # never in a contact (contype = conaffinity = 0) and no mass (density 0): the look only
    kwargs = _placed_geom(name, vis.pose, rgba, group=VISUAL_GROUP, contype=0, conaffinity=0, density=0.0)
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
    "fdir1": "fdir1",  # where no contact proxy applies it (see unsimulated_surface_parameters)
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


def unsimulated_surface_parameters(col: Collision, *, anisotropic: bool = False) -> list[str]:
    """The contact parameters a collision sets that gazelle does not honour (see docs/contact_parameters.md).
    ``<fdir1>`` counts only where it matters (``mu`` ≠ ``mu2``) and is not applied (``anisotropic`` False: no
    contact proxy, see ``_contact_pairs``)."""
    skip = "fdir1" if anisotropic or anisotropic_friction(col.surface) is None else ""
    given = {field for field in _NOT_SIMULATED if field != skip and getattr(col.surface, field) is not None}
    return [element for field, element in _NOT_SIMULATED.items() if field in given]


def _load_mesh(path: str) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (metres) and faces of a mesh file; MuJoCo collides with their convex hull."""
    try:
        verts, faces = load_mesh(path)
    except MeshReadError as err:
        raise BuildError(str(err)) from err
    if len(verts) < 4:
        raise BuildError(f"mesh '{path}' has fewer than 4 vertices")
    return verts, faces

"""The SDF loader's parts of a model: links (inertials, shapes, surfaces, materials, sensors), joints
with their axes, and lights; free functions over a :class:`~._sdf_reader.Workspace`.

Poses. SDF places every link, joint, collision, visual and sensor by a ``<pose relative_to=...>``
(SDF 1.7+; before it, links in the model frame and the rest in their link's). The model's frame
graph (:class:`~._sdf_frames.Scope`) resolves each to the model frame first (``X_M*``); this module
then expresses what the typed model keeps in the frame it is kept in: a collision's pose in its link
(``X_LG``), a joint's origin in its parent link (``X_PJ``) and its child's frame in the joint
(``X_JC``, identity in URDF, not in SDF, where a joint's frame is placed in its child by default).

Defaults. An element left out takes SDFormat's default (its ``sdf/1.x/*.sdf`` description files), as
Gazebo does: a link without ``<inertial>`` weighs 1 kg with unit inertia; a box is 1 m, a cylinder
of radius 1 and length 1, a capsule of radius 0.5. A value that cannot be read is an error or a
warning naming file:line, never a silent default.
"""

from __future__ import annotations

import math
import os
from dataclasses import replace

from lxml import etree

from ._colors import GAZEBO_COLORS
from ._diagnostics import ErrorCode, SourceLocation
from ._fuel import cache_roots, cached_file, parse_fuel_uri
from ._inertia import default_inertial, inertia_from_geometries, inertia_problem
from ._model import (
    Box,
    Capsule,
    Collision,
    Cone,
    Cylinder,
    Ellipsoid,
    Geometry,
    Inertial,
    Joint,
    JointAxis,
    JointDynamics,
    JointLimit,
    JointType,
    Light,
    Link,
    Material,
    Mesh,
    Mimic,
    Plane,
    Sensor,
    Sphere,
    Surface,
    Visual,
)
from ._pose import IDENTITY, Pose, quat_conj, quat_rotate
from ._resources import classic_model_advice
from ._sdf_frames import Scope
from ._sdf_reader import (
    _AXIS_JOINTS,
    _JOINT_TYPES,
    _UNLIMITED,
    Workspace,
    _Built,
    _Doc,
    _find,
    _findall,
    _tag,
    check_children,
    child_text,
    location_of,
    read_color,
    read_config,
    read_flag,
    read_name,
    read_number,
    read_opt_number,
    read_plugin,
    read_pose,
    read_unique_name,
    read_vec3,
    read_vector,
    resolve_uri,
    warn_extra,
    warn_unsupported,
)
from ._xml import (
    child_elements,
    parse_bool,
    parse_float,
)

# Links, joints and lights: the elements a model and a world are made of.


# ================================================================== links
def read_shapes(
    ws: Workspace, link: etree._Element, doc: _Doc, tag: str, link_name: str
) -> list[tuple[etree._Element, str, Geometry]]:
    """The link's ``<collision>`` or ``<visual>`` elements (``tag``) that have a name, used once in the
    link, and a geometry, as (element, name, geometry); the others are reported and left out.

    sdformat requires both: a collision or visual is named, and names are unique among its siblings,
    because Gazebo addresses them by ``model::link::name`` (contact sensors, the viewer's selection, a
    ``<contact><collision>`` list); a second one of a name would be unreachable, so it is an error."""
    out: list[tuple[etree._Element, str, Geometry]] = []
    seen: set[str] = set()
    for el in _findall(link, tag):
        name = read_unique_name(ws, el, doc, seen, f"{tag} name", f"link '{link_name}'")
        if name is None:
            continue
        check_children(ws, el, doc, tag)
        geometry = read_geometry(ws, el, doc)
        if geometry is not None:
            out.append((el, name, geometry))
    return out


def read_link(ws: Workspace, name: str, element: etree._Element, doc: _Doc, scope: Scope) -> Link | None:
    """A ``<link>`` with its shapes, sensors and mass, every pose in the link's frame; None when its
    own pose cannot be resolved (the frame graph reported why).

    The typed model keeps a link's parts in the link's frame, as MuJoCo places a body's geoms, so each
    part's ``<pose relative_to=...>`` is turned into the link frame here once (``X_LM · X_MR · pose``);
    the frame graph (SDF 1.7+) already knows where every named frame is in the model. ``<self_collide>``
    left out of the link stays unset, so that the model's value applies, which is gz-sim's rule."""
    loc = location_of(element, doc)
    check_children(ws, element, doc, "link")
    X_ML = scope.pose(name, loc)
    if X_ML is None:
        return None
    X_LM = X_ML.inverse()

    def local_pose(el: etree._Element) -> Pose:
        # a child's <pose> is in its link unless relative_to names another frame: X_LR * X_RG
        pose, rel = read_pose(ws, el, doc)
        if rel is None or rel == name:
            return pose
        X_MR = scope.pose(rel, location_of(el, doc))
        return pose if X_MR is None else X_LM * X_MR * pose

    collisions = [
        Collision(n, local_pose(el), g, read_surface(ws, _find(el, "surface"), doc), location_of(el, doc))
        for el, n, g in read_shapes(ws, element, doc, "collision", name)
    ]
    visuals = [
        Visual(n, local_pose(el), g, read_material(ws, _find(el, "material"), doc), location_of(el, doc))
        for el, n, g in read_shapes(ws, element, doc, "visual", name)
    ]
    sensors: list[Sensor] = []
    for sen_el in _findall(element, "sensor"):
        sensor = read_sensor(ws, sen_el, doc, local_pose(sen_el))
        if sensor is not None:
            sensors.append(sensor)
    inertial = read_inertial(
        ws, name, _find(element, "inertial"), doc, [(c.pose, c.geometry) for c in collisions], local_pose
    )
    self_collide = None  # unset: the model's <self_collide> decides (gz-sim's rule)
    if _find(element, "self_collide") is not None:
        self_collide = read_flag(ws, element, "self_collide", False, doc)
    return Link(
        name=name,
        inertial=inertial,
        visuals=tuple(visuals),
        collisions=tuple(collisions),
        sensors=tuple(sensors),
        gravity=read_flag(ws, element, "gravity", True, doc),
        kinematic=read_flag(ws, element, "kinematic", False, doc),
        self_collide=self_collide,
        pose=X_ML,
        location=loc,
    )


def read_inertial(ws: Workspace, link: str, element: etree._Element | None, doc: _Doc, shapes, local_pose) -> Inertial:
    """Mass properties: as written when valid, else derived from the collision shapes.

    No ``<inertial>`` means SDF's default (1 kg, unit inertia), as in Gazebo. A nested
    ``<inertial>`` (a common slip) is reported and its values used as the author meant.
    """
    if element is None:  # sdf/1.x/inertial.sdf: <mass> 1, <inertia> the identity
        return Inertial(mass=1.0, ixx=1.0, iyy=1.0, izz=1.0)
    check_children(ws, element, doc, "inertial")
    loc = location_of(element, doc)
    inner = _find(element, "inertial")
    source_el = element
    if inner is not None:
        ws.sink.warning(
            ErrorCode.INERTIAL_NESTED,
            f"link '{link}': <inertial> nested inside <inertial>; using its values as the outer inertial's",
            location_of(inner, doc),
        )
        source_el = inner
    pose_el = element if _find(element, "pose") is not None else source_el
    pose = local_pose(pose_el)
    # SDF 1.11's <inertial auto="true">: mass and inertia from the collisions (with <density>, 1000 kg/m³
    # by default), or the inertia alone when a <mass> is given
    auto = parse_bool(element.get("auto") or "false") is True
    mass_el = element if _find(element, "mass") is not None else source_el
    mass_child = _find(mass_el, "mass")
    mass: float | None = 1.0
    if mass_child is not None:
        mass = parse_float(mass_child.text)
        if mass is None or mass <= 0:
            ws.sink.warning(
                ErrorCode.MASS_INVALID,
                f"link '{link}': mass must be a positive number, got {(mass_child.text or '').strip()!r}; "
                "deriving mass and inertia from the collision geometry",
                location_of(mass_child, doc),
            )
            mass = None
    elif auto:
        mass = None
    if mass is None:
        return derive_inertial(shapes, None)
    if auto:
        return derive_inertial(shapes, mass)
    inertia_el = _find(source_el, "inertia")
    if inertia_el is None and inner is not None:
        inertia_el = inner  # the components sit directly in the nested <inertial>
    if inertia_el is None:
        ws.sink.warning(
            ErrorCode.INERTIA_MISSING,
            f"link '{link}': <inertial> has no <inertia>; deriving it from the collision geometry and mass {mass:g} kg",
            loc,
        )
        return derive_inertial(shapes, mass)
    values = {}
    for key, default in (("ixx", 1.0), ("ixy", 0.0), ("ixz", 0.0), ("iyy", 1.0), ("iyz", 0.0), ("izz", 1.0)):
        child = _find(inertia_el, key)
        value = default if child is None else parse_float(child.text)
        if value is None and child is not None:
            ws.sink.warning(
                ErrorCode.INERTIA_INVALID,
                f"link '{link}': <{key}> must be a number, got {(child.text or '').strip()!r}; "
                "deriving the inertia from the collision geometry",
                location_of(child, doc),
            )
            return derive_inertial(shapes, mass)
        values[key] = value
    # a tensor that is not positive definite, or breaks the triangle inequality, would make MuJoCo
    # refuse the model or the body spin off: derive one instead, and say so
    problem = inertia_problem(**values)
    if problem is not None:
        ws.sink.warning(
            ErrorCode.INERTIA_INVALID,
            f"link '{link}': {problem}; deriving it from the collision geometry",
            location_of(inertia_el, doc),
        )
        return derive_inertial(shapes, mass)
    return Inertial(mass=mass, pose=pose, **values)


def read_geometry(ws: Workspace, owner: etree._Element, doc: _Doc) -> Geometry | None:
    """The one shape in ``owner``'s ``<geometry>``, with SDFormat's default dimensions for those left out;
    None (reported) when it is missing, empty, of non-positive size or of an unsupported kind
    (heightmap, polyline), and silently for ``<empty/>``."""
    element = _find(owner, "geometry")
    owner_loc = location_of(owner, doc)
    if element is None:
        ws.sink.error(ErrorCode.ELEMENT_MISSING, f"<{_tag(owner)}> '{owner.get('name')}' has no <geometry>", owner_loc)
        return None
    shapes = [c for c in child_elements(element) if ":" not in _tag(c)]  # a prefixed tag is a custom element
    if not shapes:
        ws.sink.error(ErrorCode.ELEMENT_MISSING, "<geometry> is empty", location_of(element, doc))
        return None
    shape = shapes[0]
    kind = _tag(shape)
    loc = location_of(shape, doc)
    for extra in shapes[1:]:
        warn_extra(ws, extra, doc, "a <geometry> holds one shape")

    def positive(*values: float) -> bool:
        if all(v > 0 for v in values):
            return True
        ws.sink.error(ErrorCode.GEOMETRY_INVALID, f"<{kind}> dimensions must be positive, got {values}", loc)
        return False

    if kind == "box":
        size = read_vec3(ws, shape, "size", (1.0, 1.0, 1.0), doc)
        return Box(size) if positive(*size) else None
    if kind in ("cylinder", "capsule"):
        default_r = 1.0 if kind == "cylinder" else 0.5  # sdf/1.9/cylinder.sdf and capsule.sdf
        radius = read_number(ws, shape, "radius", default_r, doc)
        length = read_number(ws, shape, "length", 1.0, doc)
        if not positive(radius, length):
            return None
        return Cylinder(radius, length) if kind == "cylinder" else Capsule(radius, length)
    if kind == "cone":  # SDF 1.11
        radius = read_number(ws, shape, "radius", 1.0, doc)
        length = read_number(ws, shape, "length", 1.0, doc)
        return Cone(radius, length) if positive(radius, length) else None
    if kind == "sphere":
        radius = read_number(ws, shape, "radius", 1.0, doc)
        return Sphere(radius) if positive(radius) else None
    if kind == "ellipsoid":
        radii = read_vec3(ws, shape, "radii", (1.0, 1.0, 1.0), doc)
        return Ellipsoid(radii) if positive(*radii) else None
    if kind == "plane":
        return read_plane(ws, shape, doc, loc)
    if kind == "mesh":
        return read_mesh(ws, shape, doc, loc)
    if kind == "empty":
        return None
    ws.sink.warning(
        ErrorCode.ELEMENT_UNSUPPORTED,
        f"geometry <{kind}> is not supported; the shape is skipped, so as a <collision> it collides with "
        "nothing (supported: box, cylinder, sphere, capsule, cone, ellipsoid, plane, mesh)",
        loc,
    )
    return None


def read_plane(ws: Workspace, shape: etree._Element, doc: _Doc, loc: SourceLocation) -> Plane | None:
    """<plane>: its normal made a unit vector (an error if it has no length) and its size."""
    normal = read_vec3(ws, shape, "normal", (0.0, 0.0, 1.0), doc)
    size = read_vector(ws, shape, "size", 2, Plane().size, doc) or Plane().size
    n = math.sqrt(sum(v * v for v in normal))
    if n < 1e-12:
        ws.sink.error(ErrorCode.GEOMETRY_INVALID, "<plane> normal has zero length", loc)
        return None
    return Plane((normal[0] / n, normal[1] / n, normal[2] / n), (size[0], size[1]))


def read_mesh(ws: Workspace, shape: etree._Element, doc: _Doc, loc: SourceLocation) -> Mesh | None:
    """<mesh>: its file found on the resource roots (a mesh not found, or outside them, is kept without
    a path, with a warning: the shape is then left out where it is built), its scale; <submesh> and
    the other children are warned about."""
    for child in child_elements(shape):
        if _tag(child) not in ("uri", "scale") and ":" not in _tag(child):
            warn_unsupported(ws, child, doc, "mesh")
    uri = child_text(shape, "uri")
    if not uri:
        ws.sink.error(ErrorCode.ELEMENT_MISSING, "<mesh> has no <uri>", loc)
        return None
    scale = read_vec3(ws, shape, "scale", (1.0, 1.0, 1.0), doc)
    # model://, package://, file:// and plain paths are files on the resource roots; a Fuel model's file
    # (https://fuel.../<owner>/models/<name>/<version>/files/<path>) is read from Gazebo's local Fuel cache, as
    # gz-sim's find-file callback reads it (FuelClient::CachedModelFile); nothing is ever downloaded
    fuel = parse_fuel_uri(uri)
    in_cache = cached_file(fuel, cache_roots()) if fuel is not None else None
    if in_cache is not None:
        ws.resolver = ws.resolver.trusting(in_cache[0])  # the user's own Gazebo cache
        return Mesh(uri, str(in_cache[1]), scale)
    path = (
        resolve_uri(ws, uri, doc)
        if ("://" not in uri or uri.startswith(("model://", "package://", "file://")))
        else None
    )
    name = uri.strip()[len("model://") :].partition("/")[0] if uri.strip().startswith("model://") else None
    if path is None and name and ws.resolver.find_package(name) is None and ws.resolver.confined_out(name) is None:
        # a model found nowhere (a Classic world saved with the online database's models inlined): one error line
        # per model saying how to get it, as gazebo's find_file would have fetched it (ModelDatabase)
        if name not in ws.missing_models:
            ws.missing_models.add(name)
            env = ws.resolver.env if ws.resolver.env is not None else os.environ
            ws.sink.skipped(ErrorCode.URI_UNRESOLVED, classic_model_advice(name, env), loc)
        return Mesh(uri, None, scale)
    if path is None or not path.is_file():
        why = f": {ws.resolver.unresolved_reason(uri, doc.base_dir)}" if path is None else ""
        ws.sink.warning(ErrorCode.MESH_NOT_FOUND, f"mesh '{uri}' not found{why}", loc)
        return Mesh(uri, None, scale)
    if not ws.resolver.allowed(path):
        ws.sink.warning(ErrorCode.URI_UNRESOLVED, f"mesh {ws.resolver.refusal(uri)}", loc)
        return Mesh(uri, None, scale)
    return Mesh(uri, str(path), scale)


def read_surface(ws: Workspace, element: etree._Element | None, doc: _Doc) -> Surface:
    """``<surface>``: friction (ODE's ``<mu>``/``<mu2>``, else Bullet's ``<friction>``/``<friction2>``),
    torsional friction, ODE's contact stiffness and the collide bitmask, with every other parameter
    kept so the physics can name what it does not simulate."""
    if element is None:
        return Surface()
    check_children(ws, element, doc, "surface")
    friction = _find(element, "friction")
    ode = bullet = torsional = None
    if friction is not None:
        check_children(ws, friction, doc, "friction")
        ode, bullet, torsional = _find(friction, "ode"), _find(friction, "bullet"), _find(friction, "torsional")
        if ode is not None:
            check_children(ws, ode, doc, "friction_ode", "ode")
        if bullet is not None:
            check_children(ws, bullet, doc, "bullet_friction", "bullet")
        if torsional is not None:
            check_children(ws, torsional, doc, "torsional")
    contact = _find(element, "contact")
    contact_ode = None
    if contact is not None:
        check_children(ws, contact, doc, "contact")
        contact_ode = _find(contact, "ode")
        if contact_ode is not None:
            check_children(ws, contact_ode, doc, "contact_ode", "ode")
    bounce = _find(element, "bounce")
    if bounce is not None:
        check_children(ws, bounce, doc, "bounce")
    mu = read_opt_number(ws, ode, "mu", doc)
    mu2 = read_opt_number(ws, ode, "mu2", doc)
    if mu is None:
        mu = read_opt_number(ws, bullet, "friction", doc)
    if mu2 is None:
        mu2 = read_opt_number(ws, bullet, "friction2", doc)
    bitmask = None  # None: Gazebo's default mask, 0xffff
    bitmask_el = _find(contact, "collide_bitmask") if contact is not None else None
    if contact is not None and bitmask_el is not None:
        raw = child_text(contact, "collide_bitmask") or ""
        try:
            bitmask = int(raw, 0)  # Gazebo's files write it in hex (0x01) as often as in decimal
        except ValueError:
            ws.sink.error(
                ErrorCode.VALUE_INVALID,
                f"<collide_bitmask> must be an integer, got {raw!r}",
                location_of(bitmask_el, doc),
            )
    without = _find(contact, "collide_without_contact") if contact is not None else None
    if without is not None and (without.text or "").strip().lower() in ("1", "true"):
        # gz-sim: the shape reports contacts but exerts no force. MuJoCo has no such geom: it takes
        # part in no contact (rays still see it), and contact sensors do not report it either.
        # The default (false) is what gazelle does anyway: read silently (a house world of gz-sim's
        # printed 54 warnings, one a model file, for that default)
        ws.sink.warning(
            ErrorCode.ELEMENT_UNSUPPORTED,
            "<collide_without_contact> true: this collision takes part in no contact at all (no force, "
            "and contact sensors do not report it)",
            location_of(without, doc),
        )
        bitmask = 0
    return Surface(
        mu=mu,
        mu2=mu2,
        fdir1=read_vec3(ws, ode, "fdir1", None, doc),
        slip1=read_opt_number(ws, ode, "slip1", doc),
        slip2=read_opt_number(ws, ode, "slip2", doc),
        torsional=read_opt_number(ws, torsional, "coefficient", doc),
        rolling=read_opt_number(ws, bullet, "rolling_friction", doc),
        kp=read_opt_number(ws, contact_ode, "kp", doc),
        kd=read_opt_number(ws, contact_ode, "kd", doc),
        min_depth=read_opt_number(ws, contact_ode, "min_depth", doc),
        max_vel=read_opt_number(ws, contact_ode, "max_vel", doc),
        soft_cfm=read_opt_number(ws, contact_ode, "soft_cfm", doc),
        soft_erp=read_opt_number(ws, contact_ode, "soft_erp", doc),
        restitution=read_opt_number(ws, bounce, "restitution_coefficient", doc),
        collide_bitmask=bitmask,
    )


def read_material(ws: Workspace, element: etree._Element | None, doc: _Doc) -> Material | None:
    """``<material>``: its colours, an OGRE ``<script><name>`` (Gazebo Classic's Gazebo/Grey and the like,
    kept by name) and a PBR albedo map as the texture, from whichever workflow (metal, specular) has one.

    Colours left out stay None rather than take SDF's defaults, so that a visual with only a Classic
    script gets the script's colour (:data:`GAZEBO_COLORS`, shared with the URDF reader) and a visual with
    no material at all the viewer's; the albedo map is the one texture a camera or the viewer can draw."""
    if element is None:
        return None
    check_children(ws, element, doc, "material")
    script = _find(element, "script")
    name = ""
    if script is not None:
        check_children(ws, script, doc, "script")
        name = child_text(script, "name") or ""
    texture = None
    pbr = _find(element, "pbr")
    if pbr is not None:
        for workflow in child_elements(pbr):
            texture = child_text(workflow, "albedo_map") or texture
    return Material(
        name=name,
        diffuse=read_color(ws, element, "diffuse", doc) or GAZEBO_COLORS.get(name),
        ambient=read_color(ws, element, "ambient", doc),
        specular=read_color(ws, element, "specular", doc),
        emissive=read_color(ws, element, "emissive", doc),
        texture=texture,
    )


def read_sensor(ws: Workspace, element: etree._Element, doc: _Doc, pose: Pose) -> Sensor | None:
    """A ``<sensor>`` at ``pose`` (in its link), kept whole for its sensor system to read its own block;
    None when it has no type or name (reported).

    The description layer reads only what every sensor has (type, name, rate, ``<always_on>``,
    ``<topic>``, plugins); the ``<camera>``, ``<ray>``, ``<imu>`` ... blocks go through as a read-only copy
    (:class:`ConfigElement`) to the sensor systems, which own their meaning and say what they do not
    read, each at its own line."""
    name = read_name(ws, element, doc)
    loc = location_of(element, doc)
    kind = (element.get("type") or "").strip()
    if not kind:
        ws.sink.error(ErrorCode.ATTRIBUTE_MISSING, f"<sensor> '{name}' is missing the required 'type' attribute", loc)
        return None
    if name is None:
        return None
    plugins = tuple(p for p in (read_plugin(ws, e, doc) for e in _findall(element, "plugin")) if p is not None)
    return Sensor(
        name=name,
        type=kind,
        pose=pose,
        update_rate_hz=read_number(ws, element, "update_rate", 0.0, doc),
        always_on=read_flag(ws, element, "always_on", False, doc),
        topic=child_text(element, "topic") or "",
        config=read_config(element, doc),
        plugins=plugins,
        location=loc,
    )


# ================================================================== joints
def read_joint(ws: Workspace, name: str, element: etree._Element, doc: _Doc, scope: Scope, built: _Built) -> None:
    """Add a ``<joint>`` to ``built``: its type, its parent and child (``world`` allowed as a parent), its
    frame (by default at the child's frame, SDF's rule) and its axes converted to the joint frame."""
    loc = location_of(element, doc)
    check_children(ws, element, doc, "joint")
    typed = _joint_type(ws, name, element, loc)
    ends = _joint_ends(ws, name, element, doc, scope, loc) if typed is not None else None
    if typed is None or ends is None:
        return
    raw_type, jtype = typed
    parent, child = ends
    X_MJ = scope.pose(name, loc)
    X_MC = scope.pose(child, loc)
    X_MP = IDENTITY if parent == "world" else scope.pose(parent, loc)
    if X_MJ is None or X_MC is None or X_MP is None:
        return
    axes = _joint_axes(ws, name, element, doc, scope, (raw_type, jtype), X_MJ, loc)
    mimic = None
    for entry in axes:
        if entry is not None and entry[1] is not None:
            mimic = entry[1]
    joint = Joint(
        name=name,
        type=jtype,
        parent=parent,
        child=child,
        # X_PJ = X_PM · X_MJ, and the child's frame in the joint's, X_JC = X_JM · X_MC
        origin=X_MJ if parent == "world" else X_MP.inverse() * X_MJ,
        child_offset=X_MJ.inverse() * X_MC,
        axis=axes[0][0] if axes[0] else None,
        axis2=axes[1][0] if axes[1] else None,
        screw_thread_pitch=_screw_pitch(ws, element, doc) if jtype is JointType.SCREW else None,
        mimic=mimic,
        location=loc,
    )
    if parent == "world":
        # a joint to the world pins (fixed) or guides the model in the world: kept by its pose in the model
        # frame, so the spawn can place it where the model is placed
        built.world_joints[name] = X_MJ
    built.joints.append(joint)
    for sen_el in _findall(element, "sensor"):  # force_torque: kept with the child link
        pose, _rel = read_pose(ws, sen_el, doc)  # in the joint frame
        sensor = read_sensor(ws, sen_el, doc, pose)
        if sensor is not None:
            built.joint_sensors.setdefault(child, []).append(replace(sensor, joint=name))


def _joint_type(ws: Workspace, name: str, element: etree._Element, loc: SourceLocation) -> tuple[str, JointType] | None:
    """(the SDF type as written, its JointType); None (an error or warning said why) if skipped."""
    raw_type = (element.get("type") or "").strip()
    if not raw_type:
        ws.sink.error(ErrorCode.ATTRIBUTE_MISSING, f"joint '{name}' is missing the required 'type' attribute", loc)
        return None
    if raw_type == "gearbox":
        # a gearbox couples two other joints' angles through a reference body: not built (skipped, and
        # said), so the two joints move independently
        ws.sink.warning(
            ErrorCode.JOINT_TYPE_INVALID, f"joint '{name}': type 'gearbox' is not supported; joint skipped", loc
        )
        return None
    jtype = _JOINT_TYPES.get(raw_type)
    if jtype is None:
        ws.sink.error(
            ErrorCode.JOINT_TYPE_INVALID,
            f"joint '{name}' has unknown type '{raw_type}' (expected one of {', '.join(sorted(_JOINT_TYPES))})",
            loc,
        )
        return None
    if raw_type == "revolute2":
        # revolute2 is two hinges in series like universal (axis on the parent, axis2 on the child); the
        # difference is in how ODE solved it, so it runs as a universal joint and the file is told
        ws.sink.warning(
            ErrorCode.JOINT_TYPE_INVALID,
            f"joint '{name}': type 'revolute2' is not supported; loaded as 'universal'",
            loc,
        )
    return raw_type, jtype


def _joint_ends(
    ws: Workspace, name: str, element: etree._Element, doc: _Doc, scope: Scope, loc: SourceLocation
) -> tuple[str, str] | None:
    """(parent, child) as bodies of the scope; None (an error said why) if either is missing or wrong.

    sdformat's rules: the child may not be ``world``, parent and child must differ (after frames are
    resolved to the links they are attached to), and a name must exist in the model's frame graph or a
    nested model. Each problem is an error at the ``<parent>`` or ``<child>`` line, and the joint is left
    out rather than attached to a guess."""
    ends = []
    for role, code in (("parent", ErrorCode.JOINT_PARENT_INVALID), ("child", ErrorCode.JOINT_CHILD_INVALID)):
        el = _find(element, role)
        ref = (el.text or "").strip() if el is not None else ""
        if el is None or not ref:
            ws.sink.error(ErrorCode.ELEMENT_MISSING, f"joint '{name}' has no <{role}>", loc)
            return None
        where = location_of(el, doc)
        # a parent or child may be a link, a frame (resolved to the link it is attached to: SDF 1.7's
        # frame semantics), a nested model's link written model::link, or (parent only) the world
        if ref == "world" or ref in scope.nodes or ("::" in ref and ref.partition("::")[0] in scope.nested):
            body = scope.body(ref, where)
        else:
            body = None
            ws.sink.error(code, f"joint '{name}' has unknown {role} '{ref}'", where)
        if body is None:
            return None
        if role == "child" and body == "world":
            ws.sink.error(code, f"joint '{name}': the child cannot be 'world'", where)
            return None
        ends.append(body)
    parent, child = ends
    if parent == child:
        ws.sink.error(
            ErrorCode.JOINT_CHILD_INVALID, f"joint '{name}': parent and child are the same link '{child}'", loc
        )
        return None
    return parent, child


def _joint_axes(
    ws: Workspace,
    name: str,
    element: etree._Element,
    doc: _Doc,
    scope: Scope,
    typed: tuple[str, JointType],
    X_MJ: Pose,
    loc: SourceLocation,
) -> list[tuple[JointAxis, Mimic | None] | None]:
    """[<axis>, <axis2>], each (JointAxis, mimic) or None where the type has no such axis; a missing
    <axis> is 0 0 1 (with a warning), a universal joint's missing <axis2> 0 1 0.

    ``0 0 1`` is SDF's default ``<xyz>`` for both axes (sdf/1.11/joint.sdf); for a universal joint two
    z axes would be the same axis twice, so gazelle takes y for the second, the usual cardan layout,
    rather than build a joint that cannot move in its second direction."""
    raw_type, jtype = typed
    axes: list[tuple[JointAxis, Mimic | None] | None] = []
    for axis_tag in ("axis", "axis2"):
        axis_el = _find(element, axis_tag)
        if axis_el is None or jtype not in _AXIS_JOINTS or (axis_tag == "axis2" and jtype is not JointType.UNIVERSAL):
            axes.append(None)
            continue
        axes.append(read_axis(ws, name, axis_el, doc, scope, X_MJ))
    # SDF's default axis is z, but a joint that moves without an <axis> is usually a slip: said, not silent
    if jtype in _AXIS_JOINTS and _find(element, "axis") is None:
        ws.sink.warning(ErrorCode.ELEMENT_MISSING, f"joint '{name}' ({raw_type}) has no <axis>; using 0 0 1", loc)
        axes[0] = (JointAxis((0.0, 0.0, 1.0)), None)
    if jtype is JointType.UNIVERSAL and axes[1] is None:
        axes[1] = (JointAxis((0.0, 1.0, 0.0)), None)
    return axes


def _screw_pitch(ws: Workspace, element: etree._Element, doc: _Doc) -> float | None:
    """A screw joint's pitch in metres along the axis per revolution: SDF 1.10's <screw_thread_pitch>
    (sdformat's joint.sdf, default 1), or the older <thread_pitch> converted. That one is in radians per
    metre with the other sign (Gazebo Classic's ODE screw: a positive thread_pitch advanced along -axis),
    so m/rev = -2π / thread_pitch; a zero one (no coupling) is None."""
    if _find(element, "screw_thread_pitch") is not None:
        return read_number(ws, element, "screw_thread_pitch", 1.0, doc)
    thread_pitch = read_number(ws, element, "thread_pitch", 1.0, doc)
    return -2 * math.pi / thread_pitch if thread_pitch != 0 else None


def read_axis(
    ws: Workspace, joint: str, element: etree._Element, doc: _Doc, scope: Scope, X_MJ: Pose
) -> tuple[JointAxis, Mimic | None]:
    """An axis in the joint frame, plus its mimic (1.11), converting older frame conventions."""
    check_children(ws, element, doc, "axis")
    xyz_el = _find(element, "xyz")
    loc = location_of(xyz_el if xyz_el is not None else element, doc)
    xyz = read_vec3(ws, element, "xyz", (0.0, 0.0, 1.0), doc)
    # Which frame <xyz> is in changed with the versions (sdformat's "specify_pose" and "pose frame
    # semantics" proposals): up to 1.4 the model frame; 1.5 and 1.6 the joint frame unless
    # <use_parent_model_frame>; from 1.7 the joint frame unless <xyz expressed_in="...">. Whatever the
    # file says, the typed model keeps the axis in the joint frame.
    expressed_in = None
    if doc.version <= (1, 4):
        expressed_in = "__model__"
    elif _find(element, "use_parent_model_frame") is not None and read_flag(
        ws, element, "use_parent_model_frame", False, doc
    ):
        expressed_in = "__model__"
    if xyz_el is not None and doc.version >= (1, 7):
        expressed_in = (xyz_el.get("expressed_in") or "").strip() or expressed_in
    if expressed_in is not None and expressed_in != joint:
        X_MF = scope.pose(expressed_in, loc)
        if X_MF is not None:
            xyz = quat_rotate(quat_conj(X_MJ.orientation), quat_rotate(X_MF.orientation, xyz))
    norm = math.sqrt(sum(v * v for v in xyz))
    if norm < 1e-12:
        ws.sink.error(ErrorCode.JOINT_AXIS_INVALID, f"joint '{joint}': axis xyz has zero length", loc)
        norm = 1.0
        xyz = (0.0, 0.0, 1.0)
    xyz = (xyz[0] / norm, xyz[1] / norm, xyz[2] / norm)  # SDF allows any length: the direction is what counts
    limit_el = _find(element, "limit")
    limit = JointLimit()
    if limit_el is not None:
        check_children(ws, limit_el, doc, "limit")
        # SDF's defaults: ±1e16 (no limit) for the range, -1 (no limit) for effort and velocity
        lower = read_number(ws, limit_el, "lower", -1e16, doc)
        upper = read_number(ws, limit_el, "upper", 1e16, doc)
        effort = read_number(ws, limit_el, "effort", -1.0, doc)
        velocity = read_number(ws, limit_el, "velocity", -1.0, doc)
        if lower > upper:
            ws.sink.error(
                ErrorCode.VALUE_INVALID,
                f"joint '{joint}': limit lower {lower:g} > upper {upper:g}",
                location_of(limit_el, doc),
            )
        # the ±1e16 and negative defaults mean "no limit": kept as None, so the physics adds no range and
        # the controllers no clamp (URDF's continuous joints arrive the same way)
        limit = JointLimit(
            lower=lower if lower > -_UNLIMITED else None,
            upper=upper if upper < _UNLIMITED else None,
            effort=effort if effort >= 0 else None,
            velocity=velocity if velocity >= 0 else None,
        )
    # <dynamics>: viscous damping (N·m·s/rad or N·s/m), Coulomb friction (N·m or N) and a spring about
    # spring_reference, all 0 by default; the physics gives them to MuJoCo's damping, frictionloss and
    # stiffness/springref of the joint, which is what gz-sim's engines apply
    dyn_el = _find(element, "dynamics")
    dynamics = JointDynamics(
        damping=read_number(ws, dyn_el, "damping", 0.0, doc),
        friction=read_number(ws, dyn_el, "friction", 0.0, doc),
        spring_stiffness=read_number(ws, dyn_el, "spring_stiffness", 0.0, doc),
        spring_reference=read_number(ws, dyn_el, "spring_reference", 0.0, doc),
    )
    mimic = None  # SDF 1.11's <axis><mimic joint=...>: the same coupling as URDF's <mimic>
    mimic_el = _find(element, "mimic")
    if mimic_el is not None:
        leader = (mimic_el.get("joint") or "").strip()
        if not leader:
            ws.sink.error(
                ErrorCode.ATTRIBUTE_MISSING,
                "<mimic> is missing the required 'joint' attribute",
                location_of(mimic_el, doc),
            )
        else:
            mimic = Mimic(
                leader, read_number(ws, mimic_el, "multiplier", 1.0, doc), read_number(ws, mimic_el, "offset", 0.0, doc)
            )
    return JointAxis(xyz, limit, dynamics), mimic


# ================================================================== worlds
def read_light(ws: Workspace, element: etree._Element, doc: _Doc, scope: Scope | None) -> Light | None:
    """A ``<light>`` (directional, point or spot; SDF's default is point) placed in the world: its pose
    resolved through ``scope`` when it is relative to a model's frame; its colours, direction, shadows and
    attenuation range. Camera sensors light the scene with it (the browser viewer has lights of its own)."""
    name = read_name(ws, element, doc)
    loc = location_of(element, doc)
    if name is None:
        return None
    check_children(ws, element, doc, "light")
    kind = (element.get("type") or "point").strip()
    if kind not in ("directional", "point", "spot"):
        ws.sink.error(
            ErrorCode.ATTRIBUTE_INVALID,
            f"light '{name}' type must be directional, point or spot, got {kind!r}",
            loc,
        )
        return None
    pose, rel = read_pose(ws, element, doc)
    if rel not in (None, "world"):
        if scope is None:
            ws.sink.error(ErrorCode.FRAME_INVALID, f"light '{name}': unknown frame '{rel}'", loc)
        else:
            base = scope.pose(rel, loc)
            pose = pose if base is None else base * pose
    attenuation = _find(element, "attenuation")
    if attenuation is not None:
        check_children(ws, attenuation, doc, "attenuation")
    default = Light(name)
    return Light(
        name=name,
        type=kind,
        pose=pose,
        diffuse=read_color(ws, element, "diffuse", doc) or default.diffuse,
        specular=read_color(ws, element, "specular", doc) or default.specular,
        direction=read_vec3(ws, element, "direction", default.direction, doc),
        cast_shadows=read_flag(ws, element, "cast_shadows", False, doc),
        attenuation_range=read_opt_number(ws, attenuation, "range", doc),
        location=loc,
    )


def derive_inertial(shapes: list[tuple[Pose, Geometry]], mass: float | None) -> Inertial:
    """Inertia from the collision shapes (mass None: from their volume at water density).

    Same rules as the URDF loader (``_inertia``); no shape with a volume gives its placeholder.
    """
    derived = inertia_from_geometries([(g, p) for p, g in shapes], mass)
    return derived.inertial if derived is not None else default_inertial(mass)

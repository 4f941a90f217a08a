"""URDF's elements read one by one (the first of the loader's passes, see :mod:`._urdf`): links, their
shapes, materials and inertials, joints and what they hold, each value checked and every problem reported
with its source location; the drafts the later passes finish."""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol, TypeVar

from lxml import etree

from . import _inertia
from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._model import (
    Box,
    Calibration,
    Capsule,
    Collision,
    ConfigElement,
    Cylinder,
    GazeboExtension,
    Geometry,
    Joint,
    JointAxis,
    JointDynamics,
    JointLimit,
    JointType,
    Material,
    Mesh,
    Mimic,
    Plugin,
    SafetyController,
    Sensor,
    Sphere,
    Surface,
    Visual,
)
from ._pose import Pose, Vec3
from ._resources import ResourceResolver
from ._xml import child_elements, element_location, local_name, parse_bool, parse_float, parse_floats

URDF_JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
"""Joint types a URDF may use."""

_AXIS_JOINTS = frozenset({JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC, JointType.PLANAR})

_CHILDREN: dict[str, frozenset[str]] = {
    "link": frozenset({"inertial", "visual", "collision"}),
    "visual": frozenset({"origin", "geometry", "material"}),
    "collision": frozenset({"origin", "geometry"}),
    "inertial": frozenset({"origin", "mass", "inertia"}),
    "material": frozenset({"color", "texture"}),
    "joint": frozenset(
        {"origin", "parent", "child", "axis", "limit", "dynamics", "mimic", "safety_controller", "calibration"}
    ),
}
"""Known child elements of each URDF element; anything else is reported as unsupported."""


T = TypeVar("T")


class _Named(Protocol):
    @property
    def name(self) -> str: ...


D = TypeVar("D", bound=_Named)


# --------------------------------------------------------------------------- drafts
@dataclass
class InertialDraft:
    """An ``<inertial>`` as written, with what is wrong with it."""

    element: etree._Element
    """The ``<inertial>`` element, for diagnostics."""
    pose: Pose
    """``<origin>``: the centre of mass and the inertia's axes in the link frame."""
    mass: float | None
    """``<mass value>``, kg; None when missing or not a number (a problem says which)."""
    tensor: tuple[float, float, float, float, float, float] | None
    """``<inertia>``'s ixx, ixy, ixz, iyy, iyz, izz (kg·m²); None when unreadable."""
    problems: list[tuple[ErrorCode, str, SourceLocation]] = field(default_factory=list)
    """What is wrong with it (no mass, a tensor that is not physical, ...), each with its location: the finishing
    pass derives an inertia and warns with these."""


@dataclass
class LinkDraft:
    """A link while the document is being read (mutable until :func:`._urdf_checks.finish_link`)."""

    name: str
    """The link's name."""
    element: etree._Element
    """The ``<link>`` element."""
    location: SourceLocation
    """Where the link is written (file:line), the xacro file's when it came from one."""
    visuals: list[Visual] = field(default_factory=list)
    """Its visuals, in document order."""
    collisions: list[Collision] = field(default_factory=list)
    """Its collisions, in document order (unnamed ones are numbered)."""
    inertial: InertialDraft | None = None
    """Its ``<inertial>`` as written; None: none (see ``_urdf_checks.drop_massless_links``)."""
    sensors: list[Sensor] = field(default_factory=list)
    """Sensors from ``<gazebo reference=link><sensor>`` blocks."""
    surface: dict[str, object] = field(default_factory=dict)
    """Surface fields from ``<gazebo reference=link>`` (mu1, mu2, kp, kd, ...), applied to every collision of the
    link."""
    flags: dict[str, bool] = field(default_factory=dict)
    """Link flags from ``<gazebo reference=link>`` (gravity, kinematic, self_collide)."""
    gazebo_material: str | None = None
    """``<gazebo reference=link><material>``: a Gazebo classic material script name (Gazebo/Red), which Gazebo draws
    instead of the URDF colour."""


@dataclass
class UrdfDocument:
    """Everything read from the ``<robot>`` element."""

    name: str
    """``<robot name>``."""
    links: dict[str, LinkDraft] = field(default_factory=dict)
    """Links by name, in document order."""
    joints: dict[str, Joint] = field(default_factory=dict)
    """Joints by name, in document order."""
    materials: dict[str, Material] = field(default_factory=dict)
    """Top-level named ``<material>``s, which a visual may name without defining."""
    plugins: list[Plugin] = field(default_factory=list)
    """``<gazebo><plugin>``s of the whole robot (no reference)."""
    gazebo: list[GazeboExtension] = field(default_factory=list)
    """Every ``<gazebo>`` block, kept whole."""
    transmissions: list[ConfigElement] = field(default_factory=list)
    """``<transmission>`` blocks, kept as written (ROS 1's ros_control; not simulated)."""
    ros2_control: list[etree._Element] = field(default_factory=list)
    """``<ros2_control>`` blocks, read after the links and joints (they name them)."""
    model_flags: dict[str, bool] = field(default_factory=dict)
    """Robot-wide flags from ``<gazebo>`` without a reference (static, self_collide)."""


# --------------------------------------------------------------------------- reader
def gazebo_value(element: etree._Element) -> str | None:
    """The value of a ``<gazebo>`` extension element: its ``value`` attribute (``<mu1 value="1.0"/>``,
    as Gazebo Classic's URDF reader and sdformat accept it) or else its text (``<mu1>1.0</mu1>``)."""
    attr = element.get("value")
    return attr if attr is not None else element.text


@dataclass
class ElementReader:
    """Reads URDF elements, reporting problems with their source location."""

    source: str
    """The document's name in diagnostics (its file, or ``<string>``)."""
    sink: DiagnosticSink
    """Where every problem goes."""
    resolver: ResourceResolver
    """Finds ``package://`` and ``model://`` URIs on the resource roots."""
    base_dir: str | None
    """The folder relative mesh paths resolve against (None for a string)."""

    # ---- reporting
    def loc(self, element: etree._Element) -> SourceLocation:
        """Where ``element`` came from."""
        return element_location(element, self.source)

    def error(self, code: ErrorCode, message: str, element: etree._Element) -> None:
        """Report an error at ``element``."""
        self.sink.error(code, message, self.loc(element))

    def warn(self, code: ErrorCode, message: str, element: etree._Element) -> None:
        """Report a warning at ``element``."""
        self.sink.warning(code, message, self.loc(element))

    def check_children(self, element: etree._Element, what: str) -> None:
        """Warn about children of ``element`` that this loader does not read."""
        known = _CHILDREN[local_name(element)]
        for child in child_elements(element):
            if local_name(child) not in known:
                self.unsupported(child, f"<{local_name(child)}> in {what}")

    def unsupported(self, element: etree._Element, what: str) -> None:
        """Warn that ``element`` is ignored."""
        tag = local_name(element)
        hint = ""
        if tag.startswith("xacro:"):
            hint = "; this looks like xacro: load the file as xacro (a .xacro suffix or format='xacro')"
        self.warn(ErrorCode.ELEMENT_UNSUPPORTED, f"{what} is not supported and is ignored{hint}", element)

    # ---- values
    def name(self, element: etree._Element, what: str) -> str | None:
        """The required, non-empty ``name`` attribute (ATTRIBUTE_MISSING error when absent)."""
        value = element.get("name")
        if value is None or not value.strip():
            self.error(ErrorCode.ATTRIBUTE_MISSING, f"{what} has no 'name' attribute", element)
            return None
        return value

    def floats(
        self, element: etree._Element, attr: str, count: int, default: tuple[float, ...] | None
    ) -> tuple[float, ...] | None:
        """``count`` floats from attribute ``attr``; ``default`` if absent; None (after an error) if invalid.

        urdfdom throws on a malformed vector and the robot does not load at all; gazelle reports it at the
        element's line, saying whether the count or a number was wrong, and the caller decides what stands in
        (an origin reads as zero, a shape is left out)."""
        text = element.get(attr)
        if text is None:
            return default
        values = parse_floats(text, count)
        if values is None:
            parts = text.split()
            problem = f"expected {count} numbers, got {len(parts)}" if len(parts) != count else "not a number"
            self.error(
                ErrorCode.VALUE_INVALID,
                f'<{local_name(element)} {attr}="{text}">: {problem}',
                element,
            )
        return values

    def floats3(self, element: etree._Element, attr: str, default: Vec3 | None) -> Vec3 | None:
        """Three floats (a vector, a size, a scale): :meth:`floats`' rules, typed."""
        v = self.floats(element, attr, 3, default)
        return None if v is None else (v[0], v[1], v[2])

    def number(self, element: etree._Element, attr: str, default: float | None = None) -> float | None:
        """One float from attribute ``attr`` (``default`` if absent; None after an error if invalid)."""
        values = self.floats(element, attr, 1, None if default is None else (default,))
        return None if values is None else values[0]

    def numbers(self, element: etree._Element, attrs: tuple[str, ...]) -> dict[str, float]:
        """The attributes of ``attrs`` that are present and valid, as floats."""
        result: dict[str, float] = {}
        for attr in attrs:
            value = self.number(element, attr)
            if value is not None:
                result[attr] = value
        return result

    def positive(self, element: etree._Element, attr: str, what: str) -> float | None:
        """A required attribute that must be > 0 (GEOMETRY_INVALID otherwise)."""
        if element.get(attr) is None:
            self.error(ErrorCode.ATTRIBUTE_MISSING, f"{what} has no '{attr}' attribute", element)
            return None
        value = self.number(element, attr)
        if value is not None and value <= 0:
            self.error(ErrorCode.GEOMETRY_INVALID, f"{what} {attr} must be > 0, got {value:g}", element)
            return None
        return value

    def pose(self, parent: etree._Element) -> Pose:
        """The pose of the ``<origin>`` child of ``parent`` (identity when absent)."""
        origin = parent.find("origin")
        if origin is None:
            return Pose()
        # URDF's rpy: fixed-axis roll, then pitch, then yaw (R = Rz·Ry·Rx), radians; a bad value is reported
        # by floats3 and read as zero
        xyz = self.floats3(origin, "xyz", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0)
        rpy = self.floats3(origin, "rpy", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0)
        return Pose.from_xyz_rpy(xyz, rpy)

    # ---- geometry
    def geometry(self, parent: etree._Element, what: str) -> Geometry | None:
        """The shape inside ``parent``'s ``<geometry>`` (errors when missing or invalid).

        As urdfdom's ``parseGeometry`` (link.cpp), the first child element is the shape: an empty ``<geometry>``
        is an error ("Geometry tag contains no child element."), and a second shape, which urdfdom (so
        robot_state_publisher and Gazebo's URDF reader) passes over in silence, is warned about by name."""
        geom = parent.find("geometry")
        if geom is None:
            self.error(ErrorCode.ELEMENT_MISSING, f"{what} has no <geometry>", parent)
            return None
        shapes = child_elements(geom)
        if not shapes:
            self.error(ErrorCode.GEOMETRY_INVALID, f"<geometry> of {what} contains no child element", geom)
            return None
        shape = shapes[0]
        for extra in shapes[1:]:
            self.warn(
                ErrorCode.GEOMETRY_INVALID,
                f"<geometry> of {what} holds a second shape <{local_name(extra)}>; only the first, "
                f"<{local_name(shape)}>, is used (as urdfdom reads it)",
                extra,
            )
        reader = _SHAPE_READERS.get(local_name(shape))
        if reader is None:
            self.error(
                ErrorCode.GEOMETRY_INVALID,
                f"unknown geometry <{local_name(shape)}> in {what}; expected one of " + ", ".join(_SHAPE_READERS),
                shape,
            )
            return None
        return reader(self, shape, f"<{local_name(shape)}> of {what}")

    def box(self, element: etree._Element, what: str) -> Geometry | None:
        """A ``<box size="x y z">``."""
        if element.get("size") is None:
            self.error(ErrorCode.ATTRIBUTE_MISSING, f"{what} has no 'size' attribute", element)
            return None
        size = self.floats3(element, "size", None)
        if size is None:
            return None
        if min(size) <= 0:
            self.error(ErrorCode.GEOMETRY_INVALID, f"{what} size must be > 0, got {element.get('size')!r}", element)
            return None
        return Box(size)

    def sphere(self, element: etree._Element, what: str) -> Geometry | None:
        """A ``<sphere radius>``."""
        radius = self.positive(element, "radius", what)
        return None if radius is None else Sphere(radius)

    def cylinder(self, element: etree._Element, what: str) -> Geometry | None:
        """A ``<cylinder radius length>`` (``<capsule>`` reads the same attributes)."""
        radius = self.positive(element, "radius", what)
        length = self.positive(element, "length", what)
        if radius is None or length is None:
            return None
        return (Capsule if local_name(element) == "capsule" else Cylinder)(radius, length)

    def mesh(self, element: etree._Element, what: str) -> Geometry | None:
        """A ``<mesh filename scale>``, resolved to a file (a warning when it cannot be)."""
        uri = element.get("filename")
        if uri is None or not uri.strip():
            self.error(ErrorCode.ATTRIBUTE_MISSING, f"{what} has no 'filename' attribute", element)
            return None
        scale = self.floats3(element, "scale", (1.0, 1.0, 1.0))
        if scale is None:
            return None
        if 0.0 in scale:  # a negative scale mirrors the mesh (allowed); a zero one flattens it to nothing
            self.error(
                ErrorCode.GEOMETRY_INVALID, f"{what} scale must not be zero, got {element.get('scale')!r}", element
            )
            return None
        return Mesh(uri, self.mesh_path(element, uri), scale)

    def mesh_path(self, element: etree._Element, uri: str) -> str | None:
        """The absolute file of a mesh URI, or None after a URI_UNRESOLVED / MESH_NOT_FOUND warning."""
        # a relative mesh path is relative to the file that wrote it: a xacro include's own folder, which the
        # element's location names, else the document's
        loc = self.loc(element)
        base = os.path.dirname(loc.file) if loc.file != self.source and not loc.file.startswith("<") else self.base_dir
        try:
            path = self.resolver.resolve_uri(uri, base)
        except (OSError, ValueError):
            path = None
        if path is None:
            self.warn(
                ErrorCode.URI_UNRESOLVED,
                f"cannot resolve mesh URI '{uri}': {self.resolver.unresolved_reason(uri, base)}",
                element,
            )
            return None
        if not _is_file(path):
            self.warn(ErrorCode.MESH_NOT_FOUND, f"mesh file '{path}' (from '{uri}') does not exist", element)
            return None
        return str(path)

    # ---- materials
    def material(self, element: etree._Element, named: dict[str, Material]) -> Material:
        """A ``<material>`` element: inline colour/texture, or a reference to a named one."""
        name = element.get("name", "")
        color_el, texture_el = element.find("color"), element.find("texture")
        self.check_children(element, f"material '{name}'")
        # a <material name="blue"/> with no colour refers to a robot-level <material> of that name (urdfdom's
        # rule); one defined nowhere is warned about and draws in the default colour
        if color_el is None and texture_el is None:
            if name in named:
                return named[name]
            if name:
                self.warn(ErrorCode.MATERIAL_UNDEFINED, f"material '{name}' is not defined", element)
            return Material(name=name)
        rgba = None if color_el is None else self.floats(color_el, "rgba", 4, None)
        diffuse = None if rgba is None else (rgba[0], rgba[1], rgba[2], rgba[3])
        texture = None if texture_el is None else texture_el.get("filename")
        return Material(name=name, diffuse=diffuse, texture=texture)

    # ---- links
    def link(self, element: etree._Element, materials: dict[str, Material]) -> LinkDraft | None:
        """A ``<link>`` with its visuals, collisions and inertial: any number of ``<visual>`` and ``<collision>``
        (urdfdom keeps them all, each in the link frame at its ``<origin>``), one ``<inertial>`` (a second is
        warned about and left out)."""
        name = self.name(element, "<link>")
        if name is None:
            return None
        self.check_children(element, f"link '{name}'")
        draft = LinkDraft(name, element, self.loc(element))
        for i, el in enumerate(element.findall("visual")):
            visual = self.visual(el, name, i, materials)
            if visual is not None:
                draft.visuals.append(visual)
        for i, el in enumerate(element.findall("collision")):
            collision = self.collision(el, name, i)
            if collision is not None:
                draft.collisions.append(collision)
        inertials = element.findall("inertial")  # URDF allows one; a second is a slip, said and left out
        if len(inertials) > 1:
            self.warn(
                ErrorCode.ELEMENT_UNSUPPORTED,
                f"link '{name}' has {len(inertials)} <inertial>; using the first",
                inertials[1],
            )
        if inertials:
            draft.inertial = self.inertial(inertials[0])
        return draft

    def shape_header(self, element: etree._Element, link: str, index: int) -> tuple[str, str, Pose, Geometry | None]:
        """Name, description, pose and geometry shared by ``<visual>`` and ``<collision>``."""
        kind = local_name(element)
        # an unnamed shape is named by its link, kind and place: names must be unique for Gazebo's scoped
        # collision names (contact sensors, ``model::link::collision``), and URDF does not require one
        name = element.get("name") or f"{link}_{kind}_{index}"
        what = f"{kind} '{name}' of link '{link}'"
        self.check_children(element, what)
        return name, what, self.pose(element), self.geometry(element, what)

    def visual(self, element: etree._Element, link: str, index: int, materials: dict[str, Material]) -> Visual | None:
        """A ``<visual>``."""
        name, _, pose, geometry = self.shape_header(element, link, index)
        if geometry is None:
            return None
        mat_el = element.find("material")
        material = None if mat_el is None else self.material(mat_el, materials)
        return Visual(name, pose, geometry, material, self.loc(element))

    def collision(self, element: etree._Element, link: str, index: int) -> Collision | None:
        """A ``<collision>``."""
        name, _, pose, geometry = self.shape_header(element, link, index)
        if geometry is None:
            return None
        return Collision(name, pose, geometry, Surface(), self.loc(element))

    def inertial(self, element: etree._Element) -> InertialDraft:
        """An ``<inertial>``; bad mass or inertia become problems (warnings later), not errors.

        The ``<origin>`` is the centre of mass and the inertia's principal-axes frame in the link frame;
        ``<inertia>``'s six values are kg·m² about the centre of mass, a missing one 0 (urdfdom's default). A
        missing or non-positive mass, or a tensor that is not physical (not positive definite, or breaking
        the triangle inequality, which MuJoCo refuses), is kept as a problem: the link's inertia is then
        derived from its collision shapes, with the warning, rather than the spawn refused."""
        self.check_children(element, "<inertial>")
        draft = InertialDraft(element, self.pose(element), None, None)
        mass_el, inertia_el = element.find("mass"), element.find("inertia")
        if mass_el is None:
            draft.problems.append((ErrorCode.MASS_INVALID, "<inertial> has no <mass>", self.loc(element)))
        else:
            draft.mass = parse_float(mass_el.get("value"))
            if draft.mass is None or draft.mass <= 0:
                shown = mass_el.get("value")
                draft.problems.append((ErrorCode.MASS_INVALID, f"mass must be > 0, got {shown!r}", self.loc(mass_el)))
                draft.mass = None
        if inertia_el is None:
            draft.problems.append((ErrorCode.INERTIA_MISSING, "<inertial> has no <inertia>", self.loc(element)))
            return draft
        values = [parse_float(inertia_el.get(k, "0")) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")]
        if any(v is None for v in values):
            draft.problems.append(
                (ErrorCode.INERTIA_INVALID, "<inertia> has a value that is not a number", self.loc(inertia_el))
            )
            return draft
        ixx, ixy, ixz, iyy, iyz, izz = (v for v in values if v is not None)
        problem = _inertia.inertia_problem(ixx, ixy, ixz, iyy, iyz, izz)
        if problem is not None:
            draft.problems.append((ErrorCode.INERTIA_INVALID, problem, self.loc(inertia_el)))
        else:
            draft.tensor = (ixx, ixy, ixz, iyy, iyz, izz)
        return draft

    # ---- joints
    def joint(self, element: etree._Element) -> Joint | None:
        """A ``<joint>`` (JOINT_* errors for a bad type, axis, parent or child element).

        URDF's joint frame is its child link's frame: ``<origin>`` places it in the parent link (X_PJ), and the
        child sits at the joint with no offset (SDF's joints differ: placed in the child). Types are
        urdfdom's six (``revolute``, ``continuous``, ``prismatic``, ``fixed``, ``floating``, ``planar``);
        ``<mimic>``, ``<safety_controller>`` and ``<calibration>`` are kept for the systems that read them
        (joint_state_publisher, ros2_control's mimic joints)."""
        name = self.name(element, "<joint>")
        if name is None:
            return None
        self.check_children(element, f"joint '{name}'")
        type_text = element.get("type")
        if type_text not in URDF_JOINT_TYPES:
            self.error(
                ErrorCode.JOINT_TYPE_INVALID,
                f"joint '{name}' has unknown type {type_text!r}; expected one of " + ", ".join(URDF_JOINT_TYPES),
                element,
            )
            return None
        jtype = JointType(type_text)
        parent = self.link_ref(element, "parent", name, ErrorCode.JOINT_PARENT_INVALID)
        child = self.link_ref(element, "child", name, ErrorCode.JOINT_CHILD_INVALID)
        axis = self.axis(element, name, jtype)
        if parent is None or child is None or (jtype in _AXIS_JOINTS and axis is None):
            return None
        # in URDF the child link's frame is the joint frame: origin is X_PJ and the child offset stays the identity
        return Joint(
            name=name,
            type=jtype,
            parent=parent,
            child=child,
            origin=self.pose(element),
            axis=axis,
            mimic=self.optional(element, "mimic", self.mimic),
            safety_controller=self.optional(element, "safety_controller", self.safety_controller),
            calibration=self.optional(element, "calibration", self.calibration),
            location=self.loc(element),
        )

    def link_ref(self, joint: etree._Element, tag: str, name: str, code: ErrorCode) -> str | None:
        """The ``link`` attribute of the joint's ``<parent>`` or ``<child>``."""
        el = joint.find(tag)
        value = None if el is None else el.get("link")
        if value is None or not value.strip():
            self.error(code, f"joint '{name}' has no <{tag} link=\"...\">", joint if el is None else el)
            return None
        return value

    def axis(self, element: etree._Element, joint: str, jtype: JointType) -> JointAxis | None:
        """The normalised axis with limit and dynamics (None for fixed/floating, or after an error)."""
        if jtype not in _AXIS_JOINTS:
            return None
        # URDF's default axis is x (1 0 0), in the joint frame (the joint's <origin>), unlike SDF's z
        axis_el = element.find("axis")
        xyz: Vec3 | None = (1.0, 0.0, 0.0)
        if axis_el is not None:
            xyz = self.floats3(axis_el, "xyz", (1.0, 0.0, 0.0))
            if xyz is None:
                return None
        norm = math.sqrt(sum(v * v for v in xyz))
        if norm < 1e-12:
            self.error(
                ErrorCode.JOINT_AXIS_INVALID,
                f"joint '{joint}' has a zero axis",
                axis_el if axis_el is not None else element,
            )
            return None
        return JointAxis(  # urdfdom normalises the axis too: "0 0 2" is the z axis
            (xyz[0] / norm, xyz[1] / norm, xyz[2] / norm),
            limit=self.limit(element, joint, jtype),
            dynamics=self.optional(element, "dynamics", self.dynamics) or JointDynamics(),
        )

    def limit(self, element: etree._Element, joint: str, jtype: JointType) -> JointLimit:
        """``<limit>``; revolute and prismatic joints should have one (a warning otherwise)."""
        limit_el = element.find("limit")
        if limit_el is None:
            if jtype in (JointType.REVOLUTE, JointType.PRISMATIC):
                self.warn(
                    ErrorCode.ELEMENT_MISSING, f"{jtype.value} joint '{joint}' has no <limit>; it is unlimited", element
                )
            return JointLimit()
        v = self.numbers(limit_el, ("lower", "upper", "effort", "velocity"))
        for bound in ("lower", "upper"):
            if jtype is JointType.CONTINUOUS:
                v.pop(bound, None)  # a continuous joint has no position limits
            elif jtype in (JointType.REVOLUTE, JointType.PRISMATIC):
                v.setdefault(bound, 0.0)  # the URDF default
        return JointLimit(v.get("lower"), v.get("upper"), v.get("effort"), v.get("velocity"))

    def optional(self, element: etree._Element, tag: str, read: Callable[[etree._Element], T]) -> T | None:
        """``read(child)`` for the ``tag`` child of ``element``, or None when absent."""
        child = element.find(tag)
        return None if child is None else read(child)

    def dynamics(self, element: etree._Element) -> JointDynamics:
        """``<dynamics damping friction>``."""
        # urdfdom's defaults: no damping, no friction; URDF has no spring (SDF's <spring_stiffness> does)
        v = self.numbers(element, ("damping", "friction"))
        return JointDynamics(damping=v.get("damping", 0.0), friction=v.get("friction", 0.0))

    def mimic(self, element: etree._Element) -> Mimic | None:
        """``<mimic joint multiplier offset>``."""
        target = element.get("joint")
        if not target:
            self.error(ErrorCode.ATTRIBUTE_MISSING, "<mimic> has no 'joint' attribute", element)
            return None
        v = self.numbers(element, ("multiplier", "offset"))
        return Mimic(target, v.get("multiplier", 1.0), v.get("offset", 0.0))

    def safety_controller(self, element: etree._Element) -> SafetyController:
        """``<safety_controller>`` (kept; not simulated)."""
        v = self.numbers(element, ("soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"))
        return SafetyController(**v)

    def calibration(self, element: etree._Element) -> Calibration:
        """``<calibration rising falling>`` (kept; not simulated)."""
        return Calibration(**self.numbers(element, ("rising", "falling")))

    def gazebo_float(self, parent: etree._Element, tag: str) -> float | None:
        """The number in ``<gazebo>``'s child ``tag`` (None when absent; a VALUE_INVALID error when it is
        not a number)."""
        return self._gazebo_text(parent, tag, parse_float)

    def gazebo_flag(self, parent: etree._Element, tag: str) -> bool | None:
        """The ``true``/``false``/``1``/``0`` in ``<gazebo>``'s child ``tag`` (None when absent; a
        VALUE_INVALID error for anything else)."""
        return self._gazebo_text(parent, tag, parse_bool)

    def _gazebo_text(self, parent: etree._Element, tag: str, parse: Callable[[str | None], T | None]) -> T | None:
        """The parsed text of a ``<gazebo>`` block's child ``tag`` (None when absent; a VALUE_INVALID error naming
        the text when ``parse`` refuses it)."""
        el = parent.find(tag)
        if el is None:
            return None
        text = gazebo_value(el)
        value = parse(text)
        if value is None:
            self.error(ErrorCode.VALUE_INVALID, f"<{tag}> has an invalid value {text!r}", el)
        return value


def _is_file(path: Path) -> bool:
    """Whether ``path`` is a regular file (False for a path the OS refuses to look at: too long, a NUL byte)."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


_SHAPE_READERS: dict[str, Callable[[ElementReader, etree._Element, str], Geometry | None]] = {
    "box": ElementReader.box,
    "cylinder": ElementReader.cylinder,
    "sphere": ElementReader.sphere,
    "capsule": ElementReader.cylinder,
    "mesh": ElementReader.mesh,
}

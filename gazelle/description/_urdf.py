"""URDF text to :class:`Model`, with every problem reported as a located diagnostic.

Entry point: :func:`parse_urdf`. The loader reads the document in three passes:

1. elements to drafts (links, joints, materials, ``<gazebo>`` blocks), checking values;
2. the kinematic structure (names, parents, loops, roots);
3. finishing links: ``<gazebo>`` extensions applied, missing or invalid inertia derived.

Fixed joints are kept as they are (no lumping). Elements expanded by xacro carry their
original file and line (see :mod:`._xml`), so diagnostics point into the xacro sources.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field, replace
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
    ControlComponent,
    ControlInterface,
    Cylinder,
    GazeboExtension,
    Geometry,
    Inertial,
    Joint,
    JointAxis,
    JointDynamics,
    JointLimit,
    JointType,
    Link,
    Material,
    Mesh,
    Mimic,
    Model,
    Plugin,
    Pose,
    Ros2Control,
    SafetyController,
    Sensor,
    Sphere,
    Surface,
    Vec3,
    Visual,
)
from ._resources import ResourceResolver
from ._xml import (
    LOCATION_ATTRIBUTE,
    child_elements,
    element_location,
    local_name,
    parse_bool,
    parse_float,
    parse_floats,
    parse_xml,
    to_config,
)

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

# <gazebo reference="link"> tags applied to every collision's Surface: tag -> (field, vector length).
_SURFACE_TAGS: dict[str, tuple[str, int]] = {
    "mu1": ("mu", 1),
    "mu2": ("mu2", 1),
    "kp": ("kp", 1),
    "kd": ("kd", 1),
    "maxVel": ("max_vel", 1),
    "minDepth": ("min_depth", 1),
    "fdir1": ("fdir1", 3),
}
# <gazebo reference="link"> boolean tags applied to the Link: tag -> (field, inverted).
_LINK_FLAGS: dict[str, tuple[str, bool]] = {
    "selfCollide": ("self_collide", False),
    "gravity": ("gravity", False),
    "turnGravityOff": ("gravity", True),
    "kinematic": ("kinematic", False),
}
# <gazebo> (no reference) boolean tags applied to the Model.
_MODEL_FLAGS: dict[str, str] = {"static": "static", "self_collide": "self_collide"}

# Colours of the common Gazebo classic material scripts (diffuse RGBA).
_GAZEBO_COLORS: dict[str, tuple[float, float, float, float]] = {
    "Gazebo/Black": (0.0, 0.0, 0.0, 1.0),
    "Gazebo/FlatBlack": (0.1, 0.1, 0.1, 1.0),
    "Gazebo/DarkGrey": (0.175, 0.175, 0.175, 1.0),
    "Gazebo/Grey": (0.7, 0.7, 0.7, 1.0),
    "Gazebo/White": (1.0, 1.0, 1.0, 1.0),
    "Gazebo/Red": (1.0, 0.0, 0.0, 1.0),
    "Gazebo/Green": (0.0, 1.0, 0.0, 1.0),
    "Gazebo/Blue": (0.0, 0.0, 1.0, 1.0),
    "Gazebo/Yellow": (1.0, 1.0, 0.0, 1.0),
    "Gazebo/Orange": (1.0, 0.5088, 0.0468, 1.0),
    "Gazebo/Purple": (1.0, 0.0, 1.0, 1.0),
    "Gazebo/Turquoise": (0.0, 1.0, 1.0, 1.0),
    "Gazebo/Wood": (0.5, 0.3, 0.1, 1.0),
}


T = TypeVar("T")


class _Named(Protocol):
    @property
    def name(self) -> str: ...


D = TypeVar("D", bound=_Named)


# --------------------------------------------------------------------------- drafts
@dataclass
class _InertialDraft:
    """An ``<inertial>`` as written, with what is wrong with it."""

    element: etree._Element
    pose: Pose
    mass: float | None
    tensor: tuple[float, float, float, float, float, float] | None
    problems: list[tuple[ErrorCode, str, SourceLocation]] = field(default_factory=list)


@dataclass
class _LinkDraft:
    """A link while the document is being read (mutable until :meth:`_Reader.finish_link`)."""

    name: str
    element: etree._Element
    location: SourceLocation
    visuals: list[Visual] = field(default_factory=list)
    collisions: list[Collision] = field(default_factory=list)
    inertial: _InertialDraft | None = None
    sensors: list[Sensor] = field(default_factory=list)
    surface: dict[str, object] = field(default_factory=dict)
    flags: dict[str, bool] = field(default_factory=dict)
    gazebo_material: str | None = None


@dataclass
class _Document:
    """Everything read from the ``<robot>`` element."""

    name: str
    links: dict[str, _LinkDraft] = field(default_factory=dict)
    joints: dict[str, Joint] = field(default_factory=dict)
    materials: dict[str, Material] = field(default_factory=dict)
    plugins: list[Plugin] = field(default_factory=list)
    gazebo: list[GazeboExtension] = field(default_factory=list)
    transmissions: list[ConfigElement] = field(default_factory=list)
    ros2_control: list[etree._Element] = field(default_factory=list)
    model_flags: dict[str, bool] = field(default_factory=dict)


# --------------------------------------------------------------------------- reader
def gazebo_value(element: etree._Element) -> str | None:
    """The value of a ``<gazebo>`` extension element: its ``value`` attribute (``<mu1 value="1.0"/>``,
    as Gazebo Classic's URDF reader and sdformat accept it) or else its text (``<mu1>1.0</mu1>``)."""
    attr = element.get("value")
    return attr if attr is not None else element.text


@dataclass
class _Reader:
    """Reads URDF elements, reporting problems with their source location."""

    source: str
    sink: DiagnosticSink
    resolver: ResourceResolver
    base_dir: str | None

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
        """``count`` floats from attribute ``attr``; ``default`` if absent; None (after an error) if invalid."""
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
        xyz = self.floats3(origin, "xyz", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0)
        rpy = self.floats3(origin, "rpy", (0.0, 0.0, 0.0)) or (0.0, 0.0, 0.0)
        return Pose.from_xyz_rpy(xyz, rpy)

    # ---- geometry
    def geometry(self, parent: etree._Element, what: str) -> Geometry | None:
        """The one shape inside ``parent``'s ``<geometry>`` (errors when missing or invalid)."""
        geom = parent.find("geometry")
        if geom is None:
            self.error(ErrorCode.ELEMENT_MISSING, f"{what} has no <geometry>", parent)
            return None
        shapes = child_elements(geom)
        if len(shapes) != 1:
            self.error(
                ErrorCode.GEOMETRY_INVALID, f"<geometry> of {what} must hold exactly one shape, has {len(shapes)}", geom
            )
            return None
        shape = shapes[0]
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
        if 0.0 in scale:
            self.error(
                ErrorCode.GEOMETRY_INVALID, f"{what} scale must not be zero, got {element.get('scale')!r}", element
            )
            return None
        return Mesh(uri, self.mesh_path(element, uri), scale)

    def mesh_path(self, element: etree._Element, uri: str) -> str | None:
        """The absolute file of a mesh URI, or None after a URI_UNRESOLVED / MESH_NOT_FOUND warning."""
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
    def link(self, element: etree._Element, materials: dict[str, Material]) -> _LinkDraft | None:
        """A ``<link>`` with its visuals, collisions and inertial."""
        name = self.name(element, "<link>")
        if name is None:
            return None
        self.check_children(element, f"link '{name}'")
        draft = _LinkDraft(name, element, self.loc(element))
        for i, el in enumerate(element.findall("visual")):
            visual = self.visual(el, name, i, materials)
            if visual is not None:
                draft.visuals.append(visual)
        for i, el in enumerate(element.findall("collision")):
            collision = self.collision(el, name, i)
            if collision is not None:
                draft.collisions.append(collision)
        inertials = element.findall("inertial")
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

    def inertial(self, element: etree._Element) -> _InertialDraft:
        """An ``<inertial>``; bad mass or inertia become problems (warnings later), not errors."""
        self.check_children(element, "<inertial>")
        draft = _InertialDraft(element, self.pose(element), None, None)
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
        """A ``<joint>`` (JOINT_* errors for a bad type, axis, parent or child element)."""
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
        return JointAxis(
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

    # ---- <gazebo>
    def plugin(self, element: etree._Element) -> Plugin | None:
        """A ``<plugin name filename>`` with its whole element as config."""
        filename = element.get("filename")
        if not filename:
            self.error(
                ErrorCode.ATTRIBUTE_MISSING,
                f"<plugin name={element.get('name', '')!r}> has no 'filename' attribute",
                element,
            )
            return None
        return Plugin(element.get("name", ""), filename, to_config(element, self.source), self.loc(element))

    def sensor(self, element: etree._Element) -> Sensor | None:
        """A ``<sensor type name>`` inside ``<gazebo reference=link>``."""
        name = self.name(element, "<sensor>")
        stype = element.get("type")
        if not stype:
            self.error(ErrorCode.ATTRIBUTE_MISSING, f"sensor '{name}' has no 'type' attribute", element)
        if name is None or not stype:
            return None
        pose = Pose()
        pose_el = element.find("pose")
        if pose_el is not None:
            values = parse_floats(pose_el.text or "0 0 0 0 0 0", 6)
            if values is None:
                self.error(
                    ErrorCode.VALUE_INVALID, f"sensor '{name}' <pose> needs 6 numbers, got {pose_el.text!r}", pose_el
                )
            else:
                pose = Pose.from_xyz_rpy((values[0], values[1], values[2]), (values[3], values[4], values[5]))
        rate = self.text_value(element, "update_rate", parse_float)
        always_on = self.text_value(element, "always_on", parse_bool)
        plugins = [p for p in (self.plugin(el) for el in element.findall("plugin")) if p is not None]
        return Sensor(
            name=name,
            type=stype,
            pose=pose,
            update_rate_hz=rate if rate is not None else 0.0,
            always_on=bool(always_on),
            topic=(element.findtext("topic") or "").strip(),
            config=to_config(element, self.source),
            plugins=tuple(plugins),
            location=self.loc(element),
        )

    def text_value(self, parent: etree._Element, tag: str, parse: Callable[[str | None], T | None]) -> T | None:
        """The parsed text of child ``tag`` (VALUE_INVALID error when unparsable; None when absent)."""
        el = parent.find(tag)
        if el is None:
            return None
        text = gazebo_value(el)
        value = parse(text)
        if value is None:
            self.error(ErrorCode.VALUE_INVALID, f"<{tag}> has an invalid value {text!r}", el)
        return value

    def gazebo(self, element: etree._Element, doc: _Document) -> None:
        """A ``<gazebo>`` block: kept whole, and its known tags applied."""
        reference = element.get("reference")
        doc.gazebo.append(GazeboExtension(reference, to_config(element, self.source), self.loc(element)))
        if reference is None:
            self.apply_model_gazebo(element, doc)
        elif reference in doc.links:
            self.apply_link_gazebo(element, doc.links[reference], doc)
        elif reference in doc.joints:
            joint = doc.joints[reference]
            for child in child_elements(element):
                if local_name(child) == "sensor" and joint is not None and joint.child in doc.links:
                    sensor = self.sensor(child)  # force_torque: kept with the joint's child link
                    if sensor is not None:
                        doc.links[joint.child].sensors.append(replace(sensor, joint=reference))
                else:
                    self.unsupported(child, f'<{local_name(child)}> in <gazebo reference="{reference}"> (a joint)')
        else:
            self.warn(
                ErrorCode.GAZEBO_REFERENCE_INVALID,
                f'<gazebo reference="{reference}"> names no link or joint; the block is ignored',
                element,
            )

    def apply_model_gazebo(self, element: etree._Element, doc: _Document) -> None:
        """Robot-level ``<gazebo>``: plugins and model flags."""
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "plugin":
                plugin = self.plugin(child)
                if plugin is not None:
                    doc.plugins.append(plugin)
            elif tag in _MODEL_FLAGS:
                value = self.text_value(element, tag, parse_bool)
                if value is not None:
                    doc.model_flags[_MODEL_FLAGS[tag]] = bool(value)
            else:
                self.unsupported(child, f"<{tag}> in <gazebo>")

    def apply_link_gazebo(self, element: etree._Element, link: _LinkDraft, doc: _Document) -> None:
        """``<gazebo reference=link>``: surface, flags, material, sensors and plugins."""
        for child in child_elements(element):
            tag = local_name(child)
            if tag in _SURFACE_TAGS:
                field_name, count = _SURFACE_TAGS[tag]
                text = gazebo_value(child)
                values = parse_floats(text, count)
                if values is None:
                    self.error(ErrorCode.VALUE_INVALID, f"<{tag}> needs {count} number(s), got {text!r}", child)
                else:
                    link.surface[field_name] = values if count > 1 else values[0]
            elif tag in _LINK_FLAGS:
                field_name, inverted = _LINK_FLAGS[tag]
                flag = self.text_value(element, tag, parse_bool)
                if flag is not None:
                    link.flags[field_name] = bool(flag) != inverted
            elif tag == "material":
                link.gazebo_material = (child.text or "").strip() or None
            elif tag == "sensor":
                sensor = self.sensor(child)
                if sensor is not None:
                    link.sensors.append(sensor)
            elif tag == "plugin":
                plugin = self.plugin(child)
                if plugin is not None:
                    doc.plugins.append(plugin)
            else:
                self.unsupported(child, f'<{tag}> in <gazebo reference="{link.name}">')

    # ---- top level
    def document(self, root: etree._Element) -> _Document | None:
        """All of ``<robot>``, first pass.

        A ``<robot>`` with no ``<link>`` and no ``<joint>`` is an include fragment (a file of
        xacro macros, properties, materials, ``<gazebo>`` or ``<ros2_control>`` blocks): it
        needs no name, and its ``<gazebo reference>`` blocks name links defined elsewhere.
        """
        fragment = is_fragment(root)
        name = root.get("name", "").strip() if fragment else self.name(root, "<robot>")
        doc = _Document(name or "")
        doc.materials = self.named_materials(root)
        gazebo_blocks: list[etree._Element] = []
        for child in child_elements(root):
            tag = local_name(child)
            if tag == "link":
                self.add_unique(doc.links, self.link(child, doc.materials), "link", child)
            elif tag == "joint":
                self.add_unique(doc.joints, self.joint(child), "joint", child)
            elif tag == "gazebo":
                gazebo_blocks.append(child)  # after all links and joints are known
            elif tag == "transmission":
                doc.transmissions.append(to_config(child, self.source))
                self.warn(
                    ErrorCode.ELEMENT_UNSUPPORTED,
                    f"transmission '{child.get('name', '')}' is kept but not simulated",
                    child,
                )
            elif tag == "ros2_control":
                doc.ros2_control.append(child)  # read once every joint is known
            elif tag != "material":
                self.unsupported(child, f"<{tag}> in <robot>")
        for block in gazebo_blocks:
            if fragment and block.get("reference") is not None:
                doc.gazebo.append(
                    GazeboExtension(block.get("reference"), to_config(block, self.source), self.loc(block))
                )
            else:
                self.gazebo(block, doc)
        return None if name is None else doc

    def ros2_control(self, element: etree._Element, doc: _Document) -> Ros2Control | None:
        """A ``<ros2_control name type>`` block. A joint it names that the robot lacks, or a tag it
        does not know, is warned about (file:line) and left out; the rest is kept."""
        name = self.name(element, "<ros2_control>")
        if name is None:
            return None
        kind = (element.get("type") or "system").strip()
        if kind not in ("system", "actuator", "sensor"):
            self.warn(
                ErrorCode.VALUE_INVALID,
                f"ros2_control '{name}' has type '{kind}' (system, actuator or sensor)",
                element,
            )
        plugin, hw_params = "", ()
        joints: list[ControlComponent] = []
        sensors: list[ControlComponent] = []
        gpios: list[ControlComponent] = []
        for child in child_elements(element):
            tag = local_name(child)
            if tag == "hardware":
                plugin_el = child.find("plugin")
                if plugin_el is None:
                    plugin_el = child.find("classType")  # before Humble
                plugin = (plugin_el.text or "").strip() if plugin_el is not None else ""
                hw_params = self.control_params(child)
                if not plugin:
                    self.warn(ErrorCode.ELEMENT_MISSING, f"ros2_control '{name}' has no <hardware><plugin>", child)
            elif tag in ("joint", "sensor", "gpio"):
                component = self.control_component(child, tag)
                if component is None:
                    continue
                if tag == "joint" and component.name not in doc.joints:
                    known = ", ".join(sorted(doc.joints)) or "none"
                    self.warn(
                        ErrorCode.CONTROL_JOINT_INVALID,
                        f"ros2_control '{name}': joint '{component.name}' is not a joint of the robot "
                        f"(it has {known}); it is left out",
                        child,
                    )
                    continue
                {"joint": joints, "sensor": sensors, "gpio": gpios}[tag].append(component)
            else:
                self.unsupported(child, f"<{tag}> in <ros2_control>")
        if element.find("hardware") is None:
            self.warn(ErrorCode.ELEMENT_MISSING, f"ros2_control '{name}' has no <hardware>", element)
        return Ros2Control(
            name, kind, plugin, hw_params, tuple(joints), tuple(sensors), tuple(gpios), self.loc(element)
        )

    def control_params(self, element: etree._Element) -> tuple[tuple[str, str], ...]:
        """The ``<param name=...>value</param>`` children, in order."""
        return tuple(
            ((p.get("name") or "").strip(), (p.text or "").strip())
            for p in element.findall("param")
            if (p.get("name") or "").strip()
        )

    def control_component(self, element: etree._Element, tag: str) -> ControlComponent | None:
        """A ``<joint>``/``<sensor>``/``<gpio>`` of a ros2_control block, with its interfaces."""
        name = self.name(element, f"<{tag}> in <ros2_control>")
        if name is None:
            return None
        commands, states = [], []
        for child in child_elements(element):
            t = local_name(child)
            if t in ("command_interface", "state_interface"):
                iname = (child.get("name") or "").strip()
                if not iname:
                    self.warn(ErrorCode.ATTRIBUTE_MISSING, f"<{t}> of {tag} '{name}' has no name", child)
                    continue
                iface = ControlInterface(iname, self.control_params(child), self.loc(child))
                (commands if t == "command_interface" else states).append(iface)
            elif t != "param":
                self.unsupported(child, f"<{t}> in ros2_control {tag} '{name}'")
        return ControlComponent(name, tuple(commands), tuple(states), self.control_params(element), self.loc(element))

    def named_materials(self, root: etree._Element) -> dict[str, Material]:
        """Materials usable by name: top-level ones first, then any defined inline in a visual."""
        named: dict[str, Material] = {}
        top = [el for el in root.findall("material")]
        inline = [el for el in root.iterfind("link/visual/material")]
        for el in top + inline:
            has_content = el.find("color") is not None or el.find("texture") is not None
            name = el.get("name")
            if el in top and not name:
                self.error(ErrorCode.ATTRIBUTE_MISSING, "<material> has no 'name' attribute", el)
                continue
            if not name or not has_content:
                continue
            if name in named:
                if el in top:
                    self.warn(
                        ErrorCode.DUPLICATE_NAME, f"material '{name}' is defined more than once; the first is used", el
                    )
                continue
            named[name] = self.material(el, named)
        return named

    def add_unique(self, table: dict[str, D], item: D | None, what: str, element: etree._Element) -> None:
        """Add a named link/joint draft, reporting a DUPLICATE_NAME error for a repeat."""
        if item is None:
            return
        name = item.name
        if name in table:
            first = getattr(table[name], "location", None)
            where = f" (first at {first})" if first is not None else ""
            self.error(ErrorCode.DUPLICATE_NAME, f"{what} '{name}' is defined more than once{where}", element)
            return
        table[name] = item


def _is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


_SHAPE_READERS: dict[str, Callable[[_Reader, etree._Element, str], Geometry | None]] = {
    "box": _Reader.box,
    "cylinder": _Reader.cylinder,
    "sphere": _Reader.sphere,
    "capsule": _Reader.cylinder,
    "mesh": _Reader.mesh,
}


# --------------------------------------------------------------------------- fragments
def is_fragment(root: etree._Element) -> bool:
    """Whether a ``<robot>`` defines no ``<link>`` and no ``<joint>`` (an include fragment)."""
    return root.find("link") is None and root.find("joint") is None


def _report_fragment(root: etree._Element, doc: _Document, reader: _Reader) -> None:
    """One FRAGMENT warning for a document that defines no links or joints."""
    kept = []
    if doc.materials:
        kept.append(f"{len(doc.materials)} material(s)")
    if doc.gazebo:
        kept.append(f"{len(doc.gazebo)} <gazebo> block(s), for links defined elsewhere")
    if doc.transmissions:
        kept.append(f"{len(doc.transmissions)} transmission(s)")
    what = ", ".join(kept) if kept else "nothing once expanded (macros or properties only)"
    label = f"robot '{doc.name}'" if doc.name else "<robot>"
    reader.warn(
        ErrorCode.FRAGMENT,
        f"{label} defines no links (an include fragment?): it holds {what}; it cannot be simulated on its own",
        root,
    )


# --------------------------------------------------------------------------- attributes
_ATTRIBUTES: dict[str, frozenset[str]] = {
    "robot": frozenset({"name", "version"}),
    "link": frozenset({"name", "type"}),
    "joint": frozenset({"name", "type"}),
    "origin": frozenset({"xyz", "rpy"}),
    "parent": frozenset({"link"}),
    "child": frozenset({"link"}),
    "axis": frozenset({"xyz"}),
    "limit": frozenset({"lower", "upper", "effort", "velocity"}),
    "dynamics": frozenset({"damping", "friction"}),
    "mimic": frozenset({"joint", "multiplier", "offset"}),
    "safety_controller": frozenset({"soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"}),
    "calibration": frozenset({"rising", "falling", "reference_position"}),
    "inertial": frozenset(),
    "mass": frozenset({"value"}),
    "inertia": frozenset({"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}),
    "visual": frozenset({"name"}),
    "collision": frozenset({"name"}),
    "geometry": frozenset(),
    "box": frozenset({"size"}),
    "cylinder": frozenset({"radius", "length"}),
    "capsule": frozenset({"radius", "length"}),
    "sphere": frozenset({"radius"}),
    "mesh": frozenset({"filename", "scale"}),
    "material": frozenset({"name"}),
    "color": frozenset({"rgba"}),
    "texture": frozenset({"filename"}),
    "gazebo": frozenset({"reference"}),
}
"""Attributes the URDF loader reads (or knowingly accepts) on each element it interprets.

``link type`` and ``robot version`` come from the URDF spec/urdfdom and carry nothing to simulate.
Namespaced attributes (``xsi:schemaLocation``, ``{ns}...``) and namespace declarations are
extensions and never reported.
"""

_WALKED: dict[str, frozenset[str]] = {
    "robot": frozenset({"link", "joint", "material", "gazebo"}),
    "geometry": frozenset({"box", "cylinder", "capsule", "sphere", "mesh"}),
    **{k: v for k, v in _CHILDREN.items()},
}
"""Children whose attributes are checked, per element (raw blocks such as plugins are not)."""


def _check_attributes(root: etree._Element, reader: _Reader) -> None:
    """ATTRIBUTE_UNSUPPORTED warnings for attributes the loader ignores on elements it reads."""
    found: dict[tuple[str, str], list[etree._Element]] = {}
    stack = [root]
    while stack:
        element = stack.pop()
        tag = local_name(element)
        known = _ATTRIBUTES.get(tag)
        if known is not None:
            for raw in element.attrib:
                attr = str(raw)
                if attr != LOCATION_ATTRIBUTE and not attr.startswith("{") and attr not in known:
                    found.setdefault((tag, attr), []).append(element)
        walked = _WALKED.get(tag, frozenset())
        stack.extend(reversed([c for c in child_elements(element) if local_name(c) in walked]))
    # one warning per (element, attribute), at its first use: vendor attributes repeat on every joint
    for (tag, attr), elements in found.items():
        more = f" (and on {len(elements) - 1} more <{tag}>)" if len(elements) > 1 else ""
        reader.warn(
            ErrorCode.ATTRIBUTE_UNSUPPORTED,
            f'attribute {attr}="{elements[0].get(attr)}" of <{tag}> is not supported and is ignored{more}',
            elements[0],
        )


# --------------------------------------------------------------------------- structure
def _check_structure(doc: _Document, reader: _Reader) -> None:
    """Parents and children exist, one parent per link, no loops, one root."""
    parent_of: dict[str, Joint] = {}
    for joint in doc.joints.values():
        loc = joint.location
        if joint.parent not in doc.links and joint.parent != "world":
            reader.sink.error(
                ErrorCode.JOINT_PARENT_INVALID, f"joint '{joint.name}' has unknown parent link '{joint.parent}'", loc
            )
        if joint.child not in doc.links:
            reader.sink.error(
                ErrorCode.JOINT_CHILD_INVALID, f"joint '{joint.name}' has unknown child link '{joint.child}'", loc
            )
            continue
        if joint.child == joint.parent:
            reader.sink.error(
                ErrorCode.KINEMATIC_LOOP, f"joint '{joint.name}' connects link '{joint.child}' to itself", loc
            )
            continue
        if joint.child in parent_of:
            other = parent_of[joint.child]
            reader.sink.error(
                ErrorCode.JOINT_CHILD_INVALID,
                f"link '{joint.child}' has two parents: joint '{other.name}' ({other.location})"
                f" and joint '{joint.name}'",
                loc,
            )
            continue
        parent_of[joint.child] = joint
    _check_loops(doc, parent_of, reader)
    for joint in doc.joints.values():
        if joint.mimic is not None and joint.mimic.joint not in doc.joints:
            reader.sink.warning(
                ErrorCode.ATTRIBUTE_INVALID,
                f"joint '{joint.name}' mimics unknown joint '{joint.mimic.joint}'",
                joint.location,
            )
    roots = [draft for name, draft in doc.links.items() if name not in parent_of]
    if len(roots) > 1:
        names = ", ".join(f"'{r.name}'" for r in roots)
        reader.sink.error(
            ErrorCode.MULTIPLE_ROOTS,
            f"robot '{doc.name}' has {len(roots)} root links ({names}); connect them with joints into one tree",
            roots[1].location,
        )
    if not doc.links and doc.joints:
        reader.sink.error(
            ErrorCode.LINK_MISSING,
            f"robot '{doc.name}' has {len(doc.joints)} joint(s) but no links",
            next(iter(doc.joints.values())).location,
        )


def _check_loops(doc: _Document, parent_of: dict[str, Joint], reader: _Reader) -> None:
    """Report each cycle of the child -> parent relation once."""
    done: set[str] = set()
    for start in doc.links:
        path: list[str] = []
        node: str | None = start
        while node is not None and node not in done and node not in path:
            path.append(node)
            joint = parent_of.get(node)
            node = joint.parent if joint is not None else None
        if node is not None and node in path:
            cycle = path[path.index(node) :]
            chain = " -> ".join(f"'{n}'" for n in [*reversed(cycle), cycle[-1]])
            reader.sink.error(ErrorCode.KINEMATIC_LOOP, f"kinematic loop: {chain}", parent_of[cycle[0]].location)
        done.update(path)


# --------------------------------------------------------------------------- massless links (sdformat's rule)
def _has_mass(draft: _LinkDraft) -> bool:
    raw = draft.inertial
    return raw is not None and raw.mass is not None and raw.mass > 0


def _drop_massless_links(doc: _Document, reader: _Reader) -> None:
    """Leave out what Gazebo leaves out, as sdformat's URDF conversion does.

    Fixed joints are reduced first: a link fixed to its parent merges into it, massless or not, and
    a link's mass includes everything fixed below it. Then a link that still has no mass (no
    ``<inertial>``, or mass 0), reached by a moving joint or being the root, is not modelled: it
    is dropped with its parent joint and every link below it, with a warning. Its mass is never
    made up from its collision volume (that tripled Husky's mass). Static robots keep every link.
    """
    children: dict[str, list[Joint]] = {}
    parent_of: dict[str, Joint] = {}
    for j in doc.joints.values():
        children.setdefault(j.parent, []).append(j)
        parent_of[j.child] = j
    lumped: dict[str, bool] = {}
    order: list[str] = []
    stack = [name for name in doc.links if name not in parent_of]
    while stack:  # a pre-order walk, iterative (5,000-link chains)
        name = stack.pop()
        order.append(name)
        stack.extend(j.child for j in children.get(name, []) if j.child in doc.links)
    for name in reversed(order):  # children before parents
        lumped[name] = _has_mass(doc.links[name]) or any(
            lumped.get(j.child, False) for j in children.get(name, []) if j.type is JointType.FIXED
        )
    dropped: set[str] = set()
    for name in order:
        if name in dropped:
            continue
        up = parent_of.get(name)
        merged = up is not None and up.type is JointType.FIXED and up.parent not in dropped
        if merged or lumped[name]:
            continue
        below: list[str] = []
        todo = [j.child for j in children.get(name, [])]
        while todo:
            child = todo.pop()
            below.append(child)
            todo.extend(j.child for j in children.get(child, []))
        dropped.update([name, *below])
        what = f"its joint '{up.name}'" if up is not None else "it is the root"
        tail = (
            f" and the {len(below)} link(s) below it ({', '.join(below[:4])}{', ...' if len(below) > 4 else ''})"
            if below
            else ""
        )
        reader.sink.warning(
            ErrorCode.INERTIA_MISSING,
            f"link '{name}' has no <inertial> with mass > 0 (nor has anything fixed to it): Gazebo does not model "
            f"it; it is left out ({what}){tail}",
            doc.links[name].location,
        )
    if dropped:
        for name in dropped:
            del doc.links[name]
        doc.joints = {k: j for k, j in doc.joints.items() if j.child not in dropped and j.parent not in dropped}


# --------------------------------------------------------------------------- finishing links
def _finish_link(draft: _LinkDraft, movable_by: str | None, reader: _Reader, derive: bool) -> Link:
    """The frozen :class:`Link`: ``<gazebo>`` applied and the inertial settled."""
    collisions = tuple(
        dataclasses.replace(c, surface=dataclasses.replace(c.surface, **draft.surface)) for c in draft.collisions
    )
    visuals = tuple(_apply_gazebo_material(v, draft.gazebo_material) for v in draft.visuals)
    return Link(
        name=draft.name,
        inertial=_settle_inertial(draft, movable_by, reader, derive),
        visuals=visuals,
        collisions=collisions,
        sensors=tuple(draft.sensors),
        gravity=draft.flags.get("gravity", True),
        kinematic=draft.flags.get("kinematic", False),
        self_collide=draft.flags.get("self_collide"),
        location=draft.location,
    )


def _apply_gazebo_material(visual: Visual, script: str | None) -> Visual:
    if script is None:
        return visual
    diffuse = _GAZEBO_COLORS.get(script) or (visual.material.diffuse if visual.material else None)
    base = visual.material or Material()
    return dataclasses.replace(visual, material=dataclasses.replace(base, name=script, diffuse=diffuse))


def _settle_inertial(draft: _LinkDraft, movable_by: str | None, reader: _Reader, derive: bool) -> Inertial | None:
    """The link's inertial; derived (with a warning per problem) when invalid, or when missing and ``derive``
    (a robot with no mass at all); otherwise a missing one stays missing (see :func:`_drop_massless_links`)."""
    raw = draft.inertial
    if raw is not None and not raw.problems and raw.mass is not None and raw.tensor is not None:
        ixx, ixy, ixz, iyy, iyz, izz = raw.tensor
        return Inertial(raw.mass, raw.pose, ixx, ixy, ixz, iyy, iyz, izz)
    if raw is None and not derive:
        return None  # massless: merged into its parent, or carried by what is fixed to it
    if raw is None and not draft.collisions:
        if movable_by is None:
            return None  # a pure frame (base_footprint, sensor frames)
        inertial = _inertia.default_inertial()
        problems = [
            (ErrorCode.INERTIA_MISSING, f"has no <inertial> but moves with joint '{movable_by}'", draft.location)
        ]
        remedy = f"using a placeholder mass of {inertial.mass:g} kg"
    else:
        mass = raw.mass if raw is not None else None
        problems = (
            raw.problems
            if raw is not None
            else [(ErrorCode.INERTIA_MISSING, "has collision geometry but no <inertial>", draft.location)]
        )
        inertial, remedy = _derive(draft, mass)
    for code, text, loc in problems:
        reader.sink.warning(code, f"link '{draft.name}': {text}; {remedy}", loc)
    return inertial


def _derive(draft: _LinkDraft, mass: float | None) -> tuple[Inertial, str]:
    """Inertia from the collision shapes (mass from volume when ``mass`` is None) and a note saying how."""
    result = _inertia.inertia_from_geometries([(c.geometry, c.pose) for c in draft.collisions], mass)
    if result is None:
        inertial = _inertia.default_inertial(mass)
        why = "no collision shape has a volume" if draft.collisions else "the link has no collision geometry"
        return inertial, f"{why}, using mass {inertial.mass:g} kg with a placeholder inertia"
    inertial = result.inertial
    how = f"inertia derived from {len(draft.collisions)} collision shape(s)"
    if result.mass_from_volume:
        how += (
            f", mass {inertial.mass:.4g} kg from volume {result.volume:.4g} m^3 at {_inertia.DEFAULT_DENSITY:g} kg/m^3"
        )
    if result.notes:
        how += " (" + "; ".join(result.notes) + ")"
    return inertial, how


# --------------------------------------------------------------------------- entry point
def parse_urdf(
    text: str,
    *,
    source: str,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
    base_dir: str | None,
) -> Model | None:
    """Parse URDF text into a :class:`Model`.

    Args:
        text: the URDF (possibly produced by :mod:`._xacro`, with location annotations).
        source: file name used in diagnostics.
        sink: receives every diagnostic.
        resolver: resolves ``package://`` and friends for meshes.
        base_dir: folder that relative mesh paths are relative to.

    Returns:
        The model, or None when an error was reported.
    """
    root = parse_xml(text, source=source, sink=sink)
    if root is None:
        return None
    reader = _Reader(source, sink, resolver, base_dir)
    if local_name(root) != "robot":
        reader.error(
            ErrorCode.ROOT_ELEMENT_INVALID, f"root element is <{local_name(root)}>; a URDF must have <robot>", root
        )
        return None
    _check_attributes(root, reader)
    doc = reader.document(root)
    # Warnings promoted by strict mode do not stop the structure checks: only real errors do.
    if doc is None or sink.has_hard_errors:
        return None
    _check_structure(doc, reader)
    if sink.has_hard_errors:
        return None
    if not doc.links:
        _report_fragment(root, doc, reader)
    derive = False
    if doc.links and not doc.model_flags.get("static", False):
        if any(_has_mass(d) for d in doc.links.values()):
            _drop_massless_links(doc, reader)
        else:
            # Gazebo would model none of it (moveit_resources' Panda, kinematics-only descriptions):
            # here each link gets an inertia from its collision shapes, with a warning per link
            derive = True
    movers = {j.child: j.name for j in doc.joints.values() if j.type is not JointType.FIXED}
    links = tuple(_finish_link(d, movers.get(d.name), reader, derive) for d in doc.links.values())
    if sink.has_errors:
        return None  # strict mode: warnings were promoted, every one of them is reported
    return Model(
        name=doc.name,
        links=links,
        joints=tuple(doc.joints.values()),
        plugins=tuple(doc.plugins),
        gazebo=tuple(doc.gazebo),
        static=doc.model_flags.get("static", False),
        self_collide=doc.model_flags.get("self_collide", False),
        source_format="urdf",
        source_file=source,
        location=reader.loc(root),
        transmissions=tuple(doc.transmissions),
        ros2_control=tuple(rc for rc in (reader.ros2_control(el, doc) for el in doc.ros2_control) if rc is not None),
    )

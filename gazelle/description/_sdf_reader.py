"""The SDF loader's reading layer: the workspace (sink and resolver) and the document being read, the model
being built, and the free functions that read values (numbers, vectors, poses, colours, flags), names, plugins
and URIs, each reporting a bad value at its file:line, as Drake's ``detail_sdf_parser.cc`` reads SDF with free
functions given its ``ParsingWorkspace``. :mod:`._sdf_parts` reads links, shapes, joints and lights with them,
:mod:`._sdf_model` models and includes, :mod:`._sdf_world` worlds, and :mod:`._sdf` the document."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import overload

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._model import ConfigElement, Frame, Joint, JointType, Link, Plugin, Sensor
from ._pose import IDENTITY, RGBA, Pose, Vec3
from ._resources import ResourceResolver
from ._sdf_frames import ScopeFrames
from ._sdf_text import decode_config, decode_name, prepare
from ._xml import (
    child_elements,
    element_location,
    local_name,
    parse_bool,
    parse_float,
    parse_floats,
    parse_xml,
    to_config,
)

Version = tuple[int, int]

MIN_VERSION: Version = (1, 2)
"""Oldest SDF version read (1.0 used a different structure that libsdformat no longer reads)."""
MAX_VERSION: Version = (1, 11)
"""Newest SDF version read; newer files are an error (their semantics may differ)."""
MAX_NESTING = 32
"""Deepest chain of nested models and includes (guards include cycles)."""

IGNORED: dict[str, frozenset[str]] = {
    # Elements that have no effect in gazelle (rendering details, solver settings of other
    # engines, bookkeeping): skipped without a warning. Keyed by the parent element.
    #
    # ODE's bookkeeping: bodies never sleep in MuJoCo, and no wind system runs
    "model": frozenset({"allow_auto_disable", "enable_wind"}),
    "link": frozenset({"enable_wind", "must_be_base_link", "visual_groups"}),
    # laser_retro is a lidar's intensity hint (gazelle's rays report a constant intensity); max_contacts caps
    # ODE's contact points (MuJoCo makes its own); density and auto_inertia_params only tune SDF 1.11's
    # automatic inertia, which gazelle derives at its own default density
    "collision": frozenset({"laser_retro", "max_contacts", "density", "auto_inertia_params"}),
    # how a visual is drawn, not what it is: cameras and the viewer draw the geometry and its colour
    "visual": frozenset({"cast_shadows", "transparency", "laser_retro", "meta", "visibility_flags"}),
    "material": frozenset({"lighting", "shader", "double_sided", "render_order"}),
    "script": frozenset({"uri"}),  # the OGRE material file: the material is kept by its <name>
    "inertial": frozenset(),
    "surface": frozenset(),
    "friction": frozenset(),
    "friction_ode": frozenset(),
    # the contact patch of ODE's torsional friction: MuJoCo's torsional friction has its own patch model
    "torsional": frozenset({"use_patch_radius", "patch_radius", "surface_radius", "ode"}),
    "bullet_friction": frozenset({"fdir1"}),
    # other engines' contact models (Bullet's, DART's elastic ones)
    "contact": frozenset({"bullet", "collide_without_contact_bitmask", "poissons_ratio", "elastic_modulus"}),
    "contact_ode": frozenset(),
    "bounce": frozenset({"threshold"}),  # restitution itself is warned about: MuJoCo contacts do not bounce
    # per-engine joint settings, and the gearbox joint (which is refused where it is declared)
    "joint": frozenset({"physics", "gearbox_ratio", "gearbox_reference_body"}),
    "axis": frozenset({"initial_position"}),
    # the stiffness and damping of a joint's stop: MuJoCo's limit constraint has its own
    "limit": frozenset({"stiffness", "dissipation"}),
    "world": frozenset(),
    # the other engines' solver blocks: the engine is always MuJoCo; magnetic_field is read at the world level
    "physics": frozenset({"ode", "bullet", "dart", "simbody", "max_contacts", "magnetic_field"}),
    # rendering extras the viewer and cameras do not draw
    "scene": frozenset({"sky", "fog", "origin_visual"}),
    "light": frozenset({"spot", "intensity", "visualize", "light_on"}),
    "attenuation": frozenset({"constant", "linear", "quadratic"}),
    "include": frozenset(),
}
"""Known elements skipped on purpose, per parent; see the module docstring."""

_USED: dict[str, frozenset[str]] = {
    # What gazelle reads, per parent: an element in neither table is warned about with its file:line
    # (ELEMENT_UNSUPPORTED), so nothing a user wrote is dropped silently
    "model": frozenset({"static", "self_collide", "pose", "link", "joint", "frame", "model", "include", "plugin"}),
    "link": frozenset({"pose", "inertial", "collision", "visual", "sensor", "gravity", "kinematic", "self_collide"}),
    "collision": frozenset({"pose", "geometry", "surface"}),
    "visual": frozenset({"pose", "geometry", "material"}),
    "material": frozenset({"ambient", "diffuse", "specular", "emissive", "script", "pbr"}),
    "script": frozenset({"name"}),
    "inertial": frozenset({"mass", "pose", "inertia", "inertial"}),
    "surface": frozenset({"friction", "contact", "bounce"}),
    "friction": frozenset({"ode", "torsional", "bullet"}),
    "friction_ode": frozenset({"mu", "mu2", "fdir1", "slip1", "slip2"}),
    "torsional": frozenset({"coefficient"}),
    "bullet_friction": frozenset({"friction", "friction2", "rolling_friction"}),
    "contact": frozenset({"ode", "collide_bitmask", "collide_without_contact"}),
    "contact_ode": frozenset({"kp", "kd", "min_depth", "max_vel", "soft_cfm", "soft_erp"}),
    "bounce": frozenset({"restitution_coefficient"}),
    "joint": frozenset({"parent", "child", "pose", "axis", "axis2", "thread_pitch", "screw_thread_pitch", "sensor"}),
    "axis": frozenset({"xyz", "limit", "dynamics", "use_parent_model_frame", "mimic"}),
    "limit": frozenset({"lower", "upper", "effort", "velocity"}),
    "world": frozenset(
        {
            "gravity",
            "physics",
            "scene",
            "light",
            "model",
            "include",
            "plugin",
            "frame",
            "spherical_coordinates",
            "magnetic_field",
            "state",
        }
    ),
    "spherical_coordinates": frozenset(
        {"surface_model", "world_frame_orientation", "latitude_deg", "longitude_deg", "elevation", "heading_deg"}
    ),
    "physics": frozenset({"max_step_size", "real_time_factor", "real_time_update_rate", "gravity", "update_rate"}),
    "scene": frozenset({"ambient", "background", "shadows", "grid"}),
    "light": frozenset({"pose", "diffuse", "specular", "direction", "cast_shadows", "attenuation"}),
    "attenuation": frozenset({"range"}),
    "include": frozenset({"uri", "name", "pose", "static", "placement_frame", "plugin"}),
}

_JOINT_TYPES = {
    "revolute": JointType.REVOLUTE,
    "continuous": JointType.CONTINUOUS,
    "prismatic": JointType.PRISMATIC,
    "fixed": JointType.FIXED,
    "ball": JointType.BALL,
    "universal": JointType.UNIVERSAL,
    "screw": JointType.SCREW,
    "revolute2": JointType.UNIVERSAL,  # two hinges on two axes: loaded as a universal joint, with a warning
}
_AXIS_JOINTS = {JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC, JointType.SCREW, JointType.UNIVERSAL}
_UNLIMITED = 1e15
"""|limit| at or beyond this (SDF's default is ±1e16) means no limit."""
_VERSION_RE = re.compile(r"^\s*(\d+)\.(\d+)\s*$")


def _tag(element: etree._Element) -> str:
    return decode_name(local_name(element))


def _find(element: etree._Element, tag: str) -> etree._Element | None:
    """The first child element of ``element`` with local name ``tag`` (namespaces ignored), or None."""
    for child in child_elements(element):
        if _tag(child) == tag:
            return child
    return None


def _findall(element: etree._Element, tag: str) -> list[etree._Element]:
    return [c for c in child_elements(element) if _tag(c) == tag]


def parse_version(text: str | None) -> Version | None:
    """``"1.8"`` → ``(1, 8)``; None if it is not ``major.minor``."""
    m = _VERSION_RE.match(text or "")
    return (int(m.group(1)), int(m.group(2))) if m else None


@dataclass
class _Doc:
    """One SDF file being read."""

    source: str
    """The file's path, or a synthetic name (``<string>``) for a description that arrived as text."""
    base_dir: Path | None
    """The folder relative URIs resolve against; None for a string, which has none."""
    version: Version
    """The file's ``<sdf version>``: what changes with it (pose frames before 1.7, axis frames before 1.5, name
    scoping) is read the way that version defines it."""
    renamed: bool
    """Whether names were rewritten by :func:`prepare` (configs need decoding)."""


@dataclass
class _Built:
    """A parsed model before it is placed: everything in its own model frame."""

    name: str
    """The model's name (an ``<include><name>`` overrides the file's)."""
    static: bool
    """``<static>``: welded to the world."""
    self_collide: bool
    """``<self_collide>``: its links collide with one another."""
    pose: Pose
    """The model's ``<pose>``, in ``relative_to``'s frame."""
    relative_to: str | None
    """The frame the pose is in (None: the parent's frame, the world at the top level)."""
    placement_frame: str | None
    """``<placement_frame>``: the frame of the model that ``pose`` places (SDF 1.8), instead of the model frame."""
    canonical: str | None
    """``<canonical_link>``, else the first link: the link the model frame is attached to."""
    links: list[Link] = field(default_factory=list)
    """Every link, nested models' included (their names scoped ``child::link``)."""
    joints: list[Joint] = field(default_factory=list)
    """Every joint, nested models' included."""
    world_joints: dict[str, Pose] = field(default_factory=dict)
    """X_MJ of joints whose parent is ``world`` (their origin needs the model's world pose)."""
    frames: list[Frame] = field(default_factory=list)
    """Every ``<frame>``."""
    plugins: list[Plugin] = field(default_factory=list)
    """The model's plugins (an include's too)."""
    joint_sensors: dict[str, list[Sensor]] = field(default_factory=dict)
    """Child link name -> the sensors of joints above it (force_torque)."""
    exported: ScopeFrames = field(default_factory=ScopeFrames)
    """The frames a parent scope may refer to (``child::link``, ``child::frame``) when this model is nested."""
    doc: _Doc | None = None
    """The document the model was read from."""
    location: SourceLocation | None = None
    """Where the ``<model>`` is written (file:line)."""


@dataclass
class Workspace:
    """What every reader function shares while one description loads, as Drake's ``ParsingWorkspace`` is passed to
    the free functions of ``detail_sdf_parser.cc``: where problems go, and how URIs resolve (the resolver grows as
    the folders of included models are trusted)."""

    sink: DiagnosticSink
    """Receives every diagnostic, with file:line."""
    resolver: ResourceResolver
    """Finds ``model://``, ``package://`` and ``file://`` URIs."""
    missing_models: set[str] = field(default_factory=set)
    """The ``model://`` names found nowhere that were already reported (one error line per model, not per file)."""


# The readers of values into the description model, each reporting a bad value into ``ws.sink``.


# ================================================================== documents
def read_document(ws: Workspace, text: str, source: str, base_dir: Path | None) -> tuple[etree._Element, _Doc] | None:
    """Parse text into its root and the document context, checking the version.

    The text is first prepared (``_sdf_text.prepare``: a byte-order mark or blank lines before the XML
    declaration removed, names with a ``:`` that XML would take for a namespace prefix encoded), with
    line numbers unchanged, so every later message still points at the user's line. The root must be
    ``<sdf version>`` (or Gazebo 1.x's ``<gazebo version="1.2">``), from SDF 1.2 to the newest version
    gazelle reads: the version decides how poses and joint axes are read (see the module docstring of
    ``_sdf``). The version is never guessed: a file without one, or of a version outside that range, is
    refused with the reason at the root's line."""
    prepared, renamed = prepare(text)
    root = parse_xml(prepared, source=source, sink=ws.sink)
    if root is None:
        return None
    tag = _tag(root)
    loc = element_location(root, source)
    if tag not in ("sdf", "gazebo"):  # <gazebo version="1.2">: Gazebo 1.x's worlds, read as SDF 1.2
        ws.sink.error(ErrorCode.ROOT_ELEMENT_INVALID, f"root element must be <sdf>, got <{tag}>", loc)
        return None
    raw = root.get("version")
    if raw is None:
        ws.sink.error(ErrorCode.ATTRIBUTE_MISSING, f"<{tag}> has no 'version' attribute", loc)
        return None
    version = parse_version(raw)
    if version is None or not (MIN_VERSION <= version <= MAX_VERSION):
        ws.sink.error(
            ErrorCode.SDF_VERSION_UNSUPPORTED,
            f"SDF version '{raw}' is not supported (supported: "
            f"{MIN_VERSION[0]}.{MIN_VERSION[1]} to {MAX_VERSION[0]}.{MAX_VERSION[1]})",
            loc,
        )
        return None
    return root, _Doc(source, base_dir, version, renamed)


def warn_extra(ws: Workspace, element: etree._Element, doc: _Doc, why: str) -> None:
    """Warn that ``element`` is left out, and why (a second ``<world>``, a second shape in one ``<geometry>``)."""
    ws.sink.warning(ErrorCode.ELEMENT_UNSUPPORTED, f"<{_tag(element)}> ignored: {why}", location_of(element, doc))


# ================================================================== small helpers
def location_of(element: etree._Element, doc: _Doc) -> SourceLocation:
    """Where ``element`` is written (file:line), for a diagnostic."""
    return element_location(element, doc.source)


def read_config(element: etree._Element, doc: _Doc) -> ConfigElement:
    """``element`` as a read-only configuration tree for a plugin or sensor to read, with names restored where
    :func:`prepare` rewrote them."""
    cfg = to_config(element, doc.source)
    return decode_config(cfg) if doc.renamed else cfg


def warn_unsupported(ws: Workspace, element: etree._Element, doc: _Doc, parent: str) -> None:
    """Warn of an element gazelle does not read, with its file:line: nothing a user wrote is dropped silently."""
    ws.sink.warning(
        ErrorCode.ELEMENT_UNSUPPORTED,
        f"<{_tag(element)}> in <{parent}> is not supported and is ignored",
        location_of(element, doc),
    )


def check_children(ws: Workspace, element: etree._Element, doc: _Doc, kind: str, parent: str | None = None) -> None:
    """Warn about every child of ``element`` that is neither used nor ignored on purpose."""
    used = _USED.get(kind, frozenset())
    ignored = IGNORED.get(kind, frozenset())
    for child in child_elements(element):
        tag = _tag(child)
        if tag in used or tag in ignored or ":" in tag:
            continue
        warn_unsupported(ws, child, doc, parent or kind)


def read_name(ws: Workspace, element: etree._Element, doc: _Doc) -> str | None:
    """The element's required ``name``, stripped; an error (and None) when it is missing or empty."""
    value = element.get("name")
    if value is None or not value.strip():
        ws.sink.error(
            ErrorCode.ATTRIBUTE_MISSING,
            f"<{_tag(element)}> is missing the required 'name' attribute",
            location_of(element, doc),
        )
        return None
    return value.strip()


def read_unique_name(
    ws: Workspace, element: etree._Element, doc: _Doc, seen: set[str], label: str, owner: str
) -> str | None:
    """The name of ``element`` when it is new in ``seen`` (added to it); None when it has none (reported by
    :func:`read_name`) or ``label`` '...' is already used in ``owner``, an error at its line, as sdformat refuses
    a second sibling of one name (Gazebo addresses each by its scoped name, so the second would be lost)."""
    name = read_name(ws, element, doc)
    if name is None:
        return None
    if name in seen:
        ws.sink.error(ErrorCode.DUPLICATE_NAME, f"{label} '{name}' is used twice in {owner}", location_of(element, doc))
        return None
    seen.add(name)
    return name


def child_text(element: etree._Element, tag: str) -> str | None:
    """The stripped text of child ``tag``; None when it is absent."""
    child = _find(element, tag)
    return None if child is None else (child.text or "").strip()


def read_number(ws: Workspace, element: etree._Element | None, tag: str, default: float, doc: _Doc) -> float:
    """A finite number child; the default when absent; an error (and the default) when malformed.

    sdformat reports a number it cannot parse as an error too; gazelle reports it at its line and carries
    on with the default, so each slip in a file is named in one pass instead of one per run. NaN and
    infinities count as malformed: MuJoCo would accept them and the simulation would fail later, far from
    the line that caused it."""
    if element is None:
        return default
    child = _find(element, tag)
    if child is None:
        return default
    value = parse_float(child.text)
    if value is None:
        ws.sink.error(
            ErrorCode.VALUE_INVALID,
            f"<{tag}> must be a number, got {(child.text or '').strip()!r}",
            location_of(child, doc),
        )
        return default
    return value


def read_opt_number(ws: Workspace, element: etree._Element | None, tag: str, doc: _Doc) -> float | None:
    """The number in child ``tag``; None when the child is absent or not a number (the latter reported)."""
    if element is None or _find(element, tag) is None:
        return None
    value = read_number(ws, element, tag, math.nan, doc)
    return None if math.isnan(value) else value


def read_vector(
    ws: Workspace, element: etree._Element | None, tag: str, count: int, default: tuple[float, ...] | None, doc: _Doc
) -> tuple[float, ...] | None:
    """``count`` numbers from a child; default when absent; error + default when malformed (see
    :func:`read_number`). The count is SDF's type for the element (3 for a vector3, 2 for a vector2d); colours
    have their own reader, :func:`read_color`, which takes RGB as opaque RGBA."""
    if element is None:
        return default
    child = _find(element, tag)
    if child is None:
        return default
    values = parse_floats(child.text, count)
    if values is None:
        ws.sink.error(
            ErrorCode.VALUE_INVALID,
            f"<{tag}> must be {count} numbers, got {(child.text or '').strip()!r}",
            location_of(child, doc),
        )
        return default
    return values


@overload
def read_vec3(ws: Workspace, element: etree._Element | None, tag: str, default: Vec3, doc: _Doc) -> Vec3: ...
@overload
def read_vec3(ws: Workspace, element: etree._Element | None, tag: str, default: None, doc: _Doc) -> Vec3 | None: ...
def read_vec3(ws: Workspace, element: etree._Element | None, tag: str, default: Vec3 | None, doc: _Doc) -> Vec3 | None:
    """Three numbers from a child (a vector, a size, a scale); :func:`read_vector`'s rules."""
    v = read_vector(ws, element, tag, 3, default, doc)
    return None if v is None else (v[0], v[1], v[2])


def read_flag(ws: Workspace, element: etree._Element | None, tag: str, default: bool, doc: _Doc) -> bool:
    """The boolean in child ``tag`` (true/false/1/0); ``default`` when absent, and with an error naming the text
    when it is neither."""
    if element is None:
        return default
    child = _find(element, tag)
    if child is None:
        return default
    value = parse_bool(child.text)
    if value is None:
        ws.sink.error(
            ErrorCode.VALUE_INVALID,
            f"<{tag}> must be true/false/1/0, got {(child.text or '').strip()!r}",
            location_of(child, doc),
        )
        return default
    return value


def read_color(ws: Workspace, element: etree._Element | None, tag: str, doc: _Doc) -> RGBA | None:
    """An RGBA colour (RGB accepted, alpha 1); None when absent or malformed."""
    if element is None:
        return None
    child = _find(element, tag)
    if child is None:
        return None
    values = parse_floats(child.text)
    if values is None or len(values) not in (3, 4):
        ws.sink.error(
            ErrorCode.VALUE_INVALID,
            f"<{tag}> must be 3 or 4 numbers (RGBA), got {(child.text or '').strip()!r}",
            location_of(child, doc),
        )
        return None
    return (values[0], values[1], values[2], values[3] if len(values) == 4 else 1.0)  # RGB: opaque


def read_pose(ws: Workspace, element: etree._Element | None, doc: _Doc) -> tuple[Pose, str | None]:
    """The ``<pose>`` child of ``element`` and its ``relative_to`` (None = the default)."""
    child = None if element is None else _find(element, "pose")
    if child is None:
        return IDENTITY, None
    relative_to = child.get("relative_to")
    if relative_to is None and (1, 5) <= doc.version < (1, 7):
        # SDF 1.5 and 1.6 spelled it <pose frame="...">; 1.7 renamed it relative_to and gave it the frame
        # graph's semantics, which the frame attribute's few users meant anyway
        relative_to = child.get("frame")
    relative_to = (relative_to or "").strip() or None
    text = (child.text or "").strip()
    if not text:
        return IDENTITY, relative_to
    # SDF 1.9: rotation_format="euler_rpy" (the default: x y z roll pitch yaw, fixed axes, radians unless
    # degrees="true") or "quat_xyzw" (x y z qx qy qz qw, normalised here as libsdformat does)
    fmt = (child.get("rotation_format") or "euler_rpy").strip()
    degrees = parse_bool(child.get("degrees") or "false")
    loc = location_of(child, doc)
    if degrees is None:
        ws.sink.error(
            ErrorCode.ATTRIBUTE_INVALID, f"pose 'degrees' must be true/false, got {child.get('degrees')!r}", loc
        )
        degrees = False
    if fmt == "euler_rpy":
        values = parse_floats(text, 6)
        if values is None:
            ws.sink.error(
                ErrorCode.VALUE_INVALID, f"<pose> must be 6 numbers 'x y z roll pitch yaw', got {text!r}", loc
            )
            return IDENTITY, relative_to
        scale = math.pi / 180.0 if degrees else 1.0
        rpy = (values[3] * scale, values[4] * scale, values[5] * scale)
        return Pose.from_xyz_rpy((values[0], values[1], values[2]), rpy), relative_to
    if fmt == "quat_xyzw":
        values = parse_floats(text, 7)
        if values is None:
            ws.sink.error(ErrorCode.VALUE_INVALID, f"<pose> must be 7 numbers 'x y z qx qy qz qw', got {text!r}", loc)
            return IDENTITY, relative_to
        qx, qy, qz, qw = values[3:]  # the file's order is xyzw; gazelle's quaternions are wxyz
        norm = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
        if not norm > 1e-9:
            ws.sink.error(ErrorCode.VALUE_INVALID, "<pose> quaternion has zero length", loc)
            return IDENTITY, relative_to
        xyz = (values[0], values[1], values[2])
        return Pose(xyz, (qw / norm, qx / norm, qy / norm, qz / norm)), relative_to
    ws.sink.error(
        ErrorCode.ATTRIBUTE_INVALID,
        f"pose rotation_format must be 'euler_rpy' or 'quat_xyzw', got {fmt!r}",
        loc,
    )
    return IDENTITY, relative_to


def read_plugin(ws: Workspace, element: etree._Element, doc: _Doc) -> Plugin | None:
    """A ``<plugin>`` kept whole for the systems: its ``name``, ``filename`` (required) and its configuration."""
    loc = location_of(element, doc)
    filename = (element.get("filename") or "").strip()
    if not filename:
        ws.sink.error(ErrorCode.ATTRIBUTE_MISSING, "<plugin> is missing the required 'filename' attribute", loc)
        return None
    return Plugin(
        name=(element.get("name") or "").strip(), filename=filename, config=read_config(element, doc), location=loc
    )


# ================================================================== URIs and includes
def find_model_dir(ws: Workspace, name: str, doc: _Doc) -> Path | None:
    """Folder of model ``name``: the resolver first, then the folder of the current file."""
    found = ws.resolver.find_package(name)
    if found is not None:
        return found
    here = doc.base_dir
    if here is None or not ws.resolver.allowed(here):  # a string has no folder of its own
        return None
    for cand in (here if here.name == name else None, here.parent / name):
        if cand is not None and cand.is_dir() and name not in ("", ".", ".."):
            # a sibling of a model the user pointed at (models/a includes model://b): its files may be read
            ws.resolver = ws.resolver.trusting(cand)
            return cand.resolve()
    return None


def resolve_uri(ws: Workspace, uri: str, doc: _Doc) -> Path | None:
    """A ``model://``, ``package://``, ``file://`` URI or path as a file system path (may not exist)."""
    uri = uri.strip()
    if uri.startswith("model://"):
        name, _, sub = uri[len("model://") :].partition("/")
        root = find_model_dir(ws, name, doc)
        if root is None:
            return None
        # model://name/sub: the model's folder is found by name on the resource roots (Gazebo's
        # GZ_SIM_RESOURCE_PATH search); the rest may not climb out of it (model://a/../../etc), save
        # through a link colcon's --symlink-install made (TurtleBot3's models/turtlebot3_world/meshes)
        return ws.resolver.file_in(root, sub)
    try:
        return ws.resolver.resolve_uri(uri, base_dir=doc.base_dir)
    except (OSError, ValueError):
        return None


def pick_sdf(ws: Workspace, folder: Path, loc: SourceLocation) -> Path | None:
    """The SDF file of a model folder, chosen from its ``model.config`` as sdformat 14 chooses it
    (``parser.cc``, ``getModelFilePath`` and ``getBestSupportedModelVersion``).

    The config is ``model.config``, else the deprecated ``manifest.xml`` (warned). Of its ``<sdf>`` entries,
    the one with the highest ``version`` this reader supports wins, the first of equals; an entry newer than
    that is ignored with sdformat's warning; when no entry has a version gazelle can read (old models often
    give none), the first entry is used, as sdformat does. gazelle is more forgiving in one place: a config it
    cannot read or that names no file falls back to ``model.sdf`` with a warning, where sdformat fails."""
    config = folder / "model.config"
    if not config.is_file() and (folder / "manifest.xml").is_file():
        config = folder / "manifest.xml"
        ws.sink.warning(
            ErrorCode.URI_UNRESOLVED,
            f"{config}: The manifest.xml for a model is deprecated. Please rename manifest.xml to model.config.",
            loc,
        )
    chosen: str | None = None
    if config.is_file():
        try:
            root = etree.fromstring(config.read_bytes(), etree.XMLParser(resolve_entities=False, no_network=True))
        except (etree.XMLSyntaxError, OSError, ValueError):
            root = None
            ws.sink.warning(ErrorCode.URI_UNRESOLVED, f"cannot read {config}; trying model.sdf", loc)
        entries = list(root.iter("sdf")) if root is not None else []
        best: etree._Element | None = entries[0] if entries else None
        best_version: Version = (0, 0)
        for entry in entries:
            version = parse_version(entry.get("version"))
            if version is None or version <= best_version:
                continue
            if version <= MAX_VERSION:
                best, best_version = entry, version
            else:
                ws.sink.warning(
                    ErrorCode.SDF_VERSION_UNSUPPORTED,
                    f"{config}: ignoring version {entry.get('version')} of model '{folder.name}' because it is "
                    f"newer than the SDFormat gazelle reads ({'.'.join(map(str, MAX_VERSION))})",
                    loc,
                )
        chosen = (best.text or "").strip() if best is not None else None
        if root is not None and not chosen:
            ws.sink.warning(ErrorCode.URI_UNRESOLVED, f"{config} names no <sdf> file; trying model.sdf", loc)
    if chosen:
        return folder / chosen
    fallback = folder / "model.sdf"
    return fallback if fallback.is_file() else None

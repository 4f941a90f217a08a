"""SDFormat 1.2–1.11 into the description model (:class:`Model` or :class:`World`).

What the root holds decides what comes back:

* ``<world>`` → :class:`World` (the first one; more are reported and skipped);
* ``<model>`` → :class:`Model`;
* ``<light>`` alone (e.g. the ``sun`` model of the Gazebo model database) → a
  :class:`World` named ``default`` holding just that light, so callers can merge it.

Older files are read the way libsdformat converts them, the visible differences being:

* SDF ≤ 1.4: a joint ``<axis><xyz>`` is expressed in the parent *model* frame
  (libsdformat's 1.4→1.5 converter adds ``use_parent_model_frame=true``);
* SDF 1.5–1.6: in the joint frame unless ``<use_parent_model_frame>``; ``<pose frame=...>``
  acts like ``relative_to``;
* SDF ≥ 1.7: in the joint frame unless ``<xyz expressed_in=...>``;
* ``<gazebo version="1.2">`` is accepted as the root of SDF 1.2 files.

Nested models (and ``<include>`` inside a model) are flattened into their parent with
scoped names (``child::link``) and composed poses. ``JointAxis.xyz`` is always in the
joint frame; ``Joint.origin`` is X_PJ and ``Joint.child_offset`` X_JC.

Every problem is reported into the sink with file:line; see :data:`IGNORED` for the
elements skipped on purpose without a warning (everything else unknown is
``ELEMENT_UNSUPPORTED``). Custom elements with a namespace prefix (``gz:...``) are kept
silently, as libsdformat does.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import overload

from lxml import etree

from ._diagnostics import DiagnosticSink, ErrorCode, SourceLocation
from ._fuel import BUILTIN as FUEL_BUILTIN
from ._fuel import CLASSIC_BUILTIN, FuelModel, cache_roots, find_cached, parse_fuel_uri
from ._inertia import default_inertial, inertia_from_geometries, inertia_problem
from ._model import (
    DEFAULT_MAGNETIC_FIELD,
    IDENTITY,
    RGBA,
    Box,
    Capsule,
    Collision,
    Cone,
    ConfigElement,
    Cylinder,
    Ellipsoid,
    Frame,
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
    Model,
    PhysicsSettings,
    Plane,
    Plugin,
    Pose,
    Scene,
    Sensor,
    Sphere,
    SphericalCoordinates,
    Surface,
    Vec3,
    Visual,
    World,
    quat_conj,
    quat_rotate,
)
from ._resources import ResourceResolver
from ._sdf_frames import FrameNode, Scope, ScopeFrames
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
    "model": frozenset({"allow_auto_disable", "enable_wind"}),
    "link": frozenset({"enable_wind", "must_be_base_link", "visual_groups"}),
    "collision": frozenset({"laser_retro", "max_contacts", "density", "auto_inertia_params"}),
    "visual": frozenset({"cast_shadows", "transparency", "laser_retro", "meta", "visibility_flags"}),
    "material": frozenset({"lighting", "shader", "double_sided", "render_order"}),
    "script": frozenset({"uri"}),
    "inertial": frozenset(),
    "surface": frozenset(),
    "friction": frozenset(),
    "friction_ode": frozenset(),
    "torsional": frozenset({"use_patch_radius", "patch_radius", "surface_radius", "ode"}),
    "bullet_friction": frozenset({"fdir1"}),
    "contact": frozenset({"bullet", "collide_without_contact_bitmask", "poissons_ratio", "elastic_modulus"}),
    "contact_ode": frozenset(),
    "bounce": frozenset({"threshold"}),
    "joint": frozenset({"physics", "gearbox_ratio", "gearbox_reference_body"}),
    "axis": frozenset({"initial_position"}),
    "limit": frozenset({"stiffness", "dissipation"}),
    "world": frozenset(),
    "physics": frozenset({"ode", "bullet", "dart", "simbody", "max_contacts", "magnetic_field"}),
    "scene": frozenset({"sky", "fog", "origin_visual"}),
    "light": frozenset({"spot", "intensity", "visualize", "light_on"}),
    "attenuation": frozenset({"constant", "linear", "quadratic"}),
    "include": frozenset(),
}
"""Known elements skipped on purpose, per parent; see the module docstring."""

_USED: dict[str, frozenset[str]] = {
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
    "revolute2": JointType.UNIVERSAL,
}
_AXIS_JOINTS = {JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC, JointType.SCREW, JointType.UNIVERSAL}
_UNLIMITED = 1e15
"""|limit| at or beyond this (SDF's default is ±1e16) means no limit."""
_VERSION_RE = re.compile(r"^\s*(\d+)\.(\d+)\s*$")


def _tag(element: etree._Element) -> str:
    return decode_name(local_name(element))


def _find(element: etree._Element, tag: str) -> etree._Element | None:
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
    base_dir: Path | None
    """The folder relative URIs resolve against; None for a string, which has none."""
    version: Version
    renamed: bool
    """Whether names were rewritten by :func:`prepare` (configs need decoding)."""


@dataclass
class _Built:
    """A parsed model before it is placed: everything in its own model frame."""

    name: str
    static: bool
    self_collide: bool
    pose: Pose
    relative_to: str | None
    placement_frame: str | None
    canonical: str | None
    links: list[Link] = field(default_factory=list)
    joints: list[Joint] = field(default_factory=list)
    world_joints: dict[str, Pose] = field(default_factory=dict)
    """X_MJ of joints whose parent is ``world`` (their origin needs the model's world pose)."""
    frames: list[Frame] = field(default_factory=list)
    plugins: list[Plugin] = field(default_factory=list)
    joint_sensors: dict[str, list[Sensor]] = field(default_factory=dict)
    """Child link name -> the sensors of joints above it (force_torque)."""
    exported: ScopeFrames = field(default_factory=ScopeFrames)
    doc: _Doc | None = None
    location: SourceLocation | None = None


def parse_sdf(
    text: str,
    *,
    source: str,
    sink: DiagnosticSink,
    resolver: ResourceResolver,
    base_dir: str | None,
) -> Model | World | None:
    """Parse SDF text.

    Args:
        text: the document.
        source: file name used in diagnostics.
        sink: receives every diagnostic.
        resolver: finds ``model://`` and ``package://`` URIs.
        base_dir: folder relative URIs resolve against (None: a string, relative URIs resolve nowhere).

    Returns:
        A :class:`World` (for ``<world>`` or a lone ``<light>``) or a :class:`Model`;
        None when errors prevent building one (they are in ``sink``).
    """
    loader = _Loader(sink, resolver)
    try:
        return loader.load_text(text, source, Path(base_dir) if base_dir is not None else None)
    except RecursionError:
        sink.error(ErrorCode.VALUE_INVALID, "document nests too deeply to be read", SourceLocation(source))
        return None


class _Loader:
    def __init__(self, sink: DiagnosticSink, resolver: ResourceResolver) -> None:
        self.sink = sink
        self.resolver = resolver

    # ================================================================== documents
    def read(self, text: str, source: str, base_dir: Path | None) -> tuple[etree._Element, _Doc] | None:
        """Parse text into its root and the document context, checking the version."""
        prepared, renamed = prepare(text)
        root = parse_xml(prepared, source=source, sink=self.sink)
        if root is None:
            return None
        tag = _tag(root)
        loc = element_location(root, source)
        if tag not in ("sdf", "gazebo"):
            self.sink.error(ErrorCode.ROOT_ELEMENT_INVALID, f"root element must be <sdf>, got <{tag}>", loc)
            return None
        raw = root.get("version")
        if raw is None:
            self.sink.error(ErrorCode.ATTRIBUTE_MISSING, f"<{tag}> has no 'version' attribute", loc)
            return None
        version = parse_version(raw)
        if version is None or not (MIN_VERSION <= version <= MAX_VERSION):
            self.sink.error(
                ErrorCode.SDF_VERSION_UNSUPPORTED,
                f"SDF version '{raw}' is not supported (supported: "
                f"{MIN_VERSION[0]}.{MIN_VERSION[1]} to {MAX_VERSION[0]}.{MAX_VERSION[1]})",
                loc,
            )
            return None
        return root, _Doc(source, base_dir, version, renamed)

    def load_text(self, text: str, source: str, base_dir: Path | None) -> Model | World | None:
        got = self.read(text, source, base_dir)
        if got is None:
            return None
        root, doc = got
        worlds = _findall(root, "world")
        models = _findall(root, "model")
        lights = _findall(root, "light")
        for child in child_elements(root):
            tag = _tag(child)
            if tag not in ("world", "model", "light") and ":" not in tag:
                self.unsupported(child, doc, "sdf")
        if worlds:
            for extra in worlds[1:] + models + lights:
                self.warn_extra(extra, doc, "only the first <world> is loaded")
            return self.world(worlds[0], doc)
        if models:
            for extra in models[1:] + lights:
                self.warn_extra(extra, doc, "only the first <model> is loaded")
            built = self.model(models[0], doc, depth=0)
            if built is None:
                return None
            if built.relative_to not in (None, "world"):
                self.sink.error(
                    ErrorCode.FRAME_INVALID,
                    f"top-level model pose cannot be relative_to '{built.relative_to}'",
                    built.location,
                )
                return None
            pose = built.pose
            if built.placement_frame is not None:
                inner = built.exported.poses.get(built.placement_frame)
                if inner is None:
                    self.sink.error(
                        ErrorCode.FRAME_INVALID,
                        f"placement_frame '{built.placement_frame}' is not a frame of model '{built.name}'",
                        built.location,
                    )
                    return None
                pose = pose * inner.inverse()
            return self.finish_model(built, pose)
        if lights:
            for extra in lights[1:]:
                self.warn_extra(extra, doc, "only the first <light> is loaded")
            light = self.light(lights[0], doc, None)
            if light is None:
                return None
            return World(name="default", lights=(light,), source_file=doc.source, location=self.loc(root, doc))
        self.sink.error(
            ErrorCode.ELEMENT_MISSING,
            "<sdf> holds no <world>, <model> or <light>",
            self.loc(root, doc),
        )
        return None

    def warn_extra(self, element: etree._Element, doc: _Doc, why: str) -> None:
        self.sink.warning(ErrorCode.ELEMENT_UNSUPPORTED, f"<{_tag(element)}> ignored: {why}", self.loc(element, doc))

    # ================================================================== small helpers
    def loc(self, element: etree._Element, doc: _Doc) -> SourceLocation:
        return element_location(element, doc.source)

    def config(self, element: etree._Element, doc: _Doc) -> ConfigElement:
        cfg = to_config(element, doc.source)
        return decode_config(cfg) if doc.renamed else cfg

    def unsupported(self, element: etree._Element, doc: _Doc, parent: str) -> None:
        self.sink.warning(
            ErrorCode.ELEMENT_UNSUPPORTED,
            f"<{_tag(element)}> in <{parent}> is not supported and is ignored",
            self.loc(element, doc),
        )

    def check(self, element: etree._Element, doc: _Doc, kind: str, parent: str | None = None) -> None:
        """Warn about every child of ``element`` that is neither used nor ignored on purpose."""
        used = _USED.get(kind, frozenset())
        ignored = IGNORED.get(kind, frozenset())
        for child in child_elements(element):
            tag = _tag(child)
            if tag in used or tag in ignored or ":" in tag:
                continue
            self.unsupported(child, doc, parent or kind)

    def name(self, element: etree._Element, doc: _Doc) -> str | None:
        value = element.get("name")
        if value is None or not value.strip():
            self.sink.error(
                ErrorCode.ATTRIBUTE_MISSING,
                f"<{_tag(element)}> is missing the required 'name' attribute",
                self.loc(element, doc),
            )
            return None
        return value.strip()

    def text(self, element: etree._Element, tag: str) -> str | None:
        child = _find(element, tag)
        return None if child is None else (child.text or "").strip()

    def number(self, element: etree._Element | None, tag: str, default: float, doc: _Doc) -> float:
        """A finite number child; the default when absent; an error (and the default) when malformed."""
        if element is None:
            return default
        child = _find(element, tag)
        if child is None:
            return default
        value = parse_float(child.text)
        if value is None:
            self.sink.error(
                ErrorCode.VALUE_INVALID,
                f"<{tag}> must be a number, got {(child.text or '').strip()!r}",
                self.loc(child, doc),
            )
            return default
        return value

    def opt_number(self, element: etree._Element | None, tag: str, doc: _Doc) -> float | None:
        if element is None or _find(element, tag) is None:
            return None
        value = self.number(element, tag, math.nan, doc)
        return None if math.isnan(value) else value

    def vector(
        self, element: etree._Element | None, tag: str, count: int, default: tuple[float, ...] | None, doc: _Doc
    ) -> tuple[float, ...] | None:
        """``count`` numbers from a child; default when absent; error + default when malformed."""
        if element is None:
            return default
        child = _find(element, tag)
        if child is None:
            return default
        values = parse_floats(child.text, count)
        if values is None:
            self.sink.error(
                ErrorCode.VALUE_INVALID,
                f"<{tag}> must be {count} numbers, got {(child.text or '').strip()!r}",
                self.loc(child, doc),
            )
            return default
        return values

    @overload
    def vec3(self, element: etree._Element | None, tag: str, default: Vec3, doc: _Doc) -> Vec3: ...
    @overload
    def vec3(self, element: etree._Element | None, tag: str, default: None, doc: _Doc) -> Vec3 | None: ...
    def vec3(self, element: etree._Element | None, tag: str, default: Vec3 | None, doc: _Doc) -> Vec3 | None:
        """Three numbers from a child (a vector, a size, a scale); :meth:`vector`'s rules."""
        v = self.vector(element, tag, 3, default, doc)
        return None if v is None else (v[0], v[1], v[2])

    def flag(self, element: etree._Element | None, tag: str, default: bool, doc: _Doc) -> bool:
        if element is None:
            return default
        child = _find(element, tag)
        if child is None:
            return default
        value = parse_bool(child.text)
        if value is None:
            self.sink.error(
                ErrorCode.VALUE_INVALID,
                f"<{tag}> must be true/false/1/0, got {(child.text or '').strip()!r}",
                self.loc(child, doc),
            )
            return default
        return value

    def color(self, element: etree._Element | None, tag: str, doc: _Doc) -> RGBA | None:
        """An RGBA colour (RGB accepted, alpha 1); None when absent or malformed."""
        if element is None:
            return None
        child = _find(element, tag)
        if child is None:
            return None
        values = parse_floats(child.text)
        if values is None or len(values) not in (3, 4):
            self.sink.error(
                ErrorCode.VALUE_INVALID,
                f"<{tag}> must be 3 or 4 numbers (RGBA), got {(child.text or '').strip()!r}",
                self.loc(child, doc),
            )
            return None
        return (values[0], values[1], values[2], values[3] if len(values) == 4 else 1.0)

    def pose(self, element: etree._Element | None, doc: _Doc) -> tuple[Pose, str | None]:
        """The ``<pose>`` child of ``element`` and its ``relative_to`` (None = the default)."""
        child = None if element is None else _find(element, "pose")
        if child is None:
            return IDENTITY, None
        relative_to = child.get("relative_to")
        if relative_to is None and (1, 5) <= doc.version < (1, 7):
            relative_to = child.get("frame")
        relative_to = (relative_to or "").strip() or None
        text = (child.text or "").strip()
        if not text:
            return IDENTITY, relative_to
        fmt = (child.get("rotation_format") or "euler_rpy").strip()
        degrees = parse_bool(child.get("degrees") or "false")
        loc = self.loc(child, doc)
        if degrees is None:
            self.sink.error(
                ErrorCode.ATTRIBUTE_INVALID, f"pose 'degrees' must be true/false, got {child.get('degrees')!r}", loc
            )
            degrees = False
        if fmt == "euler_rpy":
            values = parse_floats(text, 6)
            if values is None:
                self.sink.error(
                    ErrorCode.VALUE_INVALID, f"<pose> must be 6 numbers 'x y z roll pitch yaw', got {text!r}", loc
                )
                return IDENTITY, relative_to
            scale = math.pi / 180.0 if degrees else 1.0
            rpy = (values[3] * scale, values[4] * scale, values[5] * scale)
            return Pose.from_xyz_rpy((values[0], values[1], values[2]), rpy), relative_to
        if fmt == "quat_xyzw":
            values = parse_floats(text, 7)
            if values is None:
                self.sink.error(
                    ErrorCode.VALUE_INVALID, f"<pose> must be 7 numbers 'x y z qx qy qz qw', got {text!r}", loc
                )
                return IDENTITY, relative_to
            qx, qy, qz, qw = values[3:]
            norm = math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw)
            if not norm > 1e-9:
                self.sink.error(ErrorCode.VALUE_INVALID, "<pose> quaternion has zero length", loc)
                return IDENTITY, relative_to
            xyz = (values[0], values[1], values[2])
            return Pose(xyz, (qw / norm, qx / norm, qy / norm, qz / norm)), relative_to
        self.sink.error(
            ErrorCode.ATTRIBUTE_INVALID,
            f"pose rotation_format must be 'euler_rpy' or 'quat_xyzw', got {fmt!r}",
            loc,
        )
        return IDENTITY, relative_to

    def plugin(self, element: etree._Element, doc: _Doc) -> Plugin | None:
        loc = self.loc(element, doc)
        filename = (element.get("filename") or "").strip()
        if not filename:
            self.sink.error(ErrorCode.ATTRIBUTE_MISSING, "<plugin> is missing the required 'filename' attribute", loc)
            return None
        return Plugin(
            name=(element.get("name") or "").strip(), filename=filename, config=self.config(element, doc), location=loc
        )

    # ================================================================== URIs and includes
    def find_model_dir(self, name: str, doc: _Doc) -> Path | None:
        """Folder of model ``name``: the resolver first, then the folder of the current file."""
        found = self.resolver.find_package(name)
        if found is not None:
            return found
        here = doc.base_dir
        if here is None or not self.resolver.allowed(here):  # a string has no folder of its own
            return None
        for cand in (here if here.name == name else None, here.parent / name):
            if cand is not None and cand.is_dir() and name not in ("", ".", ".."):
                # a sibling of a model the user pointed at (models/a includes model://b): its files may be read
                self.resolver = self.resolver.trusting(cand)
                return cand.resolve()
        return None

    def resolve(self, uri: str, doc: _Doc) -> Path | None:
        """A ``model://``, ``package://``, ``file://`` URI or path as a file system path (may not exist)."""
        uri = uri.strip()
        if uri.startswith("model://"):
            name, _, sub = uri[len("model://") :].partition("/")
            root = self.find_model_dir(name, doc)
            if root is None:
                return None
            path = (root / sub).resolve()
            return path if path == root or root in path.parents else None
        try:
            return self.resolver.resolve_uri(uri, base_dir=doc.base_dir)
        except (OSError, ValueError):
            return None

    def pick_sdf(self, folder: Path, loc: SourceLocation) -> Path | None:
        """The SDF file of a model folder: the highest ``model.config`` version we support."""
        config = folder / "model.config"
        candidates: list[tuple[Version, int, Path]] = []
        if config.is_file():
            try:
                root = etree.fromstring(config.read_bytes(), etree.XMLParser(resolve_entities=False, no_network=True))
            except (etree.XMLSyntaxError, OSError, ValueError):
                root = None
                self.sink.warning(ErrorCode.URI_UNRESOLVED, f"cannot read {config}; trying model.sdf", loc)
            if root is not None:
                for i, entry in enumerate(root.iter("sdf")):
                    version = parse_version(entry.get("version"))
                    file = (entry.text or "").strip()
                    if version is not None and file and version <= MAX_VERSION:
                        candidates.append((version, -i, folder / file))
        for _, _, path in sorted(candidates, reverse=True):
            if path.is_file():
                return path
        fallback = folder / "model.sdf"
        return fallback if fallback.is_file() else None

    def include_file(self, uri: str, path: Path | None, doc: _Doc, loc: SourceLocation) -> tuple[str, str, Path] | None:
        """(text, source, folder) of an included file, or None after reporting why it is not read."""
        if path is not None and path.is_dir():
            path = self.pick_sdf(path, loc)
        if path is None and self.resolver.refused(uri, doc.base_dir):
            self.sink.error(ErrorCode.URI_UNRESOLVED, f"include {self.resolver.refusal(uri)}", loc)
            return None
        if path is None or not path.is_file():
            self.sink.warning(ErrorCode.URI_UNRESOLVED, f"cannot resolve include URI '{uri}'; include skipped", loc)
            return None
        if not self.resolver.allowed(path):  # e.g. a model.sdf that links out of the resource paths
            self.sink.error(ErrorCode.URI_UNRESOLVED, f"include {self.resolver.refusal(uri)}", loc)
            return None
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as err:
            self.sink.error(ErrorCode.FILE_READ_ERROR, f"cannot read included file {path}: {err}", loc)
            return None
        return text, str(path), path.parent

    def fuel_include(self, fuel: FuelModel, uri: str, loc: SourceLocation) -> tuple[str, str, Path | None] | None:
        """A Fuel model without the network: built in, or from Gazebo's local Fuel cache (see :mod:`._fuel`)."""
        builtin = FUEL_BUILTIN.get(fuel.name.lower()) if fuel.owner.lower() == "openrobotics" else None
        if builtin is not None:
            return builtin, f"<builtin:fuel {fuel.label()}>", None
        cached = find_cached(fuel, cache_roots())
        if cached is not None:
            self.resolver = self.resolver.trusting(cached)  # the user's own Gazebo cache
            sdf = self.pick_sdf(cached, loc)
            if sdf is not None:
                return self.include_file(uri, sdf, _Doc(str(sdf), cached, MAX_VERSION, False), loc)
        self.sink.warning(
            ErrorCode.URI_UNRESOLVED,
            f"Fuel model '{fuel.label()}' is not built in and not in a local Fuel cache "
            f"({', '.join(str(r) for r in cache_roots()) or '~/.gz/fuel: none'}); nothing was fetched "
            "(no network); include skipped",
            loc,
        )
        return None

    def include(self, element: etree._Element, doc: _Doc, depth: int, allow_light: bool) -> _Built | Light | None:
        """Load an ``<include>``: a model (or, in a world, a light) with the overrides applied."""
        self.check(element, doc, "include")
        loc = self.loc(element, doc)
        uri = self.text(element, "uri")
        if not uri:
            self.sink.error(ErrorCode.ELEMENT_MISSING, "<include> has no <uri>", loc)
            return None
        if depth >= MAX_NESTING:
            self.sink.error(
                ErrorCode.URI_UNRESOLVED, f"includes nest deeper than {MAX_NESTING} (a cycle?) at '{uri}'", loc
            )
            return None
        fuel = parse_fuel_uri(uri)
        if fuel is not None:
            got = self.fuel_include(fuel, uri, loc)
            if got is None:
                return None
            text, source, base = got
        else:
            path = (
                None
                if "://" in uri and not uri.startswith(("model://", "package://", "file://"))
                else self.resolve(uri, doc)
            )
            stock = CLASSIC_BUILTIN.get(uri[len("model://") :].strip("/")) if uri.startswith("model://") else None
            if path is None and stock is not None:
                # Gazebo Classic installs these with itself; without them a Classic world has no floor
                got_file = (stock, f"<builtin:{uri}>", None)
            else:
                got_file = self.include_file(uri, path, doc, loc)
            if got_file is None:
                return None
            text, source, base = got_file
        got = self.read(text, source, base)
        if got is None:
            return None
        root, inner_doc = got
        model_el = _find(root, "model")
        light_el = _find(root, "light") if allow_light else None
        pose, relative_to = self.pose(element, doc)
        has_pose = _find(element, "pose") is not None
        name = self.text(element, "name")
        if model_el is None and light_el is not None:
            light = self.light(light_el, inner_doc, None)
            if light is None:
                return None
            return Light(
                name=name or light.name,
                type=light.type,
                pose=pose if has_pose else light.pose,
                diffuse=light.diffuse,
                specular=light.specular,
                direction=light.direction,
                cast_shadows=light.cast_shadows,
                attenuation_range=light.attenuation_range,
                location=loc,
            )
        if model_el is None:
            self.sink.error(ErrorCode.ELEMENT_MISSING, f"included file {source} holds no <model>", loc)
            return None
        built = self.model(model_el, inner_doc, depth + 1)
        if built is None:
            return None
        if name:
            built.name = name
        if has_pose:
            built.pose, built.relative_to = pose, relative_to
        if _find(element, "static") is not None:
            built.static = self.flag(element, "static", built.static, doc)
        placement = self.text(element, "placement_frame")
        if placement:
            built.placement_frame = placement
        for plugin_el in _findall(element, "plugin"):
            plugin = self.plugin(plugin_el, doc)
            if plugin is not None:
                built.plugins.append(plugin)
        built.location = loc
        return built

    # ================================================================== models
    def model(self, element: etree._Element, doc: _Doc, depth: int) -> _Built | None:
        """Parse a ``<model>`` (recursively flattening nested models) in its own frame."""
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        if name is None:
            return None
        if depth >= MAX_NESTING:
            self.sink.error(ErrorCode.VALUE_INVALID, f"models nest deeper than {MAX_NESTING}", loc)
            return None
        self.check(element, doc, "model")
        pose, relative_to = self.pose(element, doc)
        built = _Built(
            name=name,
            static=self.flag(element, "static", False, doc),
            self_collide=self.flag(element, "self_collide", False, doc),
            pose=pose,
            relative_to=relative_to,
            placement_frame=(element.get("placement_frame") or "").strip() or None,
            canonical=None,
            doc=doc,
            location=loc,
        )
        scope = Scope("__model__", self.sink)
        kinds: dict[str, str] = {}

        def register(node_name: str, kind: str, el: etree._Element) -> bool:
            if node_name in ("__model__", "world") or (node_name.startswith("__") and node_name.endswith("__")):
                self.sink.error(ErrorCode.VALUE_INVALID, f"'{node_name}' is a reserved name", self.loc(el, doc))
                return False
            previous = kinds.get(node_name)
            if previous is not None and (previous == kind or doc.version >= (1, 7)):
                self.sink.error(
                    ErrorCode.DUPLICATE_NAME,
                    f"{kind} name '{node_name}' is already used by a {previous} in model '{name}'",
                    self.loc(el, doc),
                )
                return False
            if previous is None:
                kinds[node_name] = kind
            return previous is None

        # -- pass 1: names, frame nodes, nested models
        link_els: list[tuple[str, etree._Element]] = []
        joint_els: list[tuple[str, etree._Element]] = []
        frame_els: list[tuple[str, etree._Element]] = []
        nested: list[_Built] = []
        for child in child_elements(element):
            tag = _tag(child)
            if tag in ("link", "joint", "frame"):
                child_name = self.name(child, doc)
                if child_name is None or not register(child_name, tag, child):
                    continue
                child_pose, child_rel = self.pose(child, doc)
                child_loc = self.loc(child, doc)
                if tag == "link":
                    link_els.append((child_name, child))
                    scope.nodes[child_name] = FrameNode(
                        child_name, "link", child_pose, child_rel or "__model__", location=child_loc
                    )
                elif tag == "joint":
                    joint_els.append((child_name, child))
                    child_ref = self.text(child, "child") or ""
                    scope.nodes[child_name] = FrameNode(
                        child_name,
                        "joint",
                        child_pose,
                        child_rel or child_ref or "__model__",
                        attached_to=child_ref,
                        location=child_loc,
                    )
                else:
                    frame_els.append((child_name, child))
                    attached = (child.get("attached_to") or "").strip() or None
                    scope.nodes[child_name] = FrameNode(
                        child_name,
                        "frame",
                        child_pose,
                        child_rel or attached or "__model__",
                        attached_to=attached,
                        location=child_loc,
                    )
            elif tag in ("model", "include"):
                sub = (
                    self.model(child, doc, depth + 1)
                    if tag == "model"
                    else self.include(child, doc, depth, allow_light=False)
                )
                if not isinstance(sub, _Built) or not register(sub.name, "model", child):
                    continue
                post = IDENTITY
                if sub.placement_frame is not None:
                    inner = sub.exported.poses.get(sub.placement_frame)
                    if inner is None:
                        self.sink.error(
                            ErrorCode.FRAME_INVALID,
                            f"placement_frame '{sub.placement_frame}' is not a frame of model '{sub.name}'",
                            sub.location,
                        )
                    else:
                        post = inner.inverse()
                nested.append(sub)
                scope.nested[sub.name] = sub.exported
                scope.nodes[sub.name] = FrameNode(
                    sub.name, "model", sub.pose, sub.relative_to or "__model__", post=post, location=sub.location
                )

        # -- canonical link
        canonical_attr = (element.get("canonical_link") or "").strip() or None
        if canonical_attr is not None:
            body = scope.body(canonical_attr, loc) if canonical_attr in scope.nodes or "::" in canonical_attr else None
            if body is None or (
                canonical_attr in scope.nodes
                and scope.nodes[canonical_attr].kind != "link"
                and "::" not in canonical_attr
            ):
                self.sink.error(
                    ErrorCode.FRAME_INVALID, f"canonical_link '{canonical_attr}' is not a link of model '{name}'", loc
                )
            else:
                built.canonical = body
        if built.canonical is None:
            if link_els:
                built.canonical = link_els[0][0]
            else:
                for sub in nested:
                    if sub.canonical is not None:
                        built.canonical = f"{sub.name}::{sub.canonical}"
                        break
        scope.canonical = built.canonical
        if built.canonical is None:
            self.sink.error(ErrorCode.LINK_MISSING, f"model '{name}' has no link", loc)
            return None

        # -- pass 2: links, joints, frames
        for link_name, link_el in link_els:
            link = self.link(link_name, link_el, doc, scope)
            if link is not None:
                built.links.append(link)
        for joint_name, joint_el in joint_els:
            self.joint(joint_name, joint_el, doc, scope, built)
        for frame_name, frame_el in frame_els:
            X_MF = scope.pose(frame_name, self.loc(frame_el, doc))
            body = scope.body(frame_name, self.loc(frame_el, doc))
            if X_MF is None or body is None:
                continue
            X_MB = IDENTITY if body == "world" else scope.pose(body, self.loc(frame_el, doc))
            if X_MB is not None:
                built.frames.append(Frame(frame_name, body, X_MB.inverse() * X_MF, self.loc(frame_el, doc)))
        for plugin_el in _findall(element, "plugin"):
            plugin = self.plugin(plugin_el, doc)
            if plugin is not None:
                built.plugins.append(plugin)

        # -- flatten nested models into this one
        for sub in nested:
            X_MS = scope.pose(sub.name, sub.location)
            if X_MS is None:
                continue
            self.flatten(built, sub, X_MS)
            if sub.static and not built.static and sub.canonical is not None:
                built.joints.append(
                    Joint(
                        name=f"{sub.name}::__static_weld__",
                        type=JointType.FIXED,
                        parent="world",
                        child=f"{sub.name}::{sub.canonical}",
                        location=sub.location,
                    )
                )
                built.world_joints[f"{sub.name}::__static_weld__"] = X_MS * _link_pose(sub, sub.canonical)
        built.exported = scope.export()
        return built

    def flatten(self, parent: _Built, sub: _Built, X_PS: Pose) -> None:
        """Move ``sub``'s content into ``parent`` with ``sub::`` names, given X_PS."""
        prefix = f"{sub.name}::"

        def scoped(n: str) -> str:
            return n if n == "world" else prefix + n

        for link in sub.links:
            parent.links.append(replace(link, name=prefix + link.name, pose=X_PS * (link.pose or IDENTITY)))
        for joint in sub.joints:
            parent.joints.append(
                Joint(
                    name=prefix + joint.name,
                    type=joint.type,
                    parent=scoped(joint.parent),
                    child=scoped(joint.child),
                    origin=joint.origin,
                    child_offset=joint.child_offset,
                    axis=joint.axis,
                    axis2=joint.axis2,
                    screw_thread_pitch=joint.screw_thread_pitch,
                    mimic=Mimic(prefix + joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset)
                    if joint.mimic
                    else None,
                    location=joint.location,
                )
            )
        for jname, X_SJ in sub.world_joints.items():
            parent.world_joints[prefix + jname] = X_PS * X_SJ
        for frame in sub.frames:
            parent.frames.append(Frame(prefix + frame.name, scoped(frame.attached_to), frame.pose, frame.location))
        parent.plugins.extend(sub.plugins)

    def finish_model(self, built: _Built, X_WM: Pose) -> Model | None:
        """The final :class:`Model` once its world pose is known."""
        joints = []
        for joint in built.joints:
            X_MJ = built.world_joints.get(joint.name)
            if X_MJ is not None and joint.parent == "world":
                joint = replace(joint, origin=X_WM * X_MJ)
            joints.append(joint)
        if not built.links:
            if self.sink.has_hard_errors:
                return None  # its links failed and were reported
            self.sink.error(ErrorCode.LINK_MISSING, f"model '{built.name}' has no link", built.location)
            return None
        return Model(
            name=built.name,
            links=tuple(
                replace(lk, sensors=(*lk.sensors, *built.joint_sensors[lk.name]))
                if lk.name in built.joint_sensors
                else lk
                for lk in built.links
            ),
            joints=tuple(joints),
            frames=tuple(built.frames),
            plugins=tuple(built.plugins),
            static=built.static,
            pose=X_WM,
            canonical_link=built.canonical,
            self_collide=built.self_collide,
            source_format="sdf",
            source_file=built.doc.source if built.doc else "",
            location=built.location,
        )

    # ================================================================== links
    def shapes(
        self, link: etree._Element, doc: _Doc, tag: str, link_name: str
    ) -> list[tuple[etree._Element, str, Geometry]]:
        """The link's ``<collision>`` or ``<visual>`` elements (``tag``) that have a name, used once in the
        link, and a geometry, as (element, name, geometry); the others are reported and left out."""
        out: list[tuple[etree._Element, str, Geometry]] = []
        seen: set[str] = set()
        for el in _findall(link, tag):
            name = self.name(el, doc)
            if name is None:
                continue
            if name in seen:
                self.sink.error(
                    ErrorCode.DUPLICATE_NAME,
                    f"{tag} name '{name}' is used twice in link '{link_name}'",
                    self.loc(el, doc),
                )
                continue
            seen.add(name)
            self.check(el, doc, tag)
            geometry = self.geometry(el, doc)
            if geometry is not None:
                out.append((el, name, geometry))
        return out

    def link(self, name: str, element: etree._Element, doc: _Doc, scope: Scope) -> Link | None:
        loc = self.loc(element, doc)
        self.check(element, doc, "link")
        X_ML = scope.pose(name, loc)
        if X_ML is None:
            return None
        X_LM = X_ML.inverse()

        def local_pose(el: etree._Element) -> Pose:
            pose, rel = self.pose(el, doc)
            if rel is None or rel == name:
                return pose
            X_MR = scope.pose(rel, self.loc(el, doc))
            return pose if X_MR is None else X_LM * X_MR * pose

        collisions = [
            Collision(n, local_pose(el), g, self.surface(_find(el, "surface"), doc), self.loc(el, doc))
            for el, n, g in self.shapes(element, doc, "collision", name)
        ]
        visuals = [
            Visual(n, local_pose(el), g, self.material(_find(el, "material"), doc), self.loc(el, doc))
            for el, n, g in self.shapes(element, doc, "visual", name)
        ]
        sensors: list[Sensor] = []
        for sen_el in _findall(element, "sensor"):
            sensor = self.sensor(sen_el, doc, local_pose(sen_el))
            if sensor is not None:
                sensors.append(sensor)
        inertial = self.inertial(
            name, _find(element, "inertial"), doc, [(c.pose, c.geometry) for c in collisions], local_pose
        )
        self_collide = None
        if _find(element, "self_collide") is not None:
            self_collide = self.flag(element, "self_collide", False, doc)
        return Link(
            name=name,
            inertial=inertial,
            visuals=tuple(visuals),
            collisions=tuple(collisions),
            sensors=tuple(sensors),
            gravity=self.flag(element, "gravity", True, doc),
            kinematic=self.flag(element, "kinematic", False, doc),
            self_collide=self_collide,
            pose=X_ML,
            location=loc,
        )

    def inertial(self, link: str, element: etree._Element | None, doc: _Doc, shapes, local_pose) -> Inertial:
        """Mass properties: as written when valid, else derived from the collision shapes.

        No ``<inertial>`` means SDF's default (1 kg, unit inertia), as in Gazebo. A nested
        ``<inertial>`` (a common slip) is reported and its values used as the author meant.
        """
        if element is None:
            return Inertial(mass=1.0, ixx=1.0, iyy=1.0, izz=1.0)
        self.check(element, doc, "inertial")
        loc = self.loc(element, doc)
        inner = _find(element, "inertial")
        source_el = element
        if inner is not None:
            self.sink.warning(
                ErrorCode.INERTIAL_NESTED,
                f"link '{link}': <inertial> nested inside <inertial>; using its values as the outer inertial's",
                self.loc(inner, doc),
            )
            source_el = inner
        pose_el = element if _find(element, "pose") is not None else source_el
        pose = local_pose(pose_el)
        auto = parse_bool(element.get("auto") or "false") is True
        mass_el = element if _find(element, "mass") is not None else source_el
        mass_child = _find(mass_el, "mass")
        mass: float | None = 1.0
        if mass_child is not None:
            mass = parse_float(mass_child.text)
            if mass is None or mass <= 0:
                self.sink.warning(
                    ErrorCode.MASS_INVALID,
                    f"link '{link}': mass must be a positive number, got {(mass_child.text or '').strip()!r}; "
                    "deriving mass and inertia from the collision geometry",
                    self.loc(mass_child, doc),
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
            self.sink.warning(
                ErrorCode.INERTIA_MISSING,
                f"link '{link}': <inertial> has no <inertia>; "
                f"deriving it from the collision geometry and mass {mass:g} kg",
                loc,
            )
            return derive_inertial(shapes, mass)
        values = {}
        for key, default in (("ixx", 1.0), ("ixy", 0.0), ("ixz", 0.0), ("iyy", 1.0), ("iyz", 0.0), ("izz", 1.0)):
            child = _find(inertia_el, key)
            value = default if child is None else parse_float(child.text)
            if value is None and child is not None:
                self.sink.warning(
                    ErrorCode.INERTIA_INVALID,
                    f"link '{link}': <{key}> must be a number, got {(child.text or '').strip()!r}; "
                    "deriving the inertia from the collision geometry",
                    self.loc(child, doc),
                )
                return derive_inertial(shapes, mass)
            values[key] = value
        problem = inertia_problem(**values)
        if problem is not None:
            self.sink.warning(
                ErrorCode.INERTIA_INVALID,
                f"link '{link}': {problem}; deriving it from the collision geometry",
                self.loc(inertia_el, doc),
            )
            return derive_inertial(shapes, mass)
        return Inertial(mass=mass, pose=pose, **values)

    def geometry(self, owner: etree._Element, doc: _Doc) -> Geometry | None:
        element = _find(owner, "geometry")
        owner_loc = self.loc(owner, doc)
        if element is None:
            self.sink.error(
                ErrorCode.ELEMENT_MISSING, f"<{_tag(owner)}> '{owner.get('name')}' has no <geometry>", owner_loc
            )
            return None
        shapes = [c for c in child_elements(element) if ":" not in _tag(c)]
        if not shapes:
            self.sink.error(ErrorCode.ELEMENT_MISSING, "<geometry> is empty", self.loc(element, doc))
            return None
        shape = shapes[0]
        kind = _tag(shape)
        loc = self.loc(shape, doc)
        for extra in shapes[1:]:
            self.warn_extra(extra, doc, "a <geometry> holds one shape")

        def positive(*values: float) -> bool:
            if all(v > 0 for v in values):
                return True
            self.sink.error(ErrorCode.GEOMETRY_INVALID, f"<{kind}> dimensions must be positive, got {values}", loc)
            return False

        if kind == "box":
            size = self.vec3(shape, "size", (1.0, 1.0, 1.0), doc)
            return Box(size) if positive(*size) else None
        if kind in ("cylinder", "capsule"):
            default_r = 1.0 if kind == "cylinder" else 0.5
            radius = self.number(shape, "radius", default_r, doc)
            length = self.number(shape, "length", 1.0, doc)
            if not positive(radius, length):
                return None
            return Cylinder(radius, length) if kind == "cylinder" else Capsule(radius, length)
        if kind == "cone":  # SDF 1.11
            radius = self.number(shape, "radius", 1.0, doc)
            length = self.number(shape, "length", 1.0, doc)
            return Cone(radius, length) if positive(radius, length) else None
        if kind == "sphere":
            radius = self.number(shape, "radius", 1.0, doc)
            return Sphere(radius) if positive(radius) else None
        if kind == "ellipsoid":
            radii = self.vec3(shape, "radii", (1.0, 1.0, 1.0), doc)
            return Ellipsoid(radii) if positive(*radii) else None
        if kind == "plane":
            normal = self.vec3(shape, "normal", (0.0, 0.0, 1.0), doc)
            size = self.vector(shape, "size", 2, Plane().size, doc) or Plane().size
            n = math.sqrt(sum(v * v for v in normal))
            if n < 1e-12:
                self.sink.error(ErrorCode.GEOMETRY_INVALID, "<plane> normal has zero length", loc)
                return None
            return Plane((normal[0] / n, normal[1] / n, normal[2] / n), (size[0], size[1]))
        if kind == "mesh":
            for child in child_elements(shape):
                if _tag(child) not in ("uri", "scale") and ":" not in _tag(child):
                    self.unsupported(child, doc, "mesh")
            uri = self.text(shape, "uri")
            if not uri:
                self.sink.error(ErrorCode.ELEMENT_MISSING, "<mesh> has no <uri>", loc)
                return None
            scale = self.vec3(shape, "scale", (1.0, 1.0, 1.0), doc)
            path = (
                self.resolve(uri, doc)
                if ("://" not in uri or uri.startswith(("model://", "package://", "file://")))
                else None
            )
            if path is None or not path.is_file():
                why = f": {self.resolver.unresolved_reason(uri, doc.base_dir)}" if path is None else ""
                self.sink.warning(ErrorCode.MESH_NOT_FOUND, f"mesh '{uri}' not found{why}", loc)
                return Mesh(uri, None, scale)
            if not self.resolver.allowed(path):
                self.sink.warning(ErrorCode.URI_UNRESOLVED, f"mesh {self.resolver.refusal(uri)}", loc)
                return Mesh(uri, None, scale)
            return Mesh(uri, str(path), scale)
        if kind == "empty":
            return None
        self.sink.warning(
            ErrorCode.ELEMENT_UNSUPPORTED,
            f"geometry <{kind}> is not supported; the shape is skipped, so as a <collision> it collides with "
            "nothing (supported: box, cylinder, sphere, capsule, cone, ellipsoid, plane, mesh)",
            loc,
        )
        return None

    def surface(self, element: etree._Element | None, doc: _Doc) -> Surface:
        if element is None:
            return Surface()
        self.check(element, doc, "surface")
        friction = _find(element, "friction")
        ode = bullet = torsional = None
        if friction is not None:
            self.check(friction, doc, "friction")
            ode, bullet, torsional = _find(friction, "ode"), _find(friction, "bullet"), _find(friction, "torsional")
            if ode is not None:
                self.check(ode, doc, "friction_ode", "ode")
            if bullet is not None:
                self.check(bullet, doc, "bullet_friction", "bullet")
            if torsional is not None:
                self.check(torsional, doc, "torsional")
        contact = _find(element, "contact")
        contact_ode = None
        if contact is not None:
            self.check(contact, doc, "contact")
            contact_ode = _find(contact, "ode")
            if contact_ode is not None:
                self.check(contact_ode, doc, "contact_ode", "ode")
        bounce = _find(element, "bounce")
        if bounce is not None:
            self.check(bounce, doc, "bounce")
        mu = self.opt_number(ode, "mu", doc)
        mu2 = self.opt_number(ode, "mu2", doc)
        if mu is None:
            mu = self.opt_number(bullet, "friction", doc)
        if mu2 is None:
            mu2 = self.opt_number(bullet, "friction2", doc)
        bitmask = None
        bitmask_el = _find(contact, "collide_bitmask") if contact is not None else None
        if contact is not None and bitmask_el is not None:
            raw = self.text(contact, "collide_bitmask") or ""
            try:
                bitmask = int(raw, 0)
            except ValueError:
                self.sink.error(
                    ErrorCode.VALUE_INVALID,
                    f"<collide_bitmask> must be an integer, got {raw!r}",
                    self.loc(bitmask_el, doc),
                )
        without = _find(contact, "collide_without_contact") if contact is not None else None
        if without is not None and (without.text or "").strip().lower() in ("1", "true"):
            # gz-sim: the shape reports contacts but exerts no force. MuJoCo has no such geom: it takes
            # part in no contact (rays still see it), and contact sensors do not report it either.
            # The default (false) is what gazelle does anyway: read silently (a house world of gz-sim's
            # printed 54 warnings, one a model file, for that default)
            self.sink.warning(
                ErrorCode.ELEMENT_UNSUPPORTED,
                "<collide_without_contact> true: this collision takes part in no contact at all (no force, "
                "and contact sensors do not report it)",
                self.loc(without, doc),
            )
            bitmask = 0
        return Surface(
            mu=mu,
            mu2=mu2,
            fdir1=self.vec3(ode, "fdir1", None, doc),
            slip1=self.opt_number(ode, "slip1", doc),
            slip2=self.opt_number(ode, "slip2", doc),
            torsional=self.opt_number(torsional, "coefficient", doc),
            rolling=self.opt_number(bullet, "rolling_friction", doc),
            kp=self.opt_number(contact_ode, "kp", doc),
            kd=self.opt_number(contact_ode, "kd", doc),
            min_depth=self.opt_number(contact_ode, "min_depth", doc),
            max_vel=self.opt_number(contact_ode, "max_vel", doc),
            soft_cfm=self.opt_number(contact_ode, "soft_cfm", doc),
            soft_erp=self.opt_number(contact_ode, "soft_erp", doc),
            restitution=self.opt_number(bounce, "restitution_coefficient", doc),
            collide_bitmask=bitmask,
        )

    def material(self, element: etree._Element | None, doc: _Doc) -> Material | None:
        if element is None:
            return None
        self.check(element, doc, "material")
        script = _find(element, "script")
        name = ""
        if script is not None:
            self.check(script, doc, "script")
            name = self.text(script, "name") or ""
        texture = None
        pbr = _find(element, "pbr")
        if pbr is not None:
            for workflow in child_elements(pbr):
                texture = self.text(workflow, "albedo_map") or texture
        return Material(
            name=name,
            diffuse=self.color(element, "diffuse", doc),
            ambient=self.color(element, "ambient", doc),
            specular=self.color(element, "specular", doc),
            emissive=self.color(element, "emissive", doc),
            texture=texture,
        )

    def sensor(self, element: etree._Element, doc: _Doc, pose: Pose) -> Sensor | None:
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        kind = (element.get("type") or "").strip()
        if not kind:
            self.sink.error(
                ErrorCode.ATTRIBUTE_MISSING, f"<sensor> '{name}' is missing the required 'type' attribute", loc
            )
            return None
        if name is None:
            return None
        plugins = tuple(p for p in (self.plugin(e, doc) for e in _findall(element, "plugin")) if p is not None)
        return Sensor(
            name=name,
            type=kind,
            pose=pose,
            update_rate_hz=self.number(element, "update_rate", 0.0, doc),
            always_on=self.flag(element, "always_on", False, doc),
            topic=self.text(element, "topic") or "",
            config=self.config(element, doc),
            plugins=plugins,
            location=loc,
        )

    # ================================================================== joints
    def joint(self, name: str, element: etree._Element, doc: _Doc, scope: Scope, built: _Built) -> None:
        loc = self.loc(element, doc)
        self.check(element, doc, "joint")
        raw_type = (element.get("type") or "").strip()
        if not raw_type:
            self.sink.error(
                ErrorCode.ATTRIBUTE_MISSING, f"joint '{name}' is missing the required 'type' attribute", loc
            )
            return
        if raw_type == "gearbox":
            self.sink.warning(
                ErrorCode.JOINT_TYPE_INVALID, f"joint '{name}': type 'gearbox' is not supported; joint skipped", loc
            )
            return
        jtype = _JOINT_TYPES.get(raw_type)
        if jtype is None:
            self.sink.error(
                ErrorCode.JOINT_TYPE_INVALID,
                f"joint '{name}' has unknown type '{raw_type}' (expected one of {', '.join(sorted(_JOINT_TYPES))})",
                loc,
            )
            return
        if raw_type == "revolute2":
            self.sink.warning(
                ErrorCode.JOINT_TYPE_INVALID,
                f"joint '{name}': type 'revolute2' is not supported; loaded as 'universal'",
                loc,
            )
        ends = []
        for role, code in (("parent", ErrorCode.JOINT_PARENT_INVALID), ("child", ErrorCode.JOINT_CHILD_INVALID)):
            el = _find(element, role)
            ref = (el.text or "").strip() if el is not None else ""
            if el is None or not ref:
                self.sink.error(ErrorCode.ELEMENT_MISSING, f"joint '{name}' has no <{role}>", loc)
                return
            where = self.loc(el, doc)
            if ref == "world" or ref in scope.nodes or ("::" in ref and ref.partition("::")[0] in scope.nested):
                body = scope.body(ref, where)
            else:
                body = None
                self.sink.error(code, f"joint '{name}' has unknown {role} '{ref}'", where)
            if body is None:
                return
            if role == "child" and body == "world":
                self.sink.error(code, f"joint '{name}': the child cannot be 'world'", where)
                return
            ends.append(body)
        parent, child = ends
        if parent == child:
            self.sink.error(
                ErrorCode.JOINT_CHILD_INVALID, f"joint '{name}': parent and child are the same link '{child}'", loc
            )
            return
        X_MJ = scope.pose(name, loc)
        X_MC = scope.pose(child, loc)
        X_MP = IDENTITY if parent == "world" else scope.pose(parent, loc)
        if X_MJ is None or X_MC is None or X_MP is None:
            return
        axes = []
        for axis_tag in ("axis", "axis2"):
            axis_el = _find(element, axis_tag)
            if (
                axis_el is None
                or jtype not in _AXIS_JOINTS
                or (axis_tag == "axis2" and jtype is not JointType.UNIVERSAL)
            ):
                axes.append(None)
                continue
            axes.append(self.axis(name, axis_el, doc, scope, X_MJ))
        if jtype in _AXIS_JOINTS and _find(element, "axis") is None:
            self.sink.warning(ErrorCode.ELEMENT_MISSING, f"joint '{name}' ({raw_type}) has no <axis>; using 0 0 1", loc)
            axes[0] = (JointAxis((0.0, 0.0, 1.0)), None)
        if jtype is JointType.UNIVERSAL and axes[1] is None:
            axes[1] = (JointAxis((0.0, 1.0, 0.0)), None)
        pitch = None
        if jtype is JointType.SCREW:
            if _find(element, "screw_thread_pitch") is not None:
                pitch = self.number(element, "screw_thread_pitch", 1.0, doc)
            else:
                thread_pitch = self.number(element, "thread_pitch", 1.0, doc)
                pitch = -2 * math.pi / thread_pitch if thread_pitch != 0 else None
        mimic = None
        for entry in axes:
            if entry is not None and entry[1] is not None:
                mimic = entry[1]
        joint = Joint(
            name=name,
            type=jtype,
            parent=parent,
            child=child,
            origin=X_MJ if parent == "world" else X_MP.inverse() * X_MJ,
            child_offset=X_MJ.inverse() * X_MC,
            axis=axes[0][0] if axes[0] else None,
            axis2=axes[1][0] if axes[1] else None,
            screw_thread_pitch=pitch,
            mimic=mimic,
            location=loc,
        )
        if parent == "world":
            built.world_joints[name] = X_MJ
        built.joints.append(joint)
        for sen_el in _findall(element, "sensor"):  # force_torque: kept with the child link
            pose, _rel = self.pose(sen_el, doc)  # in the joint frame
            sensor = self.sensor(sen_el, doc, pose)
            if sensor is not None:
                built.joint_sensors.setdefault(child, []).append(replace(sensor, joint=name))

    def axis(self, joint: str, element: etree._Element, doc: _Doc, scope: Scope, X_MJ: Pose):
        """An axis in the joint frame, plus its mimic (1.11), converting older frame conventions."""
        self.check(element, doc, "axis")
        xyz_el = _find(element, "xyz")
        loc = self.loc(xyz_el if xyz_el is not None else element, doc)
        xyz = self.vec3(element, "xyz", (0.0, 0.0, 1.0), doc)
        expressed_in = None
        if doc.version <= (1, 4):
            expressed_in = "__model__"
        elif _find(element, "use_parent_model_frame") is not None and self.flag(
            element, "use_parent_model_frame", False, doc
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
            self.sink.error(ErrorCode.JOINT_AXIS_INVALID, f"joint '{joint}': axis xyz has zero length", loc)
            norm = 1.0
            xyz = (0.0, 0.0, 1.0)
        xyz = (xyz[0] / norm, xyz[1] / norm, xyz[2] / norm)
        limit_el = _find(element, "limit")
        limit = JointLimit()
        if limit_el is not None:
            self.check(limit_el, doc, "limit")
            lower = self.number(limit_el, "lower", -1e16, doc)
            upper = self.number(limit_el, "upper", 1e16, doc)
            effort = self.number(limit_el, "effort", -1.0, doc)
            velocity = self.number(limit_el, "velocity", -1.0, doc)
            if lower > upper:
                self.sink.error(
                    ErrorCode.VALUE_INVALID,
                    f"joint '{joint}': limit lower {lower:g} > upper {upper:g}",
                    self.loc(limit_el, doc),
                )
            limit = JointLimit(
                lower=lower if lower > -_UNLIMITED else None,
                upper=upper if upper < _UNLIMITED else None,
                effort=effort if effort >= 0 else None,
                velocity=velocity if velocity >= 0 else None,
            )
        dyn_el = _find(element, "dynamics")
        dynamics = JointDynamics(
            damping=self.number(dyn_el, "damping", 0.0, doc),
            friction=self.number(dyn_el, "friction", 0.0, doc),
            spring_stiffness=self.number(dyn_el, "spring_stiffness", 0.0, doc),
            spring_reference=self.number(dyn_el, "spring_reference", 0.0, doc),
        )
        mimic = None
        mimic_el = _find(element, "mimic")
        if mimic_el is not None:
            leader = (mimic_el.get("joint") or "").strip()
            if not leader:
                self.sink.error(
                    ErrorCode.ATTRIBUTE_MISSING,
                    "<mimic> is missing the required 'joint' attribute",
                    self.loc(mimic_el, doc),
                )
            else:
                mimic = Mimic(
                    leader, self.number(mimic_el, "multiplier", 1.0, doc), self.number(mimic_el, "offset", 0.0, doc)
                )
        return JointAxis(xyz, limit, dynamics), mimic

    # ================================================================== worlds
    def light(self, element: etree._Element, doc: _Doc, scope: Scope | None) -> Light | None:
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        if name is None:
            return None
        self.check(element, doc, "light")
        kind = (element.get("type") or "point").strip()
        if kind not in ("directional", "point", "spot"):
            self.sink.error(
                ErrorCode.ATTRIBUTE_INVALID,
                f"light '{name}' type must be directional, point or spot, got {kind!r}",
                loc,
            )
            return None
        pose, rel = self.pose(element, doc)
        if rel not in (None, "world"):
            if scope is None:
                self.sink.error(ErrorCode.FRAME_INVALID, f"light '{name}': unknown frame '{rel}'", loc)
            else:
                base = scope.pose(rel, loc)
                pose = pose if base is None else base * pose
        attenuation = _find(element, "attenuation")
        if attenuation is not None:
            self.check(attenuation, doc, "attenuation")
        default = Light(name)
        return Light(
            name=name,
            type=kind,
            pose=pose,
            diffuse=self.color(element, "diffuse", doc) or default.diffuse,
            specular=self.color(element, "specular", doc) or default.specular,
            direction=self.vec3(element, "direction", default.direction, doc),
            cast_shadows=self.flag(element, "cast_shadows", False, doc),
            attenuation_range=self.opt_number(attenuation, "range", doc),
            location=loc,
        )

    def world(self, element: etree._Element, doc: _Doc) -> World | None:
        name = self.name(element, doc)
        loc = self.loc(element, doc)
        self.check(element, doc, "world")
        physics_els = _findall(element, "physics")
        physics_el = next(
            (p for p in physics_els if parse_bool(p.get("default") or "") is True),
            physics_els[0] if physics_els else None,
        )
        if physics_el is not None:
            self.check(physics_el, doc, "physics")
        gravity = (0.0, 0.0, -9.8)
        if _find(element, "gravity") is not None:
            gravity = self.vec3(element, "gravity", gravity, doc)
        elif physics_el is not None:
            gravity = self.vec3(physics_el, "gravity", gravity, doc)
        magnetic = DEFAULT_MAGNETIC_FIELD
        if _find(element, "magnetic_field") is not None:
            magnetic = self.vec3(element, "magnetic_field", magnetic, doc)
        elif physics_el is not None and _find(physics_el, "magnetic_field") is not None:
            magnetic = self.vec3(physics_el, "magnetic_field", magnetic, doc)
        spherical = None
        sph_el = _find(element, "spherical_coordinates")
        if sph_el is not None:
            self.check(sph_el, doc, "spherical_coordinates")
            orientation = (self.text(sph_el, "world_frame_orientation") or "ENU").strip().upper()
            if orientation != "ENU":
                self.sink.warning(
                    ErrorCode.VALUE_INVALID,
                    f"<world_frame_orientation> {orientation} is not simulated; GPS sensors assume ENU",
                    self.loc(sph_el, doc),
                )
            spherical = SphericalCoordinates(
                latitude_deg=self.number(sph_el, "latitude_deg", 0.0, doc),
                longitude_deg=self.number(sph_el, "longitude_deg", 0.0, doc),
                elevation=self.number(sph_el, "elevation", 0.0, doc),
                heading_deg=self.number(sph_el, "heading_deg", 0.0, doc),
                surface_model=(self.text(sph_el, "surface_model") or "EARTH_WGS84").strip(),
                world_frame_orientation=orientation,
            )
        default_physics = PhysicsSettings()
        step = self.number(physics_el, "max_step_size", default_physics.max_step_size_sec, doc)
        rate_tag = (
            "update_rate"
            if doc.version <= (1, 3) and physics_el is not None and _find(physics_el, "update_rate") is not None
            else "real_time_update_rate"
        )
        physics = PhysicsSettings(
            max_step_size_sec=step,
            real_time_factor=self.number(physics_el, "real_time_factor", default_physics.real_time_factor, doc),
            real_time_update_rate_hz=self.number(physics_el, rate_tag, default_physics.real_time_update_rate_hz, doc),
        )
        if physics_el is not None:
            for value, what in ((physics.max_step_size_sec, "max_step_size"),):
                if not value > 0:
                    self.sink.error(
                        ErrorCode.VALUE_INVALID, f"<{what}> must be > 0, got {value:g}", self.loc(physics_el, doc)
                    )
            if physics.real_time_factor < 0 or physics.real_time_update_rate_hz < 0:
                self.sink.error(
                    ErrorCode.VALUE_INVALID,
                    "real_time_factor and real_time_update_rate must be >= 0",
                    self.loc(physics_el, doc),
                )
        scene_el = _find(element, "scene")
        scene = Scene()
        if scene_el is not None:
            self.check(scene_el, doc, "scene")
            scene = Scene(
                ambient=self.color(scene_el, "ambient", doc) or scene.ambient,
                background=self.color(scene_el, "background", doc) or scene.background,
                shadows=self.flag(scene_el, "shadows", scene.shadows, doc),
                grid=self.flag(scene_el, "grid", scene.grid, doc),
            )
        scope = Scope("world", self.sink, canonical="world")
        builts: list[_Built] = []
        light_items: list[etree._Element | Light] = []
        names: set[str] = set()
        for child in child_elements(element):
            tag = _tag(child)
            sub: _Built | Light | None = None
            if tag == "model":
                sub = self.model(child, doc, 1)
            elif tag == "include":
                sub = self.include(child, doc, 0, allow_light=True)
            elif tag == "light":
                light_items.append(child)
                continue
            elif tag == "frame":
                frame_name = self.name(child, doc)
                if frame_name is None:
                    continue
                if frame_name in names:
                    self.sink.error(
                        ErrorCode.DUPLICATE_NAME,
                        f"name '{frame_name}' is used twice in world '{name}'",
                        self.loc(child, doc),
                    )
                    continue
                names.add(frame_name)
                fpose, frel = self.pose(child, doc)
                attached = (child.get("attached_to") or "").strip() or None
                scope.nodes[frame_name] = FrameNode(
                    frame_name,
                    "frame",
                    fpose,
                    frel or attached or "world",
                    attached_to=attached,
                    location=self.loc(child, doc),
                )
                continue
            else:
                continue
            if isinstance(sub, Light):
                light_items.append(sub)
            elif isinstance(sub, _Built):
                if sub.name in names:
                    self.sink.error(
                        ErrorCode.DUPLICATE_NAME,
                        f"model name '{sub.name}' is used twice in world '{name}'",
                        sub.location,
                    )
                    continue
                names.add(sub.name)
                post = IDENTITY
                if sub.placement_frame is not None:
                    inner = sub.exported.poses.get(sub.placement_frame)
                    if inner is None:
                        self.sink.error(
                            ErrorCode.FRAME_INVALID,
                            f"placement_frame '{sub.placement_frame}' is not a frame of model '{sub.name}'",
                            sub.location,
                        )
                    else:
                        post = inner.inverse()
                builts.append(sub)
                scope.nested[sub.name] = sub.exported
                scope.nodes[sub.name] = FrameNode(
                    sub.name, "model", sub.pose, sub.relative_to or "world", post=post, location=sub.location
                )
        models = []
        for sub in builts:
            X_WM = scope.pose(sub.name, sub.location)
            if X_WM is None:
                continue
            model = self.finish_model(sub, X_WM)
            if model is not None:
                models.append(model)
        lights = []
        for item in light_items:
            light = item if isinstance(item, Light) else self.light(item, doc, scope)
            if light is not None:
                lights.append(light)
        plugins = tuple(p for p in (self.plugin(e, doc) for e in _findall(element, "plugin")) if p is not None)
        if name is None:
            return None
        return World(
            name=name,
            gravity=gravity,
            physics=physics,
            scene=scene,
            models=tuple(models),
            lights=tuple(lights),
            plugins=plugins,
            source_file=doc.source,
            location=loc,
            spherical_coordinates=spherical,
            magnetic_field=magnetic,
        )


def derive_inertial(shapes: list[tuple[Pose, Geometry]], mass: float | None) -> Inertial:
    """Inertia from the collision shapes (mass None: from their volume at water density).

    Same rules as the URDF loader (``_inertia``); no shape with a volume gives its placeholder.
    """
    derived = inertia_from_geometries([(g, p) for p, g in shapes], mass)
    return derived.inertial if derived is not None else default_inertial(mass)


def _link_pose(built: _Built, link_name: str) -> Pose:
    for link in built.links:
        if link.name == link_name:
            return link.pose or IDENTITY
    return IDENTITY

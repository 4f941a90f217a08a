"""The typed description model: what every loader (URDF, xacro, SDF, SRDF) produces.

Everything here is a frozen dataclass with tuples for collections, so a loaded
model can be shared between threads and never changes under the physics layer.
Conventions: SI units and radians; quaternions are ``wxyz`` (MuJoCo's order);
``X_AB`` is the pose of frame B expressed in frame A.
"""

from __future__ import annotations

import contextlib
import contextvars
import enum
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TypeVar

from ._diagnostics import Diagnostic, SourceLocation
from ._pose import IDENTITY, RGBA, Pose, Vec3
from ._semantic_model import Ros2Control, Semantics


# --------------------------------------------------------------------------- geometry
@dataclass(frozen=True, slots=True)
class Box:
    """A box; ``size`` holds full edge lengths (x, y, z) in metres."""

    size: Vec3
    """Full edge lengths along the geometry frame's x, y, z, metres (MuJoCo's box size is half of it)."""


@dataclass(frozen=True, slots=True)
class Cylinder:
    """A cylinder along its local z axis."""

    radius: float
    """Metres."""
    length: float
    """Metres, along local z, centred on the geometry frame."""


@dataclass(frozen=True, slots=True)
class Sphere:
    """A sphere."""

    radius: float
    """Metres, centred on the geometry frame."""


@dataclass(frozen=True, slots=True)
class Capsule:
    """A capsule along local z; ``length`` excludes the two hemispherical caps (SDF)."""

    radius: float
    """Metres: the cylinder's and the caps' radius."""
    length: float
    """Metres between the two caps' centres (SDF's <length>; the capsule is length + 2·radius long)."""


@dataclass(frozen=True, slots=True)
class Cone:
    """A solid cone along local z (SDF 1.11): base of ``radius`` at z = -length/2, apex at +length/2."""

    radius: float
    """Metres: the base's radius."""
    length: float
    """Metres from base to apex, centred on the geometry frame."""


@dataclass(frozen=True, slots=True)
class Ellipsoid:
    """An ellipsoid with semi-axes ``radii``."""

    radii: Vec3
    """Semi-axes along local x, y, z, metres."""


@dataclass(frozen=True, slots=True)
class Plane:
    """An infinite plane (rendered with ``size``) with a normal in the local frame."""

    normal: Vec3 = (0.0, 0.0, 1.0)
    """The plane's normal in the geometry frame (SDF's <normal>); MuJoCo's planes face +z, so the builder rotates
    others."""
    size: tuple[float, float] = (100.0, 100.0)
    """Width and length in metres, for drawing only: the plane collides everywhere."""


@dataclass(frozen=True, slots=True)
class Mesh:
    """A triangle mesh file."""

    uri: str
    """The URI as the user wrote it (``package://``, ``model://``, ``file://`` or a path)."""
    path: str | None
    """Absolute resolved file path, or None when it could not be resolved (a diagnostic says so)."""
    scale: Vec3 = (1.0, 1.0, 1.0)
    """Scale per axis applied to the file's vertices (URDF's scale attribute, SDF's <scale>)."""


Geometry = Box | Cylinder | Sphere | Capsule | Cone | Ellipsoid | Plane | Mesh


# --------------------------------------------------------------------------- appearance / contact
@dataclass(frozen=True, slots=True)
class Material:
    """Visual appearance."""

    name: str = ""
    """Material name (URDF named material or Gazebo material script name)."""
    diffuse: RGBA | None = None
    """Base colour, RGBA 0..1; None when unspecified."""
    ambient: RGBA | None = None
    """RGBA 0..1, as written (the viewer and cameras draw the diffuse colour)."""
    specular: RGBA | None = None
    """RGBA 0..1, as written."""
    emissive: RGBA | None = None
    """RGBA 0..1, as written."""
    texture: str | None = None
    """Texture file name or URI, kept as given."""


@dataclass(frozen=True, slots=True)
class Surface:
    """Contact properties, in the SDF/ODE vocabulary. None = simulator default."""

    mu: float | None = None
    """Coulomb friction in the first friction direction (SDF ode/mu, URDF gazebo mu1)."""
    mu2: float | None = None
    """Friction in the second direction (SDF ode/mu2, URDF gazebo mu2)."""
    fdir1: Vec3 | None = None
    """ODE's first friction direction (``mu`` along it, ``mu2`` across), in the collision's frame; applied to a moving
    cylinder, sphere or capsule's contacts with planes (gazelle/physics/_contact_pairs.py), elsewhere friction is
    isotropic and a warning names it. ``0 0 0`` is no direction, as in Gazebo."""
    slip1: float | None = None
    """ODE's force-dependent slip in the first direction; not simulated (warned about)."""
    slip2: float | None = None
    """ODE's slip in the second direction; not simulated (warned about)."""
    torsional: float | None = None
    """Torsional friction coefficient."""
    rolling: float | None = None
    """Bullet's <rolling_friction>; not simulated (warned about), as gz-sim's default engine (DART) drops it."""
    kp: float | None = None
    """Contact stiffness (N/m)."""
    kd: float | None = None
    """Contact damping (N·s/m)."""
    min_depth: float | None = None
    """ODE's <min_depth> (metres of penetration before a contact pushes); not simulated (warned about)."""
    max_vel: float | None = None
    """ODE's <max_vel> (the most a contact may push apart, m/s); not simulated (warned about)."""
    soft_cfm: float | None = None
    """ODE's constraint force mixing; not simulated (warned about): MuJoCo's softness comes from kp."""
    soft_erp: float | None = None
    """ODE's error reduction parameter; not simulated (warned about)."""
    restitution: float | None = None
    """<bounce><restitution_coefficient>; not simulated (warned about): MuJoCo contacts do not bounce."""
    collide_bitmask: int | None = None
    """Gazebo's 16-bit <collide_bitmask>: two collisions touch only when their masks share a bit (MuJoCo's
    contype/conaffinity); None is Gazebo's 0xffff."""


@dataclass(frozen=True, slots=True)
class Collision:
    """A collision shape attached to a link."""

    name: str
    """The collision's name, unique within its link (URDF collisions without one are numbered)."""
    pose: Pose
    """X_LG: pose of the geometry in the link frame."""
    geometry: Geometry
    """Its shape, in the collision's own frame."""
    surface: Surface = Surface()
    """Friction, contact stiffness and bitmask (URDF <gazebo reference> tags land here too)."""
    location: SourceLocation | None = None
    """Where it is written (file:line), for diagnostics."""


@dataclass(frozen=True, slots=True)
class Visual:
    """A visual shape attached to a link."""

    name: str
    """The visual's name, unique within its link."""
    pose: Pose
    """X_LG: pose of the geometry in the link frame."""
    geometry: Geometry
    """Its shape, in the visual's own frame."""
    material: Material | None = None
    """Its colour and texture; None: a mesh file's own colours and texture, when it has them."""
    location: SourceLocation | None = None
    """Where it is written (file:line), for diagnostics."""


@dataclass(frozen=True, slots=True)
class Inertial:
    """Mass properties of a link."""

    mass: float
    """kg."""
    pose: Pose = IDENTITY
    """X_LI: centre of mass and principal-axis orientation in the link frame."""
    ixx: float = 0.0
    """Moment of inertia about the inertial frame's x axis, kg·m²."""
    ixy: float = 0.0
    """Product of inertia, kg·m² (URDF's sign convention: the tensor's off-diagonal element)."""
    ixz: float = 0.0
    """Product of inertia, kg·m²."""
    iyy: float = 0.0
    """Moment of inertia about y, kg·m²."""
    iyz: float = 0.0
    """Product of inertia, kg·m²."""
    izz: float = 0.0
    """Moment of inertia about z, kg·m²."""
    derived: bool = False
    """True when gazelle derived the inertia from geometry (a diagnostic says why)."""


# --------------------------------------------------------------------------- generic config trees
class ReadLog:
    """The child tags a piece of code looked up in configuration trees (see :func:`config_reads`), and the
    aliases under which a tag counts as read (a ROS 1 name read under its ROS 2 one)."""

    def __init__(self) -> None:
        self.tags: set[str] = set()
        self.aliases: dict[str, str] = {}
        """Tag as written -> the tag the reader looks up instead."""

    def read(self, tag: str) -> bool:
        """Whether ``tag`` (or the name it stands for) was looked up; an alias to "" is a tag the reader
        accepts on purpose with no effect (ROS 1's ``rosDebugLevel``)."""
        if tag in self.tags:
            return True
        alias = self.aliases.get(tag)
        return alias is not None and (alias == "" or alias in self.tags)


_READS: contextvars.ContextVar[ReadLog | None] = contextvars.ContextVar("gazelle_config_reads", default=None)


@contextlib.contextmanager
def config_reads() -> Iterator[ReadLog]:
    """Record, inside the block, every tag looked up with :meth:`ConfigElement.find` / ``findall`` (on any
    element): what a system's ``configure`` read of its ``<plugin>``, so that a parameter it never looked at
    is named in a warning instead of being dropped silently. Reads on other threads are not recorded."""
    log = ReadLog()
    token = _READS.set(log)
    try:
        yield log
    finally:
        _READS.reset(token)


def alias_tags(names: dict[str, str]) -> None:
    """In the active :func:`config_reads` block, count each key of ``names`` as read when its value is (a
    reader that maps ROS 1 tags onto ROS 2 ones before looking them up), or always when its value is ""."""
    log = _READS.get()
    if log is not None:
        log.aliases.update(names)


@dataclass(frozen=True, slots=True)
class ConfigElement:
    """A read-only copy of an XML element (plugin configuration, sensor blocks, extensions).

    Systems parse these into their own typed config; the physics layer never reads them.
    """

    tag: str
    """The element's name, without a namespace prefix."""
    attributes: tuple[tuple[str, str], ...] = ()
    """(name, value) pairs in document order."""
    text: str = ""
    """The element's own text (not its children's), unstripped."""
    children: tuple[ConfigElement, ...] = ()
    """The child elements in document order."""
    location: SourceLocation | None = None
    """Where the element is written (file:line)."""

    def attr(self, name: str, default: str | None = None) -> str | None:
        """Attribute value or ``default``."""
        for k, v in self.attributes:
            if k == name:
                return v
        return default

    def find(self, tag: str) -> ConfigElement | None:
        """First direct child with this tag."""
        log = _READS.get()
        if log is not None:
            log.tags.add(tag)
        for c in self.children:
            if c.tag == tag:
                return c
        return None

    def findall(self, tag: str) -> tuple[ConfigElement, ...]:
        """All direct children with this tag."""
        log = _READS.get()
        if log is not None:
            log.tags.add(tag)
        return tuple(c for c in self.children if c.tag == tag)


@dataclass(frozen=True, slots=True)
class Plugin:
    """A ``<plugin>`` block, kept with its raw configuration for the systems to read."""

    name: str
    """The plugin's name attribute (a gazebo_ros plugin's node name)."""
    filename: str
    """The filename attribute as written (libgazebo_ros_diff_drive.so, gz-sim-diff-drive-system, ...)."""
    config: ConfigElement
    """The whole ``<plugin>`` element."""
    location: SourceLocation | None = None
    """Where the <plugin> is written (file:line)."""


@dataclass(frozen=True, slots=True)
class Sensor:
    """A ``<sensor>`` block (camera, ray/lidar, imu, ...)."""

    name: str
    """The sensor's name, unique within its link."""
    type: str
    """SDF's type attribute (camera, depth, gpu_lidar, imu, ...): which sensor system runs it."""
    pose: Pose
    """Pose in the link frame."""
    update_rate_hz: float = 0.0
    """<update_rate> in Hz of sim time; 0 means every step."""
    always_on: bool = False
    """<always_on>: kept as written (gazelle's sensors run while their topics are listened to)."""
    topic: str = ""
    """<topic> (gz-sim); empty: the plugin's or gz-sim's default name."""
    config: ConfigElement | None = None
    """The whole <sensor> element, for the sensor system to read its own block (<camera>, <ray>, <imu>, ...)."""
    plugins: tuple[Plugin, ...] = ()
    """The <plugin>s inside the sensor (gazebo_ros_camera, gazebo_ros_ray_sensor, ...)."""
    location: SourceLocation | None = None
    """Where the <sensor> is written (file:line)."""
    joint: str = ""
    """For a sensor on a joint (force_torque): the joint's name. The sensor is kept with the joint's
    child link, and ``pose`` is then in the joint's frame."""


# --------------------------------------------------------------------------- kinematics
@dataclass(frozen=True, slots=True)
class Link:
    """A rigid body."""

    name: str
    """The link's name, unique in its model; scoped as model::link in the physics world."""
    inertial: Inertial | None = None
    """None means massless (only valid for links welded to a parent by a fixed joint)."""
    visuals: tuple[Visual, ...] = ()
    """What cameras and the viewer draw."""
    collisions: tuple[Collision, ...] = ()
    """What touches (and, without an <inertial>, what the mass is derived from)."""
    sensors: tuple[Sensor, ...] = ()
    """Sensors attached to this link."""
    gravity: bool = True
    """<gravity> (SDF) / <gazebo><turnGravityOff> (URDF, inverted): False cancels gravity on this link (MuJoCo's
    gravcomp)."""
    kinematic: bool = False
    """<kinematic>: moved only by set-state requests, an immovable obstacle to contacts."""
    self_collide: bool | None = None
    """<self_collide> of this link; None: the model's setting."""
    pose: Pose | None = None
    """X_ML: link pose in the model frame as the file gives it (SDF). URDF leaves None; the tree gives it."""
    location: SourceLocation | None = None
    """Where the <link> is written (file:line)."""


class JointType(enum.Enum):
    """Joint types of URDF and SDF."""

    REVOLUTE = "revolute"
    CONTINUOUS = "continuous"
    PRISMATIC = "prismatic"
    FIXED = "fixed"
    FLOATING = "floating"
    PLANAR = "planar"
    BALL = "ball"
    UNIVERSAL = "universal"
    SCREW = "screw"


@dataclass(frozen=True, slots=True)
class JointLimit:
    """A joint's range and limits (URDF ``<limit>``, SDF ``<axis><limit>``); None: unlimited."""

    lower: float | None = None
    """Lower position limit, rad or m."""
    upper: float | None = None
    """Upper position limit, rad or m."""
    effort: float | None = None
    """Max force/torque, N·m or N; None = unlimited. The physics bounds the joint's actuator force to it
    (MuJoCo's actfrcrange), as Gazebo bounds the joint's force."""
    velocity: float | None = None
    """Max speed, rad/s or m/s; None = unlimited. Not enforced on ros2_control commands (ros2_control Jazzy
    does not either); gz-sim's JointPositionController clamps its velocity mode to it."""


@dataclass(frozen=True, slots=True)
class JointDynamics:
    """A joint's damping, friction and spring (URDF ``<dynamics>``, SDF ``<axis><dynamics>``)."""

    damping: float = 0.0
    """Viscous damping, N·m·s/rad or N·s/m (MuJoCo's joint damping, integrated implicitly)."""
    friction: float = 0.0
    """Dry (Coulomb) friction, N·m or N (MuJoCo's frictionloss)."""
    spring_stiffness: float = 0.0
    """SDF <spring_stiffness>, N·m/rad or N/m, pulling toward spring_reference."""
    spring_reference: float = 0.0
    """SDF <spring_reference>: the spring's rest position, rad or m."""


@dataclass(frozen=True, slots=True)
class JointAxis:
    """A joint axis, expressed in the joint frame, unit length."""

    xyz: Vec3 = (1.0, 0.0, 0.0)
    limit: JointLimit = JointLimit()
    """Its range, effort and velocity limits."""
    dynamics: JointDynamics = JointDynamics()
    """Its damping, friction and spring."""


@dataclass(frozen=True, slots=True)
class Mimic:
    """URDF ``<mimic>``: this joint follows ``joint`` as ``multiplier * q + offset``."""

    joint: str
    """The leading joint's name."""
    multiplier: float = 1.0
    """Gain on the leader's position."""
    offset: float = 0.0
    """Added to the scaled position, rad or m."""


@dataclass(frozen=True, slots=True)
class SafetyController:
    """URDF ``<safety_controller>`` (kept for controllers that read it; not simulated)."""

    soft_lower_limit: float | None = None
    """rad or m, as written; None when not written (urdfdom reads 0 then; joint_state_publisher, which
    narrows its range to the soft limits, applies only a written one)."""
    soft_upper_limit: float | None = None
    """rad or m, as written; None when not written."""
    k_position: float = 0.0
    """As written."""
    k_velocity: float = 0.0
    """As written."""


@dataclass(frozen=True, slots=True)
class Calibration:
    """URDF ``<calibration>`` (kept as given; not simulated)."""

    rising: float | None = None
    """rad or m, as written."""
    falling: float | None = None
    """rad or m, as written."""


@dataclass(frozen=True, slots=True)
class Joint:
    """A joint between a parent link (or ``world``) and a child link.

    At joint position zero, ``X_PC = origin * child_offset``; in general
    ``X_PC(q) = origin * motion(axis, q) * child_offset``.
    """

    name: str
    """The joint's name, unique in its model."""
    type: JointType
    """Its kind (revolute, prismatic, fixed, ...)."""
    parent: str
    """Parent link name, or ``"world"``."""
    child: str
    """Child link name."""
    origin: Pose = IDENTITY
    """X_PJ: the joint frame in the parent link frame (URDF ``<origin>``)."""
    child_offset: Pose = IDENTITY
    """X_JC: the child link frame in the joint frame (identity for URDF; SDF may differ)."""
    axis: JointAxis | None = None
    """The (first) axis; None for fixed, floating and ball joints."""
    axis2: JointAxis | None = None
    """Second axis (universal joints)."""
    screw_thread_pitch: float | None = None
    """SDF 1.10's <screw_thread_pitch>: metres along the axis per revolution (an older <thread_pitch>, -2π/pitch
    rad/m, is converted to it)."""
    mimic: Mimic | None = None
    """URDF <mimic>: a MuJoCo joint equality keeps this joint at the leader's scaled position."""
    safety_controller: SafetyController | None = None
    """Kept as written, not simulated."""
    calibration: Calibration | None = None
    """Kept as written, not simulated."""
    location: SourceLocation | None = None
    """Where the <joint> is written (file:line)."""


@dataclass(frozen=True, slots=True)
class Frame:
    """A named frame attached to a link (SDF ``<frame>``)."""

    name: str
    """The frame's name, unique among the model's frames, links and joints."""
    attached_to: str
    """The link or frame it moves with."""
    pose: Pose
    """Pose in the attached-to frame."""
    location: SourceLocation | None = None
    """Where the <frame> is written (file:line)."""


@dataclass(frozen=True, slots=True)
class GazeboExtension:
    """A URDF ``<gazebo>`` block (kept whole; its known tags are also applied to links)."""

    reference: str | None
    """The link or joint the block applies to; None for the whole robot."""
    config: ConfigElement
    """The whole <gazebo> element."""
    location: SourceLocation | None = None
    """Where the block is written (file:line)."""


# --------------------------------------------------------------------------- models and worlds
@dataclass(frozen=True, slots=True)
class Model:
    """A robot or object: a tree (or forest) of links and joints with its plugins."""

    name: str
    """The model's name; the spawned entity's name may differ (-entity)."""
    links: tuple[Link, ...]
    """Every link, the root first when the file orders it so."""
    joints: tuple[Joint, ...] = ()
    """Every joint between them (and to world)."""
    frames: tuple[Frame, ...] = ()
    """SDF <frame>s."""
    plugins: tuple[Plugin, ...] = ()
    """Model-level plugins (URDF robot-level ``<gazebo><plugin>``, SDF ``<model><plugin>``)."""
    gazebo: tuple[GazeboExtension, ...] = ()
    """URDF ``<gazebo>`` blocks as written."""
    static: bool = False
    """<static>: welded to the world, never moved by physics."""
    pose: Pose = IDENTITY
    """X_WM: where the file places the model (SDF ``<pose>``; identity for URDF)."""
    canonical_link: str | None = None
    """The link whose frame is the model frame; defaults to the root link."""
    self_collide: bool = False
    """<self_collide> of the whole model: its links collide with each other (Gazebo's default is False)."""
    semantics: Semantics | None = None
    """Its SRDF, when one was loaded with it."""
    source_format: str = ""
    """"urdf", "sdf", ... for messages."""
    source_file: str = ""
    """The file it was read from; <string> for a description that arrived as a string."""
    location: SourceLocation | None = None
    """Where the <robot>/<model> is written (file:line)."""
    transmissions: tuple[ConfigElement, ...] = ()
    """URDF ``<transmission>`` blocks as written (kept, not simulated)."""
    ros2_control: tuple[Ros2Control, ...] = ()
    """URDF ``<ros2_control>`` blocks."""
    urdf: str = ""
    """The URDF text this model was read from (xacro expanded); published as /robot_description."""

    def link(self, name: str) -> Link:
        """The link with this name (KeyError if absent)."""
        for lk in self.links:
            if lk.name == name:
                return lk
        raise KeyError(name)

    def joint(self, name: str) -> Joint:
        """The joint with this name (KeyError if absent)."""
        for j in self.joints:
            if j.name == name:
                return j
        raise KeyError(name)

    @property
    def root_link(self) -> str:
        """The link that is no joint's child (the first one if several)."""
        children = {j.child for j in self.joints if j.parent != "world"}
        for lk in self.links:
            if lk.name not in children:
                return lk.name
        return self.links[0].name


@dataclass(frozen=True, slots=True)
class Light:
    """A world ``<light>``: directional, point or spot, with its colours and direction."""

    name: str
    """The light's name."""
    type: str = "point"
    """"directional", "point" or "spot" (SDF's default: point)."""
    pose: Pose = IDENTITY
    """Where the light is, in the world (point and spot lights)."""
    diffuse: RGBA = (1.0, 1.0, 1.0, 1.0)
    """RGBA 0..1; SDF's default (sdf/1.11/light.sdf, which sdformat's Light returns for an element left out)."""
    specular: RGBA = (0.1, 0.1, 0.1, 1.0)
    """RGBA 0..1; SDF's default, as :attr:`diffuse`."""
    direction: Vec3 = (0.0, 0.0, -1.0)
    """Where a directional or spot light points, in the light's frame."""
    cast_shadows: bool = False
    """<cast_shadows>: whether cameras draw its shadows."""
    attenuation_range: float | None = None
    """<attenuation><range>, metres; None: unlimited."""
    location: SourceLocation | None = None
    """Where the <light> is written (file:line)."""


@dataclass(frozen=True, slots=True)
class PhysicsSettings:
    """A world's ``<physics>``: step size and real-time factor (the engine is always MuJoCo)."""

    max_step_size_sec: float = 0.001
    """<max_step_size>: MuJoCo's timestep, seconds of sim time per step."""
    real_time_factor: float = 1.0
    """<real_time_factor>: the pace the runtime keeps (1 = real time); --rtf overrides it."""
    real_time_update_rate_hz: float = 1000.0
    """<real_time_update_rate>: steps per wall second asked for. Gazebo Classic paces by it (a pace of
    rate x max_step_size, 0 as fast as possible); gz-sim by <real_time_factor>. gazelle paces by the factor,
    as gz-sim does, and takes a rate of 0 to mean as fast as possible, as Classic does (worlds written for
    Classic set the two consistently: 1000 x 0.001 = 1)."""


@dataclass(frozen=True, slots=True)
class Scene:
    """A world's ``<scene>``: ambient and background colours, shadows, grid."""

    ambient: RGBA = (0.4, 0.4, 0.4, 1.0)
    """RGBA 0..1."""
    background: RGBA = (0.7, 0.7, 0.7, 1.0)
    """RGBA 0..1: the sky cameras and the viewer see."""
    shadows: bool = True
    """Whether cameras draw shadows."""
    grid: bool = True
    """Whether the viewer draws a ground grid."""


@dataclass(frozen=True, slots=True)
class SphericalCoordinates:
    """``<spherical_coordinates>``: where the world's origin is on the Earth (GPS sensors read it)."""

    latitude_deg: float = 0.0
    """Latitude of the world origin, degrees North."""
    longitude_deg: float = 0.0
    """Longitude of the world origin, degrees East."""
    elevation: float = 0.0
    """Metres above the WGS84 ellipsoid."""
    heading_deg: float = 0.0
    """Rotation of the world frame from ``world_frame_orientation`` about the downward vertical
    (North to East positive), as SDF defines it."""
    surface_model: str = "EARTH_WGS84"
    """Only EARTH_WGS84 is read; others are warned about."""
    world_frame_orientation: str = "ENU"
    """ENU (x East, y North, z up), as gz-sim requires."""


@dataclass(frozen=True, slots=True)
class NamedPose:
    """A world ``<frame>`` attached to the world: a named place (simulation_interfaces' named poses).

    Its description, tags and bounds come from gazelle's custom elements in the frame (``<gazelle:description>``,
    ``<gazelle:tag>`` repeated, ``<gazelle:box>`` or ``<gazelle:sphere>``), which sdformat and gz-sim ignore."""

    name: str
    """The frame's name."""
    pose: Pose
    """X_WF: where it is in the world frame."""
    description: str = ""
    """``<gazelle:description>``: what the place is for."""
    tags: tuple[str, ...] = ()
    """``<gazelle:tag>`` elements, in file order."""
    box: tuple[Vec3, Vec3] | None = None
    """``<gazelle:box>``: two opposite corners of the free space, in the pose's frame (metres)."""
    sphere_radius: float | None = None
    """``<gazelle:sphere>``: the radius of the free ball about the pose (metres)."""
    location: SourceLocation | None = None
    """Where the <frame> is written (file:line)."""


DEFAULT_MAGNETIC_FIELD: Vec3 = (5.5645e-6, 22.8758e-6, -42.3884e-6)
"""SDF's default ``<magnetic_field>`` (tesla, ENU world frame)."""


@dataclass(frozen=True, slots=True)
class World:
    """A world: settings, models and lights."""

    name: str = "default"
    """The <world name>."""
    gravity: Vec3 = (0.0, 0.0, -9.8)
    """m/s² in the world frame (SDF's default points down -z)."""
    physics: PhysicsSettings = PhysicsSettings()
    """Step size and pace."""
    scene: Scene = Scene()
    """Colours, shadows, grid."""
    models: tuple[Model, ...] = ()
    """The models the world file places (<include>s resolved)."""
    lights: tuple[Light, ...] = ()
    """Its lights."""
    plugins: tuple[Plugin, ...] = ()
    """World-level <plugin>s (gz-sim systems, gazebo_ros_state, ...)."""
    source_file: str = ""
    """The file it was read from."""
    location: SourceLocation | None = None
    """Where the <world> is written (file:line)."""
    spherical_coordinates: SphericalCoordinates | None = None
    """None: the world does not say (GPS sensors then place its origin at 0° N, 0° E, as gz-sim does)."""
    magnetic_field: Vec3 = DEFAULT_MAGNETIC_FIELD
    """``<magnetic_field>`` in tesla, world frame (magnetometers read it); SDF's default otherwise."""
    named_poses: tuple[NamedPose, ...] = ()
    """Its ``<frame>``s attached to the world, in file order (see :class:`NamedPose`)."""


_Loaded = TypeVar("_Loaded", Model, World, Semantics)


@dataclass(frozen=True, slots=True)
class LoadResult:
    """What a loader returns: the description plus every diagnostic (warnings included)."""

    value: Model | World | Semantics
    diagnostics: tuple[Diagnostic, ...] = field(default=())

    @property
    def model(self) -> Model:
        """The value as a robot or object model (a URDF, xacro or SDF ``<model>``).

        Raises:
            TypeError: the description is a world or an SRDF.
        """
        return self._as(Model, "a robot or object model")

    @property
    def world(self) -> World:
        """The value as an SDF world.

        Raises:
            TypeError: the description is a model or an SRDF.
        """
        return self._as(World, "an SDF world")

    @property
    def semantics(self) -> Semantics:
        """The value as an SRDF's semantics.

        Raises:
            TypeError: the description is a model or a world.
        """
        return self._as(Semantics, "an SRDF")

    def _as(self, kind: type[_Loaded], wanted: str) -> _Loaded:
        if not isinstance(self.value, kind):
            raise TypeError(f"expected {wanted}, but the description is a {type(self.value).__name__}")
        return self.value

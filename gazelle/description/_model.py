"""The typed description model: what every loader (URDF, xacro, SDF, SRDF) produces.

Everything here is a frozen dataclass with tuples for collections, so a loaded
model can be shared between threads and never changes under the physics layer.
Conventions: SI units and radians; quaternions are ``wxyz`` (MuJoCo's order);
``X_AB`` is the pose of frame B expressed in frame A.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import TypeVar

from ._diagnostics import Diagnostic, SourceLocation

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
RGBA = tuple[float, float, float, float]


def quat_from_rpy(roll: float, pitch: float, yaw: float) -> Quat:
    """Quaternion (wxyz) of fixed-axis roll/pitch/yaw, as URDF and SDF define it (R = Rz·Ry·Rx)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (
        cr * cp * cy + sr * sp * sy,
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
    )


def quat_mul(a: Quat, b: Quat) -> Quat:
    """Hamilton product a*b of two wxyz quaternions."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    )


def quat_rotate(q: Quat, v: Vec3) -> Vec3:
    """Rotate vector v by unit quaternion q (wxyz)."""
    w, x, y, z = q
    vx, vy, vz = v
    # t = 2 * cross(q.xyz, v)
    tx = 2 * (y * vz - z * vy)
    ty = 2 * (z * vx - x * vz)
    tz = 2 * (x * vy - y * vx)
    return (
        vx + w * tx + (y * tz - z * ty),
        vy + w * ty + (z * tx - x * tz),
        vz + w * tz + (x * ty - y * tx),
    )


def quat_conj(q: Quat) -> Quat:
    """Conjugate (inverse for unit quaternions)."""
    return (q[0], -q[1], -q[2], -q[3])


def quat_to_rpy(q: Quat) -> Vec3:
    """Roll, pitch, yaw of a wxyz quaternion (inverse of :func:`quat_from_rpy`)."""
    w, x, y, z = q
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    sinp = max(-1.0, min(1.0, 2 * (w * y - z * x)))
    pitch = math.asin(sinp)
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return (roll, pitch, yaw)


@dataclass(frozen=True, slots=True)
class Pose:
    """A rigid transform: position and orientation (wxyz)."""

    position: Vec3 = (0.0, 0.0, 0.0)
    """Translation in metres."""
    orientation: Quat = (1.0, 0.0, 0.0, 0.0)
    """Unit quaternion, wxyz."""

    @staticmethod
    def from_xyz_rpy(xyz: Vec3 = (0.0, 0.0, 0.0), rpy: Vec3 = (0.0, 0.0, 0.0)) -> Pose:
        """Pose from a translation and fixed-axis roll/pitch/yaw in radians."""
        return Pose((float(xyz[0]), float(xyz[1]), float(xyz[2])), quat_from_rpy(*rpy))

    def __mul__(self, other: Pose) -> Pose:
        """Compose: ``X_AB * X_BC = X_AC``."""
        p = quat_rotate(self.orientation, other.position)
        return Pose(
            (self.position[0] + p[0], self.position[1] + p[1], self.position[2] + p[2]),
            quat_mul(self.orientation, other.orientation),
        )

    def inverse(self) -> Pose:
        """``X_BA`` from ``X_AB``."""
        qi = quat_conj(self.orientation)
        p = quat_rotate(qi, self.position)
        return Pose((-p[0], -p[1], -p[2]), qi)

    @property
    def rpy(self) -> Vec3:
        """Roll, pitch, yaw in radians."""
        return quat_to_rpy(self.orientation)


IDENTITY = Pose()


# --------------------------------------------------------------------------- geometry
@dataclass(frozen=True, slots=True)
class Box:
    """A box; ``size`` holds full edge lengths (x, y, z) in metres."""

    size: Vec3


@dataclass(frozen=True, slots=True)
class Cylinder:
    """A cylinder along its local z axis."""

    radius: float
    length: float


@dataclass(frozen=True, slots=True)
class Sphere:
    """A sphere."""

    radius: float


@dataclass(frozen=True, slots=True)
class Capsule:
    """A capsule along local z; ``length`` excludes the two hemispherical caps (SDF)."""

    radius: float
    length: float


@dataclass(frozen=True, slots=True)
class Cone:
    """A solid cone along local z (SDF 1.11): base of ``radius`` at z = -length/2, apex at +length/2."""

    radius: float
    length: float


@dataclass(frozen=True, slots=True)
class Ellipsoid:
    """An ellipsoid with semi-axes ``radii``."""

    radii: Vec3


@dataclass(frozen=True, slots=True)
class Plane:
    """An infinite plane (rendered with ``size``) with a normal in the local frame."""

    normal: Vec3 = (0.0, 0.0, 1.0)
    size: tuple[float, float] = (100.0, 100.0)


@dataclass(frozen=True, slots=True)
class Mesh:
    """A triangle mesh file."""

    uri: str
    """The URI as the user wrote it (``package://``, ``model://``, ``file://`` or a path)."""
    path: str | None
    """Absolute resolved file path, or None when it could not be resolved (a diagnostic says so)."""
    scale: Vec3 = (1.0, 1.0, 1.0)


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
    specular: RGBA | None = None
    emissive: RGBA | None = None
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
    slip1: float | None = None
    slip2: float | None = None
    torsional: float | None = None
    """Torsional friction coefficient."""
    rolling: float | None = None
    """Rolling friction coefficient (MuJoCo extension)."""
    kp: float | None = None
    """Contact stiffness (N/m)."""
    kd: float | None = None
    """Contact damping (N·s/m)."""
    min_depth: float | None = None
    max_vel: float | None = None
    soft_cfm: float | None = None
    soft_erp: float | None = None
    restitution: float | None = None
    collide_bitmask: int | None = None


@dataclass(frozen=True, slots=True)
class Collision:
    """A collision shape attached to a link."""

    name: str
    pose: Pose
    """X_LG: pose of the geometry in the link frame."""
    geometry: Geometry
    surface: Surface = Surface()
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class Visual:
    """A visual shape attached to a link."""

    name: str
    pose: Pose
    """X_LG: pose of the geometry in the link frame."""
    geometry: Geometry
    material: Material | None = None
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class Inertial:
    """Mass properties of a link."""

    mass: float
    """kg."""
    pose: Pose = IDENTITY
    """X_LI: centre of mass and principal-axis orientation in the link frame."""
    ixx: float = 0.0
    ixy: float = 0.0
    ixz: float = 0.0
    iyy: float = 0.0
    iyz: float = 0.0
    izz: float = 0.0
    derived: bool = False
    """True when gazelle derived the inertia from geometry (a diagnostic says why)."""


# --------------------------------------------------------------------------- generic config trees
@dataclass(frozen=True, slots=True)
class ConfigElement:
    """A read-only copy of an XML element (plugin configuration, sensor blocks, extensions).

    Systems parse these into their own typed config; the physics layer never reads them.
    """

    tag: str
    attributes: tuple[tuple[str, str], ...] = ()
    text: str = ""
    children: tuple[ConfigElement, ...] = ()
    location: SourceLocation | None = None

    def attr(self, name: str, default: str | None = None) -> str | None:
        """Attribute value or ``default``."""
        for k, v in self.attributes:
            if k == name:
                return v
        return default

    def find(self, tag: str) -> ConfigElement | None:
        """First direct child with this tag."""
        for c in self.children:
            if c.tag == tag:
                return c
        return None

    def findall(self, tag: str) -> tuple[ConfigElement, ...]:
        """All direct children with this tag."""
        return tuple(c for c in self.children if c.tag == tag)


@dataclass(frozen=True, slots=True)
class Plugin:
    """A ``<plugin>`` block, kept with its raw configuration for the systems to read."""

    name: str
    filename: str
    config: ConfigElement
    """The whole ``<plugin>`` element."""
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class Sensor:
    """A ``<sensor>`` block (camera, ray/lidar, imu, ...)."""

    name: str
    type: str
    pose: Pose
    """Pose in the link frame."""
    update_rate_hz: float = 0.0
    always_on: bool = False
    topic: str = ""
    config: ConfigElement | None = None
    plugins: tuple[Plugin, ...] = ()
    location: SourceLocation | None = None
    joint: str = ""
    """For a sensor on a joint (force_torque): the joint's name. The sensor is kept with the joint's
    child link, and ``pose`` is then in the joint's frame."""


# --------------------------------------------------------------------------- kinematics
@dataclass(frozen=True, slots=True)
class Link:
    """A rigid body."""

    name: str
    inertial: Inertial | None = None
    """None means massless (only valid for links welded to a parent by a fixed joint)."""
    visuals: tuple[Visual, ...] = ()
    collisions: tuple[Collision, ...] = ()
    sensors: tuple[Sensor, ...] = ()
    gravity: bool = True
    kinematic: bool = False
    self_collide: bool | None = None
    pose: Pose | None = None
    """X_ML: link pose in the model frame as the file gives it (SDF). URDF leaves None; the tree gives it."""
    location: SourceLocation | None = None


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
    upper: float | None = None
    effort: float | None = None
    """Max force/torque; None = unlimited."""
    velocity: float | None = None


@dataclass(frozen=True, slots=True)
class JointDynamics:
    """A joint's damping, friction and spring (URDF ``<dynamics>``, SDF ``<axis><dynamics>``)."""

    damping: float = 0.0
    friction: float = 0.0
    spring_stiffness: float = 0.0
    spring_reference: float = 0.0


@dataclass(frozen=True, slots=True)
class JointAxis:
    """A joint axis, expressed in the joint frame, unit length."""

    xyz: Vec3 = (1.0, 0.0, 0.0)
    limit: JointLimit = JointLimit()
    dynamics: JointDynamics = JointDynamics()


@dataclass(frozen=True, slots=True)
class Mimic:
    """URDF ``<mimic>``: this joint follows ``joint`` as ``multiplier * q + offset``."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class SafetyController:
    """URDF ``<safety_controller>`` (kept for controllers that read it; not simulated)."""

    soft_lower_limit: float = 0.0
    soft_upper_limit: float = 0.0
    k_position: float = 0.0
    k_velocity: float = 0.0


@dataclass(frozen=True, slots=True)
class Calibration:
    """URDF ``<calibration>`` (kept as given; not simulated)."""

    rising: float | None = None
    falling: float | None = None


@dataclass(frozen=True, slots=True)
class Joint:
    """A joint between a parent link (or ``world``) and a child link.

    At joint position zero, ``X_PC = origin * child_offset``; in general
    ``X_PC(q) = origin * motion(axis, q) * child_offset``.
    """

    name: str
    type: JointType
    parent: str
    """Parent link name, or ``"world"``."""
    child: str
    origin: Pose = IDENTITY
    """X_PJ: the joint frame in the parent link frame (URDF ``<origin>``)."""
    child_offset: Pose = IDENTITY
    """X_JC: the child link frame in the joint frame (identity for URDF; SDF may differ)."""
    axis: JointAxis | None = None
    axis2: JointAxis | None = None
    """Second axis (universal joints)."""
    screw_thread_pitch: float | None = None
    mimic: Mimic | None = None
    safety_controller: SafetyController | None = None
    calibration: Calibration | None = None
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class Frame:
    """A named frame attached to a link (SDF ``<frame>``)."""

    name: str
    attached_to: str
    pose: Pose
    """Pose in the attached-to frame."""
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class GazeboExtension:
    """A URDF ``<gazebo>`` block (kept whole; its known tags are also applied to links)."""

    reference: str | None
    config: ConfigElement
    location: SourceLocation | None = None


# --------------------------------------------------------------------------- semantics (SRDF)
@dataclass(frozen=True, slots=True)
class Chain:
    """SRDF ``<chain base_link tip_link>`` inside a group."""

    base_link: str
    tip_link: str


@dataclass(frozen=True, slots=True)
class Group:
    """SRDF ``<group>``: the joints, links, chains and subgroups a planner moves together."""

    name: str
    links: tuple[str, ...] = ()
    joints: tuple[str, ...] = ()
    chains: tuple[Chain, ...] = ()
    subgroups: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class GroupState:
    """SRDF ``<group_state>``: a named joint configuration of a group (``home``, ``ready``)."""

    name: str
    group: str
    joint_values: tuple[tuple[str, tuple[float, ...]], ...] = ()


@dataclass(frozen=True, slots=True)
class EndEffector:
    """SRDF ``<end_effector>``: a group attached to a parent link (and parent group)."""

    name: str
    parent_link: str
    group: str
    parent_group: str | None = None


@dataclass(frozen=True, slots=True)
class VirtualJoint:
    """SRDF ``<virtual_joint>``: how the robot's root attaches to the world frame."""

    name: str
    type: str
    parent_frame: str
    child_link: str


@dataclass(frozen=True, slots=True)
class DisabledCollision:
    """SRDF ``<disable_collisions>``: a link pair a planner never checks, and why."""

    link1: str
    link2: str
    reason: str = ""


@dataclass(frozen=True, slots=True)
class Semantics:
    """The content of an SRDF."""

    robot_name: str
    groups: tuple[Group, ...] = ()
    group_states: tuple[GroupState, ...] = ()
    end_effectors: tuple[EndEffector, ...] = ()
    virtual_joints: tuple[VirtualJoint, ...] = ()
    passive_joints: tuple[str, ...] = ()
    disabled_collisions: tuple[DisabledCollision, ...] = ()


# --------------------------------------------------------------------------- ros2_control
SIMULATED_HARDWARE = frozenset(
    {
        "gazebo_ros2_control/GazeboSystem",
        "gz_ros2_control/GazeboSimSystem",
        "ign_ros2_control/IgnitionSystem",
        "mujoco_ros2_control/MujocoSystem",
        "mock_components/GenericSystem",
    }
)
"""``<hardware><plugin>`` names that mean "the simulator is the hardware"."""


@dataclass(frozen=True, slots=True)
class ControlInterface:
    """A ``<command_interface>`` or ``<state_interface>`` of a ros2_control component, with its
    ``<param>`` s (``min``, ``max``, ``initial_value``, ``data_type``...) as written."""

    name: str
    params: tuple[tuple[str, str], ...] = ()
    location: SourceLocation | None = None

    def param(self, name: str) -> str | None:
        """A ``<param name=...>`` value as written, or None."""
        return next((v for k, v in self.params if k == name), None)


@dataclass(frozen=True, slots=True)
class ControlComponent:
    """A ``<joint>``, ``<sensor>`` or ``<gpio>`` of a ``<ros2_control>`` block."""

    name: str
    command_interfaces: tuple[ControlInterface, ...] = ()
    state_interfaces: tuple[ControlInterface, ...] = ()
    params: tuple[tuple[str, str], ...] = ()
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class Ros2Control:
    """A URDF ``<ros2_control name type>`` block: its hardware and what it exposes to controllers."""

    name: str
    type: str
    """``system``, ``actuator`` or ``sensor``."""
    hardware_plugin: str = ""
    """``<hardware><plugin>``; see :data:`SIMULATED_HARDWARE` and :attr:`simulated`."""
    hardware_params: tuple[tuple[str, str], ...] = ()
    joints: tuple[ControlComponent, ...] = ()
    sensors: tuple[ControlComponent, ...] = ()
    gpios: tuple[ControlComponent, ...] = ()
    location: SourceLocation | None = None

    @property
    def simulated(self) -> bool:
        """Whether the hardware plugin is a simulator's (else a real driver, which the simulator stands in for)."""
        return self.hardware_plugin in SIMULATED_HARDWARE


# --------------------------------------------------------------------------- models and worlds
@dataclass(frozen=True, slots=True)
class Model:
    """A robot or object: a tree (or forest) of links and joints with its plugins."""

    name: str
    links: tuple[Link, ...]
    joints: tuple[Joint, ...] = ()
    frames: tuple[Frame, ...] = ()
    plugins: tuple[Plugin, ...] = ()
    """Model-level plugins (URDF robot-level ``<gazebo><plugin>``, SDF ``<model><plugin>``)."""
    gazebo: tuple[GazeboExtension, ...] = ()
    """URDF ``<gazebo>`` blocks as written."""
    static: bool = False
    pose: Pose = IDENTITY
    """X_WM: where the file places the model (SDF ``<pose>``; identity for URDF)."""
    canonical_link: str | None = None
    """The link whose frame is the model frame; defaults to the root link."""
    self_collide: bool = False
    semantics: Semantics | None = None
    source_format: str = ""
    """"urdf", "sdf", ... for messages."""
    source_file: str = ""
    location: SourceLocation | None = None
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
    type: str = "directional"
    """"directional", "point" or "spot"."""
    pose: Pose = IDENTITY
    diffuse: RGBA = (0.8, 0.8, 0.8, 1.0)
    specular: RGBA = (0.2, 0.2, 0.2, 1.0)
    direction: Vec3 = (0.0, 0.0, -1.0)
    cast_shadows: bool = False
    attenuation_range: float | None = None
    location: SourceLocation | None = None


@dataclass(frozen=True, slots=True)
class PhysicsSettings:
    """A world's ``<physics>``: step size and real-time factor (the engine is always MuJoCo)."""

    max_step_size_sec: float = 0.001
    real_time_factor: float = 1.0
    real_time_update_rate_hz: float = 1000.0
    """0 = as fast as possible."""


@dataclass(frozen=True, slots=True)
class Scene:
    """A world's ``<scene>``: ambient and background colours, shadows, grid."""

    ambient: RGBA = (0.4, 0.4, 0.4, 1.0)
    background: RGBA = (0.7, 0.7, 0.7, 1.0)
    shadows: bool = True
    grid: bool = True


@dataclass(frozen=True, slots=True)
class SphericalCoordinates:
    """``<spherical_coordinates>``: where the world's origin is on the Earth (GPS sensors read it)."""

    latitude_deg: float = 0.0
    longitude_deg: float = 0.0
    elevation: float = 0.0
    """Metres above the WGS84 ellipsoid."""
    heading_deg: float = 0.0
    """Rotation of the world frame from ``world_frame_orientation`` about the downward vertical
    (North to East positive), as SDF defines it."""
    surface_model: str = "EARTH_WGS84"
    world_frame_orientation: str = "ENU"


DEFAULT_MAGNETIC_FIELD: Vec3 = (5.5645e-6, 22.8758e-6, -42.3884e-6)
"""SDF's default ``<magnetic_field>`` (tesla, ENU world frame)."""


@dataclass(frozen=True, slots=True)
class World:
    """A world: settings, models and lights."""

    name: str = "default"
    gravity: Vec3 = (0.0, 0.0, -9.8)
    physics: PhysicsSettings = PhysicsSettings()
    scene: Scene = Scene()
    models: tuple[Model, ...] = ()
    lights: tuple[Light, ...] = ()
    plugins: tuple[Plugin, ...] = ()
    source_file: str = ""
    location: SourceLocation | None = None
    spherical_coordinates: SphericalCoordinates | None = None
    """None: the world does not say (GPS sensors then place its origin at 0° N, 0° E, as gz-sim does)."""
    magnetic_field: Vec3 = DEFAULT_MAGNETIC_FIELD
    """``<magnetic_field>`` in tesla, world frame (magnetometers read it); SDF's default otherwise."""


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

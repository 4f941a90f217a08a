"""The world's entities and errors: what a spawn places (:class:`Entity`, :class:`StagedRequest`), what a
query reads (:class:`EntityState`), the rules a name and a pose must pass, and the kinds of error a request
gets back (:class:`ErrorKind`: the runtime and ROS map each to their own reply codes)."""

from __future__ import annotations

import enum
import math
import re
from collections.abc import Container
from dataclasses import dataclass, field
from typing import Any

import mujoco

from .._errors import SimError
from ..description import Model, Pose, excerpt
from ._builder import SEP, BuildError, BuiltEntity

MAX_COORDINATE_M = 1.0e5
"""Farthest a spawn or set-state may place anything from the origin (100 km): beyond, float64
positions lose the millimetres contacts need, and such a pose is a mistake or an attack."""

WORLD_FRAMES = frozenset({"", "world", "/world", "map", "/map"})
"""Frame names that mean the world frame in requests and plugin configuration (gazebo_ros accepts
'' and world; map and the slashed spellings are what ROS users write)."""

ENTITY_NAME_RE = re.compile(r"^(?!\s)[^\x00-\x1f\x7f]{1,256}(?<!\s)$")
"""Entity names as Gazebo takes them: any printable text up to 256 characters without leading or
trailing white space ("Construction Cone" comes from every GUI-saved world); ``::`` is refused
separately, as it separates an entity from its links."""
NAME_RULE = "printable characters, at most 256, no leading or trailing space, no '::'"


class ErrorKind(enum.StrEnum):
    """Why a request on the world failed; the bridge maps each to the services' result codes."""

    NAME_NOT_UNIQUE = "name_not_unique"
    """A spawn under a name an entity already has (simulation_interfaces' SpawnEntity: NAME_NOT_UNIQUE)."""
    NAME_INVALID = "name_invalid"
    """A name that is empty, unprintable, too long or holds ``::`` (NAME_INVALID)."""
    NOT_FOUND = "not_found"
    """No entity (or joint, link, frame) of that name (RESULT_NOT_FOUND)."""
    INVALID_POSE = "invalid_pose"
    """A pose that is not finite, too far, or has a zero quaternion (SpawnEntity's INVALID_POSE)."""
    BUILD_FAILED = "build_failed"
    """The model could not be compiled into the world, or a plugin failed to configure (the reason is the reply's
    message)."""
    INCORRECT_STATE = "incorrect_state"
    """A request the entity cannot take in its state: a twist for a static entity."""
    DIVERGED = "diverged"
    """The physics state went NaN or ran away."""
    OVERLOAD = "overload"
    """MuJoCo ran out of its memory bounds (too many contacts or constraints)."""


class WorldError(SimError):
    """A request on the world failed; :attr:`kind` says how."""

    def __init__(self, kind: ErrorKind, message: str):
        super().__init__(message)
        self.kind = kind


class PhysicsOverload(WorldError):
    """MuJoCo cannot step the world within its memory bounds (see :meth:`PhysicsWorld._guarded`)."""

    def __init__(self, message: str):
        super().__init__(ErrorKind.OVERLOAD, message)


def checked_placement(name: str, X_WM: Pose, taken: Container[str]) -> Pose:
    """``X_WM`` with a unit quaternion, once the name is free and valid and the pose usable.

    Raises:
        WorldError: a taken or invalid name, a non-finite, absurd or zero-quaternion pose.
    """
    if name in taken:
        raise WorldError(ErrorKind.NAME_NOT_UNIQUE, f"entity '{name}' already exists")
    if not name or SEP in name or not ENTITY_NAME_RE.match(name):
        raise WorldError(ErrorKind.NAME_INVALID, f"invalid entity name {excerpt(name)}: use {NAME_RULE}")
    if not all(math.isfinite(v) for v in (*X_WM.position, *X_WM.orientation)):
        raise WorldError(ErrorKind.INVALID_POSE, f"pose of '{name}' is not finite: {X_WM}")
    far = pose_out_of_range(X_WM, "position")
    if far is not None:
        raise WorldError(ErrorKind.INVALID_POSE, f"pose of '{name}': {far}")
    qn = math.sqrt(sum(v * v for v in X_WM.orientation))
    if qn < 1e-9:
        raise WorldError(ErrorKind.INVALID_POSE, f"orientation of '{name}' is a zero quaternion")
    w, x, y, z = X_WM.orientation  # normalised: a user's 0 0 0.7071 0.7071 is a rotation, only rounded
    return Pose(X_WM.position, (w / qn, x / qn, y / qn, z / qn))


def pose_out_of_range(pose: Pose, field_name: str) -> str | None:
    """Why a pose is absurd (a coordinate beyond :data:`MAX_COORDINATE_M`), naming the field, or None."""
    for axis, v in zip("xyz", pose.position):
        if abs(v) > MAX_COORDINATE_M:
            return f"{field_name}.{axis} = {v:g} m is out of range (at most {MAX_COORDINATE_M:g} m from the origin)"
    return None


_MASSLESS = re.compile(r"mass and inertia of moving bodies must be larger than mjMINVAL Element name '([^']*)'")
"""MuJoCo's compile error for a moving body without mass; users get it in their own terms."""


def build_failed(name: str, err: Exception) -> WorldError:
    """The :class:`WorldError` (``BUILD_FAILED``) for an entity whose build (or a plugin's configure) raised."""
    return WorldError(ErrorKind.BUILD_FAILED, f"cannot build '{name}': {_describe(err)}")


def _describe(err: Exception) -> str:
    """A one-line reason for a failed build: our own errors as they are, others with their type."""
    if isinstance(err, (BuildError, WorldError)):
        return str(err)
    text = " ".join(str(err).split())
    massless = _MASSLESS.search(text)
    if massless is not None:
        entity, _, link = massless.group(1).partition(SEP)
        return (
            f"link '{link}' moves (it has a joint, or is the free root) but neither it nor any link fixed to it has "
            "mass or inertia; give it an <inertial> with mass > 0 (Gazebo would not model it)"
        )
    if isinstance(err, (ValueError, mujoco.FatalError)):
        return text
    return f"{type(err).__name__}: {text}" if text else type(err).__name__


def no_joint_message(entity: Entity, joint: str) -> str:
    """Why ``joint`` cannot be actuated: missing, or fixed (and then no MuJoCo joint exists)."""
    for j in entity.model.joints:
        if j.name == joint:
            return f"joint '{joint}' of entity '{entity.name}' is {j.type.value}: it has no degree of freedom to drive"
    movable = sorted(j.name for j in entity.model.joints if j.type.value != "fixed")
    return f"entity '{entity.name}' has no joint '{joint}' (movable joints: {', '.join(movable) or 'none'})"


@dataclass
class Entity:
    """A model living in the world."""

    name: str
    model: Model
    namespace: str
    X_WM: Pose
    """Where it was placed at spawn time."""
    built: BuiltEntity
    spawned: bool
    """True if added at run time (removed by a SCOPE_SPAWNED reset)."""
    generation_added: int = 0
    systems: list[Any] = field(default_factory=list)
    """What the runtime attached to this entity (its plugins' systems); physics never looks inside."""
    category: int | None = None
    """The category a client set (simulation_interfaces' SetEntityInfo, its EntityCategory code); None: the one its
    model implies. Physics never reads it, nor :attr:`description` and :attr:`tags`."""
    description: str | None = None
    """The description a client set; None: the one gazelle writes from the model."""
    tags: tuple[str, ...] = ()
    """The tags a client set (entity filters match them)."""

    @property
    def static(self) -> bool:
        """Whether the model is static (it never moves)."""
        return self.model.static


@dataclass(frozen=True, slots=True)
class StagedRequest:
    """One model to add in a batch (:meth:`PhysicsWorld.stage_many`)."""

    model: Model
    name: str
    X_WM: Pose
    """Where the model frame goes in the world."""
    namespace: str = ""
    spawned: bool = True


@dataclass(frozen=True)
class EntityState:
    """Ground-truth state of an entity's model frame, in the world frame."""

    pose: Pose
    linear_velocity: tuple[float, float, float]
    angular_velocity: tuple[float, float, float]


CAMERA_SENSOR_TYPES = frozenset({"camera", "depth", "depth_camera", "rgbd_camera", "rgbd", "multicamera"})


def has_camera(model: Model) -> bool:
    """Whether a model carries a camera: its visuals then go into the MuJoCo model, so it renders what users see."""
    return any(s.type in CAMERA_SENSOR_TYPES for lk in model.links for s in lk.sensors)

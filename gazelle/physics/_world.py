"""The simulated world: a MuJoCo model and data built from description objects.

``PhysicsWorld`` is not thread-safe by itself; :class:`gazelle.physics.Simulation`
owns one and serialises every access through its command queue.
"""

from __future__ import annotations

import enum
import hashlib
import logging
import math
import pickle
import re
from collections.abc import Callable, Container, Sequence
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from ..description import Light, Model, Pose, World, excerpt, quat_conj, quat_rotate, rotation_matrix
from ._builder import (
    JOINT_ARMATURE,
    SEP,
    SHARED_MESH,
    BuildError,
    BuiltEntity,
    add_model,
    add_visuals,
    friction_priority,
    scoped,
)
from ._convex import cache_dir
from ._handles import ActuatorGroup, ActuatorHandle, ActuatorKind, BodyHandle, JointGroup, JointHandle
from ._render import OffscreenRenderer
from ._servo_plan import ServoPlan, run_plans

_log = logging.getLogger("gazelle.physics")
MAX_COORDINATE_M = 1.0e5
"""Farthest a spawn or set-state may place anything from the origin (100 km): beyond, float64
positions lose the millimetres contacts need, and such a pose is a mistake or an attack."""

WORLD_FRAMES = frozenset({"", "world", "/world", "map", "/map"})
"""Frame names that mean the world frame in requests and plugin configuration (gazebo_ros accepts
'' and world; map and the slashed spellings are what ROS users write)."""

DEEP_PENETRATION_M = 0.01
"""A contact deeper than this is a start-up overlap (or a teleport), not a resting contact (~0.3 mm)."""
MAX_CORRECTING_VEL = 0.5
"""m/s: the fastest a body deep in penetration is pushed out (ODE's ``max_correcting_vel`` idea); it then
rises at most v²/2g ≈ 1.3 cm above its resting height."""
OVERLAP_CHECK_EVERY = 16
"""Steps between two overlap checks while nothing is deep in (a new overlap waits at most 16 ms)."""
OVERLAP_WATCH_SEC = 5.0
"""How long after a body is placed deep overlaps are watched for (1 m of overlap clears in 2 s)."""
MAX_CORRECTING_SPIN = 2.0
"""rad/s: the fastest such a body may spin while it is pushed out (uneven overlaps flipped it over)."""

_ACTUATOR_SUFFIX = {ActuatorKind.POSITION: "pos", ActuatorKind.VELOCITY: "vel", ActuatorKind.EFFORT: "eff"}
_ONE_DOF = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
ENTITY_NAME_RE = re.compile(r"^(?!\s)[^\x00-\x1f\x7f]{1,256}(?<!\s)$")
"""Entity names as Gazebo takes them: any printable text up to 256 characters without leading or
trailing white space ("Construction Cone" comes from every GUI-saved world); ``::`` is refused
separately, as it separates an entity from its links."""
NAME_RULE = "printable characters, at most 256, no leading or trailing space, no '::'"


class ErrorKind(enum.StrEnum):
    """Why a request on the world failed; the bridge maps each to the services' result codes."""

    NAME_NOT_UNIQUE = "name_not_unique"
    NAME_INVALID = "name_invalid"
    NOT_FOUND = "not_found"
    INVALID_POSE = "invalid_pose"
    BUILD_FAILED = "build_failed"
    INCORRECT_STATE = "incorrect_state"
    DIVERGED = "diverged"
    OVERLOAD = "overload"


class WorldError(Exception):
    """A request on the world failed; :attr:`kind` says how."""

    def __init__(self, kind: ErrorKind, message: str):
        super().__init__(message)
        self.kind = kind


class PhysicsOverload(WorldError):
    """MuJoCo cannot step the world within its memory bounds (see :meth:`PhysicsWorld._guarded`)."""

    def __init__(self, message: str):
        super().__init__(ErrorKind.OVERLOAD, message)


MAX_ARENA_BYTES = 1 << 30
"""The most MuJoCo arena (contacts, constraints, solver scratch) the world may grow to: 1 GiB."""


def _checked_placement(name: str, X_WM: Pose, taken: Container[str]) -> Pose:
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
    w, x, y, z = X_WM.orientation
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


def _no_joint_message(entity: Entity, joint: str) -> str:
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


RAY_GEOM_GROUPS = np.array([0, 0, 1, 1, 0, 0], dtype=np.uint8)
"""Geom groups rays hit: the collision geoms (groups 2 and 3), as Gazebo's ``ray`` sensor sees collisions."""


CAMERA_SENSOR_TYPES = frozenset({"camera", "depth", "depth_camera", "rgbd_camera", "rgbd", "multicamera"})


def has_camera(model: Model) -> bool:
    """Whether a model carries a camera: its visuals then go into the MuJoCo model, so it renders what users see."""
    return any(s.type in CAMERA_SENSOR_TYPES for lk in model.links for s in lk.sensors)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b for 3-vectors (np.cross costs ~10 µs a call)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


@dataclass(frozen=True)
class ContactPoint:
    """One MuJoCo contact, seen from the side of ``collision1``: the force and torque that
    ``collision2`` exerts on ``collision1`` (world frame, at the contact point), the normal pointing
    from ``collision2`` into ``collision1``, and the penetration depth (positive when overlapping)."""

    collision1: str
    collision2: str
    """Gazebo-style scoped names: ``model::link::collision``."""
    position: tuple[float, float, float]
    normal: tuple[float, float, float]
    force: tuple[float, float, float]
    torque: tuple[float, float, float]
    depth: float


def _vec3(v: Sequence[float] | np.ndarray) -> tuple[float, float, float]:
    """Three floats of a MuJoCo vector, as a typed 3-tuple."""
    return (float(v[0]), float(v[1]), float(v[2]))


def _gazebo_collision_name(geom_name: str) -> str:
    """``entity::link::collision#i`` (MuJoCo) -> ``entity::link::collision`` (Gazebo)."""
    return geom_name.rsplit("#", 1)[0] if "#" in geom_name else geom_name


class PhysicsWorld:
    """MuJoCo model + data, with spawn and delete while running."""

    def __init__(self, world: World, *, timestep_sec: float | None = None, visual_geoms: bool = False):
        """
        Args:
            world: the world description (its models are added by the runtime).
            timestep_sec: the physics step; default the world's ``max_step_size``.
            visual_geoms: put every entity's visuals in the MuJoCo model too (non-colliding, massless),
                so an offscreen camera renders what users see. Off unless something renders: the Panda's
                DAE visuals cost 0.85 s at spawn and ~20 % more time per step.
        """
        self.visual_geoms = visual_geoms
        self.description = world
        self.spec = mujoco.MjSpec()
        self.spec.modelname = world.name or "world"
        opt = self.spec.option
        opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        opt.timestep = timestep_sec or world.physics.max_step_size_sec
        opt.gravity = np.array(world.gravity, dtype=np.float64)
        opt.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        # a diverging state is found, reported and repaired per entity (recover_divergence),
        # never silently reset for the whole world as MuJoCo would
        opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_AUTORESET)
        self.spec.compiler.degree = False
        for light in world.lights:
            self._add_light(light)
        self._add_background(world)
        self.entities: dict[str, Entity] = {}
        self.generation = 0
        """Bumped at every recompile: indices cached against an older generation are stale."""
        self._before_compile: list[Callable[[], None]] = []
        self._kinematics_stale = False
        self._imu_acc, self._imu_vel, self._imu_quat, self._imu_R, self._imu_wa = (
            np.empty(6),
            np.empty(6),
            np.empty(4),
            np.empty((3, 3)),
            np.empty((2, 3)),
        )
        self._offsets: dict[Pose, tuple[np.ndarray, np.ndarray, bool, bool]] = {}
        """Sensor offsets (in their body) -> (position, rotation matrix, at the origin, unrotated)."""
        self._actuator_gains: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        """Actuator name -> its gain and bias parameters as added (see :meth:`set_actuator_enabled`)."""
        self._overlap_steps = 0
        """Steps left in which deep overlaps are limited (see :meth:`_limit_correcting_velocity`)."""
        self._deep = False
        """Whether the last check found a deep overlap (then every step is checked)."""
        self._reported: dict[tuple[str, tuple[str, ...]], int] = {}
        """(model source, unsimulated parameters) -> how many entities had them (reported at the first)."""
        self._held: tuple[np.ndarray, np.ndarray] | None | bool = False
        """(qpos addresses, dof addresses) of the hinge/slide dofs above kinematic links; False = not indexed yet."""
        self._servo_plans: list[ServoPlan] = []
        """Planned servo cycles the steps run (see :meth:`add_servo_plan`)."""
        self.model: mujoco.MjModel = self.spec.compile()
        self._timestep = float(self.model.opt.timestep)
        self.data = mujoco.MjData(self.model)
        self._state_views: tuple[Any, np.ndarray, np.ndarray] = (None, np.zeros(0), np.zeros(0))
        """(MjData, its qpos, its qvel): array views kept for the divergence check before every block of steps."""

    # ------------------------------------------------------------------ building
    def _forward(self) -> None:
        """``mj_forward``, growing the arena if the contacts need more memory (see :meth:`_guarded`)."""
        self._guarded(mujoco.mj_forward)

    def _guarded(self, fn: Callable[[mujoco.MjModel, mujoco.MjData], None]) -> None:
        """Run a MuJoCo pipeline call; when its arena (contacts, constraints) runs out, grow it and retry.

        Overlapping bodies make contacts by the thousand (8 clients spawning boxes at one spot ran
        MuJoCo's arena out and killed the simulation thread with ``mj_stackAlloc: out of memory``).
        The arena doubles, keeping the state, up to :data:`MAX_ARENA_BYTES`; past that,
        :class:`PhysicsOverload` says so, and the simulation pauses instead of dying.
        """
        try:
            fn(self.model, self.data)
            return
        except mujoco.FatalError as err:
            if "memory" not in str(err).lower() and "stack" not in str(err).lower():
                raise
            self._grow_arena(fn, str(err).strip().splitlines()[0])

    def _grow_arena(self, fn: Callable[[mujoco.MjModel, mujoco.MjData], None], reason: str) -> None:
        """After ``fn`` ran MuJoCo's arena out: grow it (see :meth:`_guarded`) and run ``fn`` again."""
        while True:
            # the interrupted pipeline left its stack frames and a partial arena in mjData: release them,
            # or copying the data (the recompile) is a fatal MuJoCo error that ends the process
            d = self.data
            d.pstack, d.pbase, d.parena, d.ncon = 0, 0, 0, 0
            current = int(self.model.narena)
            if current >= MAX_ARENA_BYTES:
                raise PhysicsOverload(
                    f"the contacts and constraints need more than {MAX_ARENA_BYTES >> 20} MiB of MuJoCo arena "
                    f"({reason}); overlapping bodies? delete some, or reset"
                )
            self.spec.memory = min(MAX_ARENA_BYTES, max(2 * current, 64 << 20))
            self._recompile()
            _log.warning(f"MuJoCo's arena ran out ({reason}): grown to {self.spec.memory >> 20} MiB")
            try:
                fn(self.model, self.data)
                return
            except mujoco.FatalError as err:
                reason = str(err).strip().splitlines()[0]

    def _recompile(self) -> None:
        self.model, self.data = self.spec.recompile(self.model, self.data)
        self.generation += 1
        self._held = False  # re-indexed at the next step, once ``entities`` matches the model

    def stage(self, model: Model, *, name: str, X_WM: Pose, namespace: str = "", spawned: bool = True) -> Entity:
        """Add a model's bodies to the world's spec, not yet to the running model.

        The caller (the runtime) then lets the entity's systems add actuators and set joint
        properties (:meth:`add_actuator`, :meth:`set_joint_armature`, ...), and finally
        :meth:`commit` s it, or :meth:`discard` s it. Until then the running model is unchanged.

        Raises:
            WorldError: a taken or invalid name, a bad pose (nothing was added), or the
                description cannot be built (``BUILD_FAILED``; what was added is removed again).
        """
        return self._stage(model, name, X_WM, namespace, spawned, self.entities)

    def _stage(
        self, model: Model, name: str, X_WM: Pose, namespace: str, spawned: bool, taken: Container[str]
    ) -> Entity:
        X_WM = _checked_placement(name, X_WM, taken)
        if has_camera(model) and not self.visual_geoms:
            # a camera comes into the world: from now on every entity's visuals are in the model, so it
            # sees the world as users do (its textures, not the collision shapes in a flat colour)
            self.visual_geoms = True
            for other in self.entities.values():
                add_visuals(self.spec, other.model, other.built)
        try:
            built = add_model(self.spec, model, name, X_WM, visuals=self.visual_geoms)
        except Exception as err:
            self._remove_elements(name)
            raise build_failed(name, err) from None
        return Entity(name, model, namespace, X_WM, built, spawned)

    def discard(self, entity: Entity) -> None:
        """Take a staged entity's elements out of the spec again (the running model never had them)."""
        self._remove_elements(entity.name)

    def commit(self, staged: list[Entity]) -> None:
        """Recompile with the staged entities, keeping every existing entity's state.

        Raises:
            WorldError: (``BUILD_FAILED``) MuJoCo refused the model: the staged entities are
                discarded and the world is as it was. (``OVERLOAD``) the new contacts need more
                memory than the world may have: they are removed again.
        """
        if not staged:
            return
        try:
            self._recompile()
        except Exception as err:
            # the recompile failed, so model/data are the old ones; removing what was staged
            # makes the spec match them again
            for e in staged:
                self._remove_elements(e.name)
            what = staged[0].name if len(staged) == 1 else "the batch"
            raise build_failed(what, err) from None
        for e in staged:
            e.generation_added = self.generation
            self.entities[e.name] = e
            self._report_unsimulated(e)
            self._report_decomposed(e)
        self._watch_overlaps()
        try:
            self._forward()
        except PhysicsOverload:
            for e in staged:
                self.remove_entity(e.name)  # the world as it was; the reply says why
            raise

    def add_entity(self, model: Model, *, name: str, X_WM: Pose, namespace: str = "", spawned: bool = True) -> Entity:
        """Add a model as a new entity (no systems) while keeping every other entity's state.

        Raises:
            WorldError: duplicate or invalid name, NaN pose, or the model cannot be built;
                the world is then unchanged.
        """
        entity = self.stage(model, name=name, X_WM=X_WM, namespace=namespace, spawned=spawned)
        self.commit([entity])
        return entity

    def _report_decomposed(self, entity: Entity) -> None:
        """Say once per mesh file what was done to its non-convex collision mesh, and what it cost."""
        for path, parts, seconds, source in entity.built.decomposed:
            key = (path, ("decomposed",))
            if key in self._reported:
                continue
            self._reported[key] = 1
            how = f"in {seconds:.2f} s" if source == "computed" else f"from the {source}"
            _log.info(
                f"'{entity.name}': collision mesh {path} is not convex: it collides as {parts} convex parts "
                f"(CoACD, {how}; cache: {cache_dir()})"
            )

    def _report_unsimulated(self, entity: Entity) -> None:
        """One warning per model file (or string) for the contact parameters MuJoCo cannot honour,
        naming them all with their places; the same file spawned again is not reported again
        (32 chess pieces made 100 lines)."""
        params = entity.built.unsimulated
        if not params:
            return
        source = entity.model.source_file
        origin = source if source and not source.startswith("<") else f"{source}:{entity.model.name}"
        key = (origin, tuple(sorted(params)))
        if key in self._reported:
            self._reported[key] += 1
            return
        self._reported[key] = 1
        places = sorted({w for where in params.values() for w in where})
        shown = ", ".join(places[:3]) + (f" and {len(places) - 3} more" if len(places) > 3 else "")
        names = ", ".join(f"<{p}>" for p in sorted(params))
        source = f" ({entity.model.source_file})" if entity.model.source_file else ""
        _log.warning(
            f"'{entity.name}'{source}: surface {names} not simulated (no MuJoCo counterpart, or read only by an "
            f"engine other than Gazebo's defaults; see docs/contact_parameters.md), on {shown}; later spawns of "
            "this model are not reported again"
        )

    def _remove_elements(self, name: str) -> None:
        prefix = name + SEP
        for act in list(self.spec.actuators):
            if act.name.startswith(prefix):
                self.spec.delete(act)
        for eq in list(self.spec.equalities):
            if eq.name.startswith(prefix):
                self.spec.delete(eq)
        for ex in list(self.spec.excludes):
            if ex.name.startswith(prefix):
                self.spec.delete(ex)
        for body in list(self.spec.worldbody.bodies):
            if body.name.startswith(prefix):
                self.spec.delete(body)
        for mesh in list(self.spec.meshes):
            if mesh.name.startswith(prefix) and not mesh.name.startswith(SHARED_MESH):
                self.spec.delete(mesh)
        # a mesh shared by content goes with the last geom that used it (see the builder's _shared_mesh)
        used = {g.meshname for g in self.spec.geoms if g.meshname}
        for mesh in list(self.spec.meshes):
            if mesh.name.startswith(SHARED_MESH) and mesh.name not in used:
                self.spec.delete(mesh)
        for material in list(self.spec.materials):  # a visual mesh's own texture (see the builder)
            if material.name.startswith(prefix):
                self.spec.delete(material)
        for texture in list(self.spec.textures):
            if texture.name.startswith(prefix):
                self.spec.delete(texture)

    def remove_entity(self, name: str) -> Entity:
        """Delete an entity; every other entity keeps its state.

        Raises:
            WorldError: no such entity.
        """
        entity = self.entities.get(name)
        if entity is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{name}' does not exist")
        self._remove_elements(name)
        self._recompile()
        del self.entities[name]
        self._servo_plans = [p for p in self._servo_plans if p.entity != name]
        self._forward()
        return entity

    def add_actuator(
        self,
        entity: Entity,
        joint: str,
        kind: ActuatorKind,
        *,
        kp: float = 0.0,
        kv: float = 0.0,
        force_limit: tuple[float, float] | None = None,
    ) -> ActuatorHandle:
        """Add an actuator on a 1-dof joint of a staged ``entity`` (between :meth:`stage` and :meth:`commit`).

        ``POSITION``: force = kp·(command − q) − kv·q̇; ``VELOCITY``: force = kv·(command − q̇);
        ``EFFORT``: force = command. MuJoCo integrates the kv terms implicitly (``implicitfast``), so a
        stiff servo stays stable at any gain. ``force_limit`` (lo, hi) clamps the force.

        Raises:
            WorldError: (``NOT_FOUND``) the entity has no such joint.
        """
        target = scoped(entity.name, joint)
        if self.spec.joint(target) is None:
            raise WorldError(ErrorKind.NOT_FOUND, _no_joint_message(entity, joint))
        name = scoped(entity.name, f"{joint}#{_ACTUATOR_SUFFIX[kind]}")
        act = self.spec.add_actuator(name=name, target=target, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        if kind is ActuatorKind.POSITION:
            act.set_to_position(kp=kp, kv=kv)
        elif kind is ActuatorKind.VELOCITY:
            act.set_to_velocity(kv=kv)
        else:
            act.set_to_motor()
        if force_limit is not None and (math.isfinite(force_limit[0]) or math.isfinite(force_limit[1])):
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            act.forcerange = np.array([max(force_limit[0], -1e30), min(force_limit[1], 1e30)])
        return ActuatorHandle(JointHandle(self, entity.name, joint), kind, name)

    def joint_group(self, entity: str, joints: tuple[str, ...]) -> JointGroup:
        """A handle reading several 1-dof joints of an entity at once (see :class:`JointGroup`)."""
        return JointGroup(self, entity, joints)

    def actuator_group(self, actuators: tuple[ActuatorHandle, ...]) -> ActuatorGroup:
        """A handle setting several actuators at once (see :class:`ActuatorGroup`)."""
        return ActuatorGroup(self, actuators)

    def set_actuator_gains(self, handle: ActuatorHandle, kp: float, kv: float) -> None:
        """Change a position (``kp``, ``kv``) or velocity (``kv``) actuator's gains, e.g. once the
        joint's inertia is known; kept in the model description, and applied when the actuator is on."""
        act = self.spec.actuator(handle.name)
        if act is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"no actuator '{handle.name}'")
        gain, bias = np.array(act.gainprm), np.array(act.biasprm)
        saved = self._actuator_gains.get(handle.name)
        if saved is not None:
            gain, bias = saved[0].copy(), saved[1].copy()
        if handle.kind is ActuatorKind.POSITION:
            gain[0], bias[1], bias[2] = kp, -kp, -kv
        elif handle.kind is ActuatorKind.VELOCITY:
            gain[0], bias[2] = kv, -kv
        else:
            return
        enabled = saved is None or bool(np.any(np.array(act.gainprm)))
        self._actuator_gains[handle.name] = (gain, bias)
        self.set_actuator_enabled(handle, enabled)

    def set_actuator_enabled(self, handle: ActuatorHandle, enabled: bool) -> None:
        """Switch an actuator on (its gains as added) or off (no force at all), as ros2_control's
        command mode switch does between a joint's position, velocity and effort interfaces.

        Kept in the model description too, so a recompile (a spawn elsewhere) keeps it."""
        act = self.spec.actuator(handle.name)
        if act is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"no actuator '{handle.name}'")
        saved = self._actuator_gains.get(handle.name)
        if saved is None:
            saved = self._actuator_gains[handle.name] = (np.array(act.gainprm), np.array(act.biasprm))
        gain, bias = (saved[0], saved[1]) if enabled else (np.zeros_like(saved[0]), np.zeros_like(saved[1]))
        act.gainprm, act.biasprm = gain.copy(), bias.copy()
        aid = self.actuator_id(handle.name)
        if aid >= 0:
            n_g, n_b = self.model.actuator_gainprm.shape[1], self.model.actuator_biasprm.shape[1]
            self.model.actuator_gainprm[aid] = gain[:n_g]
            self.model.actuator_biasprm[aid] = bias[:n_b]

    def state_digest(self) -> str:
        """SHA-256 of the whole physics state (time, positions, velocities, actuator states, controls,
        warm start: MuJoCo's ``mjSTATE_INTEGRATION``): equal digests, bit-identical worlds."""
        spec = mujoco.mjtState.mjSTATE_INTEGRATION
        state = np.empty(mujoco.mj_stateSize(self.model, spec))
        mujoco.mj_getState(self.model, self.data, state, spec)
        return hashlib.sha256(state.tobytes()).hexdigest()

    def checkpoint_extras(self) -> dict[str, object]:
        """Everything of the world a checkpoint keeps: MuJoCo's whole data (state, warm start, contacts,
        every derived quantity) and model (parameters changed at run time), and the world's own run-time
        state (see ``gazelle.sim`` checkpoints). Picklable."""
        return {
            "data": pickle.dumps(self.data, protocol=pickle.HIGHEST_PROTOCOL),
            "overlap_steps": self._overlap_steps,
            "deep": self._deep,
            "kinematics_stale": self._kinematics_stale,
            "actuator_gains": {k: (g.copy(), b.copy()) for k, (g, b) in self._actuator_gains.items()},
            "model": self.model,
        }

    def restore_checkpoint_extras(self, extras: dict[str, Any]) -> None:
        """Take back what :meth:`checkpoint_extras` gave, into a world rebuilt with the same entities:
        the model's parameters as they were at the checkpoint (gains changed at run time, static bodies
        moved), in the model and in its description (a later recompile keeps them)."""
        saved: mujoco.MjModel = extras["model"]
        for name in dir(saved):
            if name.startswith("_"):
                continue
            value = getattr(saved, name, None)
            if isinstance(value, np.ndarray):
                live = getattr(self.model, name)
                if isinstance(live, np.ndarray) and live.shape == value.shape and live.flags.writeable:
                    live[...] = value
        for struct in ("opt", "vis", "stat"):
            src, dst = getattr(saved, struct), getattr(self.model, struct)
            for field_name in dir(src):
                if field_name.startswith("_"):
                    continue
                try:
                    setattr(dst, field_name, getattr(src, field_name))
                except (AttributeError, TypeError):
                    pass  # read-only or a nested struct
        data = pickle.loads(extras["data"])
        mujoco.mj_copyData(self.data, self.model, data)
        self._overlap_steps = int(extras["overlap_steps"])
        self._deep = bool(extras["deep"])
        self._kinematics_stale = bool(extras["kinematics_stale"])
        self._actuator_gains = dict(extras["actuator_gains"])
        n_g, n_b = self.model.actuator_gainprm.shape[1], self.model.actuator_biasprm.shape[1]
        for aid in range(self.model.nu):
            act = self.spec.actuator(mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, aid))
            if act is not None:
                gain, bias = np.array(act.gainprm), np.array(act.biasprm)
                gain[:n_g], bias[:n_b] = self.model.actuator_gainprm[aid], self.model.actuator_biasprm[aid]
                act.gainprm, act.biasprm = gain, bias

    def same_structure(self, extras: dict[str, Any]) -> bool:
        """Whether the model in ``extras`` (:meth:`checkpoint_extras`) has this model's sizes and names:
        the same world, its parameters aside (so its data can be copied in)."""
        other = extras.get("model")
        if not isinstance(other, mujoco.MjModel):
            return False
        sizes = [n for n in dir(other) if n.startswith("n") and isinstance(getattr(other, n, None), int)]
        return all(getattr(other, n) == getattr(self.model, n) for n in sizes) and bytes(other.names) == bytes(
            self.model.names
        )

    def joint(self, entity: str, joint: str) -> JointHandle:
        """A handle on a 1-dof joint of an entity (by its description name; MuJoCo joint ``joint``).

        Raises:
            WorldError: (``NOT_FOUND``) the entity (staged or in the world) has no such joint.
        """
        if self.spec.joint(scoped(entity, joint)) is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no joint '{joint}'")
        return JointHandle(self, entity, joint)

    def body(self, entity: str, link: str | None = None) -> BodyHandle:
        """A handle on a link of an entity (None: its root link, the model frame)."""
        return BodyHandle(self, entity, link)

    def make_wheel_contacts_pointlike(self, entity: Entity, link: str) -> int:
        """Turn the cylinder collisions of a drive wheel into ellipsoids of the same radius.

        A cylinder lying on the ground touches it at both rim edges, so a robot turning
        in place scrubs its wheels sideways: we measured the seed robot turning 1.5 %
        slower than (v_r - v_l)/separation. An ellipsoid with semi-axes (r, r, width/2)
        rolls exactly like the cylinder but touches at one point, the centre of a real
        tyre's contact patch. Call from ``configure`` (before the recompile).
        Returns how many geoms were changed.
        """
        body = self.spec.body(scoped(entity.name, link))
        if body is None:
            return 0
        changed = 0
        for geom in body.geoms:
            if geom.type == mujoco.mjtGeom.mjGEOM_CYLINDER:
                r, half = float(geom.size[0]), float(geom.size[1])
                geom.type = mujoco.mjtGeom.mjGEOM_ELLIPSOID
                geom.size = [r, r, half]
                changed += 1
        return changed

    def make_caster_frictionless(self, entity: Entity, link: str) -> int:
        """Make the sphere collisions of ``link`` roll like a ball caster: frictionless contacts
        (``condim`` 1 and ``mu`` 0, with the priority the builder gives a frictionless surface, so the
        other geom's friction is not used: ODE's min rule). Call from ``configure`` (before the
        recompile). Returns how many geoms changed."""
        body = self.spec.body(scoped(entity.name, link))
        if body is None:
            return 0
        changed = 0
        for geom in body.geoms:
            if geom.type == mujoco.mjtGeom.mjGEOM_SPHERE and geom.contype:
                geom.condim = 1
                geom.friction = [0.0, 0.0, 0.0]
                geom.priority = friction_priority(0.0)
                changed += 1
        return changed

    def set_joint_armature(self, entity: Entity, joint: str, armature: float) -> None:
        """Set the armature (reflected rotor inertia, kg·m²) of a 1-dof joint; call from ``configure``."""
        j = self.spec.joint(scoped(entity.name, joint))
        if j is None:
            raise WorldError(ErrorKind.NOT_FOUND, _no_joint_message(entity, joint))
        j.armature = armature

    # ------------------------------------------------------------------ stepping
    @property
    def time(self) -> float:
        """Simulation time, seconds."""
        return float(self.data.time)

    @property
    def armature(self) -> float:
        """The armature every 1-dof joint gets (see the builder)."""
        return JOINT_ARMATURE

    @property
    def timestep(self) -> float:
        """The physics step, seconds (fixed for the world's lifetime)."""
        return self._timestep

    def _held_dofs(self) -> tuple[np.ndarray, np.ndarray] | None:
        if self._held is False:
            qadr: list[int] = []
            dadr: list[int] = []
            for e in self.entities.values():
                for mj in e.built.kinematic_joints:
                    jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj)
                    if jid >= 0 and int(self.model.jnt_type[jid]) in _ONE_DOF:
                        qadr.append(int(self.model.jnt_qposadr[jid]))
                        dadr.append(int(self.model.jnt_dofadr[jid]))
            self._held = (np.array(qadr), np.array(dadr)) if qadr else None
        return self._held if isinstance(self._held, tuple) else None

    def step(self, n: int = 1) -> int:
        """Take ``n`` physics steps with the actuators' commands held; returns the steps taken.

        The steps run inside MuJoCo (``mj_step(m, d, nstep)``), bit-identical to ``n`` single steps.
        Two things need Python between steps, and only while they apply: kinematic joints (held
        exactly, every step) and the overlap watch after something was placed (every
        :data:`OVERLAP_CHECK_EVERY` steps, every step while something is deep in).

        Live servo plans (:meth:`add_servo_plan`) run their cycles in the same loop, one per step, and
        bound it: fewer than ``n`` steps are taken when a plan has fewer cycles left, or stops after
        a cycle that left its path tolerance.
        """
        plans = [p for p in self._servo_plans if p.remaining > 0] if self._servo_plans else []
        if plans:
            n = min(n, min(p.remaining for p in plans))
        if not self._overlap_steps and self._held_dofs() is None:  # the usual case: one MuJoCo call
            self._kinematics_stale = True
            return self._steps(n, plans)
        taken = 0
        while taken < n:
            if self._held_dofs() is not None:
                k = 1
            elif self._overlap_steps:
                # stop exactly where single steps would have checked (see _step_block)
                k = (
                    1
                    if self._deep
                    else min(n - taken, self._overlap_steps % OVERLAP_CHECK_EVERY or OVERLAP_CHECK_EVERY)
                )
            else:
                k = n - taken
            done = self._step_block(k, plans)
            taken += done
            if done < k:
                break
        return taken

    def add_servo_plan(self, plan: ServoPlan) -> None:
        """Let the steps run ``plan``'s cycles (until it is removed; a plan with no cycles left is skipped)."""
        if plan not in self._servo_plans:
            self._servo_plans.append(plan)

    def remove_servo_plan(self, plan: ServoPlan) -> None:
        """Stop running ``plan`` (unknown plans are ignored)."""
        if plan in self._servo_plans:
            self._servo_plans.remove(plan)

    @staticmethod
    def servo_plans_available() -> bool:
        """Whether the compiled servo loop is there (see :mod:`gazelle.physics._native`)."""
        from . import _native

        return _native.available()

    def _step_block(self, k: int, plans: list[ServoPlan]) -> int:
        held = self._held_dofs()
        if held is None:
            k = self._steps(k, plans)
        else:
            # kinematic joints: no force moves them; they keep their own velocity exactly
            qadr, dadr = held
            q0, v0 = self.data.qpos[qadr], self.data.qvel[dadr]
            k = self._steps(1, plans)
            self.data.qvel[dadr] = v0
            self.data.qpos[qadr] = q0 + v0 * self.model.opt.timestep
        # mj_step computes kinematics *before* it integrates, so xpos/xquat/cvel now describe
        # the previous step's state; refresh them lazily, on the first query
        self._kinematics_stale = True
        if self._overlap_steps:  # only for a while after something was placed: costs nothing in steady state
            self._overlap_steps = max(0, self._overlap_steps - k)
            # every step while something is deep in, else every OVERLAP_CHECK_EVERY steps (~2 µs a check)
            if self._deep or self._overlap_steps % OVERLAP_CHECK_EVERY == 0:
                d = self.data
                self._deep = bool(d.ncon) and float(d.contact.dist[: d.ncon].min()) < -DEEP_PENETRATION_M
                if self._deep:
                    self._limit_correcting_velocity()
        return k

    def _steps(self, k: int, plans: list[ServoPlan] | None = None) -> int:
        """``k`` steps in one MuJoCo call (with ``plans``' cycles, which may stop it sooner: the steps
        taken are returned); after an arena growth (see :meth:`_guarded`) only the rest."""
        if plans:
            return self._planned_steps(k, plans)
        t0 = self.data.time
        try:
            mujoco.mj_step(self.model, self.data, nstep=k)
            return k
        except mujoco.FatalError as err:
            if "memory" not in str(err).lower() and "stack" not in str(err).lower():
                raise
            reason = str(err).strip().splitlines()[0]
        dt = self._timestep
        t_end = t0 + k * dt

        def rest(m: mujoco.MjModel, d: mujoco.MjData) -> None:
            left = max(0, round((t_end - d.time) / dt))
            if left:
                mujoco.mj_step(m, d, nstep=left)

        self._grow_arena(rest, reason)
        return k

    def _planned_steps(self, k: int, plans: list[ServoPlan]) -> int:
        """``k`` steps running ``plans``' servo cycles in compiled code (see :mod:`._servo_plan`)."""
        taken, error = run_plans(self, plans, k)
        if error is None:
            return taken
        if "memory" not in error.lower() and "stack" not in error.lower():
            raise mujoco.FatalError(error)
        total = [taken]

        def rest(m: mujoco.MjModel, d: mujoco.MjData) -> None:
            # the interrupted cycle runs again: its integral step is zero the second time (no time passed)
            more, again = run_plans(self, plans, k - total[0])
            total[0] += more
            if again is not None:
                raise mujoco.FatalError(again)

        self._grow_arena(rest, error.splitlines()[0])
        return total[0]

    def _watch_overlaps(self) -> None:
        """Something was placed (spawn, set-state, reset): watch for deep overlaps for a while."""
        self._overlap_steps = max(1, int(OVERLAP_WATCH_SEC / max(self.timestep, 1e-6)))
        self._deep = True  # check at the very next step

    def _limit_correcting_velocity(self) -> None:
        """Bodies deep in penetration come out at most :data:`MAX_CORRECTING_VEL` fast.

        MuJoCo pushes penetrating geoms apart with a spring whose force grows with the depth, so a
        robot spawned with its wheels 0.2 m into the ground was launched 29 m up and landed upside
        down. ODE (Gazebo) caps the correcting velocity (``max_correcting_vel``); here the free root
        of a body in a contact deeper than :data:`DEEP_PENETRATION_M` may not move apart along the
        contact normal faster than the cap, nor spin faster than :data:`MAX_CORRECTING_SPIN`.
        """
        m, d = self.model, self.data
        free = int(mujoco.mjtJoint.mjJNT_FREE)
        for i in range(d.ncon):
            c = d.contact[i]
            if c.dist >= -DEEP_PENETRATION_M:
                continue
            normal = c.frame[:3]
            for geom, sign in ((c.geom1, -1.0), (c.geom2, 1.0)):
                root = int(m.body_rootid[m.geom_bodyid[geom]])
                jnt = int(m.body_jntadr[root])
                if root == 0 or jnt < 0 or int(m.jnt_type[jnt]) != free:
                    continue
                dof = int(m.jnt_dofadr[jnt])
                v = d.qvel[dof : dof + 3]
                apart = sign * float(normal @ v)
                if apart > MAX_CORRECTING_VEL:
                    v -= sign * (apart - MAX_CORRECTING_VEL) * normal
                w = d.qvel[dof + 3 : dof + 6]
                spin = float(np.linalg.norm(w))
                if spin > MAX_CORRECTING_SPIN:
                    w *= MAX_CORRECTING_SPIN / spin

    def _add_background(self, world: World) -> None:
        """What cameras see where nothing is drawn (:attr:`background`): the world's ``<scene>
        <background>`` (SDFormat's default 0.7 grey), or the gz-sim Sensors system's ``<background_color>``,
        which wins over it, as gz-sim's sensors render (``src/systems/sensors/Sensors.cc``:
        ``background_color``, else ``src/rendering/RenderUtil.cc``: ``scene->SetBackgroundColor(
        scene.Background())``)."""
        colour = world.scene.background[:3]
        for plugin in world.plugins:
            if "sensors" not in (plugin.filename or "").lower() and not plugin.name.endswith("::Sensors"):
                continue
            el = plugin.config.find("background_color")
            try:
                values = [float(v) for v in (el.text or "").split()] if el is not None else []
            except ValueError:
                values = []
            if len(values) in (3, 4):
                colour = (values[0], values[1], values[2])
        self.background = tuple(int(round(255 * min(max(float(c), 0.0), 1.0))) for c in colour)
        """The cameras' background, 8-bit RGB."""

    def _add_light(self, light: Light) -> None:
        """A world light for cameras (its direction is in the light's frame, as SDF gives it)."""
        kinds = {"directional": mujoco.mjtLightType.mjLIGHT_DIRECTIONAL, "spot": mujoco.mjtLightType.mjLIGHT_SPOT}
        R = rotation_matrix(light.pose.orientation)
        direction = R @ np.asarray(light.direction, dtype=float)
        n = float(np.linalg.norm(direction))
        self.spec.worldbody.add_light(
            name=f"light::{light.name}",
            type=kinds.get(light.type, mujoco.mjtLightType.mjLIGHT_POINT),
            pos=list(light.pose.position),
            dir=list(direction / n) if n > 0 else [0.0, 0.0, -1.0],
            diffuse=list(light.diffuse[:3]),
            specular=list(light.specular[:3]),
            castshadow=bool(light.cast_shadows),
        )

    def joint_wrench(self, body_id: int, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(force, torque) that the parent exerts on body ``body_id`` through the joint above it, in the
        world frame, the torque about ``point`` (world). From MuJoCo's ``cfrc_int`` (after
        ``mj_rnePostConstraint``: derived fields only, the trajectory is unchanged), so gravity and
        motion of the child's whole subtree are in it, as a force-torque sensor at the joint reads."""
        self._refresh_kinematics()
        m, d = self.model, self.data
        mujoco.mj_rnePostConstraint(m, d)
        bid = body_id
        torque_c, force = np.array(d.cfrc_int[bid, :3]), np.array(d.cfrc_int[bid, 3:])
        c = d.subtree_com[int(m.body_rootid[bid])]  # cfrc_int is about its tree's centre of mass
        return force, torque_c + np.cross(c - point, force)

    def collision_geoms(self, entity: str, link: str, collision: str | None = None) -> frozenset[int]:
        """MuJoCo ids of a link's collision geoms (every convex part of a decomposed mesh), or of its
        collision named ``collision`` (valid until the next recompile)."""
        prefix = scoped(entity, f"{link}{SEP}{collision}#") if collision else scoped(entity, f"{link}{SEP}")
        m = self.model
        out = set()
        for i in range(m.ngeom):
            name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, i) or ""
            if name.startswith(prefix) and "#v" not in name[len(prefix) - 1 :]:
                out.add(i)
        return frozenset(out)

    def contacts_of(self, geoms: frozenset[int]) -> list[ContactPoint]:
        """The current contacts that involve any of ``geoms``, each seen from that geom's side."""
        m, d = self.model, self.data
        out: list[ContactPoint] = []
        f6 = np.zeros(6)
        for i in range(int(d.ncon)):
            c = d.contact[i]
            g1, g2 = int(c.geom1), int(c.geom2)
            if g1 not in geoms and g2 not in geoms:
                continue
            mujoco.mj_contactForce(m, d, i, f6)
            frame = np.asarray(c.frame, dtype=float).reshape(3, 3)  # rows: normal (geom1 -> geom2), tangents
            force_w = frame.T @ f6[:3]  # MuJoCo: the force geom1 exerts on geom2, in the contact frame
            torque_w = frame.T @ f6[3:]
            mine, other, sign = (g1, g2, -1.0) if g1 in geoms else (g2, g1, 1.0)
            normal = sign * frame[0]  # MuJoCo's normal points from geom1 to geom2: turned to point into mine
            out.append(
                ContactPoint(
                    _gazebo_collision_name(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, mine) or str(mine)),
                    _gazebo_collision_name(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, other) or str(other)),
                    _vec3(c.pos),
                    _vec3(normal),
                    _vec3(sign * force_w),
                    _vec3(sign * torque_w),
                    float(-c.dist),
                )
            )
        return out

    def offscreen_renderer(self, width: int, height: int) -> OffscreenRenderer:
        """A renderer of this world's images (create and use it on the simulation thread)."""
        return OffscreenRenderer(self, width, height)

    def refresh_kinematics(self) -> None:
        """Bring body poses up to the current state (cheap when already current); for renderers."""
        self._refresh_kinematics()

    def _refresh_kinematics(self) -> None:
        """Bring body poses and velocities up to the current qpos/qvel (derived fields only:
        the next mj_step recomputes them anyway, so trajectories are unchanged)."""
        if self._kinematics_stale:
            mujoco.mj_kinematics(self.model, self.data)
            mujoco.mj_comPos(self.model, self.data)
            mujoco.mj_comVel(self.model, self.data)
            self._kinematics_stale = False

    def recover_divergence(self) -> list[str] | None:
        """Find a diverged state (NaN, inf or runaway velocity) and repair it.

        Returns None when the state is sound (the usual case, ~0.6 µs); else the names of the
        entities that diverged (``["<world>"]`` when none can be blamed), after putting each back
        at its spawn pose, at rest, and zeroing every non-finite value.
        """
        d = self.data
        cache = self._state_views
        if cache[0] is not d:  # a recompile made a new MjData; `d.qpos` builds a new array object per access
            cache = self._state_views = (d, d.qpos, d.qvel)
        _, qpos, qvel = cache
        # fast path: a NaN/inf makes these dot products non-finite (NaN < x is False),
        # a |qvel| >= 1e4 makes the first >= 1e8
        if qvel.dot(qvel) < 1e8 and math.isfinite(qpos.dot(qpos)):
            return None
        if np.all(np.isfinite(d.qpos)) and np.all(np.isfinite(d.qvel)) and np.all(np.abs(d.qvel) < 1e4):
            return None
        names = self.diverged_entities() or ["<world>"]
        for name in names:
            e = self.entities.get(name)
            if e is None:
                continue
            d.qpos[~np.isfinite(d.qpos)] = 0.0
            d.qvel[~np.isfinite(d.qvel)] = 0.0
            if e.built.free_joint:
                self.set_entity_state(name, self._spawn_root_pose(e))
        d.qacc[:] = 0.0
        d.qacc_warmstart[:] = 0.0
        d.qvel[~np.isfinite(d.qvel)] = 0.0
        mujoco.mj_forward(self.model, d)
        return names

    def diverged_entities(self) -> list[str]:
        """Entities whose state holds NaN/inf or absurd velocities (|qvel| > 1e4)."""
        nq = {int(mujoco.mjtJoint.mjJNT_FREE): (7, 6), int(mujoco.mjtJoint.mjJNT_BALL): (4, 3)}
        bad: list[str] = []
        for e in self.entities.values():
            names = [mj for jn in e.built.joints.values() for mj in jn]
            if e.built.free_joint:
                names.append(e.built.free_joint)
            for mj in names:
                jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj)
                if jid < 0:
                    continue
                a, v = self.model.jnt_qposadr[jid], self.model.jnt_dofadr[jid]
                na, nv = nq.get(int(self.model.jnt_type[jid]), (1, 1))
                qvel = np.abs(self.data.qvel[v : v + nv])
                # written so that NaN fails the test (NaN <= x is False)
                if not (np.all(np.isfinite(self.data.qpos[a : a + na])) and np.all(qvel <= 1e4)):
                    bad.append(e.name)
                    break
        return sorted(set(bad))

    # ------------------------------------------------------------------ queries
    def body_id(self, entity: str, link: str | None = None) -> int:
        """MuJoCo id of an entity's root body, or of one of its links' bodies (valid until the next recompile)."""
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        body = e.built.root_body if link is None else e.built.bodies.get(link)
        if body is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no link '{link}'")
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, body)

    def body_pose(self, body_id: int) -> Pose:
        """World pose of a body by id (kinematics refreshed first if stale)."""
        self._refresh_kinematics()
        x, y, z = self.data.xpos[body_id].tolist()
        w, qx, qy, qz = self.data.xquat[body_id].tolist()
        return Pose((x, y, z), (w, qx, qy, qz))

    def body_poses(self, body_ids: Sequence[int] | np.ndarray) -> np.ndarray:
        """World poses of many bodies at once: an (n, 7) array of x, y, z, qw, qx, qy, qz (a copy)."""
        self._refresh_kinematics()
        ids = np.asarray(body_ids, dtype=int)
        return np.concatenate((self.data.xpos[ids], self.data.xquat[ids]), axis=1)

    def link_poses_along(
        self, entity: str, link: str, joints: Sequence[str], positions: Sequence[Sequence[float]]
    ) -> list[Pose]:
        """World poses of an entity's ``link`` were its ``joints`` (1-dof, description names) at each row
        of ``positions``, every other joint where it is now: forward kinematics on a scratch copy of the
        state (a planned path drawn before the arm moves); the simulation is untouched.

        Raises:
            WorldError: (NOT_FOUND) no such entity, link or movable joint; (INVALID_POSE) a row whose
                length is not the number of joints.
        """
        body = self.body_id(entity, link)
        e = self.entities[entity]
        addresses = []
        for joint in joints:
            mj = e.built.joints.get(joint)
            if not mj:
                raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no movable joint '{joint}'")
            jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj[0])
            if int(self.model.jnt_type[jid]) not in _ONE_DOF:
                raise WorldError(ErrorKind.NOT_FOUND, f"joint '{joint}' of '{entity}' is not a 1-dof joint")
            addresses.append(int(self.model.jnt_qposadr[jid]))
        scratch = mujoco.MjData(self.model)
        scratch.qpos[:] = self.data.qpos
        poses = []
        for row in positions:
            if len(row) != len(addresses):
                raise WorldError(ErrorKind.INVALID_POSE, f"{len(row)} positions for {len(addresses)} joints")
            scratch.qpos[addresses] = row
            mujoco.mj_kinematics(self.model, scratch)
            x, y, z = scratch.xpos[body].tolist()
            w, qx, qy, qz = scratch.xquat[body].tolist()
            poses.append(Pose((x, y, z), (w, qx, qy, qz)))
        return poses

    def body_velocity(self, body_id: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """World-frame linear velocity of the body origin and angular velocity."""
        self._refresh_kinematics()
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(self.model, self.data, mujoco.mjtObj.mjOBJ_BODY, body_id, vel, 0)
        ang = vel[:3]
        lin = vel[3:]
        return (float(lin[0]), float(lin[1]), float(lin[2])), (float(ang[0]), float(ang[1]), float(ang[2]))

    def cast_rays(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """Cast rays from ``origin`` along the unit ``directions`` (N×3, world frame) against collision
        geoms (what Gazebo's ``ray`` sensor sees), ignoring the body ``exclude_body``, in one
        ``mj_multiRay`` call. Returns (distances, geom ids): distance -1 and id -1 where nothing is hit
        within ``max_range``."""
        self._refresh_kinematics()
        origin, directions = np.ascontiguousarray(origin, dtype=float), np.ascontiguousarray(directions, dtype=float)
        return self._multi_ray(origin, directions, exclude_body, max_range)

    def cast_rays_from(
        self, body_id: int, offset: Pose, directions: np.ndarray, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`cast_rays` from a sensor at ``offset`` in body ``body_id``'s frame, with the unit
        ``directions`` (N×3) in the sensor's frame, ignoring that body (a lidar's own housing). The
        sensor's world pose is composed from MuJoCo's arrays (a lidar scans at its rate, often)."""
        self._refresh_kinematics()
        d = self.data
        p_BS, R_BS, at_origin, unrotated = self._offset(offset)
        R_WB = d.xmat[body_id].reshape(3, 3)
        origin = d.xpos[body_id] if at_origin else d.xpos[body_id] + R_WB @ p_BS
        R_WS = R_WB if unrotated else R_WB @ R_BS
        return self._multi_ray(np.ascontiguousarray(origin), directions @ R_WS.T, body_id, max_range)

    def _multi_ray(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]:
        n = len(directions)
        dist = np.empty(n)
        geom = np.empty(n, dtype=np.int32)
        mujoco.mj_multiRay(
            self.model,
            self.data,
            origin,
            directions.reshape(-1),
            RAY_GEOM_GROUPS,
            True,
            exclude_body,
            geom,
            dist,
            None,
            n,
            max_range,
        )
        return dist, geom

    def _offset(self, offset: Pose) -> tuple[np.ndarray, np.ndarray, bool, bool]:
        """A sensor's pose in its body, cached as (position, rotation matrix, at the origin, unrotated)."""
        cached = self._offsets.get(offset)
        if cached is None:
            p = np.asarray(offset.position, dtype=float)
            R = rotation_matrix(offset.orientation)
            cached = self._offsets[offset] = (p, R, not p.any(), offset.orientation == (1.0, 0.0, 0.0, 0.0))
        return cached

    def imu_reading(self, body_id: int, offset: Pose) -> list[float]:
        """What an ideal IMU at ``offset`` (a pose in the body frame) reads now, as ten floats: its world
        orientation (w, x, y, z), then its angular velocity and its proper linear acceleration, both in its
        own frame. At rest the acceleration is +g upwards (0, 0, 9.81), as a real accelerometer reads:
        MuJoCo's body accelerations (``mj_rnePostConstraint``) start from the gravity as a base
        acceleration. Only derived fields are computed, so the trajectory is unchanged.

        Called at an IMU's rate, thousands of times a wall second when the world runs faster than real
        time: a sensor at the body's origin and unrotated in it (the usual case) costs three MuJoCo calls
        (after the kinematics are brought up to date) and one 2x3 by 3x3 product."""
        self._refresh_kinematics()
        m, d = self.model, self.data
        mujoco.mj_rnePostConstraint(m, d)
        acc, vel, wa = self._imu_acc, self._imu_vel, self._imu_wa
        mujoco.mj_objectAcceleration(m, d, mujoco.mjtObj.mjOBJ_XBODY, body_id, acc, 0)
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_XBODY, body_id, vel, 0)
        p_BS, R_BS, at_origin, unrotated = self._offset(offset)
        R_WB = d.xmat[body_id].reshape(3, 3)
        wa[0] = vel[:3]
        if at_origin:
            wa[1] = acc[3:]
        else:  # a sensor off the body origin also feels alpha x r and the centripetal w x (w x r)
            r = R_WB @ p_BS
            w = vel[:3]
            wa[1] = acc[3:] + _cross(acc[:3], r) + _cross(w, _cross(w, r))
        if unrotated:
            R_WS = R_WB
            q = d.xquat[body_id].tolist()
        else:
            R_WS, q4 = self._imu_R, self._imu_quat
            mujoco.mju_mulMatMat(R_WS, R_WB, R_BS)
            mujoco.mju_mat2Quat(q4, R_WS.reshape(-1))
            q = q4.tolist()
        # the rows of wa @ R_WS are (R_WS^T w)^T and (R_WS^T a)^T: both vectors in the sensor's frame
        return q + (wa @ R_WS).ravel().tolist()

    def frame_pose(self, frame: str) -> Pose:
        """World pose of a frame named in a request: a :data:`WORLD_FRAMES` name, an entity (its model
        frame), or ``entity::link``.

        Raises:
            WorldError: (NOT_FOUND) no such entity or link.
        """
        if frame in WORLD_FRAMES:
            return Pose()
        entity, _, link = frame.partition(SEP)
        return self.entity_state(entity, link or None).pose

    def entity_state(self, entity: str, link: str | None = None) -> EntityState:
        """World pose and twist of an entity's model frame (its root link), or of one of its links."""
        bid = self.body_id(entity, link)
        lin, ang = self.body_velocity(bid)
        return EntityState(self.body_pose(bid), lin, ang)

    def set_entity_state(
        self,
        entity: str,
        pose: Pose,
        linear: tuple[float, float, float] = (0.0, 0.0, 0.0),
        angular: tuple[float, float, float] = (0.0, 0.0, 0.0),
    ) -> None:
        """Teleport an entity's free root and set its twist (world frame)."""
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        vals = (*pose.position, *pose.orientation, *linear, *angular)
        if not all(math.isfinite(v) for v in vals):
            raise WorldError(ErrorKind.INVALID_POSE, f"state for '{entity}' is not finite")
        far = pose_out_of_range(pose, "pose.position")
        if far is not None:
            raise WorldError(ErrorKind.INVALID_POSE, f"state for '{entity}': {far}")
        qn = math.sqrt(sum(v * v for v in pose.orientation))
        if qn < 1e-9:
            raise WorldError(ErrorKind.INVALID_POSE, "orientation is a zero quaternion")
        if e.built.free_joint is None:
            if any(linear) or any(angular):
                raise WorldError(ErrorKind.INCORRECT_STATE, f"entity '{entity}' is static; it cannot have a twist")
            bid = self.body_id(entity)
            self.model.body_pos[bid] = pose.position
            self.model.body_quat[bid] = [v / qn for v in pose.orientation]
            self._forward()
            return
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, e.built.free_joint)
        a, v = self.model.jnt_qposadr[jid], self.model.jnt_dofadr[jid]
        self.data.qpos[a : a + 3] = pose.position
        w, x, y, z = pose.orientation
        q = (w / qn, x / qn, y / qn, z / qn)
        self.data.qpos[a + 3 : a + 7] = q
        self.data.qvel[v : v + 3] = linear
        # free joint angular velocity is in the body frame
        self.data.qvel[v + 3 : v + 6] = quat_rotate(quat_conj(q), angular)
        self._watch_overlaps()
        self._forward()

    def joint_address(self, entity: str, mj_joint: str) -> tuple[int, int]:
        """(qposadr, dofadr) of a MuJoCo joint of an entity."""
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, scoped(entity, mj_joint))
        if jid < 0:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no joint '{mj_joint}'")
        return int(self.model.jnt_qposadr[jid]), int(self.model.jnt_dofadr[jid])

    def set_joint_state(
        self, entity: str, joint: str, position: float | None = None, velocity: float | None = None
    ) -> None:
        """Set the position and/or velocity of a 1-dof (hinge or slide) joint of an entity, by its
        description name; the way to move a kinematic joint, which no force moves."""
        e = self.entities.get(entity)
        if e is None:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' does not exist")
        mj = e.built.joints.get(joint)
        if not mj:
            raise WorldError(ErrorKind.NOT_FOUND, f"entity '{entity}' has no movable joint '{joint}'")
        if any(v is not None and not math.isfinite(v) for v in (position, velocity)):
            raise WorldError(ErrorKind.INVALID_POSE, f"state for joint '{joint}' of '{entity}' is not finite")
        jid = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, mj[0])
        if int(self.model.jnt_type[jid]) not in _ONE_DOF:
            raise WorldError(ErrorKind.INCORRECT_STATE, f"joint '{joint}' of '{entity}' is not a 1-dof joint")
        if position is not None:
            self.data.qpos[self.model.jnt_qposadr[jid]] = position
        if velocity is not None:
            self.data.qvel[self.model.jnt_dofadr[jid]] = velocity
        self._forward()
        self._kinematics_stale = False

    def actuator_id(self, name: str) -> int:
        """MuJoCo id of an actuator by its name (-1 when absent)."""
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, name)

    def reset_time(self) -> None:
        """Set sim time to zero (the state is kept)."""
        self.data.time = 0.0

    def reset_state(self) -> None:
        """Put every entity back where it was spawned, at rest."""
        mujoco.mj_resetData(self.model, self.data)
        for e in self.entities.values():
            if e.built.free_joint:
                self.set_entity_state(e.name, self._spawn_root_pose(e))
        self._watch_overlaps()
        self._forward()

    def _spawn_root_pose(self, e: Entity) -> Pose:
        root = e.model.root_link
        link = e.model.link(root)
        return e.X_WM * (link.pose or Pose())

    def stage_many(self, items: list[StagedRequest]) -> list[Entity | WorldError]:
        """:meth:`stage` several models; each that fails its own checks gets its error in its slot."""
        out: list[Entity | WorldError] = []
        taken = set(self.entities)
        for it in items:
            try:
                entity = self._stage(it.model, it.name, it.X_WM, it.namespace, it.spawned, taken)
            except WorldError as err:
                out.append(err)
                continue
            taken.add(it.name)
            out.append(entity)
        return out

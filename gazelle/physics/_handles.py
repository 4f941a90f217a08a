"""Typed handles on the compiled world: joints, actuators and bodies of one entity.

Systems (plugins, controllers, sensors next, ros2_control's hardware interface) read and
command the simulation through these and never through MuJoCo: a handle knows its
entity and element by name, and resolves MuJoCo's indices again after every recompile
(a spawn or a delete renumbers them), so it stays valid for the entity's lifetime.

A handle is used on the simulation thread only, like the world it belongs to. It names that world as a
:class:`CompiledWorld`, what it uses of it (:class:`~._world.PhysicsWorld` is one), so this module imports nothing
of the world that makes the handles.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Generic, Protocol, TypeVar

import numpy as np

from ..description import Pose

if TYPE_CHECKING:  # pragma: no cover
    import mujoco


class CompiledWorld(Protocol):
    """What the handles and servo plans use of the world they belong to (:class:`~._world.PhysicsWorld`): its
    compiled model and data, the generation that numbers each compile, and the queries and writes that take MuJoCo
    ids. A protocol, so the handles name no class of the module that makes them."""

    @property
    def generation(self) -> int: ...

    @property
    def model(self) -> mujoco.MjModel: ...

    @property
    def data(self) -> mujoco.MjData: ...

    def joint_address(self, entity: str, mj_joint: str) -> tuple[int, int]: ...

    def actuator_id(self, name: str) -> int: ...

    def body_id(self, entity: str, link: str | None = None) -> int: ...

    def body_pose(self, body_id: int) -> Pose: ...

    def body_velocity(self, body_id: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]: ...

    def cast_rays(
        self, origin: np.ndarray, directions: np.ndarray, exclude_body: int, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]: ...

    def cast_rays_from(
        self, body_id: int, offset: Pose, directions: np.ndarray, max_range: float
    ) -> tuple[np.ndarray, np.ndarray]: ...

    def joint_wrench(self, body_id: int, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]: ...

    def imu_reading(self, body_id: int, offset: Pose) -> list[float]: ...

    def set_actuator_gains(self, handle: ActuatorHandle, kp: float, kv: float) -> None: ...

    def set_actuator_enabled(self, handle: ActuatorHandle, enabled: bool) -> None: ...


W = TypeVar("W", bound=CompiledWorld)
T = TypeVar("T")


class PerGeneration(Generic[W, T]):
    """A value derived from the compiled model (MuJoCo ids, qpos/qvel addresses).

    ``get(world)`` computes it once per ``world.generation``: every recompile (a spawn,
    a delete) may renumber what it holds.
    """

    __slots__ = ("_compute", "_generation", "_value")

    def __init__(self, compute: Callable[[W], T]) -> None:
        self._compute = compute
        self._generation = -1
        self._value: T | None = None

    def get(self, world: W) -> T:
        """The value for the world's current model, computed at most once per recompile."""
        value = self._value
        if self._generation != world.generation or value is None:
            value = self._value = self._compute(world)
            self._generation = world.generation
        return value


class ActuatorKind(enum.Enum):
    """What an actuator's command means, as ros2_control's command interfaces name them."""

    POSITION = "position"
    """Target position (rad or m): a PD servo with ``kp`` and ``kv``."""
    VELOCITY = "velocity"
    """Target velocity (rad/s or m/s): a damping servo with ``kv``, integrated implicitly."""
    EFFORT = "effort"
    """Force or torque (N·m or N), applied as given."""


@dataclass(frozen=True, slots=True)
class _JointIds:
    qpos: int
    dof: int


class JointHandle:
    """One 1-dof (hinge or slide) joint of an entity: its position, velocity and actuator effort.

    Get one with :meth:`PhysicsWorld.joint`. ``position`` is in rad (hinge) or m (slide),
    ``velocity`` in rad/s or m/s, ``effort`` is the force all actuators on the joint apply (N·m or N).
    """

    __slots__ = ("world", "entity", "name", "_ids")

    def __reduce__(self) -> tuple[Any, ...]:
        """Saved by what it names (a checkpoint): found again in the world it is loaded into."""
        return (JointHandle, (self.world, self.entity, self.name))

    def __init__(self, world: CompiledWorld, entity: str, name: str) -> None:
        """A handle on joint ``name`` of ``entity``; its MuJoCo ids are looked up again whenever the model is
        recompiled (a spawn, a delete)."""
        self.world = world
        self.entity = entity
        """The entity's name."""
        self.name = name
        """The joint's name in the entity's description."""
        self._ids = PerGeneration(self._resolve)

    def _resolve(self, world: CompiledWorld) -> _JointIds:
        qadr, dadr = world.joint_address(self.entity, self.name)
        return _JointIds(qadr, dadr)

    @property
    def position(self) -> float:
        """The joint's position now (rad or m), as ros2_control's ``position`` state interface reads it."""
        return float(self.world.data.qpos[self._ids.get(self.world).qpos])

    @property
    def velocity(self) -> float:
        """The joint's velocity now (rad/s or m/s): the ``velocity`` state interface."""
        return float(self.world.data.qvel[self._ids.get(self.world).dof])

    @property
    def effort(self) -> float:
        """The actuators' force or torque on the joint in the last step: the ``effort`` state interface."""
        return float(self.world.data.qfrc_actuator[self._ids.get(self.world).dof])

    @property
    def inertia(self) -> float:
        """The joint's effective inertia now (kg·m² or kg): its diagonal entry of the mass matrix, with
        everything it carries and its armature (as of the last step)."""
        world = self.world
        dof = self._ids.get(world).dof
        m = world.model
        start, count = int(m.M_rowadr[dof]), int(m.M_rownnz[dof])  # the mass matrix's CSR row
        cols = m.M_colind[start : start + count]
        return float(world.data.M[start + int(np.flatnonzero(cols == dof)[0])])

    def __repr__(self) -> str:
        return f"JointHandle({self.entity!r}, {self.name!r})"


class JointGroup:
    """Several 1-dof joints of one entity, read together as numpy arrays (one indexing per quantity
    instead of a lookup per joint): what a ros2_control hardware component reads every cycle.

    Get one with :meth:`PhysicsWorld.joint_group`."""

    __slots__ = ("world", "entity", "names", "_ids")

    def __reduce__(self) -> tuple[Any, ...]:
        """Saved by what it names (a checkpoint): found again in the world it is loaded into."""
        return (JointGroup, (self.world, self.entity, self.names))

    def __init__(self, world: CompiledWorld, entity: str, names: tuple[str, ...]) -> None:
        """A handle on several joints of one entity, read or written with one indexed array operation."""
        self.world = world
        self.entity = entity
        self.names = names
        self._ids = PerGeneration(self._resolve)

    def _resolve(self, world: CompiledWorld) -> tuple[np.ndarray, np.ndarray]:
        """The joints' position and velocity addresses in the compiled model."""
        addresses = [world.joint_address(self.entity, n) for n in self.names]
        return (
            np.array([a[0] for a in addresses], dtype=np.intp),
            np.array([a[1] for a in addresses], dtype=np.intp),
        )

    def positions(self) -> np.ndarray:
        """Positions now, in :attr:`names` order."""
        return self.world.data.qpos[self._ids.get(self.world)[0]]

    def velocities(self) -> np.ndarray:
        """Velocities now."""
        return self.world.data.qvel[self._ids.get(self.world)[1]]

    def efforts(self) -> np.ndarray:
        """The actuators' forces on the joints in the last step."""
        return self.world.data.qfrc_actuator[self._ids.get(self.world)[1]]

    def dof_indices(self) -> np.ndarray:
        """The joints' indices in MuJoCo's velocity-sized arrays (``qvel``, ``qfrc_applied``, ...), in
        :attr:`names` order, for the current model (they move when another entity is spawned)."""
        return self._ids.get(self.world)[1]


class ActuatorHandle:
    """One actuator on a joint, added by :meth:`PhysicsWorld.add_actuator`; ``command`` sets its input.

    The command holds until the next one: the world steps with it, inside MuJoCo, for as many
    steps as go by before the system that owns the actuator runs again.
    """

    __slots__ = ("joint", "kind", "name", "_id")

    def __reduce__(self) -> tuple[Any, ...]:
        """Saved by what it names (a checkpoint): found again in the world it is loaded into."""
        return (ActuatorHandle, (self.joint, self.kind, self.name))

    def __init__(self, joint: JointHandle, kind: ActuatorKind, name: str) -> None:
        """A handle on the actuator of kind ``kind`` that drives ``joint``, found by its MuJoCo name in each
        compiled model."""
        self.joint = joint
        self.kind = kind
        self.name = name
        """The actuator's MuJoCo name (``<entity>::<joint>#<kind>``)."""
        self._id = PerGeneration(lambda w: w.actuator_id(self.name))

    def command(self, value: float) -> None:
        """Set the actuator's input: a position, a velocity or an effort, by :attr:`kind`."""
        world = self.joint.world
        world.data.ctrl[self._id.get(world)] = value

    def set_gains(self, kp: float, kv: float) -> None:
        """Change the servo gains; see :meth:`PhysicsWorld.set_actuator_gains`."""
        self.joint.world.set_actuator_gains(self, kp, kv)

    def set_enabled(self, enabled: bool) -> None:
        """Switch the actuator on (its gains) or off (no force); see :meth:`PhysicsWorld.set_actuator_enabled`."""
        self.joint.world.set_actuator_enabled(self, enabled)

    @property
    def commanded(self) -> float:
        """The input last set."""
        world = self.joint.world
        return float(world.data.ctrl[self._id.get(world)])

    @property
    def force(self) -> float:
        """The force or torque this actuator applied in the last step."""
        world = self.joint.world
        return float(world.data.actuator_force[self._id.get(world)])

    def __repr__(self) -> str:
        return f"ActuatorHandle({self.name!r}, {self.kind.value})"


class ActuatorGroup:
    """Several actuators set together (one indexed write instead of one per actuator): what a
    ros2_control hardware component writes every cycle. Get one with :meth:`PhysicsWorld.actuator_group`."""

    __slots__ = ("world", "actuators", "_ids")

    def __reduce__(self) -> tuple[Any, ...]:
        """Saved by what it names (a checkpoint): found again in the world it is loaded into."""
        return (ActuatorGroup, (self.world, self.actuators))

    def __init__(self, world: CompiledWorld, actuators: tuple[ActuatorHandle, ...]) -> None:
        self.world = world
        self.actuators = actuators
        self._ids = PerGeneration(lambda w: np.array([w.actuator_id(a.name) for a in actuators], dtype=np.intp))

    def command(self, values: list[float]) -> None:
        """Set every actuator's input, in :attr:`actuators` order."""
        world = self.world
        world.data.ctrl[self._ids.get(world)] = values


class BodyHandle:
    """One link of an entity: its world pose and velocity (ground truth)."""

    __slots__ = ("world", "entity", "link", "_id")

    def __reduce__(self) -> tuple[Any, ...]:
        """Saved by what it names (a checkpoint): found again in the world it is loaded into."""
        return (BodyHandle, (self.world, self.entity, self.link))

    def __init__(self, world: CompiledWorld, entity: str, link: str | None) -> None:
        """A handle on a link's body (or, with ``link`` None, the entity's root), found again in each compiled
        model."""
        self.world = world
        self.entity = entity
        self.link = link
        """The link's name; None for the entity's root (its model frame)."""
        self._id = PerGeneration(lambda w: w.body_id(self.entity, self.link))

    @property
    def pose(self) -> Pose:
        """World pose of the link frame."""
        return self.world.body_pose(self._id.get(self.world))

    @property
    def velocity(self) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """(linear velocity of the link origin, angular velocity), both in the world frame."""
        return self.world.body_velocity(self._id.get(self.world))

    def cast_rays(self, origin: np.ndarray, directions: np.ndarray, max_range: float) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`PhysicsWorld.cast_rays` that never hits this body (a lidar's own housing)."""
        return self.world.cast_rays(origin, directions, self._id.get(self.world), max_range)

    def joint_wrench(self, point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`PhysicsWorld.joint_wrench` of this link: what its parent exerts on it, about ``point``."""
        return self.world.joint_wrench(self._id.get(self.world), point)

    def cast_rays_from(self, offset: Pose, directions: np.ndarray, max_range: float) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`PhysicsWorld.cast_rays_from` a sensor at ``offset`` on this link (never hitting the link)."""
        return self.world.cast_rays_from(self._id.get(self.world), offset, directions, max_range)

    def imu_reading(self, offset: Pose) -> list[float]:
        """:meth:`PhysicsWorld.imu_reading` of a sensor at ``offset`` in this link's frame."""
        return self.world.imu_reading(self._id.get(self.world), offset)

    def __repr__(self) -> str:
        return f"BodyHandle({self.entity!r}, {self.link!r})"

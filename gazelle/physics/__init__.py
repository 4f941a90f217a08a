"""MuJoCo physics built from description objects: the world, its entities and typed handles.

:class:`PhysicsWorld` holds the MuJoCo model and data; entities are added in two steps
(:meth:`PhysicsWorld.stage`, then :meth:`PhysicsWorld.commit`) so that the runtime can let
an entity's systems add actuators in between. Systems read and command the world through
:class:`JointHandle`, :class:`ActuatorHandle` and :class:`BodyHandle`, never through MuJoCo.
This package imports nothing from the systems, the runtime or ROS.
"""

from ._builder import SEP as SEP
from ._builder import BuildError as BuildError
from ._convex import prepare as prepare_meshes
from ._handles import ActuatorGroup as ActuatorGroup
from ._handles import ActuatorHandle as ActuatorHandle
from ._handles import ActuatorKind as ActuatorKind
from ._handles import BodyHandle as BodyHandle
from ._handles import JointGroup as JointGroup
from ._handles import JointHandle as JointHandle
from ._handles import PerGeneration as PerGeneration
from ._render import OffscreenRenderer as OffscreenRenderer
from ._render import RenderError as RenderError
from ._servo_plan import ServoPlan as ServoPlan
from ._world import MAX_COORDINATE_M as MAX_COORDINATE_M
from ._world import WORLD_FRAMES as WORLD_FRAMES
from ._world import ContactPoint as ContactPoint
from ._world import Entity as Entity
from ._world import EntityState as EntityState
from ._world import ErrorKind as ErrorKind
from ._world import PhysicsOverload as PhysicsOverload
from ._world import PhysicsWorld as PhysicsWorld
from ._world import StagedRequest as StagedRequest
from ._world import WorldError as WorldError
from ._world import build_failed as build_failed
from ._world import pose_out_of_range as pose_out_of_range

__all__ = [
    "ContactPoint",
    "ActuatorGroup",
    "ActuatorHandle",
    "ActuatorKind",
    "BodyHandle",
    "BuildError",
    "Entity",
    "EntityState",
    "ErrorKind",
    "JointGroup",
    "JointHandle",
    "MAX_COORDINATE_M",
    "OffscreenRenderer",
    "PerGeneration",
    "PhysicsOverload",
    "PhysicsWorld",
    "RenderError",
    "SEP",
    "ServoPlan",
    "StagedRequest",
    "WORLD_FRAMES",
    "WorldError",
    "build_failed",
    "pose_out_of_range",
    "prepare_meshes",
]

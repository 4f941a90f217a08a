"""MuJoCo physics built from description objects: the world, its entities and typed handles.

:class:`PhysicsWorld` holds the MuJoCo model and data; entities are added in two steps
(:meth:`PhysicsWorld.stage`, then :meth:`PhysicsWorld.commit`) so that the runtime can let
an entity's systems add actuators in between. Systems read and command the world through
:class:`JointHandle`, :class:`ActuatorHandle` and :class:`BodyHandle`, never through MuJoCo.
This package imports nothing from the systems, the runtime or ROS.
"""

import os as _os

# ``import mujoco`` picks an OpenGL backend for ``mujoco.Renderer`` and imports it (glfw unless
# MUJOCO_GL says otherwise: 0.1-0.3 s of every process's start, a third of MuJoCo's import). gazelle
# renders through mujoco.egl / mujoco.osmesa itself (_render.py), so unless the user chose a backend the
# import is told to skip it; the variable is put back as it was, for the processes gazelle starts.
if "MUJOCO_GL" not in _os.environ:
    _os.environ["MUJOCO_GL"] = "disable"
    try:
        import mujoco as _mujoco  # noqa: F401
    finally:
        del _os.environ["MUJOCO_GL"]

from ._bounds import Aabb as Aabb
from ._bounds import collision_boxes as collision_boxes
from ._bounds import entity_box as entity_box
from ._bounds import model_box as model_box
from ._bounds import overlapping as overlapping
from ._builder import SEP as SEP
from ._builder import BuildError as BuildError
from ._convex import prepare as prepare_meshes
from ._entities import MAX_COORDINATE_M as MAX_COORDINATE_M
from ._entities import WORLD_FRAMES as WORLD_FRAMES
from ._entities import Entity as Entity
from ._entities import EntityState as EntityState
from ._entities import ErrorKind as ErrorKind
from ._entities import PhysicsOverload as PhysicsOverload
from ._entities import StagedRequest as StagedRequest
from ._entities import WorldError as WorldError
from ._entities import build_failed as build_failed
from ._entities import pose_out_of_range as pose_out_of_range
from ._handles import ActuatorGroup as ActuatorGroup
from ._handles import ActuatorHandle as ActuatorHandle
from ._handles import ActuatorKind as ActuatorKind
from ._handles import BodyHandle as BodyHandle
from ._handles import JointGroup as JointGroup
from ._handles import JointHandle as JointHandle
from ._handles import PerGeneration as PerGeneration
from ._queries import ContactPoint as ContactPoint
from ._render import OffscreenRenderer as OffscreenRenderer
from ._render import RenderError as RenderError
from ._servo_plan import ServoPlan as ServoPlan
from ._world import PhysicsWorld as PhysicsWorld

__all__ = [
    "Aabb",
    "collision_boxes",
    "entity_box",
    "model_box",
    "overlapping",
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

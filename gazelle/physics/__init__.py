"""MuJoCo physics built from description objects: step, spawn/delete, pause/step/reset, RTF."""

from ._builder import BuildError as BuildError
from ._simulation import RtfSample as RtfSample
from ._simulation import Simulation as Simulation
from ._world import Entity as Entity
from ._world import EntityState as EntityState
from ._world import ErrorKind as ErrorKind
from ._world import PhysicsWorld as PhysicsWorld
from ._world import WorldError as WorldError
from ._world import WORLD_FRAMES as WORLD_FRAMES
from ._world import PhysicsOverload as PhysicsOverload
from ._world import MAX_COORDINATE_M as MAX_COORDINATE_M
from ._world import pose_out_of_range as pose_out_of_range

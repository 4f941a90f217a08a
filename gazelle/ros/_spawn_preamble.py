"""What a spawn request goes through before the world sees it, whichever service it came by (gazebo_ros's
``/spawn_entity`` and its ROS 1 names in ``_gazebo_services.py``, simulation_interfaces' SpawnEntity and
SpawnEntities in ``_simulation_interfaces.py``): the pose checked (finite, within reach), the description parsed
(data: never xacro-expanded) into the one model it holds, its warnings logged, and the reference frame found in
the world. Written once; a refusal is a :class:`SpawnFailed` whose kind each service turns into its own reply."""

from __future__ import annotations

import enum
import math
from typing import TYPE_CHECKING

from .._errors import SimError
from ..description import ErrorCode, Model, ModelLoadError, Pose, ResourceResolver, World, load_string
from ..physics import WORLD_FRAMES, WorldError, pose_out_of_range
from ..sim import Simulation
from ._log_diagnostic import log_diagnostic

if TYPE_CHECKING:
    from rclpy.impl.rcutils_logger import RcutilsLogger


class SpawnFailure(enum.StrEnum):
    """Why a spawn request was refused before it reached the world."""

    INVALID_POSE = "invalid_pose"
    PARSE = "parse"
    UNSUPPORTED_FORMAT = "unsupported_format"
    NO_MODEL = "no_model"
    FRAME = "frame"


class SpawnFailed(SimError, ValueError):
    """A spawn request was refused; ``kind`` says why (each service maps it to its result code)."""

    def __init__(self, kind: SpawnFailure, message: str):
        super().__init__(message)
        self.kind = kind


def check_pose(pose: Pose, field: str) -> None:
    """Refuse (``INVALID_POSE``) a pose that is not finite or lies beyond reach; ``field`` names it in the reply
    (``initial_pose``, ``initial_pose.pose``)."""
    if not all(math.isfinite(v) for v in (*pose.position, *pose.orientation)):
        raise SpawnFailed(SpawnFailure.INVALID_POSE, f"{field} is not finite (NaN or inf): {pose}")
    far = pose_out_of_range(pose, f"{field}.position")
    if far is not None:
        raise SpawnFailed(SpawnFailure.INVALID_POSE, far)


def model_to_spawn(
    text: str, *, source: str, logger: RcutilsLogger, format: str = "auto", resolver: ResourceResolver | None = None
) -> tuple[Model, tuple[str, ...]]:
    """The one model a description holds (a model or robot, or a world's first model) and its warnings, each
    also logged on ``logger``.

    Raises:
        SpawnFailed: ``UNSUPPORTED_FORMAT`` (not a format gazelle reads), ``PARSE`` (it does not parse: file:line
            diagnostics), ``NO_MODEL`` (nothing in it to spawn).
    """
    try:
        loaded = load_string(text, format=format, source=source, resolver=resolver)
    except ModelLoadError as err:
        first = err.first
        unknown = first is not None and first.code is ErrorCode.UNKNOWN_FORMAT
        raise SpawnFailed(SpawnFailure.UNSUPPORTED_FORMAT if unknown else SpawnFailure.PARSE, err.summary()) from None
    value = loaded.value
    if isinstance(value, Model):
        model = value
    elif isinstance(value, World) and value.models:
        model = value.models[0]
    else:
        raise SpawnFailed(SpawnFailure.NO_MODEL, f"{source}: no <model> or <robot> to spawn")
    for d in loaded.diagnostics:
        log_diagnostic(logger, d)
    return model, tuple(d.format() for d in loaded.diagnostics)


def frame_in_world(sim: Simulation, frame: str, field: str) -> Pose:
    """The world pose of a request's reference frame: the world (``''``, ``world``, ``map``), an entity, or
    ``entity::link``; ``FRAME`` naming the request field when there is no such frame."""
    if frame in WORLD_FRAMES:
        return Pose()
    try:
        return sim.call(lambda: sim.world.frame_pose(frame))
    except WorldError:
        raise SpawnFailed(SpawnFailure.FRAME, f"{field} '{frame}' not found: no such entity or entity::link") from None

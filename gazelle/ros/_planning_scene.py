"""moveit_msgs planning-scene messages <-> gazelle.planning scene objects.

A CollisionObject's primitives (box, sphere, cylinder) become :class:`Shape` s; a mesh is planned
with as its bounding box, and a plane or a cone is not planned with; both are said in a warning, so
nothing is dropped silently.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import AttachedCollisionObject, CollisionObject
from shape_msgs.msg import SolidPrimitive

from ..planning import PlanningError, SceneObject, Shape

MAX_PRIMITIVES = 64
"""The most primitives (and meshes) one CollisionObject may hold."""
MAX_MESH_VERTICES = 100_000
"""The most vertices one mesh of a CollisionObject may have (it is planned with as its bounding box)."""
MAX_COORDINATE_M = 10_000.0
"""The farthest a pose may place anything, and the largest a shape may be (10 km): beyond is a mistake."""
_DIMENSIONS = {"box": 3, "sphere": 1, "cylinder": 2}

_KINDS = {SolidPrimitive.BOX: "box", SolidPrimitive.SPHERE: "sphere", SolidPrimitive.CYLINDER: "cylinder"}
_TYPES = {kind: t for t, kind in _KINDS.items()}


def matrix(pose: Pose) -> np.ndarray:
    """A geometry_msgs Pose as a 4x4 matrix (the quaternion normalised; all zeros is the identity)."""
    q = pose.orientation
    x, y, z, w = q.x, q.y, q.z, q.w
    n = math.sqrt(x * x + y * y + z * z + w * w)
    if n == 0.0:
        x, y, z, w, n = 0.0, 0.0, 0.0, 1.0, 1.0
    x, y, z, w = x / n, y / n, z / n, w / n
    m = np.eye(4)
    m[:3, :3] = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    m[:3, 3] = [pose.position.x, pose.position.y, pose.position.z]
    return m


def pose(m: np.ndarray) -> Pose:
    """A 4x4 matrix as a geometry_msgs Pose."""
    r = m[:3, :3]
    tr = r[0, 0] + r[1, 1] + r[2, 2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        w, x, y, z = 0.25 * s, (r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s
    elif r[0, 0] > r[1, 1] and r[0, 0] > r[2, 2]:
        s = math.sqrt(1.0 + r[0, 0] - r[1, 1] - r[2, 2]) * 2
        w, x, y, z = (r[2, 1] - r[1, 2]) / s, 0.25 * s, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s
    elif r[1, 1] > r[2, 2]:
        s = math.sqrt(1.0 + r[1, 1] - r[0, 0] - r[2, 2]) * 2
        w, x, y, z = (r[0, 2] - r[2, 0]) / s, (r[0, 1] + r[1, 0]) / s, 0.25 * s, (r[1, 2] + r[2, 1]) / s
    else:
        s = math.sqrt(1.0 + r[2, 2] - r[0, 0] - r[1, 1]) * 2
        w, x, y, z = (r[1, 0] - r[0, 1]) / s, (r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, 0.25 * s
    p = Pose()
    p.position.x, p.position.y, p.position.z = map(float, m[:3, 3])
    p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w = float(x), float(y), float(z), float(w)
    return p


def checked_matrix(p: Pose, what: str) -> np.ndarray:
    """:func:`matrix` of a pose that a request gave, refused (``FAILURE``, naming ``what``) when it is not
    finite or lies farther than :data:`MAX_COORDINATE_M`: a NaN pose accepted into the scene made every
    later plan fail until it was removed."""
    values = (p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z)
    values += (p.orientation.w,)
    if not all(math.isfinite(v) for v in values):
        raise PlanningError("FAILURE", f"{what}: the pose has a NaN or infinite value")
    if max(abs(p.position.x), abs(p.position.y), abs(p.position.z)) > MAX_COORDINATE_M:
        raise PlanningError("FAILURE", f"{what}: the pose is farther than {MAX_COORDINATE_M:g} m")
    return matrix(p)


def _checked_dimensions(kind: str, dims: list[float], what: str) -> tuple[float, ...]:
    """A shape's dimensions as MoveIt's SolidPrimitive gives them (box 3, sphere 1, cylinder 2), each
    positive, finite and no larger than :data:`MAX_COORDINATE_M`; a PlanningError naming the object otherwise."""
    need = _DIMENSIONS[kind]
    if len(dims) < need:
        raise PlanningError("FAILURE", f"{what}: a {kind} needs {need} dimension(s), got {len(dims)}")
    out = tuple(float(v) for v in dims[:need])
    if not all(math.isfinite(v) and 0.0 < v <= MAX_COORDINATE_M for v in out):
        raise PlanningError(
            "FAILURE",
            f"{what}: a {kind}'s dimensions must be positive, finite and at most "
            f"{MAX_COORDINATE_M:g} m, got {list(out)}",
        )
    return out


def shapes_of(co: CollisionObject, warn: Callable[[str], None]) -> list[Shape]:
    """The primitives (and meshes, as boxes) of a CollisionObject, in the object's frame.

    Raises:
        PlanningError: ``FAILURE`` for more than :data:`MAX_PRIMITIVES` shapes, a mesh of more than
            :data:`MAX_MESH_VERTICES`, or a NaN, infinite, non-positive or absurd size or pose.
    """
    out: list[Shape] = []
    what = f"collision object '{co.id[:80]}'"
    if len(co.primitives) + len(co.meshes) > MAX_PRIMITIVES:
        raise PlanningError(
            "FAILURE", f"{what} has {len(co.primitives) + len(co.meshes)} shapes, more than {MAX_PRIMITIVES}"
        )
    poses = list(co.primitive_poses)
    for i, primitive in enumerate(co.primitives):
        at = checked_matrix(poses[i], f"{what}: primitive_poses[{i}]") if i < len(poses) else np.eye(4)
        kind = _KINDS.get(primitive.type)
        if kind is None:
            warn(f"{what}: primitive {i} of type {primitive.type} is not planned with")
            continue
        out.append(Shape(kind, _checked_dimensions(kind, list(primitive.dimensions), f"{what}: primitives[{i}]"), at))
    mesh_poses = list(co.mesh_poses)
    for i, mesh in enumerate(co.meshes):
        if len(mesh.vertices) > MAX_MESH_VERTICES:
            raise PlanningError(
                "FAILURE", f"{what}: meshes[{i}] has {len(mesh.vertices)} vertices, more than {MAX_MESH_VERTICES}"
            )
        points = np.array([[v.x, v.y, v.z] for v in mesh.vertices], dtype=float)
        if not len(points):
            continue
        if not np.all(np.isfinite(points)) or np.abs(points).max() > MAX_COORDINATE_M:
            raise PlanningError("FAILURE", f"{what}: meshes[{i}] has a NaN, infinite or absurd vertex")
        if i < len(mesh_poses):
            checked_matrix(mesh_poses[i], f"{what}: mesh_poses[{i}]")
        lo, hi = points.min(axis=0), points.max(axis=0)
        at = (matrix(mesh_poses[i]) if i < len(mesh_poses) else np.eye(4)) @ _translation((lo + hi) / 2)
        out.append(Shape("box", tuple(float(v) for v in np.maximum(hi - lo, 1e-4)), at))
        warn(f"{what}: mesh {i} is planned with as its bounding box")
    if co.planes:
        warn(f"{what}: {len(co.planes)} plane(s) are not planned with")
    return out


def padded(shape: Shape, pad: float) -> Shape:
    """``shape`` grown by ``pad`` metres on every side."""
    d = shape.dimensions
    if shape.kind == "box":
        grown = tuple(v + 2 * pad for v in d)
    elif shape.kind == "sphere":
        grown = (d[0] + pad,)
    else:  # cylinder: height, radius
        grown = (d[0] + 2 * pad, d[1] + pad)
    return Shape(shape.kind, grown, shape.pose)


def _translation(xyz: np.ndarray) -> np.ndarray:
    m = np.eye(4)
    m[:3, 3] = xyz
    return m


def to_message(obj: SceneObject, frame: str) -> CollisionObject:
    """A scene object as a CollisionObject (ADD) in ``frame`` (the root link, or the link it is attached to)."""
    co = CollisionObject()
    co.header.frame_id = frame
    co.id = obj.name
    co.pose = pose(obj.pose)
    co.primitives = [SolidPrimitive(type=_TYPES[s.kind], dimensions=list(s.dimensions)) for s in obj.shapes]
    co.primitive_poses = [pose(s.pose) for s in obj.shapes]
    co.operation = CollisionObject.ADD
    return co


def attached_message(obj: SceneObject) -> AttachedCollisionObject:
    """An object attached to the robot as moveit_msgs/AttachedCollisionObject: the link, its shapes in that link's
    frame, and the links it may touch."""
    aco = AttachedCollisionObject()
    aco.link_name = obj.link
    aco.object = to_message(obj, obj.link)
    aco.touch_links = list(obj.touch_links)
    return aco

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

from ..planning import SceneObject, Shape

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


def shapes_of(co: CollisionObject, warn: Callable[[str], None]) -> list[Shape]:
    """The primitives (and meshes, as boxes) of a CollisionObject, in the object's frame."""
    out: list[Shape] = []
    poses = list(co.primitive_poses)
    for i, primitive in enumerate(co.primitives):
        at = matrix(poses[i]) if i < len(poses) else np.eye(4)
        kind = _KINDS.get(primitive.type)
        if kind is None:
            warn(f"collision object '{co.id}': primitive {i} of type {primitive.type} is not planned with")
            continue
        out.append(Shape(kind, tuple(float(v) for v in primitive.dimensions), at))
    mesh_poses = list(co.mesh_poses)
    for i, mesh in enumerate(co.meshes):
        points = np.array([[v.x, v.y, v.z] for v in mesh.vertices], dtype=float)
        if not len(points):
            continue
        lo, hi = points.min(axis=0), points.max(axis=0)
        at = (matrix(mesh_poses[i]) if i < len(mesh_poses) else np.eye(4)) @ _translation((lo + hi) / 2)
        out.append(Shape("box", tuple(float(v) for v in np.maximum(hi - lo, 1e-4)), at))
        warn(f"collision object '{co.id}': mesh {i} is planned with as its bounding box")
    if co.planes:
        warn(f"collision object '{co.id}': {len(co.planes)} plane(s) are not planned with")
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
    aco = AttachedCollisionObject()
    aco.link_name = obj.link
    aco.object = to_message(obj, obj.link)
    aco.touch_links = list(obj.touch_links)
    return aco

"""The simulated world's collision geometry, as a motion planner sees obstacles.

Every link of every entity that has collision geometry becomes one :class:`SceneLink`: its world pose
now, and its shapes in the link's frame, reduced to what planners check (boxes, spheres and
cylinders): a capsule or a cone as the cylinder around it, an ellipsoid or a mesh as its bounding box,
and a plane (the ground) as a slab of :data:`PLANE_THICKNESS` under it, as wide as the plane's
``<size>``: an arm bolted to the ground must not plan through the floor the simulation stops it at.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..description import (
    Box,
    Capsule,
    Cone,
    Cylinder,
    Ellipsoid,
    Mesh,
    MeshReadError,
    Model,
    Plane,
    Pose,
    Sphere,
    load_mesh,
)
from ..physics import SEP, PhysicsWorld, WorldError

PLANE_THICKNESS = 0.5
"""How deep the slab that stands for a plane is (thick enough that no planned step goes through it)."""


@dataclass(frozen=True)
class SceneShape:
    """``box`` (x, y, z sizes), ``sphere`` (radius) or ``cylinder`` (height, radius), at ``pose`` in its link.

    Metres; a box's sizes are full edge lengths and a cylinder's axis is its local z, as in
    shape_msgs/SolidPrimitive, whose dimension order (BOX_X.., CYLINDER_HEIGHT, CYLINDER_RADIUS) the
    ``dimensions`` keep so the planning-scene publisher copies them as they are."""

    kind: str
    dimensions: tuple[float, ...]
    pose: Pose


@dataclass(frozen=True)
class SceneLink:
    """One link's collision shapes and where the link is: ``name`` is ``entity::link``."""

    name: str
    pose: Pose
    shapes: tuple[SceneShape, ...]


def link_shapes(model: Model) -> dict[str, tuple[SceneShape, ...]]:
    """Each link's collision shapes (links with none are left out).

    The description's collisions, not MuJoCo's geoms: a mesh is bounded from its own vertices rather than
    from the convex parts the physics built, so the planner's box does not depend on how a mesh was
    decomposed (and needs no physics handle)."""
    out: dict[str, tuple[SceneShape, ...]] = {}
    for link in model.links:
        shapes = [s for s in (_shape(c.geometry, c.pose) for c in link.collisions) if s is not None]
        if shapes:
            out[link.name] = tuple(shapes)
    return out


def _shape(geometry: object, pose: Pose) -> SceneShape | None:
    """The planner's shape for one collision geometry at ``pose`` in its link, always one that contains
    the real one (a planner may be cautious, never blind): None for a mesh that cannot be read, which the
    description's loader has already warned about."""
    if isinstance(geometry, Box):
        return SceneShape("box", tuple(float(v) for v in geometry.size), pose)
    if isinstance(geometry, Sphere):
        return SceneShape("sphere", (float(geometry.radius),), pose)
    if isinstance(geometry, Cylinder | Cone):  # a cone inside the cylinder of its base and height
        return SceneShape("cylinder", (float(geometry.length), float(geometry.radius)), pose)
    if isinstance(geometry, Capsule):  # the cylinder that holds both hemispherical caps
        return SceneShape("cylinder", (float(geometry.length + 2 * geometry.radius), float(geometry.radius)), pose)
    if isinstance(geometry, Ellipsoid):
        return SceneShape("box", tuple(2.0 * float(r) for r in geometry.radii), pose)
    if isinstance(geometry, Mesh) and geometry.path:
        # the axis-aligned box of the scaled vertices, centred where they are (a mesh's origin is often
        # at one end, not the middle); a flat mesh keeps a 0.1 mm thickness so the box is not degenerate
        try:
            vertices, _ = load_mesh(geometry.path)
        except MeshReadError:
            return None
        if not len(vertices):
            return None
        points = np.asarray(vertices, dtype=float) * np.asarray(geometry.scale, dtype=float)
        lo, hi = points.min(axis=0), points.max(axis=0)
        mid = (lo + hi) / 2
        center = Pose((float(mid[0]), float(mid[1]), float(mid[2])))
        return SceneShape("box", tuple(float(max(v, 1e-4)) for v in hi - lo), pose * center)
    if isinstance(geometry, Plane):
        # the slab's top face is the plane: turn z onto its normal, then go half the thickness down
        n = np.asarray(geometry.normal, dtype=float)
        n = n / np.linalg.norm(n) if np.linalg.norm(n) > 0 else np.array([0.0, 0.0, 1.0])
        axis, cos = np.cross((0.0, 0.0, 1.0), n), float(n[2])
        if np.linalg.norm(axis) < 1e-9:
            turn = Pose() if cos > 0 else Pose(orientation=(0.0, 1.0, 0.0, 0.0))
        else:
            half = math.acos(max(-1.0, min(1.0, cos))) / 2.0
            x, y, z = (axis / np.linalg.norm(axis) * math.sin(half)).tolist()
            turn = Pose(orientation=(math.cos(half), x, y, z))
        width, depth = (max(float(v), 1.0) for v in geometry.size)
        return SceneShape("box", (width, depth, PLANE_THICKNESS), pose * turn * Pose((0.0, 0.0, -PLANE_THICKNESS / 2)))
    return None  # a mesh that could not be found


class SceneGeometry:
    """The world's collision geometry, kept per entity; call :meth:`links` on the simulation thread.

    Shapes are worked out once per entity (reading a mesh is slow); only poses are read each time. The
    cache is keyed by the entity's name *and* its model object, so an entity deleted and spawned again
    under the same name with another description gets its new shapes, and entries of entities that are
    gone are dropped at the next call."""

    def __init__(self) -> None:
        self._shapes: dict[tuple[str, int], dict[str, tuple[SceneShape, ...]]] = {}

    def links(self, world: PhysicsWorld) -> list[SceneLink]:
        """Every entity link with collision shapes, at its pose now."""
        out: list[SceneLink] = []
        seen = set()
        for name, entity in list(world.entities.items()):
            key = (name, id(entity.model))
            seen.add(key)
            shapes = self._shapes.get(key)
            if shapes is None:
                shapes = self._shapes[key] = link_shapes(entity.model)
            for link, link_shapes_ in shapes.items():
                try:
                    pose = world.body_pose(world.body_id(name, link))
                except WorldError:  # a link the builder made no body of (joined to nothing): it is not
                    continue  # in the world, so there is nothing there to plan around
                out.append(SceneLink(f"{name}{SEP}{link}", pose, link_shapes_))
        for key in set(self._shapes) - seen:
            del self._shapes[key]
        return out


def moved(a: Pose, b: Pose, distance: float = 1e-3, angle: float = 0.01) -> bool:
    """Whether two poses differ by more than ``distance`` metres or ``angle`` radians.

    The planning-scene publisher resends the world only when something moved this much: a settling
    object jitters by micrometres every step, and resending a whole PlanningSceneWorld for that would
    make move_group rebuild its collision world for nothing. The angle is the rotation between the two
    (``2 acos |q_a . q_b|``, either sign of a quaternion being the same rotation)."""
    if math.dist(a.position, b.position) > distance:
        return True
    dot = abs(sum(x * y for x, y in zip(a.orientation, b.orientation)))
    return 2.0 * math.acos(min(1.0, dot)) > angle
